"""OBJ files, always text: every vertex and every face in file order.

Vertex numbers start at 1; a negative one counts back from the last vertex so
far. Statements that carry no triangle (texture coordinates, normals, groups,
materials, curves) are skipped; anything else is an error on its line.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import FloatArray, IntArray
from trinormal.mesh.io.errors import MeshFileError, _show, _text
from trinormal.mesh.io.mesh_data import MeshData, _polygon_fields, _split

# OBJ statements that carry no triangle (texture, normals, grouping, materials, curves)
_OBJ_IGNORED = frozenset(
    {"vt", "vn", "vp", "g", "o", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "l", "p"}
    | {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole"}
    | {"scrv", "sp", "end", "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj"}
    | {"trace_obj", "ctech", "stech", "call", "csh"}
)


#: Tokens read at a time by `_numbers`: a (block, width) byte table of them stays small.
_TOKEN_BLOCK = 1 << 16

#: The longest number `_read_plain` reads; a longer token sends the file to `_read_lines`.
_MAX_TOKEN = 40


def _read_obj(data: bytes, name: str) -> MeshData:
    """Read OBJ text; polygons are split in their planes (`_split`).

    A file of plain lines only is read in one go by `_read_plain`; any other
    file, and every file with an error, line by line by `_read_lines`, which
    names the line.
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
    numbers from 1 up, no ``/``), blank lines and whole-line ``#`` comments,
    in ASCII, separated by spaces or tabs, ending in LF or CRLF. Each number is
    read by Python's own ``float`` and ``int`` (numpy's cast from bytes calls
    them), so the result is the one `_read_lines` gives; whenever anything
    else appears, or a number is not finite or out of range, the answer is
    None and `_read_lines` reads the file and finds the error.
    """
    if not data.isascii() or b"\\" in data or b"\x7f" in data:
        return None
    b = np.frombuffer(data, dtype=np.uint8)
    spaces = data.count(b"\n") + data.count(b"\t") + data.count(b"\r")
    if np.count_nonzero(b < 32) != spaces:
        return None  # a control character other than LF, CR and tab
    cr = np.flatnonzero(b == 13)
    if cr.size and (cr[-1] == b.size - 1 or (b[cr + 1] != 10).any()):
        return None  # a CR that ends a line by itself
    # +1 where a token starts, -1 right after it ends: starts and ends alternate
    edge = np.diff((b > 32).view(np.int8), prepend=np.int8(0), append=np.int8(0))
    bounds = np.flatnonzero(edge)
    starts, ends = bounds[0::2], bounds[1::2]
    del bounds
    # token starts and line ends in file order: a token right after a line end (or the
    # file's start) is its line's first
    events = np.flatnonzero((edge[:-1] == 1) | (b == 10))
    del edge
    after_lf = np.concatenate(([True], b[events[:-1]] == 10))
    first = after_lf[b[events] != 10]
    heads = np.flatnonzero(first)
    kw = b[starts[heads]]
    single = ends[heads] - starts[heads] == 1
    comment = kw == ord("#")
    vert, face = single & (kw == ord("v")), single & (kw == ord("f"))
    if not (vert | face | comment).all() or not (vert.any() or face.any()):
        return None
    if data.count(b"#") != np.count_nonzero(comment):
        return None  # a comment after a statement, or a second '#' in a comment
    count = np.diff(np.append(heads, starts.size))
    if (count[vert | face] != 4).any():
        return None
    kind = np.repeat(np.where(vert, 1, np.where(face, 2, 0)).astype(np.int8), count)
    kind[heads] = 0
    v = _numbers(b, starts[kind == 1], ends[kind == 1], np.float64)
    f = _numbers(b, starts[kind == 2], ends[kind == 2], np.int64)
    if v is None or f is None or not np.isfinite(v).all():
        return None
    nv = v.size // 3
    if f.size and (f.min() < 1 or f.max() > nv):
        return None
    return v.reshape(-1, 3), (f - 1).astype(np.intp).reshape(-1, 3)


def _numbers(b: npt.NDArray[np.uint8], starts: IntArray, ends: IntArray, dtype: type) -> Any:
    """Read the tokens ``b[starts[i]:ends[i]]`` as numbers, or return None if one is not one.

    The tokens are copied, a block at a time, into a table of fixed-width byte
    strings (`_token_table`). A block of plain decimals (`_plain_decimals`) is
    read by numpy's text parser, which reads a decimal as Python's ``float``
    does (both call ``PyOS_string_to_double``), or, for vertex numbers, by
    arithmetic on the digits; any other block is cast by Python's ``float``
    or ``int`` themselves.
    """
    out: npt.NDArray[Any] = np.empty(starts.size, dtype=dtype)
    if starts.size == 0:
        return out
    width = int((ends - starts).max())
    if width > _MAX_TOKEN:
        return None
    padded = np.concatenate((b, np.zeros(width, dtype=np.uint8)))
    for lo in range(0, starts.size, _TOKEN_BLOCK):
        hi = min(lo + _TOKEN_BLOCK, starts.size)
        table = _token_table(padded, starts[lo:hi], ends[lo:hi], width)
        if dtype is np.int64 and _all_digits(table):
            values = np.zeros(hi - lo, dtype=np.int64)
            for col in table.T.astype(np.int64):  # a digit more, or padding: no change
                values = np.where(col == 0, values, values * 10 + (col - ord("0")))
            out[lo:hi] = values
            continue
        if dtype is np.float64 and _plain_decimals(table):
            text = np.full((hi - lo, width + 1), 32, dtype=np.uint8)  # a space after each
            np.copyto(text[:, :width], table, where=table != 0)
            out[lo:hi] = np.fromstring(text.tobytes().rstrip(), dtype=np.float64, sep=" ")
            continue
        try:
            out[lo:hi] = table.view(f"S{width}").ravel().astype(dtype)
        except (ValueError, OverflowError):
            return None
    return out


def _token_table(padded: npt.NDArray[np.uint8], s: IntArray, e: IntArray, width: int) -> Any:
    """Copy tokens into a (n, width) table of bytes, each token padded with zero bytes."""
    cols = np.arange(width)
    table = padded[s[:, None] + cols]
    table[cols >= (e - s)[:, None]] = 0
    return table


def _all_digits(table: npt.NDArray[np.uint8]) -> bool:
    """Whether every token is digits only, short enough for an int64 (`_token_table`)."""
    return table.shape[1] <= 18 and bool((((table >= 48) & (table <= 57)) | (table == 0)).all())


# A decimal as ``float`` and ``strtod`` both read all of it: sign, digits, point, digits,
# exponent. States: 0 start, 1 sign, 2 digits, 3 point after digits, 4 point first,
# 5 fraction digits, 6 e, 7 exponent sign, 8 exponent digits, 9 end, 10 not a decimal.
# Byte kinds: digit, point, e or E, + or -, padding, other.
_DECIMAL = np.array(
    [
        [2, 4, 10, 1, 10, 10],
        [2, 4, 10, 10, 10, 10],
        [2, 3, 6, 10, 9, 10],
        [5, 10, 6, 10, 9, 10],
        [5, 10, 10, 10, 10, 10],
        [5, 10, 6, 10, 9, 10],
        [8, 10, 10, 7, 10, 10],
        [8, 10, 10, 10, 10, 10],
        [8, 10, 10, 10, 9, 10],
        [10, 10, 10, 10, 9, 10],
        [10, 10, 10, 10, 10, 10],
    ],
    dtype=np.uint8,
)
_DECIMAL_KIND = np.full(256, 5, dtype=np.uint8)
_DECIMAL_KIND[48:58] = 0
_DECIMAL_KIND[ord(".")] = 1
_DECIMAL_KIND[[ord("e"), ord("E")]] = 2
_DECIMAL_KIND[[ord("+"), ord("-")]] = 3
_DECIMAL_KIND[0] = 4


def _plain_decimals(table: npt.NDArray[np.uint8]) -> bool:
    """Whether every token of the table is a whole plain decimal (`_DECIMAL`), no nan or inf."""
    kinds = _DECIMAL_KIND[table.T]  # a row per column of the table
    moves = _DECIMAL.ravel()  # state s, byte kind k: moves[s * 6 + k]
    state = np.zeros(table.shape[0], dtype=np.uint8)
    for kind in kinds:
        state = moves[state * np.uint8(6) + kind]
    return bool(np.isin(state, (2, 3, 5, 8, 9)).all())


def _read_lines(data: bytes, name: str) -> MeshData:
    """Read OBJ text line by line, naming the line of any error."""
    text = _text(data, name, "OBJ")
    coords: list[float] = []
    polys: list[list[int]] = []
    poly_lines: list[int] = []
    nv = 0
    lines = text.splitlines()
    lineno = 0
    pending = ""
    for raw in lines:
        lineno += 1
        if raw.endswith("\\"):  # a continued line
            pending += raw[:-1] + " "
            continue
        line = pending + raw
        pending = ""
        hash_at = line.find("#")
        if hash_at >= 0:
            line = line[:hash_at]
        toks = line.split()
        if not toks:
            continue
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
                            name, "obj_back", lineno, index=i, count=nv, vertices=_vertices(nv)
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
                vertices=_vertices(nv),
            )
    vertices = np.array(coords, dtype=np.float64).reshape(-1, 3)
    split, sizes = _split(vertices, polys)
    fields = _polygon_fields(split, sizes)
    return MeshData(
        vertices, split.faces, "obj", "ascii", split.source, len(polys), name, source=data, **fields
    )


def _is_float(tok: str) -> bool:
    try:
        float(tok)
    except ValueError:
        return False
    return True


def _vertices(n: int) -> str:
    return "vertex" if n == 1 else "vertices"


def _encode_obj(v: FloatArray, f: IntArray) -> bytes:
    """Write the mesh as OBJ text: every coordinate as the shortest decimal that reads back."""
    lines = ["# written by trinormal"]
    lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
    lines += [f"f {a} {b} {c}" for a, b, c in (f + 1).tolist()]
    return ("\n".join(lines) + "\n").encode()
