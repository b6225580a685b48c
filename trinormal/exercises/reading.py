"""Reading answers: any object a student may hand to ``check``, read into exact values.

One reader serves every exercise, so an answer is read the same way wherever it
is typed. The rules:

* **Numbers.** ``int``, ``Fraction``, ``Decimal``, numpy integers, sympy
  rationals and decimal or fraction text (``"0.25"``, ``"1/3"``, ``"−6"`` with
  the Unicode minus) are *exact*: they are read as a ``Fraction``. ``float``,
  numpy floats and sympy ``Float`` are *floats*: read as a Python ``float``
  (exactly the binary value given). An irrational value (``sympy.sqrt(3) / 2``,
  ``"sqrt(3)/2"``, ``"√3/2"``, ``"2√2"``, ``"53*log(2)/log(10)"``) is read as
  the float nearest to it. The limits of the package's own reader
  ([`trinormal.validation.check_coordinate`][trinormal.validation.check_coordinate])
  apply: at most 400 digits.
* **One value in a box** counts as that value: a 0-d numpy array (what
  ``np.dot`` or ``np.cross`` of 2-D vectors return), an array, list or tuple
  of one element, a 1 × 1 sympy matrix.
* **Vectors**: tuples, lists, generators, numpy arrays of shape ``(3,)``,
  ``(3, 1)`` or ``(1, 3)``, row or column sympy matrices, and text as printed
  (``"(0, 0, 1)"``, ``"[1/√5, 2/√5, 0]"``).
* **Points**: a sequence of points, an ``(n, 3)`` array or matrix, a dict
  ``{"A": ..., "B": ..., "C": ...}``, or text such as ``"(0,0,1), (1,0,1), (0,1,1)"``.
* **Angles in degrees** may carry the degree sign (``"19.5°"``) where the
  exercise asks for degrees, and only there.

Everything else raises `AnswerError` with a message that says what was
expected; no other exception leaves this module.

Examples
--------
>>> read_number("−7/4"), read_number(2.5), read_number("√2") ** 2 > 1.99
(Fraction(-7, 4), 2.5, True)
>>> read_vector("(1/4, 0, −2)")
[Fraction(1, 4), Fraction(0, 1), Fraction(-2, 1)]
>>> read_number(None)
Traceback (most recent call last):
...
trinormal.exercises.reading.AnswerError: None is not a number (did a function print its result instead of returning it?)
"""  # noqa: E501

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Iterable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from trinormal.validation import check_coordinate

__all__ = [
    "FACES",
    "POINTS",
    "AnswerError",
    "Items",
    "Number",
    "VectorGiven",
    "describe",
    "is_exact",
    "read_bool",
    "read_expression",
    "read_number",
    "read_points",
    "read_vector",
    "read_word",
]

#: A number read from an answer: a ``Fraction`` when exact, a ``float`` otherwise.
Number = Fraction | float

#: Longest text read with sympy (an answer is a short expression).
MAX_EXPRESSION_LENGTH = 300
#: Largest exponent or factorial argument allowed in a sympy expression typed as text.
MAX_POWER = 1000
#: Functions a number typed as text may use.
ALLOWED_FUNCTIONS = frozenset(
    {"sqrt", "cbrt", "root", "log", "ln", "exp", "sin", "cos", "tan", "asin", "acos", "atan",
     "atan2", "Abs", "abs", "deg", "rad", "Pow", "Rational", "Integer", "Float", "Mul", "Add"}
)  # fmt: skip

AXIS_NAMES = ("x", "y", "z")
DEGREE_SIGNS = ("°", "º", "˚", "degrees", "degree", "deg")
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_POWER = re.compile("([⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)")


def _plain_text(text: str) -> str:
    """Turn typed math into plain text: ``x²`` → ``x**2``, full-width digits → ASCII (NFKC)."""
    import unicodedata

    text = _POWER.sub(lambda m: "**" + m[1].translate(_SUPERSCRIPTS), text)
    return unicodedata.normalize("NFKC", text).replace("\u2044", "/")


class AnswerError(ValueError):
    """An answer that cannot be read as what the exercise asks for; the message says why."""


def describe(x: Any, limit: int = 40) -> str:
    """Return a short, safe ``repr`` of ``x`` for a message (never raises).

    Examples
    --------
    >>> describe("a" * 100)
    "'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa…"
    >>> describe(10**5000)
    'an int of about 5000 digits'
    """
    if type(x) is int and x.bit_length() > 128:  # repr of a huge int is long or refused
        return f"an int of about {round(x.bit_length() * math.log10(2))} digits"
    try:
        text = repr(x)
    except Exception:  # an object whose __repr__ raises still gets a name
        text = f"a {_type_name(x)}"
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _type_name(x: Any) -> str:
    try:
        return type(x).__name__
    except Exception:  # pragma: no cover - type() of anything has a name
        return "object"


def is_exact(x: Number) -> bool:
    """Return True for a value read exactly (a ``Fraction``), False for a float."""
    return isinstance(x, Fraction)


# --------------------------------------------------------------------------- numbers


def read_number(x: Any, *, degrees: bool = False) -> Number:
    """Read one number of an answer: a ``Fraction`` when exact, a ``float`` otherwise.

    Parameters
    ----------
    x : object
        Any object; see the module's rules for what reads as a number.
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
    try:
        return _number(x, degrees, 0)
    except AnswerError:
        raise
    except RecursionError:
        raise AnswerError("this answer is nested too deeply to read") from None
    except Exception as exc:  # an object that misbehaves when asked what it is
        raise AnswerError(f"{describe(x)} could not be read as a number ({_why(exc)})") from None


def _why(exc: BaseException) -> str:
    text = str(exc)
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def _module(x: Any) -> str:
    return getattr(type(x), "__module__", "") or ""


def _number(x: Any, degrees: bool, depth: int) -> Number:
    if depth > 8:
        raise AnswerError("this answer is nested too deeply to read")
    if x is None:
        raise AnswerError(
            "None is not a number (did a function print its result instead of returning it?)"
        )
    if x is Ellipsis:
        raise AnswerError("... is not a number: replace it with your answer")
    t = type(x)
    if (
        t is bool
        or t.__name__ in ("bool_", "bool")
        or t.__name__ in ("BooleanTrue", "BooleanFalse")
    ):
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
    module = _module(x)
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
        if x.size == 1:
            return _number(
                x.reshape(()).item() if x.dtype != object else x.flat[0], degrees, depth + 1
            )
        if x.size == 0:
            raise AnswerError("an empty array is not a number")
        raise AnswerError(f"expected one number, got an array of shape {x.shape}")
    if isinstance(x, np.bool_):
        raise AnswerError(f"{x} is a truth value, not a number")
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
    if not getattr(x, "is_number", False):
        free = sorted(str(s) for s in getattr(x, "free_symbols", ()))
        if free:
            raise AnswerError(f"{describe(x)} still has {', '.join(free)} in it: give a number")
        raise AnswerError(f"{describe(x)} is not a number")
    return _sympy_value(x)


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


_SQRT = re.compile(r"√\s*(\d+(?:\.\d+)?|\(|[A-Za-z])")
_DIGIT_CALL = re.compile(r"(\d)\s*(sqrt|pi|log|ln|exp|\()")
_UNSAFE = re.compile(r"__|\.\s*[A-Za-z_]|lambda|[;:`\[\]{}@$!?'\"\\]")


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
    s = _plain_text(s).strip()
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
    if not getattr(value, "is_number", False):
        free = sorted(str(v) for v in getattr(value, "free_symbols", ()))
        if free:
            raise AnswerError(f"{describe(text)} has {', '.join(free)} in it: give a number")
        raise AnswerError(f"{describe(text)} is not a number")
    return _sympy_value(value)


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


# --------------------------------------------------------------------------- vectors and points


def _sized(kind: str, size: int) -> str:
    return f"{size} numbers (x, y, z)" if size == 3 else f"{size} numbers"


def _items(x: Any, size: int, what: str) -> list[Any]:
    """Return the elements of a vector-like answer, before each is read as a number."""
    if x is None:
        raise AnswerError(f"None is not {what}")
    if isinstance(x, str):
        return _text_items(x)
    if isinstance(x, bytes | bytearray | memoryview):
        raise AnswerError(f"bytes are not {what}")
    if isinstance(x, dict):
        raise AnswerError(f"a dict is not {what}: write it as a tuple")
    if isinstance(x, set | frozenset):
        raise AnswerError(f"a set has no order, so it is not {what}: write it as a tuple")
    module = _module(x)
    if module.startswith("numpy"):
        import numpy as np

        if isinstance(x, np.ndarray):
            if x.ndim == 0:
                raise AnswerError(f"expected {what}, got one number")
            if x.ndim == 2 and 1 in x.shape:
                return list(x.reshape(-1))
            if x.ndim != 1:
                raise AnswerError(f"expected {what}, got an array of shape {x.shape}")
            return list(x)
        raise AnswerError(f"expected {what}, got one number")
    if module.startswith("sympy"):
        if getattr(x, "is_Matrix", False):
            rows, cols = x.shape
            if rows == 1 or cols == 1:
                return list(x)
            raise AnswerError(f"expected {what}, got a {rows} × {cols} matrix")
        raise AnswerError(f"expected {what}, got one value")
    if isinstance(x, int | float | complex | Fraction) or _looks_like_number(x):
        raise AnswerError(f"expected {what}, got one number")
    if not isinstance(x, Iterable) and not hasattr(x, "__getitem__"):
        raise AnswerError(f"expected {what}, got {describe(x)}")
    items = list(itertools.islice(iter(x), size + 1))  # a generator may never end
    return items


def _looks_like_number(x: Any) -> bool:
    from decimal import Decimal
    from numbers import Number as AnyNumber

    return isinstance(x, Decimal | AnyNumber)


_BRACKETS = "()[]{}⟨⟩"


def _text_items(text: str) -> list[str]:
    s = _plain_text(text).strip()
    while len(s) >= 2 and s[0] in "([{⟨" and s[-1] in ")]}⟩":
        s = s[1:-1].strip()
    if not s:
        return []
    if any(b in s for b in _BRACKETS) and "," not in s:
        return [s]
    parts = [p.strip() for p in s.split(",")] if "," in s else s.split()
    return parts


def read_vector(x: Any, size: int = 3, *, degrees: bool = False) -> list[Number]:
    """Read a vector of ``size`` numbers.

    Parameters
    ----------
    x : object
        A tuple, list, generator, numpy array (``(3,)``, ``(3, 1)`` or
        ``(1, 3)``), row or column sympy matrix, or text such as ``"(1, 0, 2)"``.
    size : int, default 3
        How many numbers.
    degrees : bool, default False
        Passed on to `read_number` for each component.

    Returns
    -------
    list of Fraction or float

    Raises
    ------
    AnswerError
        Naming the component that cannot be read, or saying how many there are.

    Examples
    --------
    >>> read_vector(("2/7", 0, "-1.5"))
    [Fraction(2, 7), Fraction(0, 1), Fraction(-3, 2)]
    >>> read_vector([1, 2])
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.AnswerError: expected 3 numbers (x, y, z), got 2
    """
    what = _sized("vector", size)
    try:
        items = _items(x, size, what)
        if len(items) == 1 and size != 1 and not isinstance(x, str):
            inner = items[0]  # [[1, 2, 3]]: a row inside a list
            if not isinstance(inner, str) and _length(inner) == size:
                items = _items(inner, size, what)
    except AnswerError:
        raise
    except RecursionError:
        raise AnswerError("this answer is nested too deeply to read") from None
    except Exception as exc:
        raise AnswerError(f"{describe(x)} could not be read as {what} ({_why(exc)})") from None
    if len(items) != size:
        got = f"more than {size}" if len(items) > size else str(len(items))
        raise AnswerError(f"expected {what}, got {got}")
    out = []
    for i, item in enumerate(items):
        name = AXIS_NAMES[i] if size == 3 else str(i + 1)
        try:
            out.append(read_number(item, degrees=degrees))
        except AnswerError as exc:
            raise AnswerError(f"{name}: {exc}") from None
    return out


def _length(x: Any) -> int:
    try:
        return len(x)
    except Exception:
        return -1


@dataclass(frozen=True)
class Items:
    """What the triples of an answer are, as `read_points` names them in its messages."""

    one: str
    many: str
    #: after the count: "4 points (x, y, z)"
    parts: str
    #: one of them in brackets, as text answers write them
    bracketed: str
    #: what the three numbers of one are: "(x, y, z)"
    inner: str
    #: whether their order matters (a set of them is an answer only when it does not)
    ordered: bool = True


#: Points (x, y, z): `read_points`'s default.
POINTS = Items("point", "points", "(x, y, z)", "(x, y, z)", "(x, y, z)")
#: Faces of a mesh, three vertex numbers each, in any order (a set of them is read too).
FACES = Items(
    "face", "faces", "of 3 vertex numbers", "(a, b, c)", "(its corners' vertex numbers)", False
)


def read_points(
    answer: Any, count: int, *, items: Items = POINTS
) -> list[tuple[Number, Number, Number]]:
    """Read ``count`` points (x, y, z), or other triples ``items`` names.

    Parameters
    ----------
    answer : object
        A sequence of points, an ``(count, 3)`` array or sympy matrix, a dict
        keyed ``"A"``, ``"B"``, ``"C"``, or text such as ``"(0,0,1), (1,0,1), (0,1,1)"``.
    count : int
        How many points.
    items : Items, default POINTS
        What the triples are, for the messages: points (x, y, z), or `FACES`
        (three vertex numbers each).

    Returns
    -------
    list of tuple

    Raises
    ------
    AnswerError
        Naming the point that cannot be read, or the wrong count.

    Examples
    --------
    >>> read_points([(0, 0, 2), ("3/4", 0, 2)], 2)[1]
    (Fraction(3, 4), Fraction(0, 1), Fraction(2, 1))
    >>> read_points({"A": (0, 0, 0), "B": (1, 0, 0), "C": (0, 5, 0)}, 3)[2]
    (Fraction(0, 1), Fraction(5, 1), Fraction(0, 1))
    >>> read_points([(0, 1, 2)], 2, items=FACES)
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.AnswerError: give 2 faces of 3 vertex numbers, got 1
    """
    labels = "ABC" if count == 3 and items is POINTS else [str(i + 1) for i in range(count)]
    want = f"{count} {items.one if count == 1 else items.many} {items.parts}"
    try:
        items_read = _point_items(answer, count, want, labels, items)
    except AnswerError:
        raise
    except RecursionError:
        raise AnswerError("this answer is nested too deeply to read") from None
    except Exception as exc:
        raise AnswerError(f"{describe(answer)} could not be read as {want} ({_why(exc)})") from None
    if len(items_read) != count:
        got = f"more than {count}" if len(items_read) > count else str(len(items_read))
        raise AnswerError(f"give {want}, got {got}")
    points = []
    for label, p in zip(labels, items_read, strict=True):
        try:
            x, y, z = read_vector(p)
        except AnswerError as exc:
            told = str(exc).replace("(x, y, z)", items.inner)
            raise AnswerError(f"{items.one} {label}: {told}") from None
        points.append((x, y, z))
    return points


_GROUP = re.compile(r"[(\[]([^()\[\]]*)[)\]]")


def _point_items(answer: Any, count: int, want: str, labels: Any, kind: Items) -> list[Any]:
    if answer is None or answer is Ellipsis:
        raise AnswerError(f"give {want}")
    if isinstance(answer, str):
        groups = _GROUP.findall(answer)
        if not groups:
            raise AnswerError(f"give {want}, each in brackets: {kind.bracketed}")
        return groups
    if isinstance(answer, dict):
        keys = {str(k).strip().upper(): v for k, v in answer.items()}
        if set(keys) == set(labels):
            return [keys[k] for k in labels]
        raise AnswerError(f"a dict of {kind.many} needs the keys {', '.join(labels)}")
    if isinstance(answer, set | frozenset) and not kind.ordered:
        return list(itertools.islice(iter(answer), count + 1))
    if isinstance(answer, set | frozenset):
        raise AnswerError(
            f"a set has no order, and the order of the {kind.many} matters: give {want}"
        )
    if isinstance(answer, bytes | bytearray | memoryview):
        raise AnswerError(f"bytes are not {kind.many}: give {want}")
    module = _module(answer)
    if module.startswith("numpy"):
        import numpy as np

        if isinstance(answer, np.ndarray) and answer.ndim == 2 and answer.shape[1] == 3:
            return list(answer)
        raise AnswerError(f"give {want}; an array of them has shape ({count}, 3)")
    if module.startswith("sympy"):
        if getattr(answer, "is_Matrix", False) and answer.shape[1] == 3:
            return [answer.row(i) for i in range(answer.shape[0])]
        raise AnswerError(f"give {want}; a matrix of them has {count} rows of 3")
    if isinstance(answer, int | float | complex | Fraction) or _looks_like_number(answer):
        raise AnswerError(f"give {want}, not one number")
    if not isinstance(answer, Iterable):
        raise AnswerError(f"give {want}, not {describe(answer)}")
    return list(itertools.islice(iter(answer), count + 1))


# --------------------------------------------------------------------------- truth values and words

_TRUTH_WORDS = {"true": True, "false": False}


def read_bool(x: Any) -> bool:
    """Read ``True`` or ``False`` (also numpy and sympy booleans and the words as text).

    Examples
    --------
    >>> read_bool(" false "), read_bool(True)
    (False, True)
    >>> read_bool(1)
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.AnswerError: answer True or False (1 is a number)
    """
    name = _type_name(x)
    if name in ("bool", "bool_", "BooleanTrue", "BooleanFalse"):
        return bool(x)
    if isinstance(x, str) and x.strip().lower() in _TRUTH_WORDS:
        return _TRUTH_WORDS[x.strip().lower()]
    if isinstance(x, int | float | Fraction) or _looks_like_number(x):
        raise AnswerError(f"answer True or False ({describe(x)} is a number)")
    raise AnswerError("answer True or False")


_FILLER = frozenset({"the", "a", "face", "side"})


def read_word(x: Any) -> str:
    """Read a one-word answer: lower case, without "the" or "face"/"side" around it.

    Examples
    --------
    >>> read_word("  The Left side ")
    'left'
    """
    if not isinstance(x, str):
        raise AnswerError("answer with a word, in quotes")
    words = [w for w in x.strip().lower().strip(".!").split() if w not in _FILLER]
    return " ".join(words)


# --------------------------------------------------------------------------- expressions


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
        return sympify_text(answer, symbols, what=what)
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
