/*
 * Run the shared parser vectors (tests/data/parser_vectors.json) through the site's
 * trinormal-core.js and return every vector whose outcome differs from Python's.
 * Used by tests/browser/test_parser_vectors.py (in Chromium); also runs under Node:
 *   node tests/parser_vectors_check.js
 */
function checkParserVectors(T, vectors) {
  var mismatches = [];
  vectors.forEach(function (v) {
    var got;
    try {
      var value;
      if (v.kind === "coordinate") {
        var r = T.parseCoordinate(v.input, "B.y");
        value = [r[0].toString(), r[1].toString()];
      } else if (v.kind === "precision") {
        value = String(T.checkPrecision(v.input));
      } else {
        value = String(T.checkWinding(v.input));
      }
      got = { ok: true, value: value };
    } catch (err) {
      if (!(err instanceof T.InputError)) throw err;
      got = { ok: false, error: err.message };
    }
    var want = v.ok ? { ok: true, value: v.value } : { ok: false, error: v.error };
    if (JSON.stringify(got) !== JSON.stringify(want)) {
      mismatches.push({ kind: v.kind, input: v.input, want: want, got: got });
    }
  });
  return mismatches;
}

if (typeof module === "object" && module.exports) {
  module.exports = checkParserVectors;
  if (require.main === module) {
    var path = require("path");
    var root = path.join(__dirname, "..");
    var T = require(path.join(root, "docs/assets/javascripts/trinormal-core.js"));
    var vectors = require(path.join(root, "tests/data/parser_vectors.json"));
    var bad = checkParserVectors(T, vectors);
    console.log(JSON.stringify(bad, null, 1));
    process.exit(bad.length ? 1 : 0);
  }
}
