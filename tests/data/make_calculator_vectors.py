"""Generate the shared vectors that tie the site's calculator to the Python package.

Each vector holds the calculator's inputs exactly as a reader types them (strings),
the winding and the precision, and what the Python package says for them: the seven
output strings of ``triangle_normal(...).format(precision)`` and the status sentence,
or, for unreadable input, the error message and the field it names.

Run ``python tests/data/make_calculator_vectors.py`` to rewrite
``tests/data/calculator_vectors.json``; ``tests/test_calculator_vectors.py`` fails
whenever the stored file differs from what the package produces now.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from trinormal import DEFAULT_TOL, triangle_normal
from trinormal.fields import FIELDS

OUTPUT_KEYS = tuple(f.key for f in FIELDS)
PATH = Path(__file__).with_name("calculator_vectors.json")

Point = tuple[str, str, str]

# (label, A, B, C, winding, precision)
CASES: list[tuple[str, Point, Point, Point, str, int]] = [
    ("worked example", ("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("worked example, reversed", ("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ACB", 4),
    ("table row 2", ("0", "0", "0"), ("2", "0", "0"), ("0", "3", "0"), "ABC", 4),
    ("table row 3", ("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ABC", 4),
    ("table row 3, reversed", ("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ACB", 4),
    ("collinear (table row 4)", ("0", "0", "0"), ("1", "1", "1"), ("2", "2", "2"), "ABC", 4),
    ("precision 0", ("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ABC", 0),
    ("precision 10", ("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ABC", 10),
    # area = 1/8 exactly: 0.125 rounds half away from zero to 0.13
    ("area tie 0.125", ("0", "0", "0"), ("0.5", "0", "0"), ("0", "0.5", "0"), "ABC", 2),
    ("area tie 0.125, reversed", ("0", "0", "0"), ("0.5", "0", "0"), ("0", "0.5", "0"), "ACB", 2),
    # N = (0, 0, -0.25) and area 0.125 at precision 1 and 2: ties on negative numbers
    ("negative ties", ("0", "0", "0"), ("0", "0.5", "0"), ("0.5", "0", "0"), "ABC", 1),
    ("tie 0.5 at precision 0", ("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 0),
    ("tie 2.5 at precision 0", ("0", "0", "0"), ("5", "0", "0"), ("0", "1", "0"), "ABC", 0),
    ("decimals", ("0.1", "0.2", "0.3"), ("-1.5", "2.25", "0"), ("3", "-0.7", "1e-1"), "ABC", 4),
    (
        "decimals, exponent forms",
        ("2.5e3", "-1E2", ".5"),
        ("7.", "+3", "-0"),
        ("1e0", "0", "4e-2"),
        "ABC",
        6,
    ),
    ("fractions", ("1/3", "0", "0"), ("0", "2/3", "0"), ("0", "0", "-5/7"), "ABC", 4),
    (
        "fractions with spaces and signs",
        (" 1 / 3 ", "-1/-3", "2/-6"),
        ("0", "1", "0"),
        ("1", "0", "1"),
        "ACB",
        5,
    ),
    (
        "exactly collinear decimals",
        ("0", "0", "0"),
        ("0.1", "0.2", "0.3"),
        ("0.3", "0.6", "0.9"),
        "ABC",
        4,
    ),
    ("coincident A and B", ("1", "2", "3"), ("1", "2", "3"), ("4", "5", "6"), "ABC", 4),
    ("coincident A and C", ("1", "2", "3"), ("4", "5", "6"), ("1", "2", "3"), "ABC", 4),
    ("coincident B and C", ("0", "0", "0"), ("4", "5", "6"), ("4", "5", "6"), "ACB", 4),
    ("one point", ("7", "7", "7"), ("7", "7", "7"), ("7", "7", "7"), "ABC", 3),
    # sine 1e-13 (below tol 1e-12): degenerate although N is not zero
    ("near-degenerate, below tol", ("0", "0", "0"), ("1", "0", "0"), ("1", "1e-13", "0"), "ABC", 4),
    # sine 1e-11 (above tol): a proper, very thin triangle
    ("near-degenerate, above tol", ("0", "0", "0"), ("1", "0", "0"), ("1", "1e-11", "0"), "ABC", 4),
    (
        "near-degenerate, thin sliver",
        ("0", "0", "0"),
        ("1e6", "1", "0"),
        ("2e6", "2.000001", "0"),
        "ABC",
        4,
    ),
    ("huge 1e300", ("0", "0", "0"), ("1e300", "0", "0"), ("0", "1e300", "0"), "ABC", 4),
    (
        "huge 1e300 tilted",
        ("1e300", "2e300", "-3e300"),
        ("-1e300", "5e299", "0"),
        ("0", "0", "1e300"),
        "ACB",
        3,
    ),
    ("tiny 1e-300", ("0", "0", "0"), ("1e-300", "0", "0"), ("0", "1e-300", "0"), "ABC", 4),
    (
        "tiny 1e-300 tilted",
        ("1e-300", "0", "0"),
        ("0", "2e-300", "0"),
        ("0", "0", "3e-300"),
        "ABC",
        2,
    ),
    ("beyond float range", ("0", "0", "0"), ("1e399", "0", "0"), ("0", "1e-399", "1"), "ABC", 4),
    (
        "scientific switch at 1e15",
        ("0", "0", "0"),
        ("31622776.6", "0", "0"),
        ("0", "31622776.6", "0"),
        "ABC",
        2,
    ),
    ("just below 1e15", ("0", "0", "0"), ("999999999999999", "0", "0"), ("0", "1", "0"), "ABC", 1),
    (
        "rounding carries into exponent",
        ("0", "0", "0"),
        ("9.99996e-5", "0", "0"),
        ("0", "1", "0"),
        "ABC",
        4,
    ),
    (
        "small values, precision 2",
        ("0", "0", "0"),
        ("0.004", "0.001", "0"),
        ("0", "0.003", "0.002"),
        "ABC",
        2,
    ),
    ("irrational unit normal", ("1", "2", "3"), ("4", "6", "9"), ("-2", "0", "5"), "ABC", 8),
    ("negative plane offset", ("-3", "-1", "2"), ("5", "-2", "-4"), ("0.5", "4", "-1/4"), "ACB", 4),
    (
        "long decimal input",
        ("0.1234567890123456789", "0", "0"),
        ("1", "0", "0"),
        ("0", "1", "1"),
        "ABC",
        10,
    ),
    ("precision 7 on thirds", ("0", "0", "0"), ("1/3", "1/3", "0"), ("0", "1/3", "1/3"), "ABC", 7),
    ("precision 15", ("1", "1", "1"), ("2", "1", "1"), ("1", "2", "2"), "ABC", 15),
    (
        "precision 15 on thirds",
        ("0", "0", "0"),
        ("1/3", "1/3", "0"),
        ("0", "1/3", "1/3"),
        "ACB",
        15,
    ),
    ("precision 13, tiny", ("0", "0", "0"), ("1e-7", "0", "0"), ("0", "3e-7", "0"), "ABC", 13),
    # scientific only where fixed-point would show zero: 0.05 at precision 1 is 0.1
    ("fixed-point keeps 0.05", ("0", "0", "0"), ("0.1", "0", "0"), ("0", "1", "0"), "ABC", 1),
    ("0.005 at precision 2", ("0", "0", "0"), ("0.005", "0", "0"), ("0", "1", "0"), "ABC", 2),
    ("just below half", ("0", "0", "0"), ("0.0049999", "0", "0"), ("0", "1", "0"), "ABC", 2),
    ("precision 0, below half", ("0", "0", "0"), ("0.4", "0", "0"), ("0", "0.9", "0"), "ACB", 0),
    # what readers paste: the Unicode minus, spaces of every kind, a byte order mark
    ("Unicode minus", ("−1", "0", "0"), ("0", "−2.5", "0"), ("0", "0", "1/−4"), "ABC", 4),
    (
        "spaces around",
        (" 1 ", "\t2", "\u00a03\u00a0"),
        ("\u20034", "5\u3000", "\ufeff6"),
        ("7", " 8", "9 "),
        "ABC",
        3,
    ),
    ("plus and bare points", ("+.5", "5.", "-.25"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 4),
    # unreadable input: the message names the field; every output shows a dash
    ("empty field", ("", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("blank field", ("0", "0", "0"), ("1", "   ", "0"), ("0", "1", "0"), "ABC", 4),
    ("not a number", ("0", "0", "0"), ("1", "0", "0"), ("0", "abc", "0"), "ABC", 4),
    ("divides by zero", ("0", "0", "0"), ("1/0", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("NaN", ("0", "0", "NaN"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("nan lower case", ("0", "0", "0"), ("1", "0", "0"), ("0", "1", "-nan"), "ABC", 4),
    ("infinite", ("0", "0", "0"), ("inf", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("Infinity", ("0", "0", "0"), ("1", "0", "0"), ("0", "-Infinity", "0"), "ACB", 4),
    ("exponent too large", ("0", "0", "0"), ("1", "0", "0"), ("0", "1e10000", "0"), "ABC", 4),
    ("comma decimal", ("0", "0", "0"), ("1,5", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("quote in input", ("0", "it's", "0"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("first bad field wins", ("0", "0", "0"), ("x", "0", "0"), ("", "1", "0"), "ABC", 4),
    ("5000 digits", ("0", "0", "0"), ("1", "0", "0"), ("0", "1" * 5000, "0"), "ABC", 4),
    ("401 digits", ("0", "0", "0"), ("1" * 401, "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("1e-2200", ("0", "0", "0"), ("1", "0", "0"), ("0", "1", "1e-2200"), "ABC", 4),
    ("full-width digit", ("0", "0", "0"), ("\uff11", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("Arabic-Indic digit", ("\u0661", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("underscore", ("0", "0", "0"), ("1_000", "0", "0"), ("0", "1", "0"), "ABC", 4),
    ("hexadecimal", ("0", "0", "0"), ("1", "0x10", "0"), ("0", "1", "0"), "ABC", 4),
    ("invisible character", ("0", "0", "0"), ("1", "0", "0"), ("0", "1\u200b", "0"), "ABC", 4),
    (
        "too many digits together",
        (f"1/{3**800}", f"1/{7**470}", f"1/{11**380}"),
        ("1", "0", "0"),
        ("0", "1", "0"),
        "ABC",
        4,
    ),
]


# Thin and nearly coincident triangles, each listed in every order of its corners (three
# rotations, both windings): the verdict is |N| <= tol · L², L the longest side, so it is
# the same in every order, and the site's JavaScript must agree with Python on each.
_TOL_N, _TOL_D = DEFAULT_TOL.as_integer_ratio()
THIN: list[tuple[str, Point, Point, Point]] = [
    ("needle, right angle at A", ("0", "0", "0"), ("1", "0", "0"), ("0", "1e-13", "0")),
    ("needle above tol", ("0", "0", "0"), ("1", "0", "0"), ("0", "1e-11", "0")),
    ("needle far along AB", ("0", "0", "0"), ("1", "0", "0"), ("1000", "1e-8", "0")),
    ("C within 1e-13 of A", ("0", "0", "0"), ("1", "0", "0"), ("1e-13", "1e-13", "0")),
    (
        "C within 1e-13 of A, tilted",
        ("2", "-1", "3"),
        ("3", "1", "5"),
        ("2", "-1", "3.0000000000001"),
    ),
    # |N| / L² exactly the default tol (the float 1e-12), and a hair above it
    ("on the tolerance", ("0", "0", "0"), ("1", "0", "0"), ("1/2", f"{_TOL_N}/{_TOL_D}", "0")),
    (
        "just above the tolerance",
        ("0", "0", "0"),
        ("1", "0", "0"),
        ("1/2", f"{_TOL_N + 1}/{_TOL_D}", "0"),
    ),
]
ROTATIONS = (("A first", (0, 1, 2)), ("B first", (1, 2, 0)), ("C first", (2, 0, 1)))
CASES += [
    (f"{label}, {name}, {winding}", *(pts[i] for i in order), winding, 4)  # type: ignore[misc]
    for label, *pts in THIN
    for name, order in ROTATIONS
    for winding in ("ABC", "ACB")
]


def vector(
    label: str, a: Point, b: Point, c: Point, winding: str, precision: int
) -> dict[str, Any]:
    """What the Python package says for one set of calculator inputs."""
    entry: dict[str, Any] = {
        "label": label,
        "a": list(a),
        "b": list(b),
        "c": list(c),
        "winding": winding,
        "precision": precision,
    }
    try:
        r = triangle_normal(a, b, c, winding=winding)
    except ValueError as err:
        message = str(err)
        entry.update(
            ok=False,
            degenerate=None,
            status=message,
            field=message.split(" ", 1)[0],
            expected=dict.fromkeys(OUTPUT_KEYS, "—"),
        )
        return entry
    f = r.format(precision)
    entry.update(
        ok=True,
        degenerate=r.degenerate,
        status=f["status"],
        field=None,
        expected={key: f[key] for key in OUTPUT_KEYS},
    )
    return entry


def build() -> list[dict[str, Any]]:
    """Every vector, in order."""
    return [vector(*case) for case in CASES]


def dumps(vectors: list[dict[str, Any]]) -> str:
    """The stored form of the vectors (stable, one JSON document)."""
    return json.dumps(vectors, indent=1, ensure_ascii=False) + "\n"


def main() -> int:
    """Rewrite the stored vectors file."""
    PATH.write_text(dumps(build()), encoding="utf-8")
    print(f"wrote {len(CASES)} vectors to {PATH}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
