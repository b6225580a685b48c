"""The explorer: a live 3D view, sliders and exact text boxes for A, B and C, and a readout.

[`Explorer`][trinormal.widgets.Explorer] keeps every coordinate as exact text and recomputes
`Explorer.result` with [`trinormal.triangle_normal`][trinormal.core.triangle_normal] on every
change, whichever way it came: a slider, a typed value, a vertex dragged in the 3D view,
an arrow key on a focused vertex, or code ([`Explorer.set`][trinormal.widgets.Explorer.set], or
setting a control's ``value``). Every surface then shows the new state: the view, the
sliders, the text boxes and the readout.

The sliders live on a grid (``step``, default 0.1) and a value the kernel set
stays exactly as set: a slider's own rounding in the browser is recognised and
ignored (ipywidgets snaps a value to its step grid and sends the snapped value
back), so ``Explorer(a=("0.1", "0.2", "0.3"))`` computes with one tenth, one
fifth and three tenths for as long as nobody moves them.

Everything works without a browser or a kernel, which is how the doctests and
the tests drive it.
"""

from __future__ import annotations

import html
import math
from collections.abc import Iterable
from fractions import Fraction
from typing import Any

import ipywidgets as widgets
import traitlets

from trinormal.colors import ROLE_COLORS
from trinormal.core import TriangleNormal, Winding, triangle_normal
from trinormal.display import format_number, format_vector
from trinormal.explorer.figure import Snapshot
from trinormal.explorer.readout import alt_text, readout_html, summary_text
from trinormal.explorer.state import coordinate_text, exact_value, grid_text, view_state
from trinormal.explorer.view import ExplorerView
from trinormal.validation import (
    MAX_PRECISION,
    MIN_PRECISION,
    check_precision,
    check_vertex,
    check_winding,
)

__all__ = ["COORDINATES", "PRECISION_RANGE", "Explorer"]

#: Keys of the nine coordinates, in order: A's x, y, z, then B's, then C's.
COORDINATES: tuple[str, ...] = tuple(p + q for p in "abc" for q in "xyz")

#: Smallest and largest number of decimal places the precision control offers.
PRECISION_RANGE: tuple[int, int] = (MIN_PRECISION, MAX_PRECISION)

_WINDING_OPTIONS = [(w.label, w.value) for w in Winding]
#: Rounding slack when comparing a slider value from the browser with the grid: the
#: browser computes min + k * step in floating point.
_ECHO_TOLERANCE = Fraction(1, 10**9)

_RANGE_HINT = "create the Explorer with min= and max= to widen the range"


def _num(x: float) -> str:
    """Write a number for a message with as many decimals as it needs, nothing more."""
    return format_number(x, 15, trim=True)


def _name(key: str) -> str:
    return f"{key[0].upper()}.{key[1]}"


def _check_in_range(name: str, value: float, low: float, high: float) -> float:
    if value != value:
        raise ValueError(f"{name} is NaN")
    if math.isinf(value):
        raise ValueError(f"{name} is infinite; the slider range is {_num(low)} to {_num(high)}")
    if not low <= value <= high:
        raise ValueError(
            f"{name} = {_num(value)} is outside the slider range "
            f"{_num(low)} to {_num(high)}; {_RANGE_HINT}"
        )
    return value


def _check_winding(value: object) -> str:
    return check_winding(value).value


class _CoordinateSlider(widgets.FloatSlider):  # type: ignore[misc]
    """A FloatSlider that refuses values outside its range instead of clamping them."""

    def __init__(self, name: str, **kwargs: Any) -> None:
        self._coordinate_name = name
        super().__init__(**kwargs)

    @traitlets.validate("value")
    def _validate_value(self, proposal: Any) -> float:
        name = str(getattr(self, "_coordinate_name", self.description))
        return _check_in_range(name, float(proposal["value"]), self.min, self.max)


class _PrecisionSlider(widgets.IntSlider):  # type: ignore[misc]
    """An IntSlider for the decimal places that refuses values outside its range."""

    @traitlets.validate("value")
    def _validate_value(self, proposal: Any) -> int:
        return check_precision(proposal["value"])


class _WindingButtons(widgets.ToggleButtons):  # type: ignore[misc]
    """ToggleButtons for the winding whose bad values are a ValueError."""

    @traitlets.validate("value")
    def _validate_value(self, proposal: Any) -> str:
        return _check_winding(proposal["value"])


def _from_browser(widget: widgets.Widget, name: str) -> bool:
    """Say whether the change being handled came from the browser (not from Python code)."""
    return name in getattr(widget, "_property_lock", {})


class Explorer:
    """A live 3D view of a triangle with sliders, exact text boxes and a readout.

    Parameters
    ----------
    a, b, c : sequence of 3 numbers or strings, default (0, 0, 0), (1, 0, 0), (0, 1, 0)
        Where the vertices start. Strings are read exactly (``"0.1"``,
        ``"1/3"``); a float means the shortest decimal that gives it back.
        Each coordinate must lie within the range.
    winding : {"ABC", "ACB"} or Winding, default "ABC"
        ``"ABC"`` uses U = B − A and V = C − A; ``"ACB"`` swaps them, which turns
        the normal over.
    precision : int, default 4
        Decimal places in the readout, 0 to 15.
    min, max : float, default -5.0, 5.0
        The range of every coordinate.
    step : float or str, default 0.1
        The grid of the sliders, of a drag in the 3D view and of one arrow key.
    range : tuple of float, optional
        Shorthand for ``(min, max)``.

    Attributes
    ----------
    view : ExplorerView
        The live 3D view (an anywidget): drag empty space to turn it, drag a
        vertex (or its label) to move it, arrow keys and Page Up/Down move a
        focused vertex one grid step.
    controls : dict of str to ipywidgets.Widget
        ``"ax"`` … ``"cz"``: one `ipywidgets.FloatSlider` per coordinate;
        ``"winding"``: `ipywidgets.ToggleButtons` with values ``"ABC"``
        and ``"ACB"``, labelled A→B→C and A→C→B; ``"precision"``: an
        `ipywidgets.IntSlider` from 0 to 15. Setting ``.value`` from
        code works like a move; a value outside the range is a
        `ValueError` (ipywidgets would silently clamp it).
    inputs : dict of str to ipywidgets.Text
        ``"ax"`` … ``"cz"``: a text box per coordinate holding its exact text;
        type ``1/3`` or ``-2.35`` and press Enter.
    result : TriangleNormal
        The current result, recomputed on every change.
    readout : ipywidgets.HTML
        U, V, N, |N|, the area, the unit normal, the plane and a status line,
        with exactly the strings of ``result.format(precision)``.
    message : ipywidgets.HTML
        Empty, or why the last typed value was refused.

    Raises
    ------
    ValueError
        A starting coordinate outside the range, a precision outside 0–15, an
        unknown winding, or a range or step that makes no sense.

    Examples
    --------
    The guide's worked example, then the same triangle with the order reversed:

    >>> ex = Explorer(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0), winding="ABC", precision=4)
    >>> ex.result.normal, ex.result.area
    ((0.0, 0.0, 1.0), 0.5)
    >>> ex.controls["winding"].value = "ACB"
    >>> ex.result.format(4)["normal"]
    '(0.0000, 0.0000, -1.0000)'
    >>> ex.result.format(4)["normal"] in ex.readout.value
    True

    Exact values stay exact:

    >>> ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
    >>> ex.result.exact.a
    (Fraction(1, 10), Fraction(1, 5), Fraction(3, 10))
    >>> ex.view.b
    ['1/3', '0', '0']

    Three points on one line give a clear message instead of an error:

    >>> ex.set(a=(0, 0, 0), b=(1, 1, 1), c=(2, 2, 2))
    >>> ex.result.degenerate, ex.result.unit_normal
    (True, None)
    >>> "collinear" in ex.readout.value
    True

    Values outside the range are refused, not clamped:

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
        step: float | str = 0.1,
        range: tuple[float, float] | None = None,
    ) -> None:
        low, high = (min, max) if range is None else range
        low, high = float(low), float(high)
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise ValueError(f"the range needs finite min < max, got {low!r} to {high!r}")
        try:
            step_text = coordinate_text(step, "step")
            step_value = exact_value(step_text, "step")
        except (TypeError, ValueError):
            raise ValueError(f"step must be a positive decimal such as 0.1, got {step!r}") from None
        if "/" in step_text or not 0 < step_value <= Fraction(high) - Fraction(low):
            raise ValueError(f"step must be positive and at most max - min, got {step!r}")
        self.min, self.max, self.step = low, high, float(step_value)
        self._step_text = step_text
        precision = check_precision(precision)
        w = _check_winding(winding)
        texts = self._read_points({"a": a, "b": b, "c": c})

        self._texts: dict[str, str] = texts
        self._precision = precision
        self._syncing = False
        self._pushed: dict[str, Fraction] = {k: exact_value(t) for k, t in texts.items()}
        self._widget: widgets.Widget | None = None
        self._snapshot: Snapshot | None = None
        self.result: TriangleNormal = self._compute(texts, w)

        self.readout = widgets.HTML()
        self.message = widgets.HTML(layout=widgets.Layout(min_height="1.2em"))
        self.view = ExplorerView(
            a=[texts[k] for k in COORDINATES[0:3]],
            b=[texts[k] for k in COORDINATES[3:6]],
            c=[texts[k] for k in COORDINATES[6:9]],
            winding=w,
            step=step_text,
            bounds=[low, high],
            precision=precision,
            layout=widgets.Layout(width="100%"),
        )
        self.controls: dict[str, widgets.Widget] = {}
        self.inputs: dict[str, widgets.Text] = {}
        for key in COORDINATES:
            name = _name(key)
            self.controls[key] = _CoordinateSlider(
                name,
                value=float(exact_value(texts[key])),
                min=low,
                max=high,
                step=float(step_value),
                description=key[1],
                readout=False,
                continuous_update=True,
                style={"description_width": "1.2em"},
                layout=widgets.Layout(width="8.5em"),
            )
            self.inputs[key] = widgets.Text(
                value=texts[key],
                continuous_update=False,
                description_allow_html=False,
                tooltip=f"{name}: type a number such as 0.1, -2 or 1/3 and press Enter",
                layout=widgets.Layout(width="5em", margin="0 0.8em 0 0"),
            )
        self.controls["winding"] = _WindingButtons(
            options=_WINDING_OPTIONS,
            value=w,
            description="order",
            tooltips=["U = B − A, V = C − A", "U = C − A, V = B − A"],
            style={"button_width": "5.5em", "description_width": "3.5em"},
        )
        self.controls["precision"] = _PrecisionSlider(
            value=precision,
            min=PRECISION_RANGE[0],
            max=PRECISION_RANGE[1],
            step=1,
            description="decimals",
            style={"description_width": "4.5em"},
            layout=widgets.Layout(width="17em"),
        )
        self._refresh()
        for key in COORDINATES:
            self.controls[key].observe(self._slider_moved, names="value")
            self.inputs[key].observe(self._typed, names="value")
        self.controls["winding"].observe(self._winding_changed, names="value")
        self.controls["precision"].observe(self._precision_changed, names="value")
        self.view.observe(self._view_moved, names=["a", "b", "c"])
        self.view.observe(self._winding_changed, names="winding")

    # ------------------------------------------------------------------ reading values

    def _read_points(self, points: dict[str, Any]) -> dict[str, str]:
        """Check whole vertices and return their coordinates as exact text, by key."""
        texts: dict[str, str] = {}
        for p, point in points.items():
            vertex = p.upper()
            check_vertex(point, vertex)  # three numbers in an ordered sequence, each readable
            coords = list(point)
            for q, value in zip("xyz", coords, strict=True):
                texts[p + q] = self._check_text(p + q, coordinate_text(value, f"{vertex}.{q}"))
        return texts

    def _check_text(self, key: str, text: str) -> str:
        value = exact_value(text, _name(key))
        if not Fraction(self.min) <= value <= Fraction(self.max):
            raise ValueError(
                f"{_name(key)} = {text} is outside the slider range "
                f"{_num(self.min)} to {_num(self.max)}; {_RANGE_HINT}"
            )
        return text

    def _compute(self, texts: dict[str, str], winding: str) -> TriangleNormal:
        a, b, c = ([texts[p + q] for q in "xyz"] for p in "abc")
        return triangle_normal(a, b, c, winding=winding)

    # ------------------------------------------------------------------ state

    @property
    def a(self) -> tuple[float, float, float]:
        """Vertex A as floats (its exact value is ``result.exact.a``)."""
        return self.result.a

    @property
    def b(self) -> tuple[float, float, float]:
        """Vertex B as floats (its exact value is ``result.exact.b``)."""
        return self.result.b

    @property
    def c(self) -> tuple[float, float, float]:
        """Vertex C as floats (its exact value is ``result.exact.c``)."""
        return self.result.c

    @property
    def texts(self) -> dict[str, str]:
        """Every coordinate's exact text, by key (``"ax"`` … ``"cz"``)."""
        return dict(self._texts)

    @property
    def winding(self) -> Winding:
        """The current winding."""
        return self.result.winding

    @property
    def precision(self) -> int:
        """The current number of decimal places."""
        return self._precision

    def set(
        self,
        a: Iterable[Any] | None = None,
        b: Iterable[Any] | None = None,
        c: Iterable[Any] | None = None,
        winding: Winding | str | None = None,
        precision: int | None = None,
    ) -> None:
        """Change several values at once, recomputing once at the end.

        Every value is checked before anything moves, so a bad value leaves
        the explorer as it was. Values are kept exactly as given.

        Parameters
        ----------
        a, b, c : sequence of 3 numbers or strings, optional
            New positions for the vertices.
        winding : {"ABC", "ACB"} or Winding, optional
            The new order.
        precision : int, optional
            New number of decimal places.

        Raises
        ------
        ValueError
            A coordinate outside the range, an unknown winding or a precision
            outside 0–15.

        Examples
        --------
        >>> ex = Explorer()
        >>> ex.set(b=(2, 0, 0), c=(0, "3", 0), precision=1)
        >>> ex.result.format(1)["area"]
        '3.0'
        """
        points = {p: v for p, v in zip("abc", (a, b, c), strict=True) if v is not None}
        texts = {**self._texts, **self._read_points(points)}
        w = self.result.winding.value if winding is None else _check_winding(winding)
        p = self._precision if precision is None else check_precision(precision)
        self._apply(texts, w, p)

    # ------------------------------------------------------------------ updates

    def _apply(self, texts: dict[str, str], winding: str, precision: int) -> None:
        """Recompute from exact text and bring every surface up to date; never raises."""
        try:
            result = self._compute(texts, winding)
        except Exception as error:  # a callback must never raise: show the problem instead
            self.readout.value = (
                '<p role="alert"><b>Could not compute the normal:</b> '
                f"{html.escape(str(error), quote=False)}</p>"
            )
            return
        self._texts, self._precision, self.result = dict(texts), precision, result
        self.message.value = ""
        self._refresh()

    def update(self) -> None:
        """Recompute the result from the current values and refresh every surface."""
        self._apply(self._texts, self.result.winding.value, self._precision)

    def _refresh(self) -> None:
        """Push the current state to the sliders, text boxes, view and readout."""
        r, p = self.result, self._precision
        self._syncing = True
        try:
            # the view first: its readout is what the learner is watching
            with self.view.hold_sync():
                for i, name in enumerate("abc"):
                    point = [self._texts[k] for k in COORDINATES[3 * i : 3 * i + 3]]
                    if getattr(self.view, name) != point:
                        setattr(self.view, name, point)
                self.view.winding = r.winding.value
                self.view.precision = p
                self.view.state = view_state(r, p)
            for key in COORDINATES:
                text = self._texts[key]
                value = float(exact_value(text))
                if self.controls[key].value != value:
                    self.controls[key].value = value
                    self._pushed[key] = Fraction(value)
                if self.inputs[key].value != text:
                    self.inputs[key].value = text
            if self.controls["winding"].value != r.winding.value:
                self.controls["winding"].value = r.winding.value
            if self.controls["precision"].value != p:
                self.controls["precision"].value = p
        finally:
            self._syncing = False
        self.readout.value = readout_html(r, p)
        if self._snapshot is not None:
            self._snapshot.update(r, p)

    def _refuse(self, error: Exception) -> None:
        self.message.value = (
            '<span role="alert" style="color:#B3261E">'
            f"{html.escape(str(error), quote=False)}</span>"
        )

    def _slider_moved(self, change: Any) -> None:
        if self._syncing:
            return
        slider = change["owner"]
        key = next(k for k in COORDINATES if self.controls[k] is slider)
        value = float(change["new"])
        if _from_browser(slider, "value"):
            # the browser's slider moves a value we set to a nearby grid point and sends that
            # back: an echo, not a move, so the exact value stays
            if self._is_echo(key, Fraction(value)):
                return
            text = grid_text(value, self._step_text)
        else:
            text = coordinate_text(value, _name(key))
        self._apply({**self._texts, key: text}, self.result.winding.value, self._precision)

    def _is_echo(self, key: str, value: Fraction) -> bool:
        half = Fraction(self._step_text) / 2
        pushed = self._pushed.pop(key, None)
        if pushed is not None and abs(value - pushed) <= half + _ECHO_TOLERANCE:
            return True  # the first answer to a value we pushed, even from a tie
        return abs(value - exact_value(self._texts[key])) < half - _ECHO_TOLERANCE

    def _typed(self, change: Any) -> None:
        if self._syncing:
            return
        box = change["owner"]
        key = next(k for k in COORDINATES if self.inputs[k] is box)
        try:
            text = self._check_text(key, coordinate_text(str(change["new"]), _name(key)))
        except (TypeError, ValueError) as error:
            self._refuse(error)
            return
        self._apply({**self._texts, key: text}, self.result.winding.value, self._precision)

    def _view_moved(self, change: Any) -> None:
        if self._syncing:
            return
        p = change["name"]
        texts = dict(self._texts)
        try:
            values = list(change["new"])
            if len(values) != 3:
                raise ValueError(f"{p.upper()} has {len(values)} coordinates, expected 3")
            for q, value in zip("xyz", values, strict=True):
                texts[p + q] = self._check_text(p + q, coordinate_text(str(value), _name(p + q)))
        except (TypeError, ValueError) as error:
            self._refuse(error)
            self._refresh()  # put the view back where the kernel is
            return
        self._apply(texts, self.result.winding.value, self._precision)

    def _winding_changed(self, change: Any) -> None:
        if self._syncing:
            return
        try:
            w = _check_winding(change["new"])
        except ValueError as error:
            self._refuse(error)
            self._refresh()
            return
        self._apply(self._texts, w, self._precision)

    def _precision_changed(self, change: Any) -> None:
        if self._syncing:
            return
        self._apply(self._texts, self.result.winding.value, int(change["new"]))

    # ------------------------------------------------------------------ static snapshot

    @property
    def snapshot(self) -> Snapshot:
        """The matplotlib snapshot, kept up to date from the moment it is first asked for."""
        if self._snapshot is None:
            self._snapshot = Snapshot(self.result, self._precision, (self.min, self.max))
        return self._snapshot

    @property
    def figure(self) -> Any:
        """A matplotlib figure of the current state (the static snapshot)."""
        return self.snapshot.figure

    def to_png(self) -> bytes:
        r"""Draw the current state as a PNG, for print and for outputs without JavaScript.

        Examples
        --------
        >>> Explorer().to_png()[:8]
        b'\x89PNG\r\n\x1a\n'
        """
        return self.snapshot.to_png()

    def render(self) -> None:
        """Bring the snapshot's pixels up to date (see `Snapshot.render`)."""
        self.snapshot.render()

    @property
    def alt_text(self) -> str:
        """A sentence describing the current state, for screen readers and static pages."""
        return alt_text(self.result, self._precision)

    # ------------------------------------------------------------------ display

    @property
    def widget(self) -> widgets.Widget:
        """The whole explorer as one box: the 3D view with its readout, then the controls."""
        if self._widget is None:
            rows = []
            for p in "abc":
                color = ROLE_COLORS[p.upper()]
                cells: list[widgets.Widget] = [
                    widgets.HTML(
                        f'<b style="color:{color};font-size:16px">{p.upper()}</b>',
                        layout=widgets.Layout(width="1.6em"),
                    )
                ]
                for q in "xyz":
                    cells += [self.controls[p + q], self.inputs[p + q]]
                rows.append(widgets.HBox(cells, layout=widgets.Layout(align_items="center")))
            settings = widgets.HBox(
                [self.controls["winding"], self.controls["precision"]],
                layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
            )
            self._widget = widgets.VBox(
                [
                    self.view,
                    *rows,
                    settings,
                    self.message,
                ],
                layout=widgets.Layout(width="100%"),
            )
            self._widget.add_class("trinormal-explorer")
        return self._widget

    def _repr_mimebundle_(self, **kwargs: Any) -> dict[str, Any]:
        """Show the live explorer in Jupyter, with a plain-text summary for everywhere else."""
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
        return summary_text(self.result, self._precision)

    def __repr__(self) -> str:
        def v(p: tuple[float, float, float]) -> str:
            return format_vector(p, 15, trim=True)

        return (
            f"Explorer(a={v(self.a)}, b={v(self.b)}, c={v(self.c)}, "
            f"winding={self.winding.value!r}, precision={self.precision})"
        )
