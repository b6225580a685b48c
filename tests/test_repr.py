"""Results print exactly: '1/3', not 0.333...; the explorer prints as the call that recreates it."""

from __future__ import annotations

from fractions import Fraction

from trinormal import triangle_normal
from trinormal.display import exact_literal


def test_a_result_repr_shows_the_inputs_and_n_exactly() -> None:
    r = triangle_normal(("0.1", "0.2", "0.3"), ("1/3", 0, 0), (0, "2.35", 0))
    text = repr(r)
    assert text.startswith(
        "TriangleNormal(a=('0.1', '0.2', '0.3'), b=('1/3', 0, 0), c=(0, '2.35', 0),"
    )
    assert "normal=('0.705', '0.1', '289/600')" in text
    assert "magnitude_squared='5321/7200'" in text
    assert "degenerate=False" in text
    assert "0.333" not in text and "0.4816" not in text


def test_every_exact_value_in_the_repr_reads_back_to_itself() -> None:
    values = [
        Fraction(1, 3),
        Fraction(-47, 20),
        Fraction(10**30 + 1, 7),
        Fraction(5),
        Fraction(1, 2**40),
    ]
    for q in values:
        literal = exact_literal(q)
        if q.denominator == 1:
            assert literal == str(q.numerator)
        else:
            assert literal[0] == literal[-1] == "'"
            assert Fraction(literal.strip("'")) == q
    # and a result built from those strings is the same triangle
    r = triangle_normal((values[0], values[1], 0), (values[2], 0, 1), (0, values[4], values[3]))
    again = triangle_normal(
        *(tuple(exact_literal(q).strip("'") for q in p) for p in (r.exact.a, r.exact.b, r.exact.c))
    )
    assert again.exact == r.exact and repr(again) == repr(r)


def test_float_arithmetic_shows_the_computed_normal() -> None:
    r = triangle_normal((0, 0, 0), ("0.1", 0, 0), (0, "0.1", 0), arithmetic="float32")
    text = repr(r)
    assert "a=(0, 0, 0), b=('0.1', 0, 0), c=(0, '0.1', 0)" in text
    assert f"arithmetic='float32', normal={r.normal!r}" in text
