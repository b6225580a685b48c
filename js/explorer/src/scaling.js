/*
 * How long N and the unit normal are drawn, and what their labels say: a port of
 * trinormal/plotting/scale.py (tests/test_view_scale.py checks that both answer alike).
 *
 * N is drawn at its true length (in the axes' units) when that is between ¼ and 1 times the
 * triangle's longest edge; otherwise it is scaled by the power of two that brings it nearest
 * 0.7 times that edge, and its label names the factor: "N × ¼", "N × 8". The factor ½ never
 * occurs ("N × ½" beside "area = |N|/2" could be read as the area): longer than the edge,
 * N is drawn at most a quarter of its length. The unit normal follows
 * the same rule: "N/|N| × 4".
 */
const TRUE_LENGTH = [0.25, 1.0];
const AIM = 0.7;
const MAX_POWER = 1000;

/** The factor a vector of true `length` is drawn at beside a triangle whose longest edge is `longest`. */
export function drawnFactor(length, longest) {
  if (!(length > 0 && length < Infinity && longest > 0 && longest < Infinity)) return 1;
  // log2 of the ratio, taken apart: the ratio itself may overflow or underflow
  const logRatio = Math.log2(length) - Math.log2(longest);
  if (Math.log2(TRUE_LENGTH[0]) <= logRatio && logRatio <= Math.log2(TRUE_LENGTH[1])) return 1;
  let k = Math.floor(Math.log2(AIM) - logRatio + 0.5);
  if (logRatio > 0) k = Math.min(k, -2); // shorter, but never by ½
  return 2 ** Math.max(-MAX_POWER, Math.min(MAX_POWER, k));
}

/** How a vector of true `length` is drawn beside an edge of `longest`: its factor and its drawn length. */
export function drawnAt(length, longest) {
  const factor = drawnFactor(length, longest);
  return { factor, length: length * factor };
}

const FRACTIONS = { 1: "½", 2: "¼", 3: "⅛" };
const SUPERSCRIPT = { "-": "⁻", 0: "⁰", 1: "¹", 2: "²", 3: "³", 4: "⁴", 5: "⁵", 6: "⁶", 7: "⁷", 8: "⁸", 9: "⁹" };

/** The label of N drawn `factor` times its length: "N", "N × ¼", "N × 8"; unit: "N/|N|", "N/|N| × ¼". */
export function scaledLabel(factor, unit = false) {
  const base = unit ? "N/|N|" : "N";
  const k = Math.round(Math.log2(factor));
  if (k === 0) return base;
  let text;
  if (Math.abs(k) > 12) text = "2" + [...String(k)].map((d) => SUPERSCRIPT[d]).join("");
  else if (k < 0) text = FRACTIONS[-k] || `1/${2 ** -k}`;
  else text = String(2 ** k);
  return `${base} × ${text}`;
}
