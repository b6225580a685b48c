"""The printable model's features: their sizes, where they stand, and the surface they make.

`fitted` places the arrow, the ridges and the marks on the plate, shrinking them
step by step (`FITS`) for a thin triangle; `smallest_size` finds the size to name
when even the smallest do not fit; `solid` builds the one closed surface.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

from trinormal.printmodel._plane import (
    Point,
    Ring,
    dist,
    orient,
    segment_segment,
    triangulate,
)

DEFAULT_SIZE = 80.0
#: The smallest and the largest size accepted, in millimetres.
SIZE_RANGE = (50.0, 1000.0)
#: How A, B and C can be marked.
MARKS = ("letters", "braille")
#: The name of the file the explorer's "Download for 3D printing" buttons save.
DOWNLOAD_NAME = "triangle-{marks}.stl"
#: The plate's thickness, mm.
THICKNESS = 3.0

# The features, in millimetres. Braille follows the usual sizes for paper braille
# (dots about 1.5 mm across and 2.5 mm apart), printed a little taller.
MARGIN = 2.5  # from the plate's edges to a mark or a ridge's side
GAP = 1.5  # between features, as they are placed
MIN_GAP = 1.0  # between features, as checked: closer than this is refused
RIDGE_WIDTH = 2.0
RIDGE_HEIGHT = 1.2
RIDGE_TIP = 4.0  # the length of a ridge's point; its base is twice the ridge's width
SHAFT_RADIUS = 1.75
HEAD_RADIUS = 4.0
HEAD_LENGTH = 9.0
ARROW_LENGTH = 0.4  # times the size
LETTER_HEIGHT = 0.8
DOT_RADIUS = (0.75, 0.45)  # the dot's radius at the plate and at its top
DOT_HEIGHT = 0.6
DOT_SPACING = 2.5
GRID = 1024.0  # coordinates are multiples of 1/GRID mm

#: A mark's reach from its centre (letters are 5 × 7 mm, braille two dots by two).
MARK_RADIUS = {"letters": 4.4, "braille": 2.6}

#: How far the features may shrink to fit a thin triangle, tried in order until one fits:
#: (letters' scale, margin, gap, smallest gap, length of a ridge's point, ridge's width).
#: Braille keeps its standard cell; letters go down to 4 mm tall; the margins, gaps and
#: ridges stay printable with a 0.4 mm nozzle. The last entry also sizes `on_tabs`.
FITS = (
    (1.0, MARGIN, GAP, MIN_GAP, RIDGE_TIP, RIDGE_WIDTH),
    (0.8, 2.0, 1.2, 0.8, 3.0, RIDGE_WIDTH),
    (4 / 7, 1.6, 0.8, 0.6, 2.5, 1.2),
)

# Block letters, 5 × 7 mm, centred: an outline (counter-clockwise) and its holes (clockwise).
LETTERS: dict[str, tuple[tuple[tuple[float, float], ...], ...]] = {
    "A": (
        ((0, 0), (1.4, 0), (1.4, 2.6), (3.6, 2.6), (3.6, 0), (5, 0), (5, 5.6), (3.6, 7),
         (1.4, 7), (0, 5.6)),
        ((1.4, 4.0), (1.4, 5.4), (3.6, 5.4), (3.6, 4.0)),
    ),
    "B": (
        ((0, 0), (4.2, 0), (5, 0.8), (5, 2.8), (4.4, 3.5), (5, 4.2), (5, 6.2), (4.2, 7),
         (0, 7)),
        ((1.4, 1.4), (1.4, 2.8), (3.6, 2.8), (3.6, 1.4)),
        ((1.4, 4.2), (1.4, 5.6), (3.6, 5.6), (3.6, 4.2)),
    ),
    "C": (
        ((0, 0), (5, 0), (5, 1.4), (1.4, 1.4), (1.4, 5.6), (5, 5.6), (5, 7), (0, 7)),
    ),
}  # fmt: skip

#: Braille dots of each letter as (column, row) in the cell: dot 1 is (0, 0), 2 (0, 1), 4 (1, 0).
BRAILLE = {"A": ((0, 0),), "B": ((0, 0), (0, 1)), "C": ((0, 0), (1, 0))}

#: What the model generator says when it refuses, one sentence each (the site shows the same).
PRINT_MESSAGES: dict[str, str] = {
    "degenerate": "A degenerate triangle cannot be printed: its corners lie on one line "
    "(|N| ≤ tol · L²), so it has no face to stand on and no normal to show. "
    "Move a corner off the line.",
    "too_thin": "This triangle is too thin to print at {size} mm: {reason}. "
    "Print it at {fits} mm or larger (--size {fits}), or make it less thin.",
    "too_thin_always": "This triangle is too thin to print even at {size} mm: {reason}. "
    "Make it less thin.",
    "marks": "the marks at its corners do not fit inside it",
    "ridge": "the ridge {name} is too short to show",
    "touch": "{first} and {second} would touch",
    "arrow": "the arrow",
    "mark": "the mark at {name}",
    "ridge_name": "the ridge {name}",
    "edge": "an edge",
    "title": "trinormal: the triangle {order} with its normal",
    "downloaded": "Downloaded {name}: the triangle with its normal, ready for a slicer.",
    "size": "size must be a number of millimetres from {low} to {high}, got {got}",
    "marks_kind": "marks must be 'letters' or 'braille', got {got}",
    "format": "{path}: write the model to a file ending in .stl or .3mf",
}

OCTAGON = (
    (1.0, 0.0),
    (math.sqrt(0.5), math.sqrt(0.5)),
    (0.0, 1.0),
    (-math.sqrt(0.5), math.sqrt(0.5)),
    (-1.0, 0.0),
    (-math.sqrt(0.5), -math.sqrt(0.5)),
    (0.0, -1.0),
    (math.sqrt(0.5), -math.sqrt(0.5)),
)


class PrintModelError(ValueError):
    """A triangle (or a size) the model cannot be made of; the message says why."""

    __module__ = "trinormal.printmodel"  # where it is imported from


def _num(x: float) -> str:
    """Write ``x`` in the fewest digits that read back, no trailing ``.0`` (as JavaScript does)."""
    text = repr(x + 0.0)  # + 0.0: never "-0"
    return text[:-2] if text.endswith(".0") else text


def _snap(x: float) -> float:
    """Put ``x`` on the model's grid: the nearest multiple of 1/1024 mm (halves round up)."""
    return math.floor(x * GRID + 0.5) / GRID


# --------------------------------------------------------------------------- the solid


class Builder:
    """Vertices, numbered once each by their exact coordinates, and faces."""

    def __init__(self) -> None:
        self.index: dict[tuple[float, float, float], int] = {}
        self.vertices: list[tuple[float, float, float]] = []
        self.faces: list[tuple[int, int, int]] = []

    def vertex(self, p: Point, z: float) -> int:
        key = (p[0], p[1], z)
        if key not in self.index:
            self.index[key] = len(self.vertices)
            self.vertices.append(key)
        return self.index[key]

    def face(self, a: int, b: int, c: int) -> None:
        self.faces.append((a, b, c))

    def flat(self, outer: Ring, holes: list[Ring], z: float, up: bool = True) -> None:
        """Add the region ``outer`` minus ``holes`` at height z, facing up (or down)."""
        pts, triangles = triangulate(outer, holes)
        ids = [self.vertex(p, z) for p in pts]
        for a, b, c in triangles:
            if up:
                self.face(ids[a], ids[b], ids[c])
            else:
                self.face(ids[a], ids[c], ids[b])

    def band(self, lower: Ring, z0: float, upper: Ring, z1: float) -> None:
        """Add the strip from ring ``lower`` at z0 to ring ``upper`` at z1, facing right of them.

        A ring going counter-clockwise seen from above gets walls facing out of it.
        """
        n = len(lower)
        for i in range(n):
            j = (i + 1) % n
            p0, q0 = self.vertex(lower[i], z0), self.vertex(lower[j], z0)
            p1, q1 = self.vertex(upper[i], z1), self.vertex(upper[j], z1)
            self.face(p0, q0, q1)
            self.face(p0, q1, p1)

    def cone(self, ring: Ring, z: float, tip: tuple[float, float, float]) -> None:
        """Triangles from each edge of ``ring`` at z to ``tip``, facing out."""
        t = self.vertex((tip[0], tip[1]), tip[2])
        for i in range(len(ring)):
            self.face(self.vertex(ring[i], z), self.vertex(ring[(i + 1) % len(ring)], z), t)

    def prism(self, outer: Ring, holes: list[Ring], z0: float, z1: float) -> None:
        """Add a raised shape standing on the plate: walls, top, and its holes' floors at z0."""
        self.band(outer, z0, outer, z1)
        for hole in holes:
            self.band(hole, z0, hole, z1)
            self.flat(hole[::-1], [], z0)
        self.flat(outer, holes, z1)


def _ring(center: Point, radius: float) -> Ring:
    return [(_snap(center[0] + radius * x), _snap(center[1] + radius * y)) for x, y in OCTAGON]


def _shifted(points: tuple[tuple[float, float], ...], center: Point, scale: float) -> Ring:
    """Give a letter's ring, scaled by ``scale`` about its middle, centred on ``center``."""
    return [
        (_snap(center[0] + (x - 2.5) * scale), _snap(center[1] + (y - 3.5) * scale))
        for x, y in points
    ]


# --------------------------------------------------------------------------- the layout


Fit = tuple[float, float, float, float, float, float]


@dataclass(frozen=True)
class Layout:
    corners: tuple[Point, Point, Point]  # in the winding's order, first at the origin
    centroid: Point
    marks: tuple[Point, ...]  # the centre of each corner's mark
    ridges: tuple[tuple[Point, Point, Point], ...]  # (start, base of the point, tip) of U and V
    fit: Fit  # the entry of FITS the features were placed with
    outline: Ring  # the plate: the corners, and any tabs that carry the marks outside them


class Unfit(Exception):
    """The features do not fit at this size with this entry of `FITS`; the message says why."""


def flat_corners(u: Any, v: Any, size: float) -> tuple[Point, Point, Point]:
    """Lay the triangle with edges u and v from its first corner flat, scaled to ``size``.

    The first corner goes to the origin, the second (first + u) onto +x and the
    third above it, so the three turn counter-clockwise. u and v are first
    divided by their largest component, so no square overflows or underflows.
    """
    big = max(abs(x) for x in (*u, *v))
    u = [x / big for x in u]
    v = [x / big for x in v]
    w = [v[i] - u[i] for i in range(3)]
    lu = math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
    lv = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    lw = math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    scale = size / max(lu, lv, lw)
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    ln = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
    along = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / lu
    return (0.0, 0.0), (_snap(lu * scale), 0.0), (_snap(along * scale), _snap(ln / lu * scale))


def _inset(p: Point, center: Point, r: float, d: float) -> Point:
    """Move the corner p in by d from each side: towards the incentre."""
    k = (r - d) / r
    return (center[0] + (p[0] - center[0]) * k, center[1] + (p[1] - center[1]) * k)


def _unit(start: Point, end: Point) -> Point:
    length = dist(start, end)
    return ((end[0] - start[0]) / length, (end[1] - start[1]) / length)


def _ridge(start: Point, end: Point, sep: float, obstacles: list[tuple[Point, float, float]]
           ) -> list[float]:  # fmt: skip
    """Where a ridge from ``start`` towards ``end`` begins and ends, clear of ``obstacles``.

    Each obstacle is (centre, side, reach): side 1 moves the ridge's start past it,
    side -1 stops the ridge short of it (unless it lies behind the start). Returns
    the distances along the line where the ridge begins and ends, and its direction.
    """
    length = dist(start, end)
    e = _unit(start, end)
    t0, t1 = sep, length
    for m, side, reach in obstacles:
        along = (m[0] - start[0]) * e[0] + (m[1] - start[1]) * e[1]
        off = abs((m[0] - start[0]) * e[1] - (m[1] - start[1]) * e[0])
        if off < reach:
            cut = along + side * math.sqrt(reach * reach - off * off)
            if side > 0:
                t0 = max(t0, cut)
            elif cut > t0:
                t1 = min(t1, cut)
    return [t0, t1, e[0], e[1]]


def layout(
    corners: tuple[Point, Point, Point],
    marks: str,
    names: str,
    fit: Fit,
    tabs: tuple[tuple[Point, ...], Ring] | None = None,
) -> Layout:
    """Where each feature stands with the sizes ``fit``; raises `Unfit` when they do not fit.

    ``tabs``, from `on_tabs`, gives the marks' places outside the triangle and the
    plate's outline with their tabs; without it the marks stand inside, near the corners.
    """
    scale, margin, gap, min_gap, tip, width = fit
    p = corners
    sides = [dist(p[1], p[2]), dist(p[2], p[0]), dist(p[0], p[1])]
    perimeter = sides[0] + sides[1] + sides[2]
    r = orient(p[0], p[1], p[2]) / perimeter  # the inradius: twice the area over the perimeter
    center = (
        (sides[0] * p[0][0] + sides[1] * p[1][0] + sides[2] * p[2][0]) / perimeter,
        (sides[0] * p[0][1] + sides[1] * p[1][1] + sides[2] * p[2][1]) / perimeter,
    )
    radius = MARK_RADIUS[marks] * scale if marks == "letters" else MARK_RADIUS[marks]
    if r <= (margin + width / 2 if tabs else margin + radius) + min_gap:
        raise Unfit(PRINT_MESSAGES["marks"])
    spots = tabs[0] if tabs else tuple(_inset(q, center, r, margin + radius) for q in p)
    line = [_inset(q, center, r, margin + width / 2) for q in p]
    centroid = ((p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3)
    eu = _unit(line[0], line[1])
    ev = _unit(line[0], line[2])
    cos_a = eu[0] * ev[0] + eu[1] * ev[1]
    # the two ridges leave A's corner apart by their width and a gap
    sep = (width + gap) / (2 * math.sqrt((1 - cos_a) / 2))
    out: list[tuple[Point, Point, Point]] = []
    for k, name in ((1, "U"), (2, "V")):
        # clear of the first mark by half the ridge's width, of the last mark and of the
        # arrow by its point's half-width; marks on tabs stand clear of every ridge
        marks_near = [(spots[0], 1.0, radius + gap + width / 2),
                      (spots[k], -1.0, radius + gap + width)]  # fmt: skip
        arrow = (centroid, -1.0, SHAFT_RADIUS + gap + width)
        t0, t1, ex, ey = _ridge(line[0], line[k], sep, [*([] if tabs else marks_near), arrow])
        if t1 - t0 < tip + width:
            raise Unfit(PRINT_MESSAGES["ridge"].format(name=name))
        s = line[0]
        out.append(
            (
                (s[0] + ex * t0, s[1] + ey * t0),
                (s[0] + ex * (t1 - tip), s[1] + ey * (t1 - tip)),
                (s[0] + ex * t1, s[1] + ey * t1),
            )
        )
    plan = Layout(p, centroid, spots, tuple(out), fit, tabs[1] if tabs else list(p))
    _check_clearance(plan, radius, min_gap, names)
    return plan


def _check_clearance(plan: Layout, radius: float, min_gap: float, names: str) -> None:
    """Raise `Unfit` where two features come closer than ``min_gap``, or reach an edge."""
    words = PRINT_MESSAGES
    parts: list[tuple[str, Point, Point, float]] = [
        (words["arrow"], plan.centroid, plan.centroid, SHAFT_RADIUS)
    ]
    for name, spot in zip(names, plan.marks, strict=True):
        if len(plan.outline) == 3:  # marks inside the triangle, not on tabs
            parts.append((words["mark"].format(name=name), spot, spot, radius))
    width = plan.fit[5]
    for name, (s, base, tip) in zip("UV", plan.ridges, strict=True):
        parts.append((words["ridge_name"].format(name=name), s, base, width / 2))
        parts.append((words["ridge_name"].format(name=name), base, tip, width))
    for a, b in itertools.combinations(parts, 2):
        if a[0] != b[0] and segment_segment(a[1], a[2], b[1], b[2]) < a[3] + b[3] + min_gap:
            raise Unfit(words["touch"].format(first=a[0], second=b[0]))
    c = plan.corners
    for name, s, e, reach in parts:
        for k in range(3):
            if segment_segment(s, e, c[k], c[(k + 1) % 3]) < reach + min_gap:
                raise Unfit(words["touch"].format(first=name, second=words["edge"]))


def _tab(p: Point, q: Point, start: float, half: float, depth: float) -> Ring:
    """Outline a tab on the outside of the edge p→q (counter-clockwise), from ``start`` along it.

    Returns its four corners in the plate's order: on the edge, out, out, on the edge.
    """
    e = _unit(p, q)
    out = (e[1], -e[0])  # the outward normal of a counter-clockwise edge
    a = (p[0] + e[0] * start, p[1] + e[1] * start)
    b = (a[0] + e[0] * 2 * half, a[1] + e[1] * 2 * half)
    return [
        (_snap(x), _snap(y))
        for x, y in (a, (a[0] + out[0] * depth, a[1] + out[1] * depth),
                     (b[0] + out[0] * depth, b[1] + out[1] * depth), b)
    ]  # fmt: skip


def on_tabs(corners: tuple[Point, Point, Point], marks: str, names: str) -> Layout:
    """Put each mark on a tab outside the triangle, beside its corner; the ridges inside.

    The last resort of `fitted`, for a triangle too thin to hold its marks: each
    corner's tab stands on the longer of its two sides, next to it, the mark at
    its full size in the tab's middle. Raises `Unfit` when tabs or ridges collide.
    """
    _, margin, gap, min_gap, tip, width = FITS[-1]
    p = corners
    radius = MARK_RADIUS[marks]
    half = radius + margin
    depth = gap + 2 * radius + margin
    on_edge: list[list[Ring]] = [[], [], []]  # tabs on the edge from corner k to corner k + 1
    spots: list[Point] = []
    for k in range(3):
        after, before = p[(k + 1) % 3], p[(k + 2) % 3]
        longer = max(dist(p[k], after), dist(before, p[k]))
        if longer < 2 * (gap + half):  # the tab would overrun its side's far end
            raise Unfit(PRINT_MESSAGES["marks"])
        if dist(p[k], after) >= dist(before, p[k]):
            tab = _tab(p[k], after, gap, half, depth)
            on_edge[k].append(tab)
        else:
            tab = _tab(before, p[k], longer - gap - 2 * half, half, depth)
            on_edge[(k + 2) % 3].append(tab)
        spots.append(((tab[0][0] + tab[2][0]) / 2, (tab[0][1] + tab[2][1]) / 2))
    outline: Ring = []
    for k in range(3):
        outline.append(p[k])
        for tab in sorted(on_edge[k], key=lambda t: dist(p[k], t[0])):
            outline += tab
    _check_tabs([t for tabs in on_edge for t in tabs], min_gap)
    return layout(p, marks, names, (1.0, margin, gap, min_gap, tip, width), (tuple(spots), outline))


def _check_tabs(tabs: list[Ring], min_gap: float) -> None:
    """Raise `Unfit` when a tab comes nearer another than ``min_gap``."""
    for a, b in itertools.combinations(tabs, 2):
        for m, n in itertools.product(range(4), repeat=2):
            if segment_segment(a[m], a[(m + 1) % 4], b[n], b[(n + 1) % 4]) < min_gap:
                raise Unfit(PRINT_MESSAGES["marks"])


def fitted(u: Any, v: Any, size: float, marks: str, names: str) -> Layout:
    """Lay the features out at ``size``, the first entry of `FITS` that fits, or raise `Unfit`.

    When none fits inside the triangle, the marks go on tabs beside it (`on_tabs`);
    the `Unfit` raised is that last resort's reason.
    """
    corners = flat_corners(u, v, size)
    for fit in FITS:
        try:
            return layout(corners, marks, names, fit)
        except Unfit:
            continue
    return on_tabs(corners, marks, names)


def _fits(u: Any, v: Any, size: float, marks: str, names: str) -> bool:
    try:
        fitted(u, v, size, marks, names)
    except Unfit:
        return False
    return True


def smallest_size(u: Any, v: Any, size: float, marks: str, names: str) -> float | None:
    """Find the smallest whole size in mm above ``size`` at which the features fit, or None.

    Sizes grow by a quarter (whole millimetres, up to the largest accepted) until one
    fits, then halve the step between the last that did not and the first that did.
    """
    low, high = size, SIZE_RANGE[1]
    while True:
        if low >= high:
            return None
        above = min(high, float(math.floor(low * 1.25) + 1))
        if _fits(u, v, above, marks, names):
            break
        low = above
    low = float(math.floor(low))
    while above - low > 1:  # above fits; low does not (or is the size asked for)
        mid = float(math.floor((low + above) / 2))
        if _fits(u, v, mid, marks, names):
            above = mid
        else:
            low = mid
    return above


# --------------------------------------------------------------------------- the solid, built


def _ridge_outline(start: Point, base: Point, tip: Point, width: float) -> Ring:
    """Outline a ridge counter-clockwise: a strip from ``start``, a point ending at ``tip``."""
    e = _unit(start, tip)
    n = (-e[1], e[0])
    half = width / 2
    ring = [
        (start[0] - n[0] * half, start[1] - n[1] * half),
        (base[0] - n[0] * half, base[1] - n[1] * half),
        (base[0] - n[0] * width, base[1] - n[1] * width),
        tip,
        (base[0] + n[0] * width, base[1] + n[1] * width),
        (base[0] + n[0] * half, base[1] + n[1] * half),
        (start[0] + n[0] * half, start[1] + n[1] * half),
    ]
    return [(_snap(x), _snap(y)) for x, y in ring]


def solid(plan: Layout, size: float, marks: str, names: str) -> Builder:
    """Build the model as one surface: plate, arrow, ridges, marks, every face wound outward."""
    top = THICKNESS
    out = Builder()
    plate: Ring = plan.outline
    shaft = _ring(plan.centroid, SHAFT_RADIUS)
    footprints = [shaft]
    raised: list[tuple[Ring, list[Ring], float]] = []
    for s, base, tip in plan.ridges:
        outline = _ridge_outline(s, base, tip, plan.fit[5])
        footprints.append(outline)
        raised.append((outline, [], _snap(top + RIDGE_HEIGHT)))
    dots: list[tuple[Ring, Ring]] = []
    for name, spot in zip(names, plan.marks, strict=True):
        if marks == "letters":
            rings = LETTERS[name]
            outline = _shifted(rings[0], spot, plan.fit[0])
            footprints.append(outline)
            holes = [_shifted(h, spot, plan.fit[0]) for h in rings[1:]]
            raised.append((outline, holes, _snap(top + LETTER_HEIGHT)))
            continue
        for col, row in BRAILLE[name]:
            center = (spot[0] + (col - 0.5) * DOT_SPACING, spot[1] + (0.5 - row) * DOT_SPACING)
            dots.append((_ring(center, DOT_RADIUS[0]), _ring(center, DOT_RADIUS[1])))
            footprints.append(dots[-1][0])

    out.flat(plate, [], 0.0, up=False)
    out.band(plate, 0.0, plate, top)
    out.flat(plate, [f[::-1] for f in footprints], top)

    length = ARROW_LENGTH * size
    neck = _snap(top + length - HEAD_LENGTH)
    head = _ring(plan.centroid, HEAD_RADIUS)
    out.band(shaft, top, shaft, neck)
    out.band(shaft, neck, head, neck)  # the head's underside, facing down
    out.cone(head, neck, (_snap(plan.centroid[0]), _snap(plan.centroid[1]), _snap(top + length)))
    for outline, holes, height in raised:
        out.prism(outline, holes, top, height)
    for lower, upper in dots:
        out.band(lower, top, upper, _snap(top + DOT_HEIGHT))
        out.flat(upper, [], _snap(top + DOT_HEIGHT))
    return out
