"""Exercises of notebook 03, the comparison table."""

from __future__ import annotations

from trinormal.core import triangle_normal
from trinormal.exercises import Exercise, raw_normal, unit
from trinormal.exercises.judging import tolerance_text

#: The fifth row of the table, for the exercises.
ROW5 = ((0, 0, 0), (0, 2, 0), (0, 0, 2))

#: Relative tolerance of 03-row5-unit (the vector has length 1: within 0.0001 per component).
UNIT_TOL = 1e-4

#: The triangle of exercise 03-collinear.
LINE = ((1, 2, 3), (2, 4, 6), (3, 6, 9))

EXERCISES = (
    Exercise(
        "03-row5-normal",
        "A fifth row: the raw normal N of (0,0,0), (0,2,0), (0,0,2).",
        expected=lambda: raw_normal(*ROW5),
        hint="Compute U = B − A and V = C − A first, then N = U × V.",
        mistakes=(
            (
                lambda: unit(raw_normal(*ROW5)),
                "Right direction, but that is the unit normal: the raw N keeps its length |N|.",
                "unit-for-raw",
            ),
            (
                lambda: raw_normal(*ROW5, winding="ACB"),
                "Your vector points the opposite way: that is V × U. N = U × V with "
                "U = B − A first.",
                "reversed-order",
            ),
        ),
    ),
    Exercise(
        "03-row5-unit",
        "The unit normal of the same triangle (answers with "
        f"{tolerance_text(UNIT_TOL, 'vector')} count: within 0.0001, as its length is 1).",
        expected=lambda: triangle_normal(*ROW5).unit_normal,
        tol=UNIT_TOL,
        hint="Divide N by |N|.",
        mistakes=(
            (
                lambda: raw_normal(*ROW5),
                "Right direction, but that is the raw N: divide it by its length |N|.",
                "raw-for-unit",
            ),
        ),
    ),
    Exercise(
        "03-collinear",
        "Is the triangle (1,2,3), (2,4,6), (3,6,9) degenerate? Answer True or False.",
        expected=lambda: triangle_normal(*LINE).degenerate,
        hint="Compare B − A with C − A: is one a multiple of the other?",
    ),
)
