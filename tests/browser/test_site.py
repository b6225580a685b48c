"""Every page of the built site loads cleanly, offline, reads well on a phone, and has its math.

Layout checks run on every page at three viewports (phone, tablet, desktop) and in both colour
schemes (Material's ``default`` and ``slate``): no sideways scrolling of the page; every display
equation is visible and fits, or scrolls inside its own box; tables and notebook outputs scroll
inside their own box, which the keyboard can reach; no number in a notebook's text output is
broken across two lines.
"""

from __future__ import annotations

import json
import re
import urllib.request
from pathlib import Path

import yaml
from browser_support import ROOT, Traffic, site_pages

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
VIEWPORTS = {"phone": (360, 740), "tablet": (768, 1024), "desktop": (1280, 800)}
SCHEMES = ("default", "slate")
MATH_ENGINES = ("katex", "mathjax")


def _settle(page) -> None:
    page.wait_for_load_state("load")
    page.wait_for_load_state("networkidle")


def _mkdocs_config() -> dict:
    class Loader(yaml.SafeLoader):
        pass

    # mkdocs.yml uses !ENV [NAME, default]: read the default, as a build without the variable does
    Loader.add_constructor("!ENV", lambda loader, node: loader.construct_sequence(node)[-1])
    Loader.add_multi_constructor("tag:yaml.org,2002:python/", lambda loader, suffix, node: None)
    return yaml.load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"), Loader=Loader)


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
    # the theme asks for no web fonts, and nothing comes from a CDN or the GitHub API
    assert not any("fonts.googleapis" in u or "unpkg" in u or "cdn" in u for u in traffic.requests)
    assert not any("api.github.com" in u for u in traffic.requests)


# ----------------------------------------------------------------------------- math


def _has_math_markup(page) -> bool:
    """True when the article holds math: arithmatex spans, or TeX in a notebook's cells."""
    return page.evaluate(
        r"""() => {
          if (document.querySelector("article .arithmatex, article .jp-RenderedLatex")) return true;
          return [...document.querySelectorAll("article .jp-RenderedMarkdown")].some(
            e => /\$|\\\(|\\\[/.test(e.textContent) || e.querySelector(".katex"));
        }"""
    )


def test_math_engine_loads_only_where_there_is_math(page, server, site_dir, traffic):
    with_math, without = [], []
    for path in site_pages(site_dir):
        before = len(traffic.requests)
        page.goto(server + path)
        _settle(page)
        requested = traffic.requests[before:]
        engines = [u for u in requested if any(e in u.lower() for e in MATH_ENGINES)]
        if _has_math_markup(page):
            with_math.append(path)
            assert any(u.endswith("/katex.min.js") for u in engines), f"{path}: no KaTeX"
            assert page.locator("body[data-math='typeset']").count() == 1, path
        else:
            without.append(path)
            assert engines == [], f"{path} has no math but loads {engines}"
        assert not any("mathjax" in u.lower() for u in requested), path
    assert "guide/method/" in with_math and "" in without and "calculator/" in without
    assert not (site_dir / "assets" / "vendor" / "mathjax").exists(), "the MathJax bundle is back"
    assert not traffic.problems()


def _assert_math_typeset(page, where: str) -> None:
    page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
    count = page.locator("article .katex").count()
    assert count > 0, f"{where}: no typeset math"
    # the article's prose, without code (where a dollar sign or a backslash is just code)
    text = page.locator("article").evaluate(
        """a => { const c = a.cloneNode(true);
                  c.querySelectorAll('pre, code, .katex, script').forEach(e => e.remove());
                  return c.textContent; }"""
    )
    assert "$$" not in text, f"{where}: raw $$ left"
    assert "\\(" not in text and "\\[" not in text, f"{where}: raw TeX delimiters left"
    assert not re.search(r"\\(?:frac|times|hat|mathbf|displaystyle|left)\b", text), where
    errors = page.locator("article .katex-error").all_inner_texts()
    assert errors == [], f"{where}: KaTeX could not render {errors[:3]}"


def test_math_is_typeset_on_a_guide_page(page, server, traffic):
    page.goto(server + "guide/method/")
    _assert_math_typeset(page, "guide/method/")
    assert page.locator("article div.arithmatex .katex-display").count() >= 3
    # every arithmatex element was rendered, and KaTeX's MathML is there for screen readers
    assert page.locator("article .arithmatex:not(:has(.katex))").count() == 0
    assert page.locator("article .arithmatex .katex-mathml math").count() > 3
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
        rendered = page.locator(".jp-RenderedMarkdown .katex, .jp-RenderedLatex .katex").count()
        assert rendered > 0, path.name
        raw = page.locator(".jp-RenderedLatex").evaluate_all(
            "els => els.filter(e => !e.querySelector('.katex')).map(e => e.textContent)"
        )
        assert raw == [], f"{path.name}: LaTeX output left untypeset: {raw[:3]}"
    assert not traffic.problems()


# ----------------------------------------------------------------------------- layout

# One pass over a page, in the browser: a list of what a reader would find wrong.
_LAYOUT_PROBLEMS = r"""() => {
  const problems = [];
  const vw = document.documentElement.clientWidth;
  const name = el => el.tagName.toLowerCase() + (el.className && typeof el.className === "string"
      ? "." + el.className.trim().split(/\s+/).slice(0, 2).join(".") : "");
  const scrolls = el => ["auto", "scroll"].includes(getComputedStyle(el).overflowX);
  const clips = el => ["hidden", "clip"].includes(getComputedStyle(el).overflowX);
  const focusable = el => el.tabIndex >= 0 && !el.disabled && el.getAttribute("tabindex") !== "-1";

  // 1. the page itself never scrolls sideways
  const sw = document.documentElement.scrollWidth;
  if (sw > vw + 1) {
    const wide = [...document.querySelectorAll("body *")].filter(e => {
      const r = e.getBoundingClientRect(); return r.width > 0 && r.right > vw + 1;
    }).slice(0, 3).map(name);
    problems.push(`the page scrolls sideways (${sw}px wide in ${vw}px): ${wide.join(", ")}`);
  }

  // 2. display equations and tables: visible, and fitting or scrolling inside their own box
  const check = (el, what, visual) => {
    if (!el.checkVisibility()) return;  // not shown on purpose (display: none, closed details)
    const r = visual.getBoundingClientRect();
    if (r.width < 8 || r.height < 8) {
      problems.push(`${what} is not visible (${Math.round(r.width)}x${Math.round(r.height)} px)`);
      return;
    }
    let box = null;
    for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) {
      if (scrolls(a)) { box = a; break; }
      const b = a.getBoundingClientRect();
      if (clips(a) && (r.left < b.left - 1 || r.right > b.right + 1)) {
        problems.push(`${what} is cut off by ${name(a)}`);
        return;
      }
    }
    if (box) {
      const b = box.getBoundingClientRect();
      if (b.left < -1 || b.right > vw + 1) problems.push(`the box of ${what} sticks out of the page`);
      if (r.left < b.left - 1 - (box.scrollLeft || 0)) problems.push(`${what} starts left of its box`);
      if (r.right > b.right + 1 && box.scrollWidth <= box.clientWidth + 1)
        problems.push(`${what} is wider than its box, which does not scroll`);
    } else if (r.left < -1 || r.right > vw + 1) {
      problems.push(`${what} sticks out of the page (${Math.round(r.left)}..${Math.round(r.right)})`);
    }
  };
  document.querySelectorAll("article .katex-display, article .jp-RenderedLatex .katex").forEach(
    (el, i) => check(el, `equation ${i + 1}`, el.querySelector(".katex-html") || el));
  document.querySelectorAll("article table").forEach(
    (el, i) => check(el, `table ${i + 1}`, el));

  // 3. a box that scrolls sideways can be reached with the keyboard (axe: scrollable-region-focusable)
  document.querySelectorAll("article *").forEach(el => {
    if (!scrolls(el) || el.scrollWidth <= el.clientWidth) return;  // as axe counts it
    if (getComputedStyle(el).visibility === "hidden" || el.closest("[hidden], .katex-mathml")) return;
    if (focusable(el) || [...el.querySelectorAll("*")].some(focusable)) return;
    problems.push(`${name(el)} scrolls sideways but the keyboard cannot reach it`);
  });

  // 4. no number in a notebook's text output is broken across two lines
  const number = /[-−]?\d+(?:[.,/]\d+)*(?:e[-+]?\d+)?/g;
  let broken = 0, checked = 0;
  document.querySelectorAll("article .jp-OutputArea-output pre").forEach(pre => {
    const walker = document.createTreeWalker(pre, NodeFilter.SHOW_TEXT);
    for (let t = walker.nextNode(); t && checked < 400; t = walker.nextNode()) {
      for (const m of t.data.matchAll(number)) {
        if (m[0].length < 2) continue;
        const range = document.createRange();
        range.setStart(t, m.index);
        range.setEnd(t, m.index + m[0].length);
        const tops = new Set([...range.getClientRects()].map(q => Math.round(q.top)));
        checked += 1;
        if (tops.size > 1 && broken++ < 3) problems.push(`the number ${m[0]} is broken across lines`);
      }
    }
  });
  return problems;
}"""


def _set_scheme(page, scheme: str) -> None:
    page.evaluate("s => document.body.setAttribute('data-md-color-scheme', s)", scheme)


def test_every_page_reads_well_on_phone_tablet_and_desktop_in_both_schemes(
    page, server, site_dir, traffic
):
    problems: dict[str, list[str]] = {}
    pages = site_pages(site_dir)
    for path in pages:
        page.set_viewport_size(dict(zip(("width", "height"), VIEWPORTS["phone"], strict=True)))
        page.goto(server + path)
        _settle(page)
        if _has_math_markup(page):
            page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
        page.wait_for_selector("body[data-scrollboxes='checked']")
        for label, (width, height) in VIEWPORTS.items():
            page.set_viewport_size({"width": width, "height": height})
            page.wait_for_timeout(250)  # scrollboxes.js re-checks 100 ms after a resize
            for scheme in SCHEMES:
                _set_scheme(page, scheme)
                found = page.evaluate(_LAYOUT_PROBLEMS)
                if found:
                    problems[f"{path or 'home'} @ {label} {width}x{height} {scheme}"] = found
    assert not problems, json.dumps(problems, indent=1, ensure_ascii=False)
    assert not traffic.problems()


def test_the_layout_check_catches_what_it_should(page, server, traffic):
    """The checks above are not vacuous: break a page on purpose and they object."""
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
    _settle(page)
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


# ----------------------------------------------------------------------------- getting started


def test_getting_started_has_the_commands_and_the_repository(page, server, traffic):
    config = _mkdocs_config()
    repo_url = config["repo_url"].rstrip("/")
    assert repo_url.startswith("https://") and config["site_url"].startswith("https://")
    page.goto(server)
    nav = page.locator("nav.md-nav--primary a").evaluate_all("els => els.map(e => e.href)")
    assert server + "getting-started/" in nav
    page.goto(server + "getting-started/")
    _settle(page)
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


def test_every_notebook_is_in_the_site_with_a_download_link(page, server, site_dir, traffic):
    assert NOTEBOOKS, "notebooks/ holds no notebook"
    page.goto(server)
    nav = page.locator("nav.md-nav--primary a").evaluate_all("els => els.map(e => e.href)")
    for path in NOTEBOOKS:
        url = server + f"notebooks/{path.stem}/"
        assert (site_dir / "notebooks" / path.stem / "index.html").is_file(), path.name
        assert url in nav, f"{path.name} is missing from the navigation"
        page.goto(url)
        page.wait_for_load_state(
            "networkidle"
        )  # the page's scripts loaded, none cut off by the next goto
        link = page.locator(f"a[download][href='{path.name}']").first
        assert link.is_visible(), f"{path.name}: no download link"
        how = page.locator("article a[href$='getting-started/']").first
        assert how.is_visible(), f"{path.name}: no link to the instructions for running it"
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
        # every figure keeps the text alternative the notebook gave it
        assert "No description has been provided" not in html, path.name
        for img in page.locator("article img").all():
            assert (img.get_attribute("alt") or "").strip(), f"{path.name}: a figure without alt"
        if _has_widget_output(path):
            live = page.locator("article .tn-explorer-live")
            if live.count():  # the explorer notebook: its live view (test_explorer_site.py)
                assert live.first.is_visible(), f"{path.name}: the live view is hidden"
                continue
            note = page.locator(".tn-widget-note").first
            assert note.is_visible(), f"{path.name}: widget output without a note"
            text = note.inner_text()
            assert "JupyterLab" in text, path.name
            if note.locator('a[href$="mesh/"]').count():
                # a mesh view: its summary from the last run, and the page that shows one live
                assert "Check a mesh" in text and "faces" in note.locator("pre").inner_text()
                continue
            assert "Calculator" in text, path.name
            img = note.locator("img")
            assert img.get_attribute("alt")
            img.scroll_into_view_if_needed()
            page.wait_for_function(
                "img => img.complete && img.naturalWidth > 0", arg=img.element_handle()
            )
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
