"""The explorer in JupyterLab for a reader who cannot see it: described, and driven by keyboard only.

On the run's shared Jupyter server (the ``lab`` fixture, conftest.py), as a screen-reader user
works: the accessibility tree names the toolbar, its buttons, the view, its description and
every coordinate's box; from the toolbar, Tab and Enter look down the z axis, Tab reaches
vertex C, and the arrow keys move it across the line AB: the live description changes to the
back of the triangle; Enter on the flip turns it to the front, and ``ex.describe()`` in the
kernel prints the view's words (the view tells the kernel where it looks from). Every control is at least 24 px and shows its focus,
and axe-core finds nothing serious in the explorer. "Download for 3D printing" says in
words why a thin triangle is refused, and downloads the kernel's model once a cell widens it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from axe_playwright_python.base import AxeResults
from jupyterlab_support import Lab, open_notebook, output_text, run_all, run_cell, wait_idle
from page_checks import AXE, AXE_OPTIONS, serious

from trinormal import triangle_normal
from trinormal.explorer.describe import describe
from trinormal.printmodel import print_model

CELLS = [
    "from trinormal.explorer import Explorer\nex = Explorer()\nex",
    "print(ex.texts['cy'], ex.winding.value)\nprint(ex.describe())",
    "ex.set(c=(0, 1, 0))",
]

DESCRIPTION = ".tnx-root .tnx-describe"

# every control a reader can reach: its name, size and focus ring, once focused
CONTROLS = """() => [...document.querySelectorAll(
    '.tnx-root button, .tnx-root input, .tnx-root select, .tnx-root [data-vertex]')]
  .filter((e) => e.getClientRects().length)
  .map((e) => { e.focus(); const r = e.getBoundingClientRect(); const c = getComputedStyle(e);
                return { name: e.getAttribute('aria-label') || e.closest('label')?.textContent
                               || (e.matches('button') ? e.textContent : '') || '',
                         width: r.width, height: r.height, ring: c.outlineStyle }; })"""


def _tab_to(page: Any, selector: str, back: bool = False, limit: int = 60) -> None:
    """Press Tab (or Shift+Tab) until the focus is on `selector`."""
    for _ in range(limit):
        if page.evaluate("s => document.activeElement?.matches(s) ?? false", selector):
            return
        page.keyboard.press("Shift+Tab" if back else "Tab")
    raise AssertionError(f"Tab never reached {selector}")


def _said(page: Any, text: str) -> None:
    page.wait_for_function(
        "([sel, text]) => document.querySelector(sel)?.textContent === text",
        arg=[DESCRIPTION, text],
        timeout=30_000,
    )


def test_the_explorer_in_jupyterlab_is_described_and_driven_by_keyboard(
    lab: Lab, browser: Any
) -> None:
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    try:
        lab.write_notebook("words.ipynb", CELLS)
        open_notebook(lab, page, "words.ipynb")
        run_all(page)
        page.wait_for_selector('[data-vertex="C"]', timeout=60_000)
        wait_idle(page)

        tree = page.locator(".tnx-root").aria_snapshot()
        for line in ('toolbar "3D view"', 'button "View along the z axis"', 'button "Listen to U',
                     'group "3D view of the triangle ABC and its normal N', "- status:",
                     'group "Coordinates"', 'textbox "C.y, exact value'):  # fmt: skip
            assert line in tree, (line, tree)

        # into the toolbar, Tab and Enter on z: the front, A→B→C counter-clockwise
        page.locator(".tnx-toolbar button").first.focus()
        _tab_to(page, '[aria-label="View along the z axis"]')
        page.keyboard.press("Enter")
        _said(page, describe(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)), (0, 0, 1)))

        # Tab to C, arrow keys across AB: the back, and the order turns clockwise
        _tab_to(page, '[data-vertex="C"]')
        for _ in range(11):
            page.keyboard.press("ArrowDown")
        below = describe(triangle_normal((0, 0, 0), (1, 0, 0), (0, "-0.1", 0)), (0, 0, 1))
        _said(page, below)
        assert "You see the back" in below and "A→B→C turns clockwise" in below

        # back to the toolbar, Enter on the flip: the other order, the front again
        _tab_to(page, '[aria-label^="Flip the order"]', back=True)
        page.keyboard.press("Enter")
        flipped = triangle_normal((0, 0, 0), (1, 0, 0), (0, "-0.1", 0), winding="ACB")
        _said(page, describe(flipped, (0, 0, 1)))
        # the kernel says what the view says (the view told it where it looks from)
        run_cell(page, 1)
        page.wait_for_function(
            "() => document.querySelectorAll('.jp-Notebook .jp-Cell')[1]"
            ".querySelector('.jp-OutputArea-output')?.innerText.startsWith('-0.1 ACB')",
            timeout=30_000,
        )
        said = page.locator(DESCRIPTION).inner_text()
        assert output_text(page, 1).splitlines()[1] == said == describe(flipped, (0, 0, 1))

        controls = page.evaluate(CONTROLS)
        assert len(controls) >= 9 + 9 + 3 + 8  # sliders, boxes, points, buttons and more
        small = [c for c in controls if c["width"] < 24 or c["height"] < 24]
        assert small == [], small
        assert [c for c in controls if c["ring"] == "none"] == []
        assert [c for c in controls if not c["name"].strip()] == []

        page.evaluate(AXE.axe_script)
        results = page.evaluate("o => axe.run(document.querySelector('.tnx-root'), o)", AXE_OPTIONS)
        assert serious(AxeResults(results)) == []

        # Download for 3D printing: a triangle too thin for its ridges is refused in words...
        status = page.locator(".tnx-root .tnx-print-status")
        printing = page.locator(".tnx-root").get_by_role(
            "button", name="Download for 3D printing", exact=True
        )
        printing.click()
        page.wait_for_function(
            "el => el.textContent.includes('too thin')", arg=status.element_handle()
        )
        # ...and once a cell has made it wider, the kernel's model of it is downloaded
        run_cell(page, 2)
        page.wait_for_function(
            "() => document.querySelector('.tnx-root input[aria-label^=\"C.y, exact\"]')?.value === '1'",
            timeout=30_000,
        )
        with page.expect_download() as download:
            printing.click()
        want = print_model((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="ACB").stl()
        assert Path(download.value.path()).read_bytes() == want
    finally:
        context.close()
