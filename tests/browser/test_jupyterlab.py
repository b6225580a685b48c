"""The explorer in a real JupyterLab: Run All, the 3D view renders, a drag reaches the kernel.

JupyterLab is the run's shared server (the ``lab`` fixture in conftest.py: one per run,
started from a fresh venv with the built wheel; see jupyterlab_support.py), driven with
Chromium as a student would: the Run menu, a mouse drag on a vertex,
Shift+Enter on a later cell. The kernel's answer is read from that cell's output.
"""

from __future__ import annotations

import re
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

EXPLORER = """\
from fractions import Fraction
from trinormal.explorer import Explorer
ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
ex"""

CHECK = """\
print(ex.result.exact.a == (Fraction(1, 10), Fraction(1, 5), Fraction(3, 10)),
      ex.result.exact.b[0] == Fraction(1, 3))
print(*(ex.texts[k] for k in ("ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz")))"""

#: A projector: the explorer must fit this window without scrolling its output.
PROJECTOR = {"width": 1280, "height": 720}


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
    # the kernel's exact values survive the browser's sliders snapping to their grid
    assert output_text(page, 1).splitlines()[0] == "True True"
    assert coordinates(page) == ["0.1", "0.2", "0.3", "1/3", "0", "0", "0", "2.35", "0"]


def test_the_whole_explorer_fits_a_projector_window(notebook: Any) -> None:
    page = notebook
    explorer = page.locator(".trinormal-explorer").first
    explorer.scroll_into_view_if_needed()
    box = explorer.bounding_box()
    panel = page.locator(".jp-NotebookPanel-notebook").first.bounding_box()
    assert box["height"] <= panel["height"], (box, panel)
    view = page.locator(".jp-OutputArea-output canvas").first.bounding_box()
    assert view["width"] >= 480
    size = page.evaluate(
        "(e) => parseFloat(getComputedStyle(e).fontSize)",
        page.locator('[data-vertex="A"]').first.element_handle(),
    )
    assert size >= 14
    # every piece of text in the explorer, the sliders and boxes included, is at least 14 px
    smallest = page.evaluate(
        """(root) => {
            let least = Infinity;
            for (const e of root.querySelectorAll('*')) {
                const own = [...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim());
                if (own || e.tagName === 'INPUT') {
                    least = Math.min(least, parseFloat(getComputedStyle(e).fontSize));
                }
            }
            return least;
        }""",
        explorer.element_handle(),
    )
    assert smallest >= 14, smallest


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
