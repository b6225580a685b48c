"""Tests of trinormal.mesh.check, fix_winding and the topology functions.

Every count is compared with a second computation written here in plain
Python (dictionaries, a union-find, a breadth-first walk), on small meshes
with known faults and on random ones.
"""

from __future__ import annotations

import itertools
import json
from collections import Counter, defaultdict
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trinormal import mesh

DATA = Path(__file__).parent / "data" / "meshes"

pytestmark = pytest.mark.filterwarnings("error")


# --------------------------------------------------------------------------- a reference in plain Python


def clean(face):
    return len(set(face)) == 3


def half_edges(faces):
    """{unordered edge: [(face, (from, to)), ...]} over faces with three distinct vertices."""
    out = defaultdict(list)
    for i, f in enumerate(faces):
        if not clean(f):
            continue
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            out[frozenset((a, b))].append((i, (a, b)))
    return out


class UnionFind:
    def __init__(self):
        self.parent = {}

    def find(self, x):
        self.parent.setdefault(x, x)
        while self.parent[x] != x:
            self.parent[x] = self.parent[self.parent[x]]
            x = self.parent[x]
        return x

    def union(self, a, b):
        ra, rb = self.find(a), self.find(b)
        if ra != rb:
            self.parent[max(ra, rb)] = min(ra, rb)


def at_one_position(vertices, faces):
    """The faces with every vertex replaced by the first vertex at exactly its position."""
    first = {}
    rep = [first.setdefault(tuple(float(x) + 0.0 for x in p), i) for i, p in enumerate(vertices)]
    return [tuple(rep[int(i)] for i in f) for f in faces]


def reference(vertices, faces):
    """Every count of the report, computed the slow, obvious way, corners joined by position."""
    file_faces = [tuple(int(i) for i in f) for f in faces]
    faces = at_one_position(vertices, faces)
    he = half_edges(faces)
    boundary = sorted(walks[0][1] for walks in he.values() if len(walks) == 1)
    non_manifold = sorted(tuple(sorted(e)) for e, walks in he.items() if len(walks) >= 3)
    inconsistent = sorted(
        tuple(sorted(e))
        for e, walks in he.items()
        if len(walks) == 2 and walks[0][1] == walks[1][1]
    )
    # pieces: faces joined through shared edges
    uf = UnionFind()
    for i, f in enumerate(faces):
        if clean(f):
            uf.find(i)
    for walks in he.values():
        for (i, _), (j, _) in itertools.pairwise(walks):
            uf.union(i, j)
    roots = {}
    component = []
    for i, f in enumerate(faces):
        if not clean(f):
            component.append(-1)
            continue
        r = uf.find(i)
        roots.setdefault(r, len(roots))
        component.append(roots[r])
    # fans around each vertex: corners joined through shared edges at that vertex
    fans = UnionFind()
    for walks in he.values():
        for (i, (a, b)), (j, _) in itertools.pairwise(walks):
            for vtx in (a, b):
                fans.union((i, vtx), (j, vtx))
    fan_roots = defaultdict(set)
    for i, f in enumerate(faces):
        if clean(f):
            for vtx in f:
                fan_roots[vtx].add(fans.find((i, vtx)))
    non_manifold_vertices = sorted(v for v, r in fan_roots.items() if len(r) > 1)
    # duplicates: the same three vertices as an earlier face
    seen = {}
    same, rev = [], []
    for i, f in enumerate(faces):
        if not clean(f):
            continue
        key = frozenset(f)
        rotations = {f, f[1:] + f[:1], f[2:] + f[:2]}
        earlier = seen.setdefault(key, [])
        if any(g in rotations for g in earlier):
            same.append(i)
        elif earlier:
            rev.append(i)
        earlier.append(f)
    used = {i for f in file_faces for i in f}
    unused = [i for i in range(len(vertices)) if i not in used]
    v = [tuple(map(float, p)) for p in vertices]
    coincident = [i for i, f in enumerate(file_faces) if len({v[f[0]], v[f[1]], v[f[2]]}) < 3]
    return {
        "boundary_edges": boundary,
        "non_manifold_edges": non_manifold,
        "inconsistent_edges": inconsistent,
        "face_component": component,
        "non_manifold_vertices": non_manifold_vertices,
        "duplicate_faces": same,
        "reversed_duplicate_faces": rev,
        "unused_vertices": unused,
        "coincident_faces": coincident,
    }


def orient_bfs(faces, component):
    """Wind each piece like its first face by a breadth-first walk; None if it cannot be."""
    faces = [tuple(int(i) for i in f) for f in faces]
    he = half_edges(faces)
    neighbours = defaultdict(list)
    for walks in he.values():
        if len(walks) == 2:
            (i, di), (j, dj) = walks
            neighbours[i].append((j, di == dj))
            neighbours[j].append((i, di == dj))
    flip = {}
    for start in range(len(faces)):
        if component[start] < 0 or start in flip:
            continue
        flip[start] = False
        queue = [start]
        while queue:
            i = queue.pop()
            for j, same_way in neighbours[i]:
                want = flip[i] ^ same_way
                if j not in flip:
                    flip[j] = want
                    queue.append(j)
                elif flip[j] != want:
                    return None  # not orientable
    return flip


def assert_matches_reference(v, f):
    r = mesh.check(v, f, weld=0)
    ref = reference(v, f)
    assert r.boundary_edges.tolist() == [list(e) for e in ref["boundary_edges"]]
    assert r.non_manifold_edges.tolist() == [list(e) for e in ref["non_manifold_edges"]]
    assert r.inconsistent_edges.tolist() == [list(e) for e in ref["inconsistent_edges"]]
    assert r.face_component.tolist() == ref["face_component"]
    assert r.non_manifold_vertices.tolist() == ref["non_manifold_vertices"]
    assert r.duplicate_faces.tolist() == ref["duplicate_faces"]
    assert r.reversed_duplicate_faces.tolist() == ref["reversed_duplicate_faces"]
    assert r.unused_vertices.tolist() == ref["unused_vertices"]
    assert r.coincident_faces.tolist() == ref["coincident_faces"]
    assert len(r.components) == max(ref["face_component"], default=-1) + 1
    assert (r.n_vertices, r.n_faces) == (len(v), len(f))
    return r


# --------------------------------------------------------------------------- the faults file


def test_every_fault_is_found_once_in_the_faults_file():
    m = mesh.read_mesh(DATA / "faults.obj")
    r = assert_matches_reference(m.vertices, m.faces)
    # the file's comments say what is in it; the report must say the same
    assert r.collinear_faces.tolist() == [8]
    assert r.coincident_faces.tolist() == [9, 10]
    assert r.degenerate_faces.tolist() == [8, 9, 10]
    assert r.duplicate_faces.tolist() == [6]
    assert r.reversed_duplicate_faces.tolist() == [7]
    assert r.unused_vertices.tolist() == [17]
    assert r.non_manifold_edges.tolist() == [[0, 2], [10, 11], [10, 12], [11, 12]]
    assert r.non_manifold_vertices.tolist() == [5]
    assert len(r.boundary_edges) == 15  # face 10 (14 17 15) has no edges: 17 is at 14
    assert len(r.components) == 5
    assert r.face_component[10] == -1
    text = r.summary()
    for words in (
        "3 degenerate faces",
        "1 face repeats another face exactly",
        "wound the other way",
        "1 vertex is not used",
        "15 edges belong",
        "4 edges are shared by three faces",
        "1 vertex is a pinch point",
    ):
        assert words in " ".join(text.split()), words


def test_the_collinear_verdict_is_the_cores_and_scale_free():
    v = np.array([[0, 0, 0], [1, 0, 0], [2, 1e-13, 0], [0, 1, 0]], dtype=float)
    f = [[0, 1, 2], [0, 1, 3]]
    for scale in (1e-150, 1.0, 1e150):
        r = mesh.check(v * scale, f)
        assert r.collinear_faces.tolist() == [0]
        assert r.coincident_faces.tolist() == []
    from trinormal import triangle_normal

    assert triangle_normal(*v[[0, 1, 2]].tolist()).degenerate
    assert not triangle_normal(*v[[0, 1, 3]].tolist()).degenerate


# --------------------------------------------------------------------------- random meshes vs the reference


@st.composite
def messy_meshes(draw):
    """Small meshes with every kind of fault: flipped, duplicated, missing, glued faces."""
    nv = draw(st.integers(3, 9))
    faces = draw(st.lists(st.tuples(*[st.integers(0, nv - 1)] * 3), min_size=0, max_size=14))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    v = rng.normal(size=(nv, 3))
    return v, np.array(faces, dtype=np.intp).reshape(-1, 3)


@settings(max_examples=300, deadline=None)
@given(messy_meshes())
def test_report_matches_the_reference_on_random_meshes(vf):
    v, f = vf
    assert_matches_reference(v, f)


def broken_sphere(seed: int, holes: int = 0):
    v, f = mesh.icosphere(2)
    rng = np.random.default_rng(seed)
    f = f.copy()
    flip = rng.random(len(f)) < 0.3
    f[flip] = f[flip][:, [0, 2, 1]]
    if holes:
        f = np.delete(f, rng.choice(len(f), holes, replace=False), axis=0)
    return v, f[rng.permutation(len(f))]


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("holes", [0, 3])
def test_report_matches_the_reference_on_damaged_spheres(seed, holes):
    v, f = broken_sphere(seed, holes)
    r = assert_matches_reference(v, f)
    assert not r.consistent_winding
    assert r.closed == (holes == 0)


# --------------------------------------------------------------------------- fix_winding


def closed_models():
    yield "cube", mesh.cube()
    yield "icosphere", mesh.icosphere(2)
    yield "torus", mesh.torus(n_major=12, n_minor=6)
    yield "uv_sphere", mesh.uv_sphere(10, 6)
    v, f = mesh.cube()
    yield "two cubes", (np.vstack([v, v + np.array([5.0, 0, 0])]), np.vstack([f, f + 8]))


@pytest.mark.parametrize("name,vf", list(closed_models()))
@pytest.mark.parametrize("seed", range(4))
def test_fix_winding_makes_closed_models_consistent_and_outward(name, vf, seed):
    v, f = vf
    rng = np.random.default_rng(seed)
    bad = f.copy()
    flip = rng.random(len(f)) < 0.4
    bad[flip] = bad[flip][:, [0, 2, 1]]
    fixed, flipped = mesh.fix_winding(v, bad)
    assert mesh.consistent_winding(fixed)
    r = mesh.check(v, fixed)
    assert r.consistent_winding and r.closed and r.outward
    for c in r.components:
        assert c.volume is not None and c.volume > 0
    # only the reported faces changed, each turned over with its first corner kept
    changed = np.flatnonzero((fixed != bad).any(axis=1))
    assert set(changed) <= set(flipped.tolist())
    assert (fixed[flipped] == bad[flipped][:, [0, 2, 1]]).all()
    assert mesh.check(v, bad).faces_to_flip.tolist() == flipped.tolist()
    # the same faces as winding each piece like the original, outward model
    assert (np.sort(fixed, axis=1) == np.sort(bad, axis=1)).all()
    assert (fixed == f).all()
    # idempotent
    again, none = mesh.fix_winding(v, fixed)
    assert (again == fixed).all() and none.size == 0


@pytest.mark.parametrize("name,vf", list(closed_models()))
def test_fix_winding_never_changes_a_good_mesh(name, vf):
    v, f = vf
    out, flipped = mesh.fix_winding(v, f)
    assert flipped.size == 0 and (out == f).all()
    assert mesh.check(v, f).ok


@settings(max_examples=200, deadline=None)
@given(messy_meshes())
def test_fix_winding_agrees_with_a_breadth_first_walk(vf):
    v, f = vf
    fixed, flipped = mesh.fix_winding(v, f)
    r = mesh.check(v, f)
    ref = reference(v, f)
    walk = orient_bfs(fixed, ref["face_component"])
    pieces = defaultdict(list)
    for i, c in enumerate(ref["face_component"]):
        if c >= 0:
            pieces[c].append(i)
    for c, members in pieces.items():
        if not r.components[c].orientable:
            assert not set(flipped.tolist()) & set(members)
            continue
        # after the fix, a walk from any face turns nothing over within an orientable piece
        assert walk is None or not any(walk[i] for i in members) or all(walk[i] for i in members)
    fixed_report = mesh.check(v, fixed)
    assert all(c.consistent for c in fixed_report.components if c.orientable)
    again, none = mesh.fix_winding(v, fixed)
    assert none.size == 0 and (again == fixed).all()


def test_fix_winding_flips_the_fewest_faces_on_an_open_sheet():
    v, f = mesh.terrain(6, 6)
    bad = f.copy()
    bad[:5] = bad[:5, [0, 2, 1]]
    fixed, flipped = mesh.fix_winding(v, bad)
    assert flipped.tolist() == [0, 1, 2, 3, 4]
    assert (fixed == f).all()


def test_turn_over_turns_exactly_the_faces_listed_keeping_the_first_corner():
    v, f = mesh.torus(n_major=8, n_minor=5)
    which = np.array([7, 0, 31, 7], dtype=np.uint16)  # any order, any integer type, 7 twice
    out = mesh.turn_over(f.astype(np.int32), which)
    assert out.dtype == np.intp and out is not f
    listed = np.zeros(len(f), dtype=bool)
    listed[[0, 7, 31]] = True
    assert (out[listed] == f[listed][:, [0, 2, 1]]).all()
    assert (out[~listed] == f[~listed]).all()
    assert (mesh.face_normals(v, out)[listed] == -mesh.face_normals(v, f)[listed]).all()
    # the report's faces to flip, turned over, are fix_winding's answer
    bad = mesh.turn_over(f, [3, 4, 5])
    fixed, flipped = mesh.fix_winding(v, bad)
    assert flipped.tolist() == [3, 4, 5] and (fixed == f).all()
    assert (mesh.turn_over(bad, mesh.check(v, bad).faces_to_flip) == fixed).all()
    assert (mesh.turn_over(f, []) == f).all() and (mesh.turn_over(f[:0], []) == f[:0]).all()


@pytest.mark.parametrize(
    "faces,which,message",
    [
        ([[0, 1, 2]], [1], r"which\[0\] is face 1, but the valid face indices are 0 to 0$"),
        ([[0, 1, 2], [0, 2, 3]], [0, -1], r"which\[1\] is face -1"),
        (np.zeros((0, 3), dtype=int), [0], r"which\[0\] is face 0, but there are no faces"),
        ([[0, 1, 2]], [True], r"got dtype bool; for a mask of the faces, pass numpy.flatnonzero"),
        ([[0, 1, 2]], [0.0], r"which must hold face indices \(integers\), got dtype float64$"),
        ([[0, 1, 2]], [[0]], r"shape \(k,\), got shape \(1, 1\)"),
        ([[0, 1]], [0], r"faces must have shape \(F, 3\)"),
    ],
)
def test_turn_over_names_what_is_not_a_face(faces, which, message):
    with pytest.raises(ValueError, match=message):
        mesh.turn_over(faces, which)


def test_a_mobius_strip_is_reported_and_left_alone():
    n = 12
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    v = []
    for s in (-0.3, 0.3):
        v.append(
            np.stack(
                [
                    (1 + s * np.cos(t / 2)) * np.cos(t),
                    (1 + s * np.cos(t / 2)) * np.sin(t),
                    s * np.sin(t / 2),
                ],
                axis=1,
            )
        )
    v = np.vstack(v)
    f = []
    for i in range(n):
        j = (i + 1) % n
        a, b = i, n + i
        c, d = (j, n + j) if j else (n + j, j)  # the half twist joins the strip's two edges
        f += [(a, c, d), (a, d, b)]
    f = np.array(f)
    r = mesh.check(v, f)
    assert len(r.components) == 1 and not r.components[0].orientable
    assert "Möbius" in r.summary()
    out, flipped = mesh.fix_winding(v, f)
    assert flipped.size == 0 and (out == f).all()


# --------------------------------------------------------------------------- vertex normals that cancel


def test_a_face_and_its_reversed_copy_give_zero_vertex_normals():
    v = np.array(
        [[0.1, 0.2, 0.3], [1.7, 0.1, 0.2], [0.3, 1.9, 0.7], [5, 5, 5], [6, 5, 5], [5, 6, 5]]
    )
    for reversed_copy in ([0, 2, 1], [2, 1, 0], [1, 0, 2]):  # every way of writing it reversed
        f = np.array([[0, 1, 2], reversed_copy, [3, 4, 5]])
        for weighting in mesh.WEIGHTINGS:
            n = mesh.vertex_normals(v, f, weighting)
            assert (n[:3] == 0.0).all(), (reversed_copy, weighting, n[:3])
            assert np.allclose(np.linalg.norm(n[3:], axis=1), 1.0)


def test_a_reversed_copy_inside_a_mesh_changes_nothing_but_rounding():
    v, f = mesh.icosphere(1)
    extra = f[[5, 17]][:, [1, 0, 2]]  # two faces glued back on, reversed
    g = np.vstack([f, extra])
    plain = mesh.vertex_normals(v, np.delete(f, [5, 17], axis=0))
    both = mesh.vertex_normals(v, np.vstack([np.delete(f, [5, 17], axis=0), f[[5, 17]], extra]))
    np.testing.assert_allclose(both, plain, rtol=0, atol=1e-15)
    assert mesh.check(v, g).reversed_duplicate_faces.tolist() == [80, 81]


def test_only_cancelled_pairs_are_dropped():
    # a face with two copies and one reversed copy: one pair cancels, one copy remains
    v = np.array([[0.1, 0.2, 0.3], [1.7, 0.1, 0.2], [0.3, 1.9, 0.7]])
    n = mesh.vertex_normals(v, [[0, 1, 2], [1, 2, 0], [0, 2, 1]])
    np.testing.assert_allclose(
        n, np.repeat(mesh.face_normals(v, [[0, 1, 2]]), 3, axis=0), atol=1e-15
    )


# --------------------------------------------------------------------------- the report as data and words


def test_to_dict_is_json_and_matches_the_fields():
    v, f = mesh.damaged_model()
    r = mesh.check(v, f)
    d = json.loads(json.dumps(r.to_dict()))
    assert d["n_faces"] == len(f) and d["n_vertices"] == len(v)
    assert d["faces_to_flip"] == r.faces_to_flip.tolist()
    assert d["boundary_edges"] == r.boundary_edges.tolist()
    assert d["components"][0]["faces_to_flip"] == len(r.faces_to_flip)
    assert d["closed"] is False and d["consistent_winding"] is False and d["ok"] is False


def test_the_damaged_model_has_exactly_a_flipped_patch_and_a_hole():
    v, f = mesh.damaged_model()
    r = mesh.check(v, f)
    assert len(r.components) == 1
    assert not r.closed and not r.consistent_winding
    for name in (
        "degenerate_faces",
        "duplicate_faces",
        "reversed_duplicate_faces",
        "non_manifold_edges",
        "non_manifold_vertices",
        "unused_vertices",
    ):
        assert len(getattr(r, name)) == 0, name
    # the flipped faces point inward (the ball is centred on the origin)
    centres = v[f].mean(axis=1)
    inward = np.einsum("ij,ij->i", mesh.face_normals(v, f), centres) < 0
    assert r.faces_to_flip.tolist() == np.flatnonzero(inward).tolist()
    fixed, _ = mesh.fix_winding(v, f)
    assert (np.einsum("ij,ij->i", mesh.face_normals(v, fixed), centres) > 0).all()
    # one hole: its boundary edges form a single loop
    nxt = dict(r.boundary_edges.tolist())
    start = next(iter(nxt))
    loop, k = [start], nxt[start]
    while k != start:
        loop.append(k)
        k = nxt[k]
    assert len(loop) == len(r.boundary_edges)


def test_the_shipped_sample_is_what_damaged_model_writes(tmp_path):
    v, f = mesh.damaged_model()
    mesh.write_mesh(tmp_path / "damaged_ball.obj", v, f)
    assert (tmp_path / "damaged_ball.obj").read_bytes() == Path(mesh.sample_path()).read_bytes()


def test_summary_of_an_inside_out_cube():
    v, f = mesh.cube()
    r = mesh.check(v, f[:, [0, 2, 1]])
    assert r.consistent_winding and r.closed and not r.outward
    assert r.components[0].outward is False and r.components[0].volume == -8.0
    assert "inside out" in r.summary()
    assert r.faces_to_flip.tolist() == list(range(12))


def test_only_the_inside_out_piece_is_turned_over():
    v, f = mesh.cube()
    v2, f2 = np.vstack([v, v + np.array([5.0, 0, 0])]), np.vstack([f, f[:, [0, 2, 1]] + 8])
    r = mesh.check(v2, f2)
    assert [c.outward for c in r.components] == [True, False]
    fixed, flipped = mesh.fix_winding(v2, f2)
    assert flipped.tolist() == list(range(12, 24))
    assert (fixed == np.vstack([f, f + 8])).all()


@pytest.mark.parametrize("scale", [8e307, 1e300, 1e-300])
@pytest.mark.parametrize(
    "model", [mesh.cube, lambda: mesh.uv_sphere(16, 8)], ids=["cube", "sphere"]
)
def test_the_verdict_holds_at_any_scale(model, scale):
    # the module's filterwarnings("error") turns any overflow or invalid-value warning into a failure
    v, f = model()
    v = v * scale
    good = mesh.check(v, f)
    assert good.outward is True and good.faces_to_flip.size == 0
    assert "inside out" not in good.summary() and "every normal points outward" in good.summary()
    assert mesh.fix_winding(v, f)[1].size == 0
    bad = f[:, [0, 2, 1]]
    r = mesh.check(v, bad)
    assert r.outward is False and "is inside out" in r.summary()
    fixed, flipped = mesh.fix_winding(v, bad)
    assert flipped.tolist() == list(range(len(f))) and (fixed == f).all()
    # the volume in the coordinates' unit: infinite where it overflows, zero where it
    # underflows, never NaN, and of the winding's sign
    big = scale > 1
    for faces, sign in ((f, 1.0), (bad, -1.0)):
        for volume in (mesh.signed_volume(v, faces), mesh.check(v, faces).components[0].volume):
            assert volume == (sign * np.inf if big else 0.0)
            assert np.copysign(1.0, volume) == sign


def test_the_volume_keeps_its_value_where_it_fits():
    v, f = mesh.cube()
    for scale in (2.0**-300, 2.0**300, 2.0**-1000):
        expected = 8.0 * scale**3 if scale**3 > 0 else 0.0
        assert mesh.signed_volume(v * scale, f) == expected
        assert mesh.check(v * scale, f).components[0].volume == expected
        assert mesh.check(v * scale, f[:, [0, 2, 1]]).components[0].volume == -expected


def test_empty_mesh():
    r = mesh.check(np.empty((0, 3)), np.empty((0, 3), dtype=int))
    assert r.n_faces == 0 and r.components == ()
    out, flipped = mesh.fix_winding(np.empty((0, 3)), np.empty((0, 3), dtype=int))
    assert out.shape == (0, 3) and flipped.size == 0


def test_bad_arrays_name_the_row():
    with pytest.raises(ValueError, match="faces row 1 refers to vertex 9"):
        mesh.check(np.zeros((3, 3)), [[0, 1, 2], [0, 1, 9]])
    with pytest.raises(ValueError, match="vertices row 2: y is NaN"):
        mesh.fix_winding([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]], [[0, 1, 2]])


def test_topology_functions_agree_with_the_report():
    # the functions join faces by index; the report by position: give them the joined faces
    m = mesh.read_mesh(DATA / "faults.obj")
    r = mesh.check(m.vertices, m.faces)
    joined = np.array(at_one_position(m.vertices, m.faces))
    assert not (joined == m.faces).all()  # vertex 16 is at vertex 13's position
    assert (mesh.boundary_edges(joined) == r.boundary_edges).all()
    assert (mesh.non_manifold_edges(joined) == r.non_manifold_edges).all()
    assert (mesh.non_manifold_vertices(joined) == r.non_manifold_vertices).all()
    assert (mesh.connected_components(joined) == r.face_component).all()
    same, rev = mesh.duplicate_faces(joined)
    assert (same == r.duplicate_faces).all() and (rev == r.reversed_duplicate_faces).all()
    counts = Counter(map(tuple, m.faces.tolist()))
    assert counts[(10, 11, 12)] == 1  # the exact copy is written rotated in the file


@settings(max_examples=50, deadline=None)
@given(messy_meshes())
def test_huge_vertex_numbers_take_the_unpacked_sorts(vf):
    # above 2**20 the duplicate search cannot pack its keys; near 2**31 the edge sort cannot
    # pack a key with its index, above 2**31 not even a key
    _, f = vf
    for offset in (2**21, 2**31 - 16, 2**31 + 5):
        g = f + offset
        same, rev = mesh.duplicate_faces(f)
        same_g, rev_g = mesh.duplicate_faces(g)
        assert (same == same_g).all() and (rev == rev_g).all()
        assert (mesh.boundary_edges(g) == mesh.boundary_edges(f) + offset).all()
        assert (mesh.non_manifold_edges(g) == mesh.non_manifold_edges(f) + offset).all()
        assert (mesh.non_manifold_vertices(g) == mesh.non_manifold_vertices(f) + offset).all()
        assert (mesh.connected_components(g) == mesh.connected_components(f)).all()


def _pieces_by_python(n: int, a: list[int], b: list[int]) -> list[int]:
    """Connected pieces by a plain union-find, numbered by each piece's smallest node."""
    root = list(range(n))

    def find(x: int) -> int:
        while root[x] != x:
            x = root[x]
        return x

    for i, j in zip(a, b, strict=True):
        ri, rj = find(i), find(j)
        root[max(ri, rj)] = min(ri, rj)
    number: dict[int, int] = {}
    return [number.setdefault(find(x), len(number)) for x in range(n)]


@pytest.mark.parametrize("seed", range(40))
def test_pieces_of_random_graphs_match_a_plain_union_find(seed):
    from trinormal.mesh.topology import _components

    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 400))
    m = int(rng.integers(0, 2 * n))
    a, b = rng.integers(0, n, m), rng.integers(0, n, m)
    if seed % 4 == 0:  # long chains: a path numbered backwards, the worst case for hooking
        a = np.arange(n - 1)[::-1].copy()
        b = a + 1
    got = _components(n, a, b)
    assert got.tolist() == _pieces_by_python(n, a.tolist(), b.tolist())
