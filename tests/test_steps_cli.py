"""`trinormal.symbolic.steps` and the CLI's `--steps` agree on every number.

The CLI (standard library only) prints exact values as decimals, fractions and
radicals (``√314/6``); the symbolic module computes them with sympy from the
derived formulas. Each number the CLI prints is read back exactly and compared
with :func:`trinormal.symbolic.solution`, the values behind ``steps()``, whose
LaTeX is checked to show the same values.
"""

from __future__ import annotations

import random
import re
import subprocess
import sys
from fractions import Fraction

import pytest
import sympy as sp

from trinormal.cli import main
from trinormal.display import format_surd
from trinormal.symbolic import Solution, solution, steps

RADICAL = re.compile(r"(-?)(\d*)√(\d+)(?:/(\d+))?")


def read_number(text: str) -> sp.Expr:
    """One exact number as the CLI writes it: 3, -0.15, 1/3, √2/2, -3√5/10."""
    text = text.strip()
    m = RADICAL.fullmatch(text)
    if m:
        sign, coeff, root, den = m.groups()
        value = int(coeff or 1) * sp.sqrt(int(root)) / int(den or 1)
        return -value if sign else value
    f = Fraction(text)
    return sp.Rational(f.numerator, f.denominator)


def read_vector(text: str) -> tuple[sp.Expr, ...]:
    text = text.strip()
    assert text.startswith("(") and text.endswith(")"), text
    return tuple(read_number(x) for x in text[1:-1].split(","))


def split_approx(text: str) -> tuple[str, str | None]:
    exact, _, approx = text.partition(" ≈ ")
    return exact, (approx or None)


def rounded(value: sp.Expr, precision: int = 4) -> str:
    """The CLI's rounding of an exact value, from our exact value (value² is rational)."""
    sq = sp.Rational(value**2)
    return format_surd(bool(value < 0), int(sq.p), int(sq.q), precision)


def same(a: sp.Expr, b: sp.Expr) -> bool:
    return sp.simplify(a - b) == 0


def parse_cli(text: str) -> dict[str, str]:
    lines = text.splitlines()
    out = {"points": lines[0], "winding": lines[1]}
    for line in lines[2:]:
        label, _, rest = line.partition(" = ")
        out[label] = rest
    return out


def compare(cli_text: str, s: Solution) -> int:
    """Assert that every number in the CLI's --steps output equals ours; return how many."""
    cli = parse_cli(cli_text)
    count = 0
    points = dict(re.findall(r"([ABC]) = (\([^)]*\))", cli["points"]))
    for name, ours in zip("ABC", (s.a, s.b, s.c), strict=True):
        assert read_vector(points[name]) == ours
        count += 3
    for key, ours in (("U", s.u), ("V", s.v), ("N", s.normal)):
        assert read_vector(cli[key].split(" = ")[-1]) == ours, key
        count += 3
    for i, key in enumerate(("Nx", "Ny", "Nz")):
        assert read_number(cli[key].split(" = ")[-1]) == s.normal[i], key
        count += 1
    assert same(read_number(cli["|N|²"].split(" = ")[-1]), s.magnitude**2)
    for key, ours in (("|N|", s.magnitude), ("area", s.area)):
        exact, approx = split_approx(cli[key].split(" = ")[-1])
        assert same(read_number(exact), ours), key
        if approx is not None:
            assert approx == rounded(ours), key
        count += 2
    unit_text = cli["n̂"]
    if s.unit_normal is None:
        assert unit_text.startswith("undefined")
        assert s.reason in unit_text
        return count
    exact, approx = split_approx(unit_text.split(" = ")[-1])
    got = read_vector(exact)
    assert all(same(g, o) for g, o in zip(got, s.unit_normal, strict=True))
    if approx is not None:
        assert read_vector_text(approx) == [rounded(o) for o in s.unit_normal]
    assert s.offset is not None
    exact, approx = split_approx(cli["plane"].split("so d = ")[-1])
    assert same(read_number(exact), s.offset)
    if approx is not None:
        assert approx == rounded(s.offset)
    return count + 8


def read_vector_text(text: str) -> list[str]:
    return [x.strip() for x in text.strip()[1:-1].split(",")]


def our_steps_show(s: Solution, a, b, c, winding) -> None:
    """steps() prints solution()'s values: each value's LaTeX appears in its step."""
    tex = {label: latex for label, latex in steps(a, b, c, winding=winding)}
    for i, label in enumerate(("N_x", "N_y", "N_z")):
        assert tex[label].endswith("= " + sp.latex(s.normal[i]))
    assert tex["|N|"].endswith("= " + sp.latex(s.magnitude))
    assert tex["Area"].endswith("= " + sp.latex(s.area))
    if s.unit_normal is not None:
        assert tex["Unit normal"].endswith(
            r"\left(" + ", ".join(sp.latex(x) for x in s.unit_normal) + r"\right)"
        )
    else:
        assert s.reason in tex["Degenerate"]


CASES = [
    (("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ABC"),
    (("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ACB"),
    (("0", "0", "0"), ("2", "0", "0"), ("0", "3", "0"), "ABC"),
    (("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ABC"),
    (("0", "0", "0"), ("1", "1", "1"), ("2", "2", "2"), "ABC"),
    (("0.1", "0", "-1/3"), ("1", "2", "3"), ("0", "1", "0"), "ACB"),
    (("-1.5", "2.25", "7"), ("3/7", "-2", "0.125"), ("4", "4", "-4"), "ABC"),
    (("0", "0", "0"), ("1", "0", "0"), ("1", "1e-20", "0"), "ABC"),
    (("1", "1", "1"), ("1", "1", "1"), ("2", "0", "5"), "ABC"),
]


@pytest.mark.parametrize(("a", "b", "c", "winding"), CASES)
def test_cli_steps_and_symbolic_steps_agree(a, b, c, winding):
    args = [",".join(p) for p in (a, b, c)]
    p = subprocess.run(
        [sys.executable, "-m", "trinormal", *args, "--steps", "--winding", winding],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert p.returncode == 0, p.stderr
    s = solution(a, b, c, winding=winding)
    assert compare(p.stdout, s) >= 20
    our_steps_show(s, a, b, c, winding)


def test_agreement_on_random_fraction_triangles(capsys):
    rng = random.Random(5)
    for _ in range(30):
        pts = [
            tuple(
                str(Fraction(rng.randint(-30, 30), rng.choice([1, 2, 3, 5, 7, 10]))) for _ in "xyz"
            )
            for _ in "ABC"
        ]
        winding = rng.choice(["ABC", "ACB"])
        assert main([*(",".join(p) for p in pts), "--steps", "--winding", winding]) == 0
        s = solution(*pts, winding=winding)
        compare(capsys.readouterr().out, s)
        our_steps_show(s, *pts, winding)


def test_a_disagreement_is_caught():
    good = solution((0, 0, 0), (1, 0, 0), (0, 1, 0))
    text = subprocess.run(
        [sys.executable, "-m", "trinormal", "0,0,0", "1,0,0", "0,1,0", "--steps"],
        capture_output=True,
        text=True,
        timeout=60,
    ).stdout
    with pytest.raises(AssertionError):
        compare(text.replace("area = |N| / 2 = 0.5", "area = |N| / 2 = 0.6"), good)


def test_one_engine_behind_both():
    """The CLI's steps are the engine's; sympy's solution takes its numbers from the engine."""
    import trinormal.cli
    import trinormal.steps
    from trinormal import triangle_normal

    assert trinormal.cli.steps is trinormal.steps.steps
    rng = random.Random(7)
    for _ in range(20):
        pts = [tuple(Fraction(rng.randint(-9, 9), rng.randint(1, 6)) for _ in "xyz") for _ in "ABC"]
        winding = rng.choice(["ABC", "ACB"])
        w = trinormal.steps.working(triangle_normal(*pts, winding=winding))
        s = solution(*pts, winding=winding)
        assert s.a == tuple(sp.Rational(x) for x in w.a)
        assert s.u == tuple(sp.Rational(x) for x in w.u)
        assert s.normal == tuple(sp.Rational(x) for x in w.normal)
        assert same(s.magnitude, sp.Rational(w.root) * sp.sqrt(w.radicand))
        if w.unit_normal is not None:
            for x, c in zip(s.unit_normal, w.unit_normal, strict=True):
                assert same(x, sp.Rational(c) * sp.sqrt(w.radicand))
