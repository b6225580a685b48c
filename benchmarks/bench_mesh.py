"""Speed of trinormal.mesh against its peers, measured in the same run on one core.

Every side runs on one thread: libigl and numpy are told so before they are
imported (``IGL_NUM_THREADS``, ``OMP_NUM_THREADS``), and the process is pinned
to one CPU. Two height-field grids, of about one million and 43 000 faces, are
timed from ``(vertices, faces)`` to unit normals:

* ``mesh.face_normals``;
* libigl's ``per_face_normals`` (C++, with ``Z`` = 0 so degenerate faces get
  zero rows, as ours do);
* ``trimesh.triangles.normals(v[f])``;
* plain numpy, ``np.cross(v[f[:,1]] - v[f[:,0]], v[f[:,2]] - v[f[:,0]])``
  then normalised.

Also timed on the smaller grid: ``mesh.vertex_normals(weighting="angle")``
against trimesh's angle-weighted ``Trimesh(v, f, process=False).vertex_normals``.

Each timing is the best of several rounds, the functions interleaved, so a busy
machine slows every side alike; the best CPU time is printed beside the wall
time, as a busy machine inflates it less. Run:
``python benchmarks/bench_mesh.py [--cpu N]``.
"""

from __future__ import annotations

import os

# one thread everywhere: set before numpy and libigl are imported, which read these once
os.environ["IGL_NUM_THREADS"] = "1"
os.environ["OMP_NUM_THREADS"] = "1"

import argparse
import platform
import time
from collections.abc import Callable
from typing import Any

import igl
import numpy as np
import trimesh

from trinormal import mesh

#: Rounds per timing: at least this many, more for small meshes (about two million faces in all).
ROUNDS = 7
#: (label, points per side): 708 x 708 points make 999 698 faces, 148 x 148 make 43 218.
GRIDS = (("grid of 1M faces", 708), ("grid of 43k faces", 148))
#: Targets for mesh.face_normals: at most this many times libigl's time, per grid ...
TARGET_LIBIGL = {708: 1.25, 148: 1.5}
#: ... and at least this many times faster than trimesh.
TARGET_TRIMESH = {708: 3.0, 148: 2.5}

OURS = "trinormal mesh.face_normals"
LIBIGL = "libigl per_face_normals"
TRIMESH = "trimesh.triangles.normals(v[f])"
PLAIN = "plain numpy cross + norm"


def best_times(
    funcs: dict[str, Callable[[], Any]], rounds: int = ROUNDS
) -> tuple[dict[str, float], dict[str, float]]:
    """Best wall time and best CPU time of each function, the functions interleaved.

    Each round runs them in a new random order (the same orders every run), so each runs
    after each of the others: what a function finds in the caches and in the allocator's
    free memory depends on what ran before it, and a fixed order would favour some.
    """
    wall = dict.fromkeys(funcs, float("inf"))
    cpu = dict.fromkeys(funcs, float("inf"))
    names = list(funcs)
    rng = np.random.default_rng(0)
    for _ in range(rounds):
        for i in rng.permutation(len(names)):
            name = names[i]
            c0, t0 = time.process_time(), time.perf_counter()
            funcs[name]()
            wall[name] = min(wall[name], time.perf_counter() - t0)
            cpu[name] = min(cpu[name], time.process_time() - c0)
    return wall, cpu


def plain_numpy(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    return n


def trimesh_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    normals, _valid = trimesh.triangles.normals(v[f])
    return np.asarray(normals)


def report(title: str, v: np.ndarray, f: np.ndarray) -> dict[str, float]:
    """Time the four face-normal functions on one mesh; return their times over ours."""
    zero = np.zeros(3)
    funcs = {
        OURS: lambda: mesh.face_normals(v, f),
        LIBIGL: lambda: igl.per_face_normals(v, f, zero),
        TRIMESH: lambda: trimesh_normals(v, f),
        PLAIN: lambda: plain_numpy(v, f),
    }
    nf = f.shape[0]
    wall, cpu = best_times(funcs, rounds=max(ROUNDS, 2_000_000 // nf))
    print(f"\n{title}: {nf:,} faces, {v.shape[0]:,} vertices")
    for name, sec in wall.items():
        print(
            f"  {name:32s} {sec * 1e3:8.2f} ms  {nf / sec / 1e6:6.2f} M faces/s"
            f"  {cpu[name] * 1e3:8.2f} ms CPU  {sec / wall[OURS]:5.2f}x ours"
        )
    ours = mesh.face_normals(v, f)
    diffs = [
        f"{name} {np.abs(ours - funcs[name]()).max():.1e}" for name in (LIBIGL, TRIMESH, PLAIN)
    ]
    print("  largest difference from " + ", ".join(diffs))
    return {name: wall[name] / wall[OURS] for name in (LIBIGL, TRIMESH, PLAIN)} | {
        f"{name} CPU": cpu[name] / cpu[OURS] for name in (LIBIGL, TRIMESH)
    }


def report_vertex(v: np.ndarray, f: np.ndarray) -> None:
    def peer() -> np.ndarray:
        return np.asarray(trimesh.Trimesh(v, f, process=False).vertex_normals)

    ours_name, peer_name = "mesh.vertex_normals(angle)", "trimesh Trimesh(...).vertex_normals"
    wall, _ = best_times({ours_name: lambda: mesh.vertex_normals(v, f, "angle"), peer_name: peer})
    print(f"\nvertex normals, angle-weighted: {f.shape[0]:,} faces")
    for name, sec in wall.items():
        print(f"  {name:38s} {sec * 1e3:8.2f} ms")
    diff = np.abs(mesh.vertex_normals(v, f, "angle") - peer()).max()
    ratio = wall[peer_name] / wall[ours_name]
    print(f"  {ratio:.2f}x faster than trimesh; largest difference {diff:.1e}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cpu", type=int, help="the CPU to run on (default: the last allowed)")
    cpu = parser.parse_args().cpu
    if cpu is None:
        cpu = max(os.sched_getaffinity(0))
    os.sched_setaffinity(0, {cpu})
    print(
        f"numpy {np.__version__}, trimesh {trimesh.__version__}, libigl (PyPI wheel), "
        f"Python {platform.python_version()}, {platform.machine()}"
    )
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"pinned to CPU {cpu}, one thread; load average (1, 5, 15 min): {load}")
    results = {}
    for title, n in GRIDS:
        v, f = mesh.terrain(n, n)
        results[n] = report(title, v, f)
    report_vertex(*mesh.terrain(148, 148))
    print("\nsummary: mesh.face_normals against its peers (wall time; CPU time in brackets)")
    for title, n in GRIDS:
        r = results[n]
        igl_ok = r[LIBIGL] >= 1 / TARGET_LIBIGL[n]
        tri_ok = r[TRIMESH] >= TARGET_TRIMESH[n]
        print(
            f"  {title}: {1 / r[LIBIGL]:.2f}x libigl's time ({1 / r[LIBIGL + ' CPU']:.2f}x)"
            f" [target <= {TARGET_LIBIGL[n]}x: {'met' if igl_ok else 'missed'}],"
            f" {r[TRIMESH]:.2f}x faster than trimesh ({r[TRIMESH + ' CPU']:.2f}x)"
            f" [target >= {TARGET_TRIMESH[n]}x: {'met' if tri_ok else 'missed'}],"
            f" {r[PLAIN]:.2f}x faster than plain numpy"
        )


if __name__ == "__main__":
    main()
