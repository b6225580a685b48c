"""Which way a piece should face: cavities inside closed pieces, and open pieces that enclose.

* A closed piece inside another closed piece is a *cavity* when it lies inside an odd
  number of them: the wall of a hollow ball has an outer shell facing out and an inner
  shell facing into the hollow, away from the material. Its right winding is the
  other way from the piece around it: its enclosed volume is negative. Whether a
  piece lies inside another is the winding number of one point of it (the centre of
  its first face) with respect to the other (the sum of the solid angles of the
  other's faces, over 4π), after a test of their bounding boxes. Shells are assumed
  not to cross each other.
* An open piece (one with holes, no fin) *encloses a volume* when the caps that close
  its holes are less than `CAP_FRACTION` of the closed-over surface's area: a sphere
  with a small hole, or a cup (a hemisphere's cap is a third), but not a flat sheet
  or a terrain (a cap about as large as the piece itself, a half). Each hole is
  capped by a fan of triangles from the centre of its rim; the sign of the capped
  volume says which way the piece faces, as the enclosed volume of a closed one does.

Both work on the welded faces (`trinormal.mesh.welding`), coordinates divided by each
piece's power of two as `trinormal.mesh.repair` does for volumes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from trinormal.mesh._arrays import BoolArray, FloatArray, IntArray
from trinormal.mesh.topology import _HalfEdges, _Rims

__all__ = ["CAP_FRACTION"]

#: An open piece encloses a volume when its holes' caps are less than this share of the area
#: of the piece closed over its holes: a hemisphere's cap is 1/3 of it, a flat sheet's 1/2.
CAP_FRACTION: float = 0.4


def _norm_rows(p: FloatArray) -> FloatArray:
    out: FloatArray = np.sqrt(p[:, 0] * p[:, 0] + p[:, 1] * p[:, 1] + p[:, 2] * p[:, 2])
    return out


def _det_rows(p: FloatArray, q: FloatArray, s: FloatArray) -> FloatArray:
    out: FloatArray = (
        p[:, 0] * (q[:, 1] * s[:, 2] - q[:, 2] * s[:, 1])
        + p[:, 1] * (q[:, 2] * s[:, 0] - q[:, 0] * s[:, 2])
        + p[:, 2] * (q[:, 0] * s[:, 1] - q[:, 1] * s[:, 0])
    )
    return out


def _dot_rows(p: FloatArray, q: FloatArray) -> FloatArray:
    out: FloatArray = p[:, 0] * q[:, 0] + p[:, 1] * q[:, 1] + p[:, 2] * q[:, 2]
    return out


def _inside(point: FloatArray, corners: FloatArray) -> bool:
    """Whether ``point`` (3,) lies inside the closed surface of triangles ``corners`` (k, 3, 3).

    Both are already divided by a common power of two; the winding number is the sum
    of the triangles' solid angles seen from the point, over 4π (±1 inside, 0 outside).
    """
    a, b, c = (corners[:, k] - point for k in range(3))
    la, lb, lc = _norm_rows(a), _norm_rows(b), _norm_rows(c)
    below = la * lb * lc + _dot_rows(a, b) * lc + _dot_rows(a, c) * lb + _dot_rows(b, c) * la
    turns = 2.0 * np.arctan2(_det_rows(a, b, c), below)
    return bool(abs(float(turns.sum()) / (4.0 * np.pi)) > 0.5)


#: Pieces compared at once against the boxes that may hold them (`_box_holders`).
_HOLDER_BLOCK = 256


def _box_holders(which: IntArray, lo: FloatArray, hi: FloatArray) -> list[tuple[int, int]]:
    """Every pair ``(a, b)`` of pieces in ``which`` whose boxes hold: ``b``'s box holds ``a``'s.

    Pieces are taken in blocks in the order of their boxes' lowest x. The boxes that may
    hold a block's start at or before its last piece's lowest x and end at or after its
    first piece's highest x, so a block is compared with those alone: pieces side by side
    (a plate of parts, a voxel model) are never compared with the whole model.
    """
    order = which[np.argsort(lo[which, 0], kind="stable")]
    starts = lo[order, 0]
    pairs: list[tuple[int, int]] = []
    for i in range(0, order.size, _HOLDER_BLOCK):
        block = order[i : i + _HOLDER_BLOCK]
        reach = order[: np.searchsorted(starts, lo[block, 0].max(), side="right")]
        reach = reach[hi[reach, 0] >= hi[block, 0].min()]
        holds = np.ones((block.size, reach.size), dtype=bool)
        for k in range(3):
            holds &= lo[reach, k] <= lo[block, k, None]
            holds &= hi[block, k, None] <= hi[reach, k]
        ka, kb = np.nonzero(holds)
        a, b = block[ka], reach[kb]
        pairs += [(x, y) for x, y in zip(a.tolist(), b.tolist(), strict=True) if x != y]
    return pairs


def _cavities(
    v: FloatArray, f: IntArray, comp: IntArray, flip: BoolArray, solid: BoolArray, scale: FloatArray
) -> BoolArray:
    """Which pieces lie inside an odd number of the ``solid`` pieces (closed, with a volume).

    ``f`` are the welded faces, ``comp`` (F,) their pieces, ``flip`` (F,) the faces the
    consistent winding turns over, ``scale`` (C,) each piece's power of two.
    """
    nc = solid.size
    which = np.flatnonzero(solid)
    if which.size < 2:
        return np.zeros(nc, dtype=bool)
    kept = np.flatnonzero(comp >= 0)
    # every piece has a face: its faces are one run of the sorted order, lowest index first
    order = kept[np.argsort(comp[kept], kind="stable")]
    bounds = np.searchsorted(comp[order], np.arange(nc + 1))
    first = order[bounds[:-1]]
    lo = np.full((nc, 3), np.inf)
    hi = np.full((nc, 3), -np.inf)
    for k in range(3):  # each piece's box, corner by corner, over its run of faces
        corners = np.take(v, f[order, k], axis=0)
        lo = np.minimum(lo, np.minimum.reduceat(corners, bounds[:-1], axis=0))
        hi = np.maximum(hi, np.maximum.reduceat(corners, bounds[:-1], axis=0))
    depth = np.zeros(nc, dtype=np.intp)
    for a, b in _box_holders(which, lo, hi):
        s = max(float(scale[a]), float(scale[b]))
        corner = v[f[first[a]]] / s
        point = (corner[0] + corner[1] + corner[2]) / 3.0
        faces = order[bounds[b] : bounds[b + 1]]
        fb = f[faces].copy()
        turn = flip[faces]
        fb[turn, 1], fb[turn, 2] = f[faces[turn], 2], f[faces[turn], 1]
        if _inside(point, v[fb] / s):
            depth[a] += 1
    out: BoolArray = depth % 2 == 1
    return out


@dataclass(frozen=True)
class _Capped:
    """The open pieces closed over their holes, one entry per piece.

    ``encloses`` (C,): an open piece whose caps are less than `CAP_FRACTION` of the area
    and whose capped volume has a certain sign; ``volume`` and ``fixed`` (C,): six times
    the capped volume as wound now and after the consistent winding, over scale**3.
    """

    encloses: BoolArray
    volume: FloatArray
    fixed: FloatArray


def _capped(
    v: FloatArray,
    he: _HalfEdges,
    comp: IntArray,
    flip: BoolArray,
    candidate: BoolArray,
    scale: FloatArray,
    ref: FloatArray,
    rounding: int,
    rims: _Rims,
) -> _Capped:
    """Close each ``candidate`` piece over its holes and measure it (see the module docstring).

    ``ref`` (C, 3) is each piece's reference point (unscaled), ``rounding`` the volume
    rounding allowance of `trinormal.mesh.repair`, ``rims`` the loops of ``he``.
    """
    nc = candidate.size
    zero = np.zeros(nc)
    if not candidate.any():
        return _Capped(np.zeros(nc, dtype=bool), zero, zero)
    f = he.faces
    faces = np.flatnonzero((comp >= 0) & candidate[np.maximum(comp, 0)])
    c = comp[faces]
    s = scale[c][:, None]
    r = ref[c] / s
    p, q, t = (np.take(v, f[faces, k], axis=0) / s - r for k in range(3))
    det = _det_rows(p, q, t)
    sign = np.where(flip[faces], -1.0, 1.0)
    size = _norm_rows(p) * _norm_rows(q) * _norm_rows(t)
    area = _norm_rows(np.cross(q - p, t - p))

    # each loop's centre: the mean of its corners (every loop's; the candidates' are used)
    ns = scale[rims.node_piece][:, None]
    coords = v[rims.node_vertex] / ns - ref[rims.node_piece] / ns
    count = np.bincount(rims.loop)
    centre = np.stack(
        [np.bincount(rims.loop, weights=coords[:, k]) / count for k in range(3)], axis=1
    )
    # the rim edges of the candidate pieces, in half-edge order
    on = candidate[rims.piece]
    h, hc = rims.half_edges[on], rims.piece[on]
    a, b = he.start(h), he.end(h)
    m = centre[rims.loop[rims.start[on]]]
    hs = scale[hc][:, None]
    pa = v[a] / hs - ref[hc] / hs
    pb = v[b] / hs - ref[hc] / hs
    cap = _det_rows(m, pb, pa)  # the cap triangle (centre, b, a) walks the rim edge back
    cap_sign = np.where(flip[h // 3], -1.0, 1.0)
    cap_size = _norm_rows(m) * _norm_rows(pb) * _norm_rows(pa)
    cap_area = _norm_rows(np.cross(pb - m, pa - m))

    def total(at: IntArray, x: FloatArray) -> FloatArray:
        return np.bincount(at, weights=x, minlength=nc)[:nc].astype(np.float64)

    volume = total(c, det) + total(hc, cap)
    fixed = total(c, det * sign) + total(hc, cap * cap_sign)
    n_terms = np.bincount(c, minlength=nc)[:nc] + np.bincount(hc, minlength=nc)[:nc]
    sizes = total(c, size) + total(hc, cap_size)
    error = (rounding + n_terms) * np.finfo(np.float64).eps * sizes
    caps = total(hc, cap_area)
    encloses = candidate & (caps < CAP_FRACTION * (caps + total(c, area))) & (np.abs(fixed) > error)
    return _Capped(encloses, volume, fixed)
