"""The explorer in a real JupyterLab and in Jupyter Notebook 7: the kernel's state is the truth.

Both front ends are served by the run's shared Jupyter server (the ``lab`` fixture in
conftest.py: one per run, started from a fresh venv with the built wheel; see
jupyterlab_support.py). Chromium drives them as a teacher and a student would: the Run
menu, Shift+Enter, a mouse drag on a vertex, the keyboard. The kernel's state is read
from a cell's output; the view's from the page (its labels, its readout, and where it
draws the vertices).
"""

from __future__ import annotations

import ast
import json
import re
import time
from collections.abc import Iterator
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
from jupyterlab_support import (
    GRID,
    Lab,
    execution_counts,
    open_notebook,
    output_text,
    restart_and_clear,
    run_all,
    run_cell,
    wait_idle,
)

from trinormal import triangle_normal

NOTEBOOK_05 = Path(__file__).resolve().parents[2] / "notebooks" / "05_explorer.ipynb"

#: A projector: the explorer must fit this window.
PROJECTOR = {"width": 1280, "height": 720}

#: Prints the kernel's explorer `ex` as one JSON line, after a marker.
REPORT = """\
import json as _json
print("KERNEL", _json.dumps({"texts": ex.texts, "winding": ex.winding.value,
      "parallelogram": ex.view.show_parallelogram, "unit": ex.view.show_unit_normal,
      "precision": ex.precision, "format": ex.result.format(ex.precision)}))"""

#: What the views on the page show: per explorer, its vertex labels, readout and drawing.
VIEWS = """() => [...document.querySelectorAll('.tnx-root')].map((root) => ({
    labels: [...root.querySelectorAll('[data-vertex]')].map((e) => e.getAttribute('aria-label')),
    readout: Object.fromEntries([...root.querySelectorAll('.tnx-readout tr')]
        .map((tr) => [tr.dataset.key, tr.cells[1].textContent])),
    banner: !root.querySelector('.tnx-message').hidden,
    parallelogram: root.querySelector('[aria-label="Parallelogram"]').getAttribute('aria-pressed'),
    unit: root.querySelector('[aria-label="Unit normal N/|N|"]').getAttribute('aria-pressed'),
    order: root.querySelector('[aria-label^="Flip the order"]').textContent,
    boxes: [...root.querySelectorAll('.tnx-exact')].map((e) => e.value),
    sliders: [...root.querySelectorAll('.tnx-slider')].map((e) => Number(e.value)),
    decimals: root.querySelector('.tnx-decimals select').value,
    error: root.querySelector('.tnx-error').hidden ? null : root.querySelector('.tnx-error').textContent,
    drawn: root.tnxProject ? root.tnxProject() : null,
}))"""

#: Where one view draws (its tnxProject) and the boxes of its labels and overlays, in px
#: from the view's top left corner; the view is scrolled to first.
DRAWN = """(i) => {
    const root = document.querySelectorAll('.tnx-root')[i];
    const s = root.querySelector('.tnx-stage').getBoundingClientRect();
    const boxes = (selector) => [...root.querySelectorAll(selector)]
        .filter((e) => !e.hidden && !e.closest('[hidden]') && e.getClientRects().length)
        .map((e) => { const r = e.getBoundingClientRect();
                      return {text: e.textContent, left: r.left - s.left, top: r.top - s.top,
                              right: r.right - s.left, bottom: r.bottom - s.top}; });
    return {...root.tnxProject(), labels: boxes('.tnx-vertex, .tnx-arrow'),
            overlays: boxes('.tnx-message, .tnx-error, .tnx-legend, .tnx-hint')};
}"""


@pytest.fixture
def console(page: Any) -> list[str]:
    """Every console warning and error, and every page error, of this page."""
    seen: list[str] = []
    page.on(
        "console",
        lambda m: seen.append(f"{m.type}: {m.text}") if m.type in ("warning", "error") else None,
    )
    page.on("pageerror", lambda e: seen.append(f"pageerror: {e}"))
    page.set_viewport_size(PROJECTOR)
    return seen


def own_warnings(messages: list[str]) -> list[str]:
    """Console messages that come from the explorer or three.js (not the front end's own).

    Chromium without a GPU (the tests' --disable-gpu) composites WebGL canvases by reading
    their pixels back, and its driver logs that as a performance note ("GPU stall due to
    ReadPixels"); that note is about the test machine, not the page, and is left out. So is
    JupyterLab's own note that a plugin (anywidget's too) was slow to start on a busy machine.
    """
    return [
        m
        for m in messages
        if re.search(r"THREE|tnx|trinormal|explorer|WebGL|\[anywidget\]", m)
        and "GPU stall due to ReadPixels" not in m
    ]


def report(page: Any) -> dict[str, Any]:
    """The kernel's state, from the last output that holds the report."""
    text = page.locator(".jp-OutputArea-output", has_text="KERNEL {").last.inner_text()
    return dict(json.loads(text.split("KERNEL", 1)[1]))


@pytest.fixture(scope="module")
def shared_notebook(lab: Lab, browser: Any) -> Iterator[Any]:
    """Open a notebook once for the module's tests: ``open(name, cells, app)`` gives its page.

    Each notebook gets its own 1280x720 page and kernel, run once with Run All; its kernel
    is kept between tests (``Lab.kept``) and stopped with the page at the module's end.
    """
    opened: dict[tuple[str, str], Any] = {}
    contexts: list[Any] = []

    def open_(name: str, cells: list[str], app: str) -> Any:
        if (name, app) not in opened:
            context = browser.new_context(viewport=PROJECTOR)
            contexts.append(context)
            page = context.new_page()
            lab.write_notebook(name, cells)
            open_notebook(lab, page, name, app)
            lab.kept.add(name)
            run_all(page)
            opened[name, app] = page
        return opened[name, app]

    yield open_
    for context in contexts:
        context.close()
    for name, _ in opened:
        lab.kept.discard(name)
    lab.shutdown_kernels()


def wait_for_report(page: Any, count: int = 1) -> None:
    page.wait_for_function(
        """(n) => [...document.querySelectorAll('.jp-OutputArea-output')]
            .filter((o) => o.innerText.includes('KERNEL {')).length >= n""",
        arg=count,
        timeout=120_000,
    )


def point_text(texts: dict[str, str], p: str) -> str:
    return ", ".join(texts[p + q] for q in "xyz")


def assert_views_show(page: Any, state: dict[str, Any], views: int = 1) -> None:
    """The page's first ``views`` views draw and print exactly the kernel's state."""
    shown = page.evaluate(VIEWS)[:views]
    assert len(shown) == views
    texts = state["texts"]
    for view in shown:
        assert view["labels"] == [
            f"Point {p.upper()} at ({point_text(texts, p)}). Arrow keys move x and y, "
            "Page Up and Page Down move z."
            for p in "abc"
        ]
        assert view["drawn"]["values"] == [[texts[p + q] for q in "xyz"] for p in "abc"]
        for key in ("u", "v", "normal", "magnitude", "area", "unit_normal", "plane"):
            assert view["readout"][key] == state["format"][key], key
        assert view["parallelogram"] == str(state["parallelogram"]).lower()
        assert view["unit"] == str(state["unit"]).lower()
        assert view["order"] == "⇄ " + ("A→B→C" if state["winding"] == "ABC" else "A→C→B")
        assert view["decimals"] == str(state["precision"])
        # the boxes hold the kernel's exact text; each slider sits on its 0.1 grid, at the
        # grid point nearest the exact value (1/3 shows as 0.3 and stays 1/3 in the box)
        assert view["boxes"] == [texts[p + q] for p in "abc" for q in "xyz"]
        for slider, key in zip(view["sliders"], (p + q for p in "abc" for q in "xyz"), strict=True):
            assert slider * 10 == pytest.approx(round(slider * 10), abs=1e-9), (key, slider)
            assert abs(slider - float(Fraction(texts[key]))) <= 0.05 + 1e-9, (key, slider)


def assert_framed(page: Any, index: int = 0, framed: bool = True) -> dict[str, Any]:
    """View ``index`` frames its triangle, and no overlay covers a label or an arrow head.

    Framed: the triangle spans at least 40 % of the view's smaller side, and no vertex,
    arrow head or label is clipped (``framed=False`` skips that, for a view the learner
    has moved things in: a drag never re-frames). Always: no overlay (banner, refusal,
    legend, hint) covers a vertex label, an arrow's label or an arrow head.
    """
    page.locator(".tnx-root").nth(index).scroll_into_view_if_needed()
    page.evaluate("() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)))")
    drawn = page.evaluate(DRAWN, index)
    w, h = drawn["width"], drawn["height"]
    assert {b["text"] for b in drawn["labels"]} >= {"A", "B", "C"}
    if framed:
        xs, ys = zip(*(drawn["points"][k] for k in "ABC"), strict=True)
        span = max(max(xs) - min(xs), max(ys) - min(ys))
        assert span >= 0.4 * min(w, h), (span, w, h)
        for key, (x, y) in drawn["points"].items():  # the vertices and the arrow heads
            assert 0 <= x <= w and 0 <= y <= h, (key, x, y, w, h)
        for b in drawn["labels"]:
            assert b["left"] >= -1 and b["top"] >= -1, b
            assert b["right"] <= w + 1 and b["bottom"] <= h + 1, (b, w, h)
    heads = [
        {"left": x - 4, "top": y - 4, "right": x + 4, "bottom": y + 4}
        for x, y in drawn["points"].values()
    ]
    for overlay in drawn["overlays"]:
        for b in drawn["labels"] + heads:
            apart = (
                overlay["right"] <= b["left"]
                or b["right"] <= overlay["left"]
                or overlay["bottom"] <= b["top"]
                or b["bottom"] <= overlay["top"]
            )
            assert apart, (overlay, b)
    return drawn


def last_set_in_notebook_05() -> dict[str, Any]:
    """The arguments of the notebook's last ``ex.set(...)``: the state Run All must end in.

    Read from the notebook itself (its literal arguments), so the test follows the notebook
    when its last cell changes; that call must set the whole triangle and the winding.
    """
    nb = json.loads(NOTEBOOK_05.read_text(encoding="utf-8"))
    calls = [
        node
        for cell in nb["cells"]
        if cell["cell_type"] == "code"
        for node in ast.walk(ast.parse("".join(cell["source"])))
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr == "set"
        and isinstance(node.func.value, ast.Name)
        and node.func.value.id == "ex"
    ]
    assert calls, "notebook 05 never calls ex.set"
    args = {k.arg: ast.literal_eval(k.value) for k in calls[-1].keywords}
    assert set(args) == {"a", "b", "c", "winding"}, f"the last ex.set sets only {sorted(args)}"
    return args


def notebook_05_with_report() -> dict[str, Any]:
    nb = json.loads(NOTEBOOK_05.read_text(encoding="utf-8"))
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            cell["outputs"], cell["execution_count"] = [], None
    report_cell = {"cell_type": "code", "metadata": {}, "outputs": [], "source": REPORT}
    nb["cells"].append({**report_cell, "execution_count": None})
    return nb


@pytest.mark.parametrize("app", ["lab", "notebook"])
def test_run_all_of_notebook_05_ends_where_the_last_cell_put_it(
    lab: Lab, page: Any, console: list[str], app: str
) -> None:
    # twice, each on a fresh kernel (the second in a page that has loaded the app already):
    # the kernel's `ex` and the view end on what the last cell set (its ex.set, no
    # parallelogram), never on an earlier cell's state
    name = f"05_{app}.ipynb"
    nb = notebook_05_with_report()
    (lab.root / name).write_text(json.dumps(nb), encoding="utf-8")
    code_cells = sum(cell["cell_type"] == "code" for cell in nb["cells"])
    report_cell = len(nb["cells"]) - 1
    last = last_set_in_notebook_05()
    expected = triangle_normal(last["a"], last["b"], last["c"], winding=last["winding"]).format(4)
    texts = {p + q: str(last[p][i]) for p in "abc" for i, q in enumerate("xyz")}
    for run in range(2):
        # the first time on a freshly opened notebook (the page loads the app), then with
        # the Kernel menu's restart, in the same page: a new kernel each time
        if run == 0:
            open_notebook(lab, page, name, app)
        else:
            restart_and_clear(page)
        run_all(page)
        wait_for_report(page)
        page.wait_for_selector(".tnx-root canvas", timeout=60_000)
        # a fresh kernel ran every cell once, in order (Shift+Enter on the report cell below
        # adds an empty cell after it, which the next runs leave alone)
        counts = execution_counts(page)[:code_cells]
        assert counts == [f"[{i}]:" for i in range(1, code_cells + 1)], (run, counts)
        page.wait_for_timeout(1000)  # anything late from the browser would arrive by now
        run_cell(page, report_cell)  # ask the kernel again
        page.wait_for_function(
            """([i, n]) => document.querySelectorAll('.jp-Notebook .jp-Cell')[i]
                .querySelector('.jp-InputArea-prompt').textContent.trim() === `[${n}]:`""",
            arg=[report_cell, code_cells + 1],
            timeout=30_000,
        )
        wait_for_report(page)
        state = report(page)
        assert state["texts"] == texts
        assert state["winding"] == last["winding"] and state["parallelogram"] is False
        assert state["format"] == expected
        assert_views_show(page, state)
        assert [view["banner"] for view in page.evaluate(VIEWS)] == [False]  # one view
        assert_framed(page)  # the last cell set this triangle: the view frames it
    assert own_warnings(console) == [], console


LOOP = [
    "from trinormal.explorer import Explorer\nex = Explorer()\nex",
    "ex  # the same explorer, shown a second time",
    'for i in range(50):\n    ex.set(c=(f"{i % 7}/3", "0.1", f"-{i % 5}"), winding="ACB" if i % 2 else "ABC")',
    'ex.set(a=("1/3", "0.2", "0"), b=(1, "2.3", "-0.5"), c=("0.1", 1, "1/7"), winding="ABC")',
    REPORT,
    "other = Explorer(a=(0, 0, 0), b=(1, 1, 0), c=(2, 2, 0))  # a second explorer, collinear\nother",
]

#: Keys of the nine coordinates, in the order of the boxes.
KEYS = [p + q for p in "abc" for q in "xyz"]


def boxes_of(view: dict[str, Any]) -> dict[str, str]:
    return dict(zip(KEYS, view["boxes"], strict=True))


def both_views(page: Any, check: Any, what: str, timeout_s: float = 30) -> list[dict[str, Any]]:
    """Wait until views 0 and 1 (the same explorer) show the same values, and ``check`` holds."""
    deadline = time.monotonic() + timeout_s
    while True:
        shown = page.evaluate(VIEWS)[:2]
        same = all(
            shown[0][k] == shown[1][k]
            for k in ("labels", "readout", "boxes", "parallelogram", "unit", "order", "decimals")
        )
        if same and check(shown[0]):
            return shown
        brief = [{k: v[k] for k in ("boxes", "parallelogram", "unit", "order", "decimals", "error")}
                 for v in shown]  # fmt: skip
        assert time.monotonic() < deadline, f"{what}: {json.dumps(brief, ensure_ascii=False)}"
        page.wait_for_timeout(100)


def drag(page: Any, label: Any, dx: float, dy: float, steps: int = 10) -> None:
    label.scroll_into_view_if_needed()
    box = label.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, steps + 1):
        page.mouse.move(x + dx * i / steps, y + dy * i / steps)
    page.mouse.up()


@pytest.mark.parametrize("app", ["lab", "notebook"])
def test_fifty_sets_then_a_final_set_and_two_views_that_follow_each_other(
    lab: Lab, page: Any, console: list[str], app: str
) -> None:
    name = f"loop_{app}.ipynb"
    lab.write_notebook(name, LOOP)
    open_notebook(lab, page, name, app)
    run_all(page)
    wait_for_report(page)
    page.wait_for_function("() => document.querySelectorAll('.tnx-root canvas').length === 3")
    page.wait_for_timeout(500)
    state = report(page)
    final = triangle_normal(("1/3", "0.2", "0"), (1, "2.3", "-0.5"), ("0.1", 1, "1/7"))
    assert state["format"] == final.format(4)
    assert state["texts"]["ax"] == "1/3" and state["texts"]["cz"] == "1/7"
    assert_views_show(page, state, views=2)
    for index in (0, 1):  # a cell set the triangle: both views frame it
        assert_framed(page, index)
    # the other explorer: collinear, its banner under the view, not over a label
    assert page.evaluate(VIEWS)[2]["banner"] is True
    assert_framed(page, 2)

    # every kind of edit, made in either view, reaches the kernel and the other view
    # (one after another, as one learner makes them: each edit is seen before the next)
    roots = page.locator(".tnx-root")
    roots.nth(0).locator('[data-vertex="B"]').focus()
    page.keyboard.press("ArrowUp")  # an arrow key on a vertex
    both_views(page, lambda v: boxes_of(v)["by"] == "2.4", "ArrowUp")
    roots.nth(1).locator('[data-vertex="B"]').focus()
    page.keyboard.press("PageDown")
    both_views(
        page, lambda v: boxes_of(v)["by"] == "2.4" and boxes_of(v)["bz"] == "-0.6", "PageDown"
    )
    # a drag in view 1 moves C onto the grid; view 0 follows
    drag(page, roots.nth(1).locator('[data-vertex="C"]'), 60, 40)
    shown = both_views(
        page,
        lambda v: [boxes_of(v)[k] for k in ("cx", "cy", "cz")] != ["0.1", "1", "1/7"],
        "drag",
    )
    assert all(GRID.fullmatch(boxes_of(shown[0])[k]) for k in ("cx", "cy", "cz")), shown[0]
    # a slider in view 0 moves A.y on its grid; A.x stays exactly one third
    slider = roots.nth(0).locator(".tnx-slider").nth(1)
    slider.scroll_into_view_if_needed()
    width = slider.bounding_box()["width"]
    slider.click(position={"x": width * 0.8, "y": 5})
    shown = both_views(page, lambda v: boxes_of(v)["ay"] != "0.2", "slider")
    assert GRID.fullmatch(boxes_of(shown[0])["ay"]) and boxes_of(shown[0])["ax"] == "1/3"
    # an exact value typed in view 1's box for C.z
    box = roots.nth(1).locator(".tnx-exact").nth(8)
    box.fill("2/7")
    box.press("Enter")
    both_views(page, lambda v: boxes_of(v)["cz"] == "2/7", "typed")
    # the toolbar's toggles and the decimals, in turn from each view
    roots.nth(0).locator('[aria-label="Parallelogram"]').click()
    both_views(page, lambda v: v["parallelogram"] == "true", "parallelogram")
    roots.nth(1).locator('[aria-label^="Flip the order"]').click()
    both_views(page, lambda v: v["order"] == "⇄ A→C→B", "flip")
    roots.nth(0).locator('[aria-label="Unit normal N/|N|"]').click()
    both_views(page, lambda v: v["unit"] == "true", "unit normal")
    roots.nth(1).locator(".tnx-decimals select").select_option("3")
    both_views(page, lambda v: v["decimals"] == "3", "decimals")
    # a value the kernel refuses: both views say why, nothing moves, the box shows A.z again
    box = roots.nth(0).locator(".tnx-exact").nth(2)
    box.fill("abc")
    box.press("Enter")
    shown = both_views(page, lambda v: bool(v["error"]) and boxes_of(v)["az"] == "0", "refused")
    assert shown[0]["error"].startswith("A.z = 'abc' is not a number"), shown[0]["error"]
    assert shown[1]["error"] == shown[0]["error"]

    run_cell(page, 4)
    page.wait_for_function(
        """() => [...document.querySelectorAll('.jp-OutputArea-output')]
            .some((o) => o.innerText.includes('"cz": "2/7"') && o.innerText.includes('"precision": 3'))""",
        timeout=30_000,
    )
    state = report(page)
    texts = state["texts"]
    assert (texts["by"], texts["bz"], texts["cz"], texts["ax"]) == ("2.4", "-0.6", "2/7", "1/3")
    assert texts["ay"] == boxes_of(shown[0])["ay"] and texts["az"] == "0"
    assert (state["parallelogram"], state["unit"], state["winding"]) == (True, True, "ACB")
    assert state["precision"] == 3
    assert state["format"] == triangle_normal(
        *([texts[p + q] for q in "xyz"] for p in "abc"), winding="ACB"
    ).format(3)
    assert_views_show(page, state, views=2)
    # the banner of refusal, the legend and the hint cover nothing; Reset frames it again
    assert_framed(page, 0, framed=False)
    roots.nth(0).get_by_role("button", name="Reset view").click()
    assert_framed(page, 0)

    # a cell that makes the explorer again: still one three.js on the page, no warning
    run_cell(page, 0)
    page.wait_for_function(
        "() => document.querySelectorAll('.tnx-root canvas').length === 3", timeout=60_000
    )
    wait_idle(page)
    page.wait_for_timeout(500)
    runtimes = page.evaluate(
        """() => [Object.keys(globalThis.__trinormalExplorer || {}).length,
                  Object.getOwnPropertySymbols(globalThis)
                      .filter((s) => String(s).includes('trinormal.three@')).length]"""
    )
    assert runtimes == [1, 1]
    assert own_warnings(console) == [], console


#: The second cell waits (at most a minute) until the test says a drag is under way, by a
#: file it writes next to the notebook (the kernel's working folder), then sets C.
DRAG = [
    'from trinormal.explorer import Explorer\nex = Explorer(c=(0, "1/3", 0))\nex',
    "import pathlib, time\n"
    "for _ in range(1200):\n"
    "    if pathlib.Path(DRAGGING).exists():\n"
    "        break\n"
    "    time.sleep(0.05)\n"
    'ex.set(c=("-1/3", "2/3", "0.25"))',
    REPORT,
]

#: What the first view draws for C (its own edit while a drag is unanswered).
VIEW_C = "() => document.querySelector('.tnx-root').tnxProject().values[2]"


@pytest.mark.parametrize("app", ["lab", "notebook"])
def test_a_cell_that_sets_a_vertex_during_a_drag_has_the_last_word(
    lab: Lab, page: Any, console: list[str], app: str
) -> None:
    name = f"drag_{app}.ipynb"
    dragging = lab.root / f"dragging_{app}"
    dragging.unlink(missing_ok=True)
    lab.write_notebook(name, [f"DRAGGING = {dragging.name!r}\n" + DRAG[0], *DRAG[1:]])
    open_notebook(lab, page, name, app)
    run_cell(page, 0)
    page.wait_for_selector('[data-vertex="C"]', timeout=60_000)
    page.wait_for_timeout(500)
    run_cell(page, 1)  # waits for the drag below to be under way, then sets C
    label = page.locator('[data-vertex="C"]').first
    label.scroll_into_view_if_needed()
    box = label.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    # drag until the cell's C has arrived, then on for a second: the drag spans that moment
    seen: list[list[str]] = []
    cell = ["-1/3", "2/3", "0.25"]
    after = 0
    for i in range(1, 400):
        page.mouse.move(x + 2 * (i % 60), y + (i % 10))
        page.wait_for_timeout(80)
        seen.append(page.evaluate(VIEW_C))
        after += seen[-1] == cell
        if seen[-1] not in (["0", "1/3", "0"], cell) and not dragging.exists():
            dragging.touch()  # the drag has moved C: now the cell may set it
        if after >= 12:
            break
    page.mouse.up()
    assert after >= 12, f"the cell's C never reached the view while the mouse was down: {seen}"
    dragged = [c for c in seen[: seen.index(cell)] if c != ["0", "1/3", "0"]]
    assert dragged, f"the drag never moved C before the cell set it: {seen}"
    page.wait_for_timeout(800)
    run_cell(page, 2)
    wait_for_report(page)
    state = report(page)
    assert [state["texts"][k] for k in ("cx", "cy", "cz")] == cell
    assert state["texts"]["ax"] == "0" and state["texts"]["bx"] == "1"
    assert Fraction(state["texts"]["cy"]) == Fraction(2, 3)
    assert_views_show(page, state)
    assert own_warnings(console) == [], console


# --------------------------------------------------------------------------- a drag

EXPLORER = """\
from fractions import Fraction
from trinormal.explorer import Explorer
ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
ex"""

CHECK = """\
print(ex.result.exact.a == (Fraction(1, 10), Fraction(1, 5), Fraction(3, 10)),
      ex.result.exact.b[0] == Fraction(1, 3))
print(*(ex.texts[k] for k in ("ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz")))
if ex.picture_source == "view":  # not in Run All: the view has not drawn yet (no matplotlib)
    png = ex.to_png()
    print("view", int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big"))"""

#: Once the view has sent its picture of what it draws: the size of its canvas (CSS px).
PICTURE_SENT = """() => {
    const root = document.querySelector('.tnx-root');
    const sent = root.tnxPicture, drawn = root.tnxProject();
    const same = sent && JSON.stringify([sent.values.a, sent.values.b, sent.values.c])
        === JSON.stringify(drawn.values);
    const canvas = root.querySelector('canvas');
    return same && [canvas.clientWidth, canvas.clientHeight];
}"""


@pytest.fixture
def notebook(shared_notebook: Any) -> Any:
    """The explorer notebook, run once for the two tests below (the first only reads it)."""
    page = shared_notebook("explorer.ipynb", [EXPLORER, CHECK], "lab")
    page.wait_for_selector('[data-vertex="C"]', timeout=60_000)
    wait_idle(page)
    return page


def coordinates(page: Any) -> list[str]:
    return output_text(page, 1).strip().splitlines()[1].split()


def test_run_all_renders_the_live_view_with_the_exact_values(notebook: Any) -> None:
    page = notebook
    canvas = page.locator(".jp-OutputArea-output canvas").first
    assert canvas.is_visible()
    assert page.evaluate(
        "(c) => !!(c.getContext('webgl2') || c.getContext('webgl'))", canvas.element_handle()
    )
    for name in "ABC":
        assert page.locator(f'[data-vertex="{name}"]').first.is_visible()
    # the kernel's exact values are shown as set: nothing in the browser rounds them
    assert output_text(page, 1).splitlines()[0] == "True True"
    assert coordinates(page) == ["0.1", "0.2", "0.3", "1/3", "0", "0", "0", "2.35", "0"]


def test_dragging_a_vertex_updates_the_kernel(notebook: Any) -> None:
    page = notebook
    label = page.locator('[data-vertex="C"]').first
    box = label.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, 11):
        page.mouse.move(x + 6 * i, y + 3 * i)
    page.mouse.up()
    wait_idle(page)
    page.wait_for_timeout(300)
    # the view sends its picture once the drag has settled: ex.to_png() is then that picture,
    # twice the size of the canvas on the screen
    canvas = page.wait_for_function(PICTURE_SENT, timeout=30_000).json_value()
    run_cell(page, 1)
    page.wait_for_function(
        """() => {
            const cells = document.querySelectorAll('.jp-Notebook .jp-Cell');
            const out = cells[1].querySelector('.jp-OutputArea-output');
            return out && !out.innerText.includes('0 2.35 0');
        }""",
        timeout=30_000,
    )
    values = coordinates(page)
    a, b, c = values[0:3], values[3:6], values[6:9]
    assert a == ["0.1", "0.2", "0.3"] and b == ["1/3", "0", "0"]
    assert c != ["0", "2.35", "0"]
    assert all(re.fullmatch(r"-?\d+\.\d", v) for v in c), c  # on the 0.1 grid, written exactly
    assert output_text(page, 1).strip().splitlines()[2].split() == [
        "view",
        str(2 * canvas[0]),
        str(2 * canvas[1]),
    ]
    # the readout in the view shows the kernel's strings for the new position
    expected = triangle_normal(a, b, c).format(4)
    readout = page.locator(".jp-OutputArea-output").first.inner_text()
    assert expected["normal"] in readout and expected["area"] in readout


# --------------------------------------------------------------------------- fits the screen

FIT = [
    "from trinormal.explorer import Explorer\n"
    "ex = Explorer(a=('-0.06', 0.12, '-0.06'), b=(4.1, 0.5, -3.3), c=(-2.5, 4.9, 0.1))\nex"
]

#: The explorer scrolled to the top of the notebook, and the boxes that must be seen.
LAYOUT = """() => {
  const root = document.querySelector('.tnx-root');
  root.scrollIntoView({block: 'start'});
  const box = (e) => { const r = e.getBoundingClientRect();
                       return {left: r.left, top: r.top, right: r.right, bottom: r.bottom}; };
  const panel = document.querySelector('.jp-WindowedPanel-outer') ||
                document.querySelector('.jp-NotebookPanel-notebook');
  const rows = {};
  for (const tr of root.querySelectorAll('.tnx-readout tr')) {
    const vector = tr.querySelector('.tnx-vector');
    const line = parseFloat(getComputedStyle(tr.cells[1]).lineHeight);
    const height = vector ? vector.getBoundingClientRect().height : 0;
    rows[tr.dataset.key] = {...box(tr.cells[1]), lines: Math.round(height / line) || 1};
  }
  return {panel: box(panel), stage: box(root.querySelector('.tnx-stage')),
          toolbar: box(root.querySelector('.tnx-toolbar')),
          buttons: [...root.querySelectorAll('.tnx-toolbar button')].map(box), rows};
}"""


#: In full screen: the screen's size (CSS px), the boxes of the view, the readout and its
#: rows' values, and where the vertices and arrow heads are drawn (px in the view).
FULL_SCREEN = """() => {
  const root = document.querySelector('.tnx-root');
  const box = (e) => { const r = e.getBoundingClientRect();
                       return {left: r.left, top: r.top, right: r.right, bottom: r.bottom}; };
  const rows = {};
  for (const tr of root.querySelectorAll('.tnx-readout tr')) rows[tr.dataset.key] = box(tr.cells[1]);
  const points = Object.values(root.tnxProject().points);
  return {screen: [innerWidth, innerHeight], stage: box(root.querySelector('.tnx-stage')), rows,
          side: box(root.querySelector('.tnx-side')), points};
}"""


def zoom_to(page: Any, zoom: float, sessions: dict[int, Any]) -> None:
    """Browser zoom on a 1280x720 window, as Ctrl+plus sets it, and wait for the page to see it.

    The page becomes 1280/zoom by 720/zoom CSS px, drawn at ``zoom`` device px per CSS px
    (Chromium's own zoom). The override lasts as long as its DevTools session, which
    ``sessions`` keeps (one per page).
    """
    if id(page) not in sessions:
        sessions[id(page)] = page.context.new_cdp_session(page)
    width, height = round(PROJECTOR["width"] / zoom), round(PROJECTOR["height"] / zoom)
    sessions[id(page)].send(
        "Emulation.setDeviceMetricsOverride",
        {"width": width, "height": height, "deviceScaleFactor": zoom, "mobile": False},
    )
    page.wait_for_function(
        "([w, h, z]) => innerWidth === w && innerHeight === h && devicePixelRatio === z",
        arg=[width, height, zoom],
    )


def settled(page: Any, script: str, timeout_s: float = 30) -> Any:
    """What ``script`` measures once the layout has settled: the same three frames running."""
    deadline = time.monotonic() + timeout_s
    last, same = None, 0
    while same < 2:
        assert time.monotonic() < deadline, f"the layout never settled: {last}"
        page.evaluate(
            "() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)))"
        )
        m = page.evaluate(script)
        same = same + 1 if m == last else 0
        last = m
        page.wait_for_timeout(100)
    return last


@pytest.fixture(scope="module")
def cdp_sessions() -> dict[int, Any]:
    """The DevTools session of each page whose zoom a test set (see zoom_to)."""
    return {}


@pytest.mark.parametrize(
    ("app", "zoom"), [("lab", 1.0), ("lab", 1.25), ("lab", 1.5), ("notebook", 1.0)]
)
def test_view_and_readout_fit_a_projector_at_every_zoom(
    shared_notebook: Any, cdp_sessions: dict[int, Any], app: str, zoom: float
) -> None:
    # 1280x720 at browser zoom 100/125/150 %: the page is 1280/zoom CSS px wide, the file
    # browser open (JupyterLab's default); the view and the rows N, |N|, area and unit normal
    # are seen together once the explorer is scrolled to, the toolbar is one row. One page
    # per app, run once; each zoom is set on it, as a teacher zooms an open notebook.
    page = shared_notebook(f"fit_{app}.ipynb", FIT, app)
    page.wait_for_selector(".tnx-root canvas", timeout=90_000)
    zoom_to(page, zoom, cdp_sessions)
    m = settled(page, LAYOUT)
    if app == "lab":  # the file browser takes its share of the width
        files = page.locator("#filebrowser").bounding_box()
        assert files is not None and files["width"] >= 200, files
    panel, stage = m["panel"], m["stage"]
    assert stage["right"] - stage["left"] >= 360, m
    inside = ("left", "top"), ("right", "bottom")
    for what, b in [("view", stage)] + [
        (k, m["rows"][k]) for k in ("normal", "magnitude", "area", "unit_normal")
    ]:
        assert b[inside[0][0]] >= panel["left"] - 1 and b[inside[0][1]] >= panel["top"] - 1
        assert b[inside[1][0]] <= panel["right"] + 1, (what, b, panel)
        assert b[inside[1][1]] <= panel["bottom"] + 1, (what, b, panel)
    assert all(row["lines"] == 1 for row in m["rows"].values()), m["rows"]
    assert len({round(b["top"]) for b in m["buttons"]}) == 1  # one row
    assert max(b["right"] for b in m["buttons"]) <= m["toolbar"]["right"] + 1
    # full screen for the projector: the view fills the screen, the four rows over it, none
    # cut; the f key (the view focused) brings the notebook back
    page.locator(".tnx-root").get_by_role("button", name="Full screen").click()
    page.wait_for_function("() => document.fullscreenElement !== null")
    full = settled(page, FULL_SCREEN)
    width, height = full["screen"]
    assert full["stage"]["right"] - full["stage"]["left"] >= 0.95 * width, full
    assert full["stage"]["bottom"] - full["stage"]["top"] >= 0.75 * height, full
    for key in ("normal", "magnitude", "area", "unit_normal"):
        row = full["rows"][key]
        assert row["left"] >= 0 and row["right"] <= width, (key, row)
        assert row["top"] >= 0 and row["bottom"] <= height, (key, row)
    for x, _y in full["points"]:  # the picture keeps clear of the readout over it
        assert full["stage"]["left"] + x < full["side"]["left"], full
    page.locator(".tnx-stage").focus()
    page.keyboard.press("f")
    page.wait_for_function("() => document.fullscreenElement === null")
