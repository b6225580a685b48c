"""The API reference as a reader wants it, and the guide first in the site's search.

One page per public module of the package, each opening with its public names (a summary
table) and listing nothing else: only the names in the module's ``__all__``, no internals.
In the site's search, the guide's pages rank above the API's docstrings for the guide's own
words (the guide's pages carry ``search: boost: 10``, the API's ``0.001``: an API heading such as
"Winding" is a title match, which Material's search weighs 1000 times a match in the text).
"""

from __future__ import annotations

import html as html_lib
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


def _module_pages(site_dir: Path, module: str) -> dict[str, str]:
    """A module's API pages: ``api/MODULE/`` and, for a module split by topic, its sub-pages."""
    folder = site_dir / "api" / module
    pages = [folder / "index.html", *sorted(folder.glob("*/index.html"))]
    return {p.parent.relative_to(site_dir).as_posix(): p.read_text(encoding="utf-8") for p in pages}


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
    public = set(importlib.import_module(f"trinormal.{module}").__all__)
    everywhere: set[str] = set()
    for rel, html in _module_pages(site_dir, module).items():
        documented = _documented(html, module)
        everywhere |= documented
        assert documented <= public, (rel, documented - public)
        text = _article_text(html)
        assert [w for w in INTERNALS if w in text] == [], rel
        if not documented:
            continue
        # public names first: each is linked from a summary above the first documented object
        first = min(html.index(f'id="trinormal.{module}.{name}"') for name in documented)
        summary = html[:first]
        assert [n for n in documented if f'#trinormal.{module}.{n}"' not in summary] == [], rel
    assert everywhere, module


def test_every_public_function_and_class_is_documented(site_dir: Path) -> None:
    undocumented = {}
    for module in MODULES:
        mod = importlib.import_module(f"trinormal.{module}")
        documented: set[str] = set()
        for html in _module_pages(site_dir, module).values():
            documented |= _documented(html, module)
        wanted = {n for n in mod.__all__ if callable(getattr(mod, n)) and getattr(mod, n).__doc__}
        lost = wanted - documented
        if lost:
            undocumented[module] = sorted(lost)
    assert undocumented == {}


def test_a_name_split_by_topic_is_on_one_page_only(site_dir: Path) -> None:
    pages = _module_pages(site_dir, "mesh")
    assert len(pages) >= 4, pages.keys()
    where: dict[str, list[str]] = {}
    for rel, html in pages.items():
        for name in _documented(html, "mesh"):
            where.setdefault(name, []).append(rel)
    assert {n: r for n, r in where.items() if len(r) != 1} == {}
    assert set(where) == set(importlib.import_module("trinormal.mesh").__all__)


def test_the_search_index_weights_the_guide_above_the_api(site_dir: Path) -> None:
    docs = json.loads((site_dir / "search" / "search_index.json").read_text(encoding="utf-8"))
    boost = {d["location"]: d.get("boost", 1) for d in docs["docs"] if "#" not in d["location"]}
    guide = {k: v for k, v in boost.items() if k.startswith("guide/")}
    api = {k: v for k, v in boost.items() if k.startswith("api/")}
    assert len(guide) >= 6 and len(api) == len(_api_pages(site_dir))
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


# ----------------------------------------------------------------------------- public names only

#: A private name in text: ``_x`` or ``a._x`` (not a path such as ``trinormal/_notebooks``, not
#: a dunder such as ``__init__``).
PRIVATE = re.compile(r"(?<![\w/])(?:\w+\.)*_(?!_)[A-Za-z]\w*")


def _api_pages(site_dir: Path) -> list[str]:
    return sorted(
        p.parent.relative_to(site_dir).as_posix() + "/"
        for p in (site_dir / "api").rglob("index.html")
    )


def _public_names() -> set[str]:
    """Every public name of the package, as a docstring may write it.

    ``name``, ``module.name`` and ``trinormal.module.name`` for each name in a public module's
    ``__all__``; ``Class.member`` for each public member of a public class; the modules.
    """
    names = set()
    for module in MODULES:
        mod = importlib.import_module(f"trinormal.{module}")
        names |= {module, f"trinormal.{module}"}
        for name in mod.__all__:
            names |= {name, f"{module}.{name}", f"trinormal.{module}.{name}"}
            obj = getattr(mod, name)
            if isinstance(obj, type):
                names |= {f"{name}.{m}" for m in vars(obj) if not m.startswith("_")}
    return names


def _prose(html: str) -> str:
    """The article without its code blocks, links and headings: the text a mention sits in."""
    article = html[html.index("<article") : html.index("</article>")]
    return re.sub(r"<(pre|a|h[1-6])\b[^>]*>.*?</\1>", "", article, flags=re.S)


def test_no_api_page_shows_a_private_name(site_dir: Path) -> None:
    # signatures (defaults), attribute values and docstrings: the whole text of each page
    found = {}
    for rel in _api_pages(site_dir):
        text = html_lib.unescape(_article_text((site_dir / rel / "index.html").read_text()))
        private = sorted(set(PRIVATE.findall(text)))
        if private:
            found[rel] = private
    assert found == {}
    # a private default is shown as Python shows it (its repr), not by its name
    exercises = (site_dir / "api" / "exercises" / "index.html").read_text(encoding="utf-8")
    assert "<code>&lt;missing&gt;</code>" in exercises


def test_every_mention_of_a_public_name_is_a_link(site_dir: Path) -> None:
    public = _public_names()
    assert {"triangle_normal", "TriangleNormal.format", "trinormal.mesh.check"} <= public
    unlinked, linked = {}, 0
    for rel in _api_pages(site_dir):
        html = (site_dir / rel / "index.html").read_text(encoding="utf-8")
        article = html[html.index("<article") : html.index("</article>")]
        linked += len(re.findall(r'<a class="autorefs autorefs-internal"[^>]*><code>', article))
        for code in re.findall(r"<code>([^<>]+)</code>", _prose(html)):
            name = re.match(r"[A-Za-z_][\w.]*", code.strip())
            rest = code.strip()[name.end() :] if name else ""
            if name and name.group() in public and (not rest or rest[0] in "(["):
                unlinked.setdefault(rel, []).append(code)
    assert unlinked == {}
    assert linked >= 100, linked


def test_a_mention_links_to_the_name_s_own_entry(site_dir: Path) -> None:
    fields = (site_dir / "api" / "fields" / "index.html").read_text(encoding="utf-8")
    # the module docstring of trinormal.fields names FIELDS in plain code
    hrefs = re.findall(
        r'<a class="autorefs autorefs-internal"[^>]*href="([^"]+)"[^>]*><code>FIELDS<', fields
    )
    assert hrefs and all(h.endswith("#trinormal.fields.FIELDS") for h in hrefs), hrefs
