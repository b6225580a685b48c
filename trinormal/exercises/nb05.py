"""Exercises of notebook 05, the explorer.

Every answer is read exactly, so ``C = (Fraction(5, 3), Fraction(7, 3), Fraction(1, 3))``
or ``("5/3", "7/3", "1/3")`` is on the line through A and B, as it should be.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from trinormal.core import triangle_normal
from trinormal.display import format_vector
from trinormal.exercises import AnswerError, Exercise, read_number, read_points

#: Two vertices given in exercise 05-collinear; the student supplies the third.
COLLINEAR_AB: tuple[tuple[int, int, int], tuple[int, int, int]] = ((1, 2, 0), (3, 3, 1))

#: The triangle scaled in exercise 05-scale-area, and the factor.
SCALE_ABC: tuple[tuple[int, int, int], tuple[int, int, int], tuple[int, int, int]] = (
    (1, 0, 2),
    (3, 1, 0),
    (-1, 2, 1),
)
SCALE_FACTOR = 3


def _check_down_acb(answer: Any) -> bool | tuple[bool, str]:
    try:
        a, b, c = read_points(answer, 3)
    except AnswerError as error:
        return False, f"Your answer could not be read: {error}."
    r = triangle_normal(a, b, c, winding="ACB")
    if r.degenerate or r.unit_normal is None:
        return False, "These points make no triangle (zero area), so there is no normal at all."
    if r.unit_normal == (0.0, 0.0, -1.0):
        return True
    if r.unit_normal == (0.0, 0.0, 1.0):
        return False, "In the order A→C→B your normal points up (+z): swap B and C."
    return False, (
        "The normal must have no x or y part: put all three points at the same height z, "
        "then check the order A→C→B with the right-hand rule."
    )


def _check_collinear(answer: Any) -> bool | tuple[bool, str]:
    try:
        (c,) = read_points([answer], 1)
    except AnswerError as error:
        return False, f"Your answer could not be read: {error}."
    a, b = COLLINEAR_AB
    if c in (tuple(map(Fraction, a)), tuple(map(Fraction, b))):
        return False, "C must be a new point, not A or B again (that is the easy way to area 0)."
    # default tolerance: an exact answer must be on the line; a float within rounding counts
    if triangle_normal(a, b, c).degenerate:
        return True
    direction = format_vector([q - p for p, q in zip(a, b, strict=True)], 0, trim=True)
    return False, f"Not on the line yet: C − A must be a multiple of B − A = {direction}."


def _area_factor() -> Fraction:
    """Measure area(kA, kB, kC) / area(A, B, C) exactly: the square root of the |N|² ratio."""
    a, b, c = SCALE_ABC
    k = SCALE_FACTOR
    before = triangle_normal(a, b, c).exact.magnitude_squared
    ka, kb, kc = (tuple(k * x for x in p) for p in SCALE_ABC)
    after = triangle_normal(ka, kb, kc).exact.magnitude_squared
    ratio = after / before
    root = Fraction(math.isqrt(ratio.numerator), math.isqrt(ratio.denominator))
    if root * root != ratio:  # pragma: no cover - scaling by an integer keeps it a square
        raise ArithmeticError(f"the area ratio {ratio} is not a perfect square")
    return root


def _check_scale_area(answer: Any) -> bool | tuple[bool, str]:
    if not isinstance(answer, str) and hasattr(answer, "__len__"):
        return False, "Answer with one number, not a vector."
    try:
        value = read_number(answer)
    except AnswerError as error:
        return False, f"Answer with one number: {error}."
    if value == _area_factor():
        return True
    if value == SCALE_FACTOR:
        return False, "Each edge grows by that factor, but the area is a product of two edges."
    if value == SCALE_FACTOR**3:
        return False, "That is how a volume grows (three lengths); an area is two lengths."
    return False, (
        "Compute the area before and after (triangle_normal(...).area, or the explorer's "
        "readout) and divide the one by the other."
    )


def _on_the_line() -> tuple[Fraction, ...]:
    a, b = COLLINEAR_AB
    return tuple(p + Fraction(1, 3) * (q - p) for p, q in zip(a, b, strict=True))


EXERCISES = (
    Exercise(
        "05-down-acb",
        "Give three points (A, B, C) whose unit normal in the order A→C→B is exactly "
        "(0, 0, −1): the triangle faces straight down when it is walked A→C→B.",
        checker=_check_down_acb,
        example=((0, 0, 1), (1, 0, 1), (0, 1, 1)),
    ),
    Exercise(
        "05-collinear",
        f"A = {COLLINEAR_AB[0]} and B = {COLLINEAR_AB[1]}. Give a point C, different from both, "
        "that makes the area 0 (exact numbers must be exactly on the line; floats count when "
        "the sine of the angle at A is at most trinormal's default tolerance, 1e-12).",
        checker=_check_collinear,
        example=_on_the_line,
    ),
    Exercise(
        "05-scale-area",
        f"Multiply every coordinate of A = {SCALE_ABC[0]}, B = {SCALE_ABC[1]}, "
        f"C = {SCALE_ABC[2]} by {SCALE_FACTOR}. By what number is the area multiplied?",
        checker=_check_scale_area,
        example=_area_factor,
    ),
)
