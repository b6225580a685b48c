/*
 * trinormal's mesh check in the browser: which way each piece should face (repair.py's
 * volumes, trinormal/mesh/shells.py): enclosed volumes, cavities inside closed pieces, open
 * pieces closed over their holes, and each piece's entry of the report. The same operations
 * in the same order as the Python, so the same sums to the last bit.
 * Loaded after trinormal-mesh-weld.js; see trinormal-mesh-base.js for how the parts fit.
 */
self.TrinormalMesh.part("shells", "weld", function (base) {
  "use strict";
  var I = base.internal, WELD = I.WELD;
  var frexpExp = I.frexpExp, pow2 = I.pow2, sub = I.sub, cross = I.cross;
  var EPS = Math.pow(2, -52);
  var VOLUME_ROUNDING = 8;
  var HOLDER_BLOCK = 256; // shells.py's _HOLDER_BLOCK: it sets the speed, never the pairs found

  /** 2 ** (frexp(x)[1] - 1) in Python: the largest power of two <= x >= 0 (0.5 for 0). */
  function powerOfTwoBelow(x) {
    return pow2(frexpExp(x) - 1);
  }

  /**
   * Six times the enclosed volume of each piece, from the first vertex of its first face, as
   * wound now (`volume`) and after the consistent flips (`fixed`), with its rounding bound.
   * Every coordinate is first divided by its piece's `scale` (the largest power of two not
   * above its largest |coordinate|: exact in binary), so the triple products can neither
   * overflow nor underflow; the three sums are the true ones over scale ** 3.
   */
  function volumes(V, faces, comp, nComp, flip) {
    var nf = comp.length;
    var ref = new Int32Array(nComp).fill(-1);
    var largest = new Float64Array(nComp), scale = new Float64Array(nComp);
    var volume = new Float64Array(nComp), fixed = new Float64Array(nComp);
    var sizeSum = new Float64Array(nComp), nIn = new Float64Array(nComp);
    var f, k, cf, at;
    for (k = 0; k < 3 * nf; k++) {
      if ((cf = comp[(k / 3) | 0]) < 0) continue;
      at = 3 * faces[k];
      largest[cf] = Math.max(largest[cf], Math.abs(V[at]), Math.abs(V[at + 1]), Math.abs(V[at + 2]));
    }
    for (k = 0; k < nComp; k++) scale[k] = powerOfTwoBelow(largest[k]);
    for (f = 0; f < nf; f++) {
      cf = comp[f];
      if (cf < 0) continue;
      if (ref[cf] < 0) ref[cf] = 3 * faces[3 * f];
      var o = ref[cf], c = scale[cf];
      var ox = V[o] / c, oy = V[o + 1] / c, oz = V[o + 2] / c;
      var i0 = 3 * faces[3 * f], i1 = 3 * faces[3 * f + 1], i2 = 3 * faces[3 * f + 2];
      var px = V[i0] / c - ox, py = V[i0 + 1] / c - oy, pz = V[i0 + 2] / c - oz;
      var qx = V[i1] / c - ox, qy = V[i1 + 1] / c - oy, qz = V[i1 + 2] / c - oz;
      var sx = V[i2] / c - ox, sy = V[i2 + 1] / c - oy, sz = V[i2 + 2] / c - oz;
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
    for (var i = 0; i < nComp; i++) error[i] = (VOLUME_ROUNDING + nIn[i]) * EPS * sizeSum[i];
    return { volume: volume, fixed: fixed, error: error, scale: scale, ref: ref, sizeSum: sizeSum, count: nIn };
  }

  // ------------------------------------------------------------------ small vector helpers

  function det3(p, q, s) {
    return p[0] * (q[1] * s[2] - q[2] * s[1]) + p[1] * (q[2] * s[0] - q[0] * s[2]) + p[2] * (q[0] * s[1] - q[1] * s[0]);
  }

  function norm(p) {
    return Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  }

  function dot(p, q) {
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  }

  /** Vertex i divided by s, minus r (unscaled reference point, divided by s too). */
  function scaled(V, i, s, r) {
    return [V[3 * i] / s - r[0] / s, V[3 * i + 1] / s - r[1] / s, V[3 * i + 2] / s - r[2] / s];
  }

  // ------------------------------------------------------------------ cavities (shells.py)

  /** Whether `point` lies inside the closed surface of the given faces: their winding number. */
  function inside(V, faces, list, flip, s, point) {
    var turns = 0;
    for (var n = 0; n < list.length; n++) {
      var f = list[n];
      var i1 = flip[f] ? 2 : 1, i2 = flip[f] ? 1 : 2;
      var a = scaled(V, faces[3 * f], s, [0, 0, 0]), b = scaled(V, faces[3 * f + i1], s, [0, 0, 0]);
      var c = scaled(V, faces[3 * f + i2], s, [0, 0, 0]);
      a = sub(a, point);
      b = sub(b, point);
      c = sub(c, point);
      var la = norm(a), lb = norm(b), lc = norm(c);
      var below = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
      turns += 2.0 * Math.atan2(det3(a, b, c), below);
    }
    return Math.abs(turns / (4.0 * Math.PI)) > 0.5;
  }

  /**
   * Every pair [a, b] of pieces in `which` where b's box (box[b] = [lo, hi]) holds a's, as
   * shells.py's _box_holders finds them: blocks of pieces in the order of their lowest x, each
   * compared with the boxes that start at or before its last piece and end at or after its first.
   */
  function boxHolders(which, box) {
    var order = which.slice().sort(function (a, b) { return box[a][0][0] - box[b][0][0] || a - b; });
    var pairs = [];
    for (var i = 0; i < order.length; i += HOLDER_BLOCK) {
      var block = order.slice(i, i + HOLDER_BLOCK);
      var last = Math.max.apply(null, block.map(function (a) { return box[a][0][0]; }));
      var first = Math.min.apply(null, block.map(function (a) { return box[a][1][0]; }));
      var reach = [];
      for (var j = 0; j < order.length && box[order[j]][0][0] <= last; j++) {
        if (box[order[j]][1][0] >= first) reach.push(order[j]);
      }
      block.forEach(function (a) {
        reach.forEach(function (b) {
          if (a === b) return;
          for (var k = 0; k < 3; k++) if (!(box[b][0][k] <= box[a][0][k] && box[a][1][k] <= box[b][1][k])) return;
          pairs.push([a, b]);
        });
      });
    }
    return pairs;
  }

  /** Which pieces lie inside an odd number of the `solid` pieces (shells.py's cavities). */
  function cavities(V, faces, comp, nComp, flip, solid, scale) {
    var depth = new Int32Array(nComp);
    var which = [];
    for (var c = 0; c < nComp; c++) if (solid[c]) which.push(c);
    if (which.length < 2) return depth;
    var lists = [], corners = []; // each piece's faces, and their vertices
    for (c = 0; c < nComp; c++) {
      lists.push([]);
      corners.push([]);
    }
    for (var f = 0; f < comp.length; f++) {
      c = comp[f];
      if (c < 0) continue;
      lists[c].push(f);
      corners[c].push(faces[3 * f], faces[3 * f + 1], faces[3 * f + 2]);
    }
    var box = corners.map(function (list) { return I.bounds(V, list); });
    boxHolders(which, box).forEach(function (pair) {
      var pa = pair[0], pb = pair[1];
      var s = Math.max(scale[pa], scale[pb]), z = [0, 0, 0];
      var f0 = lists[pa][0];
      var p0 = scaled(V, faces[3 * f0], s, z), p1 = scaled(V, faces[3 * f0 + 1], s, z), p2 = scaled(V, faces[3 * f0 + 2], s, z);
      var point = [(p0[0] + p1[0] + p2[0]) / 3.0, (p0[1] + p1[1] + p2[1]) / 3.0, (p0[2] + p1[2] + p2[2]) / 3.0];
      if (inside(V, faces, lists[pb], flip, s, point)) depth[pa]++;
    });
    for (c = 0; c < nComp; c++) depth[c] = depth[c] % 2;
    return depth;
  }

  // ------------------------------------------------------------------ open pieces (shells.py)

  /**
   * Each `candidate` piece closed over its holes: a fan from the centre of each rim (a loop of
   * boundary edges of one piece). {encloses, volume, fixed} per piece, as shells.py's capped:
   * the faces' sums of `vol` (volumes') and the caps' sums, added.
   */
  function capped(V, faces, comp, nComp, flip, candidate, vol, boundarySides) {
    var scale = vol.scale, refOf = vol.ref;
    var nv = V.length / 3;
    var volume = new Float64Array(nComp), fixed = new Float64Array(nComp), encloses = new Uint8Array(nComp);
    var any = false;
    for (var c = 0; c < nComp; c++) if (candidate[c]) any = true;
    if (!any) return { encloses: encloses, volume: volume, fixed: fixed };
    var ref = [];
    for (c = 0; c < nComp; c++) ref.push(refOf[c] >= 0 ? [V[refOf[c]], V[refOf[c] + 1], V[refOf[c] + 2]] : [0, 0, 0]);
    var farea = new Float64Array(nComp);
    for (var f = 0; f < comp.length; f++) {
      c = comp[f];
      if (c < 0 || !candidate[c]) continue;
      var s = scale[c];
      var p = scaled(V, faces[3 * f], s, ref[c]), q = scaled(V, faces[3 * f + 1], s, ref[c]), t = scaled(V, faces[3 * f + 2], s, ref[c]);
      farea[c] += norm(cross(sub(q, p), sub(t, p)));
    }
    // the rims, in half-edge order; their corners as (piece, vertex) nodes, sorted
    var h = Array.from(boundarySides).filter(function (x) { return candidate[comp[(x / 3) | 0]]; });
    h.sort(function (x, y) { return x - y; });
    var keyA = h.map(function (x) { return comp[(x / 3) | 0] * nv + faces[x]; });
    var keyB = h.map(function (x) { return comp[(x / 3) | 0] * nv + faces[x % 3 === 2 ? x - 2 : x + 1]; });
    var nodes = Float64Array.from(new Set(keyA.concat(keyB))).sort();
    var nodeOf = new Map();
    nodes.forEach(function (key, i) { nodeOf.set(key, i); });
    var parent = I.identity(nodes.length);
    for (var e = 0; e < h.length; e++) I.union(parent, nodeOf.get(keyA[e]), nodeOf.get(keyB[e]));
    var sum = new Map();
    for (var n = 0; n < nodes.length; n++) {
      var pc = Math.floor(nodes[n] / nv), vx = nodes[n] - pc * nv;
      var xyz = scaled(V, vx, scale[pc], ref[pc]), r = I.find(parent, n);
      var acc = sum.get(r) || [0, 0, 0, 0];
      sum.set(r, [acc[0] + xyz[0], acc[1] + xyz[1], acc[2] + xyz[2], acc[3] + 1]);
    }
    var cv = new Float64Array(nComp), cf = new Float64Array(nComp), csize = new Float64Array(nComp);
    var carea = new Float64Array(nComp), caps = new Float64Array(nComp);
    for (e = 0; e < h.length; e++) {
      c = comp[(h[e] / 3) | 0];
      var tot = sum.get(I.find(parent, nodeOf.get(keyA[e])));
      var m = [tot[0] / tot[3], tot[1] / tot[3], tot[2] / tot[3]];
      var pa = scaled(V, faces[h[e]], scale[c], ref[c]);
      var pb = scaled(V, faces[h[e] % 3 === 2 ? h[e] - 2 : h[e] + 1], scale[c], ref[c]);
      var cap = det3(m, pb, pa); // the cap triangle (centre, b, a) walks the rim edge back
      cv[c] += cap;
      cf[c] += cap * (flip[(h[e] / 3) | 0] ? -1.0 : 1.0);
      csize[c] += norm(m) * norm(pb) * norm(pa);
      carea[c] += norm(cross(sub(pb, m), sub(pa, m)));
      caps[c] += 1;
    }
    for (c = 0; c < nComp; c++) {
      if (!candidate[c]) continue;
      volume[c] = vol.volume[c] + cv[c];
      fixed[c] = vol.fixed[c] + cf[c];
      var error = (VOLUME_ROUNDING + vol.count[c] + caps[c]) * EPS * (vol.sizeSum[c] + csize[c]);
      encloses[c] = carea[c] < WELD.cap_fraction * (carea[c] + farea[c]) && Math.abs(fixed[c]) > error ? 1 : 0;
    }
    return { encloses: encloses, volume: volume, fixed: fixed };
  }

  // ------------------------------------------------------------------ each piece's entry

  /**
   * Each piece's entry of the report, and the faces to flip: after the consistent flips, a
   * closed piece faces out of its material (a cavity into its hollow), and so does an open piece
   * that encloses a volume (repair.py's _winding, report.py's _component_reports).
   */
  function pieceReports(V, faces, pieces, e, w, flip) {
    var nComp = pieces.count, comp = pieces.comp;
    var vol = volumes(V, faces, comp, nComp, flip);
    var closed = new Uint8Array(nComp).fill(1), openCount = new Int32Array(nComp), boundaryCount = new Int32Array(nComp);
    var s;
    for (s = 0; s < e.openSides.length; s++) {
      closed[comp[(e.openSides.data[s] / 3) | 0]] = 0;
      openCount[comp[(e.openSides.data[s] / 3) | 0]]++;
    }
    for (s = 0; s < e.boundarySides.length; s++) boundaryCount[comp[(e.boundarySides.data[s] / 3) | 0]]++;
    var solid = new Uint8Array(nComp), candidate = new Uint8Array(nComp);
    for (var i = 0; i < nComp; i++) {
      solid[i] = closed[i] && w.orientable[i] && Math.abs(vol.fixed[i]) > vol.error[i] ? 1 : 0;
      candidate[i] = !closed[i] && openCount[i] === boundaryCount[i] && w.orientable[i] ? 1 : 0;
    }
    var cavity = cavities(V, faces, comp, nComp, flip, solid, vol.scale);
    var cap = capped(V, faces, comp, nComp, flip, candidate, vol, e.boundarySides.array());
    var inward = new Uint8Array(nComp);
    for (i = 0; i < nComp; i++) {
      inward[i] = (solid[i] && (vol.fixed[i] < 0) !== !!cavity[i]) || (cap.encloses[i] && cap.fixed[i] < 0) ? 1 : 0;
    }
    var toFlip = [];
    var flips = new Int32Array(nComp), sizes = new Int32Array(nComp);
    for (var f = 0; f < comp.length; f++) {
      if (comp[f] < 0) continue;
      sizes[comp[f]]++;
      if (flip[f] ^ inward[comp[f]]) {
        toFlip.push(f);
        flips[comp[f]]++;
      }
    }
    var components = [];
    for (i = 0; i < nComp; i++) {
      var consistent = w.inconsistent[i] === 0;
      var measurable = closed[i] && consistent;
      var v = vol.volume[i];
      var outward = measurable ? (Math.abs(v) <= vol.error[i] ? null : (v > 0) !== !!cavity[i]) : null;
      if (cap.encloses[i] && consistent) outward = cap.volume[i] > 0;
      components.push({
        faces: sizes[i],
        closed: !!closed[i],
        consistent: consistent,
        orientable: !!w.orientable[i],
        outward: outward,
        // x * scale ** 3 as Python's _unscaled takes it: ±Infinity only where the volume overflows
        volume: measurable ? v / 6.0 * vol.scale[i] * vol.scale[i] * vol.scale[i] : null,
        faces_to_flip: flips[i],
        cavity: !!cavity[i],
        judged_by: solid[i] ? "volume" : cap.encloses[i] ? "volume_over_holes" : null,
      });
    }
    return { components: components, faces_to_flip: toFlip };
  }

  return {
    internal: Object.assign({}, I, { powerOfTwoBelow, pieceReports }),
  };
});
