"""ARCHITECTURE.md stays one page, and every file it names exists.

A name in backticks is a path when it holds a ``/`` or ends in a source suffix. A path with a
``/`` is read from the repository's root (``*`` may stand for part of a name); a bare file name
must be the name of a file somewhere in the repository. A file the site build makes is not in
the repository: it may be named only if the module that writes it says its name.
"""

from __future__ import annotations

import os
import re
from fnmatch import fnmatch
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "ARCHITECTURE.md"
MAX_WORDS = 1200
SUFFIXES = (".py", ".js", ".md", ".mjs", ".ipynb")
#: Files the site build writes (not in the repository), with the module that writes each.
BUILT = {"trinormal-constants.js": "docs/hooks/site_constants.py"}
#: Folders that hold what tools made (environments, caches, the built site, npm packages).
NOT_SOURCES = {"node_modules", "site", "dist", "build", "__pycache__"}


def named_paths(text: str) -> list[str]:
    """The names in backticks that are paths."""
    spans = re.findall(r"`([^`\n]+)`", text)
    return [s for s in spans if "/" in s or s.endswith(SUFFIXES)]


def file_names(root: Path) -> set[str]:
    """The name of every file under ``root``, outside hidden folders and tools' output."""
    names: set[str] = set()
    for _folder, folders, files in os.walk(root):
        folders[:] = [f for f in folders if not f.startswith(".") and f not in NOT_SOURCES]
        names.update(files)
    return names


def missing(text: str, root: Path, names: set[str]) -> list[str]:
    """The paths ``text`` names that ``root`` does not hold (nor the build writes)."""
    gone = []
    for path in named_paths(text):
        if "/" in path:
            found = any(root.glob(path)) if "*" in path else (root / path).exists()
        else:
            found = path in BUILT or any(fnmatch(name, path) for name in names)
        if not found:
            gone.append(path)
    return gone


def test_the_page_is_at_most_1200_words():
    words = len(PAGE.read_text(encoding="utf-8").split())
    assert words <= MAX_WORDS, f"ARCHITECTURE.md has {words} words; at most {MAX_WORDS}"


def test_every_path_the_page_names_exists():
    text = PAGE.read_text(encoding="utf-8")
    assert len(named_paths(text)) >= 20  # the page names its files in backticks
    assert missing(text, ROOT, file_names(ROOT)) == []


def test_a_built_file_is_named_by_the_module_that_writes_it():
    for name, writer in BUILT.items():
        assert name in (ROOT / writer).read_text(encoding="utf-8"), (name, writer)


def test_a_missing_path_is_caught(tmp_path):
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "core.py").write_text("", encoding="utf-8")
    (tmp_path / "pkg" / "mesh-read.js").write_text("", encoding="utf-8")
    text = (
        "`pkg/core.py`, `core.py`, `pkg/` and `mesh-*.js` exist; `pkg/gone.py`, `gone.md`, "
        "`pkg/nothing-*.js` and `other/` do not; `trinormal A B C` is no path."
    )
    names = file_names(tmp_path)
    assert missing(text, tmp_path, names) == [
        "pkg/gone.py",
        "gone.md",
        "pkg/nothing-*.js",
        "other/",
    ]
