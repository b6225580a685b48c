"""Where a 3D figure's camera looks from, and the cube of space it frames."""

from __future__ import annotations

from typing import Any

__all__ = ["camera_direction", "frame_cube"]


def camera_direction(elev: float, azim: float) -> Any:
    """Return the unit vector from the scene towards a far camera, in matplotlib's angles.

    Parameters
    ----------
    elev, azim : float
        Elevation and azimuth in degrees, as in ``Axes3D.view_init``.

    Returns
    -------
    ndarray, shape (3,)

    Examples
    --------
    >>> [round(float(x), 6) for x in camera_direction(90, 0)]
    [0.0, 0.0, 1.0]
    """
    import numpy as np

    e, a = np.radians(elev), np.radians(azim)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def frame_cube(ax: Any, points: Any, zoom: float = 1.0) -> None:
    """Set equal scales on a 3D axes: the smallest cube around ``points`` (an (n, 3) array).

    ``zoom`` enlarges the cube's picture in its panel (``Axes3D.set_box_aspect``).
    """
    lo, hi = points.min(axis=0), points.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    for setlim, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid, strict=True):
        setlim(m - half, m + half)
    ax.set_box_aspect((1, 1, 1), zoom=zoom)
