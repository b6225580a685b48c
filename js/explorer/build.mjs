// Build the 3D view into one ES module for JupyterLab (anywidget) and the site:
//   node build.mjs [OUTDIR]      (default: ../../trinormal/explorer/static)
// Writes explorer.js and mesh-view.js (three.js bundled in, CSS as a string, minified, deterministic) and
// THIRD_PARTY_LICENSES.txt (three.js's licence, copied from node_modules, with its version).
//
// One three.js per page: anywidget imports the module afresh for every widget (and again
// when a cell is re-run), and each import would evaluate three.js again (three warns about
// "multiple instances"). So the bundle is an IIFE wrapped in a small ES module that keeps
// the evaluated runtime on globalThis, keyed by a hash of the code: the first import runs
// it, every later import of the same build reuses it.
import { createHash } from "node:crypto";
import { readFileSync, writeFileSync, mkdirSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { build, transform } from "esbuild";

const here = dirname(fileURLToPath(import.meta.url));
const out = resolve(process.argv[2] || join(here, "../../trinormal/explorer/static"));
mkdirSync(out, { recursive: true });

// src/*.css: minified by esbuild, then bundled as a string (src/style.js injects it)
const cssAsText = {
  name: "css-as-text",
  setup(b) {
    b.onLoad({ filter: /\.css$/ }, async (args) => {
      const { code } = await transform(readFileSync(args.path, "utf8"), { loader: "css", minify: true });
      return { contents: code.trim(), loader: "text" };
    });
  },
};

const three = JSON.parse(readFileSync(join(here, "node_modules/three/package.json"), "utf8"));

const result = await build({
  absWorkingDir: here,
  entryPoints: ["src/index.js"],
  outfile: join(out, "explorer.js"),
  write: false,
  bundle: true,
  format: "iife",
  globalName: "tnxModule",
  target: "es2020",
  minify: true,
  legalComments: "none", // the licence travels in THIRD_PARTY_LICENSES.txt next to the bundle
  charset: "utf8",
  plugins: [cssAsText],
  sourcemap: false,
  metafile: false,
  logLevel: "warning",
});
const inner = result.outputFiles[0].text.trim();
const key = createHash("sha256").update(inner).digest("hex").slice(0, 16);
writeFileSync(
  join(out, "explorer.js"),
  `/* trinormal 3D view. Bundles three.js ${three.version} (MIT licence, see THIRD_PARTY_LICENSES.txt). Built by js/explorer/build.mjs. */\n` +
    `const G=globalThis.__trinormalExplorer||(globalThis.__trinormalExplorer={});\n` +
    `const R=G["${key}"]||(G["${key}"]=(()=>{${inner}\nreturn tnxModule.default})());\n` +
    `export default R;\n`,
);

// The mesh view (src/mesh/view.js) of the site's "Check a mesh" page: a file of its own, built
// from the same three.js, so each page loads one copy of three.js (this one or explorer.js).
await build({
  absWorkingDir: here,
  entryPoints: ["src/mesh/view.js"],
  outfile: join(out, "mesh-view.js"),
  bundle: true,
  format: "esm",
  target: "es2020",
  minify: true,
  legalComments: "none",
  charset: "utf8",
  plugins: [cssAsText],
  sourcemap: false,
  metafile: false,
  logLevel: "warning",
  banner: {
    js: `/* trinormal mesh view. Bundles three.js ${three.version} (MIT licence, see THIRD_PARTY_LICENSES.txt). Built by js/explorer/build.mjs. */`,
  },
});

const licence = readFileSync(join(here, "node_modules/three/LICENSE"), "utf8").replace(/\r\n/g, "\n");
writeFileSync(
  join(out, "THIRD_PARTY_LICENSES.txt"),
  "explorer.js and mesh-view.js bundle the following third-party software.\n\n" +
    `three.js ${three.version} (npm package "three", https://threejs.org), MIT licence:\n\n` +
    licence.trimEnd() +
    "\n",
);
console.log(`built ${join(out, "explorer.js")} and mesh-view.js with three ${three.version}`);
