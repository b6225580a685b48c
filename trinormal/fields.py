"""The output fields, defined once: what each is called and where it comes from.

The CLI table, the explorer's readout, the summary sentence, the site's
calculator and its 3D view all list the same rows in the same order with the
same labels. They read them from :data:`FIELDS`; the site receives them through
the constants file the mkdocs hook writes from this module at build time.

Each field's value is the string ``TriangleNormal.format(precision)[key]``.

Examples
--------
>>> [f.key for f in FIELDS]
['u', 'v', 'normal', 'magnitude', 'area', 'unit_normal', 'plane']
>>> [label for _, label in field_labels("ACB")][:2]
['U = C − A', 'V = B − A']
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["FIELDS", "Field", "field_labels", "fields_spec"]


@dataclass(frozen=True)
class Field:
    """One row of every readout.

    Parameters
    ----------
    key : str
        The key in ``TriangleNormal.format()`` and ``to_dict()``.
    label : str
        The row's label for the order A→B→C.
    label_acb : str
        The label for the order A→C→B (the same when the order does not show).
    meaning : str
        A short phrase for readers and screen readers.
    kind : {"vector", "scalar", "equation"}
        What the value looks like when written.
    """

    key: str
    label: str
    label_acb: str
    meaning: str
    kind: str

    def label_for(self, winding: str) -> str:
        """Return the label for a winding, ``"ABC"`` or ``"ACB"``.

        Examples
        --------
        >>> FIELDS[0].label_for("ABC"), FIELDS[0].label_for("ACB")
        ('U = B − A', 'U = C − A')
        """
        return self.label_acb if str(winding) == "ACB" else self.label


#: Every output row, in the order readouts show them.
FIELDS: tuple[Field, ...] = (
    Field("u", "U = B − A", "U = C − A", "the first edge, from A", "vector"),
    Field("v", "V = C − A", "V = B − A", "the second edge, from A", "vector"),
    Field(
        "normal", "N = U × V", "N = U × V", "the normal, the cross product of the edges", "vector"
    ),
    Field("magnitude", "|N|", "|N|", "the length of N, twice the area", "scalar"),
    Field("area", "area = |N|/2", "area = |N|/2", "the area of the triangle", "scalar"),
    Field("unit_normal", "unit normal", "unit normal", "N divided by its length", "vector"),
    Field("plane", "plane", "plane", "the plane through A, B and C", "equation"),
)


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
            "label_acb": f.label_acb,
            "meaning": f.meaning,
            "kind": f.kind,
        }
        for f in FIELDS
    ]
