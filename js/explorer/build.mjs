// Build trinormal's 3D views (the triangle explorer and the mesh view) from src/:
//   node build.mjs [OUTDIR]      (default: ../../trinormal/explorer/static)
//
// Two outputs, for two kinds of host, each with THIRD_PARTY_LICENSES.txt beside it (the
// licences of three.js, three-mesh-bvh and meshoptimizer, copied from node_modules with their
// versions). Both are minified, deterministic, CSS bundled as a string, nothing loaded at run
// time from another origin.
//
// OUTDIR/explorer.js, the Jupyter widget (anywidget): ONE self-contained ES module holding both
// views (src/main.js), because anywidget loads `_esm` from a blob URL where no relative import
// resolves, and a notebook showing an Explorer and a MeshView must run three.js once. anywidget
// imports the module afresh for every widget (and again when a cell is re-run), so the bundle is
// an IIFE wrapped in a small ES module that keeps the evaluated runtime on globalThis, keyed by a
// hash of the code: the first import runs it, every later import of the same build reuses it.
// Inside it three.js is shared as well (sharedThree below), so even two builds on one page (a
// notebook's old output beside a new one) run one three.js of a version.
//
// OUTDIR/site-modules/, the site (copied to assets/explorer/ by docs/hooks): a page loads only
// the view it shows, so the calculator does not carry the mesh view's code, picking and simplifier.
// esbuild's code splitting makes one ES module per view, explorer.js (src/index.js) and mesh.js
// (src/mesh/view.js), and one shared chunk, shared-HASH.js, with three.js and the code both
// views use. The entries import the chunk by a relative URL; the browser's module map evaluates
// a URL once per page, so three.js runs once however often an entry is imported.
import { createHash } from "node:crypto";
import { mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
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

const packageOf = (pkg) => JSON.parse(readFileSync(join(here, "node_modules", pkg, "package.json"), "utf8"));
const three = packageOf("three");
const bvh = packageOf("three-mesh-bvh");
const meshopt = packageOf("meshoptimizer");
// what THIRD_PARTY_LICENSES.txt says of each bundled package: its npm name and version, its
// name and what it is for, and its licence file
const BUNDLED = [
  ["three", three.version, "three.js", "https://threejs.org", "LICENSE"],
  ["three-mesh-bvh", bvh.version, "three-mesh-bvh", "the mesh view's picking", "LICENSE"],
  ["meshoptimizer", meshopt.version, "meshoptimizer", "the mesh view's coarser copy of a big model while it turns", "LICENSE.md"],
];

// One three.js per page. Two builds of the bundle can meet on one page (a notebook saved with an
// older version's output), and three.js warns "Multiple instances of Three.js being imported"
// when its module runs twice. So our sources never run three.js themselves: every
// `import ... from "three"` (or a three.js addon) in src/ is served by a small module that takes
// three.js from globalThis, where the first build to run puts it, keyed by three's version and
// the names used. The runtime (three.js and the addons below) sits in the bundle, wrapped by
// esbuild so it runs only when no runtime of that key is on the page yet.
const ADDONS = [
  "three/addons/controls/OrbitControls.js",
  "three/addons/lines/LineMaterial.js",
  "three/addons/lines/LineSegments2.js",
  "three/addons/lines/LineSegmentsGeometry.js",
];
// npm packages bundled into a view that import three.js themselves (three-mesh-bvh, the mesh
// view's picking): their `import { ... } from "three"` is served by the shared module too, so
// they use the page's one three.js and do not bring a second copy into the bundle.
const THREE_USERS = ["three-mesh-bvh"];
// The names src/ (and THREE_USERS) import from each (the union over every source file, so every
// bundle carries the same runtime, and the runtime carries only what some view uses).
const exportNames = Object.fromEntries(["three", ...ADDONS].map((spec) => [spec, new Set()]));
const IMPORT = /import\s*\{([^}]*)\}\s*from\s*["'](three(?:\/[^"']*)?)["']/g;
function scan(dir, label, only) {
  for (const file of readdirSync(dir, { recursive: true })) {
    if (!file.endsWith(".js")) continue;
    const code = readFileSync(join(dir, file), "utf8").replace(/\/\*[\s\S]*?\*\//g, ""); // not JSDoc's @import
    for (const m of code.matchAll(IMPORT)) {
      if (only && m[2] !== only) continue;
      if (!(m[2] in exportNames)) throw new Error(`${label}/${file}: ${m[2]} is not in ADDONS (build.mjs)`);
      for (const name of m[1].split(",").map((n) => n.trim()).filter(Boolean)) exportNames[m[2]].add(name);
    }
    if (/import\s+(\*|\w+)[^;]*from\s*["']three["'/]/.test(code)) throw new Error(`${label}/${file}: import three by name`);
  }
}
scan(join(here, "src"), "src");
for (const pkg of THREE_USERS) scan(join(here, "node_modules", pkg, "src"), pkg, "three");
for (const spec in exportNames) exportNames[spec] = [...exportNames[spec]].sort();
// the key names the runtime's exports too: two builds with different runtimes never share one
const RUNTIME_KEY = `trinormal.three@${three.version}#${createHash("sha256").update(JSON.stringify(exportNames)).digest("hex").slice(0, 12)}`;
const sharedThree = {
  name: "shared-three",
  setup(b) {
    b.onResolve({ filter: /^three(\/|$)/ }, (args) => {
      if (args.namespace === "shared-three") return undefined;
      const user = THREE_USERS.find((pkg) => args.importer.includes(join("node_modules", pkg) + "/"));
      if (args.importer.includes("node_modules") && !(user && args.path === "three")) return undefined;
      if (!(args.path in exportNames)) {
        return { errors: [{ text: `${args.path}: add it to ADDONS in build.mjs (one three.js per page)` }] };
      }
      return { path: args.path, namespace: "shared-three" };
    });
    b.onResolve({ filter: /^trinormal-three-runtime$/ }, (args) => ({ path: args.path, namespace: "shared-three" }));
    b.onLoad({ filter: /.*/, namespace: "shared-three" }, (args) => {
      if (args.path === "trinormal-three-runtime") {
        const lines = Object.entries(exportNames).map(([spec, names]) => `export { ${names.join(", ")} } from "${spec}";`);
        return { contents: lines.join("\n") + "\n", resolveDir: here, loader: "js" };
      }
      const names = exportNames[args.path];
      const contents =
        `const key = Symbol.for(${JSON.stringify(RUNTIME_KEY)});\n` +
        `const T = globalThis[key] || (globalThis[key] = require("trinormal-three-runtime"));\n` +
        `export const { ${names.join(", ")} } = T;\n`;
      return { contents, resolveDir: here, loader: "js" };
    });
  },
};

const VERSIONS = `three.js ${three.version}, three-mesh-bvh ${bvh.version} and meshoptimizer ${meshopt.version}`;
const COMMON = {
  absWorkingDir: here,
  write: false,
  bundle: true,
  target: "es2020",
  minify: true,
  legalComments: "none", // the licences travel in THIRD_PARTY_LICENSES.txt next to the bundle
  charset: "utf8",
  sourcemap: false,
  metafile: false,
  logLevel: "warning",
};

/** The widget: both views in one file (see the header). */
async function buildWidget() {
  const result = await build({
    ...COMMON,
    entryPoints: ["src/main.js"],
    outfile: join(out, "explorer.js"),
    format: "iife",
    globalName: "tnxModule",
    plugins: [cssAsText, sharedThree],
  });
  const inner = result.outputFiles[0].text.trim();
  const key = createHash("sha256").update(inner).digest("hex").slice(0, 16);
  writeFileSync(
    join(out, "explorer.js"),
    `/* trinormal 3D views (the explorer and the mesh view). Bundles ${VERSIONS} (MIT licences, see THIRD_PARTY_LICENSES.txt). Built by js/explorer/build.mjs. */\n` +
      `const G=globalThis.__trinormalExplorer||(globalThis.__trinormalExplorer={});\n` +
      `const R=G["${key}"]||(G["${key}"]=(()=>{${inner}\nreturn tnxModule})());\n` +
      `export default R.default;\nexport const explorer=R.explorer,mesh=R.mesh;\n`,
  );
  writeLicences(out, "explorer.js (the explorer and the mesh view) bundles the following third-party software.");
}

/** The site: one module per view and their shared chunk (see the header). */
async function buildSite() {
  const dir = join(out, "site-modules");
  mkdirSync(dir, { recursive: true });
  // files of an earlier build (a chunk's name changes with its content)
  for (const name of readdirSync(dir)) if (name.endsWith(".js")) rmSync(join(dir, name));
  const result = await build({
    ...COMMON,
    entryPoints: { explorer: "src/index.js", mesh: "src/mesh/view.js" },
    outdir: dir,
    format: "esm",
    splitting: true,
    chunkNames: "shared-[hash]",
    banner: { js: `/* trinormal 3D views for the site, built by js/explorer/build.mjs from ${VERSIONS} (MIT licences, see THIRD_PARTY_LICENSES.txt). */` },
    plugins: [cssAsText],
  });
  for (const file of result.outputFiles) writeFileSync(file.path, file.text);
  writeLicences(
    dir,
    "explorer.js (the explorer), mesh.js (the mesh view) and shared-*.js (three.js and the code both use) bundle the following third-party software.",
  );
}

function writeLicences(dir, first) {
  const parts = BUNDLED.map(([pkg, version, name, what, file]) => {
    const licence = readFileSync(join(here, "node_modules", pkg, file), "utf8").replace(/\r\n/g, "\n").trimEnd();
    return `${name} ${version} (npm package "${pkg}", ${what}), MIT licence:\n\n${licence}`;
  });
  writeFileSync(join(dir, "THIRD_PARTY_LICENSES.txt"), [first, ...parts].join("\n\n") + "\n");
}

await buildWidget();
await buildSite();
console.log(`built ${join(out, "explorer.js")} (the widget, both views) and ${join(out, "site-modules")} (one module per view) with three ${three.version}`);
