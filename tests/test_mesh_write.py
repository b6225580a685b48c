"""A repaired file is the student's file with faces turned over, and polygons split right.

The files come from the parity corpus (``tests/mesh_corpus.py``), so the page's JavaScript
is held to the same bytes by ``tests/test_mesh_parity.py``.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from mesh_corpus import kept, l_prism, rich_ply, textured_obj

from trinormal.mesh import check, fix_winding, parse_mesh, write_mesh
from trinormal.mesh.polygons import split_polygon


def _fixed(tmp_path, name: str, data: bytes) -> bytes:
    m = parse_mesh(data, name.rsplit(".", 1)[1], name)
    faces, _ = fix_winding(m.vertices, m.faces)
    out = tmp_path / name
    write_mesh(out, m, faces)
    return out.read_bytes()


@pytest.mark.parametrize("crlf", [False, True])
def test_a_fixed_textured_obj_is_the_file_with_its_flipped_quads_turned_back(tmp_path, crlf):
    """vt/vn references travel with their corners; comments, groups, materials, colours stay."""
    flipped = textured_obj((1, 4), crlf=crlf)
    assert flipped != textured_obj(crlf=crlf)
    assert _fixed(tmp_path, "box.obj", flipped) == textured_obj(crlf=crlf)


@pytest.mark.parametrize("fmt", ["ascii", "binary_little_endian", "binary_big_endian"])
def test_a_fixed_rich_ply_keeps_its_header_properties_and_per_corner_lists(tmp_path, fmt):
    """Normals, colours, face flags, texture lists and an extra element, as they were."""
    assert _fixed(tmp_path, "l.ply", rich_ply(fmt, flip=(1, 4))) == rich_ply(fmt)
    wide = rich_ply("binary_little_endian", "int", "uint", flip=(0,))
    assert _fixed(tmp_path, "w.ply", wide) == rich_ply("binary_little_endian", "int", "uint")


def test_a_fixed_binary_stl_changes_only_the_turned_records_and_their_normals(tmp_path):
    files = dict(kept())
    data = files["cad-attributes-trailing.stl"]
    out = _fixed(tmp_path, "cad.stl", data)
    assert len(out) == len(data) and out[:84] == data[:84] and out[-3:] == data[-3:]
    n = (len(data) - 87) // 50
    rec = lambda b: np.frombuffer(b, dtype="V50", count=n, offset=84)  # noqa: E731
    assert np.flatnonzero(rec(out) != rec(data)).tolist() == [0, 7, 8]
    for i in (0, 7, 8):
        a, b = data[84 + 50 * i :][:50], out[84 + 50 * i :][:50]
        assert b[12:24] == a[12:24] and b[24:36] == a[36:48] and b[36:48] == a[24:36]
        assert b[48:] == a[48:]  # the attribute bytes
        assert b[:12] != bytes(12)  # the normal, recomputed


def test_a_fixed_ascii_stl_keeps_solid_names_and_changes_only_turned_facets(tmp_path):
    data = dict(kept())["named-solids.stl"]
    out = _fixed(tmp_path, "named.stl", data)
    before, after = data.splitlines(keepends=True), out.splitlines(keepends=True)
    assert len(before) == len(after)
    changed = [i for i, (a, b) in enumerate(zip(before, after, strict=True)) if a != b]
    facet = [i for i, line in enumerate(before) if line.strip().startswith(b"facet")]
    turned = {facet[k] for k in (0, 7, 8)}
    assert set(changed) == turned | {i + 3 for i in turned} | {i + 4 for i in turned}
    assert after[0] == b"solid part_1 (mm)\n" and b"endsolid Tetra\r\n" in after


def test_writing_a_read_model_can_only_turn_faces_over(tmp_path):
    m = parse_mesh(textured_obj(), "obj")
    with pytest.raises(ValueError, match="only turns faces over: triangle 0"):
        write_mesh(tmp_path / "x.obj", m, m.faces[:, [1, 2, 0]] * 0)
    write_mesh(tmp_path / "same.obj", m)
    assert (tmp_path / "same.obj").read_bytes() == textured_obj()
    write_mesh(tmp_path / "other.ply", m)  # another format: vertices and triangles
    assert parse_mesh((tmp_path / "other.ply").read_bytes(), "ply").faces.shape == (12, 3)


def test_the_command_line_fix_keeps_the_file(tmp_path):
    src, out = tmp_path / "box.obj", tmp_path / "fixed.obj"
    src.write_bytes(textured_obj((2,)))
    run = subprocess.run(
        [sys.executable, "-m", "trinormal.cli", "mesh", str(src), "--fix", str(out)],
        capture_output=True,
        text=True,
    )
    assert out.read_bytes() == textured_obj(), run.stderr
    assert "The stored normals of 1 face point against its winding." in run.stdout


def _area(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def test_ear_clipping_covers_random_star_shaped_polygons_exactly():
    """Concave polygons, tilted: every triangle wound the polygon's way, areas adding up."""
    rng = np.random.default_rng(31)
    concave = 0
    for _ in range(300):
        n = int(rng.integers(4, 14))
        angles = 2 * math.pi * (np.arange(n) + rng.uniform(0, 0.9, n)) / n  # gaps below pi
        r = rng.uniform(0.2, 1.0, n)
        pts = np.stack([r * np.cos(angles), r * np.sin(angles), np.zeros(n)], axis=1)
        tilt = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        tris, nonplanar, crossing = split_polygon([tuple(p) for p in (pts @ tilt.T).tolist()])
        assert len(tris) == n - 2 and not nonplanar and not crossing
        areas = [_area(pts[list(t)]) for t in tris]
        assert min(areas) > 0
        assert math.isclose(sum(areas), _area(pts), rel_tol=1e-9)
        fan = [_area(pts[[0, k, k + 1]]) for k in range(1, n - 1)]
        concave += min(fan) < 0
    assert concave > 100  # most of them a fan from the first corner would have got wrong


def _hard_polygons(rng: np.random.Generator) -> list[list[tuple[float, float, float]]]:
    """Big polygons of every kind: star-shaped, self-crossing, with repeated corners and
    straight runs, some on a coarse grid so that corners fall on other corners' triangles."""
    polys = []
    for k in range(60):
        n = int(rng.integers(49, 160))
        angles = 2 * math.pi * (np.arange(n) + rng.uniform(0, 0.9, n)) / n
        r = rng.uniform(0.2, 1.0, n)
        if k % 4 == 1:  # a self-crossing one: corners in a shuffled order
            angles = rng.permutation(angles)
        if k % 8 == 4:  # the last two corners swapped: the last side crosses one side only
            angles[[-1, -2]] = angles[[-2, -1]]
        xy = np.stack([r * np.cos(angles), r * np.sin(angles)], axis=1)
        if k % 4 == 2:  # on a grid: corners on other corners' sides, repeated corners
            xy = np.round(xy * 4) / 4
        if k % 4 == 3:  # a straight run of corners, and one corner twice
            xy[5:12, 1] = xy[5, 1]
            xy[20] = xy[19]
        pts = np.column_stack([xy, 0.1 * xy[:, 0] if k % 2 else np.zeros(n)])
        polys.append([tuple(p) for p in pts.tolist()])
    return polys


def test_big_polygons_are_split_with_arrays_exactly_as_in_a_loop(monkeypatch):
    """Over `polygons._MANY` corners the search uses numpy: the same triangles and flags."""
    from trinormal.mesh import polygons

    cases = _hard_polygons(np.random.default_rng(5))
    with_arrays = [split_polygon(p) for p in cases]
    monkeypatch.setattr(polygons, "_MANY", 10**9)
    in_a_loop = [split_polygon(p) for p in cases]
    assert with_arrays == in_a_loop
    assert sum(crossing for _, _, crossing in in_a_loop) >= 15
    assert (
        sum(tris != [(0, k, k + 1) for k in range(1, len(tris) + 1)] for tris, _, _ in in_a_loop)
        > 30
    )


def test_the_concave_cap_is_not_reported_degenerate_or_flipped():
    v, polys = l_prism()
    data = "".join(f"v {x} {y} {z}\n" for x, y, z in v.tolist())
    data += "".join("f " + " ".join(str(i + 1) for i in p) + "\n" for p in polys)
    m = parse_mesh(data.encode(), "obj")
    r = check(m.vertices, m.faces)
    assert r.closed and r.consistent_winding and r.outward and r.ok
    assert len(r.degenerate_faces) == 0 and len(r.faces_to_flip) == 0


def test_stored_normals_against_the_winding_are_counted_before_and_after_the_fix(tmp_path):
    """OBJ vn kept as they were: they agreed with the winding the fix restores."""
    m = parse_mesh(textured_obj((1, 4)), "obj", "box.obj")
    fixed, _ = fix_winding(m.vertices, m.faces)
    assert m.normals_against().tolist() == [1, 4]
    assert m.normals_against(fixed).tolist() == []
    assert m.describe().endswith("The stored normals of 2 faces point against their winding.")
    stl = dict(kept())["named-solid-normals.stl"]  # every facet says +z
    s = parse_mesh(stl, "stl")
    fixed, flipped = fix_winding(s.vertices, s.faces)
    before, after = s.normals_against(), s.normals_against(fixed)
    assert set(after.tolist()) == set(before.tolist()) - set(flipped.tolist())  # recomputed
    assert parse_mesh(textured_obj(), "obj").normals_against().tolist() == []
    assert parse_mesh(rich_ply("ascii"), "ply").normals_against().tolist() == [0]  # the floor
    assert parse_mesh(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj").normals_against() is None


def test_a_binary_stl_with_negative_zero_corners_is_kept_whole(tmp_path):
    data = dict(kept())["negative-zero.stl"]
    m = parse_mesh(data, "stl")
    assert m.stl_records is None and m.source == data
    out = _fixed(tmp_path, "z.stl", data)
    assert out[84 + 12 : 84 + 16] == data[84 + 12 : 84 + 16] == b"\x00\x00\x00\x80"  # -0.0
    assert _fixed(tmp_path, "z2.stl", out) == out  # nothing left to turn over: as it was
