"""Properties of the cross product that must hold exactly, for random exact inputs."""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from trinormal import triangle_normal


def fractions(bound: int, max_denominator: int) -> st.SearchStrategy[Fraction]:
    """Every fraction from -bound to bound whose denominator is at most ``max_denominator``.

    The same fractions ``st.fractions(-bound, bound, max_denominator=...)`` draws, drawn as
    a denominator, then a numerator that keeps the fraction in range (in fewer steps).
    """
    return st.integers(1, max_denominator).flatmap(
        lambda d: st.integers(-bound * d, bound * d).map(lambda n: Fraction(n, d))
    )


coord = fractions(1000, 1000)
point = st.tuples(coord, coord, coord)
scale = fractions(50, 50)


def dot(p, q):
    return sum((x * y for x, y in zip(p, q, strict=True)), Fraction(0))


@given(point, point, point)
def test_normal_is_orthogonal_to_both_edges(a, b, c):
    e = triangle_normal(a, b, c).exact
    assert dot(e.normal, e.u) == 0
    assert dot(e.normal, e.v) == 0


@given(point, point, point)
def test_lagrange_identity(a, b, c):
    e = triangle_normal(a, b, c).exact
    assert e.magnitude_squared == dot(e.u, e.u) * dot(e.v, e.v) - dot(e.u, e.v) ** 2


@given(point, point, point)
def test_acb_flips_n(a, b, c):
    r = triangle_normal(a, b, c)
    f = triangle_normal(a, b, c, winding="ACB")
    assert f.exact.normal == tuple(-x for x in r.exact.normal)
    assert f.normal == tuple(-x for x in r.normal)
    assert f.degenerate == r.degenerate


@given(point, point, point, point)
def test_translation_invariance(a, b, c, t):
    def shift(p):
        return tuple(x + y for x, y in zip(p, t, strict=True))

    r = triangle_normal(a, b, c)
    s = triangle_normal(shift(a), shift(b), shift(c))
    assert s.exact.normal == r.exact.normal
    assert s.degenerate == r.degenerate


@given(point, point, point, scale)
def test_scaling_scales_n_by_s_squared(a, b, c, s):
    def mul(p):
        return tuple(s * x for x in p)

    r = triangle_normal(a, b, c)
    m = triangle_normal(mul(a), mul(b), mul(c))
    assert m.exact.normal == tuple(s * s * x for x in r.exact.normal)
    if s != 0:
        assert m.degenerate == r.degenerate  # |N| <= tol · L² does not depend on scale


@settings(max_examples=300)
@given(point, point, point)
def test_unit_normal_has_length_one(a, b, c):
    r = triangle_normal(a, b, c)
    if r.degenerate:
        assert r.unit_normal is None and r.plane is None
        return
    assert r.unit_normal is not None
    length = math.fsum(x * x for x in r.unit_normal)
    # each component within 2 ulp of exact: |n|² = 1 within a few units of 2**-52
    assert abs(length - 1.0) <= 8 * 2.0**-52


@given(point, point, point)
def test_strings_read_like_fractions(a, b, c):
    as_text = [tuple(f"{x.numerator}/{x.denominator}" for x in p) for p in (a, b, c)]
    assert triangle_normal(*as_text).exact == triangle_normal(a, b, c).exact


# --------------------------------------------------------------------------- order of the corners


def _orders(a, b, c):
    """The six ways to list one triangle: three rotations, each in both windings."""
    for p, q, r in ((a, b, c), (b, c, a), (c, a, b)):
        for winding in ("ABC", "ACB"):
            yield p, q, r, winding


def _thin_near(a, b, t, k):
    """A third corner at height about t·|B − A| off the line AB, a fraction k along it."""
    d = tuple(y - x for x, y in zip(a, b, strict=True))
    # a direction across AB (any vector not parallel to it, made orthogonal exactly)
    w = (-d[1], d[0], 0) if d[0] or d[1] else (0, -d[2], d[1])
    return tuple(x + k * e + t * f for x, e, f in zip(a, d, w, strict=True))


tols = st.sampled_from([Fraction(0), Fraction(1, 10**12), Fraction(1, 1000), Fraction(1, 3)])


@given(point, point, point, tols)
def test_every_order_of_the_corners_gives_one_verdict(a, b, c, tol):
    verdicts = {
        triangle_normal(p, q, r, winding=w, tol=tol).degenerate for p, q, r, w in _orders(a, b, c)
    }
    assert len(verdicts) == 1


@given(
    point,
    point,
    st.fractions(min_value=Fraction(1, 10**14), max_value=Fraction(1, 10**10)),
    st.fractions(min_value=-2, max_value=3, max_denominator=1000),
)
@settings(max_examples=200)
def test_borderline_triangles_get_one_verdict_in_every_order(a, b, t, k):
    """Thin triangles whose |N| / L² is within a few powers of ten of the default tol."""
    c = _thin_near(a, b, t, k)
    results = [triangle_normal(p, q, r, winding=w) for p, q, r, w in _orders(a, b, c)]
    assert len({r.degenerate for r in results}) == 1
    assert len({r.thickness for r in results}) == 1
    # plain floats are read on the quick path: the same verdict
    floats = [tuple(float(x) for x in p) for p in (a, b, c)]
    quick = {triangle_normal(p, q, r, winding=w).degenerate for p, q, r, w in _orders(*floats)}
    assert len(quick) == 1


@given(
    st.integers(min_value=0, max_value=2**300),
    st.integers(min_value=0, max_value=2**200),
    st.fractions(min_value=0, max_value=1, max_denominator=2**100),
)
def test_the_degenerate_test_s_shortcut_never_changes_the_answer(norm_squared, longest, tol):
    """_thin may decide from bit lengths alone; it must agree with the products every time."""
    from trinormal.core import _thin

    tn, td = tol.numerator, tol.denominator
    want = norm_squared * td * td <= tn * tn * longest * longest
    assert _thin(norm_squared, longest, tn, td) is want
    assert _thin(0, longest, tn, td) is True
