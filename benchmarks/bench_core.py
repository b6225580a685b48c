"""How fast is triangle_normal on ordinary float input, against numpy on one triangle?

Prints the time per call of
  * trinormal.triangle_normal (exact arithmetic, the default), and
  * numpy.cross + numpy.linalg.norm giving the normal and the unit normal,
measured in the same run on the same random triangles, and their ratio.

Target: at most 20 µs per call, and faster than numpy.
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
REPEATS = 7


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
    t_ours = min(timeit.repeat(ours, number=5, repeat=REPEATS)) / (5 * TRIANGLES)
    t_peer = min(timeit.repeat(peer, number=5, repeat=REPEATS)) / (5 * TRIANGLES)
    med = statistics.median(timeit.repeat(ours, number=2, repeat=REPEATS)) / (2 * TRIANGLES)

    print("triangle_normal (exact) vs numpy.cross + numpy.linalg.norm, one triangle per call")
    print(f"  trinormal.triangle_normal : {t_ours * 1e6:7.2f} µs/call (median {med * 1e6:.2f})")
    print(f"  numpy cross + norm        : {t_peer * 1e6:7.2f} µs/call")
    print(f"  ratio numpy / trinormal   : {t_peer / t_ours:7.2f}x")
    print(f"  target ≤ 20 µs/call       : {'met' if t_ours <= 20e-6 else 'NOT met'}")
    print(f"  faster than numpy         : {'yes' if t_ours < t_peer else 'NO'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
