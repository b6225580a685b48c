"""The normals a file stores, and the faces whose stored normal points against their winding.

A file may say which way each face faces besides its winding: an STL facet's
``normal``, an OBJ corner's ``vn``, a PLY vertex's ``nx ny nz``. A face's stored
normal is the facet normal, or the sum of its corners' normals (OBJ: zero if a
corner has none; PLY: summed over the corners of its triangles); a zero one
says nothing. It points *against* the winding when its dot
product with the face's area vector (the sum of its triangles' cross products)
is negative. A fix turns faces over but leaves OBJ and PLY normals as they are
(`trinormal.mesh.io.rewrite`), so the report counts the faces whose stored
normals disagree, before the fix and after it; an STL facet turned over gets its
normal recomputed and agrees.

The stored normals are read from `MeshData.source` when asked for, so reading a
file costs nothing more.
"""

from __future__ import annotations

import contextlib
from typing import TYPE_CHECKING

import numpy as np

from trinormal.mesh._arrays import FloatArray, IntArray
from trinormal.mesh.io.errors import _decode
from trinormal.mesh.io.obj import _statements

if TYPE_CHECKING:
    from trinormal.mesh.io.mesh_data import MeshData

#: A binary STL record: stored normal, three corners, attribute bytes.
_STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attr", "<u2")])


def stored_normals(m: MeshData) -> FloatArray | None:
    """Return each face's stored normal, shape (P, 3), or None when the file stores none."""
    if m.format == "stl" and m.encoding == "binary":
        if m.stl_records is None:
            rec = np.frombuffer(m.source, dtype=_STL_RECORD, count=m.n_polygons, offset=84)
            out: FloatArray = rec["normal"].astype(np.float64)
        else:
            out = m.stl_records["normal"].astype(np.float64)
        return out
    if m.format == "stl":
        return _stl_ascii(m.source)
    if m.format == "obj":
        return _obj(m.source, m.n_polygons) if b"vn" in m.source else None
    if m.vertex_normals is None:
        return None
    sums = np.zeros((m.n_polygons, 3))  # a PLY face: its triangles' corner normals, summed
    np.add.at(sums, m.source_faces, m.vertex_normals[m.faces].sum(axis=1))
    return sums


def against(m: MeshData, faces: IntArray, turned: IntArray | None = None) -> IntArray | None:
    """Return the faces of the file whose stored normal points against the winding of ``faces``.

    ``turned`` are the faces a fix turned over: in an STL file their normals are
    recomputed, so they never disagree. None when the file stores no normals.
    """
    if m.stl_against is not None:  # found while reading the records
        bad = np.zeros(m.n_polygons, dtype=bool)
        bad[m.stl_against] = True
    else:
        normals = stored_normals(m)
        if normals is None:
            return None
        if m.format == "stl" and m.encoding == "binary" and m.stl_records is None:
            # a facet not turned over has its corners as read, one turned over a new normal:
            # the corners straight from the records, in file order (no gather by vertex)
            dot = _stl_dots(m.source, m.n_polygons, normals)
        else:
            dot = _dots(m, m.faces if m.format == "stl" else faces, normals)
        bad = dot < 0
    if turned is not None and m.format == "stl":
        bad[turned] = False
    out: IntArray = np.flatnonzero(bad).astype(np.intp)
    return out


#: Triangles `_dots` works on at a time: its (block, 3) arrays stay small.
_BLOCK = 1 << 16


def _stl_dots(data: bytes, n: int, normals: FloatArray) -> FloatArray:
    """`_dots` for a binary STL as read, its corners taken from the records."""
    rec = np.frombuffer(data, dtype=_STL_RECORD, count=n, offset=84)
    dot = np.empty(n)
    with np.errstate(over="ignore", invalid="ignore"):
        for lo in range(0, n, _BLOCK):
            c = rec["corners"][lo : lo + _BLOCK]
            first = c[:, 0].astype(np.float64)
            u, w = c[:, 1] - first, c[:, 2] - first  # float64, as v[f] - v[f] would be
            nrm = normals[lo : lo + _BLOCK]
            # np.cross's terms, then the dot product's, in their order
            dot[lo : lo + _BLOCK] = (
                (u[:, 1] * w[:, 2] - u[:, 2] * w[:, 1]) * nrm[:, 0]
                + (u[:, 2] * w[:, 0] - u[:, 0] * w[:, 2]) * nrm[:, 1]
                + (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]) * nrm[:, 2]
            )
    return dot


def _dots(m: MeshData, faces: IntArray, normals: FloatArray) -> FloatArray:
    """Each face's area vector (its triangles' cross products, summed) · its stored normal."""
    v = m.vertices
    nf = faces.shape[0]
    triangles = nf == m.n_polygons
    area = None if triangles else np.zeros((m.n_polygons, 3))
    dot = np.empty(m.n_polygons)
    with np.errstate(over="ignore", invalid="ignore"):  # at 1e300 the sign is lost: no claim
        for lo in range(0, nf, _BLOCK):
            f = faces[lo : lo + _BLOCK]
            cross = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
            if area is None:
                dot[lo : lo + _BLOCK] = (cross * normals[lo : lo + _BLOCK]).sum(axis=1)
            else:
                np.add.at(area, m.source_faces[lo : lo + _BLOCK], cross)
        if area is not None:
            dot = (area * normals).sum(axis=1)
    return dot


def _lines(data: bytes) -> list[str]:
    return _decode(data)[0].removeprefix("\ufeff").splitlines()


def _stl_ascii(data: bytes) -> FloatArray:
    """Each facet's ``facet normal x y z`` (zero when a facet has none)."""
    out: list[tuple[float, float, float]] = []
    current = (0.0, 0.0, 0.0)
    for line in _lines(data):
        toks = line.split()
        kw = toks[0].lower() if toks else ""
        if kw == "facet":
            current = (0.0, 0.0, 0.0)
            if len(toks) >= 5 and toks[1].lower() == "normal":
                with contextlib.suppress(ValueError):  # not numbers: no claim
                    current = (float(toks[2]), float(toks[3]), float(toks[4]))
        elif kw == "endloop":
            out.append(current)
            current = (0.0, 0.0, 0.0)
    return np.array(out, dtype=np.float64).reshape(-1, 3)


def _obj(data: bytes, n_polygons: int) -> FloatArray | None:
    """Each ``f`` statement's sum of its corners' ``vn`` normals (zero when one has none)."""
    vn: list[tuple[float, float, float]] = []
    out = np.zeros((n_polygons, 3))
    face = -1
    for _, toks in _statements(_lines(data)):
        if toks[0] == "vn" and len(toks) >= 4:
            try:
                vn.append((float(toks[1]), float(toks[2]), float(toks[3])))
            except ValueError:
                vn.append((0.0, 0.0, 0.0))
        elif toks[0] in ("f", "fo"):
            face += 1
            total = np.zeros(3)
            for tok in toks[1:]:
                refs = tok.split("/")
                k = _index(refs[2], len(vn)) if len(refs) >= 3 else None
                if k is None:
                    total[:] = 0.0
                    break
                total += vn[k]
            out[face] = total
    return out if vn else None


def _index(ref: str, count: int) -> int | None:
    """Turn a ``vn`` reference (from 1, or back from the last so far) into an index, or None."""
    try:
        i = int(ref)
    except ValueError:
        return None
    k = i - 1 if i > 0 else count + i
    return k if 0 <= k < count and i != 0 else None
