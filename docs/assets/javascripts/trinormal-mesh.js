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

  // ------------------------------------------------------------------ format detection

  var FORMATS = ["obj", "stl", "ply"];

  function extension(name) {
    var m = /\.([A-Za-z0-9]+)$/.exec(String(name || ""));
    return m ? m[1].toLowerCase() : "";
  }

  function startsWith(bytes, text) {
    if (bytes.length < text.length) return false;
    for (var i = 0; i < text.length; i++) if (bytes[i] !== text.charCodeAt(i)) return false;
    return true;
  }

  /** The format of a file: "obj", "stl" or "ply", from its extension (and first bytes). */
  function detectFormat(bytes, name) {
    var ext = extension(name);
    if (FORMATS.indexOf(ext) >= 0) return ext;
    if (startsWith(bytes, "ply")) return "ply";
    if (startsWith(bytes, "solid") || isBinaryStl(bytes)) return "stl";
    fail("unknown_format", { name: name, formats: FORMATS.map(function (f) { return f.toUpperCase(); }).join(", ") });
  }

  function isBinaryStl(bytes) {
    if (bytes.length < 84) return false;
    var n = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(80, true);
    return 84 + 50 * n === bytes.length;
  }

  function looksLikeText(bytes, limit) {
    var n = Math.min(bytes.length, limit || 4096);
    for (var i = 0; i < n; i++) {
      var b = bytes[i];
      if (b === 0 || (b < 32 && b !== 9 && b !== 10 && b !== 13 && b !== 12 && b !== 11)) return false;
    }
    return true;
  }

  // ------------------------------------------------------------------ text lines

  var decoder = typeof TextDecoder !== "undefined" ? new TextDecoder("utf-8", { fatal: false }) : null;

  function decode(bytes) {
    return decoder.decode(bytes);
  }

  /**
   * A number written in a text mesh file, or NaN when it is not one. Python's float() rules:
   * decimal and exponent forms, "inf"/"nan" words are refused later as not finite.
   */
  var NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
  function readNumber(token) {
    return NUMBER.test(token) ? Number(token) : NaN;
  }

  function checkFinite(x, line, what, name) {
    if (!Number.isFinite(x)) fail("bad_number", { name: name, line: line, what: what });
    return x;
  }

  // ------------------------------------------------------------------ OBJ

  function readObj(bytes, name, progress) {
    if (!looksLikeText(bytes)) fail("not_text", { name: name, format: "OBJ" });
    var text = decode(bytes);
    var coords = new Growable(Float64Array, 1024);
    var faces = new Growable(Uint32Array, 1024);
    var polygons = 0;
    var split = 0;
    var nv = 0;
    var pos = 0;
    var lineNo = 0;
    var total = text.length;
    var nextReport = 0;
    var cornerBuf = [];
    while (pos < total) {
      var end = text.indexOf("\n", pos);
      if (end < 0) end = total;
      lineNo++;
      var line = text.slice(pos, end);
      pos = end + 1;
      if (pos > nextReport) {
        progress(pos / total);
        nextReport = pos + (1 << 20);
      }
      var c0 = line.charCodeAt(0);
      if (c0 !== 118 && c0 !== 102 && c0 !== 32 && c0 !== 9) continue; // v, f, or indented
      var t = line.trim();
      if (t.length < 2) continue;
      var head = t.charCodeAt(0);
      var sep = t.charCodeAt(1);
      if (sep !== 32 && sep !== 9) continue;
      if (head === 118) {
        // v x y z [w | r g b]
        var parts = t.split(/\s+/);
        if (parts.length < 4) fail("obj_vertex", { name: name, line: lineNo });
        for (var k = 1; k <= 3; k++) {
          coords.push(checkFinite(readNumber(parts[k]), lineNo, "xyz"[k - 1], name));
        }
        nv++;
      } else if (head === 102) {
        var items = t.split(/\s+/);
        var nc = items.length - 1;
        if (nc < 3) fail("obj_face_short", { name: name, line: lineNo });
        cornerBuf.length = 0;
        for (var j = 1; j <= nc; j++) {
          var tok = items[j];
          var slash = tok.indexOf("/");
          var idx = slash < 0 ? tok : tok.slice(0, slash);
          if (!/^[+-]?\d+$/.test(idx)) fail("obj_index", { name: name, line: lineNo, index: tok });
          var i = parseInt(idx, 10);
          var v = i > 0 ? i - 1 : i < 0 ? nv + i : -1;
          if (v < 0 || v >= nv) fail("obj_index_range", { name: name, line: lineNo, index: idx, count: nv });
          cornerBuf.push(v);
        }
        polygons++;
        if (nc > 3) split++;
        for (var q = 1; q + 1 < nc; q++) {
          faces.push(cornerBuf[0]);
          faces.push(cornerBuf[q]);
          faces.push(cornerBuf[q + 1]);
        }
      }
    }
    if (nv === 0 && faces.length === 0) fail("empty", { name: name, format: "OBJ" });
    return {
      vertices: coords.array(),
      faces: faces.array(),
      polygons: polygons,
      split_polygons: split,
    };
  }

  // ------------------------------------------------------------------ STL

  /**
   * Corners with exactly equal coordinates become one vertex, in the order they first appear
   * (x == y for numbers: 0 and -0 are equal). `corners` holds 9 numbers per triangle.
   */
  /** murmur3's finaliser: every bit of h reaches the low bits used as a table slot. */
  function fmix(h) {
    h ^= h >>> 16;
    h = Math.imul(h, 0x85ebca6b);
    h ^= h >>> 13;
    h = Math.imul(h, 0xc2b2ae35);
    return h ^ (h >>> 16);
  }

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
      h = fmix(h);
      var slot = h & mask;
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

  function readStlBinary(bytes, name, progress) {
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    var n = view.getUint32(80, true);
    if (n > LIMITS.max_faces) fail("too_many_faces", { name: name, count: n, max: LIMITS.max_faces });
    var corners = new Float64Array(9 * n);
    for (var i = 0; i < n; i++) {
      if ((i & 0xffff) === 0) progress(0.4 * (i / n));
      var base = 84 + 50 * i + 12;
      for (var k = 0; k < 9; k++) {
        var x = view.getFloat32(base + 4 * k, true);
        if (!Number.isFinite(x)) {
          fail("stl_binary_number", { name: name, facet: i + 1, what: "ABC"[Math.floor(k / 3)] + "." + "xyz"[k % 3] });
        }
        corners[9 * i + k] = x;
      }
    }
    var merged = mergeCorners(corners, function (p) { progress(0.4 + 0.6 * p); });
    return { vertices: merged.vertices, faces: merged.faces, polygons: n, split_polygons: 0 };
  }

  function readStlAscii(bytes, name, progress) {
    if (!looksLikeText(bytes)) fail("not_text", { name: name, format: "STL" });
    var text = decode(bytes);
    var corners = new Growable(Float64Array, 4096);
    var lineNo = 0;
    var pos = 0;
    var total = text.length;
    var inLoop = 0; // corners in the current loop, -1 outside a loop
    var loopLine = 0;
    var facets = 0;
    var sawSolid = false;
    var nextReport = 0;
    inLoop = -1;
    while (pos < total) {
      var end = text.indexOf("\n", pos);
      if (end < 0) end = total;
      lineNo++;
      var t = text.slice(pos, end).trim();
      pos = end + 1;
      if (pos > nextReport) {
        progress(0.5 * (pos / total));
        nextReport = pos + (1 << 20);
      }
      if (!t) continue;
      var parts = t.split(/\s+/);
      var word = parts[0].toLowerCase();
      if (word === "vertex") {
        if (inLoop < 0) fail("stl_syntax", { name: name, line: lineNo, found: parts[0] });
        if (parts.length !== 4) fail("stl_vertex", { name: name, line: lineNo });
        for (var k = 1; k <= 3; k++) corners.push(checkFinite(readNumber(parts[k]), lineNo, "xyz"[k - 1], name));
        inLoop++;
      } else if (word === "outer") {
        inLoop = 0;
        loopLine = lineNo;
      } else if (word === "endloop") {
        if (inLoop !== 3) fail("stl_loop", { name: name, line: loopLine, count: Math.max(inLoop, 0) });
        inLoop = -1;
        facets++;
      } else if (word === "solid") {
        sawSolid = true;
      } else if (word === "facet" || word === "endfacet" || word === "endsolid") {
        // structure only
      } else {
        fail("stl_syntax", { name: name, line: lineNo, found: parts[0] });
      }
    }
    if (!sawSolid) fail("stl_syntax", { name: name, line: 1, found: "" });
    if (facets === 0) fail("empty", { name: name, format: "STL" });
    var merged = mergeCorners(corners.array(), function (p) { progress(0.5 + 0.5 * p); });
    return { vertices: merged.vertices, faces: merged.faces, polygons: facets, split_polygons: 0 };
  }

  function readStl(bytes, name, progress) {
    if (isBinaryStl(bytes)) return Object.assign(readStlBinary(bytes, name, progress), { binary: true });
    if (startsWith(bytes, "solid") && looksLikeText(bytes)) {
      return Object.assign(readStlAscii(bytes, name, progress), { binary: false });
    }
    if (bytes.length >= 84) {
      var n = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(80, true);
      fail("stl_size", { name: name, count: n, expected: 84 + 50 * n, size: bytes.length });
    }
    fail("stl_short", { name: name, size: bytes.length });
  }

  // ------------------------------------------------------------------ PLY

  var PLY_TYPES = {
    char: ["Int8", 1], int8: ["Int8", 1],
    uchar: ["Uint8", 1], uint8: ["Uint8", 1],
    short: ["Int16", 2], int16: ["Int16", 2],
    ushort: ["Uint16", 2], uint16: ["Uint16", 2],
    int: ["Int32", 4], int32: ["Int32", 4],
    uint: ["Uint32", 4], uint32: ["Uint32", 4],
    float: ["Float32", 4], float32: ["Float32", 4],
    double: ["Float64", 8], float64: ["Float64", 8],
  };

  function plyHeader(bytes, name) {
    // the header is text up to "end_header\n"
    var limit = Math.min(bytes.length, 1 << 16);
    var headText = "";
    for (var i = 0; i < limit; i++) headText += String.fromCharCode(bytes[i]);
    var m = /end_header[ \t]*\r?\n/.exec(headText);
    if (!m) fail("ply_header", { name: name, line: headText.split("\n").length, what: "end_header" });
    var lines = headText.slice(0, m.index).split(/\r?\n/);
    var header = { format: null, elements: [], bodyStart: m.index + m[0].length, lines: lines.length + 1 };
    var current = null;
    for (var ln = 0; ln < lines.length; ln++) {
      var p = lines[ln].trim().split(/\s+/);
      var lineNo = ln + 1;
      if (ln === 0) {
        if (p[0] !== "ply") fail("ply_header", { name: name, line: 1, what: "ply" });
        continue;
      }
      if (p[0] === "format") {
        if (["ascii", "binary_little_endian", "binary_big_endian"].indexOf(p[1]) < 0) {
          fail("ply_header", { name: name, line: lineNo, what: "format" });
        }
        header.format = p[1];
      } else if (p[0] === "element") {
        var count = Number(p[2]);
        if (p.length < 3 || !Number.isInteger(count) || count < 0) fail("ply_header", { name: name, line: lineNo, what: "element" });
        current = { name: p[1], count: count, props: [] };
        header.elements.push(current);
      } else if (p[0] === "property") {
        if (!current) fail("ply_header", { name: name, line: lineNo, what: "element" });
        if (p[1] === "list") {
          if (!PLY_TYPES[p[2]] || !PLY_TYPES[p[3]] || !p[4]) fail("ply_header", { name: name, line: lineNo, what: "property" });
          current.props.push({ name: p[4], list: true, countType: PLY_TYPES[p[2]], type: PLY_TYPES[p[3]] });
        } else {
          if (!PLY_TYPES[p[1]] || !p[2]) fail("ply_header", { name: name, line: lineNo, what: "property" });
          current.props.push({ name: p[2], list: false, type: PLY_TYPES[p[1]] });
        }
      } else if (p[0] === "comment" || p[0] === "obj_info" || p[0] === "") {
        // nothing to read
      } else {
        fail("ply_header", { name: name, line: lineNo, what: p[0] });
      }
    }
    if (!header.format) fail("ply_header", { name: name, line: 2, what: "format" });
    return header;
  }

  function plyRoles(header, name) {
    var vertex = null;
    var face = null;
    header.elements.forEach(function (el) {
      if (el.name === "vertex") vertex = el;
      if (el.name === "face") face = el;
    });
    if (!vertex) fail("ply_no_vertices", { name: name });
    var xyz = ["x", "y", "z"].map(function (axis) {
      for (var i = 0; i < vertex.props.length; i++) if (vertex.props[i].name === axis && !vertex.props[i].list) return i;
      fail("ply_no_vertices", { name: name });
    });
    var list = -1;
    if (face) {
      for (var i = 0; i < face.props.length; i++) {
        var p = face.props[i];
        if (p.list && (p.name === "vertex_indices" || p.name === "vertex_index")) list = i;
      }
      if (list < 0) fail("ply_no_faces", { name: name });
    }
    return { vertex: vertex, face: face, xyz: xyz, list: list };
  }

  function readPly(bytes, name, progress) {
    if (!startsWith(bytes, "ply")) fail("ply_header", { name: name, line: 1, what: "ply" });
    var header = plyHeader(bytes, name);
    var roles = plyRoles(header, name);
    var nvTotal = roles.vertex.count;
    var nfTotal = roles.face ? roles.face.count : 0;
    if (nfTotal > LIMITS.max_faces) fail("too_many_faces", { name: name, count: nfTotal, max: LIMITS.max_faces });
    var coords = new Float64Array(3 * nvTotal);
    var faces = new Growable(Uint32Array, 3 * nfTotal);
    var polygons = 0;
    var split = 0;
    var corner = [];
    function addPolygon(where) {
      var nc = corner.length;
      if (nc < 3) fail("ply_face_short", { name: name, where: where });
      for (var k = 0; k < nc; k++) {
        var v = corner[k];
        if (!Number.isInteger(v) || v < 0 || v >= nvTotal) fail("ply_index_range", { name: name, where: where, index: v, count: nvTotal });
      }
      polygons++;
      if (nc > 3) split++;
      for (var q = 1; q + 1 < nc; q++) {
        faces.push(corner[0]);
        faces.push(corner[q]);
        faces.push(corner[q + 1]);
      }
    }
    if (header.format === "ascii") {
      if (!looksLikeText(bytes.subarray(header.bodyStart), 1 << 16)) fail("not_text", { name: name, format: "PLY" });
      var lines = decode(bytes.subarray(header.bodyStart)).split("\n");
      var li = 0;
      var lineNo = header.lines;
      var nextLine = function () {
        while (li < lines.length) {
          var t = lines[li++].trim();
          lineNo++;
          if (t) return t;
        }
        fail("ply_short", { name: name });
      };
      header.elements.forEach(function (el) {
        for (var r = 0; r < el.count; r++) {
          if ((r & 0xffff) === 0) progress(r / Math.max(1, el.count));
          var toks = nextLine().split(/\s+/);
          var ti = 0;
          var here = lineNo;
          var take = function () {
            if (ti >= toks.length) fail("ply_row", { name: name, line: here });
            var x = readNumber(toks[ti++]);
            if (!Number.isFinite(x)) fail("bad_number", { name: name, line: here, what: el.name });
            return x;
          };
          for (var pi = 0; pi < el.props.length; pi++) {
            var prop = el.props[pi];
            if (prop.list) {
              var cnt = take();
              if (!Number.isInteger(cnt) || cnt < 0) fail("ply_row", { name: name, line: here });
              if (el === roles.face && pi === roles.list) {
                corner.length = 0;
                for (var c = 0; c < cnt; c++) corner.push(take());
              } else {
                for (var c2 = 0; c2 < cnt; c2++) take();
              }
            } else {
              var val = take();
              if (el === roles.vertex) {
                var axis = roles.xyz.indexOf(pi);
                if (axis >= 0) coords[3 * r + axis] = val;
              }
            }
          }
          if (ti !== toks.length) fail("ply_row", { name: name, line: here });
          if (el === roles.face) addPolygon(message("where_line", { line: here }));
        }
      });
    } else {
      var little = header.format === "binary_little_endian";
      var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
      var at = header.bodyStart;
      var end = bytes.length;
      var get = function (type) {
        if (at + type[1] > end) fail("ply_short", { name: name });
        var x = view["get" + type[0]](at, little);
        at += type[1];
        return x;
      };
      header.elements.forEach(function (el) {
        for (var r = 0; r < el.count; r++) {
          if ((r & 0xffff) === 0) progress(r / Math.max(1, el.count));
          for (var pi = 0; pi < el.props.length; pi++) {
            var prop = el.props[pi];
            if (prop.list) {
              var cnt = get(prop.countType);
              if (el === roles.face && pi === roles.list) {
                corner.length = 0;
                for (var c = 0; c < cnt; c++) corner.push(get(prop.type));
              } else {
                if (at + cnt * prop.type[1] > end) fail("ply_short", { name: name });
                at += cnt * prop.type[1];
              }
            } else {
              var val = get(prop.type);
              if (el === roles.vertex) {
                var axis = roles.xyz.indexOf(pi);
                if (axis >= 0) {
                  if (!Number.isFinite(val)) fail("ply_binary_number", { name: name, row: r, what: "xyz"[axis] });
                  coords[3 * r + axis] = val;
                }
              }
            }
          }
          if (el === roles.face) addPolygon(message("where_face", { face: r }));
        }
      });
    }
    return {
      vertices: coords,
      faces: faces.array(),
      polygons: polygons,
      split_polygons: split,
      binary: header.format !== "ascii",
      ply_format: header.format,
    };
  }

  /**
   * Read a mesh file. `buffer` is an ArrayBuffer (or Uint8Array), `name` the file name.
   * Returns {format, binary, vertices: Float64Array (3 per vertex), faces: Uint32Array (3 per
   * triangle), polygons, split_polygons}; throws MeshError with the package's message.
   */
  function read(buffer, name, onProgress) {
    var bytes = buffer instanceof Uint8Array ? buffer : new Uint8Array(buffer);
    var progress = onProgress || function () {};
    if (bytes.length === 0) fail("empty_file", { name: name });
    if (bytes.length > LIMITS.max_bytes) fail("too_large", { name: name, size: bytes.length, max: LIMITS.max_bytes });
    var format = detectFormat(bytes, name);
    var mesh;
    if (format === "obj") mesh = Object.assign(readObj(bytes, name, progress), { binary: false });
    else if (format === "stl") mesh = readStl(bytes, name, progress);
    else mesh = readPly(bytes, name, progress);
    mesh.format = format;
    mesh.name = name;
    if (mesh.faces.length === 0) fail("no_faces", { name: name });
    if (mesh.faces.length / 3 > LIMITS.max_faces) fail("too_many_faces", { name: name, count: mesh.faces.length / 3, max: LIMITS.max_faces });
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
    var allClosed = nComp > 0, allConsistent = true, allOutward = true;
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
      if (closed[i] && entry.outward !== true) allOutward = false;
    }
    var ok =
      allClosed && allConsistent && allOutward &&
      !degenerate.length && !dups.same.length && !dups.reversed.length &&
      !nonManifoldVertices.length && !unused.length;
    progress(1);
    return {
      n_vertices: nv,
      n_faces: nf,
      n_components: nComp,
      closed: allClosed,
      consistent_winding: allConsistent,
      outward: allOutward,
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

  /** The faces with the report's faces_to_flip reversed (corners 1 and 2 swapped). */
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

  function num(x) {
    // shortest text that reads back as the same float64 (like Python's repr)
    return Object.is(x, -0) ? "-0.0" : Number.isInteger(x) && Math.abs(x) < 1e16 ? x.toFixed(1) : String(x);
  }

  /** The mesh as a file in its own format (binary stays binary): a Uint8Array. */
  function write(mesh, faces) {
    var V = mesh.vertices;
    var nv = V.length / 3;
    var nf = faces.length / 3;
    var parts = [];
    var i;
    if (mesh.format === "obj") {
      parts.push("# written by trinormal\n");
      for (i = 0; i < nv; i++) parts.push("v " + num(V[3 * i]) + " " + num(V[3 * i + 1]) + " " + num(V[3 * i + 2]) + "\n");
      for (i = 0; i < nf; i++) parts.push("f " + (faces[3 * i] + 1) + " " + (faces[3 * i + 1] + 1) + " " + (faces[3 * i + 2] + 1) + "\n");
      return new TextEncoder().encode(parts.join(""));
    }
    if (mesh.format === "stl" && mesh.binary) {
      var buf = new ArrayBuffer(84 + 50 * nf);
      var view = new DataView(buf);
      var head = "binary STL written by trinormal";
      for (i = 0; i < head.length; i++) view.setUint8(i, head.charCodeAt(i));
      view.setUint32(80, nf, true);
      for (i = 0; i < nf; i++) {
        var base = 84 + 50 * i;
        var n = faceNormal(V, faces, i);
        for (var k = 0; k < 3; k++) view.setFloat32(base + 4 * k, n[k], true);
        for (var c = 0; c < 3; c++) {
          var p = 3 * faces[3 * i + c];
          for (var a = 0; a < 3; a++) view.setFloat32(base + 12 + 12 * c + 4 * a, V[p + a], true);
        }
      }
      return new Uint8Array(buf);
    }
    if (mesh.format === "stl") {
      parts.push("solid trinormal\n");
      for (i = 0; i < nf; i++) {
        var nn = faceNormal(V, faces, i);
        parts.push(" facet normal " + nn.map(num).join(" ") + "\n  outer loop\n");
        for (var cc = 0; cc < 3; cc++) {
          var q = 3 * faces[3 * i + cc];
          parts.push("   vertex " + num(V[q]) + " " + num(V[q + 1]) + " " + num(V[q + 2]) + "\n");
        }
        parts.push("  endloop\n endfacet\n");
      }
      parts.push("endsolid trinormal\n");
      return new TextEncoder().encode(parts.join(""));
    }
    // PLY
    var fmt = mesh.binary ? "binary_little_endian" : "ascii";
    var header =
      "ply\nformat " + fmt + " 1.0\ncomment written by trinormal\nelement vertex " + nv +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " + nf +
      "\nproperty list uchar int vertex_indices\nend_header\n";
    if (!mesh.binary) {
      parts.push(header);
      for (i = 0; i < nv; i++) parts.push(num(V[3 * i]) + " " + num(V[3 * i + 1]) + " " + num(V[3 * i + 2]) + "\n");
      for (i = 0; i < nf; i++) parts.push("3 " + faces[3 * i] + " " + faces[3 * i + 1] + " " + faces[3 * i + 2] + "\n");
      return new TextEncoder().encode(parts.join(""));
    }
    var headBytes = new TextEncoder().encode(header);
    var out = new Uint8Array(headBytes.length + 24 * nv + 13 * nf);
    out.set(headBytes, 0);
    var dv = new DataView(out.buffer);
    var at = headBytes.length;
    for (i = 0; i < 3 * nv; i++, at += 8) dv.setFloat64(at, V[i], true);
    for (i = 0; i < nf; i++) {
      dv.setUint8(at, 3);
      at += 1;
      for (var j = 0; j < 3; j++, at += 4) dv.setInt32(at, faces[3 * i + j], true);
    }
    return out;
  }

  /** The unit normal of one face for an STL facet record (0, 0, 0 when degenerate). */
  function faceNormal(V, faces, f) {
    var a = 3 * faces[3 * f], b = 3 * faces[3 * f + 1], c = 3 * faces[3 * f + 2];
    var ux = V[b] - V[a], uy = V[b + 1] - V[a + 1], uz = V[b + 2] - V[a + 2];
    var vx = V[c] - V[a], vy = V[c + 1] - V[a + 1], vz = V[c + 2] - V[a + 2];
    var n = [uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx];
    var len = Math.hypot(n[0], n[1], n[2]);
    if (!(len > 0) || !Number.isFinite(len)) return [0, 0, 0];
    return [n[0] / len, n[1] / len, n[2] / len];
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
    read: read,
    check: check,
    toDict: toDict,
    summary: summary,
    degenerateFaces: degenerateFaces,
    fixWinding: fixWinding,
    write: write,
  };
});
