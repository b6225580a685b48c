"""Speed of trinormal.mesh against its peers, measured in the same run.

A height-field grid of about one million faces, in its natural order and with
its faces shuffled, timed from ``(vertices, faces)`` to unit normals:

* ``mesh.face_normals`` against libigl's ``per_face_normals`` (C++, with
  ``Z`` = 0 so degenerate faces get zero rows, as ours do),
  ``trimesh.triangles.normals(v[f])`` and the plain numpy expression
  ``np.cross(v[f[:,1]] - v[f[:,0]], v[f[:,2]] - v[f[:,0]])`` followed by
  normalisation;
* ``mesh.vertex_normals(weighting="angle")`` against trimesh's angle-weighted
  ``Trimesh(v, f, process=False).vertex_normals``.

Each timing is the best of several rounds, peers interleaved, so a busy
machine slows every side alike; the best CPU time of each (threads added up),
which a busy machine inflates less, is printed beside the wall time. Also
printed: faces per second and the ratio
to a memory-bandwidth bound (the bytes a face must move at least, divided by
the copy bandwidth measured here). Run: ``python benchmarks/bench_mesh.py``.
"""

from __future__ import annotations

import importlib.util
import logging
import os
import platform
import time
from collections.abc import Callable
from typing import Any

import igl
import numpy as np
import trimesh

from trinormal import mesh

ROUNDS = 5
GRID = 708  # 708 x 708 points: 999 698 faces


#: Best CPU time of each function timed by `best_times` (threads added up): a busy machine
#: inflates it less than the wall time, so it is printed beside it.
CPU: dict[str, float] = {}


def best_times(funcs: dict[str, Callable[[], Any]], rounds: int = ROUNDS) -> dict[str, float]:
    """Best wall time of each function, the functions interleaved round by round.

    The order turns by one each round, so each function runs after each other one. A function
    that runs right after one that freed big arrays gets fresh memory from the system and pays
    its page faults; in a fixed order the same function always paid them (measured here: the
    same kernel 26 ms in one place, 39 ms in the other, libigl 18 ms against 28 ms).
    """
    best = dict.fromkeys(funcs, float("inf"))
    names = list(funcs)
    for r in range(rounds):
        for name in names[r % len(names) :] + names[: r % len(names)]:
            fn = funcs[name]
            c0, t0 = time.process_time(), time.perf_counter()
            fn()
            best[name] = min(best[name], time.perf_counter() - t0)
            CPU[name] = min(CPU.get(name, float("inf")), time.process_time() - c0)
    return best


def copy_bandwidth() -> float:
    """Bytes per second a plain array copy moves (read + write), best of several."""
    src = np.ones(16 * 1024 * 1024)  # 128 MiB, far beyond the caches
    dst = np.empty_like(src)
    t = best_times({"copy": lambda: np.copyto(dst, src)}, rounds=7)["copy"]
    return 2 * src.nbytes / t


def plain_numpy(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    return n


def trimesh_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    normals, _valid = trimesh.triangles.normals(v[f])
    return np.asarray(normals)


def report(title: str, v: np.ndarray, f: np.ndarray, bandwidth: float) -> dict[str, float]:
    nf, nv = f.shape[0], v.shape[0]
    zero = np.zeros(3)
    funcs = {
        "trinormal.mesh.face_normals": lambda: mesh.face_normals(v, f),
        "libigl per_face_normals": lambda: igl.per_face_normals(v, f, zero),
        "trimesh.triangles.normals(v[f])": lambda: trimesh_normals(v, f),
        "plain numpy cross + norm": lambda: plain_numpy(v, f),
    }
    CPU.clear()  # this mesh's timings only
    t = best_times(funcs)
    ours = mesh.face_normals(v, f)
    # least traffic per face: 3 indices read, one normal written, each vertex read once
    per_face = f.itemsize * 3 + 8 * 3 + v.nbytes / nf
    bound = per_face * nf / bandwidth
    print(f"\n{title}: {nf:,} faces, {nv:,} vertices")
    print(f"  memory-bandwidth bound: {per_face:.1f} bytes/face -> {bound * 1e3:.1f} ms")
    for name, sec in t.items():
        print(
            f"  {name:34s} {sec * 1e3:8.1f} ms  {nf / sec / 1e6:6.2f} M faces/s"
            f"  {sec / bound:5.1f}x the bound  {CPU[name] * 1e3:8.1f} ms CPU"
        )
    ours_name = "trinormal.mesh.face_normals"
    ratios = {
        "libigl CPU": CPU["libigl per_face_normals"] / CPU[ours_name],
        "trimesh CPU": CPU["trimesh.triangles.normals(v[f])"] / CPU[ours_name],
        "libigl": t["libigl per_face_normals"] / t["trinormal.mesh.face_normals"],
        "trimesh": t["trimesh.triangles.normals(v[f])"] / t["trinormal.mesh.face_normals"],
        "plain": t["plain numpy cross + norm"] / t["trinormal.mesh.face_normals"],
    }
    print(
        f"  speed-up over libigl: {ratios['libigl']:.2f}x ({ratios['libigl CPU']:.2f}x in CPU time)"
    )
    print(
        f"  speed-up over trimesh: {ratios['trimesh']:.2f}x "
        f"({ratios['trimesh CPU']:.2f}x in CPU time)"
    )
    print(f"  speed-up over plain numpy: {ratios['plain']:.2f}x")
    diff_i = np.abs(ours - igl.per_face_normals(v, f, zero)).max()
    print(f"  largest difference from libigl {diff_i:.1e}")
    diff_t = np.abs(ours - trimesh_normals(v, f)).max()
    diff_p = np.abs(ours - plain_numpy(v, f)).max()
    print(f"  largest difference from trimesh {diff_t:.1e}, from plain numpy {diff_p:.1e}")
    return ratios


def report_vertex(v: np.ndarray, f: np.ndarray) -> float:
    def peer() -> np.ndarray:
        return np.asarray(trimesh.Trimesh(v, f, process=False).vertex_normals)

    funcs = {
        "trinormal.mesh.vertex_normals(angle)": lambda: mesh.vertex_normals(v, f, "angle"),
        "trimesh Trimesh(...).vertex_normals": peer,
    }
    t = best_times(funcs, rounds=3)
    nf = f.shape[0]
    print(f"\nvertex normals, angle-weighted: {nf:,} faces, {v.shape[0]:,} vertices")
    for name, sec in t.items():
        print(f"  {name:38s} {sec * 1e3:8.1f} ms  {nf / sec / 1e6:6.2f} M faces/s")
    ratio = t["trimesh Trimesh(...).vertex_normals"] / t["trinormal.mesh.vertex_normals(angle)"]
    print(f"  speed-up over trimesh: {ratio:.2f}x")
    diff = np.abs(mesh.vertex_normals(v, f, "angle") - peer()).max()
    print(f"  largest difference from trimesh {diff:.1e}")
    return ratio


def main() -> None:
    has_scipy = importlib.util.find_spec("scipy") is not None
    print(
        f"numpy {np.__version__}, trimesh {trimesh.__version__}, libigl (PyPI wheel), "
        f"Python {platform.python_version()}"
    )
    print(f"machine: {platform.machine()}, blocks of {mesh.normals._BLOCK} faces")
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"load average at the start (1, 5, 15 min): {load}")
    bandwidth = copy_bandwidth()
    print(f"measured copy bandwidth: {bandwidth / 1e9:.2f} GB/s (read + write)")
    v, f = mesh.terrain(GRID, GRID)
    grid = report("height-field grid, natural order", v, f, bandwidth)
    shuffled = f[np.random.default_rng(0).permutation(f.shape[0])]
    rand = report("same grid, faces in random order", v, shuffled, bandwidth)
    if has_scipy:
        vn = report_vertex(v, f)
    else:
        # without scipy, trimesh's vertex normals fall back to a Python loop over vertices,
        # far too slow at a million faces: compare on a smaller grid instead, and say so
        logging.getLogger("trimesh").setLevel(logging.CRITICAL)
        print("\nscipy is not installed: trimesh uses its slow fallback; 161 x 161 grid")
        vs, fs = mesh.terrain(161, 161)
        vn = report_vertex(vs, fs)
    print("\nsummary (targets: >= libigl, >=3x trimesh on the grid, >=2x in random order,")
    print("         faster than plain numpy, vertex normals >=2x trimesh)")
    print(f"  threads used by mesh.face_normals here: {mesh.normals._workers(10**6)}")
    for label, r in (("grid  ", grid), ("random", rand)):
        print(
            f"  {label} {r['libigl']:.2f}x libigl, {r['trimesh']:.2f}x trimesh, "
            f"{r['plain']:.2f}x plain numpy (wall); in CPU time {r['libigl CPU']:.2f}x libigl, "
            f"{r['trimesh CPU']:.2f}x trimesh"
        )
    print(f"  vertex normals {vn:.2f}x trimesh")


if __name__ == "__main__":
    main()
