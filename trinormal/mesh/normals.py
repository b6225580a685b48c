"""Face normals, degeneracy, areas and vertex normals of whole meshes.

The kernel `_face_rows` computes, block by block, whatever per-face output a
caller asks for: unit normals, the degeneracy verdict, |N| and the interior
angles. Every public function here is one call to it plus a little numpy.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

from trinormal._optional import missing_extra

try:
    import numpy as np
    import numpy.typing as npt
except ModuleNotFoundError as exc:
    raise missing_extra(exc, __name__) from exc

from trinormal.mesh._arrays import (
    BoolArray,
    FloatArray,
    IntArray,
    Weighting,
    _cast,
    _check_tol,
    _prepare,
    _raise_range_error,
)
from trinormal.tolerances import DEFAULT_TOL

__all__ = ["WEIGHTINGS", "degenerate_faces", "face_areas", "face_normals", "vertex_normals"]

#: The vertex-normal weightings `vertex_normals` accepts.
WEIGHTINGS: tuple[str, ...] = ("angle", "area", "uniform")

#: Faces per block on one thread: small enough that the block's temporaries stay in cache.
_BLOCK = 16384
#: Faces per block when threads share a mesh: larger, so the threads hand the interpreter lock
#: to each other less often (between two numpy operations); measured by
#: benchmarks/bench_mesh.py, where 8192 for both made two threads slower than one.
_THREADED_BLOCK = 32768

#: Meshes of at least this many blocks of `_BLOCK` are shared among threads, at most this many.
_THREADED_BLOCKS = 8
_MAX_THREADS = 4

# A row goes to the careful path unless |U|²|V|² < 2**900 (no product can
# overflow) and |N|² > 2**-900 (|N| and the unit normal are full precision).
_HI = 2.0**900
_LO = 2.0**-900

# --------------------------------------------------------------------------- the kernel


class _Block:
    """Scratch arrays for one block of ``n`` faces, reused block after block.

    The edges and the normal are laid out coordinate by coordinate (one
    contiguous row of ``n`` numbers per coordinate), so the arithmetic runs on
    contiguous memory.

    Attributes
    ----------
    offsets : ndarray of int (3 n,)
        Where each corner's x is in the flattened vertices: 3 × its index, face
        by face (A, B, C of the first face, then of the second, …).
    gathered : ndarray (3 n,)
        One coordinate of the block's corners, in the same order: a take at
        ``offsets`` from the flattened vertices, shifted by the coordinate.
    edges : ndarray (2, 3, n)
        ``edges[0, k]``, ``edges[1, k]``: coordinate k of U = B − A and V = C − A.
    normal : ndarray (3, n)
        N = U × V.
    norm : ndarray (n,)
        |N|², then |N|.
    dot : ndarray (n,)
        U · V.
    bound : ndarray (n,)
        |U|²|V|², then tol²|U|²|V|² (the degeneracy bound), then |U|² − U·V.
    temp : ndarray (n,)
        One product at a time (sums of products are added one term at a time).
    in_range, degenerate : ndarray of bool (n,)
        Rows the fast arithmetic handles; rows whose sine is at most tol.
    """

    _LAST = ("normal",)  # 2-D: cut along the last axis
    _ROWS = ("norm", "dot", "bound", "temp", "in_range", "degenerate")

    def __init__(self, n: int) -> None:
        e = np.empty
        self.offsets = e(3 * n, dtype=np.intp)
        self.gathered = e(3 * n)
        self.edges = e((2, 3, n))
        self.normal = e((3, n))
        self.norm, self.dot, self.bound, self.temp = e(n), e(n), e(n), e(n)
        self.in_range, self.degenerate = e(n, dtype=bool), e(n, dtype=bool)

    def view(self, n: int) -> _Block:
        """Return the first ``n`` faces of every scratch array (for the last, shorter block)."""
        out = object.__new__(_Block)
        out.offsets = self.offsets[: 3 * n]
        out.gathered = self.gathered[: 3 * n]
        out.edges = self.edges[:, :, :n]
        for name in self._LAST:
            setattr(out, name, getattr(self, name)[:, :n])
        for name in self._ROWS:
            setattr(out, name, getattr(self, name)[:n])
        return out


def _careful(
    x: FloatArray,
    y: FloatArray,
    z: FloatArray,
    f: IntArray,
    tol2: float,
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, IntArray, BoolArray]:
    """Rows at extreme scales: edges scaled by powers of two before the cross product.

    Returns the edges U', V' (k, 3) scaled by one common power of two and
    |U' × V'| (k,), for the corner angles; the normal
    scaled once more to a largest component in [0.5, 1), N'' (k, 3), with |N''|
    and the exponent ``e`` such that N = N'' · 2**e; and the degeneracy mask.
    """
    i0, i1, i2 = f[:, 0], f[:, 1], f[:, 2]
    a = np.stack([x[i0], y[i0], z[i0]], axis=1)
    b = np.stack([x[i1], y[i1], z[i1]], axis=1)
    c = np.stack([x[i2], y[i2], z[i2]], axis=1)
    with np.errstate(all="ignore"):
        u, v = b - a, c - a
        # differences of coordinates near the float64 limit can overflow: halve first (exact)
        big = ~(np.isfinite(u).all(axis=1) & np.isfinite(v).all(axis=1))
        pre = np.where(big, 2, 0)
        if big.any():
            u[big] = b[big] * 0.25 - a[big] * 0.25
            v[big] = c[big] * 0.25 - a[big] * 0.25
    eu = np.frexp(np.abs(u).max(axis=1))[1]
    ev = np.frexp(np.abs(v).max(axis=1))[1]
    # for the corner angles: both edges scaled alike, so their dot products compare
    common = np.maximum(eu, ev)[:, None]
    uc, vc = np.ldexp(u, -common), np.ldexp(v, -common)
    nc = np.cross(uc, vc)
    nn = np.sqrt(np.einsum("ij,ij->i", nc, nc))
    u = np.ldexp(u, -eu[:, None])
    v = np.ldexp(v, -ev[:, None])
    n = np.cross(u, v)
    uu = np.einsum("ij,ij->i", u, u)
    vv = np.einsum("ij,ij->i", v, v)
    en = np.frexp(np.abs(n).max(axis=1))[1]
    ns = np.ldexp(n, -en[:, None])
    mag = np.sqrt(np.einsum("ij,ij->i", ns, ns))
    # the sine test on the scaled edges: |N'|² <= tol² |U'|² |V'|² (exact scale invariance)
    deg = np.einsum("ij,ij->i", n, n) <= tol2 * uu * vv
    deg |= mag == 0.0
    exp = (eu + ev + en + 2 * pre).astype(np.intp)
    return uc, vc, nn, ns, mag, exp, deg


def _normalize_rows(s: FloatArray) -> FloatArray:
    """Return the unit rows of ``s`` (n, 3), scaled by a power of two first; zero rows stay zero."""
    e = np.frexp(np.abs(s).max(axis=1))[1]
    s = np.ldexp(s, -e[:, None])
    r = np.sqrt(np.einsum("ij,ij->i", s, s))
    r[r == 0.0] = 1.0
    out: FloatArray = s / r[:, None]
    return out


def _plan(n: int) -> tuple[int, int]:
    """Return the block size and the number of threads for ``n`` faces."""
    workers = _workers(len(range(0, n, _BLOCK)))
    return (_THREADED_BLOCK if workers > 1 else _BLOCK), workers


def _workers(n_blocks: int) -> int:
    """How many threads share the blocks: numpy releases the GIL inside each operation."""
    if n_blocks < _THREADED_BLOCKS:
        return 1
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, _MAX_THREADS, n_blocks // 2))


@dataclass
class _Outputs:
    """Where `_face_rows` writes: any of the four per-face results (None: not wanted)."""

    unit: FloatArray | None
    degenerate: BoolArray | None
    magnitude: FloatArray | None
    angles: FloatArray | None


def _dot(x: FloatArray, y: FloatArray, out: FloatArray, temp: FloatArray) -> None:
    """Write x · y of (3, n) rows into ``out``, summed x, y, z in turn (``temp``: scratch)."""
    np.multiply(x[0], y[0], out=out)
    for k in (1, 2):
        np.multiply(x[k], y[k], out=temp)
        np.add(out, temp, out=out)


def _clear_block(edges: FloatArray, ss: FloatArray, tol2: float) -> bool:
    """Whether no face of a block can be degenerate or out of the fast path's range.

    Every |U|²|V|² of the block is at most ``bound``, the product of the sums
    of squares of the edges' largest components (times 1 + 2**-20, far more
    than the rounding of any |N|² + (U·V)² computed from them). So when the
    smallest |N|² exceeds tol² times ``bound``, each face passes the sine test
    ``|N|² > tol² |U|²|V|²`` that `_face_block` would apply row by row (the
    same verdict, without U·V), and every row is within [_LO, _HI].
    """
    with np.errstate(all="ignore"):
        top = np.maximum(edges.max(axis=2), -edges.min(axis=2))  # (2, 3): largest |U_k|, |V_k|
        su, sv = (top * top).sum(axis=1)
        bound = su * sv * (1.0 + 2.0**-20)
        low = ss.min()
    return bool(min(su, sv) > _LO and bound < _HI and low > _LO and low > tol2 * bound)


def _face_block(
    w: _Block, flat: FloatArray, f: IntArray, s: int, e: int, tol2: float, out: _Outputs
) -> IntArray | None:
    """Compute faces ``s`` to ``e`` into ``out``; return the rows the careful path must redo."""
    nv = flat.size // 3
    mul, sub, add = np.multiply, np.subtract, np.add
    unit_out, deg_out, mag_out, angles_out = out.unit, out.degenerate, out.magnitude, out.angles
    with np.errstate(all="ignore"):
        index = f[s:e].reshape(-1)  # the faces' own memory: A, B, C of each face in turn
        # one test for both ends: a negative index, read as unsigned, is beyond any count
        if index.view(np.uintp).max() >= nv:
            _raise_range_error(f, nv)
        # short local names for the block's arrays (see _Block): the kernel reads as formulas
        g, n, ss = w.gathered, w.normal, w.norm
        d, q, t = w.dot, w.bound, w.temp
        u, v = w.edges
        corner = g.reshape(-1, 3)  # corner[i, c]: this coordinate of corner c of face i
        # a corner's x, y and z share a cache line: each take after the first finds them there
        offsets = w.offsets
        mul(index, 3, out=offsets)
        for k in range(3):  # gather one coordinate of every corner, then its two edges
            np.take(flat[k:], offsets, out=g, mode="clip")
            sub(corner[:, 1], corner[:, 0], out=u[k])  # U = B - A
            sub(corner[:, 2], corner[:, 0], out=v[k])  # V = C - A
        ux, uy, uz = u
        vx, vy, vz = v
        # N = U × V
        mul(uy, vz, out=n[0])
        mul(uz, vy, out=t)
        sub(n[0], t, out=n[0])
        mul(uz, vx, out=n[1])
        mul(ux, vz, out=t)
        sub(n[1], t, out=n[1])
        mul(ux, vy, out=n[2])
        mul(uy, vx, out=t)
        sub(n[2], t, out=n[2])
        _dot(n, n, ss, t)  # |N|²
        clear = _clear_block(w.edges, ss, tol2)
        careful = False
        if not clear or angles_out is not None:
            _dot(u, v, d, t)  # U·V
        if clear:  # no face of the block is degenerate or out of range
            if deg_out is not None:
                deg_out[s:e] = False
        else:
            # |U|²|V|² = |N|² + (U·V)² (Lagrange); outside the safe range: the careful path
            mul(d, d, out=q)
            add(q, ss, out=q)
            # (NaN fails every comparison, so it goes to the careful path too)
            careful = not (q.max() < _HI and ss.min() > _LO)
            if careful:
                np.less(q, _HI, out=w.in_range)
                np.greater(ss, _LO, out=w.degenerate)
                np.logical_and(w.in_range, w.degenerate, out=w.in_range)
            # degenerate: |N|² <= tol² |U|²|V|²
            mul(q, tol2, out=q)
            np.less_equal(ss, q, out=w.degenerate)
            if deg_out is not None:
                deg_out[s:e] = w.degenerate
        np.sqrt(ss, out=ss)  # |N|
        if mag_out is not None:
            mag_out[s:e] = ss
        if angles_out is not None:
            # angle at A: atan2(|N|, U·V); at B: atan2(|N|, |U|² - U·V); C: the rest of π
            ang = angles_out[s:e]
            np.arctan2(ss, d, out=ang[:, 0])
            _dot(u, u, q, t)  # |U|²
            sub(q, d, out=q)
            np.arctan2(ss, q, out=ang[:, 1])
            add(ang[:, 0], ang[:, 1], out=t)
            sub(math.pi, t, out=ang[:, 2])
        if unit_out is not None:
            rows_out = unit_out[s:e]
            # N / |N|, correctly rounded (a product with 1/|N| rounds twice), column by column:
            # a broadcast over rows of 3 is slow
            for k in range(3):
                np.divide(n[k], ss, out=rows_out[:, k])
            if not clear and w.degenerate.any():
                rows_out[w.degenerate] = 0.0
        if careful:
            rows: IntArray = s + np.flatnonzero(~w.in_range)
            return rows
    return None


def _face_rows(
    vertices: FloatArray,
    f: IntArray,
    tol: float,
    unit_out: FloatArray | None = None,
    deg_out: BoolArray | None = None,
    mag_out: FloatArray | None = None,
    angles_out: FloatArray | None = None,
) -> IntArray | None:
    """Fill the requested per-face outputs; return the magnitude exponents if any are nonzero.

    ``unit_out`` (F, 3) unit normals (zero rows where degenerate), ``deg_out``
    (F,) degeneracy, ``mag_out`` (F,) |N| as a mantissa (times ``2**exp``),
    ``angles_out`` (F, 3) the interior angle at each corner.

    Blocks of faces are independent: on a big mesh, a few threads (this one
    among them) each take the next block as they finish one (every face is
    computed the same way whichever thread does it, so the result never
    depends on the threads). Rows at extreme scales are redone afterwards by
    `_careful`.
    """
    nf = f.shape[0]
    tol2 = tol * tol
    exps: IntArray | None = None
    flat = vertices.reshape(-1)  # x, y, z of vertex 0, then of vertex 1, … (no copy)
    out = _Outputs(unit_out, deg_out, mag_out, angles_out)
    block, workers = _plan(nf)
    starts = list(range(0, nf, block))

    def run(share: Iterator[int]) -> list[IntArray]:
        full = _Block(min(block, max(nf, 1)))
        found = []
        for s in share:
            e = min(s + block, nf)
            w = full if e - s == block else full.view(e - s)
            rows = _face_block(w, flat, f, s, e, tol2, out)
            if rows is not None:
                found.append(rows)
        return found

    if workers == 1:
        found = run(iter(starts))
    else:
        # the threads, this one among them, take the next block as each finishes one (one
        # shared iterator: taking from it is atomic), so none waits on a slower one at the end
        queue = iter(starts)
        with ThreadPoolExecutor(workers - 1) as pool:
            helpers = [pool.submit(run, queue) for _ in range(workers - 1)]
            found = run(queue)
            for h in helpers:
                found += h.result()
    if not found:
        return None
    at = np.concatenate(found)
    x, y, z = vertices.T
    with np.errstate(all="ignore"):
        uc, vc, nn, ns, mag, exp, deg = _careful(x, y, z, f[at], tol2)
    if deg_out is not None:
        deg_out[at] = deg
    if mag_out is not None:
        exps = np.zeros(nf, dtype=np.intp)
        mag_out[at] = mag
        exps[at] = exp
    if unit_out is not None:
        safe = np.where(mag == 0.0, 1.0, mag)
        unit_out[at] = np.where(deg[:, None], 0.0, ns / safe[:, None])
    if angles_out is not None:
        uv = np.einsum("ij,ij->i", uc, vc)
        uu = np.einsum("ij,ij->i", uc, uc)
        ang_a = np.arctan2(nn, uv)
        ang_b = np.arctan2(nn, uu - uv)
        angles_out[at, 0] = ang_a
        angles_out[at, 1] = ang_b
        angles_out[at, 2] = math.pi - (ang_a + ang_b)
    return exps


# --------------------------------------------------------------------------- public functions


def face_normals(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    unit: bool = True,
    tol: float = DEFAULT_TOL,
) -> FloatArray:
    """Compute the normal of every face: N = (B − A) × (C − A) for face ``(A, B, C)``.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates, float32 or float64 (integers are read as float64).
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle, in winding order.
    unit : bool, default True
        True: unit normals N / |N|. False: the raw N, whose length is twice the
        face's area (the weight the guide recommends keeping for averaging).
    tol : float, default ``trinormal.tolerances.DEFAULT_TOL``
        Degeneracy threshold on the sine of the angle between the two edges.

    Returns
    -------
    ndarray, shape (F, 3)
        One normal per face, in the vertices' dtype (float32 stays float32).
        Degenerate faces get a zero row in both modes. With ``unit=False`` a
        component whose exact value is beyond the float range is ``±inf``
        (the unit normal is still right).

    Raises
    ------
    ValueError
        Wrong shapes, non-integer faces, an index out of range, NaN or
        infinite coordinates, a negative tol. The message names the first bad row.

    Examples
    --------
    The guide's worked example, and the same triangle wound the other way:

    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    >>> face_normals(v, [[0, 1, 2], [0, 2, 1]])
    array([[ 0.,  0.,  1.],
           [ 0.,  0., -1.]])

    The raw normal keeps the area (|N| = 2 · area):

    >>> face_normals([[0, 0, 0], [2, 0, 0], [0, 3, 0]], [[0, 1, 2]], unit=False)
    array([[0., 0., 6.]])

    A collinear face gets a zero row, never NaN:

    >>> face_normals([[0, 0, 0], [1, 1, 1], [2, 2, 2]], [[0, 1, 2]])
    array([[0., 0., 0.]])

    Tiny and huge coordinates still give unit normals:

    >>> face_normals(np.array(v) * 1e-200, [[0, 1, 2]])
    array([[0., 0., 1.]])
    """
    t = _check_tol(tol)
    v, f, dtype = _prepare(vertices, faces)
    nf = f.shape[0]
    if unit:
        out = np.empty((nf, 3), dtype=dtype)
        _face_rows(v, f, t, unit_out=out)
        return out
    unit_n = np.empty((nf, 3))
    mag = np.empty(nf)
    exps = _face_rows(v, f, t, unit_out=unit_n, mag_out=mag)
    raw = unit_n * mag[:, None]
    if exps is not None:  # rows from the careful path: |N| = mag * 2**exp, maybe out of range
        with np.errstate(over="ignore", under="ignore"):
            raw = np.ldexp(raw, exps[:, None])
    return _cast(raw, dtype)


def degenerate_faces(
    vertices: npt.ArrayLike, faces: npt.ArrayLike, tol: float = DEFAULT_TOL
) -> BoolArray:
    """Which faces are degenerate: the sine of the angle between their edges is at most ``tol``.

    The test ``|N| <= tol · |U| · |V|`` is the one
    [`trinormal.triangle_normal`][trinormal.core.triangle_normal]
    uses; it does not depend on the mesh's scale or position's units.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates.
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.
    tol : float, default ``trinormal.tolerances.DEFAULT_TOL``
        Sine threshold; ``0`` flags only faces whose computed N is exactly zero.

    Returns
    -------
    ndarray of bool, shape (F,)
        True where the face has no trustworthy normal.

    Examples
    --------
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0]]
    >>> degenerate_faces(v, [[0, 1, 2], [0, 1, 3], [0, 0, 2]])
    array([False,  True,  True])

    The verdict does not change with the scale:

    >>> degenerate_faces(np.array(v) * 1e-150, [[0, 1, 2], [0, 1, 3]])
    array([False,  True])
    """
    t = _check_tol(tol)
    v, f, _ = _prepare(vertices, faces)
    out = np.empty(f.shape[0], dtype=bool)
    _face_rows(v, f, t, deg_out=out)
    return out


def face_areas(vertices: npt.ArrayLike, faces: npt.ArrayLike) -> FloatArray:
    """Area of every face, |N| / 2.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates.
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.

    Returns
    -------
    ndarray, shape (F,)
        Areas in the vertices' dtype; ``inf`` only where the exact area is
        beyond the float range. Degenerate faces keep their (tiny) area.

    Examples
    --------
    >>> face_areas([[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0], [0, 3, 0]], [[0, 1, 2], [0, 3, 4]])
    array([0.5, 3. ])
    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> float(face_areas(v, f).sum())  # a cube of side 2
    24.0
    """
    v, f, dtype = _prepare(vertices, faces)
    mag = np.empty(f.shape[0])
    exps = _face_rows(v, f, DEFAULT_TOL, mag_out=mag)
    with np.errstate(over="ignore", under="ignore"):
        area = np.ldexp(mag, (exps if exps is not None else 0) - 1)
    return _cast(area, dtype)


def vertex_normals(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    weighting: Weighting | str = "angle",
    tol: float = DEFAULT_TOL,
) -> FloatArray:
    """Compute the unit normal at every vertex, a weighted sum of its faces' normals.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates.
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.
    weighting : {"angle", "area", "uniform"}, default "angle"
        How much each face counts at a vertex: its interior angle there
        (Thürmer and Wüthrich; independent of how the surface is
        triangulated), its area, or the same for every face.
    tol : float, default ``trinormal.tolerances.DEFAULT_TOL``
        Degenerate faces (sine test) contribute nothing.

    Returns
    -------
    ndarray, shape (V, 3)
        Unit vertex normals in the vertices' dtype. A vertex that touches no
        face, or only degenerate ones, or only faces that come in pairs with
        their reversed copies (whose contributions cancel exactly), gets an
        exactly zero row, never a direction made of rounding noise.

    Examples
    --------
    At a corner of a cube, angle weighting gives the exact diagonal
    (1, 1, 1)/√3; area weighting leans toward the face split into two
    triangles at that corner:

    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> np.round(vertex_normals(v, f, "angle")[7], 6)
    array([0.57735, 0.57735, 0.57735])
    >>> np.round(vertex_normals(v, f, "area")[7], 6)
    array([0.408248, 0.408248, 0.816497])

    A face glued to its own reversed copy has no side to face:

    >>> vertex_normals([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 1]])
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 0.]])
    """
    if weighting not in WEIGHTINGS:
        raise ValueError(f"weighting must be one of {', '.join(WEIGHTINGS)}; got {weighting!r}")
    t = _check_tol(tol)
    v, f, dtype = _prepare(vertices, faces)
    nv, nf = v.shape[0], f.shape[0]
    unit = np.empty((nf, 3))
    w: FloatArray
    if weighting == "angle":
        w = np.empty((nf, 3))
        _face_rows(v, f, t, unit_out=unit, angles_out=w)
    elif weighting == "area":
        mag = np.empty(nf)
        exps = _face_rows(v, f, t, unit_out=unit, mag_out=mag)
        if exps is None:  # every |N| is a normal float of moderate size: weigh as it is
            w = np.repeat(mag[:, None], 3, axis=1)
        else:
            w = _area_weights_per_vertex(mag, exps, f, nv)
    else:
        _face_rows(v, f, t, unit_out=unit)
        w = np.ones((nf, 3))
    idx = f.T.ravel()  # corner by corner: all first corners, then all second, then third
    acc = np.empty((nv, 3))
    wc = np.empty((3, nf))
    for k in range(3):
        np.multiply(w.T, unit[:, k], out=wc)
        acc[:, k] = np.bincount(idx, weights=wc.ravel(), minlength=nv)
    _cancel_reversed_pairs(acc, w, unit, f, idx)
    return _cast(_normalize_rows(acc), dtype)


#: A vertex whose summed normal is shorter than this fraction of its total
#: weight lost most of its digits to cancellation: its faces are looked at again.
_CANCELLED = 1e-6


def _cancel_reversed_pairs(
    acc: FloatArray, w: FloatArray, unit: FloatArray, f: IntArray, idx: IntArray
) -> None:
    """Redo, without them, the sums at vertices where a face and its reversed copy meet.

    A face and the same face wound the other way contribute exactly opposite
    amounts (same weight, opposite normal); in floating point their sum is
    rounding noise, which normalising would blow up into a unit vector. At
    vertices whose sum nearly cancelled, such pairs are dropped and the sum
    redone, so a vertex with nothing else around it gets an exactly zero row.
    """
    nv = acc.shape[0]
    mass = np.bincount(idx, weights=w.T.ravel(), minlength=nv)
    with np.errstate(invalid="ignore"):
        suspect = np.abs(acc).sum(axis=1) <= _CANCELLED * mass
    suspect &= mass > 0
    if not suspect.any():
        return
    near = np.flatnonzero(suspect[f].any(axis=1))  # faces touching those vertices
    g = f[near]
    distinct = (g[:, 0] != g[:, 1]) & (g[:, 1] != g[:, 2]) & (g[:, 2] != g[:, 0])
    near, g = near[distinct], g[distinct]
    s = np.sort(g, axis=1)
    even = ((g[:, 0] < g[:, 1]).astype(np.int8) + (g[:, 1] < g[:, 2]) + (g[:, 2] < g[:, 0])) == 2
    order = np.lexsort((even, s[:, 2], s[:, 1], s[:, 0]))
    s, even, near = s[order], even[order], near[order]
    new = np.ones(near.size, dtype=bool)
    new[1:] = (s[1:] != s[:-1]).any(axis=1)
    group = np.cumsum(new) - 1
    n_even = np.bincount(group, weights=even).astype(np.intp)
    n_odd = np.bincount(group).astype(np.intp) - n_even
    pairs = np.minimum(n_even, n_odd)[group]
    start = np.flatnonzero(new)[group]
    # odd faces come first in each group (False sorts first): rank within each side
    rank = np.arange(near.size) - start - np.where(even, n_odd[group], 0)
    cancelled = np.zeros(f.shape[0], dtype=bool)
    cancelled[near[rank < pairs]] = True
    if not cancelled.any():
        return
    # redo the suspect vertices' sums from the faces that remain
    keep = np.flatnonzero(suspect[f].any(axis=1) & ~cancelled)
    acc[suspect] = 0.0
    for c in range(3):
        at = f[keep, c]
        mine = suspect[at]
        np.add.at(acc, at[mine], w[keep[mine], c, None] * unit[keep[mine]])


def _area_weights_per_vertex(mag: FloatArray, exps: IntArray, f: IntArray, nv: int) -> FloatArray:
    """Area weights (F, 3), one per corner, scaled vertex by vertex.

    |N| of face i is ``mag[i] * 2**exps[i]``, possibly far outside the float
    range. Each vertex's weights are divided by the same power of two, the
    largest among its own faces, so a vertex whose faces are all tiny keeps
    their direction even when the mesh also holds faces of ordinary size.
    """
    m, e = np.frexp(mag)  # |N| = m * 2**(e + exps), m in [0.5, 1) or 0
    e = (e + exps).astype(np.int64)
    e[m == 0.0] = np.iinfo(np.int64).min  # zero (degenerate) faces set no scale
    corner = f.T.ravel()  # corner by corner, as in vertex_normals
    top = np.full(nv, np.iinfo(np.int64).min, dtype=np.int64)
    np.maximum.at(top, corner, np.tile(e, 3))
    shift = np.tile(e, 3) - top[corner]  # <= 0 where the face counts
    shift = np.maximum(shift, -2000)  # far below: the weight is zero anyway
    with np.errstate(under="ignore"):
        w = np.ldexp(np.tile(m, 3), shift.astype(np.intp))
    out: FloatArray = w.reshape(3, -1).T
    return out
