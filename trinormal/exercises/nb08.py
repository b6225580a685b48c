"""Exercises of notebook 08, vertex normals."""

from __future__ import annotations

import math
from fractions import Fraction

from trinormal.exercises import Exercise
from trinormal.exercises.judging import tolerance_text

#: Relative tolerance of 08-cube-corner-degrees.
ANGLE_TOL = 5e-4
#: Relative tolerance of 08-sliver-weight: tight enough that 2/90 (the wrong sum) fails.
WEIGHT_TOL = 5e-3


def _corner_angle(degrees: bool = True) -> float:
    import numpy as np

    from trinormal import mesh

    v, f = mesh.cube()
    a = mesh.vertex_normals(v, f, "angle")[7]
    b = mesh.vertex_normals(v, f, "area")[7]
    angle = math.atan2(float(np.linalg.norm(np.cross(a, b))), float(a @ b))
    return math.degrees(angle) if degrees else angle


EXERCISES = (
    Exercise(
        "08-cube-corner-degrees",
        "Angle in degrees between the area- and angle-weighted normals at vertex 7 of "
        f"mesh.cube() (answers {tolerance_text(ANGLE_TOL)} count; text may end in °).",
        expected=_corner_angle,
        tol=ANGLE_TOL,
        degrees=True,
        hint="Compute both with mesh.vertex_normals and measure the angle between them with "
        "atan2(|p × q|, p · q).",
        mistakes=(
            (
                lambda: _corner_angle(degrees=False),
                "That looks like radians: the question asks for degrees (math.degrees).",
                "radians-for-degrees",
            ),
            (
                lambda: 90 - _corner_angle(),
                "That is 90° minus the angle between the two normals: measure the angle "
                "between the normals themselves.",
                "complement-angle",
            ),
        ),
    ),
    Exercise(
        "08-sliver-weight",
        "A sliver's corner at a vertex measures 2 degrees; a neighbouring face's corner "
        "measures 90 degrees. With angle weighting, what fraction of the total weight does "
        f"the sliver get? (Answers {tolerance_text(WEIGHT_TOL)} count.)",
        expected=Fraction(2, 92),
        tol=WEIGHT_TOL,
        hint="Angle weighting weighs each face by its corner angle: divide the sliver's angle "
        "by the sum of both.",
        mistakes=(
            (
                0.5,
                "One half is what uniform weighting gives; weigh by the angles.",
                "uniform-weight",
            ),
            (
                Fraction(2, 90),
                "That divides by the neighbour's angle alone: divide by the sum of both "
                "angles, the sliver's included.",
                "neighbour-angle-only",
            ),
            (
                Fraction(2, 88),
                "That divides by the difference of the angles: divide by their sum.",
                "angle-difference",
            ),
            (
                Fraction(90, 92),
                "That is the neighbour's share: the sliver gets the rest, its own angle over "
                "the sum.",
                "neighbour-share",
            ),
        ),
    ),
)
