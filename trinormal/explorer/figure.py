"""The explorer's static snapshot: a matplotlib picture for print and pages without JavaScript.

The live explorer draws in 3D in the browser (`trinormal.explorer.view`). A
notebook saved as HTML, a printed page or a static site has no JavaScript view,
so `Snapshot` draws the same state with matplotlib: the triangle in 3D
with U and V from A and N from the centre (at the scale, and with the label,
of `trinormal.plotting.scale`, as the 3D view draws it), and bar charts of the
components of N and of the unit normal, in the package's one colour code
([`trinormal.colors`][trinormal.colors]). `Explorer.to_png` returns this picture when no 3D
view has sent its own picture of the current state.

Only the moving artists are redrawn on an update; the axes, ticks and panes come
from a cached bitmap of the same figure.
"""

from __future__ import annotations

import io
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.transforms import Bbox
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from trinormal.colors import ROLE_COLORS
from trinormal.core import TriangleNormal
from trinormal.explorer.readout import alt_text
from trinormal.plotting.scale import drawn_factor, scaled_label

__all__ = ["DPI", "FIGSIZE", "Snapshot"]

#: Figure size in inches and resolution of the PNG (648 × 288 pixels).
FIGSIZE: tuple[float, float] = (9.0, 4.0)
DPI = 72

#: zlib level for the PNG: the fastest, as the picture is made again after every change.
PNG_COMPRESS_LEVEL = 1

#: How many background bitmaps (one per 3D zoom level and scale of N) to keep.
BACKGROUND_CACHE = 12

_AXIS_COLORS = (ROLE_COLORS["x"], ROLE_COLORS["y"], ROLE_COLORS["z"])
_EDGE_COLOR = "#000000"  # the spines' colour: the zero lines meet them
_FACECOLOR = "white"


Vec = tuple[float, float, float]


def _sub(p: Sequence[float], q: Sequence[float]) -> Vec:
    return p[0] - q[0], p[1] - q[1], p[2] - q[2]


def _add(p: Sequence[float], q: Sequence[float], s: float = 1.0) -> Vec:
    return p[0] + s * q[0], p[1] + s * q[1], p[2] + s * q[2]


def _norm(p: Sequence[float]) -> float:
    return math.hypot(p[0], p[1], p[2])


def _scaled(p: Sequence[float], s: float) -> Vec:
    return p[0] * s, p[1] * s, p[2] * s


def _cross(p: Sequence[float], q: Sequence[float]) -> Vec:
    return (
        p[1] * q[2] - p[2] * q[1],
        p[2] * q[0] - p[0] * q[2],
        p[0] * q[1] - p[1] * q[0],
    )


def _perpendiculars(d: Vec) -> tuple[Vec, Vec]:
    """Two unit vectors perpendicular to the unit vector ``d`` and to each other."""
    axis = min(range(3), key=lambda i: abs(d[i]))
    e = [0.0, 0.0, 0.0]
    e[axis] = 1.0
    p = _cross(d, e)
    p = _scaled(p, 1.0 / _norm(p))
    return p, _cross(d, p)


def _arrow_segments(start: Vec, vector: Vec, head: float) -> list[list[Vec]]:
    """Draw a shaft and four head strokes (a small cross-shaped cone, visible from any side)."""
    length = _norm(vector)
    tip = _add(start, vector)
    if length == 0.0:
        return [[start, tip]]
    d = _scaled(vector, 1.0 / length)
    h = min(head, 0.35 * length)
    back = _add(tip, d, -h)
    p, q = _perpendiculars(d)
    w = 0.45 * h
    segments = [[start, tip]]
    for side in (p, q):
        segments.append([tip, _add(back, side, w)])
        segments.append([tip, _add(back, side, -w)])
    return segments


def _nice_limit(x: float, smallest: float = 1.0) -> float:
    """Round up to the nearest 1, 2, 2.5 or 5 × 10**k (and to at least ``smallest``)."""
    if not math.isfinite(x) or x <= smallest:
        return smallest
    k = math.floor(math.log10(x))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10.0**k >= x:
            return m * 10.0**k
    return 10.0 ** (k + 1)  # pragma: no cover - the loop always returns


class Snapshot:
    r"""A matplotlib figure of one explorer state, updated in place.

    Parameters
    ----------
    result : TriangleNormal
        The state to draw first.
    precision : int
        Decimal places for the numbers in the text alternative.
    bounds : tuple of float
        The explorer's coordinate range; the 3D box never grows beyond it.

    Examples
    --------
    >>> from trinormal import triangle_normal
    >>> snap = Snapshot(triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)), 4, (-5.0, 5.0))
    >>> snap.to_png()[:4]
    b'\x89PNG'
    """

    def __init__(self, result: TriangleNormal, precision: int, bounds: tuple[float, float]) -> None:
        self.result, self.precision = result, precision
        self.min, self.max = bounds
        self._dynamic: list[tuple[Any, Any]] = []
        self.figure, self._artists = self._build()
        self._canvas: Any = FigureCanvasAgg(self.figure)
        self.update(result, precision)

    def to_png(self) -> bytes:
        """Render the figure to PNG bytes, redrawing only what moved."""
        from PIL import Image

        self.render()
        width, height = self._canvas.get_width_height(physical=True)
        rgba = Image.frombuffer("RGBA", (width, height), self._canvas.buffer_rgba(), "raw")
        buf = io.BytesIO()
        rgba.convert("RGB").save(buf, format="png", compress_level=PNG_COMPRESS_LEVEL)
        return buf.getvalue()

    def render(self) -> None:
        """Bring the Agg canvas's pixels up to date with the current artists.

        The figure is cut into three bands (the 3D view, the chart of N, the
        chart of the unit normal). The first time a band is needed in a given
        state (a zoom level and title for the 3D view, a scale for N), the
        figure is drawn in full without its moving artists and each band's
        pixels are kept. After that an update restores the bands and draws only
        the triangle, the arrows, the labels and the bars on top: the same
        picture as a full redraw.
        """
        canvas = self._canvas
        renderer = canvas.get_renderer()
        width, height = renderer.width, renderer.height
        size = (width, height, self.figure.dpi)
        box, top, title = self._view
        keys = {"3d": (box, title, size), "n": (top, size), "u": size}
        regions = [self._backgrounds[band].get(key) for band, key in keys.items()]
        if any(region is None for region in regions):
            shown = [(artist, artist.get_visible()) for _, artist in self._dynamic]
            for artist, _ in shown:
                artist.set_visible(False)
            try:
                canvas.draw()
            finally:
                for artist, visible in shown:
                    artist.set_visible(visible)
            for band, key in keys.items():
                cache = self._backgrounds[band]
                if len(cache) >= BACKGROUND_CACHE:
                    cache.pop(next(iter(cache)))
                cache[key] = canvas.copy_from_bbox(self._band_bbox(band, width, height))
        else:
            for region in regions:
                canvas.restore_region(region)
        ax3 = self._artists["ax3"]
        ax3.M = ax3.get_proj()
        ax3.invM = np.linalg.inv(ax3.M)
        for ax, artist in self._dynamic:
            if not artist.get_visible():
                continue
            if ax is ax3 and hasattr(artist, "do_3d_projection"):
                artist.do_3d_projection()
            ax.draw_artist(artist)

    def _band_bbox(self, band: str, width: int, height: int) -> Bbox:
        """One band of the figure in whole pixels; the three bands tile the figure exactly."""
        x_split = round(self._split[0] * width)
        y_split = round(self._split[1] * height)
        if band == "3d":
            return Bbox([[0, 0], [x_split, height]])
        if band == "n":
            return Bbox([[x_split, y_split], [width, height]])
        return Bbox([[x_split, 0], [width, y_split]])

    # ------------------------------------------------------------------ the figure

    def _build(self) -> tuple[Figure, dict[str, Any]]:
        fig = Figure(figsize=FIGSIZE, dpi=DPI, facecolor=_FACECOLOR)
        grid = fig.add_gridspec(
            2, 2, width_ratios=(1.15, 1.0), left=0.0, right=0.98, bottom=0.08, top=0.9,
            wspace=0.25, hspace=0.6,
        )  # fmt: skip
        ax3 = fig.add_subplot(grid[:, 0], projection="3d", computed_zorder=False)
        ax_n = fig.add_subplot(grid[0, 1])
        ax_u = fig.add_subplot(grid[1, 1])
        art: dict[str, Any] = {"ax3": ax3, "ax_n": ax_n, "ax_u": ax_u}

        # 3D view: equal limits on all three axes and a cubic box, so the normal looks
        # perpendicular; the limits only change in steps (see _view_limit)
        ax3.set_box_aspect((1, 1, 1), zoom=1.1)
        ax3.set_autoscale_on(False)
        for axis, name in zip((ax3.xaxis, ax3.yaxis, ax3.zaxis), "xyz", strict=True):
            axis.set_pane_color((0.96, 0.96, 0.96, 1.0))
            axis.set_label_text(name, fontsize=13)
            axis.labelpad = -2
        ax3.tick_params(labelsize=12, pad=0)
        ax3.view_init(elev=22, azim=-60)
        art["face"] = Poly3DCollection(
            [[(0, 0, 0), (1, 0, 0), (0, 1, 0)]],
            facecolor=ROLE_COLORS["front"],
            edgecolor="none",
            alpha=0.55,
        )
        ax3.add_collection3d(art["face"], autolim=False)
        (art["edges"],) = ax3.plot([], [], [], color=_EDGE_COLOR, lw=1.6)
        (art["arc"],) = ax3.plot([], [], [], color=ROLE_COLORS["N"], lw=2.0)
        for name in "UVN":
            coll = Line3DCollection([], colors=ROLE_COLORS[name], linewidths=2.5)
            ax3.add_collection3d(coll, autolim=False)
            art["arrow_" + name] = coll
            (art["tip_" + name],) = ax3.plot(
                [0], [0], [0], ls="none", marker=f"${name}$", ms=12, color=ROLE_COLORS[name]
            )
        for name in "ABC":
            (art["label_" + name],) = ax3.plot(
                [0],
                [0],
                [0],
                ls="none",
                marker=f"$\\mathbf{{{name}}}$",
                ms=13,
                color=ROLE_COLORS[name],
            )
        art["title3"] = ax3.set_title("", fontsize=13)

        # bar charts: N (limits follow the data in 1-2-5 steps) and the unit normal (fixed)
        xs = (0, 1, 2)
        for ax, key, title in (
            (ax_n, "n", "components of N = U × V"),
            (ax_u, "u", "components of the unit normal n̂ = N / |N|"),
        ):
            art["bars_" + key] = list(ax.bar(xs, (0, 0, 0), color=_AXIS_COLORS, width=0.6))
            art["zero_" + key] = ax.axhline(0.0, color=_EDGE_COLOR, lw=1.5)
            ax.set_xticks(xs, ["x", "y", "z"])
            ax.set_xlim(-0.6, 2.6)
            ax.set_title(title, fontsize=13)
            ax.tick_params(labelsize=12)
            ax.set_autoscale_on(False)
        ax_u.set_ylim(-1.4, 1.4)
        ax_u.set_yticks([-1.0, -0.5, 0.0, 0.5, 1.0])
        art["undefined"] = ax_u.text(
            1, 0.7, "", ha="center", va="center", fontsize=12, color=ROLE_COLORS["U"]
        )

        # the artists that move, in the order a full draw paints them
        moving = {id(a) for key, a in art.items() if not key.startswith(("ax", "title"))}
        moving |= {id(a) for key in ("bars_n", "bars_u") for a in art[key]}
        self._dynamic = [
            (ax, a)
            for ax in (ax3, ax_n, ax_u)
            for a in sorted(ax.get_children(), key=lambda a: a.get_zorder())
            if id(a) in moving
        ]
        self._backgrounds: dict[str, dict[Any, Any]] = {"3d": {}, "n": {}, "u": {}}
        # where the bands meet: the right edge of the 3D view's cell (the charts' tick labels
        # stay to its right) and halfway down the gap between the two charts
        top_right, bottom_right = grid[0, 1].get_position(fig), grid[1, 1].get_position(fig)
        self._split = (
            float(grid[:, 0].get_position(fig).x1),
            float(0.5 * (bottom_right.y1 + top_right.y0)),
        )
        self._view: tuple[tuple[Vec, float], float, str] = (((0.0, 0.0, 0.0), 0.0), 0.0, "")
        self._n_marker = "$N$"
        return fig, art

    def _view_box(self, points: Sequence[Vec]) -> tuple[Vec, float]:
        """Choose the 3D box: a centre and a 1-2-5 half-width that frame ``points``.

        The centre moves in steps of half the half-width, so small moves keep the
        same box (and the cached background).
        """
        lows = [min(p[i] for p in points) for i in range(3)]
        highs = [max(p[i] for p in points) for i in range(3)]
        extent = max(h - lo for h, lo in zip(highs, lows, strict=True))
        widest = max(abs(self.min), abs(self.max))
        half = min(_nice_limit(0.75 * extent, smallest=0.5), _nice_limit(widest))
        grain = half / 2
        centre = tuple(
            round((h + lo) / 2 / grain) * grain for h, lo in zip(highs, lows, strict=True)
        )
        if not all(math.isfinite(c) for c in centre):
            centre = (0.0, 0.0, 0.0)
        return (centre[0], centre[1], centre[2]), half

    def update(self, result: TriangleNormal, precision: int) -> None:
        """Move every artist to show ``result`` (the axes are never rebuilt)."""
        self.result, self.precision = result, precision
        art = self._artists
        r = self.result
        A, B, C = r.a, r.b, r.c

        centroid = _scaled(_add(_add(A, B), C), 1.0 / 3.0)
        # N at its true length when it fits beside the triangle, else scaled by a power of
        # two that its label names (trinormal.plotting.scale), as in the 3D view
        longest = max(_norm(_sub(p, q)) for p, q in ((A, B), (A, C), (B, C)))
        factor = drawn_factor(r.magnitude, longest)
        n_draw = _scaled(r.normal, factor)
        framed = [A, B, C] if r.degenerate else [A, B, C, _add(centroid, n_draw)]
        box = self._view_box(framed)
        centre, half = box
        span = 2.0 * half
        if r.degenerate:
            title = f"{r.winding.label}: degenerate, no normal direction"
        else:
            title = f"{r.winding.label}: U, V from A; N from the centre"
        top = _nice_limit(1.3 * max(abs(x) for x in r.normal))
        if (box, top, title) != self._view:
            ax3 = art["ax3"]
            for c, set_lim, set_ticks in zip(
                centre,
                (ax3.set_xlim, ax3.set_ylim, ax3.set_zlim),
                (ax3.set_xticks, ax3.set_yticks, ax3.set_zticks),
                strict=True,
            ):
                set_lim(c - half, c + half)
                set_ticks([c - half / 2, c + half / 2])  # inner ticks: no clash at corners
            art["ax_n"].set_ylim(-top, top)
            art["ax_n"].set_yticks([-top, -top / 2, 0.0, top / 2, top])
            art["title3"].set_text(title)
            self._view = (box, top, title)

        art["face"].set_verts([[A, B, C]])
        art["edges"].set_data_3d(*zip(A, B, C, A, strict=True))

        # vertex labels pushed a little away from the centre of the triangle
        for name, point in zip("ABC", (A, B, C), strict=True):
            away = _sub(point, centroid)
            length = _norm(away)
            shift = _scaled(away, 0.06 * span / length) if length > 0 else (0.0, 0.0, 0.05 * span)
            x, y, z = _add(point, shift)
            art["label_" + name].set_data_3d([x], [y], [z])

        # U and V from A; N from the centroid, scaled when it does not fit (its label says so)
        head = 0.05 * span
        for name, vec in (("U", r.u), ("V", r.v), ("N", n_draw)):
            start = centroid if name == "N" else A
            art["arrow_" + name].set_segments(_arrow_segments(start, vec, head))
            if name == "N":  # N's name just past its tip
                spot = _add(start, vec, 1.0 + 0.07 * span / max(_norm(vec), 1e-300))
            else:  # U's and V's beside the middle of the edge, outside the triangle
                middle = _add(A, vec, 0.5)
                away = _sub(middle, centroid)
                length = _norm(away)
                spot = _add(middle, away, 0.09 * span / length) if length > 0 else middle
            art["tip_" + name].set_data_3d([spot[0]], [spot[1]], [spot[2]])
        visible_n = not r.degenerate
        art["arrow_N"].set_visible(visible_n)
        art["tip_N"].set_visible(visible_n)
        label = scaled_label(factor)
        marker = f"${label}$"
        if marker != self._n_marker:  # a new marker costs a text layout: only when it changes
            art["tip_N"].set_marker(marker)
            art["tip_N"].set_markersize(11 if factor == 1 else 11 + 3 * len(label))
            self._n_marker = marker

        # the right-hand rule: a curl from U towards V around A
        art["arc"].set_data_3d(
            *(self._arc(A, r.u, r.v, 0.15 * span) if visible_n else ([], [], []))
        )

        # bars: N on a 1-2-5 scale, the unit normal on a fixed one (flat when undefined)
        unit: Vec = r.unit_normal if r.unit_normal is not None else (0.0, 0.0, 0.0)
        for key, values, limit in (("n", r.normal, top), ("u", unit, 1.4)):
            for bar, value in zip(art["bars_" + key], values, strict=True):
                bar.set_height(value if math.isfinite(value) else math.copysign(limit, value))
        art["undefined"].set_text("undefined: the triangle is degenerate" if r.degenerate else "")
        self.figure.alt_text = alt_text(r, self.precision)  # type: ignore[attr-defined]

    @staticmethod
    def _arc(
        origin: Vec, u: Vec, v: Vec, radius: float
    ) -> tuple[list[float], list[float], list[float]]:
        lu, lv = _norm(u), _norm(v)
        if lu == 0.0 or lv == 0.0:
            return [], [], []
        e1 = _scaled(u, 1.0 / lu)
        vu = sum(x * y for x, y in zip(v, e1, strict=True))
        w = _add(v, e1, -vu)
        lw = _norm(w)
        if lw == 0.0:
            return [], [], []
        e2 = _scaled(w, 1.0 / lw)
        angle = math.atan2(lw, vu)
        r = min(radius, 0.45 * lu, 0.45 * lv)
        steps = 16
        turns = (angle * i / steps for i in range(steps + 1))
        points = [_add(_add(origin, e1, r * math.cos(t)), e2, r * math.sin(t)) for t in turns]
        return [p[0] for p in points], [p[1] for p in points], [p[2] for p in points]
