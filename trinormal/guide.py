r"""The guide's inputs and published numbers, and the same numbers rebuilt by trinormal.

The guide that trinormal teaches prints a worked example, a four-row comparison
table and a table of floating-point precisions. This module keeps what the
guide *publishes* (as data, exactly as printed) next to functions that
*recompute* every value from [`trinormal.triangle_normal`][trinormal.core.triangle_normal], so a
test can check one against the other and the documentation site can show numbers
generated at build time instead of typed in.

Examples
--------
>>> print(comparison_table_markdown())
| Triangle vertices | Raw normal N | |N| | Area | Unit normal |
|---|---|---|---|---|
| (0,0,0), (1,0,0), (0,1,0) | (0, 0, 1) | 1 | 0.5 | (0, 0, 1) |
| (0,0,0), (2,0,0), (0,3,0) | (0, 0, 6) | 6 | 3 | (0, 0, 1) |
| (1,1,1), (2,1,1), (1,2,2) | (0, -1, 1) | 1.4142 | 0.7071 | (0, -0.7071, 0.7071) |
| (0,0,0), (1,1,1), (2,2,2) | (0, 0, 0) | 0 | 0 | Undefined |
"""

from __future__ import annotations

import math
import struct
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from trinormal.core import TriangleNormal, triangle_normal
from trinormal.display import format_number, format_vector

__all__ = [
    "COMPARISON_HEADERS",
    "COMPARISON_ROWS",
    "COMPARISON_TABLE_PRECISION",
    "MISTAKES",
    "PRECISION_FORMATS",
    "SLIVER_FACES",
    "SLIVER_VERTICES",
    "WORKED_EXAMPLE",
    "ComparisonRow",
    "FloatFormat",
    "NormalisingCase",
    "comparison_table_cells",
    "comparison_table_markdown",
    "normalising_cases",
    "normalising_table_markdown",
    "parse_markdown_table",
    "precision_table_markdown",
    "reflect",
    "worked_example",
    "worked_example_markdown",
]

Point = tuple[int, int, int]

# --------------------------------------------------------------------------- the worked example


@dataclass(frozen=True)
class WorkedExample:
    """The guide's worked example: its inputs and the values it prints (as printed)."""

    a: Point
    b: Point
    c: Point
    u: str
    v: str
    normal: str
    magnitude: str
    area: str
    unit_normal: str
    reversed_normal: str


#: The worked example as the guide states it; ``reversed_normal`` is (C − A) × (B − A).
WORKED_EXAMPLE = WorkedExample(
    a=(0, 0, 0),
    b=(1, 0, 0),
    c=(0, 1, 0),
    u="(1, 0, 0)",
    v="(0, 1, 0)",
    normal="(0, 0, 1)",
    magnitude="1",
    area="0.5",
    unit_normal="(0, 0, 1)",
    reversed_normal="(0, 0, -1)",
)


def worked_example(precision: int = 4, trim: bool = True) -> dict[str, str]:
    """Recompute the guide's worked example with trinormal, as display strings.

    Parameters
    ----------
    precision : int, default 4
        Decimal places (see [`trinormal.format_number`][trinormal.display.format_number]).
    trim : bool, default True
        Drop trailing zeros, as the guide prints its numbers.

    Returns
    -------
    dict of str
        ``a``, ``b``, ``c``, ``u``, ``v``, ``normal``, ``magnitude``, ``area``,
        ``unit_normal`` and ``reversed_normal`` (the ACB winding's N).

    Examples
    --------
    >>> w = worked_example()
    >>> w["normal"], w["area"], w["reversed_normal"]
    ('(0, 0, 1)', '0.5', '(0, 0, -1)')
    """
    ex = WORKED_EXAMPLE
    r = triangle_normal(ex.a, ex.b, ex.c)
    f = r.format(precision, trim=trim)
    flipped = triangle_normal(ex.a, ex.b, ex.c, winding="ACB").format(precision, trim=trim)
    computed = ("u", "v", "normal", "magnitude", "area", "unit_normal")
    return {
        "a": format_vector(ex.a, precision, trim=True),
        "b": format_vector(ex.b, precision, trim=True),
        "c": format_vector(ex.c, precision, trim=True),
        **{key: f[key] for key in computed},
        "reversed_normal": flipped["normal"],
    }


def worked_example_markdown() -> str:
    """Write the worked example as a short Markdown list, every number from trinormal.

    Examples
    --------
    >>> print(worked_example_markdown().splitlines()[0])
    - A = (0, 0, 0), B = (1, 0, 0), C = (0, 1, 0)
    """
    w = worked_example()
    return "\n".join(
        [
            f"- A = {w['a']}, B = {w['b']}, C = {w['c']}",
            f"- U = B − A = {w['u']}, V = C − A = {w['v']}",
            f"- N = U × V = {w['normal']}, |N| = {w['magnitude']}, area = {w['area']}",
            f"- unit normal = {w['unit_normal']}",
            f"- the order A → C → B gives N = {w['reversed_normal']}",
        ]
    )


# --------------------------------------------------------------------------- the comparison table

#: The table's column headers, as the guide prints them.
COMPARISON_HEADERS: tuple[str, str, str, str, str] = (
    "Triangle vertices",
    "Raw normal N",
    "|N|",
    "Area",
    "Unit normal",
)

#: Decimal places the guide's table uses (with trailing zeros dropped).
COMPARISON_TABLE_PRECISION = 4


@dataclass(frozen=True)
class ComparisonRow:
    """One row of the guide's comparison table: the inputs and the published cells."""

    a: Point
    b: Point
    c: Point
    normal: str
    magnitude: str
    area: str
    unit_normal: str


#: The four rows as the guide publishes them (the cells are strings, as printed).
COMPARISON_ROWS: tuple[ComparisonRow, ...] = (
    ComparisonRow((0, 0, 0), (1, 0, 0), (0, 1, 0), "(0, 0, 1)", "1", "0.5", "(0, 0, 1)"),
    ComparisonRow((0, 0, 0), (2, 0, 0), (0, 3, 0), "(0, 0, 6)", "6", "3", "(0, 0, 1)"),
    ComparisonRow(
        (1, 1, 1), (2, 1, 1), (1, 2, 2), "(0, -1, 1)", "1.4142", "0.7071", "(0, -0.7071, 0.7071)"
    ),
    ComparisonRow((0, 0, 0), (1, 1, 1), (2, 2, 2), "(0, 0, 0)", "0", "0", "Undefined"),
)


def _capital(text: str) -> str:
    """Upper-case the first letter only (`str.capitalize` would lower the others)."""
    return text[:1].upper() + text[1:]


def _vertices_cell(row: ComparisonRow) -> str:
    def point(p: Sequence[int]) -> str:
        return "(" + ",".join(format_number(x, 0, trim=True) for x in p) + ")"

    return ", ".join(point(p) for p in (row.a, row.b, row.c))


def _row_cells(row: ComparisonRow, r: TriangleNormal, precision: int) -> list[str]:
    f = r.format(precision, trim=True)
    unit = f["unit_normal"]
    if r.degenerate:  # the guide capitalises the word in its table
        unit = _capital(unit)
    return [_vertices_cell(row), f["normal"], f["magnitude"], f["area"], unit]


def comparison_table_cells(
    precision: int = COMPARISON_TABLE_PRECISION,
) -> list[list[str]]:
    """Recompute the guide's comparison table: a header row, then one row per triangle.

    Every number is computed by [`trinormal.triangle_normal`][trinormal.core.triangle_normal] from
    the row's vertices and formatted by
    [`TriangleNormal.format`][trinormal.core.TriangleNormal.format] with trailing zeros
    trimmed; nothing is copied from the published cells.

    Examples
    --------
    >>> comparison_table_cells()[3]
    ['(1,1,1), (2,1,1), (1,2,2)', '(0, -1, 1)', '1.4142', '0.7071', '(0, -0.7071, 0.7071)']
    """
    rows = [list(COMPARISON_HEADERS)]
    for row in COMPARISON_ROWS:
        rows.append(_row_cells(row, triangle_normal(row.a, row.b, row.c), precision))
    return rows


def comparison_table_markdown(
    precision: int = COMPARISON_TABLE_PRECISION, escape_pipes: bool = False
) -> str:
    r"""Rebuild the guide's comparison table as Markdown, from the package.

    Parameters
    ----------
    precision : int, default 4
        Decimal places (the guide uses 4).
    escape_pipes : bool, default False
        Write ``|`` inside a cell as ``\|``. The guide prints the header
        ``|N|`` unescaped, which the default reproduces character for
        character; Markdown renderers (the site, JupyterLab) need the escaped
        form to see five columns.

    Returns
    -------
    str
        The header line, the ``|---|`` line and four rows, joined by newlines.

    Examples
    --------
    >>> comparison_table_markdown(escape_pipes=True).splitlines()[0]
    '| Triangle vertices | Raw normal N | \\|N\\| | Area | Unit normal |'
    """
    cells = comparison_table_cells(precision)

    def line(row: Sequence[str]) -> str:
        if escape_pipes:
            row = [c.replace("|", "\\|") for c in row]
        return "| " + " | ".join(row) + " |"

    lines = [line(cells[0]), "|" + "---|" * len(cells[0])]
    lines += [line(r) for r in cells[1:]]
    return "\n".join(lines)


def parse_markdown_table(text: str) -> list[list[str]]:
    r"""Read the cells of a Markdown table as the guide writes it.

    Cells are separated by ``" | "`` (a pipe between spaces), so a header like
    ``|N|`` stays one cell; ``\|`` is read as a literal pipe. The ``|---|``
    line is skipped, as are lines that do not start with ``|``.

    Examples
    --------
    >>> parse_markdown_table("| a | |N| |\n|---|---|\n| 1 | 2 |")
    [['a', '|N|'], ['1', '2']]
    """
    rows = []
    for raw in text.splitlines():
        s = raw.strip().replace("\\|", "\x00")
        if not s.startswith("|"):
            continue
        body = s[1:-1] if s.endswith("|") else s[1:]
        if set(body) <= set("-|: "):
            continue
        rows.append([c.strip().replace("\x00", "|") for c in f" {body} ".split(" | ")])
    return rows


# --------------------------------------------------------------------------- precision


@dataclass(frozen=True)
class FloatFormat:
    """One IEEE binary format as the guide's precision table describes it."""

    name: str
    bits: int
    significand_bits: int
    typical_use: str
    implication: str

    @property
    def decimal_digits(self) -> float:
        """Decimal digits carried by the significand: ``significand_bits · log10(2)``."""
        return self.significand_bits * math.log10(2)

    @property
    def decimal_digits_text(self) -> str:
        """The decimal digits in words: ``about 7`` for 7.2, ``about 15 to 16`` for 15.95.

        Examples
        --------
        >>> [f.decimal_digits_text for f in PRECISION_FORMATS]
        ['about 7', 'about 15 to 16']
        """
        x = self.decimal_digits
        low = math.floor(x)
        return f"about {low}" if x - low < 0.5 else f"about {low} to {low + 1}"

    @property
    def machine_epsilon(self) -> float:
        """The gap between 1 and the next number, ``2**(1 − significand_bits)``."""
        return 2.0 ** (1 - self.significand_bits)


def _significand_bits(code: str) -> int:
    """Significand precision of a ``struct`` float format, found by testing 1 + 2**-k."""
    k = 1
    while struct.unpack(code, struct.pack(code, 1.0 + 2.0**-k))[0] != 1.0:
        k += 1
    return k


#: The two formats in the guide's precision table; the bit counts are measured, not typed.
PRECISION_FORMATS: tuple[FloatFormat, ...] = (
    FloatFormat(
        "32-bit float",
        32,
        _significand_bits("f"),
        "real-time graphics: games and GPU shaders",
        "fast, but rounding error grows for small triangles far from the origin",
    ),
    FloatFormat(
        "64-bit double",
        64,
        _significand_bits("d"),
        "engineering: CAD, simulation and science",
        "much steadier for tiny areas, large scenes and repeated transformations",
    ),
)


def precision_table_markdown() -> str:
    """Rebuild the guide's precision table as Markdown, the significand bits measured here.

    Examples
    --------
    >>> precision_table_markdown().splitlines()[2].split(" | ")[:3]
    ['| 32-bit float', '24 binary digits', 'About 7 decimal digits']
    """
    lines = [
        "| Numeric format | Significand precision | Approximate decimal digits "
        "| Machine epsilon | Typical geometry use | Practical implication for normals |",
        "|---|---|---|---|---|---|",
    ]
    for f in PRECISION_FORMATS:
        eps = format_number(f.machine_epsilon, 4)
        lines.append(
            f"| {f.name} | {f.significand_bits} binary digits | "
            f"{_capital(f.decimal_digits_text)} decimal digits | {eps} | "
            f"{_capital(f.typical_use)} | {_capital(f.implication)} |"
        )
    return "\n".join(lines)


# --------------------------------------------------------------------------- when to normalise

Vec3 = tuple[float, float, float]

#: Notebook 4's vertex: a large face facing +z and a thin sliver facing +x meet at vertex 0.
SLIVER_VERTICES: tuple[tuple[float, float, float], ...] = (
    (0, 0, 0),
    (3, 0, 0),
    (0, 3, 0),
    (0, 1, 0),
    (0, 1, 0.2),
)
#: The two faces of that vertex, each listed counter-clockwise seen from its normal's side.
SLIVER_FACES: tuple[tuple[int, int, int], ...] = ((0, 1, 2), (0, 3, 4))


@dataclass(frozen=True)
class NormalisingCase:
    """One way of summing face normals into a vertex normal, and what it amounts to.

    Attributes
    ----------
    recipe : str
        What is added up, e.g. ``"raw normals summed"``.
    weighting : str
        The weighting that recipe amounts to, or the mistake it is.
    mistake : bool
        True when the recipe is a mistake (a normalisation too early or missing).
    normal : tuple of float
        The sum, normalised once at the end: the unit vertex normal.
    """

    recipe: str
    weighting: str
    mistake: bool
    normal: Vec3


def _unit(v: Sequence[float]) -> Vec3:
    length = math.sqrt(sum(x * x for x in v))
    return (v[0] / length, v[1] / length, v[2] / length)


def _corner_angle(p: Sequence[float], q: Sequence[float], r: Sequence[float]) -> float:
    """Return the angle at corner p of triangle p, q, r (radians), from atan2(|u × v|, u · v)."""
    u = [b - a for a, b in zip(p, q, strict=True)]
    v = [b - a for a, b in zip(p, r, strict=True)]
    cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return math.atan2(
        math.sqrt(sum(x * x for x in cross)), sum(a * b for a, b in zip(u, v, strict=True))
    )


def normalising_cases(
    vertices: Sequence[Sequence[float]] = SLIVER_VERTICES,
    faces: Sequence[Sequence[int]] = SLIVER_FACES,
    vertex: int = 0,
) -> tuple[NormalisingCase, ...]:
    """Sum the normals of the faces at a vertex four ways: when to normalise, in numbers.

    A face normal's length is twice the face's area. Area weighting uses that
    length as the weight, so it sums the raw normals; angle weighting uses the
    corner angle as the whole weight, so it multiplies each *unit* normal by its
    angle. Normalising too early (unit normals summed when area weighting was
    meant) or not at all (raw normals times angles) gives a different vector.
    Every recipe normalises its sum once, at the end.

    Parameters
    ----------
    vertices : sequence of (x, y, z)
        Vertex coordinates; notebook 4's large face and sliver by default.
    faces : sequence of (i, j, k)
        Vertex indices of each triangle.
    vertex : int, default 0
        The vertex whose normal is summed.

    Returns
    -------
    tuple of NormalisingCase
        Unit normals summed (equal votes), raw normals summed (area weighting),
        unit normals times corner angles (angle weighting, recommended) and raw
        normals times corner angles (a mistake), in that order.

    Examples
    --------
    >>> for case in normalising_cases():
    ...     print(f"{case.recipe:29s} {format_vector(case.normal, 4)}")
    unit normals summed           (0.7071, 0.0000, 0.7071)
    raw normals summed            (0.0222, 0.0000, 0.9998)
    unit normals × corner angles  (0.1247, 0.0000, 0.9922)
    raw normals × corner angles   (0.0028, 0.0000, 1.0000)
    """
    raw: list[Vec3] = []
    unit: list[Vec3] = []
    angles: list[float] = []
    for face in faces:
        if vertex not in face:
            continue
        pts = [vertices[i] for i in face]
        r = triangle_normal(pts[0], pts[1], pts[2])
        if r.unit_normal is None:
            continue
        n = r.exact.normal
        raw.append((float(n[0]), float(n[1]), float(n[2])))
        unit.append(r.unit_normal)
        k = list(face).index(vertex)
        angles.append(_corner_angle(pts[k], pts[(k + 1) % 3], pts[(k + 2) % 3]))

    def total(vectors: Sequence[Vec3], weights: Sequence[float]) -> Vec3:
        return _unit(
            [sum(w * v[i] for v, w in zip(vectors, weights, strict=True)) for i in range(3)]
        )

    ones = [1.0] * len(raw)
    return (
        NormalisingCase(
            "unit normals summed",
            "equal votes: normalised too early if area weighting was meant",
            True,
            total(unit, ones),
        ),
        NormalisingCase("raw normals summed", "area weighting", False, total(raw, ones)),
        NormalisingCase(
            "unit normals × corner angles",
            "angle weighting (recommended)",
            False,
            total(unit, angles),
        ),
        NormalisingCase(
            "raw normals × corner angles",
            "area times angle: not normalised where angle weighting needs it",
            True,
            total(raw, angles),
        ),
    )


def normalising_table_markdown(precision: int = 4) -> str:
    """Tabulate the four sums of [`normalising_cases`][trinormal.guide.normalising_cases].

    Examples
    --------
    >>> print(normalising_table_markdown().splitlines()[4])
    | Unit normals × corner angles | Angle weighting (recommended) | (0.1247, 0, 0.9922) |
    """
    lines = [
        "| What is added up | What it amounts to | Vertex normal (sum normalised at the end) |",
        "|---|---|---|",
    ]
    for case in normalising_cases():
        lines.append(
            f"| {_capital(case.recipe)} | {_capital(case.weighting)} | "
            f"{format_vector(case.normal, precision, trim=True)} |"
        )
    return "\n".join(lines)


def _normalizing_too_early() -> str:
    cases = {c.recipe: format_vector(c.normal, 4, trim=True) for c in normalising_cases()}
    return (
        "The length of N is twice the area, and area weighting uses it as the weight: "
        "normalising each face normal before adding gives a sliver the same vote as a large "
        "face. At notebook 4's vertex (a large face and a sliver) the raw sum gives "
        f"{cases['raw normals summed']}, the sum of unit normals {cases['unit normals summed']}. "
        "Angle weighting, which trinormal recommends, does normalise each face first, because "
        "there the corner angle is the whole weight: unit normals times angles give "
        f"{cases['unit normals × corner angles']}, while raw normals times angles give "
        f"{cases['raw normals × corner angles']}. Either way, normalise the sum once, at the end."
    )


# --------------------------------------------------------------------------- reflection


def reflect(direction: Sequence[Any], normal: Sequence[Any]) -> tuple[Fraction, Fraction, Fraction]:
    """Reflect a ray direction d about a plane with normal N: r = d − 2 (d · n̂) n̂, exactly.

    With n̂ = N / |N| the formula becomes r = d − 2 (d · N) / (N · N) N, which
    needs no square root, so a raw normal (even an unnormalised one) gives the
    exact reflection in rational arithmetic. The reflected ray keeps the
    length of d, and d · N changes sign.

    Parameters
    ----------
    direction : sequence of 3 numbers
        The incoming ray direction d (int, float, Fraction or numeric string).
    normal : sequence of 3 numbers
        A normal of the mirror plane, of any nonzero length, e.g.
        ``triangle_normal(a, b, c).exact.normal``.

    Returns
    -------
    tuple of 3 Fraction
        The reflected direction r, exactly.

    Raises
    ------
    ValueError
        If the normal is the zero vector (a degenerate triangle has no plane).

    Examples
    --------
    A ray going down onto the floor z = 0 bounces straight back up in z:

    >>> n = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).exact.normal
    >>> format_vector(reflect((1, 2, -3), n), 4, trim=True)
    '(1, 2, 3)'
    """
    d = [Fraction(x) for x in direction]
    n = [Fraction(x) for x in normal]
    if len(d) != 3 or len(n) != 3:
        raise ValueError("reflect needs a direction and a normal of three components each")
    nn = sum(x * x for x in n)
    if nn == 0:
        raise ValueError(
            "the normal is (0, 0, 0): a degenerate triangle has no plane to reflect in"
        )
    k = 2 * sum(a * b for a, b in zip(d, n, strict=True)) / nn
    return (d[0] - k * n[0], d[1] - k * n[1], d[2] - k * n[2])


# --------------------------------------------------------------------------- mistakes

#: The guide's five common mistakes, in our words: (short name, what goes wrong).
MISTAKES: tuple[tuple[str, str], ...] = (
    (
        "wrong subtraction order",
        "Computing A − B instead of B − A, or swapping the edges, flips the sign of N.",
    ),
    (
        "dot instead of cross",
        "U · V is a single number about the angle between the edges, not a vector "
        "perpendicular to them.",
    ),
    (
        "normalizing a zero-area triangle",
        "Collinear or coincident points give N = 0, and 0 / 0 has no direction.",
    ),
    (
        "normalizing too early",
        _normalizing_too_early(),
    ),
    (
        "a 2D triangle without a third coordinate",
        "A flat triangle needs z = 0 added before a cross product exists; its normal "
        "then points along ±z, the sign set by the winding.",
    ),
)
