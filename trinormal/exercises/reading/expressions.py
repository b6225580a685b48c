"""Reading one symbolic expression (such as ``Uy·Vz − Uz·Vy``) for the derivation exercises."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from trinormal.exercises.reading.errors import AnswerError, describe
from trinormal.exercises.reading.text import sympify_text

__all__ = ["VectorGiven", "read_expression"]


class VectorGiven(AnswerError):
    """A whole vector (three items) given where one expression is asked for."""

    def __init__(self, items: Any) -> None:
        super().__init__("that is a whole vector, not one expression")
        self.items = items


def read_expression(answer: Any, symbols: dict[str, Any], *, what: str) -> Any:
    """Read one sympy expression: text, a sympy expression, or either in a box of one.

    Parameters
    ----------
    answer : object
        Text (read by `sympify_text`), a sympy expression, a number, or a
        one-element tuple, list or matrix holding one of them.
    symbols : dict
        The names the expression may use.
    what : str
        What the answer should be, for messages.

    Raises
    ------
    VectorGiven
        For three items (a whole vector); its ``items`` holds them.
    AnswerError
        For anything else that is not one expression.

    Examples
    --------
    >>> import sympy as sp
    >>> a, b = sp.symbols("a b")
    >>> read_expression(("a·b − 1",), {"a": a, "b": b}, what="an expression in a, b")
    a*b - 1
    """
    try:
        return _expression(answer, symbols, what, 0)
    except AnswerError:
        raise
    except Exception:  # an object that misbehaves when asked what it is
        raise AnswerError(f"{describe(answer)} is not {what}") from None


def _expression(answer: Any, symbols: dict[str, Any], what: str, depth: int) -> Any:
    import sympy as sp

    if isinstance(answer, str):
        value = sympify_text(answer, symbols, what=what)
        if isinstance(value, sp.Tuple):  # "(a, b, c)" typed: a vector, or a list of values
            if len(value) == 3:
                raise VectorGiven(list(value))
            raise AnswerError(f"{describe(answer)} is {len(value)} values, not {what}")
        if not isinstance(value, sp.Expr):  # True, x > 1, a set: not an expression
            raise AnswerError(f"{describe(answer)} is not {what}")
        return value
    if isinstance(answer, sp.Basic) and not getattr(answer, "is_Matrix", False):
        if isinstance(answer, sp.Expr):
            return answer
        raise AnswerError(f"{describe(answer)} is not {what}")
    size = _box_size(answer)
    if size == 1 and depth < 4:  # ("Uy*Vx - Ux*Vy",), [expr], a 1 × 1 matrix: what is inside
        inner = answer[0, 0] if getattr(answer, "is_Matrix", False) else answer[0]
        return _expression(inner, symbols, what, depth + 1)
    if size == 3:
        raise VectorGiven(list(answer))
    if answer is None or isinstance(answer, bool):
        raise AnswerError(f"{describe(answer)} is not {what}")
    if isinstance(answer, int | Fraction):
        return sp.Rational(answer)
    if isinstance(answer, float) and math.isfinite(answer):
        return sp.Float(answer)
    raise AnswerError(f"{describe(answer)} is not {what}: give text or a sympy expression")


def _box_size(answer: Any) -> int:
    if getattr(answer, "is_Matrix", False):
        rows, cols = answer.shape
        return int(rows * cols) if 1 in (rows, cols) else -1
    if isinstance(answer, tuple | list):
        return len(answer)
    return -1
