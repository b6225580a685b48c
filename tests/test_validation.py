"""One check for each kind of input, one message each, the same for every entry point."""

from __future__ import annotations

import collections
import itertools
import json
import time
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from trinormal import triangle_normal
from trinormal.cli import steps as cli_steps
from trinormal.symbolic import steps as symbolic_steps
from trinormal.validation import (
    MAX_COMMON_DIGITS,
    MAX_DIGITS,
    MAX_PRECISION,
    Winding,
    check_common,
    check_coordinate,
    check_precision,
    check_tolerance,
    check_vertex,
    check_winding,
    quote_input,
)

ORIGIN, X, Y = (0, 0, 0), (1, 0, 0), (0, 1, 0)


# --------------------------------------------------------------------------- one limit, every type

HUGE = [
    10**MAX_DIGITS,
    -(10**MAX_DIGITS),
    Decimal("1e1000000"),
    Decimal("-1e-1000000"),
    Decimal("1." + "3" * 100_000),
    Fraction(1, 10**MAX_DIGITS),
    Fraction(10**5000, 3),
    np.longdouble("1e4000") if np.finfo(np.longdouble).maxexp > 1024 else 10**5000,
    sp.Integer(10) ** 500,
    sp.Rational(1, 3**1000),
    sp.Float("1e1000000", 30),
    sp.Float("1." + "1" * 2000, 7000),
    "1" * MAX_DIGITS + "1",
    "1e-2200",
]


@pytest.mark.parametrize("value", HUGE, ids=lambda v: type(v).__name__)
def test_one_size_limit_for_every_type_names_vertex_and_axis(value):
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r"^B\.y( = '[^']+')? is too large a number") as info:
        triangle_normal(ORIGIN, (1, value, 0), Y)
    assert time.perf_counter() - start < 1.0  # refused before any big arithmetic
    assert len(str(info.value)) < 200


@pytest.mark.parametrize(
    "value",
    [
        10**MAX_DIGITS - 1,
        Fraction(1, 10**MAX_DIGITS - 1),
        Decimal("9e399"),
        Decimal("1e-399"),
        Decimal("5e-400"),  # 1 / (2 * 10**399) in lowest terms
        np.float64(5e-324),
        np.float32(3e38),
        np.int64(-(2**63)),
        sp.Integer(10) ** 399,
        sp.Float("1e-300"),
        5e-324,
        1.7976931348623157e308,
    ],
    ids=lambda v: type(v).__name__,
)
def test_values_within_the_limit_are_accepted(value):
    r = triangle_normal(ORIGIN, (1, value, 0), (0, 0, 1))
    assert r.exact.b[1] == Fraction(*check_coordinate(value))


def test_limits_apply_to_the_value_in_lowest_terms():
    big = "1" + "0" * 500
    assert check_coordinate(big + "/" + "1" + "0" * 200) == (10**300, 1)
    assert check_coordinate("0.5" + "0" * 600) == (5, 10)
    assert check_coordinate(Decimal("1" + "0" * 700 + "e-700")) == (1, 1)


def test_the_nine_coordinates_together_are_limited_too():
    a = (f"1/{3**800}", f"1/{7**470}", f"1/{11**380}")
    with pytest.raises(ValueError, match=r"^A\.z makes the nine coordinates too large") as info:
        triangle_normal(a, X, Y)
    assert str(MAX_COMMON_DIGITS) in str(info.value)
    with pytest.raises(ValueError, match=r"^A\.z makes"):
        check_common([check_coordinate(x) for x in a])


# --------------------------------------------------------------------------- accepted means usable

EXTREMES = [
    ((5e-324, 1.7e308, -1.7e308), (1.7e308, 5e-324, 2.2e-308), (-1e-300, 3e307, 1e-320)),
    (("1e399", "-1e399", "1e-399"), ("1e-399", "1e399", "0"), ("3", "1/7", "1e399")),
    ((f"1/{3**250}", f"1/{7**150}", "1"), (f"1/{13**100}", "1/17", "0"), ("2", "0", "1e-100")),
    ((1, 2, 3), (1, 2, 3 + 2**-1074 * 2**60), ("1e-399", 2, 3)),
    (("0", "0", "0"), ("1e-399", "0", "0"), ("0", "1e-399", "0")),
]


@pytest.mark.parametrize("points", EXTREMES)
def test_anything_accepted_can_be_formatted_serialised_and_worked(points):
    start = time.perf_counter()
    for winding in ("ABC", "ACB"):
        r = triangle_normal(*points, winding=winding)
        for p in (0, 4, MAX_PRECISION):
            r.format(p)
        json.dumps(r.to_dict(), allow_nan=False)
        cli_steps(r, MAX_PRECISION)
        symbolic_steps(*points, winding=winding)
        for arithmetic in ("float64", "float32"):
            try:  # a value beyond the format's range is refused (a ValueError) ...
                f = triangle_normal(*points, winding=winding, arithmetic=arithmetic)
            except ValueError as err:
                assert "range" in str(err)
            else:  # ... or the result is usable like any other
                f.format(MAX_PRECISION)
                json.dumps(f.to_dict(), allow_nan=False)
    assert time.perf_counter() - start < 10.0  # generous: each call is well under a second


# --------------------------------------------------------------------------- exact types


def test_sympy_numbers_are_exact():
    r = triangle_normal(
        (sp.Integer(0), sp.Rational(1, 3), 0), (sp.Integer(2), 0, 0), (0, sp.Float("0.5"), 0)
    )
    assert r.exact.a[1] == Fraction(1, 3) and r.exact.b[0] == 2 and r.exact.c[1] == Fraction(1, 2)
    assert check_coordinate(sp.S.Half) == (1, 2)
    assert check_coordinate(sp.Float("0.1")) == (0.1).as_integer_ratio()  # its binary value
    assert check_coordinate(-sp.Integer(7)) == (-7, 1)


@pytest.mark.parametrize(
    ("value", "error", "message"),
    [
        (sp.sqrt(3) / 2, ValueError, "B.y = sqrt(3)/2 is not a rational number"),
        (sp.pi, ValueError, "B.y = pi is not a rational number"),
        (sp.oo, ValueError, "B.y is infinite"),
        (-sp.oo, ValueError, "B.y is infinite"),
        (sp.zoo, ValueError, "B.y is infinite"),
        (sp.nan, ValueError, "B.y is NaN"),
        (sp.Float("nan"), ValueError, "B.y is NaN"),
        (sp.Float("inf"), ValueError, "B.y is infinite"),
        (sp.Symbol("x"), TypeError, "B.y is Symbol, expected a real number"),
        (sp.I, TypeError, "B.y is ImaginaryUnit, expected a real number"),
    ],
)
def test_other_sympy_objects_are_refused_clearly(value, error, message):
    with pytest.raises(error) as info:
        triangle_normal(ORIGIN, (1, value, 0), Y)
    assert str(info.value).startswith(message)


# --------------------------------------------------------------------------- vertices


class Point3:
    """A sized, ordered sequence that is not a list, tuple or array."""

    def __len__(self):
        return 3

    def __getitem__(self, i):
        if i >= 3:
            raise IndexError(i)
        return (0, 0, 1)[i]


@pytest.mark.parametrize(
    "vertex",
    [
        [0, 0, 1],
        (0, 0, 1),
        np.array([0, 0, 1]),
        np.array([0, 0, 1], dtype=np.float32),
        range(0, 2, 1) and (0, 0, 1),
        collections.deque([0, 0, 1]),
        sp.Matrix([0, 0, 1]),
        Point3(),
    ],
    ids=lambda v: type(v).__name__,
)
def test_sized_ordered_sequences_are_vertices(vertex):
    assert triangle_normal(ORIGIN, X, vertex).normal == (0.0, -1.0, 0.0)


class Counting:
    """An iterator that counts how many items were taken from it."""

    def __init__(self):
        self.taken = 0

    def __iter__(self):
        return self

    def __next__(self):
        self.taken += 1
        return 0


@pytest.mark.parametrize(
    ("vertex", "name"),
    [
        ({1, 2, 3}, "set"),
        (frozenset({1, 2, 3}), "frozenset"),
        ({"x": 1, "y": 2, "z": 3}, "dict"),
        (b"abc", "bytes"),
        (bytearray(b"abc"), "bytearray"),
        (memoryview(b"abc"), "memoryview"),
        ("1,2,3", "str"),
        (iter([1, 2, 3]), "list_iterator"),
        ((x for x in (1, 2, 3)), "generator"),
        (itertools.count(), "count"),
        (map(float, "123"), "map"),
        (5, "int"),
        (None, "NoneType"),
        (np.float64(1), "float64"),
        (np.array(1.0), "ndarray"),
    ],
)
def test_anything_else_is_a_type_error_naming_the_vertex(vertex, name):
    with pytest.raises(TypeError) as info:
        triangle_normal(ORIGIN, X, vertex)
    assert str(info.value) == (
        f"C must be 3 coordinates (x, y, z) in a list, tuple or array, got {name}"
    )


def test_an_iterator_is_never_consumed():
    it = Counting()
    with pytest.raises(TypeError, match=r"^B must be 3 coordinates"):
        triangle_normal(ORIGIN, it, Y)
    assert it.taken == 0


def test_wrong_length_is_a_value_error():
    for vertex, n in (([1, 2], 2), ([1, 2, 3, 4], 4), (np.zeros(7), 7), ([], 0)):
        with pytest.raises(ValueError, match=f"^A has {n} coordinates, expected 3$"):
            check_vertex(vertex, "A")


# --------------------------------------------------------------------------- options


def test_winding_has_one_check_and_one_message():
    assert check_winding("ACB") is Winding.ACB and check_winding(Winding.ABC) is Winding.ABC
    for bad in ("CBA", "abc", None, 3, ["ABC"]):
        with pytest.raises(ValueError, match=r"^winding must be 'ABC' or 'ACB', got .* \(invalid"):
            check_winding(bad)
        with pytest.raises(ValueError, match=r"^winding must be 'ABC' or 'ACB'"):
            triangle_normal(ORIGIN, X, Y, winding=bad)


def test_precision_has_one_check_and_one_message():
    assert [check_precision(p) for p in (0, 15, np.int64(3), "7", " 2 ")] == [0, 15, 3, 7, 2]
    for bad in (16, -1, "16", "999999999999"):
        with pytest.raises(ValueError, match=r"^precision must be from 0 to 15, got "):
            check_precision(bad)
    for bad in ("two", "2.5", "", "-1", "\uff11"):
        with pytest.raises(ValueError, match=r"^precision must be a whole number from 0 to 15"):
            check_precision(bad)
    for bad in (2.5, None, True, [4]):
        with pytest.raises(TypeError, match=r"^precision must be a whole number from 0 to 15"):
            check_precision(bad)
    r = triangle_normal(ORIGIN, X, Y)
    with pytest.raises(ValueError, match=r"^precision must be from 0 to 15, got 16$"):
        r.format(16)


def test_tolerance_has_one_check_and_one_message():
    assert check_tolerance(0) == (0, 1) and check_tolerance(1) == (1, 1)
    assert check_tolerance(Fraction(1, 3)) == (1, 3) and check_tolerance(sp.Rational(1, 3)) == (
        1,
        3,
    )
    rule = r"tol must be >= 0 and <= 1 \(it bounds \|N\| / L², L the longest side\)"
    for bad in (-1e-3, 2, Decimal("1e400"), Fraction(10**400 - 1, 1), "1.5"):
        with pytest.raises(ValueError, match=rule):
            triangle_normal(ORIGIN, X, Y, tol=bad)
    with pytest.raises(ValueError, match=r"^tol is NaN; " + rule):
        triangle_normal(ORIGIN, X, Y, tol=float("nan"))
    with pytest.raises(ValueError, match=r"^tol is too large a number"):
        triangle_normal(ORIGIN, X, Y, tol=Decimal("1e1000000"))


def test_messages_quote_input_briefly_and_show_invisible_characters():
    assert quote_input("1" * 5000) == "'" + "1" * 24 + "…'"
    assert quote_input("1\u200b") == "'1\\u200b'"
    assert quote_input("\u22121") == "'\u22121'"  # a visible symbol stays as typed
    with pytest.raises(ValueError) as info:
        check_coordinate("x" * 900, "C.z")
    assert len(str(info.value)) < 120
