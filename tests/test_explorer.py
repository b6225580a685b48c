"""trinormal.explorer: the explorer driven from pytest, without a kernel or a browser."""

from __future__ import annotations

import io
import json
import math
import re
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image

from trinormal import Winding, triangle_normal
from trinormal.explorer import COORDINATES, Explorer, ExplorerView, view_state
from trinormal.explorer import widget as tw
from trinormal.explorer.view import BUNDLE
from trinormal.explorer.widget import Control

KEYS = ("ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz")
SHARED: dict[str, Explorer] = {}


def move(ex, a, b, c):
    """Set the nine sliders one by one from code."""
    for key, value in zip(KEYS, (*a, *b, *c), strict=True):
        ex.controls[key].value = value


def decimal(points):
    """A float set from code means the shortest decimal that gives it back."""
    return [[repr(float(x)) for x in p] for p in points]


def edit(ex, changes, base=None, view="w1"):
    """Send an edit the way the view in the browser does (an anywidget custom message)."""
    edit.seq = getattr(edit, "seq", 0) + 1
    content = {
        "edit": changes,
        "seq": edit.seq,
        "view": view,
        "base": ex.view.version if base is None else base,
    }
    ex.view._handle_custom_msg(content, [])
    return ex.view.last_edit


def assert_readout_shows(ex, expected, precision):
    text = ex.readout.value
    for key, value in expected.format(precision).items():
        assert value in text, (key, value)
    assert "nan" not in text.lower()


# --------------------------------------------------------------------------- the controls


def test_controls_are_the_contracted_widgets():
    ex = Explorer(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0), winding="ABC", precision=4)
    assert set(ex.controls) == {*KEYS, "winding", "precision"}
    assert COORDINATES == KEYS
    for key in KEYS:
        slider = ex.controls[key]
        assert isinstance(slider, Control)
        assert (slider.min, slider.max, slider.step) == (-5.0, 5.0, 0.1)
    assert [ex.controls[k].value for k in KEYS] == [0, 0, 0, 1, 0, 0, 0, 1, 0]
    toggle = ex.controls["winding"]
    assert toggle.options == (("A→B→C", "ABC"), ("A→C→B", "ACB"))
    assert toggle.value == "ABC"
    precision = ex.controls["precision"]
    assert (precision.min, precision.max, precision.value) == (0, 15, 4)
    assert ex.view.precision_range == [0, 15]
    assert isinstance(ex.view, ExplorerView)
    assert [ex.inputs[k].value for k in KEYS] == ["0", "0", "0", "1", "0", "0", "0", "1", "0"]


def test_range_and_step_are_constructor_options():
    ex = Explorer(min=-10, max=10, step=0.5, b=(9.5, 0, 0))
    assert {(ex.controls[k].min, ex.controls[k].max, ex.controls[k].step) for k in KEYS} == {
        (-10.0, 10.0, 0.5)
    }
    assert ex.result.b == (9.5, 0.0, 0.0)
    ex.controls["cz"].value = -10
    assert ex.result.c == (0.0, 1.0, -10.0)
    with pytest.raises(ValueError, match=r"C\.z = 10\.5 is outside the slider range -10 to 10"):
        ex.controls["cz"].value = 10.5
    small = Explorer(range=(-1, 1), b=(1, 0, 0), c=(0, 1, 0))
    assert (small.controls["ax"].min, small.controls["ax"].max) == (-1.0, 1.0)


@pytest.mark.parametrize(
    "kwargs",
    [{"min": 1, "max": 1}, {"min": 2, "max": -2}, {"step": 0}, {"step": -0.1}, {"step": 20}],
)
def test_nonsense_range_or_step_is_refused(kwargs):
    with pytest.raises(ValueError):
        Explorer(a=(0, 0, 0), b=(0, 0, 0), c=(0, 0, 0), **kwargs)


# --------------------------------------------------------------------------- recomputation

CASES = [
    ((0, 0, 0), (1, 0, 0), (0, 1, 0)),
    ((0, 0, 0), (2, 0, 0), (0, 3, 0)),
    ((1, 1, 1), (2, 1, 1), (1, 2, 2)),
    ((0.3, -1.7, 2.2), (4.1, 0.5, -3.3), (-2.5, 4.9, 0.1)),
    ((-5, -5, -5), (5, -5, 5), (-5, 5, 5)),
]


@pytest.mark.parametrize(("a", "b", "c"), CASES)
@pytest.mark.parametrize("winding", ["ABC", "ACB"])
def test_setting_sliders_recomputes_result_and_readout(a, b, c, winding):
    ex = Explorer(winding=winding)
    move(ex, a, b, c)
    expected = triangle_normal(*decimal((a, b, c)), winding=winding)
    assert ex.result == expected
    assert ex.result.winding == Winding(winding)
    assert (ex.a, ex.b, ex.c) == (expected.a, expected.b, expected.c)
    assert_readout_shows(ex, expected, 4)
    assert Winding(winding).label in ex.readout.value


def test_every_single_slider_change_is_seen_immediately():
    ex = Explorer()
    for key in KEYS:
        before = ex.result
        ex.controls[key].value = 2.5
        points = [[ex.controls[p + q].value for q in "xyz"] for p in "abc"]
        assert ex.result == triangle_normal(*decimal(points))
        assert ex.result != before or before == triangle_normal(*decimal(points))
        assert_readout_shows(ex, ex.result, 4)


def test_winding_toggle_turns_the_normal_over():
    ex = Explorer(a=(1, 1, 1), b=(2, 1, 1), c=(1, 2, 2))
    n_abc = ex.result.normal
    ex.controls["winding"].value = "ACB"
    assert ex.result.winding is Winding.ACB
    assert ex.result.normal == tuple(-x for x in n_abc)
    assert "A→C→B" in ex.readout.value
    assert "U = C − A, V = B − A" in ex.readout.value
    assert_readout_shows(ex, triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2), winding="ACB"), 4)
    ex.controls["winding"].value = Winding.ABC  # the enum is accepted too
    assert ex.result.normal == n_abc


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.floats(-5, 5, allow_nan=False), min_size=9, max_size=9),
    st.sampled_from(["ABC", "ACB"]),
    st.integers(0, 15),
)
def test_any_position_matches_the_core(values, winding, precision):
    ex = SHARED.setdefault("ex", Explorer())  # one explorer, moved example after example
    ex.controls["winding"].value = winding
    ex.controls["precision"].value = precision
    move(ex, values[0:3], values[3:6], values[6:9])
    points = [[ex.controls[k].value for k in KEYS[i : i + 3]] for i in (0, 3, 6)]
    assert all(v == w for v, w in zip(values, (x for p in points for x in p), strict=True))
    expected = triangle_normal(*decimal(points), winding=winding)
    assert ex.result == expected
    assert_readout_shows(ex, expected, precision)
    assert ex.view.state == view_state(expected, precision)


# --------------------------------------------------------------------------- degenerate triangles


@pytest.mark.parametrize(
    ("a", "b", "c", "word"),
    [
        ((0, 0, 0), (1, 1, 1), (2, 2, 2), "collinear"),
        ((1, 2, 3), (1, 2, 3), (0, 1, 0), "coincide"),
        ((0.5, 0.5, 0.5), (0.5, 0.5, 0.5), (0.5, 0.5, 0.5), "same point"),
        ((-1, 0, 2), (1, 1, 1), (3, 2, 0), "collinear"),
    ],
)
def test_degenerate_positions_explain_instead_of_failing(a, b, c, word):
    ex = Explorer()
    move(ex, a, b, c)
    expected = triangle_normal(*decimal((a, b, c)))
    assert expected.degenerate
    assert ex.result == expected and ex.result.unit_normal is None
    assert_readout_shows(ex, expected, 4)
    assert word in ex.readout.value
    assert "No unit normal" in ex.readout.value
    assert ex.readout.value.count("undefined") >= 2  # unit normal and plane
    assert ex.view.state["degenerate"] and ex.view.state["unit_normal"] is None
    assert ex.view.state["status"] == expected.format()["status"]
    assert not ex.snapshot._artists["arrow_N"].get_visible()
    assert ex.to_png().startswith(b"\x89PNG")
    move(ex, (0, 0, 0), (1, 0, 0), (0, 1, 0))  # and back to a proper triangle
    assert not ex.result.degenerate and ex.snapshot._artists["arrow_N"].get_visible()
    assert "undefined" not in ex.readout.value


def test_a_failure_inside_the_callback_becomes_a_message(monkeypatch):
    ex = Explorer()
    good = ex.result

    def broken(*args, **kwargs):
        raise RuntimeError("something broke")

    monkeypatch.setattr(tw, "triangle_normal", broken)
    ex.controls["bx"].value = 2  # must not raise
    assert "Could not compute the normal" in ex.readout.value
    assert "something broke" in ex.readout.value
    assert ex.result is good


# --------------------------------------------------------------------------- precision


def test_precision_changes_the_readout_only():
    ex = Explorer(a=(1, 1, 1), b=(2, 1, 1), c=(1, 2, 2))
    result = ex.result
    for p in range(16):
        ex.controls["precision"].value = p
        assert ex.result == result
        assert_readout_shows(ex, triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2)), p)
        assert f"({p} decimal place" in ex.readout.value
    ex.controls["precision"].value = 0
    assert "1.4142" not in ex.readout.value
    ex.controls["precision"].value = 4
    assert "1.4142" in ex.readout.value


# --------------------------------------------------------------------------- out of range


@pytest.mark.parametrize(
    ("key", "value", "message"),
    [
        ("bx", 99, r"B\.x = 99 is outside the slider range -5 to 5"),
        ("az", -5.01, r"A\.z = -5\.01 is outside"),
        ("cy", math.inf, r"C\.y is infinite"),
        ("cy", math.nan, r"C\.y is NaN"),
        ("precision", 16, r"precision must be from 0 to 15"),
        ("precision", -1, r"precision must be from 0 to 15"),
        ("winding", "CBA", r"winding must be 'ABC' or 'ACB'"),
    ],
)
def test_out_of_range_values_are_a_value_error_not_a_clamp(key, value, message):
    ex = Explorer(b=(2, 0, 0), c=(0, 3, 0))
    before = (ex.controls[key].value, ex.result, ex.readout.value)
    with pytest.raises(ValueError, match=message):
        ex.controls[key].value = value
    assert (ex.controls[key].value, ex.result, ex.readout.value) == before


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"b": (6, 0, 0)}, r"B\.x = 6 is outside"),
        ({"c": (0, 0, -7)}, r"C\.z = -7 is outside"),
        ({"a": (0, 0)}, r"A has 2 coordinates"),
        ({"precision": 16}, r"precision"),
        ({"winding": "BAC"}, r"winding must be 'ABC' or 'ACB', got 'BAC'"),
    ],
)
def test_bad_starting_values_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        Explorer(**kwargs)


@pytest.mark.parametrize("precision", [2.5, "two", True])
def test_precision_is_checked_as_everywhere_else(precision):
    # one check, one message: the explorer refuses what the core's formatter refuses
    with pytest.raises((TypeError, ValueError)) as core:
        triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).format(precision)
    with pytest.raises(core.type, match=re.escape(str(core.value))):
        Explorer(precision=precision)


def test_set_moves_several_controls_and_checks_them_all_first():
    ex = Explorer()
    ex.set(a=(1, 1, 1), b=(2, 1, 1), c=(1, 2, 2), winding="ACB", precision=2)
    expected = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2), winding="ACB")
    assert ex.result == expected
    assert_readout_shows(ex, expected, 2)
    with pytest.raises(ValueError, match=r"C\.x = 8"):
        ex.set(a=(0, 0, 0), c=(8, 0, 0))
    assert ex.result == expected and ex.a == (1.0, 1.0, 1.0)


def test_values_are_kept_exactly_as_set():
    ex = Explorer()
    for value in (0.1 + 0.2, 1 / 3, 1 + 1e-15, 2.0782859294754533e-277, -5.0, 5.0):
        ex.controls["bx"].value = value
        assert ex.controls["bx"].value == value
        assert ex.result.b[0] == value


# --------------------------------------------------------------------------- the figure


def test_figure_is_updated_in_place():
    ex = Explorer()
    axes = list(ex.figure.axes)
    artists = dict(ex.snapshot._artists)
    ex.set(a=(1, 1, 1), b=(2, 1, 1), c=(1, 2, 2), winding="ACB")
    assert ex.figure.axes == axes
    assert all(ex.snapshot._artists[k] is v for k, v in artists.items())
    r = ex.result
    heights = [bar.get_height() for bar in ex.snapshot._artists["bars_n"]]
    assert heights == list(r.normal)
    unit = [bar.get_height() for bar in ex.snapshot._artists["bars_u"]]
    assert unit == list(r.unit_normal)
    xs, ys, zs = ex.snapshot._artists["edges"].get_data_3d()
    assert list(zip(xs, ys, zs, strict=True)) == [r.a, r.b, r.c, r.a]
    # the U arrow starts at A and ends at B (order A→C→B: U = C − A, so it ends at C)
    shaft = ex.snapshot._artists["arrow_U"]._segments3d[0]
    assert tuple(shaft[0]) == r.a and tuple(shaft[1]) == r.c


def test_three_d_view_has_equal_scales_and_labels():
    ex = Explorer(a=(-4, 1, 0), b=(3, -2, 1), c=(0, 4, -3))
    ax3 = ex.snapshot._artists["ax3"]
    limits = {ax3.get_xlim(), ax3.get_ylim(), ax3.get_zlim()}
    assert len(limits) == 1
    low, high = limits.pop()
    assert low == -high and high >= 4
    aspect = ax3.get_box_aspect()
    assert aspect[0] == aspect[1] == aspect[2]
    for name in "ABC":
        assert ex.snapshot._artists["label_" + name].get_marker() is not None
    assert {ex.snapshot._artists["tip_" + n].get_visible() for n in "UVN"} == {True}


def test_blitted_picture_equals_a_full_redraw():
    ex = Explorer()
    rng = np.random.default_rng(5)
    for i in range(8):
        ex.controls[KEYS[i % 9]].value = float(np.round(rng.uniform(-5, 5), 1))
        if i == 5:
            ex.set(b=ex.a)  # degenerate: the N arrow disappears
        ex.render()
        blitted = np.asarray(ex.snapshot._canvas.buffer_rgba()).copy()
        ex.snapshot._canvas.draw()  # the whole figure, every artist, from scratch
        full = np.asarray(ex.snapshot._canvas.buffer_rgba()).copy()
        assert np.array_equal(blitted, full), i


def test_each_axes_stays_inside_its_band():
    ex = Explorer(a=(-5, -5, -5), b=(5, -5, 5), c=(-5, 5, 5))  # the widest labels
    ex.render()
    renderer = ex.snapshot._canvas.get_renderer()
    width, height = renderer.width, renderer.height
    for band, key in (("3d", "ax3"), ("n", "ax_n"), ("u", "ax_u")):
        box = ex.snapshot._artists[key].get_tightbbox(renderer)
        limits = ex.snapshot._band_bbox(band, width, height)
        assert limits.x0 <= box.x0 and box.x1 <= limits.x1, band
        assert limits.y0 <= box.y0 and box.y1 <= limits.y1, band


def test_png_changes_with_the_triangle():
    ex = Explorer()
    first = ex.to_png()
    ex.controls["cz"].value = 2
    second = ex.to_png()
    assert first != second
    image = Image.open(io.BytesIO(second))
    assert image.format == "PNG" and image.size == (648, 288)


def test_figure_can_be_saved_in_full_by_matplotlib():
    ex = Explorer(a=(1, 1, 1), b=(2, 1, 1), c=(1, 2, 2))
    buf = io.BytesIO()
    ex.figure.savefig(buf, format="png", dpi=100)
    assert buf.getvalue().startswith(b"\x89PNG")
    assert "B = (2, 1, 1)" in ex.figure.alt_text
    ex.controls["bx"].value = 3  # the blitting path still works after another dpi
    ex.render()
    blitted = np.asarray(ex.snapshot._canvas.buffer_rgba()).copy()
    ex.snapshot._canvas.draw()
    assert np.array_equal(blitted, np.asarray(ex.snapshot._canvas.buffer_rgba()))


# --------------------------------------------------------------------------- display


def test_display_bundle_is_the_one_view_with_a_plain_text_summary():
    ex = Explorer(precision=2)
    shown = ex._repr_mimebundle_()
    bundle = shown[0] if isinstance(shown, tuple) else shown
    view = bundle["application/vnd.jupyter.widget-view+json"]
    # one widget: the controls are drawn by the view's module, no second widget can echo
    assert view["model_id"] == ex.view.model_id and ex.widget is ex.view
    assert ex.view.show_controls
    assert bundle["text/plain"] == ex.summary()
    f = ex.result.format(2)
    for key in ("u", "v", "normal", "magnitude", "area", "unit_normal", "plane", "status"):
        assert f[key] in bundle["text/plain"]


def test_repr_names_the_state():
    ex = Explorer(a=(0.5, 0, 0), winding="ACB", precision=3)
    assert (
        repr(ex)
        == "Explorer(a=('0.5', 0, 0), b=(1, 0, 0), c=(0, 1, 0), winding='ACB', precision=3)"
    )


def test_repr_is_exact_and_recreates_the_explorer():
    ex = Explorer(a=("0.1", "1e-3", -2), b=("-1/3", 0, 0), c=(0, "2.350", Fraction(7, 3)))
    text = repr(ex)
    assert text == (
        "Explorer(a=('0.1', '0.001', -2), b=('-1/3', 0, 0), c=(0, '2.35', '7/3'), "
        "winding='ABC', precision=4)"
    )
    assert "0.333" not in text
    again = eval(text, {"Explorer": Explorer})
    assert again.result.exact == ex.result.exact
    assert repr(again) == text


# --------------------------------------------------------------------------- exactness


def test_exact_values_set_by_code_stay_exact_everywhere():
    ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
    assert ex.result.exact.a == (Fraction(1, 10), Fraction(1, 5), Fraction(3, 10))
    assert ex.result.exact.b[0] == Fraction(1, 3)
    assert ex.result.exact.c[1] == Fraction(47, 20)
    assert (ex.view.a, ex.view.b, ex.view.c) == (
        ["0.1", "0.2", "0.3"],
        ["1/3", "0", "0"],
        ["0", "2.35", "0"],
    )
    assert [ex.inputs[k].value for k in ("ax", "bx", "cy")] == ["0.1", "1/3", "2.35"]
    assert ex.result == triangle_normal(("0.1", "0.2", "0.3"), ("1/3", 0, 0), (0, "2.35", 0))


def test_a_slider_moved_in_the_browser_lands_exactly_on_the_grid():
    # the view sends the grid point as text ("3.3"), never the float 3.3000000000000007
    ex = Explorer()
    assert edit(ex, {"bx": "3.3"})["ok"]
    assert ex.texts["bx"] == "3.3" and ex.result.exact.b[0] == Fraction(33, 10)
    assert ex.inputs["bx"].value == "3.3" and ex.view.b == ["3.3", "0", "0"]


# --------------------------------------------------------------------------- the edit protocol


def test_code_makes_new_versions_and_browser_edits_do_not():
    ex = Explorer()
    v0 = ex.view.version
    ex.set(b=(2, 0, 0))
    v1 = ex.view.version
    assert v1 > v0
    ex.view.show_parallelogram = True  # a trait set from a cell is the kernel's too
    assert ex.view.version > v1
    v2 = ex.view.version
    answer = edit(ex, {"cy": "2"})
    assert answer == {
        "view": "w1",
        "seq": edit.seq,
        "ok": True,
        "stale": False,
        "overwritten": [],
        "error": "",
    }
    assert ex.view.version == v2 and ex.result.exact.c == (0, 2, 0)


def test_an_edit_made_before_a_cell_set_values_is_refused():
    # Run All: the browser answers an old state after a later cell has set a new one
    ex = Explorer(c=(0, 1, 0))
    old = ex.view.version
    ex.set(a=(0, 0, 0), b=(1, 0, 0), c=(0, "1/3", 0))  # the last cell
    answer = edit(ex, {"cy": "0.3"}, base=old)  # the late answer
    assert answer["ok"] is False and answer["stale"] is True
    assert ex.result.exact.c == (0, Fraction(1, 3), 0) and ex.view.c == ["0", "1/3", "0"]
    assert ex.message.value == ""  # a stale edit is dropped quietly


def test_fifty_sets_then_a_final_one_leave_the_final_triangle():
    ex = Explorer()
    versions = []
    for i in range(50):
        ex.set(c=(0, f"{i % 10}/7", 0))
        versions.append(ex.view.version)
    assert versions == sorted(set(versions))  # every set is a new version
    stale = [edit(ex, {"cy": "0.1"}, base=v) for v in versions[:-1]]
    ex.set(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0))
    late = edit(ex, {"cy": "0.2"}, base=versions[-1])
    assert not any(a["ok"] for a in [*stale, late])
    assert ex.result.exact == triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).exact
    assert ex.view.state == view_state(ex.result, 4)


def test_two_views_share_one_model():
    ex = Explorer()
    assert edit(ex, {"ax": "0.5"}, view="first")["ok"]
    assert edit(ex, {"bx": "2"}, view="second")["ok"]  # same version: both taken
    assert ex.view.a == ["0.5", "0", "0"] and ex.view.b == ["2", "0", "0"]
    assert ex.view.last_edit["view"] == "second"


def test_two_views_editing_one_vertex_at_once_keep_both_edits():
    # one explorer shown twice: view 1 types A.x, view 2 presses the arrow key that moves
    # A.y before view 1's edit has come back; each names only its coordinate, so both land
    ex = Explorer(a=("0.1", "0.2", "0.3"))
    base = ex.view.version
    first = edit(ex, {"ax": "1/3"}, base=base, view="one")
    second = edit(ex, {"ay": "0.3"}, base=base, view="two")
    assert first["ok"] and second["ok"] and ex.view.version == base
    assert ex.result.exact.a == (Fraction(1, 3), Fraction(3, 10), Fraction(3, 10))
    assert ex.view.a == ["1/3", "0.3", "0.3"] and ex.texts["az"] == "0.3"
    assert ex.result == triangle_normal(("1/3", "0.3", "0.3"), (1, 0, 0), (0, 1, 0))


def test_a_drag_and_a_typed_value_on_one_vertex_from_two_views_both_land():
    # view 2 types C.z exactly; view 1 drags C in the plane it looks along z: C.x and C.y
    ex = Explorer(c=(0, 1, "1/7"))
    base = ex.view.version
    assert edit(ex, {"cz": "2/7"}, base=base, view="two")["ok"]
    assert edit(ex, {"cx": "0.4", "cy": "1.3"}, base=base, view="one")["ok"]
    assert ex.result.exact.c == (Fraction(2, 5), Fraction(13, 10), Fraction(2, 7))


def test_one_coordinate_edited_in_two_views_keeps_the_edit_that_arrives_last():
    ex = Explorer()
    base = ex.view.version
    assert edit(ex, {"bx": "2"}, base=base, view="one")["ok"]
    assert edit(ex, {"bx": "-1/3"}, base=base, view="two")["ok"]
    assert ex.view.b == ["-1/3", "0", "0"] and ex.result.exact.b[0] == Fraction(-1, 3)
    assert ex.view.last_edit["view"] == "two"


def test_an_edit_keeps_what_no_cell_set_since_and_loses_what_a_cell_set():
    # a cell sets B between two edits of one view: of the edit made before it, B.z (which
    # the cell set) keeps the cell's value and A.y (which no cell set) is kept, quietly;
    # the view's next edit of B, made against the new version, is taken
    ex = Explorer()
    old = ex.view.version
    assert edit(ex, {"ax": "0.5"}, base=old, view="one")["ok"]  # not a new version
    ex.set(b=("1/3", "2/3", 0))
    answer = edit(ex, {"bz": "0.4", "ay": "0.1"}, base=old, view="one")
    assert answer["ok"] is True and answer["stale"] is True and answer["seq"] == edit.seq
    assert answer["overwritten"] == ["bz"]
    assert ex.view.a == ["0.5", "0.1", "0"] and ex.view.b == ["1/3", "2/3", "0"]
    assert ex.message.value == ""
    assert edit(ex, {"bz": "0.4"}, view="one")["ok"]
    assert ex.result.exact.b == (Fraction(1, 3), Fraction(2, 3), Fraction(2, 5))


def test_the_view_alone_applies_edits_per_coordinate_all_or_nothing():
    v = ExplorerView()
    v._handle_custom_msg({"edit": {"ay": "2", "cz": "1"}, "seq": 1, "view": "w", "base": 0}, [])
    assert v.a == ["0", "2", "0"] and v.c == ["0", "1", "1"] and v.last_edit["ok"]
    v._handle_custom_msg({"edit": {"ax": "3", "winding": 5}, "seq": 2, "view": "w", "base": 0}, [])
    assert v.last_edit["ok"] is False and "winding" in v.last_edit["error"]
    assert v.a == ["0", "2", "0"] and v.winding == "ABC" and v.version == 0


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"ax": 0.5}, r"A\.x must be sent as text"),
        ({"a": ["0.5", "0", "0"]}, r"unknown field 'a'"),  # a coordinate is named by its key
        ({"ax": "0.5", "ay": "abc"}, r"A\.y = 'abc' is not a number"),  # all or nothing
        ({"zz": "1"}, r"unknown field 'zz'"),
        ({"winding": "CBA"}, r"winding must be 'ABC' or 'ACB'"),
        ({"precision": 99}, r"precision must be from 0 to 15"),
        ({"show_unit_normal": "yes"}, r"show_unit_normal must be true or false"),
    ],
)
def test_a_malformed_edit_is_refused_with_a_message(changes, message):
    ex = Explorer()
    before = (ex.result, ex.view.version)
    answer = edit(ex, changes)
    assert answer["ok"] is False and re.search(message, answer["error"])
    assert re.search(message, ex.view.message) and (ex.result, ex.view.version) == before


def test_toggles_and_precision_from_the_view():
    ex = Explorer()
    assert edit(ex, {"show_unit_normal": True, "precision": 2})["ok"]
    assert ex.view.show_unit_normal and ex.precision == 2 and ex.view.precision == 2


def test_dragging_a_vertex_in_the_view_updates_every_surface():
    ex = Explorer(precision=3)
    edit(ex, {"cx": "0.4", "cy": "1.1", "cz": "-0.7"})  # a drag moves up to three coordinates
    expected = triangle_normal((0, 0, 0), (1, 0, 0), ("0.4", "1.1", "-0.7"))
    assert ex.result == expected and ex.result.exact.c == (
        Fraction(2, 5),
        Fraction(11, 10),
        Fraction(-7, 10),
    )
    assert [ex.inputs[k].value for k in ("cx", "cy", "cz")] == ["0.4", "1.1", "-0.7"]
    assert [ex.controls[k].value for k in ("cx", "cy", "cz")] == [0.4, 1.1, -0.7]
    assert ex.view.state == view_state(expected, 3)
    assert_readout_shows(ex, expected, 3)


def test_the_view_flips_the_winding():
    ex = Explorer()
    edit(ex, {"winding": "ACB"})
    assert ex.result.winding is Winding.ACB and ex.controls["winding"].value == "ACB"
    assert ex.view.state["normal"] == [0.0, 0.0, -1.0]
    assert [row["label"] for row in ex.view.state["readout"][:2]] == ["U = C − A", "V = B − A"]


def test_a_bad_move_from_the_view_is_refused_and_the_view_keeps_the_kernel_values():
    ex = Explorer()
    before = ex.result
    edit(ex, {"ax": "9"})
    assert ex.result is before and ex.view.a == ["0", "0", "0"]
    assert "A.x = 9 is outside the slider range -5 to 5" in ex.message.value
    assert ex.view.message.startswith("A.x = 9 is outside")
    edit(ex, {"by": "nan"})
    assert ex.result is before and ex.view.b == ["1", "0", "0"]
    assert "B.y" in ex.message.value and "NaN" in ex.message.value


@pytest.mark.parametrize(
    ("typed", "value"),
    [("1/3", Fraction(1, 3)), (" -2.35 ", Fraction(-47, 20)), ("2.5e-1", Fraction(1, 4)), ("4", 4)],
)
def test_typing_a_coordinate_reads_it_exactly(typed, value):
    ex = Explorer()
    assert edit(ex, {"by": typed})["ok"]
    assert ex.result.exact.b[1] == value and ex.message.value == ""
    assert ex.controls["by"].value == float(value)


@pytest.mark.parametrize(
    ("typed", "message"),
    [("abc", r"B\.y"), ("7", r"B\.y = 7 is outside the slider range -5 to 5"), ("1/0", r"B\.y")],
)
def test_a_typo_gets_a_message_naming_the_field_and_changes_nothing(typed, message):
    ex = Explorer()
    before = ex.result
    edit(ex, {"by": typed})
    assert ex.result is before
    assert re.search(message, ex.message.value), ex.message.value
    assert "nan" not in ex.readout.value.lower()
    ex.inputs["by"].value = "0.5"  # fixing it clears the message
    assert ex.message.value == "" and ex.view.message == ""
    assert ex.result.exact.b[1] == Fraction(1, 2)


def test_view_state_follows_the_contract():
    r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    state = view_state(r, 4)
    assert set(state) == {
        "ok",
        "error",
        "points",
        "u",
        "v",
        "normal",
        "unit_normal",
        "degenerate",
        "status",
        "readout",
        "summary",
    }
    assert state["points"] == {"A": [1.0, 1.0, 1.0], "B": [2.0, 1.0, 1.0], "C": [1.0, 2.0, 2.0]}
    f = r.format(4)
    assert [(row["key"], row["value"]) for row in state["readout"]] == [
        (k, f[k]) for k in ("u", "v", "normal", "magnitude", "area", "unit_normal", "plane")
    ]
    json.dumps(state)  # the view receives it as JSON


def test_the_view_module_is_the_bundle_shipped_in_the_package():
    assert BUNDLE.is_file() and BUNDLE.name == "explorer.js"
    assert "render" in BUNDLE.read_text(encoding="utf-8")
    assert "https://" not in ExplorerView()._esm.split("import")[0]


def test_the_colour_code_is_the_package_one():
    from trinormal.colors import palette

    assert Explorer().view.palette == palette()


def test_an_off_grid_value_stays_until_someone_moves_it():
    ex = Explorer(b=("1/3", 0, 0), c=(0, "2.35", 0))
    assert ex.view.b == ["1/3", "0", "0"] and ex.controls["bx"].value == 1 / 3
    edit(ex, {"cy": "2.4"})  # the student moves the C.y slider one notch
    assert ex.texts["cy"] == "2.4" and ex.result.exact.c[1] == Fraction(12, 5)
    assert ex.result.exact.b[0] == Fraction(1, 3)
