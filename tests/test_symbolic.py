"""trinormal.symbolic: derived formulas, proven identities, exact steps, lambdify agreement."""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
import sympy as sp

from trinormal import triangle_normal
from trinormal.symbolic import (
    EDGE_SYMBOLS,
    POINT_SYMBOLS,
    edge_vectors,
    guide_formulas,
    identities,
    normal_components,
    simplifies_to_zero,
    solution,
    steps,
    steps_latex,
)

ALL_POINTS = [s for p in POINT_SYMBOLS for s in p]
ALL_EDGES = [s for e in EDGE_SYMBOLS for s in e]


def test_symbols_are_the_guides():
    assert [str(s) for s in ALL_POINTS] == ["x1", "y1", "z1", "x2", "y2", "z2", "x3", "y3", "z3"]
    assert [str(s) for s in ALL_EDGES] == ["Ux", "Uy", "Uz", "Vx", "Vy", "Vz"]


def test_derived_components_equal_the_guides_written_formulas():
    written = guide_formulas()
    derived_edges = normal_components("edges")
    for d, w in zip(derived_edges, written["N"], strict=True):
        assert sp.expand(d - w) == 0
    u, v = edge_vectors()
    for d, w in zip(list(u) + list(v), written["U"] + written["V"], strict=True):
        assert sp.expand(d - w) == 0


def test_components_in_points_are_the_edge_formulas_substituted():
    u, v = edge_vectors()
    subs = dict(zip(ALL_EDGES, list(u) + list(v), strict=True))
    for p, e in zip(normal_components(), normal_components("edges"), strict=True):
        assert sp.expand(p - e.subs(subs)) == 0
        assert p.free_symbols <= set(ALL_POINTS)


def test_a_wrong_formula_is_told_apart():
    written = guide_formulas()["N"]
    derived = normal_components("edges")
    # the y component written with the wrong sign, as the first common mistake does
    assert sp.expand(derived.y + written[1]) != 0
    assert sp.expand(derived.x - written[1]) != 0


def test_normal_components_rejects_an_unknown_basis():
    with pytest.raises(ValueError, match="in_terms_of"):
        normal_components("vertices")  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def ids():
    """The identities, proven once for this module's tests (the library keeps nothing)."""
    return identities()


def test_every_identity_is_proven_and_has_latex(ids):
    assert set(ids) == {
        "normal_perpendicular_to_U",
        "normal_perpendicular_to_V",
        "lagrange",
        "winding_flips_sign",
        "translation_invariant",
        "scaling_squared",
        "magnitude_twice_area",
    }
    for name, ident in ids.items():
        assert ident.name == name
        assert ident.proven, name
        assert "=" in ident.latex and ident.statement
        assert simplifies_to_zero(ident.difference)
        assert ident._repr_latex_().startswith("$")


def test_the_prover_can_fail():
    x1, y1 = POINT_SYMBOLS[0][:2]
    assert not simplifies_to_zero(sp.Matrix([0, x1 - y1]))
    # the scaling identity with the wrong power is not proven
    A, B, C = (sp.Matrix(p) for p in POINT_SYMBOLS)
    s = sp.Symbol("s")
    n = (B - A).cross(C - A)
    wrong = (s * B - s * A).cross(s * C - s * A) - s * n
    assert not simplifies_to_zero(wrong)


def test_identities_hold_numerically_on_a_triangle(ids):
    values = dict(zip(ALL_POINTS, [1, 2, 3, 4, 0, -1, 2, 5, 1], strict=True))
    values.update(zip(ALL_EDGES, [3, -2, -4, 1, 3, -2], strict=True))
    values.update({sp.Symbol("s", real=True): 3})
    for t in sp.symbols("tx ty tz", real=True):
        values[t] = 7
    for ident in ids.values():
        assert ident.difference.subs(values) == sp.zeros(*ident.difference.shape)


def exact_numbers(latex: str) -> str:
    return latex.split(" = ")[-1]


def test_steps_worked_example():
    s = steps((0, 0, 0), (1, 0, 0), (0, 1, 0))
    labels = [x.label for x in s]
    assert labels == [
        "Points",
        "U = B − A",
        "V = C − A",
        "N_x",
        "N_y",
        "N_z",
        "N",
        "|N|",
        "Area",
        "Unit normal",
        "Plane",
    ]
    assert all(isinstance(label, str) and isinstance(tex, str) for label, tex in s)
    assert exact_numbers(s[1].latex) == r"\left(1, 0, 0\right)"
    assert exact_numbers(s[2].latex) == r"\left(0, 1, 0\right)"
    assert exact_numbers(s[6].latex) == r"\left(0, 0, 1\right)"
    assert exact_numbers(s[7].latex) == "1"
    assert exact_numbers(s[8].latex) == r"\frac{1}{2}"
    assert exact_numbers(s[9].latex) == r"\left(0, 0, 1\right)"


def test_steps_acb_flips():
    s = steps((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="ACB")
    assert s[1].label == "U = C − A"
    assert exact_numbers(s[6].latex) == r"\left(0, 0, -1\right)"


def test_steps_keep_radicals():
    s = solution((1, 1, 1), (2, 1, 1), (1, 2, 2))
    assert s.magnitude == sp.sqrt(2)
    assert s.unit_normal == (0, -sp.sqrt(2) / 2, sp.sqrt(2) / 2)
    tex = steps((1, 1, 1), (2, 1, 1), (1, 2, 2))[9].latex
    assert r"- \frac{\sqrt{2}}{2}" in tex


def test_steps_read_decimal_and_fraction_strings_exactly():
    s = solution(("0", "0", "0"), ("0.1", "0", "0"), ("0", "1/3", "0"))
    assert s.b[0] == sp.Rational(1, 10)
    assert s.c[1] == sp.Rational(1, 3)
    assert s.normal == (0, 0, sp.Rational(1, 30))
    assert s.area == sp.Rational(1, 60)
    tex = steps_latex(steps(("0", "0", "0"), ("0.1", "0", "0"), ("0", "1/3", "0")))
    assert r"\frac{1}{30}" in tex and "0.1" not in tex


def test_steps_degenerate_verdict():
    s = steps((0, 0, 0), (1, 1, 1), (2, 2, 2))
    assert s[-1].label == "Degenerate"
    assert "collinear" in s[-1].latex
    assert exact_numbers(s[7].latex) == "0"
    sol = solution((0, 0, 0), (1, 1, 1), (2, 2, 2))
    assert sol.degenerate and sol.unit_normal is None and sol.offset is None


def test_steps_bad_input_names_the_coordinate():
    with pytest.raises(ValueError, match=r"B\.y"):
        steps((0, 0, 0), (1, "x", 0), (0, 1, 0))


def random_point(rng: random.Random) -> tuple[Fraction, Fraction, Fraction]:
    return tuple(Fraction(rng.randint(-50, 50), rng.randint(1, 12)) for _ in range(3))  # type: ignore[return-value]


@pytest.mark.parametrize("winding", ["ABC", "ACB"])
def test_solution_agrees_with_the_exact_core(winding):
    rng = random.Random(3)
    for _ in range(40):
        a, b, c = (random_point(rng) for _ in range(3))
        r = triangle_normal(a, b, c, winding=winding)
        s = solution(a, b, c, winding=winding)
        e = r.exact
        assert s.u == tuple(sp.Rational(x.numerator, x.denominator) for x in e.u)
        assert s.v == tuple(sp.Rational(x.numerator, x.denominator) for x in e.v)
        assert s.normal == tuple(sp.Rational(x.numerator, x.denominator) for x in e.normal)
        m2 = e.magnitude_squared
        assert sp.simplify(s.magnitude**2 - sp.Rational(m2.numerator, m2.denominator)) == 0
        assert s.unit_normal is not None
        for exact, approx in zip(s.unit_normal, r.unit_normal, strict=True):
            assert abs(float(exact) - approx) <= 1e-15


def test_lambdify_agrees_with_the_core_exactly_on_fractions():
    f = sp.lambdify(ALL_POINTS, list(normal_components()), modules="math")
    rng = random.Random(7)
    for _ in range(200):
        pts = [random_point(rng) for _ in range(3)]
        flat = [x for p in pts for x in p]
        got = tuple(f(*flat))
        assert got == triangle_normal(*pts).exact.normal


def test_lambdify_agrees_with_float64_on_random_floats():
    import numpy as np

    f = sp.lambdify(ALL_POINTS, list(normal_components()), modules="numpy")
    rng = np.random.default_rng(11)
    pts = rng.uniform(-10, 10, size=(500, 3, 3))
    lam = np.array(f(*[pts[:, i, j] for i in range(3) for j in range(3)])).T
    for k in range(len(pts)):
        r = triangle_normal(*pts[k].tolist())
        exact = np.array(r.normal)
        fl = np.array(triangle_normal(*pts[k].tolist(), arithmetic="float64").normal)
        scale = np.abs(np.array([r.u, r.v])).max() ** 2
        assert np.allclose(lam[k], exact, rtol=0, atol=1e-13 * scale)
        assert np.allclose(lam[k], fl, rtol=0, atol=1e-13 * scale)


def test_steps_latex_joins_lines():
    tex = steps_latex(steps((0, 0, 0), (1, 0, 0), (0, 1, 0)))
    assert tex.startswith("\\begin{aligned}") and tex.endswith("\\end{aligned}")
    assert tex.count("\\\\\n") == 10


@pytest.mark.parametrize(
    "points",
    [
        ((5e-324, 1.7e308, -1.7e308), (1.7e308, 5e-324, 2.2e-308), (-1e-300, 3e307, 1e-320)),
        (("1e399", "-1e399", "1e-399"), ("1e-399", "1e399", "0"), ("3", "1/7", "1e399")),
    ],
)
def test_extreme_inputs_keep_exact_radicals(points):
    """Huge radicands are split by trinormal itself (sympy would spend seconds on primality).

    The values stay exact: |N|² and the unit normal's length are checked by rational
    arithmetic, and the LaTeX still shows a square root.
    """
    r = triangle_normal(*points)
    s = solution(*points)
    m2 = r.exact.magnitude_squared
    assert sp.Rational(m2.numerator, m2.denominator) == s.magnitude**2
    assert 4 * s.area**2 == s.magnitude**2
    assert s.unit_normal is not None and s.offset is not None
    assert sum(x**2 for x in s.unit_normal) == 1
    assert s.offset * s.magnitude == sum(n * a for n, a in zip(s.normal, s.a, strict=True))
    latex = [st.latex for st in steps(*points)]
    assert len(latex) == 11 and r"\sqrt" in latex[-4].split(" = ")[-1]
