"""Tests of trinormal.mesh: agreement with the exact core, degeneracy, scales, dtypes, errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from test_mesh_degenerate import ORDERS, exactly_degenerate

from trinormal import mesh, triangle_normal
from trinormal.tolerances import DEFAULT_TOL

# every test here fails on any warning: the module promises never to emit a RuntimeWarning
pytestmark = pytest.mark.filterwarnings("error")

EPS = np.finfo(np.float64).eps

coord = st.floats(min_value=-1e3, max_value=1e3, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord, coord)


def angle_deg(p: np.ndarray, q: np.ndarray) -> float:
    """Angle between two vectors, from atan2(|p × q|, p · q)."""
    return math.degrees(math.atan2(np.linalg.norm(np.cross(p, q)), float(np.dot(p, q))))


# --------------------------------------------------------------------------- agreement with the core


@settings(max_examples=300, deadline=None)
@given(point, point, point)
def test_face_normals_agree_with_triangle_normal(a, b, c):
    r = triangle_normal(a, b, c)
    assume(r.thickness > 1e-6)  # |N| / L² far above the threshold (DEFAULT_TOL)
    v = np.array([a, b, c])
    f = np.array([[0, 1, 2]])
    unit = mesh.face_normals(v, f)[0]
    # the kernel forms N from the edges at A, so its direction error is about eps / sine at A
    # (at most eps / thickness); allow a generous constant
    np.testing.assert_allclose(unit, r.unit_normal, rtol=0, atol=64 * EPS / r.sine)
    raw = mesh.face_normals(v, f, unit=False)[0]
    scale = r.magnitude / r.sine  # |U| |V|, from the exact values
    tiny = 8 * np.finfo(np.float64).smallest_subnormal  # subnormal products round absolutely
    exact = np.array([float(x) for x in r.exact.normal])
    np.testing.assert_allclose(raw, exact, rtol=0, atol=8 * EPS * scale + tiny)
    area = mesh.face_areas(v, f)[0]
    assert abs(area - r.area) <= 8 * EPS * scale + tiny
    assert not mesh.degenerate_faces(v, f)[0]


@settings(max_examples=200, deadline=None)
@given(point, point, point, st.sampled_from([0, 1e-12, 1e-9, 1e-6, 1e-3, 0.1]))
def test_degenerate_verdict_is_the_exact_rule_and_the_cores_in_every_order(a, b, c, tol):
    corners = np.array([a, b, c])
    want = exactly_degenerate(a, b, c, tol)
    for order in ORDERS:
        turned = corners[list(order)]
        got = mesh.degenerate_faces(turned, [[0, 1, 2]], tol=tol)[0]
        core = triangle_normal(*turned.tolist(), tol=tol)
        assert (bool(got), core.degenerate) == (want, want), order


def test_many_faces_across_blocks_match_the_core_row_by_row():
    rng = np.random.default_rng(1)
    v = rng.normal(size=(3000, 3))
    f = rng.integers(0, 3000, size=(20_000, 3))  # more faces than one block
    got = mesh.face_normals(v, f)
    deg = mesh.degenerate_faces(v, f)
    for i in rng.choice(f.shape[0], size=300, replace=False):
        corners = [v[j].tolist() for j in f[i]]
        assert bool(deg[i]) == exactly_degenerate(*corners)
        r = triangle_normal(*corners)
        assert r.degenerate == bool(deg[i])
        if deg[i]:
            assert not got[i].any()
        else:
            np.testing.assert_allclose(got[i], r.unit_normal, atol=64 * EPS / r.sine, rtol=0)


@pytest.mark.parametrize("where", [0, 9_000, 39_999])
@pytest.mark.parametrize("ratio", [0.5, 1.5, 4.0])
def test_a_thin_face_among_many_gets_the_exact_verdict(where, ratio):
    # A block of ordinary faces is decided all at once (no face's |N| / L² can be near tol);
    # one thin face, with |N| / L² about ratio * tol, must still get the exact verdict.
    tol = 1e-9
    v, f = mesh.terrain(150, 150)  # 44 402 faces: several blocks
    f = f[:40_000]
    v = np.vstack([v, [[0, 0, 0], [1, 0, 0], [1, ratio * tol, 0]]])
    n = v.shape[0]
    f = f.copy()
    f[where] = [n - 3, n - 2, n - 1]
    deg = mesh.degenerate_faces(v, f, tol=tol)
    assert bool(deg[where]) == exactly_degenerate(*v[f[where]].tolist(), tol) == (ratio < 1)
    assert np.flatnonzero(deg).tolist() == ([where] if ratio < 1 else [])
    unit = mesh.face_normals(v, f, tol=tol)
    if ratio < 1:
        assert unit[where].tolist() == [0.0, 0.0, 0.0]
    else:
        np.testing.assert_allclose(unit[where], [0, 0, 1], rtol=0, atol=2 * EPS)


@pytest.mark.parametrize("far", [1e3, 1e9, 1e150])
def test_a_far_vertex_changes_no_row(far):
    # A block is cleared all at once from the mesh's bounding box, or judged row by row; an
    # unused vertex far away widens the box until the first test fails, and the rows must
    # not change by a bit: both paths give the same verdicts and numbers.
    v, f = mesh.terrain(150, 150)
    wide = np.vstack([v, [[far, -far, far]]])
    for unit in (True, False):
        assert (
            mesh.face_normals(wide, f, unit=unit).tobytes()
            == mesh.face_normals(v, f, unit=unit).tobytes()
        )
    assert (mesh.degenerate_faces(wide, f) == mesh.degenerate_faces(v, f)).all()


def test_each_face_gets_the_same_bits_in_any_block_and_alone():
    v, f = mesh.terrain(120, 120)  # 28 322 faces: several blocks
    v = v.copy()
    v[:50] *= 1e-200  # faces for the careful path in the first block
    v[-50:] *= 1e200  # and in the last
    f = f.copy()
    f[::997, 2] = f[::997, 1]  # degenerate faces here and there
    rows = np.r_[0:60, 9_000:9_060, len(f) - 60 : len(f)]
    for fn in (
        mesh.face_normals,
        lambda v, f: mesh.face_normals(v, f, unit=False),
        mesh.degenerate_faces,
        mesh.face_areas,
    ):
        whole = fn(v, f)
        alone = np.array([fn(v, f[i : i + 1])[0] for i in rows])
        assert whole[rows].tobytes() == alone.tobytes()
    assert np.isfinite(mesh.face_normals(v, f)).all()
    bad = f.copy()
    bad[-3, 1] = len(v)
    with pytest.raises(ValueError, match=f"faces row {len(f) - 3} refers to vertex {len(v)}"):
        mesh.face_normals(v, bad)


@pytest.mark.parametrize("rows", [0, 1, 511, 512, 513, 1025, 5000])
def test_the_bounding_box_is_the_smallest_and_largest_coordinates(rows):
    from trinormal.mesh._arrays import _box

    v = np.random.default_rng(rows).normal(size=(rows, 3)) * [1, 10, 100]
    expected = np.array([v.min(axis=0), v.max(axis=0)]) if rows else np.zeros((2, 3))
    assert _box(v).tolist() == expected.tolist()


def test_a_mesh_wider_than_the_float_range_still_gets_its_normals():
    # the box spans 2e308 along x, beyond float64: the box test cannot apply, the rows can
    v = [[-1e308, 0, 0], [1e308, 0, 0], [0, 1e308, 0], [0, 0, 1e308]]
    got = mesh.face_normals(v, [[0, 1, 2], [0, 3, 1]])
    np.testing.assert_allclose(got, [[0, 0, 1], [0, 1, 0]], atol=2 * EPS, rtol=0)


def test_face_order_does_not_change_any_row():
    v, f = mesh.terrain(40, 50)
    perm = np.random.default_rng(2).permutation(f.shape[0])
    np.testing.assert_array_equal(mesh.face_normals(v, f)[perm], mesh.face_normals(v, f[perm]))


def test_guide_table_rows():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0], [0, 3, 0], [1, 1, 1], [2, 1, 1]])
    v = np.vstack([v, [[1, 2, 2], [2, 2, 2]]])
    f = np.array([[0, 1, 2], [0, 3, 4], [5, 6, 7], [0, 5, 8]])
    raw = mesh.face_normals(v, f, unit=False)
    np.testing.assert_array_equal(raw[:3], [[0, 0, 1], [0, 0, 6], [0, -1, 1]])
    np.testing.assert_array_equal(raw[3], [0, 0, 0])  # (0,0,0), (1,1,1), (2,2,2): collinear
    np.testing.assert_allclose(mesh.face_areas(v, f), [0.5, 3, math.sqrt(2) / 2, 0], atol=1e-15)
    h = math.sqrt(0.5)
    np.testing.assert_allclose(mesh.face_normals(v, f)[2], [0, -h, h], rtol=0, atol=EPS)


# --------------------------------------------------------------------------- degenerate rows


def test_degenerate_rows_are_zero_never_nan():
    v = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1e-14, 0]], dtype=float)
    f = np.array([[0, 1, 2], [0, 0, 3], [1, 1, 1], [0, 1, 3], [0, 1, 4]])
    assert mesh.degenerate_faces(v, f).tolist() == [True, True, True, False, True]
    for unit in (True, False):
        n = mesh.face_normals(v, f, unit=unit)
        assert np.isfinite(n).all()
        assert not n[[0, 1, 2, 4]].any()
        assert n[3].tolist() == [0.0, 0.0, 1.0]
    # with tol=0 only exactly collinear faces count: the thin one gets its normal back
    assert mesh.degenerate_faces(v, f, tol=0).tolist() == [True, True, True, False, False]
    assert mesh.face_normals(v, f, tol=0)[4].tolist() == [0.0, 0.0, 1.0]


def test_degenerate_test_is_n_over_the_longest_edge_squared():
    s = 1e-6  # |N| = s, and the longest edge is A to C: L² = 1 + s²
    v = np.array([[0, 0, 0], [1, 0, 0], [1, s, 0]])
    ratio = s / (1 + s * s)
    assert mesh.degenerate_faces(v, [[0, 1, 2]], tol=ratio * 1.001)[0]
    assert not mesh.degenerate_faces(v, [[0, 1, 2]], tol=ratio * 0.999)[0]
    # a right angle at A does not save a needle: |N| / L² = 1e-13 (the sine at A is 1)
    needle = [[0, 0, 0], [1, 0, 0], [0, 1e-13, 0]]
    assert mesh.degenerate_faces(needle, [[0, 1, 2]]).tolist() == [True]
    assert not mesh.degenerate_faces(needle, [[0, 1, 2]], tol=1e-14)[0]


@pytest.mark.parametrize("k", [-1000, -600, -300, -60, 0, 60, 300, 600, 1000])
def test_degeneracy_is_scale_invariant(k):
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 3e-12, 0], [1, 1e-12, 0], [0, 1, 0]]) * 2.0**k
    f = [[0, 1, 2], [0, 1, 3], [0, 1, 4]]
    assert mesh.degenerate_faces(v, f).tolist() == [False, True, False]


def test_vertices_of_only_degenerate_faces_get_zero_vertex_normals():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5], [6, 6, 6], [7, 7, 7], [9, 9, 9]])
    f = np.array([[0, 1, 2], [3, 4, 5], [0, 3, 4]])  # face 2 is not collinear: touches 3 and 4
    f = f[:2]
    for weighting in mesh.WEIGHTINGS:
        vn = mesh.vertex_normals(v, f, weighting)
        assert np.isfinite(vn).all()
        np.testing.assert_array_equal(vn[3:], 0.0)  # collinear face only, and unused vertex 6
        np.testing.assert_array_equal(vn[:3], [[0, 0, 1]] * 3)


# --------------------------------------------------------------------------- extreme scales


@pytest.mark.parametrize("scale", [1e-300, 1e-200, 1e-160, 1e-100, 1.0, 1e100, 1e160, 1e200, 1e300])
def test_extreme_scales_give_correct_unit_normals(scale):
    v, f = mesh.icosphere(1)
    ref = mesh.face_normals(v, f)
    got = mesh.face_normals(v * scale, f)
    np.testing.assert_allclose(got, ref, rtol=0, atol=16 * EPS)
    assert not mesh.degenerate_faces(v * scale, f).any()
    np.testing.assert_allclose(
        mesh.vertex_normals(v * scale, f), mesh.vertex_normals(v, f), atol=1e-14
    )
    areas = mesh.face_areas(v * scale, f)
    assert not np.isnan(areas).any()


def test_far_from_origin_and_mixed_scales_in_one_mesh():
    v = np.array(
        [[0, 0, 0], [1e-200, 0, 0], [0, 1e-200, 0], [1e200, 0, 0], [0, 0, 1e200], [1e300, 1e300, 0]]
    )
    v = np.vstack([v, [[1.7e308, -1.7e308, 0], [-1.7e308, -1.7e308, 0], [0, 1.7e308, 0]]])
    f = np.array([[0, 1, 2], [0, 3, 4], [0, 5, 2], [6, 7, 8]])
    # face 2 has edges of length 1e300 and 1e-200 at 45 degrees: a needle (|N| / L² = 1e-500),
    # degenerate by default, with its normal back when tol = 0; face 3 overflows B - A
    n = mesh.face_normals(v, f)
    np.testing.assert_allclose(n, [[0, 0, 1], [0, -1, 0], [0, 0, 0], [0, 0, -1]], rtol=0, atol=EPS)
    assert mesh.degenerate_faces(v, f).tolist() == [False, False, True, False]
    n0 = mesh.face_normals(v, f, tol=0)
    np.testing.assert_allclose(n0, [[0, 0, 1], [0, -1, 0], [0, 0, 1], [0, 0, -1]], rtol=0, atol=EPS)
    assert not mesh.degenerate_faces(v, f, tol=0).any()
    raw = mesh.face_normals(v, f, unit=False)
    assert not np.isnan(raw).any()
    assert raw[1, 1] == -np.inf  # |N| = 1e400 is beyond the float range: an honest -inf
    assert raw[0, 2] == 0.0  # 1e-400 underflows to zero


def test_huge_coordinates_whose_differences_overflow():
    v = np.array([[-1.5e308, 0, 0], [1.5e308, 0, 0], [0, 1.5e308, 0]])
    n = mesh.face_normals(v, [[0, 1, 2]])
    np.testing.assert_allclose(n, [[0, 0, 1]], atol=EPS)


# --------------------------------------------------------------------------- float32


def test_float32_in_float32_out_computed_in_float64():
    v, f = mesh.torus()
    v32 = (v * 3.7).astype(np.float32)
    got = mesh.face_normals(v32, f)
    assert got.dtype == np.float32
    ref = mesh.face_normals(v32.astype(np.float64), f)  # the same values, read as float64
    np.testing.assert_array_equal(got, ref.astype(np.float32))
    assert mesh.vertex_normals(v32, f).dtype == np.float32
    assert mesh.face_areas(v32, f).dtype == np.float32
    assert mesh.face_normals(v32, f, unit=False).dtype == np.float32
    assert mesh.face_normals(v, f).dtype == np.float64


def test_float32_is_better_than_float32_arithmetic():
    # a thin triangle far from the origin: float32 step by step loses the direction
    a, b, c = (1000.0, 1000.0, 0.0), (1000.0625, 1000.0, 0.0), (1000.0, 1000.0, 0.0009765625)
    v32 = np.array([a, b, c], dtype=np.float32)
    exact = triangle_normal(a, b, c).unit_normal
    ours = mesh.face_normals(v32, [[0, 1, 2]])[0].astype(np.float64)
    assert np.abs(ours - exact).max() <= np.finfo(np.float32).eps


# --------------------------------------------------------------------------- vertex normals


def test_cube_corner_angle_weighting_is_exact_and_area_is_not():
    v, f = mesh.cube()
    angle = mesh.vertex_normals(v, f, "angle")
    np.testing.assert_allclose(angle, v / math.sqrt(3), rtol=0, atol=2 * EPS)
    for weighting in ("area", "uniform"):
        vn = mesh.vertex_normals(v, f, weighting)
        off = [angle_deg(vn[i], angle[i]) for i in range(8)]
        # vertex 7 has two triangles of the top face and one of each side: (1, 1, 2)/√6
        assert off[7] == pytest.approx(math.degrees(math.acos(2 * math.sqrt(2) / 3)), abs=1e-9)
        assert round(off[7], 2) == 19.47
        assert max(off) == pytest.approx(off[7])


def reference_vertex_normals(v, f, weighting):
    """Slow, independent reference: np.add.at over the corners, angles from arccos."""
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    n = np.cross(b - a, c - a)
    area2 = np.linalg.norm(n, axis=1)
    unit = n / area2[:, None]

    def angle(p, q, r):
        e1, e2 = q - p, r - p
        cos = (
            np.einsum("ij,ij->i", e1, e2) / np.linalg.norm(e1, axis=1) / np.linalg.norm(e2, axis=1)
        )
        return np.arccos(np.clip(cos, -1, 1))

    if weighting == "angle":
        w = np.stack([angle(a, b, c), angle(b, c, a), angle(c, a, b)], axis=1)
    elif weighting == "area":
        w = np.repeat(area2[:, None], 3, axis=1)
    else:
        w = np.ones((f.shape[0], 3))
    acc = np.zeros_like(v)
    for k in range(3):
        np.add.at(acc, f[:, k], unit * w[:, k, None])
    return acc / np.linalg.norm(acc, axis=1, keepdims=True)


@pytest.mark.parametrize("weighting", mesh.WEIGHTINGS)
@pytest.mark.parametrize("make", [mesh.icosphere, mesh.torus, mesh.terrain])
def test_vertex_normals_match_a_reference(make, weighting):
    v, f = make()
    v = v + np.random.default_rng(3).normal(scale=0.01, size=v.shape)  # break the symmetry
    got = mesh.vertex_normals(v, f, weighting)
    np.testing.assert_allclose(got, reference_vertex_normals(v, f, weighting), atol=1e-12)


def test_icosphere_vertex_normals_point_outward():
    v, f = mesh.icosphere(3)
    for weighting in mesh.WEIGHTINGS:
        vn = mesh.vertex_normals(v, f, weighting)
        assert np.einsum("ij,ij->i", vn, v).min() > 0.9999


# --------------------------------------------------------------------------- winding and built-ins


def test_consistent_winding_on_a_cube_with_one_flipped_face():
    _, f = mesh.cube()
    assert mesh.consistent_winding(f)
    for i in range(f.shape[0]):
        g = f.copy()
        g[i] = g[i, ::-1]
        assert not mesh.consistent_winding(g)
        bad = {tuple(e) for e in mesh.inconsistent_edges(g).tolist()}
        # every edge of the flipped face now runs the same way as in its neighbour
        assert bad == {(g[i, k], g[i, (k + 1) % 3]) for k in range(3)}


def test_shared_edge_walked_twice_the_same_way():
    assert mesh.consistent_winding([[0, 1, 2], [2, 1, 3]])
    assert not mesh.consistent_winding([[0, 1, 2], [1, 2, 3]])
    assert mesh.consistent_winding(np.empty((0, 3), dtype=int))


@pytest.mark.parametrize(
    "made",
    [mesh.cube(), mesh.icosphere(0), mesh.icosphere(2), mesh.torus(), mesh.terrain(5, 7)],
    ids=["cube", "icosahedron", "icosphere", "torus", "terrain"],
)
def test_built_in_meshes_are_consistent_and_outward(made):
    v, f = made
    assert mesh.consistent_winding(f)
    assert not mesh.degenerate_faces(v, f).any()
    n = mesh.face_normals(v, f, unit=False)
    centroids = v[f].mean(axis=1)
    if made is not None and f.shape[0] > 0 and np.ptp(v[:, 2]) < 1 and v.shape[0] == 35:
        assert (n[:, 2] > 0).all()  # the terrain faces up
    else:
        # closed surfaces: the divergence theorem gives the volume, positive when outward
        assert np.einsum("ij,ij->", centroids, n) / 6 > 0


def test_built_in_mesh_sizes():
    assert [a.shape for a in mesh.icosphere(2)] == [(162, 3), (320, 3)]
    assert [a.shape for a in mesh.torus(1, 0.3, 10, 6)] == [(60, 3), (120, 3)]
    assert [a.shape for a in mesh.terrain(4, 6)] == [(24, 3), (30, 3)]
    v, f = mesh.cube(size=4.0)
    assert np.abs(v).max() == 2.0
    assert float(mesh.face_areas(v, f).sum()) == 96.0


def test_default_tolerance_is_the_shared_one():
    import inspect

    for fn in (mesh.face_normals, mesh.degenerate_faces, mesh.vertex_normals):
        assert inspect.signature(fn).parameters["tol"].default is DEFAULT_TOL


# --------------------------------------------------------------------------- bad input

GOOD_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
GOOD_F = np.array([[0, 1, 2], [0, 2, 3]])


@pytest.mark.parametrize(
    ("vertices", "faces", "message"),
    [
        (GOOD_V[:, :2], GOOD_F, r"vertices must have shape \(V, 3\), got shape \(4, 2\)"),
        (GOOD_V.ravel(), GOOD_F, r"vertices must have shape \(V, 3\)"),
        (GOOD_V, GOOD_F[:, :2], r"faces must have shape \(F, 3\), got shape \(2, 2\)"),
        (GOOD_V, GOOD_F.astype(float), r"faces must hold integer vertex indices"),
        (GOOD_V, [[0, 1, 2], [0, 2, 4]], r"faces row 1 refers to vertex 4.*0 to 3"),
        (GOOD_V, [[0, 1, 2], [0, 1, 2], [-1, 2, 3]], r"faces row 2 refers to vertex -1"),
        (np.where(np.arange(12).reshape(4, 3) == 7, np.nan, GOOD_V), GOOD_F, r"row 2: y is NaN"),
        (
            np.where(np.arange(12).reshape(4, 3) == 3, np.inf, GOOD_V),
            GOOD_F,
            r"row 1: x is infinite",
        ),
        ([["a", "b", "c"]], [[0, 0, 0]], r"vertices must be real numbers"),
    ],
)
@pytest.mark.parametrize("fn", ["face_normals", "degenerate_faces", "face_areas", "vertex_normals"])
def test_bad_input_raises_a_clear_value_error(fn, vertices, faces, message):
    with pytest.raises(ValueError, match=message):
        getattr(mesh, fn)(vertices, faces)


def test_bad_options():
    with pytest.raises(ValueError, match="weighting must be one of angle, area, uniform"):
        mesh.vertex_normals(GOOD_V, GOOD_F, "mean")
    with pytest.raises(ValueError, match="tol must be"):
        mesh.face_normals(GOOD_V, GOOD_F, tol=-1)
    with pytest.raises(ValueError, match="tol must be"):
        mesh.degenerate_faces(GOOD_V, GOOD_F, tol=float("nan"))
    with pytest.raises(ValueError, match="faces row 0 refers to vertex -2"):
        mesh.consistent_winding([[0, 1, -2]])


def test_empty_mesh():
    assert mesh.face_normals(GOOD_V, np.empty((0, 3), dtype=int)).shape == (0, 3)
    assert mesh.vertex_normals(GOOD_V, np.empty((0, 3), dtype=int)).tolist() == [[0, 0, 0]] * 4


# --------------------------------------------------------------------------- hard inputs


def test_float32_near_its_limit_gives_inf_not_a_warning():
    v = np.array([[0, 0, 0], [1e30, 0, 0], [0, 1e30, 0], [3e38, 3e38, 0]], dtype=np.float32)
    f = [[0, 1, 2], [0, 3, 2]]
    raw = mesh.face_normals(v, f, unit=False)  # |N| = 1e60 is beyond float32: inf, quietly
    assert raw.dtype == np.float32 and raw[0, 2] == np.inf
    assert mesh.face_areas(v, f)[0] == np.inf
    np.testing.assert_array_equal(mesh.face_normals(v, f)[0], [0, 0, 1])
    for weighting in mesh.WEIGHTINGS:
        assert np.isfinite(mesh.vertex_normals(v, f, weighting)).all()


def test_area_weights_are_scaled_per_vertex_so_tiny_faces_keep_their_direction():
    s = 1e-165  # |N| about 1e-330: below the float range, but the face is valid
    v = np.array(
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5], [0, 0, 0], [s, 0, 0], [0, 0, s]], dtype=float
    )
    f = np.array([[0, 1, 2], [0, 1, 3], [4, 5, 6]])
    got = mesh.vertex_normals(v, f, "area")
    np.testing.assert_allclose(got[4:], [[0, -1, 0]] * 3, atol=EPS)  # the tiny face alone
    # the same tiny face scaled up to ordinary size gives the same vertex normals
    big = v.copy()
    big[4:] /= s
    np.testing.assert_allclose(got[4:], mesh.vertex_normals(big, f, "area")[4:], atol=EPS)
    np.testing.assert_allclose(got[:4], mesh.vertex_normals(big, f, "area")[:4], atol=1e-15)


def test_vertex_shared_by_a_tiny_and_an_ordinary_face_weighs_them_by_area():
    s = 1e-170
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, s], [s, 0, 0]], dtype=float)
    n = mesh.vertex_normals(v, [[0, 1, 2], [0, 3, 4]], "area")
    np.testing.assert_allclose(n[0], [0, 0, 1], atol=EPS)  # the tiny face counts for nothing
    np.testing.assert_allclose(n[3], [0, 1, 0], atol=EPS)  # ... except at its own corners


@pytest.mark.parametrize("top", [2**31 + 5, 2**40, 2**62, 2**63 - 1])
def test_inconsistent_edges_with_huge_indices(top):
    f = np.array([[0, top, top - 1], [top - 1, top, 7], [top, 0, 3]], dtype=np.int64)
    # faces 0 and 1 walk the edge between top - 1 and top in opposite directions, and so do
    # faces 0 and 2 with the edge between 0 and top: consistent (packing the pairs into one
    # int64 key would wrap around here)
    assert mesh.inconsistent_edges(f).tolist() == []
    g = np.vstack([f, [[0, top, 5]]])  # walks 0 -> top again, as face 0 does
    assert mesh.inconsistent_edges(g).tolist() == [[0, top]]
    assert not mesh.consistent_winding(g)


def test_indices_beyond_intp_are_refused():
    f = np.array([[0, 1, 2**64 - 1]], dtype=np.uint64)
    with pytest.raises(ValueError, match="faces row 0 refers to vertex 18446744073709551615"):
        mesh.inconsistent_edges(f)


def test_object_vertices_beyond_float64_are_a_value_error():
    v = np.array([[0, 0, 0], [10**400, 0, 0], [0, 1, 0]], dtype=object)
    with pytest.raises(ValueError, match="within the float64 range"):
        mesh.face_normals(v, [[0, 1, 2]])


def test_tolerance_is_checked_as_the_core_checks_it():
    for bad in (-1, 2, float("nan"), "abc"):
        with pytest.raises(ValueError) as info:
            mesh.face_normals(GOOD_V, GOOD_F, tol=bad)
        with pytest.raises(ValueError) as core:
            triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), tol=bad)
        assert str(info.value) == str(core.value)
