"""How fast is triangle_normal on ordinary float input, against numpy on one triangle?

Prints the time per call of
  * trinormal.triangle_normal (exact arithmetic, the default), and
  * numpy.cross + numpy.linalg.norm giving the normal and the unit normal,
measured in the same run on the same random triangles (the two timed in turn, so a
busy machine slows both alike), and the ratio of trinormal's time to numpy's.

Target: trinormal takes at most half numpy's time (ratio <= 0.5x).
Run: uv run python benchmarks/bench_core.py   (or make bench)
"""

from __future__ import annotations

import random
import statistics
import sys
import timeit

import numpy as np

from trinormal import triangle_normal

TRIANGLES = 200
REPEATS = 15
TARGET = 0.5  # trinormal may take at most this fraction of numpy's time


def main() -> int:
    rng = random.Random(2026)
    tris = [
        tuple(tuple(rng.uniform(-10, 10) for _ in range(3)) for _ in range(3))
        for _ in range(TRIANGLES)
    ]
    arrays = [tuple(np.array(p) for p in t) for t in tris]

    def ours() -> None:
        for a, b, c in tris:
            triangle_normal(a, b, c)

    def peer() -> None:
        for a, b, c in arrays:
            n = np.cross(b - a, c - a)
            _ = n / np.linalg.norm(n)

    # warm up, then take the best of several repeats (the least disturbed run)
    ours()
    peer()
    t_ours, t_peer = [], []
    for _ in range(REPEATS):
        t_ours.append(timeit.timeit(ours, number=5) / (5 * TRIANGLES))
        t_peer.append(timeit.timeit(peer, number=5) / (5 * TRIANGLES))
    ratio = min(t_ours) / min(t_peer)

    print("triangle_normal (exact) vs numpy.cross + numpy.linalg.norm, one triangle per call")
    print(
        f"  trinormal.triangle_normal : {min(t_ours) * 1e6:7.2f} µs/call "
        f"(median {statistics.median(t_ours) * 1e6:.2f})"
    )
    print(
        f"  numpy cross + norm        : {min(t_peer) * 1e6:7.2f} µs/call "
        f"(median {statistics.median(t_peer) * 1e6:.2f})"
    )
    print(f"  trinormal time / numpy    : {ratio:7.2f}x")
    print(f"  target <= {TARGET:.2f}x          : {'met' if ratio <= TARGET else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
