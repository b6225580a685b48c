"""The "Check a mesh" page in Chromium: the same report as Python, a repair that holds, no upload.

* The reader and the check (``docs/assets/javascripts/trinormal-mesh-*.js``, the very files the
  page and its worker load) run on every mesh file of ``tests/data/meshes/`` and on the page's
  examples in a blank page, after the constants the site build writes; each report must equal
  Python's ``trinormal.mesh.check(*read(file)).to_dict()`` computed here, and its sentences
  Python's ``summary()``.
* On the built page: a file chosen with the file input is reported as Python reports it; "Fix
  winding" offers a download in the same format, which Python reads back consistent and outward;
  a file that is not a mesh gets the package's message; a big binary STL moves the progress bar
  while the worker reads it; nothing leaves the site.
"""

from __future__ import annotations

import base64
import json
import random
import sys

import numpy as np
import pytest
from browser_support import ROOT
from mesh_corpus import damaged
from page_checks import resize

from trinormal.mesh_page import (
    EXAMPLES,
    LIMITS,
    MESSAGES,
    PIECE_COLUMNS,
    REPORT_ROWS,
    example_file,
    file_size,
    report_table,
)
from trinormal.printmodel import SAMPLE, sample_file

sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # the mkdocs hook, imported as the build imports it

#: The scripts in the order the worker loads them after the constants: the exact core (the
#: check takes its isqrt), then the mesh parts.
MESH_JS = [
    ROOT / "docs/assets/javascripts" / name
    for name in (
        "trinormal-core.js",
        *(
            f"trinormal-mesh-{p}.js"
            for p in ("base", "read", "weld", "shells", "check", "write", "print")
        ),
    )
]
MESHES = ROOT / "tests/data/meshes"

#: Run the reader and the check on one file's bytes (base64) in the page; a MeshError's message.
_RUN = """([name, b64]) => {
  const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
  try {
    const mesh = TrinormalMesh.read(bytes, name);
    const report = TrinormalMesh.toDict(TrinormalMesh.check(mesh.vertices, mesh.faces));
    return {report, summary: TrinormalMesh.summary(report), format: mesh.format, binary: mesh.binary};
  } catch (err) {
    return {error: err.message, kind: err.name};
  }
}"""


def python_report(name: str, data: bytes) -> tuple[dict, list[str]]:
    """Python's report of a file and its sentences, one per line."""
    from trinormal.mesh import check, parse_mesh

    m = parse_mesh(data, name.rsplit(".", 1)[-1], name)
    r = check(m.vertices, m.faces)
    return r.to_dict(), r.summary(width=0).split("\n")


def python_result(name: str, data: bytes) -> dict:
    """What Python makes of a file: its report and sentences, or its MeshFileError's message."""
    from trinormal.mesh import MeshFileError

    try:
        report, summary = python_report(name, data)
    except MeshFileError as exc:
        return {"error": str(exc)}
    return {"report": report, "summary": summary}


def _b64(data: bytes) -> str:
    return base64.b64encode(data).decode()


def js_results(page, files: list[tuple[str, bytes]]) -> list[dict]:
    return [page.evaluate(_RUN, [name, _b64(data)]) for name, data in files]


def assert_same(files: list[tuple[str, bytes]], got: list[dict]) -> None:
    for (name, data), js in zip(files, got, strict=True):
        py = python_result(name, data)
        if "error" in py:
            assert js.get("kind") == "MeshError", (name, js)
            assert js["error"] == py["error"], name
        else:
            assert "error" not in js, (name, js)
            assert js["report"] == py["report"], name
            assert js["summary"] == py["summary"], name


@pytest.fixture
def blank(page):
    page.set_content("<!doctype html><html><body></body></html>")
    page.add_script_tag(content=trinormal_site.constants_js())
    for path in MESH_JS:
        page.add_script_tag(path=str(path))
    return page


def test_every_test_file_gets_pythons_report_or_pythons_message(blank):
    """tests/data/meshes/ (good files, and bad ones under bad/) and the page's examples."""
    files = [(p.name, p.read_bytes()) for p in sorted(MESHES.rglob("*.*"))]
    files += [(name, example_file(name)) for name, _ in EXAMPLES]
    assert_same(files, js_results(blank, files))
    bad = [f for f in files if "error" in python_result(*f)]
    assert len(bad) >= 5 and len(files) - len(bad) >= 5 + len(EXAMPLES)
    for name, _ in EXAMPLES:  # each example has something to fix
        assert python_result(name, example_file(name))["report"]["faces_to_flip"], name


def test_damaged_files_get_pythons_report_or_pythons_message(blank):
    """Seeded random edits of the good test files: the same report, or the same sentence."""
    rng = random.Random(20)
    sources = sorted(MESHES.glob("*.*"))
    files = []
    for k in range(80):
        src = rng.choice(sources)
        files.append((f"damaged{k}{src.suffix}", damaged(rng, src.read_bytes())))
    # a file left with no faces is read by Python; the page says it has nothing to check
    kept = [
        f for f in files if "error" in python_result(*f) or python_result(*f)["report"]["n_faces"]
    ]
    got = js_results(blank, kept)
    assert_same(kept, got)
    assert sum("error" in g for g in got) >= 20 and sum("error" not in g for g in got) >= 10


# --------------------------------------------------------------------------- the page


def open_page(page, server: str) -> None:
    page.goto(server + "mesh/")
    page.wait_for_selector("#tn-mesh[data-ready='true']")


def reported(page) -> dict:
    page.wait_for_function(
        "() => ['done', 'fixed', 'error'].includes(document.getElementById('tn-mesh').dataset.state)"
    )
    assert page.locator("#tn-mesh").get_attribute("data-state") != "error", page.locator(
        "#tn-mesh-status"
    ).inner_text()
    return json.loads(page.locator("#tn-mesh").get_attribute("data-report"))


def open_example(page, server: str, k: int) -> dict:
    """Open the page, click example ``k``, wait for its report and its drawn view; the report."""
    open_page(page, server)
    page.locator("button[data-example]").nth(k).click()
    report = reported(page)
    page.wait_for_selector("#tn-mesh-view[data-ready='true'] canvas")
    return report


def open_stl(page, server: str, path, v, f):
    """Open the page on ``(v, f)`` written as a binary STL at ``path``; the mesh view's root."""
    path.write_bytes(binary_stl(v, f))
    open_page(page, server)
    page.set_input_files("#tn-mesh-file", str(path))
    assert reported(page)["n_faces"] == len(f)
    return page.locator("#tn-mesh-view .tnm-root")


def test_choose_fix_and_download(page, server, traffic, tmp_path):
    """The file chooser, the report, Fix winding, and a download Python reads back repaired."""
    from trinormal.mesh import check, fix_winding, parse_mesh
    from trinormal.mesh.io.rewrite import _rewrite

    name = "sphere-hole-flipped-patch.ply"
    data = example_file(name)
    path = tmp_path / name
    path.write_bytes(data)
    open_page(page, server)
    page.set_input_files("#tn-mesh-file", str(path))
    want, sentences = python_report(name, data)
    assert reported(page) == want
    assert page.locator("#tn-mesh-summary li").all_inner_texts() == sentences
    page.wait_for_selector("#tn-mesh-view[data-ready='true'] canvas")
    assert page.locator("#tn-mesh-download").is_disabled()
    # a list says what it counts, and the page says what the fix leaves (the hole)
    row = page.locator("#tn-mesh-rows tr[data-key='faces_to_flip'] td").inner_text()
    assert row == "5: faces " + ", ".join(map(str, want["faces_to_flip"]))
    assert (
        page.locator("#tn-mesh-rows tr[data-key='boundary_edges'] td")
        .inner_text()
        .startswith("6: edges ")
    )
    assert page.locator("#tn-mesh-fix-note").inner_text() == MESSAGES["fix_only_winding"]

    page.click("#tn-mesh-fix")
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'fixed'")
    after = reported(page)
    # the report is now the repaired file's, and the next step has the focus
    assert page.locator("#tn-mesh-name").inner_text() == "sphere-hole-flipped-patch-fixed.ply"
    assert page.evaluate("document.activeElement.id") == "tn-mesh-download"
    with page.expect_download() as info:
        page.click("#tn-mesh-download")
    download = info.value
    assert download.suggested_filename == "sphere-hole-flipped-patch-fixed.ply"
    saved = tmp_path / download.suggested_filename
    download.save_as(saved)
    m = parse_mesh(saved.read_bytes(), "ply", saved.name)
    again = check(m.vertices, m.faces)
    assert again.consistent_winding and len(again.faces_to_flip) == 0
    assert after == again.to_dict()  # the page's report of the repaired mesh is Python's
    original = parse_mesh(data, "ply", name)
    fixed, _ = fix_winding(original.vertices, original.faces)
    # the file itself with those faces turned over, as write_mesh of the read model writes it
    assert saved.read_bytes() == _rewrite(original, fixed)
    assert not traffic.problems()


def test_a_bad_file_shows_pythons_message_not_a_crash(page, server, traffic, tmp_path):
    data = b"\xff\xd8\xff\xe0" + bytes(300)  # a JPEG's first bytes, named .stl
    path = tmp_path / "holiday.stl"
    path.write_bytes(data)
    open_page(page, server)
    page.set_input_files("#tn-mesh-file", str(path))
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'error'")
    assert page.locator("#tn-mesh-status").inner_text() == python_result(path.name, data)["error"]
    assert page.locator("#tn-mesh-result").is_hidden()
    assert not traffic.problems()


def test_a_binary_stl_with_a_wrong_count_is_read_with_pythons_note(page, server, traffic, tmp_path):
    from trinormal.mesh import cube, parse_mesh
    from trinormal.mesh.io import _encode

    good = _encode(*cube(), "stl", "binary")
    data = good[:80] + bytes(4) + good[84:]  # a triangle count of 0, as some programs write
    path = tmp_path / "zero-count.stl"
    path.write_bytes(data)
    open_page(page, server)
    page.set_input_files("#tn-mesh-file", str(path))
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'done'")
    notes = parse_mesh(data, "stl", path.name).notes
    assert len(notes) == 1
    assert page.locator("#tn-mesh-status").inner_text() == notes[0]
    assert reported(page) == python_report(path.name, data)[0]
    assert not traffic.problems()


def test_a_big_binary_stl_moves_the_progress_bar_and_turns_as_a_coarser_copy(
    page, server, traffic, tmp_path
):
    """The worker reports progress while it reads and checks; the bar shows each step.

    Then the view: while the camera turns, the 200 000-face model is drawn as a coarser copy
    (about 30 000 faces), and in full again once the pointer is released.
    """
    from trinormal.mesh import torus

    v, f = torus(n_major=400, n_minor=250)  # 200,000 triangles, 10 MB
    path = tmp_path / "big.stl"
    path.write_bytes(binary_stl(v, f))
    open_page(page, server)
    page.evaluate(
        """() => {
          window.__seen = [];
          const bar = document.getElementById('tn-mesh-progress');
          new MutationObserver(() => window.__seen.push(bar.value))
            .observe(bar, {attributes: true, attributeFilter: ['aria-valuetext']});
        }"""
    )
    page.set_input_files("#tn-mesh-file", str(path))
    report = reported(page)
    assert report["n_faces"] == len(f) and report["ok"]
    seen = page.evaluate("window.__seen")
    steps = [x for x in seen if 0 < x < 100]
    assert len(set(steps)) >= 5 and steps == sorted(steps), seen  # it moved, forward only
    assert page.locator("#tn-mesh-progress-box").is_hidden()  # and went away at the end

    root = page.locator("#tn-mesh-view .tnm-root")
    page.wait_for_function("(r) => r.dataset.coarseFaces", arg=root.element_handle())
    coarse = int(root.get_attribute("data-coarse-faces"))
    assert 10_000 <= coarse <= 40_000, coarse
    canvas = page.locator("#tn-mesh-view canvas")
    canvas.scroll_into_view_if_needed()
    box = canvas.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    assert root.get_attribute("data-turning") != "true"  # a press alone (a pick) stays full
    page.mouse.move(x + 60, y + 10, steps=4)
    assert root.get_attribute("data-turning") == "true"
    page.mouse.up()
    assert root.get_attribute("data-turning") == "false"
    assert not traffic.problems()


def test_a_model_wound_every_which_way_still_turns_as_a_coarser_copy(
    page, server, traffic, tmp_path
):
    """Every other face reversed: the copy made while turning is still about 30 000 faces.

    (Simplifying without turning a face over keeps nearly every face of such a model; the view
    then takes the grid-merging copy, whose colours are as speckled as the model's.)
    """
    from trinormal.mesh import torus

    v, f = torus(n_major=200, n_minor=180)  # 72 000 faces, above the 60 000 of the copy
    f = f.copy()
    f[::2] = f[::2][:, [0, 2, 1]]
    root = open_stl(page, server, tmp_path / "mixed.stl", v, f)
    page.wait_for_function("(r) => r.dataset.coarseFaces", arg=root.element_handle())
    assert 10_000 <= int(root.get_attribute("data-coarse-faces")) <= 40_000
    assert not traffic.problems()


def test_many_faces_to_flip_are_outlined_by_the_rim_of_their_patch(page, server, traffic, tmp_path):
    """Above 2 000 faces to flip, only the sides on the rim of their patch are outlined.

    The rim is counted here independently: the sides of the faces to flip whose edge no other
    face to flip shares. The legend says what the outline is and how many faces it holds.
    """
    from trinormal.mesh import check, torus

    v, f = torus(n_major=120, n_minor=60)  # 14 400 faces
    f = f.copy()
    centres = v[f].mean(axis=1)
    patch = np.flatnonzero(centres[:, 0] > 0.6)  # a cap of the torus, wound backwards
    f[patch] = f[patch][:, [0, 2, 1]]
    flip = np.asarray(check(v, f).faces_to_flip)
    assert 2_000 < len(flip) < len(f) / 2
    edges: dict[tuple[int, int], int] = {}
    for face in f[flip]:
        for k in range(3):
            a, b = int(face[k]), int(face[(k + 1) % 3])
            edges[min(a, b), max(a, b)] = edges.get((min(a, b), max(a, b)), 0) + 1
    rim = sum(1 for n in edges.values() if n == 1)
    assert 0 < rim < len(flip)

    root = open_stl(page, server, tmp_path / "patch.stl", v, f)
    page.wait_for_function("(r) => r.dataset.flippedSides !== undefined", arg=root.element_handle())
    assert int(root.get_attribute("data-flipped-sides")) == rim
    legend = page.locator("#tn-mesh-view .tnm-legend").inner_text()
    assert f"outline: the rim of each patch of faces to flip ({len(flip)} faces)" in legend
    assert not traffic.problems()


def test_a_dropped_file_is_reported(page, server, traffic):
    """Dropping a file on the box reads it like the file input does."""
    name = "inside-out-torus.stl"
    data = example_file(name)
    open_page(page, server)
    page.evaluate(
        """([name, b64]) => {
          const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
          const transfer = new DataTransfer();
          transfer.items.add(new File([bytes], name));
          const box = document.getElementById('tn-mesh');
          box.dispatchEvent(new DragEvent('dragover', {dataTransfer: transfer, bubbles: true}));
          box.dispatchEvent(new DragEvent('drop', {dataTransfer: transfer, bubbles: true}));
        }""",
        [name, _b64(data)],
    )
    assert reported(page) == python_report(name, data)[0]
    assert page.locator("#tn-mesh-format").inner_text() == "STL (binary)"
    assert not traffic.problems()


def test_a_file_over_the_limit_is_refused_on_its_size_in_megabytes(page, server, traffic):
    """A 512 MiB file (a blob made of references, so nothing is copied) is refused unread."""
    open_page(page, server)
    size = page.evaluate(
        """() => {
          let blob = new Blob([new Uint8Array(1 << 20)]);
          for (let i = 0; i < 9; i++) blob = new Blob([blob, blob]);
          const transfer = new DataTransfer();
          transfer.items.add(new File([blob], 'scan.stl'));
          document.getElementById('tn-mesh')
            .dispatchEvent(new DragEvent('drop', {dataTransfer: transfer, bubbles: true}));
          return blob.size;
        }"""
    )
    assert size == 512 * 2**20
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'error'")
    status = page.locator("#tn-mesh-status").inner_text()
    assert status == MESSAGES["too_large"].format(
        name="scan.stl", size="536.9 MB", max=file_size(LIMITS["max_bytes"])
    )
    assert status.startswith("scan.stl is 536.9 MB; this page reads files of up to 300 MB.")
    assert page.locator("#tn-mesh-result").is_hidden()
    # the same rounding as Python's (up, to a tenth of a MB) on the page's own function
    sizes = [0, 1, 99_999, 100_000, 100_001, 50_000_084, 300_000_000, 300_000_001, 10**12 + 1]
    got = page.evaluate("(sizes) => sizes.map((n) => TrinormalMesh.fileSize(n))", sizes)
    assert got == [file_size(n) for n in sizes]
    assert not traffic.problems()


def test_each_piece_is_a_card_of_labels_on_a_phone_and_a_row_on_a_desktop(page, server, traffic):
    open_example(page, server, 1)  # the sphere: a piece with no answer
    heads = page.locator(".tn-mesh-pieces thead th[scope='col']").all_inner_texts()
    assert heads == [label for _, label in PIECE_COLUMNS]
    # every cell is Python's (report_table): the report for printing's rows, cavity, volume
    name = EXAMPLES[1][0]
    want = report_table(python_report(name, example_file(name))[0])
    cells = """(id) => [...document.getElementById(id).rows].map((tr) =>
      [...tr.cells].map((c) => c.textContent))"""
    assert page.evaluate(cells, "tn-mesh-rows") == [row[1:] for row in want["rows"]]
    assert page.evaluate(cells, "tn-mesh-pieces") == want["pieces"]
    labels = """() => [...document.querySelectorAll('#tn-mesh-pieces th, #tn-mesh-pieces td')]
      .map((c) => getComputedStyle(c, '::before').content)"""
    for width in (1280, 360):
        resize(page, width, 800)
        page.wait_for_timeout(100)
        shown = page.evaluate(labels)
        if width == 360:  # every value beside its column's heading
            assert shown == [f'"{h}"' for h in heads], shown
            assert page.locator(".tn-mesh-pieces thead").bounding_box()["height"] <= 1
        else:  # a table: headings in their columns, none run into the next
            assert set(shown) <= {"none", "normal"}, shown
            fits = page.evaluate(
                """() => [...document.querySelectorAll('.tn-mesh-pieces thead th')]
                  .every((th) => th.scrollWidth <= th.clientWidth)"""
            )
            assert fits
        assert page.evaluate("document.documentElement.scrollWidth") <= width
    # the sphere is open: its "faces outward" has no answer, and the note says what — means
    assert page.locator("#tn-mesh-pieces td").nth(4).inner_text() == "—"
    assert page.locator("#tn-mesh-pieces-note").inner_text() == MESSAGES["pieces_dash"]
    row_labels = page.locator("#tn-mesh-rows th").all_inner_texts()
    assert row_labels == [label for _, label in REPORT_ROWS]
    assert not traffic.problems()


def test_the_view_frames_the_model_not_its_box(page, server, traffic):
    """A round model fills the view's height (framed on its box's corners it filled half)."""
    import io

    from PIL import Image

    page.set_viewport_size({"width": 1280, "height": 800})
    open_example(page, server, 1)  # the sphere
    canvas = page.locator("#tn-mesh-view canvas")
    canvas.evaluate("c => c.scrollIntoView({block: 'center'})")  # clear of the page's header
    page.wait_for_timeout(300)
    shot = Image.open(io.BytesIO(canvas.screenshot())).convert("RGB")
    px = np.asarray(shot).astype(int)
    # the ball's front, in its yellow (shaded): the rows it covers
    r, g, b = px[..., 0], px[..., 1], px[..., 2]
    rows = np.flatnonzero(((r > 150) & (g > 150) & (b < 110)).any(axis=1))
    drawn = (rows.max() - rows.min() + 1) / px.shape[0]
    assert 0.75 <= drawn <= 0.97, drawn
    assert not traffic.problems()


def test_the_keyboard_turns_zooms_and_resets_the_view(page, server, traffic):
    open_example(page, server, 0)
    stage = page.locator("#tn-mesh-view .tnm-stage")
    assert "Arrow keys turn it" in stage.get_attribute("aria-label")
    canvas = page.locator("#tn-mesh-view canvas")
    canvas.evaluate("c => c.scrollIntoView({block: 'center'})")
    page.wait_for_timeout(200)
    home = canvas.screenshot()
    stage.focus()
    scroll = page.evaluate("window.scrollY")
    for key in ("ArrowRight", "ArrowUp", "+"):
        before = canvas.screenshot()
        page.keyboard.press(key)
        page.wait_for_timeout(150)
        assert canvas.screenshot() != before, key
    assert page.evaluate("window.scrollY") == scroll  # the keys went to the view, not the page
    page.keyboard.press("Home")
    page.wait_for_timeout(150)
    assert canvas.screenshot() == home
    assert not traffic.problems()


def test_a_finger_scrolls_the_page_over_the_view_until_a_tap(browser, server):
    context = browser.new_context(
        viewport={"width": 360, "height": 640}, has_touch=True, is_mobile=True
    )
    try:
        page = context.new_page()
        open_example(page, server, 0)
        canvas = page.locator("#tn-mesh-view canvas")
        cdp = context.new_cdp_session(page)

        def centre():
            canvas.evaluate("c => c.scrollIntoView({block: 'center'})")
            page.wait_for_timeout(200)
            box = canvas.bounding_box()
            return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2

        def swipe(x, y, dx, dy):
            cdp.send(
                "Input.dispatchTouchEvent",
                {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]},
            )
            for i in range(1, 9):
                point = {"x": x + dx * i / 8, "y": y + dy * i / 8}
                cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [point]})
            cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
            page.wait_for_timeout(300)

        x, y = centre()
        start = page.evaluate("window.scrollY")
        swipe(x, y, 0, 120)  # one finger down over the view: the page scrolls up
        assert page.evaluate("window.scrollY") < start - 50
        assert page.locator(".tnm-touch-active").count() == 0
        x, y = centre()
        for kind, points in (("touchStart", [{"x": x, "y": y}]), ("touchEnd", [])):
            cdp.send("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})
        page.wait_for_timeout(200)
        assert page.locator(".tnm-touch-active").count() == 1  # a tap turned the view on
        before = canvas.screenshot()
        scroll = page.evaluate("window.scrollY")
        swipe(x, y, 90, 40)  # now one finger turns the model, and the page stays
        assert page.evaluate("window.scrollY") == scroll
        assert canvas.screenshot() != before
        page.locator("h1").tap()  # a touch outside turns it off again
        assert page.locator(".tnm-touch-active").count() == 0
    finally:
        context.close()


def test_examples_are_one_click_away(page, server, traffic):
    open_page(page, server)
    buttons = page.locator("button[data-example]")
    assert buttons.count() == len(EXAMPLES) + 1  # and the printable triangle, last
    buttons.nth(0).click()
    want, _ = python_report(EXAMPLES[0][0], example_file(EXAMPLES[0][0]))
    assert reported(page) == want
    # the model `trinormal print-model` writes, read back, checked and drawn: nothing to fix
    page.locator("#tn-mesh").evaluate("root => { root.dataset.state = ''; }")
    buttons.nth(len(EXAMPLES)).click()
    want, _ = python_report(SAMPLE[0], sample_file())
    assert reported(page) == want
    assert want["closed"] and want["outward"] and want["n_components"] == 1
    assert want["faces_to_flip"] == []
    page.wait_for_selector("#tn-mesh-view[data-ready='true'] canvas")
    assert not traffic.problems()


# --------------------------------------------------------------------------- files


def binary_stl(v, f) -> bytes:
    record = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(f), dtype=record)
    data["corners"] = np.asarray(v)[np.asarray(f)]
    return bytes(80) + np.uint32(len(f)).tobytes() + data.tobytes()


def test_a_report_reads_well_on_a_phone_in_both_schemes(page, server, traffic):
    """At 360 px with a report shown: nothing sticks out, wide tables scroll in their own box."""
    from test_site import _LAYOUT_PROBLEMS

    page.set_viewport_size({"width": 360, "height": 740})
    open_example(page, server, 1)
    page.wait_for_timeout(250)  # scrollboxes.js re-checks 100 ms after a change
    for scheme in ("default", "slate"):
        page.evaluate("s => document.body.setAttribute('data-md-color-scheme', s)", scheme)
        assert page.evaluate(_LAYOUT_PROBLEMS) == [], scheme
    canvas = page.locator("#tn-mesh-view canvas").bounding_box()
    assert canvas and canvas["width"] <= 360 and canvas["height"] >= 200
    assert not traffic.problems()


# --------------------------------------------------------------------------- a face's readout


def python_readout(name: str, face: int) -> list[str]:
    """Python's readout of a face of an example (face_selection), as the page words it."""
    from trinormal.mesh import check, parse_mesh
    from trinormal.mesh.selection import PRECISION, SELECTION, face_selection

    m = parse_mesh(example_file(name), name.rsplit(".", 1)[-1], name)
    sel = face_selection(m.vertices, m.faces, face, PRECISION, check(m.vertices, m.faces))
    lines = [sel["title"]]
    for label, value, role in sel["rows"]:
        if role == "flipped":  # Python names its function, the page its button
            value = SELECTION["flipped"].format(fix="Fix winding")
        lines += [label, value]
    return lines


def readout(page) -> list[str]:
    panel = page.locator("#tn-mesh-view .tnm-pick")
    title = panel.locator(".tnm-pick-title").inner_text()
    return [title, *panel.locator("dt, dd").all_inner_texts()]


def test_a_click_shows_the_faces_exact_readout_as_python_writes_it(page, server, traffic):
    """The face under the pointer, and its vertices, normal and area from the site's core."""
    from trinormal.mesh import parse_mesh

    name = EXAMPLES[1][0]
    assert open_example(page, server, 1)["n_faces"]
    canvas = page.locator("#tn-mesh-view canvas")
    canvas.scroll_into_view_if_needed()
    box = canvas.bounding_box()
    page.mouse.click(box["x"] + box["width"] * 0.45, box["y"] + box["height"] * 0.45)
    root = page.locator("#tn-mesh-view .tnm-root")
    page.wait_for_function("(r) => r.dataset.picked !== undefined", arg=root.element_handle())
    face = int(root.get_attribute("data-picked"))
    assert readout(page) == python_readout(name, face)
    # the face picked is the one under the pointer: the point the ray met lies on it
    m = parse_mesh(example_file(name), name.rsplit(".", 1)[-1], name)
    a, b, c = m.vertices[m.faces[face]]
    hit = np.array([float(x) for x in root.get_attribute("data-pick-point").split(",")])
    n = np.cross(b - a, c - a)
    assert abs(np.dot(hit - a, n)) <= 1e-5 * np.linalg.norm(n)
    for p, q in ((a, b), (b, c), (c, a)):  # on the inner side of every edge
        assert np.dot(np.cross(q - p, hit - p), n) >= -1e-5 * np.dot(n, n)
    assert not traffic.problems()


def test_the_keyboard_picks_a_face_by_number_or_the_next_to_flip(page, server, traffic):
    """A labelled face-number box and buttons through the faces to flip, with focus shown and
    the readout in a live region; a number with no face gets Python's message."""
    from trinormal.mesh import check, parse_mesh
    from trinormal.mesh.selection import SELECTION

    name = EXAMPLES[1][0]
    m = parse_mesh(example_file(name), name.rsplit(".", 1)[-1], name)
    to_flip = check(m.vertices, m.faces).faces_to_flip.tolist()
    open_example(page, server, 1)
    box = page.get_by_label(f"Face number (0 to {len(m.faces) - 1})")
    box.focus()
    page.keyboard.type("7")
    page.keyboard.press("Enter")
    panel = page.locator("#tn-mesh-view .tnm-pick")
    panel.wait_for(state="visible")
    assert readout(page) == python_readout(name, 7)
    # read out once, by the view's description (a live region), which holds the same readout
    words = page.locator("#tn-mesh-view .tnm-describe")
    assert words.get_attribute("aria-live") == "polite"
    assert f"Picked: {readout(page)[0]}." in words.inner_text()
    # Tab to the buttons: the focus is drawn, and "Next face to flip" steps through the list
    page.keyboard.press("Tab")  # Show face
    page.keyboard.press("Tab")  # Previous face to flip
    page.keyboard.press("Tab")  # Next face to flip
    focused = page.evaluate(
        "() => [document.activeElement.textContent, getComputedStyle(document.activeElement)"
        ".outlineStyle, document.activeElement.matches(':focus-visible')]"
    )
    assert focused == ["Next face to flip", "solid", True], focused
    page.keyboard.press("Enter")
    after = [f for f in to_flip if f > 7]
    first = min(after) if after else min(to_flip)  # the list goes round
    assert readout(page) == python_readout(name, first)
    assert box.input_value() == str(first)
    box.fill(str(len(m.faces)))
    box.press("Enter")
    no_face = SELECTION["no_face"].format(face=len(m.faces), last=len(m.faces) - 1)
    assert readout(page) == [no_face, SELECTION["problem_label"], no_face]
    assert not traffic.problems()
