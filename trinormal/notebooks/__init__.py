"""Copy the eleven notebooks out of the installed package, to hand out or to open.

The wheel carries the notebooks (and any data they read) inside the package, so a
school's JupyterHub needs nothing but ``pip install "trinormal[notebooks]"``:

.. code-block:: console

    $ trinormal-notebooks my-class
    $ python -m trinormal.notebooks my-class

Both copy every notebook into ``my-class/`` (made if missing) and print what they
copied. A notebook already there is left alone unless ``--force`` is given, so a
student's work is never overwritten by accident. Errors print one line and exit with
status 2.

Standard library only: it runs before the notebooks' own libraries are installed.

``trinormal-notebooks report SUBMISSIONS…`` runs handed-in notebooks and writes the
class report (`trinormal.notebooks.report`, `trinormal.notebooks.class_report`);
``trinormal-notebooks worksheet --students ROSTER --out DIR`` writes worksheets with
each student's own numbers (`trinormal.notebooks.worksheet`). To copy the notebooks
into a folder called ``report`` or ``worksheet``, write ``./report``.
"""

from __future__ import annotations

import argparse
import shutil
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import NoReturn

__all__ = ["main", "notebook_files", "notebooks_source"]

#: Files and folders never copied (editor and Jupyter leftovers).
_SKIP = {".ipynb_checkpoints", "__pycache__", ".DS_Store"}


def notebooks_source() -> Path:
    """Find the folder the notebooks are copied from.

    In an installed wheel that is ``trinormal/_notebooks`` inside the package; in a
    checkout (an editable install) it is the repository's ``notebooks/``.

    Returns
    -------
    pathlib.Path
        The folder holding ``01_worked_example.ipynb`` and the other notebooks.

    Raises
    ------
    FileNotFoundError
        If neither folder exists (a broken install).

    Examples
    --------
    >>> (notebooks_source() / "01_worked_example.ipynb").is_file()
    True
    """
    package = Path(__file__).resolve().parent.parent
    for folder in (package / "_notebooks", package.parent / "notebooks"):
        if any(folder.glob("[0-9][0-9]_*.ipynb")):
            return folder
    raise FileNotFoundError(
        f"the notebooks are missing from this installation ({package / '_notebooks'}): "
        "reinstall trinormal"
    )


def notebook_files(source: Path | None = None) -> list[Path]:
    """List every file to copy, relative to the source folder, notebooks first.

    Parameters
    ----------
    source : pathlib.Path, optional
        The folder to list; `notebooks_source` by default.

    Returns
    -------
    list of pathlib.Path
        The numbered notebooks in order, then any data files beside them.

    Examples
    --------
    >>> [p.name for p in notebook_files()][:2]
    ['01_worked_example.ipynb', '02_symbolic_derivation.ipynb']
    """
    root = source if source is not None else notebooks_source()
    files = [
        p.relative_to(root)
        for p in root.rglob("*")
        if p.is_file() and not _SKIP.intersection(p.relative_to(root).parts)
    ]
    return sorted(files, key=lambda p: (p.suffix != ".ipynb" or len(p.parts) > 1, p.as_posix()))


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: {message}\n")


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="trinormal-notebooks",
        description="Copy trinormal's eleven notebooks (and the data they read) into a folder. "
        "Also: 'trinormal-notebooks report --help' (the class report from handed-in notebooks; "
        "it runs the students' code on this machine) and 'trinormal-notebooks worksheet --help'.",
    )
    parser.add_argument("dest", metavar="DEST", help="the folder to copy into (made if missing)")
    parser.add_argument(
        "--force", action="store_true", help="overwrite notebooks that are already in DEST"
    )
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Copy the notebooks into a folder; return the exit status.

    Parameters
    ----------
    argv : sequence of str, optional
        ``DEST`` and optionally ``--force``, or ``report …`` or ``worksheet …``;
        ``sys.argv[1:]`` by default.

    Returns
    -------
    int
        0 when every file was copied, 2 (after one line on stderr) when nothing was.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     status = main([tmp + "/class"])  # doctest: +ELLIPSIS
    Copied 11 notebooks into .../class
    >>> status
    0
    """
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] == ["report"]:
        from trinormal.notebooks.commands import report_main

        return report_main(argv[1:])
    if argv[:1] == ["worksheet"]:
        from trinormal.notebooks.commands import worksheet_main

        return worksheet_main(argv[1:])
    args = _parser().parse_args(argv)
    dest = Path(args.dest)
    prog = "trinormal-notebooks"
    try:
        source = notebooks_source()
        files = notebook_files(source)
        if dest.exists() and not dest.is_dir():
            raise NotADirectoryError(f"{dest} is a file, not a folder")
        there = [p for p in files if (dest / p).exists()]
        if there and not args.force:
            raise FileExistsError(
                f"{dest / there[0]} already exists ({len(there)} of the files are there): "
                "nothing was copied; use --force to overwrite them"
            )
        for rel in files:
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source / rel, dest / rel)
    except OSError as exc:
        message = str(exc) if exc.strerror is None else f"{exc.strerror}: {exc.filename}"
        print(f"{prog}: {message}", file=sys.stderr)
        return 2
    count = sum(1 for p in files if p.suffix == ".ipynb")
    others = len(files) - count
    extra = f" and {others} data file{'s' if others > 1 else ''}" if others else ""
    print(f"Copied {count} notebooks{extra} into {dest.resolve()}")
    return 0
