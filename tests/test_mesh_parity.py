"""The "Check a mesh" page and Python are one implementation: the same answer for every file.

The corpus of ``tests/mesh_corpus.py`` (every mesh file the tests use, the page's examples,
and files made in every format and encoding, many of them damaged or unreadable) is written
to a temporary folder with what Python makes of each file: the report, its sentences, the
page's tables of it (`trinormal.mesh_page.report_table`) and the repaired file, or the
error's sentence. ``tests/mesh_parity_check.js`` runs the page's own
JavaScript on the same files in Node, once for the whole corpus, and lists every file where
anything differs, down to one byte of the repaired file.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
from mesh_corpus import corpus, outcome
from node_runs import assert_port_agrees, node_path

from trinormal.mesh import degenerate_faces, face_normals
from trinormal.mesh.io import READ_ERRORS
from trinormal.mesh_page import MESSAGES, PIECE_COLUMNS
from trinormal.tolerances import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs" / "hooks"))
import trinormal_site  # noqa: E402  (the mkdocs hook, imported as the build imports it)


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
            if not entry["expected"]["report"]["faces_to_flip"]:  # nothing to turn over
                assert repaired.read_bytes() == data, name
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
    printing = [r["report"] for r in read]
    assert sum(len(r["holes"]) > 8 for r in printing) >= 1  # a list that ends in "…"
    assert sum(r["volume"] is not None and len(r["components"]) > 1 for r in printing) >= 3
    hints = {r["size"]["units_hint"] for r in printing if r["size"]}
    assert hints == {None, "metres", "inches", "micrometres"}
    assert sum(r["verdict"].endswith(": ready for a slicer") for r in printing) >= 5
    # the page's tables: cavities, a list of holes cut short, hints, no volume, infinite ones
    tables = [r["table"] for r in read]
    cells = [dict((k, t) for k, _, t in table["rows"]) for table in tables]
    cavity = [k for k, _ in PIECE_COLUMNS].index("cavity")
    assert sum(any(p[cavity] == "yes" for p in table["pieces"]) for table in tables) >= 3
    assert sum("more" in c["holes"] for c in cells) >= 3
    assert sum("Read as millimetres" in c["size"] for c in cells) >= 5
    assert sum(c["volume"] == MESSAGES["no_volume_cell"] for c in cells) >= 5
    assert sum(c["volume"] in ("inf", "-inf") for c in cells) >= 1
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
    checker = ROOT / "tests" / "mesh_parity_check.js"
    assert_port_agrees(checker, folder, constants, len(manifest), timeout=300)


def _faces_near_the_threshold(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Faces on, just off and far from the threshold |N| = tol · L², in every corner order.

    Needles, slivers and faces whose float |N| / L² falls inside the band the exact
    arithmetic decides, tilted at random, at scales from subnormal to 1e300.
    """
    corners = []
    for _ in range(300):
        b = rng.normal(size=3)
        side = np.cross(b, rng.normal(size=3))
        h = DEFAULT_TOL * (b @ b) / np.linalg.norm(np.cross(side, b))
        factor = rng.choice(
            [1.0, 1 + 2.0**-50, 1 - 2.0**-50, 1 + 2.0**-45, 0.5, 3.0, 1e-3, 1e6, 1e12]
        )
        c = rng.uniform(0, 1) * b + h * factor * side
        if rng.uniform() < 0.3:  # two corners nearly coincident
            c = b + h * factor * side
        face = np.array([rng.normal(size=3) * rng.choice([0.0, 1.0]), b, c])
        face[1:] += face[0]
        scale = rng.choice([1.0, 2.0**-1040, 1e-300, 1e-150, 1e150, 1e300, 1e307])
        for order in ((0, 1, 2), (1, 2, 0), (2, 0, 1), (0, 2, 1), (2, 1, 0), (1, 0, 2)):
            corners.append(face[list(order)] * scale)
    v = np.concatenate(corners)
    return v, np.arange(v.shape[0], dtype=np.uint32).reshape(-1, 3)


def test_the_pages_normals_and_verdicts_are_pythons_bit_for_bit_near_the_threshold(tmp_path):
    """Random faces around the degenerate threshold: the same verdicts and the same normals."""
    v, f = _faces_near_the_threshold(np.random.default_rng(32))
    want_normals = face_normals(v, f)
    coincident = (v[f[:, 0]] == v[f[:, 1]]).all(1) | (v[f[:, 1]] == v[f[:, 2]]).all(1)
    coincident |= (v[f[:, 2]] == v[f[:, 0]]).all(1)
    want_kind = np.where(coincident, 1, np.where(degenerate_faces(v, f), 2, 0))
    assert 100 < (want_kind == 2).sum() < len(f) - 100  # both verdicts, plenty of each
    (tmp_path / "v.bin").write_bytes(v.astype("<f8").tobytes())
    (tmp_path / "f.bin").write_bytes(f.astype("<u4").tobytes())
    constants = tmp_path / "constants.json"
    constants.write_text(json.dumps(trinormal_site.site_constants()), encoding="utf-8")
    script = """
        const fs = require("fs"), path = require("path");
        const [checker, dir, constants] = process.argv.slice(1);
        const M = require(checker).loadMesh(JSON.parse(fs.readFileSync(constants, "utf8")));
        const read = (n) => fs.readFileSync(path.join(dir, n));
        const vb = read("v.bin"), fb = read("f.bin");
        const v = new Float64Array(vb.buffer, vb.byteOffset, vb.length / 8);
        const f = new Uint32Array(fb.buffer, fb.byteOffset, fb.length / 4);
        fs.writeFileSync(path.join(dir, "n.bin"), M.internal.faceNormals(v, f));
        fs.writeFileSync(path.join(dir, "k.bin"), M.degenerateFaces(v, f));
    """
    run = subprocess.run(
        [
            node_path(),
            "-e",
            script,
            str(ROOT / "tests" / "mesh_parity_check.js"),
            str(tmp_path),
            str(constants),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    got_kind = np.frombuffer((tmp_path / "k.bin").read_bytes(), dtype=np.uint8)
    got_normals = np.frombuffer((tmp_path / "n.bin").read_bytes(), dtype="<f8").reshape(-1, 3)
    assert np.flatnonzero(got_kind != want_kind).tolist() == []
    differ = (got_normals.view(np.uint64) != want_normals.view(np.uint64)).any(axis=1)
    assert np.flatnonzero(differ).tolist() == []
