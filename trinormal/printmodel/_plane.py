"""Plane geometry for the printable model: distances, crossings and ear-clipping triangulation.

Plain float arithmetic in a fixed order of operations, so that the site's port
(``trinormal-printmodel.js``) computes the same numbers bit for bit.
"""

from __future__ import annotations

import math

Point = tuple[float, float]
Ring = list[Point]


def orient(p: Point, q: Point, r: Point) -> float:
    """Twice the signed area of p, q, r: positive when they turn counter-clockwise."""
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def dist(p: Point, q: Point) -> float:
    return math.sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]))


def point_segment(p: Point, a: Point, b: Point) -> float:
    """Measure the distance from p to the segment ab."""
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2
    t = min(1.0, max(0.0, t))
    return dist(p, (a[0] + t * dx, a[1] + t * dy))


def segments_meet(p1: Point, p2: Point, q1: Point, q2: Point) -> bool:
    """Whether the segments p1p2 and q1q2 cross or touch."""
    d1 = orient(q1, q2, p1)
    d2 = orient(q1, q2, p2)
    d3 = orient(p1, p2, q1)
    d4 = orient(p1, p2, q2)
    if ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)) and (
        (d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)
    ):
        return True
    return (
        (d1 == 0 and point_segment(p1, q1, q2) == 0)
        or (d2 == 0 and point_segment(p2, q1, q2) == 0)
        or (d3 == 0 and point_segment(q1, p1, p2) == 0)
        or (d4 == 0 and point_segment(q2, p1, p2) == 0)
    )


def segment_segment(p1: Point, p2: Point, q1: Point, q2: Point) -> float:
    """Measure the distance between the segments p1p2 and q1q2 (0 when they meet)."""
    if segments_meet(p1, p2, q1, q2):
        return 0.0
    return min(
        point_segment(p1, q1, q2),
        point_segment(p2, q1, q2),
        point_segment(q1, p1, p2),
        point_segment(q2, p1, p2),
    )


# --------------------------------------------------------------------------- triangulation


def bridge(
    pts: list[Point], poly: list[int], hole: list[int], others: list[list[int]]
) -> list[int]:
    """Join ``hole`` to ``poly`` by a two-way cut from the hole's rightmost vertex.

    The cut goes to the nearest vertex of ``poly`` it can reach without meeting
    an edge of ``poly``, of ``hole`` or of the holes still to join
    (``others``); vertices already at the end of a cut are passed over, so each
    vertex of ``poly`` sits in one corner of the polygon.
    """
    m_at = max(range(len(hole)), key=lambda i: pts[hole[i]][0])  # the first of the rightmost
    m = hole[m_at]
    rings = [poly, hole, *others]
    edges = [(r[i], r[(i + 1) % len(r)]) for r in rings for i in range(len(r))]
    order = sorted(range(len(poly)), key=lambda k: (dist(pts[poly[k]], pts[m]), k))
    for k in order:
        p = poly[k]
        if poly.count(p) > 1:
            continue
        if all(
            p in e or m in e or not segments_meet(pts[m], pts[p], pts[e[0]], pts[e[1]])
            for e in edges
        ):
            loop = hole[m_at:] + hole[: m_at + 1]
            return poly[: k + 1] + loop + poly[k:]
    raise RuntimeError("no vertex of the polygon can be joined to a hole")  # pragma: no cover


def triangulate(outer: Ring, holes: list[Ring]) -> tuple[list[Point], list[tuple[int, int, int]]]:
    """Cover ``outer`` (counter-clockwise) minus ``holes`` (clockwise) with triangles.

    Ear clipping: the holes are joined to the outline by cuts (`bridge`), then
    the first corner that is convex and holds no other vertex is cut off, until
    one triangle is left. Returns the points (outline, then each hole) and
    triangles of indices into them.
    """
    pts = list(outer)
    rings = []
    for hole in holes:
        rings.append(list(range(len(pts), len(pts) + len(hole))))
        pts += hole
    poly = list(range(len(outer)))
    rings.sort(key=lambda r: (-max(pts[i][0] for i in r), r[0]))
    for n in range(len(rings)):
        poly = bridge(pts, poly, rings[n], rings[n + 1 :])
    triangles = []
    while len(poly) > 3:
        for i in range(len(poly)):
            a, b, c = poly[i - 1], poly[i], poly[(i + 1) % len(poly)]
            if orient(pts[a], pts[b], pts[c]) <= 0:
                continue
            if any(
                q not in (a, b, c)
                and orient(pts[a], pts[b], pts[q]) >= 0
                and orient(pts[b], pts[c], pts[q]) >= 0
                and orient(pts[c], pts[a], pts[q]) >= 0
                for q in poly
            ):
                continue
            triangles.append((a, b, c))
            del poly[i]
            break
        else:
            raise RuntimeError("no ear to cut: the polygon is not simple")  # pragma: no cover
    triangles.append((poly[0], poly[1], poly[2]))
    return pts, triangles
