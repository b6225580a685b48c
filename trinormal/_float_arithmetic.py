"""The textbook formula with every operation rounded in float64 or float32.

``triangle_normal(..., arithmetic="float64")`` and ``"float32"`` come here: the
vertices are rounded to the format, then U, V, N, |N|, the unit normal and the
plane are computed step by step as code in that format would, to show what
rounding does. The verdict applies the rule of
[`trinormal.tolerances`][trinormal.tolerances] to the N this format computed,
evaluated exactly. The standard library is all this module needs.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable

from trinormal.core import (
    FloatRangeError,
    Plane,
    TriangleNormal,
    Vec3,
    _div,
    _exact,
    _longest_squared,
    _reason,
    _result,
    _thin,
)
from trinormal.validation import AXES, VERTICES, Winding, check_common

__all__ = ["floating"]

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


def floating(
    coords: list[tuple[int, int]], w: Winding, tn: int, td: int, fmt: str
) -> TriangleNormal:
    """Evaluate the textbook formula with every operation rounded in float64 or float32."""
    rnd: Callable[[float], float]
    if fmt == "float32":
        rnd = _f32
        vals = [_ratio_to_f32(n, d) for n, d in coords]
        limit = "±3.4e38"
    else:
        rnd = float  # a float64 operation is already rounded
        vals = [_div(n, d) for n, d in coords]
        limit = "±1.8e308"

    def overflow(what: str) -> FloatRangeError:
        return FloatRangeError(
            f"{what} overflows the {fmt} range ({limit}) for these points; use arithmetic='exact'"
        )

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
            raise overflow(name)
    ints, D = check_common([x.as_integer_ratio() for x in vals])  # the vertices as held
    degenerate = _degenerate_floats(ints, D, n, tn, td)
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
            raise overflow("|N|")
    area = rnd(magnitude / 2)
    if degenerate:
        reason = _reason(ints, m == 0.0, fmt)
    else:
        unit = (rnd(sx / root), rnd(sy / root), rnd(sz / root))
        d = rnd(rnd(rnd(unit[0] * A[0]) + rnd(unit[1] * A[1])) + rnd(unit[2] * A[2]))
        if math.isinf(d):
            raise overflow("the plane's offset n̂ · A")
        plane = Plane(unit, d)
    exact = _exact(*check_common(coords), w, tn, td, tn / td)._integers
    a, b, c = (A[0], A[1], A[2]), (B[0], B[1], B[2]), (C[0], C[1], C[2])
    fields = (w, u, v, n, magnitude, area, unit, degenerate, plane, reason)
    return _result(a, b, c, *fields, fmt, tn / td, exact)


def _ldexp(x: float, e: int) -> float:
    try:
        return math.ldexp(x, e)
    except OverflowError:
        return math.copysign(math.inf, x)


def _degenerate_floats(ints: tuple[int, ...], D: int, n: Vec3, tn: int, td: int) -> bool:
    """Apply the rule |N| <= tol · L² to the N this format computed, evaluated exactly.

    L² comes from the vertices as this format holds them (``ints / D``, exact
    differences); only N carries the format's rounding.
    """
    a, b, c = ints[0:3], ints[3:6], ints[6:9]
    u = tuple([q - p for p, q in zip(a, b, strict=True)])
    v = tuple([q - p for p, q in zip(a, c, strict=True)])
    ni, Dn = check_common([x.as_integer_ratio() for x in n])
    # |N|² = Sn / Dn² and L⁴ = L2² / D⁴: compare both times Dn² D⁴
    return _thin(sum(i * i for i in ni) * D**4, _longest_squared(u, v) * Dn, tn, td)
