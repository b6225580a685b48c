"""A student's own numbers in a notebook: `student`, `task`, and `check` judging their variant.

Once, at the top of a notebook:

.. code-block:: python

    from trinormal import exercises
    exercises.student("Ana Lima")

From then on ``exercises.task("01-normal")`` prints the prompt with Ana's numbers and
``check("01-normal", answer)`` judges her variant (an exercise without variants stays
as it is). Without a name, nothing changes: every notebook reads as it does today.

Where the choice lives
----------------------
The library keeps no state of its own. `student` stores its `Student` in the
notebook's namespace (IPython's ``user_ns``) under the name
``trinormal_student`` (``STUDENT_VARIABLE``), the one place `check` and `task` look;
re-running a cell or restarting the kernel behaves as for any other variable. Outside
IPython (a script, a test) there is no such namespace: call the methods of the
returned `Student` instead, ``me.check(...)``, ``me.task(...)``.

>>> me = Student("Ana Lima")
>>> me.variant("01-area") == me.variant("01-normal")  # one triangle for the three
True
>>> me.check("01-normal", ...)
01-normal: not answered yet. Replace ... with your answer and run the cell again.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from trinormal.exercises import (
    STUDENT_VARIABLE,
    CheckResult,
    Exercise,
    UnknownExercise,
    _record,
    get,
)

__all__ = ["Student", "student", "task"]


@dataclass(frozen=True)
class Student:
    """A student, whose variant of each exercise follows from their name and a seed.

    Attributes
    ----------
    name : str
        As the student wrote it; case and spacing do not change the variants.
    seed : int
        The class's seed (0 unless the teacher hands out another).
    code : str
        The code printed on the student's worksheet (``variants.student_code``): the
        worksheet's variants. Without it, the variants follow from the name and the seed.
    """

    name: str
    seed: int = 0
    code: str = ""

    def variant(self, name: str) -> int | None:
        """Return the student's variant of the exercise ``name``; None when it has none."""
        from trinormal.exercises.variants import group_of, read_code, variant_index

        template = group_of(name)
        if template is None:
            return None
        if self.code:
            return read_code(self.code)[template.group]
        return variant_index(name, self.name, self.seed)

    def exercise(self, name: str) -> Exercise:
        """Return the student's own exercise ``name`` (the notebook's when it has no variants)."""
        from trinormal.exercises.variants import variant_exercise

        index = self.variant(name)
        return get(name) if index is None else variant_exercise(name, index)

    def check(self, name: str, answer: Any) -> CheckResult:
        """Check an answer against the student's own variant.

        Examples
        --------
        >>> Student("Ben").check("01-nromal", 1).status
        'unknown'
        """
        try:
            return self.exercise(name).check(answer)
        except UnknownExercise as unknown:
            return CheckResult(str(name), "unknown", unknown.message)

    def task(self, name: str) -> None:
        """Print the prompt of the student's own exercise ``name``."""
        _print_task(name, self.exercise)

    def __repr__(self) -> str:
        from trinormal.exercises.variants import variant_names

        return (
            f"{self.name}: your own numbers in {len(variant_names())} exercises "
            "(exercises.task(name) prints each one's question)."
        )


def session_student() -> Student | None:
    """Return the `Student` the notebook chose with `student`, or None (always outside IPython)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    chosen = shell.user_ns.get(STUDENT_VARIABLE) if shell is not None else None
    return chosen if isinstance(chosen, Student) else None


def student(name: str, code: str = "", seed: int = 0) -> Student:
    """Give this notebook's student their own numbers: call it once, at the top.

    Parameters
    ----------
    name : str
        The student's name, as on the class roster.
    code : str, optional
        The code on the student's worksheet, to get the worksheet's numbers.
    seed : int, default 0
        The class's seed, when the teacher gives one (a code already includes it).

    Returns
    -------
    Student
        Also stored in the notebook's namespace as ``trinormal_student``, where `check`
        and `task` find it (in IPython only; elsewhere, use the returned object).

    Raises
    ------
    ValueError
        When the name is empty or the code is not one a worksheet prints.

    Examples
    --------
    >>> student("Ana Lima")  # doctest: +ELLIPSIS
    Ana Lima: your own numbers in 8 exercises (exercises.task(name) prints each one's question).
    """
    if not isinstance(name, str) or not name.strip():
        raise ValueError(f"student() needs the student's name, got {name!r}")
    from trinormal.exercises.variants import read_code

    if code:
        read_code(code)
    chosen = Student(" ".join(name.split()), int(seed), str(code).strip())
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is not None:
        shell.user_ns[STUDENT_VARIABLE] = chosen
    _record({"student": chosen.name, "seed": chosen.seed, "code": chosen.code})
    return chosen


def task(name: str) -> None:
    """Print an exercise's question, with the student's own numbers after `student`.

    Examples
    --------
    >>> task("05-scale-area")  # doctest: +ELLIPSIS
    05-scale-area: Multiply every coordinate of A = (1, 0, 1), B = (1, 1, 0), C = (-1, 1, 1) by 3...
    """
    chosen = session_student()
    _print_task(name, get if chosen is None else chosen.exercise)


def _print_task(name: str, lookup: Callable[[str], Exercise]) -> None:
    try:
        print(f"{name}: {lookup(name).prompt}")
    except UnknownExercise as unknown:
        print(f"{name}: {unknown.message}")
