"""Exercises for the notebooks: ask, answer, and [`check`][trinormal.exercises.check].

Each notebook ends with a few exercises. A student writes an answer in place
of ``...`` and runs [`check`][trinormal.exercises.check], which says whether the answer is right
and, when it is not, gives a hint that is true for that answer. It never shows the
solution; a teacher (or a student who has tried) gets it on purpose with
``get(name).solution()``.

>>> check("01-normal", ...)
01-normal: not answered yet. Replace ... with your answer and run the cell again.
>>> check("01-normal", (-1, -1, -1))  # doctest: +ELLIPSIS
01-normal: not yet. Your vector points the opposite way...

Answers are compared exactly: ``0.5``, ``"1/2"``, ``Fraction(1, 2)``,
``Decimal("0.5")``, ``numpy.float64(0.5)`` and ``sympy.Rational(1, 2)`` are
the same number. An exercise may state a tolerance (``tol``), and then a
float within it counts, as does an irrational sympy value such as
``sympy.sqrt(3) / 2`` or the string ``"sqrt(3)/2"`` (also typed the way the
notebooks print it, ``"√3/2"``, with ``·`` for a product and ``−`` for minus).
Vectors can be tuples, lists, numpy arrays or sympy matrices.

Where the exercises live
------------------------
One module per notebook, ``trinormal/exercises/nbNN.py``, holds that
notebook's exercises in a tuple named ``EXERCISES``. The list of modules is
`NOTEBOOK_MODULES`; the registry is built from it the first time an
exercise is looked up. Nothing is registered as a side effect of importing
another module. To add a notebook's exercises, write its module and add its
name to `NOTEBOOK_MODULES`.

For a quick exercise of your own (in a notebook or a course module),
[`exercise`][trinormal.exercises.exercise] registers one by hand:

>>> _ = exercise(
...     "99-demo-area",
...     "Area of the triangle (0,0,0), (2,0,0), (0,2,0).",
...     expected=lambda: triangle_normal((0, 0, 0), (2, 0, 0), (0, 2, 0)).area,
...     hint="The area is half of |N|.",
... )
>>> check("99-demo-area", "2")
99-demo-area: correct.

``expected`` may be a value or a function of no arguments (called when an
answer is checked, so the solution is computed by trinormal, never typed
in). For answers that are not numbers, decorate a checker that returns
``True``/``False`` or ``(ok, hint)``:

>>> @exercise("99-demo-word", "Which product gives the normal: dot or cross?")
... def _(answer):
...     return str(answer).strip().lower() == "cross", "The dot product is a number."
>>> check("99-demo-word", "dot")
99-demo-word: not yet. The dot product is a number.
"""

from __future__ import annotations

import difflib
import html
import importlib
import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Literal, overload

from trinormal.core import parse_coordinate, triangle_normal
from trinormal.display import format_number

__all__ = [
    "NOTEBOOK_MODULES",
    "AnswerError",
    "CheckResult",
    "Exercise",
    "check",
    "exercise",
    "get",
    "names",
    "read_number",
    "read_points",
    "read_vector",
]

Status = Literal["correct", "incorrect", "unanswered"]
Checker = Callable[[Any], bool | tuple[bool, str]]
Number = Fraction | float

#: The modules ``trinormal.exercises.<name>`` that hold the notebooks' exercises.
NOTEBOOK_MODULES: tuple[str, ...] = (
    "nb01",
    "nb02",
    "nb03",
    "nb04",
    "nb05",
    "nb06",
    "nb07",
    "nb08",
    "nb09",
    "nb10",
)


class _Missing:
    def __repr__(self) -> str:
        return "<missing>"


_MISSING: Any = _Missing()


@dataclass(frozen=True)
class CheckResult:
    """The verdict on one answer; it shows as one line in a notebook.

    Attributes
    ----------
    name : str
        The exercise.
    status : {"correct", "incorrect", "unanswered"}
        The verdict. ``bool(result)`` is True only for ``"correct"``.
    message : str
        What to do next: a hint, never the solution.
    """

    name: str
    status: Status
    message: str

    def __bool__(self) -> bool:
        return self.status == "correct"

    @property
    def correct(self) -> bool:
        """True when the answer is right."""
        return self.status == "correct"

    def __repr__(self) -> str:
        return f"{self.name}: {self.message}"

    __str__ = __repr__

    def _repr_html_(self) -> str:
        colors = {"correct": "#007A5A", "incorrect": "#D55E00", "unanswered": "#0072B2"}
        words = {"correct": "Correct", "incorrect": "Not yet", "unanswered": "Not answered"}
        return (
            f'<div class="trinormal-check trinormal-check-{self.status}" role="status" '
            f'style="border-left: 4px solid {colors[self.status]}; padding: 0.2em 0.6em;">'
            f"<strong>{words[self.status]}</strong> · <code>{html.escape(self.name)}</code>: "
            f"{html.escape(self.message)}</div>"
        )


@dataclass(frozen=True)
class Exercise:
    """One exercise.

    Attributes
    ----------
    name : str
        ``"NN-short-name"``, NN being the notebook's number.
    prompt : str
        The question, in one or two sentences.
    expected : object
        The solution, or a function of no arguments that computes it;
        unused when ``checker`` is given (then ``solution`` gives it).
    tol : float or None
        Absolute tolerance per number; ``None`` compares exactly.
    hint : str
        Shown when an answer is wrong and no more specific hint applies.
    checker : callable or None
        ``checker(answer)`` → ``bool`` or ``(bool, hint)``, for answers that
        are not one number or one vector, or that have many right values.
    mistakes : tuple of (value, hint)
        Common wrong answers (values or functions of no arguments) and the
        hint each one gets: a hint written for that answer.
    example : object
        For a checked exercise, one right answer (what
        [`solution`][trinormal.exercises.Exercise.solution] returns).
    """

    name: str
    prompt: str
    expected: Any = None
    tol: float | None = None
    hint: str = ""
    checker: Checker | None = field(default=None, repr=False)
    mistakes: tuple[tuple[Any, str], ...] = ()
    example: Any = None

    def solution(self) -> Any:
        """Return a right answer (computed when it is a function): for teachers and tests."""
        value = self.example if self.checker is not None else self.expected
        return value() if callable(value) else value

    def check(self, answer: Any) -> CheckResult:
        """Check one answer; ``...`` (Ellipsis) means not answered yet."""
        if answer is Ellipsis:
            return CheckResult(
                self.name,
                "unanswered",
                "not answered yet. Replace ... with your answer and run the cell again.",
            )
        if self.checker is not None:
            verdict = self.checker(answer)
            ok, hint = verdict if isinstance(verdict, tuple) else (bool(verdict), self.hint)
        else:
            ok, hint = _compare(self.solution(), answer, self.tol)
            if not ok:
                hint = self._mistake_hint(answer) or hint or self.hint
        if ok:
            within = "" if self.tol is None else f" (within {format_number(self.tol, 15, True)})"
            return CheckResult(self.name, "correct", f"correct{within}.")
        return CheckResult(self.name, "incorrect", f"not yet. {hint}".rstrip())

    def _mistake_hint(self, answer: Any) -> str:
        for wrong, hint in self.mistakes:
            value = wrong() if callable(wrong) else wrong
            if _compare(value, answer, self.tol if self.tol is not None else 1e-9)[0]:
                return str(hint)
        return ""


# The exercises of the notebook modules, loaded on first use, and the ones added by hand.
_NOTEBOOKS: dict[str, Exercise] = {}
_REGISTRY: dict[str, Exercise] = {}


def _load() -> dict[str, Exercise]:
    """Import every module of `NOTEBOOK_MODULES` and index its ``EXERCISES``."""
    if not _NOTEBOOKS:
        found: dict[str, Exercise] = {}
        for module in NOTEBOOK_MODULES:
            mod = importlib.import_module(f"{__name__}.{module}")
            for ex in mod.EXERCISES:
                if ex.name in found:
                    raise ValueError(f"exercise {ex.name!r} is defined twice ({module})")
                found[ex.name] = ex
        _NOTEBOOKS.update(found)
    return _NOTEBOOKS


@overload
def exercise(
    name: str, prompt: str, *, tol: float | None = None, hint: str = "", replace: bool = False
) -> Callable[[Checker], Checker]: ...


@overload
def exercise(
    name: str,
    prompt: str,
    expected: Any,
    *,
    tol: float | None = None,
    hint: str = "",
    replace: bool = False,
) -> Exercise: ...


def exercise(
    name: str,
    prompt: str,
    expected: Any = _MISSING,
    *,
    tol: float | None = None,
    hint: str = "",
    replace: bool = False,
) -> Any:  # Exercise, or a decorator
    """Register an exercise by hand, or (without ``expected``) return a decorator for a checker.

    The notebooks' own exercises are not registered this way: they live in
    ``trinormal/exercises/nbNN.py`` and are found through `NOTEBOOK_MODULES`.

    Parameters
    ----------
    name : str
        Unique name, ``"NN-short-name"``.
    prompt : str
        The question.
    expected : object or callable, optional
        The solution (number, vector, bool or string), or a function of no
        arguments returning it. Omit it to decorate a checker function.
    tol : float, optional
        Absolute tolerance on each number; exact comparison when omitted.
    hint : str
        A hint for a wrong answer.
    replace : bool, default False
        Allow replacing an exercise of the same name (re-running a cell).

    Returns
    -------
    Exercise or callable
        The registered exercise, or a decorator that registers its function
        as the checker and returns it unchanged.

    Raises
    ------
    ValueError
        When the name is taken and ``replace`` is False, or the tolerance is
        negative. A notebook's own exercise always wins over one registered
        by hand under the same name.
    """
    if tol is not None and not tol >= 0:
        raise ValueError(f"tol must be a number >= 0, got {tol!r}")

    def add(ex: Exercise) -> Exercise:
        if name in _load() and not replace:
            raise ValueError(f"{name!r} is a notebook's exercise; choose another name")
        old = _REGISTRY.get(name)
        if old is not None and not replace and old != ex:
            raise ValueError(f"an exercise named {name!r} is already registered")
        _REGISTRY[name] = ex
        return ex

    if expected is not _MISSING:
        return add(Exercise(name, prompt, expected, tol, hint))

    def decorate(fn: Checker) -> Checker:
        add(Exercise(name, prompt, None, tol, hint, checker=fn))
        return fn

    return decorate


def get(name: str) -> Exercise:
    """Return the exercise called ``name``.

    Examples
    --------
    >>> get("01-normal").solution()
    (Fraction(1, 1), Fraction(1, 1), Fraction(1, 1))

    Raises
    ------
    KeyError
        With the closest names, when there is no such exercise.
    """
    found = _load().get(name) or _REGISTRY.get(name)
    if found is not None:
        return found
    close = difflib.get_close_matches(str(name), names(), n=3)
    also = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
    raise KeyError(f"no exercise named {name!r}{also}")


def names() -> list[str]:
    """Every exercise name, sorted.

    Examples
    --------
    >>> [n for n in names() if n.startswith("01-")]
    ['01-area', '01-normal', '01-reversed']
    """
    return sorted({*_load(), *_REGISTRY})


def check(name: str, answer: Any) -> CheckResult:
    """Tell whether ``answer`` solves the exercise ``name``, with a hint if it does not.

    Parameters
    ----------
    name : str
        The exercise, such as ``"01-area"``.
    answer : object
        Your answer. ``...`` (Ellipsis) means you have not answered yet.

    Returns
    -------
    CheckResult
        Shows as one line; ``bool(result)`` is True when the answer is right.

    Examples
    --------
    >>> check("01-area", 0.866)
    01-area: correct (within 0.001).
    >>> check("01-area", 1.7321)
    01-area: not yet. That is |N|, the parallelogram's area: the triangle is half of it.
    """
    return get(name).check(answer)


# --------------------------------------------------------------------------- reading answers


class AnswerError(ValueError):
    """An answer that cannot be read as what the exercise asks for."""


def read_number(x: Any) -> Number:
    """Read one number of an answer: exact when it can be, a float otherwise.

    Parameters
    ----------
    x : object
        An int, float, ``Fraction``, ``Decimal``, numpy scalar, sympy number,
        or a string such as ``"1/3"``, ``"-2.5"`` or ``"sqrt(3)/2"``.

    Returns
    -------
    Fraction or float
        A ``Fraction`` for every exact rational value (a float is read at its
        exact binary value); a float for an irrational one such as √3 / 2.

    Raises
    ------
    AnswerError
        For booleans, ``None``, vectors and text that is not a number.

    Examples
    --------
    >>> read_number("5/3"), read_number(-2.5)
    (Fraction(5, 3), Fraction(-5, 2))
    >>> round(read_number("sqrt(3)/2"), 6), round(read_number("√3/2"), 6)
    (0.866025, 0.866025)
    """
    if isinstance(x, bool) or x is None or type(x).__name__ == "bool_":
        raise AnswerError(f"expected a number, got {x!r}")
    if getattr(x, "is_Rational", False):  # sympy Integer / Rational
        return Fraction(int(x.p), int(x.q))
    if getattr(x, "is_number", False):  # other sympy numbers, such as sqrt(3)/2
        return _real(x)
    if getattr(x, "shape", None) == ():  # 0-d numpy array
        x = x.item()
    try:
        n, d = parse_coordinate(x, "your answer")
    except (TypeError, ValueError) as exc:
        if isinstance(x, str):
            return _sympy_number(x, exc)
        raise AnswerError(str(exc)) from None
    return Fraction(n, d)


def _real(x: Any) -> Number:
    if x.is_Rational:
        return Fraction(int(x.p), int(x.q))
    if x.is_real is False or not x.is_finite:
        raise AnswerError(f"expected a real number, got {x}")
    return float(x)


def _sqrt_call(match: re.Match[str]) -> str:
    """``√3`` → ``sqrt(3)``, ``√(`` → ``sqrt(``."""
    return "sqrt(" if match[1] == "(" else f"sqrt({match[1]})"


def _sympy_number(text: str, error: Exception) -> Number:
    """Read a string such as ``"sqrt(3)/2"`` with sympy, when it is installed."""
    # the way the notebooks print math: √3/2, 1/√(2), 2√2, 2·3, 2×3, −1
    code = re.sub(r"√\s*(\d+(?:\.\d+)?|\()", _sqrt_call, text)
    code = code.replace("·", "*").replace("×", "*").replace("−", "-")
    code = re.sub(r"(\d)\s*sqrt\(", r"\1*sqrt(", code)  # 2√2 is 2*sqrt(2)
    try:
        import sympy as sp

        value = sp.sympify(code.strip(), rational=True)
    except Exception:  # any failure means: not a number
        raise AnswerError(str(error)) from None
    if not getattr(value, "is_number", False):
        raise AnswerError(f"{text!r} is not a number") from None
    return _real(value)


def read_vector(x: Any, size: int = 3) -> list[Number]:
    """Read a vector of ``size`` numbers (tuple, list, numpy array, sympy matrix).

    Examples
    --------
    >>> read_vector(("1/3", 0, "-2.5"))
    [Fraction(1, 3), Fraction(0, 1), Fraction(-5, 2)]
    """
    if isinstance(x, str | bytes) or getattr(x, "shape", None) == ():
        raise AnswerError(f"expected {size} numbers (x, y, z), got one value")
    try:
        items = list(x)
    except TypeError:
        raise AnswerError(f"expected {size} numbers (x, y, z), got {type(x).__name__}") from None
    if len(items) != size:
        raise AnswerError(f"expected {size} numbers (x, y, z), got {len(items)}")
    return [read_number(i) for i in items]


def read_points(answer: Any, count: int) -> list[tuple[Number, Number, Number]]:
    """Read ``count`` points (x, y, z), each number exactly.

    Raises
    ------
    AnswerError
        Naming the point that cannot be read, or the wrong count.

    Examples
    --------
    >>> read_points([(0, 0, 1), ("1/2", 0, 1)], 2)[1]
    (Fraction(1, 2), Fraction(0, 1), Fraction(1, 1))
    """
    if answer is None or isinstance(answer, str | bytes):
        raise AnswerError(f"give {count} point{'s' if count > 1 else ''} (x, y, z)")
    try:
        items = list(answer)
    except TypeError:
        raise AnswerError(f"give {count} point{'s' if count > 1 else ''} (x, y, z)") from None
    if len(items) != count:
        return_many = f"{count} point{'s' if count > 1 else ''}"
        raise AnswerError(f"give {return_many} (x, y, z), got {len(items)}")
    points = []
    for i, p in enumerate(items):
        try:
            x, y, z = read_vector(p)
        except AnswerError as exc:
            raise AnswerError(f"point {i + 1}: {exc}") from None
        points.append((x, y, z))
    return points


# --------------------------------------------------------------------------- comparing answers


def _close(a: Number, b: Number, tol: float | None) -> bool:
    if tol is None:
        if isinstance(a, float) or isinstance(b, float):
            return float(a) == float(b)
        return a == b
    return abs(float(a) - float(b)) <= tol


def _expected_kind(expected: Any) -> str:
    if isinstance(expected, bool):
        return "bool"
    if isinstance(expected, str):
        return "str"
    if isinstance(expected, tuple | list):
        return "vector"
    return "number"


_TRUE_WORDS = {"true": True, "false": False}


def _compare(expected: Any, answer: Any, tol: float | None) -> tuple[bool, str]:
    kind = _expected_kind(expected)
    if kind == "bool":
        if isinstance(answer, str) and answer.strip().lower() in _TRUE_WORDS:
            answer = _TRUE_WORDS[answer.strip().lower()]
        if type(answer).__name__ not in ("bool", "bool_"):
            return False, "Answer True or False."
        return bool(answer) == expected, ""
    if kind == "str":
        if not isinstance(answer, str):
            return False, "Answer with a word, in quotes."
        words = answer.strip().lower().split()
        if words[:1] == ["the"]:  # "the front" and "front face" say "front" too
            words = words[1:]
        if words[-1:] == ["face"]:
            words = words[:-1]
        return " ".join(words) == expected.strip().lower(), ""
    try:
        if kind == "vector":
            got, want = read_vector(answer), [read_number(x) for x in expected]
        else:
            if not isinstance(answer, str) and hasattr(answer, "__len__"):
                return False, "This answer is one number, not a vector."
            got, want = [read_number(answer)], [read_number(expected)]
    except AnswerError as exc:
        return False, f"Your answer could not be read: {exc}."
    if all(_close(g, w, tol) for g, w in zip(got, want, strict=True)):
        return True, ""
    return False, _diagnose(got, want, tol, kind)


def _diagnose(got: Sequence[Number], want: Sequence[Number], tol: float | None, kind: str) -> str:
    """Say what is true of a wrong answer's shape (sign, direction), never the solution."""
    if any(w != 0 for w in want) and all(
        _close(g, -w, tol) for g, w in zip(got, want, strict=True)
    ):
        return "Your vector points the opposite way." if kind == "vector" else "Wrong sign."
    if kind == "vector":
        g = [float(x) for x in got]
        w = [float(x) for x in want]
        gn, wn = math.hypot(*g), math.hypot(*w)
        if gn > 0 and wn > 0:
            cos = sum(a * b for a, b in zip(g, w, strict=True)) / (gn * wn)
            if cos > 1 - 1e-12:
                return "Right direction, wrong length."
    return ""


def unit(v: Sequence[Any]) -> tuple[float, ...]:
    """``v / |v|`` as floats: a helper for the notebook modules' expected answers.

    Examples
    --------
    >>> unit((3, 0, 4))
    (0.6, 0.0, 0.8)
    """
    xs = [float(x) for x in v]
    n = math.hypot(*xs)
    return tuple(x / n for x in xs)


def raw_normal(a: Any, b: Any, c: Any, winding: str = "ABC") -> tuple[Fraction, ...]:
    """Return the exact raw normal N of a triangle: a helper for the notebook modules.

    Examples
    --------
    >>> raw_normal((0, 0, 0), (2, 0, 0), (0, 3, 0))
    (Fraction(0, 1), Fraction(0, 1), Fraction(6, 1))
    """
    return tuple(triangle_normal(a, b, c, winding=winding).exact.normal)
