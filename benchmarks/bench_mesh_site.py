"""The "Check a mesh" page on a big file: a binary STL of a million triangles in headless Chromium.

The file (a torus, 1,000,000 triangles, 50 MB) is chosen with the page's file input, as a
reader would. Printed:

* the time from choosing the file to the report on the page (read + check in the Web Worker),
  and to the 3D view drawn (the page draws a model this big when the reader asks for it: the
  benchmark asks at once);
* the longest gap between two animation frames of the page meanwhile: the page stays
  responsive while the worker works (a frozen page would show one gap as long as the work);
* the progress bar's distinct values seen (it moves while the worker reads and checks);
* the peer, measured in the same run on the same file: the Python package's
  ``parse_mesh`` + ``check`` (numpy), and the ratio.

Nothing is asserted. Run: ``python benchmarks/bench_mesh_site.py [N_TRIANGLES]`` (uses
``TRINORMAL_SITE_DIR``, else ``site/`` when it is newer than its sources, else builds the site
into a temporary folder). Needs Chromium at /usr/bin/chromium (or ``TRINORMAL_CHROMIUM``).
Timings on a shared machine are inflated by whatever else runs: compare the ratio.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from browser_support import CHROMIUM, CHROMIUM_ARGS, built_site, serve_site  # noqa: E402

from trinormal.mesh import check, parse_mesh, torus  # noqa: E402

TWO_FRAMES = "() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))"
WATCH = """() => {
  window.__gaps = [];
  window.__seen = [];
  const bar = document.getElementById('tn-mesh-progress');
  let last = performance.now();
  const tick = (now) => {
    window.__gaps.push(now - last);
    last = now;
    if (!window.__seen.includes(bar.value)) window.__seen.push(bar.value);
    if (document.getElementById('tn-mesh').dataset.state !== 'done') requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}"""


def binary_stl(n_major: int, n_minor: int) -> bytes:
    v, f = torus(n_major=n_major, n_minor=n_minor)
    record = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(f), dtype=record)
    data["corners"] = v[f]
    return bytes(80) + np.uint32(len(f)).tobytes() + data.tobytes()


def choose_and_draw(page: Any, path: Path, timeout: float = 120_000) -> tuple[float, float]:
    """Choose a file with the page's input: seconds to the report shown, and to the 3D view drawn.

    A model too big to draw at once is drawn when the reader asks: this asks at once.
    """
    start = time.perf_counter()
    page.set_input_files("#tn-mesh-file", str(path))
    page.wait_for_function(
        "() => document.getElementById('tn-mesh').dataset.state === 'done'",
        timeout=timeout,
        polling=20,
    )
    reported = time.perf_counter() - start
    if page.locator("#tn-mesh-draw").count():
        page.click("#tn-mesh-draw")
    page.wait_for_selector("#tn-mesh-view[data-ready='true']", timeout=timeout)
    page.evaluate(TWO_FRAMES)
    return reported, time.perf_counter() - start


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
    n_minor = 500 if n >= 1_000_000 else max(8, int((n / 4) ** 0.5))
    n_major = max(3, n // (2 * n_minor))
    data = binary_stl(n_major, n_minor)
    faces = len(data[84:]) // 50
    print(f"binary STL: {faces:,} triangles, {len(data) / 1e6:.1f} MB")

    t0 = time.perf_counter()
    m = parse_mesh(data, "stl", "torus.stl")
    t1 = time.perf_counter()
    report = check(m.vertices, m.faces)
    t2 = time.perf_counter()
    python = t2 - t0
    print(
        f"Python (numpy) parse_mesh {t1 - t0:.2f} s + check {t2 - t1:.2f} s = {python:.2f} s "
        f"({report.n_vertices:,} vertices)"
    )

    site = built_site()
    with tempfile.TemporaryDirectory() as tmp, serve_site(site) as url, sync_playwright() as p:
        path = Path(tmp) / "torus.stl"
        path.write_bytes(data)
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.goto(url + "mesh/")
        page.wait_for_selector("#tn-mesh[data-ready='true']")
        page.evaluate(WATCH)
        reported, drawn = choose_and_draw(page, path)
        gaps = page.evaluate("window.__gaps")
        split = len(gaps)
        seen = page.evaluate("window.__seen")
        state = page.locator("#tn-mesh-status").inner_text()
        n_faces = page.evaluate(
            "() => JSON.parse(document.getElementById('tn-mesh').dataset.report).n_faces"
        )
        browser.close()
    print(
        f"page: file chosen -> report shown {reported:.2f} s; -> 3D view drawn {drawn:.2f} s "
        "(a model this big is drawn when the reader clicks; the benchmark clicks at once)"
    )
    print(f"page: {n_faces:,} faces reported; status {state!r}")
    print(
        f"page: longest gap between animation frames while the worker ran "
        f"{max(gaps[:split]):.0f} ms ({split} frames); progress values seen: {sorted(seen)}"
    )
    print(f"ratio page report / Python parse+check: {reported / python:.2f}")


if __name__ == "__main__":
    main()
