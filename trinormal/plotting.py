"""Figures for the notebooks and the site: one palette, fixed sizes, opaque backgrounds.

The palette is Okabe and Ito's, safe for the common forms of colour blindness.
Every helper returns a :class:`matplotlib.figure.Figure` with a white
background (legible on the site's dark theme too) and a short text alternative
in ``fig.alt_text``.
"""

from __future__ import annotations

__all__ = ["AXIS_COLORS", "FACECOLOR", "PALETTE"]

#: Okabe–Ito colour-blind-safe palette.
PALETTE: dict[str, str] = {
    "orange": "#E69F00",
    "sky": "#56B4E9",
    "green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "purple": "#CC79A7",
    "black": "#000000",
}

#: Colours for the x, y and z components, used by every chart.
AXIS_COLORS: tuple[str, str, str] = (PALETTE["vermillion"], PALETTE["green"], PALETTE["blue"])

#: Figure background: opaque white, never transparent.
FACECOLOR = "white"
