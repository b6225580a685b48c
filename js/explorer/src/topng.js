/*
 * The view's picture for the kernel's `ex.to_png()`. A cell cannot ask the browser for it (the
 * kernel hears from the browser only between cells), so the view sends it unasked: each time
 * its picture settles after a change (a cell's set(), the end of a drag, a key, a flip, the end
 * of a turn of the camera, Reset view, a new size), `settleMs` after the last frame of it, it
 * draws the picture "Save picture" downloads (present.js's pictureOf: twice its size on the
 * screen, with its labels) and sends it as a custom message with the values it shows:
 *
 *   model.send({ picture: { a, b, c, winding, show_parallelogram, show_unit_normal } },
 *              undefined, [png bytes])
 *
 * (trinormal.explorer.widget's PICTURE_FIELDS). Nothing is sent while a vertex is
 * dragged or the camera turned, nor when nothing the picture shows changed since the last one
 * sent, nor when the host does not ask for pictures (`send_pictures`: the kernel's Explorer
 * does, the site has no kernel to send them to).
 */
import { listen } from "./dom.js";
import { pictureOf } from "./present.js";

/** The values a picture shows, as the view draws them now (the host's, with the view's edits). */
function shownValues(get) {
  const values = {};
  for (const key of ["a", "b", "c"]) values[key] = (get(key) || []).map(String);
  values.winding = get("winding") === "ACB" ? "ACB" : "ABC";
  values.show_parallelogram = !!get("show_parallelogram");
  values.show_unit_normal = !!get("show_unit_normal");
  return values;
}

/** What the picture depends on: the values, the camera, the size, the scheme and the palette. */
function fingerprint(view, values) {
  const { camera } = view.stage;
  camera.updateMatrixWorld();
  const { width, height } = view.stage.size();
  return JSON.stringify([values, width, height, view.dark, view.get("palette"),
    camera.matrixWorld.elements, camera.projectionMatrix.elements]);
}

/**
 * Send the explorer `view`'s picture (index.js) to the kernel each time it settles, `settleMs`
 * after the last frame drawn; `take(stage)` draws it (a Promise of a PNG Blob). Returns
 * { rendered, stop }: `rendered()` is called after every frame the stage draws, `stop()` ends.
 * For tests, the view's root keeps what it sent last as `tnxPicture` ({ values, width, height }).
 */
export function sendPictures(view, { settleMs, take = pictureOf }) {
  const { model, stage, root } = view;
  let timer = 0;
  let turning = false; // the camera is being turned (a pointer on the stage)
  let taking = false; // pictureOf is drawing: its frames are no change
  let sent = ""; // the fingerprint of the last picture sent
  let stopped = false;

  function settle() {
    timer = 0;
    if (stopped || view.dragging || turning || !model.get("send_pictures")) return;
    const { width, height } = stage.size();
    if (!stage.canvas.isConnected || width < 2 || height < 2 || !view.frame) return; // not shown
    const values = shownValues(view.get);
    const key = fingerprint(view, values);
    if (key === sent) return;
    sent = key;
    taking = true;
    let png;
    try {
      png = take(stage);
    } finally {
      taking = false;
    }
    png.then((blob) => (blob ? blob.arrayBuffer() : null)).then((bytes) => {
      if (stopped || !bytes) return;
      model.send({ picture: values }, undefined, [bytes]);
      root.tnxPicture = { values, width, height };
    });
  }
  function schedule() {
    if (taking || stopped) return;
    clearTimeout(timer);
    timer = setTimeout(settle, settleMs);
  }
  const stopTurns = listen(stage.controls, {
    start: () => {
      turning = true;
    },
    end: () => {
      turning = false;
      schedule();
    },
  });
  return {
    rendered: schedule,
    stop() {
      stopped = true;
      clearTimeout(timer);
      stopTurns();
    },
  };
}
