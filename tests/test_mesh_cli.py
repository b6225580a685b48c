"""``trinormal mesh FILE [--fix OUT] [--json]``, run as a user runs it: through a subprocess."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from trinormal import mesh

DATA = Path(__file__).parent / "data" / "meshes"


def run(*args: str, code: str | None = None) -> subprocess.CompletedProcess[str]:
    cmd = (
        [sys.executable, "-c", code, *args] if code else [sys.executable, "-m", "trinormal", *args]
    )
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


def test_report_in_words():
    p = run("mesh", mesh.sample_path())
    assert p.returncode == 0, p.stderr
    r = mesh.check(*mesh.damaged_model())
    assert p.stdout.startswith(f"Read {mesh.sample_path()} (OBJ): 639 vertices, 1263 faces.\n")
    assert r.summary() in p.stdout
    assert p.stderr == ""


def test_json_is_the_reports_to_dict():
    p = run("mesh", str(DATA / "open_box.obj"), "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    m = mesh.read_mesh(DATA / "open_box.obj")
    assert d["report"] == json.loads(json.dumps(mesh.check(m.vertices, m.faces).to_dict()))
    assert (d["format"], d["encoding"], d["polygons"], d["polygons_split"]) == (
        "obj",
        "ascii",
        5,
        5,
    )


@pytest.mark.parametrize(
    "source,out",
    [
        ("tetra_flipped.stl", "fixed.stl"),
        ("open_box.obj", "fixed.obj"),
        ("mixed_polygons.ply", "fixed.ply"),
        ("open_box.obj", "fixed.ply"),
    ],
)
def test_fix_writes_a_consistent_file(tmp_path, source, out):
    target = tmp_path / out
    p = run("mesh", str(DATA / source), "--fix", str(target), "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    m = mesh.read_mesh(DATA / source)
    assert d["fixed"]["flipped"] == mesh.check(m.vertices, m.faces).faces_to_flip.tolist()
    back = mesh.read_mesh(target)
    same_format = target.suffix[1:] == m.format
    assert back.encoding == (m.encoding if same_format else "binary")
    r = mesh.check(back.vertices, back.faces)
    assert r.consistent_winding and r.faces_to_flip.size == 0


def test_fix_of_a_closed_model_faces_outward(tmp_path):
    p = run("mesh", str(DATA / "tetra_flipped.stl"), "--fix", str(tmp_path / "t.stl"))
    assert p.returncode == 0
    assert p.stdout.splitlines()[-1] == f"Wrote {tmp_path / 't.stl'} (STL): 1 face turned over."
    back = mesh.read_mesh(tmp_path / "t.stl")
    assert mesh.check(back.vertices, back.faces).ok


@pytest.mark.parametrize(
    "args,message",
    [
        (["mesh", str(DATA / "bad" / "bad_number.obj")], "line 2: 'zero' is not a number"),
        (["mesh", str(DATA / "bad" / "truncated.stl")], "not an STL file"),
        (["mesh", "nowhere.obj"], "nowhere.obj: cannot be read"),
        (["mesh", "model.blend"], "unknown mesh format .blend"),
        (["mesh"], "the following arguments are required: FILE"),
        (["mesh", str(DATA / "crlf.obj"), "--fix", "out.dae"], "unknown mesh format .dae"),
    ],
)
def test_bad_files_exit_2_with_one_line(args, message):
    p = run(*args)
    assert p.returncode == 2
    assert p.stdout == ""
    assert p.stderr.count("\n") == 1 and message in p.stderr
    assert p.stderr.startswith("trinormal: error: ")
    assert "Traceback" not in p.stderr


@pytest.mark.parametrize("content", [b"", b"solid x\nendsolid x\n"])
def test_a_file_with_no_faces_exits_2(tmp_path, content):
    path = tmp_path / "empty.stl"
    path.write_bytes(content)
    p = run("mesh", str(path))
    assert (p.returncode, p.stdout) == (2, "")
    assert (
        p.stderr
        == f"trinormal: error: {path}: the file has no faces: there is no surface to check\n"
    )


def test_a_note_goes_to_stderr_and_the_json_keeps_its_keys(tmp_path):
    path = tmp_path / "zero.stl"
    mesh.write_mesh(path, *mesh.cube())  # a binary STL of 12 triangles
    good = path.read_bytes()
    path.write_bytes(good[:80] + bytes(4) + good[84:])  # a triangle count of 0
    note = f"trinormal: note: {path}: the header's triangle count is 0, but the file holds 12"
    for args in ((), ("--json",)):
        p = run("mesh", str(path), *args)
        assert p.returncode == 0, p.stderr
        assert p.stderr.startswith(note) and p.stderr.count("\n") == 1
    assert list(json.loads(p.stdout)) == [
        "file", "format", "encoding", "polygons", "polygons_split", "report",
    ]  # fmt: skip
    assert json.loads(p.stdout)["report"]["n_faces"] == 12


def test_without_numpy_one_line_names_the_extra():
    code = (
        "import sys; sys.modules['numpy'] = None\n"
        "from trinormal.cli import main\n"
        "sys.exit(main(sys.argv[1:]))"
    )
    p = run("mesh", str(DATA / "crlf.obj"), code=code)
    assert p.returncode == 2
    assert p.stderr == (
        "trinormal: error: trinormal mesh needs numpy, which is not installed. "
        'Install the notebooks extra: pip install "trinormal[notebooks]"\n'
    )


def test_the_triangle_calculator_still_imports_no_numpy():
    code = (
        "import sys\n"
        "from trinormal.cli import main\n"
        "main(['0,0,0', '1,0,0', '0,1,0'])\n"
        "assert 'numpy' not in sys.modules, 'numpy was imported'\n"
    )
    p = run(code=code)
    assert p.returncode == 0, p.stderr
