"""The wheel is all a school's JupyterHub needs: installed fresh, outside the repository.

The session fixtures (conftest.py) build the wheel once, install ``wheel[notebooks]``
into a fresh venv in a temporary folder, and start the run's one JupyterLab server
from that venv. Here: the wheel carries the licences, the explorer's bundle, the
notebooks and the typing marker (and so does the wheel ``uv build`` makes from the sdist of
a fresh clone, as ``python -m build`` does); ``trinormal-notebooks`` copies the notebooks out, and
nbval runs them there, in a kernel of that venv, against the outputs stored in them (this
is the run's one nbval check of the notebooks: ``make test`` does not run them a second
time in the development environment); a core-only install runs the CLI and names the
extra to install for the rest. The explorer rendering from that install in JupyterLab and in
Notebook 7 is tested in test_wheel_lab.py.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tarfile
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path
from typing import Any

from browser_support import ROOT
from checkout_support import clean_env, fresh_clone
from install_support import install, uv

NOTEBOOKS = sorted(p.name for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))

#: How nbval cleans outputs before comparing them (the Makefile's ``nbval`` target uses it too).
SANITIZE = ROOT / "tests" / "nbval_sanitize.cfg"


def kernel_of(python: Path, where: Path) -> dict[str, str]:
    """A Jupyter kernel spec that runs ``python``'s ipykernel; the environment that finds it."""
    spec = where / "kernels" / "trinormal-wheel"
    spec.mkdir(parents=True)
    argv = [str(python), "-m", "ipykernel_launcher", "-f", "{connection_file}"]
    kernel = {"argv": argv, "display_name": "trinormal from the wheel", "language": "python"}
    (spec / "kernel.json").write_text(json.dumps(kernel), encoding="utf-8")
    return {**os.environ, "JUPYTER_PATH": str(where)}


def run(args: list[Any], cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in args], cwd=cwd, capture_output=True, text=True)


def check_contents(wheel: Path) -> None:
    """The wheel carries the licences, the explorer's bundle, every notebook and py.typed."""
    names = set(zipfile.ZipFile(wheel).namelist())
    info = next(n.split("/")[0] for n in names if n.endswith(".dist-info/METADATA"))
    assert f"{info}/licenses/LICENSE" in names
    assert f"{info}/licenses/trinormal/explorer/static/THIRD_PARTY_LICENSES.txt" in names
    for name in ("explorer.js", "THIRD_PARTY_LICENSES.txt"):
        assert f"trinormal/explorer/static/{name}" in names
    assert "trinormal/py.typed" in names
    assert sorted(n.split("/")[-1] for n in names if n.startswith("trinormal/_notebooks/")) == (
        NOTEBOOKS
    )
    assert not [n for n in names if "checkpoint" in n or n.startswith(("tests/", "docs/"))]
    with zipfile.ZipFile(wheel) as z:
        metadata = z.read(f"{info}/METADATA").decode()
        scripts = z.read(f"{info}/entry_points.txt").decode()
        bundle = z.read("trinormal/explorer/static/explorer.js")
    assert "License-Expression: MIT" in metadata
    assert "Provides-Extra: notebooks" in metadata
    assert "trinormal-notebooks = trinormal.notebooks:main" in scripts
    assert bundle == (ROOT / "trinormal" / "explorer" / "static" / "explorer.js").read_bytes()


def test_the_wheel_carries_licences_bundle_notebooks_and_types(wheel: Path) -> None:
    check_contents(wheel)


def test_uv_build_makes_the_wheel_from_the_sdist_of_a_fresh_clone(tmp_path: Path) -> None:
    """`uv build` (as `python -m build`) makes the sdist, then the wheel from the sdist alone."""
    clone = fresh_clone(tmp_path / "trinormal")
    out = tmp_path / "dist"
    done = subprocess.run(
        [uv(), "build", "--out-dir", str(out), str(clone)],
        cwd=tmp_path, env=clean_env(), capture_output=True, text=True,
    )  # fmt: skip
    assert done.returncode == 0, done.stdout + done.stderr[-3000:]
    assert "Building wheel from source distribution" in done.stdout + done.stderr
    (sdist,) = out.glob("trinormal-*.tar.gz")
    (wheel,) = out.glob("trinormal-*.whl")
    with tarfile.open(sdist) as tar:
        names = tar.getnames()
    top = names[0].split("/")[0]
    notebooks = [n.split("/")[-1] for n in names if n.startswith(f"{top}/notebooks/")]
    assert sorted(n for n in notebooks if n.endswith(".ipynb")) == NOTEBOOKS
    check_contents(wheel)


def test_copied_notebooks_execute_in_the_installed_package(wheel_env: Path, tmp_path: Path) -> None:
    bin_dir = wheel_env.parent
    dest = tmp_path / "class"
    done = run([bin_dir / "trinormal-notebooks", dest], cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout == f"Copied 11 notebooks into {dest}\n"
    assert sorted(p.name for p in dest.glob("*.ipynb")) == NOTEBOOKS
    # the kernel imports the installed package, not this checkout
    where = run([wheel_env, "-c", "import trinormal; print(trinormal.__file__)"], cwd=dest)
    assert Path(where.stdout.strip()).is_relative_to(bin_dir.parent), where
    # nbval (this environment's) checks every copied notebook's outputs, run in the installed
    # package's kernel from a clean start, in the folder they were copied to
    env = kernel_of(wheel_env, tmp_path / "jupyter")
    junit = tmp_path / "nbval.xml"
    done = subprocess.run(
        [
            sys.executable, "-m", "pytest", "--nbval", "--nbval-kernel-name", "trinormal-wheel",
            "--nbval-sanitize-with", str(SANITIZE), "-p", "no:cacheprovider", "-q",
            f"--junit-xml={junit}", str(dest),
        ],
        cwd=dest, env=env, capture_output=True, text=True,
    )  # fmt: skip
    assert done.returncode == 0, done.stdout[-6000:] + done.stderr[-3000:]
    cases = ET.parse(junit).getroot().iter("testcase")
    checked = {Path(c.get("file") or c.get("classname", "")).name for c in cases}
    assert {n for n in checked if n.endswith(".ipynb")} == set(NOTEBOOKS), checked


def test_python_m_form_copies_too(wheel_env: Path, tmp_path: Path) -> None:
    done = run([wheel_env, "-m", "trinormal.notebooks", "out"], cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in (tmp_path / "out").glob("*.ipynb")) == NOTEBOOKS


def test_a_core_only_install_runs_the_cli_and_names_the_extra(wheel: Path, tmp_path: Path) -> None:
    python = install(tmp_path / "core", wheel)
    bin_dir = python.parent
    done = run([bin_dir / "trinormal", "0,0,0", "1,0,0", "0,1,0", "--json"], cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["normal"] == [0.0, 0.0, 1.0]
    done = run([python, "-c", "import trinormal.explorer"], cwd=tmp_path)
    assert done.returncode == 1
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ModuleNotFoundError: trinormal.explorer needs "), last
    assert last.endswith('pip install "trinormal[notebooks]"'), last
    # the notebooks can be handed out before their libraries are installed
    done = run([bin_dir / "trinormal-notebooks", "out"], cwd=tmp_path)
    assert done.returncode == 0, done.stderr
