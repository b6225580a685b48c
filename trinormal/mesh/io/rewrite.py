"""Writing a read file back: its own bytes, with only the turned-over faces' records changed.

A repaired file is the student's file with faces turned over, nothing else:
comments, groups, materials, texture coordinates, normals, colours, extra
properties, headers and attribute bytes stay as they were, in their order.
A face turned over keeps its first corner and lists the others in reverse
order, each corner with its own references (OBJ ``v/vt/vn``, a PLY face's
per-corner lists): ``f 1/1/1 2/2/1 3/3/1 4/4/1`` becomes
``f 1/1/1 4/4/1 3/3/1 2/2/1``, and its triangles are the ones `fix_winding`
gave. An STL facet's stored normal is recomputed for the facets turned over
(`trinormal.mesh.face_normals`); every other byte is the file's.

The page's JavaScript (``trinormal-mesh-write.js``) writes the same bytes.
"""

from __future__ import annotations

import struct
from typing import Any

import numpy as np

from trinormal.mesh._arrays import IntArray
from trinormal.mesh.io.errors import _decode
from trinormal.mesh.io.mesh_data import MeshData
from trinormal.mesh.io.ply import _STRUCT, _face_list_name, _ply_header
from trinormal.mesh.normals import face_normals

#: A binary STL record as raw bytes: normal, three corners, attribute bytes.
_STL_RAW = np.dtype([("n", "<f4", (3,)), ("a", "V12"), ("b", "V12"), ("c", "V12"), ("x", "V2")])


def _turned_polygons(m: MeshData, faces: IntArray) -> IntArray:
    """Which faces of the file ``faces`` turns over: most of its triangles are turned over.

    ``faces`` must be `MeshData.faces` with some triangles turned over (any odd order of
    the same corners); a polygon counts as turned over when more than half of its
    triangles are, or half and its first one.
    """
    if faces.shape != m.faces.shape:
        raise ValueError(
            f"write_mesh of a read model takes its {m.faces.shape[0]} triangles, "
            f"some turned over; got {faces.shape[0]}"
        )
    # columns compared one at a time, on every face: a (F, 3) .any(axis=1) is slow, and so
    # are the rows of the changed faces gathered
    f0, f1, f2 = faces[:, 0], faces[:, 1], faces[:, 2]
    g0, g1, g2 = m.faces[:, 0], m.faces[:, 1], m.faces[:, 2]
    first_same = f0 == g0
    changed = np.flatnonzero(~first_same | (f1 != g1) | (f2 != g2))
    # turned over: the corners in an odd order, (a, c, b), (c, b, a) or (b, a, c)
    odd = first_same & (f1 == g2) & (f2 == g1)
    odd |= (f0 == g2) & (f1 == g1) & (f2 == g0)
    odd |= (f0 == g1) & (f1 == g0) & (f2 == g2)
    wrong = changed[~odd[changed]]
    if wrong.size:
        row = int(wrong[0])
        raise ValueError(
            f"write_mesh of a read model only turns faces over: triangle {row} is "
            f"{faces[row].tolist()}, not {m.faces[row].tolist()} turned over"
        )
    if changed.size == 0 or m.n_polygons == m.faces.shape[0]:  # every face a triangle
        return changed.astype(np.intp)
    n = np.bincount(m.source_faces, minlength=m.n_polygons)
    k = np.bincount(m.source_faces[changed], minlength=m.n_polygons)
    first = np.zeros(m.n_polygons, dtype=bool)
    first_row = np.concatenate([[0], np.cumsum(n)[:-1]])
    flipped = np.zeros(m.faces.shape[0], dtype=bool)
    flipped[changed] = True
    first[n > 0] = flipped[first_row[n > 0]]
    out: IntArray = np.flatnonzero((2 * k > n) | ((2 * k == n) & first)).astype(np.intp)
    return out


def _rewrite(m: MeshData, faces: IntArray) -> bytes | bytearray:
    """Return the file of ``m`` with the faces ``faces`` turns over turned over."""
    turned = _turned_polygons(m, faces)
    if turned.size == 0 and m.stl_records is None:
        return m.source
    if m.format == "stl" and m.encoding == "binary":
        return _stl_binary(m, faces, turned)
    if m.format == "stl":
        return _text_rewrite(m.source, lambda text: _stl_ascii(text, m, faces, turned))
    if m.format == "obj":
        return _text_rewrite(m.source, lambda text: _obj(text, turned))
    return _ply(m, turned)


def _text_rewrite(data: bytes, edit: Any, start: int = 0) -> bytes:
    """Decode ``data[start:]`` as the readers do (UTF-8, else Latin-1), edit, encode back."""
    text, codec = _decode(data[start:])
    bom = "\ufeff" if text.startswith("\ufeff") else ""
    lines = text[len(bom) :].splitlines(keepends=True)
    edit(lines)
    return data[:start] + (bom + "".join(lines)).encode(codec)


def _content(line: str) -> tuple[str, str]:
    """Split a line into its text and its line break."""
    parts = line.splitlines()
    content = parts[0] if parts else ""
    return content, line[len(content) :]


def _spans(content: str) -> list[tuple[int, int]]:
    """Where each whitespace-separated token of the line starts and ends."""
    spans, at = [], 0
    for tok in content.split():
        at = content.index(tok, at)
        spans.append((at, at + len(tok)))
        at += len(tok)
    return spans


def _replaced(content: str, spans: list[tuple[int, int]], new: list[str]) -> str:
    """Replace token ``spans[i]`` of the line by ``new[i]``, keeping the spacing."""
    out, at = [], 0
    for (s, e), tok in zip(spans, new, strict=True):
        out += [content[at:s], tok]
        at = e
    return "".join(out) + content[at:]


def _reversed_corners(items: list[Any], per: int) -> list[Any]:
    """Corners of ``per`` items each, the first kept and the others in reverse order."""
    groups = [items[i : i + per] for i in range(0, len(items), per)]
    return [x for g in [groups[0], *groups[:0:-1]] for x in g]


# --------------------------------------------------------------------------- OBJ


def _obj(lines: list[str], turned: IntArray) -> None:
    """Turn over the ``f`` statements numbered ``turned`` (from 0), in place."""
    todo = set(turned.tolist())
    face = -1
    first: int | None = None
    logical = ""
    for i, line in enumerate(lines):
        content, end = _content(line)
        if content.endswith("\\"):  # continued on the next line, as the reader joins it
            first = i if first is None else first
            logical += content[:-1] + " "
            continue
        start = i if first is None else first
        whole = logical + content
        first, logical = None, ""
        code = whole.split("#", 1)[0]
        toks = code.split()
        if not toks or toks[0] not in ("f", "fo"):
            continue
        face += 1
        if face not in todo:
            continue
        turned_line = _replaced(whole, _spans(code), [toks[0], *_reversed_corners(toks[1:], 1)])
        for k in range(start, i):  # a continued statement becomes one line
            lines[k] = ""
        lines[i] = turned_line + end


# --------------------------------------------------------------------------- STL


def _stl_binary(m: MeshData, faces: IntArray, turned: IntArray) -> bytearray:
    """Return a binary STL with the facets ``turned`` turned over and their normals recomputed.

    Where only its header, normals and attribute bytes were kept (``stl_records``), every
    corner is ``vertices[faces]`` as float32, the number the file holds.
    """
    nf = faces.shape[0]
    if m.stl_records is None:  # the whole file was kept
        buf = bytearray(m.source)
        raw = np.frombuffer(buf, dtype=_STL_RAW, count=nf, offset=84)
        raw["b"][turned], raw["c"][turned] = raw["c"][turned], raw["b"][turned].copy()
    else:
        buf = bytearray(84 + 50 * nf + len(m.source) - 84)
        buf[:84] = m.source[:84]
        buf[84 + 50 * nf :] = m.source[84:]
        raw = np.frombuffer(buf, dtype=_STL_RAW, count=nf, offset=84)
        raw["n"], raw["x"] = m.stl_records["normal"], m.stl_records["attr"]
        corners = m.vertices.astype(np.float32).view("V12").reshape(-1)  # a corner's 12 bytes
        raw["a"], raw["b"], raw["c"] = (corners[faces[:, k]] for k in range(3))
    raw["n"][turned] = face_normals(m.vertices, np.take(faces, turned, axis=0)).astype(np.float32)
    return buf


def _stl_ascii(lines: list[str], m: MeshData, faces: IntArray, turned: IntArray) -> None:
    """Swap the last two vertex lines of the facets ``turned``; recompute their normals."""
    normals = dict(
        zip(turned.tolist(), face_normals(m.vertices, faces[turned]).tolist(), strict=True)
    )
    facet = -1
    facet_line: int | None = None
    loop: list[int] = []
    for i, line in enumerate(lines):
        toks = line.split()
        kw = toks[0].lower() if toks else ""
        if kw == "facet":
            facet_line = i
        elif kw == "outer":
            loop = []
        elif kw == "vertex":
            loop.append(i)
        elif kw == "endloop":
            facet += 1
            if facet in normals:
                (b, eb), (c, ec) = _content(lines[loop[1]]), _content(lines[loop[2]])
                lines[loop[1]], lines[loop[2]] = c + eb, b + ec
                if facet_line is not None:
                    _set_normal(lines, facet_line, normals[facet])
            facet_line = None


def _set_normal(lines: list[str], i: int, normal: list[float]) -> None:
    """Write ``normal`` over the three numbers of a ``facet normal x y z`` line."""
    content, end = _content(lines[i])
    spans = _spans(content)
    if len(spans) < 5:
        return  # no stored normal to recompute
    toks = [content[s:e] for s, e in spans]
    toks[2:5] = [repr(x) for x in normal]
    lines[i] = _replaced(content, spans, toks) + end


# --------------------------------------------------------------------------- PLY


def _ply(m: MeshData, turned: IntArray) -> bytes:
    fmt, elements, body_start, _ = _ply_header(m.source, m.path)
    face_at = next(k for k, el in enumerate(elements) if el.name == "face")
    face = elements[face_at]
    want = _face_list_name(face)
    if fmt == "ascii":
        before = sum(el.count for el in elements[:face_at])
        return _text_rewrite(
            m.source, lambda lines: _ply_ascii(lines, before, face, want, turned), body_start
        )
    order = "<" if "little" in fmt else ">"
    return _ply_binary(m.source, body_start, elements, face_at, want, order, turned)


def _ply_ascii(
    lines: list[str], before: int, face: Any, want: str | None, turned: IntArray
) -> None:
    for row in turned.tolist():
        content, end = _content(lines[before + row])
        spans = _spans(content)
        toks = [content[s:e] for s, e in spans]
        lists, t = [], 0
        for pname, _ptype, ctype in face.props:
            if ctype is None:
                t += 1
                continue
            n = int(toks[t])
            lists.append((pname, t + 1, n))
            t += 1 + n
        _turn_lists(toks, lists, want)
        lines[before + row] = _replaced(content, spans, toks) + end


def _turn_lists(items: list[Any], lists: list[tuple[str, int, int]], want: str | None) -> None:
    """Turn over a face's corner list and every list with a whole number of items per corner."""
    corners = next(n for pname, _, n in lists if pname == want)
    for _pname, at, n in lists:
        if n and corners >= 3 and n % corners == 0:
            items[at : at + n] = _reversed_corners(items[at : at + n], n // corners)


def _ply_binary(
    data: bytes,
    pos: int,
    elements: list[Any],
    face_at: int,
    want: str | None,
    order: str,
    turned: IntArray,
) -> bytes:
    for el in elements[:face_at]:
        pos = _skip_rows(data, pos, el, order, el.count)
    buf = bytearray(data)
    row = 0
    for target in turned.tolist():
        pos = _skip_rows(data, pos, elements[face_at], order, target - row)
        row = target
        items, lists, at = [], [], pos  # the row's values as bytes, as _ply_ascii has its tokens
        for pname, ptype, ctype in elements[face_at].props:
            size = np.dtype(ptype).itemsize
            if ctype is None:
                items.append(data[at : at + size])
                at += size
                continue
            (n,) = struct.unpack_from(order + _STRUCT[ctype], data, at)
            items.append(data[at : at + np.dtype(ctype).itemsize])
            at += np.dtype(ctype).itemsize
            lists.append((pname, len(items), n))
            items += [data[at + size * i : at + size * (i + 1)] for i in range(n)]
            at += n * size
        _turn_lists(items, lists, want)
        buf[pos:at] = b"".join(items)
    return bytes(buf)


def _skip_rows(data: bytes, pos: int, el: Any, order: str, rows: int) -> int:
    """Return the offset after ``rows`` rows of element ``el`` starting at ``pos``."""
    if el.fixed:
        return pos + rows * sum(int(np.dtype(t).itemsize) for _, t, _ in el.props)
    for _ in range(rows):
        for _pname, ptype, ctype in el.props:
            if ctype is None:
                pos += np.dtype(ptype).itemsize
                continue
            (n,) = struct.unpack_from(order + _STRUCT[ctype], data, pos)
            pos += np.dtype(ctype).itemsize + n * np.dtype(ptype).itemsize
    return pos
