"""The explorer renders from the wheel's fresh venv in JupyterLab and in Notebook 7.

The run's one JupyterLab server (the ``lab`` fixture, conftest.py) is started from the venv
that ``wheel_env`` made outside the repository with ``wheel[notebooks]``, as a teacher or
a JupyterHub installs it; it serves Notebook 7 as well. Here a notebook creating the
explorer is run in each front end as a student would (the Run menu): the 3D view's canvas
renders with WebGL, the text boxes hold the values exactly as given, the readout shows the
kernel's result, and that kernel imports the package from the fresh venv.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from jupyterlab_support import Lab, open_notebook, run_all

from trinormal import triangle_normal

EXPLORER = """\
import trinormal
from trinormal.explorer import Explorer
ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
ex"""

WHERE = "print(trinormal.__file__)"

#: The exact values the explorer was given, as its text boxes must show them.
TYPED = ["0.1", "0.2", "0.3", "1/3", "0", "0", "0", "2.35", "0"]


def _open_and_run(page: Any, lab: Lab, name: str, app: str) -> None:
    page.set_viewport_size({"width": 1280, "height": 720})
    lab.write_notebook(name, [EXPLORER, WHERE])
    open_notebook(lab, page, name, app)
    run_all(page)
    page.wait_for_selector(".jp-OutputArea-output canvas", timeout=90_000)
    # the last cell's output: the kernel has run every cell
    page.wait_for_function(
        """() => {
            const cells = document.querySelectorAll('.jp-Notebook .jp-Cell');
            const out = cells[cells.length - 1].querySelector('.jp-OutputArea-output');
            return out && out.innerText.includes('trinormal');
        }""",
        timeout=90_000,
    )


def _check_the_explorer(page: Any, wheel_env: Path) -> None:
    canvas = page.locator(".jp-OutputArea-output canvas").first
    assert canvas.is_visible()
    assert page.evaluate(
        "(c) => !!(c.getContext('webgl2') || c.getContext('webgl'))", canvas.element_handle()
    )
    box = canvas.bounding_box()
    assert box["width"] >= 200 and box["height"] >= 150, box
    output = page.locator(".jp-Notebook .jp-Cell").first.locator(".jp-OutputArea-output").first
    # the text boxes hold the values exactly as given: 1/3, not 0.333...
    typed = page.evaluate(
        "(o) => [...o.querySelectorAll('input[type=text]')].map((i) => i.value)",
        output.element_handle(),
    )
    assert typed == TYPED, typed
    # the readout shows the kernel's exact result, written by the package's formatter
    expected = triangle_normal(("0.1", "0.2", "0.3"), ("1/3", 0, 0), (0, "2.35", 0)).format(4)
    text = output.inner_text()
    for key in ("normal", "area", "unit_normal"):
        assert expected[key] in text, (key, expected[key], text)
    assert "NaN" not in text
    # and that kernel runs the wheel's package, from the fresh venv
    cells = page.locator(".jp-Notebook .jp-Cell")
    where = cells.nth(cells.count() - 1).locator(".jp-OutputArea-output").first.inner_text()
    assert Path(where.strip()).is_relative_to(wheel_env.parent.parent), where


def test_the_explorer_renders_from_the_wheel_in_jupyterlab(
    lab: Lab, page: Any, wheel_env: Path
) -> None:
    _open_and_run(page, lab, "wheel_lab.ipynb", "lab")
    _check_the_explorer(page, wheel_env)


def test_the_explorer_renders_from_the_wheel_in_notebook_7(
    lab: Lab, page: Any, wheel_env: Path
) -> None:
    _open_and_run(page, lab, "wheel_nb7.ipynb", "notebook")
    assert "/notebooks/" in page.url and "/lab" not in page.url
    _check_the_explorer(page, wheel_env)
