"""Tests of trinormal.mesh.io: files written by hand (and binary ones packed here with struct)."""

from __future__ import annotations

import random
import struct
from pathlib import Path

import numpy as np
import pytest

from trinormal import mesh
from trinormal.mesh import MeshFileError, _arrays
from trinormal.mesh.io import obj, stl

DATA = Path(__file__).parent / "data" / "meshes"
BAD = DATA / "bad"

pytestmark = pytest.mark.filterwarnings("error")


# --------------------------------------------------------------------------- as stored


def test_obj_quads_split_as_fans_from_their_first_corner_in_file_order():
    m = mesh.read_mesh(DATA / "open_box.obj")
    assert m.vertices.tolist() == [
        [0, 0, 0],
        [1, 0, 0],
        [1, 1, 0],
        [0, 1, 0],
        [0, 0, 1],
        [1, 0, 1],
        [1, 1, 1],
        [0, 1, 1],
    ]
    # f 1 4 3 2 / 1 2 6 5 / 2 3 7 6 / 3 4 8 7 / 1 4 8 5, each (a, b, c), (a, c, d), 0-based
    assert m.faces.tolist() == [
        [0, 3, 2], [0, 2, 1],
        [0, 1, 5], [0, 5, 4],
        [1, 2, 6], [1, 6, 5],
        [2, 3, 7], [2, 7, 6],
        [0, 3, 7], [0, 7, 4],
    ]  # fmt: skip
    assert m.source_faces.tolist() == [0, 0, 1, 1, 2, 2, 3, 3, 4, 4]
    assert (m.format, m.encoding, m.n_polygons, m.split_polygons) == ("obj", "ascii", 5, 5)
    assert m.describe().endswith("(OBJ): 8 vertices, 5 quads, 10 triangles.")


def test_open_box_report_names_its_two_faults():
    m = mesh.read_mesh(DATA / "open_box.obj")
    r = mesh.check(m.vertices, m.faces)
    # the rim of the missing top, as the side faces walk it (the -x side is turned over)
    assert r.boundary_edges.tolist() == [[5, 4], [6, 5], [7, 4], [7, 6]]
    assert r.faces_to_flip.tolist() == [8, 9]  # the two halves of the -x quad
    assert not r.closed and not r.consistent_winding


def test_ply_polygons_keep_file_order_and_other_elements_are_skipped():
    m = mesh.read_mesh(DATA / "mixed_polygons.ply")
    assert m.vertices.tolist() == [
        [0, 0, 0],
        [1, 0, 0],
        [1.5, 1, 0],
        [0.5, 1.5, 0],
        [-0.5, 1, 0],
        [0, -1, 0],
        [1, -1, 0],
    ]
    # pentagon 0 1 2 3 4, triangle 0 5 1, quad 1 5 6 2
    assert m.faces.tolist() == [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 5, 1], [1, 5, 6], [1, 6, 2]]
    assert m.source_faces.tolist() == [0, 0, 0, 1, 2, 2]
    assert (m.encoding, m.n_polygons, m.split_polygons) == ("ascii", 3, 2)


def pack_ply(order: str, fmt: str) -> bytes:
    """The mixed_polygons.ply content, packed in binary with struct (not with our writer)."""
    header = (
        "ply\n"
        f"format {fmt} 1.0\n"
        "element vertex 7\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\n"
        "element face 3\nproperty list uchar int vertex_indices\nproperty uchar flags\n"
        "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
        "end_header\n"
    ).encode()
    verts = [(0, 0, 0), (1, 0, 0), (1.5, 1, 0), (0.5, 1.5, 0), (-0.5, 1, 0), (0, -1, 0), (1, -1, 0)]
    body = b"".join(struct.pack(order + "fffB", *p, 255) for p in verts)
    for poly in ([0, 1, 2, 3, 4], [0, 5, 1], [1, 5, 6, 2]):
        body += struct.pack(f"{order}B{len(poly)}iB", len(poly), *poly, 7)
    body += struct.pack(order + "ii", 0, 1)
    return header + body


@pytest.mark.parametrize("order,fmt", [("<", "binary_little_endian"), (">", "binary_big_endian")])
def test_binary_ply_reads_like_the_ascii_file(order, fmt):
    text = mesh.read_mesh(DATA / "mixed_polygons.ply")
    m = mesh.parse_mesh(pack_ply(order, fmt), "ply", "packed.ply")
    assert m.encoding == "binary"
    assert (m.vertices == text.vertices).all()
    assert (m.faces == text.faces).all()
    assert (m.source_faces == text.source_faces).all()


def test_binary_ply_of_triangles_only_is_read_in_one_go():
    v, f = mesh.icosphere(1)
    header = (
        f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\n"
        "property double x\nproperty double y\nproperty double z\n"
        f"element face {len(f)}\nproperty list uchar uint vertex_indices\nend_header\n"
    ).encode()
    body = v.astype("<f8").tobytes() + b"".join(struct.pack("<B3I", 3, *t) for t in f.tolist())
    m = mesh.parse_mesh(header + body, "ply")
    assert (m.vertices == v).all() and (m.faces == f).all()


def tetra_corners():
    m = mesh.read_mesh(DATA / "tetra_flipped.stl")
    return m.vertices[m.faces]


def test_ascii_stl_corners_merge_by_exact_equality_in_order_of_first_use():
    m = mesh.read_mesh(DATA / "tetra_flipped.stl")
    assert (m.format, m.encoding) == ("stl", "ascii")
    assert m.vertices.tolist() == [[0, 0, 0], [0, 1, 0], [1, 0, 0], [0, 0, 1]]
    assert m.faces.tolist() == [[0, 1, 2], [0, 2, 3], [0, 1, 3], [2, 1, 3]]
    r = mesh.check(m.vertices, m.faces)
    assert r.closed and r.faces_to_flip.tolist() == [2]


def pack_stl(corners: np.ndarray, header: bytes = b"solid (a binary file whose header says solid)"):
    out = header.ljust(80, b"\0") + struct.pack("<I", len(corners))
    for tri in corners.tolist():
        out += (
            struct.pack("<3f", 0, 0, 0)
            + struct.pack("<9f", *(x for corner in tri for x in corner))
            + b"\0\0"
        )
    return out


def test_binary_stl_with_a_solid_header_is_read_as_binary():
    m = mesh.parse_mesh(pack_stl(tetra_corners()), "stl", "tetra.stl")
    text = mesh.read_mesh(DATA / "tetra_flipped.stl")
    assert m.encoding == "binary"
    assert (m.vertices == text.vertices).all() and (m.faces == text.faces).all()


def test_stl_minus_zero_is_zero_and_nearby_points_stay_apart():
    corners = np.array(
        [[[0.0, 0, 0], [1, 0, 0], [0, 1, 0]], [[-0.0, 0, 0], [0, 1, 0], [1, 2**-20, 0]]]
    )
    m = mesh.parse_mesh(pack_stl(corners), "stl")
    assert m.faces.tolist() == [[0, 1, 2], [0, 2, 3]]  # -0.0 is the vertex 0; 1+2**-20 is new
    assert len(m.vertices) == 4


def test_stl_corners_merge_the_same_when_every_sort_key_collides(monkeypatch):
    """The merge sorts by a mix of the bit patterns; equal keys of unequal points fall back."""
    v, f = mesh.icosphere(2)
    corners = v[f].reshape(-1, 3)
    data = pack_stl(corners.reshape(-1, 3, 3))
    want = mesh.parse_mesh(data, "stl")
    monkeypatch.setattr(_arrays, "_MIX", (0, 0, 0))  # every corner gets the key 0
    got = mesh.parse_mesh(data, "stl")
    assert got.faces.tolist() == want.faces.tolist()
    assert got.vertices.tobytes() == want.vertices.tobytes()
    assert len(got.vertices) == len(v)  # the sphere's vertices are float32 numbers apart


@pytest.mark.parametrize("mix", [(1, 0, 0), (0, 0, 1)])
def test_equal_rows_are_found_exactly_when_some_sort_keys_collide(monkeypatch, mix):
    """Points that share x (or z) share a key: only their runs are sorted by value."""
    v, f = mesh.icosphere(2)
    corners = v[f].reshape(-1, 3)
    data = pack_stl(corners.reshape(-1, 3, 3))
    want = mesh.parse_mesh(data, "stl")
    soup = np.vstack([v, v[::-1]])  # every position twice: the second copy is the first's
    want_weld = mesh.welding._exact_representatives(soup)
    monkeypatch.setattr(_arrays, "_MIX", mix)
    got = mesh.parse_mesh(data, "stl")
    assert got.faces.tolist() == want.faces.tolist()
    assert got.vertices.tobytes() == want.vertices.tobytes()
    got_weld = mesh.welding._exact_representatives(soup)
    assert got_weld is not None and want_weld is not None
    assert got_weld.tolist() == want_weld.tolist()
    assert got_weld.tolist() == [*range(len(v)), *range(len(v))[::-1]]


def test_stl_and_obj_of_one_model_have_the_same_report(tmp_path):
    v, f = mesh.damaged_model()
    mesh.write_mesh(tmp_path / "ball.stl", v, f)
    stl = mesh.read_mesh(tmp_path / "ball.stl")
    obj = mesh.read_mesh(mesh.sample_path())
    assert stl.vertices.shape == obj.vertices.shape
    assert (stl.vertices[stl.faces] == obj.vertices[obj.faces].astype(np.float32)).all()
    a, b = mesh.check(stl.vertices, stl.faces), mesh.check(obj.vertices, obj.faces)
    for key in ("n_vertices", "n_faces", "faces_to_flip", "components", "closed"):
        assert (
            getattr(a, key) == getattr(b, key)
            if key != "faces_to_flip"
            else (a.faces_to_flip == b.faces_to_flip).all()
        )
    assert len(a.boundary_edges) == len(b.boundary_edges)


def test_crlf_and_continued_lines(tmp_path):
    m = mesh.read_mesh(DATA / "crlf.obj")
    assert m.faces.tolist() == [[0, 1, 2]]
    m = mesh.parse_mesh(b"v 0 0 0\nv 1 0 \\\n 0\nv 0 1 0\nf 1 2 \\\n3\n", "obj")
    assert m.vertices.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]] and m.faces.tolist() == [
        [0, 1, 2]
    ]


PLAIN = b"# cube corner\nv 0 0 0\nv 1.5 -0 .5\r\nv\t1e3  +2. 3E-2 \n\nf 1 2 3\nf 3 2 1\n"
TRIANGLE = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n"


@pytest.mark.parametrize(
    "data,plain",
    [
        (PLAIN, True),
        (
            b"v 0.1 0.30000000000000004 0.1000000000000000055511151231257827\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            True,
        ),
        (
            b"v 1 2 1.00000000000000011102230246251565404236316680908203125\n"
            + TRIANGLE
            + b"f 2 3 4",
            True,
        ),
        (TRIANGLE + b"f 1 2 3\nv 0 0 1\n# between\nf 1 2 4\nv 1 1 1\nf 01 2 005\n", True),  # mixed
        (b"f 3 1 2\n" + TRIANGLE, True),  # a face may name vertices listed after it
        (b"  v 0 0 0\n\tv 1 0 0\r\nv 0 1 0\n \t\n# a # b\n f 1 2 3", True),  # indented, no last LF
        (b"v 1_0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", False),  # an underscore: Python reads it
        (TRIANGLE + b"f 1 2 +3\n", False),  # a sign: vertex numbers are digits only here
        (TRIANGLE + b"f + 3 2\n", False),  # a sign apart from a number
        (TRIANGLE + b"f 1 2 3.0\n", False),
        (TRIANGLE + b"f 1 2 3e0\n", False),
        (TRIANGLE + b"f 1 2 99999999999999999999999\n", False),
        (TRIANGLE + b"f 1 2 3 # a comment after a face\n", False),
        (TRIANGLE + b"f 1/1 2/2 3/3\n", False),
        (TRIANGLE + b"f -3 -2 -1\n", False),
        (TRIANGLE + b"f 1 2 3 4\n", False),
        (TRIANGLE + b"f 1 2\n", False),
        (TRIANGLE + b"f 1 2 3\x0c\n", False),  # a form feed: a line break to Python
        ("# café\n".encode() + TRIANGLE + b"f 1 2 3\n", False),
        (b"v 0 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", False),
        (b"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", False),
        (b"v 0 0 0\nv 1 0 0\r\rv 0 1 0\nf 1 2 3\n", False),
        (b"v 1-2 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", False),
        (b"v 0x1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", False),
        (b"v nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", False),
        (b"v 1e999 0 0\n", False),
        (b"v 0 0 0\nv 1 0 0\nf 1 2 3\n", False),
        (b"f 1 2 3\n", False),
        (b"vn 0 0 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", False),
        (b"v1 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", False),
        (b"v 0 0 0\nv 1 0 0\nv 0 1 \\\n0\nf 1 2 3\n", False),
    ],
)
def test_plain_obj_files_are_read_in_one_go_with_the_same_result(data, plain):
    got = obj._read_plain(data)
    assert (got is not None) == plain
    if got is None:
        return
    _same_as_line_by_line(got, data)
    want = obj._read_lines(data, "x")
    m = mesh.parse_mesh(data, "obj")
    assert m.vertices.tobytes() == want.vertices.tobytes() and m.source_faces.tolist() == list(
        range(len(want.faces))
    )


def _same_as_line_by_line(got: tuple[np.ndarray, np.ndarray], data: bytes) -> None:
    want = obj._read_lines(data, "x")
    assert got[0].tobytes() == want.vertices.tobytes() and got[0].shape == want.vertices.shape
    assert got[1].dtype == want.faces.dtype and got[1].shape == want.faces.shape
    assert (got[1] == want.faces).all()


def _plain_obj(rng: random.Random) -> bytes:
    """The bytes of a random OBJ of plain lines: any finite coordinates, faces in range."""
    n = rng.randint(1, 6)
    coords = np.frombuffer(rng.randbytes(24 * n), dtype=np.float64)
    coords = np.where(np.isfinite(coords), coords, 0.5).tolist()
    forms = [repr, repr, "{:.3e}".format, "{:+.17g}".format, "{:f}".format, "{:.0f}".format]
    lines = []
    for i in range(n):
        form = rng.choice(forms) if abs(coords[3 * i]) < 1e300 else repr  # rounding stays finite
        lines.append("v" + "".join(f" {form(x)}" for x in coords[3 * i : 3 * i + 3]))
    for _ in range(rng.randint(0, 6)):
        face = "f" + "".join(f" {rng.randint(1, n):0{rng.randint(1, 3)}}" for _ in range(3))
        lines.insert(rng.randint(0, len(lines)), face)
    for _ in range(rng.randint(0, 2)):
        lines.insert(rng.randint(0, len(lines)), rng.choice(["# a # comment", "#", "", " \t"]))
    text = ""
    for line in lines:
        line = line.replace(" ", rng.choice([" ", "\t", "  "]))
        text += rng.choice(["", "", " "]) + line + rng.choice(["\n", "\n", "\r\n", " \n"])
    return text.encode()


def test_any_plain_obj_is_read_in_one_go_as_line_by_line():
    rng = random.Random(1)
    for _ in range(300):
        data = _plain_obj(rng)
        got = obj._read_plain(data)
        assert got is not None, data
        _same_as_line_by_line(got, data)


#: Pieces that make a plain OBJ something else, or leave it plain
_PIECES = [b"+", b"-", b".", b"e", b"_", b"/", b"#", b"\\", b"\r", b"\x0b", b"\x85", b"x", b" "]
_PIECES += [b" 1", b" 0", b"nan", b"inf", b"1e999", b"\nvt 0 0", b"\nf 1 2 3 4", b"\nf 1 1 9"]
_PIECES += [b"\t", b"\n", b"\n# c", b"\nv 1 2 3", b"\nf 1 1 1", b"\nf 1 1 01"]


def test_an_obj_read_in_one_go_reads_the_same_line_by_line():
    rng = random.Random(2)
    plain = 0
    for _ in range(500):
        data = _plain_obj(rng)
        at = rng.choice([i for i, c in enumerate(data) if c in b" \n"])  # after a token
        data = data[:at] + rng.choice(_PIECES) + data[at:]
        got = obj._read_plain(data)
        if got is not None:
            _same_as_line_by_line(got, data)
            plain += 1
    assert 50 < plain < 450, plain  # both ways are taken


def test_a_byte_order_mark_is_not_part_of_the_first_line():
    m = mesh.parse_mesh("\ufeffv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".encode(), "obj")
    assert m.faces.tolist() == [[0, 1, 2]]


def test_obj_negative_indices_count_back_from_the_latest_vertex():
    m = mesh.parse_mesh(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf -3 -1 -2\n", "obj")
    assert m.faces.tolist() == [[0, 1, 2], [1, 3, 2]]


# --------------------------------------------------------------------------- lenient where STL allows


def _binary_stl(n_triangles: int, count: int | None = None, extra: bytes = b"") -> bytes:
    """A binary STL of ``n_triangles`` distinct triangles whose header gives ``count``."""
    rec = np.zeros(n_triangles, dtype=stl._STL_RECORD)
    rec["corners"] = np.arange(9 * n_triangles, dtype=np.float32).reshape(-1, 3, 3) ** 1.5
    n = n_triangles if count is None else count
    return b" " * 80 + struct.pack("<I", n) + rec.tobytes() + extra


def test_an_exact_binary_stl_has_no_notes():
    m = mesh.parse_mesh(_binary_stl(3), "stl", "m.stl")
    assert m.faces.shape == (3, 3) and m.notes == ()


@pytest.mark.parametrize("count", [0, 1, 2, 4, 1000, 2**32 - 1])
def test_whole_records_are_read_whatever_the_count_says(count):
    m = mesh.parse_mesh(_binary_stl(3, count), "stl", "m.stl")
    assert m.faces.shape == (3, 3)
    assert (m.vertices[m.faces] == mesh.parse_mesh(_binary_stl(3), "stl").vertices[m.faces]).all()
    assert m.notes == (
        f"m.stl: the header's triangle count is {count:,}, but the file holds 3: its 150 bytes "
        "after the header are whole 50-byte triangle records, and all were read",
    )


@pytest.mark.parametrize("extra", range(1, 50))
def test_fewer_than_50_bytes_after_the_counted_records_are_ignored(extra):
    m = mesh.parse_mesh(_binary_stl(2, extra=bytes(range(extra))), "stl", "m.stl")
    assert m.faces.shape == (2, 3)
    word = "byte" if extra == 1 else "bytes"
    assert m.notes == (
        f"m.stl: ignored the last {extra} {word}: fewer than the 50 of a triangle record",
    )


@pytest.mark.parametrize(
    "data",
    [
        _binary_stl(2, 0, bytes(7)),  # the count is wrong, and a record is cut short
        _binary_stl(2, 3, bytes(49)),  # a third record cut short
        _binary_stl(0, 4),  # a header and nothing else
    ],
)
def test_any_other_size_is_not_an_stl_file(data):
    with pytest.raises(
        MeshFileError, match=rf"^m\.stl: not an STL file: .* has {len(data)} bytes\)$"
    ):
        mesh.parse_mesh(data, "stl", "m.stl")


@pytest.mark.parametrize(
    "data,fmt",
    [
        (b"", "obj"),
        (b"", "stl"),
        (b"", "ply"),
        (b"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "obj"),
        (b"solid x\nendsolid x\n", "stl"),
        (_binary_stl(0), "stl"),
        (_binary_stl(0, 0, bytes(30)), "stl"),
        (
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            b"property float z\nend_header\n0 0 0\n",
            "ply",
        ),
    ],
)
def test_a_file_with_no_faces_is_an_error(data, fmt):
    with pytest.raises(
        MeshFileError, match=r"^e: the file has no faces: there is no surface to check$"
    ) as err:
        mesh.parse_mesh(data, fmt, "e")
    assert err.value.key == "no_faces"


# --------------------------------------------------------------------------- round trips


@pytest.mark.parametrize(
    "fmt,enc",
    [("obj", None), ("stl", "binary"), ("stl", "ascii"), ("ply", "binary"), ("ply", "ascii")],
)
@pytest.mark.parametrize(
    "source", ["open_box.obj", "tetra_flipped.stl", "mixed_polygons.ply", "damaged"]
)
def test_read_fix_write_read(tmp_path, fmt, enc, source):
    m = mesh.read_mesh(mesh.sample_path() if source == "damaged" else DATA / source)
    fixed, _ = mesh.fix_winding(m.vertices, m.faces)
    path = tmp_path / f"out.{fmt}"
    mesh.write_mesh(path, m.vertices, fixed, encoding=enc)
    back = mesh.read_mesh(path)
    assert back.encoding == (enc or "ascii")
    if fmt == "stl":  # corners merged again: the same triangles, numbered by first use
        want = m.vertices[fixed]
        if enc == "binary":
            want = want.astype(np.float32)
        assert (back.vertices[back.faces] == want).all()
    else:
        assert (back.vertices == m.vertices).all() and (back.faces == fixed).all()
    r = mesh.check(back.vertices, back.faces)
    assert r.faces_to_flip.size == 0
    assert r.consistent_winding


def test_text_files_keep_every_digit(tmp_path):
    v = np.array([[0.1, 1 / 3, -2.5e-300], [1e300, np.nextafter(1, 2), -0.0], [5e-324, 7, 8]])
    for fmt, enc in (("obj", None), ("ply", "ascii"), ("ply", "binary")):
        mesh.write_mesh(tmp_path / f"x.{fmt}", v, [[0, 1, 2]], encoding=enc)
        back = mesh.read_mesh(tmp_path / f"x.{fmt}")
        assert back.vertices.tobytes() == v.tobytes(), fmt


# --------------------------------------------------------------------------- bad files


@pytest.mark.parametrize(
    "name,message",
    [
        ("bad_number.obj", r"bad_number\.obj, line 2: 'zero' is not a number"),
        ("bad_index.obj", r"bad_index\.obj, line 4: face 1 refers to vertex 4, but the file has 3"),
        ("not_a_mesh.obj", r"not_a_mesh\.obj, line 1: 'Hello,' is not an OBJ statement"),
        ("two_corners.stl", r"two_corners\.stl, line 6: the facet starting at line 3 has 2"),
        (
            "truncated.stl",
            r"truncated\.stl: not an STL file: .*\(3 triangles would take 234 bytes; this file has 183 bytes",
        ),
        ("png_renamed.ply", r"png_renamed\.ply, line 1: not a PLY file"),
        (
            "bad_index.ply",
            r"bad_index\.ply: face 0 refers to vertex 7, but the valid vertices are 0 to 2",
        ),
    ],
)
def test_bad_files_get_one_clear_error(name, message):
    with pytest.raises(MeshFileError, match=message) as err:
        mesh.read_mesh(BAD / name)
    assert isinstance(err.value, ValueError)
    assert err.value.path.endswith(name)
    assert "\n" not in str(err.value)


@pytest.mark.parametrize(
    "data,fmt,message",
    [
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n",
            "obj",
            "line 4: a face needs at least three corners",
        ),
        (b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "obj", "line 4: vertex numbers start at 1"),
        (b"v 0 0 nan\n", "obj", "line 1: 'nan' is not a finite number"),
        (b"v 0 0\n", "obj", "line 1: a vertex needs three coordinates"),
        (b"# nothing\n", "obj", "no vertices and no faces"),
        (b"v 0 0 0\0\n", "obj", "line 1: not a text OBJ file"),
        (
            b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n",
            "stl",
            "line 5: the file ends inside a facet",
        ),
        (
            b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 inf\n",
            "stl",
            "line 4: 'inf' is not a finite number",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nend_header\n0\n1\n",
            "ply",
            "no 'y' property",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            b"property float z\nend_header\n0 0 0\n1 0 0\n",
            "ply",
            "line 9: the file ends after 2 of 3",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            b"property float z\nend_header\n0 zero 0\n",
            "ply",
            "line 8: 'zero' is not a number",
        ),
        (
            b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
            b"property float y\nproperty float z\nend_header\n" + b"\0" * 20,
            "ply",
            "ends inside the 'vertex' element",
        ),
    ],
)
def test_bad_content_names_the_line(data, fmt, message):
    with pytest.raises(MeshFileError, match=message):
        mesh.parse_mesh(data, fmt, "x")


def test_unknown_format_and_missing_file(tmp_path):
    with pytest.raises(MeshFileError, match=r"model\.3ds: unknown mesh format \.3ds"):
        mesh.read_mesh("model.3ds")
    with pytest.raises(MeshFileError, match="cannot be read: No such file"):
        mesh.read_mesh(tmp_path / "missing.obj")
    with pytest.raises(MeshFileError, match="written as ascii, not 'binary'"):
        mesh.write_mesh(tmp_path / "x.obj", *mesh.cube(), encoding="binary")
