// Copy the browser files of the npm packages in package.json into docs/assets/vendor/, where
// the site serves them (the site never loads anything from another origin), and axe-core (a
// devDependency: the site never serves it) into tests/browser/vendor/, where the accessibility
// tests read it.
// Run `npm ci && npm run vendor` here after changing a version; the copies are committed.
import { copyFileSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const vendor = join(here, "..", "..", "docs", "assets", "vendor");

// KaTeX: the renderer, its auto-render extension, its stylesheet and fonts (woff2 only:
// every browser that renders the site reads woff2), and its MIT licence.
const katex = join(here, "node_modules", "katex");
const { version } = JSON.parse(readFileSync(join(katex, "package.json"), "utf8"));
const out = join(vendor, "katex");
rmSync(out, { recursive: true, force: true });
mkdirSync(join(out, "fonts"), { recursive: true });
copyFileSync(join(katex, "dist", "katex.min.js"), join(out, "katex.min.js"));
copyFileSync(join(katex, "dist", "contrib", "auto-render.min.js"), join(out, "auto-render.min.js"));
copyFileSync(join(katex, "LICENSE"), join(out, "LICENSE"));
const css = readFileSync(join(katex, "dist", "katex.min.css"), "utf8").replace(
  /,url\([^)]*\.woff\) format\("woff"\),url\([^)]*\.ttf\) format\("truetype"\)/g,
  "",
);
writeFileSync(join(out, "katex.min.css"), css);
for (const font of readdirSync(join(katex, "dist", "fonts"))) {
  if (font.endsWith(".woff2")) {
    copyFileSync(join(katex, "dist", "fonts", font), join(out, "fonts", font));
  }
}
writeFileSync(
  join(out, "SOURCE.txt"),
  `Vendored from the npm package \`katex@${version}\` by js/vendor/copy-vendor.mjs: dist/katex.min.js,\n` +
    "dist/contrib/auto-render.min.js, dist/katex.min.css (font sources cut to woff2), the woff2\n" +
    "fonts and the MIT LICENSE. Loaded only by pages that contain math.\n",
);
console.log(`katex ${version} -> ${out}`);

// axe-core: the accessibility engine the browser tests inject into each page
// (tests/browser/page_checks.py), its MPL-2.0 licence and its third-party licences.
const axe = join(here, "node_modules", "axe-core");
const axeVersion = JSON.parse(readFileSync(join(axe, "package.json"), "utf8")).version;
const axeOut = join(here, "..", "..", "tests", "browser", "vendor", "axe-core");
rmSync(axeOut, { recursive: true, force: true });
mkdirSync(axeOut, { recursive: true });
for (const name of ["axe.min.js", "LICENSE", "LICENSE-3RD-PARTY.txt"]) {
  copyFileSync(join(axe, name), join(axeOut, name));
}
writeFileSync(
  join(axeOut, "SOURCE.txt"),
  `Vendored from the npm package \`axe-core@${axeVersion}\` by js/vendor/copy-vendor.mjs: axe.min.js,\n` +
    "its LICENSE (MPL-2.0) and LICENSE-3RD-PARTY.txt. Injected into pages by the browser tests only;\n" +
    "the site never serves it.\n",
);
console.log(`axe-core ${axeVersion} -> ${axeOut}`);
