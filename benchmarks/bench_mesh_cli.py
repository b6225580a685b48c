"""Reading, checking and fixing mesh files, against C++ tools, measured in the same run.

The damaged torus of ``bench_mesh_repair.py`` (1M faces, 10 % flipped, then
inside out), written as a binary STL and as an OBJ:

* ``trinormal mesh FILE --fix OUT`` (read, check everything the report holds,
  fix the winding, write the binary STL), as a command, against Debian's
  ``admesh --exact --normal-directions --normal-values --write-binary-stl=OUT
  FILE`` (read, join facets by exact edges, check and fix the winding and the
  stored normals, write): wall time, CPU time (user and system) and peak memory
  (the process's maximum resident set), all from ``os.wait4``, each command in
  its own process.
* reading the OBJ: ``mesh.read_mesh`` against pymeshlab's
  ``MeshSet().load_new_mesh`` (MeshLab's reader), each in its own process
  (pymeshlab can crash); the time is taken inside the process, around the
  read alone, so importing numpy or pymeshlab is not counted.

Each figure is the best of a few rounds, peers interleaved, so a busy machine
slows both sides alike. Run: ``python benchmarks/bench_mesh_cli.py``
(``--small`` for the 100 000-face torus). Needs ``admesh`` on the PATH
(Debian: ``apt install admesh``) and pymeshlab (the bench dependency group).
"""

from __future__ import annotations

import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

from trinormal import mesh

ROUNDS = 3
HERE = os.path.dirname(os.path.abspath(__file__))

MAKE_FILES = """
import sys
sys.path.insert(0, sys.argv[5])
from bench_mesh_repair import damaged_torus
from trinormal import mesh
v, f, _ = damaged_torus(int(sys.argv[1]), int(sys.argv[2]))
mesh.write_mesh(sys.argv[3], v, f)
mesh.write_mesh(sys.argv[4], v, f)
"""

READ_OURS = """
import sys, time
from trinormal import mesh
t = time.perf_counter()
m = mesh.read_mesh(sys.argv[1])
print(time.perf_counter() - t, len(m.faces))
"""

READ_PYMESHLAB = """
import sys, time
import pymeshlab
t = time.perf_counter()
ms = pymeshlab.MeshSet()
ms.load_new_mesh(sys.argv[1])
print(time.perf_counter() - t, ms.current_mesh().face_number())
"""


def run(cmd: list[str], statuses: tuple[int, ...] = (0,)) -> tuple[float, float, float, str]:
    """Run a command: its wall time (s), CPU time (s), peak resident memory (MB) and output.

    The CPU time (user and system, from ``os.wait4``) is the steadier figure on a shared
    machine: waiting for a core counts in the wall time, not in it.

    An exit status outside ``statuses`` is an error (``trinormal mesh`` exits with 1 when
    it finds a problem, as on the damaged torus).
    """
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    assert proc.stdout is not None
    out = proc.stdout.read().decode(errors="replace")  # admesh prints Latin-1
    _, status, usage = os.wait4(proc.pid, 0)  # this process's own peak, not its siblings'
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode not in statuses:
        raise RuntimeError(f"{cmd[0]} failed ({proc.returncode}): {out[-500:]}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, out


def best(rows: list[tuple[float, ...]]) -> tuple[float, ...]:
    return tuple(min(col) for col in zip(*rows, strict=True))


def main() -> None:
    admesh = shutil.which("admesh")
    if admesh is None:
        sys.exit("admesh is not installed (Debian: apt install admesh)")
    version = subprocess.run([admesh, "--version"], capture_output=True, text=True).stdout
    print(
        f"numpy {np.__version__}, Python {platform.python_version()}, {platform.machine()}, "
        f"{os.cpu_count()} cores; {version.strip()}"
    )
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"load average at the start (1, 5, 15 min): {load}", flush=True)
    size = (250, 200) if "--small" in sys.argv else (1000, 500)
    nf = 2 * size[0] * size[1]
    with tempfile.TemporaryDirectory() as tmp:
        stl, obj = os.path.join(tmp, "torus.stl"), os.path.join(tmp, "torus.obj")
        # written by another process: a child's peak memory counts the parent's as it
        # was when the child started, so this one stays small
        run([sys.executable, "-c", MAKE_FILES, str(size[0]), str(size[1]), stl, obj, HERE])
        ours_cmd = [sys.executable, "-m", "trinormal.cli", "mesh", stl, "--fix"]
        adm_cmd = [admesh, "--exact", "--normal-directions", "--normal-values"]
        print(
            f"\nbinary STL, {os.path.getsize(stl) / 1e6:.0f} MB, {nf:,} triangles: "
            "read, check, fix the winding, write a binary STL",
            flush=True,
        )
        ours, theirs = [], []
        for _ in range(ROUNDS):
            ours.append(run([*ours_cmd, os.path.join(tmp, "ours.stl")], statuses=(1,))[:3])
            theirs.append(run([*adm_cmd, f"--write-binary-stl={tmp}/admesh.stl", stl])[:3])
        (ow, oc, orss), (aw, ac, arss) = best(ours), best(theirs)
        print(
            f"  trinormal mesh FILE --fix OUT   {ow:7.2f} s  ({oc:.2f} s CPU)  {orss:5.0f} MB peak"
        )
        print(
            f"  admesh -e -d -v -b OUT FILE     {aw:7.2f} s  ({ac:.2f} s CPU)  {arss:5.0f} MB peak"
        )
        print(
            f"  trinormal / admesh: {ow / aw:.2f}x the time ({oc / ac:.2f}x the CPU time), "
            f"{orss / arss:.2f}x the memory"
        )
        fixed = mesh.read_mesh(os.path.join(tmp, "ours.stl"))
        after = mesh.check(fixed.vertices, fixed.faces)
        print(f"  trinormal's file: consistent {after.consistent_winding}, outward {after.outward}")

        print(f"\nOBJ, {os.path.getsize(obj) / 1e6:.0f} MB, {nf:,} triangles: read", flush=True)
        ours, theirs = [], []
        for _ in range(ROUNDS):
            wall, _, _, out = run([sys.executable, "-c", READ_OURS, obj])
            ours.append((float(out.split()[0]), wall))
            wall, _, _, out = run([sys.executable, "-c", READ_PYMESHLAB, obj])
            theirs.append((float(out.split()[0]), wall))
            assert int(out.split()[1]) == nf
        (ot, ow), (pt, pw) = best(ours), best(theirs)
        print(f"  trinormal mesh.read_mesh        {ot:7.2f} s  ({ow:.2f} s with the import)")
        print(f"  pymeshlab load_new_mesh         {pt:7.2f} s  ({pw:.2f} s with the import)")
        print(f"  trinormal / pymeshlab: {ot / pt:.2f}x the time")


if __name__ == "__main__":
    main()
