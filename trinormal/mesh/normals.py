"""Face normals, degeneracy, areas and vertex normals of whole meshes.

A mesh is two arrays: ``vertices``, shape (V, 3), the coordinates (float32 or
float64; integers are read as float64), and ``faces``, shape (F, 3), each row
the three vertex indices of a triangle in winding order. Results come back in
the vertices' dtype. `face_normals` documents the pair once; the other
functions take it as it does.

The kernel `_face_rows` computes, block by block, whatever per-face output a
caller asks for: unit normals, the degeneracy verdict, |N| and the interior
angles. Every public function here is one call to it plus a little numpy.

A face A, B, C is degenerate when ``|N| <= tol · L²``, with N = (B − A) × (C − A)
and L the length of its longest edge: the same verdict whichever corner comes
first and whichever way the face is wound, and the same at every scale.
"""

from __future__ import annotations

import math
from fractions import Fraction

from trinormal._optional import missing_extra

try:
    import numpy as np
    import numpy.typing as npt
except ModuleNotFoundError as exc:
    raise missing_extra(exc, __name__) from exc

from trinormal.core import _longest_squared, _thin
from trinormal.mesh._arrays import (
    BoolArray,
    FloatArray,
    IntArray,
    Weighting,
    _cast,
    _exact_tol,
    _prepare,
    _raise_range_error,
)
from trinormal.mesh.topology import _distinct_corners
from trinormal.tolerances import DEFAULT_TOL

__all__ = ["WEIGHTINGS", "degenerate_faces", "face_areas", "face_normals", "vertex_normals"]

#: The vertex-normal weightings `vertex_normals` accepts.
WEIGHTINGS: tuple[str, ...] = ("angle", "area", "uniform")

#: Faces per block: a block's working arrays (24 numbers a face) stay in the CPU's caches
#: from one step of the kernel to the next, while the Python work per block (a few dozen
#: numpy calls) stays small beside the arithmetic.
_BLOCK = 8192

#: One vertex as a single 24-byte record, so that one take gathers x, y and z of a corner.
_RECORD = np.dtype((np.void, 24))

# The kernel keeps a row when |N|² > 2**-900 and L² < 2**450: then no product overflows,
# none underflows enough to matter, and |N| and N / |N| are full precision. `_careful`
# redoes every other row with its edges scaled by powers of two.
_LO = 2.0**-900
_HI = 2.0**450

#: Half-width of the band around the threshold, as a fraction of L² (and of tol · L²), inside
#: which the float test |N| <= tol · L² is not trusted. The float |N| and L² are within a few
#: units of roundoff (2**-53) of the values for the exact corners, so outside the band the
#: float verdict is the exact one; faces inside it are decided in exact arithmetic (`_exact`).
_BAND = 2.0**-49


def _band(tol: float) -> tuple[float, float]:
    """Return ``(lo, hi)``: a float |N| below ``lo · L²`` is degenerate, above ``hi · L²`` not."""
    return max(tol * (1 - _BAND) - _BAND, 0.0), tol * (1 + _BAND) + _BAND


def _sure(nn: FloatArray, l2: FloatArray, tol: float) -> tuple[BoolArray, BoolArray]:
    """Return the faces surely not degenerate and those surely degenerate.

    ``nn`` and ``l2`` are |N|² and L² = max(|U|², |V|², |W|²) computed in
    float64 from a face's edges (all three scaled alike, by a power of two,
    or not at all). Faces in neither mask are too close to the threshold for
    floats. All three corners at one point (L² = 0) make a degenerate face.
    """
    lo, hi = _band(tol)
    l4 = l2 * l2
    ok: BoolArray = nn > (hi * hi) * l4
    below = (lo * lo) * l4
    bad: BoolArray = ((nn < below) & (below > _LO)) | (l2 == 0.0)
    return ok, bad


def _exact(corners: FloatArray, tol: Fraction) -> FloatArray | None:
    """Return one face's unit normal computed exactly, or None when the face is degenerate.

    ``corners`` (3, 3): A, B, C. Every float is an integer over a power of
    two, so over the largest denominator among them the corners are integers,
    and the rule |N| <= tol · L² is tested exactly by the core's own test
    (`trinormal.core`'s ``_thin``). The unit normal's components are quotients
    of integers, correctly rounded.
    """
    ratios = [x.as_integer_ratio() for x in corners.ravel().tolist()]
    den = max(d for _, d in ratios)
    ax, ay, az, bx, by, bz, cx, cy, cz = (p * (den // d) for p, d in ratios)
    u, v = (bx - ax, by - ay, bz - az), (cx - ax, cy - ay, cz - az)
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    nn = sum(x * x for x in n)
    if _thin(nn, _longest_squared(u, v), tol.numerator, tol.denominator):  # the core's rule
        return None
    k = max(0, 67 - nn.bit_length() // 2)  # |N| · 2**k to 67 bits or more
    r = math.isqrt(nn << 2 * k)
    return np.array([(x << k) / r for x in n])


def _rowdot(p: FloatArray, q: FloatArray) -> FloatArray:
    """Return the dot products of the rows of ``p`` and ``q`` (k, 3)."""
    out: FloatArray = np.einsum("ij,ij->i", p, q)
    return out


def _careful(
    v: FloatArray, f: IntArray, tol: Fraction
) -> tuple[FloatArray, BoolArray, FloatArray, IntArray, FloatArray]:
    """Faces at extreme scales or near the threshold: edges scaled by powers of two first.

    Returns, for the faces ``f`` (k, 3): unit normals (k, 3), zero where
    degenerate; the verdicts (k,); |N| = ``mag · 2**exp`` as ``mag`` (k,) and
    ``exp`` (k,); the interior angles (k, 3).
    """
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    u, w, x = b - a, c - a, c - b  # U, V, W
    # differences of coordinates near the float64 limit can overflow: quarter them first (exact)
    big = ~(np.isfinite(u).all(axis=1) & np.isfinite(w).all(axis=1) & np.isfinite(x).all(axis=1))
    if big.any():
        a4, b4, c4 = a[big] * 0.25, b[big] * 0.25, c[big] * 0.25
        u[big], w[big], x[big] = b4 - a4, c4 - a4, c4 - b4
    eu = np.frexp(np.abs(u).max(axis=1))[1]
    ev = np.frexp(np.abs(w).max(axis=1))[1]
    # the verdict and the angles: the three edges scaled alike, so their products compare
    common = np.maximum(eu, ev)[:, None]
    uc, vc, wc = np.ldexp(u, -common), np.ldexp(w, -common), np.ldexp(x, -common)
    nc = np.cross(uc, vc)
    nn = _rowdot(nc, nc)
    l2 = np.maximum(np.maximum(_rowdot(uc, uc), _rowdot(vc, vc)), _rowdot(wc, wc))
    ok, bad = _sure(nn, l2, float(tol))
    uv, nc_len = _rowdot(uc, vc), np.sqrt(nn)
    ang_a, ang_b = np.arctan2(nc_len, uv), np.arctan2(nc_len, _rowdot(uc, uc) - uv)
    angles = np.stack([ang_a, ang_b, math.pi - (ang_a + ang_b)], axis=1)
    # the normal: each edge scaled on its own, so a huge edge and a tiny one keep their product
    n = np.cross(np.ldexp(u, -eu[:, None]), np.ldexp(w, -ev[:, None]))
    en = np.frexp(np.abs(n).max(axis=1))[1]
    ns = np.ldexp(n, -en[:, None])
    mag = np.sqrt(_rowdot(ns, ns))
    exp = (eu + ev + en + np.where(big, 2, 0)).astype(np.intp)
    unit = ns / np.where(mag == 0.0, 1.0, mag)[:, None]
    degenerate = ~ok
    for i in np.flatnonzero(~(ok | bad)):  # too near the threshold for floats
        exact = _exact(v[f[i]], tol)
        degenerate[i] = exact is None
        if exact is not None:
            unit[i] = exact
    unit[degenerate] = 0.0
    return unit, degenerate, mag, exp, angles


def _normalize_rows(s: FloatArray) -> FloatArray:
    """Return the unit rows of ``s`` (n, 3), scaled by a power of two first; zero rows stay zero."""
    e = np.frexp(np.abs(s).max(axis=1))[1]
    s = np.ldexp(s, -e[:, None])
    r = np.sqrt(_rowdot(s, s))
    r[r == 0.0] = 1.0
    out: FloatArray = s / r[:, None]
    return out


def _dot(x: FloatArray, y: FloatArray, out: FloatArray, rows3: FloatArray) -> None:
    """Write x · y of (3, n) rows into ``out``: three products at once, then x + y + z in turn."""
    np.multiply(x, y, out=rows3)
    np.add(rows3[0], rows3[1], out=out)
    np.add(out, rows3[2], out=out)


def _face_rows(
    vertices: FloatArray,
    f: IntArray,
    box: FloatArray,
    tol: Fraction,
    unit_out: FloatArray | None = None,
    deg_out: BoolArray | None = None,
    mag_out: FloatArray | None = None,
    angles_out: FloatArray | None = None,
) -> IntArray | None:
    """Fill the requested per-face outputs; return the magnitude exponents if any are nonzero.

    ``unit_out`` (F, 3) unit normals (zero rows where degenerate), ``deg_out``
    (F,) the verdicts, ``mag_out`` (F,) |N| as a mantissa (times ``2**exp``),
    ``angles_out`` (F, 3) the interior angle at each corner. ``box``: the
    vertices' bounding box (`_arrays._box`).

    Blocks of `_BLOCK` faces go through the same few in-place steps, on
    arrays laid out coordinate by coordinate. A block whose smallest |N|² is
    above ``clear`` has no face near the threshold or out of range (every
    edge component is at most the box's extent, so L² <= ``reach``); any other
    block is judged face by face, and its out-of-range and borderline faces
    are redone by `_careful`.
    """
    nf, nv, t = f.shape[0], vertices.shape[0], float(tol)
    with np.errstate(over="ignore", invalid="ignore"):
        span = box[1] - box[0]
        reach = float(span @ span)  # L² <= reach for every face
    hi = _band(t)[1]
    # |N|² above this clears a face: 1 + 2**-20 covers the rounding of reach and of each L²
    clear = max(_LO, hi * hi * reach * reach * (1 + 2.0**-20)) if reach < _HI else math.inf
    m = min(_BLOCK, nf)
    work = np.empty(24 * m)  # a block's working arrays, cut from one allocation per call
    corners = work[: 9 * m].reshape(m, 3, 3)  # face, corner (A, B, C), coordinate
    records = corners.reshape(-1).view(_RECORD).reshape(m, 3)  # the same memory, corner by corner
    edges = work[9 * m : 15 * m].reshape(2, 3, m)  # U = B - A, V = C - A, coordinate by coordinate
    normal, rows3 = work[15 * m : 18 * m].reshape(3, m), work[18 * m : 21 * m].reshape(3, m)
    nn, dot, aux = work[21 * m : 22 * m], work[22 * m : 23 * m], work[23 * m :]
    vertex_records = vertices.reshape(-1).view(_RECORD)  # vertex i as one record: no copy
    redo = []
    with np.errstate(all="ignore"):
        for s0 in range(0, nf, _BLOCK):
            s1 = min(s0 + _BLOCK, nf)
            k = s1 - s0
            index = f[s0:s1]
            if index.view(np.uintp).max() >= nv:  # a negative index, read as unsigned, is huge
                _raise_range_error(f, nv)
            c, (u, v), n, p = corners[:k], edges[:, :, :k], normal[:, :k], rows3[:, :k]
            q, d, r = nn[:k], dot[:k], aux[:k]
            np.take(vertex_records, index, 0, records[:k], "clip")
            np.subtract(c[:, 1:].transpose(1, 2, 0), c[:, 0].T, edges[:, :, :k])
            for row, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):  # N = U × V
                np.multiply(u[i], v[j], n[row])
                np.multiply(u[j], v[i], p[0])
                np.subtract(n[row], p[0], n[row])
            _dot(n, n, q, p)  # |N|²
            degenerate = None
            if not q.min() > clear:  # (or NaN) judge face by face: L² = max(|U|², |V|², |W|²)
                _dot(u, u, d, p)
                _dot(v, v, r, p)
                np.maximum(d, r, out=r)
                wv = c[:, 2].T - c[:, 1].T  # W = C - B
                _dot(wv, wv, d, p)
                np.maximum(d, r, out=r)
                ok, bad = _sure(q, r, t)
                degenerate = ~ok
                redo.append(s0 + np.flatnonzero(~((ok | bad) & (q > _LO) & (r < _HI))))
            if deg_out is not None:
                deg_out[s0:s1] = False if degenerate is None else degenerate
            np.sqrt(q, q)  # |N|
            if mag_out is not None:
                mag_out[s0:s1] = q
            if angles_out is not None:
                # angle at A: atan2(|N|, U·V); at B: atan2(|N|, |U|² - U·V); C: the rest of π
                ang = angles_out[s0:s1]
                _dot(u, v, d, p)
                np.arctan2(q, d, out=ang[:, 0])
                _dot(u, u, r, p)
                np.subtract(r, d, out=r)
                np.arctan2(q, r, out=ang[:, 1])
                np.add(ang[:, 0], ang[:, 1], out=r)
                np.subtract(math.pi, r, out=ang[:, 2])
            if unit_out is not None:
                rows = unit_out[s0:s1]
                np.divide(n, q, rows.T)  # N / |N|, correctly rounded, into the (F, 3) rows
                if degenerate is not None:
                    rows[degenerate] = 0.0
    at = np.concatenate(redo) if redo else np.empty(0, dtype=np.intp)
    if at.size == 0:
        return None
    with np.errstate(all="ignore"):
        unit, deg, mag, exp, angles = _careful(vertices, f[at], tol)
    if unit_out is not None:
        unit_out[at] = unit
    if deg_out is not None:
        deg_out[at] = deg
    if angles_out is not None:
        angles_out[at] = angles
    if mag_out is None:
        return None
    mag_out[at] = mag
    exps = np.zeros(nf, dtype=np.intp)
    exps[at] = exp
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
        Degeneracy threshold: a face is degenerate when ``|N| <= tol · L²``,
        L its longest edge (see `degenerate_faces`).

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
    t = _exact_tol(tol)
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
    """Which faces are degenerate: ``|N| <= tol · L²``, L the length of the longest edge.

    |N| / L² is at most sin 60° (an equilateral face has the most), so the test
    flags faces that are nearly collinear or that have one edge much shorter
    than the others, whichever corner is listed first and whichever way the
    face is wound. It does not depend on the mesh's scale or position. Faces
    so close to the threshold that float64 rounding could change the verdict
    are decided in exact arithmetic.

    Parameters
    ----------
    vertices, faces : array_like
        The mesh, as in `face_normals`.
    tol : float, default ``trinormal.tolerances.DEFAULT_TOL``
        Threshold on |N| / L²; ``0`` flags only faces whose exact N is zero
        (collinear or coincident corners).

    Returns
    -------
    ndarray of bool, shape (F,)
        True where the face has no trustworthy normal (`face_normals` gives it
        a zero row).

    Examples
    --------
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0]]
    >>> degenerate_faces(v, [[0, 1, 2], [0, 1, 3], [0, 0, 2]])
    array([False,  True,  True])

    A needle, one edge 1e-13 long, is degenerate in every order of its corners:

    >>> needle = [[0, 0, 0], [1, 0, 0], [0, 1e-13, 0]]
    >>> degenerate_faces(needle, [[0, 1, 2], [1, 2, 0], [2, 0, 1], [0, 2, 1]])
    array([ True,  True,  True,  True])

    The verdict does not change with the scale:

    >>> degenerate_faces(np.array(v) * 1e-150, [[0, 1, 2], [0, 1, 3]])
    array([False,  True])
    """
    t = _exact_tol(tol)
    v, f, _, box = _prepare(vertices, faces)
    out = np.empty(f.shape[0], dtype=bool)
    _face_rows(v, f, box, t, deg_out=out)
    return out


def face_areas(vertices: npt.ArrayLike, faces: npt.ArrayLike) -> FloatArray:
    """Area of every face, |N| / 2.

    Parameters
    ----------
    vertices, faces : array_like
        The mesh (shapes (V, 3) and (F, 3); see `face_normals`). Winding does
        not matter: an area is never negative.

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
    exps = _face_rows(v, f, box, _exact_tol(DEFAULT_TOL), mag_out=mag)
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
    vertices, faces : array_like
        The mesh, as in `face_normals`: each face adds its normal to its three
        corners, so its winding decides which way that normal points.
    weighting : {"angle", "area", "uniform"}, default "angle"
        How much each face counts at a vertex: its interior angle there
        (Thürmer and Wüthrich; independent of how the surface is
        triangulated), its area, or the same for every face.
    tol : float, default ``trinormal.tolerances.DEFAULT_TOL``
        Degenerate faces (see `degenerate_faces`) contribute nothing.

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
    t = _exact_tol(tol)
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
    distinct = _distinct_corners(g)
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
