"""Judging answers: the one rule set behind every exercise's verdict and hints.

The rules a careful teacher applies, written once:

* **Exact exercises** (no tolerance) accept exactly the right value, in any
  exact form, and also the float nearest to it (a float cannot come closer).
* **Exercises with a tolerance** accept floats within it. The tolerance is
  *relative*: a number ``x`` counts when ``|x − answer| ≤ tol · |answer|``, a
  vector when each component is within ``tol`` times the vector's length.
  Each such exercise states its tolerance in its prompt, worded by
  `tolerance_text`.
* **Hints are true for the answer given.** A listed mistake's hint is given
  only to an answer equal to that mistake (or to it rounded, to at least
  0.5 % precision); "opposite way" only to a vector that points exactly the
  other way; "right direction, wrong length" only when the direction is right
  and the length is not; an answer that is the solution rounded too coarsely
  is told so, never that it is wrong in another way. No hint quotes the
  solution or says how far from it an answer is.

Examples
--------
>>> tolerance_text(1e-3, "number")
'within 0.1 % of the right value'
>>> same_number(0.3333, Fraction(1, 3), 1e-3), same_number(0.33, Fraction(1, 3), 1e-3)
(True, False)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import TypeVar

from trinormal.display import format_number
from trinormal.exercises.reading import Number

__all__ = [
    "SLIPS",
    "Verdict",
    "decimals",
    "is_rounding",
    "judge_number",
    "judge_vector",
    "same_number",
    "same_vector",
    "tolerance_text",
]

#: A listed mistake matches an answer rounded from it when the rounding is at least this fine.
ROUNDING_PRECISION = Fraction(1, 200)
#: An answer to an exact exercise this close (relative) is told it is close but not exact.
NEAR_EXACT = Fraction(1, 10**6)
#: What such an answer is told.
NOT_EXACT = "Very close, but not exactly right: this exercise wants the exact value."

#: Every slip a verdict can name: a stable code (what the class report and its CSV show) and
#: what it means. A listed mistake names its code as the third item of its tuple; the rules
#: below name the general ones. A wrong answer that matches no slip has the code "".
SLIPS: dict[str, str] = {
    "reversed-order": "the points or the factors taken in the reversed order",
    "wrong-sign": "the right size with the wrong sign",
    "opposite-direction": "a vector pointing the opposite way",
    "wrong-length": "the right direction with the wrong length",
    "not-unit": "the right direction, not divided by its length",
    "unit-for-raw": "the unit normal N / |N| where N was asked",
    "raw-for-unit": "the raw N where the unit normal was asked",
    "magnitude-for-area": "|N| (the parallelogram) for the triangle's area",
    "half-area": "the area halved twice",
    "squared-magnitude": "|N|² where |N| or the area was asked",
    "magnitude-for-squared": "|N| where |N|² was asked",
    "area-for-raw": "the area where the raw N_z was asked",
    "zero-normal": "0 for a normal component that is not 0",
    "cross-for-dot": "a cross-product component for the dot product",
    "component-for-dot": "one component for the dot product",
    "no-subtraction": "Lagrange's identity without its subtraction",
    "unsquared-dot": "U · V subtracted instead of its square",
    "added-dot-squared": "(U · V)² added instead of subtracted",
    "linear-scaling": "the scale factor itself (a length) for an area or N",
    "cubic-scaling": "the cube of the scale factor (a volume)",
    "inverse-factor": "the inverse factor (new to old)",
    "unit-normals-summed": "unit normals summed instead of raw normals",
    "half-normals": "N / 2 summed instead of N",
    "implicit-bit-missed": "the stored bits without the implicit leading bit",
    "whole-format": "the whole format's bits for the significand",
    "bits-for-digits": "bits for decimal digits",
    "rounded-up": "a value rounded up to a whole number",
    "rounded-down": "a value rounded down to a whole number",
    "float32": "float32's count for float64",
    "round-trip-digits": "the round-trip digit count (17)",
    "radians-for-degrees": "radians for degrees",
    "complement-angle": "90° minus the angle",
    "uniform-weight": "uniform weights instead of angle weights",
    "neighbour-angle-only": "divided by the neighbour's angle alone",
    "angle-difference": "divided by the difference of the angles",
    "neighbour-share": "the neighbour's share instead of the sliver's",
    "normal-as-point": "the normal transformed like a point (M n)",
    "untransformed": "the value before the transform",
    "no-inverse-transpose": "det(M) (U × V) without M⁻ᵀ",
    "degenerate": "points on one line: no triangle",
    "tilted": "a normal that is not straight down",
    "rounded": "the right value rounded too coarsely",
    "not-exact": "very close, but not the exact value",
    "unreadable": "an answer that could not be read",
    "whole-vector": "a whole vector where one component was asked",
}

#: An answer as judged: one number, or a vector of them.
Answer = TypeVar("Answer", Number, Sequence[Number])


@dataclass(frozen=True)
class Verdict:
    """The judgement of one answer, before it is shown.

    Attributes
    ----------
    ok : bool
        Right or not.
    hint : str
        For a wrong answer: what is true of it and what to try.
    note : str
        For a right answer: anything worth adding (empty for most).
    slip : str
        For a wrong answer: the code in `SLIPS` of the slip it matched, "" for none.
    """

    ok: bool
    hint: str = ""
    note: str = ""
    slip: str = ""


def _q(x: Number | int) -> Fraction:
    return x if isinstance(x, Fraction) else Fraction(x)


def _tol(tol: float) -> Fraction:
    return Fraction(repr(float(tol)))


def tolerance_text(tol: float | None, kind: str = "number") -> str:
    """Word a relative tolerance the way prompts and verdicts state it.

    Examples
    --------
    >>> tolerance_text(5e-3), tolerance_text(1e-4, "vector")
    ('within 0.5 % of the right value', "each component within 0.01 % of the right vector's length")
    >>> tolerance_text(None)
    'exactly'
    """
    if tol is None:
        return "exactly"
    percent = format_number(_tol(tol) * 100, 6, trim=True)
    if kind == "vector":
        return f"each component within {percent} % of the right vector's length"
    return f"within {percent} % of the right value"


def same_number(got: Number, want: Number, tol: float | None) -> bool:
    """Tell whether ``got`` counts as ``want``: exactly (or its nearest float), or within ``tol``.

    Examples
    --------
    >>> same_number(0.1, Fraction(1, 10), None), same_number(0.1000001, Fraction(1, 10), None)
    (True, False)
    """
    g, w = _q(got), _q(want)
    if tol is None:
        if g == w:
            return True
        return isinstance(got, float) and isinstance(want, Fraction) and got == _nearest_float(want)
    t = _tol(tol)
    return (g - w) ** 2 <= t * t * w * w


def _nearest_float(q: Fraction) -> float | None:
    try:
        return float(q)
    except OverflowError:
        return None


def same_vector(got: Sequence[Number], want: Sequence[Number], tol: float | None) -> bool:
    """Tell whether a vector counts: every component exactly, or within ``tol`` times ``|want|``.

    Examples
    --------
    >>> want = [Fraction(3, 5), Fraction(4, 5), 0]
    >>> same_vector([0.6, 0.8, 0], want, None), same_vector([0.6000001, 0.8, 0], want, None)
    (True, False)
    >>> same_vector([0.6000001, 0.8, 0], want, 1e-6)
    True
    """
    if len(got) != len(want):
        return False
    if tol is None:
        return all(same_number(g, w, None) for g, w in zip(got, want, strict=True))
    t = _tol(tol)
    bound = t * t * sum((_q(w) ** 2 for w in want), Fraction(0))
    return all((_q(g) - _q(w)) ** 2 <= bound for g, w in zip(got, want, strict=True))


def decimals(x: Number) -> int | None:
    """Return how many decimals ``x`` was written with (None when it does not terminate).

    Examples
    --------
    >>> decimals(0.25), decimals(Fraction(1, 8)), decimals(Fraction(1, 3)), decimals(2.0)
    (2, 3, None, 0)
    """
    if isinstance(x, float):
        if not math.isfinite(x):
            return None
        mantissa, _, exp = repr(x).partition("e")  # a float's repr writes "1.5e-07"
        frac = mantissa.partition(".")[2].rstrip("0")
        return max(0, len(frac) - int(exp or 0))
    d = x.denominator
    twos = fives = 0
    while d % 2 == 0:
        d //= 2
        twos += 1
    while d % 5 == 0:
        d //= 5
        fives += 1
    return max(twos, fives) if d == 1 else None


def is_rounding(got: Number, want: Number, *, fine: bool = True) -> bool:
    """Tell whether ``got`` is ``want`` rounded to the decimals ``got`` has (at least one).

    With ``fine`` (the default), the rounding must also be at least 0.5 %
    precise, so that ``0.71`` does not count as a rounding of ``0.7071``.

    Examples
    --------
    >>> is_rounding(0.707, Fraction(7071, 10000)), is_rounding(0.71, Fraction(7071, 10000))
    (True, False)
    """
    d = decimals(got)
    if d is None or d == 0:
        return False
    half = Fraction(1, 2 * 10**d)
    w = _q(want)
    if fine and half > ROUNDING_PRECISION * abs(w):
        return False
    return abs(_q(got) - w) <= half


def _near_mistake(got: Number, value: Number, tol: float | None) -> bool:
    return same_number(got, value, tol) or is_rounding(got, value)


def _near_mistake_vector(got: Sequence[Number], value: Sequence[Number], tol: float | None) -> bool:
    if len(got) != len(value):
        return False
    if same_vector(got, value, tol):
        return True
    length = math.sqrt(sum(float(_q(v)) ** 2 for v in value))
    return all(
        same_number(g, v, tol)
        or (is_rounding(g, v, fine=False) and 10.0 ** -(decimals(g) or 0) <= 0.01 * length)
        for g, v in zip(got, value, strict=True)
    )


def judge_number(
    got: Number,
    want: Number,
    tol: float | None,
    mistakes: Sequence[tuple[Number, str, str]] = (),
    hint: str = "",
) -> Verdict:
    """Judge one number against the solution, with the hint that is true for it.

    Examples
    --------
    >>> judge_number(Fraction(-3), Fraction(3), None).hint
    'Wrong sign.'
    >>> judge_number(0.71, 0.7071068, 1e-3).hint  # doctest: +ELLIPSIS
    'Your answer looks like the right value rounded to 2 decimals...'
    """
    known = _right_or_listed(got, want, tol, mistakes, same_number, _near_mistake)
    if known is not None:
        return known
    if want != 0 and same_number(-_q(got), want, tol):
        return Verdict(False, "Wrong sign.", slip="wrong-sign")
    if tol is not None and is_rounding(got, want, fine=False):
        return Verdict(False, _rounded_hint(got, tol, "number"), slip="rounded")
    if tol is None and want != 0 and abs(_q(got) - _q(want)) <= NEAR_EXACT * abs(_q(want)):
        return Verdict(False, NOT_EXACT, slip="not-exact")
    return Verdict(False, hint)


def _right_or_listed(
    got: Answer,
    want: Answer,
    tol: float | None,
    mistakes: Sequence[tuple[Answer, str, str]],
    same: Callable[[Answer, Answer, float | None], bool],
    near: Callable[[Answer, Answer, float | None], bool],
) -> Verdict | None:
    """Return the verdict on a right answer or on a listed mistake; None for any other answer.

    ``same`` says whether an answer counts as the solution, ``near`` whether it is
    a mistake (equal to it or rounded from it): the first listed one it is gets its hint and slip.
    """
    if same(got, want, tol):
        return Verdict(True)
    for value, text, slip in mistakes:
        if near(got, value, tol):
            return Verdict(False, text, slip=slip)
    return None


def _rounded_hint(got: Number, tol: float, kind: str) -> str:
    d = decimals(got)
    return (
        f"Your answer looks like the right value rounded to {d} decimal{'s' if d != 1 else ''}, "
        f"which is further off than this exercise allows ({tolerance_text(tol, kind)}): "
        "keep more decimals."
    )


def _dot(p: Sequence[Fraction], q: Sequence[Fraction]) -> Fraction:
    return sum((a * b for a, b in zip(p, q, strict=True)), Fraction(0))


def _cross_zero(p: Sequence[Fraction], q: Sequence[Fraction], sine: Fraction | None) -> bool:
    """P ∥ q: exactly (sine None) or with |p × q| ≤ sine · |p| |q|."""
    c2 = _dot(p, p) * _dot(q, q) - _dot(p, q) ** 2  # |p × q|², by Lagrange's identity (exact)
    if sine is None:
        return c2 == 0
    return c2 <= sine * sine * _dot(p, p) * _dot(q, q)


def judge_vector(
    got: Sequence[Number],
    want: Sequence[Number],
    tol: float | None,
    mistakes: Sequence[tuple[Sequence[Number], str, str]] = (),
    hint: str = "",
) -> Verdict:
    """Judge a vector against the solution, with the hint that is true for it.

    Examples
    --------
    >>> want = [Fraction(0), Fraction(0), Fraction(4)]
    >>> judge_vector([0, 0, -4], want, None).hint
    'Your vector points the opposite way.'
    >>> judge_vector([0, 0, 2], want, None).hint
    'Right direction, wrong length.'
    """
    known = _right_or_listed(got, want, tol, mistakes, same_vector, _near_mistake_vector)
    if known is not None:
        return known
    g, w = [_q(x) for x in got], [_q(x) for x in want]
    if any(w) and same_vector([-x for x in g], w, tol):
        return Verdict(False, "Your vector points the opposite way.", slip="opposite-direction")
    if tol is not None and _rounded_vector(got, w):
        return Verdict(False, _rounded_hint(_coarsest(got), tol, "vector"), slip="rounded")
    if any(g) and any(w):
        sine = None if tol is None else _tol(tol)
        if _cross_zero(g, w, sine):
            same_way = _dot(g, w) > 0
            unit = _dot(w, w) == 1 or (
                tol is not None and abs(_dot(w, w) - 1) < Fraction(1, 10**12)
            )
            if not same_way:
                return Verdict(
                    False,
                    "Your vector points the opposite way, and its length differs too.",
                    slip="opposite-direction",
                )
            if unit:
                return Verdict(
                    False,
                    "Right direction, but not a unit vector: divide it by its length.",
                    slip="not-unit",
                )
            return Verdict(False, "Right direction, wrong length.", slip="wrong-length")
    if tol is None and any(w):
        err = sum(((a - b) ** 2 for a, b in zip(g, w, strict=True)), Fraction(0))
        if err <= NEAR_EXACT**2 * _dot(w, w):
            return Verdict(False, NOT_EXACT, slip="not-exact")
    return Verdict(False, hint)


def _rounded_vector(got: Sequence[Number], want: Sequence[Fraction]) -> bool:
    """Every component is the solution's, or the solution's rounded to its decimals."""
    pairs = list(zip(got, want, strict=True))
    return any(decimals(a) for a, _ in pairs) and all(
        _q(a) == b or is_rounding(a, b, fine=False) for a, b in pairs
    )


def _coarsest(xs: Sequence[Number]) -> Number:
    """Return the component written with the fewest decimals (the one the hint talks about)."""
    scored = [(d, x) for x in xs if (d := decimals(x))]
    return min(scored, key=lambda t: t[0])[1] if scored else xs[0]
