"""trinormal: exact, robust normals of 3D triangles, for learning and teaching.

The core needs only the standard library:

>>> from trinormal import triangle_normal
>>> triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).format(4, trim=True)["unit_normal"]
'(0, 0, 1)'

Modules beyond the core import their own dependencies when you import them:
``trinormal.symbolic`` (sympy), ``trinormal.mesh`` (numpy),
``trinormal.plotting`` (matplotlib) and ``trinormal.explorer`` (ipywidgets, anywidget).
"""

from trinormal.core import (
    ARITHMETICS,
    Exact,
    Plane,
    TriangleNormal,
    Winding,
    parse_coordinate,
    triangle_normal,
)
from trinormal.display import format_number, format_vector
from trinormal.tolerances import DEFAULT_TOL

__all__ = [
    "ARITHMETICS",
    "DEFAULT_TOL",
    "Exact",
    "Plane",
    "TriangleNormal",
    "Winding",
    "format_number",
    "format_vector",
    "parse_coordinate",
    "triangle_normal",
]

__version__ = "0.1.0"
