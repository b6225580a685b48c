/*
 * Run the shared parser vectors (tests/data/parser_vectors.json) through the site's
 * trinormal-core.js and return every vector whose outcome differs from Python's.
 * Used by tests/browser/test_parser_vectors.py (in Chromium); also runs under Node
 * (tests/test_parser_vectors.py runs it so):
 *   node tests/parser_vectors_check.js [CONSTANTS.json]
 * The core reads its limits and messages from the site's constants: the JSON file given
 * (what docs/hooks/trinormal_site.py's site_constants() returns), or else the constants
 * asked of the package through .venv/bin/python (or python3).
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
    var constants = loadConstants(root, process.argv[2]);
    var T = require(path.join(root, "docs/assets/javascripts/trinormal-core.js"))(constants);
    var vectors = require(path.join(root, "tests/data/parser_vectors.json"));
    var bad = checkParserVectors(T, vectors);
    console.log(JSON.stringify(bad, null, 1));
    process.exit(bad.length ? 1 : 0);
  }
}

/* The site's constants: from a JSON file, or from the package (the hook's site_constants()). */
function loadConstants(root, file) {
  var fs = require("fs");
  var path = require("path");
  if (file) return JSON.parse(fs.readFileSync(file, "utf8"));
  var venv = path.join(root, ".venv", "bin", "python");
  var python = fs.existsSync(venv) ? venv : "python3";
  var code =
    "import json, sys; sys.path.insert(0, 'docs/hooks'); import trinormal_site; " +
    "print(json.dumps(trinormal_site.site_constants()))";
  var out = require("child_process").execFileSync(python, ["-c", code], { cwd: root, encoding: "utf8" });
  return JSON.parse(out);
}
