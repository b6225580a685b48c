"""The teacher's commands: ``trinormal-notebooks report`` and ``trinormal-notebooks worksheet``.

Both print one line and exit with status 2 on bad input; ``report`` prints a line per
notebook as it finishes, then a summary.
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path

from trinormal.notebooks import _Parser

__all__ = ["report_main", "worksheet_main"]

PROG = "trinormal-notebooks"

REPORT_HELP = """\
Run the handed-in notebooks and report what the class understood: per exercise, how
many got it right and which slips they made; per student, a row of ✓ and ✗.

WARNING: this runs the students' code on this machine, with your rights, as nbgrader
does. Run it on the school's hub, in a container or in a throwaway account, not
where your own files are.

Each notebook runs top to bottom in a fresh kernel in a temporary folder, its stored
outputs ignored; the verdict of every check(...) it makes is recorded (the kernel is
started with TRINORMAL_CHECK_LOG naming the file check() appends to). A notebook that
fails, runs out of time or is not one of trinormal's gets one line; the others go on.
The student is named by a markdown cell starting "Name:", by the name given to
exercises.student(...), or else by the file name (its folder's, for a file named
like one of the notebooks).
"""

WORKSHEET_HELP = """\
Write one printable worksheet per student, each with the student's own numbers, and
an answer key with every student's answers and worked steps. The same roster and
seed give the same worksheets; no two students share a variant of an exercise while
the bank has enough (60 each).
"""


def _report_parser() -> argparse.ArgumentParser:
    from trinormal.notebooks.report import DEFAULT_TIMEOUT

    parser = _Parser(
        prog=f"{PROG} report",
        description=REPORT_HELP,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "submissions",
        nargs="+",
        metavar="SUBMISSIONS",
        help="notebooks (.ipynb), folders of them, or zip files (as an LMS hands them out)",
    )
    parser.add_argument("--html", type=Path, metavar="OUT", help="write the report page here")
    parser.add_argument(
        "--csv", type=Path, metavar="OUT", help="write one row per student and exercise here"
    )
    parser.add_argument(
        "--timeout",
        type=float,
        default=DEFAULT_TIMEOUT,
        metavar="S",
        help=f"seconds each notebook's cells may run in all (default {DEFAULT_TIMEOUT:g})",
    )
    parser.add_argument(
        "--jobs",
        type=int,
        default=None,
        metavar="N",
        help="notebooks run at once, each in its own kernel (default: the number of cores)",
    )
    return parser


def _installed(module: str) -> bool:
    try:
        return importlib.util.find_spec(module) is not None
    except ValueError:  # in sys.modules as None: blocked
        return False


def report_main(argv: Sequence[str]) -> int:
    """Run ``trinormal-notebooks report``; return the exit status (2 for bad input)."""
    from trinormal.notebooks.class_report import render_html, write_csv
    from trinormal.notebooks.report import Outcome, collect, run_class

    args = _report_parser().parse_args(list(argv))
    missing = [m for m in ("nbclient", "ipykernel") if not _installed(m)]
    if missing:
        print(
            f"{PROG} report: running notebooks needs {' and '.join(missing)}: "
            'pip install "trinormal[notebooks]"',
            file=sys.stderr,
        )
        return 2
    if args.timeout <= 0 or (args.jobs is not None and args.jobs < 1):
        print(f"{PROG} report: --timeout and --jobs must be positive", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory(prefix="trinormal-submissions-") as tmp:
        notebooks, problems = collect(args.submissions, Path(tmp))
        for line in problems:
            print(f"{PROG} report: {line}", file=sys.stderr)
        if not notebooks:
            print(f"{PROG} report: no notebook to run", file=sys.stderr)
            return 2
        print(
            f"Running {len(notebooks)} notebook{'s' * (len(notebooks) != 1)}, at most "
            f"{args.timeout:g} s each (the students' code runs on this machine)"
        )

        def progress(done: int, total: int, o: Outcome) -> None:
            if o.status == "ok":
                right = sum(c.status == "correct" for c in o.checks)
                what = f"{right} of {len(o.checks)} checks right"
            else:
                what = f"{o.status}: {o.note}"
            print(
                f"[{done}/{total}] {Path(o.path).name} ({o.student}): {what} ({o.seconds:.1f} s)",
                flush=True,
            )

        outcomes = run_class(notebooks, args.timeout, args.jobs, progress)
    if args.csv is not None:
        write_csv(outcomes, args.csv)
        print(f"Wrote {args.csv}")
    if args.html is not None:
        args.html.write_text(render_html(outcomes), encoding="utf-8")
        print(f"Wrote {args.html}")
    reported = sum(o.status == "ok" for o in outcomes)
    print(f"{reported} of {len(outcomes)} notebooks reported")
    return 0


def _worksheet_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog=f"{PROG} worksheet", description=WORKSHEET_HELP)
    parser.add_argument(
        "--students",
        type=Path,
        required=True,
        metavar="ROSTER",
        help="a text file, one student's name a line",
    )
    parser.add_argument(
        "--out", type=Path, required=True, metavar="DIR", help="the folder to write into"
    )
    parser.add_argument(
        "--exercises",
        metavar="NAMES",
        help="comma-separated exercises (default: every exercise with variants)",
    )
    parser.add_argument(
        "--seed", type=int, default=0, metavar="S", help="another seed, other numbers (default 0)"
    )
    return parser


def worksheet_main(argv: Sequence[str]) -> int:
    """Run ``trinormal-notebooks worksheet``; return the exit status (2 for bad input)."""
    from trinormal.exercises.variants import variant_names
    from trinormal.notebooks.worksheet import read_roster, worksheets

    args = _worksheet_parser().parse_args(list(argv))
    names = variant_names()
    if args.exercises:
        names = [n.strip() for n in args.exercises.split(",") if n.strip()]
        unknown = [n for n in names if n not in variant_names()]
        if unknown:
            print(
                f"{PROG} worksheet: {unknown[0]!r} has no variants; these do: "
                f"{', '.join(variant_names())}",
                file=sys.stderr,
            )
            return 2
    try:
        roster = read_roster(args.students)
        pages, key = worksheets(roster, names, args.seed)
        args.out.mkdir(parents=True, exist_ok=True)
        for file, page in pages.items():
            (args.out / file).write_text(page, encoding="utf-8")
        (args.out / "answer-key.html").write_text(key, encoding="utf-8")
    except (OSError, ValueError) as exc:
        print(f"{PROG} worksheet: {exc}", file=sys.stderr)
        return 2
    print(f"Wrote {len(pages)} worksheets and answer-key.html into {args.out}")
    return 0
