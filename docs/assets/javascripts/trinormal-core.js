/*
 * trinormal in the browser: the exact normal of a triangle, formatted exactly as the
 * Python package formats it (trinormal/core.py and trinormal/display.py).
 *
 * Every coordinate is read as an exact rational (BigInt numerator and denominator),
 * the cross product runs on integers, and every displayed number is +-sqrt(num/den)
 * rounded half away from zero from exact integer arithmetic. No floating point is
 * involved in any displayed digit, so the strings match Python byte for byte.
 *
 * Plain JavaScript, no dependencies. Works in the browser (window.TrinormalCore)
 * and in Node (module.exports).
 */
(function (root, factory) {
  "use strict";
  var api = factory();
  if (typeof module === "object" && module.exports) {
    module.exports = api;
  } else {
    root.TrinormalCore = api;
  }
})(typeof self !== "undefined" ? self : this, function () {
  "use strict";

  var MAX_DECIMAL_EXPONENT = 9999;
  var SCI_ABOVE_LOG10 = 15;
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

  var TOL = doubleRatio(1e-12);

  // ------------------------------------------------------------------ parsing

  /* Python's repr() of a str, for messages like  A.x = 'abc' is not a number. */
  function pyRepr(s) {
    var quote = s.indexOf("'") >= 0 && s.indexOf('"') < 0 ? '"' : "'";
    var out = quote;
    for (var i = 0; i < s.length; i++) {
      var ch = s[i];
      var code = s.charCodeAt(i);
      if (ch === "\\") out += "\\\\";
      else if (ch === quote) out += "\\" + ch;
      else if (ch === "\n") out += "\\n";
      else if (ch === "\r") out += "\\r";
      else if (ch === "\t") out += "\\t";
      else if (code < 0x20 || (code >= 0x7f && code < 0xa0)) {
        out += "\\x" + code.toString(16).padStart(2, "0");
      } else out += ch;
    }
    return out + quote;
  }

  var DECIMAL_RE = /^([+-]?)(\d+(?:\.\d*)?|\.\d+)(?:[eE]([+-]?\d+))?$/;
  var FRACTION_RE = /^([+-]?\d+)\s*\/\s*([+-]?\d+)$/;
  var NAN_WORDS = ["nan", "+nan", "-nan"];
  var INF_WORDS = ["inf", "+inf", "-inf", "infinity", "+infinity", "-infinity"];

  function InputError(message) {
    this.name = "InputError";
    this.message = message;
  }
  InputError.prototype = Object.create(Error.prototype);

  /* Read a coordinate exactly, as trinormal.core._parse_string does: [n, d] with d > 0. */
  function parseCoordinate(text, name) {
    var s = String(text).trim();
    if (!s) throw new InputError(name + " is empty");
    var low = s.toLowerCase();
    if (NAN_WORDS.indexOf(low) >= 0) throw new InputError(name + " is NaN");
    if (INF_WORDS.indexOf(low) >= 0) throw new InputError(name + " is infinite");
    var m = DECIMAL_RE.exec(s);
    if (m) {
      var sign = m[1];
      var digits = m[2];
      var e = m[3] ? parseInt(m[3], 10) : 0;
      if (digits.indexOf(".") >= 0) {
        var parts = digits.split(".");
        e -= parts[1].length;
        digits = parts[0] + parts[1];
      }
      if (Math.abs(e) > MAX_DECIMAL_EXPONENT || digits.length > 4000) {
        throw new InputError(name + " = " + pyRepr(s) + " is too large a number to read exactly");
      }
      var n = BigInt(digits) * (sign === "-" ? -1n : 1n);
      return e >= 0 ? [n * pow10(e), 1n] : [n, pow10(-e)];
    }
    m = FRACTION_RE.exec(s);
    if (m) {
      if (s.length > 4000) {
        throw new InputError(name + " = " + pyRepr(s) + " is too large a number to read exactly");
      }
      var num = BigInt(m[1]);
      var den = BigInt(m[2]);
      if (den === 0n) throw new InputError(name + " = " + pyRepr(s) + " divides by zero");
      return den > 0n ? [num, den] : [-num, -den];
    }
    throw new InputError(
      name + " = " + pyRepr(s) + " is not a number (use a decimal like 0.1 or a fraction like 1/3)"
    );
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
    var small = num * 100n ** BigInt(p) < den;
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

  function reason(ints, zeroNormal) {
    var ab = sameInts(ints, 0, 3);
    var ac = sameInts(ints, 0, 6);
    if (ab && ac) return "A, B and C are the same point.";
    if (ab) return "A and B coincide, so the triangle has no area.";
    if (ac) return "A and C coincide, so the triangle has no area.";
    if (sameInts(ints, 3, 6)) return "B and C coincide, so the triangle has no area.";
    if (zeroNormal) return "A, B and C are collinear (they lie on one line), so the area is zero.";
    return (
      "the angle between the edges is too small to trust: " +
      "the sine of it is at most the tolerance."
    );
  }

  /*
   * compute(a, b, c, winding, precision): a, b, c are arrays of 3 strings.
   * Returns {ok: true, degenerate, status, out: {u, v, normal, magnitude, area, unit_normal,
   * plane}, chart: [x, y, z] as numbers in [-1, 1] relative to the largest |component|}
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
    if (winding !== "ABC" && winding !== "ACB") {
      return { ok: false, status: "winding must be 'ABC' or 'ACB', got " + pyRepr(String(winding)), field: "winding" };
    }
    var p = Number(precision);
    if (!Number.isInteger(p) || p < 0 || p > 15) {
      return { ok: false, status: "precision must be a whole number from 0 to 10", field: "precision" };
    }
    var D = 1n;
    coords.forEach(function (r) {
      D = lcm(D, r[1]);
    });
    var ints = coords.map(function (r) {
      return r[0] * (D / r[1]);
    });
    var P = winding === "ABC" ? 3 : 6;
    var Q = winding === "ABC" ? 6 : 3;
    var u = [ints[P] - ints[0], ints[P + 1] - ints[1], ints[P + 2] - ints[2]];
    var w = [ints[Q] - ints[0], ints[Q + 1] - ints[1], ints[Q + 2] - ints[2]];
    var n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    var S = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    var uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    var ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    var tn = TOL[0];
    var td = TOL[1];
    var degenerate = S * td * td <= tn * tn * uu * ww;
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
      status = "Degenerate: " + reason(ints, S === 0n) + " No unit normal exists.";
    } else {
      var unit = n.map(function (x) {
        return formatSurd(x < 0n, x * x, S, p, false);
      });
      var dot = n[0] * ints[0] + n[1] * ints[1] + n[2] * ints[2];
      out.unit_normal = joinVector(unit);
      out.plane = planeEquation(unit, formatSurd(dot < 0n, dot * dot, S * D2, p, false));
      status = "A proper triangle: the unit normal is defined.";
    }
    var big = n.reduce(function (m, x) {
      return abs(x) > m ? abs(x) : m;
    }, 0n);
    var chart = n.map(function (x) {
      return big === 0n ? 0 : Number((x * 1000000n) / big) / 1000000;
    });
    return { ok: true, degenerate: degenerate, status: status, out: out, chart: chart };
  }

  return {
    compute: compute,
    parseCoordinate: parseCoordinate,
    formatSurd: formatSurd,
    isqrt: isqrt,
    InputError: InputError,
    OUTPUT_KEYS: ["u", "v", "normal", "magnitude", "area", "unit_normal", "plane"],
  };
});
