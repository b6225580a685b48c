"""The parser contract, JavaScript side: the site's trinormal-core.js agrees with Python.

Every vector of ``tests/data/parser_vectors.json`` (generated from
:mod:`trinormal.validation`) and of ``tests/data/calculator_vectors.json`` runs
through ``docs/assets/javascripts/trinormal-core.js`` in Chromium: the same
exact values, the same refusals, the same messages, the same formatted outputs.
The script is the very file the site serves; it is loaded into a blank page after
the constants the site build writes (``constants_js()`` of the mkdocs hook, which
carries the limits and message templates), so no site build is needed.
``node tests/parser_vectors_check.js`` runs the first half without a browser.
"""

from __future__ import annotations

import json
import sys

from browser_support import ROOT

sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # the mkdocs hook, imported as the build imports it

CORE_JS = ROOT / "docs/assets/javascripts/trinormal-core.js"
CHECK_JS = ROOT / "tests/parser_vectors_check.js"


def _load(page) -> None:
    page.set_content("<!doctype html><html><body></body></html>")
    page.add_script_tag(content=trinormal_site.constants_js())
    page.add_script_tag(path=str(CORE_JS))
    page.add_script_tag(path=str(CHECK_JS))


def test_parser_vectors_agree_in_the_browser(page):
    vectors = json.loads((ROOT / "tests/data/parser_vectors.json").read_text(encoding="utf-8"))
    _load(page)
    mismatches = page.evaluate(
        "(vectors) => checkParserVectors(window.TrinormalCore, vectors)", vectors
    )
    assert mismatches == []
    assert len(vectors) > 150


def test_calculator_vectors_agree_in_the_browser(page):
    """compute() on every calculator vector: all outputs, the status and the field named."""
    vectors = json.loads((ROOT / "tests/data/calculator_vectors.json").read_text(encoding="utf-8"))
    _load(page)
    results = page.evaluate(
        """(vectors) => vectors.map((v) => {
            const r = window.TrinormalCore.compute(v.a, v.b, v.c, v.winding, v.precision);
            return {ok: r.ok, status: r.status, field: r.ok ? null : r.field,
                    degenerate: r.ok ? r.degenerate : null, out: r.ok ? r.out : null};
        })""",
        vectors,
    )
    for v, r in zip(vectors, results, strict=True):
        assert r["ok"] is v["ok"], v["label"]
        assert r["status"] == v["status"], v["label"]
        if v["ok"]:
            assert r["degenerate"] is v["degenerate"], v["label"]
            assert {k: r["out"][k] for k in v["expected"]} == v["expected"], v["label"]
        else:
            assert r["field"] == v["field"], v["label"]
    assert {v["precision"] for v in vectors} >= {0, 15}


def test_the_limits_match_python(page):
    from trinormal.validation import limits

    _load(page)
    js = page.evaluate("() => window.TrinormalCore.LIMITS")
    assert js == limits()
