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
    here = Path(__file__).resolve().parent
    for folder in (here / "_notebooks", here.parent / "notebooks"):
        if any(folder.glob("[0-9][0-9]_*.ipynb")):
            return folder
    raise FileNotFoundError(
        f"the notebooks are missing from this installation ({here / '_notebooks'}): "
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
        description="Copy trinormal's eleven notebooks (and the data they read) into a folder.",
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
        ``DEST`` and optionally ``--force``; ``sys.argv[1:]`` by default.

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
    args = _parser().parse_args(sys.argv[1:] if argv is None else argv)
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


if __name__ == "__main__":
    sys.exit(main())
