/*
 * Numbers for drawing and for the values the view writes back.
 * The view never computes anything it prints: these helpers only turn the host's
 * exact text into floats for drawing, and turn a drag or a key press into a decimal
 * string on the grid ("0.3", "-1.2", "2").
 */

const DECIMAL = /^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/;
const FRACTION = /^([+-]?\d+)\s*\/\s*([+-]?\d+)$/;

/** A coordinate's text as a float for drawing, or NaN when it cannot be read. */
export function parseCoordinate(text) {
  const s = String(text ?? "").trim();
  if (DECIMAL.test(s)) return Number(s);
  const m = FRACTION.exec(s);
  if (m) {
    const q = Number(m[1]) / Number(m[2]);
    return Number.isFinite(q) ? q : NaN;
  }
  return NaN;
}

/** [x, y, z] floats of a vertex's three strings, or null when one is unreadable. */
export function parsePoint(values) {
  if (!Array.isArray(values) || values.length !== 3) return null;
  const p = values.map(parseCoordinate);
  return p.every(Number.isFinite) ? p : null;
}

/**
 * The grid: the step's value, its number of decimals and its value in units of 10^-decimals.
 * Read as Python's Decimal(step).normalize() reads it: "0.1" and "0.10" have 1 decimal,
 * "1e-3" has 3, "2" and "20" have none.
 */
export function readStep(step) {
  const s = String(step ?? "0.1").trim();
  const m = /^(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/.exec(s);
  if (!m || !(Number(s) > 0) || !/\d/.test((m[1] || "") + (m[2] || ""))) {
    return { value: 0.1, decimals: 1, units: 1 };
  }
  let digits = ((m[1] || "") + (m[2] || "")).replace(/^0+(?=\d)/, "");
  let exponent = Number(m[3] || 0) - (m[2] || "").length;
  while (digits.length > 1 && digits.endsWith("0")) {
    digits = digits.slice(0, -1);
    exponent += 1;
  }
  const decimals = Math.max(0, -exponent);
  const units = Number(digits) * 10 ** (exponent + decimals);
  return { value: units / 10 ** decimals, decimals, units };
}

/** The exact value of a double as [numerator, denominator] BigInts (float.as_integer_ratio). */
function ratio(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const negative = bits >> 63n === 1n;
  const biased = Number((bits >> 52n) & 0x7ffn);
  let mantissa = bits & ((1n << 52n) - 1n);
  if (biased) mantissa |= 1n << 52n;
  const e = (biased || 1) - 1075;
  const num = negative ? -mantissa : mantissa;
  return e >= 0 ? [num << BigInt(e), 1n] : [num, 1n << BigInt(-e)];
}

/** round(x / step), ties away from zero, computed exactly from the double x. */
function nearestIndex(x, grid) {
  if (!Number.isFinite(x)) return 0;
  const [num, den] = ratio(x);
  const scale = 10n ** BigInt(grid.decimals);
  const units = BigInt(grid.units);
  const top = (num < 0n ? -num : num) * scale * 2n + den * units;
  const k = top / (2n * den * units); // floor(|x| / step + 1/2)
  return Number(num < 0n ? -k : k);
}

/**
 * The grid index nearest to x (ties away from zero, as Python's snap), clamped so the
 * written value stays inside bounds.
 */
export function gridIndex(x, grid, bounds) {
  let k = nearestIndex(x, grid);
  if (Array.isArray(bounds) && bounds.length === 2) {
    const lo = Math.ceil(Number(bounds[0]) / grid.value - 1e-9);
    const hi = Math.floor(Number(bounds[1]) / grid.value + 1e-9);
    if (Number.isFinite(lo)) k = Math.max(k, lo);
    if (Number.isFinite(hi)) k = Math.min(k, hi);
  }
  return k === 0 ? 0 : k; // no -0
}

/** True when x is exactly (to rounding) the grid value number k: nothing to rewrite. */
export function onGridAt(x, k, grid) {
  return Math.abs(x - k * grid.value) <= 1e-9 * Math.max(1, Math.abs(x));
}

/** Grid index k as decimal text with the step's decimals: k = -12, step 0.1 -> "-1.2". */
export function gridText(k, grid) {
  const n = BigInt(k) * BigInt(grid.units);
  const neg = n < 0n;
  let digits = (neg ? -n : n).toString();
  if (grid.decimals > 0) {
    digits = digits.padStart(grid.decimals + 1, "0");
    digits = digits.slice(0, -grid.decimals) + "." + digits.slice(-grid.decimals);
  }
  return (neg ? "-" : "") + digits;
}

/** A power of ten S so that radius / S lies in [1, 10): the scene is drawn in units of S. */
export function powerOfTen(radius) {
  if (!(radius > 0) || !Number.isFinite(radius)) return 1;
  return 10 ** Math.floor(Math.log10(radius));
}

/** The smallest of 1, 2, 5 times a power of ten that is at least x. */
export function niceCeil(x) {
  if (!(x > 0)) return 1;
  const p = 10 ** Math.floor(Math.log10(x));
  for (const m of [1, 2, 5, 10]) if (m * p >= x * (1 - 1e-9)) return m * p;
  return 10 * p;
}

/** A tick value as short text: 0.5, 2, 1e+6. */
export function tickText(x) {
  if (x === 0) return "0";
  const a = Math.abs(x);
  if (a >= 1e5 || a < 1e-3) return x.toExponential(0).replace("e+", "e");
  return String(Number(x.toPrecision(6)));
}
