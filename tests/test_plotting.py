"""trinormal.plotting: every figure shows its point, legibly, in the project's colours."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from trinormal import colors, mesh, plotting


def pixels(fig):
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba(), dtype=float)[..., :3] / 255


def panels(fig, n):
    img = pixels(fig)
    w = img.shape[1] // n
    return [img[:, i * w : (i + 1) * w] for i in range(n)]


def test_flat_and_smooth_shading_differ_visibly():
    v, f = mesh.icosphere(1)
    flat, smooth = panels(plotting.shading_figure(v, f, (0.4, -0.5, 0.75)), 2)
    assert np.abs(flat - smooth).mean() > 0.01

    def distinct(img):
        return len(np.unique((img * 255).astype(int).reshape(-1, 3), axis=0))

    # the smooth panel blends: many more shades than the flat panel's one per face
    assert distinct(smooth) > 3 * distinct(flat)


def test_culling_panels_differ():
    v, f = mesh.torus()
    _camera, side_all, side_culled = panels(plotting.culling_figure(v, f), 3)
    assert np.abs(side_all - side_culled).mean() > 0.005
    back = np.array(matplotlib.colors.to_rgb(colors.ROLE_COLORS["back"]))

    # back faces (blue family) are drawn in the side view of all faces, and nowhere else
    def bluish(img):
        return int((np.abs(img - back * 0.8).sum(axis=2) < 0.35).sum())

    assert bluish(side_all) > 20 * max(1, bluish(side_culled))


def test_normal_transform_figure_states_both_errors():
    fig = plotting.normal_transform_figure(sx=2.0)
    assert "largest error 0.0 degrees" in fig.alt_text
    assert "up to 34.7 degrees" in fig.alt_text


def test_one_colour_code():
    assert tuple(colors.ROLE_COLORS[k] for k in "xyz") == plotting.AXIS_COLORS
    fig = plotting.right_hand_rule_figure((0, 0, 0), (1, 0, 0), (0, 1, 0))
    ax = fig.axes[0]
    text_colours = {t.get_text().strip(): t.get_color() for t in ax.texts}
    for role in "ABCUVN":
        assert text_colours[role] == colors.ROLE_COLORS[role], role


def test_text_is_at_least_12_points():
    figs = [
        plotting.right_hand_rule_figure((0, 0, 0), (1, 0, 0), (0, 1, 0)),
        plotting.component_bar_chart({"N": (0, -1, 1)}),
        plotting.normal_transform_figure(),
        plotting.precision_error_figure(
            {"float32": [0.1, 0.01]}, {"float32": [1e-7, 1e-6]}, tol=1e-12
        ),
    ]
    for fig in figs:
        fig.canvas.draw()
        sizes = [
            t.get_fontsize() for t in fig.findobj(matplotlib.text.Text) if t.get_text().strip()
        ]
        assert sizes and min(sizes) >= 12, (fig.alt_text[:40], min(sizes))


def test_show_stores_a_high_dpi_png_with_alt_text(monkeypatch):
    shown = []
    monkeypatch.setattr("IPython.display.display", lambda obj: shown.append(obj))
    fig = plotting.component_bar_chart({"N": (0, 0, 1)})
    plotting.show(fig)
    (image,) = shown
    assert image.alt.startswith("Bar chart")
    assert image.width == round(7 * plotting.DISPLAY_DPI)
    import struct

    png_width = struct.unpack(">I", image.data[16:20])[0]
    assert png_width == 7 * plotting.SAVE_DPI == 2 * image.width
    with pytest.raises(ValueError, match="text alternative"):
        plotting.show(plotting.component_bar_chart({"N": (0, 0, 1)}), alt="")
