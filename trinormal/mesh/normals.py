"""Face normals, degeneracy, areas and vertex normals of whole meshes.

The kernel `_face_rows` computes, block by block, whatever per-face output a
caller asks for: unit normals, the degeneracy verdict, |N| and the interior
angles. Every public function here is one call to it plus a little numpy.
"""

from __future__ import annotations

import math
import os
import sys
import threading
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
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

#: Faces per block: small enough that a block's scratch (18 numbers a face, 2.4 MB) stays in a
#: core's cache, large enough that threads seldom wait for the interpreter lock between two numpy
#: operations. Measured with benchmarks/bench_mesh.py: 8192 made two threads hardly faster than
#: one, and 32 768 spilled out of the cache.
_BLOCK = 16384

#: Meshes of at least this many blocks of `_BLOCK` are shared among threads, at most this many.
_THREADED_BLOCKS = 8
_MAX_THREADS = 4
#: The interpreter's switch interval (seconds) while threads share a mesh; see `_handing_over`.
_SWITCH_INTERVAL = 1e-4

#: One vertex (or corner) as a single 24-byte record: x, y and z gathered by one take.
_RECORD = np.dtype((np.void, 24))

# A row goes to the careful path unless |U|²|V|² < 2**900 (no product can
# overflow) and |N|² > 2**-900 (|N| and the unit normal are full precision).
_HI = 2.0**900
_LO = 2.0**-900

# --------------------------------------------------------------------------- the kernel


class _Block:
    """Scratch arrays for one block of up to ``n`` faces, reused block after block.

    Everything lives in one float buffer of 18 ``n`` numbers (and one bool
    buffer), cut into the views below; `view` cuts the same memory for a
    shorter last block. The edges and the normal are laid out coordinate by
    coordinate (one contiguous row of ``n`` numbers per coordinate), so the
    arithmetic runs on contiguous memory.

    Attributes
    ----------
    records : ndarray (n, 3) of 24-byte records
        The block's corners, one record (x, y, z) per corner, face by face
        (A, B, C of the first face, then of the second, …): one take from the
        vertices seen as records, instead of one take per coordinate.
    corners : ndarray (n, 3, 3)
        The same memory as numbers: ``corners[i, c, k]``, coordinate k of
        corner c of face i.
    edges : ndarray (2, 3, n)
        ``edges[0, k]``, ``edges[1, k]``: coordinate k of U = B − A and V = C − A.
    normal : ndarray (3, n)
        N = U × V, in the corners' memory (free once the edges are taken).
    rows3 : ndarray (3, n)
        Scratch for three products at once, also in the corners' memory;
        ``temp`` is its first row.
    norm : ndarray (n,)
        |N|², then |N|.
    dot : ndarray (n,)
        U · V.
    bound : ndarray (n,)
        |U|²|V|², then tol²|U|²|V|² (the degeneracy bound), then |U|² − U·V.
    in_range, degenerate : ndarray of bool (n,)
        Rows the fast arithmetic handles; rows whose sine is at most tol.
    """

    def __init__(self, n: int) -> None:
        self._numbers = np.empty(18 * n)
        self._flags = np.empty(2 * n, dtype=bool)
        self._cut(n)

    def _cut(self, n: int) -> None:
        x = self._numbers
        self.records = x[: 9 * n].view(_RECORD).reshape(n, 3)
        self.corners = x[: 9 * n].reshape(n, 3, 3)
        self.normal = x[: 3 * n].reshape(3, n)
        self.rows3 = x[3 * n : 6 * n].reshape(3, n)
        self.temp = self.rows3[0]
        self.edges = x[9 * n : 15 * n].reshape(2, 3, n)
        self.norm, self.dot, self.bound = x[15 * n : 16 * n], x[16 * n : 17 * n], x[17 * n : 18 * n]
        self.in_range, self.degenerate = self._flags[:n], self._flags[n : 2 * n]
        # the views the kernel takes every block, made once (they hold the interpreter lock)
        self.first = self.corners[:, 0, :].T  # (3, n): A
        self.others = self.corners[:, 1:3, :].transpose(1, 2, 0)  # (2, 3, n): B and C
        self.u, self.v = self.edges
        self.ux, self.uy, self.uz = self.u
        self.vx, self.vy, self.vz = self.v
        # N = U × V row by row: (N_k, U_i, V_j, U_j, V_i) with N_k = U_i V_j - U_j V_i
        self.cross = [
            (self.normal[0], self.uy, self.vz, self.uz, self.vy),
            (self.normal[1], self.uz, self.vx, self.ux, self.vz),
            (self.normal[2], self.ux, self.vy, self.uy, self.vx),
        ]

    def view(self, n: int) -> _Block:
        """Return the scratch arrays for ``n`` faces, fewer than this block's, in its memory."""
        out = object.__new__(_Block)
        out._numbers, out._flags = self._numbers, self._flags
        out._cut(n)
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


def _workers(n_blocks: int) -> int:
    """How many threads share the blocks: numpy releases the GIL inside each operation."""
    if n_blocks < _THREADED_BLOCKS:
        return 1
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, _MAX_THREADS, n_blocks // 2))


#: Full-size blocks' scratch kept between calls, at most one per thread (`_scratch`, `_keep`).
_spare: list[_Block] = []
_spare_lock = threading.Lock()


def _scratch(n: int) -> _Block:
    """Return scratch for blocks of ``n`` faces: a kept one when ``n`` is a full block.

    A fresh block's 2.4 MB are new pages, which the system maps one fault at
    a time when first written: measured here, 1 230 faults and 4 ms on a call
    that takes 17 ms with kept scratch.
    """
    if n == _BLOCK:
        with _spare_lock:
            if _spare:
                return _spare.pop()
    return _Block(n)


def _keep(w: _Block) -> None:
    """Keep a full block's scratch for the next call (up to `_MAX_THREADS` of them)."""
    if w.norm.size == _BLOCK:
        with _spare_lock:
            if len(_spare) < _MAX_THREADS:
                _spare.append(w)


_switch_lock = threading.Lock()
_switch_depth = 0
_switch_saved = 0.0
_switch_applied = 0.0


@contextmanager
def _handing_over() -> Iterator[None]:
    """Shorten the interpreter's switch interval while threads share a mesh, then restore it.

    Threads running numpy take the interpreter lock back between two
    operations. A thread that finds it taken sleeps; by the time it wakes,
    the other has often taken the lock again, and it sleeps once more. With
    the usual 5 ms interval a sleeper asks the holder for the lock only after
    5 ms; with 100 µs it asks soon, and the holder hands the lock over at
    once. Measured with benchmarks/bench_mesh.py on a million faces and two
    cores: about 120 sleeps per call fell to about 20, and the best call took
    16 ms instead of 18-19 ms.

    Calls from several threads at once share one saved value: the first one
    in saves it, the last one out restores it, unless something else changed
    the interval meanwhile (then that change stays). An interval already
    shorter than ours is left alone.
    """
    global _switch_depth, _switch_saved, _switch_applied
    with _switch_lock:
        if _switch_depth == 0:
            _switch_saved = sys.getswitchinterval()
            sys.setswitchinterval(min(_switch_saved, _SWITCH_INTERVAL))
            _switch_applied = sys.getswitchinterval()
        _switch_depth += 1
    try:
        yield
    finally:
        with _switch_lock:
            _switch_depth -= 1
            if _switch_depth == 0 and sys.getswitchinterval() == _switch_applied:
                sys.setswitchinterval(_switch_saved)


@dataclass
class _Outputs:
    """Where `_face_rows` writes: any of the four per-face results (None: not wanted)."""

    unit: FloatArray | None
    degenerate: BoolArray | None
    magnitude: FloatArray | None
    angles: FloatArray | None


def _dot(x: FloatArray, y: FloatArray, out: FloatArray, rows3: FloatArray) -> None:
    """Write x · y of (3, n) rows into ``out``: three products at once, then x + y + z in turn."""
    np.multiply(x, y, out=rows3)
    np.add(rows3[0], rows3[1], out=out)
    np.add(out, rows3[2], out=out)


def _box_bound(box: FloatArray, tol2: float) -> float:
    """Return the |N|² above which a face in ``box`` is neither degenerate nor out of range.

    Each edge's components are at most the box's extents, so |U|² and |V|² are
    at most ``s``, the sum of the extents' squares, and |U|²|V|² at most ``s²``
    (times 1 + 2**-20, far more than the rounding of any |N|² + (U·V)²
    computed from them). A face with |N|² above ``tol² s²`` passes the sine
    test ``|N|² > tol² |U|²|V|²`` that `_face_block` would apply row by row:
    the same verdict, without U·V. Infinite when the box is too large or too
    small for that argument (then each block is bounded by its own edges).
    """
    with np.errstate(all="ignore"):
        span = box[1] - box[0]
        s = float((span * span).sum())
    return _clear_threshold(s, s, tol2)


def _clear_threshold(su: float, sv: float, tol2: float) -> float:
    """Return the |N|² above which faces with |U|² <= ``su``, |V|² <= ``sv`` are clear (or inf)."""
    bound = su * sv * (1.0 + 2.0**-20)  # Python floats: an overflow is inf, quietly
    if not (min(su, sv) > _LO and bound < _HI):  # (NaN fails too)
        return math.inf
    return max(_LO, tol2 * bound)


def _clear_block(edges: FloatArray, low: float, tol2: float) -> bool:
    """Whether no face of a block can be degenerate or out of the fast path's range.

    `_box_bound` for a block: here the bound on every |U|²|V|² is the product
    of the sums of squares of the block's own largest edge components, so it
    holds where the mesh's box is far larger than its faces. ``low`` is the
    block's smallest |N|².
    """
    with np.errstate(all="ignore"):
        top = np.maximum(edges.max(axis=2), -edges.min(axis=2))  # (2, 3): largest |U_k|, |V_k|
        su, sv = (top * top).sum(axis=1)
    return bool(low > _clear_threshold(float(su), float(sv), tol2))


def _face_block(
    w: _Block,
    records: npt.NDArray[np.void],
    f: IntArray,
    s: int,
    e: int,
    tol2: float,
    clear_above: float,
    out: _Outputs,
) -> IntArray | None:
    """Compute faces ``s`` to ``e`` into ``out``; return the rows the careful path must redo.

    ``records``: the vertices as 24-byte records. ``clear_above``: `_box_bound`.
    Floating-point warnings are the caller's to silence (once per thread, not per block).
    """
    nv = records.size
    mul, sub, add = np.multiply, np.subtract, np.add
    unit_out, deg_out, mag_out, angles_out = out.unit, out.degenerate, out.magnitude, out.angles
    index = f[s:e]
    # one test for both ends: a negative index, read as unsigned, is beyond any count
    if index.view(np.uintp).max() >= nv:
        _raise_range_error(f, nv)
    # short local names for the block's arrays (see _Block): the kernel reads as formulas.
    # Outputs are passed by position: numpy parses that faster than out=, and every
    # microsecond here holds the interpreter lock that the other threads wait for.
    n, ss, d, q, t, t3 = w.normal, w.norm, w.dot, w.bound, w.temp, w.rows3
    u, v = w.u, w.v
    np.take(records, index, None, w.records, "clip")  # x, y, z of every corner
    sub(w.others, w.first, w.edges)  # U = B - A, V = C - A
    for nk, ui, vj, uj, vi in w.cross:  # N = U × V (into the corners' memory, free now)
        mul(ui, vj, nk)
        mul(uj, vi, t)
        sub(nk, t, nk)
    _dot(n, n, ss, t3)  # |N|²
    low = ss.min()
    clear = bool(low > clear_above) or _clear_block(w.edges, low, tol2)
    careful = False
    if not clear or angles_out is not None:
        _dot(u, v, d, t3)  # U·V
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
    np.sqrt(ss, ss)  # |N|
    if mag_out is not None:
        mag_out[s:e] = ss
    if angles_out is not None:
        # angle at A: atan2(|N|, U·V); at B: atan2(|N|, |U|² - U·V); C: the rest of π
        ang = angles_out[s:e]
        np.arctan2(ss, d, out=ang[:, 0])
        _dot(u, u, q, t3)  # |U|²
        sub(q, d, out=q)
        np.arctan2(ss, q, out=ang[:, 1])
        add(ang[:, 0], ang[:, 1], out=t)
        sub(math.pi, t, out=ang[:, 2])
    if unit_out is not None:
        rows_out = unit_out[s:e]
        # N / |N|, correctly rounded (a product with 1/|N| rounds twice), written
        # straight into the (faces, 3) rows
        np.divide(n, ss, rows_out.T)
        if not clear and w.degenerate.any():
            rows_out[w.degenerate] = 0.0
    if careful:
        rows: IntArray = s + np.flatnonzero(~w.in_range)
        return rows
    return None


def _face_rows(
    vertices: FloatArray,
    f: IntArray,
    box: FloatArray,
    tol: float,
    unit_out: FloatArray | None = None,
    deg_out: BoolArray | None = None,
    mag_out: FloatArray | None = None,
    angles_out: FloatArray | None = None,
) -> IntArray | None:
    """Fill the requested per-face outputs; return the magnitude exponents if any are nonzero.

    ``unit_out`` (F, 3) unit normals (zero rows where degenerate), ``deg_out``
    (F,) degeneracy, ``mag_out`` (F,) |N| as a mantissa (times ``2**exp``),
    ``angles_out`` (F, 3) the interior angle at each corner. ``box``: the
    vertices' bounding box (`_arrays._box`).

    Blocks of faces are independent: on a big mesh, a few threads (this one
    among them) each take the next block as they finish one (every face is
    computed the same way whichever thread does it, so the result never
    depends on the threads). Rows at extreme scales are redone afterwards by
    `_careful`.
    """
    nf = f.shape[0]
    tol2 = tol * tol
    exps: IntArray | None = None
    records = vertices.reshape(-1).view(_RECORD)  # vertex i: one record (x, y, z), no copy
    clear_above = _box_bound(box, tol2)
    out = _Outputs(unit_out, deg_out, mag_out, angles_out)
    block, workers = _BLOCK, _workers(len(range(0, nf, _BLOCK)))
    starts = list(range(0, nf, block))

    def run(share: Iterator[int]) -> list[IntArray]:
        full = _scratch(min(block, max(nf, 1)))
        found = []
        try:
            with np.errstate(all="ignore"):  # per thread: numpy keeps it in a context variable
                for s in share:
                    e = min(s + block, nf)
                    w = full if e - s == block else full.view(e - s)
                    rows = _face_block(w, records, f, s, e, tol2, clear_above, out)
                    if rows is not None:
                        found.append(rows)
        finally:
            _keep(full)
        return found

    if workers == 1:
        found = run(iter(starts))
    else:
        # the threads, this one among them, take the next block as each finishes one (one
        # shared iterator: taking from it is atomic), so none waits on a slower one at the end
        queue = iter(starts)
        with _handing_over(), ThreadPoolExecutor(workers - 1) as pool:
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
    v, f, dtype, box = _prepare(vertices, faces)
    nf = f.shape[0]
    if unit:
        out = np.empty((nf, 3), dtype=dtype)
        _face_rows(v, f, box, t, unit_out=out)
        return out
    unit_n = np.empty((nf, 3))
    mag = np.empty(nf)
    exps = _face_rows(v, f, box, t, unit_out=unit_n, mag_out=mag)
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
    v, f, _, box = _prepare(vertices, faces)
    out = np.empty(f.shape[0], dtype=bool)
    _face_rows(v, f, box, t, deg_out=out)
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
    v, f, dtype, box = _prepare(vertices, faces)
    mag = np.empty(f.shape[0])
    exps = _face_rows(v, f, box, DEFAULT_TOL, mag_out=mag)
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
    v, f, dtype, box = _prepare(vertices, faces)
    nv, nf = v.shape[0], f.shape[0]
    unit = np.empty((nf, 3))
    w: FloatArray
    if weighting == "angle":
        w = np.empty((nf, 3))
        _face_rows(v, f, box, t, unit_out=unit, angles_out=w)
    elif weighting == "area":
        mag = np.empty(nf)
        exps = _face_rows(v, f, box, t, unit_out=unit, mag_out=mag)
        if exps is None:  # every |N| is a normal float of moderate size: weigh as it is
            w = np.repeat(mag[:, None], 3, axis=1)
        else:
            w = _area_weights_per_vertex(mag, exps, f, nv)
    else:
        _face_rows(v, f, box, t, unit_out=unit)
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
