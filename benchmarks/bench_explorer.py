"""How long does one explorer update take, slider moved to PNG ready, against a full redraw?

One update is what happens when a student drags a slider one notch: the value
is set, ``triangle_normal`` recomputes, the readout HTML is rewritten, the
figure's artists move and the figure is rendered to a PNG for the browser (the
work the inline backend does for a figure). The explorer is displayed first
(``ex.widget``), so every update renders, exactly as in JupyterLab.

Measured in the same run, on the same random slider values:
  * the Explorer: artists moved in place, static parts restored from a cached
    bitmap, only the moving artists drawn, PNG encoded;
  * a peer that does what an ``interactive_output`` callback usually does:
    build a new figure with the same content from scratch and save it with
    ``bbox_inches="tight"``, as the inline backend does.

Target: median ≤ 50 ms per update.
Run: uv run python benchmarks/bench_explorer.py   (or make bench)
"""

from __future__ import annotations

import io
import os
import random
import statistics
import sys
import time

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt

from trinormal import triangle_normal
from trinormal.plotting import AXIS_COLORS, PALETTE
from trinormal.widgets import COORDINATES, DPI, FIGSIZE, Explorer

UPDATES = 100
PEER_UPDATES = 30  # the peer is slow: time it on the first 30 of the same values
TARGET_MS = 50.0


def peer_update(points: list[list[float]], winding: str) -> bytes:
    """Recompute and redraw everything from scratch, as a typical interactive_output callback."""
    r = triangle_normal(points[0], points[1], points[2], winding=winding)
    fig = plt.figure(figsize=FIGSIZE, dpi=DPI)
    ax3 = fig.add_subplot(1, 2, 1, projection="3d")
    a, b, c = r.a, r.b, r.c
    ax3.plot_trisurf([a[0], b[0], c[0]], [a[1], b[1], c[1]], [a[2], b[2], c[2]], alpha=0.5)
    for vec, color in ((r.u, PALETTE["orange"]), (r.v, PALETTE["sky"]), (r.normal, "black")):
        ax3.quiver(*a, *vec, color=color)
    for name, p in zip("ABC", (a, b, c), strict=True):
        ax3.text(*p, name)
    ax3.set_box_aspect((1, 1, 1))
    ax_n = fig.add_subplot(2, 2, 2)
    ax_n.bar(["x", "y", "z"], r.normal, color=AXIS_COLORS)
    ax_u = fig.add_subplot(2, 2, 4)
    ax_u.bar(["x", "y", "z"], r.unit_normal or (0, 0, 0), color=AXIS_COLORS)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def summary(times: list[float]) -> tuple[float, float]:
    ms = sorted(t * 1000 for t in times)
    return statistics.median(ms), ms[min(len(ms) - 1, round(0.95 * (len(ms) - 1)))]


def main() -> int:
    rng = random.Random(2026)
    moves = [(rng.choice(COORDINATES), round(rng.uniform(-5, 5), 1)) for _ in range(UPDATES)]

    ex = Explorer(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0))
    ex.widget  # shown: from now on every change renders the PNG  # noqa: B018
    wall, cpu = [], []
    for key, value in moves:
        t0, c0 = time.perf_counter(), time.process_time()
        ex.controls[key].value = value
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
        assert bytes(ex.image.value[:8]) == b"\x89PNG\r\n\x1a\n"

    state = {k: 0.0 for k in COORDINATES} | {"bx": 1.0, "cy": 1.0}
    peer_wall = []
    for key, value in moves[:PEER_UPDATES]:
        state[key] = value
        t0 = time.perf_counter()
        points = [[state[p + q] for q in "xyz"] for p in "abc"]
        png = peer_update(points, "ABC")
        peer_wall.append(time.perf_counter() - t0)
        assert png.startswith(b"\x89PNG")

    med, p95 = summary(wall)
    cpu_med, _ = summary(cpu)
    peer_med, peer_p95 = summary(peer_wall)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(
        f"Explorer update: one slider set, result and readout recomputed, figure rendered to PNG "
        f"({UPDATES} random values; load average {load:.2f} on {os.cpu_count()} CPUs)"
    )
    print(f"  Explorer (artists moved in place, cached background) : median {med:6.1f} ms, "
          f"p95 {p95:6.1f} ms (CPU time median {cpu_med:.1f} ms)")  # fmt: skip
    print(f"  peer: new figure + savefig(bbox_inches='tight')      : median {peer_med:6.1f} ms, "
          f"p95 {peer_p95:6.1f} ms ({PEER_UPDATES} of the same values)")  # fmt: skip
    print(f"  ratio peer / Explorer (medians)                      : {peer_med / med:6.1f}x")
    print(f"  target median ≤ {TARGET_MS:.0f} ms                               : "
          f"{'met' if med <= TARGET_MS else 'NOT met'}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
