"""Reading one number: exact values as a ``Fraction``, floats as the float given."""

from __future__ import annotations

import math
import re
from fractions import Fraction
from typing import Any

from trinormal.exercises.reading.errors import TOO_DEEP, AnswerError, describe, guarded
from trinormal.exercises.reading.text import plain_text, sympify_text
from trinormal.validation import check_coordinate

__all__ = [
    "DEGREE_SIGNS",
    "Number",
    "decimal_point",
    "is_exact",
    "looks_like_number",
    "module_of",
    "read_number",
]

#: A number read from an answer: a ``Fraction`` when exact, a ``float`` otherwise.
Number = Fraction | float

#: What may end a text answer in degrees (``"19.5°"``), where the exercise asks for degrees.
DEGREE_SIGNS = ("°", "º", "˚", "degrees", "degree", "deg")


def is_exact(x: Number) -> bool:
    """Return True for a value read exactly (a ``Fraction``), False for a float."""
    return isinstance(x, Fraction)


def read_number(x: Any, *, degrees: bool = False) -> Number:
    """Read one number of an answer: a ``Fraction`` when exact, a ``float`` otherwise.

    Parameters
    ----------
    x : object
        Any object; see the rules of ``trinormal.exercises.reading`` for what
        reads as a number.
    degrees : bool, default False
        Accept a trailing degree sign in text (``"19.5°"``): the exercise
        asks for an angle in degrees.

    Returns
    -------
    Fraction or float
        A ``Fraction`` for an exact value, the float itself for a float, and
        the nearest float for an irrational value.

    Raises
    ------
    AnswerError
        With a message saying what was expected, for anything that is not
        one real number.

    Examples
    --------
    >>> read_number("5/7"), read_number(-2.5), read_number(Fraction(3, 8))
    (Fraction(5, 7), -2.5, Fraction(3, 8))
    >>> round(read_number("sqrt(2)/4"), 6), round(read_number("√2/4"), 6)
    (0.353553, 0.353553)
    >>> read_number("12.5°", degrees=True)
    Fraction(25, 2)
    """
    return guarded(lambda: _number(x, degrees, 0), x, "a number")


def module_of(x: Any) -> str:
    """Return the module that ``x``'s type comes from (``"numpy"``, ``"sympy.core..."``)."""
    return getattr(type(x), "__module__", "") or ""


def looks_like_number(x: Any) -> bool:
    """Tell whether ``x`` is a ``Decimal`` or any other ``numbers.Number``."""
    from decimal import Decimal
    from numbers import Number as AnyNumber

    return isinstance(x, Decimal | AnyNumber)


def _number(x: Any, degrees: bool, depth: int) -> Number:
    if depth > 8:
        raise AnswerError(TOO_DEEP)
    if x is None:
        raise AnswerError(
            "None is not a number (did a function print its result instead of returning it?)"
        )
    if x is Ellipsis:
        raise AnswerError("... is not a number: replace it with your answer")
    t = type(x)
    if t.__name__ in ("bool", "bool_", "BooleanTrue", "BooleanFalse"):
        raise AnswerError(f"{x} is a truth value, not a number")
    if t is float:
        return _finite_float(x)
    if t is int or t is Fraction:
        return _exact(x)
    if isinstance(x, str):
        return _text_number(x, degrees)
    if isinstance(x, bytes | bytearray | memoryview):
        raise AnswerError("bytes are not a number: write the number itself, or text such as '1/3'")
    if isinstance(x, complex):
        if x.imag != 0:
            raise AnswerError(f"{describe(x)} is complex; the answer is a real number")
        return _finite_float(x.real)
    if isinstance(x, dict):
        raise AnswerError("a dict is not a number")
    if isinstance(x, set | frozenset):
        raise AnswerError("a set is not a number")
    module = module_of(x)
    if module.startswith("numpy"):
        return _numpy_number(x, degrees, depth)
    if module.startswith("sympy"):
        return _sympy_number(x, degrees, depth)
    if isinstance(x, list | tuple | range):
        if len(x) == 1:
            return _number(x[0], degrees, depth + 1)
        raise AnswerError(f"expected one number, got {len(x)} values")
    try:  # Decimal, numbers.Rational, and anything else check_coordinate reads
        n, d = check_coordinate(x, "your answer")
        return Fraction(n, d)
    except ValueError as exc:  # a number, but NaN, infinite or beyond the limits
        raise AnswerError(str(exc)) from None
    except TypeError:  # not a type check_coordinate knows: try float() below
        pass
    if hasattr(x, "__float__"):
        value = float(x)  # errors here are reported by read_number
        return _finite_float(value)
    raise AnswerError(f"{describe(x)} is not a number")


def _finite_float(f: float) -> float:
    if math.isnan(f):
        raise AnswerError("NaN (not a number) is not an answer")
    if math.isinf(f):
        raise AnswerError("an infinity is not an answer: the answer is a finite number")
    return float(f)


def _exact(x: Any) -> Fraction:
    try:
        n, d = check_coordinate(x, "your answer")
    except (TypeError, ValueError) as exc:
        raise AnswerError(str(exc)) from None
    return Fraction(n, d)


def _numpy_number(x: Any, degrees: bool, depth: int) -> Number:
    import numpy as np

    if isinstance(x, np.ndarray):
        x = np.asarray(x)  # a numpy.matrix too
        if x.size == 1:
            return _number(
                x.reshape(()).item() if x.dtype != object else x.flat[0], degrees, depth + 1
            )
        if x.size == 0:
            raise AnswerError("an empty array is not a number")
        raise AnswerError(f"expected one number, got an array of shape {x.shape}")
    if isinstance(x, np.integer):
        return _exact(int(x))
    if isinstance(x, np.floating):
        if not np.isfinite(x):
            return _finite_float(float(x))
        if x.dtype.itemsize > 8:  # longdouble: keep every bit
            return Fraction(*x.as_integer_ratio())
        return float(x)
    if isinstance(x, np.complexfloating):
        if x.imag != 0:
            raise AnswerError(f"{describe(x)} is complex; the answer is a real number")
        return _numpy_number(x.real, degrees, depth + 1)
    if hasattr(x, "item"):  # other numpy scalars (datetime, str_, void): read what they hold
        value = x.item()
        if type(value) is not type(x):
            return _number(value, degrees, depth + 1)
    raise AnswerError(f"{describe(x)} is not a number")


def _sympy_number(x: Any, degrees: bool, depth: int) -> Number:
    import sympy as sp

    if isinstance(x, sp.NDimArray):
        items = list(leaves(x.tolist()))
        if len(items) == 1:
            return _number(items[0], degrees, depth + 1)
        raise AnswerError(f"expected one number, got an array of shape {tuple(x.shape)}")
    if getattr(x, "is_Matrix", False):
        if x.shape[0] * x.shape[1] == 1:
            return _number(x[0], degrees, depth + 1)
        raise AnswerError(f"expected one number, got a {x.shape[0]} × {x.shape[1]} matrix")
    if getattr(x, "is_Boolean", False) and not getattr(x, "is_number", False):
        raise AnswerError(f"{x} is a truth value, not a number")
    if getattr(x, "is_Rational", False):
        return _exact(x)
    if getattr(x, "is_Float", False):
        return _finite_float(float(x)) if x.is_finite else _finite_float(float("nan"))
    _refuse_symbols(x, x, "still has")
    return _sympy_value(x)


def leaves(items: Any) -> Any:
    """Yield the leaves of nested lists (a sympy Array's ``tolist()``)."""
    if isinstance(items, list):
        for item in items:
            yield from leaves(item)
    else:
        yield items


def _refuse_symbols(value: Any, given: Any, has: str) -> None:
    """Raise unless the sympy object ``value`` is a number; name the symbols left in it.

    The message shows ``given`` (what the student typed), then ``has``: "x has a in it".
    """
    if not getattr(value, "is_number", False):
        free = sorted(str(s) for s in getattr(value, "free_symbols", ()))
        if free:
            raise AnswerError(f"{describe(given)} {has} {', '.join(free)} in it: give a number")
        raise AnswerError(f"{describe(given)} is not a number")


def _sympy_value(x: Any) -> Number:
    """Read a number sympy holds exactly: rational → Fraction, irrational → nearest float."""
    import sympy as sp

    if x.is_Rational:
        return _exact(x)
    if x.is_finite is False or x.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise AnswerError(f"{describe(x)} is not a finite number")
    if x.is_real is False:
        raise AnswerError(f"{describe(x)} is not a real number")
    value = sp.N(x, 30)
    re_part, im_part = value.as_real_imag()
    if im_part != 0 and abs(im_part) > 1e-25 * max(1, abs(re_part)):
        raise AnswerError(f"{describe(x)} is not a real number")
    if not re_part.is_Number or not re_part.is_finite:
        raise AnswerError(f"{describe(x)} is not a finite number")
    if x.is_rational and x.is_algebraic:  # sympy proved it rational: read it exactly
        q = sp.nsimplify(x)
        if q.is_Rational:
            return _exact(q)
    return _finite_float(float(re_part))


#: One number written with a decimal comma: ``0,5``, ``−12,75``.
DECIMAL_COMMA = re.compile(r"[+\-−]?\d+,\d+")
#: ... unless it reads as well with a thousands separator: ``1,500``, ``-12,750``.
THOUSANDS = re.compile(r"[+\-−]?[1-9]\d{0,2},\d{3}")


def decimal_point(text: str) -> str:
    """Write one number typed with a decimal comma (``"0,5"``) with a point; other text as is.

    A comma is a decimal comma only in text that is one number with one comma
    and digits on both sides. ``"1,500"`` (one to three digits, not starting
    with 0, then three) could be 1.5 or 1500: it is refused, with a message.

    Examples
    --------
    >>> decimal_point("0,5"), decimal_point("−12,75"), decimal_point("1, 2")
    ('0.5', '−12.75', '1, 2')
    >>> decimal_point("1,500")
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: '1,500' could be a decimal comma or a thousands separator: write it with a point (1.5) or without the comma (1500)
    """  # noqa: E501
    s = text.strip()
    if not DECIMAL_COMMA.fullmatch(s):
        return text
    if THOUSANDS.fullmatch(s):
        whole, _, part = s.partition(",")
        raise AnswerError(
            f"{describe(s)} could be a decimal comma or a thousands separator: write it with a "
            f"point ({whole}.{part.rstrip('0') or '0'}) or without the comma ({whole}{part})"
        )
    return s.replace(",", ".")


def _text_number(text: str, degrees: bool) -> Number:
    s = text.strip()
    for sign in DEGREE_SIGNS:
        head = s[: len(s) - len(sign)].rstrip()
        if s.lower().endswith(sign) and (len(sign) == 1 or not head[-1:].isalpha()):
            if not degrees:
                raise AnswerError(
                    f"{describe(text)} is marked as degrees, but this answer is not an angle"
                )
            s = head
            break
    s = decimal_point(plain_text(s).strip())
    if not s:
        raise AnswerError("empty text is not a number")
    try:  # decimals and fractions, exactly, with the package's own reader and limits
        return _exact(s)
    except AnswerError as exc:
        plain_error = str(exc)
    if "too large" in plain_error or "NaN" in plain_error or "infinit" in plain_error:
        raise AnswerError(plain_error)
    value = sympify_text(s, {}, what="a number")
    if getattr(value, "is_Symbol", False):
        raise AnswerError(f"{describe(text)} is not a number")
    _refuse_symbols(value, text, "has")
    return _sympy_value(value)
