"""The readout of one face of a mesh: its three vertices, its exact normal and its area.

[`face_selection`][trinormal.mesh.selection.face_selection] is what a 3D mesh view shows when
a face is clicked or its number typed: in Jupyter the kernel answers the view
([`MeshView`][trinormal.mesh.widget.MeshView]); on the site's "Check a mesh" page the
browser answers with the site's exact core, from the templates `SELECTION` and the rows
`RESULT_ROWS` defined here (the site build writes them into the page's constants).

Examples
--------
>>> SELECTION["vertex"].format(name="A", index=7)
'A = vertex 7'
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.core import triangle_normal
from trinormal.display import format_vector
from trinormal.fields import fields_spec
from trinormal.mesh.report import MeshReport
from trinormal.validation import check_precision

__all__ = [
    "PRECISION",
    "RESULT_ROWS",
    "SELECTION",
    "face_selection",
    "selection_constants",
    "selection_text",
]

#: The readout's wording, as templates: its title, a corner's label, the row of a face to flip
#: (``{fix}`` names the repair where the reader is: ``fix_winding`` in Python, the "Fix winding"
#: button on the site) and the answer to a face number that does not exist.
SELECTION: dict[str, str] = {
    "title": "Face {face}: vertices {a}, {b}, {c} as A, B, C",
    "vertex": "{name} = vertex {index}",
    "flipped_label": "winding",
    "flipped": "turned against its neighbours: {fix} flips this face",
    "no_face": "face {face} does not exist: the mesh has faces 0 to {last}",
    "problem_label": "problem",
}

#: Decimal places of the readout unless asked otherwise (the site's readout has these).
PRECISION = 4

#: The rows after the three corners, by key of `TriangleNormal.format` (labelled as the
#: calculator labels them, `trinormal.fields`).
RESULT_ROWS: tuple[str, ...] = ("normal", "magnitude", "area", "unit_normal", "status")


def face_selection(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    face: int,
    precision: int = PRECISION,
    report: MeshReport | None = None,
) -> dict[str, Any]:
    """Describe one face as the view shows it: its vertices, exact normal and area, as text.

    The normal comes from [`trinormal.triangle_normal`][trinormal.core.triangle_normal] on
    the face's three vertices as stored (the corners in the face's winding order as A, B
    and C), and every number is printed by the package's formatter.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
    face : int
        The face, 0 to F - 1.
    precision : int, default 4
        Decimal places, 0 to 15.
    report : MeshReport, optional
        The mesh's report; with it, a face to flip says so.

    Returns
    -------
    dict
        ``{"face": int, "title": str, "rows": [[label, value, role], ...]}``.

    Raises
    ------
    ValueError
        A face number outside 0 to F - 1.

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> sel = face_selection(v, f, 0, precision=2)
    >>> sel["title"]
    'Face 0: vertices 0, 2, 3 as A, B, C'
    >>> for label, value, role in sel["rows"]:
    ...     print(f"{label}: {value}")
    A = vertex 0: (-1.00, -1.00, -1.00)
    B = vertex 2: (-1.00, 1.00, -1.00)
    C = vertex 3: (1.00, 1.00, -1.00)
    N = U × V: (0.00, 0.00, -4.00)
    |N|: 4.00
    area = |N|/2: 2.00
    unit normal: (0.00, 0.00, -1.00)
    status: A proper triangle: the unit normal is defined.
    """
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    precision = check_precision(precision)
    if isinstance(face, bool) or not isinstance(face, (int, np.integer)):
        raise ValueError(f"the face must be a whole number, got {face!r}")
    if not 0 <= int(face) < len(f):
        raise ValueError(SELECTION["no_face"].format(face=face, last=len(f) - 1))
    face = int(face)
    corners = [int(i) for i in f[face]]
    points = [(float(v[i][0]), float(v[i][1]), float(v[i][2])) for i in corners]
    result = triangle_normal(points[0], points[1], points[2])
    text = result.format(precision)
    labels = {spec["key"]: spec["label"] for spec in fields_spec()}
    rows: list[list[str]] = [
        [SELECTION["vertex"].format(name=name, index=i), format_vector(p, precision), name]
        for name, i, p in zip("ABC", corners, points, strict=True)
    ]
    rows += [
        [labels.get(key, key), text[key], "N" if key == "normal" else ""] for key in RESULT_ROWS
    ]
    if report is not None and face in set(report.faces_to_flip.tolist()):
        rows.append(
            [
                SELECTION["flipped_label"],
                SELECTION["flipped"].format(fix="fix_winding"),
                "flipped",
            ]
        )
    a, b, c = corners
    return {
        "face": face,
        "title": SELECTION["title"].format(face=face, a=a, b=b, c=c),
        "rows": rows,
    }


def selection_text(selection: dict[str, Any]) -> str:
    """Write a face's readout (from `face_selection`) as plain text, one row a line.

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> print(selection_text(face_selection(*cube(), 0, precision=1)))  # doctest: +ELLIPSIS
    Face 0: vertices 0, 2, 3 as A, B, C
      A = vertex 0: (-1.0, -1.0, -1.0)
    ...
      area = |N|/2: 2.0
    ...
    """
    lines = [str(selection.get("title", ""))]
    lines += [f"  {label}: {value}" for label, value, _role in selection.get("rows", [])]
    return "\n".join(lines)


def selection_constants() -> dict[str, Any]:
    """Return the readout's templates and rows for the site's JavaScript (the build writes them).

    Examples
    --------
    >>> sorted(selection_constants())
    ['precision', 'rows', 'templates']
    """
    return {"templates": dict(SELECTION), "rows": list(RESULT_ROWS), "precision": PRECISION}
