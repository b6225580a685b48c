"""The command line calculator: ``trinormal A B C``.

Points are written ``x,y,z`` and read exactly (``0.1`` is one tenth, ``1/3`` a
third). Negative coordinates need no ``--``::

    trinormal -1,2,3 0,0,0 1,1,1 --precision 3
    trinormal 0,0,0 1,0,0 0,1,0 --steps
    trinormal 0,0,0 1,0,0 0,1,0 --json

A degenerate triangle is an answer (exit status 0). Bad input prints one line
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
import os
import re
import sys
from collections.abc import Sequence
from fractions import Fraction
from typing import Any, NoReturn

from trinormal.core import ARITHMETICS, TriangleNormal, Winding, triangle_normal
from trinormal.display import exact_text, format_surd, radical, radical_text
from trinormal.tolerances import DEFAULT_TOL
from trinormal.validation import check_precision, check_tolerance, check_vertex, check_winding

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


def _error(message: str) -> None:
    """Print one error line on stderr, whatever stderr can encode."""
    message = " ".join(message.split("\n"))
    if len(message) > _MAX_MESSAGE:  # argparse echoes arguments whole: never a screenful
        message = message[: _MAX_MESSAGE - 1] + "…"
    line = "trinormal: error: " + message
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
        "Example: trinormal 0,0,0 1,0,0 0,1,0 --steps",
    )
    p.add_argument("points", nargs="*", metavar="POINT", help="A, B and C, each as x,y,z")
    p.add_argument(
        "--winding",
        default="ABC",
        metavar="{ABC,ACB}",
        help="ABC: U = B − A, V = C − A (default); ACB swaps U and V and flips N",
    )
    p.add_argument("--precision", default="4", help="decimal places, 0 to 15 (default 4)")
    p.add_argument(
        "--tol",
        default=None,
        help="degeneracy threshold on the sine of the angle between U and V "
        f"(default {DEFAULT_TOL})",
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


def _split_argv(argv: Sequence[str]) -> tuple[list[str], list[str]]:
    """Separate points (tokens with commas) from options, so ``-1,2,3`` is not an option."""
    options: list[str] = []
    points: list[str] = []
    take_value = False
    for tok in argv:
        if take_value:
            options.append(tok)
            take_value = False
        elif tok in _VALUE_OPTIONS:
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


def _vec(xs: Sequence[Fraction]) -> str:
    return "(" + ", ".join(exact_text(x) for x in xs) + ")"


def _term(q: Fraction) -> str:
    """Write a number inside a formula: negative values and fractions in parentheses."""
    text = exact_text(q)
    return f"({text})" if q < 0 or "/" in text else text


def steps(r: TriangleNormal, precision: int = 4) -> list[tuple[str, str]]:
    """Write out the working for a result, step by step, with exact numbers.

    Every value is exact: rationals as decimals or fractions, and |N|, the unit
    normal and the plane offset as radicals (``√2/2``), followed by a rounded
    decimal where the value is irrational.

    Parameters
    ----------
    r : TriangleNormal
        A result from :func:`trinormal.triangle_normal`.
    precision : int, default 4
        Decimal places for the rounded decimals.

    Returns
    -------
    list of (str, str)
        ``(label, working)`` pairs.

    Examples
    --------
    >>> r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    >>> for label, text in steps(r):
    ...     print(f"{label} = {text}")
    U = B − A = (2 − 1, 1 − 1, 1 − 1) = (1, 0, 0)
    V = C − A = (1 − 1, 2 − 1, 2 − 1) = (0, 1, 1)
    Nx = Uy·Vz − Uz·Vy = 0·1 − 0·1 = 0
    Ny = Uz·Vx − Ux·Vz = 0·0 − 1·1 = -1
    Nz = Ux·Vy − Uy·Vx = 1·1 − 0·0 = 1
    N = (0, -1, 1)
    |N|² = Nx² + Ny² + Nz² = 2
    |N| = √2 ≈ 1.4142
    area = |N| / 2 = √2/2 ≈ 0.7071
    n̂ = N / |N| = (0, -√2/2, √2/2) ≈ (0.0000, -0.7071, 0.7071)
    plane = n̂ · X = n̂ · A, so d = 0
    """
    e = r.exact
    first, second = ("B", "C") if r.winding is Winding.ABC else ("C", "B")
    p_first, p_second = (e.b, e.c) if r.winding is Winding.ABC else (e.c, e.b)
    out: list[tuple[str, str]] = []
    for name, vertex, p, vec in (("U", first, p_first, e.u), ("V", second, p_second, e.v)):
        diffs = ", ".join(f"{_term(x)} − {_term(y)}" for x, y in zip(p, e.a, strict=True))
        out.append((name, f"{vertex} − A = ({diffs}) = {_vec(vec)}"))
    (ux, uy, uz), (vx, vy, vz) = e.u, e.v
    t = _term
    nx, ny, nz = (exact_text(x) for x in e.normal)
    out.append(("Nx", f"Uy·Vz − Uz·Vy = {t(uy)}·{t(vz)} − {t(uz)}·{t(vy)} = {nx}"))
    out.append(("Ny", f"Uz·Vx − Ux·Vz = {t(uz)}·{t(vx)} − {t(ux)}·{t(vz)} = {ny}"))
    out.append(("Nz", f"Ux·Vy − Uy·Vx = {t(ux)}·{t(vy)} − {t(uy)}·{t(vx)} = {nz}"))
    out.append(("N", _vec(e.normal)))
    m2 = e.magnitude_squared
    out.append(("|N|²", f"Nx² + Ny² + Nz² = {exact_text(m2)}"))

    def approx(neg: bool, q: Fraction) -> str:
        return format_surd(neg, q.numerator, q.denominator, precision)

    # |N| = sqrt(S) / D², with S the integer |N|² · D⁴: splitting S (not the reduced
    # fraction's numerator times its denominator) keeps the numbers small
    state = r._state
    k, m = radical(Fraction(state.S))
    c = k / (state.D * state.D)
    mag = radical_text(c, m)
    suffix = "" if m == 1 else f" ≈ {approx(False, m2)}"
    out.append(("|N|", f"{mag}{suffix}"))
    area = radical_text(c / 2, m)
    suffix = "" if m == 1 else f" ≈ {approx(False, m2 / 4)}"
    out.append(("area", f"|N| / 2 = {area}{suffix}"))
    if r.degenerate:
        out.append(("n̂", f"undefined. Degenerate: {r.reason}"))
        return out
    # n_i = N_i / (c √m) = (N_i / (c m)) √m
    unit = [radical_text(x / (c * m), m) for x in e.normal]
    unit_text = "(" + ", ".join(unit) + ")"
    if m != 1:
        rounded = ", ".join(approx(x < 0, x * x / m2) for x in e.normal)
        unit_text += f" ≈ ({rounded})"
    out.append(("n̂", f"N / |N| = {unit_text}"))
    dot = sum((x * y for x, y in zip(e.normal, e.a, strict=True)), Fraction(0))
    d_text = radical_text(dot / (c * m), m)
    if m != 1 and dot != 0:
        d_text += f" ≈ {approx(dot < 0, dot * dot / m2)}"
    out.append(("plane", f"n̂ · X = n̂ · A, so d = {d_text}"))
    return out


def _table(r: TriangleNormal, points: Sequence[str], precision: int) -> str:
    f = r.format(precision)
    u_label, v_label = ("B − A", "C − A") if r.winding is Winding.ABC else ("C − A", "B − A")
    rows = [
        ("A, B, C", "   ".join("(" + ", ".join(_read_point(p, "?")) + ")" for p in points)),
        ("winding", r.winding.label + ("" if r.arithmetic == "exact" else f"   ({r.arithmetic})")),
        (f"U = {u_label}", f["u"]),
        (f"V = {v_label}", f["v"]),
        ("N = U × V", f["normal"]),
        ("|N|", f["magnitude"]),
        ("area = |N|/2", f["area"]),
        ("unit normal", f["unit_normal"]),
        ("plane", f["plane"]),
    ]
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


def _render(r: TriangleNormal, args: argparse.Namespace, points: list[str], precision: int) -> str:
    """Make the text to print: JSON, the worked steps or the table."""
    if args.json:
        data = r.to_dict()
        data["precision"] = precision
        data["formatted"] = r.format(precision)
        text = json.dumps(data, indent=2, ensure_ascii=False)
        if _encodable(text, sys.stdout) != text:  # the stream cannot show every symbol
            text = json.dumps(data, indent=2, ensure_ascii=True)
        return text
    if args.steps:
        lines = [f"A = {_vec(r.exact.a)}, B = {_vec(r.exact.b)}, C = {_vec(r.exact.c)}"]
        lines.append(f"winding {r.winding.label}")
        if r.arithmetic != "exact":
            lines.append(f"(the working is exact; --arithmetic {r.arithmetic} affects the table)")
        lines += [f"{label} = {work}" for label, work in steps(r, precision)]
        return "\n".join(lines)
    return _table(r, points, precision)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
