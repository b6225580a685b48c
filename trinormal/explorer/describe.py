"""The view described in words: which way N points, which side the viewer sees, which way the order turns.

This is the one rule the explorer speaks by. The 3D view (``js/explorer/src/describe.js``,
a port of this module) writes the same sentences under the picture, in a polite live region,
and `Explorer.describe` returns them for a terminal or a notebook; ``tests/test_describe.py``
runs both on one corpus and asks for the same strings, byte for byte.

A description is written as a teacher speaks: the direction first in words, then one number
(the angle to the nearest axis), then what the viewer sees.

* **Direction.** The unit normal's components, largest first: ``+z`` is "up", ``−z``
  "down", the others "towards +x", "towards −y" and so on. A component under
  `MENTION` is left out; one under `A_LITTLE` is "a little" that way. The number is
  the angle between N and the axis it is nearest to, in whole degrees.
* **Side.** The viewer sees the *front* (the side N points out of) when the direction
  towards the viewer makes an acute angle with N, the *back* when it makes an obtuse
  one, and the triangle *edge-on* when the cosine is under `EDGE_ON`.
* **Turn.** Seen from the front the order of the vertices (A→B→C, or A→C→B when the
  winding is flipped) turns counter-clockwise, from the back clockwise: the same sign
  decides both, which is the right-hand rule.
* **Degenerate.** The core's verdict (``result.degenerate``) and its status sentence.

Examples
--------
>>> from trinormal import triangle_normal
>>> r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
>>> describe(r, viewer=(0, 0, 1))
'N points straight up, along +z. You see the front of the triangle (N points towards you), and A→B→C turns counter-clockwise.'
>>> describe(r, viewer=(0, 0, -1))
'N points straight up, along +z. You see the back of the triangle (N points away from you), and A→B→C turns clockwise.'
"""  # noqa: E501

from __future__ import annotations

import math
from collections.abc import Sequence

from trinormal.core import TriangleNormal
from trinormal.display import format_number

__all__ = ["A_LITTLE", "EDGE_ON", "MENTION", "describe", "direction_words", "viewer_words"]

#: A unit normal's component smaller than this (in size) is not mentioned in words.
MENTION = 0.05
#: A mentioned component smaller than this is "a little" that way.
A_LITTLE = 0.25
#: Below this cosine between N and the direction to the viewer, the triangle is seen edge-on.
EDGE_ON = 0.02

_AXES = "xyz"
_MINUS = "\N{MINUS SIGN}"


def _signed(axis: int, negative: bool) -> str:
    return (_MINUS if negative else "+") + _AXES[axis]


def _word(axis: int, negative: bool) -> str:
    if axis == 2:
        return "down" if negative else "up"
    return "towards " + _signed(axis, negative)


def _join(words: list[str]) -> str:
    """Join words as a sentence lists them: "a", "a and b", "a, b and c"."""
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def _degrees(x: float) -> str:
    # whole degrees through the package's formatter (which writes a nonzero value that would
    # round to 0 in scientific notation: under half a degree is said in words instead)
    return "less than 1" if x < 0.5 else format_number(x, 0)


def direction_words(unit_normal: Sequence[float]) -> str:
    """Say which way a unit normal points, in words and one number.

    Parameters
    ----------
    unit_normal : sequence of 3 float
        N / |N| (the triangle's ``unit_normal``).

    Returns
    -------
    str
        One sentence, such as ``"N points up and towards −y: mostly +z, 27° from the z axis."``

    Examples
    --------
    >>> import math
    >>> t = math.radians(27)
    >>> direction_words((0.0, -math.sin(t), math.cos(t)))
    'N points up and towards −y: mostly +z, 27° from the z axis.'
    >>> direction_words((0.0, 0.0, -1.0))
    'N points straight down, along −z.'
    >>> s = 1 / math.sqrt(3)
    >>> direction_words((s, s, s))
    'N points towards +x, towards +y and up: equally +x, +y and +z, 55° from each axis.'
    >>> direction_words((0.2, 0.0, 0.9797958971132712))
    'N points up and a little towards +x: mostly +z, 12° from the z axis.'
    """
    n = [float(x) for x in unit_normal]
    size = [abs(x) for x in n]
    signed = [_signed(i, n[i] < 0) for i in range(3)]
    order = sorted(range(3), key=lambda i: -size[i])  # stable: x, y, z among equals
    first = order[0]
    if size[order[1]] == 0 and size[order[2]] == 0:
        return f"N points straight {_word(first, n[first] < 0)}, along {signed[first]}."
    words = [
        ("a little " if size[i] < A_LITTLE else "") + _word(i, n[i] < 0)
        for i in order
        if size[i] >= MENTION
    ]
    tied = [i for i in range(3) if size[i] == size[first]]
    rest = [size[i] for i in range(3) if i != first]
    angle = math.atan2(math.sqrt(rest[0] * rest[0] + rest[1] * rest[1]), size[first])
    degrees = _degrees(angle * (180 / math.pi))
    if len(tied) == 1:
        lead = f"mostly {signed[first]}, {degrees}° from the {_AXES[first]} axis"
    elif len(tied) == 2:
        axes = _join([_AXES[i] for i in tied])
        lead = f"equally {_join([signed[i] for i in tied])}, {degrees}° from the {axes} axes"
    else:
        lead = f"equally {_join(signed)}, {degrees}° from each axis"
    return f"N points {_join(words)}: {lead}."


def viewer_words(unit_normal: Sequence[float], order: str, viewer: Sequence[float] | None) -> str:
    """Say which side of the triangle the viewer sees and which way the order turns for them.

    Parameters
    ----------
    unit_normal : sequence of 3 float
        N / |N|.
    order : str
        The order of the vertices with arrows, ``"A→B→C"`` or ``"A→C→B"``.
    viewer : sequence of 3 float or None
        The direction from the triangle towards the viewer (any length); ``None``: no
        viewer, say what is seen from the front.

    Returns
    -------
    str
        One sentence.

    Examples
    --------
    >>> viewer_words((0, 0, 1), "A→C→B", (1, 0, 0.01))
    'You see the triangle edge-on: neither side faces you.'
    >>> viewer_words((0, 0, 1), "A→B→C", None)
    'From its front (the side N points to), A→B→C turns counter-clockwise.'
    """
    v = None if viewer is None else [float(x) for x in viewer]
    length = 0.0 if v is None else math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if v is None or not length > 0 or not math.isfinite(length):
        return f"From its front (the side N points to), {order} turns counter-clockwise."
    n = [float(x) for x in unit_normal]
    cos = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / length
    if abs(cos) < EDGE_ON:
        return "You see the triangle edge-on: neither side faces you."
    if cos > 0:
        side, turn = "front of the triangle (N points towards you)", "counter-clockwise"
    else:
        side, turn = "back of the triangle (N points away from you)", "clockwise"
    return f"You see the {side}, and {order} turns {turn}."


def describe(result: TriangleNormal, viewer: Sequence[float] | None = None) -> str:
    """Describe a triangle's normal as the explorer's view says it, in one line.

    Parameters
    ----------
    result : TriangleNormal
        The triangle (``triangle_normal(a, b, c, winding=...)``).
    viewer : sequence of 3 float, optional
        The direction from the triangle towards the viewer (the camera). Without it the
        description says what is seen from the triangle's front.

    Returns
    -------
    str
        Which way N points (`direction_words`) and what the viewer sees
        (`viewer_words`); for a degenerate triangle the core's status and that there
        is no front or back.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> describe(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 1), winding="ACB"), viewer=(0, 0, 1))
    'N points towards +y and down: equally +y and −z, 45° from the y and z axes. You see the back of the triangle (N points away from you), and A→C→B turns clockwise.'
    >>> describe(triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2)))
    'Degenerate: A, B and C are collinear (they lie on one line), so the area is zero. No unit normal exists. No direction to describe: the triangle has no front or back.'
    """  # noqa: E501
    if result.degenerate or result.unit_normal is None:
        status = result.format(0)["status"]
        return f"{status} No direction to describe: the triangle has no front or back."
    n = result.unit_normal
    return f"{direction_words(n)} {viewer_words(n, result.winding.label, viewer)}"
