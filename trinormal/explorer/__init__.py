"""The explorer: a live 3D view of a triangle for JupyterLab and the site.

Rooms:

* `state` — exact coordinates as text, grid snapping,
  and [`view_state`][trinormal.explorer.view_state], what the 3D view draws;
* `readout` — the readout rows, HTML, summary and text
  alternative, all from ``TriangleNormal.format``;
* `describe` — the view in words (which way N points, which side the viewer
  sees, which way the order turns), the rule the 3D view and ``Explorer.describe`` share;
* `figure` — the static matplotlib snapshot;
* `view` — the anywidget that shares state with the
  ES module ``static/explorer.js`` (built from ``js/explorer/``);
* `widget` — [`Explorer`][trinormal.explorer.Explorer], which ties the view,
  sliders, text boxes and readout to the exact core.
"""

from trinormal._optional import missing_extra

try:
    from trinormal.explorer.state import view_state
    from trinormal.explorer.view import ExplorerView
    from trinormal.explorer.widget import COORDINATES, PRECISION_RANGE, Explorer
except ModuleNotFoundError as exc:  # anywidget, ipywidgets, numpy or matplotlib
    raise missing_extra(exc, __name__) from exc

__all__ = ["COORDINATES", "PRECISION_RANGE", "Explorer", "ExplorerView", "view_state"]
