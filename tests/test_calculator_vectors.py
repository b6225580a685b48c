"""The calculator's shared vectors: current with the package, and covering the hard cases.

The browser test (tests/browser/test_calculator.py) enters every vector into the live
calculator's form (and types a few into its boxes) and compares its outputs with these
strings; this test makes sure the strings are what the Python package says today, and
runs every vector through the site's trinormal-core.js in Node, so the two can never
drift apart.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from node_runs import node_path
from reference import DATA, vector_generator

from trinormal import triangle_normal

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # noqa: E402  (the mkdocs hook, imported as the build imports it)

GEN = vector_generator("make_calculator_vectors")
STORED = json.loads((DATA / "calculator_vectors.json").read_text(encoding="utf-8"))


def test_stored_vectors_are_current():
    fresh = GEN.dumps(GEN.build())
    stored = (DATA / "calculator_vectors.json").read_text(encoding="utf-8")
    assert stored == fresh, (
        "tests/data/calculator_vectors.json is stale: run "
        "`python tests/data/make_calculator_vectors.py` and commit the result"
    )


def test_every_vector_matches_the_package():
    for v in STORED:
        if v["ok"]:
            r = triangle_normal(v["a"], v["b"], v["c"], winding=v["winding"])
            f = r.format(v["precision"])
            assert {k: f[k] for k in GEN.OUTPUT_KEYS} == v["expected"], v["label"]
            assert f["status"] == v["status"], v["label"]
            assert r.degenerate is v["degenerate"], v["label"]
        else:
            try:
                triangle_normal(v["a"], v["b"], v["c"], winding=v["winding"])
            except ValueError as err:
                assert str(err) == v["status"], v["label"]
                assert str(err).startswith(v["field"] + " "), v["label"]
            else:
                raise AssertionError(f"{v['label']}: expected a ValueError")
            assert set(v["expected"].values()) == {"—"}


def _by_label(label: str) -> dict:
    return next(v for v in STORED if v["label"] == label)


def test_vectors_cover_the_hard_cases():
    ok = [v for v in STORED if v["ok"]]
    assert any(v["degenerate"] for v in ok)
    assert any(not v["degenerate"] for v in ok)
    assert {v["winding"] for v in STORED} == {"ABC", "ACB"}
    assert {v["precision"] for v in ok} >= {0, 2, 4, 10}
    assert all(0 <= v["precision"] <= 15 for v in STORED)
    assert {v["precision"] for v in ok} >= {0, 15}
    # the rounding tie: an area of exactly 1/8 shows 0.13 at two decimals
    tie = _by_label("area tie 0.125")
    assert tie["precision"] == 2 and tie["expected"]["area"] == "0.13"
    r = triangle_normal(tie["a"], tie["b"], tie["c"])
    assert r.exact.magnitude_squared / 4 == 1 / 64
    # near-degenerate on both sides of the tolerance
    assert _by_label("near-degenerate, below tol")["degenerate"] is True
    assert _by_label("near-degenerate, above tol")["degenerate"] is False
    # huge and tiny coordinates, in scientific notation with long exponents
    assert "e+600" in _by_label("huge 1e300")["expected"]["normal"]
    assert "e-600" in _by_label("tiny 1e-300")["expected"]["normal"]
    # decimals and fractions
    assert any("/" in x for v in ok for x in v["a"] + v["b"] + v["c"])
    assert any("." in x for v in ok for x in v["a"] + v["b"] + v["c"])
    # the four kinds of bad input the issue names, each naming its field
    bad = {v["label"]: v for v in STORED if not v["ok"]}
    assert bad["empty field"]["status"] == "A.x is empty"
    assert bad["not a number"]["field"] == "C.y"
    assert "divides by zero" in bad["divides by zero"]["status"]
    assert bad["NaN"]["status"] == "A.z is NaN"


def test_no_output_string_is_nan_undefined_or_infinity_except_the_unit_normal():
    for v in STORED:
        for key, text in v["expected"].items():
            assert "nan" not in text.lower() and "inf" not in text.lower(), v["label"]
            if text == "undefined":
                assert v["degenerate"] and key in ("unit_normal", "plane"), v["label"]


# Every vector through the site's core in Node, with the constants the site build writes.
_NODE_SCRIPT = """
const [constantsJson, coreJs, vectorsJson] = process.argv.slice(1);
const fs = require("fs");
const T = require(coreJs)(JSON.parse(fs.readFileSync(constantsJson, "utf8")));
const out = JSON.parse(fs.readFileSync(vectorsJson, "utf8")).map((v) => {
  const r = T.compute(v.a, v.b, v.c, v.winding, v.precision);
  return r.ok
    ? { ok: true, degenerate: r.degenerate, status: r.status, out: r.out }
    : { ok: false, status: r.status, field: r.field };
});
console.log(JSON.stringify(out));
"""


def test_the_site_core_in_node_agrees_with_every_vector(tmp_path):
    node = node_path()
    constants = tmp_path / "constants.json"
    constants.write_text(json.dumps(trinormal_site.site_constants()), encoding="utf-8")
    core = ROOT / "docs" / "assets" / "javascripts" / "trinormal-core.js"
    run = subprocess.run(
        [
            node,
            "-e",
            _NODE_SCRIPT,
            str(constants),
            str(core),
            str(DATA / "calculator_vectors.json"),
        ],
        check=True,
        capture_output=True,
        text=True,
    )
    for v, got in zip(STORED, json.loads(run.stdout), strict=True):
        if v["ok"]:
            assert got["ok"] and got["degenerate"] is v["degenerate"], v["label"]
            assert got["status"] == v["status"], v["label"]
            assert {k: got["out"][k] for k in GEN.OUTPUT_KEYS} == v["expected"], v["label"]
        else:
            assert got == {"ok": False, "status": v["status"], "field": v["field"]}, v["label"]


def test_thin_triangles_appear_in_every_order_with_one_verdict():
    """Each thin or nearly coincident triangle: three rotations, both windings, one verdict."""
    groups: dict[str, list[dict]] = {}
    for v in STORED:
        if " first, " in v["label"]:
            groups.setdefault(v["label"].rsplit(", ", 2)[0], []).append(v)
    assert len(groups) == len(GEN.THIN) and all(len(g) == 6 for g in groups.values())
    for label, group in groups.items():
        assert len({v["degenerate"] for v in group}) == 1, label
        assert len({frozenset(map(tuple, (v["a"], v["b"], v["c"]))) for v in group}) == 1
    assert groups["needle, right angle at A"][0]["degenerate"] is True
    assert groups["C within 1e-13 of A"][0]["degenerate"] is True
    assert groups["on the tolerance"][0]["degenerate"] is True
    assert groups["just above the tolerance"][0]["degenerate"] is False
