"""A fresh copy of the repository, as ``git clone`` of this work tree would give it.

The copy holds the files git knows (committed or not yet committed, none it ignores), links
kept as links, in a folder of the caller's, with no .venv, no .tools and no build output.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

from browser_support import ROOT


def fresh_clone(dest: Path) -> Path:
    """Copy the files git knows from this checkout to ``dest``; return ``dest``."""
    files = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=ROOT, capture_output=True, check=True,
    ).stdout.decode().split("\0")  # fmt: skip
    for name in filter(None, files):
        source = ROOT / name
        if source.is_symlink():
            (dest / name).parent.mkdir(parents=True, exist_ok=True)
            (dest / name).symlink_to(os.readlink(source))
        elif source.is_file():
            (dest / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, dest / name)
    return dest


def clean_env() -> dict[str, str]:
    """This process's environment without what ties uv or make to this checkout's venv."""
    out = {**os.environ, "UV_PYTHON_DOWNLOADS": "never"}
    for name in ("VIRTUAL_ENV", "UV_PROJECT_ENVIRONMENT", "MAKEFLAGS", "MAKELEVEL", "MFLAGS"):
        out.pop(name, None)
    return out
