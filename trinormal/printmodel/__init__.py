"""A printable teaching model of a triangle: the plate, its normal as an arrow, U and V as ridges.

`print_model` turns a triangle into one closed solid for a 3D printer:

* the triangle as a plate `THICKNESS` mm thick, lying on the printer's bed
  (z = 0), its longest side ``size`` mm long (80 by default);
* the normal N as an arrow standing on the plate's top face at the centroid;
* U and V as raised ridges from A towards the next two corners of the winding,
  each ending in a point (short of the arrow when it stands in the way);
* A, B and C marked beside their corners: embossed block letters, or braille
  cells (A = dot 1, B = dots 1 2, C = dots 1 4) with ``marks="braille"``.

A thin triangle gets smaller features, in steps (letters down to 4 mm
tall, narrower gaps and ridges; braille keeps its standard cell); if its marks
still do not fit inside, they stand on tabs of the plate beside the corners.
Only when even that fails is it refused, and the message names the smallest
whole ``size`` that fits (or says that none up to 1000 mm does).

The top face is the triangle's front: seen from above, the corners in the
order of the winding (A→B→C, or A→C→B with ``winding="ACB"``) turn
counter-clockwise, so the arrow stands on the side N points to. The model's
frame puts A at the origin and the winding's second corner on the +x axis.

Every feature stands in a hole of the plate's top face and its walls meet that
hole's rim, so the model is one surface: closed, manifold, every face wound
outward (`trinormal.mesh.check` says so, and so does the test suite's
independent check). Coordinates lie on a grid of 1/1024 mm, so a binary STL
(float32) stores them exactly and a 3MF file writes them in few digits.

This package needs only the standard library. The site's calculator runs a
port of it (``docs/assets/javascripts/trinormal-printmodel.js``) that writes
the same STL bytes and the same 3MF model, tested equal in ``tests/``.

Examples
--------
>>> m = print_model((0, 0, 0), (1, 0, 0), (0, 1, 0))
>>> len(m.vertices), len(m.faces)
(137, 270)
>>> m.corners  # A, B, C on the plate's top; BC, the longest side, is 80 mm
((0.0, 0.0, 3.0), (56.568359375, 0.0, 3.0), (0.0, 56.568359375, 3.0))
>>> m.tip[2] > THICKNESS
True
>>> len(m.stl())
13584
"""

from __future__ import annotations

import io
import math
import struct
import zipfile
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

from trinormal.core import triangle_normal
from trinormal.printmodel import _features as F
from trinormal.printmodel._features import (
    DEFAULT_SIZE,
    DOWNLOAD_NAME,
    MARKS,
    PRINT_MESSAGES,
    SIZE_RANGE,
    THICKNESS,
    PrintModelError,
    _num,
    _snap,
)
from trinormal.validation import check_winding

__all__ = [
    "DEFAULT_SIZE",
    "DOWNLOAD_NAME",
    "MARKS",
    "PRINT_MESSAGES",
    "SIZE_RANGE",
    "THICKNESS",
    "PrintModel",
    "PrintModelError",
    "build",
    "check_size",
    "print_model",
    "sample_file",
    "site_constants",
]

_STL_HEADER = b"trinormal print-model: plate, normal arrow, U and V ridges, marks".ljust(80)


# --------------------------------------------------------------------------- the model


@dataclass(frozen=True)
class PrintModel:
    """A printable model of a triangle, in millimetres, and its files.

    Attributes
    ----------
    vertices : tuple of (float, float, float)
        The points, each once; the plate's bottom at z = 0, its top at `THICKNESS`.
    faces : tuple of (int, int, int)
        Triangles of indices into ``vertices``, each wound counter-clockwise seen
        from outside (its normal ``(v1 - v0) × (v2 - v0)`` points out).
    corners : tuple of three (float, float, float)
        The top face's corners in the winding's order (A first, at the origin in
        x and y; the second corner on +x).
    names : str
        The corners' names in that order: ``"ABC"`` or ``"ACB"``.
    tip : (float, float, float)
        The arrow's tip, above the centroid.
    size : float
        The longest side, mm.
    marks : str
        ``"letters"`` or ``"braille"``.
    """

    vertices: tuple[tuple[float, float, float], ...]
    faces: tuple[tuple[int, int, int], ...]
    corners: tuple[tuple[float, float, float], ...]
    names: str
    tip: tuple[float, float, float]
    size: float
    marks: str

    def stl(self) -> bytes:
        """Return the model as a binary STL file (float32 coordinates, exact on the grid).

        Examples
        --------
        >>> data = print_model((0, 0, 0), (1, 0, 0), (0, 1, 0), marks="braille").stl()
        >>> data[:21], len(data) == 84 + 50 * int.from_bytes(data[80:84], "little")
        (b'trinormal print-model', True)
        """
        parts = [_STL_HEADER, struct.pack("<I", len(self.faces))]
        v = self.vertices
        for a, b, c in self.faces:
            p, q, r = v[a], v[b], v[c]
            e1 = (q[0] - p[0], q[1] - p[1], q[2] - p[2])
            e2 = (r[0] - p[0], r[1] - p[1], r[2] - p[2])
            n = (
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            )
            ln = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
            unit = (n[0] / ln, n[1] / ln, n[2] / ln) if ln > 0 else (0.0, 0.0, 0.0)
            parts.append(struct.pack("<12fH", *unit, *p, *q, *r, 0))
        return b"".join(parts)

    def model_xml(self) -> str:
        """Return the 3MF model part (``3D/3dmodel.model``): the mesh as XML, in millimetres.

        Examples
        --------
        >>> xml = print_model((0, 0, 0), (1, 0, 0), (0, 1, 0)).model_xml()
        >>> xml.splitlines()[7]
        '<vertex x="0" y="0" z="0"/>'
        """
        order = "→".join(self.names)
        lines = [
            '<?xml version="1.0" encoding="UTF-8"?>',
            '<model unit="millimeter" xml:lang="en-US" '
            'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">',
            '<metadata name="Title">' + PRINT_MESSAGES["title"].format(order=order) + "</metadata>",
            "<resources>",
            '<object id="1" type="model">',
            "<mesh>",
            "<vertices>",
        ]
        lines += [
            f'<vertex x="{_num(x)}" y="{_num(y)}" z="{_num(z)}"/>' for x, y, z in self.vertices
        ]
        lines += ["</vertices>", "<triangles>"]
        lines += [f'<triangle v1="{a}" v2="{b}" v3="{c}"/>' for a, b, c in self.faces]
        lines += [
            "</triangles>",
            "</mesh>",
            "</object>",
            "</resources>",
            '<build><item objectid="1"/></build>',
            "</model>",
        ]
        return "\n".join(lines) + "\n"

    def three_mf(self) -> bytes:
        """Return the model as a 3MF file: a zip of the model and the two files 3MF requires.

        Examples
        --------
        >>> data = print_model((0, 0, 0), (1, 0, 0), (0, 1, 0)).three_mf()
        >>> import zipfile, io
        >>> names = zipfile.ZipFile(io.BytesIO(data)).namelist()
        >>> len(names), names[0], names[-1]  # the content types, the relations and the model
        (3, '[Content_Types].xml', '3D/3dmodel.model')
        """
        buffer = io.BytesIO()
        with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as z:
            for name, text in (
                ("[Content_Types].xml", _CONTENT_TYPES),
                ("_rels/.rels", _RELS),
                ("3D/3dmodel.model", self.model_xml()),
            ):
                z.writestr(zipfile.ZipInfo(name, (1980, 1, 1, 0, 0, 0)), text.encode("utf-8"))
        return buffer.getvalue()

    def write(self, path: str | Path) -> Path:
        """Write the model to ``path``: ``.stl`` (binary) or ``.3mf``, by its extension.

        Examples
        --------
        >>> import tempfile, os
        >>> with tempfile.TemporaryDirectory() as d:
        ...     m = print_model((0, 0, 0), (4, 0, 0), (0, 3, 0))
        ...     os.path.getsize(m.write(os.path.join(d, "triangle.stl")))
        13584
        """
        path = Path(path)
        ext = path.suffix.lower()
        if ext == ".stl":
            path.write_bytes(self.stl())
        elif ext == ".3mf":
            path.write_bytes(self.three_mf())
        else:
            raise PrintModelError(PRINT_MESSAGES["format"].format(path=path))
        return path


_CONTENT_TYPES = (
    '<?xml version="1.0" encoding="UTF-8"?>\n'
    '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
    '<Default Extension="rels" '
    'ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
    '<Default Extension="model" '
    'ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
    "</Types>\n"
)
_RELS = (
    '<?xml version="1.0" encoding="UTF-8"?>\n'
    '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
    '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
    'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>'
    "</Relationships>\n"
)


def check_size(size: object) -> float:
    """Return the size in millimetres; refuse anything but a number from 50 to 1000.

    Examples
    --------
    >>> check_size("60")
    60.0
    >>> check_size(5)
    Traceback (most recent call last):
    ...
    trinormal.printmodel.PrintModelError: size must be ... from 50 to 1000, got 5
    """
    low, high = SIZE_RANGE
    try:
        value = float(size) if isinstance(size, int | float | str | Fraction) else math.nan
    except ValueError:
        value = math.nan
    if isinstance(size, bool) or not low <= value <= high:
        raise PrintModelError(
            PRINT_MESSAGES["size"].format(low=_num(low), high=_num(high), got=size)
        )
    return value


def build(u: Any, v: Any, names: str, size: float, marks: str) -> PrintModel:
    """Make the model of a proper triangle with edges u and v (floats), corners ``names``.

    The part the site's JavaScript ports: given the same floats it makes the
    same vertices and faces. `print_model` checks the input and calls it.
    """
    try:
        layout = F.fitted(u, v, size, marks, names)
    except F.Unfit as exc:
        fits = F.smallest_size(u, v, size, marks, names)
        if fits is None:
            words = PRINT_MESSAGES["too_thin_always"].format(size=_num(SIZE_RANGE[1]), reason=exc)
        else:
            words = PRINT_MESSAGES["too_thin"].format(size=_num(size), reason=exc, fits=_num(fits))
        raise PrintModelError(words) from None
    solid = F.solid(layout, size, marks, names)
    top = _snap(THICKNESS + F.ARROW_LENGTH * size)
    return PrintModel(
        vertices=tuple(solid.vertices),
        faces=tuple(solid.faces),
        corners=tuple((p[0], p[1], THICKNESS) for p in layout.corners),
        names=names,
        tip=(_snap(layout.centroid[0]), _snap(layout.centroid[1]), top),
        size=size,
        marks=marks,
    )


def print_model(
    a: Any,
    b: Any,
    c: Any,
    *,
    winding: object = "ABC",
    size: object = DEFAULT_SIZE,
    marks: str = "letters",
) -> PrintModel:
    """Make a printable model of the triangle ABC and its normal: plate, arrow, ridges, marks.

    Parameters
    ----------
    a, b, c : sequence of three coordinates
        The corners, read exactly as `trinormal.triangle_normal` reads them.
    winding : {"ABC", "ACB"}
        The order whose front is the plate's top: with ``"ACB"`` U = C − A,
        V = B − A and the arrow stands on the other side.
    size : float
        The plate's longest side in millimetres, 50 to 1000 (default 80).
    marks : {"letters", "braille"}
        How A, B and C are marked beside their corners.

    Returns
    -------
    PrintModel
        The solid; `PrintModel.stl`, `PrintModel.three_mf` and
        `PrintModel.write` make its files.

    Raises
    ------
    PrintModelError
        For a degenerate triangle, one too thin to carry the features at this
        size (the message names the size that fits), a size out of range or an
        unknown kind of marks.
    ValueError
        For a coordinate that cannot be read (the message names vertex and axis).

    Examples
    --------
    >>> m = print_model((0, 0, 0), (2, 0, 0), (0, 1, 1), size=100)
    >>> max(z for x, y, z in m.vertices) == m.tip[2]
    True
    >>> print_model((0, 0, 0), (1, 1, 1), (2, 2, 2))
    Traceback (most recent call last):
    ...
    trinormal.printmodel.PrintModelError: A degenerate triangle cannot be printed: ...
    >>> print_model((0, 0, 0), (1, 0, 0), (0.5, 0.2, 0)).corners  # 80 × 16 mm
    ((0.0, 0.0, 3.0), (80.0, 0.0, 3.0), (40.0, 16.0, 3.0))
    >>> print_model((0, 0, 0), (1, 0, 0), (0.5, 0.05, 0))
    Traceback (most recent call last):
    ...
    trinormal.printmodel.PrintModelError: This triangle is too thin ... (--size 159), or ...
    """
    if marks not in MARKS:
        raise PrintModelError(PRINT_MESSAGES["marks_kind"].format(got=repr(marks)))
    mm = check_size(size)
    w = check_winding(winding)
    r = triangle_normal(a, b, c, winding=w)
    if r.degenerate:
        raise PrintModelError(PRINT_MESSAGES["degenerate"])
    return build(r.u, r.v, "A" + w.value[1:], mm, marks)


def site_constants() -> dict[str, Any]:
    """Give the site's port every size, shape and message it reads, from here.

    Examples
    --------
    >>> site_constants()["braille"]["B"]
    [[0, 0], [0, 1]]
    """
    return {
        "default_size": DEFAULT_SIZE,
        "download_name": DOWNLOAD_NAME,
        "size_range": list(SIZE_RANGE),
        "marks": list(MARKS),
        "thickness": THICKNESS,
        "ridge_height": F.RIDGE_HEIGHT,
        "shaft_radius": F.SHAFT_RADIUS,
        "head_radius": F.HEAD_RADIUS,
        "head_length": F.HEAD_LENGTH,
        "arrow_length": F.ARROW_LENGTH,
        "letter_height": F.LETTER_HEIGHT,
        "dot_radius": list(F.DOT_RADIUS),
        "dot_height": F.DOT_HEIGHT,
        "dot_spacing": F.DOT_SPACING,
        "grid": F.GRID,
        "mark_radius": dict(F.MARK_RADIUS),
        "fits": [list(f) for f in F.FITS],
        "letters": {k: [[list(p) for p in ring] for ring in v] for k, v in F.LETTERS.items()},
        "braille": {k: [list(p) for p in v] for k, v in F.BRAILLE.items()},
        "messages": dict(PRINT_MESSAGES),
        "stl_header": _STL_HEADER.decode("ascii"),
    }


#: The printed model the "Check a mesh" page offers beside its damaged examples: file name,
#: the button's words, and the triangle (the one ``trinormal print-model`` is shown with).
SAMPLE = (
    "printed-triangle.stl",
    "A triangle ready to print, with its normal (binary STL from trinormal print-model)",
    ((1, 0, 0), (0, 2, 0), (0, 0, 3)),
)


def sample_file() -> bytes:
    """Return the binary STL of `SAMPLE`'s triangle, as ``trinormal print-model`` writes it.

    Examples
    --------
    >>> len(sample_file()) == 84 + 50 * 270
    True
    """
    return print_model(*SAMPLE[2]).stl()
