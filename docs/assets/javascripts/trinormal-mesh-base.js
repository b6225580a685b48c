/*
 * trinormal's mesh check in the browser, part 1 of 7: what every other part uses. The page
 * reads an OBJ, STL or PLY file, reports what is wrong with it, fixes its winding and writes
 * the repaired file, as trinormal.mesh does in Python, with these scripts loaded in order:
 *
 *   trinormal-mesh-base.js   the package's messages and limits, errors, Python's text rules
 *   trinormal-mesh-read.js   the OBJ, STL and PLY readers (trinormal/mesh/io.py)
 *   trinormal-mesh-weld.js   which vertices are one corner (welding.py)
 *   trinormal-mesh-shells.js volumes, cavities, open pieces closed over holes (shells.py)
 *   trinormal-mesh-check.js  the report (report.py, topology.py, repair.py, normals.py)
 *   trinormal-mesh-write.js  the winding fix and the writers (repair.py, io.py)
 *   trinormal-mesh-print.js  the report for printing (printing.py): holes, area, volume, size
 *
 * The messages, limits and the degeneracy tolerance are not written here: they come from the
 * package through the constants the site build writes (TRINORMAL_CONSTANTS.mesh), which must
 * load first. tests/test_mesh_parity.py runs these scripts in Node on a corpus of files and
 * requires Python's report, sentences, repaired bytes and error messages, file by file.
 *
 * Plain JavaScript, no dependencies. Each part runs as a plain script in one shared scope,
 * `self`: in a page (script tags), in the Web Worker (mesh-worker.js's importScripts) and in
 * Node (tests/mesh_parity_check.js runs each file in turn, all given one object as `self`).
 * This part sets self.TrinormalMesh; each later part is one call, TrinormalMesh.part(name,
 * after, factory), which checks that part `after` is loaded and replaces self.TrinormalMesh
 * with a copy that has what the factory returns too. Functions the later parts share, but the
 * page does not use, are under `internal`.
 */
self.TrinormalMesh = (function (root, constants) {
  "use strict";

  /** The sentence for a script loaded before what it needs. */
  function loadOrder(script, needed) {
    return script + " needs " + needed + " to be loaded first";
  }

  if (!constants || !constants.mesh) {
    throw new Error(loadOrder("trinormal-mesh-base.js", "TRINORMAL_CONSTANTS.mesh (assets/javascripts/trinormal-constants.js, written by the site build)"));
  }
  var MESH = constants.mesh;
  var MESSAGES = MESH.messages;
  var LIMITS = MESH.limits;

  // ------------------------------------------------------------------ messages and errors

  /** A file that cannot be read as a mesh: `message` is the sentence the page shows. */
  function MeshError(message) {
    this.name = "MeshError";
    this.message = message;
  }
  MeshError.prototype = Object.create(Error.prototype);
  MeshError.prototype.constructor = MeshError;

  /**
   * A template's {placeholders} filled in from `values` (left as they are when missing); a
   * (one, many) pair of templates is chosen by values.n.
   */
  function fill(template, values) {
    if (Array.isArray(template)) template = values && values.n === 1 ? template[0] : template[1];
    return template.replace(/\{(\w+)\}/g, function (m, name) {
      return values && values[name] !== undefined ? String(values[name]) : m;
    });
  }

  /** One of the package's messages, its {placeholders} filled in. */
  function message(key, values) {
    var template = MESSAGES[key];
    if (template === undefined) throw new Error("no mesh message " + key);
    return fill(template, values);
  }

  /** A whole number with its thousands set apart by commas, as Python's "{:,}" writes it. */
  function grouped(n) {
    return String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ",");
  }

  /** A file size as the page writes it: MB (10^6 bytes) rounded up to a tenth (Python's file_size). */
  function fileSize(n) {
    var tenths = Math.ceil(n / 1e5);
    return Math.floor(tenths / 10) + (tenths % 10 === 0 ? "" : "." + (tenths % 10)) + " MB";
  }

  /** The page's own limit on a file's size: its message, or null when the file is within it. */
  function sizeProblem(name, size) {
    if (size <= LIMITS.max_bytes) return null;
    return message("too_large", { name: name, size: fileSize(size), max: fileSize(LIMITS.max_bytes) });
  }

  function fail(key, values) {
    throw new MeshError(message(key, values));
  }

  /** The page's limit on the number of faces: throws its message when `count` is over it. */
  function checkFaceCount(name, count) {
    if (count > LIMITS.max_faces) fail("too_many_faces", { name: name, count: grouped(count), max: grouped(LIMITS.max_faces) });
  }

  /**
   * A file that cannot be read: "NAME[, line N]: REASON", the wording of Python's
   * MeshFileError, from the package's templates.
   */
  function fileError(name, line, key, values) {
    var reason = message(key, values);
    var where = line === null || line === undefined ? name : message("at_line", { name: name, line: line });
    throw new MeshError(where + ": " + reason);
  }

  function plural(n, one, many) {
    return n === 1 ? one : many;
  }

  // ------------------------------------------------------------------ growable typed arrays

  function Growable(Type, capacity) {
    this.Type = Type;
    this.data = new Type(Math.max(16, capacity || 0));
    this.length = 0;
  }
  Growable.prototype.push = function (x) {
    if (this.length === this.data.length) {
      var next = new this.Type(2 * this.length);
      next.set(this.data);
      this.data = next;
    }
    this.data[this.length++] = x;
  };
  Growable.prototype.array = function () {
    return this.data.slice(0, this.length);
  };

  // ------------------------------------------------------------------ numbers and vectors

  var f64 = new Float64Array(1);
  var u32 = new Uint32Array(f64.buffer);

  /** The exponent e with |x| = m * 2**e, m in [0.5, 1) (numpy.frexp's), 0 for x == 0. */
  function frexpExp(x) {
    if (x === 0 || !Number.isFinite(x)) return 0;
    f64[0] = x;
    var e = (u32[1] >>> 20) & 0x7ff;
    if (e === 0) {
      f64[0] = x * 18446744073709551616; // 2**64: a subnormal made normal, exactly
      e = ((u32[1] >>> 20) & 0x7ff) - 64;
    }
    return e - 1022;
  }

  /** 2**e for -1074 <= e <= 1023, built from its bits (exact). */
  function pow2(e) {
    u32[0] = 0;
    u32[1] = 0;
    if (e >= -1022) u32[1] = (e + 1023) << 20;
    else if (e >= -1042) u32[1] = 1 << (e + 1074 - 32);
    else u32[0] = 1 << (e + 1074);
    return f64[0];
  }

  function sub(p, q) {
    return [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
  }

  function cross(p, q) {
    return [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
  }

  // ------------------------------------------------------------------ union-find

  /** 0, 1, ..., n - 1: every element its own set, for `find` and `union`. */
  function identity(n) {
    var out = new Int32Array(n);
    for (var i = 0; i < n; i++) out[i] = i;
    return out;
  }

  function find(parent, x) {
    while (parent[x] !== x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }

  /** Join the sets of a and b; the larger root goes under the smaller. */
  function union(parent, a, b) {
    a = find(parent, a);
    b = find(parent, b);
    if (a < b) parent[b] = a;
    else if (b < a) parent[a] = b;
  }

  // ------------------------------------------------------------------ open-addressing tables

  /** murmur3's finaliser: every bit of h reaches the low bits used as a table slot. */
  function fmix(h) {
    h ^= h >>> 16;
    h = Math.imul(h, 0x85ebca6b);
    h ^= h >>> 13;
    h = Math.imul(h, 0xc2b2ae35);
    return h ^ (h >>> 16);
  }

  /**
   * An empty table for up to n keys: `slots` (-1 where free), at least twice n and a power of
   * two, so `hash & mask` is a slot and a probe moves on with `(slot + 1) & mask`.
   */
  function slotTable(n) {
    var size = 1;
    while (size < n * 2) size <<= 1;
    return { slots: new Int32Array(size).fill(-1), mask: size - 1 };
  }

  // ------------------------------------------------------------------ Python's text rules

  // characters Python's repr() escapes (str.isprintable() is false for them)
  var NOT_PRINTABLE = /[\p{Cc}\p{Cf}\p{Cs}\p{Co}\p{Cn}\p{Zl}\p{Zp}\p{Zs}]/u;
  var ESCAPES = { "\\": "\\\\", "\n": "\\n", "\r": "\\r", "\t": "\\t" };

  function hex(code, width) {
    return ("0000000" + code.toString(16)).slice(-width);
  }

  /** Python's repr() of a short token (cut at 40 characters), as the readers quote it. */
  function show(tok) {
    var chars = Array.from(tok); // code points, as Python counts characters
    var s = chars.length <= 40 ? tok : chars.slice(0, 39).join("") + "\u2026";
    var quote = s.indexOf("'") >= 0 && s.indexOf('"') < 0 ? '"' : "'";
    var out = "";
    Array.from(s).forEach(function (ch) {
      var code = ch.codePointAt(0);
      if (ESCAPES[ch]) out += ESCAPES[ch];
      else if (ch === quote) out += "\\" + ch;
      else if (code !== 32 && NOT_PRINTABLE.test(ch)) {
        out += code < 0x100 ? "\\x" + hex(code, 2) : code < 0x10000 ? "\\u" + hex(code, 4) : "\\U" + hex(code, 8);
      } else out += ch;
    });
    return quote + out + quote;
  }

  // Python's str.splitlines() and str.split(): the same line numbers and the same tokens.
  var LINE_BREAK = /\r\n|[\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029]/;
  var SPACE = /[\t\n\v\f\r \x1c-\x1f\x85\xa0\u1680\u2000-\u200a\u2028\u2029\u202f\u205f\u3000]+/;

  function splitlines(text) {
    var lines = text.split(LINE_BREAK);
    if (lines.length && lines[lines.length - 1] === "") lines.pop();
    return lines;
  }

  function tokens(line) {
    var t = line.split(SPACE);
    if (t.length && t[0] === "") t.shift();
    if (t.length && t[t.length - 1] === "") t.pop();
    return t;
  }

  /**
   * OBJ's statements, fed its physical lines in order (the reader and the writer's stored
   * normals): a line ending in a backslash goes on in the next one and "#" starts a comment.
   * Returns a statement's tokens, or null while the statement goes on.
   */
  function objStatements() {
    var pending = "";
    return function (raw) {
      if (raw.charAt(raw.length - 1) === "\\") {
        pending += raw.slice(0, -1) + " ";
        return null;
      }
      var line = pending + raw;
      pending = "";
      var hash = line.indexOf("#");
      return tokens(hash < 0 ? line : line.slice(0, hash));
    };
  }

  var DIGIT = /\p{Nd}/u;

  /**
   * The token with every Unicode decimal digit written as its ASCII digit, as Python's float()
   * and int() read it first ("\u0661" is 1). Unicode gives decimal digits in runs of ten, 0 to 9,
   * so a digit's value is its distance from the start of its run.
   */
  function asciiDigits(tok) {
    if (!/[^\x00-\x7f]/.test(tok)) return tok;
    var out = "";
    Array.from(tok).forEach(function (ch) {
      var code = ch.codePointAt(0);
      if (code < 0x80 || !DIGIT.test(ch)) {
        out += ch;
        return;
      }
      var start = code;
      while (DIGIT.test(String.fromCodePoint(start - 1))) start--;
      out += String((code - start) % 10);
    });
    return out;
  }

  var FLOAT = /^[+-]?(?:\d(?:_?\d)*(?:\.(?:\d(?:_?\d)*)?)?|\.\d(?:_?\d)*)(?:[eE][+-]?\d(?:_?\d)*)?$/;
  var SPECIAL = /^[+-]?(?:inf|infinity|nan)$/i;
  var INT = /^[+-]?\d(?:_?\d)*$/;

  /** Python's float(token), or undefined when float() would raise. */
  function pyFloat(tok) {
    var t = asciiDigits(tok);
    if (FLOAT.test(t)) return Number(t.replace(/_/g, ""));
    if (SPECIAL.test(t)) return /nan/i.test(t) ? NaN : t.charAt(0) === "-" ? -Infinity : Infinity;
    return undefined;
  }

  /**
   * Python's int(token), or undefined when int() would raise: a number, or a BigInt when it is
   * too large to be exact as a number (a message then quotes every digit, as Python does).
   */
  function pyInt(tok) {
    var t = asciiDigits(tok);
    if (!INT.test(t)) return undefined;
    var digits = t.replace(/_/g, "");
    var n = parseInt(digits, 10);
    return Number.isSafeInteger(n) ? n : BigInt(digits);
  }

  /** A coordinate: Python's float(token), which must be finite. */
  function number(tok, name, line) {
    var x = pyFloat(tok);
    if (x === undefined) fileError(name, line, "not_a_number", { token: show(tok) });
    if (!Number.isFinite(x)) fileError(name, line, "not_finite", { token: show(tok) });
    return x;
  }

  var utf8 = typeof TextDecoder !== "undefined" ? new TextDecoder("utf-8", { fatal: true }) : null;

  /** Bytes as Latin-1 text (each byte one character; TextDecoder's "latin1" is Windows-1252). */
  function latin1(bytes) {
    var parts = [];
    for (var i = 0; i < bytes.length; i += 8192) {
      parts.push(String.fromCharCode.apply(null, bytes.subarray(i, Math.min(i + 8192, bytes.length))));
    }
    return parts.join("");
  }

  /** The file as text (UTF-8, else Latin-1); NUL bytes mean it is binary. */
  function text(bytes, name, what) {
    var nul = bytes.indexOf(0);
    if (nul >= 0) {
      var line = 1;
      for (var i = 0; i < nul; i++) if (bytes[i] === 10) line++;
      fileError(name, line, "binary_data", { what: what });
    }
    try {
      return utf8.decode(bytes); // TextDecoder drops a leading byte-order mark, as Python does
    } catch (err) {
      return latin1(bytes);
    }
  }

  /**
   * Add the part trinormal-mesh-`name`.js, loaded after trinormal-mesh-`after`.js: `factory`
   * takes TrinormalMesh as the parts before made it and returns what this part adds.
   */
  function part(name, after, factory) {
    var mesh = root.TrinormalMesh;
    if (mesh.parts.indexOf(after) < 0) {
      throw new Error(loadOrder("trinormal-mesh-" + name + ".js", "trinormal-mesh-" + after + ".js"));
    }
    root.TrinormalMesh = Object.assign({}, mesh, factory(mesh), { parts: mesh.parts.concat(name) });
  }

  return {
    MeshError: MeshError,
    LIMITS: LIMITS,
    message: message,
    grouped: grouped,
    fileSize: fileSize,
    sizeProblem: sizeProblem,
    internal: {
      MESH: MESH,
      fill: fill,
      fail: fail,
      checkFaceCount: checkFaceCount,
      fileError: fileError,
      plural: plural,
      Growable: Growable,
      frexpExp: frexpExp,
      pow2: pow2,
      sub: sub,
      cross: cross,
      identity: identity,
      find: find,
      union: union,
      fmix: fmix,
      slotTable: slotTable,
      show: show,
      splitlines: splitlines,
      tokens: tokens,
      objStatements: objStatements,
      pyFloat: pyFloat,
      pyInt: pyInt,
      number: number,
      latin1: latin1,
      text: text,
    },
    parts: ["base"],
    part: part,
  };
})(self, self.TRINORMAL_CONSTANTS);
