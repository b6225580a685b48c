"""Any object at all, given to any exercise: a verdict or a clear message, never an exception.

The hypothesis runs are derandomized with a fixed budget, so CI sees the same examples
every time. Warnings are errors here: reading an answer must be quiet too.
"""

from __future__ import annotations

import itertools
import math
import random
import re
import warnings
from decimal import Decimal
from fractions import Fraction
from typing import Any

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from trinormal.exercises import UNJUDGED, CheckResult, check, get, names
from trinormal.exercises.reading import AnswerError, read_number, read_points, read_vector

pytestmark = pytest.mark.filterwarnings("error")

BUDGET = settings(
    max_examples=300,
    derandomize=True,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)

NAMES = sorted(n for n in names() if not n.startswith("9"))


# --------------------------------------------------------------------------- odd objects


class RaisingLen:
    def __len__(self) -> int:
        raise RuntimeError("no length today")

    def __iter__(self):
        return iter([1, 2, 3])


class RaisingFloat:
    def __float__(self) -> float:
        raise ValueError("no float today")


class RaisingIter:
    def __iter__(self):
        raise TypeError("not iterable today")

    def __len__(self) -> int:
        return 3


class RaisingRepr:
    def __repr__(self) -> str:
        raise RuntimeError("no repr today")


class RaisingEverything:
    def __getattr__(self, name: str) -> Any:
        raise RuntimeError(name)

    def __repr__(self) -> str:
        raise RuntimeError("repr")

    def __eq__(self, other: object) -> bool:
        raise RuntimeError("eq")

    __hash__ = None  # type: ignore[assignment]


class FloatLike:
    def __float__(self) -> float:
        return 6.0


def _deep(n: int) -> Any:
    x: Any = 6
    for _ in range(n):
        x = [x]
    return x


ODD = [
    None,
    True,
    False,
    np.bool_(True),
    {1, 2, 3},
    frozenset(),
    {"x": 1},
    {},
    [],
    (),
    [[1, 2], [3]],
    [[1, 2, 3], [4, 5, 6]],
    10**400,
    -(10**5000),
    "1e400",
    "1e-400",
    "9" * 2000,
    float("nan"),
    float("inf"),
    -float("inf"),
    Decimal("nan"),
    Decimal("-inf"),
    Decimal("1e999999999"),
    complex(1, 2),
    np.complex128(1 + 1j),
    RaisingLen(),
    RaisingFloat(),
    RaisingIter(),
    RaisingRepr(),
    RaisingEverything(),
    FloatLike(),
    object(),
    b"6",
    bytearray(b"1,2,3"),
    "",
    "   ",
    "°",
    "√",
    "−",
    "1/0",
    "0/0",
    "sqrt(-1)",
    "9**9**9",
    "10**10**10",
    "factorial(10**9)",
    "__import__('os')",
    "().__class__",
    "x" * 400,
    "(1, 2",
    "[(1,2,3), (4,5,6)",
    np.array([]),
    np.array([[1, 2], [3, 4]]),
    np.zeros((3, 3, 3)),
    np.array(["a", "b", "c"]),
    np.array([1, 2, 3], dtype=object),
    np.array(np.nan),
    np.datetime64("2026-12-02"),
    np.float16(6),
    np.longdouble(6),
    sp.nan,
    sp.zoo,
    sp.oo,
    sp.I,
    sp.Symbol("x"),
    sp.Matrix([[1, 2], [3, 4]]),
    sp.Matrix([1, 2, 3, 4]),
    sp.true,
    sp.Eq(sp.Symbol("x"), 1),
    sp.FiniteSet(1, 2, 3),
    itertools.count(),
    iter(()),
    range(3),
    range(10**30),
    _deep(50),
    _deep(2000),
    Ellipsis,
    print,
    type,
    ValueError("6"),
]


def odd(i: int) -> Any:
    """The i-th odd object (a function, so that hypothesis never prints the whole list)."""
    return ODD[i]


def assert_judged(name: str, answer: Any) -> CheckResult:
    r = check(name, answer)
    assert isinstance(r, CheckResult)
    assert r.status in ("correct", "incorrect", "unanswered")
    assert isinstance(r.message, str) and r.message
    assert UNJUDGED not in r.message, (name, r.message)
    assert len(r.message) < 400, r.message
    assert "Traceback" not in r.message
    str(r), repr(r), r._repr_html_()
    return r


@pytest.mark.parametrize("name", NAMES)
def test_odd_objects_get_a_verdict_or_a_message(name):
    for answer in ODD:
        assert_judged(name, answer)


# --------------------------------------------------------------------------- random objects

TEXT_ALPHABET = "0123456789+-−.eE/ ()[],°√·×^*xyzUVuv_sqrtpilog\t\u00a0１"
texts = st.one_of(
    st.text(TEXT_ALPHABET, max_size=24),
    st.text(max_size=12),
    st.from_regex(r"[+\-−]?[0-9]{0,3}\.?[0-9]{0,3}([eE][+\-−]?[0-9]{1,5})?°?", fullmatch=True),
    st.sampled_from(["Uy*Vx - Ux*Vy", "front", "True", "(0, 0, 1)", "√3/2", "19.47°"]),
)
scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-(10**420), 10**420),
    st.fractions(max_denominator=10**30),
    st.decimals(allow_nan=True, allow_infinity=True),
    st.complex_numbers(max_magnitude=1e10),
    st.builds(np.float32, st.floats(width=32)),
    st.builds(np.int64, st.integers(-(2**63), 2**63 - 1)),
    st.builds(np.array, st.floats()),
    st.builds(sp.Rational, st.integers(-(10**50), 10**50), st.integers(1, 10**50)),
    st.sampled_from([sp.sqrt(2), sp.pi, sp.oo, sp.nan, sp.I, sp.Symbol("Ux"), sp.true]),
    texts,
    st.integers(0, len(ODD) - 1).map(odd),
)
arrays = hnp.arrays(
    dtype=st.sampled_from([np.float64, np.float32, np.int64, np.bool_, np.complex128]),
    shape=hnp.array_shapes(min_dims=0, max_dims=3, max_side=4),
)
objects = st.recursive(
    st.one_of(scalars, arrays),
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.lists(inner, max_size=4).map(tuple),
        st.dictionaries(st.sampled_from(["A", "B", "C", "x"]), inner, max_size=3),
        st.lists(st.integers(-5, 5), max_size=4).map(sp.Matrix),
    ),
    max_leaves=12,
)


@BUDGET
@given(st.sampled_from(NAMES), objects)
def test_random_objects_get_a_verdict_or_a_message(name, answer):
    assert_judged(name, answer)


@BUDGET
@given(objects)
def test_readers_raise_only_answer_errors(answer):
    for read in (read_number, read_vector, lambda x: read_points(x, 3)):
        try:
            read(answer)
        except AnswerError as exc:
            assert str(exc)


# --------------------------------------------------------------------------- true hints

finite = st.floats(-1e6, 1e6, allow_nan=False)
vectors = st.one_of(
    st.tuples(finite, finite, finite),
    st.tuples(*[st.integers(-20, 20)] * 3),
    st.tuples(*[st.fractions(max_denominator=12).filter(lambda q: abs(q) < 50)] * 3),
)
VECTOR_EXERCISES = [
    n for n in NAMES if get(n).checker is None and isinstance(get(n).solution(), tuple)
]


def _cross(p, q):
    return (
        p[1] * q[2] - p[2] * q[1],
        p[2] * q[0] - p[0] * q[2],
        p[0] * q[1] - p[1] * q[0],
    )


@BUDGET
@given(st.sampled_from(VECTOR_EXERCISES), vectors, st.sampled_from([1, -1, 2, Fraction(1, 3)]))
def test_direction_hints_are_true(name, noise, scale):
    """Whatever the answer, "Right direction" and "opposite way" are only said when true."""
    want = [Fraction(x) for x in get(name).solution()]
    for answer in (
        noise,
        tuple(scale * w for w in want),
        tuple(w + Fraction(n) / 10**6 for w, n in zip(want, noise, strict=True)),
    ):
        message = check(name, answer).message
        got = [Fraction(x) for x in answer]
        c = _cross(got, want)
        c2 = sum(x * x for x in c)
        g2, w2 = sum(x * x for x in got), sum(x * x for x in want)
        tol = Fraction(repr(get(name).tol)) if get(name).tol is not None else 0
        parallel = c2 <= tol * tol * g2 * w2
        dot = sum(a * b for a, b in zip(got, want, strict=True))
        if "Right direction" in message:
            assert parallel and dot > 0, (name, answer, message)
        if "opposite way" in message and "that is" not in message.lower():
            assert parallel and dot < 0, (name, answer, message)


@BUDGET
@given(st.sampled_from(NAMES), st.floats(-1e3, 1e3, allow_nan=False))
def test_numbers_near_the_solution_are_judged_by_the_stated_tolerance(name, x):
    ex = get(name)
    sol = ex.solution()
    if ex.checker is not None or isinstance(sol, bool | str | tuple):
        return
    r = assert_judged(name, x)
    want = Fraction(sol)
    if ex.tol is None:
        right = Fraction(x) == want or x == float(want)
    else:
        right = abs(Fraction(x) - want) <= Fraction(repr(ex.tol)) * abs(want)
    assert r.correct == right, (name, x, r.message)
    if "Wrong sign" in r.message:
        assert math.copysign(1, x) != math.copysign(1, float(want))
    if (m := re.search(r"rounded to (\d+) decimal", r.message)) is not None:
        assert abs(Fraction(x) - want) <= Fraction(1, 2 * 10 ** int(m[1])), (name, x)


# --------------------------------------------------------------------------- forms students write


def _matrix(rows: Any) -> Any:
    """A numpy.matrix (numpy warns that the class is discouraged; students still make them)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PendingDeprecationWarning)
        return np.matrix(rows)


def _degrees_with_comma() -> str:
    text = f"{get('08-cube-corner-degrees').solution():.2f}"  # 19,471 could be 19471
    return text.replace(".", ",") + "°"


#: Right answers in the forms a class wrote them (a teacher's trial), for real exercises.
ACCEPTED: dict[str, list[Any]] = {
    # (a) the prompt's own formula, typed with the exercise's numbers
    "01-area": [
        "area = √3/2",
        "A = |N|/2 = |(1, 1, 1)|/2",
        "|(1, 1, 1)|/2",
        "sqrt(1² + 1² + 1²)/2",
        "np.sqrt(3)/2",
        "math.sqrt(3)/2",
        "0,866",
    ],
    "02-lagrange": ["|(1, 2, 2)|²·|(2, 0, 0)|² − (1·2 + 2·0 + 2·0)²", "9*4 - 2^2"],
    "04-dot-value": ["2·3 + 0·1 + 0·0", "6,0"],
    "04-2d-nz": ["0·0 − 2·3", "−6,0", "|−6|·(−1)"],
    "05-scale-area": ["3²", "3^2", "9,0"],
    "06-float64-digits": [
        "53*log10(2)",
        "53·log10(2)",
        "53 * np.log10(2)",
        "53*math.log10(2)",
        "53*log(2, 10)",
        "15,95",
    ],
    "08-cube-corner-degrees": [_degrees_with_comma()],
    "08-sliver-weight": ["2/(2 + 90)", "0,0217", "1/46"],
    "09-lambert": ["max(0, 0*0 + 0*0.6 + 1*0.8)", "max(0, 0.8)", "0,8"],
    # (b) a vector with a factor, (c) arrays and matrices, (e) decimal commas in vectors
    "01-normal": [
        "(1; 1; 1)",
        "N = (1, 1, 1)",
        "(2, 2, 2)/2",
        "[2,2,2]/2",
        "2*(1/2, 1/2, 1/2)",
        sp.Array([1, 1, 1]),
        sp.Array([[1], [1], [1]]),
        sp.Array([[1, 1, 1]]),
        sp.Matrix([[1, 1, 1]]),
        _matrix([[1, 1, 1]]),
        _matrix([[1], [1], [1]]),
        np.array([[1], [1], [1]]),
        np.array([[1, 1, 1]]),
    ],
    "03-row5-unit": ["(4, 0, 0)/4", "(4,0,0)/|(4,0,0)|", "(1,0; 0; 0)", "1,0 0 0"],
    "05-collinear": ["(5, 7, 1)/3", "[5,7,1]/3", "(5/3; 7/3; 1/3)"],
    "05-down-acb": ["(0; 0; 1), (1; 0; 1), (0; 1; 1)"],
    "10-scaled-normal": [
        "(1, 2, 0)/sqrt(5)",
        "[1,2,0]/√5",
        "(1, 2, 0)/√5",
        "1/sqrt(5)*(1, 2, 0)",
        "(0.5, 1, 0)/sqrt(5/4)",
        "(1/2, 1, 0)/|(1/2, 1, 0)|",
        "(0,44721; 0,89443; 0)",
        "0,44721 0,89443 0",
        sp.Array([1, 2, 0]) / sp.sqrt(5),
        _matrix([[0.4472136, 0.8944272, 0]]),
    ],
    # (d) numpy truth values
    "03-collinear": [
        np.bool_(True),
        np.array(True),
        np.array([True]),
        "True.",
        "True, they are on one line",
        "It is true.",
    ],
    "07-needle-degenerate": [
        np.bool_(True),
        np.array(True),
        np.array([[True]]),
        "true, it is degenerate",
    ],
    # (f) the word inside a sentence
    "09-front-face": [
        "the front side",
        "It is the front.",
        "FRONT",
        "The ray hits the front face.",
    ],
}

#: Wrong answers in the same forms: still refused.
REFUSED: dict[str, list[Any]] = {
    "01-area": ["|(1, 1, 2)|/2", "0,5", "sqrt(3)"],
    "06-float64-digits": ["54*log10(2)", "52·log10(2)", "15,85"],
    "01-normal": ["(1; 1; -1)", "(2, 2, 2)/4", sp.Array([1, 1, 0]), _matrix([[1, 1, 2]])],
    "10-scaled-normal": ["(0, -1, 1)/sqrt(2)", "[2,1,0]/√5", "(0,8944; 0,4472; 0)"],
    "03-collinear": [np.bool_(False), np.array(False), "False, it is not degenerate"],
    "07-needle-degenerate": [np.array(False), "I think it is false", "true or false"],
    "09-front-face": ["the back side", "It is the back."],
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_right_answers_in_the_forms_students_write_pass(name):
    for form in ACCEPTED[name]:
        r = assert_judged(name, form)
        assert r.correct, (name, form, r.message)
    for form in REFUSED.get(name, []):
        r = assert_judged(name, form)
        assert r.status == "incorrect", (name, form, r.message)


def test_unclear_answers_are_told_why_not_judged():
    """A sentence naming both words, a negation, or 1,500 (1.5 or 1500?) gets a reason."""
    for sentence, why in (
        ("front, not back", "names both 'front' and 'back'"),
        ("the front or the back", "names both"),
        ("not the back", "without a negation"),
        ("sideways", "'front' or 'back'"),
    ):
        r = assert_judged("09-front-face", sentence)
        assert r.status == "incorrect" and why in r.message, (sentence, r.message)
    r = assert_judged("06-float64-digits", "15,955")
    assert "thousands separator" in r.message and "15.955" in r.message
    r = assert_judged("01-normal", "2*(1,1,1)/(1,1,1)")
    assert "could not be read" in r.message


# --------------------------------------------------------------------------- text fuzz

#: Pieces of text answers: numbers, functions, formulas, vectors, sentences.
TEXT_ATOMS = [
    "1", "-1", "0", "2", "1/2", "0.5", "0,5", "1,500", "−6", "sqrt(2)", "√2", "√3/2", "2√2",
    "log(2)", "log(2, 10)", "log10(2)", "ln(2)", "pi", "e", "exp(1)", "|−6|", "|(1, 2, 2)|",
    "max(0, 0.8)", "degrees(1)", "atan2(1, 2)", "np.sqrt(2)", "math.log10(2)", "x", "Ux*Vy",
    "(0, -1, 1)", "[0,-1,1]", "(0; 1; 0)", "0,5 1 0", "(1,2,3), (4,5,6), (7,8,9)", "front",
    "the front side", "It is the front.", "front, not back", "True", "False", "yes", "1e-3",
    "19.47°", "1/0", "0/0", "oo", "zoo", "I", "nan", "", "()", "(,)", "|", "||", "|(1,2)|",
]  # fmt: skip
TEXT_JOINS = ["{a}/{b}", "{a}*{b}", "{a} {b}", "({a}, {b}, {a})/{b}", "{b}*({a}; {b}; {a})",
              "{a} - {b}", "{a}^{b}", "|{a}|/{b}", "[{a}, {b}, 0]/sqrt({b})"]  # fmt: skip


#: Bits of text run together at random: brackets, bars, separators, words, operators.
TEXT_BITS = ["1", "2", "0,5", ",", ";", " ", "(", ")", "[", "]", "|", "/", "*", "^", "²", "√",
             "sqrt", "log10", "max", "np.", "x", "Ux", "Vy", "−", "e", "front", "back", "not",
             "True", ".", "°", "1,500", "degrees", "atan2", "⟨", "{", "'", "=", "<", "&", "~", "%"]  # fmt: skip


def _texts(name: str) -> list[str]:
    pairs = itertools.product(TEXT_ATOMS[:30], TEXT_ATOMS[28:])
    joined = [join.format(a=a, b=b) for (a, b), join in zip(pairs, itertools.cycle(TEXT_JOINS))]
    rng = random.Random(name)  # the same texts on every run
    scrambled = ["".join(rng.choices(TEXT_BITS, k=rng.randint(1, 9))) for _ in range(150)]
    return TEXT_ATOMS + joined[::7] + scrambled


@pytest.mark.parametrize("name", NAMES)
def test_every_text_gets_a_verdict_or_a_reason(name):
    """Text typed for any exercise is judged, or told why it could not be read: never unjudged.

    Nothing is printed on the way either: a warning sympy gives while reading would show
    in the student's notebook, so every warning is recorded and must be absent.
    """
    for text in _texts(name):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            assert_judged(name, text)
        assert not caught, (name, text, [str(w.message)[:80] for w in caught])
