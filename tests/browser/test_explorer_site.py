"""The 3D view on the site: a real WebGL canvas, orbit, vertex drag, keys, degenerate, themes.

The view is built from the same sources as JupyterLab's (``assets/explorer/explorer.js``), driven on
the calculator page by the form and the site's exact core. What a reader relies on: turning
the view never changes the numbers; dragging a vertex or pressing an arrow key changes that
vertex's boxes, the results (the same strings as Python) and the address; a degenerate
triangle is explained, never drawn with NaN; both palettes render; nothing leaves the site.
"""

from __future__ import annotations

import io
import json
import math
import re
from urllib.parse import parse_qs, urlsplit

import pytest
from page_checks import resize
from PIL import Image

from trinormal import triangle_normal
from trinormal.colors import palette
from trinormal.fields import FIELDS as FIELDS_SPEC
from trinormal.plotting.scale import scaled_label

FIELDS = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"]
OUTPUTS = {f.key: "#" + f.output_id for f in FIELDS_SPEC}
GRID_TEXT = re.compile(r"-?\d+\.\d")  # a value the view wrote: on the 0.1 grid, one decimal
URL_SHOWS_A = """() => {
  const a = ['ax', 'ay', 'az'].map(id => document.getElementById(id).value).join(',');
  return new URLSearchParams(location.search).get('a') === a && a !== '0,0,0';
}"""


def open_view(page, url: str) -> None:
    page.goto(url)
    page.wait_for_selector("#tn-calculator[data-ready='true']")
    page.wait_for_selector("#tn-view[data-ready='true']")
    page.wait_for_load_state("networkidle")
    page.locator("#tn-view canvas").evaluate("c => c.scrollIntoView({block: 'center'})")
    settle(page)


def settle(page) -> None:
    """Wait until the view has drawn what it was asked to (two animation frames)."""
    page.evaluate(
        "() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(() => r())))"
    )


@pytest.fixture
def view(page, server, traffic):
    page.set_viewport_size({"width": 1280, "height": 900})
    open_view(page, server + "calculator/")
    yield page
    assert not traffic.problems()
    assert not traffic.off_origin


def inputs(page) -> list[str]:
    return [page.locator("#" + f).input_value() for f in FIELDS]


def outputs(page) -> dict[str, str]:
    return {key: page.locator(sel).inner_text() for key, sel in OUTPUTS.items()}


def python_outputs(values: list[str], winding: str = "ABC", precision: int = 4) -> dict[str, str]:
    a, b, c = values[0:3], values[3:6], values[6:9]
    f = triangle_normal(a, b, c, winding=winding).format(precision)
    return {key: f[key] for key in OUTPUTS}


def canvas_png(page) -> bytes:
    settle(page)
    return page.locator("#tn-view canvas").screenshot()


def centre(page, selector: str) -> tuple[float, float]:
    box = page.locator(selector).bounding_box()
    assert box is not None, selector
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def query(page) -> dict[str, list[str]]:
    return parse_qs(urlsplit(page.evaluate("location.href")).query)


def test_the_view_is_webgl_turns_without_changing_the_numbers_and_takes_both_palettes(
    view, traffic
):
    """Three checks on one visit, each leaving the view as it found it (a failure says which)."""
    _a_webgl_view_served_from_the_site(view, traffic)
    _orbiting_changes_the_picture_but_not_the_numbers(view)
    _light_and_dark_palettes_both_render(view)


def _a_webgl_view_served_from_the_site(view, traffic) -> None:
    canvas = view.locator("#tn-view canvas")
    assert canvas.count() == 1
    kind = canvas.evaluate(
        "c => c.getContext('webgl2') ? 'webgl2' : c.getContext('webgl') ? 'webgl' : null"
    )
    assert kind in ("webgl2", "webgl")
    size = canvas.bounding_box()
    assert size is not None and size["width"] >= 480 and size["height"] >= 300
    assert any(u.endswith("/assets/explorer/explorer.js") for u in traffic.requests)
    # labels A, B, C are HTML over their points: visible, focusable, at least 14 px
    for name in "ABC":
        label = view.locator(f'[data-vertex="{name}"]')
        assert label.is_visible()
        assert label.get_attribute("tabindex") == "0"
        assert name in label.get_attribute("aria-label")
        px = label.evaluate("e => parseFloat(getComputedStyle(e).fontSize)")
        assert px >= 14
    # the toolbar is made of real buttons
    buttons = view.locator("#tn-view .tnx-toolbar button")
    names = buttons.evaluate_all("bs => bs.map(b => b.getAttribute('aria-label') || b.textContent)")
    for name in ("Reset view", "View along the x axis", "View along the y axis"):
        assert name in names
    assert "View along the z axis" in names
    # the first picture frames the triangle (the Reset and new-triangle cases are below)
    assert_framed(view)


def _orbiting_changes_the_picture_but_not_the_numbers(view) -> None:
    before_inputs, before_out, before_url = inputs(view), outputs(view), view.url
    before = canvas_png(view)
    box = view.locator("#tn-view canvas").bounding_box()
    assert box is not None
    x, y = box["x"] + 30, box["y"] + 30  # a corner: empty space, far from A, B and C
    view.mouse.move(x, y)
    view.mouse.down()
    view.mouse.move(x + 160, y + 60, steps=12)
    view.mouse.up()
    after = canvas_png(view)
    assert after != before, "dragging empty space did not turn the view"
    assert inputs(view) == before_inputs
    assert outputs(view) == before_out
    assert view.url == before_url
    # reset brings the first picture back
    view.get_by_role("button", name="Reset view").click()
    assert canvas_png(view) == before


def test_dragging_vertex_a_moves_a_and_updates_results_and_url(view):
    assert inputs(view)[:3] == ["0", "0", "0"]
    x, y = centre(view, '#tn-view [data-vertex="A"]')
    view.mouse.move(x, y)
    view.mouse.down()
    view.mouse.move(x - 40, y + 50, steps=6)
    # during the drag: the boxes already follow
    view.wait_for_function("['ax','ay','az'].some(id => document.getElementById(id).value !== '0')")
    view.mouse.move(x - 90, y + 110, steps=10)
    # the address follows too, once the pointer rests
    view.wait_for_function(URL_SHOWS_A)
    view.mouse.up()
    view.wait_for_function(URL_SHOWS_A)
    values = inputs(view)
    a, rest = values[:3], values[3:]
    assert a != ["0", "0", "0"]
    assert rest == ["1", "0", "0", "0", "1", "0"], "only A may move"
    for text in a:
        assert text == "0" or GRID_TEXT.fullmatch(text), f"A moved off the 0.1 grid: {text!r}"
    assert outputs(view) == python_outputs(values)
    assert query(view)["a"] == [",".join(a)]
    assert query(view)["b"] == ["1,0,0"] and query(view)["c"] == ["0,1,0"]


def test_arrow_keys_move_the_focused_vertex_one_step_and_stop_at_the_range(view):
    """Two checks of B's keys on one visit: steps on the grid, then the range's edge."""
    _arrow_keys_move_the_focused_vertex_one_step(view)
    _keys_stop_at_the_range_and_never_rewrite_a_value(view)


def _arrow_keys_move_the_focused_vertex_one_step(view) -> None:
    label = view.locator('#tn-view [data-vertex="B"]')
    label.focus()
    label.press("ArrowRight")
    assert view.locator("#bx").input_value() == "1.1"
    label.press("ArrowUp")
    assert view.locator("#by").input_value() == "0.1"
    label.press("PageDown")
    assert view.locator("#bz").input_value() == "-0.1"
    label.press("ArrowLeft")
    label.press("ArrowLeft")
    assert view.locator("#bx").input_value() == "0.9"
    values = inputs(view)
    assert values[3:6] == ["0.9", "0.1", "-0.1"]
    assert values[:3] == ["0", "0", "0"] and values[6:] == ["0", "1", "0"]
    assert outputs(view) == python_outputs(values)
    view.wait_for_function("() => new URLSearchParams(location.search).get('b') === '0.9,0.1,-0.1'")


def _keys_stop_at_the_range_and_never_rewrite_a_value(view) -> None:
    view.fill("#bx", "5")  # the edge of the view's range, -5 to 5
    label = view.locator('#tn-view [data-vertex="B"]')
    label.focus()
    label.press("ArrowRight")
    assert view.locator("#bx").input_value() == "5"  # not "5.0", not "5.1"
    label.press("ArrowLeft")
    assert view.locator("#bx").input_value() == "4.9"
    assert outputs(view) == python_outputs(inputs(view))


def test_a_typed_value_moves_the_view_and_keeps_its_exact_text(view):
    before = canvas_png(view)
    view.fill("#cz", "1/3")
    after = canvas_png(view)
    assert after != before
    # a key press on another axis of C leaves the exact 1/3 alone
    label = view.locator('#tn-view [data-vertex="C"]')
    label.focus()
    label.press("ArrowRight")
    assert inputs(view)[6:] == ["0.1", "1", "1/3"]
    assert outputs(view) == python_outputs(inputs(view))


def test_a_degenerate_triangle_is_explained_without_nan(view):
    view.fill("#cx", "2")
    view.fill("#cy", "0")  # C on the line through A and B
    settle(view)
    message = view.locator("#tn-view .tnx-message")
    assert message.is_visible()
    status = view.locator("#out-status").inner_text()
    assert status.startswith("Degenerate: A, B and C are collinear")
    assert message.inner_text() == status
    text = view.locator("#tn-view").inner_text()
    labels = view.locator("#tn-view [aria-label]").evaluate_all(
        "els => els.map(e => e.getAttribute('aria-label')).join(' ')"
    )
    for word in ("NaN", "Infinity", "undefined"):
        assert word not in text and word not in labels
    assert not view.locator("#tn-view .tnx-arrow", has_text=re.compile(r"^N$")).is_visible()
    # moving C off the line brings the normal back
    label = view.locator('#tn-view [data-vertex="C"]')
    label.focus()
    label.press("ArrowUp")
    assert view.locator("#cy").input_value() == "0.1"
    assert not message.is_visible()
    assert outputs(view) == python_outputs(inputs(view))


def _corner(png: bytes) -> tuple[int, int, int]:
    img = Image.open(io.BytesIO(png)).convert("RGB")
    return img.getpixel((4, img.height - 4))


def _light_and_dark_palettes_both_render(view) -> None:
    light = canvas_png(view)
    view.evaluate("document.body.setAttribute('data-md-color-scheme', 'slate')")
    dark = canvas_png(view)
    assert light != dark
    assert sum(_corner(light)) > 3 * 200, "the light view is not light"
    assert sum(_corner(dark)) < 3 * 80, "the dark view is not dark"
    # the vertex labels take the dark palette's colours (from trinormal.colors)
    colour = view.locator('#tn-view [data-vertex="B"]').evaluate("e => getComputedStyle(e).color")
    want = palette()["B"]["dark"]
    rgb = tuple(int(want[i : i + 2], 16) for i in (1, 3, 5))
    assert colour == f"rgb({rgb[0]}, {rgb[1]}, {rgb[2]})"
    view.evaluate("document.body.setAttribute('data-md-color-scheme', 'default')")
    assert sum(_corner(canvas_png(view))) > 3 * 200, "switching back did not restore the light view"


def test_the_explorer_notebook_page_has_a_live_view(page, server, traffic):
    page.goto(server + "notebooks/05_explorer/")
    page.wait_for_selector(".tn-explorer-live[data-ready='true']")
    live = page.locator(".tn-explorer-live").first
    assert live.locator("canvas").count() == 1
    assert live.locator("noscript").count() == 1  # the picture stays for readers without scripts
    start = json.loads(live.get_attribute("data-explorer") or "{}")
    f = triangle_normal(start["a"], start["b"], start["c"], winding=start["winding"]).format(
        start.get("precision", 4)
    )
    rows = live.locator(".tnx-readout tr").evaluate_all(
        "rs => rs.map(r => [r.dataset.key, r.cells[1].textContent])"
    )
    assert [key for key, _ in rows] == [field.key for field in FIELDS_SPEC]
    assert all(value == f[key] for key, value in rows)
    # a key press moves the page's own triangle and its readout follows, exactly
    label = live.locator('[data-vertex="C"]')
    label.focus()
    label.press("ArrowRight")
    moved = triangle_normal(start["a"], start["b"], _right(start["c"]), winding=start["winding"])
    value = live.locator(".tnx-readout tr[data-key='u'] td").inner_text()
    assert value == moved.format(start.get("precision", 4))["u"]
    assert not traffic.problems()


def _right(point: list[str]) -> list[str]:
    """A point after one ArrowRight on the 0.1 grid (for values already on it)."""
    x = round(float(point[0]) * 10) + 1
    return [f"{x / 10:.1f}", *point[1:]]


def test_the_views_order_button_flips_the_calculator(view):
    button = view.locator("#tn-view").get_by_role("button", name=re.compile("^Flip the order"))
    assert button.inner_text() == "⇄ A→B→C"
    button.click()
    assert view.locator("#winding").input_value() == "ACB"
    assert button.inner_text() == "⇄ A→C→B"
    assert outputs(view) == python_outputs(inputs(view), winding="ACB")
    assert query(view)["w"] == ["ACB"]
    # turned over, N points the other way: Reset frames the triangle with N's head in view
    view.get_by_role("button", name="Reset view").click()
    settle(view)
    assert_framed(view)
    # and the form's own flip turns the view back
    view.click("#tn-flip")
    assert button.inner_text() == "⇄ A→B→C"


def test_results_sit_beside_the_inputs_on_wide_screens_and_under_them_on_phones(
    page, server, traffic
):
    """Opened on a phone, then widened to a desktop (one visit, both widths)."""
    page.set_viewport_size({"width": 360, "height": 800})
    open_view(page, server + "calculator/")
    for width in (360, 1280):
        if width != 360:
            resize(page, width, 800)
            settle(page)
        _results_beside_or_under_the_inputs(page, width)
    assert not traffic.problems()


def _results_beside_or_under_the_inputs(page, width: int) -> None:
    assert page.evaluate("document.documentElement.scrollWidth") <= width, (
        f"{width} px: horizontal scroll"
    )
    form = page.locator(".tn-form").bounding_box()
    results = page.locator(".tn-calc-results").bounding_box()
    assert form is not None and results is not None
    if width >= 1280:
        assert results["x"] >= form["x"] + form["width"] - 1, width  # to the right of the inputs
        assert results["y"] < form["y"] + form["height"], width  # level with them
    else:
        assert results["y"] >= form["y"] + form["height"] - 1, width  # directly below
        assert results["y"] - (form["y"] + form["height"]) < 80, width
    n_chart = page.locator("#chart").bounding_box()
    unit_chart = page.locator("#chart-unit").bounding_box()
    assert n_chart is not None and unit_chart is not None
    if width >= 1280:
        assert abs(unit_chart["y"] - n_chart["y"]) < 2, width  # the unit normal's chart beside N's
    assert (
        page.locator("#chart-unit").get_attribute("aria-label")
    ) == "Bar chart of the unit normal components: x = 0.0000, y = 0.0000, z = 1.0000."
    # the view's sliders stand in columns: one per axis on a desktop; on a phone y and z wrap
    # under x, so all nine share one left edge
    lefts = page.evaluate(
        "() => [...document.querySelectorAll('#tn-view .tnx-slider')]"
        ".map(s => Math.round(s.getBoundingClientRect().left))"
    )
    assert len(lefts) == 9
    assert len(set(lefts)) == (3 if width >= 1280 else 1), (width, lefts)
    # the vertex order's whole text fits in its box (a select cannot wrap, it cuts)
    room = page.evaluate(
        """() => {
          const s = document.getElementById('winding'), st = getComputedStyle(s);
          const ctx = document.createElement('canvas').getContext('2d');
          ctx.font = st.font;
          const text = ctx.measureText(s.options[s.selectedIndex].text).width;
          const inner = s.clientWidth - parseFloat(st.paddingLeft) - parseFloat(st.paddingRight);
          return inner - text;
        }"""
    )
    assert room > 16, (width, room)  # what the drop-down arrow needs


def test_without_javascript_the_explorer_page_shows_the_picture(browser, server):
    context = browser.new_context(java_script_enabled=False)
    try:
        page = context.new_page()
        page.goto(server + "notebooks/05_explorer/")
        picture = page.locator(".tn-explorer-live img[src$='assets/images/explorer.png']")
        assert picture.count() >= 1
        assert picture.first.is_visible()
        assert picture.first.get_attribute("alt")
    finally:
        context.close()


# --------------------------------------------------------------------------- framing, overlays

#: Where the view draws A, B, C and the arrow heads (px in the view), and its size.
PROJECTED = "() => document.querySelector('#tn-view .tnx-root').tnxProject()"


def set_triangle(page, a, b, c) -> None:
    for key, point in zip("abc", (a, b, c), strict=True):
        for q, value in zip("xyz", point, strict=True):
            page.fill(f"#{key}{q}", value)
    settle(page)
    settle(page)


def boxes(page, selector: str) -> list[dict[str, float]]:
    """Boxes of the visible elements, cut to the view (which clips the labels at its edges)."""
    stage = page.locator("#tn-view .tnx-stage").bounding_box()
    found = [
        b for b in (e.bounding_box() for e in page.locator(selector).all()) if b and b["width"]
    ]
    cut = []
    for b in found:
        x0, y0 = max(b["x"], stage["x"]), max(b["y"], stage["y"])
        x1 = min(b["x"] + b["width"], stage["x"] + stage["width"])
        y1 = min(b["y"] + b["height"], stage["y"] + stage["height"])
        if x1 > x0 and y1 > y0:
            cut.append({"x": x0, "y": y0, "width": x1 - x0, "height": y1 - y0})
    return cut


def overlaps(a: dict[str, float], b: dict[str, float]) -> bool:
    return not (
        a["x"] + a["width"] <= b["x"]
        or b["x"] + b["width"] <= a["x"]
        or a["y"] + a["height"] <= b["y"]
        or b["y"] + b["height"] <= a["y"]
    )


def assert_framed(page) -> dict[str, list[float]]:
    """The triangle spans at least 40 % of the view's smaller side; nothing is clipped."""
    drawn = page.evaluate(PROJECTED)
    w, h = drawn["width"], drawn["height"]
    corners = [drawn["points"][k] for k in "ABC"]
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    span = max(max(xs) - min(xs), max(ys) - min(ys))
    assert span >= 0.4 * min(w, h), (span, w, h)
    for key, (x, y) in drawn["points"].items():
        assert 0 <= x <= w and 0 <= y <= h, (key, x, y, w, h)
    stage = page.locator("#tn-view .tnx-stage").bounding_box()
    for label in boxes(page, "#tn-view .tnx-vertex:visible, #tn-view .tnx-arrow:visible"):
        assert label["x"] >= stage["x"] and label["y"] >= stage["y"], label
        assert label["x"] + label["width"] <= stage["x"] + stage["width"], label
        assert label["y"] + label["height"] <= stage["y"] + stage["height"], label
    return drawn["points"]


#: Triangles the camera must frame: small, off-centre, far from the origin, huge.
FRAMED = [
    (("0", "0", "0"), ("0.1", "0", "0"), ("0", "0.1", "0")),  # a tenth of the usual size
    (("0.3", "0.1", "0.2"), ("0.1", "0.4", "0"), ("0", "0", "0.3")),
    (("3", "3", "3"), ("3.5", "3", "3"), ("3", "3.5", "3.2")),  # far from the origin
    (("-4", "4", "1"), ("-3", "4.5", "1"), ("-3.6", "3.4", "2")),
    (("-1200", "300", "0"), ("4100", "900", "-800"), ("2500", "3700", "1500")),  # huge
    (("1e6", "1e6", "1e6"), ("1000400", "1e6", "1e6"), ("1e6", "1000300", "1000200")),
]


def test_the_camera_frames_a_new_triangle_and_a_drag_never_moves_it(view):
    """Each triangle of FRAMED typed in turn on one visit (a failure names the triangle)."""
    for triangle in FRAMED:
        try:
            _frame_drag_and_reset(view, triangle)
        except AssertionError as err:
            raise AssertionError(f"triangle {triangle}: {err}") from err


def _frame_drag_and_reset(view, triangle) -> None:
    set_triangle(view, *triangle)
    before = assert_framed(view)
    # dragging A moves A only: B and C stay where they are on the screen (no re-framing)
    x, y = centre(view, '#tn-view [data-vertex="A"]')
    view.mouse.move(x, y)
    view.mouse.down()
    for i in range(1, 6):
        view.mouse.move(x + 4 * i, y - 3 * i)
    view.mouse.up()
    settle(view)
    after = view.evaluate(PROJECTED)["points"]
    for key in ("B", "C"):
        assert after[key] == pytest.approx(before[key], abs=0.5), key
    # Reset view frames it again
    view.get_by_role("button", name="Reset view").click()
    settle(view)
    assert_framed(view)


def test_the_banner_and_the_legend_never_cover_a_label_or_an_arrow(view):
    set_triangle(view, ("0", "0", "0"), ("1", "0", "0"), ("2", "0", "0"))  # collinear
    banner = view.locator("#tn-view .tnx-message")
    assert banner.is_visible()
    labels = boxes(view, "#tn-view .tnx-label:visible")
    assert labels and not any(overlaps(banner.bounding_box(), b) for b in labels)
    set_triangle(view, ("1", "0", "0"), ("3", "1", "0"), ("2", "3", "0"))
    view.get_by_role("button", name="Parallelogram").click()
    settle(view)
    legend = view.locator("#tn-view .tnx-legend")
    assert legend.is_visible() and "|N|" in legend.inner_text()
    stage = view.locator("#tn-view .tnx-stage").bounding_box()
    drawn = view.evaluate(PROJECTED)
    heads = [
        {"x": stage["x"] + x - 4, "y": stage["y"] + y - 4, "width": 8, "height": 8}
        for x, y in drawn["points"].values()
    ]
    for overlay in (legend.bounding_box(), view.locator("#tn-view .tnx-hint").bounding_box()):
        if overlay is None:
            continue
        for b in [*boxes(view, "#tn-view .tnx-label:visible"), *heads]:
            assert not overlaps(overlay, b), (overlay, b)


# --------------------------------------------------------------------------- phones and touch


def swipe(cdp, x: float, y: float, dx: float, dy: float, steps: int = 10) -> None:
    """One finger from (x, y), moving (dx, dy) px a step (CDP touch events)."""
    cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]})
    for i in range(1, steps + 1):
        point = {"x": x + dx * i, "y": y + dy * i}
        cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [point]})
    cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})


def _touch_page(browser, width: int):
    context = browser.new_context(
        viewport={"width": width, "height": 640}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    return context, page


def test_a_swipe_over_the_view_scrolls_the_page_a_tap_activates_it_and_a_pinch_zooms(
    browser, server
):
    context, page = _touch_page(browser, 360)
    messages: list[str] = []
    page.on(
        "console", lambda m: messages.append(m.text) if m.type in ("warning", "error") else None
    )
    try:
        page.goto(server + "calculator/")
        page.wait_for_selector("#tn-view[data-ready='true']")
        page.locator("#tn-view canvas").evaluate("c => c.scrollIntoView({block: 'center'})")
        settle(page)
        cdp = context.new_cdp_session(page)
        box = page.locator("#tn-view .tnx-stage").bounding_box()
        x, y = box["x"] + box["width"] * 0.3, box["y"] + box["height"] * 0.6
        # one finger, downwards over the view: the page scrolls back up
        start = page.evaluate("window.scrollY")
        assert start > 100
        swipe(cdp, x, y, 0, 12)
        page.wait_for_timeout(300)
        assert page.evaluate("window.scrollY") < start - 50
        # a tap activates the view (as a map does); then one finger turns it, not the page
        page.locator("#tn-view canvas").evaluate("c => c.scrollIntoView({block: 'center'})")
        settle(page)
        box = page.locator("#tn-view .tnx-stage").bounding_box()
        x, y = box["x"] + box["width"] * 0.3, box["y"] + box["height"] * 0.6
        for kind, points in (("touchStart", [{"x": x, "y": y}]), ("touchEnd", [])):
            cdp.send("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})
        settle(page)
        assert page.locator("#tn-view .tnx-touch-active").count() == 1
        before = page.evaluate(PROJECTED)["points"]
        scroll = page.evaluate("window.scrollY")
        cdp.send(
            "Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]}
        )
        for i in range(1, 8):
            point = {"x": x + 12 * i, "y": y - 6 * i}
            cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [point]})
        cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
        settle(page)
        assert page.evaluate("window.scrollY") == scroll
        assert page.evaluate(PROJECTED)["points"]["A"] != before["A"]  # the view turned
        # two fingers apart: the view zooms in (the triangle grows on the screen)
        page.locator("#tn-view").get_by_role("button", name="Reset view").click()
        settle(page)

        drawn = page.evaluate(PROJECTED)
        far = drawn["distance"]
        # the fingers start away from the points (a finger on a point would drag it)
        spots = [
            (drawn["width"] * fx, drawn["height"] * fy)
            for fx in (0.3, 0.5, 0.7)
            for fy in (0.3, 0.5, 0.7)
        ]
        sx, sy = max(
            spots,
            key=lambda s: min(abs(s[0] - x) + abs(s[1] - y) for x, y in drawn["points"].values()),
        )
        cx, cy = box["x"] + sx, box["y"] + sy
        for i in range(0, 8):
            kind = "touchStart" if i == 0 else "touchMove"
            d = 20 + 10 * i
            points = [{"x": cx - d, "y": cy, "id": 1}, {"x": cx + d, "y": cy, "id": 2}]
            cdp.send("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})
        cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
        settle(page)
        assert page.evaluate(PROJECTED)["distance"] < far * 0.8  # the camera came closer
        assert [m for m in messages if "GPU stall due to ReadPixels" not in m] == []
    finally:
        context.close()


def test_no_readout_value_is_cut_on_the_explorer_page(browser, server):
    """Opened on a phone, then widened to a tablet and a desktop (one visit, three widths)."""
    context = browser.new_context(viewport={"width": 360, "height": 800})
    page = context.new_page()
    try:
        page.goto(server + "notebooks/05_explorer/")
        page.wait_for_selector(".tn-explorer-live[data-ready='true']")
        for width in (360, 768, 1280):
            if width != 360:
                resize(page, width, 800)
            _no_readout_value_is_cut(page, width)
    finally:
        context.close()


def _no_readout_value_is_cut(page, width: int) -> None:
    for scheme in ("default", "slate"):
        page.evaluate(f"document.body.setAttribute('data-md-color-scheme', '{scheme}')")
        settle(page)
        assert page.evaluate("document.documentElement.scrollWidth") <= width, (width, scheme)
        cells = page.locator(".tn-explorer-live .tnx-readout td").evaluate_all(
            """(cells) => cells.map((td) => {
                const r = td.getBoundingClientRect();
                const parts = [...td.querySelectorAll('.tnx-part')].map(
                    (p) => p.getClientRects().length);
                let box = td.parentElement;
                while (box && getComputedStyle(box).overflowX === 'visible') box = box.parentElement;
                return {text: td.textContent, right: r.right, cut: td.scrollWidth > td.clientWidth + 1,
                        parts, clip: box ? box.getBoundingClientRect().right : innerWidth};
            })"""
        )
        assert len(cells) == 7, (width, scheme)
        # every button of the view's toolbar is there to press, none cut off
        live = page.locator(".tn-explorer-live .tnx-stage").first.bounding_box()
        for button in page.locator(".tn-explorer-live .tnx-toolbar button").all():
            b = button.bounding_box()
            assert b is not None and b["x"] >= live["x"] - 1, (width, button.inner_text())
            assert b["x"] + b["width"] <= live["x"] + live["width"] + 1, (
                width,
                button.inner_text(),
            )
        for cell in cells:
            assert not cell["cut"] and cell["right"] <= min(width, cell["clip"]) + 1, (width, cell)
            assert all(n == 1 for n in cell["parts"]), (width, cell)  # no component breaks


def test_one_three_js_however_many_views_and_no_console_warnings(page, server, traffic):
    messages: list[str] = []
    page.on(
        "console", lambda m: messages.append(m.text) if m.type in ("warning", "error") else None
    )
    page.goto(server + "notebooks/05_explorer/")
    page.wait_for_selector(".tn-explorer-live[data-ready='true']")
    # a second and a third view of the same bundle, as a re-run cell would import it again
    count = page.evaluate(
        """async () => {
            const url = new URL('../../assets/explorer/explorer.js', location.href).href;
            for (let i = 0; i < 2; i++) {
                const view = (await import(url + '?again=' + i)).default;
                const el = document.createElement('div');
                document.body.appendChild(el);
                const state = {a: ['0', '0', '0'], b: ['1', '0', '0'], c: ['0', '1', '0'],
                               winding: 'ABC', state: {}, bounds: [-5, 5], step: '0.1'};
                view.render({model: {get: (k) => state[k], send() {}, on() {}, off() {}}, el});
            }
            await new Promise((r) => setTimeout(r, 300));
            return document.querySelectorAll('.tnx-root canvas').length;
        }"""
    )
    assert count == 3
    # three.js sits in the views' shared chunk: fetched and run once for all three imports
    assert sum("/assets/explorer/shared-" in u for u in traffic.requests) == 1
    assert [m for m in messages if "GPU stall due to ReadPixels" not in m] == []
    assert not traffic.problems()


# --------------------------------------------------------------------------- N's drawn length


def _scale_label(ratio: float, unit: bool = False) -> str:
    """The label an arrow drawn `ratio` times its true length must carry (ratio a power of 2)."""
    k = round(math.log2(ratio))
    assert ratio == pytest.approx(2.0**k, rel=1e-6), f"drawn {ratio} times: not a power of two"
    return scaled_label(2.0**k, unit)


#: Triangles and the label their N must carry: true length, shrunk, grown.
SCALED = [
    ((("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")), "N"),  # |N| = 1: true length
    ((("0", "0", "0"), ("4", "0", "0"), ("0", "4", "0")), "N × ¼"),  # |N| = 16, edges 4
    ((("0", "0", "0"), ("0.3", "0", "0"), ("0", "0.3", "0")), "N × 4"),  # |N| = 0.09
]


def test_a_scaled_n_says_by_how_much_in_its_label(view):
    """Each triangle of SCALED typed in turn on one visit, the unit normal shown."""
    unit = view.get_by_role("button", name="Unit normal N/|N|")
    unit.click()
    assert unit.get_attribute("aria-pressed") == "true"
    for triangle, expected in SCALED:
        set_triangle(view, *triangle)
        settle(view)
        drawn = view.evaluate(PROJECTED)["drawn"]
        r = triangle_normal(*triangle)
        normal = [float(x) for x in r.exact.normal]
        labels = view.locator("#tn-view .tnx-arrow:visible").all_inner_texts()
        # the arrow drawn is N times some factor: the same direction, the length the label says
        ratio = math.hypot(*drawn["N"]) / math.hypot(*normal)
        for got, want in zip(drawn["N"], normal, strict=True):
            assert got == pytest.approx(want * ratio, abs=1e-9 * math.hypot(*normal) * ratio), (
                triangle
            )
        assert _scale_label(ratio) == expected, triangle
        assert expected in labels, (triangle, labels)
        # the unit normal too: drawn `unit_ratio` times its length of 1, and labelled so
        unit_ratio = math.hypot(*drawn["unit"])
        assert _scale_label(unit_ratio, unit=True) in labels, (triangle, labels)


# --------------------------------------------------------------------------- the projector


def _inside_with_margin(page, margin: float) -> dict[str, list[float]]:
    """Every vertex and arrow head projects inside the view, `margin` px from each side."""
    drawn = page.evaluate(PROJECTED)
    for key, (x, y) in drawn["points"].items():
        assert margin <= x <= drawn["width"] - margin, (key, x, drawn["width"])
        assert margin <= y <= drawn["height"] - margin, (key, y, drawn["height"])
    return drawn


def test_collinear_points_are_framed_side_on_full_screen_and_save_picture(page, server, traffic):
    """The guide's collinear row, a flip after the parallelogram, full screen, Save picture."""
    page.set_viewport_size({"width": 1280, "height": 720})
    open_view(page, server + "calculator/?a=0,0,0&b=1,1,1&c=2,2,2")
    drawn = _inside_with_margin(page, 20)
    # seen side-on, not along the line: A and C far apart on the screen
    (ax, ay), (cx, cy) = drawn["points"]["A"], drawn["points"]["C"]
    assert math.hypot(cx - ax, cy - ay) >= 0.5 * min(drawn["width"], drawn["height"])
    # the axes are named at their ends, in the page's text, in their own greys
    axes = page.locator("#tn-view .tnx-axis")
    assert axes.all_inner_texts() == ["x", "y", "z"]
    greys = [palette()[a]["light"] for a in "xyz"]
    want = [f"rgb({int(c[1:3], 16)}, {int(c[3:5], 16)}, {int(c[5:7], 16)})" for c in greys]
    assert axes.evaluate_all("els => els.map(e => getComputedStyle(e).color)") == want
    stage = page.locator("#tn-view .tnx-stage")
    # full screen: the view fills the screen; the f key, with the view focused, returns
    page.get_by_role("button", name="Full screen").click()
    root = page.locator("#tn-view .tnx-root")
    page.wait_for_function("() => document.fullscreenElement !== null")
    settle(page)
    assert "tn-fullscreen" in (root.get_attribute("class") or "")
    box = stage.bounding_box()
    assert box["width"] >= 0.95 * 1280 and box["height"] >= 0.8 * 720, box
    assert page.locator("#tn-view .tnx-readout tr[data-key='magnitude']").is_visible()
    readout = page.locator("#tn-view .tnx-side").bounding_box()
    drawn = _inside_with_margin(page, 20)
    for key, (x, _y) in drawn["points"].items():  # the readout over the view covers no point
        assert box["x"] + x < readout["x"], key
    stage.focus()
    page.keyboard.press("f")
    page.wait_for_function("() => document.fullscreenElement === null")
    settle(page)
    assert "tn-fullscreen" not in (root.get_attribute("class") or "")
    # where the page may not use the Fullscreen API (an iframe without permission), the view is
    # pinned over the window instead, and Esc returns
    page.evaluate("() => { Element.prototype.requestFullscreen = () => Promise.reject(); }")
    page.get_by_role("button", name="Full screen").click()
    page.wait_for_function(
        "el => el.classList.contains('tn-fullscreen')", arg=root.element_handle()
    )
    assert stage.bounding_box()["width"] >= 0.95 * 1280
    page.keyboard.press("Escape")
    page.wait_for_function(
        "el => !el.classList.contains('tn-fullscreen')", arg=root.element_handle()
    )
    assert page.get_by_role("button", name="Full screen").is_visible()
    # Save picture: a PNG twice the size of the view on the screen
    size = page.evaluate(PROJECTED)
    with page.expect_download() as download:
        page.get_by_role("button", name="Save picture").click()
    picture = Image.open(download.value.path())
    assert picture.format == "PNG"
    assert picture.size == (2 * size["width"], 2 * size["height"])
    # a flip after the parallelogram keeps N's head in view, beside the triangle
    set_triangle(page, ("1", "2", "0"), ("4", "1", "0"), ("2", "4", "1"))
    page.get_by_role("button", name="Parallelogram").click()
    page.locator("#tn-view").get_by_role("button", name=re.compile("^Flip the order")).click()
    settle(page)
    drawn = _inside_with_margin(page, 20)
    assert "N" in drawn["points"]
    assert not traffic.problems()
