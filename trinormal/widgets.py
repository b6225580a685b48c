"""The interactive explorer: sliders for A, B and C, a winding toggle, live numbers and charts.

:class:`Explorer` puts nine coordinate sliders, a winding toggle and a
decimal-places control above a readout and a figure. Every change, dragged in
JupyterLab or set from code, recomputes :attr:`Explorer.result` with
:func:`trinormal.triangle_normal`, rewrites the readout from
:meth:`~trinormal.TriangleNormal.format` and moves the figure's artists in
place. The figure reaches the browser as a PNG inside an
:class:`ipywidgets.Image`, rendered by Agg from the ``observe`` callbacks, so a
notebook cell never collects stray output.

Everything works without a display or a kernel, which is how the doctests and
the tests drive it.
"""

from __future__ import annotations

import html
import io
import math
from collections.abc import Iterable, Sequence
from decimal import Decimal
from fractions import Fraction
from typing import Any

import ipywidgets as widgets
import numpy as np
import traitlets
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.transforms import Bbox
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from trinormal.core import TriangleNormal, Winding, parse_coordinate, triangle_normal
from trinormal.display import format_number, format_vector
from trinormal.exercises import exercise
from trinormal.plotting import AXIS_COLORS, FACECOLOR, PALETTE

__all__ = ["COORDINATES", "PRECISION_RANGE", "Explorer"]

#: Keys of the nine coordinate sliders, in order: A's x, y, z, then B's, then C's.
COORDINATES: tuple[str, ...] = tuple(p + q for p in "abc" for q in "xyz")

#: Smallest and largest number of decimal places the precision control offers.
PRECISION_RANGE: tuple[int, int] = (0, 10)

#: Decimal places used for the numbers written on the figure (the readout uses the full precision).
FIGURE_PRECISION_MAX = 3

#: Figure size in inches and resolution of the PNG sent to the browser (648 × 288 pixels).
FIGSIZE: tuple[float, float] = (9.0, 4.0)
DPI = 72

#: zlib level for the PNG: 1 is several times faster than the default and barely larger.
PNG_COMPRESS_LEVEL = 1

#: How many background bitmaps (one per 3D zoom level and scale of N) to keep.
BACKGROUND_CACHE = 12

_WINDING_OPTIONS = [(w.label, w.value) for w in Winding]
_ARROW_COLORS = {"U": PALETTE["orange"], "V": PALETTE["sky"], "N": PALETTE["black"]}
_FACE_COLOR = PALETTE["yellow"]
_EDGE_COLOR = PALETTE["black"]


def _num(x: float) -> str:
    """Write a number for a message with as many decimals as it needs, nothing more."""
    return format_number(x, 15, trim=True)


def _step_decimals(step: float) -> int:
    """Decimal places of the step as written (0.1 → 1, 0.25 → 2, 2 → 0)."""
    exponent = Decimal(repr(float(step))).normalize().as_tuple().exponent
    return max(0, -int(exponent))


def _check_in_range(name: str, value: float, low: float, high: float, hint: str) -> float:
    if value != value:
        raise ValueError(f"{name} is NaN")
    if math.isinf(value):
        raise ValueError(f"{name} is infinite; the slider range is {_num(low)} to {_num(high)}")
    if not low <= value <= high:
        raise ValueError(
            f"{name} = {_num(value)} is outside the slider range "
            f"{_num(low)} to {_num(high)}; {hint}"
        )
    return value


class _CoordinateSlider(widgets.FloatSlider):  # type: ignore[misc]
    """A FloatSlider that refuses values outside its range instead of clamping them.

    The value is kept exactly as set: the explorer computes with the very float
    the slider holds.
    """

    def __init__(self, name: str, **kwargs: Any) -> None:
        self._coordinate_name = name
        super().__init__(**kwargs)

    @traitlets.validate("value")
    def _validate_value(self, proposal: Any) -> float:
        value = float(proposal["value"])
        name = str(getattr(self, "_coordinate_name", self.description))
        hint = "create the Explorer with min= and max= to widen the range"
        return _check_in_range(name, value, self.min, self.max, hint)


class _PrecisionSlider(widgets.IntSlider):  # type: ignore[misc]
    """An IntSlider for the decimal places that refuses values outside 0–10."""

    @traitlets.validate("value")
    def _validate_value(self, proposal: Any) -> int:
        return _check_precision(proposal["value"], self.min, self.max)


class _WindingButtons(widgets.ToggleButtons):  # type: ignore[misc]
    """ToggleButtons for the winding whose bad values are a ValueError."""

    @traitlets.validate("value")
    def _validate_value(self, proposal: Any) -> str:
        value = proposal["value"]
        for option in self._options_values:
            if option == value:
                return str(option)
        raise ValueError(f"winding must be 'ABC' or 'ACB' (or a Winding), got {value!r}")


def _check_precision(
    value: object, low: int = PRECISION_RANGE[0], high: int = PRECISION_RANGE[1]
) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise ValueError(
                f"precision must be a whole number from {low} to {high}, got {value!r}"
            )
    if not low <= value <= high:
        raise ValueError(f"precision must be from {low} to {high} decimal places, got {value}")
    return value


def _vertex(p: Iterable[Any], name: str) -> tuple[float, float, float]:
    try:
        coords = [float(x) for x in p]
    except TypeError:
        raise TypeError(f"{name} must be 3 coordinates (x, y, z), got {p!r}") from None
    if len(coords) != 3:
        raise ValueError(f"{name} has {len(coords)} coordinates, expected 3")
    return coords[0], coords[1], coords[2]


# --------------------------------------------------------------------------- figure geometry

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


def _inside(start: Vec, vector: Vec, divisor: int, half: float) -> bool:
    """Say whether ``start + vector / divisor`` lies in the cube from -half to half."""
    return all(abs(s + v / divisor) <= half for s, v in zip(start, vector, strict=True))


def _nice_limit(x: float) -> float:
    """Round up to the nearest 1, 2, 2.5 or 5 × 10**k (and to at least 1)."""
    if not math.isfinite(x) or x <= 1.0:
        return 1.0
    k = math.floor(math.log10(x))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10.0**k >= x:
            return m * 10.0**k
    return 10.0 ** (k + 1)  # pragma: no cover - the loop always returns


# --------------------------------------------------------------------------- the explorer


class Explorer:
    """Sliders for A, B and C, a winding toggle, a live readout and a live figure.

    Parameters
    ----------
    a, b, c : sequence of 3 real numbers, default (0, 0, 0), (1, 0, 0), (0, 1, 0)
        Where the vertices start. Each coordinate must lie within the slider range.
    winding : {"ABC", "ACB"} or Winding, default "ABC"
        ``"ABC"`` uses U = B − A and V = C − A; ``"ACB"`` swaps them, which turns
        the normal over.
    precision : int, default 4
        Decimal places in the readout, 0 to 10.
    min, max : float, default -5.0, 5.0
        The range of every coordinate slider.
    step : float, default 0.1
        How far one notch of a slider moves a coordinate.
    range : tuple of float, optional
        Shorthand for ``(min, max)``.

    Attributes
    ----------
    controls : dict of str to ipywidgets.Widget
        ``"ax"`` … ``"cz"``: one :class:`ipywidgets.FloatSlider` per coordinate;
        ``"winding"``: :class:`ipywidgets.ToggleButtons` with values ``"ABC"``
        and ``"ACB"``, labelled A→B→C and A→C→B; ``"precision"``: an
        :class:`ipywidgets.IntSlider` from 0 to 10. Setting ``.value`` from
        code works exactly like dragging; a value outside the range is a
        :class:`ValueError` (ipywidgets would silently clamp it).
    result : TriangleNormal
        The current result, recomputed on every change.
    readout : ipywidgets.HTML
        U, V, N, |N|, the area, the unit normal, the plane and a status line,
        with exactly the strings of ``result.format(precision)``.
    figure : matplotlib.figure.Figure
        Left, the triangle in 3D with U, V and N drawn from A; right, bar charts
        of the components of N and of the unit normal. Its artists are moved
        in place on every change; the axes are never rebuilt.

    Raises
    ------
    ValueError
        A starting coordinate outside the range, a precision outside 0–10, an
        unknown winding, or a range/step that makes no sense.

    Examples
    --------
    The guide's worked example, then the same triangle with the order reversed:

    >>> ex = Explorer(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0), winding="ABC", precision=4)
    >>> ex.result.normal, ex.result.area
    ((0.0, 0.0, 1.0), 0.5)
    >>> ex.controls["winding"].value = "ACB"
    >>> ex.result.format(4)["normal"] in ex.readout.value
    True
    >>> ex.result.format(4)["normal"]
    '(0.0000, 0.0000, -1.0000)'

    Moving a slider from code recomputes everything, as dragging does:

    >>> ex.controls["winding"].value = "ABC"
    >>> ex.controls["bx"].value = 2
    >>> ex.controls["cy"].value = 3
    >>> ex.result.format(4, trim=True)["normal"], ex.result.area
    ('(0, 0, 6)', 3.0)

    Three points on one line give a clear message instead of an error:

    >>> ex.set(a=(0, 0, 0), b=(1, 1, 1), c=(2, 2, 2))
    >>> ex.result.degenerate, ex.result.unit_normal
    (True, None)
    >>> "collinear" in ex.readout.value
    True

    Values outside the slider range are refused, not clamped:

    >>> ex.controls["bx"].value = 99  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: B.x = 99 is outside the slider range -5 to 5; ...
    """

    def __init__(
        self,
        a: Iterable[Any] = (0, 0, 0),
        b: Iterable[Any] = (1, 0, 0),
        c: Iterable[Any] = (0, 1, 0),
        winding: Winding | str = "ABC",
        precision: int = 4,
        *,
        min: float = -5.0,
        max: float = 5.0,
        step: float = 0.1,
        range: tuple[float, float] | None = None,
    ) -> None:
        low, high = (min, max) if range is None else range
        low, high, step = float(low), float(high), float(step)
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise ValueError(f"the slider range needs finite min < max, got {low!r} to {high!r}")
        if not (math.isfinite(step) and 0.0 < step <= high - low):
            raise ValueError(f"step must be positive and at most max - min, got {step!r}")
        precision = _check_precision(precision)
        points = [_vertex(p, name) for p, name in zip((a, b, c), "ABC", strict=True)]
        hint = "pass min= and max= to widen the range"
        for point, vertex in zip(points, "ABC", strict=True):
            for value, axis in zip(point, "xyz", strict=True):
                _check_in_range(f"{vertex}.{axis}", value, low, high, hint)
        try:
            w = Winding(winding)
        except ValueError:
            raise ValueError(
                f"winding must be 'ABC' or 'ACB' (or a Winding), got {winding!r}"
            ) from None

        self.min, self.max, self.step = low, high, step
        self._batch = False
        self._live = False
        self._widget: widgets.Widget | None = None
        self.image = widgets.Image(format="png", layout=widgets.Layout(max_width="100%"))
        self.readout = widgets.HTML()
        self.controls: dict[str, widgets.Widget] = {}
        decimals = _step_decimals(step)
        for key, value in zip(COORDINATES, (x for p in points for x in p), strict=True):
            name = f"{key[0].upper()}.{key[1]}"
            self.controls[key] = _CoordinateSlider(
                name,
                value=value,
                min=low,
                max=high,
                step=step,
                description=name,
                readout_format=f".{decimals}f",
                continuous_update=True,
                style={"description_width": "2.5em"},
                layout=widgets.Layout(width="15em"),
            )
        self.controls["winding"] = _WindingButtons(
            options=_WINDING_OPTIONS,
            value=w.value,
            description="order",
            tooltips=["U = B − A, V = C − A", "U = C − A, V = B − A"],
            style={"button_width": "6em", "description_width": "4em"},
        )
        self.controls["precision"] = _PrecisionSlider(
            value=precision,
            min=PRECISION_RANGE[0],
            max=PRECISION_RANGE[1],
            step=1,
            description="decimals",
            style={"description_width": "5.5em"},
            layout=widgets.Layout(width="20em"),
        )
        self.result: TriangleNormal = triangle_normal(points[0], points[1], points[2], winding=w)
        self._dynamic: list[tuple[Any, Any]] = []
        self.figure, self._artists = self._build_figure()
        self._canvas: Any = FigureCanvasAgg(self.figure)
        self.update()
        for control in self.controls.values():
            control.observe(self._on_change, names="value")

    # ------------------------------------------------------------------ state

    @property
    def a(self) -> tuple[float, float, float]:
        """Vertex A as the sliders hold it."""
        return self._point("a")

    @property
    def b(self) -> tuple[float, float, float]:
        """Vertex B as the sliders hold it."""
        return self._point("b")

    @property
    def c(self) -> tuple[float, float, float]:
        """Vertex C as the sliders hold it."""
        return self._point("c")

    @property
    def winding(self) -> Winding:
        """The current winding."""
        return Winding(self.controls["winding"].value)

    @property
    def precision(self) -> int:
        """The current number of decimal places."""
        return int(self.controls["precision"].value)

    def _point(self, p: str) -> tuple[float, float, float]:
        x, y, z = (float(self.controls[p + q].value) for q in "xyz")
        return x, y, z

    def set(
        self,
        a: Iterable[Any] | None = None,
        b: Iterable[Any] | None = None,
        c: Iterable[Any] | None = None,
        winding: Winding | str | None = None,
        precision: int | None = None,
    ) -> None:
        """Move several controls at once, recomputing only once at the end.

        Every value is checked before any control moves, so a bad value leaves
        the explorer as it was.

        Parameters
        ----------
        a, b, c : sequence of 3 real numbers, optional
            New positions for the vertices.
        winding : {"ABC", "ACB"} or Winding, optional
            The new order.
        precision : int, optional
            New number of decimal places.

        Raises
        ------
        ValueError
            A coordinate outside the slider range, an unknown winding or a
            precision outside 0–10.

        Examples
        --------
        >>> ex = Explorer()
        >>> ex.set(b=(2, 0, 0), c=(0, 3, 0), precision=1)
        >>> ex.result.format(1)["area"]
        '3.0'
        """
        new: dict[str, Any] = {}
        hint = "create the Explorer with min= and max= to widen the range"
        for p, point in zip("abc", (a, b, c), strict=True):
            if point is None:
                continue
            coords = _vertex(point, p.upper())
            for q, value in zip("xyz", coords, strict=True):
                _check_in_range(f"{p.upper()}.{q}", value, self.min, self.max, hint)
                new[p + q] = value
        if winding is not None:
            try:
                new["winding"] = Winding(winding).value
            except ValueError:
                raise ValueError(
                    f"winding must be 'ABC' or 'ACB' (or a Winding), got {winding!r}"
                ) from None
        if precision is not None:
            new["precision"] = _check_precision(precision)
        self._batch = True
        try:
            for key, value in new.items():
                self.controls[key].value = value
        finally:
            self._batch = False
        self.update()

    # ------------------------------------------------------------------ updates

    def _on_change(self, change: Any) -> None:
        if not self._batch:
            self.update()

    def update(self) -> None:
        """Recompute the result, rewrite the readout and move the figure's artists.

        The controls call this on every change; it never raises. If anything
        goes wrong, the readout says what instead.
        """
        try:
            self.result = triangle_normal(self.a, self.b, self.c, winding=self.winding)
            self.readout.value = self._readout_html()
        except Exception as error:  # a callback must never raise: show the problem instead
            self.readout.value = (
                '<p role="alert"><b>Could not compute the normal:</b> '
                f"{html.escape(str(error), quote=False)}</p>"
            )
            return
        try:
            self._update_figure()
            if self._live:
                self.image.value = self.to_png()
        except Exception as error:  # keep the numbers even if drawing fails
            self.readout.value += (
                '<p role="alert"><b>Could not draw the figure:</b> '
                f"{html.escape(str(error), quote=False)}</p>"
            )

    def _readout_html(self) -> str:
        r = self.result
        p = self.precision
        f = r.format(p)
        first, second = ("B", "C") if r.winding is Winding.ABC else ("C", "B")
        rows = [
            ("U", f"{first} − A", f["u"]),
            ("V", f"{second} − A", f["v"]),
            ("N", "U × V", f["normal"]),
            ("|N|", "length of N, twice the area", f["magnitude"]),
            ("area", "|N| / 2", f["area"]),
            ("n̂", "unit normal, N / |N|", f["unit_normal"]),
            ("plane", "n̂ · x = n̂ · A", f["plane"]),
        ]
        th = '<th scope="row" style="text-align:left;padding-right:1em">'
        td_meaning = '<td style="padding-right:1em;color:#555">'
        td_value = '<td style="font-family:monospace;text-align:left">'
        body = "".join(
            f"<tr>{th}{html.escape(name)}</th>{td_meaning}{html.escape(meaning)}</td>"
            f"{td_value}{html.escape(value, quote=False)}</td></tr>"
            for name, meaning, value in rows
        )
        status = html.escape(f["status"], quote=False)
        if r.degenerate:
            note = (
                '<div role="status" style="border-left:4px solid #D55E00;padding:0.3em 0.6em;'
                'margin-top:0.4em"><b>No triangle to face anywhere.</b> '
                f"{status} Drag one vertex off the line through the other two and the "
                "normal comes back.</div>"
            )
        else:
            note = f'<p role="status" style="margin-top:0.4em">{status}</p>'
        caption = (
            f"Order {r.winding.label}: U = {first} − A, V = {second} − A, N = U × V "
            f"({p} decimal place{'' if p == 1 else 's'})"
        )
        return (
            '<div class="trinormal-readout">'
            f'<table><caption style="text-align:left;font-weight:bold">{html.escape(caption)}'
            f"</caption>{body}</table>{note}</div>"
        )

    @property
    def alt_text(self) -> str:
        """A sentence describing the current figure, for screen readers and static pages."""
        r = self.result
        p = min(self.precision, FIGURE_PRECISION_MAX)
        f = r.format(p, trim=True)
        unit = "undefined, the triangle is degenerate" if r.degenerate else f["unit_normal"]
        return (
            f"Left: the triangle A = {format_vector(r.a, p, trim=True)}, "
            f"B = {format_vector(r.b, p, trim=True)}, C = {format_vector(r.c, p, trim=True)} "
            f"in 3D, with the edges U = {f['u']} and V = {f['v']} and the normal N drawn "
            f"from A (order {r.winding.label}). Right: bar charts of the components of "
            f"N = {f['normal']} and of the unit normal, {unit}."
        )

    def to_png(self) -> bytes:
        r"""Render the figure to PNG bytes, the way the notebook's inline backend would.

        Only the artists that move are redrawn: the axes, ticks and panes come
        from a cached bitmap of the same figure (see :meth:`render`).

        Examples
        --------
        >>> Explorer().to_png()[:8]
        b'\x89PNG\r\n\x1a\n'
        """
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
        picture as a full redraw, several times faster.
        """
        canvas = self._canvas
        renderer = canvas.get_renderer()
        width, height = renderer.width, renderer.height
        size = (width, height, self.figure.dpi)
        half, top, title = self._view
        keys = {"3d": (half, title, size), "n": (top, size), "u": size}
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

    def _build_figure(self) -> tuple[Figure, dict[str, Any]]:
        fig = Figure(figsize=FIGSIZE, dpi=DPI, facecolor=FACECOLOR)
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
            axis.set_label_text(name)
            axis.labelpad = -2
        ax3.tick_params(labelsize=7, pad=-1)
        ax3.view_init(elev=22, azim=-60)
        art["face"] = Poly3DCollection(
            [[(0, 0, 0), (1, 0, 0), (0, 1, 0)]], facecolor=_FACE_COLOR, edgecolor="none", alpha=0.5
        )
        ax3.add_collection3d(art["face"], autolim=False)
        (art["edges"],) = ax3.plot([], [], [], color=_EDGE_COLOR, lw=1.2)
        (art["arc"],) = ax3.plot([], [], [], color=PALETTE["purple"], lw=1.5)
        for name in "UVN":
            coll = Line3DCollection([], colors=_ARROW_COLORS[name], linewidths=2.2)
            ax3.add_collection3d(coll, autolim=False)
            art["arrow_" + name] = coll
            (art["tip_" + name],) = ax3.plot(
                [0], [0], [0], ls="none", marker=f"${name}$", ms=11, color=_ARROW_COLORS[name]
            )
        for name in "ABC":
            (art["label_" + name],) = ax3.plot(
                [0], [0], [0], ls="none", marker=f"$\\mathbf{{{name}}}$", ms=12, color=_EDGE_COLOR
            )
        art["title3"] = ax3.set_title("", fontsize=10)

        # bar charts: N (limits follow the data in 1-2-5 steps) and the unit normal (fixed)
        xs = (0, 1, 2)
        for ax, key, title in (
            (ax_n, "n", "components of N = U × V"),
            (ax_u, "u", "components of the unit normal n̂ = N / |N|"),
        ):
            art["bars_" + key] = list(ax.bar(xs, (0, 0, 0), color=AXIS_COLORS, width=0.6))
            art["zero_" + key] = ax.axhline(0.0, color=_EDGE_COLOR, lw=0.8)
            ax.set_xticks(xs, ["x", "y", "z"])
            ax.set_xlim(-0.6, 2.6)
            ax.set_title(title, fontsize=10)
            ax.tick_params(labelsize=8)
            ax.set_autoscale_on(False)
        ax_u.set_ylim(-1.4, 1.4)
        ax_u.set_yticks([-1.0, -0.5, 0.0, 0.5, 1.0])
        art["undefined"] = ax_u.text(
            1, 0.7, "", ha="center", va="center", fontsize=10, color=PALETTE["vermillion"]
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
        self._view: tuple[float, float, str] = (0.0, 0.0, "")
        self._n_marker = "$N$"
        return fig, art

    def _view_limit(self) -> float:
        """Half-width of the 3D box: a 1-2-5 step that holds the vertices, within the range."""
        r = self.result
        reach = max(abs(x) for x in (*r.a, *r.b, *r.c))
        widest = max(abs(self.min), abs(self.max))
        return min(_nice_limit(1.25 * reach), _nice_limit(widest))

    def _update_figure(self) -> None:
        art = self._artists
        r = self.result
        A, B, C = r.a, r.b, r.c

        half = self._view_limit()
        span = 2.0 * half
        divisor = 1  # N is halved until it fits the view; its label says so
        while divisor < 2**60 and (
            r.magnitude / divisor > 0.4 * span
            or (r.magnitude / divisor > 0.1 * span and not _inside(A, r.normal, divisor, half))
        ):
            divisor *= 2
        if r.degenerate:
            title = f"{r.winding.label}: degenerate, no normal direction"
        else:
            title = f"{r.winding.label}: U, V and N = U × V, drawn from A"
        top = _nice_limit(1.3 * max(abs(x) for x in r.normal))
        if (half, top, title) != self._view:
            ax3 = art["ax3"]
            ax3.set_xlim(-half, half)
            ax3.set_ylim(-half, half)
            ax3.set_zlim(-half, half)
            ticks = [-half, 0.0, half]
            ax3.set_xticks(ticks)
            ax3.set_yticks(ticks)
            ax3.set_zticks(ticks)
            art["ax_n"].set_ylim(-top, top)
            art["ax_n"].set_yticks([-top, -top / 2, 0.0, top / 2, top])
            art["title3"].set_text(title)
            self._view = (half, top, title)

        art["face"].set_verts([[A, B, C]])
        art["edges"].set_data_3d(*zip(A, B, C, A, strict=True))

        # vertex labels pushed a little away from the centre of the triangle
        centre = _scaled(_add(_add(A, B), C), 1.0 / 3.0)
        for name, point in zip("ABC", (A, B, C), strict=True):
            away = _sub(point, centre)
            length = _norm(away)
            shift = _scaled(away, 0.06 * span / length) if length > 0 else (0.0, 0.0, 0.05 * span)
            x, y, z = _add(point, shift)
            art["label_" + name].set_data_3d([x], [y], [z])

        # U and V from A; N from A, halved until it fits the view (its label says so)
        head = 0.05 * span
        n_draw = _scaled(r.normal, 1.0 / divisor)
        for name, vec in (("U", r.u), ("V", r.v), ("N", n_draw)):
            art["arrow_" + name].set_segments(_arrow_segments(A, vec, head))
            if name == "N":  # N's name just past its tip
                spot = _add(A, vec, 1.0 + 0.07 * span / max(_norm(vec), 1e-300))
            else:  # U's and V's beside the middle of the edge, outside the triangle
                middle = _add(A, vec, 0.5)
                away = _sub(middle, centre)
                length = _norm(away)
                spot = _add(middle, away, 0.09 * span / length) if length > 0 else middle
            art["tip_" + name].set_data_3d([spot[0]], [spot[1]], [spot[2]])
        visible_n = not r.degenerate
        art["arrow_N"].set_visible(visible_n)
        art["tip_N"].set_visible(visible_n)
        marker = "$N$" if divisor == 1 else f"$N/{divisor}$"
        if marker != self._n_marker:  # a new marker costs a text layout: only when it changes
            art["tip_N"].set_marker(marker)
            art["tip_N"].set_markersize(11 if divisor == 1 else 16 + 4 * len(str(divisor)))
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
        self.figure.alt_text = self.alt_text  # type: ignore[attr-defined]

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
        xs, ys, zs = [], [], []
        for i in range(steps + 1):
            t = angle * i / steps
            point = _add(_add(origin, e1, r * math.cos(t)), e2, r * math.sin(t))
            xs.append(point[0])
            ys.append(point[1])
            zs.append(point[2])
        return xs, ys, zs

    # ------------------------------------------------------------------ display

    @property
    def widget(self) -> widgets.Widget:
        """The whole explorer as one ipywidgets box: controls, readout and figure.

        Asking for it switches on PNG rendering: from then on every change
        re-renders the figure into the box's image.
        """
        if self._widget is None:
            rows = [
                widgets.HBox(
                    [widgets.Label(p.upper(), layout=widgets.Layout(width="1.5em"))]
                    + [self.controls[p + q] for q in "xyz"]
                )
                for p in "abc"
            ]
            rows.append(widgets.HBox([self.controls["winding"], self.controls["precision"]]))
            self._widget = widgets.VBox(
                [widgets.VBox(rows), self.readout, self.image],
                layout=widgets.Layout(width="100%"),
            )
            self._live = True
            self.image.value = self.to_png()
        return self._widget

    def _repr_mimebundle_(self, **kwargs: Any) -> dict[str, Any]:
        """Show the live explorer in JupyterLab, with a plain-text summary for everywhere else."""
        bundle: dict[str, Any] = dict(self.widget._repr_mimebundle_(**kwargs))
        bundle["text/plain"] = self.summary()
        return bundle

    def summary(self) -> str:
        """Write the readout as plain text, one quantity a line.

        Examples
        --------
        >>> print(Explorer(precision=2).summary())
        Triangle normal explorer, order A→B→C, 2 decimal places
        A = (0.00, 0.00, 0.00)  B = (1.00, 0.00, 0.00)  C = (0.00, 1.00, 0.00)
        U = (1.00, 0.00, 0.00)
        V = (0.00, 1.00, 0.00)
        N = (0.00, 0.00, 1.00)
        |N| = 1.00
        area = 0.50
        unit normal = (0.00, 0.00, 1.00)
        plane: 0.00x + 0.00y + 1.00z = 0.00
        A proper triangle: the unit normal is defined.
        """
        r = self.result
        p = self.precision
        f = r.format(p)
        return "\n".join(
            [
                f"Triangle normal explorer, order {r.winding.label}, "
                f"{p} decimal place{'' if p == 1 else 's'}",
                f"A = {format_vector(r.a, p)}  B = {format_vector(r.b, p)}  "
                f"C = {format_vector(r.c, p)}",
                f"U = {f['u']}",
                f"V = {f['v']}",
                f"N = {f['normal']}",
                f"|N| = {f['magnitude']}",
                f"area = {f['area']}",
                f"unit normal = {f['unit_normal']}",
                f"plane: {f['plane']}",
                f["status"],
            ]
        )

    def __repr__(self) -> str:
        def v(p: tuple[float, float, float]) -> str:
            return format_vector(p, 15, trim=True)

        return (
            f"Explorer(a={v(self.a)}, b={v(self.b)}, c={v(self.c)}, "
            f"winding={self.winding.value!r}, precision={self.precision})"
        )


# --------------------------------------------------------------------------- exercises

#: Two vertices given in exercise 05-collinear; the student supplies the third.
COLLINEAR_AB: tuple[tuple[int, int, int], tuple[int, int, int]] = ((1, 2, 0), (3, 3, 1))

#: The triangle scaled in exercise 05-scale-area, and the factor.
SCALE_ABC: tuple[tuple[int, int, int], tuple[int, int, int], tuple[int, int, int]] = (
    (1, 0, 2),
    (3, 1, 0),
    (-1, 2, 1),
)
SCALE_FACTOR = 3


def _read_points(answer: Any, count: int) -> list[tuple[float, float, float]] | str:
    """Read ``count`` points from an answer, or say what is wrong with it."""
    try:
        points = [_vertex(p, f"point {i + 1}") for i, p in enumerate(answer)]
    except (TypeError, ValueError) as error:
        return f"Your answer could not be read: {error}."
    if len(points) != count:
        return f"Give {count} point{'s' if count > 1 else ''} (x, y, z), got {len(points)}."
    return points


@exercise(
    "05-down-acb",
    "Give three points (A, B, C) whose unit normal in the order A→C→B is exactly (0, 0, −1): "
    "the triangle faces straight down when it is walked A→C→B.",
    replace=True,
)
def _check_down_acb(answer: Any) -> bool | tuple[bool, str]:
    points = _read_points(answer, 3) if answer is not None else "Give three points."
    if isinstance(points, str):
        return False, points
    r = triangle_normal(points[0], points[1], points[2], winding="ACB")
    if r.degenerate or r.unit_normal is None:
        return False, "These points make no triangle (zero area), so there is no normal at all."
    if r.unit_normal == (0.0, 0.0, -1.0):
        return True
    if r.unit_normal == (0.0, 0.0, 1.0):
        return False, "In the order A→C→B your normal points up (+z): swap B and C."
    return False, (
        "The normal must have no x or y part: put all three points at the same height z, "
        "then check the order A→C→B with the right-hand rule."
    )


@exercise(
    "05-collinear",
    f"A = {COLLINEAR_AB[0]} and B = {COLLINEAR_AB[1]}. Give a point C, different from both, "
    "that makes the area exactly 0.",
    replace=True,
)
def _check_collinear(answer: Any) -> bool | tuple[bool, str]:
    points = _read_points([answer], 1) if answer is not None else "Give one point."
    if isinstance(points, str):
        return False, points
    c = points[0]
    a, b = COLLINEAR_AB
    if c in (tuple(map(float, a)), tuple(map(float, b))):
        return False, "C must be a new point, not A or B again (that is the easy way to area 0)."
    r = triangle_normal(a, b, c, tol=0)
    if r.degenerate:
        return True
    direction = format_vector(_sub(b, a), 0, trim=True)
    return False, f"Not on the line yet: C − A must be a multiple of B − A = {direction}."


@exercise(
    "05-scale-area",
    f"Multiply every coordinate of A = {SCALE_ABC[0]}, B = {SCALE_ABC[1]}, C = {SCALE_ABC[2]} "
    f"by {SCALE_FACTOR}. By what number is the area multiplied?",
    replace=True,
)
def _check_scale_area(answer: Any) -> bool | tuple[bool, str]:
    try:
        value = Fraction(*parse_coordinate(answer, "your answer"))
    except (TypeError, ValueError) as error:
        return False, f"Answer with one number: {error}."
    if value == _area_factor():
        return True
    if value == SCALE_FACTOR:
        return False, "Each edge grows by that factor, but the area is a product of two edges."
    return False, "Compare the area before and after, or think of what doubling did to N."


def _area_factor() -> Fraction:
    """Measure area(kA, kB, kC) / area(A, B, C) exactly: the square root of the |N|² ratio."""
    a, b, c = SCALE_ABC
    k = SCALE_FACTOR
    before = triangle_normal(a, b, c).exact.magnitude_squared
    ka, kb, kc = (tuple(k * x for x in p) for p in SCALE_ABC)
    after = triangle_normal(ka, kb, kc).exact.magnitude_squared
    ratio = after / before
    root = Fraction(math.isqrt(ratio.numerator), math.isqrt(ratio.denominator))
    if root * root != ratio:  # pragma: no cover - scaling by an integer keeps it a square
        raise ArithmeticError(f"the area ratio {ratio} is not a perfect square")
    return root
