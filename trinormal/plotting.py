"""Figures for the notebooks and the site: one palette, fixed sizes, opaque backgrounds.

The palette is Okabe and Ito's, safe for the common forms of colour blindness.
Every helper returns a :class:`matplotlib.figure.Figure` with a white
background (legible on the site's dark theme too) and a short text alternative
in ``fig.alt_text``.
"""

from __future__ import annotations

import io
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["AXIS_COLORS", "FACECOLOR", "PALETTE", "show"]

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


def show(fig: Figure, alt: str | None = None) -> None:
    """Display ``fig`` in a notebook as a PNG with a text alternative, then close it.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure to show.
    alt : str, optional
        The text alternative; defaults to ``fig.alt_text`` when a helper set it.

    Notes
    -----
    Displaying explicitly (instead of ending a cell with ``fig``) shows the image
    once, stores no ``<Figure size ...>`` text, and gives screen readers and the
    rendered site an ``alt`` attribute.
    """
    import matplotlib.pyplot as plt
    from IPython.display import Image, display

    text = alt if alt is not None else getattr(fig, "alt_text", "")
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, facecolor=fig.get_facecolor())
    plt.close(fig)
    display(Image(data=buf.getvalue(), format="png", alt=text))
