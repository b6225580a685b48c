/*
 * trinormal's mesh check in the browser, the report for printing: the holes (rims of boundary
 * edges, with the edges around each), the surface area, the enclosed volume, the size with a
 * units hint and the verdict, as trinormal/mesh/printing.py computes them, operation for
 * operation and in the same order, so the numbers agree to the last bit. The templates and
 * limits are the package's (TRINORMAL_CONSTANTS.mesh.printing). Loaded after
 * trinormal-mesh-check.js: its `check` and `summary` are extended here, so the report gains
 * the keys holes, surface_area, volume, size and verdict, and the summary its printing lines.
 * `table` writes the page's two tables of a report as mesh_page.report_table does in Python.
 */
self.TrinormalMesh.part("print", "check", function (base) {
  "use strict";
  var I = base.internal, P = I.MESH.printing, T = P.templates, UNITS = P.units;
  var core = self.TrinormalCore;

  /** A line or word of the printing templates: a (one, many) pair chosen by values.n. */
  function say(key, values) {
    return I.fill(T[key], values);
  }

  /** A number of the printing lines, as printing.shown writes it (significant digits). */
  function shown(x) {
    if (!Number.isFinite(x)) return Number.isNaN(x) ? "nan" : x > 0 ? "inf" : "-inf";
    var a = Math.abs(x), decimals = P.significant - 1;
    while (a >= 10.0 && decimals > 0) {
      a /= 10.0;
      decimals--;
    }
    while (a > 0.0 && a < 1.0 && decimals < 15) {
      a *= 10.0;
      decimals++;
    }
    if (a < 1.0 || Math.abs(x) >= P.sci_above) decimals = P.significant - 1;
    var r = core.doubleRatio(x);
    return core.formatSurd(r[0] < 0n, r[0] * r[0], r[1] * r[1], decimals, true);
  }

  /** The bounding box of the used vertices and the surface area (printing.measure). */
  function measure(V, F) {
    var nf = F.length / 3;
    var box = I.bounds(V, F);
    if (!box) return { surface_area: 0.0, size: null };
    // + 0 writes a zero corner as 0, never -0, whichever of the two came first
    var lo = box[0].map(function (x) { return x + 0; });
    var hi = box[1].map(function (x) { return x + 0; });
    var s = I.powerOfTwoBelow(Math.max(Math.abs(lo[0]), Math.abs(lo[1]), Math.abs(lo[2]),
      Math.abs(hi[0]), Math.abs(hi[1]), Math.abs(hi[2])));
    var total = 0.0;
    for (var f = 0; f < nf; f++) {
      var i0 = 3 * F[3 * f], i1 = 3 * F[3 * f + 1], i2 = 3 * F[3 * f + 2];
      var px = V[i0] / s, py = V[i0 + 1] / s, pz = V[i0 + 2] / s;
      var qx = V[i1] / s - px, qy = V[i1 + 1] / s - py, qz = V[i1 + 2] / s - pz;
      var sx = V[i2] / s - px, sy = V[i2 + 1] / s - py, sz = V[i2 + 2] / s - pz;
      var n0 = qy * sz - qz * sy, n1 = qz * sx - qx * sz, n2 = qx * sy - qy * sx;
      total += Math.sqrt(n0 * n0 + n1 * n1 + n2 * n2);
    }
    var extent = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    return {
      surface_area: total * 0.5 * s * s,
      size: { min: lo, max: hi, extent: extent, units_hint: unitsHint(extent) },
    };
  }

  /** "metres", "inches", "micrometres" or null: Size.units_hint. */
  function unitsHint(extent) {
    var largest = Math.max(extent[0], extent[1], extent[2]);
    if (!Number.isFinite(largest) || largest === 0.0) return null;
    if (largest < UNITS.metres_below) return "metres";
    if (largest < UNITS.inches_below) return "inches";
    if (largest > UNITS.micrometres_above) return "micrometres";
    return null;
  }

  /** The number of edges around each hole, largest first (printing._holes). */
  function holes(boundary, nv) {
    var parent = I.identity(nv);
    boundary.forEach(function (e) { I.union(parent, e[0], e[1]); });
    var count = new Map();
    boundary.forEach(function (e) {
      var r = I.find(parent, e[0]);
      count.set(r, (count.get(r) || 0) + 1);
    });
    return Array.from(count.values()).sort(function (x, y) { return y - x; });
  }

  function verdict(r, nHoles) {
    var pieces = r.components;
    var measured = pieces.filter(function (c) { return c.closed && c.consistent; });
    // an open piece judged over its holes counts as a closed one does (printing.py's _winding)
    var winding;
    if (!pieces.every(function (c) { return c.orientable; })) winding = "one_sided";
    else if (!r.consistent_winding) winding = "inconsistent";
    else if (pieces.some(function (c) { return c.outward === false; })) winding = "inside_out";
    else if (measured.some(function (c) { return c.outward === null; })) winding = "no_volume";
    else if (r.closed || (pieces.length && pieces.every(function (c) { return c.outward === true; }))) winding = "wound_outward";
    else winding = "wound_consistently";
    var conclusion;
    if (r.ok) conclusion = say("ready");
    else {
      var found = [
        ["obstacle_holes", nHoles],
        ["obstacle_fins", r.non_manifold_edges.length],
        ["obstacle_pinches", r.non_manifold_vertices.length],
        ["obstacle_degenerate", r.degenerate_faces.length],
        ["obstacle_duplicates", r.duplicate_faces.length + r.reversed_duplicate_faces.length],
        ["obstacle_unused", r.unused_vertices.length],
        ["obstacle_one_sided", pieces.filter(function (c) { return !c.orientable; }).length],
        ["obstacle_no_volume", measured.filter(function (c) { return c.outward === null; }).length],
        ["obstacle_flips", r.faces_to_flip.length],
      ];
      var obstacles = found.filter(function (x) { return x[1]; }).map(function (x) { return say(x[0], { n: x[1] }); });
      if (r.n_faces === 0) obstacles.unshift(say("no_faces"));
      conclusion = say("not_ready", { obstacles: obstacles.join(", ") });
    }
    return say("verdict", {
      closure: say(r.closed ? "watertight" : "not_watertight"),
      pieces: base.counted(pieces.length, "piece"),
      winding: say(winding),
      conclusion: conclusion,
    });
  }

  /** The sum of the pieces' known volumes, in piece order; null when none is known. */
  function totalVolume(pieces) {
    var total = null;
    pieces.forEach(function (c) {
      if (c.volume !== null) total = total === null ? c.volume : total + c.volume;
    });
    return total;
  }

  /** check() of trinormal-mesh-check.js, with the report for printing added after its keys. */
  function check(vertices, faces, onProgress, weld) {
    var r = base.check(vertices, faces, onProgress, weld);
    var m = measure(vertices, faces);
    var h = holes(r.boundary_edges, r.n_vertices);
    r.holes = h;
    r.surface_area = m.surface_area;
    r.volume = totalVolume(r.components);
    r.size = m.size;
    r.verdict = verdict(r, h.length);
    return r;
  }

  function areaVolume(r) {
    var area = shown(r.surface_area);
    if (r.volume === null) return say("area_no_volume", { area: area });
    if (r.components.length === 1) return say("area_volume", { area: area, volume: shown(r.volume) });
    var measured = [];
    r.components.forEach(function (c, i) { if (c.volume !== null) measured.push([i, c.volume]); });
    var parts = measured.slice(0, P.listed).map(function (x) { return say("piece_volume", { i: x[0] + 1, volume: shown(x[1]) }); });
    if (measured.length > P.listed) parts.push("…");
    if (measured.length < r.components.length) parts.push(say("others_none"));
    return say("area_volumes", { area: area, volume: shown(r.volume), pieces: parts.join(", ") });
  }

  /** The units hint's line of a size, if it has one: Size.lines()[1:]. */
  function hintLines(size) {
    var hint = size.units_hint, e = size.extent;
    if (hint === null) return [];
    var limit = UNITS[hint === "micrometres" ? "micrometres_above" : hint + "_below"];
    return [say("hint_" + hint, { largest: shown(Math.max(e[0], e[1], e[2])), limit: shown(limit) })];
  }

  /** The printing lines of the summary: PrintReport.lines(). */
  function printLines(r) {
    var out = [];
    var n = r.holes.length;
    if (n) {
      var edges = n === 1 ? base.counted(r.holes[0], "edge") : r.holes.slice(0, P.listed).join(", ");
      if (n > P.listed) edges += ", …";
      out.push(say("holes", { n: n, edges: edges }));
    }
    if (r.size !== null) {
      var e = r.size.extent;
      out.push(say("size", { x: shown(e[0]), y: shown(e[1]), z: shown(e[2]) }));
      out = out.concat(hintLines(r.size));
    }
    out.push(areaVolume(r));
    out.push(say("verdict_line", { verdict: r.verdict }));
    return out;
  }

  /** summary() of trinormal-mesh-check.js, then the printing lines: MeshReport.summary(). */
  function summary(r) {
    return base.summary(r).concat(printLines(r));
  }

  // ------------------------------------------------------------------ the page's tables

  /** What a row's list holds, by the row's key: faces, edges or vertices (mesh_page._noun). */
  function noun(key) {
    return /_edges$/.test(key) ? "edge" : /_vertices$/.test(key) ? "vertex" : "face";
  }

  /** How one value of the report reads in a cell: a list as "2: faces 5, 9" (mesh_page._cell). */
  function cell(value, key) {
    if (value === true) return base.message("yes");
    if (value === false) return base.message("no");
    if (value === null || value === undefined) return base.message("no_answer");
    if (Array.isArray(value)) {
      if (!value.length) return "0";
      var items = value.slice(0, I.MESH.listed).map(function (x) {
        return Array.isArray(x) ? x[0] + "–" + x[1] : String(x);
      });
      var more = value.length - I.MESH.listed;
      if (more > 0) items.push(base.message("more", { count: more }));
      if (key === "holes") return value.length + ": " + items.join(", "); // edges around each
      var forms = I.MESH.nouns[noun(key)];
      return value.length + ": " + (value.length === 1 ? forms[0] : forms[1]) + " " + items.join(", ");
    }
    return String(value);
  }

  /** A cell of a row of the report for printing (mesh_page._printing_cell). */
  function printingCell(r, key) {
    if (key === "size") {
      if (r.size === null) return base.message("no_answer");
      var e = r.size.extent;
      var box = base.message("size_cell", { x: shown(e[0]), y: shown(e[1]), z: shown(e[2]) });
      return [box].concat(hintLines(r.size)).join("\n"); // the units hint on a line of its own
    }
    if (key === "surface_area") return shown(r.surface_area);
    return r.volume === null ? base.message("no_volume_cell") : shown(r.volume);
  }

  /**
   * The report's two tables on the page, every cell as text (mesh_page.report_table): rows,
   * [key, label, text] for each report row; pieces, one list of texts per piece, one a column.
   */
  function table(r) {
    var rows = I.MESH.rows.map(function (row) {
      var key = row[0];
      var printing = key === "size" || key === "surface_area" || key === "volume";
      return [key, row[1], printing ? printingCell(r, key) : cell(r[key], key)];
    });
    var pieces = r.components.map(function (c, i) {
      return I.MESH.columns.map(function (column) {
        var key = column[0];
        if (key === "piece") return String(i + 1);
        if (key === "volume" && c.volume !== null) return shown(c.volume);
        return cell(c[key], "");
      });
    });
    return { rows: rows, pieces: pieces };
  }

  return { check: check, summary: summary, table: table };
});
