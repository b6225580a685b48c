"""Frame rate of the 3D view on the site's calculator page, while dragging a vertex and orbiting.

The view renders on demand: a frame is drawn only when something changed. While a vertex
is dragged every frame carries the whole chain a reader sees: the view writes the vertex,
the calculator rewrites its boxes, its results table (exact core) and the address, the
model recomputes the view's state, and the view redraws. While orbiting, only the camera
moves. Both are measured in headless Chromium on the built site, with the mouse driven by
one pointer move per animation frame (as a mouse gives); the time between two frames that
drew something is one frame interval. Headless Chromium renders WebGL on the CPU
(SwiftShader), so these figures are a floor, not what a GPU gives.

Measured in the same run, the old explorer's update: recompute and redraw the matplotlib
figure as a PNG (``ex.set(b=...)`` then ``ex.to_png()``), what each slider move cost.

Goal: median frame interval ≤ 17 ms (60 frames per second).
Run: uv run python benchmarks/bench_view.py   (or make bench)
"""

from __future__ import annotations

import itertools
import statistics
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from browser_support import CHROMIUM, CHROMIUM_ARGS, built_site, serve_site  # noqa: E402
from playwright.sync_api import sync_playwright  # noqa: E402

GOAL_MS = 17.0
MOVES = 240  # pointer moves per gesture
OLD_UPDATES = 20

# Count a frame only when the view drew something (a WebGL draw call happened since the last one).
INIT = """
(() => {
  window.__drawn = false;
  for (const C of [window.WebGL2RenderingContext, window.WebGLRenderingContext]) {
    if (!C) continue;
    for (const name of ["drawElements", "drawArrays"]) {
      const f = C.prototype[name];
      C.prototype[name] = function (...args) { window.__drawn = true; return f.apply(this, args); };
    }
  }
  window.__frames = [];
  window.__record = false;
  const tick = (t) => {
    if (window.__record && window.__drawn) window.__frames.push(t);
    window.__drawn = false;
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
})();
"""


def intervals(page: Any, gesture: Any) -> tuple[list[float], Any]:
    """Frame intervals (ms) between frames that drew while `gesture()` runs, and its result."""
    page.evaluate("() => { window.__frames = []; window.__record = true; }")
    result = gesture()
    frames: list[float] = page.evaluate(
        "() => { window.__record = false; return window.__frames; }"
    )
    return [b - a for a, b in itertools.pairwise(frames)], result


# One pointer move per animation frame, as a mouse gives, dispatched inside the page between
# two frames (a Playwright mouse move waits for a frame of its own, which would halve the rate
# measured).
SWEEP = """
async ([x, y, dx, dy, moves, sweeps]) => {
  const canvas = document.querySelector("#tn-view canvas");
  const form = document.getElementById("tn-calculator");
  let writes = 0; // input events the view sent to the calculator's boxes
  const count = (e) => { if (e.detail && e.detail.fromView) writes++; };
  form.addEventListener("input", count);
  for (let i = 1; i <= moves; i++) {
    await new Promise(requestAnimationFrame);
    await new Promise((r) => setTimeout(r, 0)); // between frames, where input arrives
    const f = (i * sweeps / moves) % 1;
    const s = f <= 0.5 ? 2 * f : 2 - 2 * f;
    canvas.dispatchEvent(new PointerEvent("pointermove", {
      bubbles: true, pointerId: 1, pointerType: "mouse", isPrimary: true, buttons: 1,
      clientX: x + dx * s, clientY: y + dy * s,
    }));
  }
  await new Promise(requestAnimationFrame);
  form.removeEventListener("input", count);
  return writes;
}
"""


def drag(page: Any, x: float, y: float, dx: float, dy: float, sweeps: int) -> int:
    """Press at (x, y), sweep to (x + dx, y + dy) and back `sweeps` times, release.

    Returns how many times the view wrote a new position into the calculator's boxes.
    """
    page.mouse.move(x, y)
    page.mouse.down()
    writes: int = page.evaluate(SWEEP, [x, y, dx, dy, MOVES, sweeps])
    page.mouse.up()
    return writes


def summary(name: str, values: list[float]) -> tuple[float, float]:
    values = sorted(values)
    median = statistics.median(values)
    p95 = values[min(len(values) - 1, int(0.95 * len(values)))]
    print(
        f"  {name:<28} median {median:6.1f} ms   p95 {p95:6.1f} ms   "
        f"{1000 / median:5.1f} frames/s   ({len(values)} frames)"
    )
    return median, p95


def old_explorer_ms() -> list[float]:
    import matplotlib

    matplotlib.use("Agg")
    from trinormal.explorer import Explorer

    ex = Explorer(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0))
    ex.to_png()  # warm up (fonts, caches)
    times = []
    for i in range(OLD_UPDATES):
        t0 = time.perf_counter()
        ex.set(b=(1 + (i % 10) / 10, 0, 0))
        ex.to_png()
        times.append((time.perf_counter() - t0) * 1000)
    return times


def main() -> None:
    with serve_site(built_site()) as base, sync_playwright() as p:
        url = base + "calculator/"
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        page = browser.new_page(viewport={"width": 1280, "height": 720})
        page.add_init_script(INIT)
        page.goto(url)
        page.wait_for_selector("#tn-view[data-ready='true']")
        canvas = page.locator("#tn-view canvas")
        canvas.evaluate("c => c.scrollIntoView({block: 'center'})")
        size = canvas.bounding_box()
        assert size is not None
        w, h = size["width"], size["height"]
        print(f"3D view on the calculator page, canvas {w:.0f}×{h:.0f} px, headless Chromium")
        box = page.locator('#tn-view [data-vertex="B"]').bounding_box()
        assert box is not None
        bx, by = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        # 12 moves per sweep of 240 px: every move crosses grid lines, so every frame has
        # a new value to write (a move within one grid cell writes nothing and draws nothing)
        drag_ms, writes = intervals(page, lambda: drag(page, bx, by, -240, -120, MOVES // 12))
        orbit_ms, still = intervals(
            page, lambda: drag(page, size["x"] + 20, size["y"] + 20, w * 0.5, h * 0.3, 4)
        )
        browser.close()
    drag_median, _ = summary("dragging vertex B", drag_ms)
    orbit_median, _ = summary("orbiting the camera", orbit_ms)
    print(
        f"  (the view wrote B into the calculator's boxes {writes} times in {MOVES} moves "
        f"while dragging, {still} times while orbiting)"
    )
    old = sorted(old_explorer_ms())
    old_median = statistics.median(old)
    print(
        f"old matplotlib explorer, set(b=...) + to_png(): median {old_median:6.1f} ms   "
        f"p95 {old[min(len(old) - 1, int(0.95 * len(old)))]:6.1f} ms   "
        f"{1000 / old_median:5.1f} updates/s   ({len(old)} updates)"
    )
    print(
        f"ratio: one old update takes as long as {old_median / drag_median:.1f} frames of "
        f"vertex dragging ({old_median / orbit_median:.1f} of orbiting); the old figure's time "
        "is the kernel's share only (no transfer to the browser, no decoding of the PNG), and "
        "it drew a flat picture the reader could not turn"
    )
    for name, median in (("drag", drag_median), ("orbit", orbit_median)):
        verdict = "meets" if median <= GOAL_MS else "misses"
        print(f"goal: median frame interval ≤ {GOAL_MS:.0f} ms ({name}): {verdict} it")


if __name__ == "__main__":
    main()
