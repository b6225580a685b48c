"""triangle_normal: the guide's numbers, exact reading, correct rounding, bad input."""

from __future__ import annotations

import copy
import dataclasses
import math
import pickle
import random
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
from reference import exact_normal, sqrt_decimal, ulps

from trinormal import DEFAULT_TOL, Plane, TriangleNormal, Winding, triangle_normal
from trinormal.tolerances import MAGNITUDE_ULPS, UNIT_NORMAL_ULPS

# --------------------------------------------------------------------------- the guide


def test_worked_example():
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
    assert r.u == (1.0, 0.0, 0.0)
    assert r.v == (0.0, 1.0, 0.0)
    assert r.normal == (0.0, 0.0, 1.0)
    assert (r.magnitude, r.area) == (1.0, 0.5)
    assert r.unit_normal == (0.0, 0.0, 1.0)
    assert r.plane == Plane((0.0, 0.0, 1.0), 0.0)
    assert not r.degenerate
    flipped = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="ACB")
    assert flipped.normal == (0.0, 0.0, -1.0)
    assert flipped.unit_normal == (0.0, 0.0, -1.0)


@pytest.mark.parametrize(
    ("a", "b", "c", "normal", "magnitude", "area", "unit"),
    [
        ((0, 0, 0), (1, 0, 0), (0, 1, 0), "(0, 0, 1)", "1", "0.5", "(0, 0, 1)"),
        ((0, 0, 0), (2, 0, 0), (0, 3, 0), "(0, 0, 6)", "6", "3", "(0, 0, 1)"),
        ((1, 1, 1), (2, 1, 1), (1, 2, 2), "(0, -1, 1)", "1.4142", "0.7071", "(0, -0.7071, 0.7071)"),
        ((0, 0, 0), (1, 1, 1), (2, 2, 2), "(0, 0, 0)", "0", "0", "undefined"),
    ],
)
def test_comparison_table_rows(a, b, c, normal, magnitude, area, unit):
    """The guide's table, as it prints it (4 places, trailing zeros dropped)."""
    f = triangle_normal(a, b, c).format(4, trim=True)
    assert (f["normal"], f["magnitude"], f["area"], f["unit_normal"]) == (
        normal,
        magnitude,
        area,
        unit,
    )


def test_result_is_frozen_dataclass():
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
    assert isinstance(r, TriangleNormal)
    with pytest.raises(AttributeError):
        r.area = 2.0  # type: ignore[misc]
    again = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
    assert r == again


def test_results_are_returned_not_built():
    """TriangleNormal is for type hints and isinstance: building one by hand is refused."""
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
    with pytest.raises(TypeError, match=r"returned by triangle_normal\(a, b, c\)"):
        TriangleNormal(*(getattr(r, f.name) for f in dataclasses.fields(r)))
    with pytest.raises(TypeError, match="not built directly"):
        dataclasses.replace(r, area=2.0)
    # copies and pickles keep every method working
    for same in (copy.copy(r), copy.deepcopy(r), pickle.loads(pickle.dumps(r))):
        assert same == r and same.exact == r.exact and same.format() == r.format()
        assert same.to_dict() == r.to_dict() and same.sine == r.sine


@pytest.mark.parametrize(
    ("tol", "fast"),
    [
        (DEFAULT_TOL, True),
        (float("1e-12"), True),  # equal to the default, another object: the same path
        (1e-12 * (1 + 2**-52), False),
        (Fraction(DEFAULT_TOL), False),
        ("1e-12", False),  # the decimal one trillionth, not the float
        (0.0, False),
    ],
)
def test_the_fast_path_is_chosen_by_what_the_inputs_are(monkeypatch, tol, fast):
    """Plain floats and the default tolerance's value are read quickly; the result is the same."""
    from trinormal import core

    calls = []
    real = core._plain_integers

    def spy(*args):
        calls.append(args)
        return real(*args)

    pts = ((0.1, 0.2, 0.3), (1.5, -2.0, 0.25), (-3.0, 0.5, 2.0))
    careful = triangle_normal(*[[Fraction(x) for x in p] for p in pts], tol=tol)  # never fast
    monkeypatch.setattr(core, "_plain_integers", spy)
    r = triangle_normal(*pts, tol=tol)
    assert bool(calls) is fast
    assert r == careful and r.exact == careful.exact and r.tol == careful.tol
    assert r.format(15) == careful.format(15) and r.to_dict() == careful.to_dict()


# --------------------------------------------------------------------------- exact reading


def test_decimal_strings_are_exact():
    pts = (("0", "0", "0"), ("0.1", "0.2", "0.3"), ("0.3", "0.6", "0.9"))
    r = triangle_normal(*pts, tol=0)
    assert r.degenerate and r.normal == (0.0, 0.0, 0.0)
    assert r.exact.u == (Fraction(1, 10), Fraction(1, 5), Fraction(3, 10))
    assert "collinear" in r.reason
    # The same points as binary floats are not exactly collinear...
    floats = triangle_normal((0, 0, 0), (0.1, 0.2, 0.3), (0.3, 0.6, 0.9), tol=0)
    assert floats.normal != (0.0, 0.0, 0.0)
    assert not floats.degenerate
    # ... but the default tolerance sees that the angle is hopelessly small.
    assert triangle_normal((0, 0, 0), (0.1, 0.2, 0.3), (0.3, 0.6, 0.9)).degenerate


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("0.1", Fraction(1, 10)),
        ("-2.5e3", Fraction(-2500)),
        ("1/3", Fraction(1, 3)),
        (" -7/-14 ", Fraction(1, 2)),
        ("+.5", Fraction(1, 2)),
        ("3.", Fraction(3)),
        ("1E-3", Fraction(1, 1000)),
    ],
)
def test_string_coordinates(text, value):
    r = triangle_normal((text, 0, 0), (0, 0, 0), (0, 0, 0), tol=0)
    assert r.exact.a[0] == value


def test_every_numeric_type_is_read_exactly():
    third = Fraction(1, 3)
    kinds = [
        (1, Fraction(1)),
        (0.5, Fraction(1, 2)),
        (third, third),
        (Decimal("0.1"), Fraction(1, 10)),
        (np.float32(0.1), Fraction(*np.float32(0.1).as_integer_ratio())),
        (np.float64(2.5), Fraction(5, 2)),
        (np.int64(-7), Fraction(-7)),
        ("1/3", third),
    ]
    for x, expected in kinds:
        r = triangle_normal((0, 0, 0), (x, 0, 0), (0, 1, 0))
        assert r.exact.b[0] == expected, x
        assert r.exact.normal == (0, 0, expected)


def test_numpy_arrays_as_vertices():
    a, b, c = np.array([0.0, 0, 0]), np.array([1.0, 0, 0]), np.array([0.0, 1, 0])
    assert triangle_normal(a, b, c).normal == (0.0, 0.0, 1.0)
    assert triangle_normal([0, 0, 0], (1, 0, 0), np.array([0, 1, 0])).unit_normal == (0.0, 0.0, 1.0)


# --------------------------------------------------------------------------- rounding and accuracy


def _random_float(rng: random.Random, lo: int, hi: int) -> float:
    return math.ldexp(rng.uniform(-1, 1), rng.randint(lo, hi))


@pytest.mark.parametrize("scale", [(-1000, -990), (-60, 60), (990, 1000), (-300, 300)])
def test_correct_rounding_and_ulp_bounds(scale):
    rng = random.Random(hash(scale) & 0xFFFF)
    worst_unit = worst_mag = 0.0
    for _ in range(300):
        pts = [[_random_float(rng, *scale) for _ in range(3)] for _ in range(3)]
        r = triangle_normal(*pts)
        u, v, n = exact_normal(*pts)
        assert r.u == tuple(float(x) for x in u)  # float(Fraction) rounds correctly
        assert r.v == tuple(float(x) for x in v)
        assert r.normal == tuple(_float_or_inf(x) for x in n)
        s = sum(x * x for x in n)
        if s == 0:
            continue
        mag = sqrt_decimal(s)
        if math.isfinite(r.magnitude) and r.magnitude != 0:
            worst_mag = max(worst_mag, ulps(r.magnitude, mag), ulps(r.area, mag / 2))
        if not r.degenerate:
            for got, ni in zip(r.unit_normal, n, strict=True):
                ref = (Decimal(ni.numerator) / Decimal(ni.denominator)) / mag
                worst_unit = max(worst_unit, ulps(got, ref))
    assert worst_mag <= MAGNITUDE_ULPS
    assert worst_unit <= UNIT_NORMAL_ULPS


def _float_or_inf(q: Fraction) -> float:
    try:
        return float(q)
    except OverflowError:
        return math.inf if q > 0 else -math.inf


@pytest.mark.parametrize("s", [1e-300, 1e-200, 1.0, 1e200, 1e300])
def test_extreme_scales_keep_their_normal(s):
    r = triangle_normal((0, 0, 0), (s, 0, 0), (0, s, 0))
    assert not r.degenerate
    assert r.unit_normal == (0.0, 0.0, 1.0)
    r = triangle_normal((s, s, s), (2 * s, s, s), (s, 2 * s, 2 * s))
    assert not r.degenerate
    root_half = math.sqrt(0.5)
    assert r.unit_normal is not None
    assert abs(r.unit_normal[1] + root_half) <= 2 * math.ulp(root_half)
    assert abs(r.unit_normal[2] - root_half) <= 2 * math.ulp(root_half)


def test_out_of_range_values_become_inf_or_zero_but_unit_normal_survives():
    big = triangle_normal((0, 0, 0), (1e300, 0, 0), (0, 1e300, 0))
    assert big.normal == (0.0, 0.0, math.inf)
    assert big.magnitude == math.inf
    assert big.unit_normal == (0.0, 0.0, 1.0)
    assert big.format()["normal"] == "(0.0000, 0.0000, 1.0000e+600)"
    tiny = triangle_normal((0, 0, 0), (1e-300, 0, 0), (0, 1e-300, 0))
    assert tiny.normal == (0.0, 0.0, 0.0)
    assert tiny.magnitude == 0.0 and not tiny.degenerate
    assert tiny.unit_normal == (0.0, 0.0, 1.0)
    assert tiny.format()["magnitude"] == "1.0000e-600"


def test_plane_offset():
    r = triangle_normal((0, 0, 5), (1, 0, 5), (0, 1, 5))
    assert r.plane == Plane((0.0, 0.0, 1.0), 5.0)
    r = triangle_normal((1, 2, 3), (4, 6, 3), (1, 2, 8))
    assert r.plane is not None and r.unit_normal is not None
    n, d = r.plane
    for p in (r.a, r.b, r.c):
        assert math.isclose(sum(x * y for x, y in zip(n, p, strict=True)), d, abs_tol=1e-14)


# --------------------------------------------------------------------------- winding


@pytest.mark.parametrize("seed", range(5))
def test_acb_flips_the_normal_exactly(seed):
    rng = random.Random(seed)
    pts = [[rng.uniform(-1e3, 1e3) for _ in range(3)] for _ in range(3)]
    r = triangle_normal(*pts)
    f = triangle_normal(*pts, winding="ACB")
    assert f.normal == tuple(-x for x in r.normal)
    assert f.unit_normal == tuple(-x for x in r.unit_normal)
    assert f.magnitude == r.magnitude and f.area == r.area
    assert triangle_normal(*pts, winding=Winding.ACB) == f
    assert f.winding is Winding.ACB


def test_bad_winding_lists_allowed_values():
    with pytest.raises(ValueError, match="'ABC' or 'ACB'"):
        triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="CBA")
    with pytest.raises(ValueError, match="'ABC' or 'ACB'"):
        triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), winding=None)  # type: ignore[arg-type]


# --------------------------------------------------------------------------- degeneracy


def test_coincident_points():
    r = triangle_normal((1, 2, 3), (1, 2, 3), (0, 1, 0), tol=0)
    assert r.degenerate and r.unit_normal is None and r.plane is None
    assert "A and B coincide" in r.reason
    r = triangle_normal((1, 2, 3), (1, 2, 3), (1, 2, 3))
    assert "same point" in r.reason
    assert r.format()["unit_normal"] == "undefined"
    assert "Degenerate" in r.format()["status"]


def test_degeneracy_is_thinness_against_the_longest_side_and_scale_invariant():
    # |N| / L² for A = 0, B = (1, 0, 0), C = (1, t, 0) is t / (1 + t²)
    for s in (1e-150, 1.0, 1e150):
        thin = triangle_normal((0, 0, 0), (s, 0, 0), (s, s * 1e-13, 0))
        wide = triangle_normal((0, 0, 0), (s, 0, 0), (s, s * 1e-11, 0))
        assert thin.degenerate and not wide.degenerate
        assert thin.magnitude > 0 or s < 1e-100
    # tol is the threshold on |N| / L²: decided exactly on either side of it
    t = Fraction(3, 25)  # |N| = 3, the longest side is C − A = (4, 3, 0), L² = 25
    r_at = triangle_normal((0, 0, 0), (1, 0, 0), (4, 3, 0), tol=t)
    r_above = triangle_normal((0, 0, 0), (1, 0, 0), (4, 3, 0), tol=t - Fraction(1, 10**30))
    assert r_at.degenerate and not r_above.degenerate
    assert math.isclose(r_at.thickness, 0.12) and math.isclose(r_at.sine, 0.6)


def test_degenerate_result_still_reports_edges_and_area():
    r = triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2))
    assert r.u == (1.0, 1.0, 1.0) and r.v == (2.0, 2.0, 2.0)
    assert r.normal == (0.0, 0.0, 0.0) and r.magnitude == 0.0 and r.area == 0.0
    assert r.tol == DEFAULT_TOL


# --------------------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    ("b", "error", "message"),
    [
        ((1, float("nan"), 0), ValueError, "B.y is NaN"),
        ((1, 0, float("inf")), ValueError, "B.z is infinite"),
        ((float("-inf"), 0, 0), ValueError, "B.x is infinite"),
        ((1, "nan", 0), ValueError, "B.y is NaN"),
        ((1, 0, "-Infinity"), ValueError, "B.z is infinite"),
        ((1, "", 0), ValueError, "B.y is empty"),
        ((1, "abc", 0), ValueError, "B.y = 'abc' is not a number"),
        (("1/0", 0, 0), ValueError, "B.x = '1/0' divides by zero"),
        (("1e99999", 0, 0), ValueError, "B.x = '1e99999' is too large"),
        ((1, 0), ValueError, "B has 2 coordinates, expected 3"),
        ((1, 0, 0, 0), ValueError, "B has 4 coordinates, expected 3"),
        ((1, None, 0), TypeError, "B.y is None"),
        ((True, 0, 0), TypeError, "B.x is True"),
        ((1, 0, 1j), TypeError, "B.z is complex"),
        ((1, np.bool_(True), 0), TypeError, "B.y is"),
        ((1, Decimal("NaN"), 0), ValueError, "B.y is NaN"),
        ((1, np.float64("nan"), 0), ValueError, "B.y is NaN"),
        ((1, np.float32("inf"), 0), ValueError, "B.y is infinite"),
        ((1, object(), 0), TypeError, "B.y is object"),
        (None, TypeError, "B must be 3 coordinates"),
        ("1,2,3", TypeError, "B must be 3 coordinates"),
        (5, TypeError, "B must be 3 coordinates"),
    ],
)
def test_bad_input_names_vertex_and_axis(b, error, message):
    with pytest.raises(error) as info:
        triangle_normal((0, 0, 0), b, (0, 1, 0))
    assert message in str(info.value)


def test_bad_options():
    ok = ((0, 0, 0), (1, 0, 0), (0, 1, 0))
    with pytest.raises(ValueError, match="exact, float64, float32"):
        triangle_normal(*ok, arithmetic="float16")
    with pytest.raises(ValueError, match="tol must be >= 0"):
        triangle_normal(*ok, tol=-1e-3)
    with pytest.raises(ValueError, match="tol is NaN"):
        triangle_normal(*ok, tol=float("nan"))


# --------------------------------------------------------------------------- float formats


def _textbook(a, b, c, rnd):
    """The guide's formula with every operation rounded by ``rnd`` (a reference)."""
    A, B, C = ([rnd(x) for x in p] for p in (a, b, c))
    u = [rnd(B[i] - A[i]) for i in range(3)]
    v = [rnd(C[i] - A[i]) for i in range(3)]
    n = [
        rnd(rnd(u[1] * v[2]) - rnd(u[2] * v[1])),
        rnd(rnd(u[2] * v[0]) - rnd(u[0] * v[2])),
        rnd(rnd(u[0] * v[1]) - rnd(u[1] * v[0])),
    ]
    return u, v, n


@pytest.mark.parametrize("seed", range(20))
def test_float64_and_float32_follow_the_textbook_formula(seed):
    rng = random.Random(seed)
    pts = [[rng.uniform(-100, 100) * 10 ** rng.randint(-6, 6) for _ in range(3)] for _ in range(3)]
    r64 = triangle_normal(*pts, arithmetic="float64")
    u, v, n = _textbook(*pts, float)
    assert (list(r64.u), list(r64.v), list(r64.normal)) == (u, v, n)
    assert r64.arithmetic == "float64"
    r32 = triangle_normal(*pts, arithmetic="float32")
    u, v, n = _textbook(*pts, np.float32)
    assert list(r32.u) == [float(x) for x in u]
    assert list(r32.v) == [float(x) for x in v]
    assert list(r32.normal) == [float(x) for x in n]
    for r in (r32, r64):
        assert r.unit_normal is not None
        assert math.isclose(math.hypot(*r.unit_normal), 1.0, rel_tol=1e-6)
        assert r.exact.normal == triangle_normal(*pts).exact.normal


def test_float32_loses_a_thin_triangle_that_exact_keeps():
    pts = ((0, 0, 0), (1, 1, 1), (2, 2, 2 + 1e-9))  # 2 + 1e-9 rounds to 2 in float32
    assert not triangle_normal(*pts, tol=0).degenerate
    r32 = triangle_normal(*pts, arithmetic="float32", tol=0)
    assert r32.degenerate and r32.normal == (0.0, 0.0, 0.0)
    assert "collinear in float32 arithmetic" in r32.reason


def test_float_formats_scale_before_normalising():
    # float32 cannot hold N = 1e-60: it underflows to zero, and the triangle is lost
    r = triangle_normal((0, 0, 0), (1e-30, 0, 0), (0, 1e-30, 0), arithmetic="float32")
    assert r.normal == (0.0, 0.0, 0.0) and r.degenerate
    r = triangle_normal((0, 0, 0), (1e-20, 0, 0), (0, 1e-20, 0), arithmetic="float32")
    assert r.unit_normal == (0.0, 0.0, 1.0)  # N = 1e-40 is subnormal; |N|² would underflow
    r = triangle_normal((0, 0, 0), (1e-160, 0, 0), (0, 1e-160, 0), arithmetic="float64")
    assert r.unit_normal == (0.0, 0.0, 1.0)  # |N|² = 1e-640 would underflow


def test_float_overflow_is_an_error_not_inf():
    with pytest.raises(OverflowError, match="float32"):
        triangle_normal((0, 0, 0), (1e20, 0, 0), (0, 1e20, 0), arithmetic="float32")
    with pytest.raises(OverflowError, match=r"B\.x is outside the float32 range"):
        triangle_normal((0, 0, 0), (1e39, 0, 0), (0, 1, 0), arithmetic="float32")


def test_fast_path_agrees_with_the_careful_path():
    """Plain float tuples take a shortcut; every field must match the general path."""
    rng = random.Random(9)

    def coordinate() -> float:
        k = rng.random()
        if k < 0.1:
            return rng.choice([0.0, -0.0])
        if k < 0.5:
            return math.ldexp(rng.uniform(-1, 1), rng.randint(-1074, 1023))
        return rng.uniform(-3, 3)

    def moderate() -> float:  # around the fast path's range limits 2**±400
        if rng.random() < 0.1:
            return 0.0
        return math.ldexp(rng.uniform(-1, 1), rng.randint(-420, 420) if rng.random() < 0.3 else 3)

    for i in range(4000):
        make = coordinate if i % 2 else moderate
        pts = [tuple(make() for _ in range(3)) for _ in range(3)]
        winding = rng.choice(["ABC", "ACB"])
        fast = triangle_normal(*pts, winding=winding)
        # numpy arrays never take the shortcut: the general path answers
        careful = triangle_normal(*(np.array(p) for p in pts), winding=winding)
        assert fast == careful
        assert fast.exact == careful.exact
        assert fast.format(6) == careful.format(6)


def test_fast_path_degeneracy_verdict_at_the_tolerance():
    """|N| / L² from about 2e-14 to 1e-11, at many scales: plain floats, same verdict as numpy's."""
    rng = random.Random(12)
    flips = 0
    for _ in range(2000):
        t = 10 ** rng.uniform(-13, -11)
        s = math.ldexp(1.0, rng.randint(-300, 300))
        a = (rng.uniform(-1, 1) * s, rng.uniform(-1, 1) * s, 0.0)
        b = (a[0] + s, a[1], 0.0)
        c = (a[0] + s * rng.uniform(0.5, 2), a[1] + s * t, s * t * rng.uniform(-1, 1))
        fast = triangle_normal(a, b, c)
        careful = triangle_normal(np.array(a), np.array(b), np.array(c))
        assert fast.degenerate == careful.degenerate
        assert fast == careful
        flips += fast.degenerate
    assert 0 < flips < 2000  # both verdicts occur


# --------------------------------------------------------------------------- hard inputs


def test_float_range_errors_are_value_errors_naming_what_overflowed():
    from trinormal.core import FloatRangeError

    # N's components fit in float64 but |N| = 2.1e308 does not
    pts = ((0, 0, 0), (1e154, 1e154, 0), (0, 0, 1.5e154))
    with pytest.raises(FloatRangeError, match=r"^\|N\| overflows the float64 range") as info:
        triangle_normal(*pts, arithmetic="float64")
    assert isinstance(info.value, ValueError) and isinstance(info.value, OverflowError)
    r = triangle_normal(*pts)  # the exact path has no range to leave
    assert r.magnitude == math.inf and r.format(2)["magnitude"] == "2.12e+308"
    with pytest.raises(ValueError, match=r"B\.x is outside the float32 range"):
        triangle_normal((0, 0, 0), (1e39, 0, 0), (0, 1, 0), arithmetic="float32")


@pytest.mark.parametrize("arithmetic", ["float64", "float32"])
def test_float_results_always_format(arithmetic):
    rng = random.Random(31)
    for _ in range(300):
        e = rng.randint(-1100, 1024) if arithmetic == "float64" else rng.randint(-160, 128)
        pts = [[math.ldexp(rng.uniform(-1, 1), e) for _ in range(3)] for _ in range(3)]
        try:
            r = triangle_normal(*pts, arithmetic=arithmetic)
        except ValueError as err:
            assert "range" in str(err)
            continue
        assert all(math.isfinite(x) for x in (*r.u, *r.v, *r.normal, r.magnitude, r.area))
        r.format(15)
        r.to_dict()


def test_winding_and_arithmetic_of_the_wrong_type_are_value_errors():
    ok = ((0, 0, 0), (1, 0, 0), (0, 1, 0))
    with pytest.raises(ValueError, match="winding must be 'ABC' or 'ACB'"):
        triangle_normal(*ok, winding=np.array(["ABC", "ACB"]))  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="arithmetic must be one of exact, float64, float32"):
        triangle_normal(*ok, arithmetic=None)  # type: ignore[arg-type]


def test_plain_ints_beyond_the_limit_leave_the_fast_path_and_are_refused():
    with pytest.raises(ValueError, match=r"^C\.z is too large a number"):
        triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 10**400))
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 10**399))
    assert r.exact.c[2] == 10**399


def test_the_core_imports_only_the_standard_library():
    code = (
        "import sys, trinormal, trinormal.cli, trinormal.validation;"
        "trinormal.cli.main(['0,0,0', '1,0,0', '0,1,0', '--steps']);"
        "bad = {'numpy', 'sympy', 'matplotlib', 'ipywidgets'} & set(sys.modules);"
        "sys.exit(1 if bad else 0)"
    )
    import subprocess
    import sys

    p = subprocess.run([sys.executable, "-c", code], capture_output=True, timeout=60)
    assert p.returncode == 0, p.stderr


# --------------------------------------------------------------------------- order of the corners

ORDERS = [(0, 1, 2), (1, 2, 0), (2, 0, 1)]


def _every_order(pts, **kwargs):
    return [
        triangle_normal(*(pts[i] for i in order), winding=winding, **kwargs)
        for order in ORDERS
        for winding in ("ABC", "ACB")
    ]


@pytest.mark.parametrize(
    ("pts", "degenerate"),
    [
        # a right angle at A, 1e-13 high: thin compared with its longest side, however listed
        (((0, 0, 0), (1, 0, 0), (0, 1e-13, 0)), True),
        (((0, 0, 0), (1, 0, 0), (0, 1e-11, 0)), False),
        # C within 1e-13 of A: nearly coincident points
        (((0, 0, 0), (1, 0, 0), (1e-13, 1e-13, 0)), True),
        (((0, 0, 0), (1, 0, 0), (1e-13, 0, 1e-13)), True),
        (((5, 5, 5), (5.5, 5, 5), (5, 5, 5 + 2**-46)), True),
        # a needle: the third corner far out along AB, just off the line
        (((0, 0, 0), (1, 0, 0), (1000, 1e-8, 0)), True),
        (((0, 0, 0), (1, 0, 0), (1000, 1e-4, 0)), False),
        (((0, 0, 0), (1, 0, 0), (0, 1, 0)), False),
    ],
)
def test_one_verdict_whatever_the_order_of_the_corners(pts, degenerate):
    for arithmetic in ("exact", "float64", "float32"):
        results = _every_order(pts, arithmetic=arithmetic)
        assert [r.degenerate for r in results] == [degenerate] * 6, arithmetic
    exact = _every_order(pts)
    assert len({r.thickness for r in exact}) == 1
    assert len({r.reason for r in exact}) == 1


def test_the_issue_example_and_the_sine_at_a():
    """The sine at A is 1 for this needle, which is still degenerate: the rule is |N| <= tol · L²."""
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1e-13, 0))
    assert r.degenerate and r.sine == 1.0 and r.thickness == 1e-13
    assert "too thin" in r.reason and "longest side" in r.reason
    again = triangle_normal((1, 0, 0), (0, 1e-13, 0), (0, 0, 0))
    assert again.degenerate and again.sine < 1e-12


def test_thickness_is_the_height_over_the_longest_side():
    r = triangle_normal((0, 0, 0), (4, 0, 0), (1, 1, 0))  # longest side 4, height 1
    assert r.thickness == 0.25
    equilateral = triangle_normal((1, 0, 0), (0, 1, 0), (0, 0, 1))
    assert math.isclose(equilateral.thickness, math.sqrt(3) / 2)
    assert triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2)).thickness == 0.0
    assert triangle_normal((1, 1, 1), (1, 1, 1), (1, 1, 1)).thickness == 0.0


def test_float_formats_judge_the_n_they_computed_against_the_longest_side():
    # exactly |N| / L² = 1/4 in every format; tol 1/4 is on the line, just below it is not
    pts = ((0, 0, 0), (4, 0, 0), (1, 1, 0))
    for arithmetic in ("float64", "float32"):
        assert all(r.degenerate for r in _every_order(pts, arithmetic=arithmetic, tol=0.25))
        below = _every_order(pts, arithmetic=arithmetic, tol=Fraction(1, 4) - Fraction(1, 10**40))
        assert not any(r.degenerate for r in below)


def test_the_core_imports_no_formatter():
    """core is the bottom layer: display and fields sit above it (format() imports them lazily)."""
    import ast
    import inspect

    from trinormal import core

    tree = ast.parse(inspect.getsource(core))
    top = [n for n in tree.body if isinstance(n, ast.Import | ast.ImportFrom)]
    names = {n.module for n in top if isinstance(n, ast.ImportFrom)} | {
        a.name for n in top if isinstance(n, ast.Import) for a in n.names
    }
    assert "trinormal.validation" in names
    assert not names & {"trinormal.display", "trinormal.fields", "trinormal"}
