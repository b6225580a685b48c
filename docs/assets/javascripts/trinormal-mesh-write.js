/*
 * trinormal's mesh check in the browser, part 6 of 7: the winding fix and the writers, as
 * trinormal.mesh.fix_winding turns faces over and trinormal.mesh.write_mesh writes a file
 * (byte for byte). Loaded after trinormal-mesh-check.js; see trinormal-mesh-base.js for how
 * the parts fit.
 */
self.TrinormalMesh.part("write", "check", function (base) {
  "use strict";

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

  // ------------------------------------------------------------------ the file, faces turned over

  /**
   * Which faces of the file `faces` turns over (rewrite.py's _turned_polygons): more than half
   * of a polygon's triangles, or half and its first one. A Uint8Array flag per polygon, and
   * whether any is set.
   */
  function turnedPolygons(mesh, faces) {
    var old = mesh.faces, src = mesh.source, np = mesh.polygons;
    var n = new Uint32Array(np), k = new Uint32Array(np), first = new Uint8Array(np);
    for (var t = 0; t < src.length; t++) {
      var p = src[t];
      var changed = old[3 * t] !== faces[3 * t] || old[3 * t + 1] !== faces[3 * t + 1] || old[3 * t + 2] !== faces[3 * t + 2];
      if (n[p] === 0 && changed) first[p] = 1;
      n[p]++;
      if (changed) k[p]++;
    }
    var flags = new Uint8Array(np), any = false;
    for (p = 0; p < np; p++) {
      if (2 * k[p] > n[p] || (2 * k[p] === n[p] && first[p])) {
        flags[p] = 1;
        any = true;
      }
    }
    return { flags: flags, any: any };
  }

  /** The text of `bytes` as the readers decode it (UTF-8, else Latin-1), in lines with their breaks. */
  function decode(bytes) {
    var text, utf8 = true;
    try {
      text = new TextDecoder("utf-8", { fatal: true, ignoreBOM: true }).decode(bytes);
    } catch (err) {
      text = base.internal.latin1(bytes);
      utf8 = false;
    }
    var bom = text.charAt(0) === "\ufeff" ? "\ufeff" : "";
    text = text.slice(bom.length);
    var contents = base.internal.splitlines(text), lines = [], pos = 0;
    for (var i = 0; i < contents.length; i++) {
      pos += contents[i].length;
      var end = text.substr(pos, 2) === "\r\n" ? "\r\n" : text.charAt(pos);
      pos += end.length;
      lines.push([contents[i], end]);
    }
    return { lines: lines, bom: bom, utf8: utf8 };
  }

  function encode(doc, prefix) {
    var text = doc.bom + doc.lines.map(function (l) { return l[0] + l[1]; }).join("");
    var body;
    if (doc.utf8) body = new TextEncoder().encode(text);
    else {
      body = new Uint8Array(text.length);
      for (var i = 0; i < text.length; i++) body[i] = text.charCodeAt(i);
    }
    var out = new Uint8Array(prefix.length + body.length);
    out.set(prefix, 0);
    out.set(body, prefix.length);
    return out;
  }

  /** Where each token of a line starts and ends. */
  function spans(content) {
    var at = 0;
    return base.internal.tokens(content).map(function (tok) {
      at = content.indexOf(tok, at);
      at += tok.length;
      return [at - tok.length, at];
    });
  }

  function replaced(content, where, tokens) {
    var out = "", at = 0;
    for (var i = 0; i < where.length; i++) {
      out += content.slice(at, where[i][0]) + tokens[i];
      at = where[i][1];
    }
    return out + content.slice(at);
  }

  /** Corners of `per` items each: the first kept, the others in reverse order. */
  function reversedCorners(items, per) {
    var out = items.slice(0, per);
    for (var i = items.length - per; i >= per; i -= per) out = out.concat(items.slice(i, i + per));
    return out;
  }

  function turnObj(lines, flags) {
    var face = -1, first = null, logical = "";
    for (var i = 0; i < lines.length; i++) {
      var content = lines[i][0];
      if (content.charAt(content.length - 1) === "\\") {
        if (first === null) first = i;
        logical += content.slice(0, -1) + " ";
        continue;
      }
      var start = first === null ? i : first;
      var whole = logical + content;
      first = null;
      logical = "";
      var hash = whole.indexOf("#");
      var code = hash < 0 ? whole : whole.slice(0, hash);
      var toks = base.internal.tokens(code);
      if (!toks.length || (toks[0] !== "f" && toks[0] !== "fo")) continue;
      face++;
      if (!flags[face]) continue;
      var line = replaced(whole, spans(code), [toks[0]].concat(reversedCorners(toks.slice(1), 1)));
      for (var k = start; k < i; k++) lines[k] = ["", ""];
      lines[i] = [line, lines[i][1]];
    }
  }

  function turnStlAscii(lines, flags, normalOf) {
    var facet = -1, facetLine = null, loop = [];
    for (var i = 0; i < lines.length; i++) {
      var toks = base.internal.tokens(lines[i][0]);
      var kw = toks.length ? toks[0].toLowerCase() : "";
      if (kw === "facet") facetLine = i;
      else if (kw === "outer") loop = [];
      else if (kw === "vertex") loop.push(i);
      else if (kw === "endloop") {
        facet++;
        if (flags[facet]) {
          var b = lines[loop[1]][0];
          lines[loop[1]] = [lines[loop[2]][0], lines[loop[1]][1]];
          lines[loop[2]] = [b, lines[loop[2]][1]];
          if (facetLine !== null) {
            var where = spans(lines[facetLine][0]);
            if (where.length >= 5) {
              var t = base.internal.tokens(lines[facetLine][0]);
              var nrm = normalOf(facet);
              t[2] = repr(nrm[0]);
              t[3] = repr(nrm[1]);
              t[4] = repr(nrm[2]);
              lines[facetLine] = [replaced(lines[facetLine][0], where, t), lines[facetLine][1]];
            }
          }
        }
        facetLine = null;
      }
    }
  }

  /** The unit normals of the turned-over triangles, by face: normalOf(i) = [x, y, z]. */
  function normalsOf(mesh, faces, flags) {
    var list = [];
    for (var i = 0; i < flags.length; i++) if (flags[i]) list.push(i);
    var tri = new Uint32Array(3 * list.length);
    list.forEach(function (f, j) { tri.set(faces.subarray(3 * f, 3 * f + 3), 3 * j); });
    var n = base.internal.faceNormals(mesh.vertices, tri), at = {};
    list.forEach(function (f, j) { at[f] = j; });
    return function (f) { return [n[3 * at[f]], n[3 * at[f] + 1], n[3 * at[f] + 2]]; };
  }

  function turnStlBinary(mesh, flags, normalOf) {
    var out = new Uint8Array(mesh.bytes);
    var view = new DataView(out.buffer);
    for (var i = 0; i < flags.length; i++) {
      if (!flags[i]) continue;
      var at = 84 + 50 * i;
      var b = out.slice(at + 24, at + 36);
      out.copyWithin(at + 24, at + 36, at + 48);
      out.set(b, at + 36);
      var nrm = normalOf(i);
      for (var k = 0; k < 3; k++) view.setFloat32(at + 4 * k, nrm[k], true);
    }
    return out;
  }

  /** Turn over every list of a face row with a whole number of items per corner. */
  function turnLists(items, lists, want) {
    var corners = lists.find(function (l) { return l.name === want; }).n;
    lists.forEach(function (l) {
      if (l.n && corners >= 3 && l.n % corners === 0) {
        var turned = reversedCorners(items.slice(l.at, l.at + l.n), l.n / corners);
        for (var i = 0; i < l.n; i++) items[l.at + i] = turned[i];
      }
    });
  }

  function turnPly(mesh, flags) {
    var layout = base.plyLayout, bytes = mesh.bytes;
    var head = layout.header(bytes, mesh.name);
    var els = head.elements;
    var faceAt = els.findIndex(function (el) { return el.name === "face"; });
    var face = els[faceAt], want = layout.faceListName(face);
    if (head.fmt === "ascii") {
      var doc = decode(bytes.subarray(head.bodyStart));
      var before = 0;
      for (var e = 0; e < faceAt; e++) before += els[e].count;
      for (var r = 0; r < flags.length; r++) {
        if (!flags[r]) continue;
        var line = doc.lines[before + r], where = spans(line[0]), toks = base.internal.tokens(line[0]);
        var lists = [], t = 0;
        face.props.forEach(function (p) {
          if (p.count === null) { t += 1; return; }
          var n = base.internal.pyInt(toks[t]);
          lists.push({ name: p.name, at: t + 1, n: n });
          t += 1 + n;
        });
        turnLists(toks, lists, want);
        doc.lines[before + r] = [replaced(line[0], where, toks), line[1]];
      }
      return encode(doc, bytes.subarray(0, head.bodyStart));
    }
    var little = head.fmt === "binary_little_endian";
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    var out = new Uint8Array(bytes);
    var pos = head.bodyStart;
    function skip(el, rows) {
      if (layout.isFixed(el)) {
        pos += rows * layout.rowSize(el);
        return;
      }
      for (var i = 0; i < rows; i++) {
        el.props.forEach(function (p) {
          if (p.count === null) { pos += p.type[1]; return; }
          var n = view["get" + p.count[0]](pos, little);
          pos += p.count[1] + n * p.type[1];
        });
      }
    }
    for (e = 0; e < faceAt; e++) skip(els[e], els[e].count);
    var row = 0;
    for (r = 0; r < flags.length; r++) {
      if (!flags[r]) continue;
      skip(face, r - row);
      row = r;
      // the row's list items as byte strings, turned over as the text's tokens are
      var at = pos, items = [], places = [], lists = [];
      face.props.forEach(function (p) {
        if (p.count === null) { at += p.type[1]; return; }
        var n = view["get" + p.count[0]](at, little);
        at += p.count[1];
        lists.push({ name: p.name, at: items.length, n: n });
        for (var i = 0; i < n; i++, at += p.type[1]) {
          places.push(at);
          items.push(bytes.slice(at, at + p.type[1]));
        }
      });
      turnLists(items, lists, want);
      items.forEach(function (item, j) { out.set(item, places[j]); });
    }
    return out;
  }

  // ------------------------------------------------------------------ stored normals (io/stored.py)

  /** Each face's stored normal (3 numbers a face), or null when the file stores none. */
  function storedNormals(mesh) {
    var np = mesh.polygons, out = new Float64Array(3 * np), i, k;
    var I = base.internal;
    if (mesh.format === "stl" && mesh.binary) {
      var view = new DataView(mesh.bytes.buffer, mesh.bytes.byteOffset, mesh.bytes.byteLength);
      for (i = 0; i < np; i++) for (k = 0; k < 3; k++) out[3 * i + k] = view.getFloat32(84 + 50 * i + 4 * k, true);
      return out;
    }
    var lines = decode(mesh.bytes).lines;
    if (mesh.format === "stl") {
      var facet = 0, current = [0, 0, 0];
      lines.forEach(function (l) {
        var toks = I.tokens(l[0]), kw = toks.length ? toks[0].toLowerCase() : "";
        if (kw === "facet") {
          current = [0, 0, 0];
          if (toks.length >= 5 && toks[1].toLowerCase() === "normal") {
            var xyz = [I.pyFloat(toks[2]), I.pyFloat(toks[3]), I.pyFloat(toks[4])];
            if (xyz.indexOf(undefined) < 0) current = xyz;
          }
        } else if (kw === "endloop") {
          out.set(current, 3 * facet++);
          current = [0, 0, 0];
        }
      });
      return out;
    }
    if (mesh.format === "ply") {
      var vn = mesh.vertex_normals;
      if (!vn) return null;
      for (i = 0; i < mesh.source.length; i++) {
        for (k = 0; k < 3; k++) {
          var c0 = mesh.faces[3 * i], c1 = mesh.faces[3 * i + 1], c2 = mesh.faces[3 * i + 2];
          out[3 * mesh.source[i] + k] += vn[3 * c0 + k] + vn[3 * c1 + k] + vn[3 * c2 + k];
        }
      }
      return out;
    }
    var normals = [], face = -1, statement = I.objStatements();
    lines.forEach(function (l) {
      var toks = statement(l[0]);
      if (!toks || !toks.length) return;
      if (toks[0] === "vn" && toks.length >= 4) {
        var n3 = [I.pyFloat(toks[1]), I.pyFloat(toks[2]), I.pyFloat(toks[3])];
        normals.push(n3.indexOf(undefined) < 0 ? n3 : [0, 0, 0]);
      } else if (toks[0] === "f" || toks[0] === "fo") {
        face++;
        var total = [0, 0, 0];
        for (var t = 1; t < toks.length; t++) {
          var refs = toks[t].split("/");
          var j = refs.length >= 3 ? I.pyInt(refs[2]) : undefined;
          var at = typeof j !== "number" || j === 0 ? -1 : j > 0 ? j - 1 : normals.length + j;
          if (at < 0 || at >= normals.length) {
            total = [0, 0, 0];
            break;
          }
          for (k = 0; k < 3; k++) total[k] += normals[at][k];
        }
        out.set(total, 3 * face);
      }
    });
    return normals.length ? out : null;
  }

  /**
   * How many faces' stored normals point against the winding of `faces` (io/stored.py's
   * against); `turned` (flags) are faces a fix turned over, whose STL normals are recomputed.
   * null when the file stores no normals.
   */
  function normalsAgainst(mesh, faces, turned) {
    var normals = storedNormals(mesh);
    if (!normals) return null;
    var V = mesh.vertices, area = new Float64Array(3 * mesh.polygons);
    for (var t = 0; t < mesh.source.length; t++) {
      var a = 3 * faces[3 * t], b = 3 * faces[3 * t + 1], c = 3 * faces[3 * t + 2];
      var ux = V[b] - V[a], uy = V[b + 1] - V[a + 1], uz = V[b + 2] - V[a + 2];
      var vx = V[c] - V[a], vy = V[c + 1] - V[a + 1], vz = V[c + 2] - V[a + 2];
      var p = 3 * mesh.source[t];
      area[p] += uy * vz - uz * vy;
      area[p + 1] += uz * vx - ux * vz;
      area[p + 2] += ux * vy - uy * vx;
    }
    var count = 0;
    for (var f = 0; f < mesh.polygons; f++) {
      var dot = area[3 * f] * normals[3 * f] + area[3 * f + 1] * normals[3 * f + 1] + area[3 * f + 2] * normals[3 * f + 2];
      if (dot < 0 && !(turned && turned[f] && mesh.format === "stl")) count++;
    }
    return count;
  }

  /**
   * The file the mesh was read from with the faces `faces` turns over turned over, byte for
   * byte as trinormal.mesh.write_mesh writes a read model back (trinormal/mesh/io/rewrite.py):
   * everything else in the file stays; an STL facet turned over gets its normal recomputed.
   * A Uint8Array.
   */
  function write(mesh, faces) {
    var turned = turnedPolygons(mesh, faces);
    if (!turned.any) return new Uint8Array(mesh.bytes);
    if (mesh.format === "obj") {
      var doc = decode(mesh.bytes);
      turnObj(doc.lines, turned.flags);
      return encode(doc, new Uint8Array(0));
    }
    if (mesh.format === "ply") return turnPly(mesh, turned.flags);
    var normalOf = normalsOf(mesh, faces, turned.flags);
    if (mesh.binary) return turnStlBinary(mesh, turned.flags, normalOf);
    doc = decode(mesh.bytes);
    turnStlAscii(doc.lines, turned.flags, normalOf);
    return encode(doc, new Uint8Array(0));
  }

  return {
    fixWinding: fixWinding,
    write: write,
    repr: repr,
    normalsAgainst: function (mesh, faces, fixed) {
      return normalsAgainst(mesh, faces, fixed ? turnedPolygons(mesh, faces).flags : null);
    },
  };
});
