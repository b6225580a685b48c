"""The "Check a mesh" page's weld control in Chromium: shown for a near miss, Python's weld=True.

One page load: an unwelded soup whose corners were rounded apart is reported as Python reports
it (a near miss, no weld); the control merges them and the report becomes Python's with
``weld=True``; the fix and the download then keep it, byte for byte Python's repaired file.
"""

from __future__ import annotations

import json

import numpy as np
from mesh_corpus import obj, soup, tri
from test_mesh_site import open_page, reported

from trinormal.mesh import check, fix_winding, icosphere, parse_mesh, write_mesh
from trinormal.mesh_page import MESSAGES


def test_the_weld_control_merges_a_near_miss_as_python_does(page, server, traffic, tmp_path):
    v, polys = soup(tri(*icosphere(1)), 2e-6)
    v, polys = v, np.asarray(polys)[:, ::-1].tolist()  # inside out too: the fix has work
    data = obj(v, polys)
    path = tmp_path / "soup.obj"
    path.write_bytes(data)
    m = parse_mesh(data, "obj", path.name)
    open_page(page, server)
    weld = page.locator("#tn-mesh-weld")
    assert weld.is_hidden()  # no report yet: no control
    page.set_input_files("#tn-mesh-file", str(path))
    assert reported(page) == check(m.vertices, m.faces).to_dict()
    assert weld.is_visible()
    assert weld.inner_text() == MESSAGES["weld"].format(distance="1e-5")
    weld.click()
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'welded'")
    welded = check(m.vertices, m.faces, weld=True)
    assert json.loads(page.locator("#tn-mesh").get_attribute("data-report")) == welded.to_dict()
    assert page.locator("#tn-mesh-status").inner_text() == MESSAGES["welded"].format(
        distance="1e-5"
    )
    assert weld.is_hidden()  # merged: no near miss left
    page.click("#tn-mesh-fix")
    page.wait_for_function("() => document.getElementById('tn-mesh').dataset.state === 'fixed'")
    with page.expect_download() as info:
        page.click("#tn-mesh-download")
    saved = tmp_path / "saved.obj"
    info.value.save_as(saved)
    fixed, flipped = fix_winding(m.vertices, m.faces, weld=True)
    assert len(flipped) == len(polys)
    write_mesh(tmp_path / "python.obj", m, fixed)  # the file itself, those faces turned over
    assert saved.read_bytes() == (tmp_path / "python.obj").read_bytes()
    assert not traffic.problems()
