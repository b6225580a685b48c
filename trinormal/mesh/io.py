"""Reading and writing mesh files: OBJ, STL (ASCII and binary), PLY (ASCII and binary).

The readers keep a file exactly as stored, because the report must talk about
the file the student has:

* OBJ and PLY: every vertex in file order, none merged or dropped; every face
  in file order. A polygon with n corners becomes n − 2 triangles, a fan from
  its first corner, wound as stored: ``(a, b, c, d)`` gives ``(a, b, c)`` and
  ``(a, c, d)``. `MeshData.source_faces` says which polygon each triangle
  came from.
* STL stores each triangle's three corners as coordinates, not as shared
  vertices. Corners with exactly equal coordinates become one vertex (exact
  equality, never a tolerance: ``-0.0`` equals ``0.0``), numbered in order of
  first appearance, so an STL model has the same edges, holes and pieces as
  the same model saved as OBJ.

A file that cannot be read raises `MeshFileError`, one sentence naming the
file and, in a text file, the line.

Why our own readers: well-kept libraries do not keep the file's order.
trimesh 4 (``process=False, maintain_order=True``) splits an OBJ quad
``a b c d`` into ``(a, b, c), (c, d, a)``, a fan from its third corner, and
lists a PLY file's triangles before its other polygons; meshio returns cells
grouped by type and adds a dependency. The formats are small: these readers
are the standard library and numpy, checked against files written by hand.

Examples
--------
>>> import os, tempfile
>>> from trinormal.mesh import cube
>>> v, f = cube()
>>> path = os.path.join(tempfile.mkdtemp(), "cube.stl")
>>> write_mesh(path, v, f)
>>> m = read_mesh(path)
>>> m.format, m.encoding, m.vertices.shape, m.faces.shape
('stl', 'binary', (8, 3), (12, 3))
>>> bool((m.vertices[m.faces] == v[f]).all())  # the same corners, in the same order
True
"""

from __future__ import annotations

import math
import os
import struct
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import FloatArray, IntArray, _check_faces, _check_vertices

__all__ = [
    "FORMATS",
    "OTHER_ERRORS",
    "READ_ERRORS",
    "SAMPLES",
    "MeshData",
    "MeshFileError",
    "parse_mesh",
    "read_mesh",
    "sample_path",
    "write_mesh",
]

#: The file formats read and written, by file extension.
FORMATS: tuple[str, ...] = ("obj", "stl", "ply")

#: The encodings each format can be written in; the first is the default.
ENCODINGS: dict[str, tuple[str, ...]] = {
    "obj": ("ascii",),
    "stl": ("binary", "ascii"),
    "ply": ("binary", "ascii"),
}


#: Model files shipped with the package (in ``trinormal/mesh/data/``).
SAMPLES: tuple[str, ...] = ("damaged_ball.obj",)


def sample_path(name: str = "damaged_ball.obj") -> str:
    """Return the path of a model file shipped with the package.

    Parameters
    ----------
    name : str, default "damaged_ball.obj"
        One of `SAMPLES`: ``damaged_ball.obj`` is
        [`damaged_model`][trinormal.mesh.damaged_model], a ball with a flipped
        patch and a hole.

    Returns
    -------
    str

    Examples
    --------
    >>> m = read_mesh(sample_path())
    >>> m.vertices.shape, m.faces.shape
    ((639, 3), (1263, 3))
    """
    if name not in SAMPLES:
        raise ValueError(f"no sample named {name!r}; the samples are {', '.join(SAMPLES)}")
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", name)


#: Why a file's content cannot be read, as templates: the one wording of every reason
#: `MeshFileError` gives for a file's bytes, and (through `trinormal.mesh_page.MESSAGES`, which
#: includes them) of the site's "Check a mesh" page for the same file. ``at_line`` places the
#: line; ``no_extension``, ``ply_valid`` and ``ply_no_vertices`` are parts of other reasons.
READ_ERRORS: dict[str, str] = {
    "at_line": "{name}, line {line}",
    "unknown_format": "unknown mesh format {ext}; trinormal reads .obj, .stl and .ply",
    "no_extension": "(no extension)",
    "binary_data": "not a text {what} file (binary data)",
    "not_a_number": "{token} is not a number",
    "not_finite": "{token} is not a finite number",
    "obj_vertex": "a vertex needs three coordinates: v x y z",
    "obj_face_short": "a face needs at least three corners",
    "obj_index": "{token} is not a vertex number",
    "obj_back": "face corner {index} refers back past the first vertex ({count} {vertices} so far)",
    "obj_zero": "vertex numbers start at 1, not 0",
    "obj_statement": "{token} is not an OBJ statement",
    "obj_empty": "no vertices and no faces: not an OBJ mesh",
    "obj_index_range": "face {face} refers to vertex {index}, but the file has {count} {vertices}",
    "stl_not_finite": "triangle {triangle} has a coordinate that is not finite",
    "stl_not_stl": (
        "not an STL file: a text STL starts with 'solid', and a binary STL's size follows from "
        "the triangle count in its header ({count} triangles would take {expected} bytes; this "
        "file has {size} bytes)"
    ),
    "stl_short": "not an STL file: too short, and it does not start with 'solid'",
    "stl_vertex_outside": "'vertex' outside 'outer loop' … 'endloop'",
    "stl_vertex": "a vertex needs three coordinates: vertex x y z",
    "stl_endloop": "'endloop' without 'outer loop'",
    "stl_facet": (
        "the facet starting at line {start} has {count} vertices; an STL facet has exactly 3"
    ),
    "stl_before_endloop": "{token} before 'endloop'",
    "stl_keyword": "{token} is not an STL keyword",
    "stl_ends_in_facet": "the file ends inside a facet",
    "ply_not_ply": "not a PLY file: it must start with 'ply' and have an 'end_header' line",
    "ply_format": "the format must be ascii, binary_little_endian or binary_big_endian",
    "ply_element": "write an element as: element NAME COUNT",
    "ply_property_first": "a property before any element",
    "ply_type": "unknown property type",
    "ply_property": "cannot read the property {token}",
    "ply_keyword": "{token} is not a PLY header keyword",
    "ply_no_format": "the header has no 'format' line",
    "ply_no_vertex": "the header has no 'vertex' element",
    "ply_vertex_list": "the vertex element has a list property",
    "ply_no_axis": "the vertex element has no '{axis}' property",
    "ply_not_finite": "vertex {vertex} has a coordinate that is not finite",
    "ply_corners": "face {face} has {count} corners; a face needs 3 or more",
    "ply_index_range": "face {face} refers to vertex {index}, but {valid}",
    "ply_valid": "the valid vertices are 0 to {last}",
    "ply_no_vertices": "there are no vertices",
    "ply_ascii_short": "the file ends after {rows} of {count} '{element}' rows",
    "ply_expected": "expected {count} numbers, found {found}",
    "ply_row": "cannot read this '{element}' row",
    "ply_too_many": "this '{element}' row has {count} values too many",
    "ply_binary_short": "the file ends inside the '{element}' element ({rows} of {count} rows)",
    "ply_binary_row": "the file ends inside '{element}' row {row} of {count}",
}

#: What only Python says: about the path, the ``format`` argument and writing (the site's page
#: reads bytes it was given and writes what it repaired, so none of these can happen there).
OTHER_ERRORS: dict[str, str] = {
    "cannot_read": "cannot be read: {reason}",
    "format_argument": "unknown mesh format {format}; use obj, stl or ply",
    "encoding": "a {format} file is written as {encodings}, not {encoding}",
    "cannot_write": "cannot be written: {reason}",
}


class MeshFileError(ValueError):
    """A mesh file that cannot be read (or written), with the file and line it concerns.

    Attributes
    ----------
    path : str
        The file's name as given.
    line : int or None
        The line of a text file where the problem is (1-based), or None.
    reason : str
        The problem in one sentence, without the file name.
    key : str or None
        Which template of `READ_ERRORS` (or `OTHER_ERRORS`) ``reason`` is, or None.
    params : dict
        The values filled into that template.

    Examples
    --------
    >>> str(MeshFileError("model.obj", "'x' is not a number", line=3))
    "model.obj, line 3: 'x' is not a number"
    >>> err = MeshFileError.of("model.obj", "not_a_number", line=3, token="'x'")
    >>> str(err), err.key
    ("model.obj, line 3: 'x' is not a number", 'not_a_number')
    """

    def __init__(self, path: str, reason: str, line: int | None = None) -> None:
        self.path = path
        self.line = line
        self.reason = reason
        self.key: str | None = None
        self.params: dict[str, Any] = {}
        where = path if line is None else READ_ERRORS["at_line"].format(name=path, line=line)
        super().__init__(f"{where}: {reason}")

    @classmethod
    def of(cls, path: str, key: str, line: int | None = None, **params: Any) -> MeshFileError:
        """Return the error whose reason is template ``key`` filled with ``params``."""
        template = READ_ERRORS[key] if key in READ_ERRORS else OTHER_ERRORS[key]
        err = cls(path, template.format(**params), line)
        err.key, err.params = key, params
        return err


@dataclass(frozen=True)
class MeshData:
    """A mesh as read from a file.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3)
        Coordinates in float64, in file order (STL: in order of first use).
    faces : ndarray of int, shape (F, 3)
        Triangles, in file order; polygons split into fans.
    format : str
        ``"obj"``, ``"stl"`` or ``"ply"``.
    encoding : str
        ``"ascii"`` or ``"binary"`` (a big-endian PLY reads as ``"binary"``
        and is written little-endian).
    source_faces : ndarray of int, shape (F,)
        For each triangle, the index of the face (polygon) of the file it
        comes from.
    n_polygons : int
        How many faces the file lists (before splitting).
    path : str
        The file's name.
    """

    vertices: FloatArray = field(repr=False)
    faces: IntArray = field(repr=False)
    format: str
    encoding: str
    source_faces: IntArray = field(repr=False)
    n_polygons: int
    path: str

    @property
    def split_polygons(self) -> int:
        """How many faces of the file had more than three corners."""
        if self.source_faces.size == 0:
            return 0
        counts = np.bincount(self.source_faces, minlength=self.n_polygons)
        return int((counts > 1).sum())

    def describe(self) -> str:
        r"""Say in one sentence: what was read, and how polygons were split.

        Examples
        --------
        >>> m = parse_mesh(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "obj")
        >>> print(m.describe())  # doctest: +NORMALIZE_WHITESPACE
        Read <bytes> (OBJ): 4 vertices, 1 face; 1 polygon with more than three corners split
        into 2 triangles, a fan from its first corner.
        """
        nv, np_ = self.vertices.shape[0], self.n_polygons
        enc = "" if self.format == "obj" else f", {self.encoding}"
        text = (
            f"Read {self.path} ({self.format.upper()}{enc}): "
            f"{nv} {'vertex' if nv == 1 else 'vertices'}, {np_} {'face' if np_ == 1 else 'faces'}"
        )
        k = self.split_polygons
        if k:
            tri = int(np.isin(self.source_faces, _multi(self.source_faces, np_)).sum())
            text += (
                f"; {k} {'polygon' if k == 1 else 'polygons'} with more than three corners "
                f"split into {tri} triangles, a fan from {'its' if k == 1 else 'each'} first corner"
            )
        return text + "."


def _multi(source: IntArray, n: int) -> IntArray:
    counts = np.bincount(source, minlength=n)
    out: IntArray = np.flatnonzero(counts > 1)
    return out


# --------------------------------------------------------------------------- reading


def read_mesh(path: str | os.PathLike[str], format: str | None = None) -> MeshData:
    """Read an OBJ, STL or PLY file, keeping its vertices and faces as stored.

    Parameters
    ----------
    path : str or path-like
        The file.
    format : {"obj", "stl", "ply"}, optional
        The format; by default the file's extension.

    Returns
    -------
    MeshData

    Raises
    ------
    MeshFileError
        The file cannot be opened, its format is unknown, or it is not a valid
        file of its format; the message names the file and, for text, the line.
    """
    name = os.fspath(path)
    fmt = _format_of(name, format)
    try:
        with open(name, "rb") as fh:
            data = fh.read()
    except OSError as exc:
        raise MeshFileError.of(name, "cannot_read", reason=exc.strerror or exc) from None
    return parse_mesh(data, fmt, name)


def parse_mesh(data: bytes, format: str, name: str = "<bytes>") -> MeshData:
    r"""Read a mesh from the bytes of a file (see `read_mesh`).

    Parameters
    ----------
    data : bytes
        The file's content.
    format : {"obj", "stl", "ply"}
        Its format.
    name : str, default "<bytes>"
        The name errors and `MeshData.path` use.

    Returns
    -------
    MeshData

    Examples
    --------
    >>> m = parse_mesh(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj")
    >>> m.faces
    array([[0, 1, 2]])
    >>> parse_mesh(b"v 0 0 0\nf 1 2 3\n", "obj")
    Traceback (most recent call last):
    ...
    trinormal.mesh.io.MeshFileError: <bytes>, line 2: face 1 refers to vertex 2, but ...
    """
    fmt = _format_of(name, format)
    if fmt == "obj":
        return _read_obj(data, name)
    if fmt == "stl":
        return _read_stl(data, name)
    return _read_ply(data, name)


def _format_of(name: str, format: str | None) -> str:
    if format is None:
        ext = os.path.splitext(name)[1].lower().lstrip(".")
        if ext not in FORMATS:
            shown = ("." + ext) if ext else READ_ERRORS["no_extension"]
            raise MeshFileError.of(name, "unknown_format", ext=shown)
        return ext
    fmt = format.lower().lstrip(".")
    if fmt not in FORMATS:
        raise MeshFileError.of(name, "format_argument", format=repr(format))
    return fmt


def _text(data: bytes, name: str, what: str) -> str:
    """Decode the file as UTF-8, or Latin-1 for 8-bit comments; NUL bytes mean it is binary."""
    nul = data.find(b"\0")
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise MeshFileError.of(name, "binary_data", line, what=what)
    try:
        return data.decode("utf-8").removeprefix("\ufeff")  # without a byte-order mark
    except UnicodeDecodeError:
        return data.decode("latin-1")


def _number(tok: str, name: str, line: int) -> float:
    try:
        x = float(tok)
    except ValueError:
        raise MeshFileError.of(name, "not_a_number", line, token=_show(tok)) from None
    if not math.isfinite(x):
        raise MeshFileError.of(name, "not_finite", line, token=_show(tok))
    return x


def _vertices(n: int) -> str:
    return "vertex" if n == 1 else "vertices"


def _show(tok: str) -> str:
    return repr(tok if len(tok) <= 40 else tok[:39] + "…")


def _fan(polys: list[list[int]]) -> tuple[IntArray, IntArray]:
    """Split polygons into triangles: a fan from each one's first corner, in order."""
    sizes = np.fromiter((len(p) for p in polys), dtype=np.intp, count=len(polys))
    if sizes.size and (sizes == 3).all():
        return np.array(polys, dtype=np.intp).reshape(-1, 3), np.arange(len(polys), dtype=np.intp)
    n_tri = sizes - 2
    source = np.repeat(np.arange(len(polys), dtype=np.intp), n_tri)
    flat = np.fromiter((i for p in polys for i in p), dtype=np.intp, count=int(sizes.sum()))
    start = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.intp)
    k = np.arange(source.size) - np.repeat(np.cumsum(n_tri) - n_tri, n_tri)  # 0 .. n-3
    first = start[source]
    faces = np.stack([flat[first], flat[first + k + 1], flat[first + k + 2]], axis=1)
    return faces.astype(np.intp).reshape(-1, 3), source


# OBJ statements that carry no triangle (texture, normals, grouping, materials, curves)
_OBJ_IGNORED = frozenset(
    {"vt", "vn", "vp", "g", "o", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "l", "p"}
    | {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole"}
    | {"scrv", "sp", "end", "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj"}
    | {"trace_obj", "ctech", "stech", "call", "csh"}
)


def _read_obj(data: bytes, name: str) -> MeshData:
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
    faces, source = _fan(polys) if polys else (np.empty((0, 3), np.intp), np.empty(0, np.intp))
    return MeshData(vertices, faces, "obj", "ascii", source, len(polys), name)


def _is_float(tok: str) -> bool:
    try:
        float(tok)
    except ValueError:
        return False
    return True


# --------------------------------------------------------------------------- STL

_STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attr", "<u2")])


def _read_stl(data: bytes, name: str) -> MeshData:
    if len(data) >= 84:
        (n,) = struct.unpack_from("<I", data, 80)
        if len(data) == 84 + 50 * n:  # a binary STL, even when its header starts with "solid"
            rec = np.frombuffer(data, dtype=_STL_RECORD, count=n, offset=84)
            corners = rec["corners"].reshape(-1, 3)  # float32, as stored: merged before widening
            if not np.isfinite(corners).all():
                bad = int(np.flatnonzero(~np.isfinite(corners).all(axis=1))[0]) // 3
                raise MeshFileError.of(name, "stl_not_finite", triangle=bad + 1)
            return _merge_corners(corners, name, "binary")
    if data.lstrip()[:5].lower() != b"solid" or b"\0" in data:
        if len(data) >= 84:
            (n,) = struct.unpack_from("<I", data, 80)
            raise MeshFileError.of(
                name,
                "stl_not_stl",
                count=f"{n:,}",
                expected=f"{84 + 50 * n:,}",
                size=f"{len(data):,}",
            )
        raise MeshFileError.of(name, "stl_short")
    return _read_stl_ascii(data, name)


def _read_stl_ascii(data: bytes, name: str) -> MeshData:
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
    return _merge_corners(arr, name, "ascii")


#: Odd 64-bit multipliers that mix a corner's three bit patterns into one sort key.
_MIX = (0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9)


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
    bits = corners.view(np.uint32 if corners.dtype == np.float32 else np.uint64)
    x, y, z = (bits[:, k].astype(np.uint64) for k in range(3))
    # sort by a mix of the three bit patterns; equal rows get equal keys, and the rows
    # themselves are compared after the sort, so equality is exact, never a hash match
    mx, my, mz = (np.uint64(m) for m in _MIX)
    with np.errstate(over="ignore"):
        key = x * mx
        key ^= y * my
        key ^= z * mz
    order = np.argsort(key, kind="stable")
    sx, sy, sz = x[order], y[order], z[order]
    same_row = (sx[1:] == sx[:-1]) & (sy[1:] == sy[:-1]) & (sz[1:] == sz[:-1])
    sk = key[order]
    if ((sk[1:] == sk[:-1]) & ~same_row).any():  # two different points share a key: sort rows
        order = np.lexsort((z, y, x))
        sx, sy, sz = x[order], y[order], z[order]
        same_row = (sx[1:] == sx[:-1]) & (sy[1:] == sy[:-1]) & (sz[1:] == sz[:-1])
    new = np.empty(n, dtype=bool)
    new[0] = True
    np.logical_not(same_row, out=new[1:])
    group = np.cumsum(new) - 1  # group of each sorted corner
    first = order[new]  # both sorts are stable: the first corner of each group in file order
    rank = np.empty(first.size, dtype=np.intp)
    rank[np.argsort(first)] = np.arange(first.size)
    index = np.empty(n, dtype=np.intp)
    index[order] = rank[group]
    vertices = np.empty((first.size, 3))
    vertices[rank] = corners[first]
    faces = index.reshape(-1, 3)
    nf = faces.shape[0]
    return MeshData(vertices, faces, "stl", encoding, np.arange(nf, dtype=np.intp), nf, name)


# --------------------------------------------------------------------------- PLY

_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}  # fmt: skip


@dataclass
class _Element:
    name: str
    count: int
    props: list[tuple[str, str, str | None]]  # (name, type, list count type or None)
    line: int

    @property
    def fixed(self) -> bool:
        return all(c is None for _, _, c in self.props)


def _read_ply(data: bytes, name: str) -> MeshData:
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
            if len(toks) != 3 or not toks[2].isdigit():
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
    if fmt == "ascii":
        values = _ply_ascii(data, body_start, len(header) + 2, elements, name)
        encoding = "ascii"
    else:
        values = _ply_binary(data, body_start, elements, "<" if "little" in fmt else ">", name)
        encoding = "binary"
    vdata = values["vertex"]
    vertices = np.stack([np.asarray(vdata[a], dtype=np.float64) for a in "xyz"], axis=1)
    if not np.isfinite(vertices).all():
        bad = int(np.flatnonzero(~np.isfinite(vertices).all(axis=1))[0])
        raise MeshFileError.of(name, "ply_not_finite", vertex=bad)
    polys: list[list[int]] | IntArray = values.get("face", {}).get("_polys", [])
    nv = vertices.shape[0]
    if isinstance(polys, np.ndarray):  # every face has the same number of corners
        if polys.shape[1] < 3:
            raise MeshFileError.of(name, "ply_corners", face=0, count=polys.shape[1])
        out_of_range = (polys < 0) | (polys >= nv)
        if out_of_range.any():
            row = int(np.flatnonzero(out_of_range.any(axis=1))[0])
            _ply_range_error(name, row, int(polys[row][out_of_range[row]][0]), nv)
        faces, source = _fan_uniform(polys)
        return MeshData(vertices, faces, "ply", encoding, source, polys.shape[0], name)
    for row, poly in enumerate(polys):
        if len(poly) < 3:
            raise MeshFileError.of(name, "ply_corners", face=row, count=len(poly))
        outside = [i for i in poly if not 0 <= i < nv]
        if outside:
            _ply_range_error(name, row, outside[0], nv)
    faces, source = _fan(polys) if polys else (np.empty((0, 3), np.intp), np.empty(0, np.intp))
    return MeshData(vertices, faces, "ply", encoding, source, len(polys), name)


def _ply_range_error(name: str, k: int, index: int, nv: int) -> None:
    valid = READ_ERRORS["ply_valid"].format(last=nv - 1) if nv else READ_ERRORS["ply_no_vertices"]
    raise MeshFileError.of(name, "ply_index_range", face=k, index=index, valid=valid)


def _fan_uniform(polys: IntArray) -> tuple[IntArray, IntArray]:
    """`_fan` for polygons that all have the same number of corners, shape (P, n)."""
    p, n = polys.shape
    k = np.arange(n - 2)
    faces = np.stack(
        [np.repeat(polys[:, :1], n - 2, axis=1), polys[:, k + 1], polys[:, k + 2]], axis=2
    )
    source = np.repeat(np.arange(p, dtype=np.intp), n - 2)
    return faces.reshape(-1, 3).astype(np.intp), source


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
                for pname, _ptype, ctype in el.props:
                    try:
                        if ctype is None:
                            t += 1
                            continue
                        n = int(toks[t])
                        items = [int(x) for x in toks[t + 1 : t + 1 + n]]
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
                table = arr[want].astype(np.intp) if want else np.empty((0, 3), np.intp)
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


_STRUCT = {"i1": "b", "u1": "B", "i2": "h", "u2": "H", "i4": "i", "u4": "I", "f4": "f", "f8": "d"}


# --------------------------------------------------------------------------- writing


def write_mesh(
    path: str | os.PathLike[str],
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    format: str | None = None,
    encoding: str | None = None,
) -> None:
    """Write a triangle mesh as OBJ, STL or PLY.

    Parameters
    ----------
    path : str or path-like
        The file to write.
    vertices : array_like, shape (V, 3)
        Vertex coordinates.
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.
    format : {"obj", "stl", "ply"}, optional
        By default the file's extension.
    encoding : {"binary", "ascii"}, optional
        For STL and PLY; binary by default. OBJ is always text.

    Notes
    -----
    Text formats write every coordinate with the shortest decimal that reads
    back as the same float64, so reading the file gives the same numbers. A
    binary STL holds float32 coordinates (the format has nothing else); a
    binary PLY uses float32 when every coordinate is a float32 number, float64
    otherwise. STL also stores each face's unit normal, from
    `trinormal.mesh.face_normals` (zero for a degenerate face).

    Raises
    ------
    MeshFileError
        Unknown format or encoding, or the file cannot be written.
    ValueError
        Bad arrays (the message names the first bad row).
    """
    name = os.fspath(path)
    fmt = _format_of(name, format)
    enc = encoding or ENCODINGS[fmt][0]
    if enc not in ENCODINGS[fmt]:
        raise MeshFileError.of(
            name,
            "encoding",
            format=fmt.upper(),
            encodings=" or ".join(ENCODINGS[fmt]),
            encoding=repr(enc),
        )
    v, _ = _check_vertices(vertices)
    f = _check_faces(faces, v.shape[0])
    data = _encode(v, f, fmt, enc)
    try:
        with open(name, "wb") as fh:
            fh.write(data)
    except OSError as exc:
        raise MeshFileError.of(name, "cannot_write", reason=exc.strerror or exc) from None


def _encode(v: FloatArray, f: IntArray, fmt: str, enc: str) -> bytes:
    if fmt == "obj":
        lines = ["# written by trinormal"]
        lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
        lines += [f"f {a} {b} {c}" for a, b, c in (f + 1).tolist()]
        return ("\n".join(lines) + "\n").encode()
    if fmt == "stl":
        from trinormal.mesh.normals import face_normals

        normals = face_normals(v, f) if f.shape[0] else np.empty((0, 3))
        if enc == "binary":
            rec = np.zeros(f.shape[0], dtype=_STL_RECORD)
            with np.errstate(over="ignore"):
                rec["normal"] = normals
                rec["corners"] = v[f]
            header = b"binary STL written by trinormal".ljust(80, b" ")
            return header + struct.pack("<I", f.shape[0]) + rec.tobytes()
        out = ["solid trinormal"]
        for n, tri in zip(normals.tolist(), v[f].tolist(), strict=True):
            out.append(f"facet normal {n[0]!r} {n[1]!r} {n[2]!r}")
            out.append("outer loop")
            out += [f"vertex {x!r} {y!r} {z!r}" for x, y, z in tri]
            out.append("endloop")
            out.append("endfacet")
        out.append("endsolid trinormal")
        return ("\n".join(out) + "\n").encode()
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
