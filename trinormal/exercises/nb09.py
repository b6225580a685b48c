"""Exercises of notebook 09, shading."""

from __future__ import annotations

from fractions import Fraction

from trinormal.exercises import Exercise
from trinormal.exercises.judging import tolerance_text

#: Relative tolerance of 09-lambert.
LAMBERT_TOL = 1e-3

#: Exercise 09-front-face: the ray's direction d and the face's normal N.
RAY_D, FACE_N = (1, 2, -2), (0, 1, 3)


def _side() -> str:
    """'front' when N · d < 0 (the ray travels against the normal), else 'back'."""
    return "front" if sum(n * d for n, d in zip(FACE_N, RAY_D, strict=True)) < 0 else "back"


def _lambert() -> Fraction:
    """max(0, n · l), exactly."""
    n = (Fraction(0), Fraction(0), Fraction(1))
    light = (Fraction(0), Fraction("0.6"), Fraction("0.8"))
    dot = sum((a * b for a, b in zip(n, light, strict=True)), Fraction(0))
    return dot if dot > 0 else Fraction(0)


EXERCISES = (
    Exercise(
        "09-lambert",
        "Lambert brightness max(0, n · l) for n = (0, 0, 1) and l = (0, 0.6, 0.8) "
        f"(answers {tolerance_text(LAMBERT_TOL)} count).",
        expected=_lambert,
        tol=LAMBERT_TOL,
        hint="The dot product of the two unit vectors, clipped at zero.",
        mistakes=(
            (
                0.6,
                "That is l's y component; n · l multiplies matching components and adds.",
                "component-for-dot",
            ),
        ),
    ),
    Exercise(
        "09-front-face",
        "A ray travels in direction d = (1, 2, -2) and hits a triangle whose normal is "
        "N = (0, 1, 3). Does it hit the 'front' or the 'back'?",
        expected=_side,
        choices=("front", "back"),
        hint="Compute N · d: negative means the ray travels against the normal and meets the "
        "front; positive means it meets the back.",
    ),
)
