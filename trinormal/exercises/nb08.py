"""Exercises of notebook 08, vertex normals."""

from __future__ import annotations

import math
from fractions import Fraction

from trinormal.exercises import Exercise


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
        "mesh.cube() (within 0.01).",
        expected=_corner_angle,
        tol=0.01,
        hint="Compute both with mesh.vertex_normals and measure the angle between them with "
        "atan2(|p × q|, p · q).",
        mistakes=(
            (
                lambda: _corner_angle(degrees=False),
                "That looks like radians: the question asks for degrees (math.degrees).",
            ),
        ),
    ),
    Exercise(
        "08-sliver-weight",
        "A sliver's corner at a vertex measures 2 degrees; a neighbouring face's corner "
        "measures 90 degrees. With angle weighting, what fraction of the total weight does "
        "the sliver get? (Within 0.001.)",
        expected=Fraction(2, 92),
        tol=1e-3,
        hint="Angle weighting weighs each face by its corner angle: divide the sliver's angle "
        "by the sum of both.",
        mistakes=(
            (0.5, "One half is what uniform weighting gives; weigh by the angles."),
            (
                Fraction(90, 92),
                "That is the neighbour's share: the sliver gets the rest, its own angle over "
                "the sum.",
            ),
        ),
    ),
)
