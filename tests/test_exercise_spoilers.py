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
from test_exercise_registry import notebook_names

import trinormal.exercises as exercises_pkg
from trinormal import format_number
from trinormal.exercises import check, get

ROOT = Path(__file__).resolve().parents[1]


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


# --------------------------------------------------------------------------- hints are nudges


def _triangle(points: Any, winding: str = "ABC") -> tuple[list[Any], list[Any]]:
    """A triangle's intermediate results: the edges and N (vectors), |N|² (a number)."""
    from trinormal import triangle_normal

    e = triangle_normal(*points, winding=winding).exact
    return [tuple(e.u), tuple(e.v), tuple(e.normal)], [e.magnitude_squared]


def _intermediates(name: str) -> tuple[list[Any], list[Any]]:
    """What a student computes on the way to the answer of ``name``: (vectors, numbers).

    Computed from the exercise modules' own data, never typed in.
    """
    from trinormal.exercises import nb01, nb02, nb03, nb04, nb05, nb07, nb09, nb10, nb11

    def dot(p: Any, q: Any) -> Any:
        return sum(Fraction(a) * Fraction(b) for a, b in zip(p, q, strict=True))

    vectors: list[Any] = []
    numbers: list[Any] = []

    def add(found: tuple[list[Any], list[Any]]) -> None:
        vectors.extend(found[0])
        numbers.extend(found[1])

    triangles = {
        "01": [nb01.TRIANGLE],
        "03-row5": [nb03.ROW5],
        "03-collinear": [nb03.LINE],
        "04-dot": [nb04.DOT_TRIANGLE],
        "04-weighted": [nb04.BIG, nb04.SMALL],
        "04-2d": [tuple((x, y, 0) for x, y in nb04.FLAT)],
        "05-scale": [nb05.SCALE_ABC, tuple(tuple(3 * x for x in p) for p in nb05.SCALE_ABC)],
        "07": [nb07.NEEDLE],
    }
    for prefix, tris in triangles.items():
        if name.startswith(prefix):
            for t in tris:
                add(_triangle(t))
                add(_triangle(t, "ACB"))
    if name == "02-lagrange":
        u, v = nb02.LAGRANGE_U, nb02.LAGRANGE_V
        numbers += [dot(u, u), dot(v, v), dot(u, v), dot(u, u) * dot(v, v)]
    if name == "05-collinear":
        a, b = nb05.COLLINEAR_AB
        vectors.append(tuple(q - p for p, q in zip(a, b, strict=True)))
    if name == "06-float64-digits":
        numbers += [get("06-float64-bits").solution(), Fraction("0.30103")]
    if name == "08-sliver-weight":
        numbers.append(92)
    if name == "09-front-face":
        numbers.append(dot(nb09.FACE_N, nb09.RAY_D))
    if name == "10-det-cross":
        mu, mv = (nb10.DIAG[0], 0, 0), (0, nb10.DIAG[1], 0)
        vectors += [mu, mv]
        numbers.append(nb10.DIAG[0] * nb10.DIAG[1] * nb10.DIAG[2])
    if name == "10-scaled-normal":
        vectors.append((Fraction(1, 2), 1, 0))
        numbers.append(Fraction(5, 4))
    if name == "11-repair-tetra":
        vertices = nb11.TETRA_VERTICES
        vectors.append(tuple(Fraction(sum(p[i] for p in vertices), 4) for i in range(3)))
    return vectors, numbers


def _spellings(x: Any) -> list[str]:
    q = Fraction(x)
    texts = {str(q), format_number(q, 4, trim=True), format_number(q, 3)}
    return sorted(texts | {t.replace("-", "−") for t in texts})


def _hints(name: str) -> list[str]:
    """Every hint the exercise can give: its hint, its listed mistakes' and those of probes."""
    ex = get(name)
    texts = [ex.hint] + [hint for _, hint, _ in ex.mistakes]
    probes: list[Any] = [wrong() if callable(wrong) else wrong for wrong, _, _ in ex.mistakes]
    probes += [7, "7/3", (5, 4, 3), "(5, 4, 3)", [(0, 0, 0), (1, 0, 0), (0, 1, 0)], True, "back"]
    messages = [check(name, p).message for p in probes]
    return texts + [m for m in messages if "could not be read" not in m]  # those echo the answer


def spoiled(name: str, hints: list[str] | None = None) -> list[str]:
    """The intermediate results of ``name`` that one of its hints states (and the prompt does not)."""
    vectors, numbers = _intermediates(name)
    prompt = get(name).prompt.replace(" ", "")
    found = []
    for hint in _hints(name) if hints is None else hints:
        flat = hint.replace(" ", "")
        for vec in vectors:
            forms = [
                "(" + ",".join(parts) + ")" for parts in zip(*map(_spellings, vec), strict=False)
            ]
            forms += ["(" + ",".join(_spellings(x)[0] for x in vec) + ")"]
            found += [
                f"{form} in {hint!r}" for form in forms if form in flat and form not in prompt
            ]
        for x in numbers:
            q = Fraction(x)
            if q.denominator == 1 and abs(q) <= 4:  # small whole numbers are everywhere
                continue
            for text in _spellings(x):
                pattern = rf"(?<![\d.]){re.escape(text)}(?![\d.]*\d)"
                if re.search(pattern, hint) and not re.search(pattern, get(name).prompt):
                    found.append(f"{text} in {hint!r}")
    return found


@pytest.mark.parametrize("name", sorted(notebook_names()))
def test_hints_never_state_an_intermediate_result(name):
    """A hint says what to compute next, never its value: no edge, N, |N|², dot product..."""
    assert spoiled(name) == []


def test_the_intermediate_check_can_fail():
    """Hints that state MU, det(M), |U|²|V|², B − A or the 0.301 of log10(2) are caught."""
    found = spoiled("10-det-cross", ["Multiply it out: MU = (2, 0, 0) and MV = (0, 3, 0)."])
    assert any("(2,0,0)" in f for f in found) and any("(0,3,0)" in f for f in found)
    assert spoiled("10-det-cross", ["det(M) = 24 > 0, so the orientation stays."])
    assert spoiled("02-lagrange", ["That is 36: now subtract (U · V)²."])
    assert spoiled("05-collinear", ["C − A must be a multiple of B − A = (2, 1, 1)."])
    assert spoiled("06-float64-digits", ["Each bit is worth log10(2), about 0.301 digits."])
    assert spoiled("11-repair-tetra", ["The centre is (1/4, 1/4, 1/4)."])
    assert not spoiled("10-det-cross", ["Transform U and V first, then cross them."])
