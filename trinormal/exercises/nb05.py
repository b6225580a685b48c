"""Exercises of notebook 05, the explorer.

The two exercises about exact properties (a normal exactly straight down, a
point exactly on a line) compute with the exact core: exact answers (integers,
fractions, decimal text) are judged exactly, and a near miss is told how far
off it is.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import partial
from typing import Any

from trinormal.core import triangle_normal
from trinormal.display import format_number, format_surd
from trinormal.exercises import AnswerError, Exercise, Verdict, point_text, read_points, read_vector
from trinormal.exercises.reading import is_exact
from trinormal.tolerances import DEFAULT_TOL

#: Two vertices given in exercise 05-collinear; the student supplies the third.
COLLINEAR_AB: tuple[tuple[int, int, int], tuple[int, int, int]] = ((1, 2, 0), (3, 3, 1))

#: The triangle scaled in exercise 05-scale-area, and the factor: the scaled triangle fits the
#: explorer's default range (-5 to 5), so a student can type it in the boxes.
SCALE_ABC: tuple[tuple[int, int, int], tuple[int, int, int], tuple[int, int, int]] = (
    (1, 0, 1),
    (1, 1, 0),
    (-1, 1, 1),
)
SCALE_FACTOR = 3
#: The explorer's default range (``Explorer(min=-5, max=5)``): every coordinate 05-scale-area
#: asks a student to type, in the notebook and in each student's variant, lies within it.
EXPLORER_RANGE = 5


def _unreadable(error: Exception) -> Verdict:
    return Verdict(False, f"Your answer could not be read: {error}.", slip="unreadable")


def _check_down_acb(answer: Any) -> Verdict:
    """Judged exactly: the exact normal in the order A→C→B must be (0, 0, negative)."""
    try:
        a, b, c = read_points(answer, 3)
        r = triangle_normal(a, b, c, winding="ACB")
    except (AnswerError, ValueError, TypeError) as error:
        return _unreadable(error)
    nx, ny, nz = r.exact.normal
    if nx == ny == nz == 0:
        return Verdict(
            False,
            "These points make no triangle: they lie on one line (or two of them coincide), "
            "so the area is exactly 0 and there is no normal at all.",
            slip="degenerate",
        )
    if nx == 0 and ny == 0:
        if nz > 0:
            return Verdict(
                False,
                "In the order A→C→B your normal points straight up (+z): swap B and C.",
                slip="reversed-order",
            )
        note = ""
        if r.degenerate:
            note = (
                "Exactly, it faces straight down; but its height is only "
                f"{format_number(r.thickness, 2)} times its longest side, at most trinormal's "
                f"tolerance {format_number(DEFAULT_TOL, 0)}, so triangle_normal calls it "
                "degenerate: a fatter triangle is safer."
            )
        return Verdict(True, note=note)
    off = _angle_from_down(nx, ny, nz)
    return Verdict(
        False,
        f"In the order A→C→B your normal is {off} away from straight down: it must have no x or "
        "y part. Put all three points at the same height z, then check the order A→C→B with "
        "the right-hand rule.",
        slip="tilted",
    )


def _angle_from_down(nx: Fraction, ny: Fraction, nz: Fraction) -> str:
    """Return the angle between (nx, ny, nz) and (0, 0, −1), in degrees, as text."""
    scale = max(abs(nx), abs(ny), abs(nz))
    side = math.hypot(float(nx / scale), float(ny / scale))
    if side == 0:  # below the smallest float, but not exactly 0
        return "less than 1e-300°"
    degrees = math.degrees(math.atan2(side, float(-nz / scale)))
    return f"{format_number(degrees, 2)}°"


def _check_collinear(answer: Any, ab: tuple[Any, Any] = COLLINEAR_AB) -> Verdict:
    """Exact inputs are judged exactly; floats within the stated tolerance."""
    try:
        c = tuple(read_vector(answer))
        r = triangle_normal(*ab, c)
    except (AnswerError, ValueError, TypeError) as error:
        return _unreadable(error)
    a, b = ab
    if c in (tuple(map(Fraction, a)), tuple(map(Fraction, b))):
        return Verdict(
            False, "C must be a new point, not A or B again (that is the easy way to area 0)."
        )
    distance = _distance_to_line(r.exact.magnitude_squared, ab)
    if r.exact.magnitude_squared == 0:
        return Verdict(True)
    exact_input = all(is_exact(x) for x in c)
    if not exact_input and r.degenerate:
        return Verdict(
            True,
            note=f"(As floats, C is {distance} from the line: within the tolerance for floats.)",
        )
    rule = "exact numbers must be exactly on it" if exact_input else "too far for a float"
    return Verdict(
        False,
        f"C is {distance} away from the line through A and B ({rule}): C − A must be a "
        "multiple of B − A.",
    )


def _distance_to_line(magnitude_squared: Fraction, ab: Any) -> str:
    """|N| / |B − A|: how far C is from the line through A and B."""
    a, b = ab
    ab2 = sum((q - p) ** 2 for p, q in zip(a, b, strict=True))
    q = Fraction(magnitude_squared) / ab2
    return format_surd(False, q.numerator, q.denominator, 2)


def _area_factor(abc: Any, k: int) -> Fraction:
    """Measure area(kA, kB, kC) / area(A, B, C) exactly: the square root of the |N|² ratio."""
    a, b, c = abc
    before = triangle_normal(a, b, c).exact.magnitude_squared
    ka, kb, kc = (tuple(k * x for x in p) for p in abc)
    after = triangle_normal(ka, kb, kc).exact.magnitude_squared
    ratio = after / before
    root = Fraction(math.isqrt(ratio.numerator), math.isqrt(ratio.denominator))
    if root * root != ratio:  # pragma: no cover - scaling by an integer keeps it a square
        raise ArithmeticError(f"the area ratio {ratio} is not a perfect square")
    return root


def _on_the_line(ab: Any) -> tuple[Fraction, ...]:
    a, b = ab
    return tuple(p + Fraction(1, 3) * (q - p) for p, q in zip(a, b, strict=True))


def collinear_exercise(ab: tuple[Any, Any]) -> Exercise:
    """Build 05-collinear on two points A, B (a student's own, or `COLLINEAR_AB`)."""
    return Exercise(
        "05-collinear",
        f"A = {point_text(ab[0])} and B = {point_text(ab[1])}. Give a point C, different from "
        "both, that makes the area 0 (exact numbers must be exactly on the line; floats count when "
        "the triangle is thin compared with its longest side: its height at most "
        "trinormal's default tolerance, 1e-12, times that side).",
        checker=partial(_check_collinear, ab=ab),
        example=partial(_on_the_line, ab),
    )


def scale_area_exercise(abc: Any, k: int) -> Exercise:
    """Build 05-scale-area on a triangle and a whole factor (a student's own, or the notebook's)."""
    a, b, c = (point_text(p) for p in abc)
    return Exercise(
        "05-scale-area",
        f"Multiply every coordinate of A = {a}, B = {b}, "
        f"C = {c} by {k}. By what number is the area multiplied?",
        expected=partial(_area_factor, abc, k),
        hint="Compute the area before and after (triangle_normal(...).area, or the explorer's "
        "readout) and divide the one by the other.",
        mistakes=(
            (
                k,
                "Each edge grows by that factor, but the area is a product of two edges.",
                "linear-scaling",
            ),
            (
                k**3,
                "That is how a volume grows (three lengths); an area is two lengths.",
                "cubic-scaling",
            ),
            (
                Fraction(1, k**2),
                "That is the factor from the new area back to the old one: divide the new "
                "area by the old.",
                "inverse-factor",
            ),
        ),
    )


EXERCISES = (
    Exercise(
        "05-down-acb",
        "Give three points (A, B, C) whose unit normal in the order A→C→B is exactly "
        "(0, 0, −1): the triangle faces straight down when it is walked A→C→B.",
        checker=_check_down_acb,
        example=((0, 0, 1), (1, 0, 1), (0, 1, 1)),
    ),
    collinear_exercise(COLLINEAR_AB),
    scale_area_exercise(SCALE_ABC, SCALE_FACTOR),
)
