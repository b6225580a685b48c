"""The live calculator: same strings as Python, live updates, winding, precision, URL, errors."""

from __future__ import annotations

import json
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

import pytest
from browser_support import ROOT

from trinormal import triangle_normal
from trinormal.fields import FIELDS as FIELDS_SPEC
from trinormal.printmodel import PRINT_MESSAGES, print_model

VECTORS = json.loads((ROOT / "tests/data/calculator_vectors.json").read_text(encoding="utf-8"))
FIELDS = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"]
OUTPUTS = {f.key: "#" + f.output_id for f in FIELDS_SPEC}
DASH = "—"
#: The boxes of the page as it opens (the worked example).
DEFAULT = dict(zip(FIELDS, ["0", "0", "0", "1", "0", "0", "0", "1", "0"], strict=True))


def open_calculator(page, url: str) -> None:
    """Open the calculator and wait until it is ready and the page has stopped loading."""
    page.goto(url)
    page.wait_for_selector("#tn-calculator[data-ready='true']")
    page.wait_for_load_state("networkidle")


@pytest.fixture
def calc(page, server, traffic):
    open_calculator(page, server + "calculator/")
    yield page
    assert not traffic.problems()


#: The readout as a reader sees it (each output's innerText, as Playwright's inner_text reads it),
#: its status line and the status's state, in one call.
_READOUT = """(ids) => ({
  outputs: Object.fromEntries(Object.entries(ids).map(([k, sel]) => [k, document.querySelector(sel).innerText])),
  status: document.getElementById('out-status').innerText,
  state: document.getElementById('out-status').getAttribute('data-state'),
})"""


def readout(page) -> dict:
    return page.evaluate(_READOUT, OUTPUTS)


def outputs(page) -> dict[str, str]:
    return readout(page)["outputs"]


def status(page) -> str:
    return page.locator("#out-status").inner_text()


def enter(page, a, b, c, winding="ABC", precision=4) -> None:
    for name, value in zip(FIELDS, [*a, *b, *c], strict=True):
        page.fill("#" + name, value)
    page.select_option("#winding", winding)
    page.fill("#precision", str(precision))


def expected(a, b, c, winding="ABC", precision=4) -> dict[str, str]:
    f = triangle_normal(a, b, c, winding=winding).format(precision)
    return {key: f[key] for key in OUTPUTS}


def test_the_default_page_is_the_worked_example(calc):
    assert outputs(calc) == expected(("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"))
    assert status(calc) == "A proper triangle: the unit normal is defined."


#: Every vector entered into the page's own form, one after the other, in one call: the nine
#: boxes, the winding and the precision set, then an input event sent (the page's handler reads
#: the whole form on each one, as it does when a reader types), so the page computes with its
#: core and writes the readout, which is read back as a reader sees it.
_ENTER_ALL = """([vectors, fields, ids]) => vectors.map((v) => {
  const values = [...v.a, ...v.b, ...v.c];
  fields.forEach((id, i) => { document.getElementById(id).value = values[i]; });
  document.getElementById('winding').value = v.winding;
  const precision = document.getElementById('precision');
  precision.value = String(v.precision);
  precision.dispatchEvent(new Event('input', {bubbles: true}));
  const status = document.getElementById('out-status');
  return {
    outputs: Object.fromEntries(Object.entries(ids).map(([k, sel]) => [k, document.querySelector(sel).innerText])),
    status: status.innerText,
    state: status.getAttribute('data-state'),
  };
})"""

#: Vectors also typed into the boxes through Playwright (the real UI path, each box filled and
#: the winding chosen in its select): an exact result with fractions in the ACB winding at full
#: precision, a degenerate triangle, and refused input with its message.
UI_SAMPLE = ["precision 15 on thirds", "collinear (table row 4)", "not a number", "Infinity"]


def _want(v: dict) -> dict:
    state = "error" if not v["ok"] else "degenerate" if v["degenerate"] else "ok"
    return {"outputs": v["expected"], "status": v["status"], "state": state}


def test_every_shared_vector_matches_python(calc):
    """Every shared vector through the page's form and handlers; a sample typed in the boxes."""
    assert len(VECTORS) >= 40
    got = calc.evaluate(_ENTER_ALL, [VECTORS, FIELDS, OUTPUTS])
    mismatches = [
        {"label": v["label"], "got": g, "want": _want(v)}
        for v, g in zip(VECTORS, got, strict=True)
        if g != _want(v)
    ]
    assert not mismatches, json.dumps(mismatches, indent=1, ensure_ascii=False)
    by_label = {v["label"]: v for v in VECTORS}
    sample = [by_label[label] for label in UI_SAMPLE]
    assert {_want(v)["state"] for v in sample} == {"ok", "degenerate", "error"}
    assert {v["winding"] for v in sample} == {"ABC", "ACB"}
    for v in sample:
        enter(calc, v["a"], v["b"], v["c"], v["winding"], v["precision"])
        assert readout(calc) == _want(v), v["label"]


def test_results_update_as_you_type(calc):
    calc.locator("#bx").fill("")
    calc.locator("#bx").press_sequentially("2")
    assert calc.locator("#out-u").inner_text() == "(2.0000, 0.0000, 0.0000)"
    calc.locator("#cy").press("End")
    calc.locator("#cy").press_sequentially("5")  # "1" becomes "15"
    assert calc.locator("#out-v").inner_text() == "(0.0000, 15.0000, 0.0000)"
    assert calc.locator("#out-area").inner_text() == "15.0000"
    # the chart follows: its label carries N's components
    assert "Nz = 30.0000" in calc.locator("#chart").get_attribute("aria-label")


def test_url_state_round_trip(page, server, traffic):
    url = server + "calculator/?a=1,1,1&b=2,1,1&c=1,2,2&w=ACB&p=2"
    open_calculator(page, url)
    values = [page.locator("#" + f).input_value() for f in FIELDS]
    assert values == ["1", "1", "1", "2", "1", "1", "1", "2", "2"]
    assert page.locator("#winding").input_value() == "ACB"
    assert page.locator("#precision").input_value() == "2"
    assert outputs(page) == expected(("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ACB", 2)
    # editing writes the state back into the address
    page.fill("#cz", "1/3")
    page.select_option("#winding", "ABC")
    page.fill("#precision", "5")
    query = parse_qs(urlsplit(page.evaluate("location.href")).query)
    assert query == {"a": ["1,1,1"], "b": ["2,1,1"], "c": ["1,2,1/3"], "w": ["ABC"], "p": ["5"]}
    shared = page.evaluate("location.href")
    # ... and opening that address afresh (a new document, not this one) restores the same state
    page.evaluate("window.__tnBefore = true")
    open_calculator(page, shared)
    assert page.evaluate("window.__tnBefore") is None, "the address did not load a new page"
    assert page.locator("#cz").input_value() == "1/3"
    assert outputs(page) == expected(("1", "1", "1"), ("2", "1", "1"), ("1", "2", "1/3"), "ABC", 5)
    assert not traffic.problems()


def test_url_with_odd_values_round_trips(page, server, traffic):
    open_calculator(page, server + "calculator/?a=0,0,0&b=1%2C5,0,0&c=0,1,0&w=ABC&p=4")
    assert page.locator("#bx").input_value() == "1,5"
    assert status(page).startswith("B.x = '1,5' is not a number")
    page.fill("#az", " 2 ")
    page.fill("#az", "0")
    open_calculator(page, page.evaluate("location.href"))
    assert page.locator("#bx").input_value() == "1,5"
    assert not traffic.problems()


#: Bad input in one box: the field, what is typed, the message that starts the status line.
BAD_INPUT = [
    ("ax", "", "A.x is empty"),
    ("by", "abc", "B.y = 'abc' is not a number"),
    ("cz", "1/0", "C.z = '1/0' divides by zero"),
    ("bx", "NaN", "B.x is NaN"),
    ("cy", "Infinity", "C.y is infinite"),
]


def test_bad_input_names_the_field_and_dashes_the_outputs(calc):
    """Each bad value in turn, on one visit: typed, checked, then fixed before the next."""
    for field, text, message in BAD_INPUT:
        case = f"{field} = {text!r}"
        calc.fill("#" + field, text)
        assert status(calc).startswith(message), case
        assert calc.locator("#out-status").get_attribute("data-state") == "error", case
        assert calc.locator("#" + field).get_attribute("aria-invalid") == "true", case
        shown = outputs(calc)
        assert set(shown.values()) == {DASH}, case
        page_text = calc.locator(".tn-results").inner_text()
        for word in ("NaN", "undefined", "Infinity"):
            assert word not in page_text, case
        # fixing the field brings the numbers back (the default triangle's value)
        calc.fill("#" + field, DEFAULT[field])
        assert calc.locator("#" + field).get_attribute("aria-invalid") is None, case
        assert DASH not in calc.locator("#out-normal").inner_text(), case


def test_winding_precision_degenerate_and_chart(calc):
    """Five checks on one visit; each starts by entering a whole triangle (winding ABC,
    precision 4), so none depends on the one before, and a failure's traceback names its helper."""
    _winding_flip_turns_the_normal_over(calc)
    _precision_change(calc)
    _degenerate_triangle_says_undefined(calc)
    _chart_draws_signed_bars_with_labels(calc)
    _print_buttons_download_pythons_model(calc)


def _print_buttons_download_pythons_model(calc) -> None:
    """The view's 3D printing buttons save the STL Python writes, byte for byte, or say why not."""
    calc.wait_for_selector("#tn-view[data-ready='true']")
    enter(calc, ("1", "2", "3"), ("-2", "0.5", "4"), ("1/3", "-1", "-2"), winding="ACB")
    group = calc.locator("#tn-view").get_by_role("group", name="3D printing")
    with calc.expect_download() as saved:
        group.get_by_role("button", name="Download for 3D printing with braille marks").click()
    assert saved.value.suggested_filename == "triangle-braille.stl"
    want = print_model((1, 2, 3), (-2, "0.5", 4), ("1/3", -1, -2), winding="ACB", marks="braille")
    assert Path(saved.value.path()).read_bytes() == want.stl()
    enter(calc, ("0", "0", "0"), ("1", "1", "1"), ("2", "2", "2"))
    group.get_by_role("button", name="Download for 3D printing", exact=True).click()
    assert group.get_by_role("status").inner_text() == PRINT_MESSAGES["degenerate"]


def _winding_flip_turns_the_normal_over(calc) -> None:
    enter(calc, ("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"))
    assert calc.locator("#out-normal").inner_text() == "(0.0000, -1.0000, 1.0000)"
    calc.select_option("#winding", "ACB")
    assert calc.locator("#out-normal").inner_text() == "(0.0000, 1.0000, -1.0000)"
    assert calc.locator("#out-unit").inner_text() == "(0.0000, 0.7071, -0.7071)"
    assert calc.locator("#out-area").inner_text() == "0.7071"
    calc.click("#tn-flip")
    assert calc.locator("#winding").input_value() == "ABC"
    assert calc.locator("#out-normal").inner_text() == "(0.0000, -1.0000, 1.0000)"


def _precision_change(calc) -> None:
    enter(calc, ("0", "0", "0"), ("0.5", "0", "0"), ("0", "0.5", "0"))
    calc.fill("#precision", "2")
    assert calc.locator("#out-area").inner_text() == "0.13"  # 0.125 rounds half away from zero
    calc.fill("#precision", "0")
    assert calc.locator("#out-area").inner_text() == "1e-01"
    calc.fill("#precision", "10")
    assert calc.locator("#out-area").inner_text() == "0.1250000000"
    calc.fill("#precision", "15")
    assert calc.locator("#out-area").inner_text() == "0.125000000000000"
    calc.fill("#precision", "16")
    assert status(calc) == "precision must be from 0 to 15, got 16"
    assert set(outputs(calc).values()) == {DASH}
    calc.fill("#precision", "3")
    assert calc.locator("#out-area").inner_text() == "0.125"


def _degenerate_triangle_says_undefined(calc) -> None:
    enter(calc, ("0", "0", "0"), ("1", "1", "1"), ("2", "2", "2"))
    assert calc.locator("#out-unit").inner_text() == "undefined"
    assert calc.locator("#out-plane").inner_text() == "undefined"
    assert status(calc).startswith("Degenerate: A, B and C are collinear")
    assert "Nx = 0.0000, Ny = 0.0000, Nz = 0.0000" in calc.locator("#chart").get_attribute(
        "aria-label"
    )


def _chart_draws_signed_bars_with_labels(calc) -> None:
    enter(calc, ("1", "2", "3"), ("4", "6", "9"), ("-2", "0", "5"))
    chart = calc.locator("#chart")
    assert chart.get_attribute("role") == "img"
    label = chart.get_attribute("aria-label")
    assert label == (
        "Bar chart of the normal components: Nx = 20.0000, Ny = -24.0000, Nz = 6.0000."
    )
    widths = chart.locator("rect").evaluate_all(
        "rs => rs.map(r => Number(r.getAttribute('width')))"
    )
    assert len(widths) == 3
    assert widths[1] == max(widths)  # |Ny| is the largest component
    assert widths[0] == pytest.approx(widths[1] * 20 / 24, rel=1e-3)
    texts = chart.locator("text").evaluate_all("ts => ts.map(t => t.textContent)")
    assert texts == ["Nx", "20.0000", "Ny", "-24.0000", "Nz", "6.0000"]
