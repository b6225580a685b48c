"""Exercises of notebook 07, the limits of precision."""

from __future__ import annotations

from trinormal.core import triangle_normal
from trinormal.exercises import Exercise

#: The needle of exercise 07-needle-degenerate.
NEEDLE = ((0, 0, 0), (1, 0, 0), (2, 3e-12, 0))

EXERCISES = (
    Exercise(
        "07-needle-degenerate",
        "With the default tol, is (0,0,0), (1,0,0), (2,3e-12,0) degenerate? (True/False)",
        expected=lambda: triangle_normal(*NEEDLE).degenerate,
        hint="Compute |N| and the longest of the three sides, L, then compare |N| / L² with "
        "DEFAULT_TOL = 1e-12: degenerate means |N| <= tol · L², whichever corner comes first.",
    ),
)
