"""Typed math read safely with sympy: ``√3/2``, ``2√2``, ``x²``, nothing that runs code."""

from __future__ import annotations

import re
from typing import Any

from trinormal.exercises.reading.errors import AnswerError, describe

__all__ = [
    "ALLOWED_FUNCTIONS",
    "MAX_EXPRESSION_LENGTH",
    "MAX_POWER",
    "closing",
    "plain_text",
    "split_top",
    "sympify_text",
]

#: Longest text read with sympy (an answer is a short expression).
MAX_EXPRESSION_LENGTH = 300
#: Largest exponent or factorial argument allowed in a sympy expression typed as text.
MAX_POWER = 1000
#: Functions a number typed as text may use.
ALLOWED_FUNCTIONS = frozenset(
    {"sqrt", "cbrt", "root", "log", "ln", "exp", "sin", "cos", "tan", "asin", "acos", "atan",
     "atan2", "Abs", "abs", "deg", "rad", "Max", "Min", "Pow", "Rational", "Integer", "Float",
     "Mul", "Add"}
)  # fmt: skip

_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_POWER = re.compile("([⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)")


#: ``<=``, ``>=``, ``!=`` or ``==``: a comparison, not a value given a name.
_COMPARISON = re.compile(r"[<>!=]=")


def plain_text(text: str) -> str:
    """Turn typed math into plain text: ``x²`` → ``x**2``, full-width digits → ASCII (NFKC).

    A value given a name (``"area = √3/2"``, ``"N = (1, 1, 1)"``) is the value after
    the last ``=``.

    Examples
    --------
    >>> plain_text("A = |N|/2 = √3/2"), plain_text("10⁻³")
    (' √3/2', '10**-3')
    """
    import unicodedata

    if "=" in text and not _COMPARISON.search(text):
        text = text.rsplit("=", 1)[1]
    text = _POWER.sub(lambda m: "**" + m[1].translate(_SUPERSCRIPTS), text)
    return unicodedata.normalize("NFKC", text).replace("\u2044", "/")


_SQRT = re.compile(r"√\s*(\d+(?:\.\d+)?|\(|[A-Za-z])")
#: A number (not the digits ending a name such as log10) before a function or a bracket.
_DIGIT_CALL = re.compile(r"(?<![A-Za-z_\d.])(\d+(?:\.\d+)?)\s*(sqrt|pi|log|ln|exp|\()")
#: Text that could run code, or that sympy would read as logic, a comparison or an empty tuple.
_UNSAFE = re.compile(
    r"__|\.\s*[A-Za-z_]|[;:`\[\]{}@$!?'\"\\|&~<>=]|\(\s*\)"
    r"|(?<![A-Za-z_])(?:lambda|True|False|None|not|and|or|is|in|if|else|for)(?![A-Za-z_\d])"
)
#: ``math.sqrt``, ``np.log10``, ``sympy.pi``: the module's name is dropped, the function kept.
_MODULE_PREFIX = re.compile(r"\b(?:math|numpy|np|sympy|sp)\s*\.\s*(?=[A-Za-z])")
#: ``|...|`` with no bar inside: the innermost absolute value or length.
_BARS = re.compile(r"\|([^|]*)\|")


def _bars(code: str) -> str:
    """Write ``|x|`` as ``Abs(x)`` and ``|(a, b, c)|``, a vector's length, as a square root."""
    for _ in range(code.count("|") // 2):
        match = _BARS.search(code)
        if match is None:
            break
        inner = match[1].strip()
        parts = split_top(inner[1:-1], ",") if inner[:1] in "([" and inner[-1:] in ")]" else []
        if len(parts) > 1:
            body = "+".join(f"({part})**2" for part in parts)
            code = code[: match.start()] + f"sqrt({body})" + code[match.end() :]
        else:
            code = code[: match.start()] + f"Abs({inner})" + code[match.end() :]
    return code


def closing(s: str, start: int) -> int:
    """Return the index of the bracket closing the one at ``start`` (-1 if it is not closed).

    Examples
    --------
    >>> closing("(1)/(2)", 0), closing("((1, 2))", 0), closing("(1", 0)
    (2, 7, -1)
    """
    depth = 0
    for i in range(start, len(s)):
        depth += s[i] in "([{⟨"
        depth -= s[i] in ")]}⟩"
        if depth == 0:
            return i
    return -1


def split_top(text: str, separators: str) -> list[str]:
    """Split ``text`` at the ``separators`` outside brackets, stripping each part.

    Examples
    --------
    >>> split_top("atan2(1, 2), 0, [1, 2]", ",")
    ['atan2(1, 2)', '0', '[1, 2]']
    """
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch in "([{⟨":
            depth += 1
        elif ch in ")]}⟩":
            depth -= 1
        elif depth == 0 and ch in separators:
            parts.append(text[start:i].strip())
            start = i + 1
    parts.append(text[start:].strip())
    return parts


_NAME_END = re.compile(r"[A-Za-z_][A-Za-z_0-9]*\s*$")


def _tuple_inside(code: str) -> bool:
    """Tell whether a bracket that is not a function's argument list holds a comma: a vector."""
    for match in re.finditer(r"[(\[]", code):
        if _NAME_END.search(code[: match.start()]):  # sqrt(…), log(2, 10), atan2(1, 2)
            continue
        depth = 0
        for ch in code[match.start() :]:
            depth += ch in "(["
            depth -= ch in ")]"
            if depth == 0:
                break
            if depth == 1 and ch == ",":
                return True
    return False


def sympify_text(text: str, names: dict[str, Any], *, what: str) -> Any:
    """Read a short expression typed as text with sympy, safely.

    The notebooks' way of printing math is understood: ``√3`` and ``√(2)`` are
    square roots, ``·`` and ``×`` products, ``−`` a minus, ``^`` a power, and a
    number followed by a name or a bracket multiplies (``2√2``, ``2 pi``). The
    prompts' formulas may be typed with their numbers: ``|−6|`` is an absolute
    value, ``|(1, 2, 2)|`` a vector's length, ``log10(2)`` a logarithm in base
    10, ``max(0, 0.8)`` the larger value, ``degrees(x)`` radians in degrees,
    and ``math.``, ``np.`` or ``sympy.`` before a function are dropped. Text
    that could run code (attribute access, dunder names), very long text,
    huge powers or factorials, and a vector inside a calculation are refused.

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

    Examples
    --------
    >>> sympify_text("|(1, 2, 2)|² − |−2|", {}, what="a number")
    7
    >>> sympify_text("53·np.log10(2)", {}, what="a number")
    53*log(2)/log(10)
    """
    if len(text) > MAX_EXPRESSION_LENGTH:
        raise AnswerError(f"this text is too long to be {what}")
    code = plain_text(text)
    code = _SQRT.sub(lambda m: "sqrt(" if m[1] == "(" else f"sqrt({m[1]})", code)
    code = code.replace("·", "*").replace("×", "*").replace("−", "-").replace("–", "-")
    code = code.replace("π", "pi")
    code = _MODULE_PREFIX.sub("", code)
    code = _bars(code)
    code = _DIGIT_CALL.sub(r"\1*\2", code)
    if _UNSAFE.search(code):
        raise AnswerError(f"{describe(text)} could not be read as {what}")
    stripped = code.strip()
    whole_tuple = stripped[:1] == "(" and closing(stripped, 0) == len(stripped) - 1
    if _tuple_inside(code) and not whole_tuple:
        raise AnswerError(f"{describe(text)} mixes a vector into a calculation: give {what}")
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
    local = {
        "ln": sp.log,
        "abs": sp.Abs,
        "log10": lambda x: sp.log(x, 10),
        "max": sp.Max,
        "min": sp.Min,
        "degrees": sp.deg,
        "radians": sp.rad,
        **names,
    }
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
