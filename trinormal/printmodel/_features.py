"""The printable model's features: their sizes, where they stand, and the surface they make.

`layout` places the arrow, the ridges and the marks on the plate (refusing a
triangle too thin to hold them); `solid` builds the one closed surface.
"""

from __future__ import annotations

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
    "Print it larger or make it less thin.",
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


def _ring(center: Point, radius: float, shape: tuple[Point, ...] = OCTAGON) -> Ring:
    return [(_snap(center[0] + radius * x), _snap(center[1] + radius * y)) for x, y in shape]


def _shifted(points: tuple[tuple[float, float], ...], center: Point) -> Ring:
    return [(_snap(center[0] + x - 2.5), _snap(center[1] + y - 3.5)) for x, y in points]


# --------------------------------------------------------------------------- the layout


@dataclass(frozen=True)
class Layout:
    corners: tuple[Point, Point, Point]  # in the winding's order, first at the origin
    centroid: Point
    marks: tuple[Point, Point, Point]  # the centre of each corner's mark
    ridges: tuple[tuple[Point, Point, Point], ...]  # (start, base of the point, tip) of U and V


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


def _too_thin(size: float, reason: str) -> PrintModelError:
    return PrintModelError(PRINT_MESSAGES["too_thin"].format(size=_num(size), reason=reason))


def _unit(start: Point, end: Point) -> Point:
    length = dist(start, end)
    return ((end[0] - start[0]) / length, (end[1] - start[1]) / length)


def _ridge(
    start: Point, end: Point, marks: tuple[Point, Point], radius: float, sep: float
) -> list[float]:
    """Where a ridge from ``start`` towards ``end`` begins and ends, clear of both corners' marks.

    Returns the distances along the line where it begins and ends, and the line's direction.
    """
    length = dist(start, end)
    e = _unit(start, end)
    ends = []
    # clear of the first mark by half the ridge's width, of the last by its point's half-width
    for m, sign, reach in (
        (marks[0], 1.0, radius + GAP + RIDGE_WIDTH / 2),
        (marks[1], -1.0, radius + GAP + RIDGE_WIDTH),
    ):
        along = (m[0] - start[0]) * e[0] + (m[1] - start[1]) * e[1]
        off = abs((m[0] - start[0]) * e[1] - (m[1] - start[1]) * e[0])
        ends.append(along + sign * math.sqrt(reach * reach - off * off) if off < reach else None)
    t0 = sep if ends[0] is None else max(sep, ends[0])
    t1 = length if ends[1] is None else min(length, ends[1])
    return [t0, t1, e[0], e[1]]


def layout(corners: tuple[Point, Point, Point], size: float, marks: str, names: str) -> Layout:
    """Where each feature stands; refuses a triangle too thin to hold them."""
    p = corners
    sides = [dist(p[1], p[2]), dist(p[2], p[0]), dist(p[0], p[1])]
    perimeter = sides[0] + sides[1] + sides[2]
    r = orient(p[0], p[1], p[2]) / perimeter  # the inradius: twice the area over the perimeter
    center = (
        (sides[0] * p[0][0] + sides[1] * p[1][0] + sides[2] * p[2][0]) / perimeter,
        (sides[0] * p[0][1] + sides[1] * p[1][1] + sides[2] * p[2][1]) / perimeter,
    )
    radius = MARK_RADIUS[marks]
    if r <= MARGIN + radius + MIN_GAP:
        raise _too_thin(size, PRINT_MESSAGES["marks"])
    spots = (
        _inset(p[0], center, r, MARGIN + radius),
        _inset(p[1], center, r, MARGIN + radius),
        _inset(p[2], center, r, MARGIN + radius),
    )
    line = [_inset(q, center, r, MARGIN + RIDGE_WIDTH / 2) for q in p]
    centroid = ((p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3)
    eu = _unit(line[0], line[1])
    ev = _unit(line[0], line[2])
    cos_a = eu[0] * ev[0] + eu[1] * ev[1]
    # the two ridges leave A's corner apart by their width and a gap
    sep = (RIDGE_WIDTH + GAP) / (2 * math.sqrt((1 - cos_a) / 2))
    out: list[tuple[Point, Point, Point]] = []
    for k, name in ((1, "U"), (2, "V")):
        t0, t1, ex, ey = _ridge(line[0], line[k], (spots[0], spots[k]), radius, sep)
        if t1 - t0 < RIDGE_TIP + RIDGE_WIDTH:
            raise _too_thin(size, PRINT_MESSAGES["ridge"].format(name=name))
        s = line[0]
        out.append(
            (
                (s[0] + ex * t0, s[1] + ey * t0),
                (s[0] + ex * (t1 - RIDGE_TIP), s[1] + ey * (t1 - RIDGE_TIP)),
                (s[0] + ex * t1, s[1] + ey * t1),
            )
        )
    plan = Layout(p, centroid, spots, tuple(out))
    _check_clearance(plan, radius, size, names)
    return plan


def _check_clearance(plan: Layout, radius: float, size: float, names: str) -> None:
    """Refuse a layout where two features come closer than the smallest gap, or reach an edge."""
    words = PRINT_MESSAGES
    parts: list[tuple[str, Point, Point, float]] = [
        (words["arrow"], plan.centroid, plan.centroid, SHAFT_RADIUS)
    ]
    for name, spot in zip(names, plan.marks, strict=True):
        parts.append((words["mark"].format(name=name), spot, spot, radius))
    for name, (s, base, tip) in zip("UV", plan.ridges, strict=True):
        parts.append((words["ridge_name"].format(name=name), s, base, RIDGE_WIDTH / 2))
        parts.append((words["ridge_name"].format(name=name), base, tip, RIDGE_WIDTH))
    for i in range(len(parts)):
        for j in range(i + 1, len(parts)):
            a, b = parts[i], parts[j]
            if a[0] != b[0] and segment_segment(a[1], a[2], b[1], b[2]) < a[3] + b[3] + MIN_GAP:
                raise _too_thin(size, PRINT_MESSAGES["touch"].format(first=a[0], second=b[0]))
    c = plan.corners
    for name, s, e, reach in parts:
        for k in range(3):
            if segment_segment(s, e, c[k], c[(k + 1) % 3]) < reach + MIN_GAP:
                raise _too_thin(
                    size, PRINT_MESSAGES["touch"].format(first=name, second=words["edge"])
                )


# --------------------------------------------------------------------------- the solid, built


def _ridge_outline(start: Point, base: Point, tip: Point) -> Ring:
    """Outline a ridge counter-clockwise: a strip from ``start``, a point ending at ``tip``."""
    e = _unit(start, tip)
    n = (-e[1], e[0])
    half = RIDGE_WIDTH / 2
    wide = RIDGE_WIDTH
    ring = [
        (start[0] - n[0] * half, start[1] - n[1] * half),
        (base[0] - n[0] * half, base[1] - n[1] * half),
        (base[0] - n[0] * wide, base[1] - n[1] * wide),
        tip,
        (base[0] + n[0] * wide, base[1] + n[1] * wide),
        (base[0] + n[0] * half, base[1] + n[1] * half),
        (start[0] + n[0] * half, start[1] + n[1] * half),
    ]
    return [(_snap(x), _snap(y)) for x, y in ring]


def solid(plan: Layout, size: float, marks: str, names: str) -> Builder:
    """Build the model as one surface: plate, arrow, ridges, marks, every face wound outward."""
    top = THICKNESS
    out = Builder()
    plate: Ring = list(plan.corners)
    shaft = _ring(plan.centroid, SHAFT_RADIUS)
    footprints = [shaft]
    raised: list[tuple[Ring, list[Ring], float]] = []
    for s, base, tip in plan.ridges:
        outline = _ridge_outline(s, base, tip)
        footprints.append(outline)
        raised.append((outline, [], _snap(top + RIDGE_HEIGHT)))
    dots: list[tuple[Ring, Ring]] = []
    for name, spot in zip(names, plan.marks, strict=True):
        if marks == "letters":
            rings = LETTERS[name]
            outline = _shifted(rings[0], spot)
            footprints.append(outline)
            holes = [_shifted(h, spot) for h in rings[1:]]
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
