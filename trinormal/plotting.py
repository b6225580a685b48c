"""Figures for the notebooks and the site: one palette, fixed sizes, opaque backgrounds.

The palette is Okabe and Ito's, safe for the common forms of colour blindness.
Every helper returns a :class:`matplotlib.figure.Figure` with a white
background (legible on the site's dark theme too) and a short text alternative
in ``fig.alt_text``.
"""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "AXIS_COLORS",
    "FACECOLOR",
    "PALETTE",
    "component_bar_chart",
    "precision_error_figure",
    "right_hand_rule_figure",
    "shaded_mesh_figure",
    "show",
]

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
    display(Image(data=buf.getvalue(), format="png", alt=text))  # type: ignore[no-untyped-call]


# --------------------------------------------------------------------------- right-hand rule, bars


def _fmt_vec(xs: Any) -> str:
    from trinormal.display import format_vector

    return format_vector(xs, 4, trim=True)


def right_hand_rule_figure(
    a: Sequence[Any],
    b: Sequence[Any],
    c: Sequence[Any],
    winding: str = "ABC",
    *,
    title: str | None = None,
) -> Figure:
    """Draw a triangle in 3D with its edges U, V and its normal N, on equal axis scales.

    U and V start at A; a curved arrow turns from U towards V, the way the
    fingers of a right hand curl, and N (drawn from the centroid, with the
    length of the mean edge so it stays on screen) points where the thumb does.

    Parameters
    ----------
    a, b, c : sequence of 3 numbers
        The vertices (anything :func:`trinormal.triangle_normal` reads).
    winding : {"ABC", "ACB"}, default "ABC"
        Which edge is U and which is V.
    title : str, optional
        Figure title; by default the winding and N.

    Returns
    -------
    matplotlib.figure.Figure
        6 × 5.5 inches, white, with ``fig.alt_text`` describing it.

    Examples
    --------
    >>> fig = right_hand_rule_figure((0, 0, 0), (1, 0, 0), (0, 1, 0))
    >>> fig.alt_text.split(". ")[1]
    'The normal N = (0, 0, 1) points along +z.'
    """
    import math

    import mpl_toolkits.mplot3d  # noqa: F401  (registers the 3d projection)
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from trinormal.core import triangle_normal

    r = triangle_normal(a, b, c, winding=winding)
    A, B, C = r.a, r.b, r.c
    u, v = r.u, r.v
    first, second = ("B", "C") if r.winding.value == "ABC" else ("C", "B")
    fig = Figure(figsize=(6, 5.5), facecolor=FACECOLOR)
    ax = fig.add_subplot(projection="3d")
    ax.set_facecolor(FACECOLOR)
    ax.add_collection3d(
        Poly3DCollection(
            [[A, B, C]], facecolor=PALETTE["sky"], edgecolor=PALETTE["black"], alpha=0.35
        )
    )
    for name, p in zip("ABC", (A, B, C), strict=True):
        ax.text(*p, f" {name}", color=PALETTE["black"], fontsize=12, fontweight="bold")
    colors = {"U": PALETTE["orange"], "V": PALETTE["purple"], "N": PALETTE["blue"]}
    for name, vec in (("U", u), ("V", v)):
        ax.quiver(*A, *vec, color=colors[name], linewidth=2.5, arrow_length_ratio=0.12)
        mid = [A[i] + 0.6 * vec[i] for i in range(3)]
        ax.text(*mid, f"  {name}", color=colors[name], fontsize=12, fontweight="bold")
    pts: list[Sequence[float]] = [A, B, C]
    lengths = [math.dist(p, q) for p, q in ((A, B), (A, C), (B, C))]
    scale = sum(lengths) / 3 or 1.0
    centroid = [sum(p[i] for p in pts) / 3 for i in range(3)]
    direction = "is zero, so it has no direction: the triangle is degenerate"
    unit = r.unit_normal
    if unit is not None:
        n = [x * scale for x in unit]
        ax.quiver(*centroid, *n, color=colors["N"], linewidth=3, arrow_length_ratio=0.15)
        tip = [centroid[i] + n[i] for i in range(3)]
        ax.text(*tip, "  N", color=colors["N"], fontsize=13, fontweight="bold")
        pts.append(tuple(tip))
        # the curl from U towards V, a quarter of the way along each edge
        lu = math.hypot(*u)
        uh = [x / lu for x in u]
        dot = sum(v[i] * uh[i] for i in range(3))
        w = [v[i] - dot * uh[i] for i in range(3)]
        lw = math.hypot(*w)
        wh = [x / lw for x in w]
        angle = math.atan2(lw, dot)
        rho = 0.3 * min(lu, math.hypot(*v))
        ts = [angle * k / 40 for k in range(41)]
        arc = [
            [A[i] + rho * (math.cos(t) * uh[i] + math.sin(t) * wh[i]) for t in ts] for i in range(3)
        ]
        ax.plot(*arc, color=PALETTE["black"], linewidth=1.5)
        end = [arc[i][-1] for i in range(3)]
        prev = [arc[i][-4] for i in range(3)]
        ax.quiver(
            *prev,
            *(end[i] - prev[i] for i in range(3)),
            color=PALETTE["black"],
            arrow_length_ratio=1.0,
            linewidth=1.5,
        )
        direction = f"has the unit direction {r.format(4, trim=True)['unit_normal']}"
        if sorted(abs(x) for x in unit) == [0.0, 0.0, 1.0]:
            axis = max(range(3), key=lambda i: abs(unit[i]))
            sign = "+" if unit[axis] > 0 else "-"
            direction = f"points along {sign}{'xyz'[axis]}"
    # equal scales: a cube around everything drawn
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    half = max(h - low for h, low in zip(hi, lo, strict=True)) / 2 or 1.0
    for i, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        centre = (lo[i] + hi[i]) / 2
        setter(centre - half * 1.1, centre + half * 1.1)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.view_init(elev=25, azim=-60)
    normal = _fmt_vec(r.exact.normal)
    ax.set_title(title if title is not None else f"Winding {r.winding.label}: N = {normal}")
    fig.alt_text = (  # type: ignore[attr-defined]
        f"3D view of the triangle A = {_fmt_vec(r.exact.a)}, B = {_fmt_vec(r.exact.b)}, "
        f"C = {_fmt_vec(r.exact.c)} with U = {first} − A and V = {second} − A drawn from A "
        f"and a curved arrow turning from U to V. The normal N = {normal} {direction}."
    )
    return fig


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
        6 × 3.5 inches, white, one colour per axis, each bar labelled with its
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
    fig = Figure(figsize=(6, 3.5), facecolor=FACECOLOR)
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
                fontsize=9,
                xytext=(0, 2 if values[i] >= 0 else -2),
                textcoords="offset points",
            )
        parts = ", ".join(f"{'xyz'[i]} = {texts[i]}" for i in range(3))
        described.append(f"{label}: {parts}" if label else parts)
    ax.axhline(0, color=PALETTE["black"], linewidth=0.8)
    ax.set_xticks(range(len(groups)), [str(k) for k in groups])
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.margins(y=0.2)
    ax.legend(title="component", loc="best", fontsize=9)
    fig.alt_text = f"Bar chart, {title}. " + "; ".join(described) + "."  # type: ignore[attr-defined]
    return fig


# ------------------------------------------------------------------ mesh notebooks (06, 07)


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
        Draw the degeneracy threshold as a vertical line.
    title : str
        The figure title.

    Returns
    -------
    matplotlib.figure.Figure
        The chart, with ``fig.alt_text`` set.
    """
    import matplotlib.pyplot as plt
    import numpy as np

    fig, ax = plt.subplots(figsize=(7, 4.2), facecolor=FACECOLOR)
    ax.set_facecolor(FACECOLOR)
    colors = [PALETTE["vermillion"], PALETTE["blue"], PALETTE["green"], PALETTE["purple"]]
    floor = 1e-18
    for (label, s), color in zip(sines.items(), colors, strict=False):
        e = np.maximum(np.asarray(errors[label], dtype=float), floor)
        ax.scatter(np.asarray(s, dtype=float), e, s=10, color=color, label=label, alpha=0.8)
    if tol is not None:
        ax.axvline(tol, color=PALETTE["black"], linestyle="--", linewidth=1, label=f"tol = {tol:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("sine of the angle between the edges (1 = right angle, 0 = a line)")
    ax.set_ylabel("direction error (radians)")
    ax.set_title(title)
    ax.legend(loc="upper right", fontsize=9)
    fig.tight_layout()
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Log-log scatter plot, {title}: the error of each precision grows as the sine "
        "shrinks, roughly as unit roundoff divided by the sine."
    )
    return fig


def shaded_mesh_figure(
    vertices: Any,
    faces: Any,
    panels: Mapping[str, Any],
    *,
    elev: float = 25.0,
    azim: float = -60.0,
    title: str | None = None,
) -> Figure:
    """Draw one mesh several times side by side, each face filled with a brightness.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates.
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.
    panels : mapping of title to array_like, shape (F,)
        For each panel, the brightness of every face, from 0 (black) to 1 (lit);
        NaN marks a face that is not drawn (culled).
    elev, azim : float
        The camera's elevation and azimuth in degrees (matplotlib's convention).
    title : str, optional
        A title over all the panels.

    Returns
    -------
    matplotlib.figure.Figure
        The panels, with ``fig.alt_text`` set.
    """
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.colors import LinearSegmentedColormap
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    cmap = LinearSegmentedColormap.from_list("lit", ["#101010", PALETTE["sky"], "#ffffff"])
    n = len(panels)
    fig = plt.figure(figsize=(3.6 * n, 3.8), facecolor=FACECOLOR)
    lo, hi = v.min(axis=0), v.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    described = []
    for k, (name, values) in enumerate(panels.items()):
        ax = fig.add_subplot(1, n, k + 1, projection="3d")
        ax.set_facecolor(FACECOLOR)
        b = np.asarray(values, dtype=float)
        keep = ~np.isnan(b)
        colors = cmap(np.clip(b[keep], 0, 1))
        poly = Poly3DCollection(v[f[keep]], facecolors=colors, edgecolors="none")
        ax.add_collection3d(poly)
        for setlim, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid, strict=True):
            setlim(m - half, m + half)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(name, fontsize=10)
        drawn = int(keep.sum())
        described.append(f"{name} ({drawn} of {len(b)} faces drawn)")
    if title:
        fig.suptitle(title)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.88 if title else 0.95, wspace=0)
    fig.alt_text = "Shaded renderings of a mesh: " + "; ".join(described) + "."  # type: ignore[attr-defined]
    return fig
