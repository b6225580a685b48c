"""The explorer's edit protocol: the kernel keeps every edit it did not overwrite.

A learner's edit (a drag, a typed value) is made against a version of the kernel's state;
a cell may set values before the edit reaches the kernel (the kernel was busy running it).
The kernel keeps every field of the edit that no cell set since, and the cell's value of
a field it set (`trinormal.explorer.state.merge_edit`); the view's JavaScript
(js/explorer/src/edits.js, run here under Node) draws by the same rule. A view trait set
from code goes through `Explorer.set` or raises.
"""

from __future__ import annotations

import json
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest
import traitlets
from node_runs import node_path
from test_explorer import edit

from trinormal import triangle_normal
from trinormal.explorer import Explorer, view_state
from trinormal.explorer.state import merge_edit


def test_a_drag_of_b_during_a_cell_that_sets_c_keeps_both():
    # the kernel is busy with `time.sleep(2); ex.set(c=...)` while B is dragged: the drag's
    # edits, made against the version before the cell, reach the kernel after it
    ex = Explorer()
    before = ex.view.version
    ex.set(c=("-1/3", "2/3", "0.25"))
    for x in ("1.1", "1.2", "1.3"):
        answer = edit(ex, {"bx": x, "by": "0.5"}, base=before)
        assert answer["ok"] and answer["overwritten"] == [], answer
    assert ex.texts["bx"] == "1.3" and ex.view.b == ["1.3", "0.5", "0"]
    assert ex.view.c == ["-1/3", "2/3", "0.25"]
    assert ex.result == triangle_normal((0, 0, 0), ("1.3", "0.5", 0), ("-1/3", "2/3", "0.25"))
    assert ex.view.state == view_state(ex.result, 4)


@pytest.mark.parametrize(
    ("cell", "fields"),
    [
        (lambda ex: ex.set(c=(0, 1, 0)), ["cx", "cy", "cz"]),  # C set to what it was: still set
        (lambda ex: ex.set(winding="ACB", precision=2), ["winding", "precision"]),
        (lambda ex: setattr(ex.controls["cy"], "value", 2), ["cy"]),
        (lambda ex: setattr(ex.inputs["cy"], "value", "1/7"), ["cy"]),
        (lambda ex: setattr(ex.view, "c", ["0", "3", "0"]), ["cx", "cy", "cz"]),
        (lambda ex: setattr(ex.view, "show_unit_normal", True), ["show_unit_normal"]),
    ],
)
def test_what_a_cell_sets_wins_over_an_older_edit_of_it_and_nothing_else(cell, fields):
    ex = Explorer()
    before = ex.view.version
    cell(ex)
    assert ex.view.version > before
    assert sorted(k for k, v in ex.view.set_at.items() if v > before) == sorted(fields)
    kept = ex.texts, ex.winding, ex.precision, ex.view.show_unit_normal
    everything = {
        "cx": "0.5",
        "cy": "0.5",
        "cz": "0.5",
        "winding": "ACB" if ex.winding.value == "ABC" else "ABC",
        "precision": 6,
        "show_unit_normal": not ex.view.show_unit_normal,
    }
    answer = edit(ex, {k: v for k, v in everything.items() if k in fields}, base=before)
    assert answer["ok"] is False and answer["overwritten"] == fields
    assert (ex.texts, ex.winding, ex.precision, ex.view.show_unit_normal) == kept
    assert edit(ex, {"bx": "2"}, base=before)["ok"] and ex.texts["bx"] == "2"


@pytest.mark.parametrize(
    ("edit_fields", "base", "set_at", "kept", "lost"),
    [
        ({"bx": "2"}, 3, {}, {"bx": "2"}, []),
        ({"bx": "2"}, 3, {"bx": 3}, {"bx": "2"}, []),  # set at the edit's own version: kept
        ({"bx": "2"}, 3, {"bx": 4}, {}, ["bx"]),
        ({"bx": "2", "cx": "1"}, 3, {"cx": 5, "cy": 5}, {"bx": "2"}, ["cx"]),
        ({"winding": "ACB", "ax": "0"}, 0, {"winding": 1}, {"ax": "0"}, ["winding"]),
    ],
)
def test_the_merge_rule(edit_fields, base, set_at, kept, lost):
    assert merge_edit(edit_fields, base, set_at) == (kept, lost)


def test_an_edit_naming_no_version_is_refused_as_a_whole():
    ex = Explorer()
    ex.view._handle_custom_msg({"edit": {"bx": "2"}, "seq": 1, "view": "w", "base": None}, [])
    assert ex.view.last_edit["ok"] is False and ex.view.b == ["1", "0", "0"]


def test_a_view_trait_set_from_code_goes_through_set_or_raises():
    ex = Explorer()
    ex.view.a = ["0.5", "1/3", "0"]  # as ex.set(a=...)
    assert ex.result.exact.a == (Fraction(1, 2), Fraction(1, 3), 0)
    assert ex.texts["ay"] == "1/3" and "0.5000" in ex.readout.value
    assert ex.view.state == view_state(ex.result, 4)
    ex.view.winding = "ACB"
    ex.view.precision = 2
    assert ex.winding.value == "ACB" and ex.precision == 2 and ex.view.state["readout"]
    with pytest.raises(ValueError, match=r"A\.x = 9 is outside the slider range"):
        ex.view.a = ["9", "0", "0"]
    with pytest.raises(ValueError, match="winding"):
        ex.view.winding = "CBA"
    assert ex.view.a == ["0.5", "1/3", "0"] and ex.view.winding == "ACB"
    for name, value in [
        ("bounds", [-9.0, 9.0]),
        ("step", "1"),
        ("state", {}),
        ("version", 0),
        ("fields", []),
    ]:
        with pytest.raises(traitlets.TraitError, match=f"ExplorerView.{name} cannot be set"):
            setattr(ex.view, name, value)
    assert ex.view.bounds == [-5.0, 5.0] and ex.view.state == view_state(ex.result, 2)


def test_the_views_edits_follow_the_same_rule():
    # js/explorer/src/edits.js under Node, with a fake model playing a busy kernel
    node = node_path()
    root = Path(__file__).resolve().parents[1]
    run = subprocess.run(
        [node, str(root / "tests" / "edits_check.mjs")], capture_output=True, text=True, check=True
    )
    out = json.loads(run.stdout)
    assert out["sent"] == [[1, 3, "v1", ["bx", "by"]], [2, 3, "v1", ["bx"]]]
    assert out["waitingSince"] == 1000
    # a cell set C: the drag of B stays drawn as the view's own until the kernel answers
    assert out["lostToC"] == [] and out["drawnB"] == ["1.7", "0.5", "0"]
    assert out["drawnC"] == ["-1/3", "2/3", "0.25"]
    # an edit of C made before a cell set C again: the cell's C is drawn
    assert out["lostToC2"] == ["cz"] and out["drawnC2"] == ["0", "0", "1"]
    assert out["answeredOwn"] is True and out["answeredOther"] is False
    assert out["stillWaiting"] == 1050 and out["doneWaiting"] is None
    assert out["drawnB2"] == ["1.7", "0.5", "0"]
