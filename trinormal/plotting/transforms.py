"""Normals under a transform: a stretched cylinder, normals times M against times M⁻ᵀ."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from trinormal.colors import ROLE_COLORS
from trinormal.plotting.style import FACECOLOR, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["normal_transform_figure"]


@styled
def normal_transform_figure(sx: float = 2.0, sy: float = 1.0, count: int = 16) -> Figure:
    """Draw a cylinder seen end-on, stretched, with its normals transformed two ways.

    The cylinder's axis points at the viewer, so its surface is drawn as a
    circle and its normals lie in the picture. The stretch
    ``M = diag(sx, sy, 1)`` turns it into an elliptic cylinder.

    Parameters
    ----------
    sx, sy : float
        The stretch along x and y.
    count : int
        How many normals to draw.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: the surface and its normals; the stretched copy with the
        normals multiplied by M (black, not perpendicular); the stretched
        copy with the normals multiplied by M⁻ᵀ (the ``N`` colour, perpendicular).
        ``fig.alt_text`` gives the largest error of each.
    """
    import matplotlib.pyplot as plt
    import numpy as np

    from trinormal.display import format_number

    t = np.linspace(0, 2 * np.pi, 400)
    s = np.linspace(0, 2 * np.pi, count, endpoint=False) + np.pi / count
    p = np.stack([np.cos(s), np.sin(s)], axis=1)  # points on the unit circle
    n = p.copy()  # their outward normals
    m = np.array([sx, sy])
    q = p * m
    wrong = n * m
    right = n / m
    tangent = np.stack([-np.sin(s), np.cos(s)], axis=1) * m  # the tangent, moved with the surface

    def off(normals: Any) -> Any:
        u = normals / np.linalg.norm(normals, axis=1, keepdims=True)
        tt = tangent / np.linalg.norm(tangent, axis=1, keepdims=True)
        return np.degrees(np.abs(np.arcsin(np.clip(np.abs((u * tt).sum(1)), 0, 1))))

    err_wrong, err_right = off(wrong).max(), off(right).max()
    # 10 inches: shown 1000 pixels wide, it fits a notebook on a 1280-pixel projector unscaled
    fig, axes = plt.subplots(1, 3, figsize=(10, 4.4), facecolor=FACECOLOR)
    stretch = f"x × {format_number(sx, 2, trim=True)}"
    if sy != 1:
        stretch += f", y × {format_number(sy, 2, trim=True)}"
    panels = [
        ("the surface\nand its normals", p, n, ROLE_COLORS["N"], "-", np.ones(2)),
        ("stretched,\nnormals × M (wrong)", q, wrong, "#000000", "--", m),
        ("stretched,\nnormals × M⁻ᵀ (right)", q, right, ROLE_COLORS["N"], "-", m),
    ]
    length = 0.45
    for ax, (name, pts, vecs, col, style, scale) in zip(axes, panels, strict=True):
        ax.set_facecolor(FACECOLOR)
        ax.plot(scale[0] * np.cos(t), scale[1] * np.sin(t), color=ROLE_COLORS["A"], lw=2.5)
        u = vecs / np.linalg.norm(vecs, axis=1, keepdims=True) * length
        for (x, y), (dx, dy) in zip(pts, u, strict=True):
            ax.annotate(
                "",
                xy=(x + dx, y + dy),
                xytext=(x, y),
                arrowprops={"arrowstyle": "-|>", "color": col, "lw": 2, "linestyle": style},
            )
        ax.set_aspect("equal")
        r = max(sx, sy, 1) + length + 0.1
        ax.set_xlim(-r, r)
        ax.set_ylim(-r * 0.75, r * 0.75)
        ax.set_title(name)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle(f"A cylinder seen end-on, then stretched by M ({stretch})")
    fig.tight_layout()
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Three panels. Left: a circle, the end view of a cylinder, with {count} outward "
        f"normals at right angles to it. Middle: the cylinder stretched ({stretch}) into an "
        "ellipse, with the normals multiplied by the same matrix: black arrows that lean "
        f"away from the perpendicular by up to {format_number(err_wrong, 1)} degrees. Right: "
        "the same ellipse with the normals multiplied by the inverse transpose: every arrow "
        f"is at right angles to the surface (largest error {format_number(err_right, 1)} "
        "degrees)."
    )
    return fig
