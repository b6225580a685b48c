"""Accessibility: axe-core does catch a failure, and the keyboard focus is visible on every control.

axe-core comes from npm (js/vendor's lockfile, vendored into tests/browser/vendor/) and is
injected into the page by the test (it is served by nothing on the web). Every page is checked
with it in test_every_page.py: every rule in the dark palette on a phone, where boxes that
scroll sideways are most common, and the rules that read colours in the light palette on a
desktop screen.
"""

from __future__ import annotations

import json

from page_checks import AXE_COLOUR_RULES, axe_serious, open_for_axe, run_axe, serious


def test_axe_does_see_a_contrast_failure(page, server, traffic):
    """The axe check can fail: grey text on a grey background is reported.

    By a default run, and by the colour rules alone (AXE_COLOUR_RULES, the light palette's
    run in test_every_page.py), which are every rule about colours a default run makes.
    """
    open_for_axe(page, server, "default")
    page.add_style_tag(content="article p { color: #aaa !important; background: #ccc; }")
    results = run_axe(page)
    assert "color-contrast" in [v["id"] for v in serious(results)]
    kinds = ("passes", "violations", "incomplete", "inapplicable")
    ran = {rule["id"] for kind in kinds for rule in results.response[kind]}
    colour = set(page.evaluate("() => axe.getRules(['cat.color']).map((r) => r.ruleId)"))
    assert ran & colour == set(AXE_COLOUR_RULES), ran & colour
    assert "color-contrast" in [v["id"] for v in axe_serious(page, "home", colours_only=True)]


# Every control a reader can reach with Tab shows where the focus is. The page records the focused
# control each time the focus moves (a focusin listener), so the test only presses Tab. Its style is
# read as it settles: a transition still running (Material fades some rings in) is skipped to its
# end for the reading, as the reader sees it a moment later.
_RECORD_FOCUS = """() => {
  window.__tnFocus = [];
  document.addEventListener("focusin", () => {
    const el = document.activeElement;
    if (!el || el === document.body) return;
    const transition = el.style.transition;
    el.style.transition = "none";
    const c = getComputedStyle(el);
    const ring = (c.outlineStyle !== "none" && parseFloat(c.outlineWidth) >= 1)
      || (c.boxShadow && c.boxShadow !== "none");
    el.style.transition = transition;
    const r = el.getBoundingClientRect();
    window.__tnFocus.push({ring, what: el.outerHTML.slice(0, 100), shown: r.width > 0 && r.height > 0});
  }, true);
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
        open_for_axe(page, server + path, "default")
        seen = set()
        page.locator("body").click(position={"x": 1, "y": 1})  # start from the top of the page
        page.evaluate(_RECORD_FOCUS)
        for _ in range(80):
            page.keyboard.press("Tab")
        for state in page.evaluate("window.__tnFocus"):
            if not state["shown"] or state["what"] in seen:
                continue
            seen.add(state["what"])
            if not state["ring"]:
                missing.setdefault(path or "home", []).append(state["what"])
        assert len(seen) >= 8, f"{path}: only {len(seen)} controls reached with Tab"
    assert not missing, json.dumps(missing, indent=1)
    assert not traffic.problems()
