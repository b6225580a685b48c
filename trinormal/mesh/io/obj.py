"""OBJ files, always text: every vertex and every face in file order.

Vertex numbers start at 1; a negative one counts back from the last vertex so
far. Statements that carry no triangle (texture coordinates, normals, groups,
materials, curves) are skipped; anything else is an error on its line.
"""

from __future__ import annotations

import math

import numpy as np

from trinormal.mesh._arrays import FloatArray, IntArray
from trinormal.mesh.io.errors import MeshFileError, _show, _text
from trinormal.mesh.io.mesh_data import MeshData, _fan

# OBJ statements that carry no triangle (texture, normals, grouping, materials, curves)
_OBJ_IGNORED = frozenset(
    {"vt", "vn", "vp", "g", "o", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "l", "p"}
    | {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole"}
    | {"scrv", "sp", "end", "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj"}
    | {"trace_obj", "ctech", "stech", "call", "csh"}
)


def _read_obj(data: bytes, name: str) -> MeshData:
    """Read OBJ text; polygons become fans (`_fan`)."""
    text = _text(data, name, "OBJ")
    coords: list[float] = []
    polys: list[list[int]] = []
    poly_lines: list[int] = []
    nv = 0
    lines = text.splitlines()
    lineno = 0
    pending = ""
    for raw in lines:
        lineno += 1
        if raw.endswith("\\"):  # a continued line
            pending += raw[:-1] + " "
            continue
        line = pending + raw
        pending = ""
        hash_at = line.find("#")
        if hash_at >= 0:
            line = line[:hash_at]
        toks = line.split()
        if not toks:
            continue
        kw = toks[0]
        if kw == "v":
            if len(toks) < 4:
                raise MeshFileError.of(name, "obj_vertex", lineno)
            try:
                x, y, z = float(toks[1]), float(toks[2]), float(toks[3])
            except ValueError:
                bad = next(t for t in toks[1:4] if not _is_float(t))
                raise MeshFileError.of(name, "not_a_number", lineno, token=_show(bad)) from None
            if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(z)):
                bad = next(t for t in toks[1:4] if not math.isfinite(float(t)))
                raise MeshFileError.of(name, "not_finite", lineno, token=_show(bad))
            coords += (x, y, z)
            nv += 1
        elif kw == "f" or kw == "fo":
            if len(toks) < 4:
                raise MeshFileError.of(name, "obj_face_short", lineno)
            poly = []
            for tok in toks[1:]:
                ref = tok.split("/", 1)[0]
                try:
                    i = int(ref)
                except ValueError:
                    raise MeshFileError.of(name, "obj_index", lineno, token=_show(tok)) from None
                if i > 0:
                    poly.append(i - 1)
                elif i < 0:  # counted back from the last vertex so far
                    if -i > nv:
                        raise MeshFileError.of(
                            name, "obj_back", lineno, index=i, count=nv, vertices=_vertices(nv)
                        )
                    poly.append(nv + i)
                else:
                    raise MeshFileError.of(name, "obj_zero", lineno)
            polys.append(poly)
            poly_lines.append(lineno)
        elif kw not in _OBJ_IGNORED:
            raise MeshFileError.of(name, "obj_statement", lineno, token=_show(kw))
    if nv == 0 and not polys:
        raise MeshFileError.of(name, "obj_empty")
    for k, poly in enumerate(polys):  # vertex numbers may point forward; check at the end
        over = [i for i in poly if i >= nv]
        if over:
            raise MeshFileError.of(
                name,
                "obj_index_range",
                poly_lines[k],
                face=k + 1,
                index=over[0] + 1,
                count=nv,
                vertices=_vertices(nv),
            )
    vertices = np.array(coords, dtype=np.float64).reshape(-1, 3)
    faces, source = _fan(polys)
    return MeshData(vertices, faces, "obj", "ascii", source, len(polys), name)


def _is_float(tok: str) -> bool:
    try:
        float(tok)
    except ValueError:
        return False
    return True


def _vertices(n: int) -> str:
    return "vertex" if n == 1 else "vertices"


def _encode_obj(v: FloatArray, f: IntArray) -> bytes:
    """Write the mesh as OBJ text: every coordinate as the shortest decimal that reads back."""
    lines = ["# written by trinormal"]
    lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
    lines += [f"f {a} {b} {c}" for a, b, c in (f + 1).tolist()]
    return ("\n".join(lines) + "\n").encode()
