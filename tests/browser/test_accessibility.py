"""Accessibility of every page: axe-core finds nothing serious, and the keyboard focus is visible.

axe-core comes bundled with axe-playwright-python and is injected into the page by the test (it
is served by nothing on the web). Every page is checked twice: in the light palette on a desktop
screen, and in the dark palette on a phone, where boxes that scroll sideways are most common.
"""

from __future__ import annotations

import json

import pytest
from axe_playwright_python.sync_playwright import Axe
from browser_support import site_pages

_AXE = Axe()


def _serious(results) -> list[dict]:
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


def _open(page, url: str, scheme: str) -> None:
    page.goto(url)
    page.wait_for_load_state("networkidle")
    if page.locator("article .arithmatex, article .jp-RenderedLatex").count():
        page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
    if page.locator("#tn-calculator").count():
        page.wait_for_selector("#tn-calculator[data-ready='true']")
    if page.locator("#tn-mesh").count():  # the mesh page with a report, its tables and its view
        page.wait_for_selector("#tn-mesh[data-ready='true']")
        page.locator("button[data-example]").first.click()
        page.wait_for_selector("#tn-mesh[data-state='done']")
        page.wait_for_selector("#tn-mesh-view[data-ready='true']")
    page.wait_for_selector("body[data-scrollboxes='checked']")
    # Material fades colours over 0.25 s when the palette changes; on a loaded machine a fixed wait
    # can catch the fade half-way, so axe would judge colours no reader sees at rest. Without
    # transitions the new palette's colours apply at once.
    page.add_style_tag(content="*, *::before, *::after { transition: none !important; }")
    page.evaluate("s => document.body.setAttribute('data-md-color-scheme', s)", scheme)
    page.wait_for_timeout(100)


# Two tests, one per palette and screen, so the two browser workers share the pages.
@pytest.mark.parametrize(
    ("scheme", "size"), [("default", (1280, 800)), ("slate", (360, 740))], ids=["light", "dark"]
)
def test_no_serious_accessibility_violations_on_any_page(
    page, server, site_dir, traffic, scheme, size
):
    found: dict[str, list[dict]] = {}
    checked = 0
    page.set_viewport_size({"width": size[0], "height": size[1]})
    for path in site_pages(site_dir):
        _open(page, server + path, scheme)
        results = _AXE.run(page)
        assert results.response["passes"], f"{path}: axe checked nothing"
        checked += 1
        if serious := _serious(results):
            found[f"{path or 'home'} ({scheme}, {size[0]}px)"] = serious
    assert checked >= 12
    assert not found, json.dumps(found, indent=1)
    assert not traffic.problems()


def test_axe_does_see_a_contrast_failure(page, server, traffic):
    """The check above can fail: grey text on a grey background is reported."""
    _open(page, server, "default")
    page.add_style_tag(content="article p { color: #aaa !important; background: #ccc; }")
    assert "color-contrast" in [v["id"] for v in _serious(_AXE.run(page))]


# Every control a reader can reach with Tab shows where the focus is.
_FOCUS_RING = """() => {
  const el = document.activeElement;
  if (!el || el === document.body) return null;
  const c = getComputedStyle(el);
  const ring = (c.outlineStyle !== "none" && parseFloat(c.outlineWidth) >= 1)
    || (c.boxShadow && c.boxShadow !== "none");
  const r = el.getBoundingClientRect();
  return {ring, what: el.outerHTML.slice(0, 100), shown: r.width > 0 && r.height > 0};
}"""


def test_focus_is_visible_on_every_control(page, server, traffic):
    missing: dict[str, list[str]] = {}
    for path in (
        "",
        "getting-started/",
        "calculator/",
        "mesh/",
        "notebooks/03_comparison_table/",
        "api/",
    ):
        page.set_viewport_size({"width": 1280, "height": 800})
        _open(page, server + path, "default")
        seen = set()
        page.locator("body").click(position={"x": 1, "y": 1})  # start from the top of the page
        for _ in range(80):
            page.keyboard.press("Tab")
            state = page.evaluate(_FOCUS_RING)
            if state is None or not state["shown"] or state["what"] in seen:
                continue
            seen.add(state["what"])
            if not state["ring"]:
                missing.setdefault(path or "home", []).append(state["what"])
        assert len(seen) >= 8, f"{path}: only {len(seen)} controls reached with Tab"
    assert not missing, json.dumps(missing, indent=1)
    assert not traffic.problems()
