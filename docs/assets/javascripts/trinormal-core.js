/*
 * trinormal in the browser: the exact normal of a triangle, formatted exactly as the
 * Python package formats it (trinormal/core.py and trinormal/display.py).
 *
 * Every coordinate is read as an exact rational (BigInt numerator and denominator),
 * the cross product runs on integers, and every displayed number is +-sqrt(num/den)
 * rounded half away from zero from exact integer arithmetic. No floating point is
 * involved in any displayed digit, so the strings match Python byte for byte.
 *
 * The input limits, every message wording and the degeneracy tolerance are not written
 * here: they come from trinormal/validation.py (MESSAGES and limits()) and
 * trinormal/tolerances.py (DEFAULT_TOL) through the constants the site build
 * writes, assets/javascripts/trinormal-constants.js, which must load before this file.
 *
 * Plain JavaScript, no dependencies. In the browser it reads window.TRINORMAL_CONSTANTS
 * and defines window.TrinormalCore; in Node, module.exports is a function that takes
 * those constants (the same object) and returns the API.
 */
(function (root, factory) {
  "use strict";
  if (typeof module === "object" && module.exports) {
    module.exports = factory;
  } else {
    root.TrinormalCore = factory(root.TRINORMAL_CONSTANTS);
  }
})(typeof self !== "undefined" ? self : this, function (constants) {
  "use strict";

  if (
    !constants ||
    !constants.limits ||
    !constants.messages ||
    !constants.verdicts ||
    typeof constants.tol !== "number"
  ) {
    throw new Error(
      "trinormal-core.js needs TRINORMAL_CONSTANTS (assets/javascripts/trinormal-constants.js, " +
        "written by the site build) to be loaded first"
    );
  }
  // The limits and message templates of trinormal/validation.py, as the build wrote them.
  var LIMITS = constants.limits;
  var MESSAGES = constants.messages;
  var MAX_DIGITS = LIMITS.max_digits;
  var MAX_COMMON_DIGITS = LIMITS.max_common_digits;
  var MAX_TEXT_LENGTH = LIMITS.max_text_length;
  var MIN_PRECISION = LIMITS.min_precision;
  var MAX_PRECISION = LIMITS.max_precision;
  // The verdict sentences of trinormal/core.py and the formatter's cutoff (trinormal/display.py).
  var VERDICTS = constants.verdicts;
  var SCI_ABOVE_LOG10 = constants.format.sci_above_log10;
  var AXES = "xyz";

  // ------------------------------------------------------------------ integers

  function abs(n) {
    return n < 0n ? -n : n;
  }

  function bitLength(n) {
    n = abs(n);
    if (n === 0n) return 0;
    var hex = n.toString(16);
    var first = parseInt(hex[0], 16);
    return (hex.length - 1) * 4 + (32 - Math.clz32(first));
  }

  /* floor(sqrt(n)) for n >= 0, by Newton's method from an overestimate. */
  function isqrt(n) {
    if (n < 0n) throw new RangeError("isqrt of a negative number");
    if (n < 2n) return n;
    var x = 1n << BigInt(Math.ceil(bitLength(n) / 2));
    for (;;) {
      var y = (x + n / x) >> 1n;
      if (y >= x) return x;
      x = y;
    }
  }

  function pow10(k) {
    return 10n ** BigInt(k);
  }

  function gcd(a, b) {
    a = abs(a);
    b = abs(b);
    while (b !== 0n) {
      var t = a % b;
      a = b;
      b = t;
    }
    return a;
  }

  function lcm(a, b) {
    return (a / gcd(a, b)) * b;
  }

  /* n/d as the nearest-ish double (for drawing only: never printed), without overflow on the way. */
  function toNumber(n, d) {
    if (n === 0n) return 0;
    var shift = 64 - (bitLength(n) - bitLength(d)); // keep ~64 significant bits in the quotient
    var q = shift >= 0 ? (n << BigInt(shift)) / d : n / (d << BigInt(-shift));
    var x = Number(q);
    // x * 2^-shift, in two halves so neither factor over- or underflows on its own;
    // beyond the double range the value is drawn at the edge of it
    var h = Math.trunc(-shift / 2);
    x = x * Math.pow(2, h) * Math.pow(2, -shift - h);
    return Number.isFinite(x) ? x : x > 0 ? Number.MAX_VALUE : -Number.MAX_VALUE;
  }

  /* The exact value of a double as [numerator, denominator] (like float.as_integer_ratio). */
  function doubleRatio(x) {
    var buf = new DataView(new ArrayBuffer(8));
    buf.setFloat64(0, x);
    var bits = buf.getBigUint64(0);
    var sign = bits >> 63n ? -1n : 1n;
    var exp = Number((bits >> 52n) & 0x7ffn);
    var mant = bits & ((1n << 52n) - 1n);
    if (exp === 0) exp = 1;
    else mant |= 1n << 52n;
    var e = exp - 1075;
    if (mant === 0n) return [0n, 1n];
    while ((mant & 1n) === 0n && e < 0) {
      mant >>= 1n;
      e += 1;
    }
    if (e >= 0) return [sign * (mant << BigInt(e)), 1n];
    return [sign * mant, 1n << BigInt(-e)];
  }

  // trinormal.tolerances.DEFAULT_TOL, as the build wrote it: degenerate when |N| <= TOL * L^2
  var TOL = doubleRatio(constants.tol);

  // ------------------------------------------------------------------ parsing

  var LIMIT = 10n ** BigInt(MAX_DIGITS);
  var COMMON_LIMIT = 10n ** BigInt(MAX_COMMON_DIGITS);
  var LIMIT_BITS = bitLength(LIMIT);
  var QUOTE_SHOWN = LIMITS.quote_shown;
  var SPACES = "\t\n\v\f\r \x85\xa0\u1680\u2000-\u200a\u2028\u2029\u202f\u205f\u3000\ufeff";
  var STRIP_RE = new RegExp("^[" + SPACES + "]+|[" + SPACES + "]+$", "g");
  var SHOWN_RE = /[\p{L}\p{N}\p{P}\p{S}]/u;

  /* A user's text quoted for a message, short: trinormal.validation.quote_input. */
  function quoteInput(text) {
    var chars = Array.from(text);
    var cut = chars.length > QUOTE_SHOWN;
    if (cut) chars = chars.slice(0, QUOTE_SHOWN);
    var joined = chars.join("");
    var quote = joined.indexOf("'") >= 0 && joined.indexOf('"') < 0 ? '"' : "'";
    var out = quote;
    chars.forEach(function (ch) {
      var code = ch.codePointAt(0);
      if (ch === "\\" || ch === quote) out += "\\" + ch;
      else if (ch === "\n") out += "\\n";
      else if (ch === "\r") out += "\\r";
      else if (ch === "\t") out += "\\t";
      else if (ch === " " || (code > 0x20 && code < 0x7f)) out += ch;
      else if (code >= 0xa0 && SHOWN_RE.test(ch)) out += ch;
      else if (code < 0x100) out += "\\x" + code.toString(16).padStart(2, "0");
      else if (code < 0x10000) out += "\\u" + code.toString(16).padStart(4, "0");
      else out += "\\U" + code.toString(16).padStart(8, "0");
    });
    return out + (cut ? "\u2026" + quote : quote);
  }

  /* Any value for a message, as Python shows it (None, True, False for null and booleans). */
  function show(value) {
    if (typeof value === "string") return quoteInput(value);
    if (value === null || value === undefined) return "None";
    if (typeof value === "boolean") return value ? "True" : "False";
    return String(value);
  }

  var SIGN = "[+\\-\u2212]";
  var DECIMAL_RE = new RegExp("^(" + SIGN + "?)([0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE](" + SIGN + "?[0-9]+))?$");
  var FRACTION_RE = new RegExp(
    "^(" + SIGN + "?[0-9]+)[" + SPACES + "]*/[" + SPACES + "]*(" + SIGN + "?[0-9]+)$"
  );
  var NAN_WORDS = ["nan", "+nan", "-nan"];
  var INF_WORDS = ["inf", "+inf", "-inf", "infinity", "+infinity", "-infinity"];

  function InputError(message) {
    this.name = "InputError";
    this.message = message;
  }
  InputError.prototype = Object.create(Error.prototype);

  /*
   * MESSAGES[key] with its {fields} filled in from the limits and `values`: what
   * trinormal.validation.message does with str.format (the templates use plain {name}s only).
   */
  function message(key, values) {
    var template = MESSAGES[key];
    if (typeof template !== "string") throw new Error("no message template " + key);
    return template.replace(/\{(\w+)\}/g, function (whole, field) {
      if (values && Object.prototype.hasOwnProperty.call(values, field)) return String(values[field]);
      if (Object.prototype.hasOwnProperty.call(LIMITS, field)) return String(LIMITS[field]);
      throw new Error("message " + key + " needs a value for {" + field + "}");
    });
  }

  function refuse(key, values) {
    return new InputError(message(key, values));
  }

  function tooLarge(name, shown) {
    return refuse("too_large", { subject: shown === undefined ? name : name + " = " + shown });
  }

  function checkRatio(n, d, name, shown) {
    if (-LIMIT < n && n < LIMIT && d < LIMIT) return [n, d];
    var g = gcd(n, d);
    if (g > 1n) {
      n /= g;
      d /= g;
      if (-LIMIT < n && n < LIMIT && d < LIMIT) return [n, d];
    }
    throw tooLarge(name, shown);
  }

  /* sign digits e exp, exactly, its size checked before converting: validation._decimal. */
  function readDecimal(sign, digits, exp, name, shown) {
    var shift = 0;
    if (digits.indexOf(".") >= 0) {
      var parts = digits.split(".");
      shift = -parts[1].length;
      digits = parts[0] + parts[1];
    }
    var sig = digits.replace(/^0+/, "");
    if (!sig) return [0n, 1n];
    if (exp) {
      exp = exp.replace(/\u2212/g, "-");
      if (exp.replace(/^[+-]*0*/, "").length > 6) throw tooLarge(name, shown);
      shift += parseInt(exp, 10);
    }
    var stripped = sig.replace(/0+$/, "");
    var e = shift + sig.length - stripped.length;
    sig = stripped;
    var n, d;
    if (e >= 0) {
      if (sig.length + e > MAX_DIGITS) throw tooLarge(name, shown);
      n = BigInt(sig) * pow10(e);
      d = 1n;
    } else {
      if (-e > LIMIT_BITS || sig.length > MAX_DIGITS - e) throw tooLarge(name, shown);
      n = BigInt(sig);
      d = pow10(-e);
    }
    return checkRatio(sign === "-" || sign === "\u2212" ? -n : n, d, name, shown);
  }

  /* Read a coordinate exactly, as trinormal.validation.check_coordinate reads a string. */
  function parseCoordinate(text, name) {
    text = String(text);
    var length = Array.from(text).length;
    if (length > MAX_TEXT_LENGTH) throw refuse("too_long", { name: name, length: length });
    var s = text.replace(STRIP_RE, "");
    if (!s) throw refuse("empty", { name: name });
    var shown = quoteInput(s);
    var low = s.toLowerCase().replace(/\u2212/g, "-");
    if (NAN_WORDS.indexOf(low) >= 0) throw refuse("nan", { name: name });
    if (INF_WORDS.indexOf(low) >= 0) throw refuse("infinite", { name: name });
    var m = DECIMAL_RE.exec(s);
    if (m) return readDecimal(m[1], m[2], m[3], name, shown);
    m = FRACTION_RE.exec(s);
    if (m) {
      var num = BigInt(m[1].replace(/\u2212/g, "-"));
      var den = BigInt(m[2].replace(/\u2212/g, "-"));
      if (den === 0n) throw refuse("divides_by_zero", { name: name, shown: shown });
      return den > 0n ? checkRatio(num, den, name, shown) : checkRatio(-num, -den, name, shown);
    }
    throw refuse("not_a_number", { name: name, shown: shown });
  }

  /* One common denominator for the nine coordinates, within the limit: validation.check_common. */
  function checkCommon(coords) {
    var tooLargeTogether = function (i) {
      return refuse("too_large_together", { name: "ABC"[Math.floor(i / 3)] + "." + AXES[i % 3] });
    };
    var D = 1n;
    for (var i = 0; i < coords.length; i++) {
      D = lcm(D, coords[i][1]);
      if (D >= COMMON_LIMIT) throw tooLargeTogether(i);
    }
    var ints = coords.map(function (r) {
      return r[0] * (D / r[1]);
    });
    var worst = 0;
    var over = false;
    ints.forEach(function (x, k) {
      if (abs(x) > abs(ints[worst])) worst = k;
      if (abs(x) >= COMMON_LIMIT) over = true;
    });
    if (over) throw tooLargeTogether(worst);
    return { ints: ints, D: D };
  }

  /*
   * A precision as trinormal.validation.check_precision reads it (a number or typed text).
   * `max`, when given, lowers the largest precision allowed (a view that shows fewer digits).
   */
  function checkPrecision(value, name, max) {
    var range = { name: name || "precision" };
    if (max !== undefined && max < MAX_PRECISION) range.max_precision = max;
    var p;
    if (typeof value === "string") {
      var text = value.replace(STRIP_RE, "");
      if (!/^[0-9]+$/.test(text)) throw refuse("precision_not_whole", Object.assign({ shown: show(value) }, range));
      if (text.length > 6) throw refuse("precision_range", Object.assign({ shown: show(text) }, range));
      p = parseInt(text, 10);
    } else if (typeof value === "number" && Number.isInteger(value)) {
      p = value;
    } else {
      throw refuse("precision_not_whole", Object.assign({ shown: show(value) }, range));
    }
    var top = range.max_precision === undefined ? MAX_PRECISION : range.max_precision;
    if (p < MIN_PRECISION || p > top) throw refuse("precision_range", Object.assign({ shown: p }, range));
    return p;
  }

  function checkWinding(value, name) {
    if (value === "ABC" || value === "ACB") return value;
    throw refuse("winding", { name: name || "winding", shown: show(value) });
  }

  // ------------------------------------------------------------------ formatting

  function roundSqrt(num, den, k) {
    var n2, d2;
    if (k >= 0) {
      n2 = num * pow10(2 * k);
      d2 = den;
    } else {
      n2 = num;
      d2 = den * pow10(-2 * k);
    }
    var m = isqrt(n2 / d2);
    var t = 2n * m + 1n;
    if (4n * n2 >= t * t * d2) m += 1n;
    return m;
  }

  function decimalExponent(num, den) {
    var e = Math.floor(((bitLength(num) - bitLength(den)) * Math.log10(2)) / 2);
    function atLeast(e) {
      return e >= 0 ? num >= den * 100n ** BigInt(e) : num * 100n ** BigInt(-e) >= den;
    }
    while (!atLeast(e)) e -= 1;
    while (atLeast(e + 1)) e += 1;
    return e;
  }

  function trimDigits(digits) {
    if (digits.indexOf(".") >= 0) digits = digits.replace(/0+$/, "").replace(/\.$/, "");
    return digits;
  }

  /* +-sqrt(num/den) with `precision` decimals: trinormal.display.format_surd. */
  function formatSurd(negative, num, den, precision, trim) {
    var p = precision;
    if (num === 0n) return trim || p === 0 ? "0" : "0." + "0".repeat(p);
    // scientific only where fixed-point would show zero (below half of 10**-p), or at 1e15 and above
    var small = 4n * num * 100n ** BigInt(p) < den;
    var large = num >= den * 100n ** BigInt(SCI_ABOVE_LOG10);
    var sign = negative ? "-" : "";
    var s;
    if (!(small || large)) {
      s = roundSqrt(num, den, p).toString().padStart(p + 1, "0");
      var body = p === 0 ? s : s.slice(0, -p) + "." + s.slice(-p);
      return sign + (trim ? trimDigits(body) : body);
    }
    var e = decimalExponent(num, den);
    var m = roundSqrt(num, den, p - e);
    if (m >= pow10(p + 1)) {
      e += 1;
      m = roundSqrt(num, den, p - e);
    }
    s = m.toString();
    var mantissa = p === 0 ? s : s[0] + "." + s.slice(1);
    if (trim) mantissa = trimDigits(mantissa);
    return sign + mantissa + "e" + (e < 0 ? "-" : "+") + String(Math.abs(e)).padStart(2, "0");
  }

  function formatRatio(n, d, precision) {
    return formatSurd(n < 0n, n * n, d * d, precision, false);
  }

  function joinVector(parts) {
    return "(" + parts.join(", ") + ")";
  }

  function planeEquation(parts, offset) {
    var out = parts[0] + "x";
    for (var i = 1; i < 3; i++) {
      var text = parts[i];
      var axis = AXES[i];
      if (text[0] === "-") out += " - " + text.slice(1) + axis;
      else out += " + " + text + axis;
    }
    return out + " = " + offset;
  }

  // ------------------------------------------------------------------ the normal

  function sameInts(ints, i, j) {
    return ints[i] === ints[j] && ints[i + 1] === ints[j + 1] && ints[i + 2] === ints[j + 2];
  }

  /* VERDICTS[key] with its {fields} filled in, as str.format does in trinormal/core.py. */
  function verdict(key, values) {
    return VERDICTS[key].replace(/\{(\w+)\}/g, function (whole, field) {
      return String(values[field]);
    });
  }

  /* L^2, the squared length of the longest side, from the edges U and V (V - U is the third). */
  function longestSquared(u, v) {
    var t = [v[0] - u[0], v[1] - u[1], v[2] - u[2]];
    var best = 0n;
    [u, v, t].forEach(function (e) {
      var q = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
      if (q > best) best = q;
    });
    return best;
  }

  function reason(ints, zeroNormal) {
    var ab = sameInts(ints, 0, 3);
    var ac = sameInts(ints, 0, 6);
    if (ab && ac) return verdict("same_point", {});
    if (ab) return verdict("coincide", { names: "A and B" });
    if (ac) return verdict("coincide", { names: "A and C" });
    if (sameInts(ints, 3, 6)) return verdict("coincide", { names: "B and C" });
    if (zeroNormal) return verdict("collinear", { where: "" });
    return verdict("too_thin", {});
  }

  /*
   * compute(a, b, c, winding, precision): a, b, c are arrays of 3 strings.
   * Returns {ok: true, degenerate, status, out: {u, v, normal, magnitude, area, unit_normal,
   * plane}, chart: [x, y, z] as numbers in [-1, 1] relative to the largest |component|,
   * floats: {points: {A, B, C}, u, v, normal, unit_normal (null when degenerate)} as
   * numbers for drawing}
   * or {ok: false, status: message, field: "B.y"} for unreadable input.
   */
  function compute(a, b, c, winding, precision) {
    var coords = [];
    var points = [a, b, c];
    for (var v = 0; v < 3; v++) {
      for (var k = 0; k < 3; k++) {
        var name = "ABC"[v] + "." + AXES[k];
        try {
          coords.push(parseCoordinate(points[v][k], name));
        } catch (err) {
          if (err instanceof InputError) return { ok: false, status: err.message, field: name };
          throw err;
        }
      }
    }
    var p, common;
    try {
      checkWinding(winding);
    } catch (err) {
      return { ok: false, status: err.message, field: "winding" };
    }
    try {
      p = checkPrecision(precision);
    } catch (err) {
      return { ok: false, status: err.message, field: "precision" };
    }
    try {
      common = checkCommon(coords);
    } catch (err) {
      return { ok: false, status: err.message, field: err.message.split(" ", 1)[0] };
    }
    var D = common.D;
    var ints = common.ints;
    var P = winding === "ABC" ? 3 : 6;
    var Q = winding === "ABC" ? 6 : 3;
    var u = [ints[P] - ints[0], ints[P + 1] - ints[1], ints[P + 2] - ints[2]];
    var w = [ints[Q] - ints[0], ints[Q + 1] - ints[1], ints[Q + 2] - ints[2]];
    var n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    var S = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    var tn = TOL[0];
    var td = TOL[1];
    // degenerate when |N| <= tol * L^2, L the longest side (trinormal/tolerances.py), squared
    var L2 = longestSquared(u, w);
    var degenerate = S * td * td <= tn * tn * L2 * L2;
    var D2 = D * D;
    var fmt = function (x, d) {
      return formatRatio(x, d, p);
    };
    var out = {
      u: joinVector(u.map(function (x) { return fmt(x, D); })),
      v: joinVector(w.map(function (x) { return fmt(x, D); })),
      normal: joinVector(n.map(function (x) { return fmt(x, D2); })),
      magnitude: formatSurd(false, S, D2 * D2, p, false),
      area: formatSurd(false, S, 4n * D2 * D2, p, false),
    };
    var status;
    if (degenerate) {
      out.unit_normal = "undefined";
      out.plane = "undefined";
      status = verdict("degenerate", { reason: reason(ints, S === 0n) });
    } else {
      var unit = n.map(function (x) {
        return formatSurd(x < 0n, x * x, S, p, false);
      });
      var dot = n[0] * ints[0] + n[1] * ints[1] + n[2] * ints[2];
      out.unit_normal = joinVector(unit);
      out.plane = planeEquation(unit, formatSurd(dot < 0n, dot * dot, S * D2, p, false));
      status = verdict("proper", {});
    }
    var big = n.reduce(function (m, x) {
      return abs(x) > m ? abs(x) : m;
    }, 0n);
    var chart = n.map(function (x) {
      return big === 0n ? 0 : Number((x * 1000000n) / big) / 1000000;
    });
    // floats for drawing (the 3D view): never used for a displayed digit
    var toFloats = function (xs, d) {
      return xs.map(function (x) {
        return toNumber(x, d);
      });
    };
    var floats = {
      points: { A: toFloats(ints.slice(0, 3), D), B: toFloats(ints.slice(3, 6), D), C: toFloats(ints.slice(6, 9), D) },
      u: toFloats(u, D),
      v: toFloats(w, D),
      normal: toFloats(n, D2),
      unit_normal: null,
    };
    if (!degenerate) {
      var root = isqrt(S * 4n ** 60n); // |N| * 2^60, so the unit normal keeps ~60 bits
      floats.unit_normal = n.map(function (x) {
        return toNumber(x * 2n ** 60n, root);
      });
    }
    return { ok: true, degenerate: degenerate, status: status, out: out, chart: chart, floats: floats };
  }

  return {
    compute: compute,
    parseCoordinate: parseCoordinate,
    checkPrecision: checkPrecision,
    checkWinding: checkWinding,
    quoteInput: quoteInput,
    message: message,
    LIMITS: Object.freeze(Object.assign({}, LIMITS)),
    formatSurd: formatSurd,
    doubleRatio: doubleRatio,
    isqrt: isqrt,
    InputError: InputError,
  };
});
