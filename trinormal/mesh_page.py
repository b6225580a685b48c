"""What the site's "Check a mesh" page says and allows, defined once here.

The page reads, checks and repairs a mesh file in the browser
(``docs/assets/javascripts/trinormal-mesh.js``, run in a Web Worker). Its
messages, its limits, the rows of its report and the degeneracy tolerance are
not written in JavaScript: the site build (``docs/hooks/trinormal_site.py``)
puts `site_constants()` into ``trinormal-constants.js``.

Examples
--------
>>> MESSAGES["no_faces"].format(name="model.stl")
'model.stl has no faces: there is no surface to check.'
>>> LIMITS["max_faces"]
5000000
"""

from __future__ import annotations

from typing import Any

from trinormal.mesh.report import NOUNS, SUMMARY
from trinormal.tolerances import DEFAULT_TOL

__all__ = [
    "EXAMPLES",
    "LIMITS",
    "MESSAGES",
    "NOUNS",
    "REPORT_ROWS",
    "SUMMARY",
    "example_file",
    "example_mesh",
    "site_constants",
]

#: The largest file and the most faces the page reads (a browser tab's memory is limited), and
#: the most faces it draws in 3D without being asked (a bigger model is drawn on a click: its
#: first frame can take seconds on a computer without a graphics card).
LIMITS: dict[str, int] = {
    "max_bytes": 300 * 1024 * 1024,
    "max_faces": 5_000_000,
    "max_view_faces": 300_000,
}

#: What the page says about a file it cannot read. The reasons (``at_line`` to the last PLY one)
#: are the wording of `trinormal.mesh.MeshFileError` for the same file, as templates: the page
#: writes "NAME: REASON" or "NAME, line N: REASON" as Python does, and the browser tests check
#: that both say the same on every bad file of ``tests/data/meshes/bad/``. The others are the
#: page's own (its limits, its progress and its buttons).
MESSAGES: dict[str, str] = {
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
        "not an STL file: it is not text starting with 'solid', and a binary STL of {count} "
        "triangles would have {expected} bytes, not {size}"
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
    # the page's own
    "too_large": (
        "{name} is {size} bytes; this page reads files of up to {max} bytes. "
        "The Python package (trinormal mesh FILE) has no such limit."
    ),
    "too_many_faces": (
        "{name} has {count} faces; this page checks up to {max}. "
        "The Python package (trinormal mesh FILE) has no such limit."
    ),
    "no_faces": "{name} has no faces: there is no surface to check.",
    "index_range": "Face {face} uses vertex {index}, but the mesh has {count} vertices.",
    "internal": "This file could not be read: {detail}",
    "yes": "yes",
    "no": "no",
    "more": "{count} more",
    "view_big": (
        "This model has {count} faces. Drawing it in 3D may pause the page for a few seconds "
        "on a computer without a graphics card."
    ),
    "view_draw": "Draw the model in 3D",
    "reading": "Reading {name}…",
    "checking": "Checking {name}…",
    "fixing": "Fixing the winding…",
    "fixed": "Fixed: {faces} turned over. The report below is the repaired mesh's.",
}

#: The report's rows on the page: the key of ``check(...).to_dict()`` and its label.
REPORT_ROWS: tuple[tuple[str, str], ...] = (
    ("n_vertices", "Vertices"),
    ("n_faces", "Faces (triangles)"),
    ("unused_vertices", "Vertices no face uses"),
    ("degenerate_faces", "Degenerate faces"),
    ("coincident_faces", "… with two corners at one point"),
    ("collinear_faces", "… with three corners on one line"),
    ("duplicate_faces", "Duplicate faces"),
    ("reversed_duplicate_faces", "Duplicate faces wound the other way"),
    ("boundary_edges", "Boundary edges (one face: a hole's rim)"),
    ("non_manifold_edges", "Non-manifold edges (three faces or more)"),
    ("non_manifold_vertices", "Non-manifold vertices"),
    ("inconsistent_edges", "Edges two faces walk the same way"),
    ("n_components", "Connected pieces"),
    ("closed", "Closed (no hole, no fin)"),
    ("consistent_winding", "Wound consistently"),
    ("outward", "Every closed piece faces outward"),
    ("faces_to_flip", "Faces to flip"),
)


#: The page's example models: file name, the button's words, and how the model is made.
EXAMPLES: tuple[tuple[str, str], ...] = (
    ("cube-one-face-flipped.obj", "A cube with one face flipped (OBJ)"),
    ("sphere-hole-flipped-patch.ply", "A sphere with a hole and a flipped patch (PLY)"),
    ("inside-out-torus.stl", "An inside-out torus (binary STL)"),
)


def example_mesh(name: str) -> tuple[Any, Any]:
    """Return the vertices and faces of one of the page's `EXAMPLES`.

    Examples
    --------
    >>> v, f = example_mesh("cube-one-face-flipped.obj")
    >>> v.shape, f.shape
    ((8, 3), (12, 3))
    """
    from trinormal.mesh import cube, icosphere, torus

    if name == "cube-one-face-flipped.obj":
        v, f = cube()
        f = f.copy()
        f[5] = f[5, [0, 2, 1]]
        return v, f
    if name == "sphere-hole-flipped-patch.ply":
        v, f = icosphere(2)
        f = f.copy()
        patch = [i for i in range(len(f)) if (f[i] == 0).any()]  # the faces around vertex 0
        f[patch] = f[patch][:, [0, 2, 1]]
        hole = [i for i in range(len(f)) if (f[i] == 11).any()][:2]  # two faces at vertex 11
        keep = [i for i in range(len(f)) if i not in hole]
        return v, f[keep]
    if name == "inside-out-torus.stl":
        v, f = torus(n_major=24, n_minor=12)
        return v, f[:, [0, 2, 1]]
    raise KeyError(name)


def example_file(name: str) -> bytes:
    """Return one of the page's `EXAMPLES` as the bytes of its file (OBJ, PLY or binary STL).

    Examples
    --------
    >>> example_file("cube-one-face-flipped.obj").splitlines()[1]
    b'v -1.0 -1.0 -1.0'
    """
    import numpy as np

    v, f = example_mesh(name)
    if name.endswith(".obj"):
        lines = ["# " + dict(EXAMPLES)[name]]
        lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
        lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in f.tolist()]
        return ("\n".join(lines) + "\n").encode()
    if name.endswith(".ply"):
        head = [
            "ply",
            "format ascii 1.0",
            "comment " + dict(EXAMPLES)[name],
            f"element vertex {len(v)}",
            "property double x",
            "property double y",
            "property double z",
            f"element face {len(f)}",
            "property list uchar int vertex_indices",
            "end_header",
        ]
        rows = [f"{x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
        rows += [f"3 {a} {b} {c}" for a, b, c in f.tolist()]
        return ("\n".join(head + rows) + "\n").encode()
    record = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(f), dtype=record)
    data["corners"] = v[f]
    header = dict(EXAMPLES)[name].encode().ljust(80, b" ")
    return header + np.uint32(len(f)).tobytes() + data.tobytes()


def site_constants() -> dict[str, Any]:
    """Return the mesh page's constants for the site's JavaScript (see the module docstring).

    Returns
    -------
    dict
        ``messages``, ``limits``, ``rows`` (``[key, label]`` pairs) and ``tol``.

    Examples
    --------
    >>> sorted(site_constants())
    ['limits', 'messages', 'nouns', 'rows', 'summary', 'tol']
    """
    return {
        "messages": dict(MESSAGES),
        "limits": dict(LIMITS),
        "rows": [list(r) for r in REPORT_ROWS],
        "summary": {k: list(t) if isinstance(t, tuple) else t for k, t in SUMMARY.items()},
        "nouns": {k: list(t) for k, t in NOUNS.items()},
        "tol": DEFAULT_TOL,
    }
