"""Charts of numbers: vector components as bars, and direction errors against the sine."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from trinormal.plotting.style import AXIS_COLORS, FACECOLOR, PALETTE, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["component_bar_chart", "precision_error_figure"]


@styled
def component_bar_chart(
    vectors: Mapping[str, Sequence[Any]] | Sequence[Any],
    *,
    title: str = "Components",
    ylabel: str = "value",
) -> Figure:
    """Draw the x, y and z components of one or more vectors as grouped bars.

    Parameters
    ----------
    vectors : mapping of label to 3 numbers, or 3 numbers
        The vectors, such as ``{"N (ABC)": r.normal, "N (ACB)": s.normal}``.
    title, ylabel : str
        Labels for the chart.

    Returns
    -------
    matplotlib.figure.Figure
        7 × 4.2 inches, white, one colour per axis, each bar labelled with its
        value, and ``fig.alt_text`` listing the values.

    Examples
    --------
    >>> fig = component_bar_chart({"N": (0, -1, 1)}, title="Raw normal")
    >>> fig.alt_text
    'Bar chart, Raw normal. N: x = 0, y = -1, z = 1.'
    """
    from matplotlib.figure import Figure

    from trinormal.display import format_number

    groups = dict(vectors) if isinstance(vectors, Mapping) else {"": vectors}
    fig = Figure(figsize=(7, 4.2), facecolor=FACECOLOR)
    ax = fig.add_subplot()
    ax.set_facecolor(FACECOLOR)
    width = 0.8 / 3
    described = []
    for g, (label, vec) in enumerate(groups.items()):
        values = [float(x) for x in vec]
        if len(values) != 3:
            raise ValueError(f"{label or 'the vector'} has {len(values)} components, expected 3")
        texts = [format_number(x, 4, trim=True) for x in vec]
        for i in range(3):
            x = g + (i - 1) * width
            ax.bar(x, values[i], width, color=AXIS_COLORS[i], label="xyz"[i] if g == 0 else None)
            ax.annotate(
                texts[i],
                (x, values[i]),
                ha="center",
                va="bottom" if values[i] >= 0 else "top",
                fontsize=12,
                xytext=(0, 2 if values[i] >= 0 else -2),
                textcoords="offset points",
            )
        parts = ", ".join(f"{'xyz'[i]} = {texts[i]}" for i in range(3))
        described.append(f"{label}: {parts}" if label else parts)
    ax.axhline(0, color=PALETTE["black"], linewidth=1.5)
    ax.set_xticks(range(len(groups)), [str(k) for k in groups])
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.margins(y=0.2)
    ax.legend(title="component", loc="best")
    fig.alt_text = f"Bar chart, {title}. " + "; ".join(described) + "."  # type: ignore[attr-defined]
    return fig


@styled
def precision_error_figure(
    sines: Mapping[str, Any],
    errors: Mapping[str, Any],
    *,
    tol: float | None = None,
    title: str = "Direction error of the unit normal",
) -> Figure:
    """Plot direction errors (radians) against the sine of the edge angle, log-log.

    Parameters
    ----------
    sines, errors : mapping of label to array, shape (n,)
        For each series (such as ``"float32"``), the exact sine of each
        triangle and the angle between its computed and exact unit normals.
        Zero errors are drawn at the bottom of the axis.
    tol : float, optional
        Draw a dashed vertical line at sine = ``tol``. The degeneracy rule is on
        |N| / L² (L the longest side), which is the sine at A times two side
        ratios of at most 1: for needles whose longest side starts at A the line
        marks the threshold within those ratios.
    title : str
        The figure title.

    Returns
    -------
    matplotlib.figure.Figure
        The chart, with ``fig.alt_text`` set.
    """
    import matplotlib.pyplot as plt
    import numpy as np

    from trinormal.display import format_number

    fig, ax = plt.subplots(figsize=(8, 5), facecolor=FACECOLOR)
    ax.set_facecolor(FACECOLOR)
    colors = [PALETTE["vermillion"], PALETTE["blue"], PALETTE["green"], PALETTE["purple"]]
    floor = 1e-18
    for (label, s), color in zip(sines.items(), colors, strict=False):
        e = np.maximum(np.asarray(errors[label], dtype=float), floor)
        ax.scatter(np.asarray(s, dtype=float), e, s=18, color=color, label=label, alpha=0.8)
    if tol is not None:
        ax.axvline(
            tol,
            color=PALETTE["black"],
            linestyle="--",
            linewidth=2,
            label=f"tol = {format_number(tol, 0)}",
        )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("sine of the angle between the edges (1: right angle, 0: a line)")
    ax.set_ylabel("direction error (radians)")
    ax.set_title(title)
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Log-log scatter plot, {title}: the error of each precision grows as the sine "
        "shrinks, roughly as unit roundoff divided by the sine."
    )
    return fig
