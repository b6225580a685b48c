/*
 * What the explorer prints around the picture, from the host's `state`: the readout, the
 * banner (an unreadable input, a degenerate triangle), the host's refusal of an edit, the
 * controls, the names screen readers give the points, and the parallelogram's legend.
 */
import { setAttr, setHidden, setText } from "./dom.js";

/** The readout's value of `key` ("magnitude", "area"), or null when it has none. */
function readoutValue(st, key) {
  const row = st && st.ok !== false && Array.isArray(st.readout) ? st.readout.find((r) => r.key === key) : null;
  return row ? row.value : null;
}

/** view: { model, get, root, side, readout, message, error, controls, vertexEls }; st: the host's state. */
export function updatePanels(view, st) {
  const { get, readout, message, error } = view;
  // full screen shows the readout over the view even where the page prints it elsewhere
  const shown = !!get("show_readout") || view.root.classList.contains("tn-fullscreen");
  readout.show(shown);
  view.side.classList.toggle("tnx-no-readout", !shown);
  if (shown) readout.update(st);
  const problem = st.ok === false ? st.error || st.status : st.degenerate ? st.status : "";
  setHidden(message, !problem);
  setText(message, problem || "");
  setAttr(message, "data-state", st.ok === false ? "error" : "degenerate");
  const refused = view.model.get("message") || "";
  setHidden(error, !refused);
  setText(error, refused);
  view.controls.update();
  for (const name of "ABC") {
    const values = get(name.toLowerCase()) || [];
    setAttr(
      view.vertexEls[name],
      "aria-label",
      `Point ${name} at (${values.join(", ")}). Arrow keys move x and y, Page Up and Page Down move z.`,
    );
  }
}

/** The legend under the view: the areas, when the parallelogram is drawn and the readout has them. */
export function updateLegend(view, parallelogram) {
  const st = view.get("state");
  const magnitude = readoutValue(st, "magnitude");
  const area = readoutValue(st, "area");
  const showAreas = parallelogram && magnitude !== null && area !== null;
  setHidden(view.legend, !showAreas);
  if (showAreas) setText(view.legend, `Parallelogram on U and V: area |N| = ${magnitude}. Triangle: area |N|/2 = ${area}.`);
}
