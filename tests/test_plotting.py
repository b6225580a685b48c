"""trinormal.plotting: every figure shows its point, legibly, in the project's colours."""

from __future__ import annotations

import itertools

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

    def gradual(img):
        """Neighbouring pixels of the mesh whose brightness differs by a small, nonzero step."""
        g = img.mean(axis=2)
        step = np.abs(np.diff(g, axis=1))
        on_mesh = (img.min(axis=2) < 0.99)[:, 1:]
        return int(((step > 0) & (step < 0.02) & on_mesh).sum())

    # flat: one brightness per face, so steps are zero inside a face and jumps at its edges;
    # smooth: the brightness changes a little from pixel to pixel everywhere
    assert gradual(smooth) > 4 * gradual(flat)


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


def test_right_hand_rule_pair_differs_only_where_the_winding_does():
    pts = ((1, 1, 1), (2, 1, 1), (1, 2, 2))
    abc = plotting.right_hand_rule_figure(*pts).axes[0]
    acb = plotting.right_hand_rule_figure(*pts, winding="ACB").axes[0]
    # the same box, so the triangle does not seem to move between the two pictures
    for get in ("get_xlim", "get_ylim", "get_zlim"):
        assert getattr(abc, get)() == pytest.approx(getattr(acb, get)())

    # the camera sees the front (yellow) of A→B→C and the back (sky blue) of A→C→B
    def face(ax):
        return matplotlib.colors.to_hex(ax.collections[0].get_facecolor()[0], keep_alpha=False)

    assert face(abc) == colors.ROLE_COLORS["front"].lower()
    assert face(acb) == colors.ROLE_COLORS["back"].lower()
    # the curl from U to V is drawn in N's colour, as in the 3D explorer
    (arc,) = abc.lines
    assert matplotlib.colors.to_hex(arc.get_color()) == colors.ROLE_COLORS["N"].lower()


def test_right_hand_rule_tick_labels_do_not_crowd():
    fig = plotting.right_hand_rule_figure((1, 1, 1), (2, 1, 1), (1, 2, 2))
    fig.canvas.draw()
    ax = fig.axes[0]
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        labels = [t for t in axis.get_ticklabels() if t.get_text() and t.get_visible()]
        assert len(labels) <= 6, len(labels)
        boxes = [t.get_window_extent() for t in labels]
        for a, b in itertools.pairwise(boxes):
            assert not a.overlaps(b), (a, b)


def test_multi_panel_figures_fit_a_projected_notebook():
    """Shown at 100 px per inch, no figure is wider than 1000 px: unscaled at 1280 px."""
    v, f = mesh.torus()
    sv, sf = mesh.icosphere(1)
    for fig in (
        plotting.normal_transform_figure(),
        plotting.culling_figure(v, f),
        plotting.shading_figure(sv, sf, (0.4, -0.5, 0.75)),
        plotting.right_hand_rule_figure((0, 0, 0), (1, 0, 0), (0, 1, 0)),
    ):
        assert fig.get_figwidth() <= 10, fig.alt_text[:40]
        fig.canvas.draw()
        sizes = [
            t.get_fontsize() for t in fig.findobj(matplotlib.text.Text) if t.get_text().strip()
        ]
        assert min(sizes) >= 12, fig.alt_text[:40]
