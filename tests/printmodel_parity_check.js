/*
 * Run the site's printable model (docs/assets/javascripts/trinormal-printmodel.js) on a corpus
 * of triangles and compare, case by case, with what Python made of each (trinormal.printmodel):
 * the binary STL byte for byte and the 3MF model XML character for character, or the sentence
 * of the refusal. Used by tests/test_printmodel_parity.py:
 *   node tests/printmodel_parity_check.js CORPUS_DIR CONSTANTS.json
 * CORPUS_DIR/manifest.json lists {u, v, names, size, marks, stl, xml} or {..., error}.
 * Prints {checked, mismatches} as JSON; exits 1 when anything differs.
 */
"use strict";

var fs = require("fs");
var path = require("path");

var factory = require(path.join(__dirname, "..", "docs", "assets", "javascripts", "trinormal-printmodel.js"));

function firstDifference(want, got) {
  var n = Math.min(want.length, got.length);
  for (var i = 0; i < n; i++) if (want[i] !== got[i]) return i;
  return want.length === got.length ? -1 : n;
}

function check(P, dir) {
  var manifest = JSON.parse(fs.readFileSync(path.join(dir, "manifest.json"), "utf8"));
  var mismatches = [];
  manifest.forEach(function (c, i) {
    var model, problem = "";
    try {
      model = P.build(c.u, c.v, c.names, c.size, c.marks);
    } catch (err) {
      if (!(err instanceof P.PrintModelError)) problem = "threw " + (err && err.stack ? err.stack : err);
      else if (err.message !== c.error) problem = "refused with " + JSON.stringify(err.message) + ", want " + JSON.stringify(c.error || "a model");
      if (problem) mismatches.push({ case: i, problem: problem });
      return;
    }
    if (c.error) {
      mismatches.push({ case: i, problem: "made a model, want the refusal " + JSON.stringify(c.error) });
      return;
    }
    var stl = P.stl(model);
    var want = new Uint8Array(fs.readFileSync(path.join(dir, c.stl)));
    var at = firstDifference(want, stl);
    if (at >= 0) problem = "STL: byte " + at + " of " + want.length + " differs (got " + stl.length + " bytes)";
    var xml = P.modelXml(model);
    var wantXml = fs.readFileSync(path.join(dir, c.xml), "utf8");
    at = firstDifference(wantXml, xml);
    if (!problem && at >= 0) problem = "XML: character " + at + ": want " + JSON.stringify(wantXml.slice(at, at + 60)) + ", got " + JSON.stringify(xml.slice(at, at + 60));
    if (problem) mismatches.push({ case: i, problem: problem });
  });
  return { checked: manifest.length, mismatches: mismatches };
}

var constants = JSON.parse(fs.readFileSync(process.argv[3], "utf8"));
var result = check(factory(constants.print), process.argv[2]);
console.log(JSON.stringify(result, null, 1));
process.exit(result.mismatches.length ? 1 : 0);
