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
# two paths compute the same result. The common call (plain tuples or lists of floats and
# ints, the default tolerance, exact arithmetic) takes a fast path written out in one
# function; it hands anything else (other types, strings, a degenerate or out-of-range
# triangle) to the careful path, which validates every input and explains degenerate
# triangles. The choice depends only on what the inputs are, and both paths build their
# result with the one constructor, ``_result``.

from __future__ import annotations

import math
import struct
from collections.abc import Iterable
from dataclasses import dataclass, field
from decimal import Decimal
from fractions import Fraction
from functools import cached_property
from typing import Any, Literal, NamedTuple

from trinormal import fields
from trinormal.display import exact_literal, exact_literals, format_surd
from trinormal.fields import Surd
from trinormal.tolerances import DEFAULT_TOL
from trinormal.validation import (
    _LIMIT as _INT_LIMIT,  # the size limit: the fast path takes plain ints below it
)
from trinormal.validation import (
    AXES,
    VERTICES,
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
    the name the
    core has always used: the accepted types, the size limit, the return value
    and the errors are described there. ``name`` says how to call the value in
    an error message, such as ``"B.y"``.

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


# --------------------------------------------------------------------------- float formats

_F32_MAX = struct.unpack("f", b"\xff\xff\x7f\x7f")[0]


def _f32(x: float) -> float:
    """Round a float64 to the nearest float32 (ties to even), as a Python float.

    For +, −, ×, ÷ and √ of float32 operands, computing in float64 and rounding
    once to float32 gives the correctly rounded float32 result (53 ≥ 2·24 + 2),
    so float32 arithmetic needs no numpy here; the tests compare it with
    ``numpy.float32`` step by step.
    """
    try:
        return float(struct.unpack("f", struct.pack("f", x))[0])
    except OverflowError:
        return math.copysign(math.inf, x)


def _ratio_to_f32(n: int, d: int) -> float:
    """Correctly round the rational n/d to float32 (one rounding, no double rounding)."""
    if n == 0:
        return 0.0
    sign = -1.0 if n < 0 else 1.0
    n = abs(n)
    # exponent e with 2**e <= n/d < 2**(e+1)
    e = n.bit_length() - d.bit_length()
    if (n << -e if e < 0 else n) < (d << e if e > 0 else d):
        e -= 1
    if e > 127:
        return sign * math.inf
    q = max(e, -126) - 23  # quantum: ulp of float32 at this exponent (subnormals below 2**-126)
    num, den = (n, d << q) if q >= 0 else (n << -q, d)
    m, r = divmod(num, den)
    if 2 * r > den or (2 * r == den and m & 1):
        m += 1
    value = math.ldexp(float(m), q)
    return sign * (math.inf if value > _F32_MAX else value)


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
        True when ``|N| <= tol · |U| · |V|``: the sine of the angle between the
        edges is at most ``tol``. Coincident and collinear points are degenerate.
    plane : Plane or None
        ``(n, d)``: the plane ``n · x = d`` with ``n`` the unit normal and
        ``d = n · A``; ``None`` when degenerate.
    reason : str
        One sentence saying why the triangle is degenerate, or ``""``.
    arithmetic : str
        ``"exact"``, ``"float64"`` or ``"float32"``.
    tol : float
        The sine threshold used for `degenerate`.
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
        ``float64``/``float32`` arithmetic N is the computed floats.

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
        e = self.exact
        if self.arithmetic == "exact":
            normal = exact_literals(e.normal)
            squared = exact_literal(e.magnitude_squared)
            tail = f"normal={normal}, magnitude_squared={squared}"
        else:
            tail = f"normal={self.normal!r}"
        return (
            f"TriangleNormal(a={exact_literals(e.a)}, b={exact_literals(e.b)}, "
            f"c={exact_literals(e.c)}, winding={self.winding.value!r}, "
            f"arithmetic={self.arithmetic!r}, {tail}, degenerate={self.degenerate})"
        )

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
    def sine(self) -> float:
        """Sine of the angle between U and V: |N| / (|U| |V|), 0.0 if an edge is zero.

        Examples
        --------
        >>> round(triangle_normal((0, 0, 0), (1, 0, 0), (1, 1, 0)).sine, 12)
        0.707106781187
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
        spec = fields.FIELDS
        if self.arithmetic == "exact":
            values = self._exact_fields()
        else:
            values = {f.key: _float_surds(f.kind, getattr(self, f.key)) for f in spec}
        written: dict[Surd, str] = {}  # the unit normal's numbers recur in the plane

        def number(x: Surd) -> str:
            text = written.get(x)
            if text is None:
                text = written[x] = format_surd(x[0], x[1], x[2], precision, trim)
            return text

        out = {f.key: f.write(values[f.key], number) for f in spec}
        if self.degenerate:
            out["status"] = VERDICTS["degenerate"].format(reason=self.reason)
        else:
            out["status"] = VERDICTS["proper"]
        return out

    def _exact_fields(self) -> dict[str, Any]:
        """Compute the exact value of every output field, in the form its kind takes.

        Vectors are three `trinormal.fields.Surd`, scalars one, the plane
        ``(unit normal, offset)``; ``None`` where the value is undefined.
        """
        s = self._integers
        D, D2, S = s.denominator, s.denominator * s.denominator, s.norm_squared
        unit = plane = None
        if not self.degenerate:
            unit = tuple([(i < 0, i * i, S) for i in s.normal])
            dot = sum(i * j for i, j in zip(s.normal, s.coords[0:3], strict=True))
            plane = (unit, (dot < 0, dot * dot, S * D2))
        return {
            "u": tuple([_rational_surd(i, D) for i in s.u]),
            "v": tuple([_rational_surd(i, D) for i in s.v]),
            "normal": tuple([_rational_surd(i, D2) for i in s.normal]),
            "magnitude": (False, S, D2 * D2),
            "area": (False, S, 4 * D2 * D2),
            "unit_normal": unit,
            "plane": plane,
        }

    def to_dict(self) -> dict[str, Any]:
        """Every field as JSON-ready values: floats (non-finite as strings) and exact strings.

        The output fields (`trinormal.fields.FIELDS`) appear under their
        keys, between the inputs and the verdict.

        Examples
        --------
        >>> d = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).to_dict()
        >>> d["normal"], d["plane"], d["exact"]["area_squared"]
        ([0.0, 0.0, 1.0], {'normal': [0.0, 0.0, 1.0], 'offset': 0.0}, '1/4')
        """
        e = self.exact
        out: dict[str, Any] = {
            "a": _json_vector(self.a),
            "b": _json_vector(self.b),
            "c": _json_vector(self.c),
            "winding": self.winding.value,
            "arithmetic": self.arithmetic,
            "tol": self.tol,
        }
        for f in fields.FIELDS:
            out[f.key] = _json_value(f.kind, getattr(self, f.key))
        out["degenerate"] = self.degenerate
        out["reason"] = self.reason
        out["exact"] = {
            "a": _exact_strings(e.a),
            "b": _exact_strings(e.b),
            "c": _exact_strings(e.c),
            "u": _exact_strings(e.u),
            "v": _exact_strings(e.v),
            "normal": _exact_strings(e.normal),
            "magnitude_squared": str(e.magnitude_squared),
            "area_squared": str(e.magnitude_squared / 4),
        }
        return out


def _rational_surd(n: int, d: int) -> Surd:
    """Write the rational ``n / d`` as a `Surd`."""
    return (n < 0, n * n, d * d)


def _float_surds(kind: str, value: Any) -> Any:
    """Write a field's float value (by its kind) as exact `Surd`."""
    if value is None:
        return None
    if kind == "scalar":
        return _rational_surd(*value.as_integer_ratio())
    if kind == "vector":
        return tuple([_rational_surd(*x.as_integer_ratio()) for x in value])
    normal, offset = value
    return (_float_surds("vector", normal), _rational_surd(*offset.as_integer_ratio()))


def _json_number(x: float) -> float | str:
    return x if math.isfinite(x) else str(x)


def _json_vector(xs: Iterable[float]) -> list[float | str]:
    return [_json_number(x) for x in xs]


def _json_value(kind: str, value: Any) -> Any:
    """Write a field's float value (by its kind) as JSON-ready numbers; keep ``None``."""
    if value is None:
        return None
    if kind == "scalar":
        return _json_number(value)
    if kind == "vector":
        return _json_vector(value)
    normal, offset = value
    return {"normal": _json_vector(normal), "offset": _json_number(offset)}


def _exact_strings(xs: Iterable[Fraction]) -> list[str]:
    return [str(x) for x in xs]


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


def _exact_integers(ratios: list[tuple[int, int]], winding: Winding) -> _Integers:
    """Bring the nine ``(numerator, denominator)`` coordinates to one denominator; form U, V, N."""
    coords, D = check_common(ratios)
    ax, ay, az, bx, by, bz, cx, cy, cz = coords
    if winding is Winding.ABC:
        ux, uy, uz, vx, vy, vz = bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az
    else:
        ux, uy, uz, vx, vy, vz = cx - ax, cy - ay, cz - az, bx - ax, by - ay, bz - az
    nx = uy * vz - uz * vy
    ny = uz * vx - ux * vz
    nz = ux * vy - uy * vx
    return _Integers(
        coords, D, (ux, uy, uz), (vx, vy, vz), (nx, ny, nz), nx * nx + ny * ny + nz * nz
    )


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
        "the angle between the edges is too small to trust: "
        "the sine of it is at most the tolerance."
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
        Degeneracy threshold on the sine of the angle between U and V, from 0
        to 1 (see [`trinormal.tolerances`][trinormal.tolerances]). ``0`` flags only exactly
        collinear or coincident points.
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
    # The common call (plain tuples or lists of floats and ints, the default tolerance,
    # exact arithmetic) takes the fast path; it hands anything unusual to the careful one.
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
        r = _fast_exact(a, b, c, winding == "ABC")
        if r is not None:
            return r
    coords = check_vertex(a, "A") + check_vertex(b, "B") + check_vertex(c, "C")
    w = check_winding(winding)
    tn, td = check_tolerance(tol)
    if not isinstance(arithmetic, str) or arithmetic not in ARITHMETICS:
        raise ValueError(
            f"arithmetic must be one of {', '.join(ARITHMETICS)}; got {_show(arithmetic)}"
        )
    if arithmetic == "exact":
        return _exact(coords, w, tn, td)
    return _floating(coords, w, tn, td, arithmetic)


_SEQ = (tuple, list)
_FLOAT_ONLY = {float}
_TWO53 = float(1 << 53)
_frexp = math.frexp
_pow2 = math.ldexp
_new_tuple = tuple.__new__  # builds a NamedTuple without its Python-level __new__
_new_object = object.__new__
_set = object.__setattr__
#: The fast float path handles nonzero coordinates in [2**-400, 2**400): U, V, N and
#: |N| then stay normal floats, so power-of-two scaling of them is exact.
_LOW, _HIGH = 2.0**-400, 2.0**400
_TN, _TD = DEFAULT_TOL.as_integer_ratio()
_tn_sq, _td_sq = _TN * _TN, _TD * _TD


def _fast_exact(a: Any, b: Any, c: Any, abc: bool) -> TriangleNormal | None:
    """Compute the exact path for plain tuples/lists of floats and ints, with the default tol.

    Returns None (and the careful path takes over) for anything else: other
    types, NaN or infinities, wrong lengths, degenerate triangles, results
    beyond the float range. This is the same arithmetic as `_exact` (and
    repeats the cross product of `_exact_integers` on purpose), written out
    in one function because most calls look like this and each extra Python
    function call is a visible share of its few microseconds.
    """
    if len(a) != 3 or len(b) != 3 or len(c) != 3:
        return None
    vals = (*a, *b, *c)
    types = set(map(type, vals))
    floats = types == _FLOAT_ONLY and type(a) is type(b) is type(c) is tuple
    scaled = False  # True: U, V, N convert as float(int) * 2**-s, exactly rounded
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
                    ints = tuple([int(x * p) for x in vals])
                    D = 1 << shift
                    pinv = 1.0 / p
                else:
                    ints = tuple([int(x) for x in vals])
                    D, pinv = 1, 1.0
                scaled = True
            else:  # extreme exponents: one exponent for all nine, via frexp
                fe = list(map(_frexp, vals))
                emin = min([e for _, e in fe])
                ints = tuple([int(f * _TWO53) << (e - emin) for f, e in fe])
                if emin <= 53:
                    D = 1 << (53 - emin)
                else:
                    D = 1
                    ints = tuple([i << (emin - 53) for i in ints])
        elif _PLAIN.issuperset(types):
            if max(map(abs, vals)) >= _INT_LIMIT:
                return None  # the careful path refuses it, naming the coordinate
            ratios = [x.as_integer_ratio() for x in vals]
            D = max([d for _, d in ratios])
            top = D.bit_length()
            ints = tuple([n << (top - d.bit_length()) for n, d in ratios])
        else:
            return None
    except (ValueError, OverflowError):  # NaN or an infinity
        return None
    ax, ay, az, bx, by, bz, cx, cy, cz = ints
    if abc:
        ux, uy, uz, vx, vy, vz = bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az
    else:
        ux, uy, uz, vx, vy, vz = cx - ax, cy - ay, cz - az, bx - ax, by - ay, bz - az
    nx = uy * vz - uz * vy
    ny = uz * vx - ux * vz
    nz = ux * vy - uy * vx
    S = nx * nx + ny * ny + nz * nz
    uu = ux * ux + uy * uy + uz * uz
    vv = vx * vx + vy * vy + vz * vz
    # sine² = S / (|U|²|V|²) > 2**(bits(S) − 1 − bits(|U|²) − bits(|V|²)) when S > 0: when
    # that bound is far above tol² (about 2**-79.7), the exact comparison is not needed.
    if not S or (
        S.bit_length() - uu.bit_length() - vv.bit_length() < -75 and S * _td_sq <= _tn_sq * uu * vv
    ):
        return None  # degenerate: the careful path explains why
    k = max(0, 67 - (S.bit_length() >> 1))
    r = math.isqrt(S << (k << 1))
    try:
        if scaled:
            # float(int) rounds correctly and a power-of-two factor is exact while the
            # result stays a normal float, which the bounds _LOW and _HIGH guarantee.
            f = float
            p2 = pinv * pinv
            u = (f(ux) * pinv, f(uy) * pinv, f(uz) * pinv)
            v = (f(vx) * pinv, f(vy) * pinv, f(vz) * pinv)
            normal = (f(nx) * p2, f(ny) * p2, f(nz) * p2)
            magnitude = r / (1 << k) * p2  # r / 2**k is correctly rounded; then exact
        else:
            D2 = D * D
            u = (ux / D, uy / D, uz / D)
            v = (vx / D, vy / D, vz / D)
            normal = (nx / D2, ny / D2, nz / D2)
            magnitude = r / (D2 << k)
        unit = ((nx << k) / r, (ny << k) / r, (nz << k) / r)
        return _result(
            a if floats else (float(a[0]), float(a[1]), float(a[2])),
            b if floats else (float(b[0]), float(b[1]), float(b[2])),
            c if floats else (float(c[0]), float(c[1]), float(c[2])),
            Winding.ABC if abc else Winding.ACB,
            u,
            v,
            normal,
            magnitude,
            magnitude * 0.5 if scaled else r / (D * D << (k + 1)),
            unit,
            False,
            _new_tuple(Plane, (unit, ((nx * ax + ny * ay + nz * az) << k) / (r * D))),
            "",
            "exact",
            DEFAULT_TOL,
            _new_tuple(_Integers, (ints, D, (ux, uy, uz), (vx, vy, vz), (nx, ny, nz), S)),
        )
    except OverflowError:  # an int or a result beyond the float range
        return None


def _exact(coords: list[tuple[int, int]], w: Winding, tn: int, td: int) -> TriangleNormal:
    s = _exact_integers(coords, w)
    ints, D, (ux, uy, uz), (vx, vy, vz), (nx, ny, nz), S = s
    D2 = D * D
    # degenerate <=> |N| <= tol |U||V| <=> S td² <= tn² |U|²|V|²  (all exact integers)
    degenerate = S * td * td <= tn * tn * (ux * ux + uy * uy + uz * uz) * (
        vx * vx + vy * vy + vz * vz
    )
    floats = _divide(ints, D)
    try:  # int / int is correctly rounded; it raises only beyond the float range
        u = (ux / D, uy / D, uz / D)
        v = (vx / D, vy / D, vz / D)
        normal = (nx / D2, ny / D2, nz / D2)
    except OverflowError:
        u, v, normal = _divide(s.u, D), _divide(s.v, D), _divide(s.normal, D2)
    unit = plane = None
    reason = ""
    if S == 0:
        magnitude = area = 0.0
    else:
        # r ≈ sqrt(S)·2**k with at least 66 correct bits, so each division below
        # is within 1 ulp of the exact value, at any scale
        k = max(0, 67 - (S.bit_length() >> 1))
        r = math.isqrt(S << (k << 1))
        scale = D2 << k
        try:
            magnitude = r / scale
            area = r / (scale << 1)
        except OverflowError:
            magnitude, area = _div(r, scale), _div(r, scale << 1)
    if degenerate:
        reason = _reason(ints, S == 0)
    else:
        unit = ((nx << k) / r, (ny << k) / r, (nz << k) / r)  # |unit| <= 1: no overflow
        plane = Plane(unit, _div((nx * ints[0] + ny * ints[1] + nz * ints[2]) << k, r * D))
    return _result(
        (floats[0], floats[1], floats[2]),
        (floats[3], floats[4], floats[5]),
        (floats[6], floats[7], floats[8]),
        w,
        u,
        v,
        normal,
        magnitude,
        area,
        unit,
        degenerate,
        plane,
        reason,
        "exact",
        tn / td,
        s,
    )


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
    """Build a `TriangleNormal`: the one constructor every path uses.

    The arguments are the fields in order. The result is frozen: its attributes
    are set once, here, as one dictionary (the dataclass's field-by-field
    ``__init__`` would cost about 3 µs a call, a third of the whole calculation).
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


def _floating(
    coords: list[tuple[int, int]], w: Winding, tn: int, td: int, fmt: str
) -> TriangleNormal:
    """Evaluate the textbook formula with every operation rounded in float64 or float32."""
    if fmt == "float32":
        rnd = _f32
        vals = [_ratio_to_f32(n, d) for n, d in coords]
        limit = "±3.4e38"
    else:

        def rnd(x: float) -> float:
            return x

        vals = [_div(n, d) for n, d in coords]
        limit = "±1.8e308"
    for x, i in zip(vals, range(9), strict=True):
        if math.isinf(x):
            raise FloatRangeError(
                f"{VERTICES[i // 3]}.{AXES[i % 3]} is outside the {fmt} range ({limit}); "
                "use arithmetic='exact'"
            )
    A, B, C = vals[0:3], vals[3:6], vals[6:9]
    P, Q = (B, C) if w is Winding.ABC else (C, B)
    u = (rnd(P[0] - A[0]), rnd(P[1] - A[1]), rnd(P[2] - A[2]))
    v = (rnd(Q[0] - A[0]), rnd(Q[1] - A[1]), rnd(Q[2] - A[2]))
    n = (
        rnd(rnd(u[1] * v[2]) - rnd(u[2] * v[1])),
        rnd(rnd(u[2] * v[0]) - rnd(u[0] * v[2])),
        rnd(rnd(u[0] * v[1]) - rnd(u[1] * v[0])),
    )
    for q, name in ((u, "U"), (v, "V"), (n, "N")):
        if not all(math.isfinite(x) for x in q):
            raise FloatRangeError(
                f"{name} overflows the {fmt} range ({limit}) for these points; "
                "use arithmetic='exact'"
            )
    degenerate = _degenerate_floats(u, v, n, tn, td)
    # |N| in this format, scaled by a power of two so squares neither overflow nor underflow
    m = max(abs(x) for x in n)
    unit = plane = None
    reason = ""
    if m == 0.0:
        magnitude = 0.0
    else:
        e = math.frexp(m)[1]
        sx, sy, sz = (rnd(math.ldexp(x, -e)) for x in n)
        ss = rnd(rnd(rnd(sx * sx) + rnd(sy * sy)) + rnd(sz * sz))
        root = rnd(math.sqrt(ss))
        magnitude = rnd(_ldexp(root, e))
        if math.isinf(magnitude):
            raise FloatRangeError(
                f"|N| overflows the {fmt} range ({limit}) for these points; use arithmetic='exact'"
            )
    area = rnd(magnitude / 2)
    if degenerate:
        ints = check_common([x.as_integer_ratio() for x in vals])[0]
        nr = [x.as_integer_ratio() for x in n]
        reason = _reason(ints, all(p == 0 for p, _ in nr), fmt)
    else:
        unit = (rnd(sx / root), rnd(sy / root), rnd(sz / root))
        d = rnd(rnd(rnd(unit[0] * A[0]) + rnd(unit[1] * A[1])) + rnd(unit[2] * A[2]))
        if math.isinf(d):
            raise FloatRangeError(
                f"the plane's offset n̂ · A overflows the {fmt} range ({limit}) for these "
                "points; use arithmetic='exact'"
            )
        plane = Plane(unit, d)
    return _result(
        (A[0], A[1], A[2]),
        (B[0], B[1], B[2]),
        (C[0], C[1], C[2]),
        w,
        u,
        v,
        n,
        magnitude,
        area,
        unit,
        degenerate,
        plane,
        reason,
        fmt,
        tn / td,
        _exact_integers(coords, w),
    )


def _ldexp(x: float, e: int) -> float:
    try:
        return math.ldexp(x, e)
    except OverflowError:
        return math.copysign(math.inf, x)


def _degenerate_floats(u: Vec3, v: Vec3, n: Vec3, tn: int, td: int) -> bool:
    """Apply the sine test to float-computed U, V and N, evaluated exactly."""
    uv, D = check_common([x.as_integer_ratio() for x in (*u, *v)])
    ni, Dn = check_common([x.as_integer_ratio() for x in n])
    uu = sum(i * i for i in uv[0:3])
    vv = sum(i * i for i in uv[3:6])
    Sn = sum(i * i for i in ni)
    # |N| <= tol |U||V|  with N = ni / Dn and U, V = uv / D
    return Sn * td * td * D**4 <= tn * tn * uu * vv * Dn * Dn
