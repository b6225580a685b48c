/*
 * Where the camera first looks from, and what it keeps in sight: the view frames the model on
 * its own vertices (its extremes and a sample), not on its box, whose corners lie far outside
 * a round model; and it looks towards what is wrong with it.
 */
import { Vector3 } from "three";
import { DEFAULT_DIRECTION } from "../scene.js";

/** Px the camera keeps free at each side of the model (it has no labels beyond its points). */
export const MARGIN = 28;

/** At most this many vertices, spread over the model, frame the view (besides its extremes). */
const FRAMING_SAMPLE = 4096;

/**
 * The points the view keeps in sight: the vertices furthest along each axis and each diagonal
 * of the box, both ways, and an even sample of the rest (positions: x, y, z per vertex).
 */
export function framingPoints(pos) {
  const n = pos.length / 3;
  const dirs = [];
  for (const sx of [-1, 0, 1]) for (const sy of [-1, 0, 1]) for (const sz of [-1, 0, 1]) if (sx || sy || sz) dirs.push([sx, sy, sz]);
  const best = dirs.map(() => [-Infinity, 0]);
  for (let i = 0; i < n; i++) {
    const x = pos[3 * i], y = pos[3 * i + 1], z = pos[3 * i + 2];
    for (let k = 0; k < dirs.length; k++) {
      const d = dirs[k];
      const along = d[0] * x + d[1] * y + d[2] * z;
      if (along > best[k][0]) best[k] = [along, i];
    }
  }
  const chosen = new Set(best.map((b) => b[1]));
  const step = Math.max(1, Math.ceil(n / FRAMING_SAMPLE));
  for (let i = 0; i < n; i += step) chosen.add(i);
  return [...chosen].map((i) => new Vector3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]));
}

/**
 * Where the camera first looks from: towards what is wrong (the faces to flip, else the holes'
 * rims, else the fins), tilted a little so the view stays oblique; the usual view otherwise.
 * `sets` holds the face sides (3 * face + k) of each fault.
 */
export function startDirection(pos, faces, sets) {
  const sides = sets.flipped.length ? sets.flipped : sets.boundary.length ? sets.boundary : sets.non_manifold;
  if (!sides.length) return DEFAULT_DIRECTION.clone();
  const c = new Vector3();
  for (let i = 0; i < sides.length; i++) {
    const v = faces[sides[i]];
    c.x += pos[3 * v];
    c.y += pos[3 * v + 1];
    c.z += pos[3 * v + 2];
  }
  c.divideScalar(sides.length);
  if (!(c.length() > 1e-6)) return DEFAULT_DIRECTION.clone();
  return c.normalize().multiplyScalar(3).add(DEFAULT_DIRECTION).normalize();
}
