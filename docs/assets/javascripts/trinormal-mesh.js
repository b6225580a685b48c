/*
 * trinormal's mesh check in the browser: read an OBJ, STL or PLY file, report what is wrong
 * with it, fix its winding and write the repaired file, as trinormal.mesh does in Python.
 *
 * The report has the keys and the numbers of Python's `trinormal.mesh.check(v, f).to_dict()`;
 * the browser tests run this file on every mesh of tests/data/ and compare. The messages, limits
 * and the degeneracy tolerance are not written here: they come from the package through the
 * constants the site build writes (TRINORMAL_CONSTANTS.mesh), which must load first.
 *
 * Plain JavaScript, no dependencies, typed arrays throughout (a million faces in a second or
 * two). It runs in a page, in a Web Worker (mesh-worker.js) and in Node: in a page or worker it
 * defines self.TrinormalMesh; in Node, module.exports is a function of the constants.
 */
(function (root, factory) {
  "use strict";
  if (typeof module === "object" && module.exports) {
    module.exports = factory;
  } else {
    root.TrinormalMesh = factory(root.TRINORMAL_CONSTANTS);
  }
})(typeof self !== "undefined" ? self : this, function (constants) {
  "use strict";

  if (!constants || !constants.mesh) {
    throw new Error(
      "trinormal-mesh.js needs TRINORMAL_CONSTANTS.mesh (assets/javascripts/trinormal-constants.js, " +
        "written by the site build) to be loaded first"
    );
  }
  var MESH = constants.mesh;
  var MESSAGES = MESH.messages;
  var LIMITS = MESH.limits;
  var TOL = MESH.tol;

  // ------------------------------------------------------------------ errors

  /** A file that cannot be read as a mesh: `message` is the sentence the page shows. */
  function MeshError(message) {
    this.name = "MeshError";
    this.message = message;
  }
  MeshError.prototype = Object.create(Error.prototype);
  MeshError.prototype.constructor = MeshError;

  /** One of the package's messages, its {placeholders} filled in. */
  function message(key, values) {
    var template = MESSAGES[key];
    if (template === undefined) throw new Error("no mesh message " + key);
    return template.replace(/\{(\w+)\}/g, function (m, name) {
      return values && values[name] !== undefined ? String(values[name]) : m;
    });
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

  // ------------------------------------------------------------------ growable typed arrays

  function Growable(Type, capacity) {
    this.Type = Type;
    this.data = new Type(Math.max(16, capacity || 0));
    this.length = 0;
  }
  Growable.prototype.push = function (x) {
    if (this.length === this.data.length) this.grow(this.length + 1);
    this.data[this.length++] = x;
  };
  Growable.prototype.grow = function (need) {
    var size = this.data.length;
    while (size < need) size *= 2;
    var next = new this.Type(size);
    next.set(this.data.subarray(0, this.length));
    this.data = next;
  };
  Growable.prototype.array = function () {
    return this.data.slice(0, this.length);
  };

  // ------------------------------------------------------------------ reading, as trinormal.mesh.io reads

  var FORMATS = ["obj", "stl", "ply"];

  /**
   * A file that cannot be read: "NAME[, line N]: REASON", the wording of Python's
   * MeshFileError, from the package's templates.
   */
  function fileError(name, line, key, values) {
    var reason = message(key, values);
    var where = line === null || line === undefined ? name : message("at_line", { name: name, line: line });
    throw new MeshError(where + ": " + reason);
  }

  // characters Python's repr() escapes (str.isprintable() is false for them)
  var NOT_PRINTABLE = /[\p{Cc}\p{Cf}\p{Cs}\p{Co}\p{Cn}\p{Zl}\p{Zp}\p{Zs}]/u;

  /** Python's repr() of a short token, as the readers quote what they could not read. */
  function show(tok) {
    var s = tok.length <= 40 ? tok : tok.slice(0, 39) + "\u2026";
    var quote = s.indexOf("'") >= 0 && s.indexOf('"') < 0 ? '"' : "'";
    var out = "";
    for (var i = 0; i < s.length; i++) {
      var ch = s.charAt(i);
      var code = s.charCodeAt(i);
      if (ch === "\\") out += "\\\\";
      else if (ch === quote) out += "\\" + ch;
      else if (ch === "\n") out += "\\n";
      else if (ch === "\r") out += "\\r";
      else if (ch === "\t") out += "\\t";
      else if (code < 32 || code === 127 || (code >= 0x80 && code < 0xa0) || (code !== 32 && NOT_PRINTABLE.test(ch))) {
        var hex = code.toString(16);
        out += code < 0x100 ? "\\x" + ("0" + hex).slice(-2) : "\\u" + ("000" + hex).slice(-4);
      } else out += ch;
    }
    return quote + out + quote;
  }

  function plural(n, one, many) {
    return n === 1 ? one : many;
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

  var FLOAT = /^[+-]?(?:\d(?:_?\d)*(?:\.(?:\d(?:_?\d)*)?)?|\.\d(?:_?\d)*)(?:[eE][+-]?\d(?:_?\d)*)?$/;
  var SPECIAL = /^[+-]?(?:inf|infinity|nan)$/i;
  var INT = /^[+-]?\d(?:_?\d)*$/;

  /** Python's float(token), or undefined when float() would raise. */
  function pyFloat(tok) {
    if (FLOAT.test(tok)) return Number(tok.replace(/_/g, ""));
    if (SPECIAL.test(tok)) return /nan/i.test(tok) ? NaN : tok.charAt(0) === "-" ? -Infinity : Infinity;
    return undefined;
  }

  /** Python's int(token), or undefined when int() would raise. */
  function pyInt(tok) {
    return INT.test(tok) ? parseInt(tok.replace(/_/g, ""), 10) : undefined;
  }

  function number(tok, name, line) {
    var x = pyFloat(tok);
    if (x === undefined) fileError(name, line, "not_a_number", { token: show(tok) });
    if (!Number.isFinite(x)) fileError(name, line, "not_finite", { token: show(tok) });
    return x;
  }

  function extension(name) {
    var m = /(\.[^./\\]*)$/.exec(String(name || "").replace(/^.*[/\\]/, ""));
    var ext = m && m[1] !== "." ? m[1].toLowerCase() : "";
    return /^\.+$/.test(String(name || "").replace(/^.*[/\\]/, "")) ? "" : ext.replace(/^\./, "");
  }

  var utf8 = typeof TextDecoder !== "undefined" ? new TextDecoder("utf-8", { fatal: true }) : null;

  /** Bytes as Latin-1 text (each byte one character; TextDecoder's "latin1" is Windows-1252). */
  var latin1 = {
    decode: function (bytes) {
      var parts = [];
      for (var i = 0; i < bytes.length; i += 8192) {
        parts.push(String.fromCharCode.apply(null, bytes.subarray(i, Math.min(i + 8192, bytes.length))));
      }
      return parts.join("");
    },
  };

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
      return latin1.decode(bytes);
    }
  }

  function Polygons() {
    this.faces = new Growable(Uint32Array, 1024);
    this.count = 0;
    this.split = 0;
  }
  /** A polygon as triangles: a fan from its first corner, wound as stored. */
  Polygons.prototype.add = function (corners) {
    var n = corners.length;
    for (var k = 1; k + 1 < n; k++) {
      this.faces.push(corners[0]);
      this.faces.push(corners[k]);
      this.faces.push(corners[k + 1]);
    }
    this.count++;
    if (n > 3) this.split++;
  };

  // ------------------------------------------------------------------ OBJ

  var OBJ_IGNORED = {};
  (
    "vt vn vp g o s mg usemtl mtllib usemap maplib l p cstype deg bmat step curv curv2 surf " +
    "parm trim hole scrv sp end con bevel c_interp d_interp lod shadow_obj trace_obj ctech " +
    "stech call csh"
  )
    .split(" ")
    .forEach(function (k) {
      OBJ_IGNORED[k] = true;
    });

  function readObj(bytes, name, progress) {
    var lines = splitlines(text(bytes, name, "OBJ"));
    var coords = new Growable(Float64Array, 1024);
    var polys = [];
    var polyLines = [];
    var nv = 0;
    var pending = "";
    for (var ln = 0; ln < lines.length; ln++) {
      if ((ln & 0xffff) === 0) progress(ln / lines.length);
      var lineno = ln + 1;
      var raw = lines[ln];
      if (raw.charAt(raw.length - 1) === "\\") {
        pending += raw.slice(0, -1) + " ";
        continue;
      }
      var line = pending + raw;
      pending = "";
      var hash = line.indexOf("#");
      if (hash >= 0) line = line.slice(0, hash);
      var toks = tokens(line);
      if (!toks.length) continue;
      var kw = toks[0];
      if (kw === "v") {
        if (toks.length < 4) fileError(name, lineno, "obj_vertex", {});
        var xyz = [pyFloat(toks[1]), pyFloat(toks[2]), pyFloat(toks[3])];
        for (var a = 0; a < 3; a++) {
          if (xyz[a] === undefined) fileError(name, lineno, "not_a_number", { token: show(toks[a + 1]) });
        }
        for (var b = 0; b < 3; b++) {
          if (!Number.isFinite(xyz[b])) fileError(name, lineno, "not_finite", { token: show(toks[b + 1]) });
        }
        coords.push(xyz[0]);
        coords.push(xyz[1]);
        coords.push(xyz[2]);
        nv++;
      } else if (kw === "f" || kw === "fo") {
        if (toks.length < 4) fileError(name, lineno, "obj_face_short", {});
        var poly = [];
        for (var t = 1; t < toks.length; t++) {
          var slash = toks[t].indexOf("/");
          var i = pyInt(slash < 0 ? toks[t] : toks[t].slice(0, slash));
          if (i === undefined) fileError(name, lineno, "obj_index", { token: show(toks[t]) });
          if (i > 0) poly.push(i - 1);
          else if (i < 0) {
            if (-i > nv) fileError(name, lineno, "obj_back", { index: i, count: nv, vertices: plural(nv, "vertex", "vertices") });
            poly.push(nv + i);
          } else fileError(name, lineno, "obj_zero", {});
        }
        polys.push(poly);
        polyLines.push(lineno);
      } else if (!OBJ_IGNORED[kw]) {
        fileError(name, lineno, "obj_statement", { token: show(kw) });
      }
    }
    if (nv === 0 && !polys.length) fileError(name, null, "obj_empty", {});
    var out = new Polygons();
    for (var k = 0; k < polys.length; k++) {
      for (var c = 0; c < polys[k].length; c++) {
        if (polys[k][c] >= nv) {
          fileError(name, polyLines[k], "obj_index_range", { face: k + 1, index: polys[k][c] + 1, count: nv, vertices: plural(nv, "vertex", "vertices") });
        }
      }
      out.add(polys[k]);
    }
    return { vertices: coords.array(), faces: out.faces.array(), polygons: out.count, split_polygons: out.split, binary: false };
  }

  // ------------------------------------------------------------------ STL

  /** murmur3's finaliser: every bit of h reaches the low bits used as a table slot. */
  function fmix(h) {
    h ^= h >>> 16;
    h = Math.imul(h, 0x85ebca6b);
    h ^= h >>> 13;
    h = Math.imul(h, 0xc2b2ae35);
    return h ^ (h >>> 16);
  }

  /**
   * Corners with exactly equal coordinates become one vertex, numbered in order of first use
   * (-0 equals 0). `corners` holds 9 numbers per triangle.
   */
  function mergeCorners(corners, progress) {
    var n = corners.length / 3;
    var size = 1;
    while (size < n * 2) size <<= 1;
    var mask = size - 1;
    var table = new Int32Array(size).fill(-1);
    var out = new Float64Array(corners.length);
    var faces = new Uint32Array(n);
    var nv = 0;
    var f64 = new Float64Array(1);
    var u32 = new Uint32Array(f64.buffer);
    for (var i = 0; i < n; i++) {
      if ((i & 0x3ffff) === 0) progress(i / n);
      var x = corners[3 * i] + 0, y = corners[3 * i + 1] + 0, z = corners[3 * i + 2] + 0; // -0 -> 0
      f64[0] = x;
      var h = Math.imul(u32[0] ^ 0x2545f491, 0x9e3779b1) ^ u32[1];
      f64[0] = y;
      h = Math.imul((h << 13) | (h >>> 19), 0x85ebca6b) ^ u32[0];
      h = Math.imul((h << 13) | (h >>> 19), 0xc2b2ae35) ^ u32[1];
      f64[0] = z;
      h = Math.imul((h << 13) | (h >>> 19), 0x27d4eb2f) ^ u32[0];
      h = Math.imul((h << 13) | (h >>> 19), 0x165667b1) ^ u32[1];
      var slot = fmix(h) & mask;
      for (;;) {
        var at = table[slot];
        if (at < 0) {
          table[slot] = nv;
          out[3 * nv] = x;
          out[3 * nv + 1] = y;
          out[3 * nv + 2] = z;
          faces[i] = nv++;
          break;
        }
        if (out[3 * at] === x && out[3 * at + 1] === y && out[3 * at + 2] === z) {
          faces[i] = at;
          break;
        }
        slot = (slot + 1) & mask;
      }
    }
    return { vertices: out.slice(0, 3 * nv), faces: faces };
  }

  function readStl(bytes, name, progress) {
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    if (bytes.length >= 84) {
      var n = view.getUint32(80, true);
      if (bytes.length === 84 + 50 * n) {
        // a binary STL, even when its header starts with "solid"
        if (n > LIMITS.max_faces) fail("too_many_faces", { name: name, count: grouped(n), max: grouped(LIMITS.max_faces) });
        var corners = new Float64Array(9 * n);
        for (var i = 0; i < n; i++) {
          if ((i & 0xffff) === 0) progress(0.4 * (i / n));
          var base = 84 + 50 * i + 12;
          for (var k = 0; k < 9; k++) {
            var x = view.getFloat32(base + 4 * k, true);
            if (!Number.isFinite(x)) fileError(name, null, "stl_not_finite", { triangle: i + 1 });
            corners[9 * i + k] = x;
          }
        }
        var merged = mergeCorners(corners, function (p) { progress(0.4 + 0.6 * p); });
        return { vertices: merged.vertices, faces: merged.faces, polygons: n, split_polygons: 0, binary: true };
      }
    }
    var start = 0;
    while (start < bytes.length && (bytes[start] === 32 || (bytes[start] >= 9 && bytes[start] <= 13))) start++;
    var head = "";
    for (var j = start; j < Math.min(start + 5, bytes.length); j++) head += String.fromCharCode(bytes[j]);
    if (head.toLowerCase() !== "solid" || bytes.indexOf(0) >= 0) {
      if (bytes.length >= 84) {
        var m = view.getUint32(80, true);
        fileError(name, null, "stl_not_stl", { count: grouped(m), expected: grouped(84 + 50 * m), size: grouped(bytes.length) });
      }
      fileError(name, null, "stl_short", {});
    }
    return readStlAscii(bytes, name, progress);
  }

  function readStlAscii(bytes, name, progress) {
    var lines = splitlines(text(bytes, name, "STL"));
    var corners = new Growable(Float64Array, 4096);
    var inLoop = false;
    var loopCount = 0;
    var loopLine = 0;
    var lineno = 0;
    for (var ln = 0; ln < lines.length; ln++) {
      if ((ln & 0xffff) === 0) progress(0.5 * (ln / lines.length));
      lineno = ln + 1;
      var toks = tokens(lines[ln]);
      if (!toks.length) continue;
      var kw = toks[0].toLowerCase();
      if (kw === "vertex") {
        if (!inLoop) fileError(name, lineno, "stl_vertex_outside", {});
        if (toks.length !== 4) fileError(name, lineno, "stl_vertex", {});
        for (var k = 1; k <= 3; k++) corners.push(number(toks[k], name, lineno));
        loopCount++;
      } else if (kw === "outer") {
        inLoop = true;
        loopCount = 0;
        loopLine = lineno;
      } else if (kw === "endloop") {
        if (!inLoop) fileError(name, lineno, "stl_endloop", {});
        if (loopCount !== 3) fileError(name, lineno, "stl_facet", { start: loopLine, count: loopCount });
        inLoop = false;
      } else if (kw === "solid" || kw === "endsolid" || kw === "facet" || kw === "endfacet") {
        if (inLoop) fileError(name, lineno, "stl_before_endloop", { token: show(toks[0]) });
      } else {
        fileError(name, lineno, "stl_keyword", { token: show(toks[0]) });
      }
    }
    if (inLoop) fileError(name, lineno, "stl_ends_in_facet", {});
    var merged = mergeCorners(corners.array(), function (p) { progress(0.5 + 0.5 * p); });
    var nf = merged.faces.length / 3;
    return { vertices: merged.vertices, faces: merged.faces, polygons: nf, split_polygons: 0, binary: false };
  }

  // ------------------------------------------------------------------ PLY

  var PLY_TYPES = {
    char: ["Int8", 1], int8: ["Int8", 1], uchar: ["Uint8", 1], uint8: ["Uint8", 1],
    short: ["Int16", 2], int16: ["Int16", 2], ushort: ["Uint16", 2], uint16: ["Uint16", 2],
    int: ["Int32", 4], int32: ["Int32", 4], uint: ["Uint32", 4], uint32: ["Uint32", 4],
    float: ["Float32", 4], float32: ["Float32", 4], double: ["Float64", 8], float64: ["Float64", 8],
  };

  function findBytes(bytes, textToFind, from) {
    outer: for (var i = from || 0; i + textToFind.length <= bytes.length; i++) {
      for (var k = 0; k < textToFind.length; k++) if (bytes[i + k] !== textToFind.charCodeAt(k)) continue outer;
      return i;
    }
    return -1;
  }

  function readPly(bytes, name, progress) {
    var end = findBytes(bytes, "end_header", 0);
    if (!(bytes[0] === 112 && bytes[1] === 108 && bytes[2] === 121) || end < 0) fileError(name, 1, "ply_not_ply", {});
    var nl = bytes.indexOf(10, end);
    var bodyStart = nl < 0 ? bytes.length : nl + 1;
    var header = splitlines(latin1.decode(bytes.subarray(0, end)));
    var fmt = null;
    var elements = [];
    for (var i = 0; i < header.length; i++) {
      var lineno = i + 1;
      var toks = tokens(header[i]);
      if (!toks.length || toks[0] === "ply" || toks[0] === "comment" || toks[0] === "obj_info") continue;
      if (toks[0] === "format") {
        if (toks.length < 2 || ["ascii", "binary_little_endian", "binary_big_endian"].indexOf(toks[1]) < 0) {
          fileError(name, lineno, "ply_format", {});
        }
        fmt = toks[1];
      } else if (toks[0] === "element") {
        if (toks.length !== 3 || !/^[0-9]+$/.test(toks[2])) fileError(name, lineno, "ply_element", {});
        elements.push({ name: toks[1], count: parseInt(toks[2], 10), props: [], line: lineno });
      } else if (toks[0] === "property") {
        if (!elements.length) fileError(name, lineno, "ply_property_first", {});
        var el = elements[elements.length - 1];
        if (toks.length === 5 && toks[1] === "list") {
          if (!PLY_TYPES[toks[2]] || !PLY_TYPES[toks[3]]) fileError(name, lineno, "ply_type", {});
          el.props.push({ name: toks[4], type: PLY_TYPES[toks[3]], count: PLY_TYPES[toks[2]] });
        } else if (toks.length === 3 && PLY_TYPES[toks[1]]) {
          el.props.push({ name: toks[2], type: PLY_TYPES[toks[1]], count: null });
        } else {
          fileError(name, lineno, "ply_property", { token: show(header[i].trim()) });
        }
      } else {
        fileError(name, lineno, "ply_keyword", { token: show(toks[0]) });
      }
    }
    if (fmt === null) fileError(name, null, "ply_no_format", {});
    var vert = null;
    elements.forEach(function (e) {
      if (!vert && e.name === "vertex") vert = e;
    });
    if (!vert) fileError(name, null, "ply_no_vertex", {});
    if (!isFixed(vert)) fileError(name, vert.line, "ply_vertex_list", {});
    ["x", "y", "z"].forEach(function (axis) {
      var has = vert.props.some(function (p) { return p.name === axis && p.count === null; });
      if (!has) fileError(name, vert.line, "ply_no_axis", { axis: axis });
    });
    var face = null;
    elements.forEach(function (e) {
      if (!face && e.name === "face") face = e;
    });
    if (face && face.count > LIMITS.max_faces) fail("too_many_faces", { name: name, count: grouped(face.count), max: grouped(LIMITS.max_faces) });
    var values =
      fmt === "ascii"
        ? plyAscii(bytes, bodyStart, header.length + 2, elements, name, progress)
        : plyBinary(bytes, bodyStart, elements, fmt === "binary_little_endian", name, progress);
    var v = values.vertex;
    var nv = vert.count;
    var vertices = new Float64Array(3 * nv);
    for (var r = 0; r < nv; r++) {
      for (var a = 0; a < 3; a++) vertices[3 * r + a] = v[["x", "y", "z"][a]][r];
      if (!(Number.isFinite(vertices[3 * r]) && Number.isFinite(vertices[3 * r + 1]) && Number.isFinite(vertices[3 * r + 2]))) {
        fileError(name, null, "ply_not_finite", { vertex: r });
      }
    }
    var polys = (values.face && values.face._polys) || [];
    var out = new Polygons();
    for (var q = 0; q < polys.length; q++) {
      if (polys[q].length < 3) fileError(name, null, "ply_corners", { face: q, count: polys[q].length });
      for (var c = 0; c < polys[q].length; c++) {
        var idx = polys[q][c];
        if (!(idx >= 0 && idx < nv)) {
          var valid = nv ? message("ply_valid", { last: nv - 1 }) : message("ply_no_vertices", {});
          fileError(name, null, "ply_index_range", { face: q, index: idx, valid: valid });
        }
      }
      out.add(polys[q]);
    }
    return {
      vertices: vertices,
      faces: out.faces.array(),
      polygons: out.count,
      split_polygons: out.split,
      binary: fmt !== "ascii",
    };
  }

  function faceListName(el) {
    var lists = el.props.filter(function (p) { return p.count !== null; }).map(function (p) { return p.name; });
    if (lists.indexOf("vertex_indices") >= 0) return "vertex_indices";
    if (lists.indexOf("vertex_index") >= 0) return "vertex_index";
    return lists.length ? lists[0] : null;
  }

  function isFixed(el) {
    return el.props.every(function (p) { return p.count === null; });
  }

  function plyAscii(bytes, start, firstLine, elements, name, progress) {
    var lines = splitlines(text(bytes.subarray(start), name, "PLY"));
    var out = {};
    var pos = 0;
    elements.forEach(function (el) {
      if (pos + el.count > lines.length) {
        fileError(name, firstLine + lines.length - 1, "ply_ascii_short", {
          rows: Math.max(lines.length - pos, 0), count: el.count, element: el.name,
        });
      }
      if (el.name !== "vertex" && el.name !== "face") {
        pos += el.count;
        return;
      }
      if (isFixed(el)) {
        var k = el.props.length;
        var cols = el.props.map(function () { return new Float64Array(el.count); });
        var ok = true;
        for (var r = 0; r < el.count && ok; r++) {
          if ((r & 0xffff) === 0) progress(0.5 * (r / Math.max(1, el.count)));
          var toks = tokens(lines[pos + r]);
          if (toks.length !== k) ok = false;
          for (var j = 0; j < k && ok; j++) {
            var x0 = pyFloat(toks[j]);
            if (x0 === undefined) ok = false;
            else cols[j][r] = x0;
          }
        }
        if (!ok) {
          // Python reads every number at once, then explains the first bad row
          for (var rr = 0; rr < el.count; rr++) {
            var bad = tokens(lines[pos + rr]);
            if (bad.length !== k) fileError(name, firstLine + pos + rr, "ply_expected", { count: k, found: bad.length });
            for (var jj = 0; jj < k; jj++) number(bad[jj], name, firstLine + pos + rr);
          }
        }
        var props = {};
        el.props.forEach(function (p, j2) {
          props[p.name] = cols[j2];
        });
        out[el.name] = props;
      } else {
        var want = el.name === "face" ? faceListName(el) : null;
        var polys = [];
        for (var r2 = 0; r2 < el.count; r2++) {
          if ((r2 & 0xffff) === 0) progress(0.5 + 0.5 * (r2 / Math.max(1, el.count)));
          var row = tokens(lines[pos + r2]);
          var lineno = firstLine + pos + r2;
          var t = 0;
          for (var pi = 0; pi < el.props.length; pi++) {
            var p2 = el.props[pi];
            if (p2.count === null) {
              t += 1;
              continue;
            }
            var n = t < row.length ? pyInt(row[t]) : undefined;
            var items = [];
            if (n !== undefined && n >= 0) {
              for (var q = t + 1; q < Math.min(t + 1 + n, row.length); q++) {
                var x = pyInt(row[q]);
                if (x === undefined) {
                  n = undefined;
                  break;
                }
                items.push(x);
              }
            }
            if (n === undefined || n < 0 || items.length !== n) fileError(name, lineno, "ply_row", { element: el.name });
            t += 1 + n;
            if (p2.name === want) polys.push(items);
          }
          if (t !== row.length) fileError(name, lineno, "ply_too_many", { element: el.name, count: row.length - t });
        }
        out[el.name] = { _polys: polys };
      }
      pos += el.count;
    });
    return out;
  }

  function plyBinary(bytes, start, elements, little, name, progress) {
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    var out = {};
    var pos = start;
    var size = bytes.length;
    elements.forEach(function (el) {
      if (isFixed(el)) {
        var item = 0;
        el.props.forEach(function (p) { item += p.type[1]; });
        if (pos + item * el.count > size) {
          fileError(name, null, "ply_binary_short", {
            element: el.name, rows: Math.floor((size - pos) / Math.max(item, 1)), count: el.count,
          });
        }
        if (el.name === "vertex" || el.name === "face") {
          var props = {};
          var offset = 0;
          el.props.forEach(function (p) {
            var col = new Float64Array(el.count);
            var getter = "get" + p.type[0];
            for (var r = 0; r < el.count; r++) col[r] = view[getter](pos + r * item + offset, little);
            props[p.name] = col;
            offset += p.type[1];
          });
          out[el.name] = props;
        }
        pos += item * el.count;
        return;
      }
      var want = el.name === "face" ? faceListName(el) : null;
      var polys = [];
      for (var r2 = 0; r2 < el.count; r2++) {
        if ((r2 & 0xffff) === 0) progress(r2 / Math.max(1, el.count));
        for (var pi = 0; pi < el.props.length; pi++) {
          var p2 = el.props[pi];
          if (p2.count === null) {
            pos += p2.type[1];
            if (pos > size) fileError(name, null, "ply_binary_row", { element: el.name, row: r2, count: el.count });
            continue;
          }
          if (pos + p2.count[1] > size) fileError(name, null, "ply_binary_row", { element: el.name, row: r2, count: el.count });
          var n = view["get" + p2.count[0]](pos, little);
          pos += p2.count[1];
          if (n < 0 || pos + n * p2.type[1] > size) fileError(name, null, "ply_binary_row", { element: el.name, row: r2, count: el.count });
          if (p2.name === want) {
            var items = new Array(n);
            var getter2 = "get" + p2.type[0];
            for (var q = 0; q < n; q++) items[q] = view[getter2](pos + q * p2.type[1], little);
            polys.push(items);
          }
          pos += n * p2.type[1];
        }
      }
      if (el.name === "face") out.face = { _polys: polys };
    });
    return out;
  }

  /**
   * Read a mesh file. `buffer` is an ArrayBuffer (or Uint8Array), `name` the file name; the
   * format comes from the name's extension, as in Python's read_mesh. Returns {format, binary,
   * vertices: Float64Array (3 per vertex), faces: Uint32Array (3 per triangle), polygons,
   * split_polygons}; throws MeshError with Python's sentence (or the page's own, for its limits).
   */
  function read(buffer, name, onProgress) {
    var bytes = buffer instanceof Uint8Array ? buffer : new Uint8Array(buffer);
    var progress = onProgress || function () {};
    var ext = extension(name);
    if (FORMATS.indexOf(ext) < 0) fileError(name, null, "unknown_format", { ext: ext ? "." + ext : message("no_extension", {}) });
    var tooLarge = sizeProblem(name, bytes.length);
    if (tooLarge) throw new MeshError(tooLarge);
    var mesh = ext === "obj" ? readObj(bytes, name, progress) : ext === "stl" ? readStl(bytes, name, progress) : readPly(bytes, name, progress);
    mesh.format = ext;
    mesh.name = name;
    if (mesh.faces.length === 0) fail("no_faces", { name: name });
    if (mesh.faces.length / 3 > LIMITS.max_faces) fail("too_many_faces", { name: name, count: grouped(mesh.faces.length / 3), max: grouped(LIMITS.max_faces) });
    return mesh;
  }

  // ------------------------------------------------------------------ the checks

  var TWO_900 = Math.pow(2, 900);
  var TWO_M900 = Math.pow(2, -900);
  var frexpBuf = new Float64Array(1);
  var frexpU32 = new Uint32Array(frexpBuf.buffer);

  /** The exponent e with |x| = m * 2**e, m in [0.5, 1) (numpy.frexp's), 0 for x == 0. */
  function frexpExp(x) {
    if (x === 0 || !Number.isFinite(x)) return 0;
    frexpBuf[0] = x;
    var e = (frexpU32[1] >>> 20) & 0x7ff;
    if (e === 0) {
      // subnormal: scale up first
      frexpBuf[0] = x * Math.pow(2, 64);
      e = ((frexpU32[1] >>> 20) & 0x7ff) - 64;
    }
    return e - 1022;
  }

  function ldexp(x, e) {
    // exact while the result is a normal number: split the power so no step overflows
    while (e > 1000) { x *= Math.pow(2, 1000); e -= 1000; }
    while (e < -1000) { x *= Math.pow(2, -1000); e += 1000; }
    return x * Math.pow(2, e);
  }

  /**
   * Which faces are degenerate (the sine of the angle between the edges is at most tol), with
   * numpy's arithmetic in trinormal.mesh: the same operations in the same order, so the same
   * verdicts, including the careful path for edges at extreme scales.
   * Returns a Uint8Array: 0 proper, 1 coincident corners, 2 collinear (or too thin).
   */
  function degenerateFaces(vertices, faces) {
    var nf = faces.length / 3;
    var out = new Uint8Array(nf);
    var tol2 = TOL * TOL;
    var V = vertices;
    for (var f = 0; f < nf; f++) {
      var i0 = 3 * faces[3 * f], i1 = 3 * faces[3 * f + 1], i2 = 3 * faces[3 * f + 2];
      var ax = V[i0], ay = V[i0 + 1], az = V[i0 + 2];
      var bx = V[i1], by = V[i1 + 1], bz = V[i1 + 2];
      var cx = V[i2], cy = V[i2 + 1], cz = V[i2 + 2];
      if ((ax === bx && ay === by && az === bz) || (ax === cx && ay === cy && az === cz) || (bx === cx && by === cy && bz === cz)) {
        out[f] = 1;
        continue;
      }
      var ux = bx - ax, uy = by - ay, uz = bz - az;
      var vx = cx - ax, vy = cy - ay, vz = cz - az;
      var nx = uy * vz - uz * vy;
      var ny = uz * vx - ux * vz;
      var nz = ux * vy - uy * vx;
      var ss = nx * nx + ny * ny + nz * nz;
      var d = ux * vx + uy * vy + uz * vz;
      var q = d * d + ss;
      var deg;
      if (q < TWO_900 && ss > TWO_M900) {
        deg = ss <= q * tol2;
      } else {
        deg = carefulDegenerate(ax, ay, az, bx, by, bz, cx, cy, cz, tol2);
      }
      if (deg) out[f] = 2;
    }
    return out;
  }

  function carefulDegenerate(ax, ay, az, bx, by, bz, cx, cy, cz, tol2) {
    var ux = bx - ax, uy = by - ay, uz = bz - az;
    var vx = cx - ax, vy = cy - ay, vz = cz - az;
    if (!(Number.isFinite(ux) && Number.isFinite(uy) && Number.isFinite(uz) && Number.isFinite(vx) && Number.isFinite(vy) && Number.isFinite(vz))) {
      ux = bx * 0.25 - ax * 0.25; uy = by * 0.25 - ay * 0.25; uz = bz * 0.25 - az * 0.25;
      vx = cx * 0.25 - ax * 0.25; vy = cy * 0.25 - ay * 0.25; vz = cz * 0.25 - az * 0.25;
    }
    var eu = frexpExp(Math.max(Math.abs(ux), Math.abs(uy), Math.abs(uz)));
    var ev = frexpExp(Math.max(Math.abs(vx), Math.abs(vy), Math.abs(vz)));
    ux = ldexp(ux, -eu); uy = ldexp(uy, -eu); uz = ldexp(uz, -eu);
    vx = ldexp(vx, -ev); vy = ldexp(vy, -ev); vz = ldexp(vz, -ev);
    var nx = uy * vz - uz * vy;
    var ny = uz * vx - ux * vz;
    var nz = ux * vy - uy * vx;
    var uu = ux * ux + uy * uy + uz * uz;
    var vv = vx * vx + vy * vy + vz * vz;
    var nn = nx * nx + ny * ny + nz * nz;
    var deg = nn <= tol2 * uu * vv;
    var en = frexpExp(Math.max(Math.abs(nx), Math.abs(ny), Math.abs(nz)));
    var sx = ldexp(nx, -en), sy = ldexp(ny, -en), sz = ldexp(nz, -en);
    var mag = Math.sqrt(sx * sx + sy * sy + sz * sz);
    return deg || mag === 0;
  }

  /**
   * The edges of the mesh, grouped: for each vertex lo, the half-edges (lo, hi) with lo < hi,
   * as compressed rows. A half-edge is a face side h = 3 * face + k, from corner k to corner
   * k + 1. Only faces with three distinct vertex indices have edges (trinormal.mesh.topology).
   */
  function edgeTable(faces, nv, clean) {
    var nf = faces.length / 3;
    var start = new Int32Array(nv + 1);
    var s, a, b;
    for (s = 0; s < 3 * nf; s++) {
      if (!clean[(s / 3) | 0]) continue;
      a = faces[s];
      b = faces[s % 3 === 2 ? s - 2 : s + 1];
      start[(a < b ? a : b) + 1]++;
    }
    for (var v = 0; v < nv; v++) start[v + 1] += start[v];
    var fill = start.slice(0, nv);
    var hi = new Int32Array(start[nv]);
    var side = new Int32Array(start[nv]);
    for (s = 0; s < 3 * nf; s++) {
      if (!clean[(s / 3) | 0]) continue;
      a = faces[s];
      b = faces[s % 3 === 2 ? s - 2 : s + 1];
      var at = fill[a < b ? a : b]++;
      hi[at] = a < b ? b : a;
      side[at] = s;
    }
    return { start: start, hi: hi, side: side };
  }

  function find(parent, x) {
    while (parent[x] !== x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }

  function union(parent, a, b) {
    a = find(parent, a);
    b = find(parent, b);
    if (a === b) return;
    if (a < b) parent[b] = a;
    else parent[a] = b;
  }

  function next(h) {
    return h % 3 === 2 ? h - 2 : h + 1;
  }

  /** Index lists as plain arrays, and pairs sorted lexicographically. */
  function sortedPairs(pairs) {
    var n = pairs.length / 2;
    var order = new Array(n);
    for (var i = 0; i < n; i++) order[i] = i;
    order.sort(function (x, y) {
      return pairs[2 * x] - pairs[2 * y] || pairs[2 * x + 1] - pairs[2 * y + 1];
    });
    return order.map(function (i) {
      return [pairs[2 * i], pairs[2 * i + 1]];
    });
  }

  var EPS = Math.pow(2, -52);
  var VOLUME_ROUNDING = 8;

  /**
   * The report of trinormal.mesh.check(vertices, faces): the same keys and values as its
   * to_dict(), computed the same way (trinormal/mesh/report.py, topology.py, repair.py).
   * `onProgress(fraction)` is called now and then.
   */
  function check(vertices, faces, onProgress) {
    var progress = onProgress || function () {};
    var V = vertices;
    var nv = V.length / 3;
    var nf = faces.length / 3;
    var f, k, s, i;
    for (s = 0; s < faces.length; s++) {
      if (faces[s] >= nv) fail("index_range", { face: (s / 3) | 0, index: faces[s], count: nv });
    }
    progress(0.05);

    // degenerate faces: two corners at one point, or the sine test
    var kind = degenerateFaces(V, faces);
    var coincident = [], collinear = [], degenerate = [];
    for (f = 0; f < nf; f++) {
      if (kind[f]) degenerate.push(f);
      if (kind[f] === 1) coincident.push(f);
      else if (kind[f] === 2) collinear.push(f);
    }
    var used = new Uint8Array(nv);
    for (s = 0; s < faces.length; s++) used[faces[s]] = 1;
    var unused = [];
    for (i = 0; i < nv; i++) if (!used[i]) unused.push(i);
    var clean = new Uint8Array(nf);
    for (f = 0; f < nf; f++) {
      var fa = faces[3 * f], fb = faces[3 * f + 1], fc = faces[3 * f + 2];
      clean[f] = fa !== fb && fb !== fc && fc !== fa ? 1 : 0;
    }
    var dups = duplicateFaces(faces, clean);
    progress(0.2);

    // edges: group the half-edges of each undirected edge
    var table = edgeTable(faces, nv, clean);
    progress(0.35);
    var start = table.start, hi = table.hi, side = table.side;
    var parent = new Int32Array(nf); // pieces: faces joined through shared edges
    for (f = 0; f < nf; f++) parent[f] = f;
    var fanParent = new Int32Array(3 * nf); // fans: corners joined across shared edges
    for (s = 0; s < 3 * nf; s++) fanParent[s] = s;
    var boundary = [], nonManifold = [], inconsistentPairs = [];
    var pairA = new Growable(Int32Array, nf), pairB = new Growable(Int32Array, nf); // manifold
    var openSides = new Growable(Int32Array, 64); // a half-edge of every edge not shared by two
    var group = [];
    var boundarySides = new Growable(Int32Array, 64), nonManifoldSides = new Growable(Int32Array, 64);
    for (var lo = 0; lo < nv; lo++) {
      var a1 = start[lo + 1];
      for (var x = start[lo]; x < a1; x++) {
        var h = hi[x];
        if (h < 0) continue;
        group.length = 0;
        group.push(side[x]);
        for (var y = x + 1; y < a1; y++) {
          if (hi[y] === h) {
            group.push(side[y]);
            hi[y] = -1;
          }
        }
        var count = group.length;
        if (count === 1) {
          var only = group[0];
          boundary.push(faces[only], faces[next(only)]);
          boundarySides.push(only);
          openSides.push(only);
          continue;
        }
        if (count === 2) {
          pairA.push(group[0]);
          pairB.push(group[1]);
          if (faces[group[0]] === faces[group[1]]) inconsistentPairs.push(lo, h);
        } else {
          nonManifold.push(lo, h);
          nonManifoldSides.push(group[0]);
          openSides.push(group[0]);
        }
        // every face of the group in one piece; their corners at lo in one fan, at h in one
        var h0 = group[0];
        var cLo0 = faces[h0] === lo ? h0 : next(h0);
        var cHi0 = faces[h0] === lo ? next(h0) : h0;
        for (k = 1; k < count; k++) {
          var hk = group[k];
          union(parent, (h0 / 3) | 0, (hk / 3) | 0);
          var atLo = faces[hk] === lo;
          union(fanParent, cLo0, atLo ? hk : next(hk));
          union(fanParent, cHi0, atLo ? next(hk) : hk);
        }
      }
    }
    progress(0.5);

    // pieces, numbered in the order of their first faces (-1: a face using a vertex twice)
    var comp = new Int32Array(nf).fill(-1);
    var label = new Int32Array(nf).fill(-1);
    var nComp = 0;
    for (f = 0; f < nf; f++) {
      if (!clean[f]) continue;
      var r = find(parent, f);
      if (label[r] < 0) label[r] = nComp++;
      comp[f] = label[r];
    }

    // non-manifold vertices: the corners at a vertex fall into more than one fan
    var fanOf = new Int32Array(nv).fill(-1);
    var manyFans = new Uint8Array(nv);
    for (s = 0; s < 3 * nf; s++) {
      if (!clean[(s / 3) | 0]) continue;
      var vtx = faces[s];
      var root = find(fanParent, s);
      if (fanOf[vtx] < 0) fanOf[vtx] = root;
      else if (fanOf[vtx] !== root) manyFans[vtx] = 1;
    }
    var nonManifoldVertices = [];
    for (i = 0; i < nv; i++) if (manyFans[i]) nonManifoldVertices.push(i);
    progress(0.6);

    // closed pieces: every edge shared by exactly two faces
    var closed = new Uint8Array(nComp).fill(1);
    for (i = 0; i < openSides.length; i++) closed[comp[(openSides.data[i] / 3) | 0]] = 0;
    var inconsistent = new Int32Array(nComp); // edges walked the same way by both faces

    // agreement across manifold edges: neighbours of each face side
    var across = new Int32Array(3 * nf).fill(-1);
    var agree = new Uint8Array(3 * nf);
    for (i = 0; i < pairA.length; i++) {
      var p1 = pairA.data[i], p2 = pairB.data[i];
      var same = faces[p1] === faces[p2] ? 1 : 0;
      if (same) inconsistent[comp[(p1 / 3) | 0]]++;
      across[p1] = (p2 / 3) | 0;
      across[p2] = (p1 / 3) | 0;
      agree[p1] = same;
      agree[p2] = same;
    }

    // orientation classes: faces joined by manifold edges; parity = turned relative to the
    // class's first face. A class that meets itself with the wrong parity is non-orientable.
    var parity = new Uint8Array(nf);
    var seen = new Uint8Array(nf);
    var klass = new Int32Array(nf).fill(-1);
    var queue = new Int32Array(nf);
    var classCount = [], classBad = [];
    var orientable = new Uint8Array(nComp).fill(1);
    for (var seed = 0; seed < nf; seed++) {
      if (seen[seed] || !clean[seed]) continue;
      var c = classCount.length;
      var n0 = 0, n1 = 0, bad = 0;
      var head = 0, tail = 0;
      queue[tail++] = seed;
      seen[seed] = 1;
      while (head < tail) {
        var cur = queue[head++];
        klass[cur] = c;
        if (parity[cur]) n1++;
        else n0++;
        for (k = 0; k < 3; k++) {
          var nb = across[3 * cur + k];
          if (nb < 0) continue;
          var want = parity[cur] ^ agree[3 * cur + k];
          if (!seen[nb]) {
            seen[nb] = 1;
            parity[nb] = want;
            queue[tail++] = nb;
          } else if (parity[nb] !== want) {
            bad = 1;
          }
        }
      }
      classCount.push([n0, n1]);
      classBad.push(bad);
      if (bad) orientable[comp[seed]] = 0;
    }
    // flip the side with fewer faces as they are (a tie keeps the class's first face)
    var flip = new Uint8Array(nf);
    for (f = 0; f < nf; f++) {
      if (!clean[f] || !orientable[comp[f]] || classBad[klass[f]]) continue;
      var cnt = classCount[klass[f]];
      flip[f] = cnt[1] > cnt[0] ? 1 - parity[f] : parity[f];
    }
    progress(0.75);

    // six times the enclosed volume of each piece, from the first vertex of its first face
    var ref = new Int32Array(nComp).fill(-1);
    var volume = new Float64Array(nComp), fixed = new Float64Array(nComp);
    var sizeSum = new Float64Array(nComp), nIn = new Float64Array(nComp);
    for (f = 0; f < nf; f++) {
      var cf = comp[f];
      if (cf < 0) continue;
      if (ref[cf] < 0) ref[cf] = 3 * faces[3 * f];
      var o = ref[cf];
      var i0 = 3 * faces[3 * f], i1 = 3 * faces[3 * f + 1], i2 = 3 * faces[3 * f + 2];
      var px = V[i0] - V[o], py = V[i0 + 1] - V[o + 1], pz = V[i0 + 2] - V[o + 2];
      var qx = V[i1] - V[o], qy = V[i1 + 1] - V[o + 1], qz = V[i1 + 2] - V[o + 2];
      var sx = V[i2] - V[o], sy = V[i2 + 1] - V[o + 1], sz = V[i2 + 2] - V[o + 2];
      var det = px * (qy * sz - qz * sy) + py * (qz * sx - qx * sz) + pz * (qx * sy - qy * sx);
      var size =
        Math.sqrt(px * px + py * py + pz * pz) *
        Math.sqrt(qx * qx + qy * qy + qz * qz) *
        Math.sqrt(sx * sx + sy * sy + sz * sz);
      volume[cf] += det;
      fixed[cf] += det * (flip[f] ? -1.0 : 1.0);
      sizeSum[cf] += size;
      nIn[cf] += 1;
    }
    var error = new Float64Array(nComp);
    for (i = 0; i < nComp; i++) error[i] = (VOLUME_ROUNDING + nIn[i]) * EPS * sizeSum[i];
    var inward = new Uint8Array(nComp);
    for (i = 0; i < nComp; i++) inward[i] = closed[i] && orientable[i] && fixed[i] < -error[i] ? 1 : 0;
    var toFlip = [];
    var flips = new Int32Array(nComp), sizes = new Int32Array(nComp);
    for (f = 0; f < nf; f++) {
      if (comp[f] < 0) continue;
      sizes[comp[f]]++;
      if (flip[f] ^ inward[comp[f]]) {
        toFlip.push(f);
        flips[comp[f]]++;
      }
    }
    progress(0.9);

    var components = [];
    var allClosed = nComp > 0, allConsistent = true, allOutward = true, anyClosed = false;
    for (i = 0; i < nComp; i++) {
      var consistent = inconsistent[i] === 0;
      var measurable = closed[i] && consistent;
      var out = Math.abs(volume[i]) <= error[i] ? null : volume[i] > 0;
      var entry = {
        faces: sizes[i],
        closed: !!closed[i],
        consistent: consistent,
        orientable: !!orientable[i],
        outward: measurable ? out : null,
        volume: measurable ? volume[i] / 6.0 : null,
        faces_to_flip: flips[i],
      };
      components.push(entry);
      if (!closed[i]) allClosed = false;
      if (!consistent) allConsistent = false;
      if (closed[i]) anyClosed = true;
      if (closed[i] && entry.outward !== true) allOutward = false;
    }
    var ok =
      allClosed && allConsistent && anyClosed && allOutward &&
      !degenerate.length && !dups.same.length && !dups.reversed.length &&
      !nonManifoldVertices.length && !unused.length;
    progress(1);
    return {
      n_vertices: nv,
      n_faces: nf,
      n_components: nComp,
      closed: allClosed,
      consistent_winding: allConsistent,
      outward: anyClosed ? allOutward : null, // null: no closed piece to face out
      ok: ok,
      unused_vertices: unused,
      degenerate_faces: degenerate,
      coincident_faces: coincident,
      collinear_faces: collinear,
      duplicate_faces: dups.same,
      reversed_duplicate_faces: dups.reversed,
      boundary_edges: sortedPairs(boundary),
      non_manifold_edges: sortedPairs(nonManifold),
      non_manifold_vertices: nonManifoldVertices,
      inconsistent_edges: sortedPairs(inconsistentPairs),
      components: components,
      faces_to_flip: toFlip,
      // for the 3D view: one face side (3 * face + k) of every boundary and non-manifold edge
      _boundary_sides: boundarySides.array(),
      _non_manifold_sides: nonManifoldSides.array(),
    };
  }

  /**
   * Faces that repeat an earlier face's three vertices: `same` when wound like an earlier copy,
   * `reversed` for the first copy wound the other way (trinormal.mesh.duplicate_faces).
   * Faces using a vertex twice are left out.
   */
  function duplicateFaces(faces, clean) {
    var nf = faces.length / 3;
    var size = 1;
    while (size < nf * 2) size <<= 1;
    var mask = size - 1;
    var table = new Int32Array(size).fill(-1);
    var otherWay = new Int32Array(nf).fill(-1); // first face wound the other way, per key
    var same = [];
    var reversed = [];
    for (var f = 0; f < nf; f++) {
      if (!clean[f]) continue;
      var a = faces[3 * f], b = faces[3 * f + 1], c = faces[3 * f + 2];
      var lo = Math.min(a, b, c), hi = Math.max(a, b, c), mid = a + b + c - lo - hi;
      var slot = fmix(fmix(fmix(lo) ^ mid) ^ hi) & mask;
      for (;;) {
        var at = table[slot];
        if (at < 0) {
          table[slot] = f;
          break;
        }
        var p = faces[3 * at], q = faces[3 * at + 1], r = faces[3 * at + 2];
        if (Math.min(p, q, r) === lo && Math.max(p, q, r) === hi && p + q + r - lo - hi === mid) {
          if (sameWay(a, b, c, p, q, r)) same.push(f);
          else if (otherWay[at] >= 0) same.push(f);
          else {
            otherWay[at] = f;
            reversed.push(f);
          }
          break;
        }
        slot = (slot + 1) & mask;
      }
    }
    return { same: same, reversed: reversed };
  }

  function sameWay(a, b, c, p, q, r) {
    return (a === p && b === q && c === r) || (a === q && b === r && c === p) || (a === r && b === p && c === q);
  }

  // ------------------------------------------------------------------ the fix and the writers

  /** The faces with the report's faces_to_flip turned over: (a, b, c) becomes (a, c, b). */
  function fixWinding(faces, report) {
    var out = new Uint32Array(faces);
    var list = report.faces_to_flip;
    for (var i = 0; i < list.length; i++) {
      var f = list[i];
      var t = out[3 * f + 1];
      out[3 * f + 1] = out[3 * f + 2];
      out[3 * f + 2] = t;
    }
    return out;
  }

  /** Python's repr() of a float: the shortest digits that read back, in Python's layout. */
  function repr(x) {
    if (x === 0) return Object.is(x, -0) ? "-0.0" : "0.0";
    if (!Number.isFinite(x)) return x > 0 ? "inf" : x < 0 ? "-inf" : "nan";
    var e = x.toExponential(); // shortest round-trip digits: "d.ddde+X"
    var m = /^(-?)(\d)(?:\.(\d+))?e([+-]\d+)$/.exec(e);
    var sign = m[1];
    var digits = m[2] + (m[3] || "");
    var exp = parseInt(m[4], 10);
    if (exp < -4 || exp >= 16) {
      var mant = digits.length > 1 ? digits[0] + "." + digits.slice(1) : digits;
      var ee = Math.abs(exp);
      return sign + mant + "e" + (exp < 0 ? "-" : "+") + (ee < 10 ? "0" : "") + ee;
    }
    if (exp < 0) return sign + "0." + "0".repeat(-exp - 1) + digits;
    if (digits.length <= exp + 1) return sign + digits + "0".repeat(exp + 1 - digits.length) + ".0";
    return sign + digits.slice(0, exp + 1) + "." + digits.slice(exp + 1);
  }

  /** Unit normals for STL facets as trinormal.mesh.face_normals gives them (zero if degenerate). */
  function facetNormals(V, faces) {
    var nf = faces.length / 3;
    var deg = degenerateFaces(V, faces);
    var out = new Float64Array(3 * nf);
    for (var f = 0; f < nf; f++) {
      if (deg[f]) continue;
      var a = 3 * faces[3 * f], b = 3 * faces[3 * f + 1], c = 3 * faces[3 * f + 2];
      var ux = V[b] - V[a], uy = V[b + 1] - V[a + 1], uz = V[b + 2] - V[a + 2];
      var vx = V[c] - V[a], vy = V[c + 1] - V[a + 1], vz = V[c + 2] - V[a + 2];
      var nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      var ss = nx * nx + ny * ny + nz * nz;
      var d = ux * vx + uy * vy + uz * vz;
      if (d * d + ss < TWO_900 && ss > TWO_M900) {
        var t = 1.0 / Math.sqrt(ss);
        out[3 * f] = nx * t;
        out[3 * f + 1] = ny * t;
        out[3 * f + 2] = nz * t;
      } else {
        // extreme scales: the edges scaled by powers of two first (exact), as Python does
        var eu = frexpExp(Math.max(Math.abs(ux), Math.abs(uy), Math.abs(uz)));
        var ev = frexpExp(Math.max(Math.abs(vx), Math.abs(vy), Math.abs(vz)));
        if (!(Number.isFinite(ux) && Number.isFinite(uy) && Number.isFinite(uz) && Number.isFinite(vx) && Number.isFinite(vy) && Number.isFinite(vz))) {
          ux = V[b] * 0.25 - V[a] * 0.25; uy = V[b + 1] * 0.25 - V[a + 1] * 0.25; uz = V[b + 2] * 0.25 - V[a + 2] * 0.25;
          vx = V[c] * 0.25 - V[a] * 0.25; vy = V[c + 1] * 0.25 - V[a + 1] * 0.25; vz = V[c + 2] * 0.25 - V[a + 2] * 0.25;
          eu = frexpExp(Math.max(Math.abs(ux), Math.abs(uy), Math.abs(uz)));
          ev = frexpExp(Math.max(Math.abs(vx), Math.abs(vy), Math.abs(vz)));
        }
        ux = ldexp(ux, -eu); uy = ldexp(uy, -eu); uz = ldexp(uz, -eu);
        vx = ldexp(vx, -ev); vy = ldexp(vy, -ev); vz = ldexp(vz, -ev);
        nx = uy * vz - uz * vy; ny = uz * vx - ux * vz; nz = ux * vy - uy * vx;
        var en = frexpExp(Math.max(Math.abs(nx), Math.abs(ny), Math.abs(nz)));
        nx = ldexp(nx, -en); ny = ldexp(ny, -en); nz = ldexp(nz, -en);
        var mag = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (mag > 0) {
          out[3 * f] = nx / mag;
          out[3 * f + 1] = ny / mag;
          out[3 * f + 2] = nz / mag;
        }
      }
    }
    return out;
  }

  function encodeText(lines) {
    return new TextEncoder().encode(lines.join("\n") + "\n");
  }

  /**
   * The mesh as a file in its own format and encoding, written as trinormal.mesh.write_mesh
   * writes it (byte for byte): a Uint8Array.
   */
  function write(mesh, faces) {
    var V = mesh.vertices;
    var nv = V.length / 3;
    var nf = faces.length / 3;
    var lines = [];
    var i, k;
    if (mesh.format === "obj") {
      lines.push("# written by trinormal");
      for (i = 0; i < nv; i++) lines.push("v " + repr(V[3 * i]) + " " + repr(V[3 * i + 1]) + " " + repr(V[3 * i + 2]));
      for (i = 0; i < nf; i++) lines.push("f " + (faces[3 * i] + 1) + " " + (faces[3 * i + 1] + 1) + " " + (faces[3 * i + 2] + 1));
      return encodeText(lines);
    }
    if (mesh.format === "stl") {
      var normals = facetNormals(V, faces);
      if (mesh.binary) {
        var buf = new ArrayBuffer(84 + 50 * nf);
        var view = new DataView(buf);
        var head = "binary STL written by trinormal";
        for (i = 0; i < 80; i++) view.setUint8(i, i < head.length ? head.charCodeAt(i) : 32);
        view.setUint32(80, nf, true);
        for (i = 0; i < nf; i++) {
          var base = 84 + 50 * i;
          for (k = 0; k < 3; k++) view.setFloat32(base + 4 * k, normals[3 * i + k], true);
          for (var c = 0; c < 3; c++) {
            var p = 3 * faces[3 * i + c];
            for (var a = 0; a < 3; a++) view.setFloat32(base + 12 + 12 * c + 4 * a, V[p + a], true);
          }
        }
        return new Uint8Array(buf);
      }
      lines.push("solid trinormal");
      for (i = 0; i < nf; i++) {
        lines.push("facet normal " + repr(normals[3 * i]) + " " + repr(normals[3 * i + 1]) + " " + repr(normals[3 * i + 2]));
        lines.push("outer loop");
        for (k = 0; k < 3; k++) {
          var q = 3 * faces[3 * i + k];
          lines.push("vertex " + repr(V[q]) + " " + repr(V[q + 1]) + " " + repr(V[q + 2]));
        }
        lines.push("endloop");
        lines.push("endfacet");
      }
      lines.push("endsolid trinormal");
      return encodeText(lines);
    }
    // PLY: float32 coordinates when every one is a float32 number, float64 otherwise
    var single = true;
    for (i = 0; i < V.length && single; i++) single = Math.fround(V[i]) === V[i];
    var vtype = single ? "float" : "double";
    var header = [
      "ply",
      "format " + (mesh.binary ? "binary_little_endian" : "ascii") + " 1.0",
      "comment written by trinormal",
      "element vertex " + nv,
      "property " + vtype + " x",
      "property " + vtype + " y",
      "property " + vtype + " z",
      "element face " + nf,
      "property list uchar int vertex_indices",
      "end_header",
    ];
    if (!mesh.binary) {
      for (i = 0; i < nv; i++) header.push(repr(V[3 * i]) + " " + repr(V[3 * i + 1]) + " " + repr(V[3 * i + 2]));
      for (i = 0; i < nf; i++) header.push("3 " + faces[3 * i] + " " + faces[3 * i + 1] + " " + faces[3 * i + 2]);
      return encodeText(header);
    }
    var headBytes = new TextEncoder().encode(header.join("\n") + "\n");
    var size = single ? 4 : 8;
    var out = new Uint8Array(headBytes.length + 3 * size * nv + 13 * nf);
    out.set(headBytes, 0);
    var dv = new DataView(out.buffer);
    var at = headBytes.length;
    for (i = 0; i < 3 * nv; i++, at += size) {
      if (single) dv.setFloat32(at, V[i], true);
      else dv.setFloat64(at, V[i], true);
    }
    for (i = 0; i < nf; i++) {
      dv.setUint8(at, 3);
      at += 1;
      for (var j = 0; j < 3; j++, at += 4) dv.setInt32(at, faces[3 * i + j], true);
    }
    return out;
  }

  // ------------------------------------------------------------------ the summary in words

  function counted(n, noun) {
    var forms = MESH.nouns[noun];
    return n + " " + (n === 1 ? forms[0] : forms[1]);
  }

  /** A sentence of the summary: a template, or a (one, many) pair chosen by values.n. */
  function sentence(key, values) {
    var t = MESH.summary[key];
    if (Array.isArray(t)) t = values.n === 1 ? t[0] : t[1];
    return t.replace(/\{(\w+)\}/g, function (m, name) {
      return values[name] !== undefined ? String(values[name]) : m;
    });
  }

  /** The report in plain sentences, one finding per line: MeshReport.summary() of Python. */
  function summary(r) {
    var lines = [
      sentence("sizes", {
        vertices: counted(r.n_vertices, "vertex"),
        triangles: counted(r.n_faces, "triangle"),
        pieces: counted(r.n_components, "piece"),
      }),
    ];
    if (r.ok) {
      lines.push(sentence("ok", {}));
      return lines;
    }
    var nd = r.degenerate_faces.length;
    if (nd) {
      var parts = [];
      if (r.coincident_faces.length) parts.push(sentence("coincident", { n: r.coincident_faces.length }));
      if (r.collinear_faces.length) parts.push(sentence("collinear", { n: r.collinear_faces.length }));
      lines.push(sentence("degenerate", { n: nd, parts: parts.join(", ") }));
    }
    var simple = [
      ["duplicate", r.duplicate_faces],
      ["reversed_duplicate", r.reversed_duplicate_faces],
      ["unused", r.unused_vertices],
      ["boundary", r.boundary_edges],
      ["non_manifold_edges", r.non_manifold_edges],
      ["non_manifold_vertices", r.non_manifold_vertices],
    ];
    for (var i = 0; i < simple.length; i++) {
      if (simple[i][1].length) lines.push(sentence(simple[i][0], { n: simple[i][1].length }));
    }
    var many = r.components.length > 1;
    var anyClosed = false;
    r.components.forEach(function (c, j) {
      if (c.closed) anyClosed = true;
      var name = many ? sentence("piece", { i: j + 1, faces: counted(c.faces, "face") }) : sentence("whole", {});
      if (!c.orientable) lines.push(sentence("not_orientable", { name: name }));
      else if (!c.consistent) lines.push(sentence("inconsistent", { name: name }));
      else if (c.closed && c.outward === false) lines.push(sentence("inside_out", { name: name }));
      else if (c.closed && c.outward === null) lines.push(sentence("no_volume", { name: name }));
    });
    var nFlip = r.faces_to_flip.length;
    if (nFlip) {
      lines.push(sentence("flip", { n: nFlip, end: sentence(anyClosed ? "flip_end_closed" : "flip_end_open", {}) }));
    }
    return lines;
  }

  /** The report without the view's private keys: what Python's to_dict() returns. */
  function toDict(report) {
    var out = {};
    Object.keys(report).forEach(function (k) {
      if (k.charAt(0) !== "_") out[k] = report[k];
    });
    return out;
  }

  return {
    MeshError: MeshError,
    FORMATS: FORMATS,
    LIMITS: LIMITS,
    message: message,
    grouped: grouped,
    fileSize: fileSize,
    sizeProblem: sizeProblem,
    read: read,
    check: check,
    toDict: toDict,
    summary: summary,
    counted: counted,
    degenerateFaces: degenerateFaces,
    fixWinding: fixWinding,
    write: write,
    repr: repr,
  };
});
