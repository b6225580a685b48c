"""Array checks and types shared by the mesh modules (private).

Every public mesh function reads its ``vertices`` and ``faces`` through
`_check_vertices` and `_check_faces`, so a bad input gets the same message,
naming the first bad row, whichever function it reaches.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from trinormal.validation import check_tolerance

FloatArray = npt.NDArray[np.floating[Any]]
IntArray = npt.NDArray[np.intp]
BoolArray = npt.NDArray[np.bool_]
Weighting = Literal["angle", "area", "uniform"]
# The largest vertex index: 2**63 - 1 (numpy's intp on 64-bit machines).
_MAX_INDEX = int(np.iinfo(np.intp).max)


def _check_vertices(vertices: npt.ArrayLike) -> tuple[FloatArray, np.dtype[Any]]:
    """Return the vertices as float64 (V, 3) and the dtype results come back in."""
    return _checked_vertices(vertices)[:2]


def _checked_vertices(
    vertices: npt.ArrayLike,
) -> tuple[FloatArray, np.dtype[Any], FloatArray]:
    """`_check_vertices`, and the vertices' bounding box (`_box`)."""
    arr = np.asarray(vertices)
    if arr.dtype == np.float32:
        out_dtype: np.dtype[Any] = np.dtype(np.float32)
    elif arr.dtype.kind in "fiu":
        out_dtype = np.dtype(np.float64)
    elif arr.dtype == object:
        try:
            arr = arr.astype(np.float64)
        except (TypeError, ValueError):
            raise ValueError("vertices must be real numbers") from None
        except OverflowError:  # a Python int or Fraction beyond the float64 range
            raise ValueError("vertices must be real numbers within the float64 range") from None
        out_dtype = np.dtype(np.float64)
    else:
        raise ValueError(f"vertices must be real numbers, got dtype {arr.dtype}")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"vertices must have shape (V, 3), got shape {arr.shape}")
    arr64 = np.ascontiguousarray(arr, dtype=np.float64)
    # the box doubles as the finiteness test (NaN propagates through min and max): no (V, 3) mask
    box = _box(arr64)
    if not np.isfinite(box).all():
        finite = np.isfinite(arr64)
        row = int(np.flatnonzero(~finite.all(axis=1))[0])
        col = int(np.flatnonzero(~finite[row])[0])
        what = "NaN" if np.isnan(arr64[row, col]) else "infinite"
        raise ValueError(
            f"vertices row {row}: {'xyz'[col]} is {what}; every coordinate must be a finite number"
        )
    return arr64, out_dtype, box


#: Vertices per row when `_box` reduces: a wide row keeps the reduction's inner loop long.
_BOX_ROW = 512


def _box(v: FloatArray) -> FloatArray:
    """Return the smallest and the largest x, y and z of the contiguous (V, 3) ``v``: (2, 3).

    A reduction along the first axis of a (V, 3) array runs an inner loop of only
    three numbers per row; here the coordinates are read `_BOX_ROW` vertices to a
    row (the last, shorter row folded into the first), so the loop runs along the
    wide rows, then `_BOX_ROW` vertices remain.
    """
    if v.shape[0] == 0:
        return np.zeros((2, 3))
    flat = v.reshape(-1)
    width = 3 * min(_BOX_ROW, v.shape[0])
    whole = flat.size // width * width
    wide = flat[:whole].reshape(-1, width)
    lo, hi = wide.min(axis=0), wide.max(axis=0)
    tail = flat[whole:]  # x, y, z of the last vertices, in the same order as a row's start
    np.minimum(lo[: tail.size], tail, out=lo[: tail.size])
    np.maximum(hi[: tail.size], tail, out=hi[: tail.size])
    box: FloatArray = np.stack([lo.reshape(-1, 3).min(axis=0), hi.reshape(-1, 3).max(axis=0)])
    return box


def _check_faces(
    faces: npt.ArrayLike, n_vertices: int | None, check_range: bool = True
) -> IntArray:
    """Return the faces as an intp (F, 3) array, every index checked against ``n_vertices``.

    With ``check_range=False`` only the dtype and shape are checked here: the
    kernel checks the indices block by block, where they are in cache anyway.
    """
    arr = np.asarray(faces)
    if arr.size == 0:
        if arr.ndim == 2 and arr.shape[1] != 3:
            raise ValueError(f"faces must have shape (F, 3), got shape {arr.shape}")
        return np.empty((0, 3), dtype=np.intp)
    if arr.dtype.kind not in "iu":
        raise ValueError(f"faces must hold integer vertex indices, got dtype {arr.dtype}")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"faces must have shape (F, 3), got shape {arr.shape}")
    if arr.dtype.kind == "u" and arr.dtype.itemsize >= 8 and int(arr.max()) > _MAX_INDEX:
        _raise_range_error(arr, _MAX_INDEX + 1)  # beyond what an index (intp) can hold
    if check_range:
        lo, hi = int(arr.min()), int(arr.max())
        limit = n_vertices if n_vertices is not None else hi + 1
        if lo < 0 or hi >= limit:
            _raise_range_error(arr, limit)
    return np.ascontiguousarray(arr, dtype=np.intp)


def _raise_range_error(arr: npt.NDArray[Any], limit: int) -> None:
    """Raise the ValueError naming the first row of ``arr`` with an index outside [0, limit)."""
    bad = (arr < 0) | (arr >= limit)
    row = int(np.flatnonzero(bad.any(axis=1))[0])
    index = int(arr[row][bad[row]][0])
    valid = (
        f"the valid indices are 0 to {limit - 1} ({limit} vertices)"
        if limit
        else "there are no vertices"
    )
    raise ValueError(f"faces row {row} refers to vertex {index}, but {valid}")


def _check_tol(tol: float) -> float:
    """Return the tolerance as a float, checked by `trinormal.validation.check_tolerance`."""
    n, d = check_tolerance(tol)
    return n / d  # 0 <= tol <= 1: no overflow


def _exact_tol(tol: float) -> Fraction:
    """Return the tolerance exactly as `trinormal.validation.check_tolerance` reads it."""
    return Fraction(*check_tolerance(tol))


def _cast(values: FloatArray, dtype: np.dtype[Any]) -> FloatArray:
    """Return float64 results in ``dtype``: beyond the float32 range they become ±inf, quietly."""
    if values.dtype == dtype:
        return values
    with np.errstate(over="ignore", under="ignore"):
        out: FloatArray = values.astype(dtype)
    return out


def _prepare(
    vertices: npt.ArrayLike, faces: npt.ArrayLike
) -> tuple[FloatArray, IntArray, np.dtype[Any], FloatArray]:
    """Return the checked float64 vertices (contiguous), intp faces, result dtype and `_box`."""
    v, dtype, box = _checked_vertices(vertices)
    f = _check_faces(faces, v.shape[0], check_range=False)
    return v, f, dtype, box


# --------------------------------------------------------------------------- sorting


#: Odd 64-bit multipliers that mix a row's bit patterns into one number (`_grouped`).
_MIX = (0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9)


def _packed_sort(key: npt.NDArray[Any], top: int) -> tuple[IntArray, npt.NDArray[Any]] | None:
    """Sort the keys ``0 <= key < top``, ties by index: the order and the sorted keys.

    Each key and its index are packed in one 64-bit number, the key above the index,
    and the numbers sorted: a plain sort of numbers, not of indices by key
    (``argsort``). None when the two need more than 64 bits.
    """
    n = key.shape[0]
    shift = max(1, (n - 1).bit_length())
    if max(1, (top - 1).bit_length()) + shift > 64:
        return None
    packed = key.astype(np.uint64)
    packed <<= np.uint64(shift)
    packed |= np.arange(n, dtype=np.uint64)
    packed.sort()
    order = (packed & np.uint64((1 << shift) - 1)).astype(np.intp)
    packed >>= np.uint64(shift)
    return order, packed


def _grouped(bits: npt.NDArray[np.unsignedinteger[Any]]) -> tuple[IntArray, BoolArray]:
    """Order the rows of ``bits`` (n, 3) so that equal rows are together, each group by index.

    Returns the order and, for rows 1 to n - 1 in that order, whether each equals the
    row before it. The rows are sorted by a mix of their three bit patterns
    (`_packed_sort`, in the bits the index leaves); rows of one mix that differ are
    then sorted by their values, so equality is exact, never a hash match.
    """
    n = bits.shape[0]
    shift = max(1, (n - 1).bit_length())
    wide = bits.dtype.itemsize == 8
    mix = np.zeros(n, dtype=np.uint64)
    for k in range(3):
        col = bits[:, k]
        if wide:  # a product's high bits depend only on the factors' bits below them: the
            # high half is folded onto the low one, or a float64's sign bit would flip only
            # the top bit (and x, y and -x, -y would mix alike)
            col = col ^ (col >> np.uint64(32))
        mix ^= col * np.uint64(_MIX[k])
    mix >>= np.uint64(shift)
    done = _packed_sort(mix, 1 << (64 - shift))
    assert done is not None  # the mix keeps 64 - shift bits
    order, mix = done
    same_mix = mix[1:] == mix[:-1]
    del mix
    same = _same_as_previous(np.take(bits, order, axis=0))
    clash = same_mix & ~same
    if clash.any():  # one mix, different rows: sort those runs by their values
        run = np.cumsum(np.append(True, ~same_mix))
        mixed = np.zeros(int(run[-1]) + 1, dtype=bool)
        mixed[run[1:][clash]] = True
        at = np.flatnonzero(mixed[run])
        rows = order[at]  # by index within each run: the sort below is stable
        order[at] = rows[np.lexsort((bits[rows, 2], bits[rows, 1], bits[rows, 0], run[at]))]
        same = _same_as_previous(np.take(bits, order, axis=0))
    return order, same


def _same_as_previous(rows: npt.NDArray[Any]) -> BoolArray:
    """Whether each row of a (n, 3) array equals the row before it, for rows 1 to n - 1."""
    same: BoolArray = rows[1:, 0] == rows[:-1, 0]
    same &= rows[1:, 1] == rows[:-1, 1]
    same &= rows[1:, 2] == rows[:-1, 2]
    return same
