/*
 * The explorer's HTML: the toolbar and the stage over the messages, the readout, the
 * controls and the hint beside them; and what it shows where WebGL is missing.
 */
import { element, toolbarElement } from "./dom.js";
import { createReadout } from "./readout.js";

const HINT =
  "Drag empty space to turn the view, scroll or pinch to zoom; x, y, z look along an axis. " +
  "Drag A, B or C to move a point, or Tab to it and press the arrow keys (x, y) or " +
  "Page Up/Page Down (z). On a touch screen, tap the view first, then drag.";

/**
 * Lay the explorer out in `el`: { root, main, side, toolbarEl, stageEl, message, error, legend,
 * hint, readout }.
 */
export function createLayout(el) {
  const root = element("div", "tn-view tnx-root");
  // keys pressed in the explorer (arrows on a vertex, typing a value) are the explorer's, not
  // JupyterLab's or Notebook 7's shortcuts: Lumino skips an element with this attribute (it
  // must be on the focused element itself, which a selector such as ":focus" matches)
  root.dataset.lmSuppressShortcuts = "true";
  const main = element("div", "tnx-main");
  const side = element("div", "tnx-side");
  const toolbarEl = toolbarElement("tnx-toolbar", "3D view");
  const stageEl = element("div", "tnx-stage tn-stage");
  // a click gives the view focus (not a Tab stop), so its keys (f: full screen) are its own
  stageEl.tabIndex = -1;
  stageEl.dataset.lmSuppressShortcuts = "true";
  // the banner, the refusal of an edit (`error`) and the legend sit under the view, never
  // over a label or an arrow
  const message = element("p", "tnx-message");
  message.hidden = true;
  message.setAttribute("role", "status");
  const legend = element("p", "tnx-legend");
  legend.hidden = true;
  const error = element("p", "tnx-error");
  error.hidden = true;
  error.setAttribute("role", "alert");
  const hint = element("p", "tnx-hint", HINT);
  main.append(toolbarEl, stageEl, message, error, legend);
  root.append(main, side);
  el.appendChild(root);
  const readout = createReadout(side);
  side.appendChild(hint);
  return { root, main, side, toolbarEl, stageEl, message, error, legend, hint, readout };
}

/**
 * No WebGL: the stage gives way to a note, and the readout and the controls follow the
 * model's `keys`. Returns the cleanup function.
 */
export function showWithoutWebGL(parts, { model, controls, keys }) {
  const { root, main, stageEl, hint, readout } = parts;
  stageEl.remove();
  hint.remove();
  main.appendChild(
    element("p", "tnx-nogl", "This browser cannot draw the 3D view (WebGL is not available). The readout still follows the values."),
  );
  const show = () => {
    readout.show(true);
    readout.update(model.get("state"));
    controls.update();
  };
  show();
  for (const key of keys) model.on("change:" + key, show);
  return () => {
    for (const key of keys) model.off("change:" + key, show);
    root.remove();
  };
}
