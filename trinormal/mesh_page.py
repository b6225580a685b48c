"""What the site's "Check a mesh" page says and allows, defined once here.

The page reads, checks and repairs a mesh file in the browser
(``docs/assets/javascripts/trinormal-mesh-*.js``, run in a Web Worker). Its
messages, its limits, the rows of its report and the degeneracy tolerance are
not written in JavaScript: the site build (``docs/hooks/trinormal_site.py``)
puts `site_constants()` into ``trinormal-constants.js``.

Examples
--------
>>> MESSAGES["too_many_faces"].format(name="model.stl", count="6,000,000", max="5,000,000")[:44]
'model.stl has 6,000,000 faces; this page che'
>>> LIMITS["max_faces"]
5000000
"""

from __future__ import annotations

from typing import Any

from trinormal.mesh.io import READ_ERRORS, READ_NOTES
from trinormal.mesh.printing import NO_VOLUME, Size, printing_constants, shown
from trinormal.mesh.report import NOUNS, SUMMARY
from trinormal.mesh.selection import selection_constants
from trinormal.mesh.shells import CAP_FRACTION
from trinormal.mesh.welding import WELD_AUTO, WELD_NEAR
from trinormal.tolerances import DEFAULT_TOL, PLANAR_TOL

__all__ = [
    "EXAMPLES",
    "LIMITS",
    "MESSAGES",
    "NOUNS",
    "PIECE_COLUMNS",
    "REPORT_ROWS",
    "SUMMARY",
    "TABLE_LISTED",
    "example_file",
    "example_mesh",
    "file_size",
    "report_table",
    "site_constants",
]

#: The largest file and the most faces the page reads (a browser tab's memory is limited), and
#: the most faces it draws in 3D without being asked (a bigger model is drawn on a click: its
#: first frame can take seconds on a computer without a graphics card).
LIMITS: dict[str, int] = {
    "max_bytes": 300_000_000,
    "max_faces": 5_000_000,
    "max_view_faces": 300_000,
}


def file_size(n: int) -> str:
    """Write a file's size as the page does: megabytes (10**6 bytes), rounded up to a tenth.

    Rounded up, so a file over the limit never reads as the limit itself. The page's
    JavaScript (``fileSize`` in ``trinormal-mesh-base.js``) follows the same rule; the browser
    tests compare the two.

    Examples
    --------
    >>> file_size(LIMITS["max_bytes"])
    '300 MB'
    >>> file_size(300_000_001), file_size(50_000_084), file_size(684)
    ('300.1 MB', '50.1 MB', '0.1 MB')
    """
    tenths = -(-n // 100_000)
    return f"{tenths // 10} MB" if tenths % 10 == 0 else f"{tenths // 10}.{tenths % 10} MB"


#: What the page says. The reasons a file cannot be read (``at_line`` to ``ply_binary_row``) are
#: `trinormal.mesh.io.READ_ERRORS` itself, the templates `trinormal.mesh.MeshFileError` fills
#: for the same file: the page writes "NAME: REASON" or "NAME, line N: REASON" as Python does,
#: and the browser tests check that both say the same on every bad file of
#: ``tests/data/meshes/bad/``. The notes on a file read leniently (``stl_count``,
#: ``stl_trailing``) are `trinormal.mesh.io.READ_NOTES`, written "NAME: NOTE" as
#: `trinormal.mesh.MeshData.notes` holds them. The others are the page's own (its limits, its
#: progress and its buttons).
MESSAGES: dict[str, str] = {
    **READ_ERRORS,
    **READ_NOTES,
    # the page's own
    "too_large": (
        "{name} is {size}; this page reads files of up to {max}. "
        "The Python package (trinormal mesh FILE) has no such limit."
    ),
    "too_many_faces": (
        "{name} has {count} faces; this page checks up to {max}. "
        "The Python package (trinormal mesh FILE) has no such limit."
    ),
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
    # the weld control, shown when the report finds a near miss (trinormal mesh --weld)
    "weld": "Merge corners closer than {distance}",
    "welding": "Merging corners closer than {distance}…",
    "welded": (
        "Corners closer than {distance} are merged for the check and the fix, as "
        "trinormal mesh --weld does."
    ),
    # beside "Fix winding": what it repairs, and what it leaves to a modelling program
    "fix_nothing": (
        "Every face is wound the right way round already: there is nothing to turn over."
    ),
    "fix_only_winding": (
        "Fix winding only turns faces over. Holes, fins, duplicate and degenerate faces stay "
        "as they are: a slicer needs a closed surface to tell inside from outside, so fill or "
        "remove them in a modelling program such as Blender or MeshLab."
    ),
    # in the tables: a value with no answer, the size, and no enclosed volume
    "no_answer": "—",
    "size_cell": "{x} × {y} × {z}",
    "no_volume_cell": "none: " + NO_VOLUME,
    # under the table of pieces
    "pieces_dash": (
        "— : no answer for that piece. Only a piece wound consistently that encloses a "
        "volume (closed, or open but closed over its holes) faces outward or inward, and "
        "only a closed one has its volume measured."
    ),
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
    ("closed", "Closed (no hole, no edge of three faces)"),
    ("consistent_winding", "Wound consistently"),
    ("outward", "Every closed piece faces outward"),
    ("faces_to_flip", "Faces to flip"),
    # the report for printing (trinormal.mesh.printing), in the order of the summary's lines
    ("holes", "Holes (the edges around each, largest first)"),
    ("size", "Size: x × y × z, in the file's units (slicers read mm)"),
    ("surface_area", "Surface area (the file's units squared)"),
    ("volume", "Enclosed volume (closed pieces wound consistently)"),
    ("verdict", "Verdict"),
)

#: The columns of the table of pieces: ``piece`` (its number, from 1), then keys of
#: ``ComponentReport.to_dict()``.
PIECE_COLUMNS: tuple[tuple[str, str], ...] = (
    ("piece", "Piece"),
    ("faces", "Faces"),
    ("closed", "Closed"),
    ("consistent", "Wound consistently"),
    ("orientable", "Can be wound consistently"),
    ("outward", "Faces outward"),
    ("cavity", "Cavity (inside another closed piece)"),
    ("volume", "Enclosed volume"),
    ("faces_to_flip", "Faces to flip"),
)

#: Items a cell of the tables lists before "N more".
TABLE_LISTED = 12


def _noun(key: str) -> str:
    """Name what a row's list holds, by the row's key: faces, edges or vertices."""
    return "edge" if key.endswith("_edges") else "vertex" if key.endswith("_vertices") else "face"


def _cell(value: Any, key: str = "") -> str:
    """How one value of the report reads in a cell: a list as "2: faces 5, 9" (`key` names it)."""
    if value is True or value is False:
        return MESSAGES["yes" if value else "no"]
    if value is None:
        return MESSAGES["no_answer"]
    if isinstance(value, list):
        if not value:
            return "0"
        items = [f"{x[0]}–{x[1]}" if isinstance(x, list) else str(x) for x in value[:TABLE_LISTED]]
        more = len(value) - TABLE_LISTED
        if more > 0:
            items.append(MESSAGES["more"].format(count=more))
        if key == "holes":  # edges around each hole: numbers, not indices
            return f"{len(value)}: {', '.join(items)}"
        one, many = NOUNS[_noun(key)]
        return f"{len(value)}: {one if len(value) == 1 else many} {', '.join(items)}"
    return str(value)


def _printing_cell(report: dict[str, Any], key: str) -> str:
    """Write a cell of the report for printing: its numbers as the summary writes them."""
    if key == "size":
        size = report["size"]
        if size is None:
            return MESSAGES["no_answer"]
        x, y, z = (shown(e) for e in size["extent"])
        box = Size(tuple(size["min"]), tuple(size["max"]))
        # the units hint, if any, on a line of its own
        return "\n".join([MESSAGES["size_cell"].format(x=x, y=y, z=z), *box.lines()[1:]])
    if key == "surface_area":
        return shown(report["surface_area"])
    if report["volume"] is None:
        return MESSAGES["no_volume_cell"]
    return shown(report["volume"])


def report_table(report: dict[str, Any]) -> dict[str, list[list[str]]]:
    """Write a report's two tables as the page shows them, every cell as text.

    The page's JavaScript (``table`` in ``trinormal-mesh-print.js``) writes the same cells
    from the same report; ``tests/test_mesh_parity.py`` compares the two on every file of
    its corpus.

    Parameters
    ----------
    report : dict
        ``check(...).to_dict()``.

    Returns
    -------
    dict
        ``rows``: ``[key, label, text]`` for each of `REPORT_ROWS`; ``pieces``: one list of
        texts per piece, a text for each of `PIECE_COLUMNS`.

    Examples
    --------
    >>> from trinormal.mesh import check, cube
    >>> v, f = cube()
    >>> t = report_table(check(v * 30, f[:-1]).to_dict())
    >>> [text for key, label, text in t["rows"] if key in ("boundary_edges", "holes", "size")]
    ['3: edges 4–6, 6–7, 7–4', '1: 3', '60 × 60 × 60']
    >>> t["pieces"]
    [['1', '11', 'no', 'yes', 'yes', 'yes', 'no', '—', '0']]
    """
    rows = []
    for key, label in REPORT_ROWS:
        if key in ("size", "surface_area", "volume"):
            text = _printing_cell(report, key)
        else:
            text = _cell(report[key], key)
        rows.append([key, label, text])
    pieces = []
    for i, piece in enumerate(report["components"]):
        cells = []
        for key, _ in PIECE_COLUMNS:
            if key == "piece":
                cells.append(str(i + 1))
            elif key == "volume" and piece["volume"] is not None:
                cells.append(shown(piece["volume"]))
            else:
                cells.append(_cell(piece[key]))
        pieces.append(cells)
    return {"rows": rows, "pieces": pieces}


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
        ``messages``, ``limits``, ``rows`` (``[key, label]`` pairs), ``columns`` (the
        table of pieces', as pairs), ``listed`` (`TABLE_LISTED`), ``tol``, ``planar_tol``
        (`trinormal.tolerances.PLANAR_TOL`, for splitting polygons),
        ``selection`` (the readout of a face picked in the 3D view:
        `trinormal.mesh.selection.selection_constants`), ``printing`` (the report for
        printing's templates and limits: `trinormal.mesh.printing.printing_constants`) and
        ``weld`` (the weld and near-miss distances over the model's size, and the share of
        caps below which an open piece encloses a volume).

    Examples
    --------
    >>> sorted(site_constants())  # doctest: +NORMALIZE_WHITESPACE
    ['columns', 'limits', 'listed', 'messages', 'nouns', 'planar_tol', 'printing', 'rows',
     'selection', 'summary', 'tol', 'weld']
    """
    return {
        "messages": dict(MESSAGES),
        "limits": dict(LIMITS),
        "rows": [list(r) for r in REPORT_ROWS],
        "columns": [list(c) for c in PIECE_COLUMNS],
        "listed": TABLE_LISTED,
        "summary": {k: list(t) if isinstance(t, tuple) else t for k, t in SUMMARY.items()},
        "nouns": {k: list(t) for k, t in NOUNS.items()},
        "tol": DEFAULT_TOL,
        "planar_tol": PLANAR_TOL,
        "selection": selection_constants(),
        "printing": printing_constants(),
        "weld": {"auto": WELD_AUTO, "near": WELD_NEAR, "cap_fraction": CAP_FRACTION},
    }
