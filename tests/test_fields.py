"""The field spec is the one list of outputs: every surface is built from it.

A new output (here the sine of the angle between the edges, which results
already compute) is one entry in :data:`trinormal.fields.FIELDS` plus its
computation; the test adds both to copies and checks that the CLI table, the
explorer's readout and summary, ``format()`` and ``to_dict()`` all show it
without any other edit.
"""

from __future__ import annotations

import contextlib
import io
import json
from typing import Any

import pytest

from trinormal import fields, triangle_normal
from trinormal.cli import main
from trinormal.explorer.readout import readout_html, readout_rows, summary_text
from trinormal.fields import FIELDS, Field, field_labels, fields_spec

SINE = Field(
    "sine",
    "sin θ",
    "the sine of the angle between U and V",
    "scalar",
    "sin θ",
    "Sine of the angle",
    "out-sine",
)


def _cli(*args: str) -> str:
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main(list(args)) == 0
    return buf.getvalue()


@pytest.fixture
def with_sine(monkeypatch: pytest.MonkeyPatch) -> None:
    """Add the field to the spec and its exact computation to the core, nothing else."""
    monkeypatch.setattr(fields, "FIELDS", (*FIELDS, SINE))
    exact_values = fields.exact_values

    def with_exact_sine(r: Any) -> dict[str, Any]:
        s = r._integers
        uu = sum(i * i for i in s.u)
        vv = sum(i * i for i in s.v)
        return {
            **exact_values(r),
            "sine": (False, s.norm_squared, uu * vv),
        }  # sin² = |N|²/(|U|²|V|²)

    monkeypatch.setattr(fields, "exact_values", with_exact_sine)


def test_every_surface_lists_the_spec_in_order():
    r = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    keys = [f.key for f in FIELDS]
    assert list(r.format())[:-1] == keys and list(r.format())[-1] == "status"
    assert [row["key"] for row in readout_rows(r, 4)] == keys
    d = r.to_dict()
    assert [k for k in d if k in keys] == keys
    table = _cli("1,1,1", "2,1,1", "1,2,2").splitlines()
    assert [line.split("   ")[0].rstrip() for line in table[2:-1]] == [f.label for f in FIELDS]
    assert [spec["key"] for spec in fields_spec()] == keys


def test_labels_follow_the_winding():
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0), winding="ACB")
    assert [row["label"] for row in readout_rows(r, 2)] == [lab for _, lab in field_labels("ACB")]
    table = _cli("0,0,0", "1,0,0", "0,1,0", "--winding", "ACB").splitlines()
    assert table[2].startswith("U = C − A") and table[3].startswith("V = B − A")


@pytest.mark.usefixtures("with_sine")
@pytest.mark.parametrize("arithmetic", ["exact", "float64"])
def test_a_new_field_reaches_every_surface(arithmetic: str):
    r = triangle_normal((0, 0, 0), (1, 0, 0), (1, 1, 0), arithmetic=arithmetic)
    assert r.format(4)["sine"] == "0.7071"  # √2/2, rounded from the exact value
    assert r.to_dict()["sine"] == pytest.approx(2**-0.5)
    assert json.loads(json.dumps(r.to_dict()))["sine"] == r.sine
    assert readout_rows(r, 3)[-1] == {"key": "sine", "label": "sin θ", "value": "0.707"}
    assert "sin θ</th>" in readout_html(r, 3)
    assert summary_text(r, 2).splitlines()[-2] == "sin θ = 0.71"
    table = _cli("0,0,0", "1,0,0", "1,1,0", "--arithmetic", arithmetic).splitlines()
    assert table[-2].split() == ["sin", "θ", "0.7071"]
    assert _cli("0,0,0", "1,0,0", "1,1,0", "--json").count('"sine"') == 2  # value and formatted
    assert fields_spec()[-1]["key"] == "sine"


@pytest.mark.usefixtures("with_sine")
def test_degenerate_values_with_a_new_field():
    """None is written "undefined" and null in JSON; the new field keeps its value."""
    r = triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2))
    assert r.format()["unit_normal"] == "undefined"
    assert r.to_dict()["unit_normal"] is None
    assert r.format()["sine"] == "0.0000"


def test_kinds_are_written_by_rule():
    vector, scalar, equation = (f for f in (FIELDS[0], FIELDS[3], FIELDS[6]))
    half = (False, 1, 4)
    assert vector.text((half, (True, 1, 4), (False, 0, 1)), 1) == "(0.5, -0.5, 0.0)"
    assert scalar.text((False, 2, 1), 3, trim=True) == "1.414"
    assert equation.text(((half, half, (True, 1, 2)), (True, 1, 1)), 1) == (
        "0.5x + 0.5y - 0.7z = -1.0"
    )
    assert [f.line("x") for f in (vector, scalar, equation)] == ["U = x", "|N| = x", "plane: x"]
    with pytest.raises(ValueError, match="unknown field kind 'matrix'"):
        Field("m", "M", "a matrix", "matrix", "M", "Matrix M", "out-m").text(half, 2)
