r"""The normal of a triangle, derived and proven with sympy.

Nothing here is typed in: the component formulas come from
`sympy.Matrix.cross` applied to the edge vectors, the identities are
proven by simplifying their two sides' difference to zero, and
[`steps`][trinormal.symbolic.steps] substitutes a reader's own numbers into the derived formulas
with exact rational arithmetic. The steps and their exact inputs are those of
[`trinormal.steps`][trinormal.steps], the engine behind the CLI's ``--steps`` too; this
module writes them in LaTeX.

The symbols are the guide's own: A = (x1, y1, z1), B = (x2, y2, z2),
C = (x3, y3, z3), and the edges U = (Ux, Uy, Uz), V = (Vx, Vy, Vz).

Examples
--------
>>> n = normal_components()
>>> n.z
(-x1 + x2)*(-y1 + y3) - (-x1 + x3)*(-y1 + y2)
>>> normal_components("edges")
NormalComponents(x=Uy*Vz - Uz*Vy, y=-Ux*Vz + Uz*Vx, z=Ux*Vy - Uy*Vx)
>>> for label, tex in steps((0, 0, 0), (1, 0, 0), (0, 1, 0))[-4:-1]:
...     print(label, "|", tex)
|N| | |\mathbf{N}| = \sqrt{0^{2} + 0^{2} + 1^{2}} = 1
Area | \text{Area} = \frac{|\mathbf{N}|}{2} = \frac{1}{2}
Unit normal | \hat{\mathbf{n}} = \frac{\mathbf{N}}{|\mathbf{N}|} = \left(0, 0, 1\right)
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Literal, NamedTuple

from trinormal._optional import missing_extra

try:
    import sympy as sp
except ModuleNotFoundError as exc:
    raise missing_extra(exc, __name__) from exc

from trinormal.core import TriangleNormal, Winding, triangle_normal
from trinormal.steps import CROSS_TERMS, Working, working
from trinormal.tolerances import DEFAULT_TOL

__all__ = [
    "EDGE_SYMBOLS",
    "POINT_SYMBOLS",
    "Identity",
    "NormalComponents",
    "Solution",
    "Step",
    "cross",
    "edge_vectors",
    "guide_formulas",
    "identities",
    "normal_components",
    "solution",
    "steps",
    "steps_latex",
]

#: A vertex, as `trinormal.triangle_normal` reads it.
Vertex = Iterable[Any]
#: A degeneracy threshold, as `trinormal.triangle_normal` reads it.
Tolerance = float | int | Fraction | str

#: The guide's symbols for the vertices: (x1, y1, z1), (x2, y2, z2), (x3, y3, z3).
POINT_SYMBOLS: tuple[tuple[sp.Symbol, sp.Symbol, sp.Symbol], ...] = tuple(
    tuple(sp.symbols(f"x{i} y{i} z{i}", real=True)) for i in (1, 2, 3)
)
#: The guide's symbols for the edges: (Ux, Uy, Uz) and (Vx, Vy, Vz).
EDGE_SYMBOLS: tuple[tuple[sp.Symbol, sp.Symbol, sp.Symbol], ...] = (
    tuple(sp.symbols("Ux Uy Uz", real=True)),
    tuple(sp.symbols("Vx Vy Vz", real=True)),
)


class NormalComponents(NamedTuple):
    """The three components of N as sympy expressions."""

    x: sp.Expr
    y: sp.Expr
    z: sp.Expr


def _vec(symbols: Iterable[Any]) -> sp.Matrix:
    return sp.Matrix(list(symbols))


def cross(u: Iterable[Any], v: Iterable[Any]) -> sp.Matrix:
    """Return the cross product ``u × v`` of two 3-vectors, by `sympy.Matrix.cross`.

    Examples
    --------
    >>> cross((1, 0, 0), (0, 1, 0)).T
    Matrix([[0, 0, 1]])
    """
    return _vec(u).cross(_vec(v))


def _normal(a: Iterable[Any], b: Iterable[Any], c: Iterable[Any]) -> sp.Matrix:
    """N(A, B, C) = (B − A) × (C − A) for sympy vectors."""
    A, B, C = (_vec(p) for p in (a, b, c))
    return (B - A).cross(C - A)


def edge_vectors() -> tuple[sp.Matrix, sp.Matrix]:
    """U = B − A and V = C − A in the guide's point symbols (column matrices).

    Examples
    --------
    >>> u, v = edge_vectors()
    >>> u.T
    Matrix([[-x1 + x2, -y1 + y2, -z1 + z2]])
    """
    A, B, C = (_vec(p) for p in POINT_SYMBOLS)
    return B - A, C - A


def normal_components(
    in_terms_of: Literal["points", "edges"] = "points",
) -> NormalComponents:
    """Derive the components of N = (B − A) × (C − A) with sympy's cross product.

    Parameters
    ----------
    in_terms_of : {"points", "edges"}, default "points"
        ``"points"``: in x1, y1, …, z3 (A, B, C). ``"edges"``: in Ux, …, Vz,
        the edge vectors U = B − A and V = C − A.

    Returns
    -------
    NormalComponents
        ``(x, y, z)``, each a sympy expression.

    Examples
    --------
    >>> normal_components("edges").x
    Uy*Vz - Uz*Vy
    """
    if in_terms_of == "points":
        u, v = edge_vectors()
    elif in_terms_of == "edges":
        u, v = (_vec(e) for e in EDGE_SYMBOLS)
    else:
        raise ValueError(f"in_terms_of must be 'points' or 'edges', got {in_terms_of!r}")
    n = u.cross(v)
    return NormalComponents(n[0], n[1], n[2])


def guide_formulas() -> dict[str, tuple[sp.Expr, sp.Expr, sp.Expr]]:
    """Return the formulas as the guide writes them, to check the derivation against.

    These are the only formulas here that are written out by hand: they are the
    claim being checked, not the source of any result.

    Returns
    -------
    dict
        ``"U"`` and ``"V"`` (in the point symbols) and ``"N"`` (in the edge
        symbols), each a tuple of three sympy expressions.

    Examples
    --------
    >>> guide_formulas()["N"][2]
    Ux*Vy - Uy*Vx
    """
    names = {str(s): s for p in (*POINT_SYMBOLS, *EDGE_SYMBOLS) for s in p}

    def read(texts: Sequence[str]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        x, y, z = (sp.sympify(t, locals=names) for t in texts)
        return x, y, z

    return {
        "U": read(("x2 - x1", "y2 - y1", "z2 - z1")),
        "V": read(("x3 - x1", "y3 - y1", "z3 - z1")),
        "N": read(("Uy*Vz - Uz*Vy", "Uz*Vx - Ux*Vz", "Ux*Vy - Uy*Vx")),
    }


# --------------------------------------------------------------------------- identities


@dataclass(frozen=True)
class Identity:
    """One identity about the triangle normal, with its proof by simplification.

    Attributes
    ----------
    name : str
        A short key, such as ``"lagrange"``.
    statement : str
        The identity in words.
    latex : str
        The identity as LaTeX.
    difference : sympy.Matrix
        Left side minus right side, before simplification.
    proven : bool
        True when every entry of ``difference`` simplifies to zero.
    """

    name: str
    statement: str
    latex: str
    difference: sp.Matrix
    proven: bool

    def _repr_latex_(self) -> str:
        return f"${self.latex}$"


def simplifies_to_zero(expr: Any) -> bool:
    """Tell whether sympy simplifies ``expr`` (an expression or matrix) to exactly zero.

    Examples
    --------
    >>> x = sp.Symbol("x")
    >>> simplifies_to_zero((x + 1) ** 2 - x**2 - 2 * x - 1), simplifies_to_zero(x)
    (True, False)
    """
    entries = list(expr) if isinstance(expr, sp.MatrixBase) else [expr]
    return all(sp.simplify(sp.expand(e)) == 0 for e in entries)


def _identity(name: str, statement: str, latex: str, difference: Any) -> Identity:
    diff = difference if isinstance(difference, sp.MatrixBase) else sp.Matrix([difference])
    return Identity(name, statement, latex, diff, simplifies_to_zero(diff))


def _identities() -> tuple[Identity, ...]:
    """Build every identity and prove it by simplification, anew on each call."""
    A, B, C = (_vec(p) for p in POINT_SYMBOLS)
    U, V = (_vec(e) for e in EDGE_SYMBOLS)
    N = U.cross(V)
    NP = _normal(A, B, C)
    t = _vec(sp.symbols("tx ty tz", real=True))
    s = sp.Symbol("s", real=True)
    # Heron's formula, squared: 16·Area² = 2a²b² + 2b²c² + 2c²a² − a⁴ − b⁴ − c⁴
    a2, b2, c2 = ((B - C).dot(B - C), (C - A).dot(C - A), (A - B).dot(A - B))
    heron_area2 = (2 * a2 * b2 + 2 * b2 * c2 + 2 * c2 * a2 - a2**2 - b2**2 - c2**2) / 16
    return (
        _identity(
            "normal_perpendicular_to_U",
            "N is perpendicular to the first edge U.",
            r"\mathbf{N} \cdot \mathbf{U} = 0",
            N.dot(U),
        ),
        _identity(
            "normal_perpendicular_to_V",
            "N is perpendicular to the second edge V.",
            r"\mathbf{N} \cdot \mathbf{V} = 0",
            N.dot(V),
        ),
        _identity(
            "lagrange",
            "Lagrange's identity: |N|² = |U|²|V|² − (U · V)².",
            r"|\mathbf{N}|^2 = |\mathbf{U}|^2 |\mathbf{V}|^2 - (\mathbf{U} \cdot \mathbf{V})^2",
            N.dot(N) - U.dot(U) * V.dot(V) + U.dot(V) ** 2,
        ),
        _identity(
            "winding_flips_sign",
            "Swapping B and C (winding ACB) negates the normal.",
            r"\mathbf{N}(A, C, B) = -\mathbf{N}(A, B, C)",
            _normal(A, C, B) + NP,
        ),
        _identity(
            "translation_invariant",
            "Moving all three points by the same vector t leaves N unchanged.",
            r"\mathbf{N}(A + t, B + t, C + t) = \mathbf{N}(A, B, C)",
            _normal(A + t, B + t, C + t) - NP,
        ),
        _identity(
            "scaling_squared",
            "Scaling all three points by s multiplies N by s².",
            r"\mathbf{N}(sA, sB, sC) = s^2\, \mathbf{N}(A, B, C)",
            _normal(s * A, s * B, s * C) - s**2 * NP,
        ),
        _identity(
            "magnitude_twice_area",
            "|N| is twice the area: |N|²/4 equals Heron's formula for the squared area.",
            r"\frac{|\mathbf{N}|^2}{4} = s(s-a)(s-b)(s-c)"
            r" = \frac{2a^2b^2 + 2b^2c^2 + 2c^2a^2 - a^4 - b^4 - c^4}{16}"
            r" \;\Rightarrow\; |\mathbf{N}| = 2\,\text{Area}",
            NP.dot(NP) / 4 - heron_area2,
        ),
    )


def identities() -> dict[str, Identity]:
    r"""Prove the identities every triangle normal satisfies, each by sympy simplification.

    Each entry's ``difference`` (left side minus right side, in the guide's
    symbols) is simplified; ``proven`` is True only when it reduces to zero.
    Each call proves them anew (nothing is kept between calls), so a caller
    that needs them twice keeps the returned dict.

    Returns
    -------
    dict of str to Identity
        In order: ``normal_perpendicular_to_U``, ``normal_perpendicular_to_V``,
        ``lagrange``, ``winding_flips_sign``, ``translation_invariant``,
        ``scaling_squared`` and ``magnitude_twice_area``.

    Examples
    --------
    >>> ids = identities()
    >>> print(ids["lagrange"].latex)
    |\mathbf{N}|^2 = |\mathbf{U}|^2 |\mathbf{V}|^2 - (\mathbf{U} \cdot \mathbf{V})^2
    >>> all(i.proven for i in ids.values())
    True
    """
    return {i.name: i for i in _identities()}


# --------------------------------------------------------------------------- steps


class Step(NamedTuple):
    """One line of a worked solution: a short label and its LaTeX."""

    label: str
    latex: str


def _exact_vertex(p: Iterable[Fraction]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    return _three(_rational(f) for f in p)


def _tex(x: sp.Expr) -> str:
    return str(sp.latex(x))


def _factor(x: sp.Expr) -> str:
    """LaTeX of a number used as a factor or a term: negatives in parentheses."""
    t = _tex(x)
    return f"\\left({t}\\right)" if x < 0 else t


_HAT = r"\hat{\mathbf{n}}"


def _base(x: sp.Expr) -> str:
    """LaTeX of a number raised to a power: negatives and fractions in parentheses."""
    t = _tex(x)
    return f"\\left({t}\\right)" if (x < 0 or not x.is_integer) else t


def _tuple(xs: Iterable[sp.Expr]) -> str:
    return r"\left(" + ", ".join(_tex(x) for x in xs) + r"\right)"


@dataclass(frozen=True)
class Solution:
    """Exact values for one triangle, as sympy numbers.

    ``unit_normal`` and ``offset`` (the plane is ``n̂ · X = offset``) are
    ``None`` when the triangle is degenerate; ``reason`` then says why.
    """

    a: tuple[sp.Expr, sp.Expr, sp.Expr]
    b: tuple[sp.Expr, sp.Expr, sp.Expr]
    c: tuple[sp.Expr, sp.Expr, sp.Expr]
    winding: Winding
    u: tuple[sp.Expr, sp.Expr, sp.Expr]
    v: tuple[sp.Expr, sp.Expr, sp.Expr]
    normal: tuple[sp.Expr, sp.Expr, sp.Expr]
    magnitude: sp.Expr
    area: sp.Expr
    unit_normal: tuple[sp.Expr, sp.Expr, sp.Expr] | None
    offset: sp.Expr | None
    degenerate: bool
    reason: str


def _three(xs: Iterable[sp.Expr]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    x, y, z = xs
    return x, y, z


def solution(
    a: Vertex, b: Vertex, c: Vertex, winding: Winding | str = "ABC", tol: Tolerance = DEFAULT_TOL
) -> Solution:
    """Compute every value of the worked solution exactly, with sympy.

    The coordinates are read exactly by
    [`trinormal.triangle_normal`][trinormal.core.triangle_normal]
    (whose verdict on degeneracy is used), and N comes from substituting the
    edges into the formulas [`normal_components`][trinormal.symbolic.normal_components] derived.

    Examples
    --------
    >>> s = solution((1, 1, 1), (2, 1, 1), (1, 2, 2))
    >>> s.normal, s.magnitude, s.area, s.unit_normal
    ((0, -1, 1), sqrt(2), sqrt(2)/2, (0, -sqrt(2)/2, sqrt(2)/2))
    >>> solution(("0.1", 0, 0), (0, "1/3", 0), (0, 0, 0)).normal
    (0, 0, 1/30)
    """
    return _solve(triangle_normal(a, b, c, winding=winding, tol=tol))[0]


def _solve(r: TriangleNormal) -> tuple[Solution, Working]:
    """Compute `solution` for a result; return it with the engine's working behind it."""
    w = working(r)
    A, B, C = _exact_vertex(w.a), _exact_vertex(w.b), _exact_vertex(w.c)
    u, v = _exact_vertex(w.u), _exact_vertex(w.v)
    (ux, uy, uz), (vx, vy, vz) = EDGE_SYMBOLS
    values = {ux: u[0], uy: u[1], uz: u[2], vx: v[0], vy: v[1], vz: v[2]}
    n = _three(sp.Rational(f.subs(values)) for f in normal_components("edges"))
    dot = sum(n[i] * A[i] for i in range(3))
    unit = offset = None
    if r._integers.norm_squared.bit_length() <= _SYMPY_SQRT_BITS:
        mag = sp.sqrt(sum(x**2 for x in n))
        area = mag / 2
        if not r.degenerate:
            unit = _three(sp.radsimp(x / mag) for x in n)
            offset = sp.radsimp(dot / mag)
    else:
        # |N| = c·√m as the engine splits it, written directly, because sympy would
        # spend seconds proving a large radicand's factors prime
        m = w.radicand
        root = sp.Integer(1) if m == 1 else sp.Pow(sp.Integer(m), sp.S.Half, evaluate=False)
        # (no arithmetic on the root below: sympy would try to factor m again)
        mag = _times_root(_rational(w.root), root)
        area = _times_root(_rational(w.root / 2), root)
        if w.unit_normal is not None and w.offset is not None:
            unit = _three(_times_root(_rational(x), root) for x in w.unit_normal)
            offset = _times_root(_rational(w.offset), root)
    s = Solution(A, B, C, r.winding, u, v, n, mag, area, unit, offset, r.degenerate, r.reason)
    return s, w


#: Up to this size of |N|²·D⁴ (in bits, D the common denominator of the coordinates)
#: sympy takes the square root itself; beyond it the root is built from the split
#: into a square and the rest that `trinormal.steps` makes.
_SYMPY_SQRT_BITS = 600


def _rational(q: Fraction) -> sp.Rational:
    return sp.Rational(q.numerator, q.denominator)


def _times_root(q: sp.Rational, root: sp.Expr) -> sp.Expr:
    if root == 1 or q == 0:
        return q
    return sp.Mul(q, root, evaluate=False)


def steps(
    a: Vertex, b: Vertex, c: Vertex, winding: Winding | str = "ABC", tol: Tolerance = DEFAULT_TOL
) -> list[Step]:
    r"""Work the solution for three points step by step, in exact arithmetic.

    Coordinates are read exactly (``"0.1"`` is 1/10, ``"1/3"`` is one third; a
    float is its exact binary value), substituted into the formulas derived
    by [`normal_components`][trinormal.symbolic.normal_components], and kept exact: rationals stay
    fractions and square roots stay radicals where sympy keeps them (``√2/2``).

    Parameters
    ----------
    a, b, c : sequence of 3 real numbers or strings
        The vertices, as for [`trinormal.triangle_normal`][trinormal.core.triangle_normal].
    winding : {"ABC", "ACB"}, default "ABC"
        ``"ACB"`` takes U = C − A and V = B − A, flipping N.
    tol : real, default 1e-12
        Degeneracy threshold, as for [`trinormal.triangle_normal`][trinormal.core.triangle_normal].

    Returns
    -------
    list of Step
        ``(label, latex)`` pairs: the points, U, V, N's three components, N,
        |N|, the area, then the unit normal and the plane, or the degenerate
        verdict. The values behind them are [`solution`][trinormal.symbolic.solution]'s.

    Examples
    --------
    >>> s = steps((1, 1, 1), (2, 1, 1), (1, 2, 2))
    >>> print(s[-2].latex.split(" = ")[-1])
    \left(0, - \frac{\sqrt{2}}{2}, \frac{\sqrt{2}}{2}\right)
    >>> print(steps(("0", "0", "0"), ("0.1", "0", "0"), ("0", "1/3", "0"))[5].latex)
    N_z = U_x V_y - U_y V_x = \frac{1}{10} \cdot \frac{1}{3} - 0 \cdot 0 = \frac{1}{30}
    >>> steps((0, 0, 0), (1, 1, 1), (2, 2, 2))[-1].label
    'Degenerate'
    """
    s, w = _solve(triangle_normal(a, b, c, winding=winding, tol=tol))
    A, B, C, u, v, n = s.a, s.b, s.c, s.u, s.v, s.normal
    out = [Step("Points", rf"A = {_tuple(A)},\quad B = {_tuple(B)},\quad C = {_tuple(C)}")]
    for edge, vec in zip(w.edges, (u, v), strict=True):
        name, end = edge.name, edge.end
        E = C if end == "C" else B
        diffs = ", ".join(f"{_tex(E[i])} - {_factor(A[i])}" for i in range(3))
        latex = rf"\mathbf{{{name}}} = {end} - A = \left({diffs}\right) = {_tuple(vec)}"
        out.append(Step(f"{name} = {end} − A", latex))
    axes = "xyz"
    for k, (axis, i, j) in enumerate(CROSS_TERMS):
        term = (
            f"U_{axes[i]} V_{axes[j]} - U_{axes[j]} V_{axes[i]} = "
            f"{_factor(u[i])} \\cdot {_factor(v[j])} - {_factor(u[j])} \\cdot {_factor(v[i])}"
        )
        out.append(Step(f"N_{axis}", f"N_{axis} = {term} = {_tex(n[k])}"))
    out.append(Step("N", rf"\mathbf{{N}} = \mathbf{{U}} \times \mathbf{{V}} = {_tuple(n)}"))
    squares = " + ".join(f"{_base(x)}^{{2}}" for x in n)
    out.append(Step("|N|", rf"|\mathbf{{N}}| = \sqrt{{{squares}}} = {_tex(s.magnitude)}"))
    out.append(Step("Area", rf"\text{{Area}} = \frac{{|\mathbf{{N}}|}}{{2}} = {_tex(s.area)}"))
    if s.unit_normal is None or s.offset is None:
        out.append(Step("Degenerate", rf"\text{{No unit normal: {s.reason}}}"))
        return out
    unit = rf"{_HAT} = \frac{{\mathbf{{N}}}}{{|\mathbf{{N}}|}} = {_tuple(s.unit_normal)}"
    plane = rf"{_HAT} \cdot X = d,\quad d = {_HAT} \cdot A = {_tex(s.offset)}"
    return [*out, Step("Unit normal", unit), Step("Plane", plane)]


def steps_latex(solution: Iterable[Step]) -> str:
    r"""Join steps into one LaTeX ``aligned`` block, one step a line, for ``display(Math(...))``.

    Examples
    --------
    >>> print(steps_latex([Step("a", "x = 1"), Step("b", "y = 2")]))
    \begin{aligned}
    &x = 1 \\
    &y = 2
    \end{aligned}
    """
    lines = [f"&{s.latex}" for s in solution]
    return "\\begin{aligned}\n" + " \\\\\n".join(lines) + "\n\\end{aligned}"
