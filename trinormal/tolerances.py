"""Every tolerance trinormal uses, in one place.

A triangle is *degenerate* when the sine of the angle between its two edge
vectors is at most a tolerance ``tol``::

    |N| <= tol * |U| * |V|

The test is scale-invariant: multiplying every coordinate by the same factor
never changes the verdict, so a valid triangle with edges of length 1e-200 keeps
its normal. ``tol = 0`` is the exact collinearity test (N is exactly zero).

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
    "UNIT_NORMAL_ULPS",
]

#: Default sine threshold below which a triangle counts as degenerate.
#: About 10 000 times the double-precision unit roundoff: a triangle this thin
#: has a normal that float64 arithmetic cannot be trusted to orient.
DEFAULT_TOL: float = 1e-12

#: Accuracy promised for the exact path: each unit-normal component is within
#: this many units in the last place of the exact N / |N| ...
UNIT_NORMAL_ULPS: int = 2

#: ... and |N| and the area are within this many units in the last place.
MAGNITUDE_ULPS: int = 1
