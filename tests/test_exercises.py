"""trinormal.exercises: every right answer in every exact form passes; wrong ones get true hints."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from trinormal import exercises, format_number, triangle_normal
from trinormal.exercises import (
    NOTEBOOK_MODULES,
    AnswerError,
    CheckResult,
    check,
    exercise,
    get,
    names,
    read_number,
)

ROOT = Path(__file__).resolve().parents[1]


# --------------------------------------------------------------------------- forms of a number


def exact_forms(q: Fraction) -> list[object]:
    """Every exact way a student may write the rational number q."""
    q = Fraction(q)
    forms: list[object] = [
        q,
        sp.Rational(q.numerator, q.denominator),
        f"{q.numerator}/{q.denominator}",
    ]
    if q.denominator == 1:
        n = q.numerator
        forms += [n, np.int64(n), sp.Integer(n), str(n)]
    d = q.denominator
    while d % 2 == 0:
        d //= 2
    while d % 5 == 0:
        d //= 5
    if d == 1:  # a terminating decimal
        text = str(Decimal(q.numerator) / Decimal(q.denominator))
        forms += [Decimal(text), text]
    if Fraction(float(q)) == q:  # exactly a float
        forms += [
            float(q),
            np.float64(q),
            np.float32(q) if Fraction(float(np.float32(q))) == q else float(q),
        ]
    return forms


def float_forms(x: float) -> list[object]:
    """Ways of writing a float answer (within an exercise's tolerance)."""
    return [x, np.float64(x), repr(x), Decimal(repr(x)), Fraction(x), sp.Float(x)]


def forms_of(value: object) -> list[object]:
    if isinstance(value, bool | str):
        return [value]
    if isinstance(value, tuple | list) and isinstance(value[0], tuple | list):  # points
        per = [forms_of(p) for p in value]
        count = min(len(p) for p in per)
        return [[p[i] for p in per] for i in range(count)]
    if isinstance(value, tuple | list):
        per = [forms_of(x) for x in value]
        count = min(len(p) for p in per)
        vectors: list[object] = [tuple(p[i] for p in per) for i in range(count)]
        vectors += [
            list(value),
            np.array([float(x) for x in value]),
            sp.Matrix([sp.nsimplify(x) for x in value]),
        ]
        return vectors
    if isinstance(value, float) and Fraction(value).denominator > 2**20:
        return float_forms(value)
    return exact_forms(Fraction(value))


#: Exact irrational solutions, given the sympy way.
SYMPY_SOLUTIONS = {
    "01-area": sp.sqrt(3) / 2,
    "10-scaled-normal": sp.Matrix([1 / sp.sqrt(5), 2 / sp.sqrt(5), 0]),
    "06-float64-digits": 53 * sp.log(2) / sp.log(10),
}
#: The same, as strings read with sympy.
STRING_SOLUTIONS = {"01-area": "sqrt(3)/2", "06-float64-digits": "53*log(2)/log(10)"}
#: The same, typed the way the notebooks print math (√, ·, the minus sign −).
PRINTED_SOLUTIONS = {
    "01-area": ["√3/2", "√(3)/2", "0.5·√3"],
    "02-lagrange": ["(4√2)**2", "32"],
    "10-scaled-normal": [("1/√5", "2/√5", "0"), ("√5/5", "2√5/5", 0)],
    "04-2d-nz": ["−6"],
}


def test_reading_numbers_in_every_form():
    third = Fraction(1, 3)
    for form in (third, sp.Rational(1, 3), "1/3", " 1/3 "):
        assert read_number(form) == third
    for form in (
        -2.5,
        "-2.5",
        Decimal("-2.5"),
        np.float64(-2.5),
        np.float32(-2.5),
        sp.Rational(-5, 2),
    ):
        assert read_number(form) == Fraction(-5, 2)
    assert read_number(np.int64(7)) == 7 and read_number(np.array(7)) == 7
    assert read_number(sp.sqrt(3) / 2) == pytest.approx(0.8660254037844386)
    for bad in (True, None, "thirty", "x + 1", "sqrt(-1)"):
        with pytest.raises(AnswerError):
            read_number(bad)


@pytest.mark.parametrize("name", names())
def test_the_solution_passes_in_every_form(name):
    ex = get(name)
    solution = ex.solution()
    for form in forms_of(solution):
        assert check(name, form), (name, form)
    if name in SYMPY_SOLUTIONS:
        assert check(name, SYMPY_SOLUTIONS[name]), name
    if name in STRING_SOLUTIONS:
        assert check(name, STRING_SOLUTIONS[name]), name
    for form in PRINTED_SOLUTIONS.get(name, []):
        assert check(name, form), (name, form)


def test_floats_count_within_the_stated_tolerance_only():
    want = triangle_normal((1, 0, 0), (0, 1, 0), (0, 0, 1)).area
    assert check("01-area", want + 0.0009) and check("01-area", 0.866)
    r = check("01-area", want + 0.0011)
    assert not r and r.status == "incorrect"
    assert "within 0.001" in repr(check("01-area", want))
    # the guide says "about 15 to 16 decimal digits": both are right, 17 and 14 are not
    for right in (15, 16, "15.5", 16.9):
        assert check("06-float64-digits", right), right
    for wrong in (14, 17, 7):
        assert not check("06-float64-digits", wrong), wrong
    assert check("10-scaled-normal", (0.4472, 0.8944, 0))
    assert not check("10-scaled-normal", (0.447, 0.894, 0))
    # exact exercises take the float nearest to the answer, and nothing else
    assert check("02-lagrange", 32.0) and not check("02-lagrange", 32.000001)


# --------------------------------------------------------------------------- many right answers


def test_any_point_on_the_line_is_collinear():
    from trinormal.exercises.nb05 import COLLINEAR_AB

    a, b = COLLINEAR_AB
    for t in (Fraction(1, 3), Fraction(-2), Fraction(5, 7), Fraction(3, 2), Fraction(2)):
        c = tuple(p + t * (q - p) for p, q in zip(a, b, strict=True))
        for form in forms_of(c):
            assert check("05-collinear", form), (t, form)
    third = (Fraction(5, 3), Fraction(7, 3), Fraction(1, 3))
    assert check("05-collinear", third)
    assert check("05-collinear", ("5/3", "7/3", "1/3"))
    assert check("05-collinear", (5 / 3, 7 / 3, 1 / 3))  # floats within the default tolerance
    assert check("05-collinear", (sp.Rational(5, 3), sp.Rational(7, 3), sp.Rational(1, 3)))


def test_any_downward_triangle_counts():
    from trinormal.exercises.nb05 import COLLINEAR_AB  # noqa: F401  (module reachable)

    for z in (0, "1/3", -2.5, Decimal("7.25"), sp.Rational(2, 7)):
        assert check("05-down-acb", [(0, 0, z), (1, 0, z), (0, 1, z)]), z
        assert check("05-down-acb", [(5, 5, z), (9, 6, z), (4, 8, z)]), z


def test_symbolic_answers_in_any_spelling():
    Ux, Uy, Vx, Vy = sp.symbols("Ux Uy Vx Vy")
    ux, uy, vx, vy = sp.symbols("u_x u_y v_x v_y")
    for answer in (
        "Uy*Vx - Ux*Vy",
        "-Ux*Vy + Vx*Uy",
        "-(Ux*Vy - Uy*Vx)",
        "uy*vx - ux*vy",
        "U_y*V_x - U_x*V_y",
        Uy * Vx - Ux * Vy,
        uy * vx - ux * vy,
        "Uy Vx - Ux Vy",  # products written with a space, as on paper
        "U_y V_x - U_x V_y",
        "Uy·Vx − Ux·Vy",  # typed with the notebook's symbols
    ):
        assert check("02-nz-reversed", answer), answer


def test_bools_and_words():
    for yes in (True, np.bool_(True), "True", "true"):
        assert check("03-collinear", yes)
    assert not check("03-collinear", 1)
    assert not check("02-scaling-power", True)
    for word in (" Front ", "the front", "front face", "FRONT"):
        assert check("09-front-face", word), word
    assert not check("09-front-face", "the back")


# --------------------------------------------------------------------------- wrong answers, true hints

#: For each exercise, wrong answers and a phrase the hint must contain.
WRONG = {
    "01-normal": [
        ((-1, -1, -1), "opposite way"),
        ((1 / 3**0.5,) * 3, "unit normal"),
        ((1, 2, 3), "Find U = B − A"),
    ],
    "01-area": [(3**0.5, "That is |N|"), (3**0.5 / 4, "half the area"), (3, "That is |N|²")],
    "01-reversed": [((1, 1, 1), "order A → B → C"), ((1, 2, 3), "swaps the factors")],
    "02-nz-reversed": [
        ("Ux*Vy - Uy*Vx", "That is N_z of U × V"),
        ("Uy*Vz - Uz*Vy", "does not involve Uz or Vz"),
        ("Ux*Vx - Uy*Vy", "x and y components"),
        ("a*b", "uses a, b"),
        ("UyVx - UxVy", "UxVy reads as one name"),
        ("Ux*(", "could not be read"),
    ],
    "02-scaling-power": [(1, "two edges"), (3, "volume"), (4, "two edges")],
    "02-lagrange": [
        (36, "That is |U|²|V|²"),
        (34, "its square"),
        (40, "not added"),
        (32**0.5, "That is |N|"),
        ((1, 2, 3), "one number"),
        ("thirty", "could not be read"),
    ],
    "03-row5-normal": [
        ((1, 0, 0), "unit normal"),
        ((-4, 0, 0), "opposite way"),
        ((0, 0, 4), "only one component"),
        ((1, 1), "3 numbers"),
    ],
    "03-row5-unit": [((4, 0, 0), "raw N"), ((-1, 0, 0), "opposite way"), ((0, 1, 0), "Divide N")],
    "03-collinear": [(False, "multiple"), ("yes", "True or False")],
    "04-dot-value": [(2, "That is N_z"), (5, "multiply matching"), ((0, 0, 2), "one number")],
    "04-weighted-sum": [
        ((1, 0, 1), "unit normals"),
        ((Fraction(1, 2), 0, 8), "N / 2"),
        ((-1, 0, 16), "small face"),
        ((1, 0, -16), "large face"),
        ((1, 0, 17), "component by component"),
    ],
    "04-2d-nz": [
        (6, "Wrong sign"),
        (-1, "unit normal"),
        (0, "not 0"),
        (-3, "signed area"),
        (5, "Add z = 0"),
    ],
    "05-down-acb": [
        ([(0, 0, 1), (0, 1, 1), (1, 0, 1)], "swap B and C"),
        ([(0, 0, 0), (1, 1, 1), (2, 2, 2)], "zero area"),
        ([(0, 0, 0), (0, 0, 1), (0, 1, 0)], "same height"),
        ([(0, 0, 0), (1, 0, 0)], "give 3 points"),
        ("up", "could not be read"),
    ],
    "05-collinear": [
        ((1, 2, 0), "not A or B"),
        (("3", "3", "1"), "not A or B"),
        ((5, 4, 3), "multiple of B − A = (2, 1, 1)"),
        (("5/3", "7/3", "1/2"), "multiple of B − A"),
        ((1, 2), "could not be read"),
    ],
    "05-scale-area": [
        (3, "product of two edges"),
        (27, "volume"),
        (6, "divide the one by the other"),
        (81, "before and after"),
    ],
    "06-float64-bits": [(52, "implicit"), (64, "sign and exponent"), (24, "nmant")],
    "06-float64-digits": [(53, "number of bits"), (17, "reads back exactly"), (7, "log10(2)")],
    "07-needle-degenerate": [(True, "DEFAULT_TOL"), ("maybe", "True or False")],
    "08-cube-corner-degrees": [(0.3398, "radians"), (45, "atan2")],
    "08-sliver-weight": [
        (0.5, "uniform weighting"),
        ("45/46", "neighbour's share"),
        (2, "divide the sliver"),
    ],
    "09-lambert": [(0.6, "y component"), (1, "clipped at zero")],
    "09-front-face": [("back", "N · d"), (1, "a word")],
    "10-scaled-normal": [
        ((2 / 5**0.5, 1 / 5**0.5, 0), "moved like a point"),
        ((0.5, 1, 0), "not a unit vector"),
        ((0, 0, 1), "inverse transpose"),
        (("1/√2", "1/√2", 0), "before the scale"),
    ],
    "10-det-cross": [
        ((0, 0, 24), "det(M) · (U × V)"),
        ((0, 0, 1), "before the transform"),
        ((0, 0, -6), "keeps the orientation"),
        ((0, 0, 5), "Right direction"),
    ],
}


def notebook_names() -> set[str]:
    """The notebooks' own exercises (the doctests may have registered demos by hand)."""
    return {ex.name for m in NOTEBOOK_MODULES for ex in exercises_module(m).EXERCISES}


def exercises_module(name: str):
    import importlib

    return importlib.import_module(f"trinormal.exercises.{name}")


def test_every_exercise_has_wrong_answers_tested():
    assert set(WRONG) == notebook_names()


@pytest.mark.parametrize("name", sorted(WRONG))
def test_wrong_answers_get_their_hint_and_not_the_solution(name):
    sol = get(name).solution()
    values = sol if isinstance(sol, tuple) else (sol,)
    for wrong, phrase in WRONG[name]:
        r = check(name, wrong)
        assert r.status == "incorrect", (name, wrong)
        assert r.message.startswith("not yet. ") and phrase in r.message, (name, wrong, r.message)
        if isinstance(sol, bool | str) or get(name).checker is not None:
            continue
        shown = "(" + ", ".join(format_number(x, 4, trim=True) for x in values) + ")"
        assert shown not in r.message and shown not in r._repr_html_(), name
        if not isinstance(sol, tuple):
            assert f" {format_number(sol, 4, trim=True)}" not in r.message, name


def test_hints_hold_for_the_answer_they_are_given_to():
    """Each 'mistake' hint names a real mistake: the mistaken value differs from the solution."""
    for name in names():
        ex = get(name)
        for wrong, _ in ex.mistakes:
            value = wrong() if callable(wrong) else wrong
            assert not check(name, value), (name, value)


def test_unanswered_is_friendly_and_not_an_error():
    for name in names():
        r = check(name, ...)
        assert isinstance(r, CheckResult)
        assert r.status == "unanswered" and not r
        assert (
            repr(r)
            == f"{name}: not answered yet. Replace ... with your answer and run the cell again."
        )


def test_result_displays():
    r = check("01-normal", (1, 1, 1))
    assert repr(r) == str(r) == "01-normal: correct."
    assert 'role="status"' in r._repr_html_() and r.correct and bool(r)


def test_unknown_name_suggests():
    with pytest.raises(KeyError, match="01-normal"):
        check("01-normall", 1)


# --------------------------------------------------------------------------- where exercises live


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
        "assert {n[:2] for n in names()} == {f'{i:02d}' for i in range(1, 11)}\n"
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
