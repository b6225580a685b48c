"""What the site's "Check a mesh" page says and allows, defined once here.

The page reads, checks and repairs a mesh file in the browser
(``docs/assets/javascripts/trinormal-mesh.js``, run in a Web Worker). Its
messages, its limits, the rows of its report and the degeneracy tolerance are
not written in JavaScript: the site build (``docs/hooks/trinormal_site.py``)
puts :func:`site_constants` into ``trinormal-constants.js``.

Examples
--------
>>> MESSAGES["empty_file"].format(name="model.stl")
'model.stl is empty: there is nothing to read.'
>>> LIMITS["max_faces"]
5000000
"""

from __future__ import annotations

from typing import Any

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

#: Every sentence the page can show about a file, as templates with ``{placeholders}``.
MESSAGES: dict[str, str] = {
    "empty_file": "{name} is empty: there is nothing to read.",
    "too_large": (
        "{name} is {size} bytes; this page reads files of up to {max} bytes. "
        "The Python package (trinormal mesh FILE) has no such limit."
    ),
    "unknown_format": (
        "{name} is not a mesh file this page can read: it needs to be {formats} "
        "(the name should end in .obj, .stl or .ply)."
    ),
    "not_text": "{name} is not a text {format} file: it holds bytes that are not text.",
    "empty": "{name} holds no vertices and no faces: it is not a {format} mesh.",
    "no_faces": "{name} has no faces: there is no surface to check.",
    "too_many_faces": (
        "{name} has {count} faces; this page checks up to {max}. "
        "The Python package (trinormal mesh FILE) has no such limit."
    ),
    "bad_number": "{name}, line {line}: the {what} value is not a finite number.",
    "obj_vertex": "{name}, line {line}: a vertex (v) needs three coordinates.",
    "obj_face_short": "{name}, line {line}: a face (f) needs at least three corners.",
    "obj_index": "{name}, line {line}: {index} is not a vertex number.",
    "obj_index_range": (
        "{name}, line {line}: the face uses vertex {index}, but only {count} vertices "
        "come before it."
    ),
    "stl_binary_number": "{name}, facet {facet}: corner {what} is not a finite number.",
    "stl_syntax": "{name}, line {line}: unexpected “{found}” in an ASCII STL file.",
    "stl_vertex": "{name}, line {line}: a vertex needs exactly three coordinates.",
    "stl_loop": "{name}, line {line}: a facet's loop has {count} corners; it needs 3.",
    "stl_size": (
        "{name} is not a complete binary STL file: its header announces {count} "
        "triangles ({expected} bytes), but the file has {size} bytes."
    ),
    "stl_short": "{name} is too short ({size} bytes) to be an STL file.",
    "ply_header": "{name}, line {line} of the header: “{what}” is missing or not understood.",
    "ply_no_vertices": "{name} has no vertex element with x, y and z.",
    "ply_no_faces": "{name}: the face element has no vertex_indices list.",
    "ply_short": "{name} ends before all the vertices and faces its header announces.",
    "ply_row": "{name}, line {line}: the row does not match the header's properties.",
    "ply_face_short": "{name}, {where}: a face needs at least three corners.",
    "ply_index_range": "{name}, {where}: vertex {index} does not exist ({count} vertices).",
    "ply_binary_number": "{name}, vertex {row}: {what} is not a finite number.",
    "where_line": "line {line}",
    "where_face": "face {face}",
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
    "fixed": "Fixed: {count} faces flipped. The report below is the repaired mesh's.",
    "nothing_to_fix": "Every face already agrees with its neighbours: there is nothing to flip.",
    "cannot_orient": (
        "No choice of flips makes every component agree (one is non-orientable, like a "
        "Möbius strip, or joined through non-manifold edges)."
    ),
}

#: Things counted in the summary: the singular and the plural, as ``_n`` of the report writes them.
NOUNS: dict[str, tuple[str, str]] = {
    "vertex": ("vertex", "vertices"),
    "triangle": ("triangle", "triangles"),
    "piece": ("piece", "pieces"),
    "face": ("face", "faces"),
}

#: The summary's sentences: one template, or a (one, many) pair chosen by ``{n}``.
SUMMARY: dict[str, str | tuple[str, str]] = {
    "sizes": "{vertices}, {triangles}, {pieces}.",
    "ok": (
        "No problems found: the surface is closed, every face is wound the same way round, "
        "and every normal points outward."
    ),
    "degenerate": (
        "{n} degenerate face ({parts}): no area and no normal, so they cannot be lit or oriented.",
        "{n} degenerate faces ({parts}): no area and no normal, so they cannot be lit or oriented.",
    ),
    "coincident": "{n} with two corners at the same point",
    "collinear": "{n} with corners on one line",
    "duplicate": ("{n} face repeats another face exactly.", "{n} faces repeat another face exactly."),
    "reversed_duplicate": (
        "{n} face repeats another face wound the other way: the two normals cancel, and the "
        "pair is a sheet with no inside.",
        "{n} faces repeat another face wound the other way: the two normals cancel, and the "
        "pair is a sheet with no inside.",
    ),
    "unused": ("{n} vertex is not used by any face.", "{n} vertices are not used by any face."),
    "boundary": (
        "{n} edge belongs to one face only: the surface has holes (or is an open sheet), so it "
        "has no inside. Through a hole you see the back of the faces behind it.",
        "{n} edges belong to one face only: the surface has holes (or is an open sheet), so it "
        "has no inside. Through a hole you see the back of the faces behind it.",
    ),
    "non_manifold_edges": (
        "{n} edge is shared by three faces or more, like the spine of a book: no single "
        "surface does that.",
        "{n} edges are shared by three faces or more, like the spine of a book: no single "
        "surface does that.",
    ),
    "non_manifold_vertices": (
        "{n} vertex joins pieces of surface that touch only at that point.",
        "{n} vertices join pieces of surface that touch only at that point.",
    ),
    "piece": "Piece {i} ({faces})",
    "whole": "The mesh",
    "not_orientable": (
        "{name} cannot be wound consistently at all, like a Möbius strip: it has only one side."
    ),
    "inconsistent": (
        "{name} is wound inconsistently: some faces are turned the other way round from their "
        "neighbours, so their normals point the wrong way. Lighting makes such faces dark, and "
        "back-face culling makes them vanish."
    ),
    "inside_out": (
        "{name} is inside out: every normal points inward (the enclosed volume is negative)."
    ),
    "no_volume": "{name} is closed but encloses no volume, so it has no outside.",
    "flip": (
        "fix_winding turns {n} face over to wind every piece consistently{end}",
        "fix_winding turns {n} faces over to wind every piece consistently{end}",
    ),
    "flip_end_closed": " and outward.",
    "flip_end_open": ".",
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
    """The vertices and faces of one of the page's `EXAMPLES`.

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
    """One of the page's `EXAMPLES` as the bytes of its file (OBJ, ASCII PLY or binary STL).

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
    """The mesh page's constants for the site's JavaScript (see the module docstring).

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
