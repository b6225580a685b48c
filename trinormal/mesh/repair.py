"""Repairing a mesh's winding: every piece wound one way, closed pieces facing out.

Two neighbouring faces agree when they walk their shared edge in opposite
directions. `fix_winding` turns faces over (it swaps a face's last two
corners, so ``(a, b, c)`` becomes ``(a, c, b)`` and its normal is exactly
negated) until every piece agrees with itself, flipping as few faces as
possible; then it turns a closed piece whose normals point inward (its
enclosed volume is negative) inside out.

Only edges shared by exactly two faces carry a verdict: a boundary edge has
no neighbour, and an edge shared by three faces or more cannot be walked once
each way by all of them. A piece that cannot be wound consistently at all,
like a Möbius strip, is left as it is.

`fix_winding` and `signed_volume` take a mesh as `trinormal.mesh.face_normals`
does: ``vertices``, shape (V, 3), and ``faces``, shape (F, 3), vertex indices in
winding order; `turn_over` turns chosen faces over (the report's faces to flip,
say) and needs the faces only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from trinormal.mesh import shells, welding
from trinormal.mesh._arrays import BoolArray, FloatArray, IntArray, _check_faces, _check_vertices
from trinormal.mesh.topology import _components, _HalfEdges, _Rims, _rims

__all__ = ["fix_winding", "signed_volume", "turn_over"]

#: Rounding allowance of the enclosed-volume sign, in units of the float64
#: epsilon times the sum of |a|·|b|·|c| over the piece's faces (plus one unit
#: per face, for the summation): a volume within it has no trustworthy sign.
_VOLUME_ROUNDING = 8


@dataclass(frozen=True)
class _Winding:
    """How the faces are wound now, piece by piece, and what `fix_winding` flips.

    ``component`` (F,) is the piece of each face (-1: a face using one vertex
    twice); the per-piece arrays have one entry per piece.
    """

    component: IntArray
    closed: BoolArray
    orientable: BoolArray
    inconsistent: IntArray  # (C,) edges walked the same way by both faces
    volume: FloatArray  # (C,) six times the enclosed volume, as wound now, over scale**3
    volume_error: FloatArray  # (C,) its rounding bound, in the same unit
    scale: FloatArray  # (C,) the power of two each piece's coordinates were divided by
    flip: BoolArray  # (F,) what fix_winding flips
    inconsistent_pairs: tuple[IntArray, IntArray]  # half-edges of those edges
    solid: BoolArray  # (C,) closed, orientable, its volume's sign certain: judged by it
    cavity: BoolArray  # (C,) a solid piece inside an odd number of solid pieces
    encloses: BoolArray  # (C,) an open piece judged by its volume closed over its holes
    capped_volume: FloatArray  # (C,) six times that volume as wound now, over scale**3
    rims: _Rims  # the holes' rims, loop by loop

    @property
    def n_components(self) -> int:
        return int(self.closed.shape[0])

    def enclosed_volume(self, piece: int) -> float:
        """Return the enclosed volume of one piece, in the coordinates' unit cubed."""
        return _unscaled(float(self.volume[piece]) / 6.0, float(self.scale[piece]))


def _winding(v: FloatArray, he: _HalfEdges) -> _Winding:
    f = he.faces
    nf = f.shape[0]
    comp = he.face_components
    nc = int(comp.max()) + 1 if comp.size and comp.max() >= 0 else 0
    kept = comp >= 0

    # closed: no edge of the piece is a boundary or is shared by three faces or more
    edge_comp = comp[he.order[he.starts] // 3]
    open_edges = np.bincount(edge_comp[he.counts != 2], minlength=nc)
    boundary_edges = np.bincount(edge_comp[he.counts == 1], minlength=nc)
    closed = open_edges[:nc] == 0

    # neighbours across edges shared by exactly two faces: agree or disagree?
    h1, h2 = he.manifold_pairs
    same = he.start(h1) == he.start(h2)  # both walk the edge the same way: one is flipped
    f1, f2 = h1 // 3, h2 // 3
    inconsistent = np.bincount(comp[f1[same]], minlength=nc)[:nc]

    # two copies of every face, as it is and turned over: agreeing neighbours join like
    # with like, disagreeing ones join each to the other's copy. Faces that agree with a
    # neighbour stay together in both copies, so the copies are made of the patches of
    # agreeing faces (numbered by their first faces, as-is copies before turned ones:
    # the pieces of the copies are numbered as the faces' copies would be)
    patch = _components(nf, f1[~same], f2[~same])
    n_patches = int(patch.max()) + 1 if nf else 0
    p1, p2 = patch[f1[same]], patch[f2[same]]
    label = _components(
        2 * n_patches,
        np.concatenate([p1, p1 + n_patches]),
        np.concatenate([p2 + n_patches, p2]),
    )
    del p1, p2
    as_is, turned = label[patch], label[patch + n_patches]
    del patch, label
    orientable_face = as_is != turned
    orientable = np.ones(nc, dtype=bool)
    orientable[comp[kept & ~orientable_face]] = False
    # keep the side where more faces stay as they are (ties: the side of the first face)
    count = np.bincount(as_is[kept], minlength=2 * nf)
    keep_as_is, keep_turned = count[as_is], count[turned]
    flip = (keep_turned > keep_as_is) | ((keep_turned == keep_as_is) & (turned < as_is))
    flip &= kept
    flip[kept] &= orientable[comp[kept]]

    # six times the enclosed volume of each piece: sum of a · (b × c), measured from
    # one vertex of the piece (the volume of a closed surface does not depend on it)
    idx = np.flatnonzero(kept)
    first_face = np.full(nc, nf, dtype=np.intp)
    np.minimum.at(first_face, comp[idx], idx)
    ref = v[f[first_face, 0]] if nc else np.empty((0, 3))
    scale = _piece_scales(v, f, idx, comp, nc)
    det, size = _volume_terms(v, f, idx, ref, comp, scale)
    volume = np.bincount(comp[idx], weights=det, minlength=nc)[:nc].astype(np.float64)
    n_in = np.bincount(comp[idx], minlength=nc)[:nc]
    error = (
        (_VOLUME_ROUNDING + n_in)
        * np.finfo(np.float64).eps
        * np.bincount(comp[idx], weights=size, minlength=nc)[:nc]
    )
    # after the consistent winding, a closed piece that encloses negative volume turns over,
    # unless it is a cavity (shells.py); so does an open piece whose capped volume is negative
    sign = np.where(flip[idx], -1.0, 1.0)
    fixed = np.bincount(comp[idx], weights=det * sign, minlength=nc)[:nc]
    solid = closed & orientable & (np.abs(fixed) > error)
    cavity = shells._cavities(v, f, comp, flip, solid, scale)
    open_piece = ~closed & (open_edges[:nc] == boundary_edges[:nc]) & orientable
    rims = _rims(he)
    cap = shells._capped(v, he, comp, flip, open_piece, scale, ref, _VOLUME_ROUNDING, rims)
    inward = (solid & ((fixed < 0) != cavity)) | (cap.encloses & (cap.fixed < 0))
    flip[idx] ^= inward[comp[idx]]
    return _Winding(
        component=comp,
        closed=closed,
        orientable=orientable,
        inconsistent=inconsistent,
        volume=volume,
        volume_error=error,
        scale=scale,
        flip=flip,
        inconsistent_pairs=(h1[same], h2[same]),
        solid=solid,
        cavity=cavity,
        encloses=cap.encloses,
        capped_volume=cap.volume,
        rims=rims,
    )


#: Faces `_volume_terms` works on at a time: its (block, 3) coordinate arrays stay small.
_VOLUME_BLOCK = 1 << 16


def _piece_scales(v: FloatArray, f: IntArray, idx: IntArray, comp: IntArray, nc: int) -> FloatArray:
    """For each piece, the largest power of two not above its largest |coordinate| (0: 0.5).

    Dividing by it is exact in binary (short of subnormal results) and brings every
    coordinate of the piece within (-2, 2): whatever the mesh's scale, the triple
    products of `_volume_terms` cannot overflow, the piece's volume does not vanish
    in underflow, and the sum keeps the sign its rounding bound vouches for.
    """
    largest = np.zeros(nc)
    if idx.size:
        a = np.abs(v)
        at_vertex = np.maximum(np.maximum(a[:, 0], a[:, 1]), a[:, 2])
        fi = f if idx.size == f.shape[0] else f[idx]
        corner = np.maximum(
            np.maximum(at_vertex[fi[:, 0]], at_vertex[fi[:, 1]]), at_vertex[fi[:, 2]]
        )
        np.maximum.at(largest, comp[idx], corner)
    _, exponent = np.frexp(largest)
    scale: FloatArray = np.ldexp(1.0, exponent - 1)
    return scale


def _unscaled(x: float, scale: float) -> float:
    """``x * scale**3`` as three products in turn, as the page's JavaScript takes it.

    ``scale`` is a power of two, so each product is exact unless it leaves the float
    range: the result is ±inf only where the true value overflows, 0.0 (or a subnormal)
    where it underflows, and never NaN.
    """
    return x * scale * scale * scale


def _volume_terms(
    v: FloatArray, f: IntArray, idx: IntArray, ref: FloatArray, comp: IntArray, scale: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """For faces ``idx``: a · (b × c) and |a|·|b|·|c|, corners measured from their piece's ``ref``.

    Every coordinate is first divided by its piece's ``scale`` (`_piece_scales`): the
    results are the true ones over ``scale**3``. A block of faces at a time; each face's
    two numbers do not depend on the blocks, and the sums over a piece are taken by the
    caller, over all faces at once.
    """
    det = np.empty(idx.size)
    size = np.empty(idx.size)
    for lo in range(0, idx.size, _VOLUME_BLOCK):
        blk = idx[lo : lo + _VOLUME_BLOCK]
        piece = comp[blk]
        c = scale[piece][:, None]
        r = np.take(ref, piece, axis=0) / c  # rows by np.take, which copies whole rows at once
        p = np.take(v, f[blk, 0], axis=0) / c - r
        q = np.take(v, f[blk, 1], axis=0) / c - r
        s = np.take(v, f[blk, 2], axis=0) / c - r
        det[lo : lo + blk.size] = shells._det_rows(p, q, s)
        size[lo : lo + blk.size] = (
            shells._norm_rows(p) * shells._norm_rows(q) * shells._norm_rows(s)
        )
    return det, size


def fix_winding(
    vertices: npt.ArrayLike, faces: npt.ArrayLike, weld: float | bool = False
) -> tuple[IntArray, IntArray]:
    """Wind every piece of a mesh consistently, and pieces that enclose a volume outward.

    Parameters
    ----------
    vertices, faces : array_like
        The mesh. Faces agree or disagree across the edges they share, corners
        at one position being one corner (`trinormal.mesh.welding`); the
        coordinates tell outward from inward.
    weld : float or bool, default False
        Boundary corners closer than this are one corner too (never less than
        ``WELD_AUTO`` times the model's size; 0: only corners at one position);
        True: the distance the report's near miss suggests. See `trinormal.mesh.check`.

    Returns
    -------
    faces : ndarray of int, shape (F, 3)
        The same faces in the same order, some turned over: ``(a, b, c)``
        becomes ``(a, c, b)``.
    flipped : ndarray of int
        The indices of the faces turned over, sorted.

    Notes
    -----
    A mesh already wound consistently and outward comes back unchanged, and
    fixing a fixed mesh changes nothing. Within a piece the side that needs
    fewer flips wins; then a closed piece faces out of its material (a cavity
    inside another closed piece faces into the cavity), and so does an open
    piece that mostly encloses a volume (a cup, a sphere with a hole, judged
    closed over its holes: `trinormal.mesh.shells`). An open piece that
    encloses nothing (a sheet, a terrain) has no inside to face away from,
    and a closed piece whose volume is too small for its sign to be trusted
    (a flat, doubled sheet) is only made consistent.

    Examples
    --------
    A cube with two faces turned over: exactly those two come back.

    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> bad = f.copy()
    >>> bad[[3, 8]] = bad[[3, 8]][:, [0, 2, 1]]
    >>> fixed, flipped = fix_winding(v, bad)
    >>> flipped
    array([3, 8])
    >>> bool((fixed == f).all())
    True

    An inside-out cube is turned over whole:

    >>> fixed, flipped = fix_winding(v, f[:, [0, 2, 1]])
    >>> len(flipped), bool((fixed == f).all())
    (12, True)
    """
    v, _ = _check_vertices(vertices)
    f = _check_faces(faces, v.shape[0])
    w = _winding(v, welding.weld(v, f, weld).half_edges)
    flipped = np.flatnonzero(w.flip).astype(np.intp)
    return turn_over(f, flipped), flipped


def turn_over(faces: npt.ArrayLike, which: npt.ArrayLike) -> IntArray:
    """Turn some faces over: ``(a, b, c)`` becomes ``(a, c, b)``, so each normal is negated.

    The face keeps its first corner and lists the other two the other way round, as
    `fix_winding` and ``trinormal mesh FILE --fix OUT`` turn faces over; the normal
    ``(B − A) × (C − A)`` of the face turned over is exactly minus the one before.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle, in winding order.
    which : array_like of int, shape (k,)
        The indices of the faces to turn over, in any order (``MeshReport.faces_to_flip``,
        say); a face listed twice is turned over once. For a boolean mask ``m`` of the
        faces, pass ``numpy.flatnonzero(m)``.

    Returns
    -------
    ndarray of int, shape (F, 3)
        A copy of ``faces`` with those faces turned over; the others as they were.

    Raises
    ------
    ValueError
        ``faces`` not of shape (F, 3), or ``which`` not face indices: the message names
        the first entry of ``which`` that is not a face.

    Examples
    --------
    >>> from trinormal.mesh import check, cube, face_normals
    >>> v, f = cube()
    >>> turn_over(f[:2], [1])
    array([[0, 2, 3],
           [0, 1, 3]])
    >>> bad = turn_over(f, [3, 8])
    >>> r = check(v, bad)
    >>> r.faces_to_flip, bool((turn_over(bad, r.faces_to_flip) == f).all())
    (array([3, 8]), True)
    >>> face_normals(v, turn_over(f, [0]))[0], face_normals(v, f)[0]
    (array([0., 0., 1.]), array([ 0.,  0., -1.]))
    """
    f = _check_faces(faces, None, check_range=False)
    w = np.asarray(which)
    if w.size == 0:
        return f.copy()
    if w.dtype.kind not in "iu":
        raise ValueError(
            f"which must hold face indices (integers), got dtype {w.dtype}"
            + ("; for a mask of the faces, pass numpy.flatnonzero(mask)" if w.dtype == bool else "")
        )
    if w.ndim != 1:
        raise ValueError(f"which must be a list of face indices, shape (k,), got shape {w.shape}")
    bad = np.flatnonzero((w < 0) | (w >= f.shape[0]))
    if bad.size:
        k = int(bad[0])
        raise ValueError(
            f"which[{k}] is face {int(w[k])}, but the valid face indices are 0 to {f.shape[0] - 1}"
            if f.shape[0]
            else f"which[{k}] is face {int(w[k])}, but there are no faces"
        )
    out = f.copy()
    out[w, 1], out[w, 2] = f[w, 2], f[w, 1]
    return out


def signed_volume(vertices: npt.ArrayLike, faces: npt.ArrayLike) -> float:
    """Compute the volume a closed surface encloses: negative if its normals point inward.

    It is the sum, over the faces, of the signed volumes of the tetrahedra
    each face makes with the first vertex. For a surface with holes the
    number depends on that choice and means little.

    Parameters
    ----------
    vertices, faces : array_like
        The mesh; turning every face over negates the result.

    Returns
    -------
    float
        The volume in the coordinates' unit cubed; 0.0 for no faces. It is
        computed on coordinates divided by a power of two, so it is never NaN:
        ``±inf`` only where the true volume is beyond the float range, 0.0 where
        it is below it, and its sign is right at any scale.

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> signed_volume(v, f), signed_volume(v, f[:, [0, 2, 1]])
    (8.0, -8.0)
    >>> signed_volume(v * 1e300, f), signed_volume(v * 1e-300, f)
    (inf, 0.0)
    """
    v, _ = _check_vertices(vertices)
    f = _check_faces(faces, v.shape[0])
    if f.shape[0] == 0:
        return 0.0
    idx = np.arange(f.shape[0])
    whole = np.zeros(f.shape[0], dtype=np.intp)  # the whole mesh as one piece
    scale = _piece_scales(v, f, idx, whole, 1)
    det, _ = _volume_terms(v, f, idx, v[f[:1, 0]], whole, scale)
    return _unscaled(float(det.sum()) / 6.0, float(scale[0]))
