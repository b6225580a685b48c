"""The view described in words: the rule (trinormal.explorer.describe) and its JavaScript port.

The 3D view writes its description with ``js/explorer/src/describe.js``; ``Explorer.describe``
with the Python module. One Node run says what the port makes of a corpus (random triangles in
both windings seen from every side, the borderline cases of every threshold, every degenerate
verdict), and every string must equal Python's, byte for byte.
"""

from __future__ import annotations

import json
import math
import random
import subprocess
from pathlib import Path

import pytest
from node_runs import node_path

from trinormal import triangle_normal
from trinormal.explorer import Explorer, view_state
from trinormal.explorer import describe as rule
from trinormal.explorer.describe import describe, direction_words, viewer_words

ROOT = Path(__file__).resolve().parents[1]


def _triangles() -> list:
    rng = random.Random(33)
    points = [
        [(0, 0, 0), (1, 0, 0), (0, 1, 0)],
        [(1, 1, 1), (2, 1, 1), (1, 2, 2)],
        [(0, 0, 0), (1, 0, 0), (0, 1, 1)],
        [(1, 0, 0), (0, 2, 0), (0, 0, 3)],
        [(0, 0, 0), (1, 1, 1), (2, 2, 2)],  # collinear
        [(0, 0, 0), (0, 0, 0), (1, 2, 3)],  # A and B coincide
        [(1, 1, 1), (1, 1, 1), (1, 1, 1)],  # one point
        [(0, 0, 0), (1, 0, 0), (0.5, 1e-13, 0)],  # too thin
        [(0, 0, 0), ("0.1", "0.2", "0.3"), ("0.3", "0.6", "0.9")],
        [(0, 0, 0), (1, 0, 0), (0, 1, "0.004")],  # N within half a degree of +z
        [(0, 0, 0), (1e200, 0, 0), (0, 1e200, 1e199)],  # N beyond the float range
        [(0, 0, 0), (1e-200, 0, 0), (0, 1e-200, 3e-201)],  # N below it
    ]
    for _ in range(60):
        scale = rng.choice([1, 1, 0.1, 1e-3])
        points.append([tuple(rng.randint(-5, 5) * scale for _ in range(3)) for _ in range(3)])
    return [triangle_normal(*p, winding=w) for p in points for w in ("ABC", "ACB")]


def _viewers(rng: random.Random, n: tuple[float, ...] | None) -> list:
    axes = [tuple(s * (i == k) for i in range(3)) for k in range(3) for s in (1.0, -1.0)]
    viewers: list = [None, *axes, [rng.gauss(0, 1) for _ in range(3)]]
    if n is not None:  # around edge-on, on both sides and on both sides of the threshold
        side = [n[1] - n[2], n[2] - n[0], n[0] - n[1]]
        if any(side):
            length = math.sqrt(sum(x * x for x in side))
            for cos in (0.0, 0.0199, 0.0201, -0.0199, -0.0201, 0.5, -0.9):
                sin = math.sqrt(1 - cos * cos)
                viewers.append([cos * a + sin * b / length for a, b in zip(n, side, strict=True)])
    return viewers


def _normals() -> list:
    s3, s2 = 1 / math.sqrt(3), 1 / math.sqrt(2)
    normals = [(s3, s3, s3), (-s3, s3, -s3), (s2, s2, 0.0), (0.0, -s2, s2), (-1.0, 0.0, 0.0)]
    for small in (rule.MENTION, rule.A_LITTLE):  # each threshold, just under it and just over it
        for x in (small, math.nextafter(small, 0), math.nextafter(small, 1)):
            for axis in range(3):
                n = [x, x, x]
                n[axis] = math.sqrt(1 - 2 * x * x)
                normals.append(tuple(n))
    for deg in (0.3, 0.5, 27, 44.9):
        t = math.radians(deg)
        normals.append((math.sin(t), 0.0, -math.cos(t)))
    return normals


def test_the_views_words_are_pythons_for_every_triangle_viewer_and_normal(tmp_path):
    """One Node run over the corpus: every description the port writes is Python's."""
    rng = random.Random(5)
    states, expected = [], []
    for r in _triangles():
        state = view_state(r, 4)
        for viewer in _viewers(rng, r.unit_normal):
            states.append({"state": state, "winding": r.winding.value, "viewer": viewer})
            expected.append(describe(r, viewer))
    normals = _normals()
    said = "\n".join(expected + [direction_words(n) for n in normals])
    for phrase in ("straight up", "a little", "equally", "each axis", "less than 1°",
                   "edge-on", "You see the front", "You see the back", "From its front",
                   "A→C→B turns clockwise", "collinear", "coincide", "same point", "too thin"):  # fmt: skip
        assert phrase in said, phrase  # the corpus reaches every branch of the rule
    corpus = tmp_path / "corpus.json"
    corpus.write_text(json.dumps({"states": states, "normals": normals}), encoding="utf-8")
    run = subprocess.run(
        [node_path(), str(ROOT / "tests" / "describe_parity_check.mjs"), str(corpus)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    out = json.loads(run.stdout)
    assert out["constants"] == {"MENTION": rule.MENTION, "A_LITTLE": rule.A_LITTLE,
                                "EDGE_ON": rule.EDGE_ON}  # fmt: skip
    mismatches = [
        (s, p, j) for s, p, j in zip(states, expected, out["states"], strict=True) if p != j
    ]
    assert mismatches == []
    assert out["normals"] == [direction_words(n) for n in normals]


def test_a_flip_turns_the_front_to_the_back_and_the_turn_with_it():
    """The same camera, the other order: the other side, and the order turns the other way."""
    ex = Explorer(a=(0, 0, 0), b=(1, 0, 0), c=(0, 1, 0))
    assert ex.describe(viewer=(0, 0, 1)).endswith(
        "You see the front of the triangle (N points towards you), and A→B→C turns counter-clockwise."
    )
    ex.set(winding="ACB")
    assert ex.describe(viewer=(0, 0, 1)) == (
        "N points straight down, along −z. You see the back of the triangle "
        "(N points away from you), and A→C→B turns clockwise."
    )
    assert "\n" not in ex.describe()  # one line, for a terminal


def test_the_contracts_example_and_the_degenerate_case():
    """ "N points up and towards −y: mostly +z, 27° from the z axis"; no front or back when flat."""
    t = math.radians(27)
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, math.cos(t), math.sin(t)))
    assert describe(r).startswith("N points up and towards −y: mostly +z, 27° from the z axis.")
    ex = Explorer(a=(0, 0, 0), b=(1, 1, 1), c=(2, 2, 2))
    assert ex.describe() == (
        f"{ex.result.format(4)['status']} No direction to describe: the triangle has no front or back."
    )


@pytest.mark.parametrize("viewer", [(0, 0, 0), (math.inf, 0, 0), (math.nan, 1, 1)])
def test_a_viewer_with_no_direction_is_no_viewer(viewer):
    """A zero, infinite or NaN direction says what the front shows, as no viewer does."""
    assert viewer_words((0, 0, 1), "A→B→C", viewer) == viewer_words((0, 0, 1), "A→B→C", None)


def test_listen_pans_by_x_pitches_by_y_and_brightens_by_z(tmp_path):
    """The tones of js/explorer/src/audio.js: direction only, U, V and N in order, none for N = 0."""
    script = tmp_path / "tones.mjs"
    audio = (ROOT / "js" / "explorer" / "src" / "audio.js").as_uri()
    script.write_text(
        f'import {{ toneOf, tonesOf }} from "{audio}";\n'
        "const vectors = [[3, 0, 0], [0, -2, 0], [0, 0, 5], [0, 0, -1e300], [1, 1, 1], "
        "[Infinity, 0, 0], [0, 0, 0]];\n"
        "const names = (st) => tonesOf(st).map(([name]) => name).join('');\n"
        "console.log(JSON.stringify({ tones: vectors.map(toneOf), "
        "proper: names({ u: [1, 0, 0], v: [0, 1, 0], unit_normal: [0, 0, 1] }), "
        "flat: names({ u: [1, 1, 1], v: [2, 2, 2], unit_normal: null }) }));\n",
        encoding="utf-8",
    )
    run = subprocess.run([node_path(), str(script)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    out = json.loads(run.stdout)
    right, low, up, down, diagonal, huge, zero = out["tones"]
    assert (right["pan"], right["frequency"]) == (1, 440)  # x: all the way right, y = 0
    assert (low["pan"], low["frequency"]) == (0, 220)  # −y: an octave down
    assert up["cutoff"] > diagonal["cutoff"] > right["cutoff"] > down["cutoff"]  # z: brighter up
    assert up["gain"] > right["gain"] > down["gain"]  # and louder
    assert diagonal["frequency"] == pytest.approx(440 * 2 ** (1 / math.sqrt(3)))
    assert huge == right and zero is None
    assert (out["proper"], out["flat"]) == ("UVN", "UV")


def test_the_accessibility_pages_example_is_what_the_package_prints():
    """docs/accessibility.md shows ex.describe() as a session: each line is run and compared."""
    import doctest

    page = (ROOT / "docs" / "accessibility.md").read_text(encoding="utf-8")
    sessions = [block for block in page.split("```python\n")[1:] if ">>>" in block]
    assert sessions, "the page shows no session"
    for block in sessions:
        test = doctest.DocTestParser().get_doctest(block.split("```")[0], {}, "page", None, 0)
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
        assert runner.run(test).failed == 0


def test_ex_describe_says_what_the_view_shows_once_a_view_says_where_it_looks_from():
    """The view sends its camera when it settles: from then on ex.describe() is the view's words."""
    ex = Explorer()
    assert ex.describe() == describe(ex.result)  # no view yet: what the front shows
    ex.view._handle_custom_msg({"viewer": [0.1, 0.2, -3]}, [])
    assert ex.describe() == describe(ex.result, (0, 0, -1))
    assert "You see the back" in ex.describe()
    for junk in ([0, 0], ["x", 0, 1], [math.nan, 0, 1], "up", None):
        ex.view._handle_custom_msg({"viewer": junk}, [])  # not a direction: ignored
    assert ex.describe(viewer=(0, 0, 1)).startswith("N points straight up")
    assert "You see the back" in ex.describe()
