"""The command line: ``trinormal A B C`` (one triangle) and ``trinormal mesh FILE``.

Points are written ``x,y,z`` and read exactly (``0.1`` is one tenth, ``1/3`` a
third). Negative coordinates need no ``--``::

    trinormal -1,2,3 0,0,0 1,1,1 --precision 3
    trinormal 0,0,0 1,0,0 0,1,0 --steps
    trinormal 0,0,0 1,0,0 0,1,0 --json

``trinormal mesh FILE`` reads an OBJ, STL or PLY file, prints what is wrong
with it (`trinormal.mesh.check`) and, with ``--fix OUT``, writes the faces
rewound by `trinormal.mesh.fix_winding` (OUT's extension chooses the format;
the same format and encoding as FILE when they match)::

    trinormal mesh model.stl
    trinormal mesh model.obj --fix fixed.obj
    trinormal mesh model.ply --json

It needs numpy (the ``notebooks`` extra brings it); the triangle calculator
needs nothing beyond the standard library, and numpy is imported only when
the mesh command runs.

``trinormal mesh`` exits like a linter: 0 when the report finds nothing wrong
(``MeshReport.ok``), 1 when it finds a problem (even one ``--fix`` mends: the
status is about FILE as read), 2 when the file cannot be read. A units hint
(``a 0.05 mm model is probably in metres``) is advice, not a problem.

``trinormal print-model A B C OUT`` writes a model of the triangle for a 3D
printer (`trinormal.printmodel`): the plate, its normal as an arrow on the
front face, U and V as ridges, A, B and C in embossed letters (``--braille``:
in braille), the longest side ``--size`` mm (80 by default); OUT ends in
``.stl`` or ``.3mf``. A degenerate triangle is refused (status 2)::

    trinormal print-model 0,0,0 4,0,0 0,3,0 triangle.stl
    trinormal print-model 0,0,0 4,0,0 0,3,0 triangle.3mf --size 120 --braille

``trinormal A B C`` answers a degenerate triangle (exit status 0). Bad input prints one line
naming the vertex and axis and exits with status 2; an output that cannot be
written (a full disk) prints one line and exits with status 1. Where the output
cannot show ``×``, ``−`` or ``→`` (an ASCII terminal, a Windows code page), they
are written ``x``, ``-`` and ``->``. The command never prints a traceback.
"""

from __future__ import annotations

import argparse
import contextlib
import errno
import json
import math
import os
import re
import sys
from collections.abc import Sequence
from fractions import Fraction
from typing import Any, NoReturn

from trinormal import fields
from trinormal._optional import missing_extra
from trinormal.core import ARITHMETICS, TriangleNormal, triangle_normal
from trinormal.steps import points_text, steps, working
from trinormal.tolerances import DEFAULT_TOL
from trinormal.validation import check_precision, check_tolerance, check_vertex, check_winding

# ``steps`` is `trinormal.steps.steps`, the one step-by-step engine, under the name
# this module has always exported.
__all__ = ["main", "steps"]

_VALUE_OPTIONS = {"--winding", "--precision", "--tol", "--arithmetic"}


class _UsageError(Exception):
    pass


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        raise _UsageError(message)

    def _print_message(self, message: str, file: Any = None) -> None:
        if message:
            _write(file or sys.stdout, message)


#: Stand-ins for the symbols an ASCII-only stream cannot show.
_ASCII = {
    "×": "x",
    "−": "-",
    "→": "->",
    "·": "*",
    "²": "^2",
    "√": "sqrt",
    "≈": "~",
    "n̂": "n^",
    "…": "...",
    "—": "-",
}


def _encodable(text: str, stream: Any) -> str:
    """``text`` as ``stream`` can encode it: symbols spelled in ASCII if they cannot be."""
    encoding = getattr(stream, "encoding", None) or "utf-8"
    try:
        text.encode(encoding)
        return text
    except (UnicodeEncodeError, LookupError):
        pass
    text = re.sub(r"√(\d+)", r"sqrt(\1)", text)
    for symbol, plain in _ASCII.items():
        text = text.replace(symbol, plain)
    try:
        return text.encode(encoding, "backslashreplace").decode(encoding)
    except LookupError:
        return text.encode("ascii", "backslashreplace").decode("ascii")


def _write(stream: Any, text: str) -> None:
    """Write ``text`` to ``stream`` and flush, falling back to ASCII spellings."""
    if stream is None:  # started with the stream closed (``>&-``)
        raise OSError(errno.EBADF, "the output stream is closed")
    stream.write(_encodable(text, stream))
    stream.flush()


_MAX_MESSAGE = 300


def _error(message: str, kind: str = "error") -> None:
    """Print one error line (or, with ``kind="note"``, a note) on stderr, whatever it can encode."""
    message = " ".join(message.split("\n"))
    if len(message) > _MAX_MESSAGE:  # argparse echoes arguments whole: never a screenful
        message = message[: _MAX_MESSAGE - 1] + "…"
    line = f"trinormal: {kind}: " + message
    with contextlib.suppress(OSError, ValueError):  # stderr itself is gone: nothing to do
        _write(sys.stderr, line + "\n")


def _silence_stdout() -> None:
    """Point stdout at the null device, so the interpreter's final flush cannot fail."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog="trinormal",
        description="The normal of the triangle ABC, computed exactly: edges U and V, "
        "N = U × V, |N|, the area, the unit normal and the plane.",
        epilog="Points are x,y,z with decimals (0.1, -2.5e3) or fractions (1/3), read exactly. "
        "Example: trinormal 0,0,0 1,0,0 0,1,0 --steps. "
        "To check a mesh file: trinormal mesh FILE [--fix OUT] [--json]. "
        "To print the triangle: trinormal print-model A B C OUT [--size MM] [--braille]",
    )
    p.add_argument("points", nargs="*", metavar="POINT", help="A, B and C, each as x,y,z")
    _add_winding(p, "ABC: U = B − A, V = C − A (default); ACB swaps U and V and flips N")
    p.add_argument("--precision", default="4", help="decimal places, 0 to 15 (default 4)")
    p.add_argument(
        "--tol",
        default=None,
        help="degeneracy threshold: degenerate when |N| <= tol · L², L the longest side, "
        f"in any order of the corners (default {DEFAULT_TOL})",
    )
    p.add_argument(
        "--arithmetic",
        default="exact",
        choices=ARITHMETICS,
        help="exact (default), or the textbook formula in float64 or float32",
    )
    out = p.add_mutually_exclusive_group()
    out.add_argument(
        "--json", action="store_true", help="every field as JSON, exact values as strings"
    )
    out.add_argument("--steps", action="store_true", help="the working, with your own numbers")
    return p


def _add_winding(p: argparse.ArgumentParser, help_text: str) -> None:
    """Add the option ``--winding`` (ABC or ACB) with this help text."""
    p.add_argument("--winding", default="ABC", metavar="{ABC,ACB}", help=help_text)


def _split_argv(
    argv: Sequence[str], value_options: set[str] = _VALUE_OPTIONS
) -> tuple[list[str], list[str]]:
    """Separate points (tokens with commas) from options, so ``-1,2,3`` is not an option."""
    options: list[str] = []
    points: list[str] = []
    take_value = False
    for tok in argv:
        if take_value:
            options.append(tok)
            take_value = False
        elif tok in value_options:
            options.append(tok)
            take_value = True
        elif "," in tok and not tok.startswith("--"):
            points.append(tok)
        else:
            options.append(tok)
    return options, points


def _read_point(text: str, vertex: str) -> list[str]:
    parts = [part.strip() for part in text.split(",")]
    if len(parts) != 3:
        try:
            check_vertex(parts, vertex)  # the shared message for a wrong count
        except ValueError as err:
            raise ValueError(f"{err}; write a point as x,y,z") from None
    return parts


# --------------------------------------------------------------------------- output


def _table(r: TriangleNormal, points: Sequence[str], precision: int) -> str:
    """Write the table: the points as typed, the winding, one row per field, the verdict."""
    f = r.format(precision)
    rows = [
        ("A, B, C", "   ".join("(" + ", ".join(_read_point(p, "?")) + ")" for p in points)),
        ("winding", r.winding.label + ("" if r.arithmetic == "exact" else f"   ({r.arithmetic})")),
    ]
    rows += [(field.label_for(r.winding.value), f[field.key]) for field in fields.FIELDS]
    width = max(len(label) for label, _ in rows)
    lines = [f"{label.ljust(width)}   {value}" for label, value in rows]
    lines.append(f["status"])
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line calculator; return the exit status.

    Examples
    --------
    >>> main(["0,0,0", "1,0,0", "0,1,0", "--precision", "2"])
    A, B, C        (0, 0, 0)   (1, 0, 0)   (0, 1, 0)
    winding        A→B→C
    U = B − A      (1.00, 0.00, 0.00)
    V = C − A      (0.00, 1.00, 0.00)
    N = U × V      (0.00, 0.00, 1.00)
    |N|            1.00
    area = |N|/2   0.50
    unit normal    (0.00, 0.00, 1.00)
    plane          0.00x + 0.00y + 1.00z = 0.00
    A proper triangle: the unit normal is defined.
    0
    """
    args_in = list(sys.argv[1:] if argv is None else argv)
    try:
        if args_in[:1] == ["mesh"]:
            return _run_mesh(args_in[1:])
        if args_in[:1] == ["print-model"]:
            return _run_print(args_in[1:])
        return _run(args_in)
    except KeyboardInterrupt:
        return 130
    except OSError as exc:  # writing the help or usage text failed (a full disk)
        _silence_stdout()
        _error(f"cannot write the output: {exc.strerror or exc}")
        return 1
    except Exception as exc:  # never a traceback: one line, status 1
        _error(f"unexpected {type(exc).__name__}: {exc}")
        return 1


def _run(args_in: list[str]) -> int:
    options, points = _split_argv(args_in)
    try:
        args = _parser().parse_args(options)
        points = points + list(args.points)
        if len(points) != 3:
            raise ValueError(
                f"expected three points A B C written as x,y,z (like 0,0,0 1,0,0 0,1,0), "
                f"got {len(points)}"
            )
        a, b, c = (_read_point(p, v) for p, v in zip(points, "ABC", strict=True))
        winding = check_winding(args.winding, "--winding")
        precision = check_precision(args.precision, "--precision")
        tol: float | Fraction = DEFAULT_TOL
        if args.tol is not None:
            tol = Fraction(*check_tolerance(args.tol, "--tol"))
        r = triangle_normal(a, b, c, winding=winding, tol=tol, arithmetic=args.arithmetic)
        text = _render(r, args, points, precision)
    except (_UsageError, ValueError, TypeError) as exc:
        _error(str(exc))
        return 2
    return _print(text)


def _print(text: str) -> int:
    """Print ``text`` on stdout; return 1, after one error line, when it cannot be written."""
    try:
        _write(sys.stdout, text + "\n")
    except BrokenPipeError:  # the reader stopped early (``| head``): not an error
        _silence_stdout()
    except (OSError, ValueError) as exc:  # a full disk, a closed stream
        _silence_stdout()
        reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
        _error(f"cannot write the output: {reason}")
        return 1
    return 0


def _json_text(data: Any, indent: int | None = None) -> str:
    """Write ``data`` as JSON, ASCII-escaped where stdout cannot show every symbol."""
    text = json.dumps(data, indent=indent, ensure_ascii=False)
    if _encodable(text, sys.stdout) != text:
        text = json.dumps(data, indent=indent, ensure_ascii=True)
    return text


def _render(r: TriangleNormal, args: argparse.Namespace, points: list[str], precision: int) -> str:
    """Make the text to print: JSON, the worked steps or the table."""
    if args.json:
        data = r.to_dict()
        data["precision"] = precision
        data["formatted"] = r.format(precision)
        return _json_text(data, indent=2)
    if args.steps:
        lines = [points_text(working(r))]
        lines.append(f"winding {r.winding.label}")
        if r.arithmetic != "exact":
            lines.append(f"(the working is exact; --arithmetic {r.arithmetic} affects the table)")
        lines += [f"{label} = {work}" for label, work in steps(r, precision)]
        return "\n".join(lines)
    return _table(r, points, precision)


# --------------------------------------------------------------------------- trinormal mesh


_MESH_HELP = (
    "Check a mesh file (OBJ, STL or PLY): degenerate and duplicate faces, holes, non-manifold "
    "edges and vertices, pieces, winding and outward normals; then the report for printing: "
    "holes, surface area, volume, size (with a units hint) and a verdict."
)
_MESH_EPILOG = (
    "Exit status: 0 nothing wrong, 1 a problem found (holes, winding, ...), 2 the file cannot "
    "be read. Example: trinormal mesh model.stl --fix fixed.stl"
)


def _mesh_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="trinormal mesh", description=_MESH_HELP, epilog=_MESH_EPILOG)
    p.add_argument("file", metavar="FILE", help="the mesh: .obj, .stl or .ply")
    p.add_argument(
        "--fix",
        metavar="OUT",
        help="write the mesh with every piece wound consistently (and outward where it has an "
        "inside) to OUT; its extension chooses the format",
    )
    p.add_argument(
        "--weld",
        nargs="?",
        const=True,
        default=False,
        type=_weld_distance,
        metavar="DIST",
        help="also join boundary corners up to DIST apart (without DIST: the distance the "
        "report suggests for its near miss); corners at one position are always joined",
    )
    p.add_argument("--json", action="store_true", help="the report as JSON")
    return p


def _weld_distance(text: str) -> float:
    """Read the --weld distance: a finite number >= 0."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"not a distance >= 0: {text!r}")
    return value


def _run_mesh(args_in: list[str]) -> int:
    try:
        args = _mesh_parser().parse_args(args_in)
    except _UsageError as exc:
        _error(str(exc))
        return 2
    try:
        from trinormal import mesh
    except ModuleNotFoundError as exc:  # numpy is missing: the message names the extra
        _error(str(missing_extra(exc, "trinormal mesh")))
        return 2

    try:
        data = mesh.read_mesh(args.file)
        report = mesh.check(data.vertices, data.faces, weld=args.weld)
        fixed = None
        if args.fix is not None:
            out_fmt = mesh.io._format_of(args.fix, None)
            # the faces fix_winding turns over are the report's: turn them over once found
            flipped = report.faces_to_flip
            faces = mesh.turn_over(data.faces, flipped)
            mesh.write_mesh(args.fix, data, faces, out_fmt)  # in its own format: the file, kept
            against = data.normals_against(faces) if out_fmt == data.format else None
            fixed = (out_fmt, flipped, against)
    except ValueError as exc:  # MeshFileError and bad arrays: one line, status 2
        _error(str(exc))
        return 2
    for note in data.notes:  # what the reader forgave: on stderr, so stdout keeps its form
        _error(note, "note")
    if args.json:
        out: dict[str, Any] = {
            "file": data.path,
            "format": data.format,
            "encoding": data.encoding,
            "polygons": data.n_polygons,
            "polygons_split": data.split_polygons,
            "report": report.to_dict(),
        }
        if fixed is not None:
            out["fixed"] = {"file": args.fix, "format": fixed[0], "flipped": fixed[1].tolist()}
            if fixed[2] is not None:  # stored normals that disagree with the fixed winding
                out["fixed"]["normals_against"] = fixed[2].tolist()
        text = _json_text(out)
    else:
        lines = [data.describe(), report.summary()]
        if fixed is not None:
            n = len(fixed[1])
            lines.append(
                f"Wrote {args.fix} ({fixed[0].upper()}): {n} {'face' if n == 1 else 'faces'} "
                "turned over."
            )
            if fixed[2] is not None and fixed[2].size:
                k = fixed[2].size
                lines.append(
                    f"The stored normals of {k:,} {'face' if k == 1 else 'faces'} point against "
                    "the fixed winding; the file keeps them as they were."
                )
        text = "\n".join(lines)
    if _print(text):
        return 1
    return 0 if report.ok else 1  # like a linter: 1 when the report found a problem


# --------------------------------------------------------------------------- trinormal print-model


_PRINT_HELP = (
    "Write a model of the triangle ABC for a 3D printer: the triangle as a plate, its normal as "
    "an arrow standing on the front face (the side from which the corners turn "
    "counter-clockwise), U and V as ridges from A, the corners marked."
)
_PRINT_EPILOG = "Example: trinormal print-model 0,0,0 4,0,0 0,3,0 triangle.stl --size 100"


def _print_parser() -> argparse.ArgumentParser:
    from trinormal.printmodel import DEFAULT_SIZE, SIZE_RANGE

    p = _Parser(prog="trinormal print-model", description=_PRINT_HELP, epilog=_PRINT_EPILOG)
    p.add_argument("out", metavar="OUT", help="the file to write: .stl (binary) or .3mf")
    p.add_argument(
        "--size",
        default=str(DEFAULT_SIZE),
        help=f"the longest side in millimetres, {SIZE_RANGE[0]:g} to {SIZE_RANGE[1]:g} "
        f"(default {DEFAULT_SIZE:g})",
    )
    _add_winding(p, "the order whose front is the plate's top (default ABC)")
    p.add_argument(
        "--braille", action="store_true", help="mark A, B and C in braille, not in letters"
    )
    return p


def _run_print(args_in: list[str]) -> int:
    from trinormal.printmodel import print_model

    options, points = _split_argv(args_in, {"--size", "--winding"})
    try:
        args = _print_parser().parse_args(options)
        if len(points) != 3:
            raise ValueError(
                f"expected three points A B C written as x,y,z and the file to write "
                f"(like 0,0,0 1,0,0 0,1,0 triangle.stl), got {len(points)} points"
            )
        a, b, c = (_read_point(p, v) for p, v in zip(points, "ABC", strict=True))
        marks = "braille" if args.braille else "letters"
        model = print_model(a, b, c, winding=args.winding, size=args.size, marks=marks)
        model.write(args.out)
    except (_UsageError, ValueError, TypeError) as exc:
        _error(str(exc))
        return 2
    except OSError as exc:
        _error(f"cannot write {args.out}: {exc.strerror or exc}")
        return 1
    kind = args.out.rsplit(".", 1)[-1].upper()
    text = (
        f"Wrote {args.out} ({kind}): the triangle {model.names[0]}→{model.names[1]}→"
        f"{model.names[2]}, longest side {model.size:g} mm, marked in {marks}; "
        f"{len(model.faces)} triangles, one closed solid."
    )
    return _print(text)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
