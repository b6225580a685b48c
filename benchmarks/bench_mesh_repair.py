"""Speed of checking and repairing a mesh, against trimesh, measured in the same run.

A closed torus of one million faces (1000 x 500 grid), 10 % of its faces
turned over at random, then the whole thing inside out, so both steps of a
repair have work to do:

* ``mesh.check`` (everything the report holds) and ``mesh.fix_winding``
  (consistent winding, then outward) against
* ``trimesh.repair.fix_winding`` followed by ``trimesh.repair.fix_inversion``
  on ``Trimesh(v, f, process=False)`` (building the Trimesh object is timed
  with it: trimesh's repair needs it; its caches start empty each round).

Also printed: a 1M-face binary STL read by ``mesh.read_mesh`` (with the exact
merge of equal corners) and by ``trimesh.load`` (its default ``process=True``
merges corners that agree to 8 decimals; ``process=False`` is timed too, but
leaves three separate corners per triangle, nothing a repair can join), and the
whole way from that file to a repaired mesh: read + check + fix_winding,
against trimesh's load + its two repairs. Each timing
is the best of a few rounds, peers interleaved, so a busy machine slows every
side alike; the CPU time of this process is printed too (threads added up),
which a busy machine inflates less than the wall time. Both results are
checked: consistent, outward, every face kept.
trimesh's repair walks the face graph with networkx and takes about twenty
times as long, so it is timed once. Run: ``python benchmarks/bench_mesh_repair.py``
(``--small`` for a 100 000-face torus, 250 x 200).
"""

from __future__ import annotations

import os
import platform
import sys
import tempfile
import time
from collections.abc import Callable
from typing import Any

import numpy as np
import trimesh

from trinormal import mesh

ROUNDS = 2


def best_times(
    funcs: dict[str, Callable[[], Any]], rounds: int = ROUNDS
) -> dict[str, tuple[float, float]]:
    """Best (wall, CPU) time of each function, the functions interleaved round by round."""
    best = dict.fromkeys(funcs, (float("inf"), float("inf")))
    for _ in range(rounds):
        for name, fn in funcs.items():
            c0, t0 = time.process_time(), time.perf_counter()
            fn()
            wall, cpu = time.perf_counter() - t0, time.process_time() - c0
            best[name] = (min(best[name][0], wall), min(best[name][1], cpu))
    return best


def show(t: dict[str, tuple[float, float]]) -> None:
    for name, (wall, cpu) in t.items():
        print(f"  {name:38s} {wall:7.2f} s wall {cpu:7.2f} s CPU", flush=True)


def damaged_torus(n_major: int = 1000, n_minor: int = 500) -> tuple[np.ndarray, ...]:
    v, good = mesh.torus(major=1.0, minor=0.4, n_major=n_major, n_minor=n_minor)
    rng = np.random.default_rng(0)
    f = good[:, [0, 2, 1]].copy()  # inside out
    flip = rng.random(len(f)) < 0.1
    f[flip] = f[flip][:, [0, 2, 1]]
    return v, f, good


def ours(v: np.ndarray, f: np.ndarray) -> tuple[mesh.MeshReport, np.ndarray]:
    report = mesh.check(v, f)
    fixed, _ = mesh.fix_winding(v, f)
    return report, fixed


def peer(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    tm = trimesh.Trimesh(v, f, process=False)
    trimesh.repair.fix_winding(tm)
    trimesh.repair.fix_inversion(tm)
    return np.asarray(tm.faces)


def main() -> None:
    print(
        f"numpy {np.__version__}, trimesh {trimesh.__version__}, "
        f"Python {platform.python_version()}, {platform.machine()}, {os.cpu_count()} cores"
    )
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"load average at the start (1, 5, 15 min): {load}")
    v, f, good = damaged_torus(250, 200) if "--small" in sys.argv else damaged_torus()
    nf = len(f)
    print(f"\ntorus: {nf:,} faces, {len(v):,} vertices; 10 % flipped, then inside out", flush=True)
    funcs: dict[str, Callable[[], Any]] = {
        "trinormal mesh.check": lambda: mesh.check(v, f),
        "trinormal mesh.fix_winding": lambda: mesh.fix_winding(v, f),
        "trinormal check + fix_winding": lambda: ours(v, f),
    }
    t = best_times(funcs)
    t |= best_times({"trimesh fix_winding + fix_inversion": lambda: peer(v, f)}, rounds=1)
    show(t)
    peer_repair = t["trimesh fix_winding + fix_inversion"]
    for k, kind in enumerate(("wall", "CPU")):
        ratio = t["trimesh fix_winding + fix_inversion"][k] / t["trinormal check + fix_winding"][k]
        print(f"  check + fix_winding vs trimesh's two repairs ({kind}): {ratio:.2f}x as fast")
    report, fixed = ours(v, f)
    theirs = peer(v, f)
    print(
        f"  trinormal: {len(report.faces_to_flip):,} faces to flip; fixed == original torus: "
        f"{bool((fixed == good).all())}"
    )
    after = mesh.check(v, theirs)
    print(
        f"  trimesh:   consistent {after.consistent_winding}, outward {after.outward}, "
        f"same triangles as the original: {bool((np.sort(theirs, 1) == np.sort(good, 1)).all())}"
    )

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "torus.stl")
        mesh.write_mesh(path, v, f)
        size = os.path.getsize(path)

        def trimesh_load() -> Any:
            return trimesh.load(path, force="mesh")  # process=True: merges the corners

        def trimesh_load_raw() -> Any:
            return trimesh.load(path, process=False, force="mesh")

        print(f"\nbinary STL, {size / 1e6:.0f} MB, {nf:,} triangles", flush=True)
        t = best_times(
            {
                "trinormal mesh.read_mesh": lambda: mesh.read_mesh(path),
                "trimesh.load (merging)": trimesh_load,
                "trimesh.load(process=False)": trimesh_load_raw,
            }
        )
        show(t)
        m = mesh.read_mesh(path)
        print(
            f"  trinormal merged the corners into {len(m.vertices):,} vertices, trimesh into "
            f"{len(trimesh_load().vertices):,} (the torus has {len(v):,})"
        )

        def ours_from_file() -> Any:
            m = mesh.read_mesh(path)
            return ours(m.vertices, m.faces)

        # trimesh's repair takes minutes: its load and repair timed above are added up
        peer_load = t["trimesh.load (merging)"]
        print(f"\nfrom the file to a repaired mesh, {nf:,} triangles", flush=True)
        t = best_times({"trinormal read + check + fix_winding": ours_from_file})
        t["trimesh load + fix_winding + fix_inversion"] = (
            peer_load[0] + peer_repair[0],
            peer_load[1] + peer_repair[1],
        )
        show(t)
        print("  (trimesh's line: its load and its repair timed above, added up)")
        for k, kind in enumerate(("wall", "CPU")):
            ratio = (
                t["trimesh load + fix_winding + fix_inversion"][k]
                / t["trinormal read + check + fix_winding"][k]
            )
            print(f"  read + check + fix_winding vs trimesh ({kind}): {ratio:.2f}x as fast")


if __name__ == "__main__":
    main()
