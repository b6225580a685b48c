"""The worked solution, step by step: one engine for the CLI, the notebooks and sympy.

[`working`][trinormal.steps.working] gathers every exact value a worked solution shows for one
result: the points, the edges, N and its three cross-product terms, |N|² and
|N| = c·√m (a rational times the square root of an integer), the area, the
unit normal and the plane's offset. [`steps`][trinormal.cli.steps] writes them out as plain
text (the CLI's ``--steps``); [`trinormal.symbolic.steps`][trinormal.symbolic.steps] writes the same
steps in LaTeX for the notebooks. Both read their numbers and the order of the
cross-product terms from here.

The standard library is all this module needs.

Examples
--------
>>> from trinormal import triangle_normal
>>> w = working(triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2)))
>>> w.normal, w.magnitude_squared
((Fraction(0, 1), Fraction(-1, 1), Fraction(1, 1)), Fraction(2, 1))
>>> w.root, w.radicand
(Fraction(1, 1), 2)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from trinormal.core import TriangleNormal, Winding
from trinormal.display import exact_text, format_surd, radical, radical_text

__all__ = ["CROSS_TERMS", "Edge", "Working", "points_text", "steps", "working"]

Point = tuple[Fraction, Fraction, Fraction]

#: N = U × V, component by component: ``(axis, i, j)`` means
#: ``N_axis = U_i·V_j − U_j·V_i`` (axes numbered 0, 1, 2 for x, y, z).
CROSS_TERMS: tuple[tuple[str, int, int], ...] = (("x", 1, 2), ("y", 2, 0), ("z", 0, 1))


@dataclass(frozen=True)
class Edge:
    """One edge vector: ``name = end − A``.

    Attributes
    ----------
    name : {"U", "V"}
    end : {"B", "C"}
        The vertex the edge runs to from A (set by the winding).
    end_point : tuple of Fraction
        That vertex's coordinates.
    vector : tuple of Fraction
        ``end_point − A``.
    """

    name: str
    end: str
    end_point: Point
    vector: Point


@dataclass(frozen=True)
class Working:
    """Every exact value of the worked solution for one result.

    Irrational values are written ``coefficient · √radicand`` with one
    radicand shared by all of them: |N| = ``root``·√m, the area =
    ``root``/2·√m, each unit-normal component ``unit_normal[i]``·√m and the
    plane's offset ``offset``·√m (m is `radicand`, free of small squares).

    Attributes
    ----------
    a, b, c : tuple of Fraction
        The points.
    winding : Winding
        The order, which decides the edges.
    edges : tuple of Edge
        U and V.
    normal : tuple of Fraction
        N = U × V.
    magnitude_squared : Fraction
        |N|².
    root, radicand : Fraction, int
        |N| = root·√radicand.
    unit_normal : tuple of Fraction or None
        The coefficients of √radicand in N / |N|; ``None`` when degenerate.
    offset : Fraction or None
        The coefficient of √radicand in d = n̂ · A; ``None`` when degenerate.
    degenerate : bool
    reason : str
        Why the triangle is degenerate, or ``""``.
    """

    a: Point
    b: Point
    c: Point
    winding: Winding
    edges: tuple[Edge, Edge]
    normal: Point
    magnitude_squared: Fraction
    root: Fraction
    radicand: int
    unit_normal: Point | None
    offset: Fraction | None
    degenerate: bool
    reason: str

    @property
    def u(self) -> Point:
        """The first edge vector."""
        return self.edges[0].vector

    @property
    def v(self) -> Point:
        """The second edge vector."""
        return self.edges[1].vector


def working(result: TriangleNormal) -> Working:
    """Gather the exact values of the worked solution for a result.

    Parameters
    ----------
    result : TriangleNormal
        A result from [`trinormal.triangle_normal`][trinormal.core.triangle_normal] (in any
        arithmetic: the working is always exact).

    Returns
    -------
    Working

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> w = working(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="ACB"))
    >>> [(e.name, e.end) for e in w.edges], w.unit_normal
    ([('U', 'C'), ('V', 'B')], (Fraction(0, 1), Fraction(0, 1), Fraction(-1, 1)))
    """
    e = result.exact
    ends = (("B", e.b), ("C", e.c)) if result.winding is Winding.ABC else (("C", e.c), ("B", e.b))
    edges = (Edge("U", *ends[0], e.u), Edge("V", *ends[1], e.v))
    # |N| = sqrt(S) / D² with S the integer |N|² · D⁴: splitting S (not the reduced
    # fraction's numerator times its denominator) keeps the numbers small
    integers = result._integers
    k, m = radical(Fraction(integers.norm_squared))
    root = k / (integers.denominator * integers.denominator)
    unit: Point | None = None
    offset = None
    if not result.degenerate:
        # n_i = N_i / (root·√m) = N_i / (root·m) · √m, and likewise d = (N · A) / |N|
        x, y, z = (n / (root * m) for n in e.normal)
        unit = (x, y, z)
        dot = sum((n * p for n, p in zip(e.normal, e.a, strict=True)), Fraction(0))
        offset = dot / (root * m)
    return Working(
        e.a,
        e.b,
        e.c,
        result.winding,
        edges,
        e.normal,
        e.magnitude_squared,
        root,
        m,
        unit,
        offset,
        result.degenerate,
        result.reason,
    )


# --------------------------------------------------------------------------- plain text


def _vec(xs: Sequence[Fraction]) -> str:
    return "(" + ", ".join(exact_text(x) for x in xs) + ")"


def _term(q: Fraction) -> str:
    """Write a number inside a formula: negative values and fractions in parentheses."""
    text = exact_text(q)
    return f"({text})" if q < 0 or "/" in text else text


def points_text(w: Working) -> str:
    """Write the points as the first line of the working.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> points_text(working(triangle_normal(("0.5", 0, 0), (1, 0, 0), (0, "1/3", 0))))
    'A = (0.5, 0, 0), B = (1, 0, 0), C = (0, 1/3, 0)'
    """
    return f"A = {_vec(w.a)}, B = {_vec(w.b)}, C = {_vec(w.c)}"


def steps(r: TriangleNormal, precision: int = 4) -> list[tuple[str, str]]:
    """Write out the working for a result, step by step, with exact numbers.

    Every value is exact: rationals as decimals or fractions, and |N|, the unit
    normal and the plane offset as radicals (``√2/2``), followed by a rounded
    decimal where the value is irrational.

    Parameters
    ----------
    r : TriangleNormal
        A result from [`trinormal.triangle_normal`][trinormal.core.triangle_normal].
    precision : int, default 4
        Decimal places for the rounded decimals.

    Returns
    -------
    list of (str, str)
        ``(label, working)`` pairs.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    >>> for label, text in steps(r):
    ...     print(f"{label} = {text}")
    U = B − A = (2 − 1, 1 − 1, 1 − 1) = (1, 0, 0)
    V = C − A = (1 − 1, 2 − 1, 2 − 1) = (0, 1, 1)
    Nx = Uy·Vz − Uz·Vy = 0·1 − 0·1 = 0
    Ny = Uz·Vx − Ux·Vz = 0·0 − 1·1 = -1
    Nz = Ux·Vy − Uy·Vx = 1·1 − 0·0 = 1
    N = (0, -1, 1)
    |N|² = Nx² + Ny² + Nz² = 2
    |N| = √2 ≈ 1.4142
    area = |N| / 2 = √2/2 ≈ 0.7071
    n̂ = N / |N| = (0, -√2/2, √2/2) ≈ (0.0000, -0.7071, 0.7071)
    plane = n̂ · X = n̂ · A, so d = 0
    """
    w = working(r)
    out: list[tuple[str, str]] = []
    for edge in w.edges:
        diffs = ", ".join(
            f"{_term(x)} − {_term(y)}" for x, y in zip(edge.end_point, w.a, strict=True)
        )
        out.append((edge.name, f"{edge.end} − A = ({diffs}) = {_vec(edge.vector)}"))
    axes = "xyz"
    for (axis, i, j), n in zip(CROSS_TERMS, w.normal, strict=True):
        ui, uj, vi, vj = _term(w.u[i]), _term(w.u[j]), _term(w.v[i]), _term(w.v[j])
        formula = f"U{axes[i]}·V{axes[j]} − U{axes[j]}·V{axes[i]}"
        out.append((f"N{axis}", f"{formula} = {ui}·{vj} − {uj}·{vi} = {exact_text(n)}"))
    out.append(("N", _vec(w.normal)))
    m2, m = w.magnitude_squared, w.radicand
    out.append(("|N|²", f"Nx² + Ny² + Nz² = {exact_text(m2)}"))

    def approx(neg: bool, q: Fraction) -> str:
        return format_surd(neg, q.numerator, q.denominator, precision)

    suffix = "" if m == 1 else f" ≈ {approx(False, m2)}"
    out.append(("|N|", f"{radical_text(w.root, m)}{suffix}"))
    suffix = "" if m == 1 else f" ≈ {approx(False, m2 / 4)}"
    out.append(("area", f"|N| / 2 = {radical_text(w.root / 2, m)}{suffix}"))
    if w.unit_normal is None or w.offset is None:
        out.append(("n̂", f"undefined. Degenerate: {w.reason}"))
        return out
    unit_text = "(" + ", ".join(radical_text(x, m) for x in w.unit_normal) + ")"
    if m != 1:
        rounded = ", ".join(approx(x < 0, x * x / m2) for x in w.normal)
        unit_text += f" ≈ ({rounded})"
    out.append(("n̂", f"N / |N| = {unit_text}"))
    d_text = radical_text(w.offset, m)
    if m != 1 and w.offset != 0:
        d_text += f" ≈ {approx(w.offset < 0, w.offset * w.offset * m)}"  # d² = offset²·m
    out.append(("plane", f"n̂ · X = n̂ · A, so d = {d_text}"))
    return out
