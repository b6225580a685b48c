"""`make env` and `make lab-env` on a throwaway project: nothing rebuilt, nothing removed.

The probe project has the repository's Makefile and scripts/ but no dependencies, so each
`make` takes a fraction of a second and the repository's own .venv is never touched. Its
interpreter is reached through a shim (a script that execs the real one), as pyenv's
``python3`` is: uv handed the shim's path removes and recreates .venv on every call.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: The uv the Makefile would use: on PATH, or the one it bootstrapped into .tools/.
UV = shutil.which("uv") or str(ROOT / ".tools" / "bin" / "uv")

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


def base_python() -> str:
    """The interpreter this environment was made from (not .venv's own link to it)."""
    return os.path.realpath(getattr(sys, "_base_executable", sys.executable))


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
        [UV, "lock", "--offline", "--python", base_python()],
        cwd=tmp_path, check=True, capture_output=True,
    )  # fmt: skip
    return tmp_path


def make(probe: Path, target: str) -> str:
    done = subprocess.run(
        ["make", "--no-print-directory", target, f"UV={UV}", "UV_DEP=",
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


def test_stage_times_are_recorded_and_reported_with_the_failures(tmp_path: Path) -> None:
    env = {**os.environ, "TRINORMAL_STAGE_TIMES": str(tmp_path / "times.tsv")}

    def stages(*args: str) -> subprocess.CompletedProcess[str]:
        script = ROOT / "scripts" / "stages.py"
        return subprocess.run(
            [sys.executable, str(script), *args], env=env, capture_output=True, text=True
        )

    assert stages("reset").returncode == 0
    assert stages("run", "unit", "--", sys.executable, "-c", "pass").returncode == 0
    sleeper = "import time, sys; time.sleep(0.3); sys.exit(3)"
    assert stages("run", "browser", "--", sys.executable, "-c", sleeper).returncode == 3
    lines = stages("report").stdout.strip().splitlines()
    assert lines[0] == "make test: time per stage"
    names = [line.split()[0] for line in lines[1:]]
    assert names == ["unit", "browser", "total"]
    browser = lines[2].split()
    assert float(browser[1]) >= 0.3 and browser[-1] == "FAILED"
    assert "FAILED" not in lines[1]
    assert stages("bogus").returncode == 2
