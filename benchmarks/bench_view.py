"""Frame rate of the 3D view on the site's calculator page, while dragging a vertex and orbiting.

The view renders on demand: a frame is drawn only when something changed. While a vertex
is dragged every frame carries the whole chain a reader sees: the view writes the vertex,
the calculator rewrites its boxes and its results table (exact core), the model recomputes
the view's state, and the view redraws. While orbiting, only the camera moves. Both are
measured in headless Chromium on the built site at 1280×720, with one pointer move per
animation frame (as a mouse gives); the time between two frames that drew something is one
frame interval.

Two Chromium set-ups, both drawing WebGL on the CPU (SwiftShader):
- ``--disable-gpu``: WebGL on SwiftShader, the page composited in software (only the parts
  that changed are redrawn);
- ``--use-angle=swiftshader --enable-unsafe-swiftshader``: everything through SwiftShader's
  GL, as on a machine whose GPU is missing or blocked; the page is composited by SwiftShader
  too, the whole window every frame. This is the honest software floor.

Each set-up is measured for this checkout and, in the same run, for the previous design
(``--previous REV``, default PREVIOUS below: the view's bundle and the calculator's script
built from that commit, on the same site), so the ratio holds even on a busy machine. Beside
each figure: the load average, and the CPU time all of Chromium's processes spent per frame
(less sensitive to other work on the machine than the frame interval).

Where the time goes (profiled with Chromium's tracing, per-process and per-thread CPU time,
and performance.now() around the view's work; December 2026, see the commit that added this
note): the view's own JavaScript is small (label layout 0.2-0.3 ms, three.js render call
1-2 ms, the whole pointer move with the calculator's update 6-8 ms). With --disable-gpu
SwiftShader drawing the WebGL scene is the largest part of a frame; with ANGLE on
SwiftShader the compositor redraws the whole 1280×720 window each frame (even a blank page
with a 10 px square changing costs about 20 ms of CPU per frame), which dominates, and
lowering the canvas's pixel ratio or dropping the HTML labels changed little. While
dragging, each address update (history.replaceState) made Chromium fetch the page's icon
again: the calculator now writes the address once the pointer rests.

Measured again in December 2026 with per-thread CPU time: on SwiftShader most of a frame is
SwiftShader's raster threads in the GPU process (about 28 ms of CPU per orbit frame, 33 per
drag frame, on a page whose WebGL canvas, when hidden, saved nothing). Two causes were ours:
the view's box had rounded corners, so the canvas was clipped through a mask every frame
(about 5 ms), and the view re-applied every attribute, text and style of its toolbar, sliders
and labels on every frame of a drag (a MutationObserver counted 30 writes per move), each one
a style recalculation and a repaint. Square corners and writing only what changed (the
view's dom.js) took a drag frame from about 48 to 42 ms of CPU.

Measured in the same run too, the old matplotlib explorer's update: recompute and redraw the
figure as a PNG (``ex.set(b=...)`` then ``ex.to_png()``), what each slider move cost.

Goals: median frame interval ≤ 22 ms (45 frames per second) on SwiftShader, ≤ 17 ms (60)
with --disable-gpu.
Run: uv run python benchmarks/bench_view.py [--previous REV] [--moves N]   (or make bench)
"""

from __future__ import annotations

import argparse
import itertools
import os
import shutil
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
import uuid
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from io import BytesIO
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from browser_support import CHROMIUM, CHROMIUM_ARGS, built_site, serve_site  # noqa: E402
from playwright.sync_api import sync_playwright  # noqa: E402

#: The design before the last profile-guided change (square corners, writing only what changed),
#: measured beside this one.
PREVIOUS = "dd3fdc9"
SETUPS = {
    "--disable-gpu": CHROMIUM_ARGS,
    "SwiftShader": [a for a in CHROMIUM_ARGS if a != "--disable-gpu"]
    + ["--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
}
GOALS_MS = {"--disable-gpu": 17.0, "SwiftShader": 22.0}
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


def drag(page: Any, x: float, y: float, dx: float, dy: float, moves: int, sweeps: int) -> int:
    """Press at (x, y), sweep to (x + dx, y + dy) and back `sweeps` times, release.

    Returns how many times the view wrote a new position into the calculator's boxes.
    """
    page.mouse.move(x, y)
    page.mouse.down()
    writes: int = page.evaluate(SWEEP, [x, y, dx, dy, moves, sweeps])
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


def cpu_seconds(marker: str) -> float:
    """CPU time (user + system) of the Chromium launched with `marker` and all its children."""
    tick = os.sysconf("SC_CLK_TCK")
    procs: dict[int, tuple[int, bool, float]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            stat = Path(f"/proc/{entry}/stat").read_text()
            cmd = Path(f"/proc/{entry}/cmdline").read_bytes()
        except OSError:
            continue
        rest = stat[stat.rfind(")") + 2 :].split()
        procs[int(entry)] = (
            int(rest[1]),
            marker.encode() in cmd,
            (int(rest[11]) + int(rest[12])) / tick,
        )
    todo = [pid for pid, (_, marked, _) in procs.items() if marked]
    seen: set[int] = set()
    while todo:
        pid = todo.pop()
        if pid not in seen:
            seen.add(pid)
            todo += [q for q, (ppid, _, _) in procs.items() if ppid == pid]
    return sum(procs[pid][2] for pid in seen)


@contextmanager
def previous_site(site: Path, rev: str) -> Iterator[Path | None]:
    """A copy of the built site whose view bundle and calculator script come from commit `rev`.

    Yields None (and says why) when that cannot be built here (no node, no node_modules).
    """
    node_modules = ROOT / "js" / "explorer" / "node_modules"
    if shutil.which("node") is None or not node_modules.is_dir():
        print(
            f"(previous design not measured: run `make js` first, it needs node and {node_modules})"
        )
        yield None
        return
    with tempfile.TemporaryDirectory(prefix="trinormal-previous-") as tmp:
        work = Path(tmp)
        archive = subprocess.run(
            ["git", "archive", rev, "js/explorer", "docs/assets/javascripts/calculator.js"],
            cwd=ROOT,
            check=True,
            capture_output=True,
        ).stdout
        with tarfile.open(fileobj=BytesIO(archive)) as tar:
            tar.extractall(work / "src", filter="data")
        (work / "src" / "js" / "explorer" / "node_modules").symlink_to(node_modules)
        out = work / "site"
        shutil.copytree(site, out)
        subprocess.run(
            ["node", str(work / "src" / "js" / "explorer" / "build.mjs"), str(work / "static")],
            check=True,
            capture_output=True,
        )
        # that commit's site modules (static/site-modules/) where it builds them, else its bundle
        built, assets = work / "static" / "site-modules", out / "assets" / "explorer"
        if built.is_dir():
            shutil.rmtree(assets)
            shutil.copytree(built, assets)
        else:
            shutil.copy(work / "static" / "explorer.js", assets / "explorer.js")
        shutil.copy(
            work / "src" / "docs" / "assets" / "javascripts" / "calculator.js",
            out / "assets" / "javascripts" / "calculator.js",
        )
        yield out


def measure(p: Any, url: str, args: list[str], moves: int) -> dict[str, Any]:
    """Drag vertex B and orbit on the calculator page at `url`: frame intervals, CPU per frame."""
    marker = f"--trinormal-bench={uuid.uuid4().hex[:12]}"  # finds this Chromium's processes
    browser = p.chromium.launch(executable_path=CHROMIUM, args=[*args, marker])
    page = browser.new_page(viewport={"width": 1280, "height": 720})
    page.add_init_script(INIT)
    page.goto(url)
    page.wait_for_selector("#tn-view[data-ready='true']")
    canvas = page.locator("#tn-view canvas")
    canvas.evaluate("c => c.scrollIntoView({block: 'center'})")
    size = canvas.bounding_box()
    box = page.locator('#tn-view [data-vertex="B"]').bounding_box()
    assert size is not None and box is not None
    w, h = size["width"], size["height"]
    bx, by = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    out: dict[str, Any] = {"canvas": (w, h)}
    gestures = {
        # 12 moves per sweep of 240 px: every move crosses grid lines, so every frame has a
        # new value to write (a move within one grid cell writes nothing and draws nothing)
        "drag": lambda: drag(page, bx, by, -240, -120, moves, moves // 12),
        "orbit": lambda: drag(page, size["x"] + 20, size["y"] + 20, w * 0.5, h * 0.3, moves, 4),
    }
    for name, gesture in gestures.items():
        cpu0 = cpu_seconds(marker)
        ms, writes = intervals(page, gesture)
        cpu = (cpu_seconds(marker) - cpu0) * 1000 / max(len(ms), 1)
        out[name] = {"ms": ms, "writes": writes, "cpu": cpu, "load": os.getloadavg()[0]}
    browser.close()
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--previous", default=PREVIOUS, help="commit of the previous design")
    parser.add_argument("--moves", type=int, default=MOVES, help="pointer moves per gesture")
    opts = parser.parse_args()
    site = built_site()
    results: dict[tuple[str, str], dict[str, Any]] = {}
    with ExitStack() as stack, sync_playwright() as p:
        sites = {"this": site}
        old = stack.enter_context(previous_site(site, opts.previous))
        if old is not None:
            sites[f"previous ({opts.previous})"] = old
        urls = {k: stack.enter_context(serve_site(v)) + "calculator/" for k, v in sites.items()}
        print(
            f"3D view on the calculator page, 1280×720, headless Chromium; load average before: "
            f"{os.getloadavg()[0]:.1f} (2 cores here: above 2 means other work shares the CPU)"
        )
        for setup, args in SETUPS.items():
            for design, url in urls.items():  # one after the other, so both see the same load
                results[setup, design] = measure(p, url, args, opts.moves)
    for setup in SETUPS:
        print(f"{setup}:")
        for design in urls:
            r = results[setup, design]
            for gesture in ("drag", "orbit"):
                g = r[gesture]
                median, _ = summary(f"{design}, {gesture}", g["ms"])
                g["median"] = median
                print(
                    f"      CPU of all Chromium processes {g['cpu']:5.1f} ms per frame, "
                    f"load average {g['load']:.1f}"
                )
        if len(urls) == 2:
            this, prev = (results[setup, d] for d in urls)
            for gesture in ("drag", "orbit"):
                print(
                    f"  ratio {gesture}: previous/this frame interval "
                    f"{prev[gesture]['median'] / this[gesture]['median']:.2f}, CPU per frame "
                    f"{prev[gesture]['cpu'] / max(this[gesture]['cpu'], 1e-9):.2f}"
                )
    first = results[next(iter(SETUPS)), "this"]
    print(
        f"  (while dragging the view wrote B into the calculator's boxes {first['drag']['writes']} "
        f"times in {opts.moves} moves; {first['orbit']['writes']} times while orbiting)"
    )
    old_ms = sorted(old_explorer_ms())
    old_median = statistics.median(old_ms)
    drag_median = first["drag"]["median"]
    print(
        f"old matplotlib explorer, set(b=...) + to_png(): median {old_median:6.1f} ms   "
        f"p95 {old_ms[min(len(old_ms) - 1, int(0.95 * len(old_ms)))]:6.1f} ms   "
        f"{1000 / old_median:5.1f} updates/s   ({len(old_ms)} updates); one update lasts "
        f"{old_median / drag_median:.1f} frames of dragging with --disable-gpu (the kernel's share "
        "only, and a flat picture the reader could not turn)"
    )
    for setup, goal in GOALS_MS.items():
        for gesture in ("drag", "orbit"):
            median = results[setup, "this"][gesture]["median"]
            verdict = "meets" if median <= goal else "misses"
            print(
                f"goal {setup}: median frame interval ≤ {goal:.0f} ms ({gesture}): {verdict} it "
                f"({median:.1f} ms at load {results[setup, 'this'][gesture]['load']:.1f})"
            )


if __name__ == "__main__":
    main()
