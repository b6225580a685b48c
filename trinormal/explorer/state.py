"""The explorer's state: exact coordinates as text, and what the 3D view is told to draw.

The explorer keeps every coordinate as *exact text* — the way the learner or the
code wrote it (``"0.1"``, ``"-2"``, ``"1/3"``) — and computes from that text with
the exact core. Sliders, typed values, the 3D view and the site all exchange
these strings, so nothing is rounded on the way: a value the kernel set is never
replaced by the nearest point of a slider's grid.

[`view_state`][trinormal.explorer.view_state] turns a result into the ``state`` object the 3D view
draws (see ``js/explorer/`` and ``ARCHITECTURE.md``).

Examples
--------
>>> from fractions import Fraction
>>> coordinate_text(Fraction(1, 3)), coordinate_text(0.1), coordinate_text(" 2.50 ")
('1/3', '0.1', '2.50')
>>> grid_text(Fraction(3, 10), "0.1"), grid_text(2, "0.25"), grid_text(-1, "1")
('0.3', '2.00', '-1')
"""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction
from typing import Any

from trinormal.core import TriangleNormal, parse_coordinate
from trinormal.display import exact_text
from trinormal.explorer.readout import announcement, readout_rows

__all__ = [
    "coordinate_text",
    "exact_value",
    "grid_text",
    "merge_edit",
    "snap",
    "step_decimals",
    "view_state",
]


def exact_value(text: str, name: str = "value") -> Fraction:
    """Read the exact value of a coordinate written as text.

    Examples
    --------
    >>> exact_value("0.1")
    Fraction(1, 10)
    >>> exact_value("x", "B.y")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: B.y ...
    """
    n, d = parse_coordinate(text, name)
    return Fraction(n, d)


def coordinate_text(x: Any, name: str = "value") -> str:
    """Write one coordinate as exact text, checking it first.

    Strings are kept as written (without surrounding spaces). A float is read
    as the shortest decimal that gives it back, so ``0.1`` means one tenth, as
    it would on a slider or in a text box. Every other number (int,
    ``Fraction``, ``Decimal``, numpy and sympy numbers) is written exactly.

    Parameters
    ----------
    x : number or str
        The coordinate.
    name : str
        How to name it in an error, such as ``"B.y"``.

    Returns
    -------
    str
        Text that `exact_value` reads back exactly.

    Raises
    ------
    ValueError, TypeError
        For anything the core refuses (NaN, infinities, unreadable strings, ...),
        with ``name`` in the message.

    Examples
    --------
    >>> coordinate_text(2), coordinate_text(-0.25), coordinate_text(1e-300)
    ('2', '-0.25', '1e-300')
    >>> from decimal import Decimal
    >>> coordinate_text(Decimal("1.50"))
    '1.5'
    """
    if isinstance(x, str):
        parse_coordinate(x, name)
        return x.strip()
    if isinstance(x, float) or type(x).__name__ in {"float64", "float32", "float16"}:
        value = float(x)
        parse_coordinate(value, name)  # NaN and infinities are refused here
        return repr(value)
    n, d = parse_coordinate(x, name)
    return exact_text(Fraction(n, d), max_places=40)


def step_decimals(step: str) -> int:
    """Count the decimal places of a grid step as written: ``"0.1"`` → 1, ``"2"`` → 0.

    Examples
    --------
    >>> step_decimals("0.1"), step_decimals("0.25"), step_decimals("2"), step_decimals("1e-3")
    (1, 2, 0, 3)
    """
    exponent = Decimal(step).normalize().as_tuple().exponent
    return max(0, -int(exponent))


def snap(value: Fraction | float, step: str) -> Fraction:
    """Find the grid point nearest to ``value`` (ties away from zero).

    Examples
    --------
    >>> snap(0.30000000000000004, "0.1"), snap(Fraction(-1, 20), "0.1")
    (Fraction(3, 10), Fraction(-1, 10))
    """
    s = Fraction(Decimal(step))
    k = Fraction(value) / s
    whole = math.floor(abs(k) + Fraction(1, 2))
    return s * (whole if k >= 0 else -whole)


def grid_text(value: Fraction | float, step: str) -> str:
    """Write the grid point nearest to ``value`` with the step's decimal places.

    This is how a slider move or a drag in the 3D view becomes exact text:
    ``0.30000000000000004`` on a 0.1 grid is ``"0.3"``.
    """
    places = step_decimals(step)
    snapped = snap(value, step)
    return f"{Decimal(snapped.numerator) / Decimal(snapped.denominator):.{places}f}"


def merge_edit(
    edit: dict[str, Any], base: int, set_at: dict[str, int]
) -> tuple[dict[str, Any], list[str]]:
    """Split a learner's edit into what is kept and what a later cell overwrote.

    The rule of the explorer's edit protocol, per field: an edit made against the
    kernel's version ``base`` keeps every field (``"bx"``, ``"winding"``, ...) that no
    cell set since; a field the kernel set after ``base`` (``set_at[field] > base``)
    keeps the cell's value. So a drag of B survives a cell that sets C, and a cell
    that sets B wins over a drag of B that began before it.

    Parameters
    ----------
    edit : dict
        The fields the learner changed and their new values.
    base : int
        The kernel's version the edit was made against.
    set_at : dict of str to int
        For each field, the version at which the kernel last set it (absent: never).

    Returns
    -------
    kept : dict
        The part of ``edit`` to apply.
    overwritten : list of str
        The fields a cell set after the edit began, in the edit's order.

    Examples
    --------
    >>> merge_edit({"bx": "2", "by": "0.5"}, 3, {"cx": 4, "cy": 4, "cz": 4})
    ({'bx': '2', 'by': '0.5'}, [])
    >>> merge_edit({"cx": "2", "winding": "ACB"}, 3, {"cx": 4, "cy": 4, "cz": 4})
    ({'winding': 'ACB'}, ['cx'])
    """
    overwritten = [key for key in edit if set_at.get(key, 0) > base]
    kept = {key: value for key, value in edit.items() if key not in overwritten}
    return kept, overwritten


def _floats(xs: tuple[float, float, float]) -> list[float]:
    # the view draws with floats; a value beyond the float range is drawn at the edge
    return [x if math.isfinite(x) else math.copysign(1.7976931348623157e308, x) for x in xs]


def view_state(result: TriangleNormal, precision: int) -> dict[str, Any]:
    """Build what the 3D view draws and prints for one result.

    Parameters
    ----------
    result : TriangleNormal
        The computed triangle (exact arithmetic).
    precision : int
        Decimal places for the readout.

    Returns
    -------
    dict
        ``ok``, ``error``, ``points`` (``A``, ``B``, ``C`` as floats), ``u``,
        ``v``, ``normal``, ``unit_normal`` (``None`` when degenerate),
        ``degenerate``, ``status``, ``readout`` (rows of
        `readout_rows`) and ``summary`` (a
        sentence for screen readers). JSON-ready.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> s = view_state(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)), 4)
    >>> s["normal"], s["readout"][2]["value"], s["degenerate"]
    ([0.0, 0.0, 1.0], '(0.0000, 0.0000, 1.0000)', False)
    """
    r = result
    return {
        "ok": True,
        "error": None,
        "points": {"A": _floats(r.a), "B": _floats(r.b), "C": _floats(r.c)},
        "u": _floats(r.u),
        "v": _floats(r.v),
        "normal": _floats(r.normal),
        "unit_normal": None if r.unit_normal is None else _floats(r.unit_normal),
        "degenerate": r.degenerate,
        "status": r.format(precision)["status"],
        "readout": readout_rows(r, precision),
        "summary": announcement(r, precision),
    }
