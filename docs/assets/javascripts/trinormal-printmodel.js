/*
 * trinormal's printable model in the browser: a port of trinormal/printmodel.py (the plate,
 * the normal as an arrow, U and V as ridges, A, B and C marked), operation for operation, so
 * that the same floats give the same vertices, the same faces, the same binary STL bytes and
 * the same 3MF model XML. tests/test_printmodel_parity.py holds the two equal.
 *
 * Every size, shape and message comes from the package (trinormal.printmodel.site_constants)
 * through window.TRINORMAL_CONSTANTS.print. Plain JavaScript, no dependencies. In the browser
 * it defines window.TrinormalPrintModel; in Node, module.exports is a function that takes
 * those constants and returns the API.
 */
(function (root, factory) {
  "use strict";
  if (typeof module === "object" && module.exports) {
    module.exports = factory;
  } else {
    root.TrinormalPrintModel = factory((root.TRINORMAL_CONSTANTS || {}).print);
  }
})(typeof self !== "undefined" ? self : this, function (K) {
  "use strict";

  var S = Math.sqrt(0.5);
  var OCTAGON = [[1.0, 0.0], [S, S], [0.0, 1.0], [-S, S], [-1.0, 0.0], [-S, -S], [0.0, -1.0], [S, -S]];

  /** A refusal: the message is the package's sentence. */
  function PrintModelError(message) {
    this.name = "PrintModelError";
    this.message = message;
  }
  PrintModelError.prototype = Object.create(Error.prototype);

  function fill(template, values) {
    return template.replace(/\{(\w+)\}/g, function (_, key) {
      return String(values[key]);
    });
  }

  /** Python's repr() of x without a trailing ".0"; exact for numbers on the model's grid. */
  function num(x) {
    return String(x + 0.0);
  }

  function snap(x) {
    return Math.floor(x * K.grid + 0.5) / K.grid;
  }

  // ------------------------------------------------------------------------- 2D geometry

  function orient(p, q, r) {
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
  }

  function dist(p, q) {
    return Math.sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
  }

  function pointSegment(p, a, b) {
    var dx = b[0] - a[0];
    var dy = b[1] - a[1];
    var length2 = dx * dx + dy * dy;
    var t = length2 === 0 ? 0.0 : ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2;
    t = Math.min(1.0, Math.max(0.0, t));
    return dist(p, [a[0] + t * dx, a[1] + t * dy]);
  }

  function segmentsMeet(p1, p2, q1, q2) {
    var d1 = orient(q1, q2, p1);
    var d2 = orient(q1, q2, p2);
    var d3 = orient(p1, p2, q1);
    var d4 = orient(p1, p2, q2);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    return (
      (d1 === 0 && pointSegment(p1, q1, q2) === 0) ||
      (d2 === 0 && pointSegment(p2, q1, q2) === 0) ||
      (d3 === 0 && pointSegment(q1, p1, p2) === 0) ||
      (d4 === 0 && pointSegment(q2, p1, p2) === 0)
    );
  }

  function segmentSegment(p1, p2, q1, q2) {
    if (segmentsMeet(p1, p2, q1, q2)) return 0.0;
    return Math.min(pointSegment(p1, q1, q2), pointSegment(p2, q1, q2), pointSegment(q1, p1, p2), pointSegment(q2, p1, p2));
  }

  // ------------------------------------------------------------------------- triangulation

  function bridge(pts, poly, hole, others) {
    var mAt = 0;
    for (var i = 1; i < hole.length; i++) if (pts[hole[i]][0] > pts[hole[mAt]][0]) mAt = i;
    var m = hole[mAt];
    var rings = [poly, hole].concat(others);
    var edges = [];
    rings.forEach(function (r) {
      for (var j = 0; j < r.length; j++) edges.push([r[j], r[(j + 1) % r.length]]);
    });
    var order = poly.map(function (_, k) { return k; });
    var d = poly.map(function (p) { return dist(pts[p], pts[m]); });
    order.sort(function (x, y) { return d[x] - d[y] || x - y; });
    for (var n = 0; n < order.length; n++) {
      var k = order[n];
      var p = poly[k];
      if (poly.indexOf(p) !== poly.lastIndexOf(p)) continue;
      var clear = edges.every(function (e) {
        return e[0] === p || e[1] === p || e[0] === m || e[1] === m || !segmentsMeet(pts[m], pts[p], pts[e[0]], pts[e[1]]);
      });
      if (clear) {
        var loop = hole.slice(mAt).concat(hole.slice(0, mAt + 1));
        return poly.slice(0, k + 1).concat(loop, poly.slice(k));
      }
    }
    throw new Error("no vertex of the polygon can be joined to a hole");
  }

  function triangulate(outer, holes) {
    var pts = outer.slice();
    var rings = [];
    holes.forEach(function (hole) {
      rings.push(hole.map(function (_, i) { return pts.length + i; }));
      pts = pts.concat(hole);
    });
    var poly = outer.map(function (_, i) { return i; });
    var right = function (r) {
      return Math.max.apply(null, r.map(function (i) { return pts[i][0]; }));
    };
    rings.sort(function (x, y) { return right(y) - right(x) || x[0] - y[0]; });
    for (var n = 0; n < rings.length; n++) poly = bridge(pts, poly, rings[n], rings.slice(n + 1));
    var triangles = [];
    while (poly.length > 3) {
      var cut = false;
      for (var i = 0; i < poly.length && !cut; i++) {
        var a = poly[(i - 1 + poly.length) % poly.length], b = poly[i], c = poly[(i + 1) % poly.length];
        if (orient(pts[a], pts[b], pts[c]) <= 0) continue;
        var inside = poly.some(function (q) {
          return q !== a && q !== b && q !== c &&
            orient(pts[a], pts[b], pts[q]) >= 0 && orient(pts[b], pts[c], pts[q]) >= 0 && orient(pts[c], pts[a], pts[q]) >= 0;
        });
        if (inside) continue;
        triangles.push([a, b, c]);
        poly.splice(i, 1);
        cut = true;
      }
      if (!cut) throw new Error("no ear to cut: the polygon is not simple");
    }
    triangles.push([poly[0], poly[1], poly[2]]);
    return { pts: pts, triangles: triangles };
  }

  // ------------------------------------------------------------------------- the solid

  function Builder() {
    this.index = new Map();
    this.vertices = [];
    this.faces = [];
  }
  Builder.prototype.vertex = function (p, z) {
    var key = p[0] + " " + p[1] + " " + z;
    var at = this.index.get(key);
    if (at === undefined) {
      at = this.vertices.length;
      this.index.set(key, at);
      this.vertices.push([p[0], p[1], z]);
    }
    return at;
  };
  Builder.prototype.face = function (a, b, c) {
    this.faces.push([a, b, c]);
  };
  Builder.prototype.flat = function (outer, holes, z, up) {
    var t = triangulate(outer, holes);
    var self = this;
    var ids = t.pts.map(function (p) { return self.vertex(p, z); });
    t.triangles.forEach(function (tri) {
      if (up === false) self.face(ids[tri[0]], ids[tri[2]], ids[tri[1]]);
      else self.face(ids[tri[0]], ids[tri[1]], ids[tri[2]]);
    });
  };
  Builder.prototype.band = function (lower, z0, upper, z1) {
    var n = lower.length;
    for (var i = 0; i < n; i++) {
      var j = (i + 1) % n;
      var p0 = this.vertex(lower[i], z0), q0 = this.vertex(lower[j], z0);
      var p1 = this.vertex(upper[i], z1), q1 = this.vertex(upper[j], z1);
      this.face(p0, q0, q1);
      this.face(p0, q1, p1);
    }
  };
  Builder.prototype.cone = function (ring, z, tip) {
    var t = this.vertex([tip[0], tip[1]], tip[2]);
    for (var i = 0; i < ring.length; i++) this.face(this.vertex(ring[i], z), this.vertex(ring[(i + 1) % ring.length], z), t);
  };
  Builder.prototype.prism = function (outer, holes, z0, z1) {
    var self = this;
    this.band(outer, z0, outer, z1);
    holes.forEach(function (hole) {
      self.band(hole, z0, hole, z1);
      self.flat(hole.slice().reverse(), [], z0);
    });
    this.flat(outer, holes, z1);
  };

  function ring(center, radius) {
    return OCTAGON.map(function (q) {
      return [snap(center[0] + radius * q[0]), snap(center[1] + radius * q[1])];
    });
  }

  function shifted(points, center, scale) {
    return points.map(function (q) {
      return [snap(center[0] + (q[0] - 2.5) * scale), snap(center[1] + (q[1] - 3.5) * scale)];
    });
  }

  // ------------------------------------------------------------------------- the layout

  function flatCorners(u, v, size) {
    var big = Math.max(Math.abs(u[0]), Math.abs(u[1]), Math.abs(u[2]), Math.abs(v[0]), Math.abs(v[1]), Math.abs(v[2]));
    u = u.map(function (x) { return x / big; });
    v = v.map(function (x) { return x / big; });
    var w = [v[0] - u[0], v[1] - u[1], v[2] - u[2]];
    var lu = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    var lv = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    var lw = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    var scale = size / Math.max(lu, lv, lw);
    var n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    var ln = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    var along = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / lu;
    return [[0.0, 0.0], [snap(lu * scale), 0.0], [snap(along * scale), snap((ln / lu) * scale)]];
  }

  function inset(p, center, r, d) {
    var k = (r - d) / r;
    return [center[0] + (p[0] - center[0]) * k, center[1] + (p[1] - center[1]) * k];
  }

  /** The features do not fit with one entry of K.fits (trinormal.printmodel._features.Unfit). */
  function Unfit(reason) {
    this.reason = reason;
  }

  function unit(start, end) {
    var length = dist(start, end);
    return [(end[0] - start[0]) / length, (end[1] - start[1]) / length];
  }

  /** Where a ridge begins and ends along start→end, clear of obstacles [centre, side, reach]. */
  function ridge(start, end, sep, obstacles) {
    var length = dist(start, end);
    var e = unit(start, end);
    var t0 = sep, t1 = length;
    obstacles.forEach(function (o) {
      var m = o[0], side = o[1], reach = o[2];
      var along = (m[0] - start[0]) * e[0] + (m[1] - start[1]) * e[1];
      var off = Math.abs((m[0] - start[0]) * e[1] - (m[1] - start[1]) * e[0]);
      if (off < reach) {
        var cut = along + side * Math.sqrt(reach * reach - off * off);
        if (side > 0) t0 = Math.max(t0, cut);
        else if (cut > t0) t1 = Math.min(t1, cut);
      }
    });
    return [t0, t1, e[0], e[1]];
  }

  function layout(p, marks, names, fit, tabs) {
    var scale = fit[0], margin = fit[1], gap = fit[2], minGap = fit[3], tip = fit[4], width = fit[5];
    var sides = [dist(p[1], p[2]), dist(p[2], p[0]), dist(p[0], p[1])];
    var perimeter = sides[0] + sides[1] + sides[2];
    var r = orient(p[0], p[1], p[2]) / perimeter;
    var center = [
      (sides[0] * p[0][0] + sides[1] * p[1][0] + sides[2] * p[2][0]) / perimeter,
      (sides[0] * p[0][1] + sides[1] * p[1][1] + sides[2] * p[2][1]) / perimeter,
    ];
    var radius = marks === "letters" ? K.mark_radius[marks] * scale : K.mark_radius[marks];
    if (r <= (tabs ? margin + width / 2 : margin + radius) + minGap) throw new Unfit(K.messages.marks);
    var spots = tabs ? tabs[0] : p.map(function (q) { return inset(q, center, r, margin + radius); });
    var line = p.map(function (q) { return inset(q, center, r, margin + width / 2); });
    var centroid = [(p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3];
    var eu = unit(line[0], line[1]);
    var ev = unit(line[0], line[2]);
    var cosA = eu[0] * ev[0] + eu[1] * ev[1];
    var sep = (width + gap) / (2 * Math.sqrt((1 - cosA) / 2));
    var ridges = [[1, "U"], [2, "V"]].map(function (kn) {
      var k = kn[0];
      var obstacles = tabs ? [] : [
        [spots[0], 1.0, radius + gap + width / 2],
        [spots[k], -1.0, radius + gap + width],
      ];
      obstacles.push([centroid, -1.0, K.shaft_radius + gap + width]);
      var got = ridge(line[0], line[k], sep, obstacles);
      var t0 = got[0], t1 = got[1], ex = got[2], ey = got[3];
      if (t1 - t0 < tip + width) throw new Unfit(fill(K.messages.ridge, { name: kn[1] }));
      var s = line[0];
      return [
        [s[0] + ex * t0, s[1] + ey * t0],
        [s[0] + ex * (t1 - tip), s[1] + ey * (t1 - tip)],
        [s[0] + ex * t1, s[1] + ey * t1],
      ];
    });
    var out = { corners: p, centroid: centroid, marks: spots, ridges: ridges, fit: fit, outline: tabs ? tabs[1] : p.slice() };
    checkClearance(out, radius, minGap, names);
    return out;
  }

  /** A tab outside the edge p→q from `start` along it: on the edge, out, out, on the edge. */
  function tab(p, q, start, half, depth) {
    var e = unit(p, q);
    var out = [e[1], -e[0]];
    var a = [p[0] + e[0] * start, p[1] + e[1] * start];
    var b = [a[0] + e[0] * 2 * half, a[1] + e[1] * 2 * half];
    return [a, [a[0] + out[0] * depth, a[1] + out[1] * depth], [b[0] + out[0] * depth, b[1] + out[1] * depth], b].map(
      function (q2) { return [snap(q2[0]), snap(q2[1])]; }
    );
  }

  /** The marks on tabs beside the corners, the ridges inside (trinormal's on_tabs). */
  function onTabs(p, marks, names) {
    var last = K.fits[K.fits.length - 1];
    var margin = last[1], gap = last[2], minGap = last[3], tip = last[4], width = last[5];
    var radius = K.mark_radius[marks];
    var half = radius + margin;
    var depth = gap + 2 * radius + margin;
    var onEdge = [[], [], []];
    var spots = [];
    for (var k = 0; k < 3; k++) {
      var after = p[(k + 1) % 3], before = p[(k + 2) % 3];
      var longer = Math.max(dist(p[k], after), dist(before, p[k]));
      if (longer < 2 * (gap + half)) throw new Unfit(K.messages.marks);
      var t;
      if (dist(p[k], after) >= dist(before, p[k])) {
        t = tab(p[k], after, gap, half, depth);
        onEdge[k].push(t);
      } else {
        t = tab(before, p[k], longer - gap - 2 * half, half, depth);
        onEdge[(k + 2) % 3].push(t);
      }
      spots.push([(t[0][0] + t[2][0]) / 2, (t[0][1] + t[2][1]) / 2]);
    }
    var outline = [];
    var all = [];
    for (k = 0; k < 3; k++) {
      outline.push(p[k]);
      var here = onEdge[k].slice();
      if (here.length === 2 && dist(p[k], here[1][0]) < dist(p[k], here[0][0])) here.reverse();
      here.forEach(function (t2) { outline.push.apply(outline, t2); });
      all.push.apply(all, onEdge[k]);
    }
    checkTabs(all, minGap);
    return layout(p, marks, names, [1.0, margin, gap, minGap, tip, width], [spots, outline]);
  }

  function checkTabs(tabs, minGap) {
    for (var i = 0; i < tabs.length; i++) {
      for (var j = i + 1; j < tabs.length; j++) {
        for (var m = 0; m < 4; m++) {
          for (var n = 0; n < 4; n++) {
            var a = tabs[i], b = tabs[j];
            if (segmentSegment(a[m], a[(m + 1) % 4], b[n], b[(n + 1) % 4]) < minGap) throw new Unfit(K.messages.marks);
          }
        }
      }
    }
  }

  function checkClearance(lay, radius, minGap, names) {
    var words = K.messages;
    var width = lay.fit[5];
    var parts = [[words.arrow, lay.centroid, lay.centroid, K.shaft_radius]];
    for (var i = 0; i < 3; i++) {
      if (lay.outline.length === 3) parts.push([fill(words.mark, { name: names[i] }), lay.marks[i], lay.marks[i], radius]);
    }
    ["U", "V"].forEach(function (name, k) {
      var r = lay.ridges[k];
      parts.push([fill(words.ridge_name, { name: name }), r[0], r[1], width / 2]);
      parts.push([fill(words.ridge_name, { name: name }), r[1], r[2], width]);
    });
    for (i = 0; i < parts.length; i++) {
      for (var j = i + 1; j < parts.length; j++) {
        var a = parts[i], b = parts[j];
        if (a[0] !== b[0] && segmentSegment(a[1], a[2], b[1], b[2]) < a[3] + b[3] + minGap) {
          throw new Unfit(fill(K.messages.touch, { first: a[0], second: b[0] }));
        }
      }
    }
    var c = lay.corners;
    parts.forEach(function (part) {
      for (var k = 0; k < 3; k++) {
        if (segmentSegment(part[1], part[2], c[k], c[(k + 1) % 3]) < part[3] + minGap) {
          throw new Unfit(fill(K.messages.touch, { first: part[0], second: words.edge }));
        }
      }
    });
  }

  /** The layout with the first entry of K.fits that fits, else the marks on tabs (onTabs). */
  function fitted(u, v, size, marks, names) {
    var corners = flatCorners(u, v, size);
    for (var i = 0; i < K.fits.length; i++) {
      try {
        return layout(corners, marks, names, K.fits[i]);
      } catch (err) {
        if (!(err instanceof Unfit)) throw err;
      }
    }
    return onTabs(corners, marks, names);
  }

  function fits(u, v, size, marks, names) {
    try {
      fitted(u, v, size, marks, names);
    } catch (err) {
      if (!(err instanceof Unfit)) throw err;
      return false;
    }
    return true;
  }

  /** The smallest whole size above `size` at which the features fit, or null (as Python's). */
  function smallestSize(u, v, size, marks, names) {
    var low = size, high = K.size_range[1], above;
    for (;;) {
      if (low >= high) return null;
      above = Math.min(high, Math.floor(low * 1.25) + 1);
      if (fits(u, v, above, marks, names)) break;
      low = above;
    }
    low = Math.floor(low);
    while (above - low > 1) {
      var mid = Math.floor((low + above) / 2);
      if (fits(u, v, mid, marks, names)) above = mid;
      else low = mid;
    }
    return above;
  }

  // ------------------------------------------------------------------------- the solid, built

  function ridgeOutline(start, base, tip, width) {
    var e = unit(start, tip);
    var n = [-e[1], e[0]];
    var half = width / 2;
    return [
      [start[0] - n[0] * half, start[1] - n[1] * half],
      [base[0] - n[0] * half, base[1] - n[1] * half],
      [base[0] - n[0] * width, base[1] - n[1] * width],
      tip,
      [base[0] + n[0] * width, base[1] + n[1] * width],
      [base[0] + n[0] * half, base[1] + n[1] * half],
      [start[0] + n[0] * half, start[1] + n[1] * half],
    ].map(function (q) { return [snap(q[0]), snap(q[1])]; });
  }

  function solid(lay, size, marks, names) {
    var top = K.thickness;
    var out = new Builder();
    var plate = lay.outline;
    var shaft = ring(lay.centroid, K.shaft_radius);
    var footprints = [shaft];
    var raised = [];
    lay.ridges.forEach(function (r) {
      var outline = ridgeOutline(r[0], r[1], r[2], lay.fit[5]);
      footprints.push(outline);
      raised.push([outline, [], snap(top + K.ridge_height)]);
    });
    var dots = [];
    for (var i = 0; i < 3; i++) {
      var name = names[i], spot = lay.marks[i];
      if (marks === "letters") {
        var rings = K.letters[name];
        var outline = shifted(rings[0], spot, lay.fit[0]);
        footprints.push(outline);
        var holes = rings.slice(1).map(function (h) { return shifted(h, spot, lay.fit[0]); });
        raised.push([outline, holes, snap(top + K.letter_height)]);
        continue;
      }
      K.braille[name].forEach(function (cr) {
        var center = [spot[0] + (cr[0] - 0.5) * K.dot_spacing, spot[1] + (0.5 - cr[1]) * K.dot_spacing];
        dots.push([ring(center, K.dot_radius[0]), ring(center, K.dot_radius[1])]);
        footprints.push(dots[dots.length - 1][0]);
      });
    }

    out.flat(plate, [], 0.0, false);
    out.band(plate, 0.0, plate, top);
    out.flat(plate, footprints.map(function (f) { return f.slice().reverse(); }), top);

    var length = K.arrow_length * size;
    var neck = snap(top + length - K.head_length);
    var head = ring(lay.centroid, K.head_radius);
    out.band(shaft, top, shaft, neck);
    out.band(shaft, neck, head, neck);
    out.cone(head, neck, [snap(lay.centroid[0]), snap(lay.centroid[1]), snap(top + length)]);
    raised.forEach(function (r) { out.prism(r[0], r[1], top, r[2]); });
    dots.forEach(function (d) {
      out.band(d[0], top, d[1], snap(top + K.dot_height));
      out.flat(d[1], [], snap(top + K.dot_height));
    });
    return out;
  }

  // ------------------------------------------------------------------------- the files

  /** The model as a binary STL file: a Uint8Array, the bytes PrintModel.stl() writes. */
  function stl(model) {
    var faces = model.faces, v = model.vertices;
    var view = new DataView(new ArrayBuffer(84 + 50 * faces.length));
    for (var i = 0; i < 80; i++) view.setUint8(i, K.stl_header.charCodeAt(i));
    view.setUint32(80, faces.length, true);
    var at = 84;
    faces.forEach(function (f) {
      var p = v[f[0]], q = v[f[1]], r = v[f[2]];
      var e1 = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
      var e2 = [r[0] - p[0], r[1] - p[1], r[2] - p[2]];
      var n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
      var ln = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      var u = ln > 0 ? [n[0] / ln, n[1] / ln, n[2] / ln] : [0.0, 0.0, 0.0];
      u.concat(p, q, r).forEach(function (x) {
        view.setFloat32(at, x, true);
        at += 4;
      });
      view.setUint16(at, 0, true);
      at += 2;
    });
    return new Uint8Array(view.buffer);
  }

  /** The 3MF model part, the text PrintModel.model_xml() writes. */
  function modelXml(model) {
    var lines = [
      '<?xml version="1.0" encoding="UTF-8"?>',
      '<model unit="millimeter" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">',
      '<metadata name="Title">' + fill(K.messages.title, { order: model.names.split("").join("→") }) + "</metadata>",
      "<resources>",
      '<object id="1" type="model">',
      "<mesh>",
      "<vertices>",
    ];
    model.vertices.forEach(function (p) {
      lines.push('<vertex x="' + num(p[0]) + '" y="' + num(p[1]) + '" z="' + num(p[2]) + '"/>');
    });
    lines.push("</vertices>", "<triangles>");
    model.faces.forEach(function (f) {
      lines.push('<triangle v1="' + f[0] + '" v2="' + f[1] + '" v3="' + f[2] + '"/>');
    });
    lines.push("</triangles>", "</mesh>", "</object>", "</resources>", '<build><item objectid="1"/></build>', "</model>");
    return lines.join("\n") + "\n";
  }

  /**
   * The model of a proper triangle with edges u and v (numbers) from corner A, its corners
   * named `names` ("ABC" or "ACB", the winding's order), as trinormal.printmodel.build makes
   * it: {vertices, faces, corners, names, tip, size, marks}. Throws PrintModelError (the
   * package's sentence) for a triangle too thin to carry the features at this size.
   */
  function build(u, v, names, size, marks) {
    var lay;
    try {
      lay = fitted(u, v, size, marks, names);
    } catch (err) {
      if (!(err instanceof Unfit)) throw err;
      var least = smallestSize(u, v, size, marks, names);
      if (least === null) {
        throw new PrintModelError(fill(K.messages.too_thin_always, { size: num(K.size_range[1]), reason: err.reason }));
      }
      throw new PrintModelError(fill(K.messages.too_thin, { size: num(size), reason: err.reason, fits: num(least) }));
    }
    var s = solid(lay, size, marks, names);
    return {
      vertices: s.vertices,
      faces: s.faces,
      corners: lay.corners.map(function (p) { return [p[0], p[1], K.thickness]; }),
      names: names,
      tip: [snap(lay.centroid[0]), snap(lay.centroid[1]), snap(K.thickness + K.arrow_length * size)],
      size: size,
      marks: marks,
    };
  }

  /** The refusal for a degenerate triangle, the package's sentence. */
  function degenerate() {
    return new PrintModelError(K.messages.degenerate);
  }

  return { build: build, stl: stl, modelXml: modelXml, degenerate: degenerate, PrintModelError: PrintModelError };
});
