"""The mesh parity corpus: every mesh file the tests use, and files made here.

`corpus()` returns ``(name, bytes)`` pairs: the files of ``tests/data/meshes/`` (the damaged
ones under ``bad/`` too), the models shipped in ``trinormal/mesh/data/``, the site page's
examples, and files written here from small models in every format and encoding the page
reads (OBJ, ASCII STL, binary STL, PLY ASCII, binary little endian and big endian), with
flipped patches, inside-out pieces, holes, fins, pinch points, degenerate, duplicate and
reversed faces, polygons, extreme scales and files that cannot be read (one at least for each
reason of `trinormal.mesh.io.READ_ERRORS`), and small files with random edits.

`outcome(name, data)` is what Python makes of a file, as the page shows it: the report
(``check(...).to_dict()``), its sentences, the page's tables of it
(`trinormal.mesh_page.report_table`), the format, the polygons the split found not
planar or crossing themselves, and the repaired file (`fix_winding`, then `write_mesh` of the
read model: the file itself with the faces turned over); or the sentence of the error.
``tests/test_mesh_parity.py`` runs the page's JavaScript on the same files in Node.
"""

from __future__ import annotations

import math
import random
import struct
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from trinormal.mesh import (
    check,
    cube,
    damaged_model,
    fix_winding,
    icosphere,
    parse_mesh,
    terrain,
    torus,
    uv_sphere,
    write_mesh,
)
from trinormal.mesh.io import MeshFileError, _format_of
from trinormal.mesh_page import EXAMPLES, example_file, report_table

ROOT = Path(__file__).resolve().parents[1]
STORED = (ROOT / "tests" / "data" / "meshes", ROOT / "trinormal" / "mesh" / "data")

#: A model: vertices (V, 3) and polygons (lists of vertex indices, three or more each).
Model = tuple[np.ndarray, list[list[int]]]


# --------------------------------------------------------------------------- what Python says


def _finite_or_text(x: Any) -> Any:
    """JSON has no inf or NaN: such a number is written as Python's repr of it."""
    if isinstance(x, float) and not math.isfinite(x):
        return repr(x)
    if isinstance(x, dict):
        return {k: _finite_or_text(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_finite_or_text(v) for v in x]
    return x


def outcome(name: str, data: bytes, scratch: Path) -> dict[str, Any]:
    """What the page shows for a file, computed by Python; the repaired file goes to ``scratch``."""
    try:
        m = parse_mesh(data, _format_of(name, None), name)
    except MeshFileError as exc:
        return {"error": str(exc), "key": exc.key}
    weld = name.startswith("weld-")  # the page's weld control, the CLI's --weld
    r = check(m.vertices, m.faces, weld=weld)
    fixed, _ = fix_winding(m.vertices, m.faces, weld=weld)
    write_mesh(scratch, m, fixed)
    before, after = m.normals_against(), m.normals_against(fixed)
    d = r.to_dict()
    return {
        "report": _finite_or_text(d),
        "summary": r.summary(width=0).split("\n"),
        "table": report_table(d),
        "format": m.format,
        "binary": m.encoding == "binary",
        "polygons": m.n_polygons,
        "split_polygons": m.split_polygons,
        "nonplanar_polygons": int(m.nonplanar.size),
        "crossing_polygons": int(m.crossing.size),
        "notes": list(m.notes),
        "normals_against": None if before is None else int(before.size),
        "normals_against_fixed": None if after is None else int(after.size),
    }


# --------------------------------------------------------------------------- writing files


def fan(polys: list[list[int]]) -> list[list[int]]:
    return [[p[0], p[k], p[k + 1]] for p in polys for k in range(1, len(p) - 1)]


def obj(v: np.ndarray, polys: list[list[int]], num: Callable[[float], str] = repr) -> bytes:
    lines = ["# made by tests/mesh_corpus.py", "o model"]
    lines += ["v " + " ".join(num(x) for x in row) for row in v.tolist()]
    lines += ["f " + " ".join(str(i + 1) for i in p) for p in polys]
    return ("\n".join(lines) + "\n").encode()


def stl_ascii(v: np.ndarray, polys: list[list[int]], num: Callable[[float], str] = repr) -> bytes:
    out = ["solid model"]
    for tri in fan(polys):
        out += ["  facet normal 0 0 0", "    outer loop"]
        out += ["      vertex " + " ".join(num(x) for x in v[i].tolist()) for i in tri]
        out += ["    endloop", "  endfacet"]
    out.append("endsolid model")
    return ("\n".join(out) + "\n").encode()


def stl_binary(v: np.ndarray, polys: list[list[int]], header: bytes = b"") -> bytes:
    tris = fan(polys)
    rec = np.zeros(len(tris), dtype=[("n", "<f4", 3), ("c", "<f4", (3, 3)), ("a", "<u2")])
    if tris:
        with np.errstate(over="ignore"):
            rec["c"] = v[np.array(tris)]
    return header.ljust(80, b" ")[:80] + struct.pack("<I", len(tris)) + rec.tobytes()


def ply(
    v: np.ndarray,
    polys: list[list[int]],
    fmt: str = "ascii",
    vtype: str = "double",
    count: str = "uchar",
    index: str = "int",
    extra: bool = False,
) -> bytes:
    """A PLY file; ``extra`` adds a vertex property and an element that readers skip."""
    head = ["ply", f"format {fmt} 1.0", "comment made by tests/mesh_corpus.py"]
    head += [f"element vertex {len(v)}"] + [f"property {vtype} {a}" for a in "xyz"]
    if extra:
        head.append("property uchar red")
    head += [f"element face {len(polys)}", f"property list {count} {index} vertex_indices"]
    if extra:
        head += ["element edge 1", "property int vertex1", "property int vertex2"]
    head.append("end_header")
    text = ("\n".join(head) + "\n").encode()
    if fmt == "ascii":
        rows = [" ".join(repr(x) for x in row) + (" 7" if extra else "") for row in v.tolist()]
        rows += [" ".join(str(i) for i in [len(p), *p]) for p in polys]
        rows += ["0 1"] if extra else []
        return text + ("\n".join(rows) + "\n").encode()
    o = "<" if fmt == "binary_little_endian" else ">"
    codes = {"float": "f", "double": "d", "uchar": "B", "ushort": "H", "int": "i", "uint": "I"}
    body = b"".join(
        struct.pack(o + "3" + codes[vtype], *row) + (b"\x07" if extra else b"")
        for row in v.tolist()
    )
    body += b"".join(
        struct.pack(f"{o}{codes[count]}{len(p)}{codes[index]}", len(p), *p) for p in polys
    )
    return text + body + (struct.pack(o + "2i", 0, 1) if extra else b"")


def every_encoding(name: str, model: Model) -> Iterator[tuple[str, bytes]]:
    """The model in each format and encoding the page reads."""
    v, polys = model
    yield f"{name}.obj", obj(v, polys)
    yield f"{name}-ascii.stl", stl_ascii(v, polys)
    yield f"{name}-binary.stl", stl_binary(v, polys)
    yield f"{name}-ascii.ply", ply(v, polys)
    with np.errstate(over="ignore"):
        single = bool((v.astype(np.float32).astype(np.float64) == v).all())
    vtype = "float" if single else "double"
    yield f"{name}-little.ply", ply(v, polys, "binary_little_endian", vtype)
    yield f"{name}-big.ply", ply(v, polys, "binary_big_endian", "double", "ushort", "uint")


# --------------------------------------------------------------------------- models


def tri(v: np.ndarray, f: np.ndarray) -> Model:
    return np.asarray(v, dtype=np.float64), np.asarray(f).tolist()


def turned(polys: list[list[int]], which: Any) -> list[list[int]]:
    out = [list(p) for p in polys]
    for i in which:
        out[i] = [out[i][0], *out[i][:0:-1]]
    return out


def quad_box() -> Model:
    """A box of six quads, and a pentagonal prism beside it (pentagons and quads)."""
    v, _ = cube()
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    ring = [(math.cos(2 * math.pi * k / 5) + 4, math.sin(2 * math.pi * k / 5)) for k in range(5)]
    prism = [(x, y, z) for z in (0.0, 1.5) for x, y in ring]
    polys = [*quads, [8 + k for k in range(5)][::-1], [13 + k for k in range(5)]]
    polys += [[8 + k, 8 + (k + 1) % 5, 13 + (k + 1) % 5, 13 + k] for k in range(5)]
    return np.vstack([v, prism]), polys


def mobius(n: int = 12) -> Model:
    pts = []
    for i in range(n):
        t = 2 * math.pi * i / n
        for s in (-0.3, 0.3):
            r = 1 + s * math.cos(t / 2)
            pts.append((r * math.cos(t), r * math.sin(t), s * math.sin(t / 2)))
    polys = []
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        c, d = (2 * i + 2, 2 * i + 3) if i < n - 1 else (1, 0)  # the half twist
        polys += [[a, c, b], [b, c, d]]
    return np.array(pts), polys


def tetra(shift: tuple[float, float, float] = (0, 0, 0)) -> Model:
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float) + shift
    return v, [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def joined(*models: Model) -> Model:
    vs, polys, base = [], [], 0
    for v, p in models:
        vs.append(v)
        polys += [[i + base for i in q] for q in p]
        base += len(v)
    return np.vstack(vs), polys


def faulty() -> Model:
    """A cube with every fault at once: a fin, a pinch point, flat and repeated faces."""
    v, f = cube()
    polys = np.asarray(f).tolist()
    extra = [[2.0, 2.0, 2.0], [1.0, 1.0, 3.0], [0.0, -1.0, -1.0], [5.0, 5.0, 5.0]]
    v = np.vstack([v, extra, [[1.0, 1.0, 1.0]]])  # 12: a second vertex on corner 7
    polys += [[7, 6, 8]]  # a fin on the edge 6-7
    polys += [[7, 9, 12]]  # a flat face: corners 7 and 12 at one point
    polys += [[0, 1, 10]]  # collinear: 10 is the middle of edge 0-1
    polys += [[0, 0, 3]]  # one vertex used twice
    polys += [polys[0], polys[1][::-1]]  # a repeat and a reversed repeat
    return v, polys  # vertex 11 is not used


def thin(tol_factor: float) -> Model:
    """A triangle whose |N| / L² is ``tol_factor`` times the default tolerance (1e-12)."""
    h = 1e-12 * tol_factor
    return np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, h, 0.0]]), [[0, 1, 2], [0, 2, 1]]


#: The three rotations and the two windings of a face's corners.
ORDERS = ((0, 1, 2), (1, 2, 0), (2, 0, 1), (0, 2, 1), (2, 1, 0), (1, 0, 2))


def slivers(scale: float) -> Model:
    """Thin and nearly coincident faces, each in every order of its corners, times ``scale``.

    Each face has its own copies of its corners, so none is a duplicate of another. A needle
    (one edge 1e-13 long) is degenerate whichever corner comes first; faces on and just off
    the threshold |N| = tol · L² are decided in exact arithmetic, tilted ones too, so their
    normals are quotients of integers.
    """
    tol = 1e-12
    b = np.array([1.0, 0.5, 0.25])
    side = np.cross(b, [0.0, 0.0, 1.0])
    h = tol * (b @ b) / np.linalg.norm(np.cross(side, b))
    faces = [
        [[0, 0, 0], [1, 0, 0], [0, 1e-13, 0]],  # a needle
        [[0, 0, 0], [1, 0, 0], [1, 1e-13, 0]],  # a sliver: two corners nearly coincident
        [[0, 0, 0], [1, 0, 0], [1 + 1e-13, 1e-13, 0]],
        [[0, 0, 0], [1, 0, 0], [0, 3e-12, 0]],  # thin but above the threshold
        [[0, 0, 0], [1, 0, 0], [0, tol, 0]],  # on the threshold: degenerate
        [[0, 0, 0], [1, 0, 0], [0, math.nextafter(tol, 1), 0]],  # just above it
        [[0, 0, 0], b, 0.5 * b + h * side],  # tilted, about on the threshold
        [[0, 0, 0], b, 0.5 * b + math.nextafter(h, 1) * 1.5 * side],
        [[0, 0, 0], b, 0.5 * b + h * 0.75 * side],
    ]
    v = np.array([face[k] for face in faces for order in ORDERS for k in order], dtype=np.float64)
    return v * scale, [[3 * i, 3 * i + 1, 3 * i + 2] for i in range(len(v) // 3)]


def seamed(model: Model, side: Callable[[np.ndarray], np.ndarray]) -> Model:
    """The model with its own copies of the vertices of the faces on one ``side``: a UV seam.

    Vertices no face uses afterwards are dropped, as an exporter writes only what it uses.
    """
    v, polys = model
    f = np.asarray(polys)
    mine = side(v[f].mean(axis=1))
    out = f.copy()
    out[mine] = f[mine] + len(v)
    both = np.vstack([v, v])
    used, index = np.unique(out, return_inverse=True)
    return both[used], index.reshape(out.shape).tolist()


def soup(model: Model, noise: float = 0.0, seed: int = 3) -> Model:
    """Every face with its own three corners, moved by up to ``noise`` of the size at random."""
    v, polys = model
    corners = v[np.asarray(polys)].reshape(-1, 3)
    rng = np.random.default_rng(seed)
    size = float((v.max(axis=0) - v.min(axis=0)).max())
    corners = corners + rng.uniform(-noise, noise, corners.shape) * size
    return corners, np.arange(len(corners)).reshape(-1, 3).tolist()


def last_bits(model: Model, seed: int = 4) -> Model:
    """A soup whose corners differ in their last bits: what a CAD tessellation writes."""
    v, polys = soup(model)
    rng = np.random.default_rng(seed)
    steps = rng.integers(-2, 3, v.shape)
    out = v.copy()
    for _ in range(2):
        out = np.where(steps > 0, np.nextafter(out, np.inf), out)
        out = np.where(steps < 0, np.nextafter(out, -np.inf), out)
        steps = np.sign(steps) * (np.abs(steps) - 1)
    return out, polys


def hollow_plate(n: int = 160, subdivisions: int = 0) -> Model:
    """``n`` hollow balls in a row, of radius 1 and 2 in turn, each inner shell facing its hollow.

    More pieces than one block of the cavity search's box comparison, side by side and
    nested, a small ball's box inside a big ball's in x alone.
    """
    v, f = icosphere(subdivisions)
    models = []
    for k in range(n):
        big = 1.0 + (k % 2)
        models.append(tri(v * big + (5.0 * k, 0.0, 0.0), f))
        models.append(tri(v * 0.6 * big + (5.0 * k, 0.0, 0.0), f[:, ::-1]))
    return joined(*models)


def shells_and_open_pieces() -> Iterator[tuple[str, Model]]:
    """Welded seams, soups, near misses, hollow models, cups, sheets (issue 31)."""
    ball = tri(*icosphere(2))
    yield "uv-seamed", seamed(tri(*uv_sphere(16, 8)), lambda c: c[:, 1] > 0)
    yield "cad-noise", last_bits(ball)
    yield "soup", soup(ball)
    yield "weld-soup", soup(ball)
    yield "near-miss", soup(ball, 2e-6)
    yield "weld-near-miss", soup(ball, 2e-6)
    yield "far-miss", soup(ball, 3e-3)  # a real gap: neither merged nor a near miss
    v, f = icosphere(2)
    inner = v * 0.6
    yield "hollow-ball", (np.vstack([v, inner]), f.tolist() + (f[:, ::-1] + len(v)).tolist())
    yield "hollow-ball-wrong", (np.vstack([v, inner]), f.tolist() + (f + len(v)).tolist())
    nested = [v, inner, v * 0.3]
    polys = f.tolist() + (f[:, ::-1] + len(v)).tolist() + (f + 2 * len(v)).tolist()
    yield "ball-in-hollow-ball", (np.vstack(nested), polys)  # a ball inside the cavity
    centres = v[f].mean(axis=1)
    holed = f[centres[:, 2] < 0.9]
    yield "ball-hole-inward", tri(v, holed[:, ::-1])
    yield "ball-hole", tri(v, holed)
    cup = f[centres[:, 2] < 0.05]
    yield "cup-inward", tri(v, cup[:, ::-1])
    yield "cup", tri(v, cup)
    gv, gf = terrain(6, 5)
    yield "sheet-flat", tri(gv * [1.0, 1.0, 0.0], gf)
    yield "sheet-flat-down", tri(gv * [1.0, 1.0, 0.0], np.asarray(gf)[:, ::-1])
    yield "terrain-up", tri(gv, gf)


def models() -> Iterator[tuple[str, Model]]:
    rng = np.random.default_rng(30)
    v, f = cube()
    yield "cube", tri(v, f)
    yield "cube-one-flipped", tri(v, turned(np.asarray(f).tolist(), [3]))
    yield "cube-inside-out", tri(v, np.asarray(f)[:, ::-1])
    yield "cube-hole", tri(v, np.asarray(f)[:-2])
    v, f = icosphere(2)
    centres = v[f].mean(axis=1)
    yield "ball-patch", tri(v, turned(f.tolist(), np.flatnonzero(centres[:, 0] > 0.4)))
    noisy = v * (1 + rng.normal(0, 1e-3, v.shape))
    yield "ball-noisy-inside-out", tri(noisy, np.asarray(f)[:, ::-1])
    v, f = torus(n_major=40, n_minor=24)
    noisy = v + rng.normal(0, 1e-4, v.shape)
    keep = np.flatnonzero(noisy[f].mean(axis=1)[:, 2] < 0.3)  # a torus with its top cut off
    yield "torus-noisy-mixed", tri(noisy, turned(f.tolist(), range(0, len(f), 7)))
    yield "torus-cut", tri(noisy, np.asarray(f)[keep])
    v, f = uv_sphere(16, 8)
    yield "uv-sphere", tri(v, f)
    v, f = terrain(10, 8)
    yield "terrain", tri(v, turned(f.tolist(), range(5, 40)))
    v, f = damaged_model()
    yield "damaged", tri(v, f)
    yield "polygons", quad_box()
    yield "polygons-flipped", (quad_box()[0], turned(quad_box()[1], [1, 7]))
    yield "mobius", mobius()
    yield "two-pieces", joined(tetra(), tri(*cube()))
    inner = (cube(1.0)[0], np.asarray(cube()[1])[:, ::-1].tolist())
    yield "hollow", joined(tri(*cube()), inner)  # a wall with thickness: the inner faces in
    v = np.vstack([tetra()[0], [[2.0, 0, 0], [1, 1, 0], [1, 0, 1]]])  # a second tetrahedron
    yield "pinch", (v, tetra()[1] + [[1, 5, 4], [1, 4, 6], [1, 6, 5], [4, 5, 6]])  # at vertex 1
    yield "sheet-doubled", (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]]), [[0, 1, 2], [0, 2, 1]])
    yield "every-fault", faulty()
    yield "thin-below-tol", thin(0.5)
    yield "thin-above-tol", thin(2.0)
    for scale in (1.0, 1e-300, 1e300):
        yield f"slivers-scale-{scale:g}", slivers(scale)
    for scale in (1e-300, 1e-200, 1e-160, 1e150, 1e200, 1e300):
        v, f = icosphere(1)
        yield f"ball-scale-{scale:g}", tri(v * scale, turned(f.tolist(), [0, 5]))
    v, f = cube()
    yield "cube-far", tri(v + 1e16, f)  # every edge is 2, the coordinates are 1e16
    # at 8e307 differences of coordinates overflow, at 1e300 and 1e-300 triple products do
    for scale in (8e307, 1e300, 1e-300):
        for name, (v, f) in (("cube", cube()), ("sphere", uv_sphere(16, 8))):
            yield f"{name}-scale-{scale:g}", tri(v * scale, f)
            yield f"{name}-scale-{scale:g}-inside-out", tri(v * scale, np.asarray(f)[:, ::-1])
    yield "float32", tri(icosphere(1)[0].astype(np.float32).astype(np.float64), icosphere(1)[1])
    yield "subnormal", tri(tetra()[0] * 5e-324 * 7, tetra()[1])
    yield from printing_models()


def printing_models() -> Iterator[tuple[str, Model]]:
    """The report for printing: every units hint, volumes of several pieces, many holes, -0.0."""
    v, f = cube()
    yield "print-cube-mm", tri(v * 10, f)  # 20 mm: no hint, ready for a slicer
    yield "print-cube-metres", tri(v * 0.02, f)
    yield "print-cube-micrometres", tri(v * 1e4, f)
    opened = (v + 10, np.asarray(f)[:-2].tolist())
    yield "print-closed-and-open", joined(tri(v, f), tetra((5, 0, 0)), opened)
    yield (
        "print-inside-out-piece",
        joined(tri(v, f), (tetra((5, 0, 0))[0], turned(tetra()[1], range(4)))),
    )
    v, f = icosphere(3)
    yield "print-many-holes", tri(v, np.delete(f, np.arange(0, len(f), 53), axis=0))
    v = tetra()[0] * 30
    v[0] = -0.0  # a corner at -0.0: the box starts at 0, never -0
    yield "print-negative-zero", (v, tetra()[1])


# --------------------------------------------------------------------------- variants of files


def variants() -> Iterator[tuple[str, bytes]]:
    """Files that say the same things in other ways: what readers meet in the wild."""
    v, f = cube()
    polys = np.asarray(f).tolist()
    yield "short-numbers.obj", obj(v * 1.1, polys, lambda x: f"{x:.6g}")
    yield "exponents.obj", obj(v * 1e-7, polys, lambda x: f"{x:e}")
    yield "negative-indices.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -2 -3\nf -4 -3 -1\n"
    yield "slashes.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3//1\n"
    yield "forward.obj", b"f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
    yield "continued.obj", b"v 0 0 \\\n0\nv 1 0 0\nv 0 1 0 # comment\nf 1 2 \\\n 3\n"
    yield "bom.obj", b"\xef\xbb\xbfv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"
    yield "latin1.obj", b"# caf\xe9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
    uni = "v 0 0 0\nv 1\u00a00\u30000\u2028v 0 \u0661 0\x0bv 0 0 \uff11\nf 1 2 3\x1cf 1 3 \u0664\u2029"
    uni += "v \U0001d7d9 0 0\x85f 1 \u0662 -\u0661\n"  # digits of other scripts
    yield "unicode-space.obj", uni.encode()
    yield "underscores.obj", b"v 1_0 0 0\nv 0 1_0.5 0\nv 0 0 1e1_0\nf 1 2 3\nf +1 3 0_2\n"
    yield "specials.obj", b"v +.5 -0 0\nv 5. 0 0\nv 0 1E+00 0\nf 1 2 3\n"
    yield "fo.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nfo 1 2 4 3\nl 1 2\ng x\ns off\n"
    yield "solid-header.stl", stl_binary(v, polys, b"solid but binary")
    yield "upper.stl", stl_ascii(v, polys).upper().replace(b"E+", b"e+")
    yield "short-numbers.stl", stl_ascii(v * 0.3, polys, lambda x: f"{x:.3e}")
    yield "no-triangles.stl", stl_binary(v, [])
    yield "empty-solid.stl", b"solid nothing\nendsolid nothing\n"
    yield "ushort-counts.ply", ply(v, polys, "binary_little_endian", "float", "ushort", "uint")
    yield "extras-ascii.ply", ply(v, polys, extra=True)
    yield "extras-little.ply", ply(v, polys, "binary_little_endian", extra=True)
    yield "extras-big.ply", ply(v, polys, "binary_big_endian", extra=True)
    qv, qp = quad_box()
    yield "mixed-little.ply", ply(qv, qp, "binary_little_endian", "double", "uchar", "uint")
    yield "mixed-big.ply", ply(qv, qp, "binary_big_endian", "float", "int", "int")
    yield "float-indices.ply", ply(v, polys, "binary_little_endian", "float", "uchar", "float")
    vertex_index = ply(v, polys).replace(b"vertex_indices", b"vertex_index")
    yield "vertex-index.ply", vertex_index
    yield "crlf.ply", ply(v, polys).replace(b"\n", b"\r\n")
    yield "ints.ply", ply(v.astype(int), polys, "binary_little_endian", "int")
    yield "no-faces.ply", ply(v, [])
    yield "UPPER.OBJ", obj(v, polys)
    yield "slash-back.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf -3/-1 -2/-1/-1 -1//1\n"
    yield "only-vertices.obj", b"v 0 0 0\nv 1 0 0\n"
    two = stl_ascii(v, polys[:6]) + stl_ascii(v, polys[6:]).replace(b"model", b"second")
    yield "two-solids.stl", two
    yield (
        "bare-facets.stl",
        b"solid\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n",
    )
    face_first = (
        "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar float texcoord\n"
        "property list uchar int vertex_indices\n" + _XYZ + "end_header\n"
        "2 0.5 0.5 3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n"
    )
    yield "face-first.ply", face_first.encode()
    head = face_first[: face_first.index("2 0.5")].replace("ascii", "binary_little_endian")
    body = struct.pack("<B2fB3i", 2, 0.5, 0.5, 3, 0, 1, 2) + struct.pack(
        "<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0
    )
    yield "face-first-binary.ply", head.encode() + body
    rows = struct.pack("<b3i", 3, 0, 1, 2) + struct.pack("<b3i", -1, 0, 1, 2)
    negative = ply(np.eye(3), [], "binary_little_endian", "double", "char", "int")
    yield "negative-count.ply", negative.replace(b"face 0", b"face 2") + rows
    yield "zero-corners.ply", ply(np.eye(3), [[0, 1, 2], []], "binary_little_endian")


# --------------------------------------------------------------------------- unreadable files


def _ply_text(body: str, header: str | None = None) -> bytes:
    head = header or (
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    )
    return (head + body).encode("utf-8")


_GOOD_PLY_BODY = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
_PLY_HEAD = "ply\nformat ascii 1.0\n"
_FACE_HEAD = "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
_XYZ = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"


def unreadable() -> Iterator[tuple[str, bytes]]:
    """Files Python refuses, at least one for every reason it gives, and tokens to quote."""
    tri3 = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    yield "model.txt", tri3
    yield "model", tri3
    yield ".obj", tri3
    yield "..obj", tri3
    yield "model.", tri3
    yield "nul.obj", tri3 + b"f 1 2\x003\n"
    yield "letters.obj", b"v 1 x 2\n"
    yield "quotes.obj", b"v 1 2 it's\n"
    yield "both-quotes.obj", b"v 1 2 it's\"\n"
    yield "backslash.obj", b"v 1 2 a\\b\n"
    yield "control.obj", b"v 1 2 a\x01\x7f\n"
    yield "latin1-token.obj", b"v 1 2 caf\xe9\n"
    yield "zero-width.obj", "v 1 2 a\u200bb\n".encode()
    yield "soft-hyphen.obj", "v 1 2 a\u00adb\u0085c\n".encode()
    yield "emoji.obj", "v 1 2 \U0001f600x\n".encode()
    yield "tag.obj", "v 1 2 \U000e0001\n".encode()
    yield "long-token.obj", ("v 1 2 " + "9" * 30 + "x" * 30 + "\n").encode()
    yield "long-emoji.obj", ("v 1 2 " + "\U0001f600" * 45 + "\n").encode()
    yield "minus-sign.obj", "v \u22121 0 0\n".encode()
    yield "inf.obj", b"v 0 inf 0\n"
    yield "nan.obj", b"v 0 0 -NaN\n"
    yield "overflow.obj", b"v 1e400 0 0\n"
    yield "two-coords.obj", b"v 0 0\n"
    yield "short-face.obj", tri3 + b"f 1 2\n"
    yield "bad-index.obj", tri3 + b"f 1 2 x/1\n"
    yield "float-index.obj", tri3 + b"f 1 2 3.0\n"
    yield "back.obj", tri3 + b"f -4 1 2\n"
    yield "back-one.obj", b"v 0 0 0\nf -2 1 1\n"
    yield "zero.obj", tri3 + b"f 0 1 2\n"
    yield "keyword.obj", tri3 + b"vx 1 2 3\n"
    yield "empty.obj", b"# nothing\n\n"
    yield "range.obj", tri3 + b"f 1 2 3\nf 1 2 4\n"
    yield "huge-index.obj", tri3 + b"f 1 2 3 99999999999999999999\n"
    yield "huge-back.obj", tri3 + b"f 1 2 -99999999999999999999\n"
    yield "inf.stl", stl_binary(np.array([[0, 0, 0], [1, 0, 0], [0, math.inf, 0.0]]), [[0, 1, 2]])
    yield "nan.stl", stl_binary(np.array([[0, 0, 0], [1, 0, 0], [0, math.nan, 0.0]]), [[0, 1, 2]])
    yield "jpeg.stl", b"\xff\xd8\xff\xe0" + bytes(300)
    yield "solid-nul.stl", b"solid x\n" + bytes(100)
    yield "tiny.stl", b"hello"
    facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
    yield "vertex-outside.stl", b"solid x\nvertex 0 0 0\n"
    yield "vertex-two.stl", b"solid x\nouter loop\nvertex 0 0\n"
    yield "endloop-alone.stl", b"solid x\nendloop\n"
    yield "two-vertices.stl", b"solid x\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"
    yield "endfacet-early.stl", b"solid x\nouter loop\nvertex 0 0 0\nendfacet\n"
    yield "keyword.stl", ("solid x\n" + facet + "endfacet\nnormal 0 0 1\n").encode()
    yield "ends-inside.stl", b"solid x\nouter loop\nvertex 0 0 0\n"
    yield "bad-number.stl", b"solid x\nouter loop\nvertex 0 0 zero\n"
    yield "inf-ascii.stl", b"solid x\nouter loop\nvertex 0 0 -Infinity\n"
    yield "nul-ascii.stl", b"solid x\nouter loop\n\x00"
    yield "no-ply.ply", b"PLY\nend_header\n"
    yield "no-end.ply", b"ply\nformat ascii 1.0\n"
    yield "format.ply", _ply_text("", "ply\nformat text 1.0\nend_header\n")
    yield "element.ply", _ply_text("", "ply\nformat ascii 1.0\nelement vertex x\nend_header\n")
    yield "prop-first.ply", _ply_text("", _PLY_HEAD + "property float x\nend_header\n")
    yield "type.ply", _ply_text("", _PLY_HEAD + _XYZ + "property list uchar huge i\nend_header\n")
    yield "property.ply", _ply_text("", _PLY_HEAD + _XYZ + "property  float  \nend_header\n")
    yield "keyword.ply", _ply_text("", _PLY_HEAD + "elements vertex 3\nend_header\n")
    yield "no-format.ply", _ply_text("", "ply\n" + _XYZ + "end_header\n")
    yield "no-vertex.ply", _ply_text("", _PLY_HEAD + "element face 0\nend_header\n")
    yield (
        "vertex-list.ply",
        _ply_text("", _PLY_HEAD + _XYZ + "property list uchar int i\nend_header\n"),
    )
    yield "no-z.ply", _ply_text("", _PLY_HEAD + "element vertex 0\nproperty float x\n"
                                "property float y\nend_header\n")  # fmt: skip
    yield "nan.ply", _ply_text("0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n")
    yield "two-corners.ply", _ply_text("0 0 0\n1 0 0\n0 1 0\n2 0 1\n")
    yield "range.ply", _ply_text("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")
    yield "range-none.ply", _ply_text("3 0 1 2\n", _PLY_HEAD + "element vertex 0\n"
        "property float x\nproperty float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n")  # fmt: skip
    yield "ascii-short.ply", _ply_text("0 0 0\n1 0 0\n")
    yield "expected.ply", _ply_text("0 0 0\n1 0\n0 1 0\n3 0 1 2\n")
    yield "ply-number.ply", _ply_text("0 0 0\n1 0 0\n0 1 O\n3 0 1 2\n")
    yield "row.ply", _ply_text("0 0 0\n1 0 0\n0 1 0\n3 0 1\n")
    yield "row-letter.ply", _ply_text("0 0 0\n1 0 0\n0 1 0\n3 0 one 2\n")
    yield "too-many.ply", _ply_text("0 0 0\n1 0 0\n0 1 0\n3 0 1 2 5 6\n")
    yield "nul-body.ply", _ply_text("0 0 0\n1 0 0\n0 1\x000\n3 0 1 2\n")
    v, f = cube()
    little = ply(v, np.asarray(f).tolist(), "binary_little_endian", "float")
    yield "binary-short.ply", little[: little.index(b"end_header") + 11 + 50]
    yield "binary-row.ply", little[:-7]
    big = ply(*quad_box(), "binary_big_endian")
    yield "binary-row-mixed.ply", big[:-3]
    yield "binary-inf.ply", ply(np.array([[0, 0, 0], [1, 0, 0], [0, math.inf, 0]]), [[0, 1, 2]],
                                "binary_little_endian")  # fmt: skip
    yield "binary-range.ply", ply(np.eye(3), [[0, 1, 2], [0, 1, 7]], "binary_big_endian")
    yield "good-after-bad-name.ply", _ply_text(_GOOD_PLY_BODY)
    huge = "element vertex 99999999999999999999\nproperty float x\nproperty float y\nproperty float z\n"
    yield "huge-count.ply", _ply_text("0 0 0\n", _PLY_HEAD + huge + "end_header\n")
    yield (
        "huge-count-binary.ply",
        ("ply\nformat binary_big_endian 1.0\n" + huge + "end_header\n").encode(),
    )
    yield (
        "unicode-count.ply",
        _ply_text(_GOOD_PLY_BODY, _PLY_HEAD + _XYZ.replace("3", "\u00b3") + _FACE_HEAD),
    )
    yield (
        "arabic-count.ply",
        _ply_text(_GOOD_PLY_BODY, _PLY_HEAD + _XYZ.replace("3", "\u0663") + _FACE_HEAD),
    )
    tri = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    for fmt in ("binary_little_endian", "binary_big_endian"):
        yield (
            f"negative-count-{fmt}.ply",
            ply(tri, [[0, 1, 2]], fmt, count="int")[:-16]
            + struct.pack("<i" if "little" in fmt else ">i", -3)
            + bytes(12),
        )
        yield f"float-indices-{fmt}.ply", ply(tri, [[0, 1, 2], [0, 2, 1]], fmt, index="float")
        yield f"float-half-{fmt}.ply", ply(tri, [[0, 1, 2], [0, 1.5, 2]], fmt, index="float")
        yield f"float-beyond-{fmt}.ply", ply(tri, [[0, 1, 2], [0, 9, 2, 1]], fmt, index="double")
    yield "float-indices-ascii.ply", ply(tri, [[0, 1, 2]], index="float")
    yield "float-half-ascii.ply", _ply_text("0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", _PLY_HEAD + _XYZ
        + "element face 1\nproperty list uchar float vertex_indices\nend_header\n")  # fmt: skip
    yield "zero-count.ply", _ply_text(_GOOD_PLY_BODY, _PLY_HEAD + _XYZ.replace("3", "003") + "element face 01\n"
        "property list uchar int vertex_indices\nend_header\n")  # fmt: skip


def damaged(rng: random.Random, data: bytes) -> bytes:
    """A file with a few random edits: bytes inserted, deleted or changed, or the end cut off."""
    words = [b"nan", b"inf", b"1_0", b"-0", b"x", b"#", b"\\", b"f", b"vt", b"endloop", b"3"]
    words += [b"-1", b"1e400", b"\n", b"\r\n", b"\0", b"element", b"end_header", b"99", b"\xff"]
    words += ["\u0661".encode(), b"\x85", b"solid", b"property list uchar int"]
    out = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        i, op = rng.randrange(len(out) + 1), rng.random()
        if op < 0.35:
            out[i:i] = rng.choice(words)
        elif op < 0.6:
            del out[i : i + rng.randint(1, 8)]
        elif op < 0.75:
            del out[i:]
        elif out:
            out[min(i, len(out) - 1)] = rng.randrange(256)
    return bytes(out)


def lenient() -> Iterator[tuple[str, bytes]]:
    """Binary STL files whose triangle count disagrees with their size, and empty files.

    Read with a note: whole 50-byte records after the header whatever the count says, and
    fewer than 50 bytes after the counted records. Refused: any other size, and a file with
    no faces (no bytes at all, or nothing but a header).
    """
    v, polys = tetra()
    good = stl_binary(v, polys)  # 4 triangles

    def counted(n: int, data: bytes = good) -> bytes:
        return data[:80] + struct.pack("<I", n) + data[84:]

    yield "count-zero.stl", counted(0)
    yield "count-big.stl", counted(7)
    yield "count-small.stl", counted(1)
    yield "count-huge.stl", counted(2**32 - 1)
    yield "count-zero-solid.stl", counted(0, stl_binary(v, polys, b"solid tetra"))
    for extra in range(1, 50):
        yield f"trailing-{extra}.stl", good + bytes(range(extra))
    yield "count-zero-trailing.stl", counted(0) + bytes(7)  # neither rule: not an STL
    yield "count-big-trailing.stl", counted(5) + bytes(49)
    yield "header-only.stl", good[:84]  # the count says 4: not an STL
    yield "header-only-zero.stl", counted(0, good[:84])  # no faces
    yield "header-trailing.stl", counted(0, good[:84]) + bytes(30)  # no faces, a note
    yield "solid-empty.stl", b"solid empty\nendsolid empty\n"
    for ext in ("obj", "stl", "ply", "STL"):
        yield f"zero-bytes.{ext}", b""


# --------------------------------------------------------------------------- what a fix keeps


def _box_quads() -> tuple[np.ndarray, list[list[int]]]:
    v, _ = cube()
    return v, [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def textured_obj(flip: tuple[int, ...] = (), crlf: bool = False) -> bytes:
    """Textured quads as exporters write them: vt, vn, usemtl, g, o, s, comments, colours.

    Faces ``flip`` are written turned over (corners, with their references, reversed).
    """
    v, quads = _box_quads()
    lines = ["# Blender 4.2 export", "mtllib box.mtl", "o Box"]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f} 0.8 0.{k} 0.1" for k, (x, y, z) in enumerate(v.tolist())]
    lines += ["vt 0.0 0.0", "vt 1.0 0.0", "vt 1.0 1.0", "vt 0.0 1.0"]
    normals = ["0 0 -1", "0 0 1", "0 -1 0", "0 1 0", "-1 0 0", "1 0 0"]
    lines += [f"vn {n}" for n in normals]
    lines += ["g sides", "usemtl red", "s 1"]
    for k, q in enumerate(quads):
        if k == 3:
            lines += ["# the top and the sides", "g top", "usemtl blue", "s off"]
        refs = [f"{i + 1}/{c + 1}/{k + 1}" for c, i in enumerate(q)]
        if k in flip:
            refs = [refs[0], *refs[:0:-1]]
        lines.append("f  " + "  ".join(refs) + ("  # a comment" if k == 1 else ""))
    lines.append("l 1 2")
    return ("\r\n" if crlf else "\n").join(lines).encode() + b"\n"


def l_prism(flip: tuple[int, ...] = ()) -> Model:
    """A prism over an L: two concave hexagon caps and six quad sides."""
    ring = [(1, 2), (0, 2), (0, 0), (2, 0), (2, 1), (1, 1)]
    v = np.array([(x, y, z) for z in (0.0, 1.0) for x, y in ring], dtype=np.float64)
    polys = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11]]
    polys += [[k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k] for k in range(6)]
    return v, turned(polys, flip)


def warped() -> Model:
    """Quads over a wavy grid (not planar), one self-crossing quad and a flat pentagon."""
    xs = np.arange(4.0)
    v = np.array([(x, y, 0.3 * math.sin(x + 2 * y)) for y in xs for x in xs])
    polys = [
        [4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4] for j in range(3) for i in range(3)
    ]
    polys = turned(polys, [4])
    bow = np.array([[10, 0, 0], [12, 2, 0], [12, 0, 0], [10, 1, 0.0]])
    star = np.array([[20 + math.cos(a), math.sin(a), 0] for a in np.arange(5) * 4 * math.pi / 5])
    return np.vstack([v, bow, star]), [*polys, [16, 17, 18, 19], [20, 21, 22, 23, 24]]


def rich_ply(
    fmt: str, count: str = "uchar", index: str = "int", flip: tuple[int, ...] = ()
) -> bytes:
    """A PLY of the L prism with vertex normals and colours, face flags and texture lists."""
    v, polys = l_prism(flip)
    head = ["ply", f"format {fmt} 1.0", "comment made by tests/mesh_corpus.py", "obj_info an L"]
    head += [f"element vertex {len(v)}"] + [f"property float {a}" for a in "xyz"]
    head += ["property float nx", "property float ny", "property float nz"]
    head += ["property uchar red", "property uchar green", "property uchar blue"]
    head += [f"element face {len(polys)}", "property uchar flags"]
    head += [f"property list {count} {index} vertex_indices", "property list uchar float texcoord"]
    head += ["comment after the faces", "element material 1", "property uchar id", "end_header"]
    text = ("\n".join(head) + "\n").encode()
    uv = [[(k % 3) * 0.5, (k // 3) * 0.25] for k in range(12)]
    if fmt == "ascii":
        rows = [" ".join(f"{x:g}" for x in row) + f" 0 0 1 {k} 20 200" for k, row in enumerate(v)]
        rows += [
            f"{k % 3} {len(p)} "
            + " ".join(map(str, p))
            + f"  {2 * len(p)} "
            + " ".join(f"{c:g}" for i in p for c in uv[i])
            for k, p in enumerate(polys)
        ]
        return text + ("\n".join([*rows, "9"]) + "\n").encode()
    o = "<" if fmt == "binary_little_endian" else ">"
    codes = {"uchar": "B", "int": "i", "uint": "I", "ushort": "H"}
    body = b"".join(struct.pack(o + "6f3B", *row, 0, 0, 1, k, 20, 200) for k, row in enumerate(v))
    for k, p in enumerate(polys):
        body += struct.pack(f"{o}B{codes[count]}{len(p)}{codes[index]}", k % 3, len(p), *p)
        body += struct.pack(f"{o}B{2 * len(p)}f", 2 * len(p), *[c for i in p for c in uv[i]])
    return text + body + b"\x09"


def kept() -> Iterator[tuple[str, bytes]]:
    """Files whose repair must keep everything: rich OBJ, PLY and STL, polygons of every kind."""
    for flip, tag in (((), "fine"), ((1, 4), "flipped")):
        yield f"textured-{tag}.obj", textured_obj(flip)
        yield f"textured-crlf-{tag}.obj", textured_obj(flip, crlf=True)
        for fmt, short in (
            ("ascii", "ascii"),
            ("binary_little_endian", "le"),
            ("binary_big_endian", "be"),
        ):
            yield f"rich-{short}-{tag}.ply", rich_ply(fmt, flip=flip)
        yield f"rich-int-{tag}.ply", rich_ply("binary_little_endian", "int", "uint", flip)
    yield "rich-all-inside-out.ply", rich_ply("ascii", flip=tuple(range(8)))
    continued = textured_obj((2,)).replace(b"f  1/1/3", b"f  1/1/3 \\\n")
    yield "textured-continued.obj", continued
    yield "bom-flipped.obj", b"\xef\xbb\xbf" + textured_obj((0,))
    yield "latin1-flipped.obj", b"# caf\xe9\n" + textured_obj((5,))
    for name, model in (("l-prism", l_prism((0, 3))), ("warped", warped())):
        yield from every_encoding(name, model)
    v, f = icosphere(1)
    polys = turned(np.asarray(f).tolist(), [0, 7, 8])
    header = b"COLOR=\xff\x00\x00\xff MATERIAL=\x01\x02 exported by a CAD program"
    data = bytearray(stl_binary(v, polys, header))
    for i in range(len(polys)):
        data[84 + 50 * i + 48 : 84 + 50 * i + 50] = struct.pack("<H", 0x8000 | i * 37)
    yield "cad-attributes.stl", bytes(data)
    yield "cad-attributes-trailing.stl", bytes(data) + b"\x00\x01\x02"
    yield "cad-attributes-fine.stl", stl_binary(v, np.asarray(f).tolist(), header)
    signed = tetra()[0] - 0.0 * np.array([1.0, 0.0, 0.0])  # -0.0 corners: the whole file is kept
    signed[0, 0] = -0.0
    yield "negative-zero.stl", stl_binary(signed, turned(tetra()[1], [1]), header)
    text = (
        stl_ascii(v, polys)
        .replace(b"solid model", b"solid part_1 (mm)")
        .replace(b"endsolid model", b"endsolid part_1 (mm)")
    )
    second = stl_ascii(*tetra((3, 0, 0))).replace(b"model", b"Tetra")
    yield "named-solids.stl", text + second.replace(b"\n", b"\r\n")
    yield "named-solid-normals.stl", text.replace(b"facet normal 0 0 0", b"FACET NORMAL 0 0 1")


def corpus() -> list[tuple[str, bytes]]:
    """Every file of the corpus, as (name, bytes); names are unique."""
    files = [(p.name, p.read_bytes()) for d in STORED for p in sorted(d.rglob("*")) if p.is_file()]
    files += [(name, example_file(name)) for name, _ in EXAMPLES]
    for name, model in models():
        files += every_encoding(name, model)
    files += variants()
    files += kept()
    files += unreadable()
    rng = random.Random(31)  # seeded: the same damaged files every run
    small = [(n, d) for n, d in files if 0 < len(d) < 4000 and "." in n[1:]]
    for k in range(400):
        name, data = rng.choice(small)
        files.append((f"damaged{k}-{name}", damaged(rng, data)))
    files += lenient()
    for name, model in shells_and_open_pieces():  # after the random edits: they pick the same
        files += every_encoding(name, model)
    files.append(("hollow-plate.stl", stl_binary(*hollow_plate())))
    names = [n for n, _ in files]
    assert len(set(names)) == len(names), "two corpus files share a name"
    return files
