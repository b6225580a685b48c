"""One surface per position: which vertices the checks treat as one corner.

Exporters write one point several times: along a texture seam an OBJ or PLY lists
a vertex once for each side, a triangle soup lists every corner of every face, and
a CAD tessellation computes the corners two faces share once for each face, so they
differ in the last bits. Faces that meet there share no vertex *index*, and a check
that joins faces by index alone sees holes, and pieces, that are not in the model.

So the topology of `trinormal.mesh.check` and `trinormal.mesh.fix_winding` (edges,
boundary, pieces, winding, shells) is computed on *welded* faces, where every
vertex is replaced by its representative:

* vertices at exactly the same position are one corner, always (-0.0 is 0.0);
* corners on a boundary (an edge only one face walks) closer than a weld distance
  to another such corner are one corner too. The distance is `WELD_AUTO` times the
  model's size unless a larger one is asked for (``weld=``). Closer than means no
  farther apart than the distance along each of x, y and z.

A representative is the smallest index of its group, so every index the report
gives is one of the file's own, and the faces written back are the file's.

Near misses are reported, not merged: boundary corners whose nearest other
boundary corner lies within `WELD_NEAR` times the model's size. The report says how
many boundary edges would close if they were merged, and the distance to ask for.

Examples
--------
Two triangles of a square, each with its own copies of the shared corners:

>>> import numpy as np
>>> v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 0, 0], [1, 1, 0], [0, 1, 0.0]])
>>> f = np.array([[0, 1, 2], [3, 4, 5]])
>>> w = weld(v, f)
>>> w.faces
array([[0, 1, 2],
       [0, 2, 5]])
>>> w.merged
2
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from trinormal.mesh._arrays import _MIX, FloatArray, IntArray, _grouped
from trinormal.mesh.topology import _components, _HalfEdges

__all__ = ["WELD_AUTO", "WELD_MAX", "WELD_NEAR", "Weld", "model_size", "weld"]

#: Corners closer than this times the model's size are merged without asking. Float noise
#: is far below it: rounding a coordinate to float64 moves it by 1.1e-16 of its size, and
#: the few hundred operations of an export's transforms stay below 1e-13; the issue's
#: contract asks for 1e-12 of the size and below to merge, and a diagonal of three such
#: errors is 1.7e-12. A real gap is far above it: CAD kernels treat points closer than
#: 1e-8 m as one point (Parasolid's resolution), which is 1e-10 of a 100 m model, and no
#: printer resolves a thousandth of that.
WELD_AUTO: float = 1e-10

#: Boundary corners closer than this times the model's size to another boundary corner are
#: reported as a near miss: an export that did not weld its vertices (coordinates rounded
#: to 6 digits, or to float32, land within 1e-6 of the size of each other).
WELD_NEAR: float = 1e-4

#: The largest weld distance that may be asked for, times the model's size: merging
#: farther apart closes real holes and collapses small faces.
WELD_MAX: float = 1e-2


@dataclass(frozen=True)
class Weld:
    """The welded faces of a mesh and how they came about.

    Attributes
    ----------
    faces : ndarray of int, shape (F, 3)
        The faces with every vertex replaced by its representative (the smallest index
        of the corners merged with it); the file's faces when nothing was merged.
    merged : int
        How many vertices were replaced by another at exactly their position.
    welded : int
        How many other vertices were replaced by a boundary corner within the distance.
    distance : float
        The weld distance: boundary corners no farther apart along each axis are one.
    size : float
        The model's size (`model_size`).
    half_edges : _HalfEdges
        The edges of the welded faces.
    near_edges : int
        Boundary edges that would close if boundary corners closer than
        ``near_distance`` were merged (0: no near miss).
    near_distance : float or None
        The distance to weld at to close them: 1, 2 or 5 times a power of ten.
    exact : ndarray of int, shape (V,), or None
        Each vertex's smallest index at exactly its position; None when no two vertices
        share a position.
    """

    faces: IntArray
    merged: int
    welded: int
    distance: float
    size: float
    half_edges: _HalfEdges = field(repr=False)
    near_edges: int = 0
    near_distance: float | None = None
    exact: IntArray | None = field(default=None, repr=False)


def model_size(v: FloatArray, f: IntArray) -> float:
    """Return the longest side of the bounding box of the vertices the faces use (0.0: none).

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> model_size(*cube())
    2.0
    """
    if f.size == 0:
        return 0.0
    used = np.zeros(v.shape[0], dtype=bool)
    used[f.ravel()] = True
    p = v[used]
    return float((p.max(axis=0) - p.min(axis=0)).max())


def _exact_representatives(v: FloatArray) -> IntArray | None:
    """Each vertex's smallest index at exactly its position; None when every position is unique.

    Equal rows are found by their bit patterns (`_grouped`), ``-0.0`` written ``0.0``.
    """
    n = v.shape[0]
    if n < 2:
        return None
    order, same = _grouped(np.ascontiguousarray(v + 0.0).view(np.uint64))
    if not same.any():
        return None
    # each group is sorted by index: its first row is its smallest index
    start = np.arange(n)
    start[1:][same] = 0
    np.maximum.accumulate(start, out=start)
    rep = np.empty(n, dtype=np.intp)
    rep[order] = order[start]
    return rep


def _close_pairs(p: FloatArray, dist: float) -> tuple[IntArray, IntArray, FloatArray]:
    """Pairs ``i < j`` of rows of ``p`` no farther apart than ``dist`` along each axis.

    Returns the two row numbers and their distance (the largest of |dx|, |dy|, |dz|).
    Rows are put in cells of side 2 · dist; only rows in neighbouring cells are compared.
    """
    empty = np.empty(0, dtype=np.intp)
    if p.shape[0] < 2 or not dist > 0:
        return empty, empty, np.empty(0)
    cell = np.floor((p - p.min(axis=0)) / (2.0 * dist)).astype(np.int64)
    key = _cell_hash(cell)
    order = np.argsort(key, kind="stable")
    sorted_key = key[order]
    found_i, found_j = [], []
    for step in itertools.product((-1, 0, 1), repeat=3):
        k = _cell_hash(cell + np.array(step, dtype=np.int64))
        lo = np.searchsorted(sorted_key, k, "left")
        hi = np.searchsorted(sorted_key, k, "right")
        count = hi - lo
        if not count.any():
            continue
        i = np.repeat(np.arange(p.shape[0]), count)
        offsets = np.repeat(lo - np.cumsum(np.append(0, count[:-1])), count)
        j = order[np.arange(i.size) + offsets]
        # j's cell is i's moved by the step (not another cell of the same hash)
        keep = (i < j) & (cell[j] == cell[i] + step).all(axis=1)
        found_i.append(i[keep])
        found_j.append(j[keep])
    if not found_i:
        return empty, empty, np.empty(0)
    i, j = np.concatenate(found_i), np.concatenate(found_j)
    d = np.abs(p[i] - p[j]).max(axis=1)
    near = d <= dist
    return i[near].astype(np.intp), j[near].astype(np.intp), d[near]


def _cell_hash(cell: IntArray) -> Any:
    c = cell.astype(np.uint64)
    out = c[:, 0] * np.uint64(_MIX[0])
    out ^= c[:, 1] * np.uint64(_MIX[1])
    out ^= c[:, 2] * np.uint64(_MIX[2])
    return out


def _boundary_vertices(he: _HalfEdges) -> IntArray:
    out: IntArray = np.unique(np.concatenate([he.start(he.boundary), he.end(he.boundary)]))
    return out


def _merge_close(
    v: FloatArray, rep: IntArray, he: _HalfEdges, dist: float
) -> tuple[IntArray, bool]:
    """Merge the boundary corners of ``he`` within ``dist`` of each other (single linkage)."""
    b = _boundary_vertices(he)
    i, j, _ = _close_pairs(v[b], dist)
    if not i.size:
        return rep, False
    label = _components(b.size, i, j)
    smallest = np.full(int(label.max()) + 1, v.shape[0], dtype=np.intp)
    np.minimum.at(smallest, label, b)
    to = np.arange(v.shape[0], dtype=np.intp)
    to[b] = smallest[label]
    return to[rep], True


def round_distance(x: float, above: bool = True) -> tuple[float, str]:
    """Return the smallest of 1, 2 and 5 times a power of ten above ``x`` > 0, and its text.

    With ``above=False``, the smallest at or above ``x``. The value is read from the
    text (``float("2e-6")``), so the page's ``parseFloat`` reads the same number.

    Examples
    --------
    >>> round_distance(1.3e-6), round_distance(2e-6), round_distance(2e-6, above=False)
    ((2e-06, '2e-6'), (5e-06, '5e-6'), (2e-06, '2e-6'))
    >>> round_distance(150.0)
    (200.0, '200')
    """
    k = math.floor(math.log10(x)) - 1
    while True:
        for m in (1, 2, 5):
            text = str(m * 10**k) if 0 <= k <= 3 else f"{m}e{k}"
            d = float(text)
            if d > x or (d == x and not above):
                return d, text
        k += 1


def weld(vertices: FloatArray, faces: IntArray, distance: float | bool = False) -> Weld:
    """Weld a checked mesh: ``vertices`` (V, 3) float64 and ``faces`` (F, 3) int.

    Parameters
    ----------
    vertices, faces : ndarray
        The mesh, already checked (``_check_vertices``, ``_check_faces``).
    distance : float or bool, default False
        False: merge at `WELD_AUTO` times the model's size. A number: merge boundary
        corners no farther apart than it (never less than the automatic distance; 0,
        only corners at exactly one position).
        True: merge at the distance the near miss suggests, when there is one.

    Returns
    -------
    Weld
        The welded faces, and the near miss found beyond the weld distance.

    Raises
    ------
    ValueError
        A distance that is negative, not finite, or above `WELD_MAX` times the size.

    Examples
    --------
    A ball as a soup of faces, every other corner moved 2e-6 along x: a near miss.

    >>> from trinormal.mesh import icosphere
    >>> v, f = icosphere(1)
    >>> corners = v[f].reshape(-1, 3) + np.tile([[2e-6, 0, 0], [0, 0, 0]], (120, 1))
    >>> soup = np.arange(len(corners)).reshape(-1, 3)
    >>> w = weld(corners, soup)
    >>> w.merged, w.welded, w.near_edges, w.near_distance
    (156, 0, 200, 5e-06)
    >>> w = weld(corners, soup, True)
    >>> w.welded, w.distance, w.near_edges
    (42, 5e-06, 0)
    """
    v, f = vertices, faces
    size = model_size(v, f)
    auto = WELD_AUTO * size
    dist = auto
    if distance is not True and distance is not False:
        asked = float(distance)
        if not math.isfinite(asked) or asked < 0:
            raise ValueError(f"the weld distance must be a number >= 0, not {distance!r}")
        if asked > WELD_MAX * size:
            raise ValueError(
                f"the weld distance {asked!r} is more than {WELD_MAX!r} times the model's size "
                f"({size!r}): merging corners that far apart closes real holes"
            )
        dist = max(asked, auto) if asked > 0 else 0.0
    exact = _exact_representatives(v)
    rep = np.arange(v.shape[0], dtype=np.intp) if exact is None else exact
    wf = f if exact is None else rep[f]
    he = _HalfEdges.of(wf)
    if he.boundary.size and dist > 0:
        rep, changed = _merge_close(v, rep, he, dist)
        if changed:
            wf = rep[f]
            he = _HalfEdges.of(wf)
    near_edges, near_dist = 0, None
    near_range = WELD_NEAR * size
    if he.boundary.size and near_range > dist:
        b = _boundary_vertices(he)
        i, j, d = _close_pairs(v[b], near_range)
        if i.size:
            nearest = np.full(b.size, np.inf)
            np.minimum.at(nearest, i, d)
            np.minimum.at(nearest, j, d)
            suggest, _ = round_distance(float(nearest[np.isfinite(nearest)].max()))
            rep2, _ = _merge_close(v, rep, he, suggest)
            he2 = _HalfEdges.of(rep2[f])
            closed = he.boundary.size - he2.boundary.size
            if closed > 0:
                near_edges, near_dist = closed, suggest
                if distance is True:
                    rep, wf, dist, he = rep2, he2.faces, suggest, he2
                    near_edges, near_dist = 0, None
    merged = 0 if exact is None else int(np.count_nonzero(exact != np.arange(v.shape[0])))
    welded = int(np.count_nonzero(rep != np.arange(v.shape[0]))) - merged
    return Weld(wf, merged, welded, dist, size, he, near_edges, near_dist, exact)
