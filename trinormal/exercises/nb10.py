"""Exercises of notebook 10, transforms."""

from __future__ import annotations

from trinormal.exercises import Exercise, unit
from trinormal.exercises.judging import tolerance_text

#: Relative tolerance of 10-scaled-normal (length 1: within 0.0001 per component).
UNIT_TOL = 1e-4

#: Exercise 10-det-cross: M = diag(2, 3, 4), U = (1, 0, 0), V = (0, 1, 0).
DIAG = (2, 3, 4)


def _det_cross() -> tuple[int, int, int]:
    mu, mv = (DIAG[0], 0, 0), (0, DIAG[1], 0)
    return (
        mu[1] * mv[2] - mu[2] * mv[1],
        mu[2] * mv[0] - mu[0] * mv[2],
        mu[0] * mv[1] - mu[1] * mv[0],
    )


EXERCISES = (
    Exercise(
        "10-scaled-normal",
        "A plane has unit normal (1, 1, 0)/√2. Scale x by 2. What is its new unit normal? "
        f"(Answers with {tolerance_text(UNIT_TOL, 'vector')} count: within 0.0001, as its "
        "length is 1.)",
        expected=lambda: unit((1 / 2, 1, 0)),
        tol=UNIT_TOL,
        hint="Transform the normal by the inverse transpose, then normalise.",
        mistakes=(
            (
                lambda: unit((2, 1, 0)),
                "That is M n normalised: the normal moved like a point. Use M⁻ᵀ, the "
                "inverse transpose, instead.",
                "normal-as-point",
            ),
            (
                (1 / 2, 1, 0),
                "Right direction, but not a unit vector yet: divide by its length.",
                "not-unit",
            ),
            (
                lambda: unit((1, 1, 0)),
                "That is the normal before the scale: stretching x tilts the plane, so its "
                "normal changes too.",
                "untransformed",
            ),
        ),
    ),
    Exercise(
        "10-det-cross",
        "For M = diag(2, 3, 4), U = (1, 0, 0), V = (0, 1, 0): what is (MU) × (MV)?",
        expected=_det_cross,
        hint="Transform U and V first (MU and MV), then take their cross product.",
        mistakes=(
            (
                (0, 0, 24),
                "That is det(M) · (U × V). The identity is det(M) · M⁻ᵀ (U × V): apply M⁻ᵀ "
                "too, or compute MU and MV and cross them.",
                "no-inverse-transpose",
            ),
            (
                (0, 0, 1),
                "That is U × V before the transform: transform U and V first.",
                "untransformed",
            ),
            (
                (0, 0, -6),
                "Your vector points the opposite way: det(M) is positive, so the transform "
                "keeps the orientation.",
                "reversed-order",
            ),
        ),
    ),
)
