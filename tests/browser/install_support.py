"""The package as a teacher installs it: a wheel built from this tree, in a fresh venv.

The wheel is built with ``uv build`` and installed with ``uv pip`` into a venv outside the
repository, with the versions pinned by ``uv.lock`` (exported as constraints), so the run
needs no network when uv's cache holds them. ``shared`` lets pytest-xdist workers build
one wheel and one venv per run: the first worker builds under a file lock, the others
wait and reuse it.
"""

from __future__ import annotations

import fcntl
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def uv() -> str:
    """The uv the Makefile uses: on PATH, or the one it bootstrapped into .tools/."""
    return shutil.which("uv") or str(ROOT / ".tools" / "bin" / "uv")


def base_python() -> str:
    """The interpreter the test environment was made from (a fresh venv starts from it)."""
    return os.path.realpath(getattr(sys, "_base_executable", sys.executable))


def _run(args: list[str], cwd: Path = ROOT) -> str:
    env = {**os.environ, "UV_PYTHON_DOWNLOADS": "never", "UV_COMPILE_BYTECODE": "0"}
    env.pop("VIRTUAL_ENV", None)
    done = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed:\n{done.stdout}\n{done.stderr}")
    return done.stdout + done.stderr


def build_wheel(out: Path) -> Path:
    """Build the wheel from this tree into ``out``; return its path."""
    _run([uv(), "build", "--wheel", "--out-dir", str(out), str(ROOT)])
    (wheel,) = out.glob("trinormal-*.whl")
    return wheel


def venv_python(venv: Path) -> Path:
    return venv / ("Scripts/python.exe" if os.name == "nt" else "bin/python")


def install(venv: Path, wheel: Path, extra: str | None = None) -> Path:
    """Make a fresh venv and install the wheel (with an extra) at uv.lock's versions.

    Returns the venv's Python.
    """
    _run([uv(), "venv", "--quiet", "--python", base_python(), str(venv)])
    python = venv_python(venv)
    requirement = f"{wheel}[{extra}]" if extra else str(wheel)
    args = [uv(), "pip", "install", "--quiet", "--python", str(python), requirement]
    if extra:
        constraints = venv.parent / f"constraints-{extra}.txt"
        _run([
            uv(), "export", "--frozen", "--no-hashes", "--no-emit-project", "--no-header",
            "--no-default-groups", "--extra", extra, "--format", "requirements-txt",
            "--output-file", str(constraints),
        ])  # fmt: skip
        args += ["--constraint", str(constraints)]
    _run(args, cwd=venv.parent)
    return python


def shared(folder: Path, name: str, make: Callable[[Path], Path]) -> Path:
    """Run ``make(folder / name)`` once for every worker of this run; return what it returned.

    ``folder`` is shared by the workers (pytest's base temporary folder for this run). The
    result's path is stored in ``folder / f"{name}.done"``.
    """
    folder.mkdir(parents=True, exist_ok=True)
    done = folder / f"{name}.done"
    with (folder / f"{name}.lock").open("w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if done.is_file():
            return Path(done.read_text(encoding="utf-8"))
        result = make(folder / name)
        done.write_text(str(result), encoding="utf-8")
        return result
