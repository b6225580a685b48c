"""How faces fit together: shared edges, their directions, and connected pieces.

Every answer here comes from the faces alone (which vertex indices each face
uses, in which order), never from coordinates. An *edge* is an unordered pair
of vertices that some face walks from one to the other; a face ``(i, j, k)``
walks ``i → j``, ``j → k`` and ``k → i``.

* A *boundary* edge is walked by one face only: the rim of a hole or of an
  open sheet.
* A *non-manifold* edge is shared by three faces or more: no surface can
  have a fin like that.
* A *non-manifold* vertex is where pieces of surface meet at a single point
  (two cones touching at their tips): its faces fall into more than one fan.
* In a *consistently wound* piece, every edge shared by two faces is walked
  once each way.

Every public function here takes one argument, ``faces``: an array_like of
int, shape (F, 3), each row the three vertex indices of a triangle in winding
order. A face that uses one vertex twice, like ``(4, 4, 7)``, has no edges in
this sense (it is a degenerate face, reported by `trinormal.mesh.check`):
every function here leaves it out.

Examples
--------
Two triangles glued along the edge 0–2, then a third face on that edge:

>>> boundary_edges([[0, 1, 2], [0, 2, 3]])
array([[0, 1],
       [1, 2],
       [2, 3],
       [3, 0]])
>>> non_manifold_edges([[0, 1, 2], [0, 2, 3], [0, 2, 4]])
array([[0, 2]])
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import BoolArray, IntArray, _check_faces, _packed_sort

__all__ = [
    "boundary_edges",
    "connected_components",
    "consistent_winding",
    "duplicate_faces",
    "inconsistent_edges",
    "non_manifold_edges",
    "non_manifold_vertices",
]


def _components(n: int, a: IntArray, b: IntArray) -> IntArray:
    """Label the connected pieces of the graph on nodes ``0..n-1`` with edges ``a[i]–b[i]``.

    Labels are 0, 1, 2, … in the order of each piece's smallest node (`_roots`).
    """
    root = _roots(n, a, b)
    is_root = root == np.arange(n)
    out: IntArray = (np.cumsum(is_root) - 1)[root].astype(np.intp)
    return out


def _roots(n: int, a: IntArray, b: IntArray) -> npt.NDArray[Any]:
    """Return each node's root, the smallest node of its piece (int32 when n < 2**31).

    Pure numpy, in rounds: every root is hooked to the smallest root it touches;
    the roots just hooked follow their chains (each step halves them), and then
    every node, which pointed at a root, takes that root's root; edges inside one
    piece are dropped. A handful of rounds on a mesh.
    """
    # node numbers in 4 bytes when they fit: half the memory, the same roots
    node = np.int32 if n < 2**31 else np.intp
    parent = np.arange(n, dtype=node)
    # each edge as the roots of its two ends (at first every node is its own): an edge
    # between two roots joins what the edge between their members joins
    ra = np.asarray(a).astype(node, copy=False)
    rb = np.asarray(b).astype(node, copy=False)
    hooked_mask = np.zeros(n, dtype=bool)
    while ra.size:
        differ = ra != rb
        if not differ.all():
            if not differ.any():
                break
            ra, rb = ra[differ], rb[differ]
        high = np.maximum(ra, rb)
        np.minimum.at(parent, high, np.minimum(ra, rb))  # labels only decrease: no cycles
        hooked_mask[high] = True
        hooked = np.flatnonzero(hooked_mask)
        hooked_mask[hooked] = False
        top = parent[hooked]
        while True:
            up = parent[top]
            if np.array_equal(up, top):
                break
            parent[hooked] = top = up
        parent = parent[parent]
        ra, rb = parent[ra], parent[rb]
    return parent


def _distinct_corners(f: IntArray) -> BoolArray:
    """Which faces have three distinct vertices (the others have no edges)."""
    out: BoolArray = (f[:, 0] != f[:, 1]) & (f[:, 1] != f[:, 2]) & (f[:, 2] != f[:, 0])
    return out


def _next_corner(h: IntArray) -> IntArray:
    """Return the next corner of the same face: half-edge ``h`` arrives at its vertex."""
    # h + 1, less 3 where h + 1 starts the next face: there (h + 1) // 3 is one more than
    # h // 3 (a division by a constant, not a remainder and a masked update)
    up = h + 1
    out: IntArray = up - 3 * (up // 3 - h // 3)
    return out


@dataclass(frozen=True)
class _HalfEdges:
    """Every edge walk of every face with three distinct vertices, grouped by edge.

    Half-edge ``h`` belongs to face ``h // 3`` and runs from corner ``h % 3``
    to the next corner. ``order`` lists the half-edges sorted by their
    unordered edge; ``starts`` and ``counts`` delimit each edge's group in it.
    """

    faces: IntArray
    clean: BoolArray
    order: IntArray
    starts: IntArray
    counts: IntArray

    @classmethod
    def of(cls, faces: IntArray) -> _HalfEdges:
        f = faces
        clean = _distinct_corners(f)
        h = np.flatnonzero(np.repeat(clean, 3))
        a = f.ravel()[h]
        b = f[:, [1, 2, 0]].ravel()[h]
        lo, hi = np.minimum(a, b), np.maximum(a, b)
        del a, b
        nv = int(hi.max()) + 1 if hi.size else 0
        new = np.ones(h.size, dtype=bool)
        # one number per edge, unless it would overflow: then sort on both columns
        if nv < 2**31:
            key = lo * nv + hi
            del lo, hi
            # the key and the index in one number when they fit (the order of an edge's
            # walks does not matter: ties are by index there, in any order here)
            done = _packed_sort(key, nv * nv)
            if done is None:
                order = np.argsort(key)
                key = key[order]
            else:
                order, key = done
            if order.size:
                np.not_equal(key[1:], key[:-1], out=new[1:])
            del key
        else:
            order = np.lexsort((hi, lo))
            lo_s, hi_s = lo[order], hi[order]
            if order.size:
                new[1:] = (lo_s[1:] != lo_s[:-1]) | (hi_s[1:] != hi_s[:-1])
        # half-edge numbers in 4 bytes when they fit: every array of them is half the size
        half: Any = np.int32 if f.size < 2**31 else np.intp
        starts = np.flatnonzero(new).astype(half)
        counts = np.diff(np.append(starts, order.size)).astype(half)
        return cls(f, clean, h[order].astype(half), starts, counts)

    def start(self, h: IntArray) -> IntArray:
        """Return the vertex each half-edge leaves from."""
        out: IntArray = self.faces.ravel()[h]
        return out

    def end(self, h: IntArray) -> IntArray:
        """Return the vertex each half-edge arrives at."""
        out: IntArray = self.faces.ravel()[_next_corner(h)]
        return out

    def undirected(self, h: IntArray) -> IntArray:
        """Return the edges of half-edges ``h`` as (smaller, larger) vertex pairs, shape (k, 2)."""
        a, b = self.start(h), self.end(h)
        out: IntArray = np.stack([np.minimum(a, b), np.maximum(a, b)], axis=1).reshape(-1, 2)
        return out

    @cached_property
    def boundary(self) -> IntArray:
        """The half-edges of the edges one face walks (the boundary), in edge order."""
        out: IntArray = self.order[self.starts[self.counts == 1]]
        return out

    @cached_property
    def manifold_pairs(self) -> tuple[IntArray, IntArray]:
        """The two half-edges of every edge shared by exactly two faces."""
        g = self.starts[self.counts == 2]
        return self.order[g], self.order[g + 1]

    @cached_property
    def shared_pairs(self) -> tuple[IntArray, IntArray]:
        """Neighbouring half-edges of every edge shared by two faces or more: each and the next."""
        groups = np.flatnonzero(self.counts >= 2)
        first, size = self.starts[groups], self.counts[groups]
        # position of every half-edge but the last in its group, and its successor
        offsets = np.repeat(first - np.cumsum(np.append(0, size[:-1] - 1)), size - 1)
        pos = np.arange(offsets.size) + offsets
        return self.order[pos], self.order[pos + 1]

    @cached_property
    def face_components(self) -> IntArray:
        """Pieces of faces joined through shared edges; faces left out get -1."""
        nf = self.faces.shape[0]
        h1, h2 = self.shared_pairs
        label = np.full(nf, -1, dtype=np.intp)
        kept = np.flatnonzero(self.clean)
        index = np.full(nf, -1, dtype=np.intp)  # the kept faces numbered 0, 1, 2, …
        index[kept] = np.arange(kept.size)
        label[kept] = _components(kept.size, index[h1 // 3], index[h2 // 3])
        return label


@dataclass(frozen=True)
class _Rims:
    """The rims of the holes: the boundary half-edges joined end to end, piece by piece.

    ``half_edges`` (B,) are the boundary half-edges in increasing order, ``piece`` (B,)
    their pieces. The rims' corners, one per piece and vertex, ordered by piece then
    vertex, are ``node_piece`` and ``node_vertex`` (N,); ``start`` (B,) is the corner
    each half-edge leaves from, and ``loop`` (N,) each corner's loop: the rim edges of
    one piece that join end to end (`trinormal.mesh.shells` caps each loop,
    `trinormal.mesh.printing` counts the holes).
    """

    half_edges: IntArray
    piece: IntArray
    start: IntArray
    node_piece: IntArray
    node_vertex: IntArray
    loop: IntArray


def _rims(he: _HalfEdges) -> _Rims:
    """Join the boundary half-edges of ``he`` into loops, piece by piece (`_Rims`)."""
    h = np.sort(he.boundary.astype(np.intp))
    piece = he.face_components[h // 3]
    a, b = he.start(h), he.end(h)
    nv = int(max(a.max(), b.max())) + 1 if h.size else 1
    key = piece.astype(np.int64) * nv
    nodes, inv = np.unique(np.concatenate([key + a, key + b]), return_inverse=True)
    loop = _components(nodes.size, inv[: h.size], inv[h.size :])
    return _Rims(h, piece, inv[: h.size], nodes // nv, nodes % nv, loop)


def _half_edges(faces: npt.ArrayLike) -> _HalfEdges:
    return _HalfEdges.of(_check_faces(faces, None))


def boundary_edges(faces: npt.ArrayLike) -> IntArray:
    """Edges walked by one face only: the rims of holes and of open sheets.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles; the winding of the one face on an edge sets its direction.

    Returns
    -------
    ndarray of int, shape (B, 2)
        Each boundary edge as ``(from, to)``, sorted by those two vertices;
        empty for a closed surface.

    Examples
    --------
    >>> boundary_edges([[0, 1, 2]])
    array([[0, 1],
           [1, 2],
           [2, 0]])
    >>> from trinormal.mesh import cube
    >>> boundary_edges(cube()[1]).shape
    (0, 2)
    """
    return _boundary_edges(_half_edges(faces))


def _boundary_edges(he: _HalfEdges) -> IntArray:
    a, b = he.start(he.boundary), he.end(he.boundary)
    order = np.lexsort((b, a))
    out: IntArray = np.stack([a[order], b[order]], axis=1).reshape(-1, 2)
    return out


def non_manifold_edges(faces: npt.ArrayLike) -> IntArray:
    """Edges shared by three faces or more.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles, wound either way: only how many faces share an edge counts.

    Returns
    -------
    ndarray of int, shape (E, 2)
        Each such edge once, as ``(smaller, larger)`` vertex index, sorted.

    Examples
    --------
    Three pages of a book share its spine, the edge 0–1:

    >>> non_manifold_edges([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    array([[0, 1]])
    """
    return _non_manifold_edges(_half_edges(faces))


def _non_manifold_edges(he: _HalfEdges) -> IntArray:
    return he.undirected(he.order[he.starts[he.counts >= 3]])


def _fans(he: _HalfEdges) -> IntArray:
    """Return the vertex of each fan: a vertex with two fans or more is listed as often."""
    h1, h2 = he.shared_pairs
    # the two faces meet at both ends a and b of the edge h1 walks: join their corners there.
    # h1's corner at a is its own, at b the next; h2's are the same if it walks a → b too,
    # swapped if it walks b → a
    along = he.start(h2) == he.start(h1)
    next1, next2 = _next_corner(h1), _next_corner(h2)
    root = _roots(
        he.faces.size,
        np.concatenate([h1, next1]),
        np.concatenate([np.where(along, h2, next2), np.where(along, next2, h2)]),
    )
    del along, next1, next2
    # a fan lies around one vertex and has one root, its smallest corner; the corners of
    # a face that uses a vertex twice are in no fan
    is_root = root == np.arange(root.size)
    is_root &= np.repeat(he.clean, 3)
    out: IntArray = he.faces.ravel()[is_root]
    return out


def non_manifold_vertices(faces: npt.ArrayLike) -> IntArray:
    """Vertices where separate fans of faces meet at a single point.

    Around an ordinary vertex the faces form one fan: each joined to the next
    through an edge at that vertex. Two cones touching tip to tip, or two
    cubes sharing one corner, meet at a vertex with two fans.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles. Winding does not matter.

    Returns
    -------
    ndarray of int, shape (k,)
        The pinch points: vertex indices with two fans or more, in increasing order.

    Examples
    --------
    Two triangles that touch only at vertex 0 (a bow tie):

    >>> non_manifold_vertices([[0, 1, 2], [0, 3, 4]])
    array([0])
    >>> non_manifold_vertices([[0, 1, 2], [0, 2, 3]])
    array([], dtype=int64)
    """
    return _non_manifold_vertices(_half_edges(faces))


def _non_manifold_vertices(he: _HalfEdges) -> IntArray:
    # sorted, not counted in an array as long as the largest index: indices may be huge
    fan_vertex = np.sort(_fans(he))
    twice = fan_vertex[1:][fan_vertex[1:] == fan_vertex[:-1]]
    return np.unique(twice).astype(np.intp)


def connected_components(faces: npt.ArrayLike) -> IntArray:
    """Which piece each face belongs to: faces are in one piece when edges join them.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles; two faces sharing an edge are in one piece however each is wound.

    Returns
    -------
    ndarray of int, shape (F,)
        Piece numbers 0, 1, 2, … in the order of each piece's first face; -1
        for a face that uses one vertex twice (it has no edges to join by).

    Examples
    --------
    Two separate triangles, and a third glued to the first:

    >>> connected_components([[0, 1, 2], [3, 4, 5], [0, 2, 6]])
    array([0, 1, 0])
    """
    return _half_edges(faces).face_components


def duplicate_faces(faces: npt.ArrayLike) -> tuple[IntArray, IntArray]:
    """Faces that repeat an earlier face's three vertices.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles, compared as sets of three vertices (and then by winding).

    Returns
    -------
    same : ndarray of int
        Faces that repeat an earlier face wound the same way (``(1, 2, 0)``
        repeats ``(0, 1, 2)``).
    reversed : ndarray of int
        Faces that repeat an earlier face only wound the other way
        (``(0, 2, 1)`` after ``(0, 1, 2)``): together they are a sheet with
        no inside, whose normals cancel.

    Notes
    -----
    Every face after the first with its three vertices is in exactly one of
    the two lists. Faces that use a vertex twice are left out.

    Examples
    --------
    >>> duplicate_faces([[0, 1, 2], [1, 2, 0], [0, 2, 1], [2, 3, 4]])
    (array([1]), array([2]))
    """
    f = _check_faces(faces, None)
    return _duplicates(f)


def _duplicates(f: IntArray) -> tuple[IntArray, IntArray]:
    clean = np.flatnonzero(_distinct_corners(f))
    fc = np.take(f, clean, axis=0)
    a, b, c = fc[:, 0], fc[:, 1], fc[:, 2]
    even = ((a < b).astype(np.int8) + (b < c) + (c < a)) == 2
    # the three vertices in increasing order: s0 <= s1 <= s2
    s0, s2 = np.minimum(a, b), np.maximum(a, b)
    s1 = np.maximum(s0, np.minimum(s2, c))
    np.minimum(s0, c, out=s0)
    np.maximum(s2, c, out=s2)
    del fc, a, b, c
    top = int(s2.max()) + 1 if s2.size else 0
    same_key = np.zeros(clean.size, dtype=bool)
    same_side = np.zeros(clean.size, dtype=bool)
    if top <= 2**20:  # the three vertices and the winding packed in one 61-bit key
        key = ((s0 * top + s1) * top + s2) * 2 + even
        del s0, s1, s2
        order = np.argsort(key, kind="stable")  # stable: file order within a key
        key = key[order]
        np.equal(key[1:] >> 1, key[:-1] >> 1, out=same_key[1:])
        np.equal(key[1:], key[:-1], out=same_side[1:])
        del key
    else:
        order = np.lexsort((clean, even, s2, s1, s0))
        s0, s1, s2, even = s0[order], s1[order], s2[order], even[order]
        same_key[1:] = (s0[1:] == s0[:-1]) & (s1[1:] == s1[:-1]) & (s2[1:] == s2[:-1])
        same_side[1:] = same_key[1:] & (even[1:] == even[:-1])
    idx = clean[order]
    same = np.sort(idx[same_side])
    # the first face of its winding is reversed when the group began earlier (other winding)
    key_start = np.flatnonzero(~same_key)
    key_id = np.cumsum(~same_key) - 1
    group_first = np.minimum.reduceat(idx, key_start) if idx.size else idx
    lead = ~same_side & (idx > group_first[key_id])
    reversed_ = np.sort(idx[lead])
    return same.astype(np.intp), reversed_.astype(np.intp)


def inconsistent_edges(faces: npt.ArrayLike) -> IntArray:
    """Directed edges that appear in two faces running the same way.

    In a consistently wound mesh every interior edge is walked once in each
    direction, by the two faces that share it. An edge walked the same way
    twice means one of those faces is flipped.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles in winding order: face ``(i, j, k)`` walks ``i → j``.

    Returns
    -------
    ndarray of int, shape (E, 2)
        Every directed edge ``(i, j)`` that two faces or more walk, once each;
        rows sorted.

    Examples
    --------
    >>> inconsistent_edges([[0, 1, 2], [0, 2, 3]])
    array([], shape=(0, 2), dtype=int64)
    >>> inconsistent_edges([[0, 1, 2], [0, 3, 2]])
    array([[2, 0]])
    """
    f = _check_faces(faces, None)
    # directed edges as (start, end) rows, compared as rows: no packing into one integer,
    # which would wrap around for indices above 2**31
    edges = np.stack([f.ravel(), f[:, [1, 2, 0]].ravel()], axis=1)
    rows, count = np.unique(edges, axis=0, return_counts=True)
    dup: IntArray = rows[count >= 2]
    return dup


def consistent_winding(faces: npt.ArrayLike) -> bool:
    """Whether every edge shared by two faces runs opposite ways in them.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        The triangles, as in `inconsistent_edges`.

    Returns
    -------
    bool
        True when no directed edge appears twice (see
        [`inconsistent_edges`][trinormal.mesh.inconsistent_edges]).

    Examples
    --------
    Two triangles sharing the edge 0–2, wound the same way round, then one flipped:

    >>> consistent_winding([[0, 1, 2], [0, 2, 3]])
    True
    >>> consistent_winding([[0, 1, 2], [0, 3, 2]])
    False
    """
    return bool(inconsistent_edges(faces).shape[0] == 0)
