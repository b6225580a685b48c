"""The 3D view's bundle: committed output equals a fresh build from js/explorer/, and it is offline.

``trinormal/explorer/static/explorer.js`` (three.js bundled with the view) and its licence
file are built by ``make js`` from ``js/explorer/src`` and ``package-lock.json``. These tests
rebuild into a temporary directory and compare byte for byte, so a change to the sources
without a rebuild (or a hand edit of the bundle) fails here.
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
OUTPUTS = ("explorer.js", "THIRD_PARTY_LICENSES.txt")
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


@pytest.mark.parametrize("name", OUTPUTS)
def test_committed_bundle_matches_a_fresh_build(fresh: Path, name: str) -> None:
    committed = STATIC / name
    assert committed.is_file(), f"{committed.relative_to(ROOT)} is missing: {REBUILD}"
    assert committed.read_bytes() == (fresh / name).read_bytes(), (
        f"{committed.relative_to(ROOT)} differs from a fresh build of js/explorer/: {REBUILD}"
    )


def test_the_build_is_pinned_and_locked() -> None:
    package = json.loads((JS / "package.json").read_text(encoding="utf-8"))
    lock = json.loads((JS / "package-lock.json").read_text(encoding="utf-8"))
    for group in ("dependencies", "devDependencies"):
        for name, version in package.get(group, {}).items():
            assert re.fullmatch(r"\d+\.\d+\.\d+", version), f"{name} is not pinned: {version!r}"
            assert lock["packages"][f"node_modules/{name}"]["version"] == version, name
    assert "three" in package["dependencies"]


def test_the_licence_names_the_bundled_three_version() -> None:
    lock = json.loads((JS / "package-lock.json").read_text(encoding="utf-8"))
    version = lock["packages"]["node_modules/three"]["version"]
    text = (STATIC / "THIRD_PARTY_LICENSES.txt").read_text(encoding="utf-8")
    assert f"three.js {version}" in text
    assert "Permission is hereby granted, free of charge" in text  # the MIT licence itself
    assert f"three.js {version}" in (STATIC / "explorer.js").read_text(encoding="utf-8")[:300]
    # the mesh view's picking (three-mesh-bvh) is bundled too: its licence travels with it
    bvh = lock["packages"]["node_modules/three-mesh-bvh"]["version"]
    assert f"three-mesh-bvh {bvh}" in text and "Copyright (c) 2018 Garrett Johnson" in text
    assert f"three-mesh-bvh {bvh}" in (STATIC / "explorer.js").read_text(encoding="utf-8")[:300]
    # and meshoptimizer, the coarser copy of a big model while it turns
    meshopt = lock["packages"]["node_modules/meshoptimizer"]["version"]
    assert f"meshoptimizer {meshopt}" in text and "Arseny Kapoulkine" in text
    assert f"meshoptimizer {meshopt}" in (STATIC / "explorer.js").read_text(encoding="utf-8")[:300]


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


@pytest.mark.parametrize("name", ["explorer.js"])
def test_the_bundle_loads_nothing_from_another_origin(name: str) -> None:
    text = (STATIC / name).read_text(encoding="utf-8")
    found = [m.group(0) for m in _REMOTE.finditer(text)]
    assert found == [], f"{name} would load from another origin: {found[:5]}"
    # one file: no relative imports left for anywidget's blob URL to fail on
    assert not re.search(r"""\bfrom\s*["'`]\.{0,2}/""", text)
    assert not re.search(r"""\bimport\s*\(\s*["'`]\.{0,2}/""", text)


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
