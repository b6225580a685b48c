/*
 * trinormal's mesh check in the browser, part 5 of 7: the report. The same keys and values
 * as Python's trinormal.mesh.check(vertices, faces).to_dict(), computed the same way
 * (trinormal/mesh/report.py, topology.py, repair.py, normals.py), and its sentences.
 * Loaded after trinormal-mesh-shells.js; see trinormal-mesh-base.js for how the parts fit.
 */
self.TrinormalMesh.part("check", "shells", function (base) {
  "use strict";
  var I = base.internal, MESH = I.MESH, TOL = MESH.tol, Growable = I.Growable;
  var frexpExp = I.frexpExp, pow2 = I.pow2, sub = I.sub, cross = I.cross, find = I.find, union = I.union;
  // The exact core's math.isqrt and float.as_integer_ratio, so the two ports share them.
  if (!self.TrinormalCore) {
    throw new Error("trinormal-mesh-check.js needs trinormal-core.js to be loaded first");
  }
  var isqrt = self.TrinormalCore.isqrt, doubleRatio = self.TrinormalCore.doubleRatio;

  // ------------------------------------------------------------------ each face: normal and degeneracy
  //
  // trinormal/mesh/normals.py, operation for operation. A face A, B, C is degenerate when
  // |N| <= tol · L², N = (B − A) × (C − A) and L its longest edge: one verdict whatever the
  // order of the corners. The float test is trusted outside a narrow band around the
  // threshold; faces inside it, or at extreme scales, take the careful path, and the faces
  // still undecided there are decided in exact (BigInt) arithmetic.

  // A face stays on the fast path when |N|² > 2**-900 and L² < 2**450 (normals.py's _LO, _HI).
  var TWO_M900 = Math.pow(2, -900);
  var TWO_450 = Math.pow(2, 450);
  // The band: a float |N| below LO_T · L² is degenerate, above HI_T · L² not (normals.py's _band).
  var BAND = Math.pow(2, -49);
  var LO_T = Math.max(TOL * (1 - BAND) - BAND, 0.0);
  var HI_T = TOL * (1 + BAND) + BAND;

  /** 1: surely not degenerate, -1: surely degenerate, 0: too near the threshold (_sure). */
  function sure(nn, l2) {
    var l4 = l2 * l2;
    if (nn > HI_T * HI_T * l4) return 1;
    var below = LO_T * LO_T * l4;
    return (nn < below && below > TWO_M900) || l2 === 0.0 ? -1 : 0;
  }

  /** x * 2**e rounded once, as C's ldexp (numpy.ldexp): exact unless the result is subnormal. */
  function ldexp(x, e) {
    if (x === 0 || !Number.isFinite(x) || e === 0) return x;
    var ex = frexpExp(x);
    var t = ex + e; // x * 2**e = m * 2**t with m in [0.5, 1)
    if (t > 1024) return x * Infinity;
    if (t < -1074) return x * 0; // below half the smallest subnormal: zero, with x's sign
    var m = ex < -1000 ? x * 18446744073709551616 * pow2(-ex - 64) : x * pow2(-ex);
    return t === 1024 ? m * 2 * pow2(1023) : m * pow2(t);
  }

  function ldexp3(p, e) {
    return [ldexp(p[0], e), ldexp(p[1], e), ldexp(p[2], e)];
  }

  function maxAbs(p) {
    return Math.max(Math.abs(p[0]), Math.abs(p[1]), Math.abs(p[2]));
  }

  /**
   * p·q of two rows as numpy's einsum("ij,ij->i") adds it in normals.py's _careful (its
   * _rowdot): two lanes at a time, so (p0 q0 + p2 q2) + p1 q1. The fast path adds in order.
   */
  function einsumDot(p, q) {
    return p[0] * q[0] + p[2] * q[2] + p[1] * q[1];
  }

  // ---- exact arithmetic for the faces too near the threshold (normals.py's _exact)

  function bitLength(n) {
    return n === 0n ? 0 : n.toString(2).length;
  }

  /** a / b correctly rounded to a double (b > 0), as Python's int / int. */
  function divide(a, b) {
    if (a === 0n) return 0;
    var neg = a < 0n;
    if (neg) a = -a;
    var s = 55 - (bitLength(a) - bitLength(b)); // the quotient to 55 or 56 bits
    var num = s >= 0 ? a << BigInt(s) : a;
    var den = s >= 0 ? b : b << BigInt(-s);
    var q = num / den;
    var inexact = num % den !== 0n;
    var top = bitLength(q) - 1 - s; // a / b in [2**top, 2**(top + 1))
    var keep = top >= -1022 ? 53 : 53 - (-1022 - top); // fewer bits for a subnormal
    if (keep < 0) return neg ? -0 : 0;
    var drop = bitLength(q) - keep;
    var m = q >> BigInt(drop);
    var rest = q - (m << BigInt(drop));
    var half = drop > 0 ? 1n << BigInt(drop - 1) : 0n;
    if (drop > 0 && (rest > half || (rest === half && (inexact || (m & 1n) === 1n)))) m += 1n;
    var out = ldexp(Number(m), drop - s);
    return neg ? -out : out;
  }

  var TOL_RATIO = doubleRatio(TOL); // tol = n / d exactly, as check_tolerance reads the float
  var TOL_N = TOL_RATIO[0], TOL_D = TOL_RATIO[1];

  /**
   * One face's unit normal computed exactly, or null when it is degenerate: the corners as
   * integers over their largest denominator (a power of two), |N|² d² <= n² L⁴ for tol = n / d,
   * and each component a quotient of integers, correctly rounded.
   */
  function exact(corners) {
    var ratios = corners.map(doubleRatio);
    var den = ratios.reduce(function (d, r) { return r[1] > d ? r[1] : d; }, 1n);
    var p = ratios.map(function (r) { return r[0] * (den / r[1]); });
    var u = [p[3] - p[0], p[4] - p[1], p[5] - p[2]];
    var v = [p[6] - p[0], p[7] - p[1], p[8] - p[2]];
    var w = [p[6] - p[3], p[7] - p[4], p[8] - p[5]];
    var n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    var sq = function (e) { return e[0] * e[0] + e[1] * e[1] + e[2] * e[2]; };
    var nn = sq(n);
    var l2 = [sq(u), sq(v), sq(w)].reduce(function (x, y) { return x > y ? x : y; });
    if (nn * TOL_D * TOL_D <= TOL_N * TOL_N * l2 * l2) return null;
    var k = Math.max(0, 67 - Math.floor(bitLength(nn) / 2)); // |N| * 2**k to 67 bits or more
    var r = isqrt(nn << BigInt(2 * k));
    return n.map(function (x) { return divide(x << BigInt(k), r); });
  }

  /**
   * A face at an extreme scale or near the threshold (normals.py's _careful): its edges scaled
   * by powers of two (exact), quartered first when their differences overflow. Writes its unit
   * normal into normals[at..at+2] (when given); returns whether it is degenerate.
   */
  function careful(V, i0, i1, i2, normals, at) {
    var a = [V[i0], V[i0 + 1], V[i0 + 2]], b = [V[i1], V[i1 + 1], V[i1 + 2]], c = [V[i2], V[i2 + 1], V[i2 + 2]];
    var quarter = function (p) { return [p[0] * 0.25, p[1] * 0.25, p[2] * 0.25]; };
    var u = sub(b, a), w = sub(c, a), x = sub(c, b); // U, V, W
    if (!u.concat(w, x).every(Number.isFinite)) {
      u = sub(quarter(b), quarter(a));
      w = sub(quarter(c), quarter(a));
      x = sub(quarter(c), quarter(b));
    }
    var eu = frexpExp(maxAbs(u)), ev = frexpExp(maxAbs(w));
    // the verdict: the three edges scaled alike, so that their products compare
    var common = Math.max(eu, ev);
    var uc = ldexp3(u, -common), vc = ldexp3(w, -common), wc = ldexp3(x, -common);
    var nc = cross(uc, vc);
    var verdict = sure(einsumDot(nc, nc), Math.max(Math.max(einsumDot(uc, uc), einsumDot(vc, vc)), einsumDot(wc, wc)));
    // the normal: each edge scaled on its own
    var n = cross(ldexp3(u, -eu), ldexp3(w, -ev));
    var ns = ldexp3(n, -frexpExp(maxAbs(n)));
    var mag = Math.sqrt(einsumDot(ns, ns));
    if (mag === 0) mag = 1;
    var unit = [ns[0] / mag, ns[1] / mag, ns[2] / mag];
    var deg = verdict !== 1;
    if (verdict === 0) {
      unit = exact(a.concat(b, c));
      deg = unit === null;
    }
    if (normals && !deg) {
      normals[at] = unit[0];
      normals[at + 1] = unit[1];
      normals[at + 2] = unit[2];
    }
    return deg;
  }

  /**
   * Every face's verdict: 0 proper, 1 two corners at one point, 2 degenerate otherwise
   * (|N| <= tol · L²); and, when `normals` (3 numbers per face) is given, its unit normal
   * there, zero when degenerate. The arithmetic of trinormal.mesh.normals: the same
   * operations in the same order, so the same verdicts and the same bits of every normal.
   */
  function faceRows(vertices, faces, normals) {
    var nf = faces.length / 3;
    var kind = new Uint8Array(nf);
    var V = vertices;
    for (var f = 0; f < nf; f++) {
      var i0 = 3 * faces[3 * f], i1 = 3 * faces[3 * f + 1], i2 = 3 * faces[3 * f + 2];
      var ax = V[i0], ay = V[i0 + 1], az = V[i0 + 2];
      var bx = V[i1], by = V[i1 + 1], bz = V[i1 + 2];
      var cx = V[i2], cy = V[i2 + 1], cz = V[i2 + 2];
      if ((ax === bx && ay === by && az === bz) || (ax === cx && ay === cy && az === cz) || (bx === cx && by === cy && bz === cz)) {
        kind[f] = 1;
        continue;
      }
      var ux = bx - ax, uy = by - ay, uz = bz - az;
      var vx = cx - ax, vy = cy - ay, vz = cz - az;
      var wx = cx - bx, wy = cy - by, wz = cz - bz;
      var nx = uy * vz - uz * vy;
      var ny = uz * vx - ux * vz;
      var nz = ux * vy - uy * vx;
      var nn = nx * nx + ny * ny + nz * nz;
      var l2 = Math.max(Math.max(ux * ux + uy * uy + uz * uz, vx * vx + vy * vy + vz * vz), wx * wx + wy * wy + wz * wz);
      var verdict = sure(nn, l2);
      if (!(verdict !== 0 && nn > TWO_M900 && l2 < TWO_450)) {
        if (careful(V, i0, i1, i2, normals, 3 * f)) kind[f] = 2;
      } else if (verdict < 0) {
        kind[f] = 2;
      } else if (normals) {
        var m = Math.sqrt(nn); // N / |N|, correctly rounded, as Python divides
        normals[3 * f] = nx / m;
        normals[3 * f + 1] = ny / m;
        normals[3 * f + 2] = nz / m;
      }
    }
    return kind;
  }

  /** Which faces are degenerate: a Uint8Array, 0 proper, 1 coincident corners, 2 collinear. */
  function degenerateFaces(vertices, faces) {
    return faceRows(vertices, faces, null);
  }

  /** Unit normals, 3 per face, as trinormal.mesh.face_normals gives them (zero if degenerate). */
  function faceNormals(vertices, faces) {
    var out = new Float64Array(faces.length);
    faceRows(vertices, faces, out);
    return out;
  }

  // ------------------------------------------------------------------ edges and pieces

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

  /**
   * Every undirected edge, by how many face sides share it: a boundary (one side), a manifold
   * edge (two: `pairA`, `pairB`) or a non-manifold one (three or more). On the way, faces
   * that share an edge join one piece (`parent`, by face) and their corners at each end of it
   * one fan (`fanParent`, by face side).
   */
  function edgeGroups(faces, nv, clean) {
    var nf = faces.length / 3;
    var table = edgeTable(faces, nv, clean);
    var start = table.start, hi = table.hi, side = table.side;
    var e = {
      parent: I.identity(nf),
      fanParent: I.identity(3 * nf),
      boundary: [],
      nonManifold: [],
      inconsistentPairs: [],
      pairA: new Growable(Int32Array, nf),
      pairB: new Growable(Int32Array, nf),
      openSides: new Growable(Int32Array, 64), // a face side of every edge not shared by two
      boundarySides: new Growable(Int32Array, 64),
      nonManifoldSides: new Growable(Int32Array, 64),
    };
    var group = [];
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
        addEdge(e, faces, lo, h, group);
      }
    }
    return e;
  }

  /** One edge (lo, h) and the face sides along it, into the findings `e` of edgeGroups. */
  function addEdge(e, faces, lo, h, group) {
    var count = group.length;
    if (count === 1) {
      var only = group[0];
      e.boundary.push(faces[only], faces[next(only)]);
      e.boundarySides.push(only);
      e.openSides.push(only);
      return;
    }
    if (count === 2) {
      e.pairA.push(group[0]);
      e.pairB.push(group[1]);
      if (faces[group[0]] === faces[group[1]]) e.inconsistentPairs.push(lo, h);
    } else {
      e.nonManifold.push(lo, h);
      e.nonManifoldSides.push(group[0]);
      e.openSides.push(group[0]);
    }
    // every face of the group in one piece; their corners at lo in one fan, at h in one
    var h0 = group[0];
    var cLo0 = faces[h0] === lo ? h0 : next(h0);
    var cHi0 = faces[h0] === lo ? next(h0) : h0;
    for (var k = 1; k < count; k++) {
      var hk = group[k];
      union(e.parent, (h0 / 3) | 0, (hk / 3) | 0);
      var atLo = faces[hk] === lo;
      union(e.fanParent, cLo0, atLo ? hk : next(hk));
      union(e.fanParent, cHi0, atLo ? next(hk) : hk);
    }
  }

  /** The piece of each face, numbered in the order of their first faces (-1: a vertex used twice). */
  function pieceLabels(parent, clean) {
    var nf = clean.length;
    var comp = new Int32Array(nf).fill(-1);
    var label = new Int32Array(nf).fill(-1);
    var n = 0;
    for (var f = 0; f < nf; f++) {
      if (!clean[f]) continue;
      var r = find(parent, f);
      if (label[r] < 0) label[r] = n++;
      comp[f] = label[r];
    }
    return { comp: comp, count: n };
  }

  /** Vertices whose corners fall into more than one fan: pinch points. */
  function pinchPoints(faces, nv, fanParent, clean) {
    var fanOf = new Int32Array(nv).fill(-1);
    var manyFans = new Uint8Array(nv);
    for (var s = 0; s < faces.length; s++) {
      if (!clean[(s / 3) | 0]) continue;
      var vtx = faces[s];
      var root = find(fanParent, s);
      if (fanOf[vtx] < 0) fanOf[vtx] = root;
      else if (fanOf[vtx] !== root) manyFans[vtx] = 1;
    }
    return indicesWhere(manyFans, function (many) { return many; });
  }

  // ------------------------------------------------------------------ winding (repair.py)

  /**
   * Which faces fix_winding turns over so that each piece agrees with itself, flipping the
   * fewer faces; a piece that meets itself turned over cannot be wound (not orientable).
   * Orientation classes are faces joined by manifold edges; parity is turned relative to the
   * class's first face. Also counts each piece's inconsistent edges.
   */
  function consistentFlips(faces, e, pieces, clean) {
    var nf = clean.length;
    var comp = pieces.comp;
    var inconsistent = new Int32Array(pieces.count); // edges walked the same way by both faces
    var across = new Int32Array(3 * nf).fill(-1); // the face across each manifold side
    var agree = new Uint8Array(3 * nf);
    for (var i = 0; i < e.pairA.length; i++) {
      var p1 = e.pairA.data[i], p2 = e.pairB.data[i];
      var same = faces[p1] === faces[p2] ? 1 : 0;
      if (same) inconsistent[comp[(p1 / 3) | 0]]++;
      across[p1] = (p2 / 3) | 0;
      across[p2] = (p1 / 3) | 0;
      agree[p1] = same;
      agree[p2] = same;
    }
    var parity = new Uint8Array(nf);
    var seen = new Uint8Array(nf);
    var klass = new Int32Array(nf).fill(-1);
    var queue = new Int32Array(nf);
    var classCount = [], classBad = [];
    var orientable = new Uint8Array(pieces.count).fill(1);
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
        for (var k = 0; k < 3; k++) {
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
    for (var f = 0; f < nf; f++) {
      if (!clean[f] || !orientable[comp[f]] || classBad[klass[f]]) continue;
      var cnt = classCount[klass[f]];
      flip[f] = cnt[1] > cnt[0] ? 1 - parity[f] : parity[f];
    }
    return { flip: flip, orientable: orientable, inconsistent: inconsistent };
  }

  // ------------------------------------------------------------------ the report

  function indicesWhere(array, test) {
    var out = [];
    for (var i = 0; i < array.length; i++) if (test(array[i])) out.push(i);
    return out;
  }

  /** Which faces have three distinct vertices: the faces that have edges. */
  function cleanFaces(faces) {
    var nf = faces.length / 3;
    var clean = new Uint8Array(nf);
    for (var f = 0; f < nf; f++) {
      var fa = faces[3 * f], fb = faces[3 * f + 1], fc = faces[3 * f + 2];
      clean[f] = fa !== fb && fb !== fc && fc !== fa ? 1 : 0;
    }
    return clean;
  }

  /** The welded faces and their edges, for a representative of every vertex (`rep`). */
  function joined(faces, nv, rep) {
    var wf = rep ? I.weldMapped(faces, rep) : faces;
    var clean = cleanFaces(wf);
    return { rep: rep, faces: wf, clean: clean, e: edgeGroups(wf, nv, clean) };
  }

  /** The boundary corners of a joined mesh, sorted. */
  function boundaryCorners(t) {
    return Int32Array.from(new Set(t.e.boundary)).sort();
  }

  /**
   * The topology of trinormal.mesh.welding.weld: corners at one position joined, then boundary
   * corners within the weld distance, then the near miss beyond it (`weld`: false, a number or
   * true, as Python's weld=).
   */
  function welded(V, faces, nv, weld) {
    var size = I.modelSize(V, faces), auto = I.WELD.auto * size;
    var dist = weld === true || weld === false || weld === undefined ? auto : weld > 0 ? Math.max(weld, auto) : 0;
    var exact = I.exactRepresentatives(V);
    var t = joined(faces, nv, exact);
    if (t.e.boundarySides.length && dist > 0) {
      var rep = I.mergeClose(V, exact || I.identity(nv), boundaryCorners(t), dist);
      if (rep) t = joined(faces, nv, rep);
    }
    var near = { edges: 0, distance: null };
    var range = I.WELD.near * size;
    if (t.e.boundarySides.length && range > dist) {
      var b = boundaryCorners(t);
      var most = I.nearestLargest(V, b, range);
      if (most !== null) {
        var suggest = I.roundDistance(most, true)[0];
        var t2 = joined(faces, nv, I.mergeClose(V, t.rep || I.identity(nv), b, suggest));
        var closes = t.e.boundarySides.length - t2.e.boundarySides.length;
        if (closes > 0 && weld === true) {
          t = t2;
          dist = suggest;
        } else if (closes > 0) near = { edges: closes, distance: suggest };
      }
    }
    var merged = I.replaced(exact);
    return { t: t, distance: dist, merged: merged, welded: I.replaced(t.rep) - merged, near: near };
  }

  /**
   * The report of trinormal.mesh.check(vertices, faces, weld=weld): the same keys and values as
   * its to_dict(), and for the 3D view one face side (3 * face + k) of every boundary and
   * non-manifold edge. `onProgress(fraction)` is called now and then.
   */
  function check(vertices, faces, onProgress, weld) {
    var progress = onProgress || function () {};
    var nv = vertices.length / 3;
    var nf = faces.length / 3;
    var s;
    for (s = 0; s < faces.length; s++) {
      if (faces[s] >= nv) I.fail("index_range", { face: (s / 3) | 0, index: faces[s], count: nv });
    }
    progress(0.05);
    var kind = degenerateFaces(vertices, faces);
    var used = new Uint8Array(nv);
    for (s = 0; s < faces.length; s++) used[faces[s]] = 1;
    progress(0.2);
    var w0 = welded(vertices, faces, nv, weld || false);
    var wf = w0.t.faces, clean = w0.t.clean, e = w0.t.e;
    var dups = duplicateFaces(wf, clean);
    progress(0.5);
    var pieces = pieceLabels(e.parent, clean);
    var pinches = pinchPoints(wf, nv, e.fanParent, clean);
    progress(0.6);
    var w = consistentFlips(wf, e, pieces, clean);
    progress(0.75);
    var p = I.pieceReports(vertices, wf, pieces, e, w, w.flip);
    progress(0.9);
    var c = p.components;
    var judged = c.some(function (x) { return x.closed || x.judged_by !== null; });
    var degenerate = indicesWhere(kind, function (k) { return k > 0; });
    var unused = indicesWhere(used, function (u) { return !u; });
    var report = {
      n_vertices: nv,
      n_faces: nf,
      n_components: pieces.count,
      closed: c.length > 0 && c.every(function (x) { return x.closed; }),
      consistent_winding: c.every(function (x) { return x.consistent; }),
      outward: judged ? c.every(function (x) { return !(x.closed || x.judged_by !== null) || x.outward === true; }) : null,
      ok: false,
      unused_vertices: unused,
      degenerate_faces: degenerate,
      coincident_faces: indicesWhere(kind, function (k) { return k === 1; }),
      collinear_faces: indicesWhere(kind, function (k) { return k === 2; }),
      duplicate_faces: dups.same,
      reversed_duplicate_faces: dups.reversed,
      boundary_edges: sortedPairs(e.boundary),
      non_manifold_edges: sortedPairs(e.nonManifold),
      non_manifold_vertices: pinches,
      inconsistent_edges: sortedPairs(e.inconsistentPairs),
      components: c,
      faces_to_flip: p.faces_to_flip,
      weld_distance: w0.distance,
      merged_vertices: w0.merged,
      welded_vertices: w0.welded,
      near_miss: w0.near.distance === null ? null : w0.near,
      _boundary_sides: e.boundarySides.array(),
      _non_manifold_sides: e.nonManifoldSides.array(),
    };
    report.ok =
      report.closed && report.consistent_winding && report.outward === true &&
      !degenerate.length && !dups.same.length && !dups.reversed.length && !pinches.length && !unused.length;
    progress(1);
    return report;
  }

  /**
   * Faces that repeat an earlier face's three vertices: `same` when wound like an earlier copy,
   * `reversed` for the first copy wound the other way (trinormal.mesh.duplicate_faces).
   * Faces using a vertex twice are left out.
   */
  function duplicateFaces(faces, clean) {
    var nf = faces.length / 3;
    var table = I.slotTable(nf);
    var fmix = I.fmix;
    var otherWay = new Int32Array(nf).fill(-1); // first face wound the other way, per key
    var same = [];
    var reversed = [];
    for (var f = 0; f < nf; f++) {
      if (!clean[f]) continue;
      var a = faces[3 * f], b = faces[3 * f + 1], c = faces[3 * f + 2];
      var lo = Math.min(a, b, c), hi = Math.max(a, b, c), mid = a + b + c - lo - hi;
      var slot = fmix(fmix(fmix(lo) ^ mid) ^ hi) & table.mask;
      for (;;) {
        var at = table.slots[slot];
        if (at < 0) {
          table.slots[slot] = f;
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
        slot = (slot + 1) & table.mask;
      }
    }
    return { same: same, reversed: reversed };
  }

  function sameWay(a, b, c, p, q, r) {
    return (a === p && b === q && c === r) || (a === q && b === r && c === p) || (a === r && b === p && c === q);
  }


  // ------------------------------------------------------------------ the summary in words

  function counted(n, noun) {
    var forms = MESH.nouns[noun];
    return n + " " + (n === 1 ? forms[0] : forms[1]);
  }

  /** A sentence of the summary: a template, or a (one, many) pair chosen by values.n. */
  function sentence(key, values) {
    return I.fill(MESH.summary[key], values);
  }

  /** A distance as the summary writes it: rounded up to 1, 2 or 5 times a power of ten. */
  function distanceText(x) {
    return I.roundDistance(x, false)[1];
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
    if (r.welded_vertices) lines.push(sentence("welded", { n: r.welded_vertices, distance: distanceText(r.weld_distance) }));
    if (r.ok) {
      lines.push(sentence("ok", {}));
      return lines.concat(pieceLines(r));
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
    if (r.near_miss) lines.push(sentence("near_miss", { n: r.near_miss.edges, distance: distanceText(r.near_miss.distance) }));
    lines = lines.concat(pieceLines(r));
    var nFlip = r.faces_to_flip.length;
    if (nFlip) {
      var judged = r.components.some(function (c) { return c.closed || c.judged_by !== null; });
      lines.push(sentence("flip", { n: nFlip, end: sentence(judged ? "flip_end_closed" : "flip_end_open", {}) }));
    }
    return lines;
  }

  /** What can be said of each piece's winding, and why (report.py's _piece_lines). */
  function pieceLines(r) {
    var lines = [], sheets = [], enclosing = [];
    var many = r.components.length > 1;
    r.components.forEach(function (c, j) {
      var name = many ? sentence("piece", { i: j + 1, faces: counted(c.faces, "face") }) : sentence("whole", {});
      if (!c.orientable) lines.push(sentence("not_orientable", { name: name }));
      else if (!c.consistent) lines.push(sentence("inconsistent", { name: name }));
      else if (c.closed && c.cavity) lines.push(sentence(c.outward ? "cavity" : "cavity_inside_out", { name: name }));
      else if (c.closed && c.outward === false) lines.push(sentence("inside_out", { name: name }));
      else if (c.closed && c.outward === null) lines.push(sentence("no_volume", { name: name }));
      else if (!c.closed && c.outward === false) lines.push(sentence("open_inside_out", { name: name }));
      else if (!c.closed && c.outward === true) enclosing.push(name);
      else if (!c.closed) sheets.push(name);
    });
    [["open_encloses", enclosing], ["open_sheet", sheets]].forEach(function (kf) {
      if (kf[1].length) lines.push(sentence(kf[0], { n: kf[1].length, name: kf[1][0] }));
    });
    return lines;
  }

  /** The report without the view's private keys: what Python's to_dict() returns. */
  function toDict(report) {
    return Object.fromEntries(Object.entries(report).filter(function (kv) { return kv[0].charAt(0) !== "_"; }));
  }

  return {
    check: check,
    toDict: toDict,
    summary: summary,
    counted: counted,
    degenerateFaces: degenerateFaces,
    internal: Object.assign({}, I, { faceNormals: faceNormals }),
  };
});
