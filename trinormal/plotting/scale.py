"""How long N is drawn, and what its label says: one rule for every picture of a triangle.

N is drawn at its true length (in the axes' units) when that fits beside the
triangle: between `TRUE_LENGTH` times its longest edge, so the triangle keeps
its share of the picture. Otherwise it is drawn scaled by the power of two that
brings it nearest `AIM` times the longest edge, and its label names the factor:
``N × ¼``, ``N × 8``. A factor of ½ never occurs (``N × ½`` beside
"area = |N|/2" could be read as the area): above the range the factor is at
most ¼, below it at least 2. The unit normal follows the same rule with the
label ``N/|N| × 4``.

The figures (`right_hand_rule_figure`), the explorer's static snapshot and the
3D view (``js/explorer/src/scaling.js``, a port checked against this module by
``tests/test_view_scale.py``) all use it.

Examples
--------
>>> drawn_factor(1.0, 1.4), scaled_label(1.0)
(1.0, 'N')
>>> drawn_factor(400.0, 28.3), scaled_label(drawn_factor(400.0, 28.3))
(0.0625, 'N × 1/16')
>>> scaled_label(4.0, unit=True)
'N/|N| × 4'
"""

from __future__ import annotations

import math

__all__ = ["AIM", "TRUE_LENGTH", "drawn_factor", "scaled_label"]

#: N is drawn at its true length when it is between these times the longest edge.
TRUE_LENGTH: tuple[float, float] = (0.25, 1.0)

#: Otherwise its drawn length aims at this many times the longest edge.
AIM = 0.7

#: The furthest power of two a factor goes to (a float's exponent range, with room).
_MAX_POWER = 1000

_FRACTIONS = {1: "½", 2: "¼", 3: "⅛"}
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def drawn_factor(length: float, longest_edge: float) -> float:
    """Return the factor a vector of ``length`` is drawn at beside a triangle.

    Parameters
    ----------
    length : float
        The vector's true length (|N|, or 1 for the unit normal), in the axes' units.
    longest_edge : float
        The triangle's longest edge, in the same units.

    Returns
    -------
    float
        1.0 (true length) or a power of two; 1.0 when either length is zero or not finite.

    Examples
    --------
    >>> drawn_factor(16.0, 5.66), drawn_factor(0.09, 0.424), drawn_factor(0.0, 1.0)
    (0.25, 4.0, 1.0)
    >>> drawn_factor(1.4, 1.0)  # longer than the edge: a quarter (a half would read as the area)
    0.25
    """
    if not (0 < length < math.inf and 0 < longest_edge < math.inf):
        return 1.0
    # log2 of the ratio, taken apart: the ratio itself may overflow or underflow
    log_ratio = math.log2(length) - math.log2(longest_edge)
    low, high = TRUE_LENGTH
    if math.log2(low) <= log_ratio <= math.log2(high):
        return 1.0
    k = math.floor(math.log2(AIM) - log_ratio + 0.5)  # rounds as JavaScript's Math.round
    if log_ratio > 0:
        k = min(k, -2)  # shorter, but never by ½
    return 2.0 ** max(-_MAX_POWER, min(_MAX_POWER, k))


def scaled_label(factor: float, unit: bool = False) -> str:
    """Return the label of N (or of the unit normal) drawn ``factor`` times its length.

    Parameters
    ----------
    factor : float
        A power of two, from `drawn_factor`.
    unit : bool, default False
        Label the unit normal ``N/|N|`` instead of ``N``.

    Returns
    -------
    str
        ``"N"`` at true length, else ``"N × ¼"``, ``"N × 1/16"``, ``"N × 8"``,
        ``"N × 2⁻²⁰"`` (past 4096).

    Examples
    --------
    >>> [scaled_label(f) for f in (1.0, 0.25, 0.125, 2.0**-5, 8.0, 2.0**20)]
    ['N', 'N × ¼', 'N × ⅛', 'N × 1/32', 'N × 8', 'N × 2²⁰']
    >>> scaled_label(2.0**-20, unit=True)
    'N/|N| × 2⁻²⁰'
    """
    base = "N/|N|" if unit else "N"
    k = round(math.log2(factor))
    if k == 0:
        return base
    if abs(k) > 12:
        text = "2" + str(k).translate(_SUPERSCRIPT)
    elif k < 0:
        text = _FRACTIONS.get(-k, f"1/{2**-k}")
    else:
        text = str(2**k)
    return f"{base} × {text}"
