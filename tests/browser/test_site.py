"""The built site: offline, its math, its layout check, links, search, the getting-started page.

The checks made on every page (loading, math engine, layout at every width in both palettes,
axe-core, notebook pages) are in test_every_page.py, which visits each page once per screen.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import yaml
from browser_support import ROOT
from page_checks import LAYOUT_PROBLEMS as _LAYOUT_PROBLEMS  # test_mesh_site.py imports it here
from page_checks import assert_math_typeset, settle


def _mkdocs_config() -> dict:
    class Loader(yaml.SafeLoader):
        pass

    # mkdocs.yml uses !ENV [NAME, default]: read the default, as a build without the variable does
    Loader.add_constructor("!ENV", lambda loader, node: loader.construct_sequence(node)[-1])
    Loader.add_multi_constructor("tag:yaml.org,2002:python/", lambda loader, suffix, node: None)
    return yaml.load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"), Loader=Loader)


def test_every_request_stays_on_127_0_0_1(page, server, traffic):
    page.goto(server + "calculator/")
    settle(page)
    assert traffic.requests
    foreign = [u for u in traffic.requests if not u.startswith((traffic.origin, "data:", "blob:"))]
    assert foreign == []
    # the theme asks for no web fonts, and nothing comes from a CDN or the GitHub API
    assert not any("fonts.googleapis" in u or "unpkg" in u or "cdn" in u for u in traffic.requests)
    assert not any("api.github.com" in u for u in traffic.requests)


# ----------------------------------------------------------------------------- math


def test_math_is_typeset_on_a_guide_page(page, server, traffic):
    page.goto(server + "guide/method/")
    assert_math_typeset(page, "guide/method/")
    assert page.locator("article div.arithmatex .katex-display").count() >= 3
    # every arithmatex element was rendered, and KaTeX's MathML is there for screen readers
    assert page.locator("article .arithmatex:not(:has(.katex))").count() == 0
    assert page.locator("article .arithmatex .katex-mathml math").count() > 3
    assert not traffic.problems()


def test_the_layout_check_catches_what_it_should(page, server, traffic):
    """The layout check (test_every_page.py) is not vacuous: break a page and it objects."""
    page.set_viewport_size({"width": 360, "height": 740})
    page.goto(server + "guide/method/")
    page.wait_for_selector("body[data-math='typeset']")
    page.wait_for_selector("body[data-scrollboxes='checked']")
    assert page.evaluate(_LAYOUT_PROBLEMS) == []
    page.add_style_tag(
        content=".md-typeset div.arithmatex { overflow: visible !important; }"
        ".md-typeset div.arithmatex .katex-display { width: 900px !important; }"
    )
    found = " ".join(page.evaluate(_LAYOUT_PROBLEMS))
    assert re.search("sticks out|scrolls sideways|cut off", found), found
    page.reload()
    page.wait_for_selector("body[data-math='typeset']")
    page.add_style_tag(content=".katex-html { display: inline-block; width: 1px; height: 1px; }")
    assert "is not visible" in " ".join(page.evaluate(_LAYOUT_PROBLEMS))
    page.goto(server + "notebooks/03_comparison_table/")
    page.wait_for_selector("body[data-scrollboxes='checked']")
    page.add_style_tag(
        content=".md-content .jupyter-wrapper .jp-OutputArea-output pre "
        "{ word-break: break-all !important; }"
    )
    assert "is broken across lines" in " ".join(page.evaluate(_LAYOUT_PROBLEMS))


# ----------------------------------------------------------------------------- links, search, API


def _built_html(site_dir: Path) -> dict[str, str]:
    return {
        p.relative_to(site_dir).as_posix(): p.read_text(encoding="utf-8")
        for p in sorted(site_dir.rglob("*.html"))
    }


def test_no_link_points_at_localhost(site_dir):
    local = re.compile(
        r"""(?:href|src|action)\s*=\s*["']?(?:https?:)?//(?:127\.0\.0\.1|localhost)"""
    )
    found = {name: local.findall(html)[:3] for name, html in _built_html(site_dir).items()}
    assert {k: v for k, v in found.items() if v} == {}
    text = (site_dir / "index.html").read_text(encoding="utf-8")
    assert "127.0.0.1" not in text and "localhost" not in text


_ROLE = re.compile(
    r":(?:py:)?(?:func|class|meth|attr|data|mod|exc|obj|ref|term|const)[:`]\s*(?:`|<code>)"
)


def test_no_raw_sphinx_roles_anywhere(site_dir):
    found = {name: _ROLE.findall(html)[:3] for name, html in _built_html(site_dir).items()}
    index = (site_dir / "search" / "search_index.json").read_text(encoding="utf-8")
    found["search/search_index.json"] = _ROLE.findall(index)[:3]
    assert {k: v for k, v in found.items() if v} == {}


def test_api_reference_links_its_cross_references(page, server, site_dir, traffic):
    # one page per module (docs/api/): every cross-reference link, within a page or to
    # another, lands on an element with that id
    pages = sorted((site_dir / "api").rglob("index.html"))
    assert len(pages) >= 15
    total, missing = 0, []
    for html_path in pages:
        html = html_path.read_text(encoding="utf-8")
        for href in re.findall(r'<a class="autorefs autorefs-internal"[^>]*href="([^"]+)"', html):
            total += 1
            target, _, anchor = href.partition("#")
            target_path = (html_path.parent / target / "index.html") if target else html_path
            if target.endswith(".html"):
                target_path = html_path.parent / target
            target_path = target_path.resolve()
            if not target_path.is_file() or (
                anchor and f'id="{anchor}"' not in target_path.read_text(encoding="utf-8")
            ):
                missing.append(f"{html_path.relative_to(site_dir)} -> {href}")
    assert total >= 20, "the API reference has few cross-reference links"
    assert missing == []
    page.goto(server + "api/core/")
    settle(page)
    assert page.locator("article a.autorefs-internal").count() >= 5
    assert not traffic.problems()


def test_search_snippets_are_readable_text(site_dir):
    docs = json.loads((site_dir / "search" / "search_index.json").read_text(encoding="utf-8"))[
        "docs"
    ]
    code = re.compile(r"<pre>.*?</pre>|<code>.*?</code>", re.S)
    tex = re.compile(r"\\[()\[\]]|\$\$|\\(?:frac|times|hat|mathbf|sqrt|cdot|displaystyle)\b")
    raw = {d["location"]: tex.findall(code.sub("", d["text"]))[:3] for d in docs}
    assert {k: v for k, v in raw.items() if v} == {}
    method = " ".join(d["text"] for d in docs if d["location"].startswith("guide/method/"))
    assert "N = U × V" in method  # the math became text, not nothing
    # the API's examples and the notebooks' cells are left out, their words kept: every page
    # loads this index when it opens
    words_only = [d for d in docs if d["location"].startswith(("api/", "notebooks/"))]
    assert [d["location"] for d in words_only if "<pre>" in d["text"]] == []
    notebook = " ".join(d["text"] for d in words_only if d["location"].startswith("notebooks/01"))
    assert "the normal of the triangle" in notebook
    assert any("<pre>" in d["text"] for d in docs if d["location"].startswith("guide/"))


# ----------------------------------------------------------------------------- getting started


def test_getting_started_has_the_commands_and_the_repository(page, server, traffic):
    config = _mkdocs_config()
    repo_url = config["repo_url"].rstrip("/")
    assert repo_url.startswith("https://") and config["site_url"].startswith("https://")
    page.goto(server)
    nav = page.locator("nav.md-nav--primary a").evaluate_all("els => els.map(e => e.href)")
    assert server + "getting-started/" in nav
    page.goto(server + "getting-started/")
    settle(page)
    text = page.locator("article").inner_text()
    for needed in ("make lab", "make test", "pip install", "uv run jupyter lab notebooks"):
        assert needed in text, needed
    assert "JupyterLab" in text
    hrefs = page.locator("article a").evaluate_all("els => els.map(e => e.href)")
    assert any(h.rstrip("/") == repo_url for h in hrefs), "no link to the repository"
    assert f"git clone {repo_url}.git" in text
    # the header links to the repository too (without asking the GitHub API for stars)
    assert page.locator(f"header a.md-source[href='{repo_url}']").count() == 1
    assert not traffic.problems()


def test_home_shows_the_explorer_picture(page, server, traffic):
    """The home page shows the live 3D view's screenshot, whole, on a phone as on a desktop."""
    for width in (360, 1280):
        page.set_viewport_size({"width": width, "height": 800})
        page.goto(server)
        img = page.locator("article img[src$='assets/images/explorer-3d.png']")
        assert img.count() == 1
        alt = img.get_attribute("alt") or ""
        assert "3D explorer" in alt and "triangle" in alt
        page.wait_for_function(
            "img => img.complete && img.naturalWidth > 600", arg=img.element_handle()
        )
        box = img.bounding_box()
        assert box is not None and box["x"] >= 0 and box["x"] + box["width"] <= width
        assert box["width"] >= min(300, width - 40), box  # not shrunk below legibility
    assert not traffic.problems()


def test_guide_numbers_come_from_the_package(page, server, traffic):
    from trinormal.guide import comparison_table_cells

    page.goto(server + "guide/method/")
    rows = page.locator("article table").first.locator("tr")
    cells = [rows.nth(i).locator("th, td").all_inner_texts() for i in range(rows.count())]
    assert cells == comparison_table_cells()
    assert not traffic.problems()
