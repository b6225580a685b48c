"""The 3D mesh view on the "Check a mesh" page: is it still interactive at 200 000 faces?

A torus with a patch of faces wound the wrong way (outlined by the view) is written as a binary
STL and chosen with the page's file input, as a reader would. Printed, for each model size:

* file chosen -> first picture: the report shown and the view's first frame drawn (the worker
  reads and checks the file, the page builds the geometry and renders);
* the frame interval while orbiting (one pointer move per animation frame, dispatched inside
  the page, as bench_view.py does; only frames that drew count);
* a face pick: the time from the click (pointer up) to the face's readout on the page, and the
  frame interval while picking faces one after another.

The peers, measured in the same run with the same browser: the same view on a model ten times
smaller (20 000 faces), and, with ``--peer-site DIR``, the same page of another build of the
site (an earlier design of the view) on the biggest model. Both Chromium software renderers are
measured: ``--disable-gpu`` (the browser tests' flags) and ``--use-angle=swiftshader
--enable-unsafe-swiftshader`` (the slower, honest software floor). A graphics card does better;
these are floors.

Where the time went (December 2026, per-thread CPU time and one change at a time): a frame's
cost grows with the faces and outlined sides drawn, not the pixels (a canvas 5 times smaller
saved an eighth), and SwiftShader draws each instanced wide-line segment of the outlines as a
draw of its own (with the coarser copy below drawn, the torus's 1 000 outlined faces still took
a frame from 17 to 83 ms). So while the camera turns the view draws thin outlines and, above
60 000 faces, a coarser copy of about 30 000 faces: 200 000 faces turned at 133 ms a frame
before that change and 33 ms after, on both renderers, in runs an hour apart on the same
machine (at rest it draws everything).

Nothing is asserted. Run: ``python benchmarks/bench_mesh_view.py [--faces N ...] [--peer-site
DIR]`` (default 200000 20000; uses ``TRINORMAL_SITE_DIR``, else an up-to-date ``site/``, else
builds the site). Timings on a shared machine are inflated by whatever else runs: compare the
ratios.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))
sys.path.insert(0, str(ROOT / "benchmarks"))

from bench_mesh_site import choose_and_draw  # noqa: E402
from bench_view import INIT, intervals  # noqa: E402
from browser_support import CHROMIUM, CHROMIUM_ARGS, built_site, serve_site  # noqa: E402

from trinormal.mesh import torus  # noqa: E402

RENDERERS = {
    "--disable-gpu": [],
    "swiftshader": ["--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
}
MOVES = 180  # pointer moves while orbiting
PICKS = 12  # faces picked one after another

# Orbit: press at the canvas centre, sweep right and back, one move per animation frame.
ORBIT = """
async ([moves]) => {
  const canvas = document.querySelector("#tn-mesh-view canvas");
  const r = canvas.getBoundingClientRect();
  const x = r.left + r.width / 2, y = r.top + r.height / 2;
  const ev = (type, cx, cy) => canvas.dispatchEvent(new PointerEvent(type, {
    bubbles: true, pointerId: 1, pointerType: "mouse", isPrimary: true, button: 0,
    buttons: type === "pointerup" ? 0 : 1, clientX: cx, clientY: cy }));
  ev("pointerdown", x, y);
  for (let i = 1; i <= moves; i++) {
    await new Promise(requestAnimationFrame);
    await new Promise((res) => setTimeout(res, 0));
    const f = (i * 2 / moves) % 1;
    const s = f <= 0.5 ? 2 * f : 2 - 2 * f;
    ev("pointermove", x + 0.4 * r.width * s, y + 0.1 * r.height * s);
  }
  ev("pointerup", x + 0.4 * r.width, y);
  await new Promise(requestAnimationFrame);
}
"""

# Pick faces: a click (down and up in place) at points across the middle of the canvas; the
# time from the click to the readout on the page (the view's pick and the page's readout).
PICK = """
async ([picks]) => {
  const canvas = document.querySelector("#tn-mesh-view canvas");
  const root = document.querySelector("#tn-mesh-view .tnm-root");
  const r = canvas.getBoundingClientRect();
  const times = [];
  let hits = 0;
  let shown = 0;
  for (let i = 0; i < picks; i++) {
    const cx = r.left + r.width * (0.35 + 0.3 * i / picks), cy = r.top + r.height * 0.5;
    const ev = (type) => canvas.dispatchEvent(new PointerEvent(type, {
      bubbles: true, pointerId: 1, pointerType: "mouse", isPrimary: true, button: 0,
      buttons: type === "pointerup" ? 0 : 1, clientX: cx, clientY: cy }));
    await new Promise(requestAnimationFrame);
    const before = root.dataset.picked;
    ev("pointerdown");
    const t0 = performance.now();
    ev("pointerup");
    if (root.dataset.picked !== before) {
      times.push(performance.now() - t0);
      hits++;
    }
    const readout = root.querySelector(".tnm-pick");
    if (readout && !readout.hidden) shown++;
  }
  await new Promise(requestAnimationFrame);
  return { times, hits, shown };
}
"""


def flipped_torus_stl(faces: int) -> bytes:
    """A binary STL of a torus of about ``faces`` triangles, one patch of faces wound backwards."""
    n_minor = max(8, int((faces / 4) ** 0.5))
    n_major = max(3, faces // (2 * n_minor))
    v, f = torus(n_major=n_major, n_minor=n_minor)
    f = f.copy()
    patch = slice(0, max(1, len(f) // 200))
    f[patch] = f[patch][:, [0, 2, 1]]
    record = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(f), dtype=record)
    data["corners"] = v[f]
    return bytes(80) + np.uint32(len(f)).tobytes() + data.tobytes()


def median(values: list[float]) -> float:
    return statistics.median(values) if values else float("nan")


def p95(values: list[float]) -> float:
    v = sorted(values)
    return v[min(len(v) - 1, int(0.95 * len(v)))] if v else float("nan")


def measure(page: Any, url: str, path: Path) -> dict[str, Any]:
    page.goto(url + "mesh/")
    page.wait_for_selector("#tn-mesh[data-ready='true']")
    reported, drawn = choose_and_draw(page, path, timeout=300_000)
    page.locator("#tn-mesh-view canvas").scroll_into_view_if_needed()
    orbit, _ = intervals(page, lambda: page.evaluate(ORBIT, [MOVES]))
    pick_frames, picked = intervals(page, lambda: page.evaluate(PICK, [PICKS]))
    faces = page.evaluate(
        "() => JSON.parse(document.getElementById('tn-mesh').dataset.report).n_faces"
    )
    return {
        "faces": faces,
        "reported": reported,
        "drawn": drawn,
        "orbit": orbit,
        "pick": picked["times"],
        "hits": picked["hits"],
        "shown": picked["shown"],
        "pick_frames": pick_frames,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--faces", type=int, nargs="+", default=[200_000, 20_000])
    parser.add_argument("--peer-site", type=Path, help="another build of the site, measured too")
    args = parser.parse_args()
    sizes = args.faces
    nan = float("nan")
    sites = {"this": built_site()}
    if args.peer_site:
        sites["peer"] = args.peer_site
    results: dict[tuple[str, str, int], dict[str, Any]] = {}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        paths = {}
        for n in sizes:
            paths[n] = Path(tmp) / f"torus-{n}.stl"
            paths[n].write_bytes(flipped_torus_stl(n))
        for name, extra in RENDERERS.items():
            browser = p.chromium.launch(
                executable_path=CHROMIUM, args=CHROMIUM_ARGS + extra, headless=True
            )
            page = browser.new_page(viewport={"width": 1280, "height": 720})
            page.add_init_script(INIT)
            for label, site in sites.items():
                with serve_site(site) as url:
                    # the peer site on the biggest model only
                    for n in sizes if label == "this" else [max(sizes)]:
                        results[name, label, n] = measure(page, url, paths[n])
            browser.close()
    with open("/proc/loadavg") as f:
        load = f.read().split()[:3]
    print(f"mesh view on the Check a mesh page, headless Chromium 1280x720, load {' '.join(load)}")
    if args.peer_site:
        print(f"(peer: {args.peer_site})")
    for (name, label, _), r in results.items():
        print(
            f"{name:<14} {label:<5}{r['faces']:>8,} faces: report {r['reported']:5.2f} s, "
            f"first picture "
            f"{r['drawn']:5.2f} s; orbit median {median(r['orbit']):6.1f} ms "
            f"p95 {p95(r['orbit']):6.1f} ms ({len(r['orbit'])} frames); pick "
            f"median {median(r['pick']):6.1f} ms max {max(r['pick'], default=nan):6.1f} ms "
            f"({r['hits']}/{PICKS} hit, {r['shown']} with a readout), frames while picking median "
            f"{median(r['pick_frames']):6.1f} ms"
        )
    big, small = max(sizes), min(sizes)
    pairs = []
    if big != small:
        pairs.append(("this", big, "this", small, f"{big:,} / {small:,} faces"))
    if args.peer_site:
        pairs.append(("this", big, "peer", big, f"this / peer at {big:,} faces"))
    for name in RENDERERS:
        for la, na, lb, nb, what in pairs:
            a, b = results[name, la, na], results[name, lb, nb]
            print(
                f"{name:<14} {what}: first picture x{a['drawn'] / b['drawn']:.2f}, "
                f"orbit frame x{median(a['orbit']) / median(b['orbit']):.2f}, "
                f"pick x{median(a['pick']) / median(b['pick']):.2f}"
            )


if __name__ == "__main__":
    main()
