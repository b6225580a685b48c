/*
 * What the explorer frames: the units the triangle is drawn in (the data divided by a power
 * of ten S, less an offset when the triangle is far from the origin), the axes' length and
 * ticks, the points the camera keeps in view, where the camera first looks from, and which
 * views show the triangle (never edge-on to its plane, never along the line of collinear
 * points). Pure functions of the points: tests/test_view_scale.py runs them in Node.
 */
import { Vector3 } from "three";
import { niceCeil, powerOfTen } from "./numbers.js";
import { DEFAULT_DIRECTION } from "./scene.js";
import { drawnAt } from "./scaling.js";

// the views the camera may start from when the usual one is poor: 8 azimuths at 3 elevations
const CANDIDATES = [20, 35, 55].flatMap((elevation) =>
  [...Array(8).keys()].map((k) => {
    const az = ((k * 45 + 37) * Math.PI) / 180;
    const el = (elevation * Math.PI) / 180;
    return new Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
  }),
);
// a view is poor when it looks within about 14 degrees of the triangle's plane (|cos| to N
// below 0.25), or, for points on a line, within about 45 degrees of that line (|cos| above 0.7)
const EDGE_ON = 0.25;
const ALONG_LINE = 0.7;

/**
 * True when looking from `direction` shows the frame's triangle: not edge-on to its plane,
 * not along its line when its points are collinear. A frame with neither (one point) takes any.
 */
export function showsTriangle(direction, frame) {
  const d = direction.clone().normalize();
  if (frame.normal) return Math.abs(d.dot(frame.normal)) >= EDGE_ON;
  if (frame.line) return Math.abs(d.dot(frame.line)) <= ALONG_LINE;
  return true;
}

/**
 * Where the camera first looks from: the usual oblique view, unless it sees the triangle
 * nearly edge-on or N nearly head-on (or looks nearly along the line of collinear points);
 * then the one of 24 views from above that sees the face at about 50 degrees, its front
 * rather than its back (for a line: the one nearest the usual view that sees it from at
 * least 70 degrees), so the face, N and the
 * parallelogram can all be seen. Both windings of one triangle start from the same view
 * when the usual one suits them: a flip shows N turning over, not the camera moving.
 */
function startDirection(normal, line) {
  if (normal) {
    const cos = Math.abs(DEFAULT_DIRECTION.dot(normal));
    if (cos >= 0.35 && cos <= 0.8) return DEFAULT_DIRECTION.clone();
  } else if (line) {
    if (Math.abs(DEFAULT_DIRECTION.dot(line)) <= 0.35) return DEFAULT_DIRECTION.clone();
  } else return DEFAULT_DIRECTION.clone();
  // a line: the view nearest the usual one among those square to it within about 70 degrees
  const miss = (d) => {
    if (!normal) return Math.abs(d.dot(line)) <= 0.35 ? 1 - d.dot(DEFAULT_DIRECTION) : 3 + Math.abs(d.dot(line));
    const cos = d.dot(normal);
    return Math.abs(Math.abs(cos) - 0.65) + (cos < 0 ? 0.05 : 0);
  };
  let best = DEFAULT_DIRECTION.clone();
  for (const d of CANDIDATES) if (miss(d) < miss(best) - 1e-9) best = d.clone();
  return best;
}

/** The two of `points` (Vector3s) farthest apart and their distance: { ends: [p, q], far } (ends null when they coincide). */
export function farthestPair(points) {
  let ends = null;
  let far = 0;
  for (let i = 0; i < points.length; i++) {
    for (let j = i + 1; j < points.length; j++) {
      const d = points[i].distanceTo(points[j]);
      if (d > far) [far, ends] = [d, [points[i], points[j]]];
    }
  }
  return { ends, far };
}

/** The direction of the line through collinear points (display units), or null when they coincide. */
function lineOf(disp) {
  const { ends } = farthestPair(disp);
  return ends ? ends[1].clone().sub(ends[0]).normalize() : null;
}

/**
 * N and the unit normal as drawn from the centroid, for n = U x V in display units (N / S^2,
 * so N's true length in display units is |n| * S): their vectors and scale factors.
 */
export function drawnArrows(n, S, lMax, degenerate, showUnit) {
  let nDraw = new Vector3();
  let nFactor = 1;
  if (!degenerate) {
    const d = drawnAt(n.length() * S, lMax);
    nFactor = d.factor;
    nDraw = n.clone().setLength(d.length);
  }
  let unitDraw = null;
  let unitFactor = 1;
  if (!degenerate && showUnit) {
    const d = drawnAt(1 / S, lMax);
    unitFactor = d.factor;
    unitDraw = n.clone().setLength(d.length);
  }
  return { nDraw, nFactor, unitDraw, unitFactor };
}

/** A data point ([x, y, z]) in the display units of `frame` ({ S, offset }). */
export function toDisplay(p, { S, offset }) {
  return new Vector3(p[0] - offset.x, p[1] - offset.y, p[2] - offset.z).divideScalar(S);
}

/**
 * The frame of the points `pts` (data floats) drawn in `winding`, with the unit normal when
 * `showUnit`; `degenerate` when the host calls the triangle degenerate (it is then drawn as
 * points on a line): { S, offset, includeOrigin, box, L, t, start, normal,
 * line }. `normal` is N's direction as drawn (null for a degenerate triangle), `line` the
 * direction of the line through collinear points (null otherwise, or when they coincide).
 */
export function computeFrame(pts, winding, showUnit, degenerate = false) {
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
  const plane = !degenerate && n.length() > 0 && Number.isFinite(n.length());
  if (plane) {
    const { nDraw, unitDraw } = drawnArrows(n, S, lMax, false, showUnit);
    box.push(centroid.clone().add(nDraw));
    if (unitDraw) box.push(centroid.clone().add(unitDraw));
  }
  if (lMax === 0) {
    // one point: frame a tick's width around it, so the view does not zoom into a dot
    for (const sign of [-1, 1]) box.push(a.clone().addScalar((sign * t) / 2));
  }
  const normal = plane ? n.clone().normalize() : null;
  const line = plane ? null : lineOf(disp);
  return { S, offset, includeOrigin, box, L, t, normal, line, start: startDirection(normal, line) };
}

/** True when two frames draw in the same units (the same S, offset and origin). */
export function sameUnits(a, b) {
  return a && b && a.S === b.S && a.includeOrigin === b.includeOrigin && a.offset.equals(b.offset);
}
