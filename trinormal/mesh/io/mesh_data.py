"""What a reader returns: `MeshData`, with polygons split into triangles in their planes.

How polygons are split: `trinormal.mesh.io`. `MeshData.source` keeps the file's bytes, so
that `write_mesh` can write the file back with only the faces a fix turns over changed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import FloatArray, IntArray
from trinormal.mesh.polygons import split_polygons

__all__ = ["MeshData"]


def _none() -> IntArray:
    return np.empty(0, dtype=np.intp)


@dataclass(frozen=True)
class MeshData:
    """A mesh as read from a file.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3)
        Coordinates in float64, in file order (STL: in order of first use).
    faces : ndarray of int, shape (F, 3)
        Triangles, in file order; polygons split in their planes (`trinormal.mesh.polygons`).
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
    source : bytes
        The file's bytes, as read: what `write_mesh` writes back, with the
        records of the faces a fix turns over changed and nothing else. A binary
        STL keeps its 84-byte header and any bytes after its records here, the
        rest in ``stl_records``.
    nonplanar : ndarray of int
        The polygons (faces of the file, from 0) whose corners are not on one
        plane (`trinormal.tolerances.PLANAR_TOL`): their split is a guess.
    crossing : ndarray of int
        The polygons that cross themselves.
    vertex_normals : ndarray, shape (V, 3), or None
        A PLY file's ``nx ny nz`` vertex properties, when it has them.
    stl_records : ndarray or None
        A binary STL's stored normal and attribute bytes, a record per triangle, when
        ``source`` holds only its header and what follows its records (its corners are
        ``vertices[faces]``, exactly): a binary STL keeps 14 bytes a triangle, not 50.
    stl_against : ndarray of int or None
        With ``stl_records``: the facets whose stored normal points against their
        winding as read (`normals_against`).
    """

    vertices: FloatArray = field(repr=False)
    faces: IntArray = field(repr=False)
    format: str
    encoding: str
    source_faces: IntArray = field(repr=False)
    n_polygons: int
    path: str
    notes: tuple[str, ...] = ()
    source: bytes = field(default=b"", repr=False)
    nonplanar: IntArray = field(default_factory=_none, repr=False)
    crossing: IntArray = field(default_factory=_none, repr=False)
    stl_records: Any = field(default=None, repr=False)
    stl_against: IntArray | None = field(default=None, repr=False)
    vertex_normals: FloatArray | None = field(default=None, repr=False)

    @property
    def corners(self) -> IntArray:
        """How many corners each face of the file has, shape (P,)."""
        out: IntArray = np.bincount(self.source_faces, minlength=self.n_polygons) + 2
        return out

    @property
    def split_polygons(self) -> int:
        """How many faces of the file had more than three corners."""
        return int((self.corners > 3).sum())

    def normals_against(self, faces: IntArray | None = None) -> IntArray | None:
        r"""Return the faces whose stored normals point against the winding (None: none stored).

        Parameters
        ----------
        faces : ndarray of int, shape (F, 3), optional
            The triangles as wound: by default as read; after a fix, the fixed ones, and
            then, as `write_mesh` writes the file, an STL facet turned over has a
            recomputed normal and agrees (`trinormal.mesh.io.stored`).

        Examples
        --------
        >>> from trinormal.mesh import parse_mesh, fix_winding
        >>> m = parse_mesh(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -1\nf 1//1 2//1 3//1\n", "obj")
        >>> m.normals_against()
        array([0])
        """
        from trinormal.mesh.io.rewrite import _turned_polygons
        from trinormal.mesh.io.stored import against

        if faces is None:
            return against(self, self.faces, None)
        return against(self, faces, _turned_polygons(self, faces))

    def describe(self) -> str:
        r"""Say in one sentence what was read: vertices, faces, and polygons and triangles.

        Examples
        --------
        >>> from trinormal.mesh import parse_mesh
        >>> m = parse_mesh(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "obj")
        >>> print(m.describe())
        Read <bytes> (OBJ): 4 vertices, 1 quad, 2 triangles.
        >>> m = parse_mesh(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nf 1 2 3 4\n", "obj")
        >>> print(m.describe())  # doctest: +NORMALIZE_WHITESPACE
        Read <bytes> (OBJ): 4 vertices, 1 quad, 2 triangles; 1 quad is not planar: its
        triangles are one of several surfaces through its corners.
        """
        nv, np_ = self.vertices.shape[0], self.n_polygons
        enc = "" if self.format == "obj" else f", {self.encoding}"
        text = f"Read {self.path} ({self.format.upper()}{enc}): {nv} {_plural(nv, 'vertex')}"
        nf = self.faces.shape[0]
        if nf == np_:
            return text + f", {np_} {_plural(np_, 'face')}." + self._normals_sentence()
        corners = self.corners
        noun = "quad" if corners.size and (corners == 4).all() else "polygon"
        text += f", {np_:,} {_plural(np_, noun)}, {nf:,} {_plural(nf, 'triangle')}"
        odd = []
        for k, one, many in (
            (self.nonplanar.size, "is not planar", "are not planar"),
            (self.crossing.size, "crosses itself", "cross themselves"),
        ):
            if k:
                odd.append(f"{k:,} {_plural(k, noun)} {one if k == 1 else many}")
        if odd:
            its = "its" if self.nonplanar.size + self.crossing.size == 1 else "their"
            text += f"; {' and '.join(odd)}: {its} triangles are one of several surfaces"
            text += f" through {its} corners"
        return text + "." + self._normals_sentence()

    def _normals_sentence(self) -> str:
        bad = self.normals_against()
        if bad is None or bad.size == 0:
            return ""
        k = bad.size
        return (
            f" The stored normals of {k:,} {_plural(k, 'face')} point against "
            f"{'its' if k == 1 else 'their'} winding."
        )


def _plural(n: int, noun: str) -> str:
    if n == 1:
        return noun
    return "vertices" if noun == "vertex" else noun + "s"


def _polygon_mesh(
    vertices: FloatArray,
    polys: list[list[Any]] | npt.NDArray[Any],
    fmt: str,
    encoding: str,
    **fields: Any,
) -> MeshData:
    """Return the `MeshData` of a file's polygons (corner lists, or a (P, n) table), split.

    The corners are vertex numbers, checked: integers, or whole numbers of a float type.
    """
    if isinstance(polys, np.ndarray):
        sizes = np.full(polys.shape[0], polys.shape[1], dtype=np.intp)
        flat = polys.astype(np.intp).ravel()
    else:
        sizes = np.fromiter((len(p) for p in polys), dtype=np.intp, count=len(polys))
        flat = np.fromiter((i for p in polys for i in p), dtype=np.intp, count=int(sizes.sum()))
    split = split_polygons(vertices, flat, sizes)
    return MeshData(
        vertices,
        split.faces,
        fmt,
        encoding,
        split.source,
        len(sizes),
        nonplanar=np.flatnonzero(split.nonplanar).astype(np.intp),
        crossing=np.flatnonzero(split.crossing).astype(np.intp),
        **fields,
    )
