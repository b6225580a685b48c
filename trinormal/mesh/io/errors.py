"""Why a mesh file cannot be read or written: one sentence that names the file and line.

`READ_ERRORS` and `OTHER_ERRORS` hold every reason once, as a template;
`MeshFileError` fills one in and places it in the file. The helpers below are
the ones the text formats share: decoding the bytes, reading a number on a
given line, and quoting a token inside a reason.
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["OTHER_ERRORS", "READ_ERRORS", "READ_NOTES", "MeshFileError"]

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
    "no_faces": "the file has no faces: there is no surface to check",
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
    "ply_negative": "'{element}' row {row} gives a list {count} items: a count is never negative",
}

#: What a reader says of a file it reads although it breaks its format where the format
#: allows leniency, as templates. `MeshData.notes` holds them filled in, each as
#: "NAME: NOTE"; the site's page says the same (`trinormal.mesh_page.MESSAGES` includes them).
READ_NOTES: dict[str, str] = {
    "stl_count": (
        "the header's triangle count is {count}, but the file holds {records}: its {size} bytes "
        "after the header are whole 50-byte triangle records, and all were read"
    ),
    "stl_trailing": "ignored the last {extra} {bytes}: fewer than the 50 of a triangle record",
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


def _text(data: bytes, name: str, what: str) -> str:
    """Decode the file as UTF-8, or Latin-1 for 8-bit comments; NUL bytes mean it is binary."""
    nul = data.find(b"\0")
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise MeshFileError.of(name, "binary_data", line, what=what)
    return _decode(data)[0].removeprefix("\ufeff")  # without a byte-order mark


def _decode(data: bytes) -> tuple[str, str]:
    """Return a file's text and its codec: UTF-8, or Latin-1 for 8-bit comments."""
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        return data.decode("latin-1"), "latin-1"


def _number(tok: str, name: str, line: int) -> float:
    """Read a coordinate on line ``line``: a finite number, or the error that says why not."""
    try:
        x = float(tok)
    except ValueError:
        raise MeshFileError.of(name, "not_a_number", line, token=_show(tok)) from None
    if not math.isfinite(x):
        raise MeshFileError.of(name, "not_finite", line, token=_show(tok))
    return x


def _show(tok: str) -> str:
    """Quote a token for a reason, cut to 40 characters."""
    return repr(tok if len(tok) <= 40 else tok[:39] + "…")
