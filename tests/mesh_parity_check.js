/*
 * Run the mesh page's JavaScript (docs/assets/javascripts/trinormal-mesh*.js, loaded in the
 * order mesh-worker.js loads them) on a corpus of mesh files and compare, file by file, with
 * what Python made of each: the report, its sentences, the page's tables of it, the format,
 * the repaired file byte for byte, or the error message. Used by tests/test_mesh_parity.py:
 *   node tests/mesh_parity_check.js CORPUS_DIR CONSTANTS.json
 * CORPUS_DIR/manifest.json lists {name, file, expected, repaired}: `file` holds the bytes the
 * page is given, `repaired` (when the file can be read) the bytes Python's write_mesh wrote for
 * the repaired mesh. Prints {checked, mismatches} as JSON; exits 1 when anything differs.
 */
"use strict";

var fs = require("fs");
var path = require("path");

var JS_DIR = path.join(__dirname, "..", "docs", "assets", "javascripts");

/** The script names mesh-worker.js gives importScripts, after the constants: the mesh parts. */
function meshParts() {
  var worker = fs.readFileSync(path.join(JS_DIR, "mesh-worker.js"), "utf8");
  var call = /importScripts\(([^)]*)\)/.exec(worker);
  return call[1]
    .split(",")
    .map(function (s) { return s.trim().replace(/^["']|["']$/g, ""); })
    .filter(function (s) { return s && s !== "trinormal-constants.js"; });
}

/**
 * TrinormalMesh as the worker has it: each part run as a plain script, in order, all of them
 * given one object as `self` (the worker's global scope) that starts with only the constants.
 */
function loadMesh(constants) {
  var scope = { TRINORMAL_CONSTANTS: constants };
  meshParts().forEach(function (part) {
    var file = path.join(JS_DIR, part);
    var source = fs.readFileSync(file, "utf8") + "\n//# sourceURL=" + file;
    new Function("self", "module", source)(scope, undefined); // no CommonJS `module`, as in a worker
  });
  return scope.TrinormalMesh;
}

/** Numbers JSON cannot hold, as Python's repr writes them (the corpus does the same). */
function finiteOrText(x) {
  if (typeof x === "number" && !Number.isFinite(x)) return x > 0 ? "inf" : x < 0 ? "-inf" : "nan";
  if (Array.isArray(x)) return x.map(finiteOrText);
  if (x && typeof x === "object") {
    var out = {};
    Object.keys(x).forEach(function (k) { out[k] = finiteOrText(x[k]); });
    return out;
  }
  return x;
}

/** Where two JSON values differ first ("" when equal); -0 differs from 0. */
function difference(want, got, where) {
  if (Array.isArray(want) || (want && typeof want === "object")) {
    if (!got || typeof got !== "object" || Array.isArray(want) !== Array.isArray(got)) {
      return where + ": want " + JSON.stringify(want).slice(0, 200) + ", got " + JSON.stringify(got).slice(0, 200);
    }
    var keys = Object.keys(want);
    if (keys.join() !== Object.keys(got).join()) return where + ": keys " + keys + " != " + Object.keys(got);
    for (var i = 0; i < keys.length; i++) {
      var d = difference(want[keys[i]], got[keys[i]], where + "." + keys[i]);
      if (d) return d;
    }
    return "";
  }
  return Object.is(want, got) ? "" : where + ": want " + JSON.stringify(want) + ", got " + JSON.stringify(got);
}

/** Where two files differ first: the byte, and for text the line of each. */
function byteDifference(want, got) {
  var n = Math.min(want.length, got.length);
  var at = 0;
  while (at < n && want[at] === got[at]) at++;
  if (at === n && want.length === got.length) return "";
  var lineStart = want.lastIndexOf(10, at - 1) + 1;
  var line = 1;
  for (var i = 0; i < lineStart; i++) if (want[i] === 10) line++;
  function lineOf(bytes) {
    var end = bytes.indexOf(10, lineStart);
    return JSON.stringify(Buffer.from(bytes.subarray(lineStart, end < 0 ? Math.min(bytes.length, lineStart + 80) : end)).toString("latin1"));
  }
  return "repaired file: byte " + at + " of " + want.length + " (got " + got.length + " bytes), line " + line +
    ": want " + lineOf(want) + ", got " + lineOf(got);
}

/** What the page makes of one file: {report, summary, format, ...} or {error}; and the repair. */
function run(M, name, bytes) {
  var mesh;
  try {
    mesh = M.read(bytes, name);
  } catch (err) {
    if (!(err instanceof M.MeshError)) throw err;
    return { shown: { error: err.message }, repaired: null };
  }
  var report = M.check(mesh.vertices, mesh.faces, null, /^weld-/.test(name)); // the weld control
  var dict = M.toDict(report);
  var shown = {
    report: finiteOrText(dict),
    summary: M.summary(dict),
    table: M.table(dict),
    format: mesh.format,
    binary: !!mesh.binary,
    polygons: mesh.polygons,
    split_polygons: mesh.split_polygons,
    nonplanar_polygons: mesh.nonplanar_polygons,
    crossing_polygons: mesh.crossing_polygons,
    notes: mesh.notes,
  };
  var faces = M.fixWinding(mesh.faces, report);
  shown.normals_against = M.normalsAgainst(mesh, mesh.faces, false);
  shown.normals_against_fixed = M.normalsAgainst(mesh, faces, true);
  return { shown: shown, repaired: M.write(mesh, faces) };
}

function checkCorpus(M, dir) {
  var manifest = JSON.parse(fs.readFileSync(path.join(dir, "manifest.json"), "utf8"));
  var mismatches = [];
  manifest.forEach(function (entry) {
    var bytes = new Uint8Array(fs.readFileSync(path.join(dir, entry.file)));
    var got;
    try {
      got = run(M, entry.name, bytes);
    } catch (err) {
      mismatches.push({ name: entry.name, problem: "threw " + (err && err.stack ? err.stack : err) });
      return;
    }
    var want = Object.assign({}, entry.expected);
    delete want.key;
    var problem = difference(want, got.shown, "");
    if (!problem && got.repaired && !entry.expected.report.faces_to_flip.length) {
      problem = byteDifference(bytes, got.repaired); // nothing to turn over: the file as it was
    }
    if (!problem && entry.repaired) {
      problem = byteDifference(new Uint8Array(fs.readFileSync(path.join(dir, entry.repaired))), got.repaired);
    }
    if (problem) mismatches.push({ name: entry.name, problem: problem });
  });
  return { checked: manifest.length, mismatches: mismatches };
}

if (require.main === module) {
  var constants = JSON.parse(fs.readFileSync(process.argv[3], "utf8"));
  var result = checkCorpus(loadMesh(constants), process.argv[2]);
  console.log(JSON.stringify(result, null, 1));
  process.exit(result.mismatches.length ? 1 : 0);
}

module.exports = { loadMesh: loadMesh, checkCorpus: checkCorpus };
