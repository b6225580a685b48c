/*
 * The explorer for a reader who cannot see the picture: the view described in words under it
 * (describe.js, the rule of trinormal.explorer.describe), in a polite live region that is also
 * the stage's accessible description (aria-describedby), and the Listen button (audio.js).
 *
 * The description follows the host's state (a cell, an answered edit, a flip) and the camera
 * (a drag, a key, a view button). It is written once a change settles, SETTLE_MS after the last
 * event of it, so a drag is said once, when it ends, and a screen reader hears each change once.
 */
import { createListen } from "./audio.js";
import { describeState } from "./describe.js";
import { element, setAttr, setText } from "./dom.js";
import { injectStyle } from "./style.js";
import CSS from "./access.css";

const SETTLE_MS = 250;

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
 * Add the description (under the stage) and the Listen button (at the end of the toolbar) to
 * the explorer `view` (index.js). Returns the function that removes them.
 */
export function addAccess(view) {
  const { model, stage, stageEl, toolbarEl } = view;
  injectStyle(stageEl.ownerDocument || document, "trinormal-access-style", CSS);
  const text = element("p", "tnx-describe");
  text.id = `tnx-describe-${++ids}`;
  text.setAttribute("role", "status");
  text.setAttribute("aria-live", "polite");
  stageEl.after(text);
  stageEl.setAttribute("role", "group");
  stageEl.setAttribute("aria-label", "3D view of the triangle ABC and its normal N");
  setAttr(stageEl, "aria-describedby", text.id);
  stage.canvas.setAttribute("aria-hidden", "true"); // the picture itself: its words are in `text`

  const listen = createListen(toolbarEl, () => model.get("state"));
  let timer = 0;
  let lastState = null;
  function settle() {
    timer = 0;
    const st = model.get("state");
    setText(text, describeState(st, model.get("winding"), viewerOf(view)));
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
    listen.dispose();
    text.remove();
  };
}
