"""One surface per position, cavities and open pieces (issue 31), on real-looking exports.

The files are made here as exporters make them: an OBJ whose UV seam lists its vertices
twice, a CAD STL whose shared corners differ in the last bits, an unwelded triangle soup,
one whose corners were rounded apart (a near miss), hollow balls, a holed ball and a cup
wound inward, flat sheets and a terrain.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from mesh_corpus import hollow_plate, last_bits, obj, seamed, soup, stl_binary, tri

from trinormal import mesh
from trinormal.mesh import icosphere, terrain, uv_sphere
from trinormal.mesh.welding import WELD_AUTO, WELD_NEAR, model_size, round_distance

ROOT = Path(__file__).resolve().parents[1]
BALL = tri(*icosphere(2))


def read(tmp_path: Path, name: str, data: bytes) -> mesh.MeshData:
    path = tmp_path / name
    path.write_bytes(data)
    return mesh.read_mesh(path)


# --------------------------------------------------------------------------- one surface per position


def test_a_uv_seamed_obj_is_one_closed_piece_and_keeps_its_indices(tmp_path):
    v, polys = seamed(tri(*uv_sphere(16, 8)), lambda c: c[:, 1] > 0)
    m = read(tmp_path, "capsule.obj", obj(v, polys))
    by_index = mesh.boundary_edges(m.faces)
    assert len(by_index) > 20  # joined by index alone, the seam is a rim
    r = mesh.check(m.vertices, m.faces)
    assert r.ok and len(r.components) == 1 and len(r.boundary_edges) == 0
    assert r.merged_vertices > 0 and r.welded_vertices == 0
    # every index the report names is one of the file's, and no seam vertex (the copies)
    assert r.face_component.max() == 0
    flipped = mesh.fix_winding(m.vertices, m.faces[:, [0, 2, 1]])[0]
    assert (flipped == m.faces).all()  # the file's own indices come back


def test_a_cad_stl_whose_corners_differ_in_the_last_bits_is_closed(tmp_path):
    v, polys = last_bits(BALL)
    r = mesh.check(v, np.array(polys))
    assert r.ok and r.welded_vertices > 0
    assert "are taken as that corner" in r.summary()
    # in a binary STL (float32) the corners read back equal: the reader joins them
    m = read(tmp_path, "part.stl", stl_binary(v, polys))
    assert mesh.check(m.vertices, m.faces).ok


def test_an_unwelded_soup_is_one_piece_not_one_per_face():
    v, polys = soup(BALL)
    r = mesh.check(v, np.array(polys))
    assert len(r.components) == 1 and r.ok
    assert r.merged_vertices == len(v) - 162


def test_minus_zero_is_zero():
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [-0.0, 0, 0], [0, -1, 0]])
    r = mesh.check(v, [[0, 1, 2], [3, 4, 1]])
    assert len(r.components) == 1 and r.merged_vertices == 1


def test_float_noise_is_merged_and_a_real_gap_never_is():
    f = np.array(BALL[1])
    size = model_size(BALL[0], np.array(BALL[1]))
    for noise, merged in ((1e-12, True), (1e-8, False), (1e-3, False)):
        v, polys = soup(BALL, noise / size)  # moved by up to `noise` along each axis
        r = mesh.check(v, np.array(polys))
        assert (len(r.components) == 1) is merged, noise
    assert len(f) == 320
    assert WELD_AUTO * size > 1.8e-12 * size  # a diagonal of three 1e-12 errors


def test_a_near_miss_is_reported_in_words_and_merged_on_request():
    v, polys = soup(BALL, 2e-6)
    f = np.array(polys)
    r = mesh.check(v, f)
    assert len(r.components) == 320
    assert r.near_miss_edges == 960 and r.near_miss_distance == 1e-5
    text = " ".join(r.summary().split())
    assert "960 boundary edges would close if corners closer than 1e-5 were merged: " in text
    assert "probably an export that did not weld its vertices" in text
    assert r.to_dict()["near_miss"] == {"edges": 960, "distance": 1e-5}
    welded = mesh.check(v, f, weld=True)
    assert welded.ok and welded.weld_distance == 1e-5 and welded.to_dict()["near_miss"] is None
    assert mesh.check(v, f, weld=1e-5).ok
    # a distance smaller than the gaps merges some corners, not all
    some = mesh.check(v, f, weld=1e-6)
    assert 0 < some.welded_vertices < 798 and some.near_miss_distance == 1e-5
    # no near miss where the gap is real: farther than WELD_NEAR of the size
    far = soup(BALL, 30 * WELD_NEAR)
    assert mesh.check(far[0], np.array(far[1])).near_miss_distance is None


def test_a_weld_distance_must_be_small_and_a_number():
    v, f = BALL
    for bad in (-1.0, float("nan"), float("inf"), 0.1):
        with pytest.raises(ValueError, match="weld distance"):
            mesh.check(v, f, weld=bad)
    # 0: only corners at exactly one position
    sv, sp = soup(BALL, 1e-13)
    assert len(mesh.check(sv, np.array(sp), weld=0).components) == 320


def test_distances_are_written_as_1_2_or_5_times_a_power_of_ten():
    assert round_distance(1.3e-6) == (2e-6, "2e-6")
    assert round_distance(2e-6) == (5e-6, "5e-6")
    assert round_distance(2e-6, above=False) == (2e-6, "2e-6")
    assert round_distance(7.0) == (10.0, "10")
    assert round_distance(4321.0) == (5000.0, "5000")
    assert round_distance(43210.0) == (50000.0, "5e4")


# --------------------------------------------------------------------------- shells


def hollow(inner_faces_inward: bool) -> tuple[np.ndarray, np.ndarray]:
    v, f = icosphere(2)
    inner = f[:, ::-1] if inner_faces_inward else f
    return np.vstack([v, v * 0.6]), np.vstack([f, inner + len(v)])


def test_a_hollow_ball_with_its_inner_shell_facing_the_cavity_is_right():
    v, f = hollow(True)
    r = mesh.check(v, f)
    assert r.ok and len(r.faces_to_flip) == 0
    assert [c.cavity for c in r.components] == [False, True]
    assert r.components[1].volume < 0 and r.components[1].outward is True
    assert "Piece 2 (320 faces) is a cavity" in " ".join(r.summary().split())
    assert mesh.fix_winding(v, f)[1].size == 0
    # its volume, outer minus inner, is the wall's
    total = sum(c.volume for c in r.components)
    assert total == pytest.approx(mesh.signed_volume(v, f))


def test_a_hollow_ball_with_its_inner_shell_facing_out_is_fixed():
    v, f = hollow(False)
    r = mesh.check(v, f)
    assert not r.ok and r.outward is False
    assert r.faces_to_flip.tolist() == list(range(320, 640))
    assert "but its normals point out of the hollow" in " ".join(r.summary().split())
    fixed, _ = mesh.fix_winding(v, f)
    assert mesh.check(v, fixed).ok


def test_an_inside_out_hollow_ball_turns_both_shells_over():
    v, f = hollow(True)
    fixed, flipped = mesh.fix_winding(v, f[:, ::-1])
    assert len(flipped) == 640 and mesh.check(v, fixed).ok


def test_every_inner_shell_of_a_plate_of_hollow_balls_is_a_cavity():
    v, polys = hollow_plate(subdivisions=1)
    r = mesh.check(v, np.array(polys))
    assert r.ok and len(r.components) == 320
    assert [c.cavity for c in r.components] == [False, True] * 160


def test_the_box_holders_are_every_pair_whose_box_holds_the_other():
    from trinormal.mesh.shells import _box_holders

    rng = np.random.default_rng(7)
    n = 700  # boxes on a coarse grid, so that many share a face or are equal
    lo = rng.integers(0, 6, size=(n, 3)).astype(float)
    hi = lo + rng.integers(0, 4, size=(n, 3))
    which = np.flatnonzero(rng.random(n) < 0.9)
    expected = {
        (a, b)
        for a in which.tolist()
        for b in which.tolist()
        if a != b and (lo[b] <= lo[a]).all() and (hi[a] <= hi[b]).all()
    }
    got = _box_holders(which, lo, hi)
    assert len(got) == len(set(got)) and set(got) == expected and len(expected) > 1000


# --------------------------------------------------------------------------- open pieces


def holed_ball() -> tuple[np.ndarray, np.ndarray]:
    v, f = icosphere(2)
    return v, f[v[f].mean(axis=1)[:, 2] < 0.9]


def test_a_ball_with_a_small_hole_wound_inward_is_inside_out_and_fixed():
    v, f = holed_ball()
    r = mesh.check(v, f[:, ::-1])
    c = r.components[0]
    assert (c.closed, c.outward, c.judged_by) == (False, False, "volume_over_holes")
    assert len(r.faces_to_flip) == len(f)
    assert "closed over its holes it encloses a volume, and every normal points inward" in (
        " ".join(r.summary().split())
    )
    fixed, _ = mesh.fix_winding(v, f[:, ::-1])
    assert mesh.check(v, fixed).outward is True


def test_a_cup_is_judged_and_a_sheet_or_terrain_only_for_consistency():
    v, f = icosphere(2)
    cup = f[v[f].mean(axis=1)[:, 2] < 0.05]
    r = mesh.check(v, cup)
    assert r.components[0].judged_by == "volume_over_holes" and r.outward is True
    assert mesh.check(v, cup[:, ::-1]).outward is False
    gv, gf = terrain(6, 5)
    for verts in (gv, gv * [1.0, 1.0, 0.0]):
        for faces in (gf, gf[:, ::-1]):
            r = mesh.check(verts, faces)
            c = r.components[0]
            assert (c.outward, c.judged_by, r.outward, len(r.faces_to_flip)) == (
                None,
                None,
                None,
                0,
            )
            assert "encloses nothing, like a sheet or a terrain" in " ".join(r.summary().split())


# --------------------------------------------------------------------------- the command line and the page


def run_cli(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    """``trinormal mesh ARGS`` in this process: its status, stdout and stderr."""
    from trinormal.cli import main

    status = main(["mesh", *args])
    out = capsys.readouterr()
    return status, out.out, out.err


def test_the_command_line_welds_on_request(tmp_path, capsys):
    v, polys = soup(BALL, 2e-6)
    path = tmp_path / "soup.obj"
    path.write_bytes(obj(v, polys))
    _, plain, _ = run_cli(capsys, str(path), "--json")
    assert json.loads(plain)["report"]["near_miss"] == {"edges": 960, "distance": 1e-5}
    for extra in (["--weld"], ["--weld", "1e-5"]):
        out = json.loads(run_cli(capsys, str(path), "--json", *extra)[1])["report"]
        assert out["n_components"] == 1 and out["near_miss"] is None, extra
    for bad in ("x", "-1", "nan"):
        status, _, err = run_cli(capsys, str(path), "--weld", bad)
        assert status == 2 and "--weld" in err, bad
    status, _, err = run_cli(capsys, str(path), "--weld", "1")
    assert status == 2 and "weld distance 1.0" in err


def test_the_page_draws_no_merged_seam_as_a_hole(tmp_path):
    """The view's hole rims are the report's boundary sides: none on a welded seam."""
    sys.path.insert(0, str(ROOT / "docs" / "hooks"))
    import trinormal_site  # the mkdocs hook, as test_mesh_parity.py imports it

    v, polys = seamed(tri(*uv_sphere(16, 8)), lambda c: c[:, 1] > 0)
    (tmp_path / "c.json").write_text(json.dumps(trinormal_site.site_constants()))
    (tmp_path / "m.obj").write_bytes(obj(v, polys))
    script = """
        const fs = require("fs");
        const [checker, constants, file] = process.argv.slice(1);
        const M = require(checker).loadMesh(JSON.parse(fs.readFileSync(constants, "utf8")));
        const mesh = M.read(new Uint8Array(fs.readFileSync(file)), "m.obj");
        const r = M.check(mesh.vertices, mesh.faces);
        console.log(JSON.stringify([r._boundary_sides.length, r.n_components, r.ok]));
    """
    run = subprocess.run(
        [
            "node",
            "-e",
            script,
            str(ROOT / "tests" / "mesh_parity_check.js"),
            str(tmp_path / "c.json"),
            str(tmp_path / "m.obj"),
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout) == [0, 1, True]


def test_the_notebook_view_draws_a_real_hole_on_a_seamed_model_and_not_the_seam():
    from trinormal.mesh.widget import MeshView

    v, polys = seamed(tri(*uv_sphere(16, 8)), lambda c: c[:, 1] > 0)
    f = np.array(polys)
    # a hole at the seam, in a face that uses a copy: the report names the first vertex there
    first = {}
    rep = np.array([first.setdefault(tuple(p), i) for i, p in enumerate(v.tolist())])
    hole = int(np.flatnonzero((rep[f] != f).any(axis=1))[0])
    holed = np.delete(f, hole, axis=0)
    r = mesh.check(v, holed)
    assert len(r.boundary_edges) == 3 and not set(f[hole]) >= set(r.boundary_edges.ravel())
    view = MeshView(v, holed)
    sides = np.frombuffer(view.boundary, dtype="<i4")
    assert len(sides) == 3  # the hole's rim, found on the file's faces; the seam is none
    assert set((sides // 3).tolist()) <= set(range(len(holed)))
