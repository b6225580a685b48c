"""The 3D view of a whole mesh in Jupyter: an anywidget on the site's mesh view.

[`MeshView`][trinormal.mesh.widget.MeshView] draws a mesh with the same view as the
site's "Check a mesh" page (the mesh view in ``trinormal/explorer/static/explorer.js``, the
one bundle of both 3D views, built from ``js/explorer/src/`` with three.js) and the same
colour code: the front of each face in the ``front`` colour, its back in the ``back`` colour,
faces to flip outlined, the rims of holes and non-manifold edges drawn thick, face normals
as short arrows (a sample of at most ``max_arrows`` faces on big models), vertex normals on
request, flat or smooth shading, back-face culling. Click a face and the kernel answers with
its three vertices, its exact normal and its area from
[`trinormal.triangle_normal`][trinormal.core.triangle_normal], printed by the package's
formatter.

Geometry travels as binary buffers (float64 positions, uint32 faces), not JSON lists: a big
model reaches the browser as its arrays' bytes, not as text. The view centres and scales
the coordinates in float64 before drawing in float32 (tiny and huge models draw); what the
readout prints comes from the kernel, from the vertices the view was given.

Importing this module needs anywidget (the ``notebooks`` extra); ``trinormal.mesh`` itself
needs numpy only.
"""

from __future__ import annotations

from pathlib import PurePath
from typing import Any

from trinormal._optional import missing_extra

try:
    import anywidget
    import numpy as np
    import numpy.typing as npt
    import traitlets
except ModuleNotFoundError as exc:  # anywidget (the notebooks extra) or numpy
    raise missing_extra(exc, __name__) from exc

from trinormal.colors import palette
from trinormal.explorer.view import BUNDLE
from trinormal.mesh.normals import face_normals, vertex_normals
from trinormal.mesh.report import MeshReport, check
from trinormal.mesh.selection import PRECISION, SELECTION, face_selection, selection_text
from trinormal.mesh.welding import weld
from trinormal.validation import check_precision

__all__ = ["MAX_ARROWS", "MESH_BUNDLE", "MeshView", "face_selection", "selection_text"]

#: The bundled ES module of the mesh view: the explorer's own (both views and one three.js in
#: one file, built by ``make js``); the ``_view`` trait tells it which view to draw.
MESH_BUNDLE = BUNDLE

#: Most face-normal arrows drawn by default: every face up to this many, a sample above.
MAX_ARROWS = 2000


def _buffer(array: Any, dtype: Any) -> bytes:
    """Little-endian bytes of an array, C order: what the view reads as a typed array."""
    return np.ascontiguousarray(array, dtype=np.dtype(dtype).newbyteorder("<")).tobytes()


def _edge_sides(faces: npt.NDArray[np.intp], edges: Any, n_vertices: int) -> npt.NDArray[np.intp]:
    """One face side ``3 * face + k`` (the edge from corner k to corner k + 1) per edge.

    An edge is matched in either direction; where several faces share it, the first side wins.
    """
    pairs = np.asarray(edges, dtype=np.intp).reshape(-1, 2)
    if not len(pairs) or not len(faces):
        return np.zeros(0, dtype=np.intp)
    start = faces.reshape(-1)
    end = faces[:, [1, 2, 0]].reshape(-1)
    side_key = np.minimum(start, end) * n_vertices + np.maximum(start, end)
    edge_key = pairs.min(axis=1) * n_vertices + pairs.max(axis=1)
    order = np.argsort(side_key, kind="stable")
    at = np.searchsorted(side_key[order], edge_key)
    at = np.minimum(at, len(order) - 1)
    found = side_key[order[at]] == edge_key
    out: npt.NDArray[np.intp] = np.unique(order[at[found]])
    return out


def _about(name: str | None, report: MeshReport) -> dict[str, Any]:
    """Return the ``about`` trait: the model's name and what the description says of each piece."""
    keys = ("faces", "closed", "outward", "faces_to_flip")  # no volume: JSON has no inf
    pieces = [{k: getattr(c, k) for k in keys} for c in report.components]
    return {"name": name or "", "pieces": pieces}


class MeshView(anywidget.AnyWidget):
    """A live 3D view of a mesh: its two sides, its normals, and what is wrong with it.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertex coordinates (or pass a [`MeshData`][trinormal.mesh.MeshData] from
        [`read_mesh`][trinormal.mesh.read_mesh] and no ``faces``).
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle, in winding order.
    report : MeshReport, optional
        The mesh's [`check`][trinormal.mesh.check] report, if already made.
    name : str, optional
        What the view's description calls the model; by default the file's name (without
        its folder) of a ``MeshData``, and "The model" for arrays.
    precision : int, default 4
        Decimal places of the readout of a clicked face.
    max_arrows : int, default `MAX_ARROWS`
        Most face-normal arrows: every face if the mesh has no more, else an evenly
        spread sample of this many.
    **kwargs
        Initial values of the traitlets below (``cull=True``, ``smooth=True`` ...).

    Traitlets
    ---------
    positions, faces : bytes
        The vertices as float64 and the faces as uint32, little-endian.
    flipped, boundary, non_manifold : bytes
        int32: the faces to flip; one face side ``3 * face + k`` per boundary and
        non-manifold edge.
    arrow_faces, arrow_normals : bytes
        int32 faces that get an arrow, and their unit normals as float32 (zero for a
        degenerate face, which gets no arrow).
    vertex_normals : bytes
        float32 angle-weighted unit vertex normals (smooth shading, vertex arrows).
    cull, smooth, show_face_normals, show_vertex_normals : bool
        Back-face culling, smooth shading, face and vertex normal arrows.
    about : dict
        What the description under the view names: ``name`` (the model's, "" for none) and
        ``pieces``, one dict per piece of the report (``faces``, ``closed``, ``outward``,
        ``faces_to_flip``: `ComponentReport`'s), as the site's "Check a mesh" page gives
        its view.
    picked : int
        The face last clicked (-1: none); setting it from code selects a face too.
    selection : dict
        The readout of the picked face (see `face_selection`).

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> view = MeshView(*cube())
    >>> view.n_faces, len(view.faces) // 4, len(view.positions) // 8
    (12, 36, 24)
    >>> view.about
    {'name': '', 'pieces': [{'faces': 12, 'closed': True, 'outward': True, 'faces_to_flip': 0}]}
    >>> from trinormal.mesh import read_mesh, sample_path
    >>> MeshView(read_mesh(sample_path())).about["name"]
    'damaged_ball.obj'
    >>> view.picked = 3
    >>> view.selection["title"]
    'Face 3: vertices 0, 5, 4 as A, B, C'
    >>> [value for label, value, role in view.selection["rows"] if label == "N = U × V"]
    ['(0.0000, -4.0000, 0.0000)']
    """

    _esm = MESH_BUNDLE
    #: Which view of the bundle draws this widget (the explorer's widgets have no ``_view``).
    _view = traitlets.Unicode("mesh").tag(sync=True)

    positions = traitlets.Bytes(b"").tag(sync=True)
    faces = traitlets.Bytes(b"").tag(sync=True)
    flipped = traitlets.Bytes(b"").tag(sync=True)
    boundary = traitlets.Bytes(b"").tag(sync=True)
    non_manifold = traitlets.Bytes(b"").tag(sync=True)
    arrow_faces = traitlets.Bytes(b"").tag(sync=True)
    arrow_normals = traitlets.Bytes(b"").tag(sync=True)
    vertex_normals = traitlets.Bytes(b"").tag(sync=True)
    revision = traitlets.Int(0).tag(sync=True)
    palette = traitlets.Dict(default_value=palette()).tag(sync=True)
    cull = traitlets.Bool(False).tag(sync=True)
    smooth = traitlets.Bool(False).tag(sync=True)
    show_face_normals = traitlets.Bool(True).tag(sync=True)
    show_vertex_normals = traitlets.Bool(False).tag(sync=True)
    picked = traitlets.Int(-1).tag(sync=True)
    selection = traitlets.Dict().tag(sync=True)
    precision = traitlets.Int(PRECISION).tag(sync=True)
    about = traitlets.Dict().tag(sync=True)

    def __init__(
        self,
        vertices: Any,
        faces: npt.ArrayLike | None = None,
        *,
        report: MeshReport | None = None,
        name: str | None = None,
        precision: int = PRECISION,
        max_arrows: int = MAX_ARROWS,
        **kwargs: Any,
    ) -> None:
        super().__init__(precision=precision, **kwargs)
        if isinstance(max_arrows, bool) or not isinstance(max_arrows, int) or max_arrows < 0:
            raise ValueError(f"max_arrows must be a whole number, 0 or more, got {max_arrows!r}")
        self.max_arrows = max_arrows
        self.set_mesh(vertices, faces, report=report, name=name)
        self.observe(self._on_picked, names="picked")
        self.observe(self._new_precision, names="precision")

    # ------------------------------------------------------------------ the mesh

    def set_mesh(
        self,
        vertices: Any,
        faces: npt.ArrayLike | None = None,
        *,
        report: MeshReport | None = None,
        name: str | None = None,
    ) -> None:
        """Show another mesh (a repaired one, say), checked unless ``report`` is given.

        Parameters
        ----------
        vertices : array_like, shape (V, 3), or MeshData
        faces : array_like of int, shape (F, 3); omitted with a MeshData
        report : MeshReport, optional
            Its [`check`][trinormal.mesh.check] report, if already made.
        name : str, optional
            What the description calls the model: by default a MeshData's file name, else
            none ("The model").

        Raises
        ------
        ValueError
            Arrays that are not a mesh (the message names the first bad row), or a name
            that is not a string.
        """
        if name is not None and not isinstance(name, str):
            raise ValueError(f"name must be a string (the model's name), got {name!r}")
        if faces is None:
            if not hasattr(vertices, "faces"):
                raise ValueError("give vertices and faces, or a MeshData from read_mesh")
            if name is None:
                name = PurePath(vertices.path).name
            vertices, faces = vertices.vertices, vertices.faces
        # check() validates the arrays (shapes, finite coordinates, indices in range)
        self.report = check(vertices, faces) if report is None else report
        v = np.asarray(vertices, dtype=float).reshape(-1, 3)
        f = np.asarray(faces, dtype=np.intp).reshape(-1, 3)
        self._vertices, self._faces = v, f
        nv, nf = len(v), len(f)
        if nf > self.max_arrows > 0:
            arrow = np.unique(np.linspace(0, nf - 1, self.max_arrows).round().astype(np.intp))
        else:
            arrow = np.arange(nf if self.max_arrows else 0, dtype=np.intp)
        normals = face_normals(v, f[arrow]) if len(arrow) else np.zeros((0, 3))
        with self.hold_sync():
            self.positions = _buffer(v, "f8")
            self.faces = _buffer(f, "u4")
            self.flipped = _buffer(self.report.faces_to_flip, "i4")
            # the report's edges join corners by position (welding.py): match them on the same faces
            joined = weld(v, f, self.report.weld_distance).faces if nf else f
            self.boundary = _buffer(_edge_sides(joined, self.report.boundary_edges, nv), "i4")
            self.non_manifold = _buffer(
                _edge_sides(joined, self.report.non_manifold_edges, nv), "i4"
            )
            self.arrow_faces = _buffer(arrow, "i4")
            self.arrow_normals = _buffer(normals, "f4")
            self.vertex_normals = _buffer(
                vertex_normals(v, f, "angle") if nf else np.zeros((nv, 3)), "f4"
            )
            self.about = _about(name, self.report)
            self.picked = -1
            self.selection = {}
            self.revision += 1

    @property
    def vertices_array(self) -> npt.NDArray[np.float64]:
        """The vertices shown, as float64 (the readout computes from these)."""
        return self._vertices

    @property
    def faces_array(self) -> npt.NDArray[np.intp]:
        """The faces shown."""
        return self._faces

    @property
    def n_faces(self) -> int:
        """How many faces the view shows."""
        return len(self._faces)

    # ------------------------------------------------------------------ a clicked face

    def select(self, face: int) -> dict[str, Any]:
        """Select a face as a click does, and return its readout.

        Raises
        ------
        ValueError
            A face that does not exist.
        """
        self.selection = face_selection(
            self._vertices, self._faces, face, self.precision, self.report
        )
        if self.picked != int(face):
            self._selecting = True
            try:
                self.picked = int(face)
            finally:
                self._selecting = False
        return dict(self.selection)

    def describe(self, face: int) -> str:
        """Select a face as a click does, and return its readout as plain text.

        Examples
        --------
        >>> from trinormal.mesh import cube
        >>> print(MeshView(*cube(), precision=0).describe(5))  # doctest: +ELLIPSIS
        Face 5: vertices 0, 6, 2 as A, B, C
          A = vertex 0: (-1, -1, -1)
          B = vertex 6: (-1, 1, 1)
          C = vertex 2: (-1, 1, -1)
          N = U × V: (-4, 0, 0)
          |N|: 4
          area = |N|/2: 2
          unit normal: (-1, 0, 0)
          status: A proper triangle: the unit normal is defined.
        """
        return selection_text(self.select(face))

    def summary(self) -> str:
        """Say in one line what the view shows (the plain-text form of the widget)."""
        r = self.report
        parts = [
            f"{r.n_vertices} {'vertex' if r.n_vertices == 1 else 'vertices'}",
            f"{r.n_faces} {'face' if r.n_faces == 1 else 'faces'}",
            f"{len(r.faces_to_flip)} to flip (outlined)",
            f"{len(r.boundary_edges)} boundary and {len(r.non_manifold_edges)} non-manifold "
            "edges (thick)",
        ]
        return "Mesh view: " + ", ".join(parts) + "."

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        """Show the live view in Jupyter, with `summary` as its plain text (not the buffers)."""
        bundle = super()._repr_mimebundle_(**kwargs)
        if isinstance(bundle, tuple):
            data, metadata = bundle
            return {**data, "text/plain": self.summary()}, metadata
        if isinstance(bundle, dict):
            return {**bundle, "text/plain": self.summary()}
        return bundle

    def __repr__(self) -> str:
        return f"<{self.summary()}>"

    def _on_picked(self, change: Any) -> None:
        if getattr(self, "_selecting", False):
            return
        face = change["new"]
        if face == -1:
            self.selection = {}
            return
        try:
            self.select(face)
        except ValueError as error:  # a click never raises: say what went wrong instead
            self.selection = {
                "face": face,
                "title": str(error),
                "rows": [[SELECTION["problem_label"], str(error), ""]],
            }

    @traitlets.validate("precision")
    def _valid_precision(self, proposal: Any) -> int:
        return check_precision(proposal["value"])

    def _new_precision(self, change: Any) -> None:
        if self.picked >= 0:
            self.select(self.picked)
