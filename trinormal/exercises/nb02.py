"""Exercises of notebook 02, the symbolic derivation."""

from __future__ import annotations

import math
from typing import Any

from trinormal.core import triangle_normal
from trinormal.exercises import AnswerError, Exercise, Verdict, point_text
from trinormal.exercises.reading import VectorGiven, read_expression

#: The edges of exercise 02-lagrange.
LAGRANGE_U, LAGRANGE_V = (1, 2, 2), (2, 0, 0)


def _dot(p: tuple[Any, ...], q: tuple[Any, ...]) -> Any:
    return sum(a * b for a, b in zip(p, q, strict=True))


def _lagrange(u: tuple[Any, ...], v: tuple[Any, ...]) -> Any:
    return triangle_normal((0, 0, 0), u, v).exact.magnitude_squared


def _scaling_power() -> int:
    """Measure k in N(sA, sB, sC) = s**k N(A, B, C) with s = 2 on a sample triangle."""
    a, b, c = (1, 2, 3), (4, 0, -1), (2, 5, 1)
    n1 = triangle_normal(a, b, c).exact.normal
    sa, sb, sc = (tuple(2 * x for x in p) for p in (a, b, c))
    n2 = triangle_normal(sa, sb, sc).exact.normal
    ratio = next(y / x for x, y in zip(n1, n2, strict=True) if x != 0)
    return int(ratio.numerator).bit_length() - 1


_NAMES = ("Ux", "Uy", "Uz", "Vx", "Vy", "Vz")
_WHAT = "an expression in Ux, Uy, Uz, Vx, Vy, Vz"


def _check_nz(answer: Any) -> Verdict:
    import sympy as sp

    from trinormal.symbolic import EDGE_SYMBOLS, normal_components

    symbols = {str(s): s for e in EDGE_SYMBOLS for s in e}
    # ux, U_x and u_x mean Ux too: match names without case or underscores
    loose = {name.lower(): symbols[name] for name in _NAMES}
    nz = normal_components("edges").z
    try:
        expr = read_expression(answer, symbols, what=_WHAT)
    except VectorGiven as whole:
        try:
            last, unknown = _rename(read_expression(whole.items[-1], symbols, what=_WHAT), loose)
            right = not unknown and sp.expand(last + nz) == 0
        except (AnswerError, VectorGiven):
            right = False
        if right:
            return Verdict(
                False, "Your last component is right: give it alone, not the whole vector."
            )
        return Verdict(
            False,
            "That is a whole vector: give only its z component, one expression.",
            slip="whole-vector",
        )
    except AnswerError as error:
        return Verdict(False, f"Your answer could not be read: {error}.", slip="unreadable")
    expr, unknown = _rename(expr, loose)
    for name in unknown:  # "UxVy": two names run together
        key = name.replace("_", "").lower()
        if len(key) == 4 and key[:2] in loose and key[2:] in loose:
            return Verdict(
                False,
                f"{name} reads as one name: write a product with * or a space, "
                f"as in {loose[key[:2]]}*{loose[key[2:]]}.",
            )
    if unknown:
        return Verdict(
            False,
            f"Your answer uses {', '.join(unknown)}: write it with Ux, Uy, Uz, Vx, Vy, Vz only.",
        )
    if sp.expand(expr + nz) == 0:  # (V × U)_z = −(U × V)_z
        return Verdict(True)
    if sp.expand(expr - nz) == 0:
        return Verdict(
            False,
            "That is N_z of U × V, the order A → B → C. V × U has its factors swapped: "
            "what does that do to the sign?",
            slip="reversed-order",
        )
    used = {str(s) for s in expr.free_symbols}
    if used & {"Uz", "Vz"}:
        return Verdict(
            False,
            "A z component does not involve Uz or Vz: only the x and y components of U and V.",
        )
    return Verdict(
        False,
        "Use the x and y components of U and V: the z component is (one product) − (another).",
    )


def _rename(expr: Any, loose: dict[str, Any]) -> tuple[Any, list[str]]:
    """Map ux, U_x, u_x to Ux (and so on); return the expression and the unknown names."""
    unknown = []
    for sym in expr.free_symbols:
        key = str(sym).replace("_", "").lower()
        if key in loose:
            expr = expr.subs(sym, loose[key])
        else:
            unknown.append(str(sym))
    return expr, sorted(unknown)


def lagrange_exercise(u: tuple[Any, ...], v: tuple[Any, ...]) -> Exercise:
    """Build 02-lagrange on the edges ``u`` and ``v`` (a student's own, or the notebook's)."""
    return Exercise(
        "02-lagrange",
        f"U = {point_text(u)} and V = {point_text(v)}. Use Lagrange's identity to find |N|² "
        "exactly.",
        expected=lambda: _lagrange(u, v),
        hint="|N|² = |U|²|V|² − (U · V)²: compute the three dot products first.",
        mistakes=(
            (
                lambda: _dot(u, u) * _dot(v, v),
                "That is |U|²|V|²: now subtract (U · V)².",
                "no-subtraction",
            ),
            (
                lambda: _dot(u, u) * _dot(v, v) - _dot(u, v),
                "You subtracted U · V: subtract its square, (U · V)².",
                "unsquared-dot",
            ),
            (
                lambda: _dot(u, u) * _dot(v, v) + _dot(u, v) ** 2,
                "(U · V)² is subtracted, not added.",
                "added-dot-squared",
            ),
            (
                lambda: math.sqrt(_lagrange(u, v)),
                "That is |N|: the question asks for |N|².",
                "magnitude-for-squared",
            ),
        ),
    )


EXERCISES = (
    Exercise(
        "02-nz-reversed",
        "Write the z component of V × U (the normal for the order A → C → B) in terms of the "
        "edge components Ux, Uy, Uz, Vx, Vy, Vz (a sympy expression or a string such as "
        "'Uy*Vz - ...').",
        checker=_check_nz,
        example="Uy*Vx - Ux*Vy",  # the z component of V × U: the notebook never prints it
    ),
    Exercise(
        "02-scaling-power",
        "Scaling all three points by s multiplies N by s**k. What is k?",
        expected=_scaling_power,
        hint="Each edge is scaled by s, and N multiplies two edges.",
        mistakes=(
            (1, "Each edge grows by s, but N is a product of two edges.", "linear-scaling"),
            (
                3,
                "Three factors of s would scale a volume; N is a product of two edges.",
                "cubic-scaling",
            ),
        ),
    ),
    lagrange_exercise(LAGRANGE_U, LAGRANGE_V),
)
