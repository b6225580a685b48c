/*
 * What the explorer frames: the units the triangle is drawn in (the data divided by a power
 * of ten S, less an offset when the triangle is far from the origin), the axes' length and
 * ticks, the box the camera keeps in view, and where the camera first looks from.
 */
import { Vector3 } from "three";
import { niceCeil, powerOfTen } from "./numbers.js";
import { DEFAULT_DIRECTION } from "./scene.js";
import { drawnAt, N_AIM, UNIT_AIM } from "./scaling.js";

/**
 * Where the camera first looks from: the usual oblique view, unless it sees the triangle
 * nearly edge-on or N nearly head-on; then the one of 24 views around the scene that sees
 * the front face at about 50 degrees, so the faces, N and the parallelogram can all be seen.
 */
function startDirection(normal) {
  if (!(normal.length() > 0)) return DEFAULT_DIRECTION.clone();
  const n = normal.clone().normalize();
  const cos = DEFAULT_DIRECTION.dot(n);
  if (cos >= 0.35 && cos <= 0.8) return DEFAULT_DIRECTION.clone();
  // aim for cos(angle to N) = 0.65: the front face well in view, N still clearly an arrow
  let best = DEFAULT_DIRECTION.clone();
  let miss = Math.abs(DEFAULT_DIRECTION.dot(n) - 0.65);
  for (const elevation of [20, 35, 55]) {
    for (let k = 0; k < 8; k++) {
      const az = ((k * 45 + 37) * Math.PI) / 180;
      const el = (elevation * Math.PI) / 180;
      const d = new Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
      const m = Math.abs(d.dot(n) - 0.65);
      if (m < miss - 1e-9) [best, miss] = [d, m];
    }
  }
  return best;
}

/** A data point ([x, y, z]) in the display units of `frame` ({ S, offset }). */
export function toDisplay(p, { S, offset }) {
  return new Vector3(p[0] - offset.x, p[1] - offset.y, p[2] - offset.z).divideScalar(S);
}

/**
 * The frame of the points `pts` (data floats) drawn in `winding`, with the unit normal when
 * `showUnit`: { S, offset, includeOrigin, radius, center, box, L, t, start }.
 */
export function computeFrame(pts, winding, showUnit) {
  const ext = Math.max(...pts.flat().map(Math.abs));
  const edges = [
    [0, 1],
    [0, 2],
    [1, 2],
  ].map(([i, j]) => Math.hypot(...pts[i].map((x, k) => x - pts[j][k])));
  const size = Math.max(...edges);
  const includeOrigin = size === 0 ? true : ext <= 6 * size;
  const R = includeOrigin ? ext || size || 1 : size;
  const S = powerOfTen(R);
  const offset = includeOrigin
    ? new Vector3()
    : new Vector3(...[0, 1, 2].map((k) => Number(((pts[0][k] + pts[1][k] + pts[2][k]) / 3).toPrecision(3))));
  const disp = pts.map((p) => toDisplay(p, { S, offset }));
  const extD = Math.max(...disp.map((p) => Math.max(Math.abs(p.x), Math.abs(p.y), Math.abs(p.z))));
  const t = niceCeil(Math.max(extD, 1e-9) / 1.5); // a labelled tick every t, grid lines every t/2
  const L = t * (Math.floor(extD / t + 1e-9) + 1.5);
  // the framed box: the points and the tips of N and the unit normal as drawn (the origin
  // and the axes are context: framing them too would make a triangle away from it small)
  const box = disp.slice();
  const [a, b, c] = disp;
  // N as drawn: A→C→B turns it over (framing the other side would leave its head out)
  const n = new Vector3().crossVectors(b.clone().sub(a), c.clone().sub(a));
  if (winding === "ACB") n.negate();
  const lMax = Math.max(a.distanceTo(b), a.distanceTo(c), b.distanceTo(c));
  const centroid = a.clone().add(b).add(c).divideScalar(3);
  if (n.length() > 0) {
    // n = U x V in display units is N / S^2: N's true length in display units is |n| * S
    box.push(centroid.clone().add(n.clone().setLength(drawnAt(n.length() * S, N_AIM * lMax).length)));
    if (showUnit) box.push(centroid.clone().add(n.clone().setLength(drawnAt(1 / S, UNIT_AIM * lMax).length)));
  }
  const lo = box[0].clone();
  const hi = box[0].clone();
  for (const p of box) {
    lo.min(p);
    hi.max(p);
  }
  const center = lo.clone().add(hi).multiplyScalar(0.5);
  const radius = Math.max(hi.distanceTo(lo) / 2, 1e-3);
  return { S, offset, includeOrigin, radius, center, box, L, t, start: startDirection(n) };
}

/** True when two frames draw in the same units (the same S, offset and origin). */
export function sameUnits(a, b) {
  return a && b && a.S === b.S && a.includeOrigin === b.includeOrigin && a.offset.equals(b.offset);
}
