"""Fuzzing every entry point with hostile input: an answer or a clear error, quickly, quietly.

Every call either returns or raises ``ValueError``/``TypeError``; no other exception,
no warning (warnings are errors here), no NaN from finite input, and each call ends
within a generous time bound (a hang or a runaway computation fails; ordinary calls
take microseconds to milliseconds). The runs are derandomized with a fixed budget, so
CI sees the same examples every time.
"""

from __future__ import annotations

import contextlib
import io
import itertools
import json
import math
import time
from collections.abc import Callable
from decimal import Decimal
from fractions import Fraction
from typing import Any

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trinormal import DEFAULT_TOL, format_number, format_vector, mesh, triangle_normal
from trinormal.cli import main
from trinormal.cli import steps as cli_steps
from trinormal.symbolic import steps as symbolic_steps
from trinormal.validation import check_precision, check_tolerance, check_winding

pytestmark = pytest.mark.filterwarnings("error")

#: Seconds any single call may take before the test calls it a hang.
TIME_BOUND = 3.0
BUDGET = settings(
    max_examples=150,
    derandomize=True,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)


def bounded(fn: Callable[..., Any], *args: Any, **kwargs: Any) -> tuple[bool, Any]:
    """Call ``fn``: ``(True, result)`` or ``(False, error)`` for ValueError/TypeError only."""
    start = time.perf_counter()
    try:
        out: tuple[bool, Any] = (True, fn(*args, **kwargs))
    except (ValueError, TypeError) as err:
        out = (False, err)
    elapsed = time.perf_counter() - start
    assert elapsed < TIME_BOUND, (fn.__name__, elapsed)
    if not out[0]:
        message = str(out[1])
        assert message and len(message) < 400, message[:400]
    return out


# --------------------------------------------------------------------------- strategies

TEXT_ALPHABET = "0123456789+-−.eE/ _x\t\u00a0\u3000\ufeff\u200b١１nafity"
texts = st.one_of(
    st.text(TEXT_ALPHABET, max_size=12),
    st.from_regex(r"[+\-−]?[0-9]{0,3}\.?[0-9]{0,3}([eE][+\-−]?[0-9]{1,5})?", fullmatch=True),
    st.builds(lambda n, k: "9" * n + "e" + str(k), st.integers(0, 1200), st.integers(-9999, 9999)),
    st.builds(lambda n, d: f"{n}/{d}", st.integers(-(10**450), 10**450), st.integers(-3, 10**450)),
    st.sampled_from(["nan", "-inf", "Infinity", "", " ", "1" * 1001, "1e-2200", "0x10", "1_0"]),
)
numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-(10**420), 10**420),
    st.fractions(max_denominator=10**420),
    st.decimals(allow_nan=True, allow_infinity=True),
    st.builds(
        lambda m, e: Decimal(f"{m}e{e}"), st.integers(-999, 999), st.integers(-(10**7), 10**7)
    ),
    st.builds(np.float32, st.floats(width=32, allow_nan=False)),
    st.builds(np.float64, st.floats(allow_nan=True)),
    st.builds(np.int64, st.integers(-(2**63), 2**63 - 1)),
    st.builds(sp.Rational, st.integers(-(10**410), 10**410), st.integers(1, 10**410)),
    st.builds(lambda x: sp.Float(x), st.floats(allow_nan=False, allow_infinity=False)),
    st.sampled_from([sp.sqrt(2), sp.oo, sp.nan, sp.Symbol("x"), sp.I, sp.pi]),
)
junk = st.sampled_from([None, True, 1j, object(), b"1", [1], {1: 2}])
coordinates = st.one_of(numbers, texts, junk)

vertices = st.one_of(
    st.lists(coordinates, min_size=3, max_size=3),
    st.tuples(coordinates, coordinates, coordinates),
    st.lists(numbers, min_size=0, max_size=5),
    st.builds(lambda xs: np.array(xs, dtype=float), st.lists(st.floats(), min_size=3, max_size=3)),
    st.sampled_from(
        [{1, 2, 3}, {"x": 1}, "1,2,3", b"123", bytearray(b"123"), 5, None, np.array(1.0)]
    ),
    st.builds(lambda xs: iter(xs), st.lists(st.integers(), max_size=3)),
    st.just(itertools.count()),
)
ordinary = st.tuples(*[st.floats(-10, 10, allow_nan=False)] * 3)
windings = st.sampled_from(["ABC", "ACB", "CBA", "abc", "", None, 3, ["ABC"]])
tolerances = st.one_of(
    st.just(DEFAULT_TOL),
    st.floats(allow_nan=True),
    st.fractions(max_denominator=10**30),
    st.decimals(allow_nan=True),
    texts,
    junk,
)
arithmetics = st.sampled_from(["exact", "exact", "float64", "float32", "float16", None])
precisions = st.one_of(st.integers(-2, 17), st.sampled_from(["4", "x", 2.5, None, True]))


# --------------------------------------------------------------------------- the core


@BUDGET
@given(vertices, vertices, vertices, windings, tolerances, arithmetics, precisions)
def test_core_answers_or_refuses_clearly(a, b, c, winding, tol, arithmetic, precision):
    ok, r = bounded(triangle_normal, a, b, c, winding, tol, arithmetic)
    if not ok:
        return
    _usable(r, precision)


@BUDGET
@given(st.tuples(numbers, numbers, numbers), ordinary, ordinary, arithmetics)
def test_core_on_any_numbers_in_one_vertex(a, b, c, arithmetic):
    ok, r = bounded(triangle_normal, a, b, c, arithmetic=arithmetic)
    if ok:
        _usable(r, 15)
        finite = all(
            math.isfinite(float(x))
            for x in (*r.exact.a, *r.exact.b, *r.exact.c)
            if abs(x) < 10**300
        )
        if finite:
            assert not any(math.isnan(x) for x in (*r.u, *r.v, *r.normal, r.magnitude, r.area))


def _usable(r: Any, precision: Any) -> None:
    """Everything a result offers works: formatting, JSON, both step-by-step engines."""
    ok, f = bounded(r.format, precision)
    if not ok:
        assert bounded(check_precision, precision)[0] is False
        f = r.format(4)
    assert all(isinstance(v, str) and "nan" not in v.lower() for v in f.values())
    json.dumps(r.to_dict(), allow_nan=False)
    assert bounded(cli_steps, r, 4)[0]
    e = r.exact
    assert bounded(symbolic_steps, e.a, e.b, e.c, r.winding, r.tol)[0]


@BUDGET
@given(windings, tolerances, precisions)
def test_option_checks_refuse_with_value_or_type_errors(winding, tol, precision):
    bounded(check_winding, winding)
    bounded(check_tolerance, tol)
    bounded(check_precision, precision)


# --------------------------------------------------------------------------- the formatter


@BUDGET
@given(st.one_of(numbers, junk), precisions, st.booleans())
def test_formatter_answers_or_refuses_clearly(x, precision, trim):
    ok, text = bounded(format_number, x, precision, trim)
    if ok:
        assert text and "nan" not in text.lower() and "inf" not in text.lower()
        assert bounded(format_vector, (x, x, x), precision, trim) == (
            True,
            f"({text}, {text}, {text})",
        )


# --------------------------------------------------------------------------- the CLI

point_texts = st.one_of(
    st.builds(",".join, st.lists(texts, min_size=1, max_size=4)),
    st.sampled_from(["0,0,0", "1,0,0", "0,1,0", "-1,2,3", "1e300,0,0", "5e-324,1,0"]),
)
options = st.lists(
    st.one_of(
        st.sampled_from(["--json", "--steps", "--bogus", "-h", "--", "x"]),
        st.tuples(
            st.sampled_from(["--winding", "--precision", "--tol", "--arithmetic"]),
            st.one_of(texts, st.sampled_from(["ACB", "15", "0", "float32", "float64"])),
        ).map(list),
    ),
    max_size=3,
)


@BUDGET
@given(st.lists(point_texts, min_size=0, max_size=4), options)
def test_cli_never_prints_a_traceback(points, opts):
    argv = list(points)
    for o in opts:
        argv += o if isinstance(o, list) else [o]
    out, err = io.StringIO(), io.StringIO()
    start = time.perf_counter()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv)
        except SystemExit as exit_:  # --help and -h end here, as argparse does
            status = exit_.code
    assert time.perf_counter() - start < TIME_BOUND
    assert status in (0, 1, 2)
    if status:
        lines = err.getvalue().splitlines()
        assert len(lines) == 1 and lines[0].startswith("trinormal: error: "), err.getvalue()
        assert len(lines[0]) < 400
    assert "Traceback" not in err.getvalue()


# --------------------------------------------------------------------------- the mesh functions

values = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False),
    st.floats(-1e-300, 1e-300),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([1.7e308, -1.7e308, 5e-324, 3e38, 1e30, 1e-165]),
)


@st.composite
def meshes(draw: Any) -> tuple[Any, Any]:
    nv = draw(st.integers(0, 7))
    finite = draw(st.booleans())
    vals = values if not finite else st.one_of(values.filter(math.isfinite), st.just(0.0))
    v = np.array(draw(st.lists(vals, min_size=3 * nv, max_size=3 * nv)), dtype=float)
    v = v.reshape(nv, 3)
    kind = draw(st.sampled_from(["float64", "float32", "int", "object", "shape"]))
    if kind == "float32":
        with np.errstate(over="ignore"):
            v = v.astype(np.float32)
    elif kind == "int":
        v = np.nan_to_num(v, nan=0, posinf=0, neginf=0).clip(-1e15, 1e15).astype(np.int64)
    elif kind == "object":
        v = v.astype(object)
    elif kind == "shape":
        v = v.reshape(-1)
    nf = draw(st.integers(0, 6))
    top = draw(st.sampled_from([nv + 1, 2**62, 2**63 - 1]))
    f = draw(st.lists(st.integers(-2, nv + 1) | st.just(top), min_size=3 * nf, max_size=3 * nf))
    faces = np.array(f, dtype=np.int64).reshape(nf, 3)
    if draw(st.booleans()) and nf:
        faces = faces.astype(np.uint64) if (faces >= 0).all() else faces.astype(float)
    return v, faces


@BUDGET
@given(meshes(), st.sampled_from(["angle", "area", "uniform", "mean"]), tolerances)
def test_mesh_functions_answer_or_refuse_clearly(m, weighting, tol):
    v, f = m
    finite = v.dtype != object and np.isfinite(np.asarray(v, dtype=float)).all()
    for fn, args in (
        (mesh.face_normals, (v, f, True, tol)),
        (mesh.face_normals, (v, f, False)),
        (mesh.degenerate_faces, (v, f, tol)),
        (mesh.face_areas, (v, f)),
        (mesh.vertex_normals, (v, f, weighting, tol)),
    ):
        ok, out = bounded(fn, *args)
        if ok and finite:
            assert not np.isnan(np.asarray(out, dtype=float)).any(), fn.__name__
    bounded(mesh.inconsistent_edges, f)
    bounded(mesh.consistent_winding, f)


def test_the_budget_is_fixed_and_derandomized():
    assert BUDGET.derandomize and BUDGET.max_examples == 150 and BUDGET.database is None
    assert Fraction(1, 3) and Decimal("1")  # the exact types the strategies use
