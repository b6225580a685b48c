"""A sample class of generated submissions, to try the class report on (and to test it).

`write_sample_class` writes small notebooks as students hand them in: right answers
written in different forms, every listed slip of a few exercises, a student with their
own numbers, one notebook that raises, one that never ends, one that is not ours and
one with a misspelt exercise name. The docs' sample report is made from it.

>>> import tempfile
>>> with tempfile.TemporaryDirectory() as tmp:
...     names = [p.name for p in write_sample_class(Path(tmp))]
>>> names[:3]
['ana_lima.ipynb', 'ben_okafor.ipynb', 'cleo_diaz.ipynb']
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path
from typing import Any

from trinormal.exercises import Student, get

__all__ = [
    "SAMPLE_ROSTER",
    "SAMPLE_TIMEOUT",
    "SLIP_EXERCISES",
    "SLIP_STUDENTS",
    "notebook",
    "write_sample_class",
]

#: The time limit the sample class is run with (``--timeout``): the endless loop's limit.
SAMPLE_TIMEOUT = 6
#: The roster of the docs' sample worksheets.
SAMPLE_ROSTER = ("Ana Lima", "Ben Okafor", "Cleo Diaz")

#: The exercises whose every listed slip a student of the sample class makes.
SLIP_EXERCISES = ("01-normal", "01-area", "01-reversed", "04-dot-value", "05-scale-area")
#: The students who make them: the k-th makes each exercise's k-th listed slip.
SLIP_STUDENTS = ("Ben Okafor", "Cleo Diaz", "Dara Novak")
#: 05-down-acb's answers: right, and the three slips its checker knows (one per slip student).
DOWN_ACB = {
    "right": "((0, 0, 1), (1, 0, 1), (0, 1, 1))",
    "reversed-order": "[(0, 0, 2), (0, 1, 2), (1, 0, 2)]",
    "degenerate": "((0, 0, 0), (1, 1, 1), (2, 2, 2))",
    "tilted": "((0, 0, 0), (1, 0, 1), (0, 1, 0))",
}


def _source(value: Any) -> str:
    """Write an answer as a student might type it: exact numbers as text, floats as floats."""
    if isinstance(value, tuple | list):
        if all(isinstance(x, Fraction | int) for x in value):
            return repr("(" + ", ".join(str(x) for x in value) + ")")
        return repr([float(x) for x in value])
    if isinstance(value, Fraction):
        return repr(str(value))
    return repr(value)


def notebook(cells: list[tuple[str, str]]) -> dict[str, Any]:
    """Build a notebook (nbformat 4) from ``(kind, source)`` pairs, kind "code" or "markdown"."""
    out = []
    for number, (kind, source) in enumerate(cells):
        cell: dict[str, Any] = {
            "cell_type": kind,
            "id": f"cell-{number}",
            "metadata": {},
            "source": source,
        }
        if kind == "code":
            cell |= {"execution_count": None, "outputs": []}
        out.append(cell)
    return {
        "cells": out,
        "metadata": {
            "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }


_IMPORT = "from trinormal import exercises\nfrom trinormal.exercises import check"


def _checks(answers: dict[str, str]) -> list[tuple[str, str]]:
    return [("code", f"check({name!r}, {text})") for name, text in answers.items()]


def _slips(k: int) -> dict[str, str]:
    """Answer each of `SLIP_EXERCISES` with its k-th listed slip (those with that many)."""
    answers = {}
    for name in SLIP_EXERCISES:
        mistakes = get(name).mistakes
        if k < len(mistakes):
            wrong = mistakes[k][0]
            answers[name] = _source(wrong() if callable(wrong) else wrong)
    answers["05-down-acb"] = list(DOWN_ACB.values())[1 + k]
    return answers


def write_sample_class(folder: Path) -> list[Path]:
    """Write the sample class's notebooks into ``folder``; return their paths, sorted."""
    books: dict[str, dict[str, Any]] = {}
    right = {
        "01-normal": repr("(1, 1, 1)"),
        "01-area": repr("0,866"),
        "01-reversed": "[-1, -1, -1]",
        "04-dot-value": "Fraction(6)",
        "05-scale-area": "9.0",
        "05-down-acb": DOWN_ACB["right"],
        "04-2d-nz": "...",
    }
    books["ana_lima"] = notebook(
        [
            ("markdown", "**Name:** Ana Lima"),
            ("code", f"{_IMPORT}\nfrom fractions import Fraction"),
            *_checks(right),
        ]
    )
    for k, student in enumerate(SLIP_STUDENTS):
        file = student.lower().replace(" ", "_")
        books[file] = notebook(
            [("markdown", f"Name: {student}"), ("code", _IMPORT), *_checks(_slips(k))]
        )
    me = Student("Farah Haddad")
    own = {n: _source(me.exercise(n).solution()) for n in ("01-normal", "01-area", "05-scale-area")}
    own["01-reversed"] = _source(me.exercise("01-normal").solution())  # the order slip, her numbers
    books["farah_haddad_01_worked_example"] = notebook(
        [("code", _IMPORT + '\nexercises.student("Farah Haddad")'), *_checks(own)]
    )
    books["gus_moreau"] = notebook(
        [
            ("code", _IMPORT),
            *_checks({"01-normal": repr("(1, 1, 1)")}),
            ("code", "1 / 0  # a student's slip in their own code"),
            *_checks({"01-area": "0.866"}),
        ]
    )
    books["hana_sato"] = notebook([("code", _IMPORT), ("code", "while True:\n    pass")])
    books["holiday_photos"] = notebook([("code", "print(1 + 1)")])
    books["ivo_petrov"] = notebook(
        [("code", _IMPORT), *_checks({"01-nromal": repr("(1, 1, 1)"), "01-area": "0.866"})]
    )
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for stem, book in books.items():
        path = folder / f"{stem}.ipynb"
        path.write_text(json.dumps(book, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
        paths.append(path)
    return sorted(paths)
