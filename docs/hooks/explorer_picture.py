"""The explorer's picture for pages with no live view, and its text alternative.

``assets/images/explorer.png`` is drawn by :class:`trinormal.widgets.Explorer`; its alt text
is the package's own description of the same triangle.
"""

from __future__ import annotations

import html
from typing import Any

from site_paths import EXPLORER_PNG

#: The triangle the picture shows: tilted, so that the normal leans out of every axis plane.
PICTURE: dict[str, Any] = {"a": (0, 0, 0), "b": (2, 0, 0), "c": (0, 1, 1), "precision": 4}


def explorer_png() -> bytes:
    """The explorer's figure for :data:`PICTURE`, drawn by the package (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    from trinormal.widgets import Explorer

    return bytes(Explorer(**PICTURE).to_png())


def explorer_alt() -> str:
    """The package's description of that figure, as ``Explorer.alt_text`` gives it."""
    from trinormal import triangle_normal
    from trinormal.explorer.readout import alt_text

    result = triangle_normal(PICTURE["a"], PICTURE["b"], PICTURE["c"])
    return str(alt_text(result, PICTURE["precision"]))


def explorer_img() -> str:
    """The picture as HTML on a notebook's page, in the place of a widget."""
    return (
        f'<p><img src="../../{EXPLORER_PNG}" alt="{html.escape(explorer_alt())}" '
        'width="720" loading="lazy"></p>'
    )
