"""Triangle meshes with numpy: normals, what is wrong with a model, and its repair.

A mesh is two arrays: ``vertices`` of shape (V, 3), one point per row, and
``faces`` of shape (F, 3), three row indices into ``vertices`` per triangle.
Face ``(i, j, k)`` has the normal ``N = (v[j] - v[i]) × (v[k] - v[i])``, the
same formula and the same winding as [`trinormal.triangle_normal`][trinormal.core.triangle_normal].

The modules, each named for what it answers:

* `normals` — [`face_normals`][trinormal.mesh.face_normals],
  [`vertex_normals`][trinormal.mesh.vertex_normals],
  [`degenerate_faces`][trinormal.mesh.degenerate_faces],
  [`face_areas`][trinormal.mesh.face_areas];
* `topology` — how faces fit together: shared, boundary and non-manifold
  edges, connected pieces, [`consistent_winding`][trinormal.mesh.consistent_winding];
* `repair` — [`fix_winding`][trinormal.mesh.fix_winding]: every piece wound
  one way, closed pieces facing out; [`turn_over`][trinormal.mesh.turn_over]
  turns chosen faces over;
* `report` — [`check`][trinormal.mesh.check]: everything wrong with a mesh,
  as counts, face lists and plain sentences;
* `printing` — [`PrintReport`][trinormal.mesh.PrintReport], ``check(...).printing``:
  holes, surface area, volume, size with a units hint, and whether a slicer can take it;
* `io` — [`read_mesh`][trinormal.mesh.read_mesh] and
  [`write_mesh`][trinormal.mesh.write_mesh] for OBJ, STL and PLY files, and
  [`sample_path`][trinormal.mesh.sample_path], the models shipped with the package;
* `shapes` — small meshes made in code ([`cube`][trinormal.mesh.cube],
  [`icosphere`][trinormal.mesh.icosphere], [`torus`][trinormal.mesh.torus],
  [`uv_sphere`][trinormal.mesh.uv_sphere], [`terrain`][trinormal.mesh.terrain]),
  outward-facing and consistently wound, and
  [`damaged_model`][trinormal.mesh.damaged_model], one with a flipped patch
  and a hole to practise on.

The promises, for every normal computed here:

* No NaN and no ``RuntimeWarning``, whatever the input. A degenerate face
  (``|N| <= tol · L²``, L its longest edge: the same verdict for every order of
  its corners and at every scale) gets a zero normal; a vertex that touches
  only degenerate faces gets a zero vertex normal.
* Coordinates near 1e-200 or 1e200 still give correct unit normals: rows that
  would underflow or overflow are redone with their edges scaled by powers of
  two, which is exact.
* float32 vertices are computed in float64 (the product of two float32 numbers
  is exact in float64) and the result comes back as float32. Any other real
  input is computed and returned in float64.
* Bad input raises a `ValueError` that names the first bad row.

Speed comes from plain numpy on one thread: the corners are gathered block by
block, 8 192 faces at a time, so that every temporary stays in the CPU cache,
and every operation writes in place. There is no Python loop over faces (only
over blocks of them, and over the rare faces too close to the threshold for
float64, which are decided exactly).

Examples
--------
>>> from trinormal import mesh
>>> v, f = mesh.cube()
>>> v.shape, f.shape
((8, 3), (12, 3))
>>> mesh.face_normals(v, f)[:2]
array([[ 0.,  0., -1.],
       [ 0.,  0., -1.]])
>>> bool(mesh.consistent_winding(f))
True
"""

from trinormal._optional import missing_extra

try:
    import numpy  # noqa: F401  (only to name the extra if it is missing)
except ModuleNotFoundError as exc:
    raise missing_extra(exc, __name__) from exc

from trinormal.mesh.io import (
    FORMATS,
    SAMPLES,
    MeshData,
    MeshFileError,
    parse_mesh,
    read_mesh,
    sample_path,
    write_mesh,
)
from trinormal.mesh.normals import (
    WEIGHTINGS,
    degenerate_faces,
    face_areas,
    face_normals,
    vertex_normals,
)
from trinormal.mesh.printing import PrintReport, Size
from trinormal.mesh.repair import fix_winding, signed_volume, turn_over
from trinormal.mesh.report import ComponentReport, MeshReport, check
from trinormal.mesh.shapes import cube, damaged_model, icosphere, terrain, torus, uv_sphere
from trinormal.mesh.topology import (
    boundary_edges,
    connected_components,
    consistent_winding,
    duplicate_faces,
    inconsistent_edges,
    non_manifold_edges,
    non_manifold_vertices,
)

__all__ = [
    "FORMATS",
    "SAMPLES",
    "WEIGHTINGS",
    "ComponentReport",
    "MeshData",
    "MeshFileError",
    "MeshReport",
    "PrintReport",
    "Size",
    "boundary_edges",
    "check",
    "connected_components",
    "consistent_winding",
    "cube",
    "damaged_model",
    "degenerate_faces",
    "duplicate_faces",
    "face_areas",
    "face_normals",
    "fix_winding",
    "icosphere",
    "inconsistent_edges",
    "non_manifold_edges",
    "non_manifold_vertices",
    "parse_mesh",
    "read_mesh",
    "sample_path",
    "signed_volume",
    "terrain",
    "torus",
    "turn_over",
    "uv_sphere",
    "vertex_normals",
    "write_mesh",
]
