"""trinormal.exercises: every right answer in every exact form passes; wrong ones get true hints."""

from __future__ import annotations

import json
import math
import re
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
    nb11,
    raw_normal,
    read_number,
    unit,
)
from trinormal.exercises.judging import tolerance_text

ROOT = Path(__file__).resolve().parents[1]


def notebook_names() -> set[str]:
    """The notebooks' own exercises (the doctests may have registered demos by hand)."""
    return {ex.name for m in NOTEBOOK_MODULES for ex in exercises_module(m).EXERCISES}


def exercises_module(name: str):
    import importlib

    return importlib.import_module(f"trinormal.exercises.{name}")


# --------------------------------------------------------------------------- forms of an answer


def printed(q: Fraction) -> str:
    """q as the notebooks print it: a decimal when it terminates, else p/q; the minus sign −."""
    d = q.denominator
    while d % 2 == 0:
        d //= 2
    while d % 5 == 0:
        d //= 5
    text = str(Decimal(q.numerator) / Decimal(q.denominator)) if d == 1 else str(q)
    return text.replace("-", "−")


def exact_forms(q: Fraction) -> list[object]:
    """Every exact way a student may write the rational number q."""
    q = Fraction(q)
    forms: list[object] = [
        q,
        sp.Rational(q.numerator, q.denominator),
        f"{q.numerator}/{q.denominator}",
        printed(q),
        (q,),  # a one-element tuple
        [str(q)],
        sp.Matrix([[sp.Rational(q.numerator, q.denominator)]]),  # 1 × 1, as U.T * V gives
    ]
    if q.denominator == 1:
        n = q.numerator
        forms += [n, np.int64(n), np.array(n), sp.Integer(n), str(n), np.array([[n]])]
    if printed(q) != str(q):  # a terminating decimal
        text = printed(q).replace("−", "-")
        forms += [Decimal(text), text]
    if Fraction(float(q)) == q:  # exactly a float
        forms += [float(q), np.float64(q), np.array(float(q)), sp.Float(float(q))]
        if Fraction(float(np.float32(q))) == q:
            forms.append(np.float32(q))
    return forms


def decimals_for(x: float, tol: float) -> str:
    """x printed with the fewest decimals that stay within the relative tolerance."""
    for d in range(16):
        text = format_number(x, d)
        if abs(Fraction(text) - Fraction(x)) <= Fraction(tol) * abs(Fraction(x)):
            return text
    raise AssertionError(x)


def float_forms(x: float, tol: float) -> list[object]:
    """Ways of writing a float answer, within the exercise's tolerance."""
    text = decimals_for(x, tol)
    return [
        x,
        np.float64(x),
        np.array(x),
        repr(x),
        Decimal(repr(x)),
        Fraction(x),
        sp.Float(x),
        (x,),
        text,
        text.replace("-", "−"),
    ]


def number_forms(value: object, tol: float | None) -> list[object]:
    if isinstance(value, float) and Fraction(value).denominator > 2**20:
        assert tol is not None, "an exact exercise with a float answer"
        return float_forms(value, tol)
    forms = exact_forms(Fraction(value))
    if tol is not None:  # an exact answer to an exercise with a tolerance: floats count too
        forms += float_forms(float(value), tol)
    return forms


def vector_forms(value: tuple, tol: float | None) -> list[object]:
    per = [number_forms(x, tol) for x in value]
    count = min(len(p) for p in per)
    vectors: list[object] = [tuple(p[i] for p in per) for i in range(count)]
    floats = [float(x) for x in value]
    exact_floats = all(Fraction(f) == Fraction(x) for f, x in zip(floats, value, strict=True))
    symbolic = [sp.nsimplify(x) for x in value]
    vectors += [
        list(value),
        sp.Matrix(symbolic),  # a column
        sp.Matrix(symbolic).T,  # a row
        sp.ImmutableMatrix(symbolic),
        "(" + ", ".join(printed(Fraction(x)) if tol is None else str(x) for x in value) + ")",
        "[" + ", ".join(str(x) for x in value) + "]",
        [[x] for x in value],  # a column as nested lists
    ]
    if exact_floats or tol is not None:
        vectors += [
            np.array(floats),
            np.array(floats).reshape(3, 1),
            np.array(floats).reshape(1, 3),
            (x for x in floats),  # a generator
        ]
    return vectors


def forms_of(value: object, tol: float | None = None) -> list[object]:
    if isinstance(value, bool | str):
        return [value]
    if isinstance(value, tuple | list) and isinstance(value[0], tuple | list):  # points
        per = [vector_forms(tuple(p), tol) for p in value]
        count = min(len(p) for p in per)
        forms: list[object] = [[p[i] for p in per] for i in range(count)]
        forms += [
            np.array(value, dtype=float),
            sp.Matrix(value),
            ", ".join("(" + ", ".join(str(x) for x in p) + ")" for p in value),
        ]
        if len(value) == 3:  # three points A, B, C (not the four faces of 11-repair-tetra)
            forms.append(dict(zip("ABC", value, strict=True)))
        else:  # the four faces of 11-repair-tetra, whose order does not matter
            forms += [set(map(tuple, value)), frozenset(map(tuple, value)), list(reversed(value))]
        return forms
    if isinstance(value, tuple | list):
        return vector_forms(tuple(value), tol)
    return number_forms(value, tol)


def _area_exact():
    from trinormal.exercises.nb01 import TRIANGLE

    return sp.sqrt(sp.Rational(triangle_normal(*TRIANGLE).exact.magnitude_squared)) / 2


def _scaled_normal_exact():
    v = sp.Matrix([sp.Rational(1, 2), 1, 0])
    return v / v.norm()


def _digits_exact():
    return get("06-float64-bits").solution() * sp.log(2) / sp.log(10)


#: Exact irrational solutions, the sympy way, computed from the exercises' own data.
SYMPY_SOLUTIONS = {
    "01-area": _area_exact,
    "10-scaled-normal": _scaled_normal_exact,
    "06-float64-digits": _digits_exact,
}


def _strings(name: str) -> list[object]:
    """The same, typed as text: sympy's spelling and the notebooks' (√, ·, −, °)."""
    if name == "01-area":
        m2 = triangle_normal(*exercises_module("nb01").TRIANGLE).exact.magnitude_squared
        return [f"sqrt({m2})/2", f"√{m2}/2", f"√({m2})/2", f"0.5·√{m2}", f"(1/2)*{m2}^(1/2)"]
    if name == "06-float64-digits":
        bits = get("06-float64-bits").solution()
        return [f"{bits}*log(2)/log(10)", f"{bits}·log(2)/log(10)"]
    if name == "10-scaled-normal":
        v = _scaled_normal_exact()
        as_text = [str(x).replace("sqrt(5)", "√5") for x in v]
        return [tuple(as_text), "(" + ", ".join(as_text) + ")", tuple(str(x) for x in v)]
    if name == "02-lagrange":
        root = sp.sqrt(get(name).solution())  # 4*sqrt(2)
        return [f"({str(root).replace('*sqrt(2)', '√2')})**2", f"({root})^2"]
    if name == "08-cube-corner-degrees":
        sol = get(name).solution()
        return [
            f"{format_number(sol, 4)}°",
            f"{format_number(sol, 3)} °",
            f"{format_number(sol, 4)}",
        ]
    if name == "04-2d-nz":
        return [f"−{-get(name).solution()}", f"- {-get(name).solution()}"]
    return []


def test_reading_numbers_in_every_form():
    third = Fraction(1, 3)
    for form in (
        third,
        sp.Rational(1, 3),
        "1/3",
        " 1/3 ",
        (third,),
        np.array([[third]], dtype=object),
    ):
        assert read_number(form) == third
    for form in (
        -2.5,
        "-2.5",
        "−2.5",
        Decimal("-2.5"),
        np.float64(-2.5),
        np.float32(-2.5),
        np.array(-2.5),
        sp.Rational(-5, 2),
        sp.Float(-2.5),
    ):
        assert read_number(form) == Fraction(-5, 2), form
    assert read_number(np.int64(7)) == 7 and read_number(np.array(7)) == 7
    # typed the way math is printed or typed on a phone: superscripts, full-width digits, ½
    assert read_number("(2√3)²") == 12 and read_number("１/３") == third
    assert read_number("½") == Fraction(1, 2) and read_number("10⁻³") == Fraction(1, 1000)
    for form in ("12.5°", "12.5 °", "12.5º", "12.5 deg", "12.5 degrees"):
        assert read_number(form, degrees=True) == Fraction(25, 2), form
        with pytest.raises(AnswerError, match="marked as degrees"):
            read_number(form)
    assert read_number(sp.sqrt(3) / 2) == pytest.approx(0.8660254037844386)
    for bad in (True, None, "thirty", "x + 1", "sqrt(-1)", "1e400", float("nan"), 10**400):
        with pytest.raises(AnswerError):
            read_number(bad)


@pytest.mark.parametrize("name", sorted(names()))
def test_the_solution_passes_in_every_form(name):
    ex = get(name)
    solution = ex.solution()
    forms = forms_of(solution, ex.tol)
    assert len(forms) >= (1 if isinstance(solution, bool | str) else 8), name
    for form in forms:
        r = check(name, form)
        assert r, (name, form, r.message)
    if name in SYMPY_SOLUTIONS:
        value = SYMPY_SOLUTIONS[name]()
        assert check(name, value), name
        if isinstance(value, sp.MatrixBase):
            assert check(name, value.T) and check(name, tuple(value)), name
    for form in _strings(name):
        assert check(name, form), (name, form)


def test_numpy_results_of_2d_products_are_numbers():
    """np.cross of 2-D vectors and np.dot give 0-d arrays or numpy scalars: numbers, not vectors."""
    from trinormal.exercises.nb04 import DOT_TRIANGLE, FLAT

    a, b, c = (np.array(p, dtype=float) for p in DOT_TRIANGLE)
    assert check("04-dot-value", np.dot(b - a, c - a))
    assert check("04-dot-value", np.array(np.dot(b - a, c - a)))
    assert check("04-dot-value", (b - a) @ (c - a))
    p, q, r = (np.array(x) for x in FLAT)
    u, v = q - p, r - p
    nz = u[0] * v[1] - u[1] * v[0]  # what np.cross of two 2-D vectors computes
    assert check("04-2d-nz", np.array(nz)) and check("04-2d-nz", np.int64(nz))
    assert check("04-2d-nz", np.array([[nz]])) and check("04-2d-nz", sp.Matrix([[nz]]))


# --------------------------------------------------------------------------- tolerances


def tol_exercises() -> list[str]:
    return sorted(n for n in notebook_names() if get(n).tol is not None)


def _kind(solution: object) -> str:
    return "vector" if isinstance(solution, tuple | list) else "number"


@pytest.mark.parametrize("name", tol_exercises())
def test_floats_count_within_the_stated_tolerance_only(name):
    ex = get(name)
    sol, tol = ex.solution(), ex.tol
    if _kind(sol) == "number":
        x = float(sol)
        for factor in (1 - 0.99 * tol, 1 + 0.99 * tol):
            assert check(name, x * factor), (name, x * factor)
        for factor in (1 - 1.01 * tol, 1 + 1.01 * tol):
            r = check(name, x * factor)
            assert r.status == "incorrect", (name, x * factor)
    else:
        v = [float(c) for c in sol]
        length = math.hypot(*v)
        for i in range(3):
            for sign in (1, -1):
                near = list(v)
                near[i] += sign * 0.99 * tol * length
                assert check(name, near), (name, near)
                far = list(v)
                far[i] += sign * 1.01 * tol * length
                assert not check(name, far), (name, far)
    # the verdict and the prompt state the same tolerance
    text = tolerance_text(tol, _kind(sol))
    assert text in ex.prompt, name
    assert text in check(name, sol).message, name


def test_the_tolerance_is_stated_in_each_notebook_too():
    """The exercise's text in the notebook (the markdown cell before its check) states it."""
    seen = set()
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        nb = json.loads(path.read_text(encoding="utf-8"))
        text_above = ""
        for cell in nb["cells"]:
            source = "".join(cell["source"])
            if cell["cell_type"] == "markdown":
                text_above = source
                continue
            for name in re.findall(r'check\("([0-9]{2}-[a-z0-9-]+)"', source):
                ex = get(name)
                assert f"**{name}.**" in text_above, (path.name, name)
                if ex.tol is not None:
                    assert tolerance_text(ex.tol, _kind(ex.solution())) in text_above, name
                    seen.add(name)
    assert seen == set(tol_exercises())


def test_no_common_slip_passes():
    """Every listed mistake is outside the tolerance (no slip is accepted as right)."""
    for name in notebook_names():
        ex = get(name)
        for wrong, hint, _ in ex.mistakes:
            value = wrong() if callable(wrong) else wrong
            r = check(name, value)
            assert r.status == "incorrect", (name, value)
            assert r.message == f"not yet. {hint}", (name, value, r.message)


def test_dividing_by_the_wrong_angle_fails():
    """The slip of issue 18: 2/90 instead of 2/92 is 2 % off, four times the tolerance."""
    sliver, neighbour = 2, 90
    r = check("08-sliver-weight", sliver / neighbour)
    assert r.status == "incorrect" and "neighbour's angle alone" in r.message
    assert check("08-sliver-weight", sliver / (sliver + neighbour))


def test_exact_exercises_take_the_exact_value_or_its_nearest_float():
    assert check("02-lagrange", 32.0) and check("02-lagrange", np.float64(32))
    r = check("02-lagrange", 32.000001)
    assert r.message == (
        "not yet. Very close, but not exactly right: this exercise wants the exact value."
    )
    third = Fraction(1, 3)  # a hand-made exact exercise with a non-binary answer
    exercise("98-third", "One third.", expected=third, replace=True)
    try:
        assert check("98-third", 1 / 3) and check("98-third", "1/3")
        assert not check("98-third", np.float32(1 / 3)) and not check("98-third", "0.3333")
    finally:
        exercises._REGISTRY.pop("98-third", None)


# --------------------------------------------------------------------------- many right answers


def test_any_point_on_the_line_is_collinear():
    from trinormal.exercises.nb05 import COLLINEAR_AB

    a, b = COLLINEAR_AB
    for t in (Fraction(1, 3), Fraction(-2), Fraction(5, 7), Fraction(3, 2), Fraction(2)):
        c = tuple(p + t * (q - p) for p, q in zip(a, b, strict=True))
        for form in forms_of(c):
            assert check("05-collinear", form), (t, form)
    floats = tuple(float(p + Fraction(1, 3) * (q - p)) for p, q in zip(a, b, strict=True))
    r = check("05-collinear", floats)  # floats within the default tolerance
    assert r and "within the tolerance for floats" in r.message


def test_the_scaled_triangle_can_be_typed_in_the_explorer():
    # 05-scale-area says "type the new coordinates in the boxes": the explorer takes each one,
    # in the notebook's triangle and in every student's variant
    from trinormal.exercises.nb05 import EXPLORER_RANGE, SCALE_ABC, SCALE_FACTOR
    from trinormal.exercises.variants import TEMPLATES
    from trinormal.explorer import Explorer

    ex = Explorer(a=SCALE_ABC[0], b=SCALE_ABC[1], c=SCALE_ABC[2])
    assert (ex.view.bounds[0], ex.view.bounds[1]) == (-EXPLORER_RANGE, EXPLORER_RANGE)
    before = ex.result.area
    for p, point in zip("abc", SCALE_ABC, strict=True):
        for q, x in zip("xyz", point, strict=True):
            ex.inputs[p + q].value = str(SCALE_FACTOR * x)
            assert ex.message.value == "", ex.message.value
    assert ex.result.exact.c == tuple(SCALE_FACTOR * x for x in SCALE_ABC[2])
    assert check("05-scale-area", ex.result.area / before)
    (template,) = [t for t in TEMPLATES if t.group == "05-scale-area"]
    for triangle, k in template.numbers():
        assert all(abs(k * x) <= EXPLORER_RANGE for p in triangle for x in p), (triangle, k)


def test_exact_properties_are_judged_exactly_and_a_near_miss_is_measured():
    from trinormal.exercises.nb05 import COLLINEAR_AB

    a, b = COLLINEAR_AB
    t = Fraction(1, 3)
    c = [p + t * (q - p) for p, q in zip(a, b, strict=True)]
    c[2] += Fraction(1, 10**20)  # exact, and 1e-20 off the line in z
    r = check("05-collinear", tuple(c))
    # distance to the line: |N| / |B − A|, from the exact core
    n2 = triangle_normal(a, b, c).exact.magnitude_squared
    ab2 = sum((q - p) ** 2 for p, q in zip(a, b, strict=True))
    distance = math.sqrt(float(n2 / ab2))
    assert r.status == "incorrect"
    assert f"C is {format_number(distance, 2)} away from the line" in r.message
    assert "exact numbers must be exactly on it" in r.message
    # a downward triangle a hair off horizontal: how far from straight down, in degrees
    tilt = Fraction(1, 100)
    r = check("05-down-acb", [(0, 0, 0), (1, 0, 0), (0, 1, tilt)])
    n = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, tilt), winding="ACB").exact.normal
    off = math.degrees(math.atan2(math.hypot(float(n[0]), float(n[1])), -float(n[2])))
    assert f"is {format_number(off, 2)}° away from straight down" in r.message


def test_a_needle_facing_down_is_right_and_not_called_zero_area():
    needle = [(0, 0, 0), (1, 0, 0), (2, 1e-13, 0)]
    r = triangle_normal(*needle, winding="ACB")
    assert r.area > 0 and r.degenerate  # a real area, below the direction tolerance
    res = check("05-down-acb", needle)
    assert res and "zero area" not in res.message and "no triangle" not in res.message
    assert f"its height is only {format_number(r.thickness, 2)} times" in res.message
    flat = check("05-down-acb", [(0, 0, 0), (1, 0, 0), (2, 0, 0)])
    assert not flat and "the area is exactly 0" in flat.message


def test_any_downward_triangle_counts():
    for z in (0, "1/3", -2.5, Decimal("7.25"), sp.Rational(2, 7), "−4"):
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
        ("Uy*Vx - Ux*Vy",),  # one-element tuple
        [Uy * Vx - Ux * Vy],
        sp.Matrix([[Uy * Vx - Ux * Vy]]),
    ):
        assert check("02-nz-reversed", answer), answer


def test_bools_and_words():
    for yes in (True, np.bool_(True), "True", "true", sp.true):
        assert check("03-collinear", yes)
    assert not check("03-collinear", 1)
    assert not check("02-scaling-power", True)
    for word in (" Front ", "the front", "front face", "FRONT", "front side"):
        assert check("09-front-face", word), word
    assert not check("09-front-face", "the back")


# --------------------------------------------------------------------------- wrong answers, true hints


def _sol(name: str):
    return get(name).solution()


def _scaled(name: str, k):
    return tuple(k * x for x in _sol(name))


def _neg(name: str):
    return _scaled(name, -1)


#: For each exercise, its common slips (computed from its own solution where they can be)
#: and the whole hint each one gets.
WRONG: dict[str, list[tuple[object, str]]] = {
    "01-normal": [
        (lambda: _neg("01-normal"), "Your vector points the opposite way: that is (C − A) × (B − A). Keep U = B − A as the first factor."),
        (lambda: tuple(round(x, 3) for x in unit(_sol("01-normal"))), "Right direction, but that is the unit normal N / |N|; this question asks for N itself."),
        (lambda: _scaled("01-normal", 2), "Right direction, wrong length."),
        (lambda: _scaled("01-normal", -2), "Your vector points the opposite way, and its length differs too."),
        ((1, 2, 3), "Find U = B − A and V = C − A first, then N = (UyVz − UzVy, UzVx − UxVz, UxVy − UyVx)."),
        (lambda: _sol("01-normal")[:2], "Your answer could not be read: expected 3 numbers (x, y, z), got 2."),
    ],
    "01-area": [
        (lambda: 2 * _sol("01-area"), "That is |N|, the parallelogram's area: the triangle is half of it."),
        (lambda: round(2 * _sol("01-area"), 3), "That is |N|, the parallelogram's area: the triangle is half of it."),
        (lambda: _sol("01-area") / 2, "That is half the area: |N| is already twice the area, so halve it only once."),
        (lambda: round(4 * _sol("01-area") ** 2), "That is |N|², the sum of the squares: take its square root, then halve it."),
        (lambda: round(_sol("01-area"), 2), "Your answer looks like the right value rounded to 2 decimals, which is further off than this exercise allows (within 0.1 % of the right value): keep more decimals."),
        (lambda: -_sol("01-area"), "Wrong sign."),
        (1, "The area is |N| / 2, and |N| is the square root of the sum of N's squared components."),
    ],
    "01-reversed": [
        (lambda: _neg("01-reversed"), "That is N for the order A → B → C. In the order A → C → B the first edge is C − A."),
        ((1, 2, 3), "Swapping the two edges swaps the factors of the cross product."),
    ],
    "02-nz-reversed": [
        ("Ux*Vy - Uy*Vx", "That is N_z of U × V, the order A → B → C. V × U has its factors swapped: what does that do to the sign?"),
        ("Uy*Vz - Uz*Vy", "A z component does not involve Uz or Vz: only the x and y components of U and V."),
        ("Ux*Vx - Uy*Vy", "Use the x and y components of U and V: the z component is (one product) − (another)."),
        ("a*b", "Your answer uses a, b: write it with Ux, Uy, Uz, Vx, Vy, Vz only."),
        ("UyVx - UxVy", "UxVy reads as one name: write a product with * or a space, as in Ux*Vy."),
        ("Ux*(", "Your answer could not be read: 'Ux*(' could not be read as an expression in Ux, Uy, Uz, Vx, Vy, Vz."),
        (sp.Matrix(sp.symbols("Vy Vz Vx")), "That is a whole vector: give only its z component, one expression."),
        (("Uy*Vz - Uz*Vy", "Uz*Vx - Ux*Vz", "Uy*Vx - Ux*Vy"), "Your last component is right: give it alone, not the whole vector."),
        (None, "Your answer could not be read: None is not an expression in Ux, Uy, Uz, Vx, Vy, Vz."),
    ],
    "02-scaling-power": [
        (1, "Each edge grows by s, but N is a product of two edges."),
        (3, "Three factors of s would scale a volume; N is a product of two edges."),
        (lambda: -_sol("02-scaling-power"), "Wrong sign."),
        (4, "Each edge is scaled by s, and N multiplies two edges."),
    ],
    "02-lagrange": [
        (36, "That is |U|²|V|²: now subtract (U · V)²."),
        (34, "You subtracted U · V: subtract its square, (U · V)²."),
        (40, "(U · V)² is subtracted, not added."),
        (lambda: math.sqrt(_sol("02-lagrange")), "That is |N|: the question asks for |N|²."),
        (lambda: round(math.sqrt(_sol("02-lagrange")), 3), "That is |N|: the question asks for |N|²."),
        ((1, 2, 3), "Your answer could not be read: expected one number, got 3 values."),
        ("thirty", "Your answer could not be read: 'thirty' is not a number."),
        ("Ux + 1", "Your answer could not be read: 'Ux + 1' has Ux in it: give a number."),
    ],
    "03-row5-normal": [
        (lambda: unit(_sol("03-row5-normal")), "Right direction, but that is the unit normal: the raw N keeps its length |N|."),
        (lambda: _neg("03-row5-normal"), "Your vector points the opposite way: that is V × U. N = U × V with U = B − A first."),
        ((0, 0, 4), "Compute U = B − A and V = C − A first, then N = U × V."),
        ((1, 1), "Your answer could not be read: expected 3 numbers (x, y, z), got 2."),
    ],
    "03-row5-unit": [
        (lambda: raw_normal(*exercises_module("nb03").ROW5), "Right direction, but that is the raw N: divide it by its length |N|."),
        (lambda: _neg("03-row5-unit"), "Your vector points the opposite way."),
        ((0, 1, 0), "Divide N by |N|."),
        ((2, 0, 0), "Right direction, but not a unit vector: divide it by its length."),
    ],
    "03-collinear": [
        (False, "Compare B − A with C − A: is one a multiple of the other?"),
        ("yes", "Answer True or False."),
        (1, "Answer True or False (1 is a number)."),
    ],
    "04-dot-value": [
        (2, "That is N_z, the z component of U × V. The dot product multiplies matching components (x with x, y with y, z with z) and adds them."),
        (5, "U · V = UxVx + UyVy + UzVz: multiply matching components and add."),
        ((0, 0, 2), "Your answer could not be read: expected one number, got 3 values."),
        (lambda: -_sol("04-dot-value"), "Wrong sign."),
        (lambda: _sol("04-dot-value") + 1e-9, "Very close, but not exactly right: this exercise wants the exact value."),
    ],
    "04-weighted-sum": [
        ((1, 0, 1), "You added unit normals, so both faces count the same. Add the raw normals, whose lengths are twice the areas."),
        (lambda: _scaled("04-weighted-sum", Fraction(1, 2)), "That is the sum of N / 2 (the areas as vectors): add the raw normals N themselves."),
        ((-1, 0, 16), "The small face's normal is reversed: for (0,0,0), (0,1,0), (0,0,1) take U = B − A, its second point minus its first, as the first factor."),
        ((1, 0, -16), "The large face's normal is reversed: for (0,0,0), (4,0,0), (0,4,0) take U = B − A, its second point minus its first, as the first factor."),
        ((1, 0, 17), "Compute each raw normal N = U × V, then add them component by component."),
    ],
    "04-2d-nz": [
        (lambda: -_sol("04-2d-nz"), "Wrong sign. Seen from +z, does P → Q → R turn counterclockwise (positive) or clockwise?"),
        (-1, "That is the unit normal's z component: the question asks for the raw N_z, whose size is twice the area."),
        (0, "A flat triangle in the xy-plane has its normal along z, so N_z is not 0."),
        (lambda: _sol("04-2d-nz") / 2, "That is the signed area of the triangle: the raw N_z is twice it."),
        (5, "Add z = 0 to each point, then N_z = UxVy − UyVx with U = Q − P and V = R − P."),
    ],
    "05-down-acb": [
        ([(0, 0, 1), (0, 1, 1), (1, 0, 1)], "In the order A→C→B your normal points straight up (+z): swap B and C."),
        ([(0, 0, 0), (1, 1, 1), (2, 2, 2)], "These points make no triangle: they lie on one line (or two of them coincide), so the area is exactly 0 and there is no normal at all."),
        ([(0, 0, 0), (0, 0, 1), (0, 1, 0)], "In the order A→C→B your normal is 90.00° away from straight down: it must have no x or y part. Put all three points at the same height z, then check the order A→C→B with the right-hand rule."),
        ([(0, 0, 0), (1, 0, 0)], "Your answer could not be read: give 3 points (x, y, z), got 2."),
        ("up", "Your answer could not be read: give 3 points (x, y, z), each in brackets: (x, y, z)."),
        ({(0, 0, 1), (1, 0, 1), (0, 1, 1)}, "Your answer could not be read: a set has no order, and the order of the points matters: give 3 points (x, y, z)."),
    ],
    "05-collinear": [
        ((1, 2, 0), "C must be a new point, not A or B again (that is the easy way to area 0)."),
        (("3", "3", "1"), "C must be a new point, not A or B again (that is the easy way to area 0)."),
        ((5, 4, 3), "C is 0.91 away from the line through A and B (exact numbers must be exactly on it): C − A must be a multiple of B − A."),
        ((1, 2), "Your answer could not be read: expected 3 numbers (x, y, z), got 2."),
        ((5.0, 4.0, 2.001), "C is 9.13e-04 away from the line through A and B (too far for a float): C − A must be a multiple of B − A."),
    ],
    "05-scale-area": [
        (lambda: exercises_module("nb05").SCALE_FACTOR, "Each edge grows by that factor, but the area is a product of two edges."),
        (lambda: exercises_module("nb05").SCALE_FACTOR ** 3, "That is how a volume grows (three lengths); an area is two lengths."),
        (lambda: 1 / _sol("05-scale-area"), "That is the factor from the new area back to the old one: divide the new area by the old."),
        (6, "Compute the area before and after (triangle_normal(...).area, or the explorer's readout) and divide the one by the other."),
    ],
    "06-float64-bits": [
        (lambda: _sol("06-float64-bits") - 1, "That is nmant, the stored bits: one more leading bit is implicit."),
        (64, "64 is the whole format, sign and exponent included: count the significand."),
        (24, "np.finfo(np.float64).nmant counts the stored bits; add the implicit leading bit."),
    ],
    "06-float64-digits": [
        (lambda: get("06-float64-bits").solution(), "That is the number of bits: multiply it by log10(2)."),
        (17, "17 digits are what it takes to write any float64 so that it reads back exactly; the digits it carries are fewer: count log10(2) per significand bit."),
        (7, "That is about float32's count, from its 24 significand bits: a float64 has more."),
        (lambda: 24 * math.log10(2), "That is float32's count, from its 24 significand bits: a float64 has more."),
        (14, "Each significand bit is worth log10(2) decimal digits: count the bits, then multiply."),
        (lambda: math.ceil(_sol("06-float64-digits")), "That is p · log10(2) rounded up to a whole number: give the value itself."),
        (lambda: math.floor(_sol("06-float64-digits")), "That is p · log10(2) rounded down to a whole number: give the value itself."),
        (lambda: (get("06-float64-bits").solution() - 1) * math.log10(2), "That counts the stored bits (nmant) only: p includes the implicit leading bit."),
    ],
    "07-needle-degenerate": [
        (lambda: not _sol("07-needle-degenerate"), "Compute |N| and the longest of the three sides, L, then compare |N| / L² with DEFAULT_TOL = 1e-12: degenerate means |N| <= tol · L², whichever corner comes first."),
        ("maybe", "Answer True or False."),
    ],
    "08-cube-corner-degrees": [
        (lambda: math.radians(_sol("08-cube-corner-degrees")), "That looks like radians: the question asks for degrees (math.degrees)."),
        (lambda: 90 - _sol("08-cube-corner-degrees"), "That is 90° minus the angle between the two normals: measure the angle between the normals themselves."),
        (lambda: round(_sol("08-cube-corner-degrees"), 1), "Your answer looks like the right value rounded to 1 decimal, which is further off than this exercise allows (within 0.05 % of the right value): keep more decimals."),
        (45, "Compute both with mesh.vertex_normals and measure the angle between them with atan2(|p × q|, p · q)."),
        ("19.47 rad", "Your answer could not be read: '19.47 rad' could not be read as a number."),
    ],
    "08-sliver-weight": [
        (0.5, "One half is what uniform weighting gives; weigh by the angles."),
        ("2/90", "That divides by the neighbour's angle alone: divide by the sum of both angles, the sliver's included."),
        (lambda: round(2 / 90, 4), "That divides by the neighbour's angle alone: divide by the sum of both angles, the sliver's included."),
        ("2/88", "That divides by the difference of the angles: divide by their sum."),
        ("45/46", "That is the neighbour's share: the sliver gets the rest, its own angle over the sum."),
        (lambda: round(float(_sol("08-sliver-weight")), 3), "Your answer looks like the right value rounded to 3 decimals, which is further off than this exercise allows (within 0.5 % of the right value): keep more decimals."),
        (2, "Angle weighting weighs each face by its corner angle: divide the sliver's angle by the sum of both."),
        ("2°", "Your answer could not be read: '2°' is marked as degrees, but this answer is not an angle."),
    ],
    "09-lambert": [
        (0.6, "That is l's y component; n · l multiplies matching components and adds."),
        (1, "The dot product of the two unit vectors, clipped at zero."),
        (lambda: -_sol("09-lambert"), "Wrong sign."),
    ],
    "09-front-face": [
        ("back", "Compute N · d: negative means the ray travels against the normal and meets the front; positive means it meets the back."),
        (1, "Answer with a word in quotes: 'front' or 'back'."),
    ],
    "10-scaled-normal": [
        (lambda: unit((2, 1, 0)), "That is M n normalised: the normal moved like a point. Use M⁻ᵀ, the inverse transpose, instead."),
        ((0.5, 1, 0), "Right direction, but not a unit vector yet: divide by its length."),
        (lambda: unit((1, 1, 0)), "That is the normal before the scale: stretching x tilts the plane, so its normal changes too."),
        (("1/√2", "1/√2", 0), "That is the normal before the scale: stretching x tilts the plane, so its normal changes too."),
        ((0, 0, 1), "Transform the normal by the inverse transpose, then normalise."),
        (lambda: tuple(round(x, 3) for x in _sol("10-scaled-normal")), "Your answer looks like the right value rounded to 3 decimals, which is further off than this exercise allows (each component within 0.01 % of the right vector's length): keep more decimals."),
        ((1, 2, 0), "Right direction, but not a unit vector: divide it by its length."),
        (lambda: _neg("10-scaled-normal"), "Your vector points the opposite way."),
    ],
    "10-det-cross": [
        (lambda: _scaled("10-det-cross", 4), "That is det(M) · (U × V). The identity is det(M) · M⁻ᵀ (U × V): apply M⁻ᵀ too, or compute MU and MV and cross them."),
        ((0, 0, 1), "That is U × V before the transform: transform U and V first."),
        (lambda: _neg("10-det-cross"), "Your vector points the opposite way: det(M) is positive, so the transform keeps the orientation."),
        ((0, 0, 5), "Right direction, wrong length."),
        ((0, 6, 0), "Transform U and V first (MU and MV), then take their cross product."),
    ],
    "11-flipped-face": [
        (0, "Face 0 is wound like its neighbours: its normal points out of the ball. The faces to flip are the ones the view outlines (a face you see blue through the hole is the inside of a face wound correctly); report.faces_to_flip lists them."),
        ("17", "Face 17 is wound like its neighbours: its normal points out of the ball. The faces to flip are the ones the view outlines (a face you see blue through the hole is the inside of a face wound correctly); report.faces_to_flip lists them."),
        (1263, "The ball has faces 0 to 1262; there is no face 1263. Click a face with an outline in the view to see its number."),
        (-1, "The ball has faces 0 to 1262; there is no face -1. Click a face with an outline in the view to see its number."),
        (1.5, "Your answer could not be read: a face or vertex number is a whole number such as 17."),
        ("seventy", "Your answer could not be read: 'seventy' is not a number."),
    ],
    "11-repair-tetra": [
        (nb11.TETRA_FACES, "These are the faces as given: one of them is still wound against its neighbours. Swap two corners of that one face."),
        ([(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 2, 3)], "Your faces are not wound consistently: across every shared edge the two faces must walk the edge in opposite directions (mesh.check says to turn 3 faces over)."),
        ([(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)], "Every face is wound the same way now, but the normals point into the tetrahedron (its signed volume is negative): turn every face over."),
        ([(0, 2, 1)] * 4, "Keep the same four triangles: each face must use the same three corners as one of the faces given. Only the order of the corners in one face changes."),
        ([(0, 2, 1), (0, 1, 3), (0, 3, 2)], "Your answer could not be read: give 4 faces of 3 vertex numbers, got 3."),
        (list(range(12)), "Your answer could not be read: give 4 faces of 3 vertex numbers, got more than 4."),
        ([(0, 2, 1), (0, 1), (0, 3, 2), (1, 2, 3)], "Your answer could not be read: face 2: expected 3 numbers (its corners' vertex numbers), got 2."),
        ([(0, 2, 1), (0, 1.5, 3), (0, 3, 2), (1, 2, 3)], "Your answer could not be read: face 2: a face or vertex number is a whole number such as 17."),
        ("faces", "Your answer could not be read: give 4 faces of 3 vertex numbers, each in brackets: (a, b, c)."),
    ],
}  # fmt: skip


def test_every_exercise_has_wrong_answers_tested():
    assert set(WRONG) == notebook_names()


@pytest.mark.parametrize("name", sorted(WRONG))
def test_wrong_answers_get_their_hint_and_not_the_solution(name):
    sol = get(name).solution()
    values = sol if isinstance(sol, tuple) else (sol,)
    for wrong, hint in WRONG[name]:
        answer = wrong() if callable(wrong) else wrong
        r = check(name, answer)
        assert r.status == "incorrect", (name, answer)
        assert r.message == f"not yet. {hint}", (name, answer, r.message)
        if isinstance(sol, bool | str) or get(name).checker is not None:
            continue
        if isinstance(values[0], tuple):
            continue
        shown = "(" + ", ".join(format_number(x, 4, trim=True) for x in values) + ")"
        assert shown not in r.message and shown not in r._repr_html_(), name
        if not isinstance(sol, tuple) and format_number(sol, 4, trim=True) not in hint:
            assert f" {format_number(sol, 4, trim=True)}" not in r.message, name


def test_hints_about_direction_and_length_hold_for_the_answer():
    """ "Right direction" only for a parallel answer; "opposite" only for an antiparallel one."""
    rng = np.random.default_rng(18)
    for name in ("01-normal", "03-row5-normal", "03-row5-unit", "10-scaled-normal", "10-det-cross"):
        want = np.array([float(x) for x in get(name).solution()])
        tries = [want * k for k in (-3, -1, 0.5, 2, 1.0001)]
        tries += [want + rng.normal(size=3) * s for s in (1e-3, 0.1, 1)]
        for answer in tries:
            message = check(name, tuple(answer)).message
            cross = np.linalg.norm(np.cross(answer, want))
            scale = np.linalg.norm(answer) * np.linalg.norm(want)
            if "Right direction" in message:
                assert cross <= 1e-4 * scale and answer @ want > 0, (name, answer, message)
            if "opposite way" in message:
                assert cross <= 1e-4 * scale and answer @ want < 0, (name, answer, message)
            if "rounded to" in message:
                d = int(re.search(r"rounded to (\d+) decimal", message)[1])
                assert np.all(np.abs(answer - want) <= 0.5 * 10.0**-d + 1e-15), (name, answer)


def test_a_correctly_rounded_unit_vector_is_told_it_is_rounded_not_wrong_length():
    sol = get("10-scaled-normal").solution()
    coarse = tuple(round(x, 3) for x in sol)
    fine = tuple(round(x, 5) for x in sol)
    assert check("10-scaled-normal", fine)
    r = check("10-scaled-normal", coarse)
    assert "rounded to 3 decimals" in r.message
    assert "Right direction" not in r.message and "wrong length" not in r.message


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
