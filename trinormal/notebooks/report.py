"""Run the handed-in notebooks and gather every ``check(...)`` verdict: the class report's data.

Each notebook runs top to bottom in a fresh kernel of its own, in a temporary folder
(with the data files the notebooks read), with a time limit for the whole notebook.
Stored outputs are never read: the outputs are cleared and every cell runs again. The
kernel is started with the environment variable ``TRINORMAL_CHECK_LOG``
(``trinormal.exercises.CHECK_LOG_VARIABLE``) naming a file in that folder; every
``check(...)`` the notebook makes appends one JSON line to it (exercise, verdict, slip,
the answer as text, and the student's variant when ``exercises.student(...)`` chose
one). Those lines are the report: what the notebook printed does not count.

The students' code runs on the machine that runs the report, with that user's rights,
as with nbgrader: run it on the hub, in a container or in a throwaway account.

Notebooks run in parallel, one worker process (and one kernel) each, up to the number
of cores. Running needs nbclient and ipykernel (both in ``trinormal[notebooks]``).
"""

from __future__ import annotations

import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

__all__ = [
    "DEFAULT_TIMEOUT",
    "Check",
    "Outcome",
    "collect",
    "run_class",
    "run_notebook",
    "student_name",
]

#: Seconds a notebook's cells may run in all (the kernel's start not counted), unless
#: ``--timeout`` says otherwise.
DEFAULT_TIMEOUT = 120.0
#: Seconds a kernel may take to start (not counted in the notebook's time limit).
STARTUP_TIMEOUT = 60.0
#: A cell naming the student: its first line is ``Name: …`` (markdown or raw; ``**Name:**`` too).
NAME_CELL = re.compile(r"^\W*(?:name|student)\W*:\W*\s*(?P<name>[^*\n]+?)\W*$", re.IGNORECASE)
#: What marks a notebook as one of ours: a code cell using trinormal.
OURS = re.compile(r"\btrinormal\b")


@dataclass(frozen=True)
class Check:
    """One ``check(...)`` verdict as the notebook's kernel recorded it.

    Attributes
    ----------
    exercise : str
    status : {"correct", "incorrect", "unanswered", "unknown"}
    slip : str
        The slip's code (``trinormal.exercises.judging.SLIPS``), "" for none.
    answer : str
        The student's answer as text.
    message : str
        What ``check`` told the student.
    variant : int or None
        The student's variant of the exercise, None for the notebook's own numbers.
    """

    exercise: str
    status: str
    slip: str
    answer: str
    message: str
    variant: int | None = None


@dataclass(frozen=True)
class Outcome:
    """What running one handed-in notebook gave.

    Attributes
    ----------
    path : str
        The notebook, as found (inside a zip: ``archive.zip:member``).
    student : str
        The name cell's name, the name given to ``exercises.student``, or one taken from
        the file name (see `student_name`).
    status : {"ok", "failed", "timeout", "not-ours", "no-checks"}
    note : str
        For any status but "ok": the one line saying what happened.
    checks : tuple of Check
        The last verdict on each exercise, in the order the notebook first checked them.
    seconds : float
    """

    path: str
    student: str
    status: str
    note: str = ""
    checks: tuple[Check, ...] = field(default=())
    seconds: float = 0.0


def _notebook_stems() -> list[str]:
    from trinormal.notebooks import notebook_files

    return [p.stem for p in notebook_files() if p.suffix == ".ipynb" and len(p.parts) == 1]


def student_name(path: Path, cells: Sequence[dict[str, Any]] = ()) -> str:
    """Name the student of a notebook: a name cell, else the file name without our notebook's.

    A file called ``ana_lima_01_worked_example.ipynb`` names ``ana lima``; one called just
    ``01_worked_example.ipynb`` (as in a folder per student) names its folder.

    Examples
    --------
    >>> student_name(Path("ana_lima_01_worked_example.ipynb"))
    'ana lima'
    >>> student_name(Path("Ben Okafor/05_explorer.ipynb"))
    'Ben Okafor'
    >>> student_name(Path("x.ipynb"), [{"cell_type": "markdown", "source": "**Name:** Cleo Diaz"}])
    'Cleo Diaz'
    """
    for cell in cells:
        if cell.get("cell_type") in ("markdown", "raw"):
            found = NAME_CELL.match(_first_line("".join(cell.get("source", ""))))
            if found:
                return found["name"].strip()
    stem = path.stem
    for ours in _notebook_stems():
        stem = stem.replace(ours, "")
    stem = " ".join(re.split(r"[_\s-]+", stem)).strip()
    return stem or path.parent.name or path.stem


def collect(sources: Iterable[str | Path], into: Path) -> tuple[list[Path], list[str]]:
    """Find the notebooks in files, folders and zip files; unpack the zips into ``into``.

    Returns
    -------
    notebooks : list of pathlib.Path
        Every ``.ipynb`` found, in order (``.ipynb_checkpoints`` skipped).
    problems : list of str
        One line for each source that is missing or holds no notebook.
    """
    found: list[Path] = []
    problems: list[str] = []
    for number, source in enumerate(map(Path, sources)):
        if source.is_dir():
            here = sorted(p for p in source.rglob("*.ipynb") if ".ipynb_checkpoints" not in p.parts)
        elif source.suffix.lower() == ".zip" and source.is_file():
            here = _unzip(source, into / f"{number:03d}-{source.stem}")
        elif source.suffix.lower() == ".ipynb" and source.is_file():
            here = [source]
        elif not source.exists():
            problems.append(f"{source}: no such file or folder")
            continue
        else:
            problems.append(f"{source}: not a notebook, a folder or a zip file")
            continue
        if not here:
            problems.append(f"{source}: holds no notebook (.ipynb)")
        found.extend(here)
    return found, problems


def _unzip(archive: Path, dest: Path) -> list[Path]:
    """Extract the notebooks of a zip file (each under its own path, never outside ``dest``)."""
    out = []
    with zipfile.ZipFile(archive) as zf:
        for info in zf.infolist():
            parts = [p for p in Path(info.filename).parts if p not in ("", ".", "..", "/")]
            if not parts or info.is_dir() or not parts[-1].endswith(".ipynb"):
                continue
            if ".ipynb_checkpoints" in parts or parts[0] == "__MACOSX":
                continue
            target = dest.joinpath(*parts)
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(zf.read(info))
            out.append(target)
    return sorted(out)


def _read_log(log: Path) -> tuple[list[Check], str]:
    """Read the kernel's verdicts: the last one per exercise, and the name given to student()."""
    latest: dict[str, Check] = {}
    named = ""
    if not log.exists():
        return [], named
    for line in log.read_text(encoding="utf-8").splitlines():
        entry = json.loads(line)
        if "exercise" not in entry:
            named = entry.get("student", named)
            continue
        latest[entry["exercise"]] = Check(
            entry["exercise"],
            entry["status"],
            entry["slip"],
            entry["answer"],
            entry["message"],
            entry.get("variant"),
        )
    return list(latest.values()), named


def _copy_data(dest: Path) -> None:
    """Put the data files the notebooks read (not the notebooks) beside the one that runs."""
    from trinormal.notebooks import notebook_files, notebooks_source

    source = notebooks_source()
    for rel in notebook_files(source):
        if rel.suffix != ".ipynb":
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source / rel, dest / rel)


def run_notebook(path: str, timeout: float = DEFAULT_TIMEOUT) -> Outcome:
    """Run one handed-in notebook in a fresh kernel in a temporary folder; gather its verdicts.

    Never raises for the notebook's own faults: a notebook that cannot be read, raises,
    runs out of time or is not one of ours gives an `Outcome` saying so in one line.
    """
    start = time.monotonic()
    source = Path(path)
    try:
        nb = json.loads(source.read_text(encoding="utf-8"))
        cells = nb["cells"]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        return Outcome(path, student_name(source), "not-ours", f"not a notebook ({exc})")
    name = student_name(source, cells)
    code = "\n".join("".join(c.get("source", "")) for c in cells if c.get("cell_type") == "code")
    if not OURS.search(code):
        return Outcome(
            path, name, "not-ours", "not one of trinormal's notebooks: it never uses trinormal"
        )
    with tempfile.TemporaryDirectory(prefix="trinormal-report-") as tmp:
        folder = Path(tmp)
        _copy_data(folder)
        log = folder / ".trinormal-checks.jsonl"
        status, note = _execute(nb, folder, log, timeout)
        checks, named = _read_log(log)
    if named and name == student_name(source):  # no name cell: the name given to student()
        name = named
    if status == "ok" and not checks:
        status, note = "no-checks", "ran, but never called check(...)"
    return Outcome(path, name, status, note, tuple(checks), time.monotonic() - start)


def _execute(nb: dict[str, Any], folder: Path, log: Path, timeout: float) -> tuple[str, str]:
    """Run the cells (outputs cleared first) with nbclient; return (status, note).

    The time limit is for all the cells together: it starts with the first cell, once the
    kernel is up, and each cell may use what is left of it.
    """
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError, CellTimeoutError, DeadKernelError

    from trinormal.exercises import CHECK_LOG_VARIABLE

    node = nbformat.from_dict(nb)  # type: ignore[no-untyped-call]
    for cell in node.cells:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    deadline: list[float] = []  # set when the first cell starts

    def time_left(_cell: Any) -> int:
        if not deadline:
            deadline.append(time.monotonic() + timeout)
        return max(1, math.ceil(deadline[0] - time.monotonic()))

    client = NotebookClient(
        node,
        timeout=math.ceil(timeout),
        timeout_func=time_left,
        startup_timeout=int(STARTUP_TIMEOUT),
        kernel_name="python3",
        resources={"metadata": {"path": str(folder)}},
        shutdown_kernel="immediate",
    )
    # The kernel talks over files in its own folder, not TCP ports: kernels started at the
    # same moment by other workers cannot pick the same port, and nothing listens on the network.
    manager = client.create_kernel_manager()
    manager.transport, manager.ip = "ipc", str(folder / "kernel")
    env = {**os.environ, CHECK_LOG_VARIABLE: str(log), "MPLBACKEND": "agg"}
    try:  # the kernel's own warnings and tracebacks would drown the progress lines
        client.execute(env=env, stderr=subprocess.DEVNULL)
    except CellTimeoutError:
        return "timeout", f"still running after {timeout:g} s: stopped (an endless loop?)"
    except CellExecutionError as exc:
        where = _failed_cell(node)
        return "failed", f"stopped at cell {where}: {exc.ename}: {_first_line(exc.evalue)[:160]}"
    except DeadKernelError as exc:
        return "failed", f"the kernel died ({_first_line(str(exc))[:160]})"
    return "ok", ""


def _failed_cell(node: Any) -> int:
    """Return the number (from 1, all cells counted) of the cell whose output is an error."""
    for number, cell in enumerate(node.cells, 1):
        if any(out.get("output_type") == "error" for out in cell.get("outputs", [])):
            return number
    return 0


def _first_line(text: str) -> str:
    lines = (text or "").strip().splitlines()
    return lines[0] if lines else ""


def run_class(
    notebooks: Sequence[Path],
    timeout: float = DEFAULT_TIMEOUT,
    jobs: int | None = None,
    progress: Callable[[int, int, Outcome], None] | None = None,
) -> list[Outcome]:
    """Run every notebook, ``jobs`` at a time (the number of cores by default), each in a process.

    Each notebook is run by a Python process of its own (``python -m
    trinormal.notebooks.report NOTEBOOK TIMEOUT OUT``, which writes its `Outcome` as JSON):
    this process starts them and waits for them, and starts no thread.
    ``progress(done, total, outcome)`` is called as each notebook finishes. The outcomes
    come back in the order of ``notebooks``.
    """
    if not notebooks:
        return []
    workers = max(1, min(jobs or os.cpu_count() or 1, len(notebooks)))
    pending = list(enumerate(notebooks))
    running: dict[int, subprocess.Popen[bytes]] = {}
    results: dict[int, Outcome] = {}
    with tempfile.TemporaryDirectory(prefix="trinormal-class-") as tmp:
        out = Path(tmp)
        while pending or running:
            while pending and len(running) < workers:
                i, path = pending.pop(0)
                command = [
                    sys.executable,
                    "-m",
                    __name__,
                    str(path),
                    repr(timeout),
                    str(out / f"{i}.json"),
                ]
                running[i] = subprocess.Popen(
                    command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
                )
            finished = [i for i, proc in running.items() if proc.poll() is not None]
            if not finished:
                time.sleep(0.05)
            for i in finished:
                del running[i]
                results[i] = _read_outcome(out / f"{i}.json", notebooks[i])
                if progress is not None:
                    progress(len(results), len(notebooks), results[i])
    return [results[i] for i in range(len(notebooks))]


def _read_outcome(path: Path, notebook: Path) -> Outcome:
    """Read the `Outcome` a runner process wrote, or say in one line that the runner failed."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        checks = tuple(Check(**c) for c in data.pop("checks"))
        return Outcome(**data, checks=checks)
    except (OSError, ValueError, KeyError, TypeError):
        return Outcome(str(notebook), student_name(notebook), "failed", "its runner stopped")


def _run_one(argv: Sequence[str]) -> None:
    """``NOTEBOOK TIMEOUT OUT``: run one notebook (`run_notebook`), its `Outcome` as JSON to OUT."""
    notebook, timeout, out = argv
    outcome = run_notebook(notebook, float(timeout))
    Path(out).write_text(json.dumps(asdict(outcome)), encoding="utf-8")


if __name__ == "__main__":
    _run_one(sys.argv[1:])
