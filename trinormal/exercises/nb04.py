"""Exercises of notebook 04, common mistakes."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from trinormal.core import triangle_normal
from trinormal.exercises import Exercise, point_text, raw_normal, unit

#: The triangle of exercise 04-dot-value: U · V and N_z differ on purpose.
DOT_TRIANGLE = ((0, 0, 0), (2, 0, 0), (3, 1, 0))
#: The two faces of exercise 04-weighted-sum.
BIG = ((0, 0, 0), (4, 0, 0), (0, 4, 0))
SMALL = ((0, 0, 0), (0, 1, 0), (0, 0, 1))
#: The 2D triangle of exercise 04-2d-nz, as (x, y) points P, Q, R.
FLAT = ((0, 0), (0, 2), (3, 0))


def _dot_value(triangle: Any) -> Fraction:
    e = triangle_normal(*triangle).exact
    return sum((u * v for u, v in zip(e.u, e.v, strict=True)), Fraction(0))


def _add(p: tuple[Any, ...], q: tuple[Any, ...]) -> tuple[Any, ...]:
    return tuple(x + y for x, y in zip(p, q, strict=True))


def _weighted_sum() -> tuple[Fraction, ...]:
    return _add(raw_normal(*BIG), raw_normal(*SMALL))


def _flat_nz(flat: Any) -> Fraction:
    p, q, r = ((x, y, 0) for x, y in flat)
    return raw_normal(p, q, r)[2]


def dot_value_exercise(triangle: Any) -> Exercise:
    """Build 04-dot-value on a triangle (a student's own, or `DOT_TRIANGLE`)."""
    a, b, c = (point_text(p).replace(" ", "") for p in triangle)
    return Exercise(
        "04-dot-value",
        f"For A = {a}, B = {b}, C = {c}, what is U · V (the product that is not N)?",
        expected=lambda: _dot_value(triangle),
        hint="U · V = UxVx + UyVy + UzVz: multiply matching components and add.",
        mistakes=(
            (
                lambda: raw_normal(*triangle)[2],
                "That is N_z, the z component of U × V. The dot product multiplies matching "
                "components (x with x, y with y, z with z) and adds them.",
                "cross-for-dot",
            ),
        ),
    )


def flat_nz_exercise(flat: Any) -> Exercise:
    """Build 04-2d-nz on a 2D triangle (a student's own, or `FLAT`)."""
    p, q, r = (point_text(pt) for pt in flat)
    return Exercise(
        "04-2d-nz",
        f"The 2D triangle P = {p}, Q = {q}, R = {r}, placed at z = 0: what is N_z, "
        "the z component of its raw normal, for the order P → Q → R?",
        expected=lambda: _flat_nz(flat),
        hint="Add z = 0 to each point, then N_z = UxVy − UyVx with U = Q − P and V = R − P.",
        mistakes=(
            (
                lambda: -_flat_nz(flat),
                "Wrong sign. Seen from +z, does P → Q → R turn counterclockwise (positive) "
                "or clockwise?",
                "wrong-sign",
            ),
            (
                lambda: _flat_nz(flat) / abs(_flat_nz(flat)),
                "That is the unit normal's z component: the question asks for the raw N_z, "
                "whose size is twice the area.",
                "unit-for-raw",
            ),
            (
                0,
                "A flat triangle in the xy-plane has its normal along z, so N_z is not 0.",
                "zero-normal",
            ),
            (
                lambda: _flat_nz(flat) / 2,
                "That is the signed area of the triangle: the raw N_z is twice it.",
                "area-for-raw",
            ),
        ),
    )


EXERCISES = (
    dot_value_exercise(DOT_TRIANGLE),
    Exercise(
        "04-weighted-sum",
        "Add the raw normals of (0,0,0), (4,0,0), (0,4,0) and (0,0,0), (0,1,0), (0,0,1) "
        "(the area-weighted sum).",
        expected=_weighted_sum,
        hint="Compute each raw normal N = U × V, then add them component by component.",
        mistakes=(
            (
                lambda: _add(unit(raw_normal(*BIG)), unit(raw_normal(*SMALL))),
                "You added unit normals, so both faces count the same. Add the raw normals, "
                "whose lengths are twice the areas.",
                "unit-normals-summed",
            ),
            (
                lambda: tuple(x / 2 for x in _weighted_sum()),
                "That is the sum of N / 2 (the areas as vectors): add the raw normals N "
                "themselves.",
                "half-normals",
            ),
            (
                lambda: _add(raw_normal(*BIG), raw_normal(*SMALL, winding="ACB")),
                "The small face's normal is reversed: for (0,0,0), (0,1,0), (0,0,1) take "
                "U = B − A, its second point minus its first, as the first factor.",
                "reversed-order",
            ),
            (
                lambda: _add(raw_normal(*BIG, winding="ACB"), raw_normal(*SMALL)),
                "The large face's normal is reversed: for (0,0,0), (4,0,0), (0,4,0) take "
                "U = B − A, its second point minus its first, as the first factor.",
                "reversed-order",
            ),
        ),
    ),
    flat_nz_exercise(FLAT),
)
