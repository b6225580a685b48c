"""Typed math read safely with sympy: ``√3/2``, ``2√2``, ``x²``, nothing that runs code."""

from __future__ import annotations

import re
from typing import Any

from trinormal.exercises.reading.errors import AnswerError, describe

__all__ = ["ALLOWED_FUNCTIONS", "MAX_EXPRESSION_LENGTH", "MAX_POWER", "plain_text", "sympify_text"]

#: Longest text read with sympy (an answer is a short expression).
MAX_EXPRESSION_LENGTH = 300
#: Largest exponent or factorial argument allowed in a sympy expression typed as text.
MAX_POWER = 1000
#: Functions a number typed as text may use.
ALLOWED_FUNCTIONS = frozenset(
    {"sqrt", "cbrt", "root", "log", "ln", "exp", "sin", "cos", "tan", "asin", "acos", "atan",
     "atan2", "Abs", "abs", "deg", "rad", "Pow", "Rational", "Integer", "Float", "Mul", "Add"}
)  # fmt: skip

_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_POWER = re.compile("([⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)")


def plain_text(text: str) -> str:
    """Turn typed math into plain text: ``x²`` → ``x**2``, full-width digits → ASCII (NFKC)."""
    import unicodedata

    text = _POWER.sub(lambda m: "**" + m[1].translate(_SUPERSCRIPTS), text)
    return unicodedata.normalize("NFKC", text).replace("\u2044", "/")


_SQRT = re.compile(r"√\s*(\d+(?:\.\d+)?|\(|[A-Za-z])")
_DIGIT_CALL = re.compile(r"(\d)\s*(sqrt|pi|log|ln|exp|\()")
_UNSAFE = re.compile(r"__|\.\s*[A-Za-z_]|lambda|[;:`\[\]{}@$!?'\"\\]")


def sympify_text(text: str, names: dict[str, Any], *, what: str) -> Any:
    """Read a short expression typed as text with sympy, safely.

    The notebooks' way of printing math is understood: ``√3`` and ``√(2)`` are
    square roots, ``·`` and ``×`` products, ``−`` a minus, ``^`` a power, and a
    number followed by a name or a bracket multiplies (``2√2``, ``2 pi``).
    Text that could run code (attribute access, dunder names), very long text
    and huge powers or factorials are refused.

    Parameters
    ----------
    text : str
        The expression.
    names : dict
        Names the expression may use (symbols), besides sympy's functions.
    what : str
        What the text should be, for the error message ("a number").

    Raises
    ------
    AnswerError
        When the text cannot be read.
    """
    if len(text) > MAX_EXPRESSION_LENGTH:
        raise AnswerError(f"this text is too long to be {what}")
    code = _SQRT.sub(lambda m: "sqrt(" if m[1] == "(" else f"sqrt({m[1]})", text)
    code = code.replace("·", "*").replace("×", "*").replace("−", "-").replace("–", "-")
    code = code.replace("π", "pi")
    code = _DIGIT_CALL.sub(r"\1*\2", code)
    if _UNSAFE.search(code):
        raise AnswerError(f"{describe(text)} could not be read as {what}")
    try:
        import sympy as sp
        from sympy.parsing.sympy_parser import (
            convert_xor,
            implicit_multiplication,
            parse_expr,
            standard_transformations,
        )
    except ImportError:  # pragma: no cover - sympy is a dependency of the exercises
        raise AnswerError(f"{describe(text)} could not be read as {what}") from None
    transformations = (*standard_transformations, implicit_multiplication, convert_xor)
    local = {"ln": sp.log, "abs": sp.Abs, **names}
    try:
        tree = parse_expr(code, local_dict=dict(local), transformations=transformations,
                          evaluate=False)  # fmt: skip
        _refuse_huge(tree)
        value = parse_expr(code, local_dict=dict(local), transformations=transformations)
        return sp.sympify(value)
    except AnswerError:
        raise
    except Exception:  # any parse failure (SyntaxError, TokenError, SympifyError, ...)
        raise AnswerError(f"{describe(text)} could not be read as {what}") from None


def _refuse_huge(tree: Any) -> None:
    """Refuse powers and factorials that would take long to evaluate (``9**9**9``)."""
    import sympy as sp

    for node in sp.postorder_traversal(tree):  # inner powers first: 9**9 before 9**9**9
        if isinstance(node, sp.Pow):
            exponent = node.exp
            if exponent.is_number:
                size = sp.N(exponent, 15)
                if not size.is_Number or abs(size) > MAX_POWER:
                    raise AnswerError("this expression has a power too large to evaluate")
        elif isinstance(node, sp.Function) or getattr(node, "is_Function", False):
            name = getattr(node.func, "__name__", "")
            if name not in ALLOWED_FUNCTIONS and not getattr(node, "is_Symbol", False):
                raise AnswerError(f"this expression uses {name}, which no answer here needs")
