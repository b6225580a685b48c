"""Small meshes made in code: outward-facing, consistently wound."""

from __future__ import annotations

import math

import numpy as np

from trinormal.mesh._arrays import FloatArray, IntArray


def cube(size: float = 2.0) -> tuple[FloatArray, IntArray]:
    """Make a cube centred on the origin: 8 vertices and 12 outward-facing triangles.

    Vertex ``i`` has coordinates ``±size/2`` with the sign of x, y, z taken from
    bits 0, 1, 2 of ``i``, so vertex 7 is the corner (1, 1, 1) of the default
    cube. Each square face is split along one diagonal; at vertex 7 only the
    top face (+z) is split through the corner, which is what makes area and
    angle weighting disagree there.

    Parameters
    ----------
    size : float, default 2.0
        Edge length.

    Returns
    -------
    vertices : ndarray, shape (8, 3)
    faces : ndarray of int, shape (12, 3)

    Examples
    --------
    >>> v, f = cube()
    >>> v[7], f[-2:]
    (array([1., 1., 1.]), array([[4, 5, 7],
           [4, 7, 6]]))
    """
    i = np.arange(8)
    v = (np.stack([i & 1, (i >> 1) & 1, (i >> 2) & 1], axis=1) - 0.5) * float(size)
    f = np.array(
        [
            [0, 2, 3], [0, 3, 1],  # -z  (bottom)
            [0, 1, 5], [0, 5, 4],  # -y
            [0, 4, 6], [0, 6, 2],  # -x
            [1, 3, 5], [3, 7, 5],  # +x
            [2, 6, 3], [3, 6, 7],  # +y
            [4, 5, 7], [4, 7, 6],  # +z  (top)
        ],
        dtype=np.intp,
    )  # fmt: skip
    return v, f


def icosphere(subdivisions: int = 2, radius: float = 1.0) -> tuple[FloatArray, IntArray]:
    """Make a sphere of triangles: an icosahedron whose faces are split in four, repeatedly.

    Parameters
    ----------
    subdivisions : int, default 2
        How many times every triangle is split into four (0 is the icosahedron).
    radius : float, default 1.0
        Every vertex lies at this distance from the origin.

    Returns
    -------
    vertices : ndarray, shape (10 · 4**s + 2, 3)
    faces : ndarray of int, shape (20 · 4**s, 3)
        Outward-facing, consistently wound.

    Examples
    --------
    >>> v, f = icosphere(1)
    >>> v.shape, f.shape
    ((42, 3), (80, 3))
    >>> bool(np.allclose(np.linalg.norm(v, axis=1), 1.0))
    True
    """
    if subdivisions < 0:
        raise ValueError(f"subdivisions must be >= 0, got {subdivisions}")
    p = (1.0 + math.sqrt(5.0)) / 2.0
    v = np.array(
        [
            [-1, p, 0], [1, p, 0], [-1, -p, 0], [1, -p, 0],
            [0, -1, p], [0, 1, p], [0, -1, -p], [0, 1, -p],
            [p, 0, -1], [p, 0, 1], [-p, 0, -1], [-p, 0, 1],
        ],
        dtype=np.float64,
    )  # fmt: skip
    f = np.array(
        [
            [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
            [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
            [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
            [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
        ],
        dtype=np.intp,
    )  # fmt: skip
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    for _ in range(subdivisions):
        # one new vertex per edge, shared by the two faces on either side
        edges = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
        key = np.sort(edges, axis=1)
        uniq, inverse = np.unique(key, axis=0, return_inverse=True)
        mid = v[uniq[:, 0]] + v[uniq[:, 1]]
        mid /= np.linalg.norm(mid, axis=1, keepdims=True)
        m = inverse.reshape(3, -1) + v.shape[0]  # midpoints of edges 01, 12, 20 of each face
        v = np.concatenate([v, mid])
        a, b, c = f[:, 0], f[:, 1], f[:, 2]
        ab, bc, ca = m[0], m[1], m[2]
        f = np.concatenate(
            [
                np.stack([a, ab, ca], axis=1),
                np.stack([b, bc, ab], axis=1),
                np.stack([c, ca, bc], axis=1),
                np.stack([ab, bc, ca], axis=1),
            ]
        )
    return v * float(radius), f.astype(np.intp)


def torus(
    major: float = 1.0, minor: float = 0.35, n_major: int = 32, n_minor: int = 16
) -> tuple[FloatArray, IntArray]:
    """Make a ring around the z axis: a circle of radius ``minor`` swept along radius ``major``.

    Parameters
    ----------
    major, minor : float
        Radius of the ring's centre line and of its tube (``0 < minor < major``).
    n_major, n_minor : int
        Vertices around the ring and around the tube (at least 3 each).

    Returns
    -------
    vertices : ndarray, shape (n_major · n_minor, 3)
    faces : ndarray of int, shape (2 · n_major · n_minor, 3)
        Outward-facing, consistently wound, closed (no boundary).

    Examples
    --------
    >>> v, f = torus(n_major=8, n_minor=4)
    >>> v.shape, f.shape
    ((32, 3), (64, 3))
    """
    if not 0 < minor < major:
        raise ValueError(f"need 0 < minor < major, got minor={minor}, major={major}")
    if n_major < 3 or n_minor < 3:
        raise ValueError(f"n_major and n_minor must be >= 3, got {n_major}, {n_minor}")
    th = np.linspace(0.0, 2.0 * np.pi, n_major, endpoint=False)[:, None]
    ph = np.linspace(0.0, 2.0 * np.pi, n_minor, endpoint=False)[None, :]
    r = major + minor * np.cos(ph)
    v = np.stack(
        [
            (r * np.cos(th)).ravel(),
            (r * np.sin(th)).ravel(),
            np.broadcast_to(minor * np.sin(ph), (n_major, n_minor)).ravel(),
        ],
        axis=1,
    )
    i = np.arange(n_major)[:, None]
    j = np.arange(n_minor)[None, :]
    p00 = (i * n_minor + j).ravel()
    p10 = (((i + 1) % n_major) * n_minor + j).ravel()
    p01 = (i * n_minor + (j + 1) % n_minor).ravel()
    p11 = (((i + 1) % n_major) * n_minor + (j + 1) % n_minor).ravel()
    f = np.concatenate([np.stack([p00, p10, p11], 1), np.stack([p00, p11, p01], 1)])
    return v, f.astype(np.intp)


def uv_sphere(n_around: int = 24, n_down: int = 12) -> tuple[FloatArray, IntArray]:
    """Make a unit sphere cut along meridians and parallels, like a globe's grid.

    Unlike `icosphere`, its triangles are far from equal: they grow thin and
    small near the poles, which is what makes vertex-normal weightings differ.

    Parameters
    ----------
    n_around : int, default 24
        Meridians (vertices around each parallel), at least 3.
    n_down : int, default 12
        Bands from pole to pole, at least 3.

    Returns
    -------
    vertices : ndarray, shape (n_around · (n_down − 1) + 2, 3)
        The parallels' vertices, then the north and the south pole.
    faces : ndarray of int, shape (2 · n_around · (n_down − 1), 3)
        Outward-facing, consistently wound, closed.

    Examples
    --------
    >>> v, f = uv_sphere(8, 4)
    >>> v.shape, f.shape
    ((26, 3), (48, 3))
    >>> bool(np.allclose(np.linalg.norm(v, axis=1), 1.0))
    True
    """
    if n_around < 3 or n_down < 3:
        raise ValueError(f"n_around and n_down must be >= 3, got {n_around}, {n_down}")
    theta = np.linspace(0.0, np.pi, n_down + 1)[1:-1]
    phi = np.linspace(0.0, 2.0 * np.pi, n_around, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    ring = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], -1).reshape(-1, 3)
    vertices = np.vstack([ring, [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    north, south, last = len(ring), len(ring) + 1, (n_down - 2) * n_around
    faces = []
    for i in range(n_down - 2):  # two triangles per cell between neighbouring parallels
        for j in range(n_around):
            a, b = i * n_around + j, i * n_around + (j + 1) % n_around
            faces += [(a, a + n_around, b + n_around), (a, b + n_around, b)]
    for j in range(n_around):  # a fan at each pole
        faces += [(north, j, (j + 1) % n_around), (south, last + (j + 1) % n_around, last + j)]
    return vertices, np.array(faces, dtype=np.intp)


def terrain(
    nx: int = 32, ny: int = 32, size: float = 1.0, height: float = 0.15, seed: int = 0
) -> tuple[FloatArray, IntArray]:
    """Make a height-field grid: ``nx`` by ``ny`` points over a square, z a smooth landscape.

    Faces are listed row by row, two triangles per grid cell, all facing up
    (+z side), so neighbouring faces share neighbouring vertices: the natural
    order a mesh file usually has.

    Parameters
    ----------
    nx, ny : int
        Grid points along x and y (at least 2 each).
    size : float, default 1.0
        Side of the square, centred on the origin.
    height : float, default 0.15
        Largest height of the landscape.
    seed : int, default 0
        Seed of the random hills (same seed, same terrain).

    Returns
    -------
    vertices : ndarray, shape (nx · ny, 3)
    faces : ndarray of int, shape (2 (nx − 1)(ny − 1), 3)

    Examples
    --------
    >>> from trinormal.mesh import face_normals
    >>> v, f = terrain(3, 4)
    >>> v.shape, f.shape
    ((12, 3), (12, 3))
    >>> bool((face_normals(v, f)[:, 2] > 0).all())
    True
    """
    if nx < 2 or ny < 2:
        raise ValueError(f"nx and ny must be >= 2, got {nx}, {ny}")
    rng = np.random.default_rng(seed)
    xs = np.linspace(-size / 2, size / 2, nx)
    ys = np.linspace(-size / 2, size / 2, ny)
    gx, gy = np.meshgrid(xs, ys, indexing="xy")  # shape (ny, nx): row j, column i
    k = rng.uniform(1.0, 4.0, size=(4, 2)) * (2 * np.pi / size)
    phase = rng.uniform(0, 2 * np.pi, size=4)
    amp = rng.uniform(0.3, 1.0, size=4)
    z = sum(a * np.sin(kx * gx + ky * gy + p) for (kx, ky), p, a in zip(k, phase, amp, strict=True))
    z = z * (height / amp.sum())
    v = np.stack([gx.ravel(), gy.ravel(), np.asarray(z).ravel()], axis=1)
    j, i = np.meshgrid(np.arange(ny - 1), np.arange(nx - 1), indexing="ij")
    p00 = (j * nx + i).ravel()
    p10, p01, p11 = p00 + 1, p00 + nx, p00 + nx + 1
    f = np.stack([p00, p10, p11, p00, p11, p01], axis=1).reshape(-1, 3)
    return v, f.astype(np.intp)


def damaged_model() -> tuple[FloatArray, IntArray]:
    """Make a ball with two faults to find and fix: a flipped patch and a hole.

    It is [`icosphere(3)`][trinormal.mesh.icosphere] (a unit sphere of 1280
    triangles) with the faces of one round patch turned over (each one's last
    two corners swapped, so its normal points inward) and the faces of another,
    smaller patch removed, together with the vertices only they used. The
    package ships it as ``trinormal/mesh/data/damaged_ball.obj`` (see
    [`sample_path`][trinormal.mesh.sample_path]), written by this function.

    Returns
    -------
    vertices : ndarray, shape (V, 3)
    faces : ndarray of int, shape (F, 3)

    Examples
    --------
    >>> from trinormal.mesh import check
    >>> v, f = damaged_model()
    >>> r = check(v, f)
    >>> len(r.faces_to_flip), len(r.boundary_edges), r.closed, r.consistent_winding
    (53, 13, False, False)
    """
    v, f = icosphere(3)
    centre = v[f].mean(axis=1)
    centre /= np.linalg.norm(centre, axis=1, keepdims=True)
    toward_viewer = np.array([0.6, -0.64, 0.48])  # the patch faces a default 3D view's camera
    hole_side = np.array([-0.48, 0.6, 0.64])
    patch = centre @ (toward_viewer / np.linalg.norm(toward_viewer)) > math.cos(math.radians(24))
    hole = centre @ (hole_side / np.linalg.norm(hole_side)) > math.cos(math.radians(14))
    f = f.copy()
    f[patch] = f[patch][:, [0, 2, 1]]
    f = f[~hole]
    used = np.zeros(v.shape[0], dtype=bool)
    used[f.ravel()] = True
    renumber = np.cumsum(used) - 1
    return v[used], renumber[f].astype(np.intp)
