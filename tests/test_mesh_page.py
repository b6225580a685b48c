"""The "Check a mesh" page's constants: defined once in Python, complete, and all used.

The page's JavaScript (``docs/assets/javascripts/trinormal-mesh-*.js``, ``mesh-page.js``) names
no sentence, limit or report row of its own: it reads them from ``trinormal.mesh_page`` through
the constants file the site build writes. These tests check that every message key the
JavaScript asks for exists here and that every one defined here is used, that the examples
the page offers are real meshes with something to fix, and that the mesh view's colours can
be told from the page's backgrounds. Browser tests (``tests/browser/test_mesh_site.py``)
compare the page's reports, sentences, messages and repaired files with Python's.
"""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from trinormal import colors, mesh_page
from trinormal.mesh import MeshFileError, check, parse_mesh, read_mesh
from trinormal.mesh.io import OTHER_ERRORS, READ_ERRORS
from trinormal.mesh.printing import shown

ROOT = Path(__file__).resolve().parents[1]
JS = ROOT / "docs" / "assets" / "javascripts"
sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # noqa: E402  (the mkdocs hook, imported as the build imports it)

# message("key" ...), fail("key" ...) and fileError(name, line, "key" ...) in the page's scripts
_KEY = re.compile(r'\b(?:message|fail)\(\s*"(\w+)"|fileError\([^,]+,[^,]+,\s*"(\w+)"')


def js_message_keys() -> set[str]:
    keys = set()
    scripts = [*sorted(JS.glob("trinormal-mesh-*.js")), JS / "mesh-page.js", JS / "mesh-worker.js"]
    for path in scripts:
        for m in _KEY.finditer(path.read_text(encoding="utf-8")):
            keys.add(m.group(1) or m.group(2))
    return keys


def test_every_message_the_page_uses_is_defined_once_in_python_and_every_one_is_used():
    used = js_message_keys()
    assert used - set(mesh_page.MESSAGES) == set()
    assert set(mesh_page.MESSAGES) - used == set()


BAD = ROOT / "tests" / "data" / "meshes" / "bad"


@pytest.mark.parametrize("path", sorted(BAD.iterdir()), ids=lambda p: p.name)
def test_pythons_error_for_a_bad_file_is_the_pages_template(path):
    """The sentence Python raises is the page's template (the same object) filled in."""
    with pytest.raises(MeshFileError) as info:
        read_mesh(path)
    err = info.value
    assert err.key is not None
    assert mesh_page.MESSAGES[err.key] is READ_ERRORS[err.key]
    reason = mesh_page.MESSAGES[err.key].format(**err.params)
    where = mesh_page.MESSAGES["at_line"].format(name=str(path), line=err.line)
    assert str(err) == (f"{where}: {reason}" if err.line else f"{path}: {reason}")
    assert "{" not in str(err)  # every field filled


def test_the_readers_reasons_are_written_once_for_python_and_the_page():
    assert {k: mesh_page.MESSAGES[k] for k in READ_ERRORS} == READ_ERRORS
    assert set(OTHER_ERRORS).isdisjoint(mesh_page.MESSAGES)  # about paths and writing: Python's
    # every MeshFileError the reader raises is made from a template: no sentence of its own
    sources = sorted((ROOT / "trinormal" / "mesh" / "io").glob("*.py"))
    assert {"obj.py", "stl.py", "ply.py"} <= {path.name for path in sources}
    direct = [
        (path.name, node.lineno)
        for path in sources
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id == "MeshFileError"
    ]
    assert direct == []


def test_the_site_build_writes_the_page_constants():
    js = trinormal_site.constants_js()
    assert '"mesh": {' in js
    assert trinormal_site.site_constants()["mesh"] == mesh_page.site_constants()


def test_the_report_rows_are_keys_of_pythons_report():
    v, f = mesh_page.example_mesh("cube-one-face-flipped.obj")
    keys = set(check(v, f).to_dict())
    assert {key for key, _ in mesh_page.REPORT_ROWS} <= keys


def test_the_piece_columns_are_keys_of_pythons_pieces():
    v, f = mesh_page.example_mesh("cube-one-face-flipped.obj")
    keys = set(check(v, f).components[0].to_dict())
    first, *others = (key for key, _ in mesh_page.PIECE_COLUMNS)
    assert first == "piece" and set(others) == keys - {"judged_by"}


def _rows(report: dict) -> dict[str, str]:
    return {key: text for key, _, text in mesh_page.report_table(report)["rows"]}


def test_the_tables_show_a_cavity_its_volume_and_the_report_for_printing():
    """A hollow ball in metres: the inner shell is a cavity with a negative volume."""
    from trinormal.mesh import icosphere

    v, f = icosphere(2)
    hollow = check(np.vstack([v, v * 0.5]), np.vstack([f, f[:, ::-1] + len(v)]))
    d = hollow.to_dict()
    table = mesh_page.report_table(d)
    columns = [key for key, _ in mesh_page.PIECE_COLUMNS]
    outer, inner = ({k: c for k, c in zip(columns, p, strict=True)} for p in table["pieces"])
    assert (outer["piece"], outer["cavity"], inner["piece"], inner["cavity"]) == (
        "1",
        "no",
        "2",
        "yes",
    )
    assert inner["outward"] == "yes" and inner["volume"] == shown(hollow.components[1].volume)
    assert inner["volume"].startswith("-") and not outer["volume"].startswith("-")
    rows = _rows(d)
    p = hollow.printing
    # the words of the summary's lines: its numbers, its units hint, its verdict
    assert rows["surface_area"] == shown(p.surface_area) and rows["volume"] == shown(p.volume)
    assert rows["size"] == "2 × 2 × 2\n" + p.size.lines()[1]
    assert rows["verdict"] == p.verdict and rows["holes"] == "0"
    assert f"Surface area {rows['surface_area']};" in hollow.summary(width=0)


def test_a_table_cell_lists_twelve_items_then_how_many_more():
    # fifteen separate triangles: fifteen pieces, each a hole of 3 edges
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]) + 2.0 * np.arange(15)[:, None, None]
    d = check(v.reshape(-1, 3), np.arange(45).reshape(-1, 3)).to_dict()
    rows = _rows(d)
    holes = d["holes"]
    assert len(holes) > mesh_page.TABLE_LISTED
    listed = ", ".join(str(h) for h in holes[: mesh_page.TABLE_LISTED])
    assert rows["holes"] == f"{len(holes)}: {listed}, {len(holes) - 12} more"
    assert rows["volume"] == mesh_page.MESSAGES["no_volume_cell"]
    assert rows["boundary_edges"].startswith(f"{len(d['boundary_edges'])}: edges ")
    assert rows["unused_vertices"] == "0" and rows["n_components"] == "15"
    empty = _rows(check(np.zeros((0, 3)), np.zeros((0, 3), dtype=int)).to_dict())
    assert empty["size"] == "—" and empty["outward"] == "—"


@pytest.mark.parametrize("name", [n for n, _ in mesh_page.EXAMPLES])
def test_each_example_is_a_file_python_reads_with_something_to_fix(name):
    data = mesh_page.example_file(name)
    m = parse_mesh(data, name.rsplit(".", 1)[-1], name)
    report = check(m.vertices, m.faces)
    assert len(report.faces_to_flip) > 0
    assert not report.ok
    assert m.encoding == ("binary" if name.endswith(".stl") else "ascii")


def _luminance(hex_colour: str) -> float:
    rgb = [int(hex_colour[i : i + 2], 16) / 255 for i in (1, 3, 5)]
    lin = [c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4 for c in rgb]
    return 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]


def _contrast(a: str, b: str) -> float:
    hi, lo = sorted((_luminance(a), _luminance(b)), reverse=True)
    return (hi + 0.05) / (lo + 0.05)


@pytest.mark.parametrize("role", ["flipped", "boundary", "non_manifold"])
def test_the_mesh_views_colours_stand_out_from_the_background(role):
    assert _contrast(colors.color(role), "#FFFFFF") >= 3
    assert _contrast(colors.color(role, dark=True), "#1B1D24") >= 3
