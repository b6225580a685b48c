/*
 * The one ES module of trinormal's 3D views: the triangle explorer (index.js) and the mesh view
 * (mesh/view.js), so a page or a notebook that shows both loads three.js once, from one file.
 *
 * anywidget runs the default export's render for every widget: a MeshView says so in its
 * `_view` trait ("mesh"); anything else is the explorer. A page can also call either view's
 * render directly (the named exports `explorer` and `mesh`).
 */
import explorer from "./index.js";
import mesh from "./mesh/view.js";

function render(context) {
  return (context.model.get("_view") === "mesh" ? mesh : explorer).render(context);
}

export { explorer, mesh };
export default { render };
