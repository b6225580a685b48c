/*
 * trinormal's mesh check in the browser, part 2 of 7: the OBJ, STL and PLY readers, as
 * trinormal/mesh/io.py reads (the same vertices and faces in the same order, the same error
 * for the same bad file). Loaded after trinormal-mesh-base.js; see there how the parts fit.
 */
self.TrinormalMesh.part("read", "base", function (base) {
  "use strict";
  var I = base.internal;
  var MeshError = base.MeshError;
  var message = base.message;
  var grouped = base.grouped;
  var fileError = I.fileError, plural = I.plural, show = I.show;
  var splitlines = I.splitlines, tokens = I.tokens, pyFloat = I.pyFloat, pyInt = I.pyInt;
  var number = I.number, text = I.text, latin1 = I.latin1, Growable = I.Growable;

  var FORMATS = ["obj", "stl", "ply"];

  /** The format a file's name gives: its extension, as Python's os.path.splitext finds it. */
  function extension(name) {
    var base = String(name).slice(String(name).lastIndexOf("/") + 1);
    var dot = base.lastIndexOf(".");
    // a name that is only dots before its last dot (".obj", "..obj") has no extension
    if (dot < 0 || /^\.*$/.test(base.slice(0, dot))) return "";
    return base.slice(dot + 1).toLowerCase();
  }

  /**
   * Triangles made of polygons, split in their planes (splitPolygon), and what the split found:
   * how many polygons, how many had more than 3 corners, which triangle came from which polygon,
   * how many polygons are not planar or cross themselves, and whether all of them are quads.
   */
  function Polygons(V) {
    this.V = V;
    this.faces = new Growable(Uint32Array, 1024);
    this.source = new Growable(Uint32Array, 1024);
    this.count = 0;
    this.split = 0;
    this.nonplanar = 0;
    this.crossing = 0;
    this.quads = true;
  }
  Polygons.prototype.add = function (corners) {
    var n = corners.length;
    var tris = [[0, 1, 2]];
    if (n > 3) {
      var points = corners.map(function (c) { return [this.V[3 * c], this.V[3 * c + 1], this.V[3 * c + 2]]; }, this);
      var r = splitPolygon(points);
      tris = r.triangles;
      if (r.nonplanar) this.nonplanar++;
      if (r.crossing) this.crossing++;
    }
    for (var t = 0; t < tris.length; t++) {
      for (var k = 0; k < 3; k++) this.faces.push(corners[tris[t][k]]);
      this.source.push(this.count);
    }
    if (n !== 4) this.quads = false;
    this.count++;
    if (n > 3) this.split++;
  };
  /** What a reader returns of its polygons (with vertices, binary and notes added). */
  Polygons.prototype.result = function () {
    return {
      faces: this.faces.array(), source: this.source.array(), polygons: this.count, split_polygons: this.split,
      nonplanar_polygons: this.nonplanar, crossing_polygons: this.crossing, quads: this.quads && this.count > 0,
    };
  };

  // ------------------------------------------------------------------ polygons (trinormal/mesh/polygons.py)

  var PLANAR_TOL = base.internal.MESH.planar_tol;

  function orient(xs, ys, a, b, c) {
    return (xs[b] - xs[a]) * (ys[c] - ys[a]) - (ys[b] - ys[a]) * (xs[c] - xs[a]);
  }

  /**
   * One polygon ([x, y, z] corners) split by ear clipping in its plane, as Python's
   * split_polygon, operation for operation: {triangles: [[i, j, k]...], nonplanar, crossing}.
   */
  function splitPolygon(points) {
    var n = points.length, i;
    var fan = [];
    for (i = 1; i + 1 < n; i++) fan.push([0, i, i + 1]);
    var p0 = points[0];
    var d = points.map(function (p) { return [p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]]; });
    var m = 0;
    d.forEach(function (p) { m = Math.max(m, Math.max(Math.abs(p[0]), Math.abs(p[1]), Math.abs(p[2]))); });
    if (!(m > 0 && Number.isFinite(m))) return { triangles: fan, nonplanar: false, crossing: false };
    var q = d.map(function (p) { return [p[0] / m, p[1] / m, p[2] / m]; });
    var nx = 0, ny = 0, nz = 0;
    for (i = 0; i < n; i++) {
      var a = q[i], b = q[(i + 1) % n];
      nx += (a[1] - b[1]) * (a[2] + b[2]);
      ny += (a[2] - b[2]) * (a[0] + b[0]);
      nz += (a[0] - b[0]) * (a[1] + b[1]);
    }
    var u, v, s;
    if (Math.abs(nz) >= Math.abs(nx) && Math.abs(nz) >= Math.abs(ny)) { u = 0; v = 1; s = nz; }
    else if (Math.abs(ny) >= Math.abs(nx)) { u = 2; v = 0; s = ny; }
    else { u = 1; v = 2; s = nx; }
    var xs, ys;
    if (s === 0) {
      var spread = [0, 1, 2].map(function (k) {
        var hi = -Infinity, lo = Infinity;
        q.forEach(function (p) { hi = Math.max(hi, p[k]); lo = Math.min(lo, p[k]); });
        return hi - lo;
      });
      var w = spread[2] <= spread[1] && spread[2] <= spread[0] ? 2 : spread[1] <= spread[0] ? 1 : 0;
      xs = q.map(function (p) { return p[(w + 1) % 3]; });
      ys = q.map(function (p) { return p[(w + 2) % 3]; });
      return { triangles: fan, nonplanar: false, crossing: crosses(xs, ys) };
    }
    var sign = s > 0 ? 1 : -1;
    var nonplanar = notPlanar(q, nx, ny, nz);
    xs = q.map(function (p) { return p[u]; });
    ys = q.map(function (p) { return p[v]; });
    var convex = n === 4;
    for (i = 0; i < 4 && convex; i++) convex = sign * orient(xs, ys, (i + 3) % 4, i, (i + 1) % 4) > 0;
    return { triangles: clip(xs, ys, sign), nonplanar: nonplanar, crossing: !convex && crosses(xs, ys) };
  }

  function notPlanar(q, nx, ny, nz) {
    var n = q.length, hi = -Infinity, lo = Infinity, longest = 0;
    for (var i = 0; i < n; i++) {
      var p = q[i], e = q[(i + 1) % n];
      var dot = p[0] * nx + p[1] * ny + p[2] * nz;
      hi = Math.max(hi, dot);
      lo = Math.min(lo, dot);
      var dx = e[0] - p[0], dy = e[1] - p[1], dz = e[2] - p[2];
      longest = Math.max(longest, dx * dx + dy * dy + dz * dz);
    }
    var norm = Math.sqrt(nx * nx + ny * ny + nz * nz);
    return hi - lo > PLANAR_TOL * Math.sqrt(longest) * norm;
  }

  function crosses(xs, ys) {
    var n = xs.length;
    function opposite(x, y) { return (x > 0 && y < 0) || (x < 0 && y > 0); }
    for (var i = 0; i < n - 2; i++) {
      for (var j = i + 2; j < n; j++) {
        if (i === 0 && j === n - 1) continue;
        var a = i, b = i + 1, c = j, d = (j + 1) % n;
        if (opposite(orient(xs, ys, a, b, c), orient(xs, ys, a, b, d)) && opposite(orient(xs, ys, c, d, a), orient(xs, ys, c, d, b))) return true;
      }
    }
    return false;
  }

  function clip(xs, ys, sign) {
    var rest = [];
    for (var i = 0; i < xs.length; i++) rest.push(i);
    var out = [];
    var at = 1;
    while (rest.length > 3) {
      var k = rest.length, found = -1, a, b, c;
      for (var t = 0; t < k; t++) {
        var pos = (at + t) % k;
        a = rest[(pos + k - 1) % k]; b = rest[pos]; c = rest[(pos + 1) % k];
        if (isEar(xs, ys, sign, rest, a, b, c)) { found = pos; break; }
      }
      if (found < 0) {
        for (var j = 1; j < k - 1; j++) out.push([rest[0], rest[j], rest[j + 1]]);
        return out;
      }
      out.push([a, b, c]);
      rest.splice(found, 1);
      at = found < rest.length ? found : 0;
    }
    out.push([rest[0], rest[1], rest[2]]);
    return out;
  }

  function isEar(xs, ys, sign, rest, a, b, c) {
    if (sign * orient(xs, ys, a, b, c) <= 0) return false;
    for (var i = 0; i < rest.length; i++) {
      var p = rest[i];
      if (p === a || p === b || p === c) continue;
      if ((xs[p] === xs[a] && ys[p] === ys[a]) || (xs[p] === xs[b] && ys[p] === ys[b]) || (xs[p] === xs[c] && ys[p] === ys[c])) continue;
      if (sign * orient(xs, ys, a, b, p) >= 0 && sign * orient(xs, ys, b, c, p) >= 0 && sign * orient(xs, ys, c, a, p) >= 0) return false;
    }
    return true;
  }

  // ------------------------------------------------------------------ OBJ

  var OBJ_IGNORED = new Set(
    (
      "vt vn vp g o s mg usemtl mtllib usemap maplib l p cstype deg bmat step curv curv2 surf " +
      "parm trim hole scrv sp end con bevel c_interp d_interp lod shadow_obj trace_obj ctech " +
      "stech call csh"
    ).split(" ")
  );

  function readObj(bytes, name, progress) {
    var lines = splitlines(text(bytes, name, "OBJ"));
    var coords = new Growable(Float64Array, 1024);
    var polys = [];
    var polyLines = [];
    var nv = 0;
    var statement = I.objStatements();
    for (var ln = 0; ln < lines.length; ln++) {
      if ((ln & 0xffff) === 0) progress(ln / lines.length);
      var lineno = ln + 1;
      var toks = statement(lines[ln]);
      if (!toks || !toks.length) continue;
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
          // (a BigInt when too large to be exact: no file has that many vertices)
          if (i > 0) poly.push(typeof i === "bigint" ? i - BigInt(1) : i - 1);
          else if (i < 0) {
            if (-i > nv) fileError(name, lineno, "obj_back", { index: i, count: nv, vertices: plural(nv, "vertex", "vertices") });
            poly.push(nv + i);
          } else fileError(name, lineno, "obj_zero", {});
        }
        polys.push(poly);
        polyLines.push(lineno);
      } else if (!OBJ_IGNORED.has(kw)) {
        fileError(name, lineno, "obj_statement", { token: show(kw) });
      }
    }
    if (nv === 0 && !polys.length) fileError(name, null, "obj_empty", {});
    var V = coords.array();
    var out = new Polygons(V);
    for (var k = 0; k < polys.length; k++) {
      for (var c = 0; c < polys[k].length; c++) {
        var index = polys[k][c];
        if (index >= nv) {
          var shown = typeof index === "bigint" ? index + BigInt(1) : index + 1;
          fileError(name, polyLines[k], "obj_index_range", { face: k + 1, index: shown, count: nv, vertices: plural(nv, "vertex", "vertices") });
        }
      }
      out.add(polys[k]);
    }
    return Object.assign(out.result(), { vertices: V, binary: false });
  }

  // ------------------------------------------------------------------ STL

  /**
   * Corners with exactly equal coordinates become one vertex, numbered in order of first use
   * (-0 equals 0). `corners` holds 9 numbers per triangle.
   */
  function mergeCorners(corners, progress) {
    var n = corners.length / 3;
    var table = I.slotTable(n);
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
      var slot = I.fmix(h) & table.mask;
      for (;;) {
        var at = table.slots[slot];
        if (at < 0) {
          table.slots[slot] = nv;
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
        slot = (slot + 1) & table.mask;
      }
    }
    return { vertices: out.slice(0, 3 * nv), faces: faces };
  }

  /** What the STL readers return: each triangle is its own face. */
  function stlMesh(merged, binary, notes) {
    var n = merged.faces.length / 3;
    return {
      vertices: merged.vertices, faces: merged.faces, source: I.identity(n), polygons: n, split_polygons: 0,
      nonplanar_polygons: 0, crossing_polygons: 0, quads: false, binary: binary, notes: notes,
    };
  }

  function readStl(bytes, name, progress) {
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    if (bytes.length >= 84) {
      var n = view.getUint32(80, true);
      var notes = [];
      if (bytes.length !== 84 + 50 * n && !looksLikeText(bytes)) {
        var held = recordsIn(bytes.length, n, name);
        n = held.n;
        notes = held.notes;
      }
      if (bytes.length === 84 + 50 * n || notes.length) {
        // a binary STL, even when its header starts with "solid"
        I.checkFaceCount(name, n);
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
        return stlMesh(merged, true, notes);
      }
    }
    if (!looksLikeText(bytes)) fileError(name, null, "stl_short", {});
    return readStlAscii(bytes, name, progress);
  }

  /** Whether the file can be a text STL: it starts with "solid" and has no NUL byte. */
  function looksLikeText(bytes) {
    var start = 0;
    while (start < bytes.length && (bytes[start] === 32 || (bytes[start] >= 9 && bytes[start] <= 13))) start++;
    return latin1(bytes.subarray(start, start + 5)).toLowerCase() === "solid" && bytes.indexOf(0) < 0;
  }

  /**
   * How many triangles a binary STL of `size` bytes whose count `n` disagrees with its size
   * holds, and the note (stl.py's _records_in): the bytes after the header are whole 50-byte
   * records, or the n records and fewer than 50 bytes more; any other size is not an STL file.
   */
  function recordsIn(size, n, name) {
    var whole = Math.floor((size - 84) / 50), extra = (size - 84) % 50;
    if (extra === 0 && whole > 0) {
      return { n: whole, notes: [name + ": " + message("stl_count", { count: grouped(n), records: grouped(whole), size: grouped(size - 84) })] };
    }
    if (whole === n) return { n: n, notes: [name + ": " + message("stl_trailing", { extra: extra, bytes: extra === 1 ? "byte" : "bytes" })] };
    fileError(name, null, "stl_not_stl", { count: grouped(n), expected: grouped(84 + 50 * n), size: grouped(size) });
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
    return stlMesh(merged, false, []);
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

  /**
   * A PLY file's header, as ply.py's _ply_header reads it: {fmt, elements (name, count, rows,
   * props: {name, type, count}, line), bodyStart, bodyLine, vert}; a bad header throws Python's error.
   */
  function plyHeader(bytes, name) {
    var end = findBytes(bytes, "end_header", 0);
    if (!(bytes[0] === 112 && bytes[1] === 108 && bytes[2] === 121) || end < 0) fileError(name, 1, "ply_not_ply", {});
    var nl = bytes.indexOf(10, end);
    var bodyStart = nl < 0 ? bytes.length : nl + 1;
    var header = splitlines(latin1(bytes.subarray(0, end)));
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
        // `rows` as written, exact (a BigInt when huge) for messages; `count` for arithmetic
        var rows = pyInt(toks[2]);
        elements.push({ name: toks[1], count: Number(rows), rows: rows, props: [], line: lineno });
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
    var vert = elements.find(function (e) { return e.name === "vertex"; });
    if (!vert) fileError(name, null, "ply_no_vertex", {});
    if (!isFixed(vert)) fileError(name, vert.line, "ply_vertex_list", {});
    ["x", "y", "z"].forEach(function (axis) {
      var has = vert.props.some(function (p) { return p.name === axis && p.count === null; });
      if (!has) fileError(name, vert.line, "ply_no_axis", { axis: axis });
    });
    return { fmt: fmt, elements: elements, bodyStart: bodyStart, bodyLine: header.length + 2, vert: vert };
  }

  function readPly(bytes, name, progress) {
    var head = plyHeader(bytes, name);
    var fmt = head.fmt, elements = head.elements, bodyStart = head.bodyStart, vert = head.vert;
    var face = elements.find(function (e) { return e.name === "face"; });
    if (face) I.checkFaceCount(name, face.rows);
    var values =
      fmt === "ascii"
        ? plyAscii(bytes, bodyStart, head.bodyLine, elements, name, progress)
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
    var out = new Polygons(vertices);
    for (var q = 0; q < polys.length; q++) {
      if (polys[q].length < 3) fileError(name, null, "ply_corners", { face: q, count: polys[q].length });
      for (var c = 0; c < polys[q].length; c++) {
        var idx = polys[q][c];
        if (!(idx >= 0 && idx < nv && Number.isInteger(idx))) { // a float list's 1.5 is no vertex
          var valid = nv ? message("ply_valid", { last: nv - 1 }) : message("ply_no_vertices", {});
          fileError(name, null, "ply_index_range", { face: q, index: idx, valid: valid });
        }
      }
      out.add(polys[q]);
    }
    var normals = null;
    if (v.nx && v.ny && v.nz) {
      normals = new Float64Array(3 * nv);
      for (r = 0; r < nv; r++) {
        normals[3 * r] = v.nx[r];
        normals[3 * r + 1] = v.ny[r];
        normals[3 * r + 2] = v.nz[r];
      }
    }
    return Object.assign(out.result(), { vertices: vertices, binary: fmt !== "ascii", vertex_normals: normals });
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

  /** The bytes of one row of an element without lists. */
  function rowSize(el) {
    return el.props.reduce(function (size, p) { return size + p.type[1]; }, 0);
  }

  function plyAscii(bytes, start, firstLine, elements, name, progress) {
    var lines = splitlines(text(bytes.subarray(start), name, "PLY"));
    var out = {};
    var pos = 0;
    elements.forEach(function (el) {
      if (pos + el.count > lines.length) {
        fileError(name, firstLine + lines.length - 1, "ply_ascii_short", {
          rows: Math.max(lines.length - pos, 0), count: el.rows, element: el.name,
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
            if (typeof n === "bigint") n = undefined; // more items than any row has
            var items = [];
            if (n !== undefined && n >= 0) {
              var isFloat = p2.type[0].charAt(0) === "F";
              for (var q = t + 1; q < Math.min(t + 1 + n, row.length); q++) {
                // a list's items are numbers of its type; vertex indices must be whole numbers
                var x = isFloat ? pyFloat(row[q]) : pyInt(row[q]);
                if (isFloat && p2.name === want && !Number.isInteger(x)) x = undefined;
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
        var item = rowSize(el);
        if (pos + item * el.count > size) {
          fileError(name, null, "ply_binary_short", {
            element: el.name, rows: Math.floor((size - pos) / Math.max(item, 1)), count: el.rows,
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
            if (pos > size) fileError(name, null, "ply_binary_row", { element: el.name, row: r2, count: el.rows });
            continue;
          }
          if (pos + p2.count[1] > size) fileError(name, null, "ply_binary_row", { element: el.name, row: r2, count: el.rows });
          var n = view["get" + p2.count[0]](pos, little);
          pos += p2.count[1];
          if (n < 0) fileError(name, null, "ply_negative", { element: el.name, row: r2, count: n });
          if (pos + n * p2.type[1] > size) fileError(name, null, "ply_binary_row", { element: el.name, row: r2, count: el.rows });
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
   * split_polygons, notes: Python's MeshData.notes}; throws MeshError with Python's sentence (or the page's own, for its limits).
   */
  function read(buffer, name, onProgress) {
    var bytes = buffer instanceof Uint8Array ? buffer : new Uint8Array(buffer);
    var progress = onProgress || function () {};
    var ext = extension(name);
    if (FORMATS.indexOf(ext) < 0) fileError(name, null, "unknown_format", { ext: ext ? "." + ext : message("no_extension", {}) });
    var tooLarge = base.sizeProblem(name, bytes.length);
    if (tooLarge) throw new MeshError(tooLarge);
    if (bytes.length === 0) fileError(name, null, "no_faces", {});
    var mesh = ext === "obj" ? readObj(bytes, name, progress) : ext === "stl" ? readStl(bytes, name, progress) : readPly(bytes, name, progress);
    mesh.format = ext;
    mesh.name = name;
    mesh.notes = mesh.notes || [];
    mesh.bytes = bytes;
    if (mesh.faces.length === 0) fileError(name, null, "no_faces", {});
    I.checkFaceCount(name, mesh.faces.length / 3);
    return mesh;
  }

  return { FORMATS: FORMATS, read: read, plyLayout: { header: plyHeader, faceListName: faceListName, isFixed: isFixed, rowSize: rowSize } };
});
