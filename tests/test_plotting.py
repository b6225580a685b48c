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


def _screen(ax, p):
    """Pixel position (column, row from the top) of the 3D point p in the drawn figure."""
    from mpl_toolkits.mplot3d import proj3d

    x, y, _ = proj3d.proj_transform(*p, ax.get_proj())
    col, row = ax.transData.transform((x, y))
    return np.array([col, ax.figure.bbox.height - row])


def _curl_ink(winding):
    """Where the N-coloured ink near A lies: angle (0 along AB, 1 along AC) and distance.

    Looks only at the rendered pixels: each pixel of N's colour is mapped back into the
    triangle's plane (through the projected corners), and those within 0.55 of A in space
    and inside the angle BAC are kept, with their angle from AB as a fraction of angle BAC.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    pts = ((1, 1, 1), (2, 1, 1), (1, 2, 2))
    fig = plotting.right_hand_rule_figure(*pts, winding=winding)
    FigureCanvasAgg(fig)  # the figure is built without pyplot: give it a raster canvas
    img = pixels(fig)
    ax = fig.axes[0]
    a, b, c = (_screen(ax, p) for p in pts)
    n_colour = np.array(matplotlib.colors.to_rgb(colors.ROLE_COLORS["N"]))
    rows, cols = np.nonzero(np.abs(img - n_colour).sum(axis=-1) < 0.25)
    d = np.stack([cols, rows], axis=1) - a
    st = np.linalg.solve(np.stack([b - a, c - a], axis=1), d.T).T  # plane coordinates
    A, B, C = (np.array(p, dtype=float) for p in pts)
    q = st[:, :1] * (B - A) + st[:, 1:] * (C - A)  # the pixel's point in space, from A
    ab, ac = B - A, C - A
    angle = np.arctan2(np.linalg.norm(np.cross(ab, q), axis=1), q @ ab)
    frac = angle / np.arctan2(np.linalg.norm(np.cross(ab, ac)), ab @ ac)
    dist = np.linalg.norm(q, axis=1)
    keep = (dist < 0.55) & (st >= 0).all(axis=1)
    return frac[keep], dist[keep]


def _widths(frac, dist, bins=20):
    """The radial width of the ink in each angular bin (0 for an empty bin)."""
    k = np.clip((frac * bins).astype(int), 0, bins - 1)
    return np.array([np.ptp(dist[k == i]) if (k == i).any() else 0.0 for i in range(bins)])


def test_the_curl_arrowhead_shows_which_way_each_winding_turns():
    """A→B→C curls from AB to AC; A→C→B from AC to AB: visibly, in pixels.

    The same arc is drawn for both windings: a bare line (the tail) from U, then a wide
    head pointing at V. Seen as widths along the angle BAC, the widest bin is the head,
    and the thin bins lie mostly on the U side of it. A head no wider than the arc's line
    (a blob of a few pixels) fails, and so does a head at the wrong end.
    """
    abc, acb = _widths(*_curl_ink("ABC")), _widths(*_curl_ink("ACB"))
    line = min(np.percentile(w[w > 0], 25) for w in (abc, acb))  # the arc line's own width
    assert abc.max() > 3 * line and acb.max() > 3 * line, (abc.round(3), acb.round(3))

    def tail_towards_ab(widths):
        """Thin bins on AB's side of the widest one, minus those on AC's side."""
        k, thin = widths.argmax(), (widths > 0) & (widths < 1.5 * line)
        return int(thin[:k].sum()) - int(thin[k + 1 :].sum())

    assert tail_towards_ab(abc) >= 3, abc.round(3)  # tail at AB = U, head towards AC = V
    assert tail_towards_ab(acb) <= -3, acb.round(3)  # tail at AC = U, head towards AB = V


def test_n_is_drawn_at_its_true_length_or_labelled_with_its_scale():
    import math

    def drawn_n(fig):
        ax = fig.axes[0]
        (label,) = [t.get_text().strip() for t in ax.texts if "N" in t.get_text()]
        from mpl_toolkits.mplot3d.art3d import Line3DCollection

        n_hex = colors.ROLE_COLORS["N"].lower()
        (quiver,) = [
            q
            for q in ax.collections
            if isinstance(q, Line3DCollection)
            and matplotlib.colors.to_hex(q.get_color()[0]) == n_hex
        ]
        shaft = np.array(quiver._segments3d[0])  # the first segment of a 3D quiver is its shaft
        return label, float(np.linalg.norm(shaft[1] - shaft[0]))

    # |N| = √2 next to edges of about 1.4: true length, plain label
    fig = plotting.right_hand_rule_figure((1, 1, 1), (2, 1, 1), (1, 2, 2))
    label, length = drawn_n(fig)
    assert label == "N" and length == pytest.approx(math.sqrt(2), rel=1e-9)
    assert "N is drawn at its true length" in fig.alt_text
    # |N| = 400 next to edges of about 23: scaled, and the label says by how much
    fig = plotting.right_hand_rule_figure((0, 0, 0), (20, 0, 0), (0, 20, 0))
    label, length = drawn_n(fig)
    assert label == "N × 1/16"
    assert length == pytest.approx(400 / 16, rel=1e-9)
    assert f"labelled {label}" in fig.alt_text
    # a tiny triangle: N is far shorter than its edges, drawn longer and labelled so
    fig = plotting.right_hand_rule_figure((0, 0, 0), (0.01, 0, 0), (0, 0.01, 0))
    label, length = drawn_n(fig)
    assert label.startswith("N × ") and label[4:].isdigit()
    assert length == pytest.approx(1e-4 * int(label[4:]), rel=1e-9)
