"""Every tolerance trinormal uses, in one place.

A triangle is *degenerate* when it is thin compared with its longest side::

    |N| <= tol * L**2,   L**2 = max(|B - A|**2, |C - A|**2, |C - B|**2)

|N| is twice the area, so |N| / L is the height of the triangle over its
longest side and the rule reads: the height is at most ``tol`` times the
longest side. The rule is the same for every order of the corners (each
rotation, both windings), so a needle is degenerate whichever corner is A,
and so are nearly coincident points (L is then a side the third point is
close to, or the height over it is tiny).

The test is scale-invariant: multiplying every coordinate by the same factor
never changes the verdict, so a valid triangle with edges of length 1e-200 keeps
its normal. ``tol = 0`` is the exact collinearity test (N is exactly zero).
``|N| / L**2`` is at most √3/2 (an equilateral triangle), so ``tol = 1`` marks
every triangle degenerate. The core decides it in exact integers; results show
the measured value as ``TriangleNormal.thickness``. This docstring is the one
statement of the rule; the core, the mesh kernel, the command line and the
site's calculator apply it.

Examples
--------
>>> DEFAULT_TOL
1e-12
>>> UNIT_NORMAL_ULPS, MAGNITUDE_ULPS
(2, 1)
"""

from __future__ import annotations

__all__ = [
    "DEFAULT_TOL",
    "MAGNITUDE_ULPS",
    "PLANAR_TOL",
    "UNIT_NORMAL_ULPS",
]

#: Default threshold on |N| / L² at or below which a triangle counts as degenerate.
#: About 10 000 times the double-precision unit roundoff: a triangle this thin
#: has a normal that float64 arithmetic cannot be trusted to orient.
DEFAULT_TOL: float = 1e-12

#: Accuracy promised for the exact path: each unit-normal component is within
#: this many units in the last place of the exact N / |N| ...
UNIT_NORMAL_ULPS: int = 2

#: ... and |N| and the area are within this many units in the last place.
MAGNITUDE_ULPS: int = 1

#: A polygon of a mesh file is *not planar* when its corners spread along its normal
#: (Newell's) by more than this times its longest side: far above float64 rounding
#: (about 1e-16 of the size), far below a warp anyone models on purpose. Its split into
#: triangles then chooses a surface the file does not define (`trinormal.mesh.polygons`).
PLANAR_TOL: float = 1e-6
