"""The degenerate rule of trinormal.mesh: a face is degenerate iff |N| <= tol · L².

N = (B − A) × (C − A) and L² = max(|B − A|², |C − A|², |C − B|²). The reference
here is the rule in exact rational arithmetic, written independently of the
package; the mesh's verdicts must equal it for every face, also for faces so
close to the threshold that float64 rounding alone could not decide them.
"""

from __future__ import annotations

from fractions import Fraction
from itertools import permutations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trinormal import mesh
from trinormal.tolerances import DEFAULT_TOL
from trinormal.validation import check_tolerance

pytestmark = pytest.mark.filterwarnings("error")

EPS = np.finfo(np.float64).eps
#: The three rotations of the corners in both windings.
ORDERS = list(permutations(range(3)))


def exact_edges(a, b, c):
    """U = B − A, V = C − A, W = C − B and N = U × V, as Fractions."""
    pa, pb, pc = ([Fraction(x) for x in p] for p in (a, b, c))
    u = [y - x for x, y in zip(pa, pb, strict=True)]
    v = [y - x for x, y in zip(pa, pc, strict=True)]
    w = [y - x for x, y in zip(pb, pc, strict=True)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return u, v, w, n


def exact_ratio(a, b, c) -> Fraction:
    """|N|² / L⁴ of face A, B, C, exactly (0 when all three corners are one point)."""
    u, v, w, n = exact_edges(a, b, c)
    l2 = max(sum(x * x for x in e) for e in (u, v, w))
    return sum(x * x for x in n) / (l2 * l2) if l2 else Fraction(0)


def exactly_degenerate(a, b, c, tol: object = DEFAULT_TOL) -> bool:
    """The rule in exact arithmetic, tol read exactly as the package reads it."""
    t = Fraction(*check_tolerance(tol))
    return exact_ratio(a, b, c) <= t * t


def float_verdict(a, b, c, tol: float) -> bool:
    """The rule evaluated naively in float64, for showing where floats alone go wrong."""
    a, b, c = (np.asarray(p, dtype=np.float64) for p in (a, b, c))
    u, v, w = b - a, c - a, c - b
    n = np.cross(u, v)
    l2 = max(u @ u, v @ v, w @ w)
    return bool(n @ n <= tol * tol * l2 * l2)


def borderline_faces(n: int, tol: float, seed: int, spread: float = 3e-4) -> np.ndarray:
    """Faces (n, 3, 3) whose |N| / L² is within ``spread`` (relative) of ``tol``, turned at random.

    Each starts as A = 0, B = (1, 0, 0), C = (x, h, 0) with x in [0.2, 0.8] (so L = |B − A|
    = 1) and h = tol (1 + δ); a random rotation and offset then round the corners to floats.
    """
    rng = np.random.default_rng(seed)
    faces = np.zeros((n, 3, 3))
    faces[:, 1, 0] = 1.0
    faces[:, 2, 0] = rng.uniform(0.2, 0.8, n)
    faces[:, 2, 1] = tol * (1 + rng.uniform(-spread, spread, n))
    q, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    offset = rng.normal(size=(n, 1, 3)) * rng.choice([0.0, 1.0, 100.0], size=(n, 1, 1))
    out: np.ndarray = faces @ q.transpose(0, 2, 1) + offset
    return out


def as_mesh(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A soup mesh: every face its own three vertices."""
    return corners.reshape(-1, 3), np.arange(corners.shape[0] * 3).reshape(-1, 3)


def verdicts_in_every_order(v: np.ndarray, f: np.ndarray, tol: float) -> np.ndarray:
    """degenerate_faces for each of the six orders of every face's corners: (6, F)."""
    return np.array([mesh.degenerate_faces(v, f[:, list(o)], tol=tol) for o in ORDERS])


# --------------------------------------------------------------------------- symmetry


@pytest.mark.parametrize("scale", [1.0, 2.0**-1000, 2.0**1000])
def test_a_needle_is_degenerate_in_every_order(scale):
    # a right angle at A, yet the face is a needle: |N| / L² = 1e-13
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1e-13, 0]]) * scale
    f = np.array([[0, 1, 2]])
    assert verdicts_in_every_order(v, f, DEFAULT_TOL).all()
    for o in ORDERS:
        assert exactly_degenerate(*v[list(o)].tolist())
        assert mesh.face_normals(v, f[:, list(o)]).tolist() == [[0.0, 0.0, 0.0]]
    # with a tolerance below 1e-13 it has a normal again, the same way up in every rotation
    loose = verdicts_in_every_order(v, f, 1e-14)
    assert not loose.any()


@pytest.mark.parametrize("seed", range(5))
def test_c_within_1e_13_of_a_is_degenerate_in_every_order(seed):
    rng = np.random.default_rng(seed)
    a = rng.normal(size=(200, 3))
    b = a + rng.normal(size=(200, 3)) * 3  # edges about 1 to 10 long
    step = rng.normal(size=(200, 3))
    c = a + step / np.linalg.norm(step, axis=1, keepdims=True) * rng.uniform(0, 1e-13, (200, 1))
    v, f = as_mesh(np.stack([a, b, c], axis=1))
    assert verdicts_in_every_order(v, f, DEFAULT_TOL).all()
    assert all(exactly_degenerate(*v[row].tolist()) for row in f[:20])


point = st.tuples(*[st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)] * 3)


@settings(max_examples=200, deadline=None)
@given(point, point, point, st.sampled_from([0, 1e-12, 1e-6, 0.1, 0.8]))
def test_every_order_gets_the_exact_verdict(a, b, c, tol):
    v = np.array([a, b, c])
    got = verdicts_in_every_order(v, np.array([[0, 1, 2]]), tol)[:, 0]
    assert got.tolist() == [exactly_degenerate(a, b, c, tol)] * 6


def test_random_meshes_get_one_verdict_per_face_whatever_the_order():
    rng = np.random.default_rng(7)
    v = rng.normal(size=(500, 3))
    v[::7] = v[::7].round(1)  # many exactly collinear or coincident corners among these
    f = rng.integers(0, 500, size=(3000, 3))
    got = verdicts_in_every_order(v, f, 1e-3)
    assert (got == got[0]).all()
    assert got[0].tolist() == [exactly_degenerate(*v[row].tolist(), 1e-3) for row in f]


# --------------------------------------------------------------------------- near the threshold


@pytest.mark.parametrize("tol", [DEFAULT_TOL, 1e-9, 1e-3])
def test_borderline_faces_get_the_exact_verdict(tol):
    # |N| / L² within about the rounding of a float |N| (EPS · L²) of the threshold
    corners = borderline_faces(400, tol, seed=int(-np.log10(tol)), spread=1.5 * EPS / tol)
    expected = [exactly_degenerate(*c.tolist(), tol) for c in corners]
    naive = [float_verdict(*c, tol) for c in corners]
    assert 0 < sum(expected) < len(expected)  # both verdicts occur
    assert naive != expected  # floats alone get some of these wrong: the test can tell
    v, f = as_mesh(corners)
    got = verdicts_in_every_order(v, f, tol)
    assert (got == np.array(expected)).all()
    # a non-degenerate face keeps a unit normal, a degenerate one gets a zero row
    unit = mesh.face_normals(v, f, tol=tol)
    length = np.linalg.norm(unit, axis=1)
    np.testing.assert_allclose(length[~np.array(expected)], 1.0, rtol=0, atol=4 * EPS)
    assert not unit[np.array(expected)].any()


@pytest.mark.parametrize("k", [-1000, -500, 500, 1000])
def test_borderline_faces_at_extreme_scales_get_the_exact_verdict(k):
    corners = borderline_faces(200, DEFAULT_TOL, seed=k + 2000) * 2.0**k  # exact scaling
    expected = [exactly_degenerate(*c.tolist()) for c in corners]
    v, f = as_mesh(corners)
    assert mesh.degenerate_faces(v, f).tolist() == expected
    # the same faces at ordinary size: the same verdicts (the rule is scale-free)
    assert mesh.degenerate_faces(v * 2.0**-k, f).tolist() == expected


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_borderline_faces_inside_a_big_mesh(dtype):
    # a mesh of several blocks: the borderline faces are judged in the kernel's row-by-row test
    tol = 1e-6  # coarse enough for float32 corners to land near the threshold
    v, f = mesh.terrain(150, 150)
    corners = borderline_faces(300, tol, seed=11, spread=3e-3).astype(dtype)
    v = np.vstack([v.astype(dtype), corners.reshape(-1, 3)])
    extra = len(v) - 900 + np.arange(900).reshape(-1, 3)
    at = np.random.default_rng(0).choice(len(f) + 300, size=300, replace=False)
    g = np.empty((len(f) + 300, 3), dtype=np.intp)
    g[at] = extra
    g[np.setdiff1d(np.arange(len(g)), at)] = f
    expected = np.zeros(len(g), dtype=bool)
    expected[at] = [exactly_degenerate(*v[row].astype(np.float64).tolist(), tol) for row in extra]
    assert 0 < expected.sum() < 300
    assert (mesh.degenerate_faces(v, g, tol=tol) == expected).all()
    unit = mesh.face_normals(v, g, tol=tol)
    assert not unit[expected].any()
    assert (np.abs(np.linalg.norm(unit[~expected].astype(np.float64), axis=1) - 1) < 1e-6).all()


def test_tol_zero_flags_exactly_collinear_faces_only():
    # (0.1, 0.2, 0.3) and (0.3, 0.6, 0.9) are not exactly on one line once rounded to floats
    v = np.array([[0, 0, 0], [0.1, 0.2, 0.3], [0.3, 0.6, 0.9], [1, 2, 3], [3, 6, 9]])
    f = np.array([[0, 1, 2], [0, 3, 4]])
    expected = [exactly_degenerate(*v[row].tolist(), 0) for row in f]
    assert expected == [False, True]
    assert verdicts_in_every_order(v, f, 0).T.tolist() == [[False] * 6, [True] * 6]
    # the first face has a normal, though floats lose most of it: it is computed exactly
    unit = mesh.face_normals(v, f, tol=0)
    n = np.array([float(x) for x in exact_edges(*v[f[0]].tolist())[3]])
    np.testing.assert_allclose(unit[0], n / np.linalg.norm(n), rtol=0, atol=4 * EPS)
    assert unit[1].tolist() == [0.0, 0.0, 0.0]
