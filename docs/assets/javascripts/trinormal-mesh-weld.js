/*
 * trinormal's mesh check in the browser: which vertices are one corner (trinormal/mesh/welding.py).
 * Vertices at exactly one position are one corner; boundary corners within the weld distance
 * (WELD_AUTO times the model's size, or more when asked) too; a representative is the smallest
 * index of its group. Near misses beyond it are found here and reported by the check.
 * Loaded after trinormal-mesh-read.js; see trinormal-mesh-base.js for how the parts fit.
 */
self.TrinormalMesh.part("weld", "read", function (base) {
  "use strict";
  var I = base.internal, WELD = I.MESH.weld;
  var f64 = new Float64Array(1);
  var u32 = new Uint32Array(f64.buffer);

  /** The bounding box of the vertices the faces use, [lo, hi] (null: no faces). */
  function bounds(V, faces) {
    if (!faces.length) return null;
    var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (var s = 0; s < faces.length; s++) {
      for (var k = 0; k < 3; k++) {
        var x = V[3 * faces[s] + k];
        if (x < lo[k]) lo[k] = x;
        if (x > hi[k]) hi[k] = x;
      }
    }
    return [lo, hi];
  }

  /** The longest side of the bounding box of the vertices the faces use (0: no faces). */
  function modelSize(V, faces) {
    var box = bounds(V, faces);
    return box ? Math.max(box[1][0] - box[0][0], box[1][1] - box[0][1], box[1][2] - box[0][2]) : 0;
  }

  /** h mixed with the two 32-bit words of x's float64 bits (-0 is 0). */
  function mixIn(h, x) {
    f64[0] = x + 0.0;
    return I.fmix(I.fmix(h ^ u32[0]) ^ u32[1]);
  }

  /** Each vertex's smallest index at exactly its position; null when every position is unique. */
  function exactRepresentatives(V) {
    var n = V.length / 3;
    var table = I.slotTable(n);
    var rep = null;
    for (var i = 0; i < n; i++) {
      var x = V[3 * i], y = V[3 * i + 1], z = V[3 * i + 2];
      var slot = mixIn(mixIn(mixIn(0, x), y), z) & table.mask;
      for (;;) {
        var at = table.slots[slot];
        if (at < 0) {
          table.slots[slot] = i;
          break;
        }
        if (V[3 * at] === x && V[3 * at + 1] === y && V[3 * at + 2] === z) {
          if (!rep) rep = I.identity(n);
          rep[i] = at;
          break;
        }
        slot = (slot + 1) & table.mask;
      }
    }
    return rep;
  }

  /**
   * Pairs of rows of points P (k rows of 3) no farther apart than `dist` along each axis:
   * {i, j, d} arrays (i < j, d the largest of |dx|, |dy|, |dz|). Rows go in cells of side
   * 2 · dist; only rows in neighbouring cells are compared (welding.py's _close_pairs).
   */
  function closePairs(P, dist) {
    var k = P.length / 3;
    var out = { i: [], j: [], d: [] };
    if (k < 2 || !(dist > 0)) return out;
    var lo = [Infinity, Infinity, Infinity];
    for (var r = 0; r < k; r++) for (var a = 0; a < 3; a++) lo[a] = Math.min(lo[a], P[3 * r + a]);
    var cells = new Map(), cell = new Float64Array(3 * k);
    for (r = 0; r < k; r++) {
      for (a = 0; a < 3; a++) cell[3 * r + a] = Math.floor((P[3 * r + a] - lo[a]) / (2.0 * dist));
    }
    // a cell's key: a 32-bit hash of its three numbers (cells that share one are told apart below)
    var keyOf = function (x, y, z) {
      return Math.imul(x >>> 0, 73856093) ^ Math.imul(y >>> 0, 19349663) ^ Math.imul(z >>> 0, 83492791);
    };
    for (r = 0; r < k; r++) {
      var key = keyOf(cell[3 * r], cell[3 * r + 1], cell[3 * r + 2]);
      var list = cells.get(key);
      if (list) list.push(r);
      else cells.set(key, [r]);
    }
    for (r = 0; r < k; r++) {
      var cx = cell[3 * r], cy = cell[3 * r + 1], cz = cell[3 * r + 2];
      for (var dx = -1; dx <= 1; dx++) {
        for (var dy = -1; dy <= 1; dy++) {
          for (var dz = -1; dz <= 1; dz++) {
            var near = cells.get(keyOf(cx + dx, cy + dy, cz + dz));
            if (!near) continue;
            for (var n = 0; n < near.length; n++) {
              var j = near[n];
              if (j <= r || cell[3 * j] !== cx + dx || cell[3 * j + 1] !== cy + dy || cell[3 * j + 2] !== cz + dz) continue;
              var d = Math.max(Math.abs(P[3 * r] - P[3 * j]), Math.abs(P[3 * r + 1] - P[3 * j + 1]), Math.abs(P[3 * r + 2] - P[3 * j + 2]));
              if (d <= dist) {
                out.i.push(r);
                out.j.push(j);
                out.d.push(d);
              }
            }
          }
        }
      }
    }
    return out;
  }

  function rows(V, list) {
    var P = new Float64Array(3 * list.length);
    for (var r = 0; r < list.length; r++) for (var a = 0; a < 3; a++) P[3 * r + a] = V[3 * list[r] + a];
    return P;
  }

  /**
   * `rep` with the boundary corners `b` (sorted vertex indices) within `dist` of each other
   * merged, single linkage, each group into its smallest index; null when none are.
   */
  function mergeClose(V, rep, b, dist) {
    var pairs = closePairs(rows(V, b), dist);
    if (!pairs.i.length) return null;
    var parent = I.identity(b.length);
    for (var p = 0; p < pairs.i.length; p++) I.union(parent, pairs.i[p], pairs.j[p]);
    var to = I.identity(rep.length);
    for (var r = 0; r < b.length; r++) to[b[r]] = b[I.find(parent, r)];
    var out = new Int32Array(rep.length);
    for (r = 0; r < rep.length; r++) out[r] = to[rep[r]];
    return out;
  }

  /** For each boundary corner, the distance to its nearest other within `range`; the largest. */
  function nearestLargest(V, b, range) {
    var pairs = closePairs(rows(V, b), range);
    if (!pairs.i.length) return null;
    var nearest = new Float64Array(b.length).fill(Infinity);
    for (var p = 0; p < pairs.i.length; p++) {
      nearest[pairs.i[p]] = Math.min(nearest[pairs.i[p]], pairs.d[p]);
      nearest[pairs.j[p]] = Math.min(nearest[pairs.j[p]], pairs.d[p]);
    }
    var most = -Infinity;
    for (var r = 0; r < b.length; r++) if (Number.isFinite(nearest[r])) most = Math.max(most, nearest[r]);
    return most;
  }

  /** [value, text]: the smallest of 1, 2 and 5 times a power of ten above x (at or above). */
  function roundDistance(x, above) {
    var k = Math.floor(Math.log10(x)) - 1;
    for (;;) {
      for (var m = 1; m <= 5; m += m === 2 ? 3 : 1) {
        var text = k >= 0 && k <= 3 ? String(m * Math.pow(10, k)) : m + "e" + k;
        var d = parseFloat(text);
        if (d > x || (d === x && !above)) return [d, text];
      }
      k++;
    }
  }

  /** The faces with every vertex replaced by its representative. */
  function mapped(faces, rep) {
    var out = new Uint32Array(faces.length);
    for (var s = 0; s < faces.length; s++) out[s] = rep[faces[s]];
    return out;
  }

  /** How many vertices `rep` replaces by another. */
  function replaced(rep) {
    var n = 0;
    if (rep) for (var i = 0; i < rep.length; i++) if (rep[i] !== i) n++;
    return n;
  }

  return {
    internal: Object.assign({}, I, {
      WELD, bounds, modelSize, exactRepresentatives, mergeClose, nearestLargest, roundDistance,
      weldMapped: mapped,
      replaced,
    }),
  };
});
