"""Compatibility: the explorer now lives in [`trinormal.explorer`][trinormal.explorer].

``from trinormal.widgets import Explorer`` keeps working.

Examples
--------
>>> from trinormal.widgets import Explorer
>>> Explorer().result.normal
(0.0, 0.0, 1.0)
"""

from __future__ import annotations

from trinormal.explorer import COORDINATES, PRECISION_RANGE, Explorer

__all__ = ["COORDINATES", "PRECISION_RANGE", "Explorer"]
