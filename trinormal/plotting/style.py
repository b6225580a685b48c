"""How every figure looks and is shown: the palette, the sizes, `STYLE` and `show`."""

from __future__ import annotations

import functools
import io
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

from trinormal._optional import require
from trinormal.colors import ROLE_COLORS

require("trinormal.plotting", "matplotlib", "numpy")

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Okabe–Ito colour-blind-safe palette (for series that are not one of the roles).
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

#: Colours for the x, y and z components: the roles ``x``, ``y``, ``z`` of `trinormal.colors`.
AXIS_COLORS: tuple[str, str, str] = (ROLE_COLORS["x"], ROLE_COLORS["y"], ROLE_COLORS["z"])

#: The colour of a lit surface in the shading figures: a warm grey, so that the role colours
#: keep their meaning (sky blue is the ``back`` of a face, yellow its ``front``).
SURFACE = "#A0988A"

#: Figure background: opaque white, never transparent.
FACECOLOR = "white"
#: Behind the meshes of `winding_figure`: a culled gap shows as this slate colour, which no
#: shade of the (warm grey) surface takes, rather than as white, which the lit surface reaches.
BACKDROP = "#7f93a8"

#: Pixels per inch of figure at the size a figure is shown.
DISPLAY_DPI = 100
#: Pixels per inch stored in the PNG: twice the shown size, sharp on high-DPI screens.
SAVE_DPI = 200

#: Matplotlib settings for every figure: text of 12 pt or more, lines of 1.5 px or more.
STYLE: dict[str, Any] = {
    "font.size": 13,
    "axes.titlesize": 14,
    "axes.labelsize": 13,
    "xtick.labelsize": 12,
    "ytick.labelsize": 12,
    "legend.fontsize": 12,
    "legend.title_fontsize": 12,
    "figure.titlesize": 15,
    "lines.linewidth": 2.0,
    "axes.linewidth": 1.2,
    "xtick.major.width": 1.2,
    "ytick.major.width": 1.2,
}

F = TypeVar("F", bound=Callable[..., Any])


def styled(fn: F) -> F:
    """Build the figure under `STYLE` (a decorator for every figure helper)."""

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        import matplotlib

        with matplotlib.rc_context(STYLE):  # type: ignore[arg-type]
            return fn(*args, **kwargs)

    return wrapper  # type: ignore[return-value]


def show(fig: Figure, alt: str | None = None) -> None:
    """Display ``fig`` in a notebook as a sharp PNG with a text alternative, then close it.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure to show.
    alt : str, optional
        The text alternative; defaults to ``fig.alt_text`` when a helper set it.

    Notes
    -----
    The PNG is stored at `SAVE_DPI` and shown `DISPLAY_DPI` pixels
    per inch of figure wide, so a 12 pt label is 12 pt on screen and every
    pixel of the picture is two pixels of a high-DPI screen. Displaying
    explicitly (instead of ending a cell with ``fig``) shows the image once,
    stores no ``<Figure size ...>`` text, and gives screen readers and the
    rendered site an ``alt`` attribute.
    """
    import matplotlib.pyplot as plt
    from IPython.display import Image, display

    text = alt if alt is not None else getattr(fig, "alt_text", "")
    if not text:
        raise ValueError("every figure needs a text alternative: pass alt=")
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=SAVE_DPI, facecolor=fig.get_facecolor())
    width = round(fig.get_figwidth() * DISPLAY_DPI)
    plt.close(fig)
    display(Image(data=buf.getvalue(), format="png", width=width, alt=text))  # type: ignore[no-untyped-call]
