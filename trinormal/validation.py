"""Every input check, in one place: coordinates, vertices, winding, precision, tolerance.

The core, the command line, the explorer and the mesh functions all validate
through these functions, so each kind of bad input gets one behaviour and one
message wherever it is typed. The site's calculator (``trinormal-core.js``)
follows the same rules; ``tests/data/parser_vectors.json`` holds strings and
what these functions say about them, and both sides are tested against it.

The rules
---------
* A **coordinate** is an ``int``, ``float``, `Fraction`,
  `Decimal`, numpy real scalar, sympy ``Integer``,
  ``Rational`` or ``Float``, or a string holding a decimal (``"0.1"``,
  ``"-2.5e3"``, ``".5"``, ``"5."``) or a fraction (``"1/3"``). It is read as
  an exact ratio. A sympy ``Float`` is its exact binary value; an exact sympy
  expression that is not rational (``sqrt(3)/2``) is refused, because the
  arithmetic works with rationals.
* **Strings**: ASCII digits only (``"١"`` and ``"１"`` are refused, as are
  ``"1_000"`` and ``"0x10"``); the minus sign may be ``-`` or the Unicode minus
  ``−`` (as printed text uses it); spaces around the number, a byte order mark
  and Unicode spaces such as the no-break space are ignored. At most
  `MAX_TEXT_LENGTH` characters.
* **One size limit for every type**: the value, as a fraction in lowest terms,
  has a numerator and a denominator of at most `MAX_DIGITS` digits each
  (every float qualifies). It is checked before any large arithmetic, so an
  input such as ``Decimal("1e1000000")`` is refused at once. The nine
  coordinates of a triangle together must also fit over one common
  denominator with at most `MAX_COMMON_DIGITS` digits in it and in every
  numerator. Within these limits every result can be printed, turned into
  JSON and worked step by step.
* A **vertex** is a sized, ordered sequence of exactly three coordinates: a
  list, a tuple, a numpy array, or any other object with a length that can be
  indexed. Sets, dictionaries, strings, bytes and iterators (whose length is
  unknown) are refused without reading any item from them.
* **winding** is ``"ABC"`` or ``"ACB"``; **precision** is a whole number from
  0 to 15; **tol** (a bound on how thin a triangle may be compared with its
  longest side, `trinormal.tolerances`) is from 0 to 1.

Examples
--------
>>> check_coordinate("−2.5e3", "B.x")
(-2500, 1)
>>> check_precision(4), check_winding("ACB"), check_tolerance("1/2")
(4, <Winding.ACB: 'ACB'>, (1, 2))
>>> check_coordinate("１", "A.y")
Traceback (most recent call last):
...
ValueError: A.y = '１' is not a number (use a decimal like 0.1 or a fraction like 1/3)
"""

from __future__ import annotations

import itertools
import math
import re
import unicodedata
from collections.abc import Mapping
from decimal import Decimal
from enum import StrEnum
from numbers import Integral, Rational, Real
from typing import Any, cast

__all__ = [
    "MAX_COMMON_DIGITS",
    "MAX_DIGITS",
    "MAX_PRECISION",
    "MAX_TEXT_LENGTH",
    "MESSAGES",
    "MIN_PRECISION",
    "Winding",
    "check_coordinate",
    "check_precision",
    "check_tolerance",
    "check_vertex",
    "check_winding",
    "limits",
    "message",
]
# Also used inside the package, and not part of its public API (so not in __all__ nor in the
# API reference): check_common (one denominator for the core) and quote_input (for messages).

#: Most digits in the numerator, and in the denominator, of one coordinate (lowest terms).
MAX_DIGITS = 400
#: Most digits in the common denominator of a triangle's nine coordinates and in
#: each coordinate over it: enough for any mix of floats and ordinary decimals, and
#: small enough that every exact result stays printable (Python prints at most
#: 4300 digits of one integer) and is worked step by step in well under a second.
MAX_COMMON_DIGITS = 850
#: Most characters in a coordinate written as text.
MAX_TEXT_LENGTH = 1000
#: The range of ``precision``, the number of decimal places shown.
MIN_PRECISION, MAX_PRECISION = 0, 15
#: Characters of an input echoed in a message; longer inputs are cut (see `quote_input`).
QUOTE_SHOWN = 24
_ESCAPES = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}

VERTICES = "ABC"
AXES = "xyz"


def limits() -> dict[str, int]:
    """Return the limits as one JSON-ready dictionary, for the site's generated constants.

    Examples
    --------
    >>> limits()["max_precision"], limits()["max_digits"]
    (15, 400)
    """
    return {
        "max_digits": MAX_DIGITS,
        "max_common_digits": MAX_COMMON_DIGITS,
        "max_text_length": MAX_TEXT_LENGTH,
        "min_precision": MIN_PRECISION,
        "max_precision": MAX_PRECISION,
        "quote_shown": QUOTE_SHOWN,
    }


#: Every message these checks give, as a ``str.format`` template. The site's
#: calculator fills in the same templates (the build writes them into its
#: constants), so a wording changed here changes on both. A template uses only
#: plain ``{field}`` names: the names of `limits` (filled in by `message`) and
#: ``name`` (the value's name, such as ``B.y``), ``shown`` (the input, quoted
#: by `quote_input`) and the few others listed with each.
MESSAGES: dict[str, str] = {
    "too_long": "{name} is too long ({length} characters; at most {max_text_length})",
    "empty": "{name} is empty",
    "nan": "{name} is NaN",
    "infinite": "{name} is infinite",
    "divides_by_zero": "{name} = {shown} divides by zero",
    "not_a_number": (
        "{name} = {shown} is not a number (use a decimal like 0.1 or a fraction like 1/3)"
    ),
    # subject: the name, or "name = shown" when the input was text
    "too_large": (
        "{subject} is too large a number, or too small a fraction, to compute with exactly "
        "(at most {max_digits} digits in its numerator and in its denominator)"
    ),
    "too_large_together": (
        "{name} makes the nine coordinates too large to compute with exactly: "
        "over one common denominator they would need more than {max_common_digits} digits"
    ),
    "not_rational": (
        "{name} = {shown} is not a rational number: "
        "give it as a decimal or a fraction (the arithmetic is exact on rationals)"
    ),
    # what: the type's name, or the value itself for None and booleans
    "not_real": "{name} is {what}, expected a real number",
    # kind: the type's name
    "not_a_vertex": "{name} must be 3 coordinates (x, y, z) in a list, tuple or array, got {kind}",
    # count: how many coordinates there are
    "vertex_size": "{name} has {count} coordinates, expected 3",
    "winding": "{name} must be 'ABC' or 'ACB', got {shown} (invalid choice)",
    "precision_not_whole": (
        "{name} must be a whole number from {min_precision} to {max_precision}, got {shown}"
    ),
    "precision_range": "{name} must be from {min_precision} to {max_precision}, got {shown}",
    "tolerance_rule": "{name} must be >= 0 and <= 1 (it bounds |N| / L², L the longest side)",
}


def message(key: str, **values: object) -> str:
    """Fill in the template ``MESSAGES[key]`` with the limits and ``values``.

    Examples
    --------
    >>> message("nan", name="B.y")
    'B.y is NaN'
    >>> message("too_long", name="A.x", length=1200)
    'A.x is too long (1200 characters; at most 1000)'
    """
    return MESSAGES[key].format(**limits(), **values)


_LIMIT = 10**MAX_DIGITS
_COMMON_LIMIT = 10**MAX_COMMON_DIGITS
# log2(10**MAX_DIGITS), rounded up: a denominator 2**k with k beyond this is too large
_LIMIT_BITS = _LIMIT.bit_length()


class Winding(StrEnum):
    """Vertex order: which way round the triangle is traversed.

    ``ABC`` uses U = B − A and V = C − A; ``ACB`` swaps the two edges, which
    flips the normal.

    Examples
    --------
    >>> Winding("ACB") is Winding.ACB
    True
    >>> Winding.ABC == "ABC"
    True
    """

    ABC = "ABC"
    ACB = "ACB"

    @property
    def label(self) -> str:
        """The order with arrows, as shown on buttons: ``A→B→C``."""
        return "→".join(self.value)

    def __str__(self) -> str:
        return self.value


# --------------------------------------------------------------------------- showing input


def quote_input(text: str) -> str:
    r"""Quote a user's text for an error message, as Python's ``repr`` would, but short.

    Characters that are not letters, digits, punctuation or symbols (spaces
    other than the plain space, control and format characters) are escaped,
    so an invisible character shows. Text longer than 24 characters is cut
    and marked with ``…``. The site's calculator quotes the same way.

    Examples
    --------
    >>> quote_input("abc"), quote_input("it's")
    ("'abc'", '"it\'s"')
    >>> quote_input("1\u00a02")
    "'1\\xa02'"
    >>> quote_input("1" * 30)
    "'111111111111111111111111…'"
    """
    cut = len(text) > QUOTE_SHOWN
    if cut:
        text = text[:QUOTE_SHOWN]
    quote = '"' if "'" in text and '"' not in text else "'"
    out = [quote]
    for ch in text:
        code = ord(ch)
        if ch in ("\\", quote):
            out.append("\\" + ch)
        elif ch in _ESCAPES:
            out.append(_ESCAPES[ch])
        elif (
            ch == " "
            or 0x20 < code < 0x7F
            or (code >= 0xA0 and unicodedata.category(ch)[0] in "LNPS")
        ):
            out.append(ch)
        elif code < 0x100:
            out.append(f"\\x{code:02x}")
        elif code < 0x10000:
            out.append(f"\\u{code:04x}")
        else:
            out.append(f"\\U{code:08x}")
    out.append("…" + quote if cut else quote)
    return "".join(out)


def _show(value: object) -> str:
    """Show any value briefly in a message: quoted text or a clipped repr."""
    if isinstance(value, str):
        return quote_input(value)
    try:
        text = repr(value)
    except ValueError:  # an int too long for repr
        return type(value).__name__
    return text if len(text) <= 40 else text[:39] + "…"


# --------------------------------------------------------------------------- coordinates

#: Characters ignored around a number: ASCII and Unicode spaces and the byte order mark.
SPACES = "\t\n\v\f\r \x85\xa0\u1680\u2000\u2001\u2002\u2003\u2004\u2005\u2006\u2007\u2008\u2009\u200a\u2028\u2029\u202f\u205f\u3000\ufeff"  # noqa: E501
_SIGN = "[+\\-\u2212]"
_DECIMAL_RE = re.compile(
    rf"({_SIGN}?)([0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE]({_SIGN}?[0-9]+))?", re.ASCII
)
_FRACTION_RE = re.compile(rf"({_SIGN}?[0-9]+)[{SPACES}]*/[{SPACES}]*({_SIGN}?[0-9]+)", re.ASCII)
_NAN_WORDS = {"nan", "+nan", "-nan"}
_INF_WORDS = {"inf", "+inf", "-inf", "infinity", "+infinity", "-infinity"}


def _too_large(name: str, shown: str | None = None) -> ValueError:
    subject = name if shown is None else f"{name} = {shown}"
    return ValueError(message("too_large", subject=subject))


def _check_ratio(n: int, d: int, name: str, shown: str | None = None) -> tuple[int, int]:
    """Apply the size limit to ``n / d`` (``d > 0``), reducing it first if it is too big."""
    if -_LIMIT < n < _LIMIT and d < _LIMIT:
        return n, d
    g = math.gcd(n, d)
    if g > 1:
        n, d = n // g, d // g
        if -_LIMIT < n < _LIMIT and d < _LIMIT:
            return n, d
    raise _too_large(name, shown)


def _decimal(
    sign: str, digits: str, exp: str | None, name: str, shown: str | None
) -> tuple[int, int]:
    """Read a decimal ``sign digits e exp`` exactly, checking its size before converting."""
    if "." in digits:
        whole, frac = digits.split(".")
        shift = -len(frac)
        digits = whole + frac
    else:
        shift = 0
    sig = digits.lstrip("0")
    if not sig:
        return 0, 1
    if exp:
        exp = exp.replace("\u2212", "-")
        if len(exp.lstrip("+-").lstrip("0")) > 6:  # beyond a million: too large either way
            raise _too_large(name, shown)
        shift += int(exp)
    stripped = sig.rstrip("0")
    e = shift + len(sig) - len(stripped)
    sig = stripped  # the value is sig * 10**e, and sig is not a multiple of 10
    if e >= 0:
        if len(sig) + e > MAX_DIGITS:
            raise _too_large(name, shown)
        n, d = int(sig) * 10**e, 1
    else:
        # lowest terms divide 10**-e by a power of 2 or of 5 only, so d >= 2**-e
        if -e > _LIMIT_BITS or len(sig) > MAX_DIGITS - e:
            raise _too_large(name, shown)
        n, d = int(sig), 10**-e
    return _check_ratio(-n if sign in ("-", "\u2212") else n, d, name, shown)


def _parse_text(text: str, name: str) -> tuple[int, int]:
    if len(text) > MAX_TEXT_LENGTH:
        raise ValueError(message("too_long", name=name, length=len(text)))
    s = text.strip(SPACES)
    if not s:
        raise ValueError(message("empty", name=name))
    shown = quote_input(s)
    low = s.lower().replace("\u2212", "-")
    if low in _NAN_WORDS:
        raise ValueError(message("nan", name=name))
    if low in _INF_WORDS:
        raise ValueError(message("infinite", name=name))
    m = _DECIMAL_RE.fullmatch(s)
    if m:
        return _decimal(m.group(1), m.group(2), m.group(3), name, shown)
    m = _FRACTION_RE.fullmatch(s)
    if m:
        top, bottom = (g.replace("\u2212", "-") for g in m.groups())
        n, d = int(top), int(bottom)  # at most MAX_TEXT_LENGTH digits: cheap
        if d == 0:
            raise ValueError(message("divides_by_zero", name=name, shown=shown))
        return _check_ratio(n, d, name, shown) if d > 0 else _check_ratio(-n, -d, name, shown)
    raise ValueError(message("not_a_number", name=name, shown=shown))


def _from_decimal(x: Decimal, name: str) -> tuple[int, int]:
    if x.is_nan():
        raise ValueError(message("nan", name=name))
    if x.is_infinite():
        raise ValueError(message("infinite", name=name))
    if x.is_zero():
        return 0, 1
    adjusted = x.adjusted()  # 10**adjusted <= |x| < 10**(adjusted + 1)
    if adjusted >= MAX_DIGITS or adjusted < -MAX_DIGITS - 1:
        raise _too_large(name)
    t = x.as_tuple()
    if len(t.digits) <= 60:  # the common case: small enough to convert directly
        return _check_ratio(*x.as_integer_ratio(), name)
    # a long coefficient: read its text (cheap) with the string rules' size checks
    m = _DECIMAL_RE.fullmatch(str(x))
    assert m is not None
    return _decimal(m.group(1), m.group(2), m.group(3), name, None)


def _from_sympy(x: Any, name: str) -> tuple[int, int] | None:
    """Exact ratio of a sympy number, or None when ``x`` is not from sympy."""
    if not type(x).__module__.startswith("sympy"):
        return None
    if getattr(x, "is_Rational", False):  # Integer, Rational, Half, One, ...
        return _check_ratio(int(x.p), int(x.q), name)
    if getattr(x, "is_Float", False):
        sign, mantissa, exp, bc = x._mpf_
        man = int(mantissa)
        if man == 0:
            if exp == 0:
                return 0, 1
            raise ValueError(message("nan" if exp == -123 else "infinite", name=name))
        # value = ±man * 2**exp with man odd: limits apply to man and 2**-exp
        if bc > _LIMIT_BITS or exp + bc > _LIMIT_BITS or -exp > _LIMIT_BITS:
            raise _too_large(name)
        n = -man if sign else man
        return _check_ratio(n << exp, 1, name) if exp >= 0 else _check_ratio(n, 1 << -exp, name)
    if getattr(x, "is_number", False):
        if type(x).__name__ == "NaN":
            raise ValueError(message("nan", name=name))
        if getattr(x, "is_infinite", False):
            raise ValueError(message("infinite", name=name))
        if getattr(x, "is_real", False):
            raise ValueError(message("not_rational", name=name, shown=_show(x)))
    raise TypeError(message("not_real", name=name, what=type(x).__name__))


def check_coordinate(x: object, name: str = "value") -> tuple[int, int]:
    r"""Read one coordinate as an exact ratio ``(numerator, denominator)``, denominator > 0.

    Parameters
    ----------
    x : int, float, Fraction, Decimal, numpy or sympy real number, or str
        The coordinate. A string holds a decimal (``"0.1"``, ``"-2.5e3"``) or a
        fraction (``"1/3"``) and is read exactly (see the module's rules).
    name : str
        How to name the value in an error message, such as ``"B.y"``.

    Returns
    -------
    tuple of int
        ``(n, d)`` with the value equal to ``n / d``.

    Raises
    ------
    ValueError
        NaN, an infinity, an empty, unreadable or over-long string, a zero
        denominator, a value beyond the size limit, an irrational sympy number.
    TypeError
        ``None``, ``bool``, complex numbers and other non-real types.

    Examples
    --------
    >>> check_coordinate("0.1"), check_coordinate(" 1/3 "), check_coordinate(0.5)
    ((1, 10), (1, 3), (1, 2))
    >>> check_coordinate("+.5"), check_coordinate("5."), check_coordinate("\ufeff−1")
    ((5, 10), (5, 1), (-1, 1))
    >>> check_coordinate(float("nan"), "B.y")
    Traceback (most recent call last):
    ...
    ValueError: B.y is NaN
    >>> check_coordinate(10**400, "C.z")
    Traceback (most recent call last):
    ...
    ValueError: C.z is too large a number, or too small a fraction, to compute with exactly (at most 400 digits in its numerator and in its denominator)
    """  # noqa: E501
    t = type(x)
    if t is float:  # the common cases first
        f = cast(float, x)
        if f != f:
            raise ValueError(message("nan", name=name))
        if f in (math.inf, -math.inf):
            raise ValueError(message("infinite", name=name))
        return f.as_integer_ratio()
    if t is int:
        i = cast(int, x)
        if -_LIMIT < i < _LIMIT:
            return i, 1
        raise _too_large(name)
    if isinstance(x, str):
        return _parse_text(x, name)
    if x is None or isinstance(x, bool) or t.__name__ == "bool_":
        raise TypeError(message("not_real", name=name, what=repr(x)))
    sym = _from_sympy(x, name)
    if sym is not None:
        return sym
    if isinstance(x, Integral):
        return _check_ratio(int(x), 1, name)
    if isinstance(x, Rational):  # Fraction and other exact rationals
        return _check_ratio(int(x.numerator), int(x.denominator), name)
    if isinstance(x, Decimal):
        return _from_decimal(x, name)
    if isinstance(x, Real) and hasattr(x, "as_integer_ratio"):  # numpy floating scalars
        if x != x:
            raise ValueError(message("nan", name=name))
        try:
            n, d = x.as_integer_ratio()
        except (OverflowError, ValueError):
            raise ValueError(message("infinite", name=name)) from None
        return _check_ratio(int(n), int(d), name)
    raise TypeError(message("not_real", name=name, what=t.__name__))


def check_common(coords: list[tuple[int, int]]) -> tuple[tuple[int, ...], int]:
    """Bring exact ratios to one denominator ``D``; return the integer numerators and ``D``.

    Parameters
    ----------
    coords : list of (int, int)
        Up to nine ratios ``(n, d)`` with ``d > 0``, as
        [`check_coordinate`][trinormal.validation.check_coordinate]
        returns them, in the order ``A.x`` … ``C.z`` (that is how messages name them).

    Returns
    -------
    ints : tuple of int
        Each value times ``D``.
    D : int
        The least common denominator.

    Raises
    ------
    ValueError
        When ``D`` or a numerator over it would need more than
        `MAX_COMMON_DIGITS` digits; the message names the coordinate
        that made it so.

    Examples
    --------
    >>> check_common([(1, 2), (1, 3), (5, 1)])
    ((3, 2, 30), 6)
    >>> check_common([(1, 3**800), (1, 7**470), (1, 11**380)])
    Traceback (most recent call last):
    ...
    ValueError: A.z makes the nine coordinates too large to compute with exactly: over one common denominator they would need more than 850 digits
    """  # noqa: E501
    D = 1
    pow2 = True
    for _, d in coords:
        if d & (d - 1):
            pow2 = False
        if d > D:
            D = d
    if pow2:  # every float input: shift instead of multiplying
        top = D.bit_length()
        ints = tuple([n << (top - d.bit_length()) for n, d in coords])
    else:
        D = 1
        for i, (_, d) in enumerate(coords):
            D = math.lcm(D, d)
            if D >= _COMMON_LIMIT:
                raise _too_large_together(i)
        ints = tuple([n * (D // d) for n, d in coords])
    if D >= _COMMON_LIMIT or any(not -_COMMON_LIMIT < i < _COMMON_LIMIT for i in ints):
        worst = max(range(len(ints)), key=lambda k: abs(ints[k]))
        raise _too_large_together(worst)
    return ints, D


def _too_large_together(i: int) -> ValueError:
    return ValueError(message("too_large_together", name=f"{VERTICES[i // 3]}.{AXES[i % 3]}"))


# --------------------------------------------------------------------------- vertices

_NOT_SEQUENCES = (str, bytes, bytearray, memoryview)


def check_vertex(p: object, vertex: str) -> list[tuple[int, int]]:
    """Read a vertex: a sized, ordered sequence of exactly three coordinates.

    Parameters
    ----------
    p : list, tuple, numpy array or other sized sequence
        The point ``(x, y, z)``.
    vertex : str
        Its name in messages, such as ``"B"``; coordinates are ``B.x``, ``B.y``, ``B.z``.

    Returns
    -------
    list of (int, int)
        The three exact ratios, as [`check_coordinate`][trinormal.validation.check_coordinate] reads
        them.

    Raises
    ------
    TypeError
        Not a sized, ordered sequence: a set, dict, string, bytes, number,
        ``None`` or an iterator (nothing is read from an iterator).
    ValueError
        A sequence with another number of items than three, or a bad coordinate.

    Examples
    --------
    >>> check_vertex(("0.5", 1, 2), "B")
    [(5, 10), (1, 1), (2, 1)]
    >>> check_vertex({1, 2, 3}, "C")
    Traceback (most recent call last):
    ...
    TypeError: C must be 3 coordinates (x, y, z) in a list, tuple or array, got set
    >>> check_vertex([1, 2], "A")
    Traceback (most recent call last):
    ...
    ValueError: A has 2 coordinates, expected 3
    """
    not_a_sequence = TypeError(message("not_a_vertex", name=vertex, kind=type(p).__name__))
    if (
        isinstance(p, (*_NOT_SEQUENCES, Mapping))
        or not hasattr(p, "__getitem__")
        or not hasattr(p, "__len__")
    ):
        raise not_a_sequence
    try:
        size = len(p)
    except TypeError:  # a 0-d array, for one
        raise not_a_sequence from None
    if size != 3:
        raise ValueError(message("vertex_size", name=vertex, count=size))
    items = list(itertools.islice(p, 4))  # type: ignore[call-overload]
    if len(items) != 3:
        raise ValueError(message("vertex_size", name=vertex, count=len(items)))
    return [check_coordinate(x, f"{vertex}.{axis}") for x, axis in zip(items, AXES, strict=True)]


# --------------------------------------------------------------------------- options

_WINDINGS = {"ABC": Winding.ABC, "ACB": Winding.ACB}


def check_winding(winding: object, name: str = "winding") -> Winding:
    """Read a winding: ``"ABC"``, ``"ACB"`` or a [`Winding`][trinormal.core.Winding].

    Parameters
    ----------
    winding : str or Winding
        The order. Nothing else is accepted (not ``"abc"``, not ``" ABC"``).
    name : str, default "winding"
        How messages name it (the command line says ``--winding``).

    Returns
    -------
    Winding

    Raises
    ------
    ValueError
        Anything else: ``winding must be 'ABC' or 'ACB', got … (invalid choice)``.

    Examples
    --------
    >>> check_winding("ABC")
    <Winding.ABC: 'ABC'>
    >>> check_winding("CBA")
    Traceback (most recent call last):
    ...
    ValueError: winding must be 'ABC' or 'ACB', got 'CBA' (invalid choice)
    """
    try:
        return _WINDINGS[winding]  # type: ignore[index]
    except (KeyError, TypeError):
        pass
    raise ValueError(message("winding", name=name, shown=_show(winding)))


_WHOLE_RE = re.compile(r"[0-9]+", re.ASCII)


def check_precision(precision: object, name: str = "precision") -> int:
    """Read a precision: a whole number of decimal places from 0 to 15.

    Parameters
    ----------
    precision : int or str
        An ``int`` (or numpy integer), or text of ASCII digits as typed in a
        box or on the command line (spaces around it are ignored).
    name : str, default "precision"
        How messages name it (the command line says ``--precision``).

    Returns
    -------
    int
        The number of decimal places.

    Raises
    ------
    TypeError
        Neither an integer nor text (a float such as ``2.0``, ``None``, a bool).
    ValueError
        Text that is not a whole number, or a number outside 0 to 15.

    Examples
    --------
    >>> check_precision(0), check_precision(" 15 ")
    (0, 15)
    >>> check_precision(16)
    Traceback (most recent call last):
    ...
    ValueError: precision must be from 0 to 15, got 16
    >>> check_precision("two")
    Traceback (most recent call last):
    ...
    ValueError: precision must be a whole number from 0 to 15, got 'two'
    """
    if isinstance(precision, str):
        text = precision.strip(SPACES)
        if not _WHOLE_RE.fullmatch(text):
            raise ValueError(message("precision_not_whole", name=name, shown=_show(precision)))
        if len(text) > 6:
            raise ValueError(message("precision_range", name=name, shown=_show(text)))
        p = int(text)
    elif isinstance(precision, Integral) and not isinstance(precision, bool):
        p = int(precision)
    else:
        raise TypeError(message("precision_not_whole", name=name, shown=_show(precision)))
    if not MIN_PRECISION <= p <= MAX_PRECISION:
        raise ValueError(message("precision_range", name=name, shown=p))
    return p


def check_tolerance(tol: object, name: str = "tol") -> tuple[int, int]:
    """Read a degeneracy tolerance exactly: a number from 0 to 1, as ``(n, d)``.

    ``tol`` bounds |N| / L², L the longest side (the rule of
    [`trinormal.tolerances`][trinormal.tolerances]), which is at most √3/2, so 1
    already marks every triangle degenerate; larger values are refused.

    Parameters
    ----------
    tol : real or str
        Any type [`check_coordinate`][trinormal.validation.check_coordinate] reads, so
        ``Decimal("1e400")`` is refused at once rather than overflowing.
    name : str, default "tol"
        How messages name it (the command line says ``--tol``).

    Returns
    -------
    tuple of int
        ``(n, d)`` with ``0 <= n / d <= 1``.

    Raises
    ------
    ValueError
        A value outside 0 to 1, or one [`check_coordinate`][trinormal.validation.check_coordinate]
        refuses; the message then ends with the rule.
    TypeError
        A type [`check_coordinate`][trinormal.validation.check_coordinate] refuses.

    Examples
    --------
    >>> check_tolerance(0), check_tolerance("1e-12")
    ((0, 1), (1, 1000000000000))
    >>> check_tolerance(-1)
    Traceback (most recent call last):
    ...
    ValueError: tol must be >= 0 and <= 1 (it bounds |N| / L², L the longest side), got -1
    >>> check_tolerance(float("nan"))
    Traceback (most recent call last):
    ...
    ValueError: tol is NaN; tol must be >= 0 and <= 1 (it bounds |N| / L², L the longest side)
    """
    rule = message("tolerance_rule", name=name)
    try:
        n, d = check_coordinate(tol, name)
    except ValueError as err:
        raise ValueError(f"{err}; {rule}") from None
    except TypeError as err:
        raise TypeError(f"{err}; {rule}") from None
    if n < 0 or n > d:
        raise ValueError(f"{rule}, got {_show(tol)}")
    return n, d
