"""The right-hand rule: one triangle in 3D with its edges U, V, its normal N and the curl."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from trinormal.colors import ROLE_COLORS
from trinormal.plotting.camera import camera_direction
from trinormal.plotting.scale import drawn_factor, scaled_label
from trinormal.plotting.style import FACECOLOR, PALETTE, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from trinormal.core import TriangleNormal

__all__ = ["right_hand_rule_figure"]

Point = Sequence[float]


def _fmt_vec(xs: Any) -> str:
    from trinormal.display import format_vector

    return format_vector(xs, 4, trim=True)


@styled
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
    thumb does. N is drawn at its true length when that is between ¼ and 1
    times the longest edge; otherwise it is scaled by a power of two and labelled
    so (``N × ¼``, ``N × 4``), and the alt text says which
    (`trinormal.plotting.scale`).
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
    import mpl_toolkits.mplot3d  # noqa: F401  (registers the 3d projection)
    from matplotlib.figure import Figure
    from matplotlib.ticker import MaxNLocator
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from trinormal.core import triangle_normal

    r = triangle_normal(a, b, c, winding=winding)
    A, B, C = r.a, r.b, r.c
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
    pts: list[Point] = [A, B, C]
    centroid = [sum(p[i] for p in pts) / 3 for i in range(3)]
    lengths = [math.dist(p, q) for p, q in ((A, B), (A, C), (B, C))]
    scale = 0.75 * (sum(lengths) / 3) or 1.0
    _draw_edges(ax, A, (r.u, r.v), centroid, scale)
    direction = "is zero, so it has no direction: the triangle is degenerate"
    drawn = ""
    if unit is not None:
        n, label, drawn = _drawn_normal(r, unit, max(lengths))
        ax.quiver(*centroid, *n, color=ROLE_COLORS["N"], linewidth=3, arrow_length_ratio=0.15)
        tip = [centroid[i] + n[i] for i in range(3)]
        ax.text(*tip, "  " + label, color=ROLE_COLORS["N"], fontsize=15, fontweight="bold")
        # both ends, so the other winding of the same points gets the same axes
        pts += [tuple(tip), tuple(centroid[i] - n[i] for i in range(3))]
        fig.curl_head = _draw_curl(ax, A, r.u, r.v)  # type: ignore[attr-defined]
        direction = _direction_words(r, unit, seen)
    _frame_equal(ax, pts)
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


def _draw_edges(
    ax: Any, A: Point, edges: tuple[Point, Point], centroid: Point, scale: float
) -> None:
    """Draw U and V from A, each labelled beside its arrow's head, outside the face."""
    for name, vec in zip("UV", edges, strict=True):
        ax.quiver(*A, *vec, color=ROLE_COLORS[name], linewidth=2.5, arrow_length_ratio=0.12)
        mid = [A[i] + 0.8 * vec[i] for i in range(3)]
        out = [mid[i] - centroid[i] for i in range(3)]
        ee = sum(x * x for x in vec) or 1.0
        along = sum(out[i] * vec[i] for i in range(3)) / ee
        perp = [out[i] - along * vec[i] for i in range(3)]
        size = math.hypot(*perp) or 1.0
        away = [mid[i] + 0.2 * scale * perp[i] / size for i in range(3)]
        ax.text(*away, name, color=ROLE_COLORS[name], fontsize=14, fontweight="bold", ha="center")


def _drawn_normal(
    r: TriangleNormal, unit: Point, longest_edge: float
) -> tuple[list[float], str, str]:
    """Return N as drawn (`trinormal.plotting.scale`), its label and the alt text's words on it."""
    length_n = math.sqrt(float(r.exact.magnitude_squared))
    factor = drawn_factor(length_n, longest_edge)
    n = [x * length_n * factor for x in unit]
    label = scaled_label(factor)
    if factor == 1.0:
        return n, label, "N is drawn at its true length"
    if factor < 1.0:
        return n, label, f"N is drawn at 1/{round(1 / factor)} of its length (labelled {label})"
    return n, label, f"N is drawn {round(factor)} times longer than it is (labelled {label})"


def _draw_curl(ax: Any, A: Point, u: Point, v: Point) -> tuple[tuple[float, ...], ...]:
    """Draw the curl from U towards V around A, ending in a large filled arrowhead near V.

    Returns the arrowhead's base and tip on the arc (``fig.curl_head``, for tests).
    """
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

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
    ax.plot(*arc, color=ROLE_COLORS["N"], linewidth=3.5)
    outer, inner = on_arc(t_base, rho + 0.38 * head), on_arc(t_base, rho - 0.38 * head)
    ax.add_collection3d(
        Poly3DCollection(
            [[on_arc(t_tip), outer, inner]],
            facecolor=ROLE_COLORS["N"],
            edgecolor=ROLE_COLORS["N"],
            linewidth=1.5,
        )
    )
    return tuple(on_arc(t_base)), tuple(on_arc(t_tip))


def _direction_words(r: TriangleNormal, unit: Point, seen: str) -> str:
    """Say where N points (an axis when it is one) and which side of the face the camera sees."""
    direction = f"has the unit direction {r.format(4, trim=True)['unit_normal']}"
    if sorted(abs(x) for x in unit) == [0.0, 0.0, 1.0]:
        axis = max(range(3), key=lambda i: abs(unit[i]))
        sign = "+" if unit[axis] > 0 else "-"
        direction = f"points along {sign}{'xyz'[axis]}"
    colour = "yellow" if seen == "front" else "sky blue"
    return direction + f"; the camera sees the {seen} of the face ({colour})"


def _frame_equal(ax: Any, pts: Sequence[Point]) -> None:
    """Equal scales: a cube around everything drawn, with a margin."""
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    half = max(h - low for h, low in zip(hi, lo, strict=True)) / 2 or 1.0
    for i, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        centre = (lo[i] + hi[i]) / 2
        setter(centre - half * 1.1, centre + half * 1.1)
    ax.set_box_aspect((1, 1, 1))
