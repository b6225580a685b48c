"""The "Check a mesh" page and Python are one implementation: the same answer for every file.

The corpus of ``tests/mesh_corpus.py`` (every mesh file the tests use, the page's examples,
and files made in every format and encoding, many of them damaged or unreadable) is written
to a temporary folder with what Python makes of each file: the report, its sentences and the
repaired file, or the error's sentence. ``tests/mesh_parity_check.js`` runs the page's own
JavaScript on the same files in Node, once for the whole corpus, and lists every file where
anything differs, down to one byte of the repaired file.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

from mesh_corpus import corpus, outcome

from trinormal.mesh.io import READ_ERRORS

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # noqa: E402  (the mkdocs hook, imported as the build imports it)


def _node() -> str:
    path = shutil.which("node")
    assert path, "`node` is not on PATH: install Node.js to test the site's JavaScript"
    return path


def write_corpus(folder: Path) -> list[dict]:
    """The corpus on disk with Python's outcomes; its manifest."""
    manifest = []
    for i, (name, data) in enumerate(corpus()):
        (folder / f"{i}.in").write_bytes(data)
        entry = {"name": name, "file": f"{i}.in", "repaired": None}
        repaired = folder / f"{i}.out.{name.rsplit('.', 1)[-1].lower()}"
        entry["expected"] = outcome(name, data, repaired)
        if "error" not in entry["expected"]:
            entry["repaired"] = repaired.name
        manifest.append(entry)
    (folder / "manifest.json").write_text(json.dumps(manifest), encoding="utf-8")
    return manifest


def assert_every_kind_of_file(manifest: list[dict]) -> None:
    """Enough files of each format and encoding, fixable ones, and every reason for refusal."""
    read = [e["expected"] for e in manifest if "error" not in e["expected"]]
    kinds = {(r["format"], r["binary"]) for r in read}
    assert kinds == {("obj", False), ("stl", False), ("stl", True), ("ply", False), ("ply", True)}
    assert sum(bool(r["report"]["faces_to_flip"]) for r in read) >= 40
    assert sum(r["split_polygons"] > 0 for r in read) >= 5
    for key in ("boundary_edges", "non_manifold_edges", "non_manifold_vertices", "duplicate_faces",
                "reversed_duplicate_faces", "coincident_faces", "collinear_faces"):  # fmt: skip
        assert sum(bool(r["report"][key]) for r in read) >= 3, key
    refused = {e["expected"].get("key") for e in manifest}
    parts = {"at_line", "no_extension", "ply_valid", "ply_no_vertices"}  # parts of sentences
    assert set(READ_ERRORS) - parts - refused == set()
    assert "no_faces" in refused


def test_the_page_gives_pythons_answer_and_file_for_every_corpus_file(tmp_path):
    """One Node run for the whole corpus (which must hold every kind of file): no difference."""
    folder = tmp_path / "corpus"
    folder.mkdir()
    manifest = write_corpus(folder)
    assert_every_kind_of_file(manifest)
    constants = tmp_path / "constants.json"
    constants.write_text(json.dumps(trinormal_site.site_constants()), encoding="utf-8")
    run = subprocess.run(
        [_node(), str(ROOT / "tests" / "mesh_parity_check.js"), str(folder), str(constants)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.stdout, run.stderr
    result = json.loads(run.stdout)
    assert result["checked"] == len(manifest)
    assert result["mismatches"] == []
    assert run.returncode == 0, run.stderr
