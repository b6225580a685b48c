"""Display formatting: the one formatter behind notebooks, the CLI, widgets and the site.

Rules (the site's JavaScript calculator follows the same ones):

* ``precision`` is the number of decimal places, 0 to 15.
* Rounding is half away from zero, applied to the *exact* value, so an area of
  exactly 0.125 shows ``0.13`` at precision 2. Square roots are rounded from an
  exact integer evaluation, so they are correctly rounded too.
* A nonzero value never prints as zero: only when fixed-point at this precision
  would show it as zero (it is below half of ``10**-precision``), and also at
  ``1e15`` and above, the number switches to scientific notation with
  ``precision`` digits after the point (``2.7756e-17``). So 0.707 at precision 0
  is ``1`` and 0.4 is ``4e-01``. Exponents have at least two digits, as in
  Python's ``format(x, ".4e")``.
* Zero never carries a minus sign.
* ``trim=True`` drops trailing zeros and a bare point (``0.5``, ``1.4142``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from decimal import Decimal
from fractions import Fraction
from numbers import Integral, Rational, Real

from trinormal.validation import MAX_PRECISION as MAX_PRECISION  # re-exported
from trinormal.validation import check_coordinate, check_precision

__all__ = ["format_number", "format_vector"]

#: Values of at least 10**SCI_ABOVE_LOG10 print in scientific notation.
SCI_ABOVE_LOG10 = 15


def _round_sqrt(num: int, den: int, k: int) -> int:
    """Round ``sqrt(num / den) * 10**k`` half away from zero to an integer."""
    if k >= 0:
        n2, d2 = num * 10 ** (2 * k), den
    else:
        n2, d2 = num, den * 10 ** (-2 * k)
    m = math.isqrt(n2 // d2)
    # sqrt(n2/d2) >= m + 1/2  <=>  4 n2 >= (2m + 1)^2 d2
    if 4 * n2 >= (2 * m + 1) ** 2 * d2:
        m += 1
    return m


def _decimal_exponent(num: int, den: int) -> int:
    """Return ``e`` with ``10**e <= sqrt(num/den) < 10**(e+1)`` (``num, den > 0``)."""
    e = math.floor((num.bit_length() - den.bit_length()) * math.log10(2) / 2)

    def at_least(e: int) -> bool:  # sqrt(num/den) >= 10**e  <=>  num >= den * 100**e
        return bool(num >= den * 100**e if e >= 0 else num * 100 ** (-e) >= den)

    while not at_least(e):
        e -= 1
    while at_least(e + 1):
        e += 1
    return e


def _trim(digits: str) -> str:
    if "." in digits:
        digits = digits.rstrip("0").rstrip(".")
    return digits


def format_surd(negative: bool, num: int, den: int, precision: int, trim: bool = False) -> str:
    """Format ``±sqrt(num / den)`` for exact non-negative integers ``num`` and ``den > 0``.

    Every displayed number goes through here: a rational ``p/q`` is the surd
    ``p**2 / q**2``, and ``|N| = sqrt(S) / D**2`` is exact without being rational.

    Examples
    --------
    >>> format_surd(False, 2, 1, 4)             # sqrt(2)
    '1.4142'
    >>> format_surd(True, 1, 2, 4)              # -sqrt(1/2)
    '-0.7071'
    >>> format_surd(False, 1, 64, 2)            # 0.125 rounds half away from zero
    '0.13'
    """
    p = check_precision(precision)
    if num == 0:
        return "0" if (trim or p == 0) else "0." + "0" * p
    # Scientific where fixed-point would show zero, sqrt(num/den) < 10**-p / 2, that is
    # 4 num 100**p < den; and at 1e15 and above
    small = 4 * num * 100**p < den
    large = num >= den * 100**SCI_ABOVE_LOG10
    sign = "-" if negative else ""
    if not (small or large):
        m = _round_sqrt(num, den, p)
        s = str(m).rjust(p + 1, "0")
        body = s if p == 0 else f"{s[:-p]}.{s[-p:]}"
        return sign + (_trim(body) if trim else body)
    e = _decimal_exponent(num, den)
    m = _round_sqrt(num, den, p - e)
    if m >= 10 ** (p + 1):  # rounding carried into a new digit: 9.99995 -> 10.0000
        e += 1
        m = _round_sqrt(num, den, p - e)
    s = str(m)
    mantissa = s if p == 0 else f"{s[0]}.{s[1:]}"
    if trim:
        mantissa = _trim(mantissa)
    return f"{sign}{mantissa}e{'-' if e < 0 else '+'}{abs(e):02d}"


#: The largest numerator or denominator, in bits, `format_number` accepts (about
#: 3900 digits: Python prints integers of at most 4300 digits).
_FORMAT_BITS = 13_000


def exact_ratio(x: object) -> tuple[int, int]:
    """Return ``(numerator, denominator)`` of a finite real number, exactly.

    Any number [`trinormal.validation.check_coordinate`][trinormal.validation.check_coordinate]
    reads (sympy numbers too), with numerator and denominator of up to about 3900 digits.

    Examples
    --------
    >>> exact_ratio(0.5), exact_ratio(Fraction(1, 3)), exact_ratio(Decimal("0.1"))
    ((1, 2), (1, 3), (1, 10))
    """
    if isinstance(x, bool | str):
        raise TypeError(f"expected a real number, got {type(x).__name__}")
    too_large = ValueError(f"cannot format {type(x).__name__}: it has too many digits")
    if isinstance(x, Decimal):
        if not x.is_finite():
            raise ValueError(f"cannot format {x!r}: it is not a finite number")
        if (x and not -3900 < x.adjusted() < 3900) or len(x.as_tuple().digits) > 3900:
            raise too_large
    if isinstance(x, Integral):
        n, d = int(x), 1
    elif isinstance(x, Rational):
        n, d = int(x.numerator), int(x.denominator)
    elif isinstance(x, Real | Decimal) and hasattr(x, "as_integer_ratio"):
        try:
            n, d = x.as_integer_ratio()
        except (OverflowError, ValueError):
            raise ValueError(f"cannot format {x!r}: it is not a finite number") from None
        n, d = int(n), int(d)
    else:
        try:  # sympy numbers and the like: read, or refused, as a coordinate is
            n, d = check_coordinate(x, "the value")
        except TypeError:
            raise TypeError(f"expected a real number, got {type(x).__name__}") from None
    if max(-n, n, d).bit_length() > _FORMAT_BITS:
        raise too_large
    return n, d


def format_number(
    x: float | int | Fraction | Decimal, precision: int = 4, trim: bool = False
) -> str:
    """Format one real number for display, from its exact value.

    Parameters
    ----------
    x : int, float, Fraction or Decimal
        A finite real number. A float is formatted from its exact binary value.
    precision : int, default 4
        Decimal places, 0 to 15.
    trim : bool, default False
        Drop trailing zeros and a bare decimal point.

    Returns
    -------
    str
        Fixed-point text, or scientific notation for a nonzero value that
        fixed-point would show as zero (below half of ``10**-precision``) or
        at ``1e15`` and above.

    Raises
    ------
    ValueError
        For NaN, infinities, or a precision outside 0 to 15.

    Examples
    --------
    >>> format_number(0.125, 2)
    '0.13'
    >>> format_number(0.25, 1)
    '0.3'
    >>> format_number(0.707, 0), format_number(0.4, 0), format_number(0.00005, 4)
    ('1', '4e-01', '0.0001')
    >>> format_number(-0.0)
    '0.0000'
    >>> format_number(2.7755575615628914e-17)
    '2.7756e-17'
    >>> format_number(Fraction(1, 2), 4, trim=True)
    '0.5'
    >>> format_number(10**600 // 13)
    '7.6923e+598'
    """
    n, d = exact_ratio(x)
    return format_surd(n < 0, n * n, d * d, precision, trim)


def format_vector(
    xs: Iterable[float | int | Fraction | Decimal], precision: int = 4, trim: bool = False
) -> str:
    """Format a vector as ``(x, y, z)`` with [`format_number`][trinormal.display.format_number].

    Examples
    --------
    >>> format_vector((0.0, -0.5, 0.5), 4)
    '(0.0000, -0.5000, 0.5000)'
    >>> format_vector((0, -1, 1), 4, trim=True)
    '(0, -1, 1)'
    """
    return "(" + ", ".join(format_number(x, precision, trim) for x in xs) + ")"


def join_vector(parts: Iterable[str]) -> str:
    """Join already formatted components as ``(x, y, z)``."""
    return "(" + ", ".join(parts) + ")"


def plane_equation(parts: tuple[str, str, str], offset: str) -> str:
    """Write the plane ``n · x = d`` as ``ax + by + cz = d`` from formatted numbers.

    The sign between terms is taken from each formatted coefficient, so a
    coefficient that rounds to zero reads ``+ 0.0000y``.

    Examples
    --------
    >>> plane_equation(("0.0000", "-0.7071", "0.7071"), "0.0000")
    '0.0000x - 0.7071y + 0.7071z = 0.0000'
    """
    out = parts[0] + "x"
    for text, axis in zip(parts[1:], "yz", strict=True):
        if text.startswith("-"):
            out += f" - {text[1:]}{axis}"
        else:
            out += f" + {text}{axis}"
    return f"{out} = {offset}"


# --------------------------------------------------------------------------- exact text


def exact_text(q: Fraction | int, max_places: int = 20) -> str:
    """Write an exact rational the way a person would: ``3``, ``-0.15`` or ``1/3``.

    A value whose decimal expansion ends within ``max_places`` places is written
    as a decimal, any other as a fraction.

    Examples
    --------
    >>> exact_text(Fraction(3, 20)), exact_text(Fraction(-1, 3)), exact_text(6)
    ('0.15', '-1/3', '6')
    >>> exact_text(Fraction(1, 2**30)), exact_text(Fraction(1, 2**30), max_places=40)
    ('1/1073741824', '0.000000000931322574615478515625')
    """
    q = Fraction(q)
    n, d = q.numerator, q.denominator
    if d == 1:
        return str(n)
    twos = (d & -d).bit_length() - 1
    rest, fives = d >> twos, 0
    while rest % 5 == 0:
        rest //= 5
        fives += 1
    places = max(twos, fives)
    if rest == 1 and places <= max_places:
        digits = str(abs(n) * 10**places // d).rjust(places + 1, "0")
        return ("-" if n < 0 else "") + f"{digits[:-places]}.{digits[-places:]}"
    return f"{n}/{d}"


def exact_literal(q: Fraction | int) -> str:
    """Write an exact rational as Python code that gives it back exactly, for a ``repr``.

    An integer is written bare; any other value as the quoted `exact_text`, which
    `trinormal.triangle_normal` and ``Explorer`` read exactly (a bare ``0.1`` would be a
    float, not one tenth).

    Examples
    --------
    >>> print(exact_literal(Fraction(1, 3)), exact_literal(Fraction(47, 20)), exact_literal(-2))
    '1/3' '2.35' -2
    """
    q = Fraction(q)
    return str(q.numerator) if q.denominator == 1 else repr(exact_text(q))


def exact_literals(values: Iterable[Fraction | int]) -> str:
    """Write a vector of exact rationals as a tuple literal of `exact_literal` values.

    Examples
    --------
    >>> print(exact_literals([Fraction(1, 3), 0, Fraction(1, 10)]))
    ('1/3', 0, '0.1')
    """
    return "(" + ", ".join(exact_literal(q) for q in values) + ")"


def _square_split(m: int) -> tuple[int, int]:
    """Split ``m > 0`` as ``k*k*rest``, pulling out square factors found by trial division."""
    k = 1
    p = 2
    while p * p <= m and p < 10_000:
        while m % (p * p) == 0:
            m //= p * p
            k *= p
        p += 1 if p == 2 else 2
    r = math.isqrt(m)
    if r * r == m:
        return k * r, 1
    return k, m


def radical(q: Fraction) -> tuple[Fraction, int]:
    """Write ``sqrt(q)`` as ``c * sqrt(m)`` with ``c`` rational and ``m`` free of small squares.

    Examples
    --------
    >>> radical(Fraction(1, 2))
    (Fraction(1, 2), 2)
    >>> radical(Fraction(8))
    (Fraction(2, 1), 2)
    >>> radical(Fraction(9, 4))
    (Fraction(3, 2), 1)
    """
    if q < 0:
        raise ValueError("radical() takes a non-negative number")
    if q == 0:
        return Fraction(0), 1
    # sqrt(p/r) = sqrt(p*r) / r
    k, m = _square_split(q.numerator * q.denominator)
    return Fraction(k, q.denominator), m


def radical_text(c: Fraction, m: int) -> str:
    """Write ``c * sqrt(m)`` as sympy prints it: ``√2/2``, ``-3√5/10``, ``1/3``.

    Examples
    --------
    >>> radical_text(Fraction(1, 2), 2), radical_text(Fraction(-3, 10), 5)
    ('√2/2', '-3√5/10')
    >>> radical_text(Fraction(1, 3), 1)
    '1/3'
    """
    if m == 1 or c == 0:
        return exact_text(c)
    n, d = c.numerator, c.denominator
    sign = "-" if n < 0 else ""
    coeff = "" if abs(n) == 1 else str(abs(n))
    return f"{sign}{coeff}√{m}" + ("" if d == 1 else f"/{d}")
