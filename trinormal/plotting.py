"""Figures for the notebooks and the site: one colour code, legible from the back of a room.

Every helper returns a `matplotlib.figure.Figure` with an opaque white
background and a short text alternative in ``fig.alt_text``. The colours are
the roles of [`trinormal.colors`][trinormal.colors] (A, B, C, U, V, N, front and back faces,
the x, y and z axes), the same code the 3D explorer and the site use. Text is
at least 12 pt and lines at least 1.5 px at the size [`show`][trinormal.plotting.show] displays a
figure (100 pixels per inch of figure), and [`show`][trinormal.plotting.show] stores the picture at
twice that resolution for high-DPI screens and projectors.
"""

from __future__ import annotations

import functools
import io
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeVar

from trinormal._optional import require
from trinormal.colors import ROLE_COLORS

require(__name__, "matplotlib", "numpy")

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "AXIS_COLORS",
    "DISPLAY_DPI",
    "FACECOLOR",
    "PALETTE",
    "SAVE_DPI",
    "STYLE",
    "SURFACE",
    "component_bar_chart",
    "culling_figure",
    "normal_transform_figure",
    "precision_error_figure",
    "right_hand_rule_figure",
    "shaded_mesh_figure",
    "shading_figure",
    "show",
    "winding_figure",
]

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


def _styled(fn: F) -> F:
    """Build the figure under `STYLE`."""

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


# --------------------------------------------------------------------------- right-hand rule, bars


def _fmt_vec(xs: Any) -> str:
    from trinormal.display import format_vector

    return format_vector(xs, 4, trim=True)


@_styled
def right_hand_rule_figure(
    a: Sequence[Any],
    b: Sequence[Any],
    c: Sequence[Any],
    winding: str = "ABC",
    *,
    title: str | None = None,
) -> Figure:
    """Draw a triangle in 3D with its edges U, V and its normal N, on equal axis scales.

    U and V start at A; a curved arrow (in N's colour, as in the explorer)
    turns from U towards V, the way the fingers of a right hand curl, with a
    large filled head near V, and N (drawn from the centroid) points where the
    thumb does. N is drawn at its true length when that is between 0.4 and 1.5
    times the mean edge; otherwise it is scaled by a power of two and labelled
    so (``N/4``, ``2N``), and the alt text says which.
    The face is filled in the ``front`` colour when the camera sees the side N
    points out of, and in the ``back`` colour when it sees the other side. The
    axes are the same for both windings of the same points, so the two
    pictures differ only in what the winding changes.

    Parameters
    ----------
    a, b, c : sequence of 3 numbers
        The vertices (anything [`trinormal.triangle_normal`][trinormal.core.triangle_normal] reads).
    winding : {"ABC", "ACB"}, default "ABC"
        Which edge is U and which is V.
    title : str, optional
        Figure title; by default the winding and N.

    Returns
    -------
    matplotlib.figure.Figure
        6.5 × 6 inches, white, with ``fig.alt_text`` describing it.

    Examples
    --------
    >>> fig = right_hand_rule_figure((0, 0, 0), (1, 0, 0), (0, 1, 0))
    >>> fig.alt_text.split(". ")[1]
    'The normal N = (0, 0, 1) points along +z; the camera sees the front of the face (yellow)'
    >>> fig.alt_text.endswith("N is drawn at its true length.")
    True
    >>> right_hand_rule_figure((0, 0, 0), (1, 0, 0), (0, 1, 0), "ACB").alt_text.split(". ")[1]
    'The normal N = (0, 0, -1) points along -z; the camera sees the back of the face (sky blue)'
    """
    import math

    import mpl_toolkits.mplot3d  # noqa: F401  (registers the 3d projection)
    from matplotlib.figure import Figure
    from matplotlib.ticker import MaxNLocator
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from trinormal.core import triangle_normal

    r = triangle_normal(a, b, c, winding=winding)
    A, B, C = r.a, r.b, r.c
    u, v = r.u, r.v
    first, second = ("B", "C") if r.winding.value == "ABC" else ("C", "B")
    elev, azim = 25.0, -60.0
    fig = Figure(figsize=(6.5, 6), facecolor=FACECOLOR)
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False  # draw in the order added: the face first, labels on top
    ax.set_facecolor(FACECOLOR)
    eye = camera_direction(elev, azim)
    unit = r.unit_normal
    seen = "front" if unit is None or sum(unit[i] * eye[i] for i in range(3)) > 0 else "back"
    ax.add_collection3d(
        Poly3DCollection(
            [[A, B, C]], facecolor=ROLE_COLORS[seen], edgecolor=PALETTE["black"], alpha=0.5
        )
    )
    for name, p in zip("ABC", (A, B, C), strict=True):
        ax.text(*p, f" {name}", color=ROLE_COLORS[name], fontsize=14, fontweight="bold")
    colors = {k: ROLE_COLORS[k] for k in "UVN"}
    pts: list[Sequence[float]] = [A, B, C]
    centroid = [sum(p[i] for p in pts) / 3 for i in range(3)]
    lengths = [math.dist(p, q) for p, q in ((A, B), (A, C), (B, C))]
    scale = 0.75 * (sum(lengths) / 3) or 1.0
    for name, vec in (("U", u), ("V", v)):
        ax.quiver(*A, *vec, color=colors[name], linewidth=2.5, arrow_length_ratio=0.12)
        # the label sits beside the head of its arrow, outside the face
        mid = [A[i] + 0.8 * vec[i] for i in range(3)]
        out = [mid[i] - centroid[i] for i in range(3)]
        ee = sum(x * x for x in vec) or 1.0
        along = sum(out[i] * vec[i] for i in range(3)) / ee
        perp = [out[i] - along * vec[i] for i in range(3)]
        size = math.hypot(*perp) or 1.0
        away = [mid[i] + 0.2 * scale * perp[i] / size for i in range(3)]
        ax.text(*away, name, color=colors[name], fontsize=14, fontweight="bold", ha="center")
    direction = "is zero, so it has no direction: the triangle is degenerate"
    drawn = ""
    if unit is not None:
        # N at its true length when that fits the picture; otherwise scaled by a power of two,
        # and the label says by how much (N/4, 2N), as in the explorer
        length_n = math.sqrt(float(r.exact.magnitude_squared))
        mean_edge = sum(lengths) / 3 or 1.0
        factor = 1.0
        if not 0.4 * mean_edge <= length_n <= 1.5 * mean_edge:
            factor = 2.0 ** round(math.log2(scale / length_n))
        n = [x * length_n * factor for x in unit]
        if factor == 1.0:
            label, drawn = "N", "N is drawn at its true length"
        elif factor < 1.0:
            label = f"N/{round(1 / factor)}"
            drawn = f"N is drawn at 1/{round(1 / factor)} of its length (labelled {label})"
        else:
            label = f"{round(factor)}N"
            drawn = f"N is drawn {round(factor)} times longer than it is (labelled {label})"
        ax.quiver(*centroid, *n, color=colors["N"], linewidth=3, arrow_length_ratio=0.15)
        tip = [centroid[i] + n[i] for i in range(3)]
        ax.text(*tip, "  " + label, color=colors["N"], fontsize=15, fontweight="bold")
        # both ends, so the other winding of the same points gets the same axes
        pts += [tuple(tip), tuple(centroid[i] - n[i] for i in range(3))]
        # the curl from U towards V around A, ending in a large filled arrowhead near V
        lu = math.hypot(*u)
        uh = [x / lu for x in u]
        dot = sum(v[i] * uh[i] for i in range(3))
        w = [v[i] - dot * uh[i] for i in range(3)]
        lw = math.hypot(*w)
        wh = [x / lw for x in w]
        angle = math.atan2(lw, dot)
        rho = 0.34 * min(lu, math.hypot(*v))

        def on_arc(t: float, radius: float = rho) -> list[float]:
            return [A[i] + radius * (math.cos(t) * uh[i] + math.sin(t) * wh[i]) for i in range(3)]

        head = 0.8 * rho  # arrowhead length, along the arc
        t_tip = 0.9 * angle
        t_base = max(t_tip - head / rho, 0.25 * t_tip)
        ts = [t_base * k / 40 for k in range(41)]
        arc = [[on_arc(t)[i] for t in ts] for i in range(3)]
        ax.plot(*arc, color=colors["N"], linewidth=3.5)
        outer, inner = on_arc(t_base, rho + 0.38 * head), on_arc(t_base, rho - 0.38 * head)
        ax.add_collection3d(
            Poly3DCollection(
                [[on_arc(t_tip), outer, inner]],
                facecolor=colors["N"],
                edgecolor=colors["N"],
                linewidth=1.5,
            )
        )
        fig.curl_head = (tuple(on_arc(t_base)), tuple(on_arc(t_tip)))  # type: ignore[attr-defined]
        direction = f"has the unit direction {r.format(4, trim=True)['unit_normal']}"
        if sorted(abs(x) for x in unit) == [0.0, 0.0, 1.0]:
            axis = max(range(3), key=lambda i: abs(unit[i]))
            sign = "+" if unit[axis] > 0 else "-"
            direction = f"points along {sign}{'xyz'[axis]}"
        colour = "yellow" if seen == "front" else "sky blue"
        direction += f"; the camera sees the {seen} of the face ({colour})"
    # equal scales: a cube around everything drawn
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    half = max(h - low for h, low in zip(hi, lo, strict=True)) / 2 or 1.0
    for i, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        centre = (lo[i] + hi[i]) / 2
        setter(centre - half * 1.1, centre + half * 1.1)
    ax.set_box_aspect((1, 1, 1))
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):  # few ticks, so 12 pt labels never overlap
        axis.set_major_locator(MaxNLocator(nbins=4))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.view_init(elev=elev, azim=azim)
    normal = _fmt_vec(r.exact.normal)
    ax.set_title(title if title is not None else f"Winding {r.winding.label}: N = {normal}")
    fig.alt_text = (  # type: ignore[attr-defined]
        f"3D view of the triangle A = {_fmt_vec(r.exact.a)}, B = {_fmt_vec(r.exact.b)}, "
        f"C = {_fmt_vec(r.exact.c)} with U = {first} − A and V = {second} − A drawn from A "
        f"and a curved arrow turning from U to V. The normal N = {normal} {direction}."
        + (f" {drawn}." if drawn else "")
    )
    return fig


@_styled
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


# ------------------------------------------------------------------ mesh notebooks (06, 07)


@_styled
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


@_styled
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
    cmap = LinearSegmentedColormap.from_list("lit", ["#101010", SURFACE, "#ffffff"])
    from trinormal import mesh

    facing = mesh.face_normals(v, f) @ camera_direction(elev, azim) > 0
    n = len(panels)
    fig = plt.figure(figsize=(4 * n, 4.2), facecolor=FACECOLOR)
    lo, hi = v.min(axis=0), v.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    described = []
    for k, (name, values) in enumerate(panels.items()):
        ax = fig.add_subplot(1, n, k + 1, projection="3d")
        ax.set_facecolor(FACECOLOR)
        b = np.asarray(values, dtype=float)
        keep = ~np.isnan(b)
        colors = cmap(np.clip(b[keep], 0, 1))
        # each face's edge is stroked in its own colour to close the seams between faces; not
        # for faces turned away from the camera, which (drawn first) would line the seams
        edges = colors.copy()
        edges[~facing[keep]] = 0.0
        poly = Poly3DCollection(v[f[keep]], facecolors=colors, edgecolors=edges, linewidths=0.4)
        ax.add_collection3d(poly)
        for setlim, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid, strict=True):
            setlim(m - half, m + half)
        ax.set_box_aspect((1, 1, 1), zoom=1.5)  # the mesh fills its panel
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(name, fontsize=13)
        drawn = int(keep.sum())
        described.append(f"{name} ({drawn} of {len(b)} faces drawn)")
    if title:
        fig.suptitle(title)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.84 if title else 0.95, wspace=0)
    fig.alt_text = "Shaded renderings of a mesh: " + "; ".join(described) + "."  # type: ignore[attr-defined]
    return fig


# ------------------------------------------------------------- shading, culling, transforms


def camera_direction(elev: float, azim: float) -> Any:
    """Return the unit vector from the scene towards a far camera, in matplotlib's angles.

    Parameters
    ----------
    elev, azim : float
        Elevation and azimuth in degrees, as in ``Axes3D.view_init``.

    Returns
    -------
    ndarray, shape (3,)

    Examples
    --------
    >>> [round(float(x), 6) for x in camera_direction(90, 0)]
    [0.0, 0.0, 1.0]
    """
    import numpy as np

    e, a = np.radians(elev), np.radians(azim)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def _lit(brightness: Any, base: str = SURFACE) -> Any:
    """Colours from black (0) through ``base`` to white (1) for brightness values."""
    import numpy as np
    from matplotlib.colors import LinearSegmentedColormap

    cmap = LinearSegmentedColormap.from_list("lit", ["#101010", base, "#ffffff"])
    return cmap(np.clip(np.asarray(brightness, dtype=float), 0, 1))


def _cube_limits(ax: Any, points: Any) -> None:
    import numpy as np

    lo, hi = points.min(axis=0), points.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    for setlim, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid, strict=True):
        setlim(m - half, m + half)
    ax.set_box_aspect((1, 1, 1))
    del np


def _subdivide(tri: Any, k: int) -> tuple[Any, Any]:
    """Split every triangle of ``tri`` (F, 3, 3) into k² small ones.

    Returns the small triangles (F·k², 3, 3) and the barycentric weights of
    each small triangle's centre (k², 3), the same for every face.
    """
    import numpy as np

    bary, centres = [], []
    for i in range(k):
        for j in range(k - i):
            corners = [(i, j), (i + 1, j), (i, j + 1)]
            bary.append(corners)
            if j < k - i - 1:
                bary.append([(i + 1, j), (i + 1, j + 1), (i, j + 1)])
    w = np.array([[[1 - (a + b) / k, a / k, b / k] for a, b in t] for t in bary])  # (k², 3, 3)
    centres = w.mean(axis=1)  # (k², 3)
    small = np.einsum("sci,fid->fscd", w, tri).reshape(-1, 3, 3)
    return small, centres


@_styled
def shading_figure(
    vertices: Any,
    faces: Any,
    light: Sequence[float],
    *,
    weighting: str = "angle",
    subdivisions: int = 8,
    elev: float = 20.0,
    azim: float = -50.0,
) -> Figure:
    """Flat and smooth Lambert shading of one closed mesh, side by side.

    Flat shading lights each triangle with its face normal, so every facet
    has one brightness. Smooth shading interpolates the vertex normals across
    each triangle (the way a renderer blends them between the corners), and
    here each triangle is cut into ``subdivisions²`` small pieces, each lit
    with the normalised blend of the corner normals at its centre.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
        A closed, outward-wound mesh (only faces turned towards the camera are drawn).
    light : sequence of 3 floats
        Direction towards the light (normalised here).
    weighting : {"angle", "area", "uniform"}
        How [`trinormal.mesh.vertex_normals`][trinormal.mesh.vertex_normals] averages the face
        normals.
    subdivisions : int
        How finely each triangle is cut for the smooth panel.
    elev, azim : float
        The camera, in matplotlib's angles (degrees).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels, with ``fig.alt_text`` set.
    """
    import matplotlib.pyplot as plt
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from trinormal import mesh

    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    lt = np.asarray(light, dtype=float)
    lt = lt / np.linalg.norm(lt)
    eye = camera_direction(elev, azim)
    fn = mesh.face_normals(v, f)
    vn = mesh.vertex_normals(v, f, weighting)
    seen = fn @ eye > 0
    tri = v[f[seen]]
    flat_polys, flat_b = tri, np.maximum(0.0, fn[seen] @ lt)
    small, centres = _subdivide(tri, subdivisions)
    blend = np.einsum("si,fid->fsd", centres, vn[f[seen]]).reshape(-1, 3)
    blend /= np.linalg.norm(blend, axis=1, keepdims=True)
    smooth_b = np.maximum(0.0, blend @ lt)
    fig = plt.figure(figsize=(9, 4.8), facecolor=FACECOLOR)
    panels = {
        "flat: one normal per face": (flat_polys, flat_b),
        "smooth: vertex normals blended": (small, smooth_b),
    }
    for k, (name, (polys, b)) in enumerate(panels.items()):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        ax.set_facecolor(FACECOLOR)
        lit = _lit(b)  # edges in the face colour: no seams between the small pieces
        ax.add_collection3d(Poly3DCollection(polys, facecolors=lit, edgecolors=lit, linewidths=0.4))
        _cube_limits(ax, v)
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(name)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.9, wspace=0)
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Two renderings of the same mesh of {len(f)} triangles under one light. Left, flat "
        "shading: every triangle has a single brightness, so the facets show as a mosaic. "
        f"Right, smooth shading with {weighting}-weighted vertex normals blended across each "
        "triangle: the brightness changes gradually and the facets disappear, although the "
        "outline is still the same polygon."
    )
    return fig


@_styled
def culling_figure(
    vertices: Any,
    faces: Any,
    *,
    camera: tuple[float, float] = (30.0, -90.0),
    side: tuple[float, float] = (30.0, 0.0),
) -> Figure:
    """Show what back-face culling removes: the camera's view, then the mesh from the side.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
        A closed, outward-wound mesh.
    camera : (elev, azim)
        The camera that decides front from back (matplotlib's angles, degrees).
    side : (elev, azim)
        A second camera, off to the side, that shows what was removed.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: the camera's view of the front faces; all faces from the
        side, front faces in the ``front`` colour and back faces in the ``back``
        colour of [`trinormal.colors`][trinormal.colors]; the front faces alone from the side.
    """
    import matplotlib.pyplot as plt
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from trinormal import mesh

    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    fn = mesh.face_normals(v, f)
    eye = camera_direction(*camera)
    front = fn @ eye > 0
    light = eye + np.array([0.0, 0.0, 0.6])
    light /= np.linalg.norm(light)
    shade = 0.55 + 0.45 * np.abs(fn @ light)
    from matplotlib.colors import to_rgb

    def colours(mask: Any) -> Any:
        base = np.where(
            mask[:, None], np.array(to_rgb(ROLE_COLORS["front"])), to_rgb(ROLE_COLORS["back"])
        )
        return np.clip(base * shade[:, None], 0, 1)

    all_colours = colours(front)
    panels = [
        ("the camera's view", front, camera),
        ("from the side:\nall faces", np.ones(len(f), bool), side),
        ("from the side:\nback faces culled", front, side),
    ]
    # 10 inches: shown 1000 pixels wide, it fits a notebook on a 1280-pixel projector unscaled
    fig = plt.figure(figsize=(10, 4.4), facecolor=FACECOLOR)
    for k, (name, keep, (el, az)) in enumerate(panels):
        ax = fig.add_subplot(1, 3, k + 1, projection="3d")
        ax.set_facecolor(FACECOLOR)
        ax.add_collection3d(
            Poly3DCollection(v[f[keep]], facecolors=all_colours[keep], edgecolors="none")
        )
        _cube_limits(ax, v)
        ax.set_box_aspect((1, 1, 1), zoom=1.4)  # the mesh fills its panel
        ax.view_init(elev=el, azim=az)
        ax.set_axis_off()
        ax.set_title(name)
    from matplotlib.patches import Patch

    fig.legend(
        handles=[
            Patch(color=ROLE_COLORS["front"], label="front face (towards the camera)"),
            Patch(color=ROLE_COLORS["back"], label="back face"),
        ],
        loc="lower center",
        ncol=2,
        frameon=False,
    )
    fig.subplots_adjust(left=0, right=1, bottom=0.1, top=0.9, wspace=0)
    n_front = int(front.sum())
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Three views of a mesh of {len(f)} triangles. First, the camera's view, which shows "
        f"only the {n_front} faces whose normals point towards it. Second, the same mesh from "
        "the side with every face drawn: the half facing the camera in yellow, the other half "
        "in blue. Third, the same side view after culling: the blue back half is gone, and "
        "the camera never saw it."
    )
    return fig


@_styled
def winding_figure(
    vertices: Any,
    faces: Any,
    *,
    elev: float = 29.0,
    azim: float = -47.0,
    title: str | None = None,
) -> Figure:
    """Show what a renderer does with faces wound the wrong way: lit black, or culled away.

    Two panels of the same mesh from the same camera. Left, every face lit by one
    light from behind the camera with one-sided Lambert shading, brightness
    ``max(0, n · l)`` from each face's unit normal ``n`` as stored: a face whose
    normal points away from the light is black. Right, back-face culling: only the
    faces whose normal points towards the camera are drawn, so a face wound the
    wrong way (or seen through a hole) disappears and the slate backdrop behind
    both panels shows through.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
    elev, azim : float
        The camera, in matplotlib's angles (degrees); the light comes from the
        camera, raised a little.
    title : str, optional
        A title over both panels.

    Returns
    -------
    matplotlib.figure.Figure
        Two panels, with ``fig.alt_text`` giving the counts of black and culled faces.
    """
    import numpy as np

    from trinormal import mesh

    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    n = mesh.face_normals(v, f)
    eye = camera_direction(elev, azim)
    light = camera_direction(elev + 15.0, azim + 10.0)
    towards = n @ eye
    lit = np.maximum(0.0, n @ light)
    shade = 0.08 + 0.92 * lit  # one scale for both panels: a face looks the same in each
    culled = np.where(towards > 0, shade, np.nan)
    fig = shaded_mesh_figure(
        v,
        f,
        {"lit from the camera's side": shade, "back faces culled": culled},
        elev=elev,
        azim=azim,
        title=title,
    )
    for ax in fig.axes:  # the backdrop: what shows through where no face is drawn
        ax.set_facecolor(BACKDROP)
    # faces well inside the camera's half of the model (not at the outline) whose normals
    # point away from it: seen from outside they are the wrong way round
    centre = v[f].mean(axis=1) - v.mean(axis=0)
    size = np.linalg.norm(centre, axis=1)
    near = centre @ eye > 0.2 * np.where(size > 0, size, 1.0)
    dark = int((near & (towards <= 0)).sum())
    faces_text = "1 face" if dark == 1 else f"{dark} faces"
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Two renderings of a mesh of {len(f)} triangles from one camera. Left, lit from the "
        f"camera's side: {faces_text} on the near side, away from the outline, "
        f"{'has its normal' if dark == 1 else 'have normals'} pointing away from the camera "
        "and show black. Right, with back faces culled: such faces are not drawn and the "
        f"slate backdrop shows through; {int((towards > 0).sum())} faces are drawn."
    )
    return fig


@_styled
def normal_transform_figure(sx: float = 2.0, sy: float = 1.0, count: int = 16) -> Figure:
    """Draw a cylinder seen end-on, stretched, with its normals transformed two ways.

    The cylinder's axis points at the viewer, so its surface is drawn as a
    circle and its normals lie in the picture. The stretch
    ``M = diag(sx, sy, 1)`` turns it into an elliptic cylinder.

    Parameters
    ----------
    sx, sy : float
        The stretch along x and y.
    count : int
        How many normals to draw.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: the surface and its normals; the stretched copy with the
        normals multiplied by M (dashed black, not perpendicular); the stretched
        copy with the normals multiplied by M⁻ᵀ (the ``N`` colour, perpendicular).
        ``fig.alt_text`` gives the largest error of each.
    """
    import matplotlib.pyplot as plt
    import numpy as np

    from trinormal.display import format_number

    t = np.linspace(0, 2 * np.pi, 400)
    s = np.linspace(0, 2 * np.pi, count, endpoint=False) + np.pi / count
    p = np.stack([np.cos(s), np.sin(s)], axis=1)  # points on the unit circle
    n = p.copy()  # their outward normals
    m = np.array([sx, sy])
    q = p * m
    wrong = n * m
    right = n / m
    tangent = np.stack([-np.sin(s), np.cos(s)], axis=1) * m  # the tangent, moved with the surface

    def off(normals: Any) -> Any:
        u = normals / np.linalg.norm(normals, axis=1, keepdims=True)
        tt = tangent / np.linalg.norm(tangent, axis=1, keepdims=True)
        return np.degrees(np.abs(np.arcsin(np.clip(np.abs((u * tt).sum(1)), 0, 1))))

    err_wrong, err_right = off(wrong).max(), off(right).max()
    # 10 inches: shown 1000 pixels wide, it fits a notebook on a 1280-pixel projector unscaled
    fig, axes = plt.subplots(1, 3, figsize=(10, 4.4), facecolor=FACECOLOR)
    stretch = f"x × {format_number(sx, 2, trim=True)}"
    if sy != 1:
        stretch += f", y × {format_number(sy, 2, trim=True)}"
    panels = [
        ("the surface\nand its normals", p, n, ROLE_COLORS["N"], "-", np.ones(2)),
        ("stretched,\nnormals × M (wrong)", q, wrong, "#000000", "--", m),
        ("stretched,\nnormals × M⁻ᵀ (right)", q, right, ROLE_COLORS["N"], "-", m),
    ]
    length = 0.45
    for ax, (name, pts, vecs, col, style, scale) in zip(axes, panels, strict=True):
        ax.set_facecolor(FACECOLOR)
        ax.plot(scale[0] * np.cos(t), scale[1] * np.sin(t), color=ROLE_COLORS["A"], lw=2.5)
        u = vecs / np.linalg.norm(vecs, axis=1, keepdims=True) * length
        for (x, y), (dx, dy) in zip(pts, u, strict=True):
            ax.annotate(
                "",
                xy=(x + dx, y + dy),
                xytext=(x, y),
                arrowprops={"arrowstyle": "-|>", "color": col, "lw": 2, "linestyle": style},
            )
        ax.set_aspect("equal")
        r = max(sx, sy, 1) + length + 0.1
        ax.set_xlim(-r, r)
        ax.set_ylim(-r * 0.75, r * 0.75)
        ax.set_title(name)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle(f"A cylinder seen end-on, then stretched by M ({stretch})")
    fig.tight_layout()
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Three panels. Left: a circle, the end view of a cylinder, with {count} outward "
        f"normals at right angles to it. Middle: the cylinder stretched ({stretch}) into an "
        "ellipse, with the normals multiplied by the same matrix: dashed arrows that lean "
        f"away from the perpendicular by up to {format_number(err_wrong, 1)} degrees. Right: "
        "the same ellipse with the normals multiplied by the inverse transpose: every arrow "
        f"is at right angles to the surface (largest error {format_number(err_right, 1)} "
        "degrees)."
    )
    return fig
