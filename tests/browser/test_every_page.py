"""Every page of the built site, visited once, with every per-page check made in that visit.

Each page is one test (parametrized from the site's sources, so the two browser workers share
the pages); ``test_the_pages_tested_are_the_pages_built`` holds that list to the build. A
phone (360x740) opens the page, which is then widened to a tablet's (768x1024) and a desktop's
(1280x800) width:

* the page loads without a failed request, an HTTP error, a console or page error, or a
  request to another origin;
* the layout reads well at each width, in both palettes: no sideways scrolling of the page;
  every display equation visible and fitting or scrolling inside its own box; tables and
  notebook outputs scrolling inside their own box, which the keyboard can reach; no number of
  a notebook's text output broken across two lines (``page_checks.LAYOUT_PROBLEMS``);
* axe-core finds nothing serious: on the phone in the dark palette, every rule of a default
  run; on the desktop in the light palette, the rules that read colours
  (``page_checks.AXE_COLOUR_RULES``: contrast, and links told apart from their text). A
  palette changes only colours, so the other rules run once, where the page shows axe the
  most: on the phone, with its boxes that scroll sideways and its navigation drawer that
  holds the table of contents;
* the math engine (KaTeX) loads only where there is math, and has typeset it by then;
  MathJax never loads;
* a notebook's page, on the desktop: a download link to the very notebook, a link to the
  instructions for running it, its navigation entry, its math typeset, its widget outputs
  replaced by a note (and a picture) and every figure with a text alternative.
"""

from __future__ import annotations

import functools
import json
import re
import urllib.request
from pathlib import Path
from typing import Any

import pytest
from browser_support import ROOT, Traffic, site_pages, source_pages
from page_checks import (
    MATH_ENGINES,
    VIEWPORTS,
    assert_math_typeset,
    axe_serious,
    changes_page_for_axe,
    has_math_markup,
    layout_problems,
    open_for_axe,
    prepare_for_axe,
    resize,
    set_scheme,
    settle,
    size,
)

PAGES = source_pages()
#: The tallest an API page may be at 1280 px wide, in CSS pixels: a reader finds a name by
#: scrolling, so a module with many names is split over several pages (api/mesh/).
API_MAX_HEIGHT = 30_000
NOTEBOOKS = {f"notebooks/{p.stem}/": p for p in sorted((ROOT / "notebooks").glob("*.ipynb"))}
#: Pages whose math (or lack of it) the math-engine check must see as such.
MATH_EXPECTED = {"guide/method/": True, "": False, "calculator/": False}


def _page_id(path: str) -> str:
    return path.rstrip("/") or "home"


def test_the_pages_tested_are_the_pages_built(site_dir: Path) -> None:
    assert sorted(site_pages(site_dir)) == PAGES
    assert len(PAGES) >= 12, PAGES
    assert set(NOTEBOOKS) <= set(PAGES) and NOTEBOOKS, "notebooks/ holds no notebook"
    assert set(MATH_EXPECTED) <= set(PAGES)
    assert _notebooks_with_math(), "no notebook has math (Markdown TeX or a text/latex output)"
    assert not (site_dir / "assets" / "vendor" / "mathjax").exists(), "the MathJax bundle is back"


def _loads_cleanly(page: Any, url: str, traffic: Traffic, where: str) -> None:
    response = page.goto(url)
    assert response is not None and response.ok, f"{where}: {response and response.status}"
    settle(page)
    assert not traffic.problems(), json.dumps({where: traffic.problems()}, indent=1)
    assert not traffic.off_origin
    assert len(traffic.requests) > 1, f"{where}: no stylesheet, script or image was requested"


def test_the_404_page_loads_without_errors_or_foreign_requests(page, server, traffic):
    _loads_cleanly(page, server + "404.html", traffic, "404.html")


@pytest.mark.parametrize("path", PAGES, ids=_page_id)
def test_every_page_at_every_width_in_both_palettes(page, server, traffic, path):
    where = path or "home"
    problems: dict[str, list[str]] = {}

    # a phone opens the page: it loads cleanly, its math is typeset, its boxes checked
    page.set_viewport_size(size("phone"))
    _loads_cleanly(page, server + path, traffic, where)
    has_math = has_math_markup(page)
    if has_math:
        page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
    page.wait_for_selector("body[data-scrollboxes='checked']")
    problems |= layout_problems(page, f"{where} @ phone")

    # axe on the page as opened on the phone, in the dark palette; a page that axe's
    # preparation changes (the mesh page loads an example) is opened again for it, after the
    # layout checks
    changes = changes_page_for_axe(page)
    dark: list[dict[str, Any]] = []
    if not changes:
        prepare_for_axe(page, "slate")
        dark = axe_serious(page, where)

    # the API's module pages share one template, which the API index is checked in at the
    # tablet's width; on the desktop, each of them is at most API_MAX_HEIGHT tall
    module_page = path.startswith("api/") and path != "api/"
    for label in ("desktop",) if module_page else ("tablet", "desktop"):
        resize(page, *VIEWPORTS[label])
        problems |= layout_problems(page, f"{where} @ {label}")
    assert not problems, json.dumps(problems, indent=1, ensure_ascii=False)
    if path.startswith("api/"):
        height = page.evaluate("document.documentElement.scrollHeight")
        assert height <= API_MAX_HEIGHT, f"{where} is {height} px tall at 1280 px"

    # the math engine: loaded only where there is math, and done by the time the page is idle
    engines = [u for u in traffic.requests if any(e in u.lower() for e in MATH_ENGINES)]
    assert has_math is MATH_EXPECTED.get(path, has_math), f"{where}: math found: {has_math}"
    if has_math:
        assert any(u.endswith("/katex.min.js") for u in engines), f"{where}: no KaTeX"
        assert page.locator("body[data-math='typeset']").count() == 1, where
    else:
        assert engines == [], f"{where} has no math but loads {engines}"
    assert not any("mathjax" in u.lower() for u in traffic.requests), where

    if changes:
        page.set_viewport_size(size("phone"))
        open_for_axe(page, server + path, "slate")
        dark = axe_serious(page, where)
        resize(page, *VIEWPORTS["desktop"])
    assert not dark, json.dumps({f"{where} (dark, 360px)": dark}, indent=1)

    # on the desktop, in the light palette: a notebook's page, then axe's colour rules on the
    # page from its top
    if path in NOTEBOOKS:
        _check_notebook_page(page, server, NOTEBOOKS[path])
        page.evaluate("() => window.scrollTo(0, 0)")
    set_scheme(page, "default")  # the page was prepared for axe on the phone
    light = axe_serious(page, where, colours_only=True)
    assert not light, json.dumps({f"{where} (light, 1280px)": light}, indent=1)
    assert not traffic.problems()


# ----------------------------------------------------------------------------- notebook pages


@functools.cache
def _notebooks_with_math() -> list[Path]:
    """Notebooks with TeX in a Markdown cell or a text/latex output (sympy's display)."""
    out = []
    for path in NOTEBOOKS.values():
        nb = json.loads(path.read_text(encoding="utf-8"))
        for cell in nb["cells"]:
            markdown_math = cell["cell_type"] == "markdown" and re.search(
                r"\$|\\\(|\\\[", "".join(cell["source"])
            )
            latex_output = any("text/latex" in o.get("data", {}) for o in cell.get("outputs", []))
            if markdown_math or latex_output:
                out.append(path)
                break
    return out


def _has_widget_output(path: Path) -> bool:
    nb = json.loads(path.read_text(encoding="utf-8"))
    return any(
        "application/vnd.jupyter.widget-view+json" in out.get("data", {})
        for cell in nb["cells"]
        for out in cell.get("outputs", [])
    )


def _check_notebook_page(page: Any, server: str, path: Path) -> None:
    """A notebook's page: navigation entry, download, instructions, math, widget outputs."""
    url = server + f"notebooks/{path.stem}/"
    nav = page.locator("nav.md-nav--primary a").evaluate_all("els => els.map(e => e.href)")
    assert url in nav, f"{path.name} is missing from the navigation"
    link = page.locator(f"a[download][href='{path.name}']").first
    assert link.is_visible(), f"{path.name}: no download link"
    how = page.locator("article a[href$='getting-started/']").first
    assert how.is_visible(), f"{path.name}: no link to the instructions for running it"
    with urllib.request.urlopen(url + path.name) as resp:  # the link's target is served
        downloaded = json.loads(resp.read())
    assert downloaded == json.loads(path.read_text(encoding="utf-8"))

    if path in _notebooks_with_math():
        assert_math_typeset(page, path.name)
        rendered = page.locator(".jp-RenderedMarkdown .katex, .jp-RenderedLatex .katex").count()
        assert rendered > 0, path.name
        raw = page.locator(".jp-RenderedLatex").evaluate_all(
            "els => els.filter(e => !e.querySelector('.katex')).map(e => e.textContent)"
        )
        assert raw == [], f"{path.name}: LaTeX output left untypeset: {raw[:3]}"

    html = page.content()
    assert "application/vnd.jupyter.widget" not in html, path.name
    assert not re.search(r'"model_id"\s*:', page.locator("article").inner_text()), path.name
    # every figure keeps the text alternative the notebook gave it
    assert "No description has been provided" not in html, path.name
    for img in page.locator("article img").all():
        assert (img.get_attribute("alt") or "").strip(), f"{path.name}: a figure without alt"
    if not _has_widget_output(path):
        return
    live = page.locator("article .tn-explorer-live")
    if live.count():  # the explorer notebook: its live view (test_explorer_site.py)
        assert live.first.is_visible(), f"{path.name}: the live view is hidden"
        return
    note = page.locator(".tn-widget-note").first
    assert note.is_visible(), f"{path.name}: widget output without a note"
    text = note.inner_text()
    assert "JupyterLab" in text, path.name
    if note.locator('a[href$="mesh/"]').count():
        # a mesh view: its summary from the last run, and the page that shows one live
        assert "Check a mesh" in text and "faces" in note.locator("pre").inner_text()
        return
    assert "Calculator" in text, path.name
    img = note.locator("img")
    assert img.get_attribute("alt")
    img.scroll_into_view_if_needed()
    page.wait_for_function("img => img.complete && img.naturalWidth > 0", arg=img.element_handle())
