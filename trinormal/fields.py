"""The output fields, defined once: what each is called and where it comes from.

The CLI table, the explorer's readout, the summary sentence, the site's
calculator and its 3D view all list the same rows in the same order with the
same labels. They read them from `FIELDS`; the site receives them through
the constants file the mkdocs hook writes from this module at build time.

Each field's value is the string ``TriangleNormal.format(precision)[key]``;
its ``kind`` says how that string is written ([`Field.text`][trinormal.fields.Field.text]), and the
same key names the float value in ``TriangleNormal.to_dict()``.

Adding an output is one entry in `FIELDS` plus its computation in
[`trinormal.core`][trinormal.core]: the attribute of
[`TriangleNormal`][trinormal.core.TriangleNormal] of
the same name (the float value) and its entry in the exact fields of ``trinormal/core.py``
(the exact value the text is rounded from). Code that reads the fields looks
them up as ``fields.FIELDS`` when it runs, never copies them.

Examples
--------
>>> [f.key for f in FIELDS]
['u', 'v', 'normal', 'magnitude', 'area', 'unit_normal', 'plane']
>>> [label for _, label in field_labels("ACB")][:2]
['U = C − A', 'V = B − A']
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from trinormal.display import format_surd, join_vector, plane_equation

__all__ = ["FIELDS", "KINDS", "Field", "Surd", "field_labels", "fields_spec"]

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

        def number(x: Surd) -> str:
            return format_surd(x[0], x[1], x[2], precision, trim)

        return self.write(value, number)

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
