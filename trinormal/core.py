"""The exact core: the normal of one triangle, computed without rounding.

Every coordinate is read as an exact rational number (a float is its exact
binary value, the string ``"0.1"`` is exactly 1/10). All nine are brought to a
common denominator ``D`` so the cross product runs on plain Python integers;
each reported float is then one correctly rounded division. Square roots use
`math.isqrt` on integers scaled by a power of two, so results stay
accurate at any scale, from 1e-300 to 1e300, with nothing overflowing on the
way. Results come from [`triangle_normal`][trinormal.core.triangle_normal].

The standard library is all this module needs.
"""

# How it is built (for maintainers; the API reference shows only the docstring above):
# the inputs are read into nine integers over one denominator, either quickly
# (_plain_integers: plain tuples or lists of floats and ints, the default tolerance) or by
# trinormal.validation (anything else, with errors that name the coordinate); then one
# exact path, _exact, computes the result and builds it with the one constructor,
# ``_result``. Formatting (format, to_dict, repr) lives in trinormal.fields, which the
# methods below import when called: the core imports no formatter.

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from decimal import Decimal
from fractions import Fraction
from functools import cached_property
from typing import Any, Literal, NamedTuple

from trinormal.tolerances import DEFAULT_TOL
from trinormal.validation import (
    _LIMIT as _INT_LIMIT,  # the size limit: _plain_integers takes plain ints below it
)
from trinormal.validation import (
    Winding,
    _show,
    check_common,
    check_coordinate,
    check_tolerance,
    check_vertex,
    check_winding,
)

__all__ = [
    "ARITHMETICS",
    "Exact",
    "FloatRangeError",
    "Plane",
    "TriangleNormal",
    "Winding",
    "parse_coordinate",
    "triangle_normal",
]

Vec3 = tuple[float, float, float]
Arithmetic = Literal["exact", "float64", "float32"]
ARITHMETICS: tuple[str, ...] = ("exact", "float64", "float32")


class FloatRangeError(ValueError, OverflowError):
    """A value leaves the float64 or float32 range in ``arithmetic="float64"``/``"float32"``.

    It is a `ValueError` (the inputs cannot be computed in that format)
    and, for code written before it existed, an `OverflowError`.
    """


class Plane(NamedTuple):
    """The plane ``normal · x = offset`` through the triangle (``normal`` is unit length)."""

    normal: Vec3
    offset: float


@dataclass(frozen=True)
class Exact:
    """Exact rational values behind a result (`fractions.Fraction`).

    ``magnitude_squared`` is |N|² (|N| itself is usually irrational); ``area``
    squared is ``magnitude_squared / 4``.
    """

    a: tuple[Fraction, Fraction, Fraction]
    b: tuple[Fraction, Fraction, Fraction]
    c: tuple[Fraction, Fraction, Fraction]
    u: tuple[Fraction, Fraction, Fraction]
    v: tuple[Fraction, Fraction, Fraction]
    normal: tuple[Fraction, Fraction, Fraction]
    magnitude_squared: Fraction


# --------------------------------------------------------------------------- parsing


def parse_coordinate(x: object, name: str = "value") -> tuple[int, int]:
    """Read one coordinate as an exact ratio ``(numerator, denominator)``, denominator > 0.

    This is [`trinormal.validation.check_coordinate`][trinormal.validation.check_coordinate] under
    the name the core has always used: the accepted types, the size limit, the return
    value and the errors are described there. ``name`` says how to call the value in an
    error message, such as ``"B.y"``.

    Examples
    --------
    >>> parse_coordinate("0.1")
    (1, 10)
    >>> parse_coordinate("-2.5e3")
    (-2500, 1)
    >>> parse_coordinate(" 1/3 ")
    (1, 3)
    >>> parse_coordinate(0.5)
    (1, 2)
    >>> parse_coordinate(float("nan"), "B.y")
    Traceback (most recent call last):
    ...
    ValueError: B.y is NaN
    """
    return check_coordinate(x, name)


_PLAIN = frozenset((float, int))


# --------------------------------------------------------------------------- the result


class _Integers(NamedTuple):
    """The exact values behind a result, as integers over one common denominator.

    Every coordinate is ``coords[i] / denominator``, U and V are
    ``u / denominator`` and ``v / denominator``, N is ``normal / denominator**2``
    and |N|² is ``norm_squared / denominator**4``.
    """

    coords: tuple[int, ...]  # ax ay az bx by bz cx cy cz, each times the denominator
    denominator: int
    u: tuple[int, int, int]
    v: tuple[int, int, int]
    normal: tuple[int, int, int]
    norm_squared: int  # nx² + ny² + nz²


@dataclass(frozen=True, init=False)
class TriangleNormal:
    """The normal of a triangle and everything derived from it.

    Results are returned by [`triangle_normal`][trinormal.core.triangle_normal], not built directly:
    calling ``TriangleNormal(...)`` raises `TypeError`. The name is public for
    type hints and ``isinstance`` checks. Results are immutable, compare equal
    when every attribute below is equal, and can be copied and pickled.

    Attributes
    ----------
    a, b, c : tuple of float
        The vertices, correctly rounded to float (the exact values are in
        [`exact`][trinormal.core.TriangleNormal.exact]).
    winding : Winding
        ``ABC``: U = B − A, V = C − A. ``ACB``: U = C − A, V = B − A.
    u, v : tuple of float
        The edge vectors.
    normal : tuple of float
        N = U × V, correctly rounded from the exact value (``±inf`` or ``0.0``
        where the exact value is outside the float range).
    magnitude : float
        |N|, twice the area.
    area : float
        |N| / 2.
    unit_normal : tuple of float or None
        N / |N|; ``None`` when the triangle is degenerate.
    degenerate : bool
        True when ``|N| <= tol · L²``, L the longest side: the triangle is thin
        compared with its longest side (the rule of
        [`trinormal.tolerances`][trinormal.tolerances]). Coincident and collinear
        points are degenerate. The verdict is the same whichever corner is A and
        for both windings.
    plane : Plane or None
        ``(n, d)``: the plane ``n · x = d`` with ``n`` the unit normal and
        ``d = n · A``; ``None`` when degenerate.
    reason : str
        One sentence saying why the triangle is degenerate, or ``""``.
    arithmetic : str
        ``"exact"``, ``"float64"`` or ``"float32"``.
    tol : float
        The threshold used for `degenerate`.
    """

    a: Vec3
    b: Vec3
    c: Vec3
    winding: Winding
    u: Vec3
    v: Vec3
    normal: Vec3
    magnitude: float
    area: float
    unit_normal: Vec3 | None
    degenerate: bool
    plane: Plane | None
    reason: str
    arithmetic: str
    tol: float
    _integers: _Integers = field(repr=False, compare=False)

    def __init__(self, *args: object, **kwargs: object) -> None:
        """Refuse direct construction: results come from `triangle_normal`.

        Examples
        --------
        >>> TriangleNormal((0, 0, 0), (1, 0, 0), (0, 1, 0))
        Traceback (most recent call last):
        ...
        TypeError: TriangleNormal is returned by triangle_normal(a, b, c), not built directly
        """
        raise TypeError(
            "TriangleNormal is returned by triangle_normal(a, b, c), not built directly"
        )

    def __repr__(self) -> str:
        """Show the inputs and N exactly, so the result can be recognised (and rebuilt).

        Exact values are written as Python literals: integers bare, anything else
        quoted (``'1/3'``, ``'0.1'``), the form `triangle_normal` reads exactly. In
        ``float64``/``float32`` arithmetic N is the computed floats. Written by
        [`trinormal.fields.result_repr`][trinormal.fields.result_repr].

        Examples
        --------
        >>> triangle_normal(("0.1", "0.2", "0.3"), ("1/3", 0, 0), (0, "2.35", 0))
        ... # doctest: +NORMALIZE_WHITESPACE
        TriangleNormal(a=('0.1', '0.2', '0.3'), b=('1/3', 0, 0), c=(0, '2.35', 0),
                       winding='ABC', arithmetic='exact', normal=('0.705', '0.1', '289/600'),
                       magnitude_squared='5321/7200', degenerate=False)
        >>> triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2))  # doctest: +NORMALIZE_WHITESPACE
        TriangleNormal(a=(0, 0, 0), b=(1, 1, 1), c=(2, 2, 2), winding='ABC', arithmetic='exact',
                       normal=(0, 0, 0), magnitude_squared=0, degenerate=True)
        """
        from trinormal.fields import result_repr  # the formatter sits above the core

        return result_repr(self)

    @cached_property
    def exact(self) -> Exact:
        """Exact rational values of the vertices, edges, N and |N|² for these inputs.

        In ``float64``/``float32`` arithmetic this is still the exact answer for
        the inputs as given, so the rounding error of that format can be measured.

        Examples
        --------
        >>> r = triangle_normal(("0", "0", "0"), ("0.1", "0", "0"), ("0", "1/3", "0"))
        >>> r.exact.normal
        (Fraction(0, 1), Fraction(0, 1), Fraction(1, 30))
        """
        s = self._integers
        D, D2 = s.denominator, s.denominator * s.denominator

        def fr(xs: Iterable[int], den: int) -> tuple[Fraction, Fraction, Fraction]:
            x, y, z = (Fraction(i, den) for i in xs)
            return x, y, z

        return Exact(
            a=fr(s.coords[0:3], D),
            b=fr(s.coords[3:6], D),
            c=fr(s.coords[6:9], D),
            u=fr(s.u, D),
            v=fr(s.v, D),
            normal=fr(s.normal, D2),
            magnitude_squared=Fraction(s.norm_squared, D2 * D2),
        )

    @property
    def thickness(self) -> float:
        """|N| / L², L the longest side: the number the degenerate test compares with ``tol``.

        |N| / L is the triangle's height over its longest side, so this is that
        height as a fraction of the longest side: 0 for points on one line (or
        on one spot), √3/2 ≈ 0.866 at most (an equilateral triangle). It does not
        depend on which corner is A or on the winding, nor on the scale. In
        ``float64``/``float32`` arithmetic it is still the exact value for the
        inputs as given (the verdict there uses the N that format computed).

        Examples
        --------
        >>> triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).thickness
        0.5
        >>> triangle_normal((0, 1e-13, 0), (0, 0, 0), (1, 0, 0)).thickness
        1e-13
        """
        s = self._integers
        return _sqrt_ratio(s.norm_squared, _longest_squared(s.u, s.v) ** 2)

    @property
    def sine(self) -> float:
        """Sine of the angle at A between U and V: |N| / (|U| |V|), 0.0 if an edge is zero.

        It describes the corner A only, so it changes when another corner comes
        first; the degenerate verdict does not use it (see
        [`thickness`][trinormal.core.TriangleNormal.thickness]). A right angle at
        A has sine 1 however thin the triangle is.

        Examples
        --------
        >>> round(triangle_normal((0, 0, 0), (1, 0, 0), (1, 1, 0)).sine, 12)
        0.707106781187
        >>> triangle_normal((0, 0, 0), (1, 0, 0), (0, 1e-13, 0)).sine
        1.0
        """
        s = self._integers
        uu = sum(i * i for i in s.u)
        vv = sum(i * i for i in s.v)
        if uu == 0 or vv == 0:
            return 0.0
        return _sqrt_ratio(s.norm_squared, uu * vv)

    def format(self, precision: int = 4, trim: bool = False) -> dict[str, str]:
        """Display strings for every output field, from the exact values.

        In ``float64``/``float32`` arithmetic the strings are those of the
        computed floats, written exactly before rounding to ``precision``.
        Written by [`trinormal.fields.format_fields`][trinormal.fields.format_fields].

        Parameters
        ----------
        precision : int, default 4
            Decimal places, 0 to 15 (see
            [`trinormal.format_number`][trinormal.display.format_number]).
        trim : bool, default False
            Drop trailing zeros, as the guide's table does.

        Returns
        -------
        dict of str
            One key per field of `trinormal.fields.FIELDS` (``u``,
            ``v``, ``normal``, ``magnitude``, ``area``, ``unit_normal``,
            ``plane``) and ``status`` (one sentence).

        Examples
        --------
        >>> r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
        >>> f = r.format(4)
        >>> f["normal"], f["magnitude"], f["unit_normal"]
        ('(0.0000, -1.0000, 1.0000)', '1.4142', '(0.0000, -0.7071, 0.7071)')
        >>> f["plane"]
        '0.0000x - 0.7071y + 0.7071z = 0.0000'
        >>> r.format(4, trim=True)["unit_normal"]
        '(0, -0.7071, 0.7071)'
        >>> triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2)).format()["unit_normal"]
        'undefined'
        """
        from trinormal.fields import format_fields  # the formatter sits above the core

        return format_fields(self, precision, trim)

    def to_dict(self) -> dict[str, Any]:
        """Every field as JSON-ready values: floats (non-finite as strings) and exact strings.

        The output fields (`trinormal.fields.FIELDS`) appear under their
        keys, between the inputs and the verdict. Written by
        [`trinormal.fields.result_dict`][trinormal.fields.result_dict].

        Examples
        --------
        >>> d = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).to_dict()
        >>> d["normal"], d["plane"], d["exact"]["area_squared"]
        ([0.0, 0.0, 1.0], {'normal': [0.0, 0.0, 1.0], 'offset': 0.0}, '1/4')
        """
        from trinormal.fields import result_dict  # the formatter sits above the core

        return result_dict(self)


# --------------------------------------------------------------------------- arithmetic


def _div(n: int, d: int) -> float:
    """Correctly rounded n / d, with ±inf beyond the float range."""
    try:
        return n / d
    except OverflowError:
        return math.inf if (n < 0) == (d < 0) else -math.inf


def _divide(nums: tuple[int, ...], d: int) -> Any:
    """Correctly rounded ``n / d`` for each n, with ±inf beyond the float range."""
    try:
        return tuple([i / d for i in nums])
    except OverflowError:
        return tuple([_div(i, d) for i in nums])


def _sqrt_ratio(num: int, den: int) -> float:
    """sqrt(num / den) within 1 ulp, for non-negative integers (den > 0), at any scale."""
    if num == 0:
        return 0.0
    # scale by 4**k so the integer square root carries at least 66 bits
    k = max(0, (2 * 66 - num.bit_length() + den.bit_length()) // 2 + 1)
    r = math.isqrt((num << (2 * k)) // den)
    return _div(r, 1 << k)


def _longest_squared(u: tuple[int, ...], v: tuple[int, ...]) -> int:
    """L², the squared length of the longest side, from the edges U and V (V − U is the third)."""
    ux, uy, uz = u
    vx, vy, vz = v
    wx, wy, wz = vx - ux, vy - uy, vz - uz
    return max(
        ux * ux + uy * uy + uz * uz, vx * vx + vy * vy + vz * vz, wx * wx + wy * wy + wz * wz
    )


def _thin(norm_squared: int, longest_squared: int, tn: int, td: int) -> bool:
    """Decide |N| <= tol · L² (the degenerate test) squared, in exact integers (tol = tn / td).

    ``norm_squared`` and ``longest_squared`` must be over the same denominator
    (|N|² over D⁴ and L² over D², as `_Integers` holds them).
    """
    # 2**(bits − 1) <= x < 2**bits: when the bit lengths alone put the left side above the
    # right one, the products are not needed (the usual case, a triangle far from thin)
    # (N = 0 is always degenerate: it has no lower bound to compare)
    bits = td.bit_length() - tn.bit_length() - longest_squared.bit_length()
    if norm_squared and norm_squared.bit_length() + 2 * bits >= 3:
        return False
    return norm_squared * td * td <= tn * tn * longest_squared * longest_squared


#: The verdict sentences, as ``str.format`` templates: the status line of every result
#: and, for a degenerate triangle, the reason in it. The site's JavaScript reads them from
#: the constants file the site build writes, so both say the same words.
VERDICTS: dict[str, str] = {
    "proper": "A proper triangle: the unit normal is defined.",
    "degenerate": "Degenerate: {reason} No unit normal exists.",
    "same_point": "A, B and C are the same point.",
    "coincide": "{names} coincide, so the triangle has no area.",
    "collinear": "A, B and C are collinear{where} (they lie on one line), so the area is zero.",
    "too_thin": (
        "it is too thin to trust (its height is at most the tolerance times its longest side)."
    ),
}


def _reason(coords: tuple[int, ...], zero_normal: bool, fmt: str = "exact") -> str:
    """One sentence saying why a triangle is degenerate (``coords`` over one denominator)."""
    a, b, c = coords[0:3], coords[3:6], coords[6:9]
    if a == b == c:
        return VERDICTS["same_point"]
    for p, q, names in ((a, b, "A and B"), (a, c, "A and C"), (b, c, "B and C")):
        if p == q:
            return VERDICTS["coincide"].format(names=names)
    if zero_normal:
        where = "" if fmt == "exact" else f" in {fmt} arithmetic"
        return VERDICTS["collinear"].format(where=where)
    return VERDICTS["too_thin"]


def triangle_normal(
    a: Iterable[Any],
    b: Iterable[Any],
    c: Iterable[Any],
    winding: Winding | str = "ABC",
    tol: float | int | Fraction | Decimal | str = DEFAULT_TOL,
    arithmetic: Arithmetic | str = "exact",
) -> TriangleNormal:
    """Compute the normal of the triangle ABC.

    Parameters
    ----------
    a, b, c : sequence of 3 real numbers
        The vertices (list, tuple, numpy array or another sized, ordered
        sequence). Each coordinate may be an int, float, Fraction, Decimal,
        numpy real scalar, sympy ``Integer``/``Rational``/``Float``, or a string
        holding a decimal (``"0.1"``, ``"−2.5e3"``) or a fraction (``"1/3"``),
        read exactly. The rules and size limits are
        [`trinormal.validation`][trinormal.validation]'s.
    winding : {"ABC", "ACB"} or Winding, default "ABC"
        ``"ABC"``: U = B − A, V = C − A. ``"ACB"``: U = C − A, V = B − A.
        N = U × V, so the two orders give opposite normals.
    tol : real, default 1e-12
        Degeneracy threshold, from 0 to 1: the triangle is degenerate when
        ``|N| <= tol · L²``, L its longest side (see
        [`trinormal.tolerances`][trinormal.tolerances]), whichever corner is A.
        ``0`` flags only exactly collinear or coincident points.
    arithmetic : {"exact", "float64", "float32"}, default "exact"
        ``"exact"`` computes with rationals and rounds once at the end.
        ``"float64"``/``"float32"`` evaluate the textbook formula step by step in
        that IEEE format, to show what rounding does.

    Returns
    -------
    TriangleNormal
        The edges, N, |N|, area, unit normal, plane and degeneracy verdict.

    Raises
    ------
    ValueError
        NaN or infinite coordinates, a vertex without exactly 3 coordinates, an
        unreadable string, a value beyond the size limit, an unknown winding or
        arithmetic, a tol outside 0 to 1; in ``float64``/``float32`` arithmetic,
        a value beyond that format's range ([`FloatRangeError`][trinormal.core.FloatRangeError]).
    TypeError
        ``None``, ``bool``, complex or other non-real coordinates; a vertex
        that is not a sized, ordered sequence (a set, dict, string or iterator).

    Examples
    --------
    The guide's worked example:

    >>> r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
    >>> r.u, r.v, r.normal
    ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    >>> r.magnitude, r.area, r.unit_normal
    (1.0, 0.5, (0.0, 0.0, 1.0))

    Reversing the order flips the normal:

    >>> triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="ACB").normal
    (0.0, 0.0, -1.0)

    The guide's comparison table, row by row:

    >>> triangle_normal((0, 0, 0), (2, 0, 0), (0, 3, 0)).format(4, trim=True)["normal"]
    '(0, 0, 6)'
    >>> r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    >>> r.normal, round(r.magnitude, 4), round(r.area, 4)
    ((0.0, -1.0, 1.0), 1.4142, 0.7071)
    >>> r = triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2))
    >>> r.degenerate, r.unit_normal, r.magnitude
    (True, None, 0.0)

    Decimal strings are exact, so these points are exactly collinear:

    >>> r = triangle_normal(("0", "0", "0"), ("0.1", "0.2", "0.3"), ("0.3", "0.6", "0.9"), tol=0)
    >>> r.degenerate, r.normal
    (True, (0.0, 0.0, 0.0))

    Bad input names the vertex and the axis:

    >>> triangle_normal((0, 0, 0), (1, float("nan"), 0), (0, 1, 0))
    Traceback (most recent call last):
    ...
    ValueError: B.y is NaN
    """
    # the common call is read by _plain_integers, anything else by validation (see the top)
    if (
        arithmetic == "exact"
        and type(tol) is float
        and tol == DEFAULT_TOL
        and isinstance(winding, str)
        and (winding == "ABC" or winding == "ACB")
        and type(a) in _SEQ
        and type(b) in _SEQ
        and type(c) in _SEQ
    ):
        plain = _plain_integers(a, b, c)
        if plain is not None:
            ints, D, pinv = plain
            w = Winding.ABC if winding == "ABC" else Winding.ACB
            points = (a, b, c) if pinv and type(a) is type(b) is type(c) is tuple else None
            return _exact(ints, D, w, _TN, _TD, DEFAULT_TOL, pinv, points)
    coords = check_vertex(a, "A") + check_vertex(b, "B") + check_vertex(c, "C")
    w = check_winding(winding)
    tn, td = check_tolerance(tol)
    if not isinstance(arithmetic, str) or arithmetic not in ARITHMETICS:
        raise ValueError(
            f"arithmetic must be one of {', '.join(ARITHMETICS)}; got {_show(arithmetic)}"
        )
    if arithmetic == "exact":
        ints, D = check_common(coords)
        return _exact(ints, D, w, tn, td, tn / td)
    from trinormal._float_arithmetic import floating  # the rarer path, read when used

    return floating(coords, w, tn, td, arithmetic)


_SEQ = (tuple, list)
_FLOAT_ONLY = {float}
_TWO53 = float(1 << 53)
_frexp = math.frexp
_pow2 = math.ldexp
_new_tuple = tuple.__new__  # builds a NamedTuple without its Python-level __new__
_new_object = object.__new__
_set = object.__setattr__
#: Plain floats with every nonzero coordinate in [2**-400, 2**400): U, V, N and |N|
#: then stay normal floats, so power-of-two scaling of them is exact.
_LOW, _HIGH = 2.0**-400, 2.0**400
_TN, _TD = DEFAULT_TOL.as_integer_ratio()


def _plain_integers(a: Any, b: Any, c: Any) -> tuple[tuple[int, ...], int, float] | None:
    """Read three plain vertices of floats and ints as ``(ints, D, pinv)``, or None.

    ``ints`` are the nine coordinates times ``D``; ``pinv`` is ``1 / D`` when
    ``float(i) * pinv`` is ``i / D`` correctly rounded (every nonzero coordinate a
    float in [2**-400, 2**400)), else ``0.0``. None (validation then reads the
    vertices) for anything else: other types or lengths, NaN, infinities, huge ints.
    """
    if len(a) != 3 or len(b) != 3 or len(c) != 3:
        return None
    vals = (*a, *b, *c)
    types = set(map(type, vals))
    pinv = 0.0
    try:
        if types == _FLOAT_ONLY:
            mags = list(map(abs, vals))
            hi = max(mags)
            lo = min([x for x in mags if x]) if hi else 1.0
            if lo >= _LOW and hi < _HIGH:
                # Every nonzero coordinate is m · 2**(e − 53) with e ≥ e(lo): multiplying
                # by 2**(53 − e(lo)) turns all nine into integers, exactly.
                shift = 53 - _frexp(lo)[1]
                if shift > 0:
                    p = _pow2(1.0, shift)
                    return tuple([int(x * p) for x in vals]), 1 << shift, 1.0 / p
                return tuple([int(x) for x in vals]), 1, 1.0
            # extreme exponents: one exponent for all nine, via frexp
            fe = list(map(_frexp, vals))
            emin = min([e for _, e in fe])
            ints = tuple([int(f * _TWO53) << (e - emin) for f, e in fe])
            if emin <= 53:
                return ints, 1 << (53 - emin), pinv
            return tuple([i << (emin - 53) for i in ints]), 1, pinv
        if _PLAIN.issuperset(types):
            if max(map(abs, vals)) >= _INT_LIMIT:
                return None  # validation refuses it, naming the coordinate
            ratios = [x.as_integer_ratio() for x in vals]
            D = max([d for _, d in ratios])
            top = D.bit_length()
            return tuple([n << (top - d.bit_length()) for n, d in ratios]), D, pinv
    except (ValueError, OverflowError):  # NaN or an infinity
        return None
    return None


def _exact(
    ints: tuple[int, ...],
    D: int,
    w: Winding,
    tn: int,
    td: int,
    tol: float,
    pinv: float = 0.0,
    points: tuple[Any, Any, Any] | None = None,
) -> TriangleNormal:
    """Compute the result exactly from the nine coordinates ``ints / D``: the one exact path.

    ``tol`` is ``tn / td`` as a float (the result's ``tol``). ``pinv`` is
    ``1 / D`` when `_plain_integers` found the scaled floats exact (else 0.0);
    ``points`` are the vertices when they are already tuples of floats.
    """
    ax, ay, az, bx, by, bz, cx, cy, cz = ints
    if w is Winding.ABC:
        ux, uy, uz, vx, vy, vz = bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az
    else:
        ux, uy, uz, vx, vy, vz = cx - ax, cy - ay, cz - az, bx - ax, by - ay, bz - az
    nx = uy * vz - uz * vy
    ny = uz * vx - ux * vz
    nz = ux * vy - uy * vx
    S = nx * nx + ny * ny + nz * nz
    s = _new_tuple(_Integers, (ints, D, (ux, uy, uz), (vx, vy, vz), (nx, ny, nz), S))
    degenerate = _thin(S, _longest_squared(s.u, s.v), tn, td)
    if points is None:
        f = _divide(ints, D)
        points = ((f[0], f[1], f[2]), (f[3], f[4], f[5]), (f[6], f[7], f[8]))
    k = r = 0
    if S:
        # r ≈ sqrt(S)·2**k with at least 66 correct bits, so each division below
        # is within 1 ulp of the exact value, at any scale
        k = max(0, 67 - (S.bit_length() >> 1))
        r = math.isqrt(S << (k << 1))
    if pinv:
        # float(int) rounds correctly and a power-of-two factor is exact while the
        # result stays a normal float, which _plain_integers's bounds guarantee; it
        # overflows only when the coordinates span more than about 2**±500 together.
        try:
            p2 = pinv * pinv
            u = (float(ux) * pinv, float(uy) * pinv, float(uz) * pinv)
            v = (float(vx) * pinv, float(vy) * pinv, float(vz) * pinv)
            normal = (float(nx) * p2, float(ny) * p2, float(nz) * p2)
            magnitude = r / (1 << k) * p2  # r / 2**k is correctly rounded; then exact
            area = magnitude * 0.5
        except OverflowError:
            pinv = 0.0
    if not pinv:
        D2 = D * D
        try:  # int / int is correctly rounded; it raises only beyond the float range
            u = (ux / D, uy / D, uz / D)
            v = (vx / D, vy / D, vz / D)
            normal = (nx / D2, ny / D2, nz / D2)
        except OverflowError:
            u, v, normal = _divide(s.u, D), _divide(s.v, D), _divide(s.normal, D2)
        magnitude, area = _div(r, D2 << k), _div(r, D2 << (k + 1))
    unit = plane = None
    reason = ""
    if degenerate:
        reason = _reason(ints, S == 0)
    else:
        unit = ((nx << k) / r, (ny << k) / r, (nz << k) / r)  # |unit| <= 1: no overflow
        offset = _div((nx * ax + ny * ay + nz * az) << k, r * D)
        plane = _new_tuple(Plane, (unit, offset))
    fields = (w, u, v, normal, magnitude, area, unit, degenerate, plane, reason)
    return _result(points[0], points[1], points[2], *fields, "exact", tol, s)


def _result(
    a: Vec3,
    b: Vec3,
    c: Vec3,
    winding: Winding,
    u: Vec3,
    v: Vec3,
    normal: Vec3,
    magnitude: float,
    area: float,
    unit_normal: Vec3 | None,
    degenerate: bool,
    plane: Plane | None,
    reason: str,
    arithmetic: str,
    tol: float,
    integers: _Integers,
) -> TriangleNormal:
    """Build a `TriangleNormal` from its fields in order: the one constructor every path uses.

    The frozen attributes are set once, as one dictionary (the dataclass's
    ``__init__`` refuses, and setting them field by field would be slower).
    """
    r = _new_object(TriangleNormal)
    _set(
        r,
        "__dict__",
        {
            "a": a,
            "b": b,
            "c": c,
            "winding": winding,
            "u": u,
            "v": v,
            "normal": normal,
            "magnitude": magnitude,
            "area": area,
            "unit_normal": unit_normal,
            "degenerate": degenerate,
            "plane": plane,
            "reason": reason,
            "arithmetic": arithmetic,
            "tol": tol,
            "_integers": integers,
        },
    )
    return r
