"""axe-core (bundled by axe-playwright-python): no serious or critical violations."""

from __future__ import annotations

import json

import pytest
from axe_playwright_python.sync_playwright import Axe

PAGES = ["", "guide/method/", "calculator/"]


@pytest.mark.parametrize("path", PAGES, ids=["home", "guide", "calculator"])
def test_no_serious_accessibility_violations(page, server, traffic, path):
    page.goto(server + path)
    page.wait_for_load_state("networkidle")
    if path == "guide/method/":
        page.wait_for_selector("body[data-math='typeset']", timeout=20_000)
    if path == "calculator/":
        page.wait_for_selector("#tn-calculator[data-ready='true']")
    results = Axe().run(page)
    violations = results.response["violations"]
    assert results.response["passes"] is not None or violations is not None
    serious = [
        {
            "id": v["id"],
            "impact": v["impact"],
            "help": v["help"],
            "nodes": [n["target"] for n in v["nodes"]][:5],
        }
        for v in violations
        if v["impact"] in ("serious", "critical")
    ]
    assert not serious, json.dumps(serious, indent=1)
    assert not traffic.problems()
