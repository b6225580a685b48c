"""How faces fit together: shared edges, their directions, and winding."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import IntArray, _check_faces


def inconsistent_edges(faces: npt.ArrayLike) -> IntArray:
    """Directed edges that appear in two faces running the same way.

    In a consistently wound mesh every interior edge is walked once in each
    direction, by the two faces that share it. An edge walked the same way
    twice means one of those faces is flipped.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.

    Returns
    -------
    ndarray of int, shape (E, 2)
        Each offending directed edge ``(i, j)`` once, sorted.

    Examples
    --------
    >>> inconsistent_edges([[0, 1, 2], [0, 2, 3]])
    array([], shape=(0, 2), dtype=int64)
    >>> inconsistent_edges([[0, 1, 2], [0, 3, 2]])
    array([[2, 0]])
    """
    f = _check_faces(faces, None)
    if f.shape[0] == 0:
        return np.empty((0, 2), dtype=np.intp)
    # directed edges as (start, end) rows, sorted; no packing into one integer, which
    # would wrap around for indices above 2**31
    edges = np.stack([f.ravel(), f[:, [1, 2, 0]].ravel()], axis=1)
    edges = edges[np.lexsort((edges[:, 1], edges[:, 0]))]
    same = (edges[1:] == edges[:-1]).all(axis=1)
    dup: IntArray = np.unique(edges[1:][same], axis=0).reshape(-1, 2).astype(np.intp)
    return dup


def consistent_winding(faces: npt.ArrayLike) -> bool:
    """Whether every edge shared by two faces runs opposite ways in them.

    Parameters
    ----------
    faces : array_like of int, shape (F, 3)
        Vertex indices of each triangle.

    Returns
    -------
    bool
        True when no directed edge appears twice (see
        [`inconsistent_edges`][trinormal.mesh.inconsistent_edges]).

    Examples
    --------
    Two triangles sharing the edge 0–2, wound the same way round, then one flipped:

    >>> consistent_winding([[0, 1, 2], [0, 2, 3]])
    True
    >>> consistent_winding([[0, 1, 2], [0, 3, 2]])
    False
    """
    return bool(inconsistent_edges(faces).shape[0] == 0)
