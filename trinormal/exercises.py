"""Exercises for the notebooks: ask, answer, and :func:`check`.

Each notebook ends with a few exercises. A student writes an answer in place
of ``...`` and runs :func:`check`, which says whether the answer is right and,
when it is not, gives a hint. It never shows the solution.

>>> check("01-normal", ...)
01-normal: not answered yet. Replace ... with your answer and run the cell again.
>>> check("01-normal", (-1, -1, -1))  # doctest: +ELLIPSIS
01-normal: not yet. Your vector points the opposite way: check the order of the ...

Answers are compared exactly (``0.5``, ``"1/2"`` and ``Fraction(1, 2)`` are
the same number) unless the exercise states a tolerance, such as
``abs(answer - solution) <= 0.001``. Vectors can be tuples, lists, numpy
arrays or sympy matrices.

Adding exercises from another module
------------------------------------
Exercises live in one registry, keyed by name. The convention for names is
``"NN-short-name"``, NN being the notebook's number. Any module registers its
own with :func:`exercise`, without editing this file:

>>> from trinormal.exercises import exercise
>>> _ = exercise(
...     "99-demo-area",
...     "Area of the triangle (0,0,0), (2,0,0), (0,2,0).",
...     expected=lambda: triangle_normal((0, 0, 0), (2, 0, 0), (0, 2, 0)).area,
...     hint="The area is half of |N|.",
... )
>>> check("99-demo-area", 2)
99-demo-area: correct.

``expected`` may be a value or a function of no arguments (called when an
answer is checked, so the solution is computed by trinormal, never typed
in). Give ``tol=`` for a tolerance. For answers that are not numbers, use
:func:`exercise` as a decorator on a checker that returns ``True``/``False``
or ``(ok, hint)``:

>>> @exercise("99-demo-word", "Which product gives the normal: dot or cross?")
... def _(answer):
...     return str(answer).strip().lower() == "cross", "The dot product is a number."
>>> check("99-demo-word", "dot")
99-demo-word: not yet. The dot product is a number.

The first time a name is not found, :func:`check` imports every
``trinormal/exercises_<topic>.py`` module and the package modules listed in
``_REGISTERING_MODULES`` (the explorer's and the mesh notebooks'), so a
student never has to import anything for ``check`` to know an exercise.
"""

from __future__ import annotations

import difflib
import html
import importlib
import math
import pkgutil
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Literal, overload

from trinormal.core import parse_coordinate, triangle_normal
from trinormal.display import format_number

__all__ = ["CheckResult", "Exercise", "check", "exercise", "get", "names"]

Status = Literal["correct", "incorrect", "unanswered"]
Checker = Callable[[Any], bool | tuple[bool, str]]


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
        colors = {"correct": "#009E73", "incorrect": "#D55E00", "unanswered": "#0072B2"}
        words = {"correct": "Correct", "incorrect": "Not yet", "unanswered": "Not answered"}
        return (
            f'<div class="trinormal-check trinormal-check-{self.status}" role="status" '
            f'style="border-left: 4px solid {colors[self.status]}; padding: 0.2em 0.6em;">'
            f"<strong>{words[self.status]}</strong> · <code>{html.escape(self.name)}</code>: "
            f"{html.escape(self.message)}</div>"
        )


@dataclass(frozen=True)
class Exercise:
    """One registered exercise.

    Attributes
    ----------
    name : str
        ``"NN-short-name"``.
    prompt : str
        The question, in one or two sentences.
    expected : object
        The solution, or a function of no arguments that computes it;
        unused when ``checker`` is given.
    tol : float or None
        Absolute tolerance per number; ``None`` compares exactly.
    hint : str
        Shown when an answer is wrong and no more specific hint applies.
    checker : callable or None
        ``checker(answer)`` → ``bool`` or ``(bool, hint)``, for answers that
        are not numbers or vectors.
    """

    name: str
    prompt: str
    expected: Any = None
    tol: float | None = None
    hint: str = ""
    checker: Checker | None = field(default=None, repr=False)

    def solution(self) -> Any:
        """Return the expected answer (computed if it is a function): for tests, not students."""
        return self.expected() if callable(self.expected) else self.expected

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
            hint = hint or self.hint
        if ok:
            within = "" if self.tol is None else f" (within {format_number(self.tol, 15, True)})"
            return CheckResult(self.name, "correct", f"correct{within}.")
        return CheckResult(self.name, "incorrect", f"not yet. {hint}".rstrip())


_REGISTRY: dict[str, Exercise] = {}


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
    """Register an exercise, or (without ``expected``) return a decorator for a checker.

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
        Allow replacing an exercise of the same name (re-running a module).

    Returns
    -------
    Exercise or callable
        The registered exercise, or a decorator that registers its function
        as the checker and returns it unchanged.

    Raises
    ------
    ValueError
        When the name is taken (and ``replace`` is False) or the tolerance is negative.
    """
    if tol is not None and not tol >= 0:
        raise ValueError(f"tol must be a number >= 0, got {tol!r}")

    def add(ex: Exercise) -> Exercise:
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


#: Package modules that register exercises for their own notebooks.
_REGISTERING_MODULES = ("trinormal.widgets", "trinormal.mesh")


def _discover() -> None:
    """Import every module that registers exercises, so :func:`check` finds them all."""
    import trinormal

    for info in pkgutil.iter_modules(trinormal.__path__):
        if info.name.startswith("exercises_") or f"trinormal.{info.name}" in _REGISTERING_MODULES:
            importlib.import_module(f"trinormal.{info.name}")


def get(name: str) -> Exercise:
    """Return the exercise called ``name``.

    Raises
    ------
    KeyError
        With the closest registered names, when there is no such exercise.
    """
    if name not in _REGISTRY:
        _discover()
    try:
        return _REGISTRY[name]
    except KeyError:
        close = difflib.get_close_matches(str(name), list(_REGISTRY), n=3)
        also = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
        raise KeyError(f"no exercise named {name!r}{also}") from None


def names() -> list[str]:
    """Every registered exercise name, sorted.

    Examples
    --------
    >>> [n for n in names() if n.startswith("01-")]
    ['01-area', '01-normal', '01-reversed']
    """
    _discover()
    return sorted(_REGISTRY)


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
    01-area: not yet. That is twice the expected value: the area is half of |N|.
    """
    return get(name).check(answer)


# --------------------------------------------------------------------------- comparing answers


class _BadAnswer(Exception):
    pass


def _number(x: Any) -> Fraction | float:
    """Read an answer's number: a Fraction when exact, a float for irrational sympy values."""
    if isinstance(x, bool) or x is None:
        raise _BadAnswer(f"expected a number, got {x!r}")
    if getattr(x, "is_Rational", False):  # sympy Rational
        return Fraction(int(x.p), int(x.q))
    if getattr(x, "is_number", False):  # other sympy numbers, such as sqrt(3)/2
        return float(x)
    if hasattr(x, "shape") and getattr(x, "shape", None) == ():  # 0-d numpy array
        x = x.item()
    try:
        n, d = parse_coordinate(x, "your answer")
    except (TypeError, ValueError) as exc:
        raise _BadAnswer(str(exc)) from None
    return Fraction(n, d)


def _vector(x: Any) -> list[Fraction | float]:
    try:
        if isinstance(x, str | bytes):
            raise TypeError
        items = list(x)
    except TypeError:
        raise _BadAnswer(f"expected 3 numbers (x, y, z), got {type(x).__name__}") from None
    if len(items) != 3:
        raise _BadAnswer(f"expected 3 numbers (x, y, z), got {len(items)}")
    return [_number(i) for i in items]


def _close(a: Fraction | float, b: Fraction | float, tol: float | None) -> bool:
    if tol is None:
        return a == b or (isinstance(a, float) and a == float(b))
    return abs(float(a) - float(b)) <= tol


def _expected_kind(expected: Any) -> str:
    if isinstance(expected, bool):
        return "bool"
    if isinstance(expected, str):
        return "str"
    if isinstance(expected, tuple | list):
        return "vector"
    return "number"


def _compare(expected: Any, answer: Any, tol: float | None) -> tuple[bool, str]:
    kind = _expected_kind(expected)
    if kind == "bool":
        if type(answer).__name__ not in ("bool", "bool_"):
            return False, "Answer True or False."
        return bool(answer) == expected, ""
    if kind == "str":
        if not isinstance(answer, str):
            return False, "Answer with a word, in quotes."
        return answer.strip().lower() == expected.strip().lower(), ""
    try:
        if kind == "vector":
            got, want = _vector(answer), [_number(x) for x in expected]
        else:
            if not isinstance(answer, str) and hasattr(answer, "__len__"):
                return False, "This answer is one number, not a vector."
            got, want = [_number(answer)], [_number(expected)]
    except _BadAnswer as exc:
        return False, f"Your answer could not be read: {exc}."
    if all(_close(g, w, tol) for g, w in zip(got, want, strict=True)):
        return True, ""
    return False, _diagnose(got, want, tol, kind)


def _diagnose(
    got: list[Fraction | float], want: list[Fraction | float], tol: float | None, kind: str
) -> str:
    """Find a hint in the shape of the mistake, without giving the solution away."""

    def scaled(k: float) -> bool:
        return all(_close(g, w * k, tol) for g, w in zip(got, want, strict=True))

    what = "Your vector" if kind == "vector" else "Your number"
    if any(w != 0 for w in want) and scaled(-1):
        if kind == "vector":
            return (
                f"{what} points the opposite way: check the order of the subtractions "
                "(B − A, C − A) and of the cross product."
            )
        return f"{what} has the wrong sign."
    if kind == "number" and any(w != 0 for w in want):
        if scaled(2):
            return "That is twice the expected value: the area is half of |N|."
        if scaled(0.5):
            return "That is half the expected value: |N| itself is twice the area."
    if kind == "vector":
        g = [float(x) for x in got]
        w = [float(x) for x in want]
        gn, wn = math.hypot(*g), math.hypot(*w)
        if gn > 0 and wn > 0:
            cos = sum(a * b for a, b in zip(g, w, strict=True)) / (gn * wn)
            if cos > 1 - 1e-9:
                return (
                    "Right direction, wrong length: check whether this question wants the "
                    "raw normal N or the unit normal N / |N|."
                )
    return ""


# --------------------------------------------------------------------------- notebooks 01–04

_T = ((1, 0, 0), (0, 1, 0), (0, 0, 1))  # notebook 01's exercise triangle

exercise(
    "01-normal",
    "Compute N = (B − A) × (C − A) for A = (1, 0, 0), B = (0, 1, 0), C = (0, 0, 1).",
    expected=lambda: triangle_normal(*_T).exact.normal,
    hint="Find U = B − A and V = C − A first, then N = (UyVz − UzVy, UzVx − UxVz, UxVy − UyVx).",
)
exercise(
    "01-area",
    "The area of the same triangle, to within 0.001.",
    expected=lambda: triangle_normal(*_T).area,
    tol=1e-3,
    hint="The area is |N| / 2, and |N| is the square root of the sum of N's squared components.",
)
exercise(
    "01-reversed",
    "N for the same points taken in the order A → C → B.",
    expected=lambda: triangle_normal(*_T, winding="ACB").exact.normal,
    hint="Swapping the two edges swaps the factors of the cross product.",
)


def _lagrange_edges() -> tuple[tuple[int, int, int], tuple[int, int, int]]:
    return (1, 2, 2), (2, 0, 0)


def _scaling_power() -> int:
    """Measure k in N(sA, sB, sC) = s**k N(A, B, C) with s = 2 on a sample triangle."""
    a, b, c = (1, 2, 3), (4, 0, -1), (2, 5, 1)
    n1 = triangle_normal(a, b, c).exact.normal
    sa, sb, sc = (tuple(2 * x for x in p) for p in (a, b, c))
    n2 = triangle_normal(sa, sb, sc).exact.normal
    ratio = next(y / x for x, y in zip(n1, n2, strict=True) if x != 0)
    return ratio.numerator.bit_length() - 1


@exercise(
    "02-nz-formula",
    "Write N_z in terms of the edge components Ux, Uy, Uz, Vx, Vy, Vz "
    "(a sympy expression or a string such as 'Ux*Vy - ...').",
    hint="N_z only involves the x and y components of U and V.",
)
def _check_nz(answer: Any) -> bool | tuple[bool, str]:
    import sympy as sp

    from trinormal.symbolic import EDGE_SYMBOLS, normal_components

    names = {str(s): s for e in EDGE_SYMBOLS for s in e}
    try:
        expr = sp.sympify(answer, locals=names) if isinstance(answer, str) else answer
        expr = sp.sympify(expr)
        for sym in expr.free_symbols:  # symbols made elsewhere without real=True
            if str(sym) in names:
                expr = expr.subs(sym, names[str(sym)])
        diff = sp.expand(expr - normal_components("edges").z)
    except (sp.SympifyError, TypeError, SyntaxError):
        return False, "Your answer could not be read as an expression in Ux, Uy, Uz, Vx, Vy, Vz."
    if diff == 0:
        return True
    if sp.expand(expr + normal_components("edges").z) == 0:
        return False, "You have the right terms with the opposite sign: which product comes first?"
    return False, "N_z only involves the x and y components of U and V."


exercise(
    "02-scaling-power",
    "Scaling all three points by s multiplies N by s**k. What is k?",
    expected=_scaling_power,
    hint="Each edge is scaled by s, and N multiplies two edges.",
)
exercise(
    "02-lagrange",
    "U = (1, 2, 2) and V = (2, 0, 0). Use Lagrange's identity to find |N|² exactly.",
    expected=lambda: triangle_normal((0, 0, 0), *_lagrange_edges()).exact.magnitude_squared,
    hint="|N|² = |U|²|V|² − (U · V)²: compute the three dot products first.",
)

_ROW5 = ((0, 0, 0), (0, 2, 0), (0, 0, 2))
exercise(
    "03-row5-normal",
    "A fifth row: the raw normal N of (0,0,0), (0,2,0), (0,0,2).",
    expected=lambda: triangle_normal(*_ROW5).exact.normal,
    hint="U = (0, 2, 0) and V = (0, 0, 2); only one component of N is nonzero.",
)
exercise(
    "03-row5-unit",
    "The unit normal of the same triangle.",
    expected=lambda: triangle_normal(*_ROW5).unit_normal,
    tol=1e-4,
    hint="Divide N by |N|.",
)
exercise(
    "03-collinear",
    "Is the triangle (1,2,3), (2,4,6), (3,6,9) degenerate? Answer True or False.",
    expected=lambda: triangle_normal((1, 2, 3), (2, 4, 6), (3, 6, 9)).degenerate,
    hint="Compare B − A with C − A: is one a multiple of the other?",
)

exercise(
    "04-dot-value",
    "For A = (0,0,0), B = (1,0,0), C = (1,1,0), what is U · V (the product that is not N)?",
    expected=lambda: sum(
        (u * v for u, v in zip(*_edges((0, 0, 0), (1, 0, 0), (1, 1, 0)), strict=True)),
        Fraction(0),
    ),
    hint="U · V = UxVx + UyVy + UzVz: one number, not a vector.",
)


def _edges(a: Any, b: Any, c: Any) -> tuple[tuple[Fraction, ...], tuple[Fraction, ...]]:
    e = triangle_normal(a, b, c).exact
    return e.u, e.v


_BIG = ((0, 0, 0), (4, 0, 0), (0, 4, 0))
_SMALL = ((0, 0, 0), (0, 1, 0), (0, 0, 1))
exercise(
    "04-weighted-sum",
    "Add the raw normals of (0,0,0), (4,0,0), (0,4,0) and (0,0,0), (0,1,0), (0,0,1) "
    "(the area-weighted sum).",
    expected=lambda: tuple(
        x + y
        for x, y in zip(
            triangle_normal(*_BIG).exact.normal, triangle_normal(*_SMALL).exact.normal, strict=True
        )
    ),
    hint="Compute each raw normal N = U × V, then add them component by component.",
)
exercise(
    "04-2d-sign",
    "The 2D triangle P = (0, 0), Q = (0, 1), R = (1, 0), placed at z = 0: what is the z "
    "component of its unit normal (order P → Q → R)?",
    expected=lambda: (
        triangle_normal((0, 0, 0), (0, 1, 0), (1, 0, 0)).exact.normal[2]
        / abs(triangle_normal((0, 0, 0), (0, 1, 0), (1, 0, 0)).exact.normal[2])
    ),
    hint="Add z = 0 to each point; the normal lies along z, and the order P → Q → R is clockwise "
    "seen from +z.",
)
