"""Exercises of notebook 06, float precision."""

from __future__ import annotations

import math

from trinormal.exercises import Exercise
from trinormal.exercises.judging import tolerance_text

#: Relative tolerance of 06-float64-digits: tight enough that the slip of counting the stored
#: bits only (52 instead of 53) and the whole numbers around the answer fail.
DIGITS_TOL = 1e-3


def _bits(dtype: str = "float64") -> int:
    """Count the significand bits of a float type, the implicit leading bit included."""
    import numpy as np

    return int(np.finfo(dtype).nmant) + 1


def _digits(dtype: str = "float64") -> float:
    return _bits(dtype) * math.log10(2)


EXERCISES = (
    Exercise(
        "06-float64-bits",
        "How many significand bits does a float64 carry (numpy.finfo helps)?",
        expected=_bits,
        hint="np.finfo(np.float64).nmant counts the stored bits; add the implicit leading bit.",
        mistakes=(
            (
                lambda: _bits() - 1,
                "That is nmant, the stored bits: one more leading bit is implicit.",
                "implicit-bit-missed",
            ),
            (
                64,
                "64 is the whole format, sign and exponent included: count the significand.",
                "whole-format",
            ),
        ),
    ),
    Exercise(
        "06-float64-digits",
        "How many decimal digits does a float64 carry: p · log10(2), p being its number of "
        f"significand bits? (Answers {tolerance_text(DIGITS_TOL)} count.)",
        expected=_digits,
        tol=DIGITS_TOL,
        hint="Each significand bit is worth log10(2) decimal digits: count the bits, then "
        "multiply.",
        mistakes=(
            (
                _bits,
                "That is the number of bits: multiply it by log10(2).",
                "bits-for-digits",
            ),
            (
                lambda: (_bits() - 1) * math.log10(2),
                "That counts the stored bits (nmant) only: p includes the implicit leading bit.",
                "implicit-bit-missed",
            ),
            (
                lambda: math.ceil(_digits()),
                "That is p · log10(2) rounded up to a whole number: give the value itself.",
                "rounded-up",
            ),
            (
                lambda: math.floor(_digits()),
                "That is p · log10(2) rounded down to a whole number: give the value itself.",
                "rounded-down",
            ),
            (
                lambda: _digits("float32"),
                "That is float32's count, from its 24 significand bits: a float64 has more.",
                "float32",
            ),
            (
                lambda: round(_digits("float32")),
                "That is about float32's count, from its 24 significand bits: a float64 has more.",
                "float32",
            ),
            (
                17,
                "17 digits are what it takes to write any float64 so that it reads back "
                "exactly; the digits it carries are fewer: count log10(2) per significand bit.",
                "round-trip-digits",
            ),
        ),
    ),
)
