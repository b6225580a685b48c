"""PLY files, text and binary (either byte order): vertices and faces in file order."""

from __future__ import annotations

import struct
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import FloatArray, IntArray
from trinormal.mesh.io.errors import READ_ERRORS, MeshFileError, _number, _show, _text
from trinormal.mesh.io.mesh_data import MeshData, _polygon_mesh

#: The PLY property types, by both their names, as numpy type codes.
_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}  # fmt: skip

#: The `struct` code of each PLY number type, for rows read one at a time.
_STRUCT = {"i1": "b", "u1": "B", "i2": "h", "u2": "H", "i4": "i", "u4": "I", "f4": "f", "f8": "d"}


@dataclass
class _Element:
    """One ``element`` of the header: its name, row count, properties and line."""

    name: str
    count: int
    props: list[tuple[str, str, str | None]]  # (name, type, list count type or None)
    line: int

    @property
    def fixed(self) -> bool:
        return all(c is None for _, _, c in self.props)


def _read_ply(data: bytes, name: str) -> MeshData:
    """Read a PLY file: its ``vertex`` element's x, y, z and its ``face`` element's lists."""
    fmt, elements, body_start, body_line = _ply_header(data, name)
    if fmt == "ascii":
        values = _ply_ascii(data, body_start, body_line, elements, name)
        encoding = "ascii"
    else:
        values = _ply_binary(data, body_start, elements, "<" if "little" in fmt else ">", name)
        encoding = "binary"
    vdata = values["vertex"]
    vertices = np.stack([np.asarray(vdata[a], dtype=np.float64) for a in "xyz"], axis=1)
    if not np.isfinite(vertices).all():
        bad = int(np.flatnonzero(~np.isfinite(vertices).all(axis=1))[0])
        raise MeshFileError.of(name, "ply_not_finite", vertex=bad)
    polys: list[list[Any]] | npt.NDArray[Any] = values.get("face", {}).get("_polys", [])
    normals = None
    if all(k in vdata for k in ("nx", "ny", "nz")):
        normals = np.stack([np.asarray(vdata[k], dtype=np.float64) for k in ("nx", "ny", "nz")], 1)
    _check_ply_faces(polys, vertices.shape[0], name)
    return _polygon_mesh(
        vertices, polys, "ply", encoding, path=name, source=data, vertex_normals=normals
    )


def _ply_header(data: bytes, name: str) -> tuple[str, list[_Element], int, int]:
    """Read the header: the format, the elements with their properties, where the rows begin.

    Returns the format, the elements, the byte offset of the first row and its
    line number (for a text file's errors).
    """
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise MeshFileError.of(name, "ply_not_ply", 1)
    nl = data.find(b"\n", end)
    body_start = len(data) if nl < 0 else nl + 1
    header = data[:end].decode("latin-1").splitlines()
    fmt: str | None = None
    elements: list[_Element] = []
    for lineno, line in enumerate(header, start=1):
        toks = line.split()
        if not toks or toks[0] in ("ply", "comment", "obj_info"):
            continue
        if toks[0] == "format":
            if len(toks) < 2 or toks[1] not in (
                "ascii",
                "binary_little_endian",
                "binary_big_endian",
            ):
                raise MeshFileError.of(name, "ply_format", lineno)
            fmt = toks[1]
        elif toks[0] == "element":
            if len(toks) != 3 or not (toks[2].isascii() and toks[2].isdigit()):  # not '²' '٣'
                raise MeshFileError.of(name, "ply_element", lineno)
            elements.append(_Element(toks[1], int(toks[2]), [], lineno))
        elif toks[0] == "property":
            if not elements:
                raise MeshFileError.of(name, "ply_property_first", lineno)
            if len(toks) == 5 and toks[1] == "list":
                if toks[2] not in _PLY_TYPES or toks[3] not in _PLY_TYPES:
                    raise MeshFileError.of(name, "ply_type", lineno)
                elements[-1].props.append((toks[4], _PLY_TYPES[toks[3]], _PLY_TYPES[toks[2]]))
            elif len(toks) == 3 and toks[1] in _PLY_TYPES:
                elements[-1].props.append((toks[2], _PLY_TYPES[toks[1]], None))
            else:
                raise MeshFileError.of(name, "ply_property", lineno, token=_show(line.strip()))
        else:
            raise MeshFileError.of(name, "ply_keyword", lineno, token=_show(toks[0]))
    if fmt is None:
        raise MeshFileError.of(name, "ply_no_format")
    vert = next((e for e in elements if e.name == "vertex"), None)
    if vert is None:
        raise MeshFileError.of(name, "ply_no_vertex")
    if not vert.fixed:
        raise MeshFileError.of(name, "ply_vertex_list", vert.line)
    for axis in "xyz":
        if not any(p[0] == axis and p[2] is None for p in vert.props):
            raise MeshFileError.of(name, "ply_no_axis", vert.line, axis=axis)
    return fmt, elements, body_start, len(header) + 2


def _check_ply_faces(polys: list[list[Any]] | npt.NDArray[Any], nv: int, name: str) -> None:
    """Check the face lists against the ``nv`` vertices: three corners or more, each in range.

    A list of a float type must hold whole numbers (a vertex 1.5 is out of range).
    """
    if isinstance(polys, np.ndarray):  # every face has the same number of corners
        if polys.shape[1] < 3:
            raise MeshFileError.of(name, "ply_corners", face=0, count=polys.shape[1])
        out_of_range = (polys < 0) | (polys >= nv) | (polys != np.floor(polys))
        if out_of_range.any():
            row = int(np.flatnonzero(out_of_range.any(axis=1))[0])
            _ply_range_error(name, row, polys[row][out_of_range[row]][0].item(), nv)
        return
    for row, poly in enumerate(polys):
        if len(poly) < 3:
            raise MeshFileError.of(name, "ply_corners", face=row, count=len(poly))
        outside = [i for i in poly if not (0 <= i < nv and float(i).is_integer())]
        if outside:
            _ply_range_error(name, row, outside[0], nv)


def _ply_range_error(name: str, k: int, index: float, nv: int) -> None:
    if isinstance(index, float) and index.is_integer():
        index = int(index)  # a whole number from a float list, written as the page writes it
    valid = READ_ERRORS["ply_valid"].format(last=nv - 1) if nv else READ_ERRORS["ply_no_vertices"]
    raise MeshFileError.of(name, "ply_index_range", face=k, index=index, valid=valid)


def _face_list_name(el: _Element) -> str | None:
    lists = [p[0] for p in el.props if p[2] is not None]
    for want in ("vertex_indices", "vertex_index"):
        if want in lists:
            return want
    return lists[0] if lists else None


def _ply_ascii(
    data: bytes, start: int, first_line: int, elements: list[_Element], name: str
) -> dict[str, dict[str, Any]]:
    text = _text(data[start:], name, "PLY")
    lines = text.splitlines()
    out: dict[str, dict[str, Any]] = {}
    pos = 0
    for el in elements:
        if pos + el.count > len(lines):
            raise MeshFileError.of(
                name,
                "ply_ascii_short",
                first_line + len(lines) - 1,
                rows=max(len(lines) - pos, 0),
                count=el.count,
                element=el.name,
            )
        rows = lines[pos : pos + el.count]
        if el.name not in ("vertex", "face"):
            pos += el.count
            continue
        if el.fixed:
            tokens = " ".join(rows).split()
            k = len(el.props)
            try:
                if len(tokens) != k * el.count:
                    raise ValueError
                arr = np.array(tokens, dtype=np.float64).reshape(el.count, k)
            except ValueError:
                _ply_bad_row(rows, k, first_line + pos, name)
            out[el.name] = {p[0]: arr[:, i] for i, p in enumerate(el.props)}
        else:
            want = _face_list_name(el) if el.name == "face" else None
            polys: list[list[int]] = []
            for r, row in enumerate(rows):
                toks = row.split()
                lineno = first_line + pos + r
                t = 0
                for pname, ptype, ctype in el.props:
                    try:
                        if ctype is None:
                            t += 1
                            continue
                        n = int(toks[t])
                        items = _ascii_list(toks[t + 1 : t + 1 + n], ptype, pname == want)
                        if len(items) != n or n < 0:
                            raise IndexError
                    except (ValueError, IndexError):
                        raise MeshFileError.of(name, "ply_row", lineno, element=el.name) from None
                    t += 1 + n
                    if pname == want:
                        polys.append(items)
                if t != len(toks):
                    raise MeshFileError.of(
                        name, "ply_too_many", lineno, element=el.name, count=len(toks) - t
                    )
            out[el.name] = {"_polys": polys}
        pos += el.count
    return out


def _ascii_list(toks: list[str], ptype: str, indices: bool) -> list[Any]:
    """Read a list property's items: numbers of its type; vertex indices must be whole."""
    if ptype not in ("f4", "f8"):
        return [int(x) for x in toks]
    values = [float(x) for x in toks]
    if not indices:
        return values
    if not all(x.is_integer() for x in values):
        raise ValueError("a vertex index that is not a whole number")
    return [int(x) for x in values]


def _ply_bad_row(rows: list[str], k: int, first: int, name: str) -> None:
    for r, row in enumerate(rows):
        toks = row.split()
        if len(toks) != k:
            raise MeshFileError.of(name, "ply_expected", first + r, count=k, found=len(toks))
        for tok in toks:
            _number(tok, name, first + r)
    raise MeshFileError.of(name, "ply_row", first, element="vertex")  # pragma: no cover


def _ply_binary(
    data: bytes, start: int, elements: list[_Element], order: str, name: str
) -> dict[str, dict[str, Any]]:
    out: dict[str, dict[str, Any]] = {}
    pos = start
    for el in elements:
        if el.fixed:
            dt = np.dtype([(p[0], order + p[1]) for p in el.props])
            size = dt.itemsize * el.count
            if pos + size > len(data):
                raise MeshFileError.of(
                    name,
                    "ply_binary_short",
                    element=el.name,
                    rows=(len(data) - pos) // max(dt.itemsize, 1),
                    count=el.count,
                )
            if el.name in ("vertex", "face"):
                arr = np.frombuffer(data, dtype=dt, count=el.count, offset=pos)
                out[el.name] = {p[0]: arr[p[0]] for p in el.props}
            pos += size
            continue
        want = _face_list_name(el) if el.name == "face" else None
        polys, pos = _ply_binary_lists(data, pos, el, order, want, name)
        if el.name == "face":
            out["face"] = {"_polys": polys}
    return out


def _ply_binary_lists(
    data: bytes, pos: int, el: _Element, order: str, want: str | None, name: str
) -> tuple[list[list[int]] | IntArray, int]:
    """Rows with list properties: every row the same length is read in one go, else row by row."""
    # fast path: guess that every list has the length of the first row's lists
    try:
        fields: list[Any] = []
        p = pos
        for pname, ptype, ctype in el.props:
            if ctype is None:
                fields.append((pname, order + ptype))
                p += np.dtype(ptype).itemsize
            else:
                (n,) = struct.unpack_from(order + _STRUCT[ctype], data, p)
                if n < 0:
                    raise struct.error  # a negative count: the rows one by one find the error
                fields.append((pname + "#n", order + ctype))
                fields.append((pname, order + ptype, (n,)))
                p += np.dtype(ctype).itemsize + n * np.dtype(ptype).itemsize
        dt = np.dtype(fields)
        if el.count and pos + dt.itemsize * el.count <= len(data):
            arr = np.frombuffer(data, dtype=dt, count=el.count, offset=pos)
            uniform = all(
                (arr[p[0] + "#n"] == dt[p[0]].shape[0]).all() for p in el.props if p[2] is not None
            )
            if uniform:
                table = arr[want] if want else np.empty((0, 3), np.intp)
                return table, pos + dt.itemsize * el.count
    except struct.error:
        pass
    polys: list[list[int]] = []
    for r in range(el.count):
        for pname, ptype, ctype in el.props:
            try:
                if ctype is None:
                    pos += np.dtype(ptype).itemsize
                    if pos > len(data):
                        raise struct.error
                    continue
                (n,) = struct.unpack_from(order + _STRUCT[ctype], data, pos)
                if n < 0:
                    raise MeshFileError.of(
                        name, "ply_negative", element=el.name, row=r, count=n
                    ) from None
                pos += np.dtype(ctype).itemsize
                items = struct.unpack_from(f"{order}{n}{_STRUCT[ptype]}", data, pos)
                pos += n * np.dtype(ptype).itemsize
            except struct.error:
                raise MeshFileError.of(
                    name, "ply_binary_row", element=el.name, row=r, count=el.count
                ) from None
            if pname == want:
                polys.append(list(items))
    return polys, pos


def _encode_ply(v: FloatArray, f: IntArray, enc: str) -> bytes:
    """Write the mesh as PLY: float32 coordinates when they all are float32 numbers, else double."""
    with np.errstate(over="ignore"):
        single = bool((v.astype(np.float32).astype(np.float64) == v).all())
    vtype = "float" if single else "double"
    head = [
        "ply",
        f"format {'ascii' if enc == 'ascii' else 'binary_little_endian'} 1.0",
        "comment written by trinormal",
        f"element vertex {v.shape[0]}",
        f"property {vtype} x",
        f"property {vtype} y",
        f"property {vtype} z",
        f"element face {f.shape[0]}",
        "property list uchar int vertex_indices",
        "end_header",
    ]
    header = ("\n".join(head) + "\n").encode()
    if enc == "ascii":
        body = [f"{x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
        body += [f"3 {a} {b} {c}" for a, b, c in f.tolist()]
        return header + ("\n".join(body) + "\n").encode()
    vbytes = v.astype("<f4" if single else "<f8").tobytes()
    fr = np.zeros(f.shape[0], dtype=[("n", "u1"), ("i", "<i4", (3,))])
    fr["n"] = 3
    fr["i"] = f
    return header + vbytes + fr.tobytes()
