/*
 * How long N and the unit normal are drawn, and what their labels say.
 *
 * N is drawn at its true length (in the axes' units) when that is about the longest edge
 * (0.49 to 0.99 times it); otherwise it is scaled by a power of two into that range, so the
 * triangle and N fit the picture together, and its label says so: "N/4", "2N" (as the
 * matplotlib figure labels it). The unit normal likewise: "N/(4|N|)", "2N/|N|".
 */
export const N_AIM = 0.7; // the drawn length aimed at, times the longest edge (at most 0.99 of it: the triangle keeps its share of the frame)
export const UNIT_AIM = 0.5;

/** The power of two that brings `length` nearest to `aim` on a log scale (1 when it is 0). */
function drawScale(length, aim) {
  if (!(length > 0) || !(aim > 0) || !Number.isFinite(length)) return 1;
  return 2 ** Math.round(Math.log2(aim / length));
}

/** How a vector of true `length` (display units) is drawn: its factor and its drawn length. */
export function drawnAt(length, aim) {
  const factor = drawScale(length, aim);
  return { factor, length: length * factor };
}

const SUPERSCRIPT = "⁰¹²³⁴⁵⁶⁷⁸⁹";
function powerText(factor) {
  const k = Math.round(Math.log2(factor));
  if (Math.abs(k) <= 12) return String(2 ** Math.abs(k));
  return "2" + [...String(Math.abs(k))].map((d) => SUPERSCRIPT[Number(d)]).join("");
}

/** The label of N drawn `factor` times its length: "N", "N/4", "2N"; unit: "N/|N|", "N/(4|N|)", "2N/|N|". */
export function scaledLabel(factor, unit = false) {
  if (factor === 1) return unit ? "N/|N|" : "N";
  const f = powerText(factor);
  if (factor < 1) return unit ? `N/(${f}|N|)` : `N/${f}`;
  return unit ? `${f}N/|N|` : `${f}N`;
}
