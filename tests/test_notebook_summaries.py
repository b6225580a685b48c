"""The site's list of notebooks summarises each by what the reader will do in it."""

from __future__ import annotations

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs" / "hooks"))

from notebook_pages import WHAT_YOU_DO, notebook_paths, notebook_summary  # noqa: E402


def test_each_notebook_is_summarised_by_its_what_you_will_do_paragraph() -> None:
    for path in notebook_paths():
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        opening = "".join(cells[0]["source"]).split("\n\n")
        said = next(p for p in opening if p.startswith(WHAT_YOU_DO))
        said = " ".join(said.removeprefix(WHAT_YOU_DO).split())
        summary = notebook_summary(path)
        assert summary[0].isupper(), (path.name, summary)
        assert summary.removesuffix(" …")[1:] in said, (path.name, summary)
