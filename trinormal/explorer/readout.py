"""What the explorer writes: the readout rows, its HTML, the summary and the text alternative.

Every string here comes from
[`trinormal.TriangleNormal.format`][trinormal.core.TriangleNormal.format] and the
rows of `trinormal.fields.FIELDS`, so the explorer, the CLI and the site
print the same labels and the same digits.

Examples
--------
>>> from trinormal import triangle_normal
>>> r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
>>> for row in readout_rows(r, 2)[:3]:
...     print(row["label"], row["value"])
U = B − A (1.00, 0.00, 0.00)
V = C − A (0.00, 1.00, 0.00)
N = U × V (0.00, 0.00, 1.00)
>>> announcement(r, 2)
'N = (0.00, 0.00, 1.00), area 0.50.'
"""

from __future__ import annotations

import html

from trinormal import fields
from trinormal.core import TriangleNormal, Winding
from trinormal.display import format_vector

__all__ = ["alt_text", "announcement", "readout_html", "readout_rows", "summary_text"]

#: Decimal places used for the numbers in the figure's text alternative.
ALT_PRECISION_MAX = 3


def _places(p: int) -> str:
    return f"{p} decimal place{'' if p == 1 else 's'}"


def readout_rows(result: TriangleNormal, precision: int) -> list[dict[str, str]]:
    """List one ``{"key", "label", "value"}`` row per output field, in `FIELDS` order.

    Parameters
    ----------
    result : TriangleNormal
        The computed triangle.
    precision : int
        Decimal places, 0 to 15.

    Returns
    -------
    list of dict
        The label follows the winding (``U = C − A`` for A→C→B); the value is
        ``result.format(precision)[key]``.
    """
    f = result.format(precision)
    w = result.winding.value
    return [{"key": fd.key, "label": fd.label_for(w), "value": f[fd.key]} for fd in fields.FIELDS]


def announcement(result: TriangleNormal, precision: int) -> str:
    """Write one short sentence for screen readers after every change.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> text = announcement(triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2)), 1)
    >>> text.startswith("Degenerate:") and "collinear" in text
    True
    """
    f = result.format(precision)
    if result.degenerate:
        return f["status"]
    return f"N = {f['normal']}, area {f['area']}."


def readout_html(result: TriangleNormal, precision: int) -> str:
    """Write the readout as an HTML table with a caption and a status line.

    Parameters
    ----------
    result, precision
        As for `readout_rows`.

    Returns
    -------
    str
        A ``<div class="trinormal-readout">`` holding the table of
        `readout_rows` and the core's status sentence.
    """
    f = result.format(precision)
    first, second = ("B", "C") if result.winding is Winding.ABC else ("C", "B")
    th = '<th scope="row" style="text-align:left;padding-right:1em">'
    td = '<td style="font-family:monospace;text-align:left">'
    body = "".join(
        f"<tr>{th}{html.escape(row['label'])}</th>{td}{html.escape(row['value'], quote=False)}"
        "</td></tr>"
        for row in readout_rows(result, precision)
    )
    status = html.escape(f["status"], quote=False)
    if result.degenerate:
        note = (
            '<div role="status" style="border-left:4px solid #D55E00;padding:0.3em 0.6em;'
            'margin-top:0.4em"><b>No triangle to face anywhere.</b> '
            f"{status} Drag one vertex off the line through the other two and the "
            "normal comes back.</div>"
        )
    else:
        note = f'<p role="status" style="margin-top:0.4em">{status}</p>'
    caption = (
        f"Order {result.winding.label}: U = {first} − A, V = {second} − A, N = U × V "
        f"({_places(precision)})"
    )
    return (
        '<div class="trinormal-readout">'
        f'<table><caption style="text-align:left;font-weight:bold">{html.escape(caption)}'
        f"</caption>{body}</table>{note}</div>"
    )


def summary_text(result: TriangleNormal, precision: int) -> str:
    """Write the readout as plain text, one quantity a line (see ``Explorer.summary``)."""
    r, p = result, precision
    f = r.format(p)
    return "\n".join(
        [
            f"Triangle normal explorer, order {r.winding.label}, {_places(p)}",
            f"A = {format_vector(r.a, p)}  B = {format_vector(r.b, p)}  "
            f"C = {format_vector(r.c, p)}",
            *(fd.line(f[fd.key]) for fd in fields.FIELDS),
            f["status"],
        ]
    )


def alt_text(result: TriangleNormal, precision: int) -> str:
    """Describe the snapshot figure in one sentence, for screen readers and static pages.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> alt_text(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)), 4)[:60]
    'Left: the triangle A = (0, 0, 0), B = (1, 0, 0), C = (0, 1, '
    """
    r = result
    p = min(precision, ALT_PRECISION_MAX)
    f = r.format(p, trim=True)
    unit = "undefined, the triangle is degenerate" if r.degenerate else f["unit_normal"]
    normal = "no normal is drawn" if r.degenerate else "the normal N drawn from the centre"
    return (
        f"Left: the triangle A = {format_vector(r.a, p, trim=True)}, "
        f"B = {format_vector(r.b, p, trim=True)}, C = {format_vector(r.c, p, trim=True)} "
        f"in 3D, with the edges U = {f['u']} and V = {f['v']} drawn from A and {normal} "
        f"(order {r.winding.label}). Right: bar charts of the components of "
        f"N = {f['normal']} and of the unit normal, {unit}."
    )
