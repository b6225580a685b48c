"""Normals of whole triangle meshes, vectorized with numpy.

A mesh is two arrays: ``vertices`` of shape (V, 3), one point per row, and
``faces`` of shape (F, 3), three row indices into ``vertices`` per triangle.
Face ``(i, j, k)`` has the normal ``N = (v[j] - v[i]) × (v[k] - v[i])``, the
same formula and the same winding as [`trinormal.triangle_normal`][trinormal.core.triangle_normal].

The promises, for every function here:

* No NaN and no ``RuntimeWarning``, whatever the input. A degenerate face (the
  sine of the angle between its edges is at most ``tol``, the scale-invariant
  test of [`trinormal.tolerances`][trinormal.tolerances]) gets a zero normal; a vertex that
  touches only degenerate faces gets a zero vertex normal.
* Coordinates near 1e-200 or 1e200 still give correct unit normals: rows that
  would underflow or overflow are redone with their edges scaled by powers of
  two, which is exact.
* float32 vertices are computed in float64 (the product of two float32 numbers
  is exact in float64) and the result comes back as float32. Any other real
  input is computed and returned in float64.
* Bad input raises a `ValueError` that names the first bad row.

Speed comes from plain numpy: the coordinates are split into three contiguous
arrays, faces are processed in blocks of a few thousand so that every
temporary stays in the CPU cache, and every operation writes in place. There
is no Python loop over faces (only over blocks of them).

The small meshes [`cube`][trinormal.mesh.cube], [`icosphere`][trinormal.mesh.icosphere],
[`torus`][trinormal.mesh.torus] and
[`terrain`][trinormal.mesh.terrain] are generated in code, outward-facing and consistently wound.

Examples
--------
>>> from trinormal import mesh
>>> v, f = mesh.cube()
>>> v.shape, f.shape
((8, 3), (12, 3))
>>> mesh.face_normals(v, f)[:2]
array([[ 0.,  0., -1.],
       [ 0.,  0., -1.]])
>>> bool(mesh.consistent_winding(f))
True
"""

from __future__ import annotations

import math
from typing import Any, Literal

from trinormal._optional import missing_extra

try:
    import numpy as np
    import numpy.typing as npt
except ModuleNotFoundError as exc:
    raise missing_extra(exc, __name__) from exc

from trinormal.tolerances import DEFAULT_TOL
from trinormal.validation import check_tolerance

__all__ = [
    "WEIGHTINGS",
    "consistent_winding",
    "cube",
    "degenerate_faces",
    "face_areas",
    "face_normals",
    "icosphere",
    "inconsistent_edges",
    "terrain",
    "torus",
    "uv_sphere",
    "vertex_normals",
]

FloatArray = npt.NDArray[np.floating[Any]]
IntArray = npt.NDArray[np.intp]
BoolArray = npt.NDArray[np.bool_]
Weighting = Literal["angle", "area", "uniform"]

#: The vertex-normal weightings `vertex_normals` accepts.
WEIGHTINGS: tuple[str, ...] = ("angle", "area", "uniform")

#: Faces per block: small enough that the block's temporaries stay in cache.
_BLOCK = 8192

# A row goes to the careful path unless |U|²|V|² < 2**900 (no product can
# overflow) and |N|² > 2**-900 (|N| and the unit normal are full precision).
_HI = 2.0**900
_LO = 2.0**-900

# One vertex row (3 float64) as a single item, so a gather moves whole rows.
_ROW = np.dtype((np.void, 24))

# The largest vertex index: 2**63 - 1 (numpy's intp on 64-bit machines).
_MAX_INDEX = int(np.iinfo(np.intp).max)


# --------------------------------------------------------------------------- validation


def _check_vertices(vertices: npt.ArrayLike) -> tuple[FloatArray, np.dtype[Any]]:
    """Return the vertices as float64 (V, 3) and the dtype results come back in."""
    arr = np.asarray(vertices)
    if arr.dtype == np.float32:
        out_dtype: np.dtype[Any] = np.dtype(np.float32)
    elif arr.dtype.kind in "fiu":
        out_dtype = np.dtype(np.float64)
    elif arr.dtype == object:
        try:
            arr = arr.astype(np.float64)
        except (TypeError, ValueError):
            raise ValueError("vertices must be real numbers") from None
        except OverflowError:  # a Python int or Fraction beyond the float64 range
            raise ValueError("vertices must be real numbers within the float64 range") from None
        out_dtype = np.dtype(np.float64)
    else:
        raise ValueError(f"vertices must be real numbers, got dtype {arr.dtype}")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"vertices must have shape (V, 3), got shape {arr.shape}")
    arr64 = arr.astype(np.float64, copy=False)
    # two reductions (NaN propagates through min and max) instead of a (V, 3) mask
    if arr64.size and not (np.isfinite(arr64.min()) and np.isfinite(arr64.max())):
        finite = np.isfinite(arr64)
        row = int(np.flatnonzero(~finite.all(axis=1))[0])
        col = int(np.flatnonzero(~finite[row])[0])
        what = "NaN" if np.isnan(arr64[row, col]) else "infinite"
        raise ValueError(
            f"vertices row {row}: {'xyz'[col]} is {what}; every coordinate must be a finite number"
        )
    return arr64, out_dtype


def _check_faces(
    faces: npt.ArrayLike, n_vertices: int | None, check_range: bool = True
) -> IntArray:
    """Return the faces as an intp (F, 3) array, every index checked against ``n_vertices``.

    With ``check_range=False`` only the dtype and shape are checked here: the
    kernel checks the indices block by block, where they are in cache anyway.
    """
    arr = np.asarray(faces)
    if arr.size == 0:
        if arr.ndim == 2 and arr.shape[1] != 3:
            raise ValueError(f"faces must have shape (F, 3), got shape {arr.shape}")
        return np.empty((0, 3), dtype=np.intp)
    if arr.dtype.kind not in "iu":
        raise ValueError(f"faces must hold integer vertex indices, got dtype {arr.dtype}")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"faces must have shape (F, 3), got shape {arr.shape}")
    if arr.dtype.kind == "u" and arr.dtype.itemsize >= 8 and int(arr.max()) > _MAX_INDEX:
        _raise_range_error(arr, _MAX_INDEX + 1)  # beyond what an index (intp) can hold
    if check_range:
        lo, hi = int(arr.min()), int(arr.max())
        limit = n_vertices if n_vertices is not None else hi + 1
        if lo < 0 or hi >= limit:
            _raise_range_error(arr, limit)
    return np.ascontiguousarray(arr, dtype=np.intp)


def _raise_range_error(arr: npt.NDArray[Any], limit: int) -> None:
    """Raise the ValueError naming the first row of ``arr`` with an index outside [0, limit)."""
    bad = (arr < 0) | (arr >= limit)
    row = int(np.flatnonzero(bad.any(axis=1))[0])
    index = int(arr[row][bad[row]][0])
    valid = (
        f"the valid indices are 0 to {limit - 1} ({limit} vertices)"
        if limit
        else "there are no vertices"
    )
    raise ValueError(f"faces row {row} refers to vertex {index}, but {valid}")


def _check_tol(tol: float) -> float:
    """Return the tolerance as a float, checked by `trinormal.validation.check_tolerance`."""
    n, d = check_tolerance(tol)
    return n / d  # 0 <= tol <= 1: no overflow


def _cast(values: FloatArray, dtype: np.dtype[Any]) -> FloatArray:
    """Return float64 results in ``dtype``: beyond the float32 range they become ±inf, quietly."""
    if values.dtype == dtype:
        return values
    with np.errstate(over="ignore", under="ignore"):
        out: FloatArray = values.astype(dtype)
    return out


def _prepare(
    vertices: npt.ArrayLike, faces: npt.ArrayLike
) -> tuple[FloatArray, IntArray, np.dtype[Any]]:
    v, dtype = _check_vertices(vertices)
    f = _check_faces(faces, v.shape[0], check_range=False)
    return np.ascontiguousarray(v), f, dtype


# --------------------------------------------------------------------------- the kernel


class _Block:
    """Scratch arrays for one block of ``n`` faces, reused block after block.

    Attributes
    ----------
    corners : ndarray (3, n, 3)
        The corners A, B, C of each face; the kernel then turns B and C into
        the edges U = B − A and V = C − A in place.
    corner_rows : ndarray (3, n)
        The same memory seen as one 24-byte item per corner, for gathering.
    normal : ndarray (n, 3)
        N = U × V.
    products : ndarray (n, 3)
        Component-wise products (N·N, U·V, U·U) before they are summed.
    norm : ndarray (n,)
        |N|², then |N|.
    dot : ndarray (n,)
        U · V.
    bound : ndarray (n,)
        |U|²|V|², then tol²|U|²|V|² (the degeneracy bound), then |U|² − U·V.
    temp : ndarray (n,)
        One product at a time.
    in_range, degenerate : ndarray of bool (n,)
        Rows the fast arithmetic handles; rows whose sine is at most tol.
    """

    _ROWS = ("normal", "products", "norm", "dot", "bound", "temp", "in_range", "degenerate")

    def __init__(self, n: int) -> None:
        e = np.empty
        self.corners = e((3, n, 3))
        self.corner_rows = self.corners.view(_ROW).reshape(3, n)
        self.normal, self.products = e((n, 3)), e((n, 3))
        self.norm, self.dot, self.bound, self.temp = e(n), e(n), e(n), e(n)
        self.in_range, self.degenerate = e(n, dtype=bool), e(n, dtype=bool)

    def view(self, n: int) -> _Block:
        """Return the first ``n`` rows of every scratch array (for the last, shorter block)."""
        out = object.__new__(_Block)
        out.corners = self.corners[:, :n]
        out.corner_rows = self.corner_rows[:, :n]
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


def _blocks(n: int) -> range:
    return range(0, n, _BLOCK)


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
    """
    nf = f.shape[0]
    tol2 = tol * tol
    exps: IntArray | None = None
    rows_v = vertices.view(_ROW).ravel()  # (V,) items of 24 bytes, no copy
    x, y, z = vertices[:, 0], vertices[:, 1], vertices[:, 2]
    full = _Block(min(_BLOCK, max(nf, 1)))
    mul, sub, add = np.multiply, np.subtract, np.add
    with np.errstate(all="ignore"):
        for s in _blocks(nf):
            e = min(s + _BLOCK, nf)
            w = full if e - s == _BLOCK else full.view(e - s)
            # gather whole rows: one memory access per corner, not one per coordinate
            fb = f[s:e]
            try:  # take checks the upper bound itself; it would wrap negative indices
                if fb.min() < 0:
                    raise IndexError
                np.take(rows_v, fb.T, out=w.corner_rows)
            except IndexError:
                _raise_range_error(f, rows_v.shape[0])
            # short local names for the block's arrays (see _Block): the kernel reads as formulas
            g, n, sq, ss = w.corners, w.normal, w.products, w.norm
            d, q, t = w.dot, w.bound, w.temp
            sub(g[1], g[0], out=g[1])  # U = B - A
            sub(g[2], g[0], out=g[2])  # V = C - A
            ux, uy, uz = g[1, :, 0], g[1, :, 1], g[1, :, 2]
            vx, vy, vz = g[2, :, 0], g[2, :, 1], g[2, :, 2]
            # N = U × V
            mul(uy, vz, out=n[:, 0])
            mul(uz, vy, out=t)
            sub(n[:, 0], t, out=n[:, 0])
            mul(uz, vx, out=n[:, 1])
            mul(ux, vz, out=t)
            sub(n[:, 1], t, out=n[:, 1])
            mul(ux, vy, out=n[:, 2])
            mul(uy, vx, out=t)
            sub(n[:, 2], t, out=n[:, 2])
            # |N|² and U·V
            mul(n, n, out=sq)
            add(sq[:, 0], sq[:, 1], out=ss)
            add(ss, sq[:, 2], out=ss)
            mul(g[1], g[2], out=sq)
            add(sq[:, 0], sq[:, 1], out=d)
            add(d, sq[:, 2], out=d)
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
                mul(g[1], g[1], out=sq)
                add(sq[:, 0], sq[:, 1], out=q)
                add(q, sq[:, 2], out=q)
                sub(q, d, out=q)
                np.arctan2(ss, q, out=ang[:, 1])
                add(ang[:, 0], ang[:, 1], out=t)
                sub(math.pi, t, out=ang[:, 2])
            if unit_out is not None:
                np.divide(1.0, ss, out=t)
                if w.degenerate.any():
                    t[w.degenerate] = 0.0
                out = unit_out[s:e]
                for k in range(3):  # column by column: a broadcast over rows of 3 is slow
                    mul(n[:, k], t, out=out[:, k])
            if careful:
                rows = np.flatnonzero(~w.in_range)
                uc, vc, nn, ns, mag, exp, deg = _careful(x, y, z, f[s + rows], tol2)
                at = s + rows
                if deg_out is not None:
                    deg_out[at] = deg
                if mag_out is not None:
                    if exps is None:
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
        face, or only degenerate ones, or whose contributions cancel exactly,
        gets a zero row.

    Examples
    --------
    At a corner of a cube, angle weighting gives the exact diagonal
    (1, 1, 1)/√3; area weighting leans toward the face split into two
    triangles at that corner:

    >>> v, f = cube()
    >>> np.round(vertex_normals(v, f, "angle")[7], 6)
    array([0.57735, 0.57735, 0.57735])
    >>> np.round(vertex_normals(v, f, "area")[7], 6)
    array([0.408248, 0.408248, 0.816497])
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
    return _cast(_normalize_rows(acc), dtype)


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


def inconsistent_edges(faces: npt.ArrayLike) -> IntArray:
    """Directed edges that appear in two faces running the same way.

    In a consistently wound mesh every interior edge is walked once in each
    direction, by the two faces that share it. An edge walked the same way
    twice means one of those faces is flipped.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.

    Returns
    -------
    ndarray of int, shape (E, 2)
        Each offending directed edge ``(i, j)`` once, sorted.

    Examples
    --------
    >>> inconsistent_edges([[0, 1, 2], [0, 2, 3]])
    array([], shape=(0, 2), dtype=int64)
    >>> inconsistent_edges([[0, 1, 2], [0, 3, 2]])
    array([[2, 0]])
    """
    f = _check_faces(faces, None)
    if f.shape[0] == 0:
        return np.empty((0, 2), dtype=np.intp)
    # directed edges as (start, end) rows, sorted; no packing into one integer, which
    # would wrap around for indices above 2**31
    edges = np.stack([f.ravel(), f[:, [1, 2, 0]].ravel()], axis=1)
    edges = edges[np.lexsort((edges[:, 1], edges[:, 0]))]
    same = (edges[1:] == edges[:-1]).all(axis=1)
    dup: IntArray = np.unique(edges[1:][same], axis=0).reshape(-1, 2).astype(np.intp)
    return dup


def consistent_winding(faces: npt.ArrayLike) -> bool:
    """Whether every edge shared by two faces runs opposite ways in them.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.

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


# --------------------------------------------------------------------------- built-in meshes


def cube(size: float = 2.0) -> tuple[FloatArray, IntArray]:
    """Make a cube centred on the origin: 8 vertices and 12 outward-facing triangles.

    Vertex ``i`` has coordinates ``±size/2`` with the sign of x, y, z taken from
    bits 0, 1, 2 of ``i``, so vertex 7 is the corner (1, 1, 1) of the default
    cube. Each square face is split along one diagonal; at vertex 7 only the
    top face (+z) is split through the corner, which is what makes area and
    angle weighting disagree there.

    Parameters
    ----------
    size : float, default 2.0
        Edge length.

    Returns
    -------
    vertices : ndarray, shape (8, 3)
    faces : ndarray of int, shape (12, 3)

    Examples
    --------
    >>> v, f = cube()
    >>> v[7], f[-2:]
    (array([1., 1., 1.]), array([[4, 5, 7],
           [4, 7, 6]]))
    """
    i = np.arange(8)
    v = (np.stack([i & 1, (i >> 1) & 1, (i >> 2) & 1], axis=1) - 0.5) * float(size)
    f = np.array(
        [
            [0, 2, 3], [0, 3, 1],  # -z  (bottom)
            [0, 1, 5], [0, 5, 4],  # -y
            [0, 4, 6], [0, 6, 2],  # -x
            [1, 3, 5], [3, 7, 5],  # +x
            [2, 6, 3], [3, 6, 7],  # +y
            [4, 5, 7], [4, 7, 6],  # +z  (top)
        ],
        dtype=np.intp,
    )  # fmt: skip
    return v, f


def icosphere(subdivisions: int = 2, radius: float = 1.0) -> tuple[FloatArray, IntArray]:
    """Make a sphere of triangles: an icosahedron whose faces are split in four, repeatedly.

    Parameters
    ----------
    subdivisions : int, default 2
        How many times every triangle is split into four (0 is the icosahedron).
    radius : float, default 1.0
        Every vertex lies at this distance from the origin.

    Returns
    -------
    vertices : ndarray, shape (10 · 4**s + 2, 3)
    faces : ndarray of int, shape (20 · 4**s, 3)
        Outward-facing, consistently wound.

    Examples
    --------
    >>> v, f = icosphere(1)
    >>> v.shape, f.shape
    ((42, 3), (80, 3))
    >>> bool(np.allclose(np.linalg.norm(v, axis=1), 1.0))
    True
    """
    if subdivisions < 0:
        raise ValueError(f"subdivisions must be >= 0, got {subdivisions}")
    p = (1.0 + math.sqrt(5.0)) / 2.0
    v = np.array(
        [
            [-1, p, 0], [1, p, 0], [-1, -p, 0], [1, -p, 0],
            [0, -1, p], [0, 1, p], [0, -1, -p], [0, 1, -p],
            [p, 0, -1], [p, 0, 1], [-p, 0, -1], [-p, 0, 1],
        ],
        dtype=np.float64,
    )  # fmt: skip
    f = np.array(
        [
            [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
            [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
            [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
            [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
        ],
        dtype=np.intp,
    )  # fmt: skip
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    for _ in range(subdivisions):
        # one new vertex per edge, shared by the two faces on either side
        edges = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
        key = np.sort(edges, axis=1)
        uniq, inverse = np.unique(key, axis=0, return_inverse=True)
        mid = v[uniq[:, 0]] + v[uniq[:, 1]]
        mid /= np.linalg.norm(mid, axis=1, keepdims=True)
        m = inverse.reshape(3, -1) + v.shape[0]  # midpoints of edges 01, 12, 20 of each face
        v = np.concatenate([v, mid])
        a, b, c = f[:, 0], f[:, 1], f[:, 2]
        ab, bc, ca = m[0], m[1], m[2]
        f = np.concatenate(
            [
                np.stack([a, ab, ca], axis=1),
                np.stack([b, bc, ab], axis=1),
                np.stack([c, ca, bc], axis=1),
                np.stack([ab, bc, ca], axis=1),
            ]
        )
    return v * float(radius), f.astype(np.intp)


def torus(
    major: float = 1.0, minor: float = 0.35, n_major: int = 32, n_minor: int = 16
) -> tuple[FloatArray, IntArray]:
    """Make a ring around the z axis: a circle of radius ``minor`` swept along radius ``major``.

    Parameters
    ----------
    major, minor : float
        Radius of the ring's centre line and of its tube (``0 < minor < major``).
    n_major, n_minor : int
        Vertices around the ring and around the tube (at least 3 each).

    Returns
    -------
    vertices : ndarray, shape (n_major · n_minor, 3)
    faces : ndarray of int, shape (2 · n_major · n_minor, 3)
        Outward-facing, consistently wound, closed (no boundary).

    Examples
    --------
    >>> v, f = torus(n_major=8, n_minor=4)
    >>> v.shape, f.shape
    ((32, 3), (64, 3))
    """
    if not 0 < minor < major:
        raise ValueError(f"need 0 < minor < major, got minor={minor}, major={major}")
    if n_major < 3 or n_minor < 3:
        raise ValueError(f"n_major and n_minor must be >= 3, got {n_major}, {n_minor}")
    th = np.linspace(0.0, 2.0 * np.pi, n_major, endpoint=False)[:, None]
    ph = np.linspace(0.0, 2.0 * np.pi, n_minor, endpoint=False)[None, :]
    r = major + minor * np.cos(ph)
    v = np.stack(
        [
            (r * np.cos(th)).ravel(),
            (r * np.sin(th)).ravel(),
            np.broadcast_to(minor * np.sin(ph), (n_major, n_minor)).ravel(),
        ],
        axis=1,
    )
    i = np.arange(n_major)[:, None]
    j = np.arange(n_minor)[None, :]
    p00 = (i * n_minor + j).ravel()
    p10 = (((i + 1) % n_major) * n_minor + j).ravel()
    p01 = (i * n_minor + (j + 1) % n_minor).ravel()
    p11 = (((i + 1) % n_major) * n_minor + (j + 1) % n_minor).ravel()
    f = np.concatenate([np.stack([p00, p10, p11], 1), np.stack([p00, p11, p01], 1)])
    return v, f.astype(np.intp)


def uv_sphere(n_around: int = 24, n_down: int = 12) -> tuple[FloatArray, IntArray]:
    """Make a unit sphere cut along meridians and parallels, like a globe's grid.

    Unlike `icosphere`, its triangles are far from equal: they grow thin and
    small near the poles, which is what makes vertex-normal weightings differ.

    Parameters
    ----------
    n_around : int, default 24
        Meridians (vertices around each parallel), at least 3.
    n_down : int, default 12
        Bands from pole to pole, at least 3.

    Returns
    -------
    vertices : ndarray, shape (n_around · (n_down − 1) + 2, 3)
        The parallels' vertices, then the north and the south pole.
    faces : ndarray of int, shape (2 · n_around · (n_down − 1), 3)
        Outward-facing, consistently wound, closed.

    Examples
    --------
    >>> v, f = uv_sphere(8, 4)
    >>> v.shape, f.shape
    ((26, 3), (48, 3))
    >>> bool(np.allclose(np.linalg.norm(v, axis=1), 1.0))
    True
    """
    if n_around < 3 or n_down < 3:
        raise ValueError(f"n_around and n_down must be >= 3, got {n_around}, {n_down}")
    theta = np.linspace(0.0, np.pi, n_down + 1)[1:-1]
    phi = np.linspace(0.0, 2.0 * np.pi, n_around, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    ring = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], -1).reshape(-1, 3)
    vertices = np.vstack([ring, [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    north, south, last = len(ring), len(ring) + 1, (n_down - 2) * n_around
    faces = []
    for i in range(n_down - 2):  # two triangles per cell between neighbouring parallels
        for j in range(n_around):
            a, b = i * n_around + j, i * n_around + (j + 1) % n_around
            faces += [(a, a + n_around, b + n_around), (a, b + n_around, b)]
    for j in range(n_around):  # a fan at each pole
        faces += [(north, j, (j + 1) % n_around), (south, last + (j + 1) % n_around, last + j)]
    return vertices, np.array(faces, dtype=np.intp)


def terrain(
    nx: int = 32, ny: int = 32, size: float = 1.0, height: float = 0.15, seed: int = 0
) -> tuple[FloatArray, IntArray]:
    """Make a height-field grid: ``nx`` by ``ny`` points over a square, z a smooth landscape.

    Faces are listed row by row, two triangles per grid cell, all facing up
    (+z side), so neighbouring faces share neighbouring vertices: the natural
    order a mesh file usually has.

    Parameters
    ----------
    nx, ny : int
        Grid points along x and y (at least 2 each).
    size : float, default 1.0
        Side of the square, centred on the origin.
    height : float, default 0.15
        Largest height of the landscape.
    seed : int, default 0
        Seed of the random hills (same seed, same terrain).

    Returns
    -------
    vertices : ndarray, shape (nx · ny, 3)
    faces : ndarray of int, shape (2 (nx − 1)(ny − 1), 3)

    Examples
    --------
    >>> v, f = terrain(3, 4)
    >>> v.shape, f.shape
    ((12, 3), (12, 3))
    >>> bool((face_normals(v, f)[:, 2] > 0).all())
    True
    """
    if nx < 2 or ny < 2:
        raise ValueError(f"nx and ny must be >= 2, got {nx}, {ny}")
    rng = np.random.default_rng(seed)
    xs = np.linspace(-size / 2, size / 2, nx)
    ys = np.linspace(-size / 2, size / 2, ny)
    gx, gy = np.meshgrid(xs, ys, indexing="xy")  # shape (ny, nx): row j, column i
    k = rng.uniform(1.0, 4.0, size=(4, 2)) * (2 * np.pi / size)
    phase = rng.uniform(0, 2 * np.pi, size=4)
    amp = rng.uniform(0.3, 1.0, size=4)
    z = sum(a * np.sin(kx * gx + ky * gy + p) for (kx, ky), p, a in zip(k, phase, amp, strict=True))
    z = z * (height / amp.sum())
    v = np.stack([gx.ravel(), gy.ravel(), np.asarray(z).ravel()], axis=1)
    j, i = np.meshgrid(np.arange(ny - 1), np.arange(nx - 1), indexing="ij")
    p00 = (j * nx + i).ravel()
    p10, p01, p11 = p00 + 1, p00 + nx, p00 + nx + 1
    f = np.stack([p00, p10, p11, p00, p11, p01], axis=1).reshape(-1, 3)
    return v, f.astype(np.intp)
