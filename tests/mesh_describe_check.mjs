/*
 * Run the mesh view's description (js/explorer/src/mesh/describe.js) on facts given as JSON on
 * stdin ([{ about, faces, flipped, picked, selection }]) and print what it says, one text per
 * fact, as JSON; for tests/test_mesh_widget.py, which gives it MeshView's traits. describe.js
 * imports its style sheet as text (esbuild's loader): Node is given an empty one.
 */
import { register } from "node:module";

const cssAsText = `export async function load(url, context, next) {
  if (url.endsWith(".css")) return { format: "module", source: "export default '';", shortCircuit: true };
  return next(url, context);
}`;
register("data:text/javascript," + encodeURIComponent(cssAsText));
const { describeMesh } = await import("../js/explorer/src/mesh/describe.js");

let input = "";
process.stdin.on("data", (d) => (input += d));
process.stdin.on("end", () => process.stdout.write(JSON.stringify(JSON.parse(input).map(describeMesh))));
