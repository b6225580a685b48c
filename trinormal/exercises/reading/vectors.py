"""Reading vectors and lists of points (or of faces): tuples, arrays, matrices, text."""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from trinormal.exercises.reading.errors import AnswerError, check_count, describe, guarded
from trinormal.exercises.reading.numbers import (
    DECIMAL_COMMA,
    Number,
    leaves,
    looks_like_number,
    module_of,
    read_number,
)
from trinormal.exercises.reading.text import closing, plain_text, split_top

__all__ = ["FACES", "POINTS", "Items", "read_points", "read_vector"]

AXIS_NAMES = ("x", "y", "z")


def _items(x: Any, size: int, what: str) -> list[Any]:
    """Return the elements of a vector-like answer, before each is read as a number."""
    if x is None:
        raise AnswerError(f"None is not {what}")
    if isinstance(x, str):
        return _text_items(x)
    if isinstance(x, bytes | bytearray | memoryview):
        raise AnswerError(f"bytes are not {what}")
    if isinstance(x, dict):
        raise AnswerError(f"a dict is not {what}: write it as a tuple")
    if isinstance(x, set | frozenset):
        raise AnswerError(f"a set has no order, so it is not {what}: write it as a tuple")
    module = module_of(x)
    if module.startswith("numpy"):
        import numpy as np

        if isinstance(x, np.ndarray):
            x = np.asarray(x)  # a numpy.matrix too: a plain array of its shape
            if x.ndim == 0:
                raise AnswerError(f"expected {what}, got one number")
            if x.ndim == 2 and 1 in x.shape:
                return list(x.reshape(-1))
            if x.ndim != 1:
                raise AnswerError(f"expected {what}, got an array of shape {x.shape}")
            return list(x)
        raise AnswerError(f"expected {what}, got one number")
    if module.startswith("sympy"):
        if getattr(x, "is_Matrix", False):
            rows, cols = x.shape
            if rows == 1 or cols == 1:
                return list(x)
            raise AnswerError(f"expected {what}, got a {rows} × {cols} matrix")
        shape = tuple(getattr(x, "shape", ()) or ())
        if hasattr(x, "tolist") and (len(shape) == 1 or (len(shape) == 2 and 1 in shape)):
            return list(leaves(x.tolist()))  # a sympy Array of shape (3,), (3, 1) or (1, 3)
        if shape:
            raise AnswerError(f"expected {what}, got an array of shape {shape}")
        raise AnswerError(f"expected {what}, got one value")
    if isinstance(x, int | float | complex | Fraction) or looks_like_number(x):
        raise AnswerError(f"expected {what}, got one number")
    if not isinstance(x, Iterable) and not hasattr(x, "__getitem__"):
        raise AnswerError(f"expected {what}, got {describe(x)}")
    return list(itertools.islice(iter(x), size + 1))  # a generator may never end


_BRACKETS = "()[]{}⟨⟩"
_OPEN, _CLOSE = "([{⟨", ")]}⟩"
#: One number in a vector written with spaces between its components: ``0,5``, ``-2``, ``1/3``.
_SPACED_NUMBER = re.compile(r"[+\-−]?\d+(?:[.,]\d+)?(?:/\d+)?")
#: What may join a factor to a vector: ``2*(1, 0, 0)``, ``(1, 0, 0)/√2``.
_TIMES = "*·×"


def _text_items(text: str) -> list[str]:
    """Return the components of a vector typed as text, each as text for `read_number`."""
    s = plain_text(text).strip()
    scaled = _scaled(s)
    if scaled is not None:
        return scaled
    while len(s) >= 2 and s[0] in _OPEN and closing(s, 0) == len(s) - 1:
        s = s[1:-1].strip()
    return _components(s)


def _components(body: str) -> list[str]:
    """Split the inside of a vector's brackets into its components.

    A comma separates components, unless ``;`` does (then a comma is a decimal
    comma: ``0,5; 1; 0``) or spaces do between numbers with decimal commas
    (``0,5 1 0``).
    """
    if not body:
        return []
    if len(split_top(body, ";")) > 1:
        return [_point(p) for p in split_top(body, ";")]
    parts = split_top(body, ",")
    if len(parts) > 1:
        tokens = body.split()
        spaced = len(tokens) > 1 and any(" " in p for p in parts)
        if spaced and all(_SPACED_NUMBER.fullmatch(t) for t in tokens):
            return [_point(t) for t in tokens]
        return parts
    if any(b in body for b in _BRACKETS):
        return [body]
    return body.split()


def _point(part: str) -> str:
    """Write a component typed with a decimal comma (``0,5``) with a point."""
    return part.replace(",", ".") if DECIMAL_COMMA.fullmatch(part.strip()) else part


def _scaled(s: str) -> list[str] | None:
    """Read ``2*(1, 0, 0)`` or ``(0, -1, 1)/sqrt(2)``: each component with the factor.

    Returns None unless the text is a bracketed vector with a factor before or after it.
    """
    i = 0
    while i < len(s):
        end = closing(s, i) if s[i] in "([" else -1
        if end < 0:
            i += 1
            continue
        function = re.search(r"[A-Za-z_][A-Za-z_0-9]*\s*$", s[:i])
        parts = _components(s[i + 1 : end].strip())
        if function is None and len(parts) > 1:
            return _times(s[:i].strip(), parts, s[end + 1 :].strip())
        i = end + 1  # a function's arguments, or one value in brackets: look further on
    return None


def _times(before: str, parts: list[str], after: str) -> list[str] | None:
    """Write each component with the factor before (``2*``) and after (``/√2``) the vector."""
    if not before and not after:
        return None
    if after and after[0] not in "/" + _TIMES:
        return None
    factor = before.rstrip(_TIMES + " ")
    if factor and before[-1:] not in _TIMES and not (factor[-1:].isdigit() or factor[-1:] == ")"):
        return None
    return [f"{factor}*({p}){after}" if factor else f"({p}){after}" for p in parts]


def read_vector(x: Any, size: int = 3, *, degrees: bool = False) -> list[Number]:
    """Read a vector of ``size`` numbers.

    Parameters
    ----------
    x : object
        A tuple, list, generator, numpy array (``(3,)``, ``(3, 1)`` or
        ``(1, 3)``), row or column sympy matrix, or text such as ``"(1, 0, 2)"``.
    size : int, default 3
        How many numbers.
    degrees : bool, default False
        Passed on to `read_number` for each component.

    Returns
    -------
    list of Fraction or float

    Raises
    ------
    AnswerError
        Naming the component that cannot be read, or saying how many there are.

    Examples
    --------
    >>> read_vector(("2/7", 0, "-1.5"))
    [Fraction(2, 7), Fraction(0, 1), Fraction(-3, 2)]
    >>> read_vector([1, 2])
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: expected 3 numbers (x, y, z), got 2
    """
    what = f"{size} numbers (x, y, z)" if size == 3 else f"{size} numbers"
    items = guarded(lambda: _vector_items(x, size, what), x, what)
    check_count(items, size, f"expected {what}")
    out = []
    for i, item in enumerate(items):
        name = AXIS_NAMES[i] if size == 3 else str(i + 1)
        try:
            out.append(read_number(item, degrees=degrees))
        except AnswerError as exc:
            raise AnswerError(f"{name}: {exc}") from None
    return out


def _vector_items(x: Any, size: int, what: str) -> list[Any]:
    """Return the elements of a vector, also of one given as a row inside a list."""
    items = _items(x, size, what)
    if len(items) == 1 and size != 1 and not isinstance(x, str):
        inner = items[0]  # [[1, 2, 3]]: a row inside a list
        if not isinstance(inner, str) and _length(inner) == size:
            items = _items(inner, size, what)
    return items


def _length(x: Any) -> int:
    try:
        return len(x)
    except Exception:
        return -1


@dataclass(frozen=True)
class Items:
    """What the triples of an answer are, as `read_points` names them in its messages."""

    one: str
    many: str
    #: after the count: "4 points (x, y, z)"
    parts: str
    #: one of them in brackets, as text answers write them
    bracketed: str
    #: what the three numbers of one are: "(x, y, z)"
    inner: str
    #: whether their order matters (a set of them is an answer only when it does not)
    ordered: bool = True


#: Points (x, y, z): `read_points`'s default.
POINTS = Items("point", "points", "(x, y, z)", "(x, y, z)", "(x, y, z)")
#: Faces of a mesh, three vertex numbers each, in any order (a set of them is read too).
FACES = Items(
    "face", "faces", "of 3 vertex numbers", "(a, b, c)", "(its corners' vertex numbers)", False
)


def read_points(
    answer: Any, count: int, *, items: Items = POINTS
) -> list[tuple[Number, Number, Number]]:
    """Read ``count`` points (x, y, z), or other triples ``items`` names.

    Parameters
    ----------
    answer : object
        A sequence of points, an ``(count, 3)`` array or sympy matrix, a dict
        keyed ``"A"``, ``"B"``, ``"C"``, or text such as ``"(0,0,1), (1,0,1), (0,1,1)"``.
    count : int
        How many points.
    items : Items, default POINTS
        What the triples are, for the messages: points (x, y, z), or `FACES`
        (three vertex numbers each).

    Returns
    -------
    list of tuple

    Raises
    ------
    AnswerError
        Naming the point that cannot be read, or the wrong count.

    Examples
    --------
    >>> read_points([(0, 0, 2), ("3/4", 0, 2)], 2)[1]
    (Fraction(3, 4), Fraction(0, 1), Fraction(2, 1))
    >>> read_points({"A": (0, 0, 0), "B": (1, 0, 0), "C": (0, 5, 0)}, 3)[2]
    (Fraction(0, 1), Fraction(5, 1), Fraction(0, 1))
    >>> read_points([(0, 1, 2)], 2, items=FACES)
    Traceback (most recent call last):
    ...
    trinormal.exercises.reading.errors.AnswerError: give 2 faces of 3 vertex numbers, got 1
    """
    labels = "ABC" if count == 3 and items is POINTS else [str(i + 1) for i in range(count)]
    want = f"{count} {items.one if count == 1 else items.many} {items.parts}"
    items_read = guarded(lambda: _point_items(answer, count, want, labels, items), answer, want)
    check_count(items_read, count, f"give {want}")
    points = []
    for label, p in zip(labels, items_read, strict=True):
        try:
            x, y, z = read_vector(p)
        except AnswerError as exc:
            told = str(exc).replace("(x, y, z)", items.inner)
            raise AnswerError(f"{items.one} {label}: {told}") from None
        points.append((x, y, z))
    return points


_GROUP = re.compile(r"[(\[]([^()\[\]]*)[)\]]")


def _point_items(answer: Any, count: int, want: str, labels: Any, kind: Items) -> list[Any]:
    if answer is None or answer is Ellipsis:
        raise AnswerError(f"give {want}")
    if isinstance(answer, str):
        groups = _GROUP.findall(answer)
        if not groups:
            raise AnswerError(f"give {want}, each in brackets: {kind.bracketed}")
        return groups
    if isinstance(answer, dict):
        keys = {str(k).strip().upper(): v for k, v in answer.items()}
        if set(keys) == set(labels):
            return [keys[k] for k in labels]
        raise AnswerError(f"a dict of {kind.many} needs the keys {', '.join(labels)}")
    if isinstance(answer, set | frozenset) and not kind.ordered:
        return list(itertools.islice(iter(answer), count + 1))
    if isinstance(answer, set | frozenset):
        raise AnswerError(
            f"a set has no order, and the order of the {kind.many} matters: give {want}"
        )
    if isinstance(answer, bytes | bytearray | memoryview):
        raise AnswerError(f"bytes are not {kind.many}: give {want}")
    module = module_of(answer)
    if module.startswith("numpy"):
        import numpy as np

        if isinstance(answer, np.ndarray) and answer.ndim == 2 and answer.shape[1] == 3:
            return list(answer)
        raise AnswerError(f"give {want}; an array of them has shape ({count}, 3)")
    if module.startswith("sympy"):
        if getattr(answer, "is_Matrix", False) and answer.shape[1] == 3:
            return [answer.row(i) for i in range(answer.shape[0])]
        raise AnswerError(f"give {want}; a matrix of them has {count} rows of 3")
    if isinstance(answer, int | float | complex | Fraction) or looks_like_number(answer):
        raise AnswerError(f"give {want}, not one number")
    if not isinstance(answer, Iterable):
        raise AnswerError(f"give {want}, not {describe(answer)}")
    return list(itertools.islice(iter(answer), count + 1))
