"""The mesh view in a real JupyterLab: it renders, a click on a face shows its exact normal.

A face's number typed in the view's box, and its "Next face to flip" button, pressed with the
keyboard, get the kernel's readout too.

The run's shared JupyterLab (the ``lab`` fixture in conftest.py, from the wheel's fresh venv)
opens a notebook that shows the triangle explorer and the mesh view of the shipped damaged
ball on one page, runs it with the Run menu as a student would, and clicks the model. The
readout under the view must be the kernel's: the clicked face's normal and area from
``triangle_normal`` on its stored coordinates, computed here again from the same file. The
browser console must stay free of warnings and errors, in particular three.js's "Multiple
instances of Three.js being imported" (both views share one three.js). The one message let
through is Chromium's own "GL Driver Message ... GPU stall due to ReadPixels", which headless
Chromium with ``--disable-gpu`` prints whenever its software compositor reads back any WebGL
canvas: it comes from the browser, not from the page; and the front end's own "Plugin ... took
... to activate" timings (of any of its plugins), which a loaded machine produces while it starts.
"""

from __future__ import annotations

import re
from typing import Any

from jupyterlab_support import Lab, open_notebook, output_text, run_all, run_cell, wait_idle

from trinormal import mesh, triangle_normal

#: Chromium's compositor reading WebGL back in software (see above), the only message allowed.
CHROMIUM_READBACK = re.compile(
    r"^warning: \[\.WebGL-0x[0-9a-f]+\]GL Driver Message \(OpenGL, Performance"
)

CELLS = [
    "from trinormal.explorer import Explorer\nExplorer()",
    "from trinormal import mesh\n"
    "from trinormal.mesh.widget import MeshView\n"
    "model = mesh.read_mesh(mesh.sample_path())\n"
    "view = MeshView(model)\n"
    "view",
    "print(view.picked, view.selection.get('title'))",
]


def test_the_mesh_view_renders_and_a_click_shows_the_exact_normal(lab: Lab, page: Any) -> None:
    messages: list[str] = []
    page.on(
        "console",
        lambda m: (
            messages.append(f"{m.type}: {m.text}") if m.type in ("warning", "error") else None
        ),
    )
    page.on("pageerror", lambda e: messages.append(f"pageerror: {e}"))
    page.set_viewport_size({"width": 1280, "height": 720})
    lab.write_notebook("mesh_view.ipynb", CELLS)
    open_notebook(lab, page, "mesh_view.ipynb")
    run_all(page)
    root = page.locator('.tnm-root[data-faces="1263"]').first
    root.wait_for(timeout=90_000)
    wait_idle(page)
    canvas = root.locator("canvas").first
    root.scroll_into_view_if_needed()
    assert page.evaluate(
        "(c) => !!(c.getContext('webgl2') || c.getContext('webgl'))", canvas.element_handle()
    )
    # the faults are drawn and named in the legend: 53 faces to flip, 13 rim edges, arrows
    legend = root.locator(".tnm-legend").inner_text()
    assert "(53)" in legend and "(13)" in legend and "1263 drawn" in legend, legend
    # the words under the view name the file, as the site page's do (issue 33)
    words = root.locator(".tnm-describe").inner_text()
    assert words.startswith("damaged_ball.obj: 1263 faces in 1 piece."), words

    # a click in the middle of the view: the camera starts looking at the flipped patch
    box = canvas.bounding_box()
    page.mouse.click(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    panel = root.locator(".tnm-pick")
    panel.wait_for(state="visible", timeout=30_000)
    page.wait_for_function(
        "(p) => p.innerText.includes('Face ')", arg=panel.element_handle(), timeout=30_000
    )
    face = int(root.get_attribute("data-picked"))
    model = mesh.read_mesh(mesh.sample_path())
    corners = model.faces[face]
    expected = triangle_normal(*(model.vertices[i].tolist() for i in corners)).format(4)
    text = panel.inner_text()
    assert f"Face {face}: vertices {corners[0]}, {corners[1]}, {corners[2]}" in text, text
    for key in ("normal", "area", "unit_normal"):
        assert expected[key] in text, (key, expected[key], text)
    assert "NaN" not in text
    # the middle of the first view is the damaged patch: the face is one to flip
    assert "fix_winding flips this face" in text, text

    # the keyboard's way: a face number typed in the labelled box, then Enter
    typed = 0 if face != 0 else 1
    number = root.get_by_label(re.compile(r"^Face number"))
    number.fill(str(typed))
    number.press("Enter")
    page.wait_for_function(
        "([p, f]) => p.innerText.startsWith(`Face ${f}:`)",
        arg=[panel.element_handle(), typed],
        timeout=30_000,
    )
    corners = model.faces[typed]
    expected = triangle_normal(*(model.vertices[i].tolist() for i in corners)).format(4)
    assert expected["normal"] in panel.inner_text()
    # and "Next face to flip", pressed with the keyboard, picks the first face to flip after it
    to_flip = mesh.check(model.vertices, model.faces).faces_to_flip.tolist()
    following = min([f for f in to_flip if f > typed] or to_flip)  # the list goes round
    root.get_by_role("button", name="Next face to flip").press("Enter")
    page.wait_for_function(
        "([p, f]) => p.innerText.startsWith(`Face ${f}:`)",
        arg=[panel.element_handle(), int(following)],
        timeout=30_000,
    )
    assert "fix_winding flips this face" in panel.inner_text()
    face = int(following)

    # the kernel holds the same selection
    run_cell(page, 2)
    page.wait_for_function(
        """(face) => {
            const cells = document.querySelectorAll('.jp-Notebook .jp-Cell');
            const out = cells[2].querySelector('.jp-OutputArea-output');
            return out && out.innerText.startsWith(String(face) + ' Face');
        }""",
        arg=face,
        timeout=30_000,
    )
    assert output_text(page, 2).startswith(f"{face} Face {face}: vertices")

    # the explorer above rendered too, from the same three.js
    assert page.locator('[data-vertex="A"]').first.is_visible()
    assert not [m for m in messages if "Three.js" in m or "THREE" in m], messages
    # the front end's note that one of its plugins (JupyterLab's, Notebook 7's, the widget
    # manager's) was slow to start on a busy machine
    lab_timing = re.compile(r"^warning: Plugin @\S+ .*(too long to activate|to activate)")
    left = [m for m in messages if not (CHROMIUM_READBACK.match(m) or lab_timing.match(m))]
    assert not left, left
