"""Splitting a file's polygons into triangles for the checks: ear clipping in the polygon's plane.

A polygon with n corners becomes n − 2 triangles, wound as stored. Each polygon
is projected onto the coordinate plane its normal (Newell's, the sum over its
edges) is most nearly perpendicular to; dropping a coordinate is exact, so the
projection adds no rounding. Then ears are cut off in order: a corner is an ear
when it turns the polygon's way and no other corner lies inside or on the
triangle it makes with its two neighbours. The search starts at the second
corner and, after each cut, goes on from where it cut, so a convex polygon
``(a, b, c, d, …)`` gives the fan ``(a, b, c), (a, c, d), …`` and a concave
one gives triangles that cover it exactly, none of them flipped or overlapping.

Two kinds of polygon are counted, because no split is right for them:

* **not planar**: its corners lie farther from its plane than `PLANAR_TOL`
  times its longest side, so the split chooses a surface the file does not
  define;
* **self-crossing**: two of its sides that do not meet at a corner cross in
  the plane; ear clipping then stops where no ear is left and the rest is
  split as a fan from its first remaining corner.

A polygon with no area at all (every corner on one line or at one point) is
split as a fan; its triangles are degenerate and the check says so.

The page's JavaScript (``trinormal-mesh-read.js``) splits with the same
arithmetic, operation for operation, so both give the same triangles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from trinormal.mesh._arrays import BoolArray, FloatArray, IntArray
from trinormal.tolerances import PLANAR_TOL

__all__ = ["PLANAR_TOL", "Split", "split_polygon", "split_polygons"]


@dataclass(frozen=True)
class Split:
    """Polygons split into triangles.

    Attributes
    ----------
    faces : ndarray of int, shape (F, 3)
        The triangles, polygon after polygon, each polygon's in the order they were cut.
    source : ndarray of int, shape (F,)
        The polygon each triangle comes from.
    nonplanar : ndarray of bool, shape (P,)
        Which polygons are not planar (`PLANAR_TOL`).
    crossing : ndarray of bool, shape (P,)
        Which polygons cross themselves.
    """

    faces: IntArray
    source: IntArray
    nonplanar: BoolArray
    crossing: BoolArray


def split_polygon(
    points: list[tuple[float, float, float]],
) -> tuple[list[tuple[int, int, int]], bool, bool]:
    """Split one polygon by ear clipping in its plane.

    Parameters
    ----------
    points : list of (x, y, z)
        The polygon's corners in order, three or more.

    Returns
    -------
    triangles : list of (i, j, k)
        n − 2 triangles of corner positions (0 to n − 1), wound as the polygon.
    nonplanar : bool
        Whether the corners lie off one plane (`PLANAR_TOL`).
    crossing : bool
        Whether two sides that do not share a corner cross.

    Examples
    --------
    A convex quad is split as a fan from its first corner; an L-shaped hexagon,
    concave at corner 3, is split without a triangle outside it:

    >>> split_polygon([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    ([(0, 1, 2), (0, 2, 3)], False, False)
    >>> L = [(1, 2, 0), (0, 2, 0), (0, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0)]
    >>> split_polygon(L)[0]  # a fan from corner 0 would leave the L: (0, 2, 3) crosses corner 5
    [(0, 1, 2), (2, 3, 4), (2, 4, 5), (0, 2, 5)]

    A notched pentagon, concave at corner 3, the same way:

    >>> split_polygon([(0, 0, 0), (2, 0, 0), (2, 2, 0), (1, 0.5, 0), (0, 2, 0)])[0]
    [(1, 2, 3), (3, 4, 0), (0, 1, 3)]

    A bow tie crosses itself, and a warped quad is not planar:

    >>> split_polygon([(0, 0, 0), (2, 2, 0), (2, 0, 0), (0, 1, 0)])
    ([(0, 1, 2), (0, 2, 3)], False, True)
    >>> split_polygon([(0, 0, 0), (1, 1, 0), (1, 0, 0), (0, 1, 0)])[2]  # no area at all
    True
    >>> split_polygon([(0, 0, 0), (1, 0, 0), (1, 1, 0.5), (0, 1, 0)])[1]  # a warped quad
    True
    """
    n = len(points)
    fan = [(0, k, k + 1) for k in range(1, n - 1)]
    x0, y0, z0 = points[0]
    d = [(x - x0, y - y0, z - z0) for x, y, z in points]
    m = max(max(abs(a), abs(b), abs(c)) for a, b, c in d)
    if not (m > 0 and math.isfinite(m)):
        return fan, False, False
    q = [(a / m, b / m, c / m) for a, b, c in d]
    nx = ny = nz = 0.0
    for i in range(n):
        a, b = q[i], q[(i + 1) % n]
        nx += (a[1] - b[1]) * (a[2] + b[2])
        ny += (a[2] - b[2]) * (a[0] + b[0])
        nz += (a[0] - b[0]) * (a[1] + b[1])
    if abs(nz) >= abs(nx) and abs(nz) >= abs(ny):
        u, v, s = 0, 1, nz
    elif abs(ny) >= abs(nx):
        u, v, s = 2, 0, ny
    else:
        u, v, s = 1, 2, nx
    if s == 0:  # no area: a fan; it crosses itself if it does in its flattest projection
        spread = [max(p[k] for p in q) - min(p[k] for p in q) for k in range(3)]
        w = min((2, 1, 0), key=lambda k: spread[k])  # the flattest axis; ties: z, then y
        xs = [p[(w + 1) % 3] for p in q]
        ys = [p[(w + 2) % 3] for p in q]
        return fan, False, _crossing(xs, ys)
    sign = 1.0 if s > 0 else -1.0
    nonplanar = _nonplanar(q, nx, ny, nz)
    xs = [p[u] for p in q]
    ys = [p[v] for p in q]
    # a quad whose four corners all turn its way is convex: no side can cross another
    convex = n == 4 and all(
        sign * _orient(xs, ys, (i + 3) % 4, i, (i + 1) % 4) > 0 for i in range(4)
    )
    crossing = not convex and _crossing(xs, ys)
    return _clip(xs, ys, sign), nonplanar, crossing


#: A polygon with more corners than this is searched with numpy arrays, with the same
#: arithmetic in the same order: a loop in Python over a cap of thousands of corners (a
#: finely divided cylinder, a lettering outline) is quadratic in the corners, in Python.
_MANY = 48


def _orient(xs: list[float], ys: list[float], a: int, b: int, c: int) -> float:
    """Twice the signed area of the projected triangle (a, b, c)."""
    return (xs[b] - xs[a]) * (ys[c] - ys[a]) - (ys[b] - ys[a]) * (xs[c] - xs[a])


def _nonplanar(q: list[tuple[float, float, float]], nx: float, ny: float, nz: float) -> bool:
    """Whether the corners spread farther along the normal than `PLANAR_TOL` × the longest side."""
    n = len(q)
    dots = [p[0] * nx + p[1] * ny + p[2] * nz for p in q]
    longest = 0.0
    for i in range(n):
        a, b = q[i], q[(i + 1) % n]
        dx, dy, dz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
        longest = max(longest, dx * dx + dy * dy + dz * dz)
    norm = math.sqrt(nx * nx + ny * ny + nz * nz)
    return max(dots) - min(dots) > PLANAR_TOL * math.sqrt(longest) * norm


def _crossing(xs: list[float], ys: list[float]) -> bool:
    """Whether two sides that share no corner cross properly (each strictly splits the other)."""
    n = len(xs)
    if n > _MANY:
        return _crossing_arrays(np.array(xs), np.array(ys))
    for i in range(n - 2):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # the last side meets the first at corner 0
            a, b, c, d = i, i + 1, j, (j + 1) % n
            o1, o2 = _orient(xs, ys, a, b, c), _orient(xs, ys, a, b, d)
            o3, o4 = _orient(xs, ys, c, d, a), _orient(xs, ys, c, d, b)
            if ((o1 > 0 and o2 < 0) or (o1 < 0 and o2 > 0)) and (
                (o3 > 0 and o4 < 0) or (o3 < 0 and o4 > 0)
            ):
                return True
    return False


def _crossing_arrays(x: FloatArray, y: FloatArray) -> bool:
    """`_crossing` on arrays: each side against every later side that shares no corner."""
    n = x.size
    x_next, y_next = np.roll(x, -1), np.roll(y, -1)  # each side's end
    for i in range(n - 2):
        later = slice(i + 2, n - 1 if i == 0 else n)  # the sides from corner i + 2 on
        xc, yc, xd, yd = x[later], y[later], x_next[later], y_next[later]
        ax, ay, bx, by = x[i], y[i], x[i + 1], y[i + 1]
        o1 = (bx - ax) * (yc - ay) - (by - ay) * (xc - ax)
        o2 = (bx - ax) * (yd - ay) - (by - ay) * (xd - ax)
        ex, ey = xd - xc, yd - yc
        o3 = ex * (ay - yc) - ey * (ax - xc)
        o4 = ex * (by - yc) - ey * (bx - xc)
        split = ((o1 > 0) & (o2 < 0)) | ((o1 < 0) & (o2 > 0))
        if (split & (((o3 > 0) & (o4 < 0)) | ((o3 < 0) & (o4 > 0)))).any():
            return True
    return False


class _Corners:
    """A big polygon's projected corners as arrays: an ear test looks at all of them at once."""

    def __init__(self, xs: list[float], ys: list[float]) -> None:
        self.x, self.y = np.array(xs), np.array(ys)
        self.alive = np.ones(len(xs), dtype=bool)

    def ear(self, sign: float, a: int, b: int, c: int) -> bool:
        """`_is_ear` on arrays, over the corners not yet cut off."""
        x, y = self.x, self.y
        xa, ya, xb, yb, xc, yc = x[a], y[a], x[b], y[b], x[c], y[c]
        if sign * ((xb - xa) * (yc - ya) - (yb - ya) * (xc - xa)) <= 0:
            return False
        near = ((x == xa) & (y == ya)) | ((x == xb) & (y == yb)) | ((x == xc) & (y == yc))
        inside = self.alive & ~near
        inside &= sign * ((xb - xa) * (y - ya) - (yb - ya) * (x - xa)) >= 0
        inside &= sign * ((xc - xb) * (y - yb) - (yc - yb) * (x - xb)) >= 0
        inside &= sign * ((xa - xc) * (y - yc) - (ya - yc) * (x - xc)) >= 0
        return not inside.any()


def _clip(xs: list[float], ys: list[float], sign: float) -> list[tuple[int, int, int]]:
    """Ear clipping of the projected polygon turning the way of ``sign``."""
    rest = list(range(len(xs)))
    big = _Corners(xs, ys) if len(xs) > _MANY else None
    out: list[tuple[int, int, int]] = []
    at = 1
    while len(rest) > 3:
        k = len(rest)
        for t in range(k):
            pos = (at + t) % k
            a, b, c = rest[(pos + k - 1) % k], rest[pos], rest[(pos + 1) % k]
            if big.ear(sign, a, b, c) if big else _is_ear(xs, ys, sign, rest, a, b, c):
                break
        else:  # no ear: the rest crosses itself or has no area; a fan from its first corner
            out += [(rest[0], rest[j], rest[j + 1]) for j in range(1, k - 1)]
            return out
        out.append((a, b, c))
        del rest[pos]
        if big:
            big.alive[b] = False
        at = pos if pos < len(rest) else 0
    out.append((rest[0], rest[1], rest[2]))
    return out


def _is_ear(
    xs: list[float], ys: list[float], sign: float, rest: list[int], a: int, b: int, c: int
) -> bool:
    """Whether corner b turns the polygon's way and no other corner is in or on (a, b, c)."""
    if sign * _orient(xs, ys, a, b, c) <= 0:
        return False
    for p in rest:
        if p in (a, b, c) or any(xs[p] == xs[k] and ys[p] == ys[k] for k in (a, b, c)):
            continue
        if (
            sign * _orient(xs, ys, a, b, p) >= 0
            and sign * _orient(xs, ys, b, c, p) >= 0
            and sign * _orient(xs, ys, c, a, p) >= 0
        ):
            return False
    return True


def split_polygons(vertices: FloatArray, corners: IntArray, sizes: IntArray) -> Split:
    """Split every polygon of a mesh (`split_polygon`), in order.

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
        The coordinates.
    corners : ndarray of int, shape (sum(sizes),)
        The polygons' vertex indices, one polygon after the other.
    sizes : ndarray of int, shape (P,)
        How many corners each polygon has (three or more).

    Returns
    -------
    Split

    Notes
    -----
    Triangles need no work and a quad whose four corners all turn the same way
    (in the projection `split_polygon` uses) is a fan from its first corner:
    both are split with numpy; every other polygon one at a time.

    Examples
    --------
    >>> v = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0.0]])
    >>> s = split_polygons(v, np.array([4, 5, 0, 1, 2, 3]), np.array([6]))
    >>> s.faces.tolist()
    [[4, 5, 0], [0, 1, 2], [0, 2, 3], [4, 0, 3]]
    """
    p = sizes.size
    nonplanar = np.zeros(p, dtype=bool)
    crossing = np.zeros(p, dtype=bool)
    n_tri = sizes - 2
    source = np.repeat(np.arange(p, dtype=np.intp), n_tri)
    start = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.intp)
    row = np.concatenate([[0], np.cumsum(n_tri)[:-1]]).astype(np.intp)  # first triangles
    k = np.arange(source.size) - row[source]  # 0 .. n-3
    first = start[source]
    faces = np.stack([corners[first], corners[first + k + 1], corners[first + k + 2]], axis=1)
    faces = faces.astype(np.intp).reshape(-1, 3)
    if (sizes == 3).all():
        return Split(faces, source, nonplanar, crossing)
    quads = np.flatnonzero(sizes == 4)
    fine = _convex_quads(vertices, corners[start[quads, None] + np.arange(4)])
    alone = sizes != 3
    alone[quads[fine]] = False
    for poly in np.flatnonzero(alone).tolist():
        idx = corners[start[poly] : start[poly] + sizes[poly]]
        tris, nonplanar[poly], crossing[poly] = split_polygon(
            [tuple(c) for c in vertices[idx].tolist()]
        )
        faces[row[poly] : row[poly] + len(tris)] = idx[np.array(tris)]
    return Split(faces, source, nonplanar, crossing)


def _convex_quads(vertices: FloatArray, quads: IntArray) -> BoolArray:
    """Which quads `split_polygon` splits as a fan, planar and not crossing: found with numpy.

    The same arithmetic as `split_polygon`, operation for operation, on every quad at
    once; a quad is fine when its normal is not zero, its corners lie on its plane and
    all four turn its way (then no side crosses another and corner 1 is an ear).
    """
    if quads.shape[0] == 0:
        return np.zeros(0, dtype=bool)
    pts = vertices[quads]  # (Q, 4, 3)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        d = pts - pts[:, :1]
        m = np.abs(d).max(axis=(1, 2))
        q = d / m[:, None, None]
        nx = ny = nz = np.zeros(quads.shape[0])
        for i in range(4):
            a, b = q[:, i], q[:, (i + 1) % 4]
            nx = nx + (a[:, 1] - b[:, 1]) * (a[:, 2] + b[:, 2])
            ny = ny + (a[:, 2] - b[:, 2]) * (a[:, 0] + b[:, 0])
            nz = nz + (a[:, 0] - b[:, 0]) * (a[:, 1] + b[:, 1])
        ax, ay, az = np.abs(nx), np.abs(ny), np.abs(nz)
        on_z = (az >= ax) & (az >= ay)
        on_y = ~on_z & (ay >= ax)
        u = np.where(on_z, 0, np.where(on_y, 2, 1))
        v = np.where(on_z, 1, np.where(on_y, 0, 2))
        s = np.where(on_z, nz, np.where(on_y, ny, nx))
        sign = np.where(s > 0, 1.0, -1.0)
        rows = np.arange(quads.shape[0])[:, None]
        xs = q[rows, np.arange(4), u[:, None]]
        ys = q[rows, np.arange(4), v[:, None]]
        ok = (m > 0) & np.isfinite(m) & (s != 0)
        for i in range(4):
            a, b, c = (i + 3) % 4, i, (i + 1) % 4
            turn = (xs[:, b] - xs[:, a]) * (ys[:, c] - ys[:, a]) - (ys[:, b] - ys[:, a]) * (
                xs[:, c] - xs[:, a]
            )
            ok &= sign * turn > 0
        dots = q[:, :, 0] * nx[:, None] + q[:, :, 1] * ny[:, None] + q[:, :, 2] * nz[:, None]
        e = q[:, [1, 2, 3, 0]] - q
        e *= e
        longest = (e[:, :, 0] + e[:, :, 1] + e[:, :, 2]).max(axis=1)
        norm = np.sqrt(nx * nx + ny * ny + nz * nz)
        spread = dots.max(axis=1) - dots.min(axis=1)
        ok &= ~(spread > PLANAR_TOL * np.sqrt(longest) * norm)
    out: BoolArray = ok
    return out
