"""What the browser tests check on a page of the site: layout, math, accessibility (axe-core).

Kept apart from the tests so that one visit of a page can run every check
(``test_every_page.py``) and the tests of single pages can run the same ones.
"""

from __future__ import annotations

import re
from typing import Any

from axe_playwright_python.base import AxeResults
from axe_playwright_python.sync_playwright import Axe
from browser_support import ROOT

#: axe-core from npm (js/vendor's lockfile, copied by js/vendor/copy-vendor.mjs), injected into the
#: page by the tests; the site never serves it.
AXE_JS = ROOT / "tests" / "browser" / "vendor" / "axe-core" / "axe.min.js"
AXE = Axe.from_file(AXE_JS)
#: Only violations are listed in full.
AXE_OPTIONS = {
    "resultTypes": ["violations"],
}
#: axe's rules that read colours (its rules tagged ``cat.color`` that a default run makes,
#: as test_accessibility.py checks): the only ones whose answer a change of palette can change.
AXE_COLOUR_RULES = ("color-contrast", "link-in-text-block")

VIEWPORTS = {"phone": (360, 740), "tablet": (768, 1024), "desktop": (1280, 800)}
SCHEMES = ("default", "slate")  # Material's light and dark palettes
MATH_ENGINES = ("katex", "mathjax")


def size(name: str) -> dict[str, int]:
    """A viewport of VIEWPORTS as Playwright takes it."""
    width, height = VIEWPORTS[name]
    return {"width": width, "height": height}


def settle(page: Any) -> None:
    """Wait until the page has loaded and made no request for half a second."""
    page.wait_for_load_state("load")
    page.wait_for_load_state("networkidle")


def set_scheme(page: Any, scheme: str) -> None:
    page.evaluate("s => document.body.setAttribute('data-md-color-scheme', s)", scheme)


def resize(page: Any, width: int, height: int) -> None:
    """Resize the viewport and wait until scrollboxes.js has re-checked the boxes at the new size.

    scrollboxes.js re-checks 100 ms after a resize and then sets ``data-scrollboxes``; the
    attribute is removed when the resize event arrives, so only a check made after it counts.
    """
    page.evaluate(
        """() => {
          window.__tnResized = false;
          addEventListener("resize", () => {
            document.body.removeAttribute("data-scrollboxes");
            window.__tnResized = true;
          }, {once: true});
        }"""
    )
    page.set_viewport_size({"width": width, "height": height})
    page.wait_for_function(
        "() => window.__tnResized && document.body.getAttribute('data-scrollboxes') === 'checked'"
    )


# ----------------------------------------------------------------------------- math


def has_math_markup(page: Any) -> bool:
    """True when the article holds math: arithmatex spans, or TeX in a notebook's cells."""
    return bool(
        page.evaluate(
            r"""() => {
          if (document.querySelector("article .arithmatex, article .jp-RenderedLatex")) return true;
          return [...document.querySelectorAll("article .jp-RenderedMarkdown")].some(
            e => /\$|\\\(|\\\[/.test(e.textContent) || e.querySelector(".katex"));
        }"""
        )
    )


def assert_math_typeset(page: Any, where: str) -> None:
    """KaTeX typeset the article's math: no raw TeX left in its prose, no KaTeX error."""
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


# ----------------------------------------------------------------------------- layout

#: One pass over a page, in the browser: a list of what a reader would find wrong.
LAYOUT_PROBLEMS = r"""() => {
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


def layout_problems(page: Any, label: str) -> dict[str, list[str]]:
    """LAYOUT_PROBLEMS at the current viewport in both schemes, keyed by where they were found."""
    width, height = page.viewport_size["width"], page.viewport_size["height"]
    found = {}
    for scheme in SCHEMES:
        set_scheme(page, scheme)
        if problems := page.evaluate(LAYOUT_PROBLEMS):
            found[f"{label} {width}x{height} {scheme}"] = problems
    return found


# ----------------------------------------------------------------------------- accessibility


def prepare_for_axe(page: Any, scheme: str) -> None:
    """Bring a page that has just been opened to the state axe reads, in the given palette.

    Everything has loaded and is drawn: the math, the calculator, and on the mesh page an
    example's report, tables and view (so axe reads them too).
    """
    page.wait_for_load_state("networkidle")
    if page.locator("article .arithmatex, article .jp-RenderedLatex").count():
        page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
    if page.locator("#tn-calculator").count():
        page.wait_for_selector("#tn-calculator[data-ready='true']")
    if page.locator("#tn-mesh").count():  # the mesh page with a report, its tables and its view
        page.wait_for_selector("#tn-mesh[data-ready='true']")
        page.locator("button[data-example]").first.click()
        # the pointer leaves the button: at another width it would hover whatever is there (a
        # link in its hover colour), which no reader at rest sees
        page.mouse.move(0, 0)
        page.wait_for_selector("#tn-mesh[data-state='done']")
        page.wait_for_selector("#tn-mesh-view[data-ready='true']")
    page.wait_for_selector("body[data-scrollboxes='checked']")
    # Material fades colours over 0.25 s when the palette changes; on a loaded machine a wait
    # can catch the fade half-way, so axe would judge colours no reader sees at rest. Without
    # transitions the new palette's colours apply at once (axe reads computed styles, which
    # the browser brings up to date when asked).
    page.add_style_tag(content="*, *::before, *::after { transition: none !important; }")
    set_scheme(page, scheme)


def open_for_axe(page: Any, url: str, scheme: str) -> None:
    page.goto(url)
    prepare_for_axe(page, scheme)


def changes_page_for_axe(page: Any) -> bool:
    """True on a page that ``prepare_for_axe`` changes (the mesh page loads an example)."""
    return bool(page.locator("#tn-mesh").count())


def serious(results: Any) -> list[dict[str, Any]]:
    """axe's serious and critical violations, each with its first five elements."""
    return [
        {
            "id": v["id"],
            "impact": v["impact"],
            "help": v["help"],
            "nodes": [n["target"] for n in v["nodes"]][:5],
        }
        for v in results.response["violations"]
        if v["impact"] in ("serious", "critical")
    ]


def run_axe(page: Any, options: dict[str, Any] = AXE_OPTIONS) -> Any:
    """axe-core's results for the page as it is; axe is injected once per loaded document."""
    if page.evaluate("() => typeof window.axe") == "undefined":
        page.evaluate(AXE.axe_script)
    return AxeResults(page.evaluate("options => axe.run(document, options)", options))


def axe_serious(page: Any, where: str, colours_only: bool = False) -> list[dict[str, Any]]:
    """Run axe on the page as it is; its serious violations (it must have checked something).

    ``colours_only``: only AXE_COLOUR_RULES, for a page whose every rule was run in another
    palette (the structure, names and roles a palette leaves as they are).
    """
    options = AXE_OPTIONS
    if colours_only:
        options = {**AXE_OPTIONS, "runOnly": {"type": "rule", "values": list(AXE_COLOUR_RULES)}}
    results = run_axe(page, options)
    assert results.response["passes"], f"{where}: axe checked nothing"
    if colours_only:
        ran = {
            r["id"]
            for kind in ("passes", "violations", "incomplete")
            for r in results.response[kind]
        }
        assert "color-contrast" in ran, f"{where}: axe checked no colour"
    return serious(results)
