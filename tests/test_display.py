"""The formatter: half away from zero on exact values, the scientific switch, trim, never -0."""

from __future__ import annotations

import random
from decimal import ROUND_HALF_UP, Decimal, localcontext
from fractions import Fraction

import pytest

from trinormal import format_number, format_vector, triangle_normal
from trinormal.display import exact_text, format_surd, radical, radical_text


@pytest.mark.parametrize(
    ("x", "p", "text"),
    [
        (0.125, 2, "0.13"),
        (-0.125, 2, "-0.13"),
        (0.25, 1, "0.3"),
        (2.5, 0, "3"),
        (-2.5, 0, "-3"),
        (-0.0, 4, "0.0000"),
        (0, 0, "0"),
        (1.0, 4, "1.0000"),
        (Fraction(1, 3), 15, "0.333333333333333"),
        (2.7755575615628914e-17, 4, "2.7756e-17"),
        (1e-4, 4, "0.0001"),
        (0.99999e-5, 4, "9.9999e-06"),
        (0.99999e-4, 4, "0.0001"),  # fixed-point shows it: no switch to scientific
        (0.707, 0, "1"),
        (0.4, 0, "4e-01"),
        (0.5, 0, "1"),  # a tie rounds away from zero, so fixed-point shows it
        (-0.00004999, 4, "-4.9990e-05"),
        (1e15, 4, "1.0000e+15"),
        (999999999999999.0, 2, "999999999999999.00"),
        (-3e-9, 0, "-3e-09"),
        (Fraction(9999995, 10**12), 4, "1.0000e-05"),  # 9.999995e-6 carries into a new digit
        (Decimal("0.1"), 1, "0.1"),
        (7.3710e599 if False else 7371 * 10**596, 4, "7.3710e+599"),
    ],
)
def test_format_number(x, p, text):
    assert format_number(x, p) == text


def test_trim():
    assert format_number(0.5, 4, trim=True) == "0.5"
    assert format_number(2.0, 4, trim=True) == "2"
    assert format_number(-0.0, 4, trim=True) == "0"
    assert format_number(5e-6, 4, trim=True) == "5e-06"
    assert format_number(5e-5, 4, trim=True) == "0.0001"
    assert format_vector((0.0, -0.70710678, 0.70710678), 4, trim=True) == "(0, -0.7071, 0.7071)"


def test_nonzero_never_prints_as_zero_and_zero_never_negative():
    rng = random.Random(7)
    for _ in range(2000):
        x = rng.choice([-1, 1]) * 10 ** rng.uniform(-30, 30)
        for p in (0, 2, 4, 10):
            text = format_number(x, p)
            assert any(ch in "123456789" for ch in text.split("e")[0]), (x, p, text)
    for z in (0, 0.0, -0.0, Fraction(0)):
        assert not format_number(z, 3).startswith("-")


def test_rationals_round_half_away_from_zero_exactly():
    rng = random.Random(3)
    for _ in range(3000):
        q = Fraction(rng.randint(-(10**9), 10**9), rng.randint(1, 10**6))
        p = rng.randint(0, 6)
        with localcontext() as ctx:
            ctx.prec = 60
            ref = (Decimal(q.numerator) / Decimal(q.denominator)).quantize(
                Decimal(1).scaleb(-p), rounding=ROUND_HALF_UP
            )
        if 2 * abs(q) < Fraction(1, 10**p) and q != 0:
            continue  # fixed-point would show zero: scientific notation, checked elsewhere
        assert format_number(q, p) == f"{ref:.{p}f}"


def test_square_roots_are_correctly_rounded():
    rng = random.Random(11)
    for _ in range(2000):
        num, den = rng.randint(1, 10**12), rng.randint(1, 10**6)
        p = rng.randint(0, 12)
        with localcontext() as ctx:
            ctx.prec = 80
            exact = (Decimal(num) / Decimal(den)).sqrt()
            if 2 * exact < Decimal(1).scaleb(-p):
                continue
            ref = exact.quantize(Decimal(1).scaleb(-p), rounding=ROUND_HALF_UP)
        assert format_surd(False, num, den, p) == f"{ref:.{p}f}"


def test_scientific_exactly_where_fixed_point_would_show_zero():
    """The switch happens at half of 10**-p: below it fixed-point rounds to zero."""
    for p in range(16):
        half = Fraction(1, 2 * 10**p)
        assert "e" not in format_number(half, p)  # a tie rounds away from zero: 0.0…1
        assert format_number(half, p).endswith("1")
        assert "e-" in format_number(half - Fraction(1, 10**40), p)
        assert "e" not in format_number(-half, p) and format_number(-half, p).startswith("-")
    # the unit normal of the guide's third row at precision 0 (issue: it read 7e-01)
    r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    assert r.format(0)["unit_normal"] == "(0, -1, 1)"
    assert format_number(0.707, 0) == "1"


def test_square_root_ties_are_exact():
    # sqrt(0.015625) = 0.125 exactly: half away from zero gives 0.13 (a float might not)
    assert format_surd(False, 1, 64, 2) == "0.13"
    # |N| = 0.15 from exact decimal inputs: the area 0.075 rounds to 0.08, not 0.07
    r = triangle_normal(("0", "0", "0"), ("0.3", "0", "0"), ("0", "0.5", "0"))
    assert r.format(2)["area"] == "0.08"
    assert r.format(1)["magnitude"] == "0.2"  # 0.15 exactly


def test_bad_precision():
    with pytest.raises(ValueError, match="0 to 15"):
        format_number(1.0, 16)
    with pytest.raises(ValueError, match="0 to 15"):
        format_number(1.0, -1)
    with pytest.raises(TypeError):
        format_number(1.0, 2.5)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="not a finite number"):
        format_number(float("nan"))
    with pytest.raises(ValueError, match="not a finite number"):
        format_number(float("inf"))


def test_result_format_keys_and_status():
    r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    f = r.format(4)
    assert set(f) == {"u", "v", "normal", "magnitude", "area", "unit_normal", "plane", "status"}
    assert f["u"] == "(1.0000, 0.0000, 0.0000)"
    assert f["plane"] == "0.0000x - 0.7071y + 0.7071z = 0.0000"
    d = triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2)).format(2)
    assert d["unit_normal"] == "undefined" and d["plane"] == "undefined"
    assert "collinear" in d["status"]


def test_format_agrees_with_float_fields():
    rng = random.Random(5)
    for _ in range(200):
        pts = [[rng.uniform(-9, 9) for _ in range(3)] for _ in range(3)]
        r = triangle_normal(*pts)
        f = r.format(6)
        assert f["magnitude"] == format_number(r.magnitude, 6)
        assert f["normal"] == format_vector(r.normal, 6)
        assert f["unit_normal"] == format_vector(r.unit_normal, 6)


def test_exact_text_and_radicals():
    assert exact_text(Fraction(1, 8)) == "0.125"
    assert exact_text(Fraction(2, 3)) == "2/3"
    assert exact_text(Fraction(1, 2**70)) == "1/1180591620717411303424"
    assert radical(Fraction(72)) == (Fraction(6), 2)
    assert radical_text(*radical(Fraction(1, 3))) == "√3/3"
    with pytest.raises(ValueError):
        radical(Fraction(-1))
