"""The parser contract, Python side: the shared vectors are current and say what validation does.

``tests/data/parser_vectors.json`` lists coordinate strings (and precisions and
windings) with what :mod:`trinormal.validation` answers: the exact value or the
message. ``tests/browser/test_parser_vectors.py`` runs the same file through the
site's ``trinormal-core.js`` in Chromium (and ``tests/test_site_constants.py`` in
Node), so the two parsers cannot drift apart; the JavaScript takes its limits and
message templates from :mod:`trinormal.validation` through the site build.
"""

from __future__ import annotations

import json
import time

import pytest
from reference import DATA, vector_generator

from trinormal import triangle_normal
from trinormal.validation import MAX_TEXT_LENGTH, check_coordinate

GEN = vector_generator("make_parser_vectors")
STORED = json.loads((DATA / "parser_vectors.json").read_text(encoding="utf-8"))


def test_stored_vectors_are_current():
    stored = (DATA / "parser_vectors.json").read_text(encoding="utf-8")
    assert stored == GEN.dumps(GEN.build()), (
        "tests/data/parser_vectors.json is stale: run `python tests/data/make_parser_vectors.py`"
    )


def _by_input(text: str) -> dict:
    return next(v for v in STORED if v["kind"] == "coordinate" and v["input"] == text)


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("\u22121", ["-1", "1"]),  # the Unicode minus, as the guide's text prints it
        ("\ufeff1", ["1", "1"]),
        ("\u00a01\u00a0", ["1", "1"]),
        ("+.5", ["5", "10"]),
        ("5.", ["5", "1"]),
        (" 1 / 3 ", ["1", "3"]),
    ],
)
def test_what_readers_paste_is_accepted(text, value):
    assert _by_input(text) == {"kind": "coordinate", "input": text, "ok": True, "value": value}
    n, d = check_coordinate(text)
    assert [str(n), str(d)] == value


@pytest.mark.parametrize("text", ["\u0661", "\uff11", "1_000", "0x10", "1\u200b", "1e-2200"])
def test_other_notations_are_refused_with_a_message_naming_the_field(text):
    v = _by_input(text)
    assert v["ok"] is False and v["error"].startswith("B.y ")


def test_a_long_input_gets_a_short_message():
    for v in STORED:
        if not v["ok"]:
            assert len(v["error"]) < 200, v["error"]
    v = _by_input("1" * 5000)
    assert v["error"] == f"B.y is too long (5000 characters; at most {MAX_TEXT_LENGTH})"


def test_every_vector_is_what_the_package_says_for_a_triangle():
    """A coordinate string behaves the same inside triangle_normal as alone."""
    for v in STORED:
        if v["kind"] != "coordinate":
            continue
        try:
            r = triangle_normal((0, 0, 0), (1, v["input"], 0), (0, 0, 1))
        except ValueError as err:
            assert not v["ok"] and str(err) == v["error"], v["input"][:40]
        else:
            assert v["ok"], v["input"][:40]
            n, d = (int(x) for x in v["value"])
            assert r.exact.b[1] * d == n


def test_refusals_are_quick():
    """Every refused string is refused in well under 10 ms (best of five)."""
    for v in STORED:
        if v["kind"] == "coordinate" and not v["ok"]:
            best = min(_time(v["input"]) for _ in range(5))
            assert best < 0.01, (v["input"][:40], best)


def _time(text: str) -> float:
    start = time.perf_counter()
    with pytest.raises(ValueError):
        check_coordinate(text, "B.y")
    return time.perf_counter() - start
