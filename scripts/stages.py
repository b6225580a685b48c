"""Time the stages of ``make test`` and print a table of them at the end.

``python scripts/stages.py run NAME -- COMMAND...`` runs COMMAND, adds its wall time to
NAME in ``.cache/stage-times.tsv`` (``TRINORMAL_STAGE_TIMES`` names another file) and exits
with COMMAND's status; ``reset`` empties that file and notes the time; ``report`` prints one
line per stage and the wall-clock time since ``reset`` (stages may run side by side, so it
can be less than their sum). Standard library only: it runs before ``.venv`` exists.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

TIMES = Path(
    os.environ.get("TRINORMAL_STAGE_TIMES")
    or Path(__file__).resolve().parents[1] / ".cache" / "stage-times.tsv"
)


#: The line ``reset`` writes: when the run started (seconds since the epoch), for the total.
_START = "started"


def run(name: str, command: list[str]) -> int:
    """Run ``command``, record its wall time under ``name`` and return its exit status."""
    start = time.monotonic()
    try:
        status = subprocess.call(command)
    except KeyboardInterrupt:
        status = 130
    seconds = time.monotonic() - start
    TIMES.parent.mkdir(parents=True, exist_ok=True)
    with TIMES.open("a", encoding="utf-8") as f:
        f.write(f"{name}\t{seconds:.1f}\t{status}\n")
    return status


def report() -> None:
    """Print each recorded stage's total time (in the order they first ran) and the sum."""
    if not TIMES.is_file():
        print("stage times: none recorded")
        return
    stages: dict[str, list[float]] = {}
    started = None
    for line in TIMES.read_text(encoding="utf-8").splitlines():
        name, seconds, status = line.split("\t")
        if name == _START:
            started = float(seconds)
            continue
        entry = stages.setdefault(name, [0.0, 0.0])
        entry[0] += float(seconds)
        entry[1] = max(entry[1], float(status != "0"))
    total = sum(s for s, _ in stages.values()) if started is None else time.time() - started
    print("\nmake test: time per stage")
    for stage, (spent, failed) in stages.items():
        print(f"  {stage:<12} {spent:7.1f} s{'  FAILED' if failed else ''}")
    print(f"  {'total':<12} {total:7.1f} s ({total / 60:.1f} min)")


def main(argv: list[str]) -> int:
    """Dispatch ``run``, ``reset`` or ``report``; exit status 2 with a usage line otherwise."""
    if argv[:1] == ["run"] and len(argv) >= 4 and argv[2] == "--":
        return run(argv[1], argv[3:])
    if argv == ["reset"]:
        TIMES.parent.mkdir(parents=True, exist_ok=True)
        TIMES.write_text(f"{_START}\t{time.time()}\t0\n", encoding="utf-8")
        return 0
    if argv == ["report"]:
        report()
        return 0
    print("usage: stages.py run NAME -- COMMAND... | reset | report", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
