"""What a student preparing a 3D print needs to read: holes, area, volume, size and a verdict.

`trinormal.mesh.check` measures the surface area and the bounding box (`measure`) and
derives the rest from its findings (`print_report`): the holes (rims of boundary edges,
with the number of edges around each), the volume each closed piece encloses and their
sum, and one line that says whether the model is ready for a slicer or what stands in the
way. ``MeshReport.to_dict()`` adds them under the keys ``holes``, ``surface_area``,
``volume``, ``size`` and ``verdict``; ``MeshReport.summary()`` ends with them in words.

Slicers read a file's coordinates as millimetres. A model whose largest side, read so, is
below ``UNITS["metres_below"]`` (1 mm) is almost surely in metres (or inches); below
``UNITS["inches_below"]`` (10 mm) it may be in inches or centimetres; above
``UNITS["micrometres_above"]`` (2000 mm, beyond the bed of any common printer) it is
probably in micrometres or meant to be scaled down. The size line says so
(``units_hint``); the hint is advice and no problem of the mesh: it never changes
``MeshReport.ok`` nor the exit status of ``trinormal mesh``.

The site's "Check a mesh" page computes the same (``docs/assets/javascripts/
trinormal-mesh-print.js``), with these templates, limits and the same additions in the
same order, so the two give the same numbers to the last bit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import partial, reduce
from operator import add
from typing import TYPE_CHECKING, Any

import numpy as np

from trinormal.display import SCI_ABOVE_LOG10, format_number
from trinormal.mesh._arrays import BoolArray, FloatArray, IntArray
from trinormal.mesh.topology import _components, _Rims

if TYPE_CHECKING:
    from trinormal.mesh.report import MeshReport

__all__ = [
    "PRINTING",
    "UNITS",
    "Measures",
    "PrintReport",
    "Size",
    "measure",
    "print_report",
    "printing_constants",
    "shown",
]

#: Where a model's largest side, read as millimetres, suggests other units (see the module text).
UNITS: dict[str, float] = {
    "metres_below": 1.0,
    "inches_below": 10.0,
    "micrometres_above": 2000.0,
}

#: Significant digits of the numbers in the printing lines (areas, volumes, sizes).
SIGNIFICANT = 6

#: Pieces, or holes, listed one by one in a line before the rest are written "…".
LISTED = 8

#: Why a model has no enclosed volume, in the summary line and the page's tables.
NO_VOLUME = "only a closed, consistently wound piece has an inside to measure"

#: The printing lines and the verdict's words: a template, or a (one, many) pair chosen by ``{n}``.
PRINTING: dict[str, str | tuple[str, str]] = {
    "holes": (
        "{n} hole: {edges} around it.",
        "{n} holes, with {edges} edges around them.",
    ),
    "size": "Size: {x} × {y} × {z} (x, y, z) in the file's units, which slicers read as mm.",
    "hint_metres": (
        "Read as millimetres its largest side, {largest}, is under {limit} mm: the model is "
        "probably in metres (scale it by 1000) or inches (by 25.4)."
    ),
    "hint_inches": (
        "Read as millimetres its largest side, {largest}, is under {limit} mm: if the model is "
        "in inches, scale it by 25.4 (by 10 if it is in centimetres)."
    ),
    "hint_micrometres": (
        "Read as millimetres its largest side, {largest}, is over {limit} mm, larger than a "
        "printer's bed: the model is probably in micrometres (scale it by 0.001) or meant to "
        "be scaled down."
    ),
    "area_volume": "Surface area {area}; enclosed volume {volume}.",
    "area_volumes": "Surface area {area}; enclosed volume {volume} in all ({pieces}).",
    "piece_volume": "piece {i}: {volume}",
    "others_none": "the other pieces, open or wound inconsistently, enclose none",
    "area_no_volume": "Surface area {area}; no enclosed volume: " + NO_VOLUME + ".",
    "verdict_line": "Verdict: {verdict}.",
    "verdict": "{closure}, {pieces}, {winding}: {conclusion}",
    "watertight": "watertight",
    "not_watertight": "not watertight",
    "wound_outward": "wound outward",
    "wound_consistently": "wound consistently",
    "one_sided": "one-sided",
    "inconsistent": "wound inconsistently",
    "inside_out": "inside out",
    "no_volume": "enclosing no volume",
    "ready": "ready for a slicer",
    "not_ready": "not ready for a slicer ({obstacles})",
    "no_faces": "no faces",
    "obstacle_holes": ("{n} hole", "{n} holes"),
    "obstacle_fins": ("{n} edge of three faces or more", "{n} edges of three faces or more"),
    "obstacle_pinches": ("{n} pinch point", "{n} pinch points"),
    "obstacle_degenerate": ("{n} degenerate face", "{n} degenerate faces"),
    "obstacle_duplicates": ("{n} duplicate face", "{n} duplicate faces"),
    "obstacle_unused": ("{n} unused vertex", "{n} unused vertices"),
    "obstacle_one_sided": ("{n} one-sided piece", "{n} one-sided pieces"),
    "obstacle_no_volume": ("{n} closed piece with no volume", "{n} closed pieces with no volume"),
    "obstacle_flips": ("{n} face to turn over", "{n} faces to turn over"),
}

#: Faces whose areas `measure` works on at a time: its (block, 3) arrays stay small.
_AREA_BLOCK = 1 << 16


def _fill(
    templates: dict[str, str | tuple[str, str]], key: str, n: int | None = None, **values: str | int
) -> str:
    """Fill ``templates[key]``: a (one, many) pair is chosen by the count ``n``."""
    template = templates[key]
    if isinstance(template, tuple):
        template = template[0] if n == 1 else template[1]
    return template.format(n=n, **values)


_say = partial(_fill, PRINTING)


def shown(x: float) -> str:
    """Write a number of the printing lines: `SIGNIFICANT` digits, trailing zeros dropped.

    The decimals are found by multiplying or dividing by ten in float arithmetic (as the
    page's JavaScript does), then the package's formatter rounds the exact value; below
    1e-10 and from 1e15 on it writes ``SIGNIFICANT`` digits in scientific notation.

    Examples
    --------
    >>> shown(24.0), shown(4.18879020478639), shown(0.05), shown(123456789.0), shown(-2.5e-7)
    ('24', '4.18879', '0.05', '123456789', '-0.00000025')
    >>> shown(1e-20), shown(1.2345678e20), shown(1234567.25), shown(0.0), shown(float("inf"))
    ('1e-20', '1.23457e+20', '1234567', '0', 'inf')
    """
    if not math.isfinite(x):
        return "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")
    a, decimals = abs(x), SIGNIFICANT - 1
    while a >= 10.0 and decimals > 0:
        a /= 10.0
        decimals -= 1
    while 0.0 < a < 1.0 and decimals < 15:
        a *= 10.0
        decimals += 1
    if a < 1.0 or abs(x) >= 10.0**SCI_ABOVE_LOG10:  # zero, or written m·10^e: `SIGNIFICANT` digits
        decimals = SIGNIFICANT - 1
    return format_number(x, decimals, trim=True)


@dataclass(frozen=True)
class Size:
    """The bounding box of the vertices the faces use.

    Attributes
    ----------
    minimum, maximum : tuple of float
        Its corners (x, y, z); a zero is never written ``-0.0``.
    """

    minimum: tuple[float, float, float]
    maximum: tuple[float, float, float]

    @property
    def extent(self) -> tuple[float, float, float]:
        """Its sides along x, y and z."""
        lo, hi = self.minimum, self.maximum
        return (hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2])

    @property
    def units_hint(self) -> str | None:
        """``"metres"``, ``"inches"`` or ``"micrometres"`` when the size suggests those units.

        Read as millimetres, as slicers read a file; None when the size looks like a model
        in millimetres (or the box is a point, or beyond the float range). See `UNITS`.

        Examples
        --------
        >>> Size((0.0, 0.0, 0.0), (0.05, 0.02, 0.01)).units_hint
        'metres'
        >>> Size((0.0, 0.0, 0.0), (50.0, 20.0, 10.0)).units_hint is None
        True
        """
        largest = max(self.extent)
        if not math.isfinite(largest) or largest == 0.0:
            return None
        if largest < UNITS["metres_below"]:
            return "metres"
        if largest < UNITS["inches_below"]:
            return "inches"
        if largest > UNITS["micrometres_above"]:
            return "micrometres"
        return None

    def to_dict(self) -> dict[str, Any]:
        """``min``, ``max``, ``extent`` (lists of x, y, z) and ``units_hint``."""
        return {
            "min": list(self.minimum),
            "max": list(self.maximum),
            "extent": list(self.extent),
            "units_hint": self.units_hint,
        }

    def lines(self) -> list[str]:
        """Return the size line, and the units hint's line when there is one."""
        x, y, z = (shown(s) for s in self.extent)
        out = [_say("size", x=x, y=y, z=z)]
        hint = self.units_hint
        if hint is not None:
            limit = UNITS["micrometres_above" if hint == "micrometres" else hint + "_below"]
            out.append(_say("hint_" + hint, largest=shown(max(self.extent)), limit=shown(limit)))
        return out


@dataclass(frozen=True)
class Measures:
    """What `measure` takes from the coordinates: the surface area and the size."""

    surface_area: float
    size: Size | None


def measure(vertices: FloatArray, faces: IntArray, used: BoolArray) -> Measures:
    """Measure the surface area and the bounding box of a checked mesh.

    Parameters
    ----------
    vertices : ndarray of float64, shape (V, 3)
    faces : ndarray of int, shape (F, 3)
        Checked arrays, as `trinormal.mesh.check` holds them.
    used : ndarray of bool, shape (V,)
        The vertices some face uses: the box is theirs alone.

    Returns
    -------
    Measures
        The area is the sum of |N| / 2 over the faces, N = (B − A) × (C − A), computed on
        coordinates divided by one power of two (so that no product overflows or
        underflows, at any scale) and added face after face, in the order of the faces.

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> m = measure(v, f, np.ones(8, dtype=bool))
    >>> m.surface_area, m.size.extent
    (24.0, (2.0, 2.0, 2.0))
    """
    if not used.any():
        return Measures(surface_area=0.0, size=None)
    inf = float("inf")
    # `+ 0.0` writes a zero corner as 0.0, never -0.0, whichever of the two min() meets first
    lo = np.min(vertices, axis=0, where=used[:, None], initial=inf) + 0.0
    hi = np.max(vertices, axis=0, where=used[:, None], initial=-inf) + 0.0
    # the largest power of two not above the largest |coordinate| (0.5 for 0), as
    # `repair._piece_scales` finds it: dividing by it is exact
    _, exponent = math.frexp(float(max(np.abs(lo).max(), np.abs(hi).max())))
    scale = math.ldexp(1.0, exponent - 1)
    total = 0.0
    for start in range(0, faces.shape[0], _AREA_BLOCK):
        blk = faces[start : start + _AREA_BLOCK]
        # corners over the scale (exact), edges q = B − A and s = C − A, in place (rows
        # gathered by np.take, which copies whole rows at once)
        p = np.take(vertices, blk[:, 0], axis=0)
        p /= scale
        q = np.take(vertices, blk[:, 1], axis=0)
        q /= scale
        q -= p
        s = np.take(vertices, blk[:, 2], axis=0)
        s /= scale
        s -= p
        # |N|² = n0² + n1² + n2², each n_i a difference of two products, added in this order
        n = q[:, 1] * s[:, 2]
        n -= q[:, 2] * s[:, 1]
        n *= n
        t = q[:, 2] * s[:, 0]
        t -= q[:, 0] * s[:, 2]
        t *= t
        n += t
        t = q[:, 0] * s[:, 1]
        t -= q[:, 1] * s[:, 0]
        t *= t
        n += t
        np.sqrt(n, out=n)  # twice each face's area, over scale²
        n[0] += total  # cumsum adds one term after the other: the sum in face order
        total = float(np.cumsum(n, out=n)[-1])
    size = Size(
        (float(lo[0]), float(lo[1]), float(lo[2])), (float(hi[0]), float(hi[1]), float(hi[2]))
    )
    return Measures(surface_area=total * 0.5 * scale * scale, size=size)


def _holes(rims: _Rims) -> tuple[int, ...]:
    """Count the edges around each hole; the counts largest first.

    A hole is a set of boundary edges joined end to end: the loops of `_Rims`, and
    loops that touch at one vertex count as one hole, of one piece or of two.
    """
    if rims.half_edges.size == 0:
        return ()
    # a piece's loops already meet at their shared vertices; join those of different pieces
    by_vertex = np.argsort(rims.node_vertex, kind="stable")
    vertex = rims.node_vertex[by_vertex]
    shared = np.flatnonzero(vertex[1:] == vertex[:-1])
    n_loops = int(rims.loop.max()) + 1
    hole = _components(n_loops, rims.loop[by_vertex[shared]], rims.loop[by_vertex[shared + 1]])
    counts = np.bincount(hole[rims.loop[rims.start]])
    return tuple(sorted((int(c) for c in counts if c), reverse=True))


@dataclass(frozen=True)
class PrintReport:
    """The report for printing (see the module text); `print_report` makes it.

    Attributes
    ----------
    holes : tuple of int
        The number of edges around each hole, largest first.
    surface_area : float
        The area of all faces, in the file's units squared.
    volume : float or None
        The volume the closed, consistently wound pieces enclose together, as wound now
        (an inside-out piece counts negative); None when no piece is such.
    piece_volumes : tuple of (float or None)
        Each piece's enclosed volume (``ComponentReport.volume``).
    size : Size or None
        The bounding box; None when there are no faces.
    verdict : str
        One line: ready for a slicer, or what stands in the way.
    """

    holes: tuple[int, ...]
    surface_area: float
    volume: float | None
    piece_volumes: tuple[float | None, ...]
    size: Size | None
    verdict: str

    def to_dict(self) -> dict[str, Any]:
        """Return the keys ``holes``, ``surface_area``, ``volume``, ``size`` and ``verdict``."""
        return {
            "holes": list(self.holes),
            "surface_area": self.surface_area,
            "volume": self.volume,
            "size": None if self.size is None else self.size.to_dict(),
            "verdict": self.verdict,
        }

    def lines(self) -> list[str]:
        """Return the printing lines of the summary: holes, size, area and volume, verdict."""
        out = []
        if self.holes:
            listed = ", ".join(str(h) for h in self.holes[:LISTED])
            edges = _counted(self.holes[0], "edge") if len(self.holes) == 1 else listed
            if len(self.holes) > LISTED:
                edges += ", …"
            out.append(_say("holes", n=len(self.holes), edges=edges))
        if self.size is not None:
            out += self.size.lines()
        out.append(self._area_volume())
        out.append(_say("verdict_line", verdict=self.verdict))
        return out

    def _area_volume(self) -> str:
        area = shown(self.surface_area)
        if self.volume is None:
            return _say("area_no_volume", area=area)
        if len(self.piece_volumes) == 1:
            return _say("area_volume", area=area, volume=shown(self.volume))
        measured = [(i, v) for i, v in enumerate(self.piece_volumes) if v is not None]
        parts = [_say("piece_volume", i=i + 1, volume=shown(v)) for i, v in measured[:LISTED]]
        if len(measured) > LISTED:
            parts.append("…")
        if len(measured) < len(self.piece_volumes):
            parts.append(_say("others_none"))
        return _say("area_volumes", area=area, volume=shown(self.volume), pieces=", ".join(parts))


def _counted(n: int, noun: str) -> str:
    """``n`` and the noun, as the summary writes counts ("1 edge", "3 pieces")."""
    from trinormal.mesh.report import _n  # the report imports this module: imported here

    return _n(n, noun)


def _winding(r: MeshReport) -> str:
    """Return the verdict's word on the winding.

    An open piece judged over its holes counts as a closed one does; a sheet, which has no
    outside, leaves "wound consistently".
    """
    pieces = r.components
    if not all(c.orientable for c in pieces):
        return "one_sided"
    if not r.consistent_winding:
        return "inconsistent"
    if any(c.outward is False for c in pieces):
        return "inside_out"
    if any(c.closed and c.outward is None for c in pieces):
        return "no_volume"
    if r.closed or (pieces and all(c.outward for c in pieces)):
        return "wound_outward"
    return "wound_consistently"


def _verdict(r: MeshReport) -> str:
    pieces = r.components
    closed_consistent = [c for c in pieces if c.closed and c.consistent]
    winding = _winding(r)
    if r.ok:
        conclusion = _say("ready")
    else:
        found = (
            ("obstacle_holes", len(r.holes)),
            ("obstacle_fins", len(r.non_manifold_edges)),
            ("obstacle_pinches", len(r.non_manifold_vertices)),
            ("obstacle_degenerate", len(r.degenerate_faces)),
            ("obstacle_duplicates", len(r.duplicate_faces) + len(r.reversed_duplicate_faces)),
            ("obstacle_unused", len(r.unused_vertices)),
            ("obstacle_one_sided", sum(not c.orientable for c in pieces)),
            ("obstacle_no_volume", sum(c.outward is None for c in closed_consistent)),
            ("obstacle_flips", len(r.faces_to_flip)),
        )
        obstacles = [_say(key, n=n) for key, n in found if n]
        if r.n_faces == 0:
            obstacles.insert(0, _say("no_faces"))
        conclusion = _say("not_ready", obstacles=", ".join(obstacles))
    return _say(
        "verdict",
        closure=_say("watertight" if r.closed else "not_watertight"),
        pieces=_counted(len(pieces), "piece"),
        winding=_say(winding),
        conclusion=conclusion,
    )


def print_report(r: MeshReport) -> PrintReport:
    """Make the report for printing of a mesh `trinormal.mesh.check` has checked.

    Examples
    --------
    >>> from trinormal.mesh import check, cube
    >>> v, f = cube()
    >>> p = print_report(check(v, f))
    >>> p.holes, p.surface_area, p.volume, p.verdict
    ((), 24.0, 8.0, 'watertight, 1 piece, wound outward: ready for a slicer')
    >>> print_report(check(v * 0.01, f[:-2])).to_dict()["verdict"]
    'not watertight, 1 piece, wound outward: not ready for a slicer (1 hole)'
    >>> print_report(check(v * 0.01, f[:-2, ::-1])).to_dict()["verdict"]
    'not watertight, 1 piece, inside out: not ready for a slicer (1 hole, 10 faces to turn over)'
    """
    volumes = tuple(c.volume for c in r.components)
    known = [v for v in volumes if v is not None]  # added in piece order
    return PrintReport(
        holes=r.holes,
        surface_area=r.measures.surface_area,
        volume=reduce(add, known) if known else None,
        piece_volumes=volumes,
        size=r.measures.size,
        verdict=_verdict(r),
    )


def printing_constants() -> dict[str, Any]:
    """Return the templates and limits the site's JavaScript reads (``TRINORMAL_CONSTANTS.mesh``).

    Examples
    --------
    >>> sorted(printing_constants())
    ['listed', 'sci_above', 'significant', 'templates', 'units']
    """
    return {
        "templates": {k: list(t) if isinstance(t, tuple) else t for k, t in PRINTING.items()},
        "units": dict(UNITS),
        "significant": SIGNIFICANT,
        "listed": LISTED,
        "sci_above": 10.0**SCI_ABOVE_LOG10,  # where `shown` writes m·10^e, as format_number does
    }
