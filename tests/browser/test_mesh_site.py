"""The "Check a mesh" page in Chromium: the same report as Python, a repair that holds, no upload.

* The reader and the check (``docs/assets/javascripts/trinormal-mesh.js``, the very file the page
  and its worker load) run on every mesh file of ``tests/data/meshes/`` and on the page's
  examples in a blank page, after the constants the site build writes; each report must equal
  Python's ``trinormal.mesh.check(*read(file)).to_dict()`` computed here, and its sentences
  Python's ``summary()``.
* On the built page: a file chosen with the file input is reported as Python reports it; "Fix
  winding" offers a download in the same format, which Python reads back consistent and outward;
  a file that is not a mesh gets the package's message; a big binary STL moves the progress bar
  while the worker reads it; nothing leaves the site.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from browser_support import ROOT

from trinormal.mesh_page import EXAMPLES, MESSAGES, example_file

sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # the mkdocs hook, imported as the build imports it

MESH_JS = ROOT / "docs/assets/javascripts/trinormal-mesh.js"

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
    """Python's report of a file and its sentences, one per line (unwrapped)."""
    from trinormal.mesh import check, parse_mesh

    m = parse_mesh(data, name.rsplit(".", 1)[-1], name)
    r = check(m.vertices, m.faces)
    return r.to_dict(), re.sub(r"\n  ", " ", r.summary()).split("\n")


def _b64(data: bytes) -> str:
    import base64

    return base64.b64encode(data).decode()


@pytest.fixture
def blank(page):
    page.set_content("<!doctype html><html><body></body></html>")
    page.add_script_tag(content=trinormal_site.constants_js())
    page.add_script_tag(path=str(MESH_JS))
    return page


def test_the_examples_are_reported_as_python_reports_them(blank):
    for name, _label in EXAMPLES:
        got = blank.evaluate(_RUN, [name, _b64(example_file(name))])
        assert "error" not in got, (name, got)
        want, sentences = python_report(name, example_file(name))
        assert got["report"] == want, name
        assert got["summary"] == sentences, name
        assert want["faces_to_flip"], f"{name}: an example should have something to fix"


def test_a_file_that_is_not_a_mesh_gets_the_packages_message(blank):
    cases = {
        "photo.stl": b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4,
        "notes.obj": b"Dear student,\nthis is a letter, not a model.\n",
        "empty.ply": b"",
        "letter.txt": b"hello",
        "bad-number.obj": b"v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n",
    }
    expected = {
        "photo.stl": MESSAGES["stl_size"].split("{")[0],
        "notes.obj": MESSAGES["empty"].format(name="notes.obj", format="OBJ"),
        "empty.ply": MESSAGES["empty_file"].format(name="empty.ply"),
        "letter.txt": MESSAGES["unknown_format"].split("{")[0],
        "bad-number.obj": MESSAGES["bad_number"].format(name="bad-number.obj", line=2, what="y"),
    }
    for name, data in cases.items():
        got = blank.evaluate(_RUN, [name, _b64(data)])
        assert got.get("kind") == "MeshError", (name, got)
        assert got["error"].startswith(expected[name]), (name, got["error"])
        assert "NaN" not in got["error"] and " at " not in got["error"], got["error"]


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


def test_choose_fix_and_download(page, server, traffic, tmp_path):
    """The file chooser, the report, Fix winding, the download read back by Python."""
    from trinormal.mesh import check

    name = "sphere-hole-flipped-patch.ply"
    path = tmp_path / name
    path.write_bytes(example_file(name))
    open_page(page, server)
    page.set_input_files("#tn-mesh-file", str(path))
    want, sentences = python_report(name, example_file(name))
    assert reported(page) == want
    assert page.locator("#tn-mesh-summary li").all_inner_texts() == sentences
    page.wait_for_selector("#tn-mesh-view[data-ready='true'] canvas")
    assert page.locator("#tn-mesh-download").is_disabled()

    page.click("#tn-mesh-fix")
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'fixed'")
    after = reported(page)
    assert after["faces_to_flip"] == [] and after["consistent_winding"]
    with page.expect_download() as info:
        page.click("#tn-mesh-download")
    download = info.value
    assert download.suggested_filename == "sphere-hole-flipped-patch-fixed.ply"
    saved = tmp_path / download.suggested_filename
    download.save_as(saved)
    v, f = read_ply(saved)
    again = check(v, f)
    assert again.consistent_winding and len(again.faces_to_flip) == 0
    assert after == again.to_dict()  # the page's report of the repaired mesh is Python's
    assert not traffic.problems()


def test_a_bad_file_shows_a_message_not_a_crash(page, server, traffic, tmp_path):
    path = tmp_path / "holiday.stl"
    path.write_bytes(b"\xff\xd8\xff\xe0" + bytes(300))
    open_page(page, server)
    page.set_input_files("#tn-mesh-file", str(path))
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'error'")
    text = page.locator("#tn-mesh-status").inner_text()
    assert text.startswith("holiday.stl is not a complete binary STL file"), text
    assert page.locator("#tn-mesh-result").is_hidden()
    assert not traffic.problems()


def test_a_big_binary_stl_moves_the_progress_bar(page, server, traffic, tmp_path):
    """The worker reports progress while it reads; the page keeps drawing frames meanwhile."""
    from trinormal.mesh import torus

    v, f = torus(n_major=400, n_minor=250)  # 200,000 triangles, 10 MB
    path = tmp_path / "big.stl"
    path.write_bytes(binary_stl(v, f))
    open_page(page, server)
    page.evaluate(
        """() => {
          window.__seen = [];
          window.__frames = 0;
          const bar = document.getElementById('tn-mesh-progress');
          const tick = () => {
            window.__frames++;
            if (!window.__seen.includes(bar.value)) window.__seen.push(bar.value);
            if (document.getElementById('tn-mesh').dataset.state !== 'done') requestAnimationFrame(tick);
          };
          requestAnimationFrame(tick);
        }"""
    )
    page.set_input_files("#tn-mesh-file", str(path))
    report = reported(page)
    assert report["n_faces"] == len(f) and report["ok"]
    seen = page.evaluate("window.__seen")
    assert any(0 < x < 100 for x in seen), seen  # the bar moved while the page kept drawing
    assert not traffic.problems()


def test_examples_are_one_click_away(page, server, traffic):
    open_page(page, server)
    buttons = page.locator("button[data-example]")
    assert buttons.count() == len(EXAMPLES)
    buttons.nth(0).click()
    want, _ = python_report(EXAMPLES[0][0], example_file(EXAMPLES[0][0]))
    assert reported(page) == want
    assert not traffic.problems()


# --------------------------------------------------------------------------- files


def binary_stl(v, f) -> bytes:
    record = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(f), dtype=record)
    data["corners"] = np.asarray(v)[np.asarray(f)]
    return bytes(80) + np.uint32(len(f)).tobytes() + data.tobytes()


def read_ply(path: Path):
    lines = path.read_text().splitlines()
    end = lines.index("end_header")
    nv = int(next(x for x in lines if x.startswith("element vertex")).split()[-1])
    body = lines[end + 1 :]
    v = np.array([[float(t) for t in row.split()] for row in body[:nv]])
    f = np.array([[int(t) for t in row.split()[1:]] for row in body[nv:]])
    return v, f
