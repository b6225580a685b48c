"""The output fields, defined once: what each is called and where it comes from.

The CLI table, the explorer's readout, the summary sentence, the site's
calculator and its 3D view all list the same rows in the same order with the
same labels. They read them from `FIELDS`; the site receives them through
the constants file the mkdocs hook writes from this module at build time.

Each field's value is the string ``TriangleNormal.format(precision)[key]``;
its ``kind`` says how that string is written ([`Field.text`][trinormal.fields.Field.text]), and the
same key names the float value in ``TriangleNormal.to_dict()``.

This module also writes a whole result: [`format_fields`][trinormal.fields.format_fields]
(the strings behind ``TriangleNormal.format``), [`result_dict`][trinormal.fields.result_dict]
(``to_dict``) and [`result_repr`][trinormal.fields.result_repr] (``repr``). The core
computes; it imports nothing from here.

Adding an output is one entry in `FIELDS` plus its computation: the attribute of
[`TriangleNormal`][trinormal.core.TriangleNormal] of the same name (the float value,
in [`trinormal.core`][trinormal.core]) and its entry in
[`exact_values`][trinormal.fields.exact_values] (the exact value the text is rounded
from). Code that reads the fields looks them up as ``fields.FIELDS`` when it runs,
never copies them.

Examples
--------
>>> [f.key for f in FIELDS]
['u', 'v', 'normal', 'magnitude', 'area', 'unit_normal', 'plane']
>>> [label for _, label in field_labels("ACB")][:2]
['U = C − A', 'V = B − A']
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from trinormal.display import (
    exact_literal,
    exact_literals,
    format_surd,
    join_vector,
    plane_equation,
)

if TYPE_CHECKING:
    from trinormal.core import TriangleNormal

__all__ = [
    "FIELDS",
    "KINDS",
    "Field",
    "Surd",
    "exact_values",
    "field_labels",
    "fields_spec",
    "format_fields",
    "result_dict",
    "result_repr",
]

#: An exact number as ``(negative, num, den)``: the value ``±sqrt(num / den)``.
#: A rational ``p/q`` is ``(p < 0, p*p, q*q)``; |N| is ``(False, |N|², 1)``.
Surd = tuple[bool, int, int]

#: The kinds of value a field holds, and the exact value each is computed as:
#: ``"vector"``, three `Surd`; ``"scalar"``, one; ``"equation"``, the plane's
#: unit normal (three) and its offset (one). ``None`` stands for "undefined".
KINDS: tuple[str, ...] = ("vector", "scalar", "equation")


@dataclass(frozen=True)
class Field:
    """One row of every readout.

    Parameters
    ----------
    key : str
        The key in ``TriangleNormal.format()`` and ``to_dict()``.
    label : str
        The row's label for the order A→B→C.
    meaning : str
        A short phrase for readers and screen readers.
    kind : {"vector", "scalar", "equation"}
        What the value looks like when written (see `KINDS`).
    short : str
        The name in a one-line summary, such as ``"area"`` in ``area = 0.5000``.
    page_label : str
        The row's heading on the site's calculator page, for a reader.
    output_id : str
        The ``id`` of the calculator page's ``<output>`` that shows the value.
    label_acb : str, optional
        The label for the order A→C→B, where it differs from ``label``.
    """

    key: str
    label: str
    meaning: str
    kind: str
    short: str
    page_label: str
    output_id: str
    label_acb: str = ""

    def label_for(self, winding: str) -> str:
        """Return the label for a winding, ``"ABC"`` or ``"ACB"``.

        Examples
        --------
        >>> FIELDS[0].label_for("ABC"), FIELDS[0].label_for("ACB")
        ('U = B − A', 'U = C − A')
        """
        return self.label_acb if self.label_acb and str(winding) == "ACB" else self.label

    def text(self, value: Any, precision: int, trim: bool = False) -> str:
        """Write an exact value of this field's kind, rounded to ``precision`` places.

        Examples
        --------
        >>> FIELDS[0].text(((False, 1, 1), (True, 1, 4), (False, 0, 1)), 2)
        '(1.00, -0.50, 0.00)'
        >>> FIELDS[6].text((((False, 0, 1), (False, 0, 1), (False, 1, 1)), (False, 0, 1)), 1)
        '0.0x + 0.0y + 1.0z = 0.0'
        >>> FIELDS[5].text(None, 4)
        'undefined'
        """
        return self.write(value, lambda x: format_surd(*x, precision, trim))

    def write(self, value: Any, number: Callable[[Surd], str]) -> str:
        """Write an exact value of this field's kind, each number written by ``number``.

        [`text`][trinormal.fields.Field.text] with a number formatter chosen by the caller, such as
        one that remembers numbers several fields share (the unit normal and the
        plane's coefficients).
        """
        if value is None:
            return "undefined"
        if self.kind == "vector":
            return join_vector([number(x) for x in value])
        if self.kind == "scalar":
            return number(value)
        if self.kind == "equation":
            normal, offset = value
            x, y, z = (number(c) for c in normal)
            return plane_equation((x, y, z), number(offset))
        raise ValueError(f"unknown field kind {self.kind!r}; expected one of {', '.join(KINDS)}")

    def line(self, value: str) -> str:
        """Write one line of the plain-text summary: ``area = 0.5000``, ``plane: …``.

        Examples
        --------
        >>> FIELDS[4].line("0.5000"), FIELDS[6].line("z = 0")
        ('area = 0.5000', 'plane: z = 0')
        """
        return f"{self.short}{': ' if self.kind == 'equation' else ' = '}{value}"


#: Every output row, in the order readouts show them.
FIELDS: tuple[Field, ...] = (
    Field(
        "u", "U = B − A", "the first edge, from A", "vector", "U",
        "Edge U", "out-u", label_acb="U = C − A",
    ),
    Field(
        "v", "V = C − A", "the second edge, from A", "vector", "V",
        "Edge V", "out-v", label_acb="V = B − A",
    ),
    Field(
        "normal", "N = U × V", "the normal, the cross product of the edges", "vector", "N",
        "Normal N = U × V", "out-normal",
    ),
    Field(
        "magnitude", "|N|", "the length of N, twice the area", "scalar", "|N|",
        "Length |N|", "out-magnitude",
    ),
    Field(
        "area", "area = |N|/2", "the area of the triangle", "scalar", "area",
        "Area |N| / 2", "out-area",
    ),
    Field(
        "unit_normal", "unit normal", "N divided by its length", "vector", "unit normal",
        "Unit normal N / |N|", "out-unit",
    ),
    Field(
        "plane", "plane", "the plane through A, B and C", "equation", "plane",
        "Plane n · x = n · A", "out-plane",
    ),
)  # fmt: skip


def field_labels(winding: str = "ABC") -> list[tuple[str, str]]:
    """``(key, label)`` for every field, for one winding.

    Examples
    --------
    >>> field_labels()[2]
    ('normal', 'N = U × V')
    """
    return [(f.key, f.label_for(winding)) for f in FIELDS]


def fields_spec() -> list[dict[str, str]]:
    """Return the fields as JSON-ready dictionaries, for the site's generated constants.

    Examples
    --------
    >>> fields_spec()[3]["label"]
    '|N|'
    """
    return [
        {
            "key": f.key,
            "label": f.label,
            "label_acb": f.label_for("ACB"),
            "meaning": f.meaning,
            "kind": f.kind,
            "short": f.short,
            "page_label": f.page_label,
            "output_id": f.output_id,
        }
        for f in FIELDS
    ]


# --------------------------------------------------------------------------- one result


def exact_values(r: TriangleNormal) -> dict[str, Any]:
    """Compute the exact value of every output field of an exact result, as its kind takes it.

    Vectors are three `Surd`, scalars one, the plane ``(unit normal, offset)``;
    ``None`` where the value is undefined.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> exact_values(triangle_normal((0, 0, 0), (2, 0, 0), (0, 1, 0)))["area"]
    (False, 4, 4)
    """
    s = r._integers
    D, D2, S = s.denominator, s.denominator * s.denominator, s.norm_squared
    unit = plane = None
    if not r.degenerate:
        unit = tuple([(i < 0, i * i, S) for i in s.normal])
        dot = sum(i * j for i, j in zip(s.normal, s.coords[0:3], strict=True))
        plane = (unit, (dot < 0, dot * dot, S * D2))
    return {
        "u": tuple([_rational_surd(i, D) for i in s.u]),
        "v": tuple([_rational_surd(i, D) for i in s.v]),
        "normal": tuple([_rational_surd(i, D2) for i in s.normal]),
        "magnitude": (False, S, D2 * D2),
        "area": (False, S, 4 * D2 * D2),
        "unit_normal": unit,
        "plane": plane,
    }


def format_fields(r: TriangleNormal, precision: int = 4, trim: bool = False) -> dict[str, str]:
    """Display strings for every output field of a result, and its ``status`` sentence.

    This is ``TriangleNormal.format`` (documented there). Exact results are
    rounded from [`exact_values`][trinormal.fields.exact_values]; ``float64``/``float32``
    results from the computed floats, written exactly.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> format_fields(triangle_normal((0, 0, 0), (2, 0, 0), (0, 3, 0)), 2)["area"]
    '3.00'
    """
    from trinormal.core import VERDICTS

    if r.arithmetic == "exact":
        values = exact_values(r)
    else:
        values = {f.key: _float_surds(f.kind, getattr(r, f.key)) for f in FIELDS}
    written: dict[Surd, str] = {}  # the unit normal's numbers recur in the plane

    def number(x: Surd) -> str:
        text = written.get(x)
        if text is None:
            text = written[x] = format_surd(x[0], x[1], x[2], precision, trim)
        return text

    out = {f.key: f.write(values[f.key], number) for f in FIELDS}
    out["status"] = (
        VERDICTS["degenerate"].format(reason=r.reason) if r.degenerate else VERDICTS["proper"]
    )
    return out


def result_dict(r: TriangleNormal) -> dict[str, Any]:
    """Every field of a result as JSON-ready values: ``TriangleNormal.to_dict`` (documented there).

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> result_dict(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)))["exact"]["normal"]
    ['0', '0', '1']
    """
    e = r.exact
    out: dict[str, Any] = {
        "a": _json_vector(r.a),
        "b": _json_vector(r.b),
        "c": _json_vector(r.c),
        "winding": r.winding.value,
        "arithmetic": r.arithmetic,
        "tol": r.tol,
    }
    for f in FIELDS:
        out[f.key] = _json_value(f.kind, getattr(r, f.key))
    out["degenerate"] = r.degenerate
    out["reason"] = r.reason
    vectors = ("a", "b", "c", "u", "v", "normal")
    out["exact"] = {key: [str(x) for x in getattr(e, key)] for key in vectors}
    out["exact"]["magnitude_squared"] = str(e.magnitude_squared)
    out["exact"]["area_squared"] = str(e.magnitude_squared / 4)
    return out


def result_repr(r: TriangleNormal) -> str:
    """Write a result's inputs and N exactly as Python literals: a `TriangleNormal`'s ``repr``.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> result_repr(triangle_normal((0, 0, 0), (1, 0, 0), (0, "1/2", 0), arithmetic="float64"))
    "TriangleNormal(a=(0, 0, 0), b=(1, 0, 0), c=(0, '0.5', 0), winding='ABC', \
arithmetic='float64', normal=(0.0, 0.0, 0.5), degenerate=False)"
    """
    e = r.exact
    if r.arithmetic == "exact":
        normal = exact_literals(e.normal)
        squared = exact_literal(e.magnitude_squared)
        tail = f"normal={normal}, magnitude_squared={squared}"
    else:
        tail = f"normal={r.normal!r}"
    return (
        f"TriangleNormal(a={exact_literals(e.a)}, b={exact_literals(e.b)}, "
        f"c={exact_literals(e.c)}, winding={r.winding.value!r}, "
        f"arithmetic={r.arithmetic!r}, {tail}, degenerate={r.degenerate})"
    )


def _rational_surd(n: int, d: int) -> Surd:
    """Write the rational ``n / d`` as a `Surd`."""
    return (n < 0, n * n, d * d)


def _float_surds(kind: str, value: Any) -> Any:
    """Write a field's float value (by its kind) as exact `Surd`."""
    if value is None:
        return None
    if kind == "scalar":
        return _rational_surd(*value.as_integer_ratio())
    if kind == "vector":
        return tuple([_rational_surd(*x.as_integer_ratio()) for x in value])
    normal, offset = value
    return (_float_surds("vector", normal), _rational_surd(*offset.as_integer_ratio()))


def _json_number(x: float) -> float | str:
    return x if math.isfinite(x) else str(x)


def _json_vector(xs: Iterable[float]) -> list[float | str]:
    return [_json_number(x) for x in xs]


def _json_value(kind: str, value: Any) -> Any:
    """Write a field's float value (by its kind) as JSON-ready numbers; keep ``None``."""
    if value is None:
        return None
    if kind == "scalar":
        return _json_number(value)
    if kind == "vector":
        return _json_vector(value)
    normal, offset = value
    return {"normal": _json_vector(normal), "offset": _json_number(offset)}
