"""trinormal.exercises: the registry, check(), hints that never give the solution away."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from trinormal import exercises, format_number, triangle_normal
from trinormal.exercises import CheckResult, check, exercise, get, names


def test_every_notebook_01_to_04_has_two_to_four_exercises():
    for nb in ("01", "02", "03", "04"):
        count = sum(n.startswith(nb + "-") for n in names())
        assert 2 <= count <= 4, nb


def test_unanswered_is_friendly_and_not_an_error():
    for name in names():
        r = check(name, ...)
        assert isinstance(r, CheckResult)
        assert r.status == "unanswered" and not r
        assert (
            repr(r)
            == f"{name}: not answered yet. Replace ... with your answer and run the cell again."
        )


def test_the_solutions_pass():
    for name in names():
        ex = get(name)
        if ex.checker is None:
            assert check(name, ex.solution()), name


def test_numbers_are_compared_exactly_in_any_form():
    assert check("03-row5-normal", (4, 0, 0))
    assert check("03-row5-normal", [4.0, 0.0, 0.0])
    assert check("03-row5-normal", np.array([4, 0, 0]))
    assert check("03-row5-normal", sp.Matrix([4, 0, 0]))
    assert check("03-row5-normal", ("4", "0", "0"))
    assert check("02-lagrange", Fraction(32))
    assert check("02-lagrange", "32")
    assert not check("02-lagrange", 32.000001)


def test_tolerance_is_stated_and_applied():
    want = triangle_normal((1, 0, 0), (0, 1, 0), (0, 0, 1)).area
    assert check("01-area", want + 0.0009)
    assert check("01-area", sp.sqrt(3) / 2)
    r = check("01-area", want + 0.0011)
    assert not r and r.status == "incorrect"
    assert "within 0.001" in repr(check("01-area", want))


def test_wrong_answers_get_hints_without_the_solution():
    cases = {
        "01-normal": (5, 5, 4),
        "01-reversed": (1, 2, 3),
        "01-area": 3,
        "02-scaling-power": 3,
        "02-lagrange": 31,
        "03-row5-normal": (0, 0, 4),
        "03-row5-unit": (0, 1, 0),
        "04-dot-value": 2,
        "04-weighted-sum": (0, 0, 17),
        "04-2d-sign": 0,
    }
    for name, wrong in cases.items():
        r = check(name, wrong)
        assert r.status == "incorrect", name
        assert r.message.startswith("not yet.") and len(r.message) > len("not yet. "), name
        sol = get(name).solution()
        values = sol if isinstance(sol, tuple) else (sol,)
        shown = "(" + ", ".join(format_number(x, 4, trim=True) for x in values) + ")"
        assert shown not in r.message and shown not in r._repr_html_(), name
        if not isinstance(sol, tuple):
            assert f" {format_number(sol, 4, trim=True)}" not in r.message, name


def test_specific_hints():
    assert "opposite way" in check("01-normal", (-1, -1, -1)).message
    assert (
        "twice"
        in check("01-area", 2 * triangle_normal((1, 0, 0), (0, 1, 0), (0, 0, 1)).area).message
    )
    assert "Right direction, wrong length" in check("03-row5-normal", (1, 0, 0)).message
    assert "3 numbers" in check("01-normal", (1, 1)).message
    assert "one number" in check("02-lagrange", (1, 2, 3)).message
    assert "could not be read" in check("02-lagrange", "thirty").message
    assert "True or False" in check("03-collinear", "yes").message


def test_booleans_are_not_numbers():
    assert check("03-collinear", True)
    assert check("03-collinear", np.bool_(True))
    assert not check("03-collinear", 1)
    assert not check("02-scaling-power", True)


def test_symbolic_answer():
    Ux, Uy, Vx, Vy = sp.symbols("Ux Uy Vx Vy")
    assert check("02-nz-formula", "Ux*Vy - Uy*Vx")
    assert check("02-nz-formula", Ux * Vy - Uy * Vx)
    assert "opposite sign" in check("02-nz-formula", Uy * Vx - Ux * Vy).message
    assert not check("02-nz-formula", "Uy*Vz - Uz*Vy")
    assert "could not be read" in check("02-nz-formula", "Ux*(").message


def test_unknown_name_suggests():
    with pytest.raises(KeyError, match="01-normal"):
        check("01-normall", 1)


def test_register_from_another_module_and_replace():
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
    finally:
        exercises._REGISTRY.pop("98-test-sum", None)
        exercises._REGISTRY.pop("98-test-word", None)


def test_negative_tolerance_is_refused():
    with pytest.raises(ValueError, match="tol"):
        exercise("98-bad", "?", expected=1, tol=-1)


def test_result_displays():
    r = check("01-normal", (1, 1, 1))
    assert repr(r) == str(r) == "01-normal: correct."
    assert 'role="status"' in r._repr_html_() and r.correct and bool(r)


def test_modules_named_exercises_star_are_discovered(monkeypatch, tmp_path):
    import trinormal

    (tmp_path / "exercises_zz_test.py").write_text(
        "from trinormal.exercises import exercise\n"
        "exercise('97-found', 'found?', expected=True, replace=True)\n"
    )
    monkeypatch.setattr(trinormal, "__path__", [*trinormal.__path__, str(tmp_path)])
    try:
        assert check("97-found", True)
    finally:
        exercises._REGISTRY.pop("97-found", None)
        import sys

        sys.modules.pop("trinormal.exercises_zz_test", None)


def test_check_finds_exercises_of_every_notebook_without_imports():
    """A fresh interpreter: check() must find the explorer's exercises by itself."""
    import subprocess
    import sys

    code = (
        "from trinormal.exercises import check, names\n"
        "r = check('05-collinear', ...)\n"
        "assert 'not answered yet' in str(r), r\n"
        "assert any(n.startswith('05-') for n in names())\n"
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
