"""Packaging from the inside: missing extras named, the notebooks command, LICENSE, py.typed.

The wheel itself (built, installed into a fresh venv, its notebooks copied out and
executed, the explorer rendered from it in JupyterLab and Notebook 7) is tested in
tests/browser/test_wheel.py, with the slow tests; what the lab group installs (uv's export
of the lockfile) in tests/browser/test_dependency_groups.py, and the wheel built from the sdist
in tests/browser/test_sdist.py.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from trinormal import notebooks

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted(p.name for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
INSTALL = 'pip install "trinormal[notebooks]"'


@pytest.mark.parametrize(
    ("module", "dependency", "named"),
    [
        ("trinormal.explorer", "anywidget", "trinormal.explorer"),
        ("trinormal.explorer", "ipywidgets", "trinormal.explorer"),
        ("trinormal.explorer", "matplotlib", "trinormal.explorer"),
        ("trinormal.widgets", "anywidget", "trinormal.explorer"),
        ("trinormal.mesh", "numpy", "trinormal.mesh"),
        ("trinormal.symbolic", "sympy", "trinormal.symbolic"),
        ("trinormal.plotting", "matplotlib", "trinormal.plotting"),
    ],
)
def test_a_missing_optional_dependency_names_the_extra(
    module: str, dependency: str, named: str
) -> None:
    # a fresh interpreter in which the dependency cannot be imported (None in sys.modules)
    code = (
        f"import sys; sys.modules[{dependency!r}] = None\n"
        f"try:\n    import {module}\n"
        "except ImportError as exc:\n    print(type(exc).__name__, exc.name, '|', exc)\n"
        "else:\n    print('imported')\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.strip()
    kind, name, _, message = out.split(" ", 3)
    assert kind == "ModuleNotFoundError" and name == dependency, out
    assert message.startswith(f"{named} needs {dependency}, which is not installed"), out
    assert INSTALL in message, out


def test_the_core_imports_without_any_optional_dependency() -> None:
    blocked = ["numpy", "sympy", "matplotlib", "ipywidgets", "anywidget", "traitlets"]
    code = (
        f"import sys\nfor m in {blocked!r}: sys.modules[m] = None\n"
        "import trinormal, trinormal.cli, trinormal.notebooks\n"
        "print(trinormal.triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).normal)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "(0.0, 0.0, 1.0)"


def test_every_optional_dependency_is_in_the_notebooks_extra() -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    extra = {r.split(">")[0].split("<")[0].split("=")[0] for r in project["optional-dependencies"]["notebooks"]}  # fmt: skip
    assert {"numpy", "sympy", "matplotlib", "ipywidgets", "anywidget"} <= extra
    # and what `jupyter lab` needs to open the notebooks and show the explorer
    assert {"jupyterlab", "notebook", "ipykernel"} <= extra
    assert project["dependencies"] == []  # the core: standard library only


def test_licence_and_typing_marker_are_in_place() -> None:
    text = (ROOT / "LICENSE").read_text()
    assert text.startswith("MIT License")
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["license"] == "MIT"
    assert "LICENSE" in project["license-files"]
    assert (ROOT / "trinormal" / "py.typed").is_file()


# --------------------------------------------------------------------------- trinormal-notebooks


def test_the_command_copies_every_notebook(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    dest = tmp_path / "class" / "week1"
    assert notebooks.main([str(dest)]) == 0
    assert sorted(p.name for p in dest.glob("*.ipynb")) == NOTEBOOKS
    assert len(NOTEBOOKS) == 11
    for name in NOTEBOOKS:
        assert (dest / name).read_bytes() == (ROOT / "notebooks" / name).read_bytes()
        json.loads((dest / name).read_text(encoding="utf-8"))
    assert capsys.readouterr().out == f"Copied 11 notebooks into {dest.resolve()}\n"


def test_the_command_never_overwrites_without_force(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert notebooks.main([str(tmp_path)]) == 0
    mine = tmp_path / NOTEBOOKS[0]
    mine.write_text("a student's work")
    capsys.readouterr()
    assert notebooks.main([str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith("trinormal-notebooks: ") and "--force" in err
    assert mine.read_text() == "a student's work"
    assert notebooks.main([str(tmp_path), "--force"]) == 0
    assert mine.read_bytes() == (ROOT / "notebooks" / NOTEBOOKS[0]).read_bytes()


@pytest.mark.parametrize("argv", [[], ["a", "b"], ["--bogus", "x"]])
def test_bad_arguments_exit_2_with_one_line(argv: list[str]) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "trinormal.notebooks", *argv], capture_output=True, text=True
    )
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and done.stderr.startswith("trinormal-notebooks: ")


def test_a_file_in_the_way_is_one_line_not_a_traceback(tmp_path: Path) -> None:
    target = tmp_path / "notes.txt"
    target.write_text("x")
    done = subprocess.run(
        [sys.executable, "-m", "trinormal.notebooks", str(target)], capture_output=True, text=True
    )
    assert done.returncode == 2
    assert done.stderr == f"trinormal-notebooks: {target} is a file, not a folder\n"


def test_data_files_beside_the_notebooks_travel_too(tmp_path: Path) -> None:
    source = tmp_path / "source"
    (source / "data").mkdir(parents=True)
    (source / "01_a.ipynb").write_text("{}")
    (source / "data" / "mesh.obj").write_text("v 0 0 0\n")
    (source / ".ipynb_checkpoints").mkdir()
    (source / ".ipynb_checkpoints" / "01_a-checkpoint.ipynb").write_text("{}")
    files = notebooks.notebook_files(source)
    assert [p.as_posix() for p in files] == ["01_a.ipynb", "data/mesh.obj"]
