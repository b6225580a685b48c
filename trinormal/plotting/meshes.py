"""Meshes as a renderer shows them: shaded faces, flat against smooth, culled, wrongly wound."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from trinormal.colors import ROLE_COLORS
from trinormal.plotting.camera import camera_direction, frame_cube
from trinormal.plotting.style import BACKDROP, FACECOLOR, SURFACE, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["culling_figure", "shaded_mesh_figure", "shading_figure", "winding_figure"]


def _seen(vertices: Any, faces: Any, elev: float, azim: float) -> tuple[Any, Any, Any, Any]:
    """Return the vertices (float), faces, face normals and `camera_direction` as arrays."""
    import numpy as np

    from trinormal import mesh

    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    return v, f, mesh.face_normals(v, f), camera_direction(elev, azim)


def _panel(
    fig: Figure,
    count: int,
    k: int,
    polys: Any,
    v: Any,
    view: tuple[float, float],
    zoom: float = 1.0,
) -> Any:
    """Add panel ``k`` of ``count`` in a row: ``polys`` on white, no axes, a cube around ``v``."""
    ax = fig.add_subplot(1, count, k + 1, projection="3d")
    ax.set_facecolor(FACECOLOR)
    ax.add_collection3d(polys)
    frame_cube(ax, v, zoom)
    ax.view_init(elev=view[0], azim=view[1])
    ax.set_axis_off()
    return ax


def _lit(brightness: Any, base: str = SURFACE) -> Any:
    """Colours from black (0) through ``base`` to white (1) for brightness values."""
    import numpy as np
    from matplotlib.colors import LinearSegmentedColormap

    cmap = LinearSegmentedColormap.from_list("lit", ["#101010", base, "#ffffff"])
    return cmap(np.clip(np.asarray(brightness, dtype=float), 0, 1))


@styled
def shaded_mesh_figure(
    vertices: Any,
    faces: Any,
    panels: Mapping[str, Any],
    *,
    elev: float = 25.0,
    azim: float = -60.0,
    title: str | None = None,
) -> Figure:
    """Draw one mesh several times side by side, each face filled with a brightness.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates.
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.
    panels : mapping of title to array_like, shape (F,)
        For each panel, the brightness of every face, from 0 (black) to 1 (lit);
        NaN marks a face that is not drawn (culled).
    elev, azim : float
        The camera's elevation and azimuth in degrees (matplotlib's convention).
    title : str, optional
        A title over all the panels.

    Returns
    -------
    matplotlib.figure.Figure
        The panels, with ``fig.alt_text`` set.
    """
    import matplotlib.pyplot as plt
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    v, f, normals, eye = _seen(vertices, faces, elev, azim)
    facing = normals @ eye > 0
    n = len(panels)
    fig = plt.figure(figsize=(4 * n, 4.2), facecolor=FACECOLOR)
    described = []
    for k, (name, values) in enumerate(panels.items()):
        b = np.asarray(values, dtype=float)
        keep = ~np.isnan(b)
        colors = _lit(b[keep])
        # each face's edge is stroked in its own colour to close the seams between faces; not
        # for faces turned away from the camera, which (drawn first) would line the seams
        edges = colors.copy()
        edges[~facing[keep]] = 0.0
        poly = Poly3DCollection(v[f[keep]], facecolors=colors, edgecolors=edges, linewidths=0.4)
        ax = _panel(fig, n, k, poly, v, (elev, azim), zoom=1.5)  # the mesh fills its panel
        ax.set_title(name, fontsize=13)
        drawn = int(keep.sum())
        described.append(f"{name} ({drawn} of {len(b)} faces drawn)")
    if title:
        fig.suptitle(title)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.84 if title else 0.95, wspace=0)
    fig.alt_text = "Shaded renderings of a mesh: " + "; ".join(described) + "."  # type: ignore[attr-defined]
    return fig


def _subdivide(tri: Any, k: int) -> tuple[Any, Any]:
    """Split every triangle of ``tri`` (F, 3, 3) into k² small ones.

    Returns the small triangles (F·k², 3, 3) and the barycentric weights of
    each small triangle's centre (k², 3), the same for every face.
    """
    import numpy as np

    bary = []
    for i in range(k):
        for j in range(k - i):
            bary.append([(i, j), (i + 1, j), (i, j + 1)])
            if j < k - i - 1:
                bary.append([(i + 1, j), (i + 1, j + 1), (i, j + 1)])
    w = np.array([[[1 - (a + b) / k, a / k, b / k] for a, b in t] for t in bary])  # (k², 3, 3)
    centres = w.mean(axis=1)  # (k², 3)
    small = np.einsum("sci,fid->fscd", w, tri).reshape(-1, 3, 3)
    return small, centres


@styled
def shading_figure(
    vertices: Any,
    faces: Any,
    light: Sequence[float],
    *,
    weighting: str = "angle",
    subdivisions: int = 8,
    elev: float = 20.0,
    azim: float = -50.0,
) -> Figure:
    """Flat and smooth Lambert shading of one closed mesh, side by side.

    Flat shading lights each triangle with its face normal, so every facet
    has one brightness. Smooth shading interpolates the vertex normals across
    each triangle (the way a renderer blends them between the corners), and
    here each triangle is cut into ``subdivisions²`` small pieces, each lit
    with the normalised blend of the corner normals at its centre.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
        A closed, outward-wound mesh (only faces turned towards the camera are drawn).
    light : sequence of 3 floats
        Direction towards the light (normalised here).
    weighting : {"angle", "area", "uniform"}
        How [`trinormal.mesh.vertex_normals`][trinormal.mesh.vertex_normals] averages the face
        normals.
    subdivisions : int
        How finely each triangle is cut for the smooth panel.
    elev, azim : float
        The camera, in matplotlib's angles (degrees).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels, with ``fig.alt_text`` set.
    """
    import matplotlib.pyplot as plt
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from trinormal import mesh

    v, f, fn, eye = _seen(vertices, faces, elev, azim)
    lt = np.asarray(light, dtype=float)
    lt = lt / np.linalg.norm(lt)
    vn = mesh.vertex_normals(v, f, weighting)
    seen = fn @ eye > 0
    tri = v[f[seen]]
    flat_polys, flat_b = tri, np.maximum(0.0, fn[seen] @ lt)
    small, centres = _subdivide(tri, subdivisions)
    blend = np.einsum("si,fid->fsd", centres, vn[f[seen]]).reshape(-1, 3)
    blend /= np.linalg.norm(blend, axis=1, keepdims=True)
    smooth_b = np.maximum(0.0, blend @ lt)
    fig = plt.figure(figsize=(9, 4.8), facecolor=FACECOLOR)
    panels = {
        "flat: one normal per face": (flat_polys, flat_b),
        "smooth: vertex normals blended": (small, smooth_b),
    }
    for k, (name, (polys, b)) in enumerate(panels.items()):
        lit = _lit(b)  # edges in the face colour: no seams between the small pieces
        poly = Poly3DCollection(polys, facecolors=lit, edgecolors=lit, linewidths=0.4)
        _panel(fig, 2, k, poly, v, (elev, azim)).set_title(name)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.9, wspace=0)
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Two renderings of the same mesh of {len(f)} triangles under one light. Left, flat "
        "shading: every triangle has a single brightness, so the facets show as a mosaic. "
        f"Right, smooth shading with {weighting}-weighted vertex normals blended across each "
        "triangle: the brightness changes gradually and the facets disappear, although the "
        "outline is still the same polygon."
    )
    return fig


@styled
def culling_figure(
    vertices: Any,
    faces: Any,
    *,
    camera: tuple[float, float] = (30.0, -90.0),
    side: tuple[float, float] = (30.0, 0.0),
) -> Figure:
    """Show what back-face culling removes: the camera's view, then the mesh from the side.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
        A closed, outward-wound mesh.
    camera : (elev, azim)
        The camera that decides front from back (matplotlib's angles, degrees).
    side : (elev, azim)
        A second camera, off to the side, that shows what was removed.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: the camera's view of the front faces; all faces from the
        side, front faces in the ``front`` colour and back faces in the ``back``
        colour of [`trinormal.colors`][trinormal.colors]; the front faces alone from the side.
    """
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.colors import to_rgb
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    v, f, fn, eye = _seen(vertices, faces, *camera)
    front = fn @ eye > 0
    light = eye + np.array([0.0, 0.0, 0.6])
    light /= np.linalg.norm(light)
    shade = 0.55 + 0.45 * np.abs(fn @ light)
    base = np.where(
        front[:, None], np.array(to_rgb(ROLE_COLORS["front"])), to_rgb(ROLE_COLORS["back"])
    )
    all_colours = np.clip(base * shade[:, None], 0, 1)
    panels = [
        ("the camera's view", front, camera),
        ("from the side:\nall faces", np.ones(len(f), bool), side),
        ("from the side:\nback faces culled", front, side),
    ]
    # 10 inches: shown 1000 pixels wide, it fits a notebook on a 1280-pixel projector unscaled
    fig = plt.figure(figsize=(10, 4.4), facecolor=FACECOLOR)
    for k, (name, keep, view) in enumerate(panels):
        poly = Poly3DCollection(v[f[keep]], facecolors=all_colours[keep], edgecolors="none")
        ax = _panel(fig, 3, k, poly, v, view, zoom=1.4)  # the mesh fills its panel
        ax.set_title(name)
    fig.legend(
        handles=[
            Patch(color=ROLE_COLORS["front"], label="front face (towards the camera)"),
            Patch(color=ROLE_COLORS["back"], label="back face"),
        ],
        loc="lower center",
        ncol=2,
        frameon=False,
    )
    fig.subplots_adjust(left=0, right=1, bottom=0.1, top=0.9, wspace=0)
    n_front = int(front.sum())
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Three views of a mesh of {len(f)} triangles. First, the camera's view, which shows "
        f"only the {n_front} faces whose normals point towards it. Second, the same mesh from "
        "the side with every face drawn: the half facing the camera in yellow, the other half "
        "in blue. Third, the same side view after culling: the blue back half is gone, and "
        "the camera never saw it."
    )
    return fig


@styled
def winding_figure(
    vertices: Any,
    faces: Any,
    *,
    elev: float = 29.0,
    azim: float = -47.0,
    title: str | None = None,
) -> Figure:
    """Show what a renderer does with faces wound the wrong way: lit black, or culled away.

    Two panels of the same mesh from the same camera. Left, every face lit by one
    light from behind the camera with one-sided Lambert shading, brightness
    ``max(0, n · l)`` from each face's unit normal ``n`` as stored: a face whose
    normal points away from the light is black. Right, back-face culling: only the
    faces whose normal points towards the camera are drawn, so a face wound the
    wrong way (or seen through a hole) disappears and the slate backdrop behind
    both panels shows through.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    faces : array_like of int, shape (F, 3)
    elev, azim : float
        The camera, in matplotlib's angles (degrees); the light comes from the
        camera, raised a little.
    title : str, optional
        A title over both panels.

    Returns
    -------
    matplotlib.figure.Figure
        Two panels, with ``fig.alt_text`` giving the counts of black and culled faces.
    """
    import numpy as np

    v, f, n, eye = _seen(vertices, faces, elev, azim)
    light = camera_direction(elev + 15.0, azim + 10.0)
    towards = n @ eye
    lit = np.maximum(0.0, n @ light)
    shade = 0.08 + 0.92 * lit  # one scale for both panels: a face looks the same in each
    culled = np.where(towards > 0, shade, np.nan)
    fig = shaded_mesh_figure(
        v,
        f,
        {"lit from the camera's side": shade, "back faces culled": culled},
        elev=elev,
        azim=azim,
        title=title,
    )
    for ax in fig.axes:  # the backdrop: what shows through where no face is drawn
        ax.set_facecolor(BACKDROP)
    # faces well inside the camera's half of the model (not at the outline) whose normals
    # point away from it: seen from outside they are the wrong way round
    centre = v[f].mean(axis=1) - v.mean(axis=0)
    size = np.linalg.norm(centre, axis=1)
    near = centre @ eye > 0.2 * np.where(size > 0, size, 1.0)
    dark = int((near & (towards <= 0)).sum())
    faces_text = "1 face" if dark == 1 else f"{dark} faces"
    fig.alt_text = (  # type: ignore[attr-defined]
        f"Two renderings of a mesh of {len(f)} triangles from one camera. Left, lit from the "
        f"camera's side: {faces_text} on the near side, away from the outline, "
        f"{'has its normal' if dark == 1 else 'have normals'} pointing away from the camera "
        "and show black. Right, with back faces culled: such faces are not drawn and the "
        f"slate backdrop shows through; {int((towards > 0).sum())} faces are drawn."
    )
    return fig
