"""The live 3D view in Jupyter: an anywidget whose traitlets the kernel and the browser share.

[`ExplorerView`][trinormal.explorer.ExplorerView] holds state and nothing else; the ES module
``trinormal/explorer/static/explorer.js`` (built from ``js/explorer/`` with
three.js) renders it. The same module renders the site's calculator with a small
model object fed by the site's JavaScript core, so the view is written once.

State flows one way, kernel → traitlets → view, plus the learner's moves, view
→ traitlets → kernel: a drag or an arrow key writes the moved vertex's
coordinates as exact grid text (``"0.3"``) into ``a``, ``b`` or ``c``; the
kernel recomputes with the exact core and answers with ``state``.
"""

from __future__ import annotations

from pathlib import Path

import anywidget
import traitlets

from trinormal.colors import palette
from trinormal.fields import fields_spec

__all__ = ["BUNDLE", "ExplorerView"]

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
