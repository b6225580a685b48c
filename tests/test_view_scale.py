"""How the 3D views look and fit: one colour code, N drawn to scale, every triangle framed.

The framing and scaling rules of the view are pure functions of ``js/explorer/src``
(framing.js, scene.js's fitCamera, scaling.js); they run here in Node, without a browser:
for triangles of every kind (tiny, huge, far from the origin, collinear, two points equal,
both windings) each point the camera must keep in view projects inside the view with the
label margin, and the camera never starts edge-on to the plane nor along the line of
collinear points. The label of a scaled N is Python's (trinormal.plotting.scale), character
for character.
"""

from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import pytest
from node_runs import node_path

from trinormal import colors
from trinormal.plotting.scale import drawn_factor, scaled_label

ROOT = Path(__file__).resolve().parents[1]
JS = ROOT / "js" / "explorer"


def _contrast(fg: str, bg: str) -> float:
    def luminance(hex_colour: str) -> float:
        rgb = [int(hex_colour[i : i + 2], 16) / 255 for i in (1, 3, 5)]
        lin = [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in rgb]
        return 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]

    hi, lo = sorted((luminance(fg), luminance(bg)), reverse=True)
    return (hi + 0.05) / (lo + 0.05)


@pytest.mark.parametrize("dark", [False, True])
def test_the_axes_are_neutral_greys_apart_from_the_vectors_and_faces(dark: bool) -> None:
    background = "#1B1D24" if dark else "#FFFFFF"
    axes = [colors.color(a, dark) for a in "xyz"]
    for hex_colour in axes:
        assert hex_colour[1:3] == hex_colour[3:5] == hex_colour[5:7], hex_colour  # grey
        assert _contrast(hex_colour, background) >= 3, hex_colour
    assert len(set(axes)) == 3  # told apart by lightness
    others = {colors.color(role, dark) for role in ("U", "V", "N", "front", "back", "A")}
    assert not others & set(axes)


def test_notebooks_01_and_03_state_the_one_colour_code() -> None:
    for name in ("01_worked_example", "03_comparison_table"):
        notebook = json.loads((ROOT / "notebooks" / f"{name}.ipynb").read_text(encoding="utf-8"))
        text = " ".join(
            "".join(c["source"]) for c in notebook["cells"] if c["cell_type"] == "markdown"
        )
        assert colors.COLOR_CODE in text, name


def _node(script: str, data: object) -> object:
    node = node_path()
    result = subprocess.run(
        [node, "--input-type=module", "-e", script],
        cwd=JS,
        input=json.dumps(data),
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(result.stdout)


_SCALE_SCRIPT = """
import { drawnFactor, scaledLabel } from "./src/scaling.js";
let input = "";
process.stdin.on("data", (d) => (input += d)).on("end", () => {
  const out = JSON.parse(input).map(([n, edge]) => {
    const f = drawnFactor(n, edge);
    return [f, scaledLabel(f), scaledLabel(f, true)];
  });
  process.stdout.write(JSON.stringify(out));
});
"""


def test_the_views_scale_and_labels_of_n_are_pythons() -> None:
    cases = [(n, 1.0) for n in (0.0, 1e-300, 1e-9, 0.01, 0.2, 0.247, 0.25, 1.0, 1.01, 1.4, 2.0)]
    cases += [(n, 1.0) for n in (3.0, 5.6, 16.0, 40.0, 1e5, 1e9, 1e300)]
    cases += [(16.0, 5.656854249492381), (0.09, 0.4242640687119285), (400.0, 28.28), (1.0, 0.0)]
    got = _node(_SCALE_SCRIPT, cases)
    for (n, edge), (factor, label, unit) in zip(cases, got, strict=True):
        want = drawn_factor(n, edge)
        assert (factor, label, unit) == (want, scaled_label(want), scaled_label(want, True)), n
        assert "½" not in label  # "N × ½" beside "area = |N|/2" could be read as the area
        if factor != 1.0:  # outside the true-length range only
            assert not 0.25 <= n / edge <= 1.0, n


_FRAME_SCRIPT = """
import { PerspectiveCamera } from "three";
import { computeFrame, showsTriangle } from "./src/framing.js";
import { fitCamera, LABEL_MARGIN } from "./src/scene.js";
let input = "";
process.stdin.on("data", (d) => (input += d)).on("end", () => {
  const { triangles, sizes } = JSON.parse(input);
  const out = [];
  for (const [pts, winding, degenerate] of triangles) {
    const frame = computeFrame(pts, winding, true, degenerate);
    for (const [width, height] of sizes) {
      const fit = fitCamera(frame.box, frame.start, { width, height });
      const camera = new PerspectiveCamera(40, width / height, fit.distance / 200, fit.distance * 50);
      camera.up.set(0, 0, 1);
      camera.position.copy(fit.target).addScaledVector(fit.direction, fit.distance);
      camera.lookAt(fit.target);
      camera.updateMatrixWorld();
      const px = frame.box.map((p) => {
        const q = p.clone().project(camera);
        return [((q.x + 1) / 2) * width, ((1 - q.y) / 2) * height, q.z];
      });
      const d = fit.direction;
      out.push({
        px, width, height, margin: LABEL_MARGIN, shows: showsTriangle(d, frame),
        cosNormal: frame.normal ? Math.abs(d.dot(frame.normal)) : null,
        cosLine: frame.line ? Math.abs(d.dot(frame.line)) : null,
        boxSize: frame.box.length,
      });
    }
  }
  process.stdout.write(JSON.stringify(out));
});
"""

#: (points, degenerate): every kind of triangle the view must frame.
TRIANGLES = [
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], False),
    ([[0, 0, 0], [1, 1, 1], [2, 2, 2]], True),  # the guide's collinear row
    ([[0, 0, 0], [1, 0, 0], [2, 0, 0]], True),  # collinear along x
    ([[1, 2, 3], [1, 2, 3], [1, 2, 9]], True),  # two points equal
    ([[1, 1, 1], [1, 1, 1], [1, 1, 1]], True),  # one point
    ([[0, 0, 0], [1e-6, 0, 0], [0, 1e-6, 0]], False),  # tiny
    ([[-1200, 300, 0], [4100, 900, -800], [2500, 3700, 1500]], False),  # huge
    ([[1e6, 1e6, 1e6], [1000400, 1e6, 1e6], [1e6, 1000300, 1000200]], False),  # far away
    ([[3, 3, 3], [3.5, 3, 3], [3, 3.5, 3.2]], False),
    ([[0, 0, 0], [4, 0, 0], [0, 4, 0]], False),  # N scaled down
    ([[0, 0, 0], [1, 0, 0], [0, 0, 1]], False),  # upright: the usual view sees it edge-on
    ([[0, 0, 0], [1, 0.75, 0.65], [0, 0, 1]], False),  # contains the usual direction
    ([[0, 0, 0], [5, 0, 0], [0, 5, 0.001]], False),  # a thin sliver
]
#: View sizes (px): the site, a narrow notebook, a projector in full screen, a phone.
SIZES = [[600, 370], [470, 170], [1280, 720], [340, 300]]


def test_every_triangle_is_framed_with_its_labels_margin_and_seen_face_on() -> None:
    triangles = [(pts, w, deg) for pts, deg in TRIANGLES for w in ("ABC", "ACB")]
    got = _node(_FRAME_SCRIPT, {"triangles": triangles, "sizes": SIZES})
    assert isinstance(got, list) and len(got) == len(triangles) * len(SIZES)
    for k, shot in enumerate(got):
        pts, winding, degenerate = triangles[k // len(SIZES)]
        where = (pts, winding, shot["width"], shot["height"])
        # the margin is the label margin, or what is left of it on a very small view
        mx = min(shot["margin"], 0.3 * shot["width"]) - 0.5
        my = min(shot["margin"], 0.3 * shot["height"]) - 0.5
        for x, y, z in shot["px"]:
            assert mx <= x <= shot["width"] - mx, where
            assert my <= y <= shot["height"] - my, where
            assert -1 < z < 1, where
        assert shot["shows"], where
        if degenerate:
            assert shot["cosNormal"] is None
            if shot["cosLine"] is not None:
                assert shot["cosLine"] <= 0.35, where  # square to the line, never along it
        else:
            assert 0.35 <= shot["cosNormal"] <= 0.9, where  # never edge-on, never head-on
            assert shot["boxSize"] == 5, where  # A, B, C and the tips of N and N/|N|
    assert math.isfinite(len(got))
