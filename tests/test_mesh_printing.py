"""The report for printing (`trinormal.mesh.printing`): holes, area, volume, size and verdict."""

from __future__ import annotations

import math

import numpy as np
import pytest

from trinormal.mesh import check, cube, face_areas, icosphere, signed_volume, torus
from trinormal.mesh.printing import UNITS, Size, shown


def _without(f: np.ndarray, faces) -> np.ndarray:
    return np.delete(f, list(faces), axis=0)


def test_holes_are_rims_with_the_edges_around_each():
    v, f = icosphere(3)
    # faces around three vertices far apart: three holes, five or six edges around each
    gone = [i for i in range(len(f)) if np.isin(f[i], [0, 3, 9]).any()]
    p = check(v, _without(f, gone)).printing
    rims = sorted(int(np.isin(f[gone], c).any(axis=1).sum()) for c in (0, 3, 9))
    assert sorted(p.holes) == rims and list(p.holes) == sorted(p.holes, reverse=True)
    # one face missing: a hole of three edges; two faces sharing an edge: one hole of four
    assert check(v, _without(f, [0])).printing.holes == (3,)
    a, b = 0, next(i for i in range(1, len(f)) if len(set(f[0]) & set(f[i])) == 2)
    assert check(v, _without(f, [a, b])).printing.holes == (4,)
    # two faces sharing only a corner: their rims touch at one vertex and count as one hole
    c = next(i for i in range(1, len(f)) if len(set(f[0]) & set(f[i])) == 1)
    assert check(v, _without(f, [a, c])).printing.holes == (6,)
    assert check(v, f).printing.holes == ()
    # so do the rims of two pieces that touch at one vertex: two triangles sharing a corner,
    # and two strips of two triangles each, touching at both ends
    v = np.random.default_rng(1).random((6, 3))
    assert check(v[:5], [[0, 1, 2], [0, 3, 4]]).printing.holes == (6,)
    strips = [[0, 1, 2], [1, 3, 2], [0, 4, 5], [4, 3, 5]]
    r = check(v, strips)
    assert len(r.components) == 2 and r.printing.holes == (8,)


@pytest.mark.parametrize("scale", [1.0, 1e-150, 1e150, 3.7e-5, 1e300])
def test_surface_area_is_the_sum_of_the_face_areas_at_any_scale(scale):
    v, f = torus(n_major=30, n_minor=12)
    v = v * scale + scale * 0.25
    want = math.fsum(face_areas(v, f).tolist())
    got = check(v, f).printing.surface_area
    assert got == pytest.approx(want, rel=1e-12)


def test_volume_per_closed_piece_and_in_all():
    v, f = cube()
    small = (v * 0.5 + 5, f[:, [0, 2, 1]])  # a second closed piece, inside out
    opened = (v + 20, f[:-2])  # an open piece: no volume
    parts = [(v, f), small, opened]
    vs = np.vstack([p[0] for p in parts])
    fs = np.vstack([f, small[1] + 8, opened[1] + 16])
    r = check(vs, fs)
    p = r.printing
    assert p.piece_volumes == (8.0, -1.0, None)
    assert p.piece_volumes[:2] == (signed_volume(*parts[0]), signed_volume(*small))
    assert p.volume == 7.0
    assert r.to_dict()["volume"] == 7.0
    assert check(*opened).printing.volume is None
    assert check(v * 1e300, f).printing.volume == math.inf  # beyond the float range, not NaN


def test_size_is_the_box_of_the_used_vertices_and_never_minus_zero():
    v = np.array([[-0.0, 0.0, -0.0], [30.0, 0, 0], [0, 20, 0], [0, 0, 10], [1e6, 1e6, 1e6]])
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])  # vertex 4 is not used
    size = check(v, f).printing.size
    assert size.minimum == (0.0, 0.0, 0.0)
    assert all(math.copysign(1.0, x) == 1.0 for x in size.minimum)
    assert (size.maximum, size.extent, size.units_hint) == ((30.0, 20.0, 10.0),) * 2 + (None,)


@pytest.mark.parametrize(
    "largest,hint",
    [
        (0.05, "metres"),
        (math.nextafter(UNITS["metres_below"], 0), "metres"),
        (UNITS["metres_below"], "inches"),
        (math.nextafter(UNITS["inches_below"], 0), "inches"),
        (UNITS["inches_below"], None),
        (UNITS["micrometres_above"], None),
        (math.nextafter(UNITS["micrometres_above"], math.inf), "micrometres"),
        (0.0, None),
    ],
)
def test_units_hint_at_its_thresholds(largest, hint):
    size = Size((0.0, 0.0, 0.0), (largest, largest / 2, 0.0))
    assert size.units_hint == hint
    lines = size.lines()
    assert len(lines) == (1 if hint is None else 2)
    if hint is not None:
        assert f"its largest side, {shown(largest)}, is" in lines[1]


def _verdict(v, f) -> str:
    return check(v, f).printing.verdict


def test_the_verdict_says_ready_or_what_stands_in_the_way():
    v, f = cube()
    assert _verdict(v * 10, f) == "watertight, 1 piece, wound outward: ready for a slicer"
    assert _verdict(v, f[:, [0, 2, 1]]) == (
        "watertight, 1 piece, inside out: not ready for a slicer (12 faces to turn over)"
    )
    bad = f.copy()
    bad[3] = bad[3, [0, 2, 1]]
    assert _verdict(v, bad[:-2]) == (
        "not watertight, 1 piece, wound inconsistently: not ready for a slicer "
        "(1 hole, 1 face to turn over)"
    )
    v2 = np.vstack([v, [[9.0, 9.0, 9.0]]])
    assert _verdict(v2, f) == (
        "watertight, 1 piece, wound outward: not ready for a slicer (1 unused vertex)"
    )
    assert _verdict(v, np.vstack([f, f[:1]])) == (  # a face twice: its edges have three faces
        "not watertight, 1 piece, wound consistently: not ready for a slicer "
        "(3 edges of three faces or more, 1 duplicate face)"
    )
    # an open piece that mostly encloses a volume is judged as a closed one is; a sheet is not
    assert _verdict(v, f[:-2]) == (
        "not watertight, 1 piece, wound outward: not ready for a slicer (1 hole)"
    )
    assert _verdict(v, f[:-2, ::-1]) == (
        "not watertight, 1 piece, inside out: not ready for a slicer "
        "(1 hole, 10 faces to turn over)"
    )
    assert _verdict(v[:4], f[:2]) == (  # the square of the first two faces
        "not watertight, 1 piece, wound consistently: not ready for a slicer (1 hole)"
    )
    assert _verdict(v[:0], np.empty((0, 3), dtype=int)) == (
        "not watertight, 0 pieces, wound consistently: not ready for a slicer (no faces)"
    )


def test_a_mobius_strip_is_one_sided():
    n, pts, polys = 12, [], []
    for i in range(n):
        t = 2 * math.pi * i / n
        for s in (-0.3, 0.3):
            r = 1 + s * math.cos(t / 2)
            pts.append((r * math.cos(t), r * math.sin(t), s * math.sin(t / 2)))
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        c, d = (2 * i + 2, 2 * i + 3) if i < n - 1 else (1, 0)
        polys += [[a, c, b], [b, c, d]]
    assert _verdict(np.array(pts), np.array(polys)) == (
        "not watertight, 1 piece, one-sided: not ready for a slicer (1 hole, 1 one-sided piece)"
    )


def test_the_summary_ends_with_the_printing_lines():
    v, f = cube()
    r = check(v * 0.025, f[:-2])
    assert r.summary(width=0).split("\n")[-5:] == [
        "1 hole: 4 edges around it.",
        "Size: 0.05 × 0.05 × 0.05 (x, y, z) in the file's units, which slicers read as mm.",
        "Read as millimetres its largest side, 0.05, is under 1 mm: the model is probably in "
        "metres (scale it by 1000) or inches (by 25.4).",
        "Surface area 0.0125; no enclosed volume: only a closed, consistently wound piece has "
        "an inside to measure.",
        "Verdict: not watertight, 1 piece, wound outward: not ready for a slicer (1 hole).",
    ]
