"""Figures for the notebooks and the site: one colour code, legible from the back of a room.

Every helper returns a `matplotlib.figure.Figure` with an opaque white
background and a short text alternative in ``fig.alt_text``. The colours are
the roles of [`trinormal.colors`][trinormal.colors] (A, B, C, U, V, N, front and back faces,
the x, y and z axes), the same code the 3D explorer and the site use. Text is
at least 12 pt and lines at least 1.5 px at the size [`show`][trinormal.plotting.show] displays a
figure (100 pixels per inch of figure), and [`show`][trinormal.plotting.show] stores the picture at
twice that resolution for high-DPI screens and projectors.

The modules, each named for what it draws:

* `style` — the palette, the sizes (`STYLE`, `DISPLAY_DPI`, `SAVE_DPI`) and
  [`show`][trinormal.plotting.show];
* `triangle` — [`right_hand_rule_figure`][trinormal.plotting.right_hand_rule_figure];
* `charts` — [`component_bar_chart`][trinormal.plotting.component_bar_chart] and
  [`precision_error_figure`][trinormal.plotting.precision_error_figure];
* `meshes` — [`shaded_mesh_figure`][trinormal.plotting.shaded_mesh_figure],
  [`shading_figure`][trinormal.plotting.shading_figure],
  [`culling_figure`][trinormal.plotting.culling_figure] and
  [`winding_figure`][trinormal.plotting.winding_figure];
* `transforms` — [`normal_transform_figure`][trinormal.plotting.normal_transform_figure];
* `camera` — `camera_direction`, the unit vector towards matplotlib's camera.
"""

from trinormal.plotting.camera import camera_direction as camera_direction
from trinormal.plotting.charts import component_bar_chart, precision_error_figure
from trinormal.plotting.meshes import (
    culling_figure,
    shaded_mesh_figure,
    shading_figure,
    winding_figure,
)
from trinormal.plotting.style import (
    AXIS_COLORS,
    DISPLAY_DPI,
    FACECOLOR,
    PALETTE,
    SAVE_DPI,
    STYLE,
    SURFACE,
    show,
)
from trinormal.plotting.transforms import normal_transform_figure
from trinormal.plotting.triangle import right_hand_rule_figure

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
