"""`make env` and `make lab-env` on a throwaway project: nothing rebuilt, nothing removed.

The probe project has the repository's Makefile and scripts/ but no dependencies, so each
`make` takes a fraction of a second and the repository's own .venv is never touched. Its
interpreter is reached through a shim (a script that execs the real one), as pyenv's
``python3`` is: uv handed the shim's path removes and recreates .venv on every call.

These run uv (offline, from its cache), so they are in the browser stage with the other tests
that need a full checkout and uv.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from browser_support import ROOT
from install_support import base_python, uv

PYPROJECT = """\
[project]
name = "probe"
version = "0"
requires-python = ">=3.11"
dependencies = []

[dependency-groups]
lab = []

[tool.uv]
package = false
"""


@pytest.fixture
def probe(tmp_path: Path) -> Path:
    shutil.copy(ROOT / "Makefile", tmp_path / "Makefile")
    shutil.copytree(ROOT / "scripts", tmp_path / "scripts")
    (tmp_path / "pyproject.toml").write_text(PYPROJECT)
    shim = tmp_path / "shims" / "python3"
    shim.parent.mkdir()
    shim.write_text(f'#!/bin/sh\nexec "{base_python()}" "$@"\n')
    shim.chmod(0o755)
    subprocess.run(
        [uv(), "lock", "--offline", "--python", base_python()],
        cwd=tmp_path, check=True, capture_output=True,
    )  # fmt: skip
    return tmp_path


def make(probe: Path, target: str) -> str:
    done = subprocess.run(
        ["make", "--no-print-directory", target, f"UV={uv()}", "UV_DEP=",
         f"PYTHON={probe / 'shims' / 'python3'}"],
        cwd=probe, capture_output=True, text=True,
        env={**os.environ, "UV_OFFLINE": "1"},
    )  # fmt: skip
    out = done.stdout + done.stderr
    assert done.returncode == 0, out
    return out


def fake_package(venv: Path, name: str) -> Path:
    """Register a package in the venv by hand, as another target's install would."""
    site = next(venv.glob("lib/python3*/site-packages"))
    info = site / f"{name}-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 1.0\n")
    (info / "INSTALLER").write_text("uv\n")
    (info / "RECORD").write_text(f"{name}-1.0.dist-info/METADATA,,\n")
    return info


def test_a_second_make_env_through_a_shim_keeps_the_environment(probe: Path) -> None:
    first = make(probe, "env")
    assert "Creating virtual environment" in first
    cfg = probe / ".venv" / "pyvenv.cfg"
    before = cfg.stat()
    second = make(probe, "env")
    assert "Removed virtual environment" not in second
    assert "Creating virtual environment" not in second
    assert ".venv is up to date" in second
    after = cfg.stat()
    assert (after.st_ino, after.st_mtime_ns) == (before.st_ino, before.st_mtime_ns)


def test_make_lab_env_keeps_what_make_env_installed(probe: Path) -> None:
    make(probe, "env")
    extra = fake_package(probe / ".venv", "playwright_stand_in")
    out = make(probe, "lab-env")
    assert "Removed virtual environment" not in out
    assert extra.is_dir(), out
