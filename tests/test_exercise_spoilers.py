"""No answer before its exercise: not in an earlier output, a widget's state, or a docstring.

A solution may be reached on purpose (``get(name).solution()``), never by accident:
``help(check)``, ``help(get)`` and the API page (rendered from the same docstrings) show
no exercise's answer, the notebooks print none above the exercise, and the explorer is not
left on one.
"""

from __future__ import annotations

import contextlib
import doctest
import importlib
import inspect
import io
import json
import pkgutil
import pydoc
import re
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest

import trinormal.exercises as exercises_pkg
from trinormal import format_number
from trinormal.exercises import NOTEBOOK_MODULES, check, get

ROOT = Path(__file__).resolve().parents[1]


def notebook_names() -> set[str]:
    return {
        ex.name
        for m in NOTEBOOK_MODULES
        for ex in importlib.import_module(f"trinormal.exercises.{m}").EXERCISES
    }


def solution_texts(name: str) -> list[str]:
    """How a solution would look if printed: the non-trivial ones (small integers are everywhere)."""
    sol = get(name).solution()
    if isinstance(sol, bool | str):
        return []
    if isinstance(sol, tuple) and isinstance(sol[0], tuple):  # points
        return []
    values = sol if isinstance(sol, tuple) else (sol,)
    exact = [Fraction(v) for v in values]
    texts = []
    axis = sum(v != 0 for v in exact) == 1 and all(abs(v) in (0, 1) for v in exact)
    if isinstance(sol, tuple) and not axis:  # (1, 0, 0) is everywhere, and no answer by itself
        texts.append("(" + ", ".join(format_number(v, 4, trim=True) for v in exact) + ")")
        texts.append("(" + ", ".join(format_number(v, 4) for v in exact) + ")")
        texts.append(repr(sol))
    if get(name).checker is not None:  # one answer of many: only the whole of it would tell
        return texts
    for v in exact:
        if v.denominator != 1:
            texts += [format_number(v, 3), format_number(v, 4), str(v)]
    return [t for t in texts if t not in ("0.000", "0.0000")]


# --------------------------------------------------------------------------- docstrings


def _docstrings() -> list[tuple[str, str]]:
    """Every docstring in trinormal.exercises and its modules: (where, text)."""
    found = []
    modules = [exercises_pkg] + [
        importlib.import_module(f"trinormal.exercises.{m.name}")
        for m in pkgutil.iter_modules(exercises_pkg.__path__)
    ]
    for mod in modules:
        found.append((mod.__name__, inspect.getdoc(mod) or ""))
        for attr, obj in vars(mod).items():
            if inspect.isfunction(obj) or inspect.isclass(obj):
                if getattr(obj, "__module__", "") != mod.__name__:
                    continue
                found.append((f"{mod.__name__}.{attr}", inspect.getdoc(obj) or ""))
                if inspect.isclass(obj):
                    for meth, m_obj in vars(obj).items():
                        doc = inspect.getdoc(m_obj) if callable(m_obj) else None
                        if doc:
                            found.append((f"{mod.__name__}.{attr}.{meth}", doc))
    return found


def test_doc_examples_show_notebook_exercises_only_unanswered():
    """An example may run a notebook's exercise only with ``...``; demos use exercises of their own."""
    names = notebook_names()
    parser = doctest.DocTestParser()
    for where, doc in _docstrings():
        for example in parser.get_examples(doc):
            for name in re.findall(r"""["']([0-9]{2}-[a-z0-9-]+)["']""", example.source):
                if name not in names:
                    continue
                assert "solution()" not in example.source, (where, example.source)
                if "check(" in example.source:
                    assert "not answered yet" in example.want, (where, example.source)


@pytest.mark.parametrize("name", sorted(notebook_names()))
def test_help_and_the_api_docstrings_show_no_solution(name):
    rendered = "\n".join(
        pydoc.render_doc(obj, renderer=pydoc.plaintext)
        for obj in (exercises_pkg, exercises_pkg.check, exercises_pkg.get, exercises_pkg.Exercise)
    )
    rendered += "\n".join(doc for _, doc in _docstrings())
    for text in solution_texts(name):
        assert text not in rendered, (name, text)
    assert f"{name}: correct" not in rendered


# --------------------------------------------------------------------------- notebook outputs


def _cells(path: Path) -> list[dict[str, Any]]:
    return json.loads(path.read_text(encoding="utf-8"))["cells"]


def _output_text(cell: dict[str, Any]) -> str:
    parts = []
    for out in cell.get("outputs", []):
        parts.append("".join(out.get("text", "")))
        data = out.get("data", {})
        for key in ("text/plain", "text/markdown", "text/latex", "text/html"):
            parts.append("".join(data.get(key, "")))
    return "\n".join(parts)


def _asked(path: Path) -> dict[str, int]:
    """The exercises a notebook asks, with the index of the cell that checks each."""
    asked = {}
    for i, cell in enumerate(_cells(path)):
        if cell["cell_type"] == "code":
            for name in re.findall(r'check\("([0-9]{2}-[a-z0-9-]+)"', "".join(cell["source"])):
                asked[name] = i
    return asked


NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_no_output_above_an_exercise_prints_its_solution(path):
    cells = _cells(path)
    for name, index in _asked(path).items():
        above = "\n".join(_output_text(c) for c in cells[:index])
        for text in solution_texts(name):
            assert text not in above, (path.name, name, text)


def test_no_output_above_05_down_acb_shows_a_downward_normal_in_the_order_acb():
    path = ROOT / "notebooks" / "05_explorer.ipynb"
    cells = _cells(path)
    index = _asked(path)["05-down-acb"]
    above = "\n".join(_output_text(c) for c in cells[:index])
    for line in above.splitlines():
        if "A→C→B" not in line:
            continue
        for vector in re.findall(r"N = \(([^)]*)\)", line):
            x, y, z = (float(v) for v in vector.split(","))
            assert not (x == 0 and y == 0 and z < 0), line


def test_the_explorer_is_not_left_on_an_answer():
    """Run notebook 05 up to its exercises: the explorer's triangle answers none of them."""
    path = ROOT / "notebooks" / "05_explorer.ipynb"
    cells = _cells(path)
    first = min(_asked(path).values())
    namespace: dict[str, Any] = {}
    with contextlib.redirect_stdout(io.StringIO()):
        for cell in cells[:first]:
            if cell["cell_type"] == "code":
                exec(compile("".join(cell["source"]), path.name, "exec"), namespace)
    ex = namespace["ex"]
    a, b, c = (tuple(p) for p in (ex.result.exact.a, ex.result.exact.b, ex.result.exact.c))
    for points in ([a, b, c], [a, c, b], [b, a, c], [c, b, a]):  # either order, any labels
        assert not check("05-down-acb", points), points
    for point in (a, b, c):
        assert not check("05-collinear", point), point
