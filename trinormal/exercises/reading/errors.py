"""What a reader says when it cannot read an answer: `AnswerError` and its messages."""

from __future__ import annotations

import math
from collections.abc import Callable, Sized
from typing import Any, TypeVar

__all__ = ["TOO_DEEP", "AnswerError", "check_count", "describe", "guarded", "type_name", "why"]

T = TypeVar("T")

#: The message for an answer nested so deeply (lists in lists...) that reading it recurses too far.
TOO_DEEP = "this answer is nested too deeply to read"


class AnswerError(ValueError):
    """An answer that cannot be read as what the exercise asks for; the message says why."""


def describe(x: Any, limit: int = 40) -> str:
    """Return a short, safe ``repr`` of ``x`` for a message (never raises).

    Examples
    --------
    >>> describe("a" * 100)
    "'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa…"
    >>> describe(10**5000)
    'an int of about 5000 digits'
    """
    if type(x) is int and x.bit_length() > 128:  # repr of a huge int is long or refused
        return f"an int of about {round(x.bit_length() * math.log10(2))} digits"
    try:
        text = repr(x)
    except Exception:  # an object whose __repr__ raises still gets a name
        text = f"a {type_name(x)}"
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def type_name(x: Any) -> str:
    """Return the name of ``x``'s type (never raises)."""
    try:
        return type(x).__name__
    except Exception:  # pragma: no cover - type() of anything has a name
        return "object"


def why(exc: BaseException) -> str:
    """Name an exception and its message, for the end of an `AnswerError`'s message."""
    text = str(exc)
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def guarded(read: Callable[[], T], x: Any, what: str) -> T:
    """Return ``read()``; any exception it raises but an `AnswerError` becomes one.

    An object that misbehaves when asked what it is (a ``__len__`` or
    ``__float__`` that raises, endless nesting) gets a message naming it and
    ``what`` it could not be read as, never the exception itself.

    Examples
    --------
    >>> guarded(lambda: 1 / 0, "1/0", "a number")
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: '1/0' could not be read as a number (ZeroDivisionError: division by zero)
    """  # noqa: E501
    try:
        return read()
    except AnswerError:
        raise
    except RecursionError:
        raise AnswerError(TOO_DEEP) from None
    except Exception as exc:  # an object that misbehaves when asked what it is
        raise AnswerError(f"{describe(x)} could not be read as {what} ({why(exc)})") from None


def check_count(items: Sized, count: int, expected: str) -> None:
    """Raise an `AnswerError` unless there are ``count`` items: "``expected``, got 2".

    The reader takes at most ``count + 1`` items from an iterator (a generator
    may never end), so more than ``count`` is said as "more than".
    """
    if len(items) != count:
        got = f"more than {count}" if len(items) > count else str(len(items))
        raise AnswerError(f"{expected}, got {got}")
