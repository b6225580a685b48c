"""Reading truth values and one-word answers."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from trinormal.exercises.reading.errors import AnswerError, describe, type_name
from trinormal.exercises.reading.numbers import looks_like_number

__all__ = ["read_bool", "read_word"]

_TRUTH_WORDS = {"true": True, "false": False}


def read_bool(x: Any) -> bool:
    """Read ``True`` or ``False`` (also numpy and sympy booleans and the words as text).

    Examples
    --------
    >>> read_bool(" false "), read_bool(True)
    (False, True)
    >>> read_bool(1)
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: answer True or False (1 is a number)
    """
    name = type_name(x)
    if name in ("bool", "bool_", "BooleanTrue", "BooleanFalse"):
        return bool(x)
    if isinstance(x, str) and x.strip().lower() in _TRUTH_WORDS:
        return _TRUTH_WORDS[x.strip().lower()]
    if isinstance(x, int | float | Fraction) or looks_like_number(x):
        raise AnswerError(f"answer True or False ({describe(x)} is a number)")
    raise AnswerError("answer True or False")


_FILLER = frozenset({"the", "a", "face", "side"})


def read_word(x: Any) -> str:
    """Read a one-word answer: lower case, without "the" or "face"/"side" around it.

    Examples
    --------
    >>> read_word("  The Left side ")
    'left'
    """
    if not isinstance(x, str):
        raise AnswerError("answer with a word, in quotes")
    words = [w for w in x.strip().lower().strip(".!").split() if w not in _FILLER]
    return " ".join(words)
