/*
 * The explorer for a reader who cannot see the picture: the view described in words beside it
 * (describe.js, the rule of trinormal.explorer.describe), in a polite live region that is also
 * the stage's accessible description (aria-describedby), the Listen button (audio.js), and the
 * view turned by keys on the focused stage.
 *
 * The description follows the host's state (a cell, an answered edit, a flip) and the camera
 * (a drag, a key, a view button). It is written once a change settles, SETTLE_MS after the last
 * event of it, so a drag is said once, when it ends, and a screen reader hears each change once.
 */
import { createListen } from "./audio.js";
import { describeState } from "./describe.js";
import { element, setAttr, setText } from "./dom.js";
import { turnWithKeys } from "./mesh/keys.js";
import { injectStyle } from "./style.js";
import CSS from "./access.css";

export const SETTLE_MS = 250;

let ids = 0;

/** Where the viewer is, seen from the triangle: camera minus centroid, display units (null: not drawn). */
function viewerOf(view) {
  const d = view.display;
  if (!d) return null;
  const c = d.A.clone().add(d.B).add(d.C).divideScalar(3);
  const v = view.stage.camera.position.clone().sub(c);
  return [v.x, v.y, v.z];
}

/**
 * Add the description and the Listen button (after the readout, beside or under the view) to
 * the explorer `view` (index.js). Returns the function that removes them.
 */
export function addAccess(view) {
  const { model, stage, stageEl } = view;
  injectStyle(stageEl.ownerDocument || document, "trinormal-access-style", CSS);
  // the words and the sound together: the description, then the Listen button
  const block = element("div", "tnx-access");
  const text = element("p", "tnx-describe");
  text.id = `tnx-describe-${++ids}`;
  text.setAttribute("role", "status");
  text.setAttribute("aria-live", "polite");
  // beside the view, after the readout (on a narrow screen: under the view, after the readout),
  // so the readout's rows keep their place next to the picture on a projector
  block.append(text);
  view.side.insertBefore(block, view.hint);
  stageEl.setAttribute("role", "group");
  stageEl.setAttribute("aria-label", "3D view of the triangle ABC and its normal N. Arrow keys turn it, + and − zoom, Home resets the view.");
  stageEl.tabIndex = 0;
  stageEl.dataset.lmSuppressShortcuts = "true"; // its keys are the view's, not JupyterLab's
  const stopKeys = turnWithKeys(stageEl, stage);
  setAttr(stageEl, "aria-describedby", text.id);
  stage.canvas.setAttribute("aria-hidden", "true"); // the picture itself: its words are in `text`

  const listen = createListen(block, () => model.get("state"));
  let timer = 0;
  let lastState = null;
  let lastViewer = "";
  function settle() {
    timer = 0;
    const st = model.get("state");
    const viewer = viewerOf(view);
    setText(text, describeState(st, model.get("winding"), viewer));
    // the kernel's ex.describe() says what this view shows (a host without a kernel ignores it)
    if (viewer && String(viewer) !== lastViewer) {
      lastViewer = String(viewer);
      model.send({ viewer });
    }
    if (st !== lastState) {
      lastState = st;
      listen.changed(); // the triangle changed (not only the camera): heard again, if listening
    }
  }
  function schedule() {
    clearTimeout(timer);
    timer = setTimeout(settle, SETTLE_MS);
  }
  const keys = ["state", "winding"];
  for (const key of keys) model.on("change:" + key, schedule);
  stage.controls.addEventListener("change", schedule);
  settle();
  lastState = model.get("state");

  return () => {
    clearTimeout(timer);
    for (const key of keys) model.off("change:" + key, schedule);
    stage.controls.removeEventListener("change", schedule);
    stopKeys();
    listen.dispose();
    block.remove();
  };
}
