"""The 3D views' bundles: committed output equals a fresh build from js/explorer/, and is offline.

``make js`` builds from ``js/explorer/src`` and ``package-lock.json``, into
``trinormal/explorer/static/``: ``explorer.js`` (the Jupyter widget: both views and three.js in
one file) and ``site-modules/`` (the site's modules: ``explorer.js``, ``mesh.js`` and their shared
chunk), each with its licence file. These tests rebuild into a temporary directory and compare
every file byte for byte, so a change to the sources without a rebuild (or a hand edit of a
bundle, or a file the build no longer writes) fails here.
"""

from __future__ import annotations

import json
import random
import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
JS = ROOT / "js" / "explorer"
STATIC = ROOT / "trinormal" / "explorer" / "static"
#: The files the build writes whatever the sources (the shared chunk's name has a hash).
OUTPUTS = (
    "explorer.js",
    "THIRD_PARTY_LICENSES.txt",
    "site-modules/explorer.js",
    "site-modules/mesh.js",
    "site-modules/THIRD_PARTY_LICENSES.txt",
)
REBUILD = "run `make js` and commit trinormal/explorer/static/"


def _tool(name: str) -> str:
    path = shutil.which(name)
    assert path, f"`{name}` is not on PATH: install Node.js (with npm) to build the 3D view"
    return path


@pytest.fixture(scope="module")
def fresh(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bundle built now from js/explorer/ (installing its locked packages if needed)."""
    if (
        not (JS / "node_modules" / "three").is_dir()
        or not (JS / "node_modules" / "esbuild").is_dir()
    ):
        subprocess.run(
            [_tool("npm"), "ci", "--no-audit", "--no-fund"], cwd=JS, check=True, capture_output=True
        )
    out = tmp_path_factory.mktemp("explorer-build")
    subprocess.run(
        [_tool("node"), "build.mjs", str(out)], cwd=JS, check=True, capture_output=True, text=True
    )
    return out


def _files(where: Path) -> list[str]:
    return sorted(p.relative_to(where).as_posix() for p in where.rglob("*") if p.is_file())


def test_the_build_writes_the_widget_and_the_sites_modules(fresh: Path) -> None:
    names = _files(fresh)
    assert set(OUTPUTS) <= set(names), names
    chunks = [n for n in names if n not in OUTPUTS]
    assert len(chunks) == 1 and re.fullmatch(r"site-modules/shared-\w+\.js", chunks[0]), chunks


def test_committed_bundles_match_a_fresh_build(fresh: Path) -> None:
    # every file the build writes, and no other (a shared chunk of an older build, say)
    assert _files(STATIC) == _files(fresh), REBUILD
    for name in _files(fresh):
        assert (STATIC / name).read_bytes() == (fresh / name).read_bytes(), (
            f"trinormal/explorer/static/{name} differs from a fresh build of js/explorer/: {REBUILD}"
        )


def test_the_build_is_pinned_and_locked() -> None:
    package = json.loads((JS / "package.json").read_text(encoding="utf-8"))
    lock = json.loads((JS / "package-lock.json").read_text(encoding="utf-8"))
    for group in ("dependencies", "devDependencies"):
        for name, version in package.get(group, {}).items():
            assert re.fullmatch(r"\d+\.\d+\.\d+", version), f"{name} is not pinned: {version!r}"
            assert lock["packages"][f"node_modules/{name}"]["version"] == version, name
    assert "three" in package["dependencies"]


def _scripts() -> list[Path]:
    return sorted(STATIC.rglob("*.js"))


@pytest.mark.parametrize("folder", ["", "site-modules"])
def test_the_licences_beside_each_bundle_name_the_bundled_versions(folder: str) -> None:
    lock = json.loads((JS / "package-lock.json").read_text(encoding="utf-8"))
    versions = {
        name: lock["packages"][f"node_modules/{name}"]["version"]
        for name in ("three", "three-mesh-bvh", "meshoptimizer")
    }
    text = (STATIC / folder / "THIRD_PARTY_LICENSES.txt").read_text(encoding="utf-8")
    assert f"three.js {versions['three']}" in text
    assert "Permission is hereby granted, free of charge" in text  # the MIT licence itself
    # the mesh view's picking (three-mesh-bvh) is bundled too: its licence travels with it
    assert f"three-mesh-bvh {versions['three-mesh-bvh']}" in text
    assert "Copyright (c) 2018 Garrett Johnson" in text
    # and meshoptimizer, the coarser copy of a big model while it turns
    assert f"meshoptimizer {versions['meshoptimizer']}" in text and "Arseny Kapoulkine" in text
    for script in (STATIC / folder).glob("*.js"):  # each file names what it bundles
        head = script.read_text(encoding="utf-8")[:300]
        assert f"three.js {versions['three']}" in head, script.name
        assert f"three-mesh-bvh {versions['three-mesh-bvh']}" in head, script.name
        assert f"meshoptimizer {versions['meshoptimizer']}" in head, script.name
        assert "THIRD_PARTY_LICENSES.txt" in head, script.name


# Ways a script could load code or data from another origin at run time.
_REMOTE = re.compile(
    r"""import\s*\(\s*[`'"](?:https?:)?//"""  # dynamic import("https://...")
    r"""|\bfrom\s*[`'"](?:https?:)?//"""  # static import ... from "https://..."
    r"""|\bimport\s*[`'"](?:https?:)?//"""  # import "https://..."
    r"""|<script[^>]*\bsrc\s*=\s*[`'"]?(?:https?:)?//"""  # a script tag pointing elsewhere
    r"""|\bimportScripts\s*\(\s*[`'"](?:https?:)?//"""
    r"""|\bfetch\s*\(\s*[`'"](?:https?:)?//"""
    r"""|@import\s+(?:url\()?\s*[`'"]?(?:https?:)?//""",  # CSS imports (fonts)
    re.IGNORECASE,
)


def test_the_pattern_catches_remote_loads() -> None:
    for bad in (
        'import("https://cdn.example/three.js")',
        'import {x} from "https://esm.sh/three"',
        '<script src="http://cdn.example/a.js">',
        "fetch('https://example.org/data.json')",
        "@import url('https://fonts.example/css')",
    ):
        assert _REMOTE.search(bad), bad
    assert not _REMOTE.search('createElementNS("http://www.w3.org/1999/xhtml", "img")')


_RELATIVE = re.compile(r"""\b(?:from|import)\s*\(?\s*["'`](\.{0,2}/[^"'`]*)""")


def test_the_bundles_load_nothing_from_another_origin() -> None:
    scripts = _scripts()
    assert len(scripts) == 4, scripts
    for script in scripts:
        found = [m.group(0) for m in _REMOTE.finditer(script.read_text(encoding="utf-8"))]
        assert found == [], f"{script.name} would load from another origin: {found[:5]}"


def test_the_widget_is_one_file_and_the_site_modules_import_only_their_chunk() -> None:
    # anywidget loads the widget from a blob URL, where no relative import resolves
    assert _RELATIVE.findall((STATIC / "explorer.js").read_text(encoding="utf-8")) == []
    site = STATIC / "site-modules"
    (chunk,) = site.glob("shared-*.js")
    assert _RELATIVE.findall(chunk.read_text(encoding="utf-8")) == []
    for entry in ("explorer.js", "mesh.js"):
        imports = _RELATIVE.findall((site / entry).read_text(encoding="utf-8"))
        assert imports == [f"./{chunk.name}"], (entry, imports)


# The view writes a dragged or keyed vertex as grid text; the kernel's sliders and the
# Python side write the same values with trinormal.explorer.state.grid_text. One rule.
_GRID_SCRIPT = """
import { readStep, gridIndex, gridText } from "./src/numbers.js";
let input = "";
process.stdin.on("data", (d) => (input += d));
process.stdin.on("end", () => {
  const { steps, values } = JSON.parse(input);
  const out = steps.map((s) => values.map((x) => gridText(gridIndex(x, readStep(s), null), readStep(s))));
  process.stdout.write(JSON.stringify(out));
});
"""


def test_the_views_grid_text_is_pythons() -> None:
    from trinormal.explorer.state import grid_text

    rng = random.Random(10)
    values = [0.0, -0.05, 0.05, 0.15, 0.25, -0.125, 0.30000000000000004, 1.2345, 2.5, -2.5]
    values += [rng.uniform(-5, 5) for _ in range(200)]
    values += [round(rng.uniform(-5, 5), 2) for _ in range(200)]  # ties are common here
    steps = ["0.1", "0.10", "0.25", "0.05", "1", "2", "1e-3", "0.5"]
    result = subprocess.run(
        [_tool("node"), "--input-type=module", "-e", _GRID_SCRIPT],
        cwd=JS,
        input=json.dumps({"steps": steps, "values": values}),
        capture_output=True,
        text=True,
        check=True,
    )
    got = json.loads(result.stdout)
    for step, row in zip(steps, got, strict=True):
        want = [grid_text(x, step) for x in values]
        bad = [(x, g, w) for x, g, w in zip(values, row, want, strict=True) if g != w]
        assert not bad, f"step {step}: (value, view, python) {bad[:5]}"
