"""One explorer shown twice in JupyterLab: edits made in both views at once both land.

A learner (or two, sharing a screen) edits the same vertex in the two outputs of one
explorer faster than the kernel answers: view 0 types A.x while view 1 presses the arrow
key that moves A.y; view 1 types B.z while view 0 drags B in the view seen along z (which
moves B.x and B.y). All four edits are made in one task of the page, so none of them has
come back from the kernel when the next is made. Each edit names only the coordinates the
learner changed, so the kernel ends with all four, exactly, and both views show that.
A learner edits B while a cell runs that sets C: both are kept, and while the kernel is
busy the readout says it is waiting for it instead of showing the old numbers as current.
Uses the run's shared JupyterLab server (the ``lab`` fixture, conftest.py).
"""

from __future__ import annotations

import json
import time
from typing import Any

from jupyterlab_support import GRID, Lab, open_notebook, output_text, run_all, run_cell
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from trinormal.explorer.view import WAITING

CELLS = [
    "from trinormal.explorer import Explorer\nex = Explorer()\nex",
    "ex  # the same explorer, shown a second time",
    "import json\n_runs = globals().get('_runs', 0) + 1\n"
    "print('RUN', _runs, json.dumps({'texts': ex.texts,\n"
    "      'exact': [[str(x) for x in p] for p in (ex.result.exact.a, ex.result.exact.b)]}))",
]

#: Four edits in one task of the page, two views, two vertices, none answered before the next.
RACE = """() => {
  const [v0, v1] = document.querySelectorAll('.tnx-root');
  const type = (root, index, text) => {
    const box = root.querySelectorAll('.tnx-exact')[index];
    box.value = text;
    box.dispatchEvent(new Event('input', {bubbles: true}));
    box.dispatchEvent(new KeyboardEvent('keydown', {key: 'Enter', bubbles: true}));
  };
  const press = (root, name, key) => root.querySelector(`[data-vertex="${name}"]`)
      .dispatchEvent(new KeyboardEvent('keydown', {key, bubbles: true, cancelable: true}));
  const drag = (root, name, dx, dy) => {
    const label = root.querySelector(`[data-vertex="${name}"]`);
    const r = label.getBoundingClientRect();
    const [x, y] = [r.left + r.width / 2, r.top + r.height / 2];
    const at = (type, cx, cy, buttons) => label.dispatchEvent(new PointerEvent(type, {
      bubbles: true, cancelable: true, pointerId: 1, pointerType: 'mouse', isPrimary: true,
      button: 0, buttons, clientX: cx, clientY: cy}));
    at('pointerdown', x, y, 1);
    at('pointermove', x + dx, y + dy, 1);
    at('pointerup', x + dx, y + dy, 0);
  };
  type(v0, 0, '1/3');          // view 0: A.x
  press(v1, 'A', 'ArrowUp');   // view 1: A.y one grid step up
  type(v1, 5, '2/7');          // view 1: B.z
  drag(v0, 'B', 80, -50);      // view 0, seen along z: B.x and B.y
}"""

#: Per view: its exact boxes (ax … cz) and its vertex labels' positions as it says them.
SHOWN = """() => [...document.querySelectorAll('.tnx-root')].map((root) => ({
  boxes: [...root.querySelectorAll('.tnx-exact')].map((e) => e.value),
  drawn: root.tnxProject().values,
}))"""


def kernel(page: Any, run: int) -> dict[str, Any]:
    """The kernel's texts and exact values, from the ``run``-th run of the last cell."""
    page.wait_for_function(
        """(n) => {
            const out = document.querySelectorAll('.jp-Notebook .jp-Cell')[2]
                .querySelector('.jp-OutputArea-output');
            return out && out.innerText.startsWith('RUN ' + n + ' ');
        }""",
        arg=run,
        timeout=60_000,
    )
    return dict(json.loads(output_text(page, 2).split(" ", 2)[2]))


def test_two_views_editing_one_vertex_at_once_keep_both_edits(lab: Lab, page: Any) -> None:
    page.set_viewport_size({"width": 1280, "height": 720})
    lab.write_notebook("two_views.ipynb", CELLS)
    open_notebook(lab, page, "two_views.ipynb")
    run_all(page)
    page.wait_for_function("() => document.querySelectorAll('.tnx-root canvas').length === 2")
    assert kernel(page, 1)["texts"]["ax"] == "0"
    roots = page.locator(".tnx-root")
    roots.nth(0).scroll_into_view_if_needed()
    roots.nth(0).get_by_role("button", name="View along the z axis").click()

    page.evaluate(RACE)
    run_cell(page, 2)  # its request reaches the kernel after the four edits
    state = kernel(page, 2)
    texts = state["texts"]
    assert (texts["ax"], texts["ay"], texts["az"]) == ("1/3", "0.1", "0"), texts
    assert state["exact"][0] == ["1/3", "1/10", "0"]
    assert texts["bz"] == "2/7" and state["exact"][1][2] == "2/7", texts
    assert (texts["bx"], texts["by"]) != ("1", "0"), texts  # the drag moved B
    assert GRID.fullmatch(texts["bx"]) and GRID.fullmatch(texts["by"]), texts

    # both views show the kernel's values: every box and every drawn vertex
    boxes = [texts[p + q] for p in "abc" for q in "xyz"]
    drawn = [[texts[p + q] for q in "xyz"] for p in "abc"]
    want = {"boxes": boxes, "drawn": drawn}
    deadline = time.monotonic() + 10
    while (shown := page.evaluate(SHOWN)) != [want, want]:
        assert time.monotonic() < deadline, (shown, want)
        page.wait_for_timeout(100)


#: A cell that keeps the kernel busy until the test has made its edits, then sets C.
BUSY = """\
import os, time
while not os.path.exists({flag!r}):
    time.sleep(0.05)
ex.set(c=("-1/3", "2/3", "0.25"))"""

#: The view's readout status, its B and C boxes, and where it draws B and C.
STATUS = """() => {
  const root = document.querySelector('.tnx-root');
  const status = root.querySelector('.tnx-status');
  return {state: status.dataset.state, text: status.textContent,
          boxes: [...root.querySelectorAll('.tnx-exact')].slice(3).map((e) => e.value),
          drawn: root.tnxProject().values.slice(1)};
}"""


def test_an_edit_of_b_while_a_cell_sets_c_keeps_both(lab: Lab, page: Any) -> None:
    flag = lab.root / "edits_made"
    flag.unlink(missing_ok=True)
    cells = [CELLS[0], BUSY.format(flag=flag.name), CELLS[2]]
    lab.write_notebook("busy_kernel.ipynb", cells)
    open_notebook(lab, page, "busy_kernel.ipynb")
    run_cell(page, 0)
    page.wait_for_selector('.tnx-root [data-vertex="B"]', timeout=60_000)
    run_cell(page, 1)  # the kernel is busy until the flag exists
    page.wait_for_selector(".jp-Notebook-ExecutionIndicator[data-status='busy']")
    page.evaluate(
        """() => {
          const root = document.querySelector('.tnx-root');
          const box = root.querySelectorAll('.tnx-exact')[5];  // B.z
          box.value = '2/7';
          box.dispatchEvent(new Event('input', {bubbles: true}));
          box.dispatchEvent(new KeyboardEvent('keydown', {key: 'Enter', bubbles: true}));
          root.querySelector('[data-vertex="B"]').dispatchEvent(new KeyboardEvent('keydown',
              {key: 'ArrowUp', bubbles: true, cancelable: true}));  // B.y one grid step up
        }"""
    )
    # the readout says the kernel has not answered instead of showing its old N as current
    page.wait_for_function(f"() => ({STATUS})().state === 'waiting'", timeout=10_000)
    waiting = page.evaluate(STATUS)
    assert waiting["text"] == WAITING, waiting
    assert waiting["boxes"][:3] == ["1", "0.1", "2/7"], waiting  # the view draws its edits
    flag.touch()  # the cell sets C; then the kernel reads the two edits made before it
    run_cell(page, 2)
    texts = kernel(page, 1)["texts"]
    assert [texts[k] for k in ("bx", "by", "bz")] == ["1", "0.1", "2/7"], texts
    assert [texts[k] for k in ("cx", "cy", "cz")] == ["-1/3", "2/3", "0.25"], texts
    boxes = ["1", "0.1", "2/7", "-1/3", "2/3", "0.25"]
    want = [boxes, [boxes[:3], boxes[3:]]]
    try:
        page.wait_for_function(
            f"""(want) => {{
              const s = ({STATUS})();
              return s.state !== 'waiting' && JSON.stringify([s.boxes, s.drawn]) === want;
            }}""",
            arg=json.dumps(want, separators=(",", ":")),
            timeout=10_000,
        )
    except PlaywrightTimeout:
        shown = page.evaluate(STATUS)
        raise AssertionError(f"the view shows {shown}, not {want}") from None
