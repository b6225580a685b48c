"""scripts/stages.py: each stage of `make test` timed, and the table printed, failures included.

The tests of `make env` and `make lab-env` run uv, so they are in the browser stage, where a
full checkout and uv are at hand: tests/browser/test_make_env.py.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_stage_times_are_recorded_and_reported_with_the_failures(tmp_path: Path) -> None:
    env = {**os.environ, "TRINORMAL_STAGE_TIMES": str(tmp_path / "times.tsv")}

    def stages(*args: str) -> subprocess.CompletedProcess[str]:
        script = ROOT / "scripts" / "stages.py"
        return subprocess.run(
            [sys.executable, str(script), *args], env=env, capture_output=True, text=True
        )

    assert stages("reset").returncode == 0
    assert stages("run", "unit", "--", sys.executable, "-c", "pass").returncode == 0
    sleeper = "import time, sys; time.sleep(0.3); sys.exit(3)"
    assert stages("run", "browser", "--", sys.executable, "-c", sleeper).returncode == 3
    lines = stages("report").stdout.strip().splitlines()
    assert lines[0] == "make test: time per stage"
    names = [line.split()[0] for line in lines[1:]]
    assert names == ["unit", "browser", "total"]
    browser = lines[2].split()
    assert float(browser[1]) >= 0.3 and browser[-1] == "FAILED"
    assert "FAILED" not in lines[1]
    assert float(lines[3].split()[1]) >= 0.3  # the wall clock since reset
    assert stages("bogus").returncode == 2
