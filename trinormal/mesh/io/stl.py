"""STL files, text and binary: corners with exactly equal coordinates become one vertex.

Why, and in which order they are numbered: `trinormal.mesh.io`.
"""

from __future__ import annotations

import struct
from dataclasses import replace
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import FloatArray, IntArray, _grouped
from trinormal.mesh.io.errors import READ_NOTES, MeshFileError, _number, _show, _text
from trinormal.mesh.io.mesh_data import MeshData
from trinormal.mesh.io.stored import _STL_RECORD, _stl_dots
from trinormal.mesh.normals import face_normals


def _read_stl(data: bytes, name: str) -> MeshData:
    """Read a binary STL (its size follows from its triangle count) or a text one.

    A binary STL whose count disagrees with its size is read anyway when the
    bytes after the header say how many triangles it has (`_records_in`),
    with a note in `MeshData.notes`.
    """
    notes: tuple[str, ...] = ()
    if len(data) >= 84:
        (n,) = struct.unpack_from("<I", data, 80)
        if len(data) != 84 + 50 * n and not _looks_like_text(data):
            n, notes = _records_in(data, n, name)
        if len(data) == 84 + 50 * n or notes:  # binary, even when its header starts with "solid"
            rec = np.frombuffer(data, dtype=_STL_RECORD, count=n, offset=84)
            # float32, as stored: merged before widening
            corners = rec["corners"].reshape(-1, 3)
            if not np.isfinite(corners).all():
                bad = int(np.flatnonzero(~np.isfinite(corners).all(axis=1))[0]) // 3
                raise MeshFileError.of(name, "stl_not_finite", triangle=bad + 1)
            merged = _merge_corners(corners, name, "binary")
            return replace(merged, notes=notes, **_kept(data, rec, corners))
    if not _looks_like_text(data):
        raise MeshFileError.of(name, "stl_short")
    return _read_stl_ascii(data, name)


#: A binary STL record's stored normal and attribute bytes, as raw bytes.
_KEPT = np.dtype([("normal", "<f4", (3,)), ("attr", "V2")])


def _kept(data: bytes, rec: Any, corners: Any) -> dict[str, Any]:
    """Keep what `write_mesh` needs to write a binary STL back (source, stl_records).

    Its corners are the read vertices, exactly, unless one is -0.0 (read as 0.0): then
    the whole file is kept; else its header and trailing bytes, and each record's
    normal and attribute bytes (14 bytes of 50). The facets whose stored normal points
    against their winding are found here, from the records in file order.
    """
    n = rec.shape[0]
    if np.signbit(corners[corners == 0]).any():
        return {"source": data}
    raw = np.frombuffer(data, dtype=np.uint8, count=50 * n, offset=84).reshape(n, 50)
    kept = np.empty((n, 14), dtype=np.uint8)  # plain byte columns copy fast
    kept[:, :12], kept[:, 12:] = raw[:, :12], raw[:, 48:]
    kept_records = kept.view(_KEPT).reshape(n)
    against = np.flatnonzero(_stl_dots(data, n, kept_records["normal"].astype(np.float64)) < 0)
    return {
        "source": data[:84] + data[84 + 50 * n :],
        "stl_records": kept_records,
        "stl_against": against.astype(np.intp),
    }


def _looks_like_text(data: bytes) -> bool:
    """Whether the file can be a text STL: it starts with 'solid' and has no NUL byte."""
    return data.lstrip()[:5].lower() == b"solid" and b"\0" not in data


def _records_in(data: bytes, n: int, name: str) -> tuple[int, tuple[str, ...]]:
    """How many triangles a binary STL whose size disagrees with its count ``n`` holds; the note.

    Lenient where the format allows: the bytes after the 84-byte header are
    whole 50-byte records (the count is then 0, as some programs write it, or
    wrong), or the ``n`` records the count gives and fewer than 50 bytes more.
    Any other size is not an STL file.
    """
    whole, extra = divmod(len(data) - 84, 50)
    if extra == 0 and whole > 0:
        note = READ_NOTES["stl_count"].format(
            count=f"{n:,}", records=f"{whole:,}", size=f"{len(data) - 84:,}"
        )
        return whole, (f"{name}: {note}",)
    if whole == n:  # and 0 < extra < 50
        word = "byte" if extra == 1 else "bytes"
        note = READ_NOTES["stl_trailing"].format(extra=extra, bytes=word)
        return n, (f"{name}: {note}",)
    raise MeshFileError.of(
        name, "stl_not_stl", count=f"{n:,}", expected=f"{84 + 50 * n:,}", size=f"{len(data):,}"
    )


def _read_stl_ascii(data: bytes, name: str) -> MeshData:
    """Read STL text: facets of exactly three vertices, keywords in any case."""
    text = _text(data, name, "STL")
    corners: list[float] = []
    in_loop = False
    loop_count = 0
    loop_line = 0
    lineno = 0
    for line in text.splitlines():
        lineno += 1
        toks = line.split()
        if not toks:
            continue
        kw = toks[0].lower()
        if kw == "vertex":
            if not in_loop:
                raise MeshFileError.of(name, "stl_vertex_outside", lineno)
            if len(toks) != 4:
                raise MeshFileError.of(name, "stl_vertex", lineno)
            corners += (_number(t, name, lineno) for t in toks[1:])
            loop_count += 1
        elif kw == "outer":
            in_loop, loop_count, loop_line = True, 0, lineno
        elif kw == "endloop":
            if not in_loop:
                raise MeshFileError.of(name, "stl_endloop", lineno)
            if loop_count != 3:
                raise MeshFileError.of(name, "stl_facet", lineno, start=loop_line, count=loop_count)
            in_loop = False
        elif kw in ("solid", "endsolid", "facet", "endfacet"):
            if in_loop:
                raise MeshFileError.of(name, "stl_before_endloop", lineno, token=_show(toks[0]))
        else:
            raise MeshFileError.of(name, "stl_keyword", lineno, token=_show(toks[0]))
    if in_loop:
        raise MeshFileError.of(name, "stl_ends_in_facet", lineno)
    arr = np.array(corners, dtype=np.float64).reshape(-1, 3)
    return replace(_merge_corners(arr, name, "ascii"), source=data)


def _merge_corners(corners: FloatArray, name: str, encoding: str) -> MeshData:
    """Corners with exactly equal coordinates become one vertex, numbered by first use.

    ``corners`` (3F, 3) holds float32 (binary STL) or float64 (ASCII) numbers;
    they are compared as stored, by their bit patterns, and widened to float64
    only once merged.
    """
    corners = corners + corners.dtype.type(0)  # -0.0 becomes 0.0: equal numbers, one vertex
    n = corners.shape[0]
    if n == 0:
        empty = np.empty((0, 3), np.intp)
        return MeshData(np.empty((0, 3)), empty, "stl", encoding, np.empty(0, np.intp), 0, name)
    # the bit patterns as stored (4 bytes a number in a binary STL), widened only in the key
    bits: npt.NDArray[np.unsignedinteger[Any]] = corners.view(
        np.uint32 if corners.dtype == np.float32 else np.uint64
    )
    order, same = _grouped(bits)
    new = np.empty(n, dtype=bool)  # the first corner of each point, in sorted order
    new[0] = True
    np.logical_not(same, out=new[1:])
    del same
    starts = np.flatnonzero(new)
    first = order[starts]  # each point's first corner in the file (the groups are by index)
    del new
    is_first = np.zeros(n, dtype=bool)
    is_first[first] = True
    number = np.cumsum(is_first) - 1  # vertices numbered in the order of their first use
    index = np.empty(n, dtype=np.intp)
    index[order] = np.repeat(number[first], np.diff(np.append(starts, n)))
    vertices = corners[is_first].astype(np.float64)
    faces = index.reshape(-1, 3)
    nf = faces.shape[0]
    source = np.arange(nf, dtype=np.intp)
    return MeshData(vertices, faces, "stl", encoding, source, nf, name)


def _encode_stl(v: FloatArray, f: IntArray, enc: str) -> bytes | bytearray:
    """Write the mesh as STL, each face with its unit normal (zero for a degenerate face)."""
    normals = face_normals(v, f) if f.shape[0] else np.empty((0, 3))
    if enc == "binary":
        nf = f.shape[0]
        buf = bytearray(84 + _STL_RECORD.itemsize * nf)
        buf[:84] = b"binary STL written by trinormal".ljust(80, b" ") + struct.pack("<I", nf)
        rec = np.frombuffer(buf, dtype=_STL_RECORD, count=nf, offset=84)
        with np.errstate(over="ignore"):
            rec["normal"] = normals
            del normals
            for k in range(3):
                rec["corners"][:, k] = v[f[:, k]]
        return buf
    out = ["solid trinormal"]
    for n, tri in zip(normals.tolist(), v[f].tolist(), strict=True):
        out.append(f"facet normal {n[0]!r} {n[1]!r} {n[2]!r}")
        out.append("outer loop")
        out += [f"vertex {x!r} {y!r} {z!r}" for x, y, z in tri]
        out.append("endloop")
        out.append("endfacet")
    out.append("endsolid trinormal")
    return ("\n".join(out) + "\n").encode()
