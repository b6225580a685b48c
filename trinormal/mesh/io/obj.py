"""OBJ files, always text: every vertex and every face in file order.

Vertex numbers start at 1; a negative one counts back from the last vertex so
far. Statements that carry no triangle (texture coordinates, normals, groups,
materials, curves) are skipped; anything else is an error on its line.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import FloatArray, IntArray
from trinormal.mesh.io.errors import MeshFileError, _show, _text
from trinormal.mesh.io.mesh_data import MeshData, _plural, _polygon_mesh

# OBJ statements that carry no triangle (texture, normals, grouping, materials, curves)
_OBJ_IGNORED = frozenset(
    {"vt", "vn", "vp", "g", "o", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "l", "p"}
    | {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole"}
    | {"scrv", "sp", "end", "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj"}
    | {"trace_obj", "ctech", "stech", "call", "csh"}
)


def _read_obj(data: bytes, name: str) -> MeshData:
    """Read OBJ text: plain lines in one go (`_read_plain`), else line by line (`_read_lines`).

    Every file with an error is read line by line, which names the line.
    """
    plain = _read_plain(data)
    if plain is None:
        return _read_lines(data, name)
    vertices, faces = plain
    nf = faces.shape[0]
    source = np.arange(nf, dtype=np.intp)
    return MeshData(vertices, faces, "obj", "ascii", source, nf, name, source=data)


def _read_plain(data: bytes) -> tuple[FloatArray, IntArray] | None:
    """Read an OBJ of plain lines with numpy, or return None to leave it to `_read_lines`.

    Plain lines are ``v x y z`` (three numbers), ``f a b c`` (three vertex
    numbers from 1 up, digits only), blank lines and whole-line ``#`` comments,
    in ASCII, separated by spaces or tabs, ending in LF or CRLF. The numbers of
    the ``v`` lines are read by one call of numpy's text parser, which reads a
    decimal with ``PyOS_string_to_double`` as Python's ``float`` does, and those
    of the ``f`` lines by another (`_numbers`), so the result is the one
    `_read_lines` gives. Whenever anything else appears, a number is not finite
    or a vertex number is out of range, the answer is None and `_read_lines`
    reads the file and finds the error.
    """
    if not data.isascii() or b"\\" in data:
        return None  # non-ASCII text, or a continued line
    if not data.endswith(b"\n"):
        data += b"\n"
    b = np.frombuffer(data, dtype=np.uint8)
    flags = np.equal(b, 10)  # one scratch array of a flag per byte, used three times
    lf = np.flatnonzero(flags)
    others = np.count_nonzero(np.less(b, 32, out=flags)) - lf.size  # tabs and CRs, or worse
    if others and others != data.count(b"\t") + data.count(b"\r\n"):
        return None  # a control character other than tab, or a CR that ends a line by itself
    # space[i + 1]: whether b[i] is a space (a byte up to 32); space[0] stands for the start
    space = np.empty(b.size + 1, dtype=bool)
    space[0] = True
    np.less_equal(b, 32, out=space[1:])
    begins = np.flatnonzero(np.greater(space[:-1], space[1:], out=flags))  # a space, then not
    del flags
    # line k is b[bounds[k] + 1 : bounds[k + 1] + 1] and has the tokens begins[at[k] : at[k + 1]]
    bounds = np.concatenate(([-1], lf))
    at = np.searchsorted(begins, bounds)
    count = np.diff(at)
    lines = np.flatnonzero(count)  # the lines that are not blank
    heads = begins[at[lines]]  # where their first token begins
    del begins, at
    kw = b[heads]
    single = space[heads + 2]  # a space after the first letter
    vert, face = single & (kw == ord("v")), single & (kw == ord("f"))
    if not (vert | face | (kw == ord("#"))).all() or not (vert.any() or face.any()):
        return None
    if (count[lines[vert | face]] != 4).any():
        return None
    v = _numbers(b, bounds, lines, heads, vert, np.float64)
    f = _numbers(b, bounds, lines, heads, face, np.int64)
    if v is None or f is None or not np.isfinite(v).all():
        return None
    nv = v.size // 3
    if f.size and (f.min() < 1 or f.max() > nv):
        return None
    return v.reshape(-1, 3), (f - 1).astype(np.intp).reshape(-1, 3)


def _numbers(
    b: npt.NDArray[np.uint8],
    bounds: IntArray,
    lines: IntArray,
    heads: IntArray,
    mine: npt.NDArray[np.bool_],
    dtype: type,
) -> Any:
    """Read the three numbers after the keyword of each line ``lines[mine]``, or return None.

    The text read runs from the first of these lines to the last; their
    keywords (at ``heads[mine]``) and any other line between them are read as
    spaces. None when a token is not one number: numpy's text parser stops at
    it (and vertex numbers must be digits only, as its integer parser also
    reads a sign alone, or one apart from its digits).
    """
    if not mine.any():
        return np.empty(0, dtype=dtype)
    first, last = lines[mine][[0, -1]]
    start = bounds[first] + 1
    chars = b[start : bounds[last + 1] + 1].copy()
    chars[heads[mine] - start] = 32
    between = lines[~mine & (lines > first) & (lines < last)]  # comments, the other kind
    if between.size:
        blank = np.zeros(last + 1 - first, dtype=bool)
        blank[between - first] = True
        chars[np.repeat(blank, np.diff(bounds[first : last + 2]))] = 32
    text = chars.tobytes()
    del chars
    if dtype is np.int64 and text.translate(None, b"0123456789 \t\r\n"):
        return None  # not digits only
    try:
        out: npt.NDArray[Any] = np.fromstring(text, dtype=dtype, sep=" ")
    except ValueError:
        return None
    return out if out.size == 3 * np.count_nonzero(mine) else None


def _read_lines(data: bytes, name: str) -> MeshData:
    """Read OBJ text line by line, naming the line of any error."""
    text = _text(data, name, "OBJ")
    coords: list[float] = []
    polys: list[list[int]] = []
    poly_lines: list[int] = []
    nv = 0
    for lineno, toks in _statements(text.splitlines()):
        kw = toks[0]
        if kw == "v":
            if len(toks) < 4:
                raise MeshFileError.of(name, "obj_vertex", lineno)
            try:
                x, y, z = float(toks[1]), float(toks[2]), float(toks[3])
            except ValueError:
                bad = next(t for t in toks[1:4] if not _is_float(t))
                raise MeshFileError.of(name, "not_a_number", lineno, token=_show(bad)) from None
            if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(z)):
                bad = next(t for t in toks[1:4] if not math.isfinite(float(t)))
                raise MeshFileError.of(name, "not_finite", lineno, token=_show(bad))
            coords += (x, y, z)
            nv += 1
        elif kw == "f" or kw == "fo":
            if len(toks) < 4:
                raise MeshFileError.of(name, "obj_face_short", lineno)
            poly = []
            for tok in toks[1:]:
                ref = tok.split("/", 1)[0]
                try:
                    i = int(ref)
                except ValueError:
                    raise MeshFileError.of(name, "obj_index", lineno, token=_show(tok)) from None
                if i > 0:
                    poly.append(i - 1)
                elif i < 0:  # counted back from the last vertex so far
                    if -i > nv:
                        raise MeshFileError.of(
                            name,
                            "obj_back",
                            lineno,
                            index=i,
                            count=nv,
                            vertices=_plural(nv, "vertex"),
                        )
                    poly.append(nv + i)
                else:
                    raise MeshFileError.of(name, "obj_zero", lineno)
            polys.append(poly)
            poly_lines.append(lineno)
        elif kw not in _OBJ_IGNORED:
            raise MeshFileError.of(name, "obj_statement", lineno, token=_show(kw))
    if nv == 0 and not polys:
        raise MeshFileError.of(name, "obj_empty")
    for k, poly in enumerate(polys):  # vertex numbers may point forward; check at the end
        over = [i for i in poly if i >= nv]
        if over:
            raise MeshFileError.of(
                name,
                "obj_index_range",
                poly_lines[k],
                face=k + 1,
                index=over[0] + 1,
                count=nv,
                vertices=_plural(nv, "vertex"),
            )
    vertices = np.array(coords, dtype=np.float64).reshape(-1, 3)
    return _polygon_mesh(vertices, polys, "obj", "ascii", path=name, source=data)


def _statements(lines: list[str]) -> Iterator[tuple[int, list[str]]]:
    """Each statement's tokens and line (its last, from 1): continued lines joined, no comments."""
    pending = ""
    for lineno, raw in enumerate(lines, start=1):
        if raw.endswith("\\"):  # a continued line
            pending += raw[:-1] + " "
            continue
        toks = (pending + raw).split("#", 1)[0].split()
        pending = ""
        if toks:
            yield lineno, toks


def _is_float(tok: str) -> bool:
    try:
        float(tok)
    except ValueError:
        return False
    return True


def _encode_obj(v: FloatArray, f: IntArray) -> bytes:
    """Write the mesh as OBJ text: every coordinate as the shortest decimal that reads back."""
    lines = ["# written by trinormal"]
    lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
    lines += [f"f {a} {b} {c}" for a, b, c in (f + 1).tolist()]
    return ("\n".join(lines) + "\n").encode()
