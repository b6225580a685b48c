"""``trinormal mesh FILE [--fix OUT] [--json]``, run as a user runs it: through a subprocess."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from trinormal import mesh

ROOT = Path(__file__).resolve().parents[1]
DATA = Path(__file__).parent / "data" / "meshes"


def run(*args: str, code: str | None = None) -> subprocess.CompletedProcess[str]:
    cmd = (
        [sys.executable, "-c", code, *args] if code else [sys.executable, "-m", "trinormal", *args]
    )
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


def test_report_in_words():
    p = run("mesh", mesh.sample_path())
    assert p.returncode == 1, p.stderr  # a hole and flipped faces: a problem found
    r = mesh.check(*mesh.damaged_model())
    assert p.stdout.startswith(f"Read {mesh.sample_path()} (OBJ): 639 vertices, 1263 faces.\n")
    assert r.summary() in p.stdout
    assert p.stderr == ""


def test_json_is_the_reports_to_dict():
    p = run("mesh", str(DATA / "open_box.obj"), "--json")
    assert p.returncode == 1, p.stderr
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
    d = json.loads(p.stdout)
    m = mesh.read_mesh(DATA / source)
    assert p.returncode == (0 if mesh.check(m.vertices, m.faces).ok else 1), p.stderr
    assert d["fixed"]["flipped"] == mesh.check(m.vertices, m.faces).faces_to_flip.tolist()
    back = mesh.read_mesh(target)
    same_format = target.suffix[1:] == m.format
    assert back.encoding == (m.encoding if same_format else "binary")
    r = mesh.check(back.vertices, back.faces)
    assert r.consistent_winding and r.faces_to_flip.size == 0


def test_fix_of_a_closed_model_faces_outward(tmp_path):
    p = run("mesh", str(DATA / "tetra_flipped.stl"), "--fix", str(tmp_path / "t.stl"))
    assert p.returncode == 1  # the status is about the file as read
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


def _write(path: Path, vertices, faces) -> Path:
    mesh.write_mesh(path, vertices, faces)
    return path


@pytest.mark.parametrize(
    "name,edit,status",
    [
        ("clean.stl", lambda v, f: (v * 10, f), 0),  # a 20 mm cube: nothing wrong
        ("metres.obj", lambda v, f: (v * 0.025, f), 0),  # a units hint is no problem
        ("hole.ply", lambda v, f: (v * 10, f[:-2]), 1),
        ("inside_out.stl", lambda v, f: (v * 10, f[:, [0, 2, 1]]), 1),
        ("unused.obj", lambda v, f: (np.vstack([v, [[9, 9, 9]]]) * 10, f), 1),
    ],
)
def test_exit_status_is_0_clean_1_problem(tmp_path, name, edit, status):
    path = _write(tmp_path / name, *edit(*mesh.cube()))
    p = run("mesh", str(path))
    assert (p.returncode, p.stderr) == (status, "")
    verdict = " ".join(p.stdout.split("\nVerdict: ")[1].split())  # unwrapped
    assert verdict.endswith(": ready for a slicer.") == (status == 0)
    assert run("mesh", str(path), "--json").returncode == status


def test_unreadable_file_exits_2(tmp_path):
    path = tmp_path / "broken.obj"
    path.write_text("v 0 0 0\nf 1 2 3\n")
    p = run("mesh", str(path))
    assert (p.returncode, p.stdout) == (2, "")


def test_json_has_the_report_for_printing(tmp_path):
    v, f = mesh.cube()
    path = _write(tmp_path / "box.stl", v * 0.025, f[:-2])  # 5 cm wide in metres, one side open
    p = run("mesh", str(path), "--json")
    assert p.returncode == 1, p.stderr
    r = json.loads(p.stdout)["report"]
    assert list(r)[-5:] == ["holes", "surface_area", "volume", "size", "verdict"]
    assert r["holes"] == [4]
    assert r["surface_area"] == pytest.approx(5 * 0.05**2)
    assert r["volume"] is None  # open: no volume
    assert r["size"]["extent"] == pytest.approx([0.05, 0.05, 0.05])
    assert r["size"]["units_hint"] == "metres"
    assert r["verdict"] == (
        "not watertight, 1 piece, wound outward: not ready for a slicer (1 hole)"
    )
    text = " ".join(run("mesh", str(path)).stdout.split())  # unwrapped
    assert "1 hole: 4 edges around it." in text
    assert "Size: 0.05 × 0.05 × 0.05 (x, y, z)" in text
    assert "is under 1 mm: the model is probably in metres" in text


def test_the_readmes_check_a_mesh_session_is_the_commands_output(tmp_path):
    """The README's console block, run as written (in a scratch folder, for fixed.obj)."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme.split("## Check a mesh", 1)[1]
    block = section.split("```console\n", 1)[1].split("```", 1)[0]
    command, *shown = block.rstrip("\n").split("\n")
    assert command.startswith("$ trinormal mesh ")
    args = command.removeprefix("$ trinormal ").split()
    args = [str(ROOT / a) if a.startswith("trinormal/") else a for a in args]
    p = subprocess.run(
        [sys.executable, "-m", "trinormal", *args],
        capture_output=True, text=True, timeout=120, cwd=tmp_path, env={**os.environ, "COLUMNS": "88"},
    )  # fmt: skip
    status = shown[-2:]
    assert status == ["$ echo $?", str(p.returncode)]
    assert p.stdout.replace(str(ROOT) + "/", "").splitlines() == shown[:-2]
