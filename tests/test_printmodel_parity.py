"""The site's printable model and Python's are one: the same STL bytes, the same 3MF model.

A corpus of triangles (right, equilateral, obtuse, tilted in 3D, at tiny and huge
coordinates, both windings, both kinds of marks, several sizes, and thin ones the
generator refuses, naming the size that fits or saying none does, and thin ones whose
marks stand on tabs beside the corners) is made into models by `trinormal.printmodel`;
``tests/printmodel_parity_check.js`` runs ``trinormal-printmodel.js`` in Node on the
same edges and compares every STL byte, every character of the 3MF model XML and
every refusal's sentence.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from node_runs import assert_port_agrees

from trinormal.core import triangle_normal
from trinormal.printmodel import PrintModelError, build

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs" / "hooks"))
from site_constants import print_constants  # noqa: E402  (the site build's own function)

TRIANGLES = [
    ((0, 0, 0), (1, 0, 0), (0, 1, 0)),  # the guide's right triangle
    ((0, 0, 0), (2, 0, 0), (1, "1.7320508", 0)),  # nearly equilateral
    ((0, 0, 0), (5, 0, 0), (-1, 2, 0)),  # obtuse at A
    ((1, 2, 3), (-2, "0.5", 4), ("1/3", -1, -2)),  # tilted, fractions
    (("-0.5", "0.25", 7), (3, 1, 2), (0, 4, 1)),
    (("1e-200", 0, 0), (0, "1e-200", 0), (0, 0, "1e-200")),  # tiny
    (("1e200", 0, 0), (0, "1e200", 0), (0, 0, "-1e200")),  # huge
    ((0, 0, 0), (10, 0, 0), (9, "0.4", 3)),  # thin: refused
    ((0, 0, 0), (1, 0, 0), ("0.5", "0.05", 0)),  # thin: refused
    ((3, 6, -8), (-6, -6, -2), (-6, -5, 0)),  # the arrow would touch the mark at A
    ((7, -3, -8), (-2, 1, 1), (-2, 2, 5)),  # the arrow would touch the ridge V
    ((0, 0, 0), (1, 0, 0), ("0.5", "0.2", 0)),  # thin, 80 × 16 mm: smaller features fit
    ((0, 0, 0), (5, 0, 0), ("2.5", "0.5", 0)),  # thinner: the smallest features fit
    ((0, 0, 0), (1, 0, 0), ("0.9", "0.06", 0)),  # too thin at 80 mm: the size that fits named
    ((0, 0, 0), (1, 0, 0), ("0.5", "0.001", 0)),  # too thin at any size accepted
    (("-3.4", "3.3", "-1.2"), (-2, "2.6", "1.9"), ("3.7", "1.5", "4.9")),  # marks on tabs
    (("0.3", "-2.1", "-2.2"), ("-1.6", "-3.2", "-0.6"), ("2.3", "-1.2", "-2.5")),  # tabs
]


def corpus() -> list[dict]:
    """Every triangle in both windings, with letters and braille, at a few sizes."""
    cases = []
    sizes = [80.0, 60.0, 150.0, 1000.0, 52.5]
    for i, (a, b, c) in enumerate(TRIANGLES):
        for winding in ("ABC", "ACB"):
            for marks in ("letters", "braille"):
                size = sizes[(i + len(cases)) % len(sizes)]
                r = triangle_normal(a, b, c, winding=winding)
                cases.append(
                    {
                        "u": list(r.u),
                        "v": list(r.v),
                        "names": "A" + winding[1:],
                        "size": size,
                        "marks": marks,
                    }
                )
    return cases


def _outline(xml: Path) -> int:
    """How many corners the plate's bottom has: 3 for the triangle, more with tabs."""
    text = xml.read_text(encoding="utf-8")
    return text.count('z="0"/>')


def test_the_site_makes_pythons_model_byte_for_byte(tmp_path):
    """One Node run for the whole corpus: no difference in any file or refusal."""
    manifest = []
    for i, case in enumerate(corpus()):
        entry = dict(case)
        try:
            model = build(case["u"], case["v"], case["names"], case["size"], case["marks"])
        except PrintModelError as exc:
            entry["error"] = str(exc)
        else:
            (tmp_path / f"{i}.stl").write_bytes(model.stl())
            (tmp_path / f"{i}.xml").write_text(model.model_xml(), encoding="utf-8")
            entry["stl"], entry["xml"] = f"{i}.stl", f"{i}.xml"
        manifest.append(entry)
    made = sum("stl" in e for e in manifest)
    assert made >= 20 and len(manifest) - made >= 4  # models and refusals both compared
    assert {e["marks"] for e in manifest if "stl" in e} == {"letters", "braille"}
    assert sum("would touch" in e.get("error", "") for e in manifest) >= 2
    assert sum("mm or larger (--size" in e.get("error", "") for e in manifest) >= 4
    assert sum("even at 1000 mm" in e.get("error", "") for e in manifest) >= 2
    tabs = [e for e in manifest if "xml" in e and _outline(tmp_path / e["xml"]) > 3]
    assert len(tabs) >= 4  # plates with the marks on tabs beside their corners compared too
    (tmp_path / "manifest.json").write_text(json.dumps(manifest), encoding="utf-8")
    constants = tmp_path / "constants.json"
    constants.write_text(json.dumps({"print": print_constants()}), encoding="utf-8")
    checker = ROOT / "tests" / "printmodel_parity_check.js"
    assert_port_agrees(checker, tmp_path, constants, len(manifest), timeout=120)
