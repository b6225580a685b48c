"""What welding and shell containment cost inside a mesh check, measured in the same run.

Issue 31 asks that joining corners by position (``trinormal/mesh/welding.py``) and telling
cavities and open pieces (``trinormal/mesh/shells.py``) change the speed figures of
``bench_mesh_cli.py`` by at most 20 %. This script checks three models and prints, for each,
the time of ``mesh.check`` (best of a few rounds) beside the time spent in those two parts,
taken from one profiled run (``cProfile``: the parts' share of the profiled check):

* the damaged torus of ``bench_mesh_repair.py`` (1M faces, one piece, inside out, 10 %
  flipped), as the command-line benchmark reads it;
* a hollow model of many pieces: 200 balls in a row, each a closed outer shell around an
  inner shell facing into its cavity (2 048 000 faces), where containment has work;
* a voxel model: 20 000 separate cubes on a grid (240 000 faces), where containment has
  many pieces to compare and none inside another.

Run: ``python benchmarks/bench_mesh_parts.py`` (``--small`` for smaller models).
"""

from __future__ import annotations

import cProfile
import platform
import pstats
import sys
import time

import numpy as np

from trinormal import mesh
from trinormal.mesh import shells, welding
from trinormal.mesh.shapes import icosphere

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from bench_mesh_repair import damaged_torus

ROUNDS = 3


def hollow_balls(n: int, subdivisions: int) -> tuple[np.ndarray, np.ndarray]:
    """`n` hollow balls in a row: an outer shell facing out, an inner one facing into it."""
    v1, f1 = icosphere(subdivisions)
    vs, fs = [], []
    for i in range(n):
        for radius, faces in ((1.0, f1), (0.8, f1[:, ::-1])):
            fs.append(faces + sum(len(x) for x in vs))
            vs.append(v1 * radius + [3.0 * i, 0.0, 0.0])
    return np.vstack(vs), np.vstack(fs)


def voxels(n: int) -> tuple[np.ndarray, np.ndarray]:
    """`n` unit cubes, each a closed piece, two units apart on a cubic grid."""
    corners = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)
    box = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4], [2, 6, 3]])
    box = np.vstack([box, [[3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]])
    side = int(np.ceil(n ** (1 / 3)))
    grid = np.stack(np.meshgrid(*[np.arange(side)] * 3, indexing="ij"), -1).reshape(-1, 3)[:n]
    v = (corners[None] + 2.0 * grid[:, None]).reshape(-1, 3)
    f = (box[None] + 8 * np.arange(n)[:, None, None]).reshape(-1, 3)
    return v, f


def best_time(v: np.ndarray, f: np.ndarray) -> float:
    times = []
    for _ in range(ROUNDS):
        t = time.perf_counter()
        mesh.check(v, f)
        times.append(time.perf_counter() - t)
    return min(times)


def parts(v: np.ndarray, f: np.ndarray) -> tuple[float, float, float]:
    """Seconds in the whole profiled check, in welding, and in shells (cumulative)."""
    profile = cProfile.Profile()
    profile.runcall(mesh.check, v, f)
    stats = pstats.Stats(profile).stats  # type: ignore[attr-defined]
    total = welded = shelled = 0.0
    for (filename, _line, name), (_cc, _nc, _tt, cumulative, _callers) in stats.items():
        if name == "check" and filename.endswith("report.py"):
            total = cumulative
        elif filename == welding.__file__ and name == "weld":
            welded += cumulative
        elif filename == shells.__file__ and name in ("_cavities", "_capped"):
            shelled += cumulative
    return total, welded, shelled


def main() -> None:
    small = "--small" in sys.argv
    print(f"Python {platform.python_version()}, numpy {np.__version__}, {platform.machine()}")
    torus = damaged_torus(250, 200) if small else damaged_torus()
    models = {
        "damaged torus": torus[:2],
        "hollow balls": hollow_balls(20 if small else 200, 3 if small else 4),
        "voxels": voxels(2000 if small else 20000),
    }
    for name, (v, f) in models.items():
        report = mesh.check(v, f)
        cavities = sum(c.cavity for c in report.components)
        took = best_time(v, f)
        total, welded, shelled = parts(v, f)
        print(
            f"{name}: {len(f):,} faces, {len(report.components)} pieces ({cavities} cavities); "
            f"mesh.check {took:.3f} s; in one profiled check of {total:.3f} s, welding "
            f"{welded:.3f} s ({100 * welded / total:.0f} %), shells {shelled:.3f} s "
            f"({100 * shelled / total:.0f} %), together {100 * (welded + shelled) / total:.0f} %"
        )


if __name__ == "__main__":
    main()
