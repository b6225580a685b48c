"""MeshView: the buffers it sends, and a clicked face's exact normal from the kernel.

Every expected value is computed here a second way: the buffers decoded with numpy and
compared with the arrays and the report, the clicked face's normal with Fractions.
"""

from __future__ import annotations

import json
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from node_runs import node_path

from trinormal import mesh
from trinormal.display import format_number, format_vector
from trinormal.explorer.view import BUNDLE
from trinormal.mesh.widget import MAX_ARROWS, MESH_BUNDLE, MeshView, face_selection


def decode(view: MeshView, name: str, dtype: str, width: int = 1) -> np.ndarray:
    data = np.frombuffer(getattr(view, name), dtype=np.dtype(dtype).newbyteorder("<"))
    return data.reshape(-1, width) if width > 1 else data


def side_edges(faces: np.ndarray, sides: np.ndarray) -> set[frozenset[int]]:
    """The edges (unordered vertex pairs) of face sides 3 * face + k."""
    out = set()
    for h in sides:
        f, k = divmod(int(h), 3)
        out.add(frozenset((int(faces[f][k]), int(faces[f][(k + 1) % 3]))))
    return out


@pytest.fixture(scope="module")
def ball() -> mesh.MeshData:
    return mesh.read_mesh(mesh.sample_path())


def test_the_module_is_the_sites_mesh_view_bundle() -> None:
    # one bundle for both views (one three.js): the widget says which view draws it
    assert MESH_BUNDLE == BUNDLE and MESH_BUNDLE.is_file()
    assert MeshView(mesh.read_mesh(mesh.sample_path())).get_state()["_view"] == "mesh"
    assert sorted(p.name for p in BUNDLE.parent.glob("*.js")) == ["explorer.js"]
    assert str(MeshView._esm) == MESH_BUNDLE.read_text(encoding="utf-8")


def test_geometry_travels_as_little_endian_binary_buffers(ball: mesh.MeshData) -> None:
    view = MeshView(ball)
    for name in ("positions", "faces", "flipped", "boundary", "arrow_faces", "vertex_normals"):
        assert isinstance(getattr(view, name), bytes), name
    np.testing.assert_array_equal(decode(view, "positions", "f8", 3), ball.vertices)
    np.testing.assert_array_equal(decode(view, "faces", "u4", 3), ball.faces)
    vn = mesh.vertex_normals(ball.vertices, ball.faces, "angle").astype(np.float32)
    np.testing.assert_array_equal(decode(view, "vertex_normals", "f4", 3), vn)


def test_faults_match_the_report(ball: mesh.MeshData) -> None:
    report = mesh.check(ball.vertices, ball.faces)
    view = MeshView(ball)
    np.testing.assert_array_equal(decode(view, "flipped", "i4"), report.faces_to_flip)
    sides = decode(view, "boundary", "i4")
    rims = {frozenset(map(int, e)) for e in report.boundary_edges}
    assert len(sides) == len(rims) == 13
    assert side_edges(ball.faces, sides) == rims
    assert decode(view, "non_manifold", "i4").size == 0


def test_non_manifold_edges_get_one_side_each() -> None:
    v, f = mesh.cube()
    a, b = f[0][0], f[0][1]  # a fin: a third face on one of the cube's edges
    v = np.vstack([v, [[5.0, 5.0, 5.0]]])
    f = np.vstack([f, [[a, b, len(v) - 1]]])
    report = mesh.check(v, f)
    assert len(report.non_manifold_edges) == 1
    view = MeshView(v, f)
    sides = decode(view, "non_manifold", "i4")
    assert len(sides) == 1
    assert side_edges(f, sides) == {frozenset((int(a), int(b)))}


def test_arrows_are_every_face_on_a_small_model_and_a_sample_on_a_big_one(
    ball: mesh.MeshData,
) -> None:
    view = MeshView(ball)
    faces = decode(view, "arrow_faces", "i4")
    np.testing.assert_array_equal(faces, np.arange(len(ball.faces)))
    normals = decode(view, "arrow_normals", "f4", 3)
    np.testing.assert_array_equal(
        normals, mesh.face_normals(ball.vertices, ball.faces).astype(np.float32)
    )
    v, f = mesh.terrain(320, 320)  # 203 522 faces
    assert len(f) > 200_000
    big = MeshView(v, f)
    picked = decode(big, "arrow_faces", "i4")
    assert 0 < len(picked) <= MAX_ARROWS and np.all(np.diff(picked) > 0)
    assert picked[0] == 0 and picked[-1] == len(f) - 1  # spread over the whole model
    np.testing.assert_array_equal(
        decode(big, "arrow_normals", "f4", 3), mesh.face_normals(v, f[picked]).astype(np.float32)
    )
    # what crosses to the browser: binary, 24 + 12 bytes a vertex (with its normal), 12 a face
    sent = sum(len(getattr(big, n)) for n in ("positions", "faces", "vertex_normals"))
    assert sent == 36 * len(v) + 12 * len(f)
    assert len(MeshView(v, f, max_arrows=0).arrow_faces) == 0


def exact_normal(points: np.ndarray) -> tuple[Fraction, ...]:
    a, b, c = ([Fraction(float(x)) for x in p] for p in points)
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def test_a_click_gets_the_exact_normal_and_area_from_the_kernel(ball: mesh.MeshData) -> None:
    report = mesh.check(ball.vertices, ball.faces)
    view = MeshView(ball, report=report, precision=6)
    for face in (int(report.faces_to_flip[0]), 0, len(ball.faces) - 1):
        view.picked = face  # what the browser writes on a click
        rows = {label: value for label, value, _ in view.selection["rows"]}
        corners = ball.faces[face]
        assert view.selection["face"] == face
        assert view.selection["title"].startswith(f"Face {face}: vertices {corners[0]}, ")
        n = exact_normal(ball.vertices[corners])
        assert rows["N = U × V"] == format_vector(n, 6)
        area = (sum(x * x for x in n)) ** 0.5 / 2
        assert abs(float(rows["area = |N|/2"]) - area) <= 0.5e-6 * 1.0000001
        for name, i in zip("ABC", corners, strict=True):
            assert rows[f"{name} = vertex {i}"] == format_vector(ball.vertices[i], 6)
        flagged = "winding" in rows
        assert flagged == (face in set(report.faces_to_flip.tolist()))
    # the clicked face of the damaged patch points into the ball: N · centre < 0
    face = int(report.faces_to_flip[0])
    n = exact_normal(ball.vertices[ball.faces[face]])
    centre = ball.vertices[ball.faces[face]].mean(axis=0)
    assert sum(float(a) * c for a, c in zip(n, centre, strict=True)) < 0


def test_precision_reformats_the_selection_and_bad_input_is_a_message(
    ball: mesh.MeshData,
) -> None:
    view = MeshView(ball)
    view.picked = 5
    before = dict((label, value) for label, value, _ in view.selection["rows"])
    view.precision = 2
    after = dict((label, value) for label, value, _ in view.selection["rows"])
    assert before["|N|"] != after["|N|"]
    assert after["|N|"] == format_number(float(after["|N|"]), 2)
    view.picked = len(ball.faces) + 7  # a face that does not exist: said, not raised
    assert "does not exist" in view.selection["title"]
    view.picked = -1
    assert view.selection == {}
    with pytest.raises(ValueError, match="precision"):
        view.precision = 99
    with pytest.raises(ValueError, match="does not exist"):
        face_selection(ball.vertices, ball.faces, -3)
    with pytest.raises(ValueError, match="max_arrows"):
        MeshView(ball, max_arrows=-1)
    with pytest.raises(ValueError):
        MeshView([[0.0, 0.0, float("nan")]] * 3, [[0, 1, 2]])


def test_set_mesh_shows_the_repair(ball: mesh.MeshData) -> None:
    view = MeshView(ball)
    view.picked = 3
    revision = view.revision
    fixed, _ = mesh.fix_winding(ball.vertices, ball.faces)
    view.set_mesh(ball.vertices, fixed)
    assert view.revision == revision + 1 and view.picked == -1 and view.selection == {}
    assert decode(view, "flipped", "i4").size == 0
    assert "0 to flip" in view.summary() and "13 boundary" in view.summary()
    bundle = view._repr_mimebundle_()
    data = bundle[0] if isinstance(bundle, tuple) else bundle
    assert data["text/plain"] == view.summary()
    assert "application/vnd.jupyter.widget-view+json" in data


def view_words(*views: MeshView) -> list[str]:
    """The words under each view, as the mesh view's describe.js writes them from its traits."""
    node = node_path()
    facts = [
        {
            "about": v.about,
            "faces": v.n_faces,
            "flipped": decode(v, "flipped", "i4").tolist(),
            "picked": v.picked,
            "selection": v.selection,
        }
        for v in views
    ]
    script = Path(__file__).parent / "mesh_describe_check.mjs"
    run = subprocess.run(
        [node, str(script)], input=json.dumps(facts), capture_output=True, text=True, check=True
    )
    words: list[str] = json.loads(run.stdout)
    return words


def test_the_description_names_the_file_and_its_pieces_as_the_site_page_does(
    ball: mesh.MeshData,
) -> None:
    """A view of a file names the file (the site names the file chosen); arrays, "The model"."""
    from_file = MeshView(ball)
    report = from_file.report
    assert from_file.about == {
        "name": "damaged_ball.obj",
        "pieces": [
            {k: getattr(c, k) for k in ("faces", "closed", "outward", "faces_to_flip")}
            for c in report.components
        ],
    }
    v, f = mesh.cube()
    two = np.vstack([f, f + 8])[:-1]  # two cubes, the second with a hole
    arrays = MeshView(np.vstack([v, v + 5.0]), two)
    named = MeshView(ball.vertices, ball.faces, report=report, name="my ball.stl")
    words = view_words(from_file, arrays, named)
    assert words[0].startswith("damaged_ball.obj: 1263 faces in 1 piece. The piece is open"), words
    assert "Faces to flip (outlined): " in words[0]
    assert words[1].startswith(
        "The model: 23 faces in 2 pieces. Its pieces: piece 1, 12 faces: closed; "
        "piece 2, 11 faces: open (it has a hole)."
    ), words[1]
    assert words[2].startswith("my ball.stl: 1263 faces"), words[2]
    # another mesh shown in the same view: its own name, or none
    from_file.set_mesh(v, f)
    assert from_file.about["name"] == "" and view_words(from_file)[0].startswith("The model: 12")
    from_file.set_mesh(ball, name="again.obj")
    assert from_file.about["name"] == "again.obj"
    with pytest.raises(ValueError, match=r"name must be a string \(the model's name\), got 3"):
        MeshView(v, f, name=3)


def test_without_anywidget_the_error_names_the_extra() -> None:
    code = (
        "import sys\n"
        "sys.modules['anywidget'] = None\n"
        "try:\n"
        "    import trinormal.mesh.widget\n"
        "except ImportError as e:\n"
        "    print(e)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True
    ).stdout
    assert "trinormal.mesh.widget needs anywidget" in out and "trinormal[notebooks]" in out
