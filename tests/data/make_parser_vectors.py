"""Generate the parser contract shared by Python and the site's JavaScript.

Each vector is one input and what :mod:`trinormal.validation` says about it:
a coordinate string read exactly (``value`` is ``[numerator, denominator]`` as
decimal strings) or refused (``error`` is the message), a precision or a
winding accepted or refused. ``tests/test_parser_vectors.py`` checks the
Python side and that the stored file is current;
``tests/browser/test_parser_vectors.py`` runs every vector through
``docs/assets/javascripts/trinormal-core.js`` in Chromium.

Run ``python tests/data/make_parser_vectors.py`` to rewrite
``tests/data/parser_vectors.json``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from trinormal.validation import check_coordinate, check_precision, check_winding

PATH = Path(__file__).with_name("parser_vectors.json")

#: Coordinate strings: ordinary forms, what readers paste, and what must be refused.
COORDINATES: list[str] = [
    # ordinary decimals and fractions
    *("0", "-0", "+0", "1", "-1", "0.1", "-2.5e3", "1E+05", "2.5e-3", "007", "0.10"),
    *("1/3", "-1/3", "1/-3", "-2/-6", " 1 / 3 ", "10/4", "0/5", "1/0", "0/0", "-0/-1"),
    # bare points and explicit plus signs
    *("+.5", "5.", ".5", "-.5", "5.e2", ".5e-1", "+5", "+1/+2", ".", "-.", "e5", "5e", "5e+"),
    # the Unicode minus (as printed text uses it), in every place a sign may go
    *("\u22121", "\u22120.5", "1e\u22123", "\u22121/\u22123", "1/\u22124", "\u2212\u22121"),
    # spaces of every kind around the number, and a byte order mark
    *(" 1", "1 ", "\t1\n", "\u00a01\u00a0", "\u20031", "1\u3000", "\ufeff1", "\ufeff\u22121"),
    *("\u200a2.5\u2009", "\u202f3\u205f", "\x851\x85", "1\u2028", " \u00a0 "),
    # spaces inside a number are not ignored, except around the fraction bar
    *("1 000", "1\u00a0000", "- 1", "1 /\u00a02", "1 . 5"),
    # digits other than ASCII 0-9, and other notations: refused
    *("\u0661", "\uff11", "\u0661\u0662", "\u09e7", "\U0001d7cf", "\u00b2", "\u2155"),
    *("1_000", "0x10", "0b11", "0o7", "1,5", "1.2.3", "1e1e1", "1/2/3", "1.5/2", "½"),
    *("\u20131", "\u2014", "--1", "+-1", "(1)", "1%", "$1", "1d", "1f"),
    # invisible and control characters are refused and shown escaped
    *("1\u200b", "\u200b", "1\x00", "1\x1f", "\x7f", "\u00ad1", "1\ud7ff"),
    # NaN and infinities in the spellings Python's float() knows
    *("nan", "NaN", "-nan", "+NAN", "inf", "-inf", "+Infinity", "\u2212inf", "infinity"),
    *("nan1", "infinit", "\u221e", "snan"),
    # empty and blank
    *("", " ", "\t\n", "\ufeff"),
    # quotes and backslashes in a message
    *("it's", 'say "1"', "a'b\"c", "1\\2"),
    # the size limit: 400 digits in the numerator and in the denominator
    "9" * 400,
    "9" * 401,
    "1" + "0" * 399,
    "1" + "0" * 400,
    "1e399",
    "1e400",
    "1e-399",
    "1e-400",
    "5e-400",  # 1 / (2 * 10**399): within the limit in lowest terms
    "0.5" + "0" * 600,
    "1" + "0" * 500 + "/" + "1" + "0" * 200,  # 10**300 in lowest terms
    "1/" + "9" * 400,
    "1/" + "9" * 401,
    "1e-2200",
    "1e99999",
    "1e1000000000",
    "0e1000000000",
    "1e-1000000000",
    "1e0000001",  # leading zeros in an exponent, without and with a sign
    "1e+00000000000001",
    "0." + "0" * 398 + "1",
    "0." + "0" * 399 + "1",
    # the text length limit: 1000 characters, never echoed in the message
    "1" * 1000,
    "1" * 1001,
    "1" * 5000,
    " " * 995 + "1",
    " " * 1001 + "1",
    "x" * 60,
]

PRECISIONS: list[Any] = [0, 4, 15, 16, -1, "0", " 7 ", "15", "16", "-1", "two", "", "2.5", "1e1"]
PRECISIONS += ["\uff11", "9" * 20, 2.5, None]
WINDINGS: list[Any] = ["ABC", "ACB", "abc", "CBA", "", " ABC", None, 3]


def _outcome(fn: Any, *args: Any) -> dict[str, Any]:
    try:
        value = fn(*args)
    except (ValueError, TypeError) as err:
        return {"ok": False, "error": str(err)}
    if isinstance(value, tuple):
        return {"ok": True, "value": [str(value[0]), str(value[1])]}
    return {"ok": True, "value": str(value)}


def build() -> list[dict[str, Any]]:
    """Every vector, in order."""
    out: list[dict[str, Any]] = []
    for text in COORDINATES:
        out.append({"kind": "coordinate", "input": text, **_outcome(check_coordinate, text, "B.y")})
    for p in PRECISIONS:
        out.append({"kind": "precision", "input": p, **_outcome(check_precision, p)})
    for w in WINDINGS:
        out.append({"kind": "winding", "input": w, **_outcome(check_winding, w)})
    return out


def dumps(vectors: list[dict[str, Any]]) -> str:
    """The stored form: one vector a line, ASCII with escapes, so invisible characters show."""
    return "[\n" + ",\n".join(json.dumps(v, ensure_ascii=True) for v in vectors) + "\n]\n"


def main() -> int:
    """Rewrite the stored vectors file."""
    vectors = build()
    PATH.write_text(dumps(vectors), encoding="utf-8")
    print(f"wrote {len(vectors)} vectors to {PATH}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
