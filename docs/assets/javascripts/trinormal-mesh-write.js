/*
 * trinormal's mesh check in the browser, part 4 of 4: the winding fix and the writers, as
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

  /** Three numbers of `values` from `at`, as Python writes f"{x!r} {y!r} {z!r}". */
  function triple(values, at) {
    return repr(values[at]) + " " + repr(values[at + 1]) + " " + repr(values[at + 2]);
  }

  function encodeText(lines) {
    return new TextEncoder().encode(lines.join("\n") + "\n");
  }

  function writeObj(V, faces) {
    var lines = ["# written by trinormal"];
    for (var i = 0; i < V.length; i += 3) lines.push("v " + triple(V, i));
    for (i = 0; i < faces.length; i += 3) lines.push("f " + (faces[i] + 1) + " " + (faces[i + 1] + 1) + " " + (faces[i + 2] + 1));
    return encodeText(lines);
  }

  function writeStlBinary(V, faces, normals) {
    var nf = faces.length / 3;
    var view = new DataView(new ArrayBuffer(84 + 50 * nf));
    var head = "binary STL written by trinormal";
    for (var i = 0; i < 80; i++) view.setUint8(i, i < head.length ? head.charCodeAt(i) : 32);
    view.setUint32(80, nf, true);
    for (i = 0; i < nf; i++) {
      var at = 84 + 50 * i;
      for (var k = 0; k < 3; k++, at += 4) view.setFloat32(at, normals[3 * i + k], true);
      for (var c = 0; c < 3; c++) {
        var p = 3 * faces[3 * i + c];
        for (var a = 0; a < 3; a++, at += 4) view.setFloat32(at, V[p + a], true);
      }
    }
    return new Uint8Array(view.buffer);
  }

  function writeStlAscii(V, faces, normals) {
    var lines = ["solid trinormal"];
    for (var i = 0; i < faces.length; i += 3) {
      lines.push("facet normal " + triple(normals, i), "outer loop");
      for (var k = 0; k < 3; k++) lines.push("vertex " + triple(V, 3 * faces[i + k]));
      lines.push("endloop", "endfacet");
    }
    lines.push("endsolid trinormal");
    return encodeText(lines);
  }

  /** PLY: float32 coordinates when every one is a float32 number, float64 otherwise. */
  function writePly(V, faces, binary) {
    var nv = V.length / 3, nf = faces.length / 3;
    var single = true;
    for (var i = 0; i < V.length && single; i++) single = Math.fround(V[i]) === V[i];
    var vtype = single ? "float" : "double";
    var lines = [
      "ply",
      "format " + (binary ? "binary_little_endian" : "ascii") + " 1.0",
      "comment written by trinormal",
      "element vertex " + nv,
      "property " + vtype + " x",
      "property " + vtype + " y",
      "property " + vtype + " z",
      "element face " + nf,
      "property list uchar int vertex_indices",
      "end_header",
    ];
    if (!binary) {
      for (i = 0; i < V.length; i += 3) lines.push(triple(V, i));
      for (i = 0; i < faces.length; i += 3) lines.push("3 " + faces[i] + " " + faces[i + 1] + " " + faces[i + 2]);
      return encodeText(lines);
    }
    var head = encodeText(lines);
    var size = single ? 4 : 8;
    var out = new Uint8Array(head.length + 3 * size * nv + 13 * nf);
    out.set(head, 0);
    var view = new DataView(out.buffer);
    var at = head.length;
    for (i = 0; i < V.length; i++, at += size) {
      if (single) view.setFloat32(at, V[i], true);
      else view.setFloat64(at, V[i], true);
    }
    for (i = 0; i < faces.length; i += 3) {
      view.setUint8(at++, 3);
      for (var j = 0; j < 3; j++, at += 4) view.setInt32(at, faces[i + j], true);
    }
    return out;
  }

  /**
   * The mesh as a file in its own format and encoding (a big-endian PLY is written little
   * endian), written as trinormal.mesh.write_mesh writes it, byte for byte: a Uint8Array.
   * An STL holds each face's unit normal, as trinormal.mesh.face_normals gives it.
   */
  function write(mesh, faces) {
    var V = mesh.vertices;
    if (mesh.format === "obj") return writeObj(V, faces);
    if (mesh.format === "ply") return writePly(V, faces, mesh.binary);
    var normals = base.internal.faceNormals(V, faces);
    return mesh.binary ? writeStlBinary(V, faces, normals) : writeStlAscii(V, faces, normals);
  }

  return { fixWinding: fixWinding, write: write, repr: repr };
});
