/*
 * The view described in words: which way N points, which side the viewer sees, which way the
 * order of the vertices turns for them. A port of trinormal/explorer/describe.py, the one rule
 * (read its header for the wording); tests/test_describe.py runs both on one corpus and asks
 * for the same strings, byte for byte. Plain functions over numbers, no three.js, so Node runs
 * this file as it is.
 */

// the thresholds of trinormal.explorer.describe (MENTION, A_LITTLE, EDGE_ON); the parity test
// reads them from here and compares them with Python's
export const MENTION = 0.05;
export const A_LITTLE = 0.25;
export const EDGE_ON = 0.02;

const AXES = "xyz";
const MINUS = "\u2212";

const signedAxis = (axis, negative) => (negative ? MINUS : "+") + AXES[axis];
const word = (axis, negative) => (axis === 2 ? (negative ? "down" : "up") : "towards " + signedAxis(axis, negative));
/** "a", "a and b", "a, b and c". */
const join = (words) => (words.length === 1 ? words[0] : words.slice(0, -1).join(", ") + " and " + words[words.length - 1]);
// whole degrees, rounded half away from zero from the exact value as the package's formatter
// does (for a positive number Math.round does the same); under half a degree in words
const degrees = (x) => (x < 0.5 ? "less than 1" : String(Math.round(x)));

/** Which way a unit normal ([x, y, z]) points, in words and one number (describe.direction_words). */
export function directionWords(unitNormal) {
  const n = unitNormal.map(Number);
  const size = n.map(Math.abs);
  const signed = [0, 1, 2].map((i) => signedAxis(i, n[i] < 0));
  const order = [0, 1, 2].sort((i, j) => size[j] - size[i]); // stable: x, y, z among equals
  const first = order[0];
  if (size[order[1]] === 0 && size[order[2]] === 0) return `N points straight ${word(first, n[first] < 0)}, along ${signed[first]}.`;
  const words = order.filter((i) => size[i] >= MENTION).map((i) => (size[i] < A_LITTLE ? "a little " : "") + word(i, n[i] < 0));
  const tied = [0, 1, 2].filter((i) => size[i] === size[first]);
  const rest = [0, 1, 2].filter((i) => i !== first).map((i) => size[i]);
  const angle = Math.atan2(Math.sqrt(rest[0] * rest[0] + rest[1] * rest[1]), size[first]);
  const deg = degrees(angle * (180 / Math.PI));
  let lead;
  if (tied.length === 1) lead = `mostly ${signed[first]}, ${deg}° from the ${AXES[first]} axis`;
  else if (tied.length === 2) lead = `equally ${join(tied.map((i) => signed[i]))}, ${deg}° from the ${join(tied.map((i) => AXES[i]))} axes`;
  else lead = `equally ${join(signed)}, ${deg}° from each axis`;
  return `N points ${join(words)}: ${lead}.`;
}

/**
 * Which side the viewer sees and which way `order` ("A→B→C") turns for them (describe.viewer_words).
 * viewer: the direction from the triangle towards the viewer ([x, y, z], any length), or null.
 */
export function viewerWords(unitNormal, order, viewer) {
  const v = viewer ? viewer.map(Number) : null;
  const length = v ? Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) : 0;
  if (!v || !(length > 0) || !Number.isFinite(length)) return `From its front (the side N points to), ${order} turns counter-clockwise.`;
  const n = unitNormal.map(Number);
  const cos = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / length;
  if (Math.abs(cos) < EDGE_ON) return "You see the triangle edge-on: neither side faces you.";
  const [side, turn] =
    cos > 0 ? ["front of the triangle (N points towards you)", "counter-clockwise"] : ["back of the triangle (N points away from you)", "clockwise"];
  return `You see the ${side}, and ${order} turns ${turn}.`;
}

/**
 * The description of a host's `state` ({ ok, error, degenerate, status, unit_normal }) drawn in
 * `winding` ("ABC" or "ACB"), seen from `viewer` (describe.describe). A state the host could not
 * compute (an unreadable coordinate on the site) is described by its error.
 */
export function describeState(state, winding, viewer) {
  const st = state || {};
  if (st.ok === false) return `Nothing to describe: ${st.error || st.status || ""}`.trim();
  if (st.degenerate || !Array.isArray(st.unit_normal)) {
    return `${st.status || ""} No direction to describe: the triangle has no front or back.`.trim();
  }
  const order = winding === "ACB" ? "A→C→B" : "A→B→C";
  return `${directionWords(st.unit_normal)} ${viewerWords(st.unit_normal, order, viewer)}`;
}
