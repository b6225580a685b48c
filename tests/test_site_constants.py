"""Python reaches the site with no step to remember: limits and messages go through the build.

The site build (``docs/hooks/trinormal_site.py``) writes
``assets/javascripts/trinormal-constants.js`` from the package, including
:data:`trinormal.validation.MESSAGES` and :func:`trinormal.validation.limits`;
the calculator's ``trinormal-core.js`` reads them from there. These tests run
that very JavaScript in Node, as a page loads it (the constants file, then the
core), so a wording or a limit edited in Python is what the site says after the
next build.
"""

from __future__ import annotations

import json
import re
import string
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest
from node_runs import node_path

from trinormal import tolerances, triangle_normal, validation
from trinormal.core import VERDICTS
from trinormal.display import SCI_ABOVE_LOG10
from trinormal.validation import MESSAGES, check_coordinate, check_precision, limits

ROOT = Path(__file__).resolve().parents[1]
JS = ROOT / "docs" / "assets" / "javascripts"
CORE_JS = JS / "trinormal-core.js"
sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # noqa: E402  (the mkdocs hook, imported as the build imports it)

#: Load the constants file, then the core, into one global object as a page does, and run
#: the calls given as JSON ([method, args]) through window.TrinormalCore.
_PAGE_SCRIPT = """
const fs = require("fs");
const vm = require("vm");
const [constantsJs, coreJs, callsJson] = process.argv.slice(1);
const page = {};
page.window = page;
page.self = page;
vm.createContext(page);
vm.runInContext(fs.readFileSync(constantsJs, "utf8"), page, { filename: constantsJs });
vm.runInContext(fs.readFileSync(coreJs, "utf8"), page, { filename: coreJs });
const T = page.TrinormalCore;
const out = JSON.parse(fs.readFileSync(callsJson, "utf8")).map(([method, args]) => {
  try {
    const result = T[method](...args);
    // compute() answers with an object: its status line is what the page prints
    return { ok: true, value: result && result.status !== undefined ? result.status : String(result) };
  } catch (err) {
    if (!(err instanceof T.InputError)) throw err;
    return { ok: false, error: err.message };
  }
});
console.log(JSON.stringify(out));
"""


def _on_the_site(tmp_path: Path, calls: list[tuple[str, list[object]]]) -> list[dict]:
    """Build the constants file now, and run ``calls`` in the site's core as a page would."""
    constants = tmp_path / "trinormal-constants.js"
    constants.write_text(trinormal_site.constants_js(), encoding="utf-8")
    calls_file = tmp_path / "calls.json"
    calls_file.write_text(json.dumps(calls), encoding="utf-8")
    run = subprocess.run(
        [node_path(), "-e", _PAGE_SCRIPT, str(constants), str(CORE_JS), str(calls_file)],
        check=True,
        capture_output=True,
        text=True,
    )
    return json.loads(run.stdout)


def _python_error(check, *args) -> str:
    with pytest.raises((ValueError, TypeError)) as info:
        check(*args)
    return str(info.value)


def test_the_constants_carry_the_limits_and_every_message():
    constants = trinormal_site.site_constants()
    assert constants["limits"] == limits()
    assert constants["messages"] == MESSAGES
    assert constants["verdicts"] == VERDICTS
    assert constants["tol"] == tolerances.DEFAULT_TOL
    assert constants["format"] == {"sci_above_log10": SCI_ABOVE_LOG10}
    assert constants["precision"] == {
        "min": limits()["min_precision"],
        "max": limits()["max_precision"],
    }


def test_an_edited_message_reaches_the_site(tmp_path, monkeypatch):
    """Change two wordings in Python only: the site's core says the new words."""
    monkeypatch.setitem(MESSAGES, "nan", "{name} holds NaN, which is not a number")
    monkeypatch.setitem(MESSAGES, "divides_by_zero", "{name} = {shown} has a zero denominator")
    got = _on_the_site(
        tmp_path, [("parseCoordinate", ["nan", "B.y"]), ("parseCoordinate", ["1/0", "C.x"])]
    )
    assert got == [
        {"ok": False, "error": "B.y holds NaN, which is not a number"},
        {"ok": False, "error": "C.x = '1/0' has a zero denominator"},
    ]
    assert got[0]["error"] == _python_error(check_coordinate, "nan", "B.y")
    assert got[1]["error"] == _python_error(check_coordinate, "1/0", "C.x")


def test_edited_limits_reach_the_site(tmp_path, monkeypatch):
    """Lower three limits in Python only: the site's core applies and quotes the new ones."""
    monkeypatch.setattr(validation, "MAX_TEXT_LENGTH", 5)
    monkeypatch.setattr(validation, "MAX_PRECISION", 6)
    monkeypatch.setattr(validation, "MAX_DIGITS", 3)
    got = _on_the_site(
        tmp_path,
        [
            ("parseCoordinate", ["123456", "A.x"]),
            ("checkPrecision", [7]),
            ("checkPrecision", ["6"]),
            ("parseCoordinate", ["1234", "A.z"]),
            ("parseCoordinate", ["123", "A.z"]),
        ],
    )
    assert got[:3] == [
        {"ok": False, "error": _python_error(check_coordinate, "123456", "A.x")},
        {"ok": False, "error": _python_error(check_precision, 7)},
        {"ok": True, "value": "6"},
    ]
    assert got[0]["error"] == "A.x is too long (6 characters; at most 5)"
    assert got[1]["error"] == "precision must be from 0 to 6, got 7"
    assert got[3]["error"].startswith("A.z = '1234' is too large")
    assert got[3]["error"].endswith("(at most 3 digits in its numerator and in its denominator)")
    assert got[4] == {"ok": True, "value": "123,1"}


def test_the_node_core_agrees_with_every_parser_vector(tmp_path):
    """``node tests/parser_vectors_check.js``: every shared vector, the constants built now."""
    constants = tmp_path / "constants.json"
    constants.write_text(json.dumps(trinormal_site.site_constants()), encoding="utf-8")
    run = subprocess.run(
        [node_path(), str(ROOT / "tests" / "parser_vectors_check.js"), str(constants)],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0 and json.loads(run.stdout) == [], run.stdout[:2000] + run.stderr


def test_templates_use_plain_fields_only():
    """The site fills ``{name}`` fields by name: no format specs, conversions or braces."""
    values = {
        "name": "B.y",
        "shown": "'x'",
        "subject": "B.y",
        "length": 1,
        "what": "list",
        "kind": "set",
        "count": 2,
    }
    for key, template in MESSAGES.items():
        for literal, field, spec, conversion in string.Formatter().parse(template):
            assert "{" not in literal and "}" not in literal, key
            if field is not None:
                assert re.fullmatch(r"[a-z_]+", field) and not spec and not conversion, key
                assert field in limits() or field in values, (key, field)


def test_an_edited_verdict_reaches_the_site(tmp_path, monkeypatch):
    """Reword the status sentences in Python only: the site's core writes the new ones."""
    monkeypatch.setitem(VERDICTS, "proper", "Fine: this triangle has a direction.")
    monkeypatch.setitem(VERDICTS, "coincide", "{names} sit on one spot: no area at all.")
    got = _on_the_site(
        tmp_path,
        [
            ("compute", [["0", "0", "0"], ["1", "0", "0"], ["0", "1", "0"], "ABC", "4"]),
            ("compute", [["0", "0", "0"], ["2", "1", "0"], ["2", "1", "0"], "ABC", "4"]),
        ],
    )
    proper = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).format(4)["status"]
    coincide = triangle_normal((0, 0, 0), (2, 1, 0), (2, 1, 0)).format(4)["status"]
    assert proper == "Fine: this triangle has a direction."
    assert coincide == "Degenerate: B and C sit on one spot: no area at all. No unit normal exists."
    assert got == [{"ok": True, "value": proper}, {"ok": True, "value": coincide}]


def test_an_edited_tolerance_reaches_the_site(tmp_path, monkeypatch):
    """Raise DEFAULT_TOL in Python only: the site's core calls a thickness-1e-4 triangle thin."""
    thin = [["0", "0", "0"], ["1", "0", "0"], ["1/2", "1/10000", "0"]]
    fair = [["0", "0", "0"], ["1", "0", "0"], ["1/2", "1/100", "0"]]
    before = _on_the_site(tmp_path, [("compute", [*thin, "ABC", "4"])])
    monkeypatch.setattr(tolerances, "DEFAULT_TOL", 1e-3)
    after = _on_the_site(
        tmp_path, [("compute", [*thin, "ABC", "4"]), ("compute", [*fair, "ABC", "4"])]
    )

    def status(corners: list[list[str]], tol: float) -> str:
        a, b, c = ([Fraction(x) for x in corner] for corner in corners)
        return triangle_normal(a, b, c, tol=tol).format(4)["status"]

    assert before == [{"ok": True, "value": status(thin, 1e-12)}]
    assert after == [
        {"ok": True, "value": status(thin, 1e-3)},
        {"ok": True, "value": status(fair, 1e-3)},
    ]
    assert after[0]["value"].startswith("Degenerate:") and before[0]["value"] != after[0]["value"]
    assert after[1]["value"] == VERDICTS["proper"]


def test_the_hand_written_javascript_holds_no_wording_of_its_own():
    """No fixed phrase of a message or verdict template appears in the site's JavaScript."""
    sources = {p.name: p.read_text(encoding="utf-8") for p in JS.glob("*.js")}
    assert "trinormal-core.js" in sources
    phrases = 0
    for template in [*MESSAGES.values(), *VERDICTS.values()]:
        for part in re.split(r"\{\w+\}", template):
            phrase = part.strip(" ,;:()")
            if " " in phrase and len(phrase) >= 6:
                phrases += 1
                assert [name for name, text in sources.items() if phrase in text] == [], phrase
    assert phrases >= len(MESSAGES) + len(VERDICTS) - 1


def test_the_site_loads_the_constants_before_the_core():
    listed = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    assert listed.index("javascripts/trinormal-constants.js") < listed.index(
        "javascripts/trinormal-core.js"
    )
