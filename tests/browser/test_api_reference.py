"""The API reference as a reader wants it, and the guide first in the site's search.

One page per public module of the package, each opening with its public names (a summary
table) and listing nothing else: only the names in the module's ``__all__``, no internals.
In the site's search, the guide's pages rank above the API's docstrings for the guide's own
words (the guide's pages carry ``search: boost: 10``, the API's ``0.001``: an API heading such as
"Winding" is a title match, which Material's search weighs 1000 times a match in the text).
"""

from __future__ import annotations

import importlib
import json
import re
from pathlib import Path
from typing import Any

import pytest
from browser_support import ROOT

#: The package's public modules: every module and subpackage not named with an underscore.
MODULES = sorted(
    [p.stem for p in (ROOT / "trinormal").glob("*.py") if not p.stem.startswith("_")]
    + [p.parent.name for p in (ROOT / "trinormal").glob("*/__init__.py")]
)
#: Words of the guide that the API's docstrings use too.
GUIDE_WORDS = ["winding", "degenerate", "collinear", "cross product", "unit normal"]
INTERNALS = ["fast path", "_result", "check_common", "quote_input", "_integers", "_fast_exact"]


def _documented(html: str, module: str) -> set[str]:
    """The top-level names a page documents (the anchors of its object headings)."""
    ids = re.findall(rf'id="trinormal\.{module}\.([A-Za-z_][A-Za-z0-9_]*)"', html)
    return set(ids)


def _article_text(html: str) -> str:
    article = html[html.index("<article") : html.index("</article>")]
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", article))


def test_one_page_per_public_module(site_dir: Path) -> None:
    assert len(MODULES) >= 15, MODULES
    missing = [m for m in MODULES if not (site_dir / "api" / m / "index.html").is_file()]
    assert missing == []
    index = (site_dir / "api" / "index.html").read_text(encoding="utf-8")
    for module in MODULES:
        assert f'href="{module}/"' in index, f"the API index does not link {module}"


@pytest.mark.parametrize("module", MODULES)
def test_a_module_page_lists_its_public_names_only(site_dir: Path, module: str) -> None:
    html = (site_dir / "api" / module / "index.html").read_text(encoding="utf-8")
    public = set(importlib.import_module(f"trinormal.{module}").__all__)
    documented = _documented(html, module)
    assert documented, module
    assert documented <= public, documented - public
    assert not any(name.startswith("_") for name in documented)
    text = _article_text(html)
    assert [w for w in INTERNALS if w in text] == []
    # public names first: the summary of them comes before the first documented object
    first = min(html.index(f'id="trinormal.{module}.{name}"') for name in documented)
    summary = re.search(r"(Classes|Functions|Attributes|Modules):", text)
    assert summary is not None, f"no summary of the public names on {module}"
    assert html.index(">" + summary.group(1) + ":") < first


def test_every_public_function_and_class_is_documented(site_dir: Path) -> None:
    undocumented = {}
    for module in MODULES:
        mod = importlib.import_module(f"trinormal.{module}")
        html = (site_dir / "api" / module / "index.html").read_text(encoding="utf-8")
        wanted = {n for n in mod.__all__ if callable(getattr(mod, n)) and getattr(mod, n).__doc__}
        lost = wanted - _documented(html, module)
        if lost:
            undocumented[module] = sorted(lost)
    assert undocumented == {}


def test_the_search_index_weights_the_guide_above_the_api(site_dir: Path) -> None:
    docs = json.loads((site_dir / "search" / "search_index.json").read_text(encoding="utf-8"))
    boost = {d["location"]: d.get("boost", 1) for d in docs["docs"] if "#" not in d["location"]}
    guide = {k: v for k, v in boost.items() if k.startswith("guide/")}
    api = {k: v for k, v in boost.items() if k.startswith("api/")}
    assert len(guide) >= 6 and len(api) == len(MODULES) + 1
    assert min(guide.values()) > max(api.values()), (guide, api)


@pytest.mark.parametrize("words", GUIDE_WORDS)
def test_searching_the_guide_s_words_lists_the_guide_first(
    page: Any, server: str, traffic: Any, words: str
) -> None:
    page.goto(server + "api/")
    page.wait_for_load_state("load")
    page.set_viewport_size({"width": 1280, "height": 800})
    box = page.locator("input.md-search__input")
    box.click()
    # typed as a person types; Material's search answers once its worker has the index
    box.press_sequentially(words, delay=30)
    results = page.locator(".md-search-result__item > a.md-search-result__link")
    results.first.wait_for(timeout=90_000)
    hrefs = results.evaluate_all("els => els.map(e => e.getAttribute('href'))")
    where = [h.split(server, 1)[-1].lstrip("./") for h in hrefs]
    kinds = [w.split("/")[0] for w in where if w.startswith(("guide/", "api/"))]
    # the guide is listed, and every guide page comes before every API page
    assert "guide" in kinds, where
    assert kinds == sorted(kinds, key=lambda k: k != "guide"), where
    assert not traffic.problems()
