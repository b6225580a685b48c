"""The explorer: a live 3D view, sliders and exact text boxes for A, B and C, and a readout.

[`Explorer`][trinormal.widgets.Explorer] keeps every coordinate as exact text and recomputes
`Explorer.result` with [`trinormal.triangle_normal`][trinormal.core.triangle_normal] on every
change, whichever way it came: a slider, a typed value, a vertex dragged in the 3D view,
an arrow key on a focused vertex, or code ([`Explorer.set`][trinormal.widgets.Explorer.set], or
setting a control's ``value``). Every surface then shows the new state: the view, the
sliders, the text boxes and the readout.

The sliders live on a grid (``step``, default 0.1) and a value the kernel set
stays exactly as set: the controls are drawn by the view's own ES module and
write nothing back unless the learner moves them, and every move reaches the
kernel as an identified edit made against a version of the kernel's state (see
[`ExplorerView`][trinormal.explorer.ExplorerView]). So ``Explorer(a=("0.1", "0.2", "0.3"))``
computes with one tenth, one fifth and three tenths for as long as nobody moves
them, and a cell's ``ex.set(...)`` is never overwritten by a late answer from
the browser.

Everything works without a browser or a kernel, which is how the doctests and
the tests drive it.
"""

from __future__ import annotations

import html
import math
from collections.abc import Callable, Iterable
from fractions import Fraction
from functools import partial
from pathlib import Path
from typing import Any

from trinormal.core import TriangleNormal, Winding, triangle_normal
from trinormal.display import exact_literals, format_number
from trinormal.explorer.describe import describe
from trinormal.explorer.figure import Snapshot
from trinormal.explorer.readout import alt_text, readout_html, summary_text
from trinormal.explorer.state import coordinate_text, exact_value, view_state
from trinormal.explorer.view import COORDINATES, ExplorerView
from trinormal.printmodel import DEFAULT_SIZE, PrintModel, print_model
from trinormal.validation import (
    MAX_PRECISION,
    MIN_PRECISION,
    check_precision,
    check_vertex,
    check_winding,
)

__all__ = ["COORDINATES", "PRECISION_RANGE", "Control", "Explorer", "Text"]

#: Smallest and largest number of decimal places the precision control offers.
PRECISION_RANGE: tuple[int, int] = (MIN_PRECISION, MAX_PRECISION)

_WINDING_OPTIONS = tuple((w.label, w.value) for w in Winding)

_RANGE_HINT = "create the Explorer with min= and max= to widen the range"

#: What a picture of the 3D view shows besides the camera: the values its message names.
PICTURE_FIELDS = ("a", "b", "c", "winding", "show_parallelogram", "show_unit_normal")

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _picture_key(read: Callable[[str], Any]) -> tuple[Any, ...]:
    """Read the values of `PICTURE_FIELDS` by name into one comparable tuple (lists as tuples)."""
    return tuple(tuple(v) if isinstance(v, list) else v for v in map(read, PICTURE_FIELDS))


def _num(x: float) -> str:
    """Write a number for a message with as many decimals as it needs, nothing more."""
    return format_number(x, 15, trim=True)


def _name(key: str) -> str:
    return f"{key[0].upper()}.{key[1]}"


def _outside(name: str, shown: str, low: float, high: float) -> ValueError:
    return ValueError(
        f"{name} = {shown} is outside the slider range {_num(low)} to {_num(high)}; {_RANGE_HINT}"
    )


def _check_in_range(name: str, value: float, low: float, high: float) -> float:
    if value != value:
        raise ValueError(f"{name} is NaN")
    if math.isinf(value):
        raise ValueError(f"{name} is infinite; the slider range is {_num(low)} to {_num(high)}")
    if not low <= value <= high:
        raise _outside(name, _num(value), low, high)
    return value


def _check_winding(value: object) -> str:
    return check_winding(value).value


class Control:
    """One of the explorer's controls as code sees it: setting ``value`` works like moving it.

    The controls themselves (sliders, exact text boxes, the order toggle, the
    decimals) are drawn by the 3D view's ES module, so there is no second widget in
    the browser whose own rounding could come back as a move. Other attributes
    (``min``, ``max``, ``step``, ``options``) describe the control.
    """

    def __init__(
        self, read: Callable[[], Any], write: Callable[[Any], None], **attributes: Any
    ) -> None:
        self._read, self._write = read, write
        for name, value in attributes.items():
            setattr(self, name, value)

    @property
    def value(self) -> Any:
        """The control's current value."""
        return self._read()

    @value.setter
    def value(self, value: Any) -> None:
        self._write(value)

    def __repr__(self) -> str:
        return f"Control(value={self.value!r})"


class Text:
    """A piece of HTML the explorer keeps up to date (its readout, its message)."""

    def __init__(self, value: str = "") -> None:
        self.value = value

    def _repr_html_(self) -> str:
        return self.value


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
        The live explorer (one anywidget): the 3D view with its toolbar and
        readout, then a slider and an exact text box per coordinate and the
        decimals. Drag empty space to turn the view, drag a vertex (or its
        label) to move it; arrow keys and Page Up/Down move a focused vertex
        one grid step; type ``1/3`` or ``-2.35`` in a box and press Enter.
    controls : dict of str to Control
        ``"ax"`` … ``"cz"``: each coordinate as a float, with ``min``, ``max``
        and ``step``; ``"winding"``: ``"ABC"`` or ``"ACB"`` (``options`` pairs
        the labels A→B→C and A→C→B with them); ``"precision"``: 0 to 15.
        Setting ``.value`` from code works like a move; a value outside the
        range is a `ValueError`, never a clamp.
    inputs : dict of str to Control
        ``"ax"`` … ``"cz"``: each coordinate's exact text; setting ``.value``
        works like typing it (a bad value is a message, as in the box).
    result : TriangleNormal
        The current result, recomputed on every change.
    readout : Text
        U, V, N, |N|, the area, the unit normal, the plane and a status line as
        HTML, with exactly the strings of ``result.format(precision)``.
    message : Text
        Empty, or why the last typed or moved value was refused.

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
        precision = check_precision(precision)
        w = _check_winding(winding)
        texts = self._read_points({"a": a, "b": b, "c": c})

        self._texts: dict[str, str] = texts
        self._precision = precision
        self._snapshot: Snapshot | None = None
        self.result: TriangleNormal = self._compute(texts, w)

        self.readout = Text()
        self.message = Text()
        self.view = ExplorerView(
            a=[texts[k] for k in COORDINATES[0:3]],
            b=[texts[k] for k in COORDINATES[3:6]],
            c=[texts[k] for k in COORDINATES[6:9]],
            winding=w,
            step=step_text,
            bounds=[low, high],
            precision=precision,
            precision_range=list(PRECISION_RANGE),
            send_pictures=True,
        )
        self.view.add_class("trinormal-explorer")
        self.view.edit_handler = self._edit
        # a vertex, the winding or the decimals code set on the view (``ex.view.a = ...``)
        self.view.code_setter = lambda name, value: self.set(**{name: value})
        #: Where a 3D view of this explorer last looked from (its camera), for `describe`.
        self._viewer: tuple[float, float, float] | None = None
        #: The last picture a 3D view sent (`to_png`): the values it shows, and the PNG.
        self._view_picture: tuple[tuple[Any, ...], bytes] | None = None
        self.view.on_msg(self._on_view_message)
        self.controls: dict[str, Control] = {}
        self.inputs: dict[str, Control] = {}
        for key in COORDINATES:
            self.controls[key] = Control(
                partial(self._number, key),
                partial(self._slide, key),
                min=low,
                max=high,
                step=self.step,
            )
            self.inputs[key] = Control(partial(self._text_of, key), partial(self._type, key))
        self.controls["winding"] = Control(
            lambda: self.result.winding.value,
            lambda value: self.set(winding=value),
            options=_WINDING_OPTIONS,
        )
        self.controls["precision"] = Control(
            lambda: self._precision,
            lambda value: self.set(precision=value),
            min=PRECISION_RANGE[0],
            max=PRECISION_RANGE[1],
        )
        self._refresh()

    def _number(self, key: str) -> float:
        return float(exact_value(self._texts[key]))

    def _text_of(self, key: str) -> str:
        return self._texts[key]

    def _slide(self, key: str, value: Any) -> None:
        """Move a coordinate's slider to ``value`` (a number in the range) from code."""
        number = _check_in_range(_name(key), float(value), self.min, self.max)
        texts = {**self._texts, key: coordinate_text(number, _name(key))}
        self._apply(texts, self.result.winding.value, self._precision, [key])

    def _type(self, key: str, value: Any) -> None:
        """Type ``value`` in a coordinate's box from code (a bad value is a message)."""
        self._edit({key: value}, marked=[key])

    # ------------------------------------------------------------------ reading values

    def _read_points(self, points: dict[str, Any]) -> dict[str, str]:
        """Check whole vertices and return their coordinates as exact text, by key."""
        texts: dict[str, str] = {}
        for p, point in points.items():
            vertex = p.upper()
            check_vertex(point, vertex)  # three numbers in an ordered sequence, each readable
            for q, value in zip("xyz", point, strict=True):
                texts[p + q] = self._check_text(p + q, coordinate_text(value, f"{vertex}.{q}"))
        return texts

    def _check_text(self, key: str, text: str) -> str:
        value = exact_value(text, _name(key))
        if not Fraction(self.min) <= value <= Fraction(self.max):
            raise _outside(_name(key), text, self.min, self.max)
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
        marked = [key for key in COORDINATES if key[0] in points]
        marked += [k for k, v in (("winding", winding), ("precision", precision)) if v is not None]
        self._apply(texts, w, p, marked)

    # ------------------------------------------------------------------ updates

    def _apply(
        self, texts: dict[str, str], winding: str, precision: int, marked: Iterable[str] = ()
    ) -> None:
        """Recompute from exact text and bring every surface up to date; never raises.

        ``marked`` names the fields code set (a cell's ``set()``): the view records them, so a
        learner's edit of them made before now loses to the cell (`merge_edit`).
        """
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
        self._refresh(marked)

    def update(self) -> None:
        """Recompute the result from the current values and refresh every surface."""
        self._apply(self._texts, self.result.winding.value, self._precision)

    def _refresh(self, marked: Iterable[str] = ()) -> None:
        """Push the current state to the view (one update), the readout and the snapshot."""
        r, p = self.result, self._precision
        marked = list(marked)
        with self.view.hold_sync(), self.view.own_changes():
            if marked:
                self.view.mark_set(marked)
            for i, name in enumerate("abc"):
                point = [self._texts[k] for k in COORDINATES[3 * i : 3 * i + 3]]
                if getattr(self.view, name) != point:
                    setattr(self.view, name, point)
            self.view.winding = r.winding.value
            self.view.precision = p
            self.view.state = view_state(r, p)
            self.view.message = self.message.value
        self.readout.value = readout_html(r, p)
        if self._snapshot is not None:
            self._snapshot.update(r, p)

    def _refuse(self, error: Exception) -> None:
        self.message.value = (
            '<span role="alert" style="color:#B3261E">'
            f"{html.escape(str(error), quote=False)}</span>"
        )
        with self.view.own_changes():
            self.view.message = str(error)

    def _edit(self, edit: dict[str, Any], marked: Iterable[str] = ()) -> str | None:
        """Apply one edit from the browser (or a value typed from code); return why it was refused.

        All of the edit is checked before anything moves. ``marked``: the fields code set
        this way (``ex.inputs["bx"].value = ...``), as in `_apply`.
        """
        texts = dict(self._texts)
        winding, precision = self.result.winding.value, self._precision
        toggles: dict[str, bool] = {}
        try:
            for key, value in edit.items():
                if key in COORDINATES:
                    texts[key] = self._typed_text(key, value)
                elif key == "winding":
                    winding = _check_winding(value)
                elif key == "precision":
                    precision = check_precision(value)
                elif key in ("show_parallelogram", "show_unit_normal"):
                    if not isinstance(value, bool):
                        raise ValueError(f"{key} must be true or false, got {value!r}")
                    toggles[key] = value
                else:
                    raise ValueError(f"unknown field {key!r}")
        except (TypeError, ValueError) as error:
            self._refuse(error)
            return str(error)
        with self.view.own_changes():
            for key, on in toggles.items():
                setattr(self.view, key, on)
        self._apply(texts, winding, precision, marked)
        return None

    def _typed_text(self, key: str, value: Any) -> str:
        if not isinstance(value, str):
            raise ValueError(f"{_name(key)} must be sent as text, got {value!r}")
        return self._check_text(key, coordinate_text(value, _name(key)))

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

    @property
    def picture_source(self) -> str:
        """Which picture `to_png` gives now: ``"view"`` (the 3D view's) or ``"snapshot"``.

        ``"view"`` when a 3D view of this explorer has sent its picture of the current
        state (the same A, B and C, order and toggles); ``"snapshot"`` otherwise.

        Examples
        --------
        >>> Explorer().picture_source  # no view has drawn it
        'snapshot'
        """
        return "snapshot" if self._view_png() is None else "view"

    def _view_png(self) -> bytes | None:
        """Return the last picture a 3D view sent if it shows the current state, else None."""
        picture = self._view_picture
        current = _picture_key(lambda name: getattr(self.view, name))
        return picture[1] if picture is not None and picture[0] == current else None

    def to_png(self) -> bytes:
        r"""Give the current state as a PNG: the 3D view's own picture, else a matplotlib one.

        While the explorer is shown in Jupyter, its 3D view sends the kernel the
        picture *Save picture* downloads (the view as it is on the screen, at twice
        its size there, labels included) each time that picture settles after a
        change: a cell's `set`, the end of a drag, a key, a flip, the end of a turn of
        the camera, *Reset view*, a new size. `to_png` returns that picture when one
        has arrived for the current state: the same A, B and C (their exact text),
        the same order and the same *Parallelogram* and *N/|N|* toggles.

        Otherwise it returns the matplotlib drawing of the same state (`Snapshot`,
        as `figure` shows it: the same colours, N at the same scale and label as in
        the view): when no view is shown, when there is no JavaScript (a script,
        nbconvert, a static page), or when the view has not yet drawn the current
        state. The kernel hears from the browser only between cells, so a cell that
        calls ``ex.set(...)`` and then ``ex.to_png()`` gets the matplotlib drawing,
        and so do the cells after the one that shows the explorer in *Run All*; run
        the cell again once the view shows the triangle. `picture_source` says which
        of the two you get.

        Returns
        -------
        bytes
            A PNG file.

        Examples
        --------
        No view has drawn this explorer, so the picture is the matplotlib drawing:

        >>> ex = Explorer()
        >>> ex.picture_source
        'snapshot'
        >>> ex.to_png()[:8]
        b'\x89PNG\r\n\x1a\n'
        """
        png = self._view_png()
        return self.snapshot.to_png() if png is None else png

    def render(self) -> None:
        """Bring the snapshot's pixels up to date (see `Snapshot.render`)."""
        self.snapshot.render()

    # ------------------------------------------------------------------ 3D printing

    def print_model(self, size: float = DEFAULT_SIZE, marks: str = "letters") -> PrintModel:
        """Make the printable model of the current triangle (`trinormal.printmodel.print_model`).

        Examples
        --------
        >>> len(Explorer().print_model().faces)
        270
        """
        a, b, c = ([self._texts[p + q] for q in "xyz"] for p in "abc")
        return print_model(a, b, c, winding=self.winding, size=size, marks=marks)

    def to_stl(self, path: str | Path, size: float = DEFAULT_SIZE, marks: str = "letters") -> Path:
        """Write the printable model of the current triangle as a binary STL file.

        The plate with the normal as an arrow on its front, U and V as ridges,
        A, B and C in letters (or ``marks="braille"``), the longest side ``size``
        mm. A degenerate triangle is refused with a `ValueError` saying why.

        Examples
        --------
        >>> import tempfile, os
        >>> with tempfile.TemporaryDirectory() as d:
        ...     os.path.getsize(Explorer().to_stl(os.path.join(d, "triangle.stl")))
        13584
        """
        path = Path(path)
        path.write_bytes(self.print_model(size, marks).stl())
        return path

    def to_3mf(self, path: str | Path, size: float = DEFAULT_SIZE, marks: str = "letters") -> Path:
        """Write the printable model of the current triangle as a 3MF file (see `to_stl`).

        Examples
        --------
        >>> import tempfile, os, zipfile
        >>> with tempfile.TemporaryDirectory() as d:
        ...     zipfile.is_zipfile(Explorer().to_3mf(os.path.join(d, "triangle.3mf")))
        True
        """
        path = Path(path)
        path.write_bytes(self.print_model(size, marks).three_mf())
        return path

    @property
    def alt_text(self) -> str:
        """A sentence describing the current state, for screen readers and static pages."""
        return alt_text(self.result, self._precision)

    def describe(self, viewer: Iterable[float] | None = None) -> str:
        """Say in one line which way N points, and what a viewer sees: the view's description.

        Parameters
        ----------
        viewer : sequence of 3 float, optional
            The direction from the triangle towards the viewer, such as ``(0, 0, 1)``
            (looking down the z axis, as the view's *z* button does). Without it: where
            the 3D view looks from (the view last turned, when there are several), so
            the words are the view's; before any view is drawn, what is seen from the
            triangle's front.

        Returns
        -------
        str
            The sentences of ``trinormal.explorer.describe``, the rule the 3D view
            writes under the picture.

        Examples
        --------
        >>> ex = Explorer()
        >>> ex.describe()
        'N points straight up, along +z. From its front (the side N points to), A→B→C turns counter-clockwise.'
        >>> ex.set(winding="ACB")
        >>> ex.describe(viewer=(0, 0, 1))
        'N points straight down, along −z. You see the back of the triangle (N points away from you), and A→C→B turns clockwise.'
        """  # noqa: E501
        return describe(self.result, self._viewer if viewer is None else tuple(viewer))

    def _on_view_message(self, _widget: Any, content: Any, buffers: Any) -> None:
        """Keep what a 3D view sends when it settles: where it looks from, and its picture.

        ``{"viewer": [x, y, z]}`` is the direction towards its camera (`describe`);
        ``{"picture": {"a": [...], ..., "show_unit_normal": ...}}`` with one buffer, a
        PNG, is its picture and the values it shows (`to_png`).
        """
        if not isinstance(content, dict):
            return
        shown = content.get("picture")
        png = bytes(buffers[0]) if buffers else b""
        if isinstance(shown, dict) and png.startswith(_PNG_SIGNATURE):
            self._view_picture = (_picture_key(shown.get), png)
        viewer = content.get("viewer")
        if (
            isinstance(viewer, list)
            and len(viewer) == 3
            and all(isinstance(x, (int, float)) and math.isfinite(x) for x in viewer)
        ):
            self._viewer = (float(viewer[0]), float(viewer[1]), float(viewer[2]))

    # ------------------------------------------------------------------ display

    @property
    def widget(self) -> ExplorerView:
        """The whole explorer, one widget: the 3D view, its readout and its controls."""
        return self.view

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        """Show the live explorer in Jupyter, with a plain-text summary for everywhere else."""
        shown = self.view._repr_mimebundle_(**kwargs)
        data, metadata = shown if isinstance(shown, tuple) else (shown, None)
        bundle: dict[str, Any] = {**(data or {}), "text/plain": self.summary()}
        return bundle if metadata is None else (bundle, metadata)

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
        """Show the state exactly, as the call that recreates it.

        Examples
        --------
        >>> ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
        >>> ex  # doctest: +NORMALIZE_WHITESPACE
        Explorer(a=('0.1', '0.2', '0.3'), b=('1/3', 0, 0), c=(0, '2.35', 0),
                 winding='ABC', precision=4)
        """
        e = self.result.exact
        return (
            f"Explorer(a={exact_literals(e.a)}, b={exact_literals(e.b)}, c={exact_literals(e.c)}, "
            f"winding={self.winding.value!r}, precision={self.precision})"
        )
