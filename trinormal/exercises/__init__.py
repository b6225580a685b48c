"""Exercises for the notebooks: ask, answer, and [`check`][trinormal.exercises.check].

Each notebook ends with a few exercises. A student writes an answer in place
of ``...`` and runs [`check`][trinormal.exercises.check], which says whether the answer is right
and, when it is not, gives a hint that is true for that answer. It never shows the
solution; a teacher (or a student who has tried) gets it on purpose with
``get(name).solution()``.

>>> check("01-normal", ...)
01-normal: not answered yet. Replace ... with your answer and run the cell again.

Every exercise is judged by one rule set, so an answer means the same
everywhere:

* **Reading** (``trinormal.exercises.reading``): ``0.5``, ``"1/2"``, ``"0,5"``
  (a decimal comma), ``Fraction(1, 2)``, ``Decimal("0.5")``,
  ``numpy.float64(0.5)``, a 0-d numpy array and ``sympy.Rational(1, 2)`` are
  the same number; an irrational value may be a sympy expression or text as
  the notebooks print it (``"√3/2"``, ``"sqrt(3)/2"``, ``"−6"`` with the minus
  sign, ``"2√2"``) or a prompt's formula with its numbers (``"|(2, 3, 6)|/2"``,
  ``"53·log10(2)"``). Vectors may be tuples, lists, numpy arrays or matrices
  (also ``(3, 1)`` and ``(1, 3)``), sympy matrices or arrays, or text such as
  ``"(0, 0, 1)"``, ``"(0, -1, 1)/sqrt(2)"`` or ``"(0,5; 1; 0)"``. A true/false
  answer may be a numpy boolean; a word answer may be a sentence naming it.
  Any other object gets a message saying what was expected, never an
  exception; the full rules are in ``trinormal.exercises.reading``.
* **Judging** (``trinormal.exercises.judging``): exact exercises accept the
  exact value (or the float nearest to it); an exercise with a tolerance
  states it in its prompt, relative to the answer, and accepts floats within
  it. Hints are true for the answer given and never quote the solution.

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
...     replace=True,
... )
>>> check("99-demo-area", "2")
99-demo-area: correct.
>>> check("99-demo-area", (0, 0, 4))
99-demo-area: not yet. Your answer could not be read: expected one number, got 3 values.
>>> check("99-demo-area", -2)
99-demo-area: not yet. Wrong sign.

``expected`` may be a value or a function of no arguments (called when an
answer is checked, so the solution is computed by trinormal, never typed
in). For answers that are not numbers, decorate a checker that returns
``True``/``False`` or ``(ok, hint)``:

>>> @exercise("99-demo-word", "Which product gives the normal: dot or cross?", replace=True)
... def _(answer):
...     return str(answer).strip().lower() == "cross", "The dot product is a number."
>>> check("99-demo-word", "dot")
99-demo-word: not yet. The dot product is a number.
"""

from __future__ import annotations

import difflib
import html
import importlib
import json
import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from functools import partial
from typing import Any, Literal, overload

from trinormal.core import triangle_normal
from trinormal.exercises.judging import Verdict, judge_number, judge_vector, tolerance_text
from trinormal.exercises.reading import (
    AnswerError,
    read_bool,
    read_choice,
    read_number,
    read_points,
    read_vector,
    read_word,
)

__all__ = [
    "CHECK_LOG_VARIABLE",
    "NOTEBOOK_MODULES",
    "STUDENT_VARIABLE",
    "AnswerError",
    "CheckResult",
    "Exercise",
    "Student",
    "UnknownExercise",
    "Verdict",
    "check",
    "exercise",
    "get",
    "names",
    "read_bool",
    "read_choice",
    "read_number",
    "read_points",
    "read_vector",
    "read_word",
    "student",
    "task",
]

Status = Literal["correct", "incorrect", "unanswered", "unknown"]
Checker = Callable[[Any], "bool | tuple[bool, str] | Verdict"]

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
    "nb11",
)

#: The environment variable naming the file `check` appends one JSON line per verdict to. Only
#: the class report (``trinormal-notebooks report``) sets it, for the kernels it starts.
CHECK_LOG_VARIABLE = "TRINORMAL_CHECK_LOG"
#: The variable of the notebook's namespace (IPython's ``user_ns``) where `student` keeps the
#: student it was given: the one place the choice lives between cells.
STUDENT_VARIABLE = "trinormal_student"
#: The colour of each verdict (Okabe and Ito's palette), in the notebook and the class report.
STATUS_COLORS: dict[str, str] = {
    "correct": "#007A5A",
    "incorrect": "#D55E00",
    "unanswered": "#0072B2",
    "unknown": "#CC79A7",
}
#: The word for each verdict, in the notebook and the class report.
STATUS_WORDS: dict[str, str] = {
    "correct": "Correct",
    "incorrect": "Not yet",
    "unanswered": "Not answered",
    "unknown": "No such exercise",
}
#: The longest answer text a verdict's record keeps.
ANSWER_TEXT_LIMIT = 200

#: The start of the message for an answer no rule could judge (a bug: tests assert it never shows).
UNJUDGED = "This answer could not be judged"


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
    status : {"correct", "incorrect", "unanswered", "unknown"}
        The verdict (``"unknown"``: there is no exercise of that name).
        ``bool(result)`` is True only for ``"correct"``.
    message : str
        What to do next: a hint, never the solution.
    slip : str
        For a wrong answer, the code (in ``judging.SLIPS``) of the slip it matched; "" for none.
    """

    name: str
    status: Status
    message: str
    slip: str = ""

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
        colors, words = STATUS_COLORS, STATUS_WORDS
        return (
            f'<div class="trinormal-check trinormal-check-{self.status}" role="status" '
            f'style="border-left: 4px solid {colors[self.status]}; padding: 0.2em 0.6em;">'
            f"<strong>{words[self.status]}</strong> · <code>{html.escape(self.name)}</code>: "
            f"{html.escape(self.message)}</div>"
        )


def _kind(solution: Any) -> str:
    if isinstance(solution, bool):
        return "bool"
    if isinstance(solution, str):
        return "word"
    if isinstance(solution, tuple | list):
        return "vector"
    return "number"


def _sentence(error: Exception) -> str:
    text = str(error).rstrip(".")
    return text[:1].upper() + text[1:] + "."


@dataclass(frozen=True)
class Exercise:
    """One exercise.

    Attributes
    ----------
    name : str
        ``"NN-short-name"``, NN being the notebook's number.
    prompt : str
        The question, in one or two sentences; it states the tolerance when
        there is one (worded by ``judging.tolerance_text``).
    expected : object
        The solution, or a function of no arguments that computes it;
        unused when ``checker`` is given (then ``solution`` gives it).
    tol : float or None
        Relative tolerance: a number counts within ``tol · |solution|``, a
        vector when each component is within ``tol · |solution vector|``.
        ``None`` compares exactly (the nearest float to the solution counts too).
    hint : str
        Shown when an answer is wrong and no more specific hint applies.
    checker : callable or None
        ``checker(answer)`` → ``bool``, ``(bool, hint)`` or a ``Verdict``, for
        answers that are not one number or one vector, or that have many
        right values.
    mistakes : tuple of (value, hint, slip)
        Common wrong answers (values or functions of no arguments), the
        hint each one gets (written for that answer) and the slip's code in
        ``judging.SLIPS`` (what the class report counts).
    example : object
        For a checked exercise, one right answer (what
        [`solution`][trinormal.exercises.Exercise.solution] returns).
    degrees : bool
        The answer is an angle in degrees: text may end in a degree sign.
    choices : tuple of str
        For a word answer: the words that may be meant (``("front", "back")``);
        a sentence naming exactly one of them counts as that word.
    """

    name: str
    prompt: str
    expected: Any = None
    tol: float | None = None
    hint: str = ""
    checker: Checker | None = field(default=None, repr=False)
    mistakes: tuple[tuple[Any, str, str], ...] = ()
    example: Any = None
    degrees: bool = False
    choices: tuple[str, ...] = ()

    def solution(self) -> Any:
        """Return a right answer (computed when it is a function): for teachers and tests."""
        value = self.example if self.checker is not None else self.expected
        return value() if callable(value) else value

    def check(self, answer: Any) -> CheckResult:
        """Check one answer; ``...`` (Ellipsis) means not answered yet. Never raises."""
        if answer is Ellipsis:
            return CheckResult(
                self.name,
                "unanswered",
                "not answered yet. Replace ... with your answer and run the cell again.",
            )
        try:
            verdict = self.judge(answer)
        except Exception as exc:  # a last resort: the tests assert it is never reached
            verdict = Verdict(False, f"{UNJUDGED} ({type(exc).__name__}).")
        if verdict.ok:
            within = ""
            if self.tol is not None and self.checker is None:
                within = f" ({tolerance_text(self.tol, _kind(self.solution()))})"
            note = f" {verdict.note}" if verdict.note else ""
            return CheckResult(self.name, "correct", f"correct{within}.{note}")
        return CheckResult(
            self.name, "incorrect", f"not yet. {verdict.hint}".rstrip(), verdict.slip
        )

    def judge(self, answer: Any) -> Verdict:
        """Judge one answer by the shared rules (or the exercise's checker)."""
        if self.checker is not None:
            result = self.checker(answer)
            if isinstance(result, tuple):
                ok, hint = bool(result[0]), str(result[1])
                result = Verdict(ok, "" if ok else hint)
            elif not isinstance(result, Verdict):
                result = Verdict(bool(result))
            return (
                result if result.ok or result.hint else Verdict(False, self.hint, slip=result.slip)
            )
        solution = self.solution()
        kind = _kind(solution)
        if kind == "bool":
            try:
                value = read_bool(answer)
            except AnswerError as exc:
                return Verdict(False, _sentence(exc), slip="unreadable")
            return Verdict(value == solution, self.hint)
        if kind == "word":
            try:
                word = read_choice(answer, self.choices) if self.choices else read_word(answer)
            except AnswerError as exc:
                return Verdict(False, _sentence(exc), slip="unreadable")
            return Verdict(word == read_word(solution), self.hint)
        read: Callable[..., Any] = read_number
        judge: Callable[..., Verdict] = judge_number
        if kind == "vector":
            read, judge = partial(read_vector, size=len(solution)), judge_vector
        want = read(solution)
        try:
            got = read(answer, degrees=self.degrees)
        except AnswerError as exc:
            return Verdict(False, f"Your answer could not be read: {exc}.", slip="unreadable")
        mistakes = [
            (read(wrong() if callable(wrong) else wrong), hint, slip)
            for wrong, hint, slip in self.mistakes
        ]
        return judge(got, want, self.tol, mistakes, self.hint)


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


class UnknownExercise(KeyError):
    """No exercise has the name asked for; the message names the closest ones.

    It shows as one readable line (a plain ``KeyError`` would show its message in quotes).
    """

    def __init__(self, name: Any) -> None:
        self.name = name
        close = difflib.get_close_matches(str(name), names(), n=3)
        also = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
        self.message = f"no exercise named {name!r}{also} (names() lists them all)"
        super().__init__(self.message)

    def __str__(self) -> str:
        return self.message


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
        Relative tolerance (``1e-3`` accepts answers within 0.1 % of the
        solution); exact comparison when omitted. Say it in the prompt.
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

    ``get(name).solution()`` returns a right answer: call it on purpose,
    after trying.

    Raises
    ------
    UnknownExercise
        A ``KeyError`` naming the closest names, when there is no such exercise.

    Examples
    --------
    >>> get("01-normal").prompt[:28]
    'Compute N = (B − A) × (C − A'
    >>> get("01-nromal")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    trinormal.exercises.UnknownExercise: no exercise named '01-nromal'; did you mean '01-normal', ...? (names() lists them all)
    """  # noqa: E501
    found = (_load().get(name) or _REGISTRY.get(name)) if isinstance(name, str) else None
    if found is not None:
        return found
    raise UnknownExercise(name)


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
    >>> _ = exercise("99-demo-half", "Half of 0.9, within 1 %.", expected=0.45, tol=0.01, replace=True)
    >>> check("99-demo-half", "0.451")
    99-demo-half: correct (within 1 % of the right value).
    >>> check("99-demo-half", [0.45, 0])
    99-demo-half: not yet. Your answer could not be read: expected one number, got 2 values.
    >>> check("99-demo-half", None)
    99-demo-half: not yet. Your answer could not be read: None is not a number (did a function print its result instead of returning it?).

    A mistyped name gets the closest names, as one line:

    >>> check("99-demo-hlaf", 0.45)  # doctest: +ELLIPSIS
    99-demo-hlaf: no exercise named '99-demo-hlaf'; did you mean '99-demo-half'...? (names() lists them all)
    """  # noqa: E501
    chosen = session_student()
    try:
        ex = chosen.exercise(name) if chosen is not None else get(name)
    except UnknownExercise as unknown:
        result = CheckResult(str(name), "unknown", unknown.message)
    else:
        result = ex.check(answer)
    _record(
        {
            "exercise": result.name,
            "status": result.status,
            "slip": result.slip,
            "answer": _answer_text(answer),
            "message": result.message,
            "student": chosen.name if chosen is not None else "",
            "variant": chosen.variant(result.name) if chosen is not None else None,
        }
    )
    return result


def _answer_text(answer: Any) -> str:
    """Write an answer as text for the class report: a string as written, else its repr."""
    try:
        text = answer if isinstance(answer, str) else repr(answer)
    except Exception as exc:  # a student's object whose repr fails
        text = f"<{type(answer).__name__}: repr failed ({type(exc).__name__})>"
    if len(text) > ANSWER_TEXT_LIMIT:
        text = text[: ANSWER_TEXT_LIMIT - 1] + "…"
    return text


def _record(entry: dict[str, Any]) -> None:
    """Append one JSON line to the file `CHECK_LOG_VARIABLE` names; nothing when it is unset."""
    path = os.environ.get(CHECK_LOG_VARIABLE)
    if path:
        with open(path, "a", encoding="utf-8") as log:
            log.write(json.dumps(entry, ensure_ascii=False) + "\n")


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


def point_text(p: Sequence[Any]) -> str:
    """Write a point as prompts show it: whole numbers and fractions, ``(1/2, 0, 3)``.

    Examples
    --------
    >>> point_text((Fraction(1, 2), 0, 3))
    '(1/2, 0, 3)'
    """
    return "(" + ", ".join(str(x) for x in p) + ")"


# A student's own numbers (students.py imports this module's names, so it comes last).
from trinormal.exercises.students import Student, session_student, student, task  # noqa: E402
