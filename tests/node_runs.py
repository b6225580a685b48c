"""Node, for the tests that run the site's and the views' JavaScript beside the Python it ports."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path


def node_path() -> str:
    """The path of ``node``; a failed test that says how to get it when it is missing."""
    path = shutil.which("node")
    assert path, "`node` is not on PATH: install Node.js to test the JavaScript"
    return path


def assert_port_agrees(
    checker: Path, folder: Path, constants: Path, files: int, timeout: int
) -> None:
    """Run a parity checker (``node CHECKER FOLDER CONSTANTS``) over a corpus of ``files`` files.

    It prints ``{"checked": n, "mismatches": [...]}``: every file checked, none different.
    """
    run = subprocess.run(
        [node_path(), str(checker), str(folder), str(constants)],
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    assert run.stdout, run.stderr
    result = json.loads(run.stdout)
    assert result["checked"] == files
    assert result["mismatches"] == []
    assert run.returncode == 0, run.stderr
