"""What the lab group installs, read from uv.lock by uv: the lab, and no development tools.

It runs uv, so it is in the browser stage, where a full checkout and uv are at hand.
"""

from __future__ import annotations

import subprocess

from browser_support import ROOT
from install_support import uv


def test_the_lab_group_installs_the_lab_and_no_development_tools() -> None:
    # what `uv run jupyter lab notebooks` (the default group) and `make lab` install
    def exported(*groups: str) -> set[str]:
        out = subprocess.run(
            [uv(), "export", "--frozen", "--no-hashes", "--no-header", "--no-annotate",
             "--format", "requirements-txt", "--no-emit-project", *groups],
            cwd=ROOT, capture_output=True, text=True, check=True,
        ).stdout  # fmt: skip
        return {line.split("==")[0].lower() for line in out.splitlines() if "==" in line}

    default = exported()
    assert default == exported("--no-default-groups", "--group", "lab")
    assert {"jupyterlab", "notebook", "ipykernel", "anywidget", "ipywidgets", "numpy"} <= default
    tools = {
        "pytest",
        "playwright",
        "mkdocs",
        "mkdocs-material",
        "trimesh",
        "scipy",
        "mypy",
        "ruff",
    }
    assert not tools & default
    assert tools <= exported("--all-groups")
