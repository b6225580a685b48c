"""Reading truth values, one-word answers and the choice a sentence names."""

from __future__ import annotations

import re
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

from trinormal.exercises.reading.errors import AnswerError, describe, type_name
from trinormal.exercises.reading.numbers import looks_like_number

__all__ = ["read_bool", "read_choice", "read_word"]

_TRUTH_WORDS = {"true": True, "false": False}


def read_bool(x: Any) -> bool:
    """Read ``True`` or ``False`` (also numpy and sympy booleans and the words as text).

    Text may be the word alone, a sentence that starts with it (``"False, it is not
    degenerate"``), or a sentence that names one of the two words and no negation
    (``"It is true."``).

    Examples
    --------
    >>> import numpy as np
    >>> read_bool(" false "), read_bool(True), read_bool(np.array(True)), read_bool(np.bool_(False))
    (False, True, True, False)
    >>> read_bool("True, the points are on one line."), read_bool("I think it is false")
    (True, False)
    >>> read_bool("true or false?")
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: your answer names both 'true' and 'false': give one
    >>> read_bool(1)
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: answer True or False (1 is a number)
    """  # noqa: E501
    name = type_name(x)
    if name in ("bool", "bool_", "BooleanTrue", "BooleanFalse"):
        return bool(x)
    if name == "ndarray" and str(getattr(x, "dtype", "")) == "bool" and x.size == 1:
        return bool(x.reshape(-1)[0])  # np.array(True), np.array([True]): one truth value
    if isinstance(x, str):
        words = re.findall(r"[^\W\d_]+", x.lower())
        named = {w for w in words if w in _TRUTH_WORDS}
        if len(named) == 1 and words[0] in named:  # "False, it is not degenerate."
            return _TRUTH_WORDS[words[0]]
        if named:  # "It is true." (a sentence naming both, or with a negation, is not read)
            return _TRUTH_WORDS[read_choice(x, ("true", "false"))]
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


#: Words that turn a sentence around ("not the back"): such a sentence is not read as a choice.
_NEGATIONS = re.compile(r"\b(?:not|no|never|neither|nor)\b|n['’]t\b")


def read_choice(x: Any, choices: Sequence[str]) -> str:
    """Read which one of ``choices`` an answer names: one word, or a sentence naming one.

    The answer may be the word alone (``"Front"``) or a sentence that names exactly
    one of the choices (``"the front side"``, ``"It is the front."``). A sentence
    naming two of them, or with a negation ("not the back"), is not read: it is
    not clear which one is meant.

    Raises
    ------
    AnswerError
        When no choice, or more than one, is named, or a negation makes it unclear.

    Examples
    --------
    >>> read_choice("It is the FRONT.", ("front", "back"))
    'front'
    >>> read_choice("front or back", ("front", "back"))
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: your answer names both 'front' and 'back': give one
    """  # noqa: E501
    listed = " or ".join(repr(c) for c in choices)
    if not isinstance(x, str):
        raise AnswerError(f"answer with a word in quotes: {listed}")
    words = re.findall(r"[^\W\d_]+", x.lower())
    named = [c for c in choices if c.lower() in words]
    if len(named) > 1:
        both = " and ".join(repr(c) for c in named)
        raise AnswerError(f"your answer names both {both}: give one")
    if not named:
        raise AnswerError(f"answer {listed}")
    if _NEGATIONS.search(x.lower()):
        raise AnswerError(f"say which one it is, without a negation: {listed}")
    return named[0]
