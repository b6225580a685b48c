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
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
from jupyterlab_support import (
    Lab,
    kernel_ready,
    output_text,
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
      "parallelogram": ex.view.show_parallelogram, "format": ex.result.format(ex.precision)}))"""

#: What the views on the page show: per explorer, its vertex labels, readout and drawing.
VIEWS = """() => [...document.querySelectorAll('.tnx-root')].map((root) => ({
    labels: [...root.querySelectorAll('[data-vertex]')].map((e) => e.getAttribute('aria-label')),
    readout: Object.fromEntries([...root.querySelectorAll('.tnx-readout tr')]
        .map((tr) => [tr.dataset.key, tr.cells[1].textContent])),
    banner: !root.querySelector('.tnx-message').hidden,
    parallelogram: root.querySelector('[aria-label="Parallelogram"]').getAttribute('aria-pressed'),
    drawn: root.tnxProject ? root.tnxProject() : null,
}))"""


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


def open_notebook(lab: Lab, page: Any, name: str, app: str) -> None:
    lab.shutdown_kernels()  # a fresh kernel for this page
    url = f"{lab.url}lab/tree/{name}?reset" if app == "lab" else lab.notebook7_url(name)
    page.goto(url)
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=60_000)
    kernel_ready(lab)


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
    """Every view on the page draws and prints exactly the kernel's state."""
    shown = page.evaluate(VIEWS)
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
    # three times, each on a fresh kernel: the kernel's `ex` and the view end on what the
    # last cell set (its ex.set, no parallelogram), never on an earlier cell's state
    name = f"05_{app}.ipynb"
    (lab.root / name).write_text(json.dumps(notebook_05_with_report()), encoding="utf-8")
    last = last_set_in_notebook_05()
    expected = triangle_normal(last["a"], last["b"], last["c"], winding=last["winding"]).format(4)
    texts = {p + q: str(last[p][i]) for p in "abc" for i, q in enumerate("xyz")}
    for _ in range(3):
        open_notebook(lab, page, name, app)
        run_all(page)
        wait_for_report(page)
        page.wait_for_selector(".tnx-root canvas", timeout=60_000)
        page.wait_for_timeout(1000)  # anything late from the browser would arrive by now
        run_cell(page, -1)  # ask the kernel again
        page.wait_for_timeout(500)
        wait_for_report(page)
        state = report(page)
        assert state["texts"] == texts
        assert state["winding"] == last["winding"] and state["parallelogram"] is False
        assert state["format"] == expected
        assert_views_show(page, state)
        assert page.evaluate(VIEWS)[0]["banner"] is False
    assert own_warnings(console) == [], console


LOOP = [
    "from trinormal.explorer import Explorer\nex = Explorer()\nex",
    "ex  # the same explorer, shown a second time",
    'for i in range(50):\n    ex.set(c=(f"{i % 7}/3", "0.1", f"-{i % 5}"), winding="ACB" if i % 2 else "ABC")',
    'ex.set(a=("1/3", "0.2", "0"), b=(1, "2.3", "-0.5"), c=("0.1", 1, "1/7"), winding="ABC")',
    REPORT,
]


@pytest.mark.parametrize("app", ["lab", "notebook"])
def test_fifty_sets_then_a_final_set_and_two_views_that_follow_each_other(
    lab: Lab, page: Any, console: list[str], app: str
) -> None:
    name = f"loop_{app}.ipynb"
    lab.write_notebook(name, LOOP)
    open_notebook(lab, page, name, app)
    run_all(page)
    wait_for_report(page)
    page.wait_for_function("() => document.querySelectorAll('.tnx-root canvas').length === 2")
    page.wait_for_timeout(500)
    state = report(page)
    final = triangle_normal(("1/3", "0.2", "0"), (1, "2.3", "-0.5"), ("0.1", 1, "1/7"))
    assert state["format"] == final.format(4)
    assert state["texts"]["ax"] == "1/3" and state["texts"]["cz"] == "1/7"
    assert_views_show(page, state, views=2)

    # an edit in either view reaches the kernel and the other view
    for index, key in ((0, "ArrowUp"), (1, "PageDown")):
        label = page.locator('[data-vertex="B"]').nth(index)
        label.focus()
        page.keyboard.press(key)
        page.wait_for_timeout(400)
    run_cell(page, 4)
    page.wait_for_function(
        """() => [...document.querySelectorAll('.jp-OutputArea-output')]
            .some((o) => o.innerText.includes('"by": "2.4"') && o.innerText.includes('"bz": "-0.6"'))""",
        timeout=30_000,
    )
    state = report(page)
    assert state["texts"]["by"] == "2.4" and state["texts"]["bz"] == "-0.6"
    assert state["texts"]["ax"] == "1/3"  # untouched values stay exact
    assert_views_show(page, state, views=2)
    assert own_warnings(console) == [], console


DRAG = [
    'from trinormal.explorer import Explorer\nex = Explorer(c=(0, "1/3", 0))\nex',
    'import time\ntime.sleep(2.5)\nex.set(c=("-1/3", "2/3", "0.25"))',
    REPORT,
]


def test_a_cell_that_sets_a_vertex_during_a_drag_has_the_last_word(
    lab: Lab, page: Any, console: list[str]
) -> None:
    lab.write_notebook("drag.ipynb", DRAG)
    open_notebook(lab, page, "drag.ipynb", "lab")
    run_cell(page, 0)
    page.wait_for_selector('[data-vertex="C"]', timeout=60_000)
    page.wait_for_timeout(500)
    run_cell(page, 1)  # sleeps, then sets C while the drag below is still going
    label = page.locator('[data-vertex="C"]').first
    box = label.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, 60):  # about 5 s of dragging, across the moment the cell sets C
        page.mouse.move(x + 2 * i, y + (i % 10))
        page.wait_for_timeout(80)
    page.mouse.up()
    page.wait_for_timeout(800)
    run_cell(page, 2)
    wait_for_report(page)
    state = report(page)
    assert [state["texts"][k] for k in ("cx", "cy", "cz")] == ["-1/3", "2/3", "0.25"]
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
print(*(ex.texts[k] for k in ("ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz")))"""


@pytest.fixture
def notebook(lab: Lab, page: Any) -> Any:
    page.set_viewport_size(PROJECTOR)
    page.goto(lab.write_notebook("explorer.ipynb", [EXPLORER, CHECK]))
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=60_000)
    kernel_ready(lab)
    run_all(page)
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


@pytest.mark.parametrize(
    ("app", "zoom"), [("lab", 1.0), ("lab", 1.25), ("lab", 1.5), ("notebook", 1.0)]
)
def test_view_and_readout_fit_a_projector_at_every_zoom(
    lab: Lab, browser: Any, app: str, zoom: float
) -> None:
    # 1280x720 at browser zoom 100/125/150 %: the page is 1280/zoom CSS px wide, the file
    # browser open (JupyterLab's default); the view and the rows N, |N|, area and unit normal
    # are seen together once the explorer is scrolled to, the toolbar is one row
    context = browser.new_context(
        viewport={"width": round(1280 / zoom), "height": round(720 / zoom)},
        device_scale_factor=zoom,
    )
    page = context.new_page()
    try:
        lab.write_notebook("fit.ipynb", FIT)
        open_notebook(lab, page, "fit.ipynb", app)
        run_all(page)
        page.wait_for_selector(".tnx-root canvas", timeout=90_000)
        page.wait_for_timeout(800)
        m = page.evaluate(LAYOUT)
        page.wait_for_timeout(200)
        m = page.evaluate(LAYOUT)
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
    finally:
        context.close()
