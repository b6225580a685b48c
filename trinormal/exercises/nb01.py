"""Exercises of notebook 01, the worked example."""

from __future__ import annotations

from typing import Any

from trinormal.core import triangle_normal
from trinormal.exercises import Exercise, point_text, raw_normal, unit
from trinormal.exercises.judging import tolerance_text

#: The exercise triangle: A = (1, 0, 0), B = (0, 1, 0), C = (0, 0, 1).
TRIANGLE = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
#: Relative tolerance of 01-area (three significant digits count, two do not).
AREA_TOL = 1e-3


def exercises_for(triangle: tuple[Any, Any, Any]) -> tuple[Exercise, ...]:
    """Build the notebook's three exercises on one triangle (a student's own, or `TRIANGLE`)."""
    a, b, c = (point_text(p) for p in triangle)

    def _area() -> float:
        return triangle_normal(*triangle).area

    return (
        Exercise(
            "01-normal",
            f"Compute N = (B − A) × (C − A) for A = {a}, B = {b}, C = {c}.",
            expected=lambda: raw_normal(*triangle),
            hint="Find U = B − A and V = C − A first, then "
            "N = (UyVz − UzVy, UzVx − UxVz, UxVy − UyVx).",
            mistakes=(
                (
                    lambda: raw_normal(*triangle, winding="ACB"),
                    "Your vector points the opposite way: that is (C − A) × (B − A). "
                    "Keep U = B − A as the first factor.",
                    "reversed-order",
                ),
                (
                    lambda: unit(raw_normal(*triangle)),
                    "Right direction, but that is the unit normal N / |N|; "
                    "this question asks for N itself.",
                    "unit-for-raw",
                ),
            ),
        ),
        Exercise(
            "01-area",
            f"The area of the same triangle (answers {tolerance_text(AREA_TOL)} count).",
            expected=_area,
            tol=AREA_TOL,
            hint="The area is |N| / 2, and |N| is the square root of the sum of N's squared "
            "components.",
            mistakes=(
                (
                    lambda: 2 * _area(),
                    "That is |N|, the parallelogram's area: the triangle is half of it.",
                    "magnitude-for-area",
                ),
                (
                    lambda: _area() / 2,
                    "That is half the area: |N| is already twice the area, so halve it only once.",
                    "half-area",
                ),
                (
                    lambda: 4 * _area() ** 2,
                    "That is |N|², the sum of the squares: take its square root, then halve it.",
                    "squared-magnitude",
                ),
            ),
        ),
        Exercise(
            "01-reversed",
            "N for the same points taken in the order A → C → B.",
            expected=lambda: raw_normal(*triangle, winding="ACB"),
            hint="Swapping the two edges swaps the factors of the cross product.",
            mistakes=(
                (
                    lambda: raw_normal(*triangle),
                    "That is N for the order A → B → C. In the order A → C → B the first "
                    "edge is C − A.",
                    "reversed-order",
                ),
            ),
        ),
    )


EXERCISES = exercises_for(TRIANGLE)
