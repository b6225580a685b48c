"""What a reader returns: `MeshData`, with polygons split into triangles as a fan.

A polygon with n corners becomes n − 2 triangles, a fan from its first corner,
wound as stored: ``(a, b, c, d)`` gives ``(a, b, c)`` and ``(a, c, d)``.
`MeshData.source_faces` says which polygon each triangle came from.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from trinormal.mesh._arrays import FloatArray, IntArray

__all__ = ["MeshData"]


@dataclass(frozen=True)
class MeshData:
    """A mesh as read from a file.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3)
        Coordinates in float64, in file order (STL: in order of first use).
    faces : ndarray of int, shape (F, 3)
        Triangles, in file order; polygons split into fans.
    format : str
        ``"obj"``, ``"stl"`` or ``"ply"``.
    encoding : str
        ``"ascii"`` or ``"binary"`` (a big-endian PLY reads as ``"binary"``
        and is written little-endian).
    source_faces : ndarray of int, shape (F,)
        For each triangle, the index of the face (polygon) of the file it
        comes from.
    n_polygons : int
        How many faces the file lists (before splitting).
    path : str
        The file's name.
    notes : tuple of str
        What the reader forgave, one sentence each ("NAME: NOTE", from
        `trinormal.mesh.io.READ_NOTES`): a binary STL whose triangle count
        disagrees with its size, for one. Empty for a file read as it is.
    """

    vertices: FloatArray = field(repr=False)
    faces: IntArray = field(repr=False)
    format: str
    encoding: str
    source_faces: IntArray = field(repr=False)
    n_polygons: int
    path: str
    notes: tuple[str, ...] = ()

    @property
    def split_polygons(self) -> int:
        """How many faces of the file had more than three corners."""
        if self.source_faces.size == 0:
            return 0
        counts = np.bincount(self.source_faces, minlength=self.n_polygons)
        return int((counts > 1).sum())

    def describe(self) -> str:
        r"""Say in one sentence: what was read, and how polygons were split.

        Examples
        --------
        >>> from trinormal.mesh import parse_mesh
        >>> m = parse_mesh(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "obj")
        >>> print(m.describe())  # doctest: +NORMALIZE_WHITESPACE
        Read <bytes> (OBJ): 4 vertices, 1 face; 1 polygon with more than three corners split
        into 2 triangles, a fan from its first corner.
        """
        nv, np_ = self.vertices.shape[0], self.n_polygons
        enc = "" if self.format == "obj" else f", {self.encoding}"
        text = (
            f"Read {self.path} ({self.format.upper()}{enc}): "
            f"{nv} {'vertex' if nv == 1 else 'vertices'}, {np_} {'face' if np_ == 1 else 'faces'}"
        )
        k = self.split_polygons
        if k:
            tri = int(np.isin(self.source_faces, _multi(self.source_faces, np_)).sum())
            text += (
                f"; {k} {'polygon' if k == 1 else 'polygons'} with more than three corners "
                f"split into {tri} triangles, a fan from {'its' if k == 1 else 'each'} first corner"
            )
        return text + "."


def _multi(source: IntArray, n: int) -> IntArray:
    counts = np.bincount(source, minlength=n)
    out: IntArray = np.flatnonzero(counts > 1)
    return out


def _fan(polys: list[list[int]]) -> tuple[IntArray, IntArray]:
    """Split polygons into triangles: a fan from each one's first corner, in order."""
    if not polys:
        return np.empty((0, 3), np.intp), np.empty(0, np.intp)
    sizes = np.fromiter((len(p) for p in polys), dtype=np.intp, count=len(polys))
    if sizes.size and (sizes == 3).all():
        return np.array(polys, dtype=np.intp).reshape(-1, 3), np.arange(len(polys), dtype=np.intp)
    n_tri = sizes - 2
    source = np.repeat(np.arange(len(polys), dtype=np.intp), n_tri)
    flat = np.fromiter((i for p in polys for i in p), dtype=np.intp, count=int(sizes.sum()))
    start = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.intp)
    k = np.arange(source.size) - np.repeat(np.cumsum(n_tri) - n_tri, n_tri)  # 0 .. n-3
    first = start[source]
    faces = np.stack([flat[first], flat[first + k + 1], flat[first + k + 2]], axis=1)
    return faces.astype(np.intp).reshape(-1, 3), source


def _fan_uniform(polys: IntArray) -> tuple[IntArray, IntArray]:
    """`_fan` for polygons that all have the same number of corners, shape (P, n)."""
    p, n = polys.shape
    k = np.arange(n - 2)
    faces = np.stack(
        [np.repeat(polys[:, :1], n - 2, axis=1), polys[:, k + 1], polys[:, k + 2]], axis=2
    )
    source = np.repeat(np.arange(p, dtype=np.intp), n - 2)
    return faces.reshape(-1, 3).astype(np.intp), source
