"""The live 3D view in Jupyter: an anywidget whose traitlets the kernel and the browser share.

[`ExplorerView`][trinormal.explorer.ExplorerView] holds state and nothing else; the ES module
``trinormal/explorer/static/explorer.js`` (built from ``js/explorer/`` with
three.js) renders it. The same sources render the site's calculator with a small
model object fed by the site's JavaScript core, so the view is written once.

State flows one way, kernel → traitlets → view. The browser never writes a
traitlet: a learner's move (a drag, an arrow key, a slider, a typed value, a
toolbar toggle) reaches the kernel as an *identified edit*, a custom message
``{"edit": {...}, "seq": n, "view": id, "base": version}``. The edit names only
what the learner changed: a coordinate by its key (``{"ay": "2/7"}``; a drag
names each coordinate it moved, up to three), the winding, the decimals or a
toggle. So two views of one explorer that edit different coordinates of one
vertex at once both land, and for one coordinate the edit that reaches the
kernel last wins. ``version`` counts the kernel's own changes (a cell calling
``ex.set``, a trait set from code) and ``set_at`` says, per field, at which
version the kernel last set it (a vertex set from code sets its three
coordinates). The kernel keeps every field of an edit that no cell set since
the edit's ``base``; a field a cell set after it keeps the cell's value
(``merge_edit`` in ``trinormal.explorer.state``). So a drag of B made while a
cell sets C keeps both, and a browser's late answer never overwrites what a cell
set. The kernel applies the kept part with the exact core and answers in one
update: the new values, ``state`` and ``last_edit`` (which edit this was,
whether it was taken, and which fields a cell had overwritten).

Once an [`Explorer`][trinormal.widgets.Explorer] owns the view, a vertex, the
winding or the decimals set on the view from code go through
[`Explorer.set`][trinormal.widgets.Explorer.set]; what the Explorer computes or
fixes when it is created (``state``, ``bounds``, ``step``, ...) cannot be set
from code: that raises, it is never silently undone.

Examples
--------
>>> v = ExplorerView()
>>> v.version
0
>>> v.a = ["0.5", "0", "0"]  # set from code: a new version
>>> v.version
1
>>> v.set_at["ax"], v.set_at.get("bx")
(1, None)
>>> v._handle_custom_msg({"edit": {"ax": "2", "bx": "2"}, "seq": 1, "view": "w", "base": 0}, [])
>>> v.a, v.b, v.last_edit["overwritten"]  # A was set after version 0: the cell's A stays
(['0.5', '0', '0'], ['2', '0', '0'], ['ax'])
>>> v._handle_custom_msg({"edit": {"bz": "1/3"}, "seq": 1, "view": "w2", "base": 1}, [])
>>> v.b, v.last_edit["ok"], v.version  # taken; a browser edit is not a new version
(['2', '0', '1/3'], True, 1)
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import anywidget
import traitlets

from trinormal.colors import palette
from trinormal.explorer.state import merge_edit
from trinormal.fields import fields_spec
from trinormal.validation import MAX_PRECISION, MIN_PRECISION

__all__ = ["BUNDLE", "COORDINATES", "EDIT_FIELDS", "WAITING", "ExplorerView"]

#: Keys of the nine coordinates, in order: A's x, y, z, then B's, then C's.
COORDINATES: tuple[str, ...] = tuple(p + q for p in "abc" for q in "xyz")

#: The traits a learner can change in the browser (through an edit) and code can set.
EDITABLE = ("a", "b", "c", "winding", "precision", "show_parallelogram", "show_unit_normal")

#: What an edit may name: a coordinate (its new exact text), or one of the other editable traits.
EDIT_FIELDS: tuple[str, ...] = (*COORDINATES, *EDITABLE[3:])

#: An edit handler: applies one edit and returns why it was refused, or None.
EditHandler = Callable[[dict[str, Any]], "str | None"]

#: The owner's setter: sets one of `OWNED` from code (`Explorer.set`), or raises.
CodeSetter = Callable[[str, Any], None]

#: The traits an owner (`Explorer`) sets itself when code sets them on the view.
OWNED = ("a", "b", "c", "winding", "precision")

#: The traits an owner computes or fixes when it is created, and how to change them instead.
FIXED = {
    "step": "create the Explorer with step=",
    "bounds": "create the Explorer with min= and max=",
    "precision_range": "the decimals run from 0 to 15",
    "state": "the Explorer computes it; change the triangle with ex.set(...)",
    "fields": "the readout's rows come from trinormal.fields with the state",
    "message": "the Explorer writes it when it refuses a value",
    "version": "the Explorer counts its own changes",
    "set_at": "the Explorer records what code set",
    "last_edit": "the Explorer answers the browser's edits",
}

#: What the readout says while a learner's edits wait for a busy kernel.
WAITING = "Waiting for the kernel…"

#: The bundled ES module (three.js included), built by ``make js``.
BUNDLE = Path(__file__).with_name("static") / "explorer.js"


class ExplorerView(anywidget.AnyWidget):
    """The 3D view of one triangle: turn it, zoom it, drag its vertices.

    Traitlets
    ---------
    a, b, c : list of 3 str
        Each vertex's coordinates as exact text.
    winding : {"ABC", "ACB"}
        The order of the vertices.
    step : str
        The grid a drag or an arrow key snaps to, such as ``"0.1"``.
    bounds : list of 2 float
        The range the view may move a coordinate in.
    show_parallelogram, show_unit_normal, show_readout : bool
        What the view draws besides the triangle, U, V and N.
    palette : dict
        The colour code, from [`trinormal.colors.palette`][trinormal.colors.palette].
    fields : list of dict
        The output rows, from [`trinormal.fields.fields_spec`][trinormal.fields.fields_spec].
    state : dict
        What to draw and print, from
        [`trinormal.explorer.state.view_state`][trinormal.explorer.view_state].
    show_controls : bool
        Whether the sliders and exact text boxes are shown under the view.
    precision_range : list of 2 int
        The decimals the precision control offers.
    message : str
        Empty, or why the last edit was refused (shown in the view).
    version : int
        Counts the changes made by the kernel; browser edits name the version
        they were made against.
    set_at : dict of str to int
        Per field (``"ax"`` … ``"cz"``, ``"winding"``, ...), the version at which
        the kernel last set it.
    last_edit : dict
        The last edit the kernel answered: ``view``, ``seq``, ``ok``, ``stale``
        (a cell had set some of its fields since), ``overwritten`` (those fields)
        and ``error``.
    waiting : str
        What the readout says while the view's edits wait for a busy kernel.
    send_pictures : bool
        Whether the view sends the kernel its picture each time it settles after a
        change, as ``{"picture": {...}}`` with the PNG as a buffer (`Explorer.to_png`
        keeps it). Off by default; an `Explorer` turns it on for its view.
    """

    _esm = BUNDLE

    a = traitlets.List(traitlets.Unicode(), default_value=["0", "0", "0"]).tag(sync=True)
    b = traitlets.List(traitlets.Unicode(), default_value=["1", "0", "0"]).tag(sync=True)
    c = traitlets.List(traitlets.Unicode(), default_value=["0", "1", "0"]).tag(sync=True)
    winding = traitlets.Unicode("ABC").tag(sync=True)
    step = traitlets.Unicode("0.1").tag(sync=True)
    bounds = traitlets.List(traitlets.Float(), default_value=[-5.0, 5.0]).tag(sync=True)
    precision = traitlets.Int(4).tag(sync=True)
    show_parallelogram = traitlets.Bool(False).tag(sync=True)
    show_unit_normal = traitlets.Bool(False).tag(sync=True)
    show_readout = traitlets.Bool(True).tag(sync=True)
    palette = traitlets.Dict(default_value=palette()).tag(sync=True)
    fields = traitlets.List(default_value=fields_spec()).tag(sync=True)
    state = traitlets.Dict().tag(sync=True)
    show_controls = traitlets.Bool(True).tag(sync=True)
    precision_range = traitlets.List(
        traitlets.Int(), default_value=[MIN_PRECISION, MAX_PRECISION]
    ).tag(sync=True)
    message = traitlets.Unicode("").tag(sync=True)
    version = traitlets.Int(0).tag(sync=True)
    set_at = traitlets.Dict().tag(sync=True)
    last_edit = traitlets.Dict().tag(sync=True)
    waiting = traitlets.Unicode(WAITING).tag(sync=True)
    send_pictures = traitlets.Bool(False).tag(sync=True)

    def __init__(self, **kwargs: Any) -> None:
        self._own = 1  # the starting values are version 0
        super().__init__(**kwargs)
        self._own = 0
        #: Applies a browser edit (set by `Explorer`); without one, edits set the traits.
        self.edit_handler: EditHandler | None = None
        #: Sets a vertex, the winding or the decimals from code (set by `Explorer`).
        self.code_setter: CodeSetter | None = None
        self.on_msg(self._on_msg)

    @traitlets.observe(*EDITABLE)
    def _kernel_changed(self, change: Any) -> None:
        if not self._own:  # a change code made on the view: edits made before it lose it
            name = change["name"]
            self.mark_set([name + q for q in "xyz"] if name in "abc" else [name])

    @traitlets.validate(*OWNED, *FIXED)
    def _set_from_code(self, proposal: Any) -> Any:
        name = proposal["trait"].name
        if self._own or self.code_setter is None:
            return proposal["value"]
        if name in FIXED:
            raise traitlets.TraitError(
                f"ExplorerView.{name} cannot be set from code: {FIXED[name]}"
            )
        self.code_setter(name, proposal["value"])  # checks and sets it, or raises
        return getattr(self, name)

    @contextmanager
    def own_changes(self) -> Iterator[None]:
        """Write traits as the view's owner or its edit handler (no new version, no check)."""
        self._own += 1
        try:
            yield
        finally:
            self._own -= 1

    def mark_set(self, fields: Iterable[str]) -> None:
        """Record that the kernel set ``fields`` now: a new version, and ``set_at`` for each."""
        with self.own_changes():
            self.version += 1
            self.set_at = {**self.set_at, **dict.fromkeys(fields, self.version)}

    def _on_msg(self, _widget: Any, content: Any, _buffers: Any) -> None:
        if isinstance(content, dict) and isinstance(content.get("print"), dict):
            self._print(content["print"])
            return
        if not isinstance(content, dict) or not isinstance(content.get("edit"), dict):
            return
        ident = {"view": str(content.get("view", "")), "seq": content.get("seq", 0)}
        base = content.get("base")
        if not isinstance(base, int) or isinstance(base, bool):
            base = -1  # an edit that names no version is refused as a whole
        edit, overwritten = merge_edit(content["edit"], base, self.set_at)
        answer = {**ident, "stale": bool(overwritten), "overwritten": overwritten}
        with self.hold_sync(), self.own_changes():
            if overwritten and not edit:
                self.last_edit = {**answer, "ok": False, "error": ""}
                return
            try:
                error = (self.edit_handler or self._set_traits)(edit)
            except Exception as problem:  # a message handler must never raise
                error = str(problem)
            self.last_edit = {**answer, "ok": error is None, "error": error or ""}

    def _print(self, request: dict[str, Any]) -> None:
        """Answer "Download for 3D printing": the STL bytes of the drawn triangle, or why not.

        The answer is ``{"printed": {"seq", "name", "error", "done"}}`` with the file as one buffer
        (``js/explorer/src/printing.js`` reads it).
        """
        from trinormal.printmodel import DOWNLOAD_NAME, MARKS, PRINT_MESSAGES, print_model

        marks = str(request.get("marks")) if request.get("marks") in MARKS else MARKS[0]
        answer = {"seq": request.get("seq", 0), "name": DOWNLOAD_NAME.format(marks=marks)}
        try:
            model = print_model(self.a, self.b, self.c, winding=self.winding, marks=marks)
        except ValueError as problem:  # degenerate, too thin, or a coordinate refused
            self.send({"printed": {**answer, "error": str(problem)}})
            return
        done = PRINT_MESSAGES["downloaded"].format(name=answer["name"])
        self.send({"printed": {**answer, "error": "", "done": done}}, buffers=[model.stl()])

    def _set_traits(self, edit: dict[str, Any]) -> str | None:
        unknown = sorted(set(edit) - set(EDIT_FIELDS))
        if unknown:
            return f"unknown field {unknown[0]!r}"
        points = {p: list(getattr(self, p)) for p in "abc"}
        for key, value in edit.items():
            if key in COORDINATES:
                points[key[0]]["xyz".index(key[1])] = value
        try:
            with self.hold_trait_notifications():  # all or nothing
                for p, point in points.items():
                    setattr(self, p, point)
                for key, value in edit.items():
                    if key not in COORDINATES:
                        setattr(self, key, value)
        except traitlets.TraitError as error:
            return str(error)
        return None
