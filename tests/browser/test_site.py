"""Every page of the built site loads cleanly, offline, with its math typeset."""

from __future__ import annotations

import json
import re
import urllib.request
from pathlib import Path

from browser_support import ROOT, Traffic, site_pages

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


def _settle(page) -> None:
    page.wait_for_load_state("load")
    page.wait_for_load_state("networkidle")


def test_every_page_loads_without_errors_or_foreign_requests(page, server, site_dir, traffic):
    pages = [*site_pages(site_dir), "404.html"]
    assert len(pages) >= 12, pages
    problems: dict[str, list[str]] = {}
    seen = 0
    for path in pages:
        before = len(traffic.requests)
        mark = {k: len(getattr(traffic, k)) for k in ("off_origin", "failed", "bad_status")}
        mark |= {k: len(getattr(traffic, k)) for k in ("console_errors", "page_errors")}
        response = page.goto(server + path)
        assert response is not None and response.ok, f"{path}: {response and response.status}"
        _settle(page)
        seen += len(traffic.requests) - before
        fresh = Traffic(origin=traffic.origin)
        for k, n in mark.items():
            setattr(fresh, k, getattr(traffic, k)[n:])
        if fresh.problems():
            problems[path] = fresh.problems()
    assert not problems, json.dumps(problems, indent=1)
    assert not traffic.off_origin
    assert seen > len(pages)  # stylesheets, scripts and images were requested (and served)


def test_every_request_stays_on_127_0_0_1(page, server, traffic):
    page.goto(server + "calculator/")
    _settle(page)
    assert traffic.requests
    foreign = [u for u in traffic.requests if not u.startswith((traffic.origin, "data:", "blob:"))]
    assert foreign == []
    # the theme asks for no web fonts and MathJax is served locally
    assert any(u.endswith("assets/vendor/mathjax/tex-svg-full.js") for u in traffic.requests)
    assert not any("fonts.googleapis" in u or "unpkg" in u or "cdn" in u for u in traffic.requests)


def _assert_math_typeset(page, where: str) -> None:
    page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
    count = page.locator("mjx-container").count()
    assert count > 0, f"{where}: no typeset math"
    # the article's prose, without code (where a dollar sign or a backslash is just code)
    text = page.locator("article").evaluate(
        """a => { const c = a.cloneNode(true);
                  c.querySelectorAll('pre, code, mjx-container, script').forEach(e => e.remove());
                  return c.textContent; }"""
    )
    assert "$$" not in text, f"{where}: raw $$ left"
    assert "\\(" not in text and "\\[" not in text, f"{where}: raw TeX delimiters left"
    assert page.locator("mjx-merror").count() == 0, f"{where}: MathJax reported a TeX error"


def test_math_is_typeset_on_a_guide_page(page, server, traffic):
    page.goto(server + "guide/method/")
    _assert_math_typeset(page, "guide/method/")
    assert page.locator("article mjx-container[display='true']").count() >= 3
    assert not traffic.problems()


def _notebooks_with_math() -> list[Path]:
    """Notebooks with TeX in a Markdown cell or a text/latex output (sympy's display)."""
    out = []
    for path in NOTEBOOKS:
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


def test_math_is_typeset_on_a_notebook_page(page, server, traffic):
    with_math = _notebooks_with_math()
    assert with_math, "no notebook in notebooks/ has math (Markdown TeX or a text/latex output)"
    for path in with_math:
        page.goto(server + f"notebooks/{path.stem}/")
        _assert_math_typeset(page, path.name)
        rendered = page.locator(
            ".jp-RenderedMarkdown mjx-container, .jp-RenderedLatex mjx-container"
        ).count()
        assert rendered > 0, path.name
        raw = page.locator(".jp-RenderedLatex").evaluate_all(
            "els => els.filter(e => !e.querySelector('mjx-container')).map(e => e.textContent)"
        )
        assert raw == [], f"{path.name}: LaTeX output left untypeset: {raw[:3]}"
    assert not traffic.problems()


def test_every_notebook_is_in_the_site_with_a_download_link(page, server, site_dir, traffic):
    assert NOTEBOOKS, "notebooks/ holds no notebook"
    page.goto(server)
    nav = page.locator("nav.md-nav--primary a").evaluate_all("els => els.map(e => e.href)")
    for path in NOTEBOOKS:
        url = server + f"notebooks/{path.stem}/"
        assert (site_dir / "notebooks" / path.stem / "index.html").is_file(), path.name
        assert url in nav, f"{path.name} is missing from the navigation"
        page.goto(url)
        link = page.locator(f"a[download][href='{path.name}']").first
        assert link.is_visible(), f"{path.name}: no download link"
        with urllib.request.urlopen(url + path.name) as resp:  # the link's target is served
            downloaded = json.loads(resp.read())
        assert downloaded == json.loads(path.read_text(encoding="utf-8"))
    assert not traffic.problems()


def _has_widget_output(path: Path) -> bool:
    nb = json.loads(path.read_text(encoding="utf-8"))
    return any(
        "application/vnd.jupyter.widget-view+json" in out.get("data", {})
        for cell in nb["cells"]
        for out in cell.get("outputs", [])
    )


def test_widget_outputs_are_replaced_by_a_note_and_a_picture(page, server, traffic):
    for path in NOTEBOOKS:
        page.goto(server + f"notebooks/{path.stem}/")
        _settle(page)
        html = page.content()
        assert "application/vnd.jupyter.widget" not in html, path.name
        assert not re.search(r'"model_id"\s*:', page.locator("article").inner_text()), path.name
        if _has_widget_output(path):
            note = page.locator(".tn-widget-note").first
            assert note.is_visible(), f"{path.name}: widget output without a note"
            assert "JupyterLab" in note.inner_text() and "Calculator" in note.inner_text()
            img = note.locator("img")
            assert img.get_attribute("alt")
            img.scroll_into_view_if_needed()
            page.wait_for_function(
                "img => img.complete && img.naturalWidth > 0", arg=img.element_handle()
            )
    assert not traffic.problems()


def test_home_shows_the_explorer_picture(page, server, traffic):
    page.goto(server)
    img = page.locator("article img[src$='assets/images/explorer.png']")
    assert img.count() == 1
    assert "triangle" in (img.get_attribute("alt") or "")
    page.wait_for_function(
        "img => img.complete && img.naturalWidth > 300", arg=img.element_handle()
    )
    assert not traffic.problems()


def test_guide_numbers_come_from_the_package(page, server, traffic):
    from trinormal.guide import comparison_table_cells

    page.goto(server + "guide/method/")
    rows = page.locator("article table").first.locator("tr")
    cells = [rows.nth(i).locator("th, td").all_inner_texts() for i in range(rows.count())]
    assert cells == comparison_table_cells()
    assert not traffic.problems()
