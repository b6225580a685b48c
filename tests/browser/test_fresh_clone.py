"""From a fresh copy of the repository: `uv run jupyter lab notebooks` and `make lab`.

The copy (checkout_support.fresh_clone) holds the files git knows, in a temporary folder, with
no .venv. uv's cache makes the installs quick and offline.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
import urllib.request
from pathlib import Path

import pytest
from checkout_support import clean_env, fresh_clone
from install_support import base_python, uv
from jupyterlab_support import free_port

#: The test, site and benchmark tools: the lab's environment has none of them.
TOOLS = {"pytest", "playwright", "mkdocs", "mkdocs-material", "trimesh", "scipy", "mypy", "ruff"}


@pytest.fixture(scope="module")
def clone(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return fresh_clone(tmp_path_factory.mktemp("clone") / "trinormal")


def installed(venv: Path) -> set[str]:
    site = next(venv.glob("lib/python3*/site-packages"))
    return {p.name.split("-")[0].lower().replace("_", "-") for p in site.glob("*.dist-info")}


def test_uv_run_then_make_lab_from_a_fresh_clone(clone: Path) -> None:
    # 1. uv run: the lab's packages only
    done = subprocess.run(
        [uv(), "run", "--locked", "--python", base_python(), "jupyter", "lab", "--version"],
        cwd=clone, env=clean_env(), capture_output=True, text=True,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    packages = installed(clone / ".venv")
    assert {"trinormal", "jupyterlab", "notebook", "anywidget", "ipykernel"} <= packages
    assert not TOOLS & packages, TOOLS & packages
    cfg = (clone / ".venv" / "pyvenv.cfg").stat()

    # 2. make lab: the environment uv made is already right, so it is kept, then JupyterLab serves
    port = free_port()
    log = clone.parent / "make-lab.log"
    with log.open("w") as out:
        proc = subprocess.Popen(
            ["make", "lab", f"LAB_ARGS=--no-browser --port={port} --ServerApp.ip=127.0.0.1 "
             "--ServerApp.token= --ServerApp.port_retries=0"],
            cwd=clone, env=clean_env(), stdout=out, stderr=subprocess.STDOUT, start_new_session=True,
        )  # fmt: skip
    try:
        deadline = time.monotonic() + 120
        status = None
        while status != 200:
            assert proc.poll() is None, log.read_text()[-3000:]
            assert time.monotonic() < deadline, log.read_text()[-3000:]
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/status", timeout=2) as r:
                    status = r.status
            except OSError:
                time.sleep(0.5)
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/contents", timeout=10) as r:
            listing = r.read().decode()
        assert "01_worked_example.ipynb" in listing
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(timeout=30)
    text = log.read_text()
    assert ".venv is up to date" in text, text[-3000:]
    assert "Removed virtual environment" not in text and "Creating virtual environment" not in text
    after = (clone / ".venv" / "pyvenv.cfg").stat()
    assert (after.st_ino, after.st_mtime_ns) == (cfg.st_ino, cfg.st_mtime_ns)
    assert not TOOLS & installed(clone / ".venv")
    # make lab's environment gives Notebook 7 too (the README says the explorer works there)
    notebook = subprocess.run(
        [str(clone / ".venv" / "bin" / "jupyter"), "notebook", "--version"],
        cwd=clone, env=clean_env(), capture_output=True, text=True,
    )  # fmt: skip
    assert notebook.returncode == 0 and notebook.stdout.startswith("7."), notebook
