"""trinormal.exercises: where the exercises live, the registry, and names that are not there."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from trinormal import exercises
from trinormal.exercises import NOTEBOOK_MODULES, check, exercise, get

ROOT = Path(__file__).resolve().parents[1]


def notebook_names() -> set[str]:
    """The notebooks' own exercises (the doctests may have registered demos by hand)."""
    import importlib

    return {
        ex.name
        for m in NOTEBOOK_MODULES
        for ex in importlib.import_module(f"trinormal.exercises.{m}").EXERCISES
    }


def test_unknown_name_suggests():
    r = check("01-normall", 1)
    assert r.status == "unknown" and not r
    assert str(r).startswith(
        "01-normall: no exercise named '01-normall'; did you mean '01-normal', "
    )
    assert str(r).endswith("? (names() lists them all)") and "\n" not in str(r)
    assert "No such exercise" in r._repr_html_()
    with pytest.raises(KeyError, match="did you mean '05-down-acb'") as info:
        get("05-down-abc")
    assert isinstance(info.value, exercises.UnknownExercise)
    assert str(info.value).startswith("no exercise named '05-down-abc'")  # no quotes around it
    assert check(["a list"], 1).status == "unknown"  # not a name at all: no TypeError either


def test_each_notebook_module_is_listed_and_holds_its_own_exercises():
    package = ROOT / "trinormal" / "exercises"
    files = sorted(p.stem for p in package.glob("nb*.py"))
    assert files == sorted(NOTEBOOK_MODULES)
    for module in NOTEBOOK_MODULES:
        mod = __import__(f"trinormal.exercises.{module}", fromlist=["EXERCISES"])
        assert mod.EXERCISES, module
        for ex in mod.EXERCISES:
            assert ex.name.startswith(module[2:] + "-"), (module, ex.name)


def test_notebooks_use_exactly_their_exercises():
    """Every exercise is asked in the notebook its number names, and only there."""
    asked: dict[str, str] = {}
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        nb = json.loads(path.read_text(encoding="utf-8"))
        for cell in nb["cells"]:
            if cell["cell_type"] != "code":
                continue
            for name in re.findall(r'check\("([0-9]{2}-[a-z0-9-]+)"', "".join(cell["source"])):
                assert path.name.startswith(name[:2] + "_"), (path.name, name)
                asked[name] = path.name
    assert set(asked) == notebook_names()


def test_importing_other_modules_registers_nothing():
    code = (
        "import trinormal.mesh, trinormal.plotting, trinormal.symbolic\n"
        "from trinormal import exercises\n"
        "assert not exercises._NOTEBOOKS and not exercises._REGISTRY\n"
        "assert len(exercises.names()) > 20\n"
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr


def test_check_finds_every_notebooks_exercises_in_a_fresh_interpreter():
    code = (
        "from trinormal.exercises import check, names\n"
        "r = check('05-collinear', ...)\n"
        "assert 'not answered yet' in str(r), r\n"
        "assert {n[:2] for n in names()} == {f'{i:02d}' for i in range(1, 12)}\n"
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr


def test_register_by_hand_and_replace():
    ex = exercise("98-test-sum", "1 + 1", expected=lambda: 2, hint="Count.")
    try:
        assert get("98-test-sum") is ex
        assert check("98-test-sum", 2) and not check("98-test-sum", 3)
        assert "Count." in check("98-test-sum", 5).message
        with pytest.raises(ValueError, match="already registered"):
            exercise("98-test-sum", "1 + 1", expected=3)
        exercise("98-test-sum", "1 + 1", expected=3, replace=True)
        assert check("98-test-sum", 3)

        @exercise("98-test-word", "Say cross.", hint="Not that one.")
        def checker(answer):
            return answer == "cross"

        assert check("98-test-word", "cross")
        assert check("98-test-word", "dot").message == "not yet. Not that one."
        assert callable(checker)
        with pytest.raises(ValueError, match="notebook's exercise"):
            exercise("01-normal", "?", expected=1)
    finally:
        exercises._REGISTRY.pop("98-test-sum", None)
        exercises._REGISTRY.pop("98-test-word", None)


def test_a_notebooks_exercise_wins_over_one_registered_by_hand():
    try:
        exercise("05-collinear", "?", expected=1, replace=True)
        assert check("05-collinear", ("5/3", "7/3", "1/3"))
    finally:
        exercises._REGISTRY.pop("05-collinear", None)


def test_negative_tolerance_is_refused():
    with pytest.raises(ValueError, match="tol"):
        exercise("98-bad", "?", expected=1, tol=-1)


def test_notebook_modules_read_answers_only_with_the_shared_reader():
    """No exercise parses an answer its own way: reading/ and judging.py hold the rules."""
    ad_hoc = (
        "parse_expr",
        "sympify(",
        "str(answer",
        "float(answer",
        "hasattr(answer",
        "len(answer",
    )
    for module in NOTEBOOK_MODULES:
        source = (ROOT / "trinormal" / "exercises" / f"{module}.py").read_text(encoding="utf-8")
        for word in ad_hoc:
            assert word not in source, (module, word)
