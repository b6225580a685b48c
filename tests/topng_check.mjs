// The view's picture for the kernel (js/explorer/src/topng.js), run by Node from
// tests/test_explorer_picture.py: a fake stage and model; prints one JSON line of results.
import { sendPictures } from "../js/explorer/src/topng.js";

const host = {
  a: ["0", "0", "0"], b: ["1", "0", "0"], c: ["0", "1", "0"], winding: "ABC",
  show_parallelogram: false, show_unit_normal: false, send_pictures: true, palette: {},
};
const sent = [];
const model = { get: (key) => host[key], send: (content, callbacks, buffers) => sent.push({ content, buffers }) };
const listeners = {};
let size = { width: 400, height: 300 };
const camera = {
  matrixWorld: { elements: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 6, 1] },
  projectionMatrix: { elements: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -1, 0, 0, -0.1, 0] },
  updateMatrixWorld() {},
};
const stage = {
  size: () => size,
  canvas: { isConnected: true },
  camera,
  controls: {
    addEventListener: (type, f) => { listeners[type] = f; },
    removeEventListener: (type) => { delete listeners[type]; },
  },
};
const view = { model, stage, root: {}, get: (key) => host[key], dark: false, frame: {}, dragging: false };
let takes = 0;
const pictures = sendPictures(view, {
  settleMs: 0,
  take() {
    takes += 1;
    pictures.rendered(); // the frames pictureOf draws: no change of the picture
    const png = new Uint8Array([0x89, 0x50, 0x4e, 0x47, takes]);
    return Promise.resolve({ arrayBuffer: async () => png.buffer });
  },
});
// one turn of the event loop: the settle timer (0 ms) runs, then the promises of its send
const turn = () => new Promise((resolve) => setTimeout(resolve, 0));
const count = () => ({ takes, sent: sent.length });
const out = {};

// the first drawing: three frames, one picture, sent with the values it shows
pictures.rendered();
pictures.rendered();
pictures.rendered();
await turn();
await turn();
out.first = count();
out.message = sent[0].content;
out.buffer = [...new Uint8Array(sent[0].buffers[0])];
out.root = view.root.tnxPicture;
// a frame that changes nothing the picture shows: nothing sent
pictures.rendered();
await turn();
out.unchanged = count();
// a vertex dragged: nothing while the drag lasts, one picture at its end
view.dragging = true;
host.c = ["0", "1.5", "0"];
pictures.rendered();
await turn();
out.duringDrag = count();
view.dragging = false;
pictures.rendered();
await turn();
out.afterDrag = count();
out.dragged = sent.at(-1).content.picture.c;
// the camera turned: nothing while the pointer turns it, one picture when it lets go
listeners.start();
camera.matrixWorld.elements[12] = 2;
pictures.rendered();
await turn();
out.duringTurn = count();
listeners.end();
await turn();
out.afterTurn = count();
// a new size, a flip: one picture each
size = { width: 500, height: 300 };
pictures.rendered();
await turn();
host.winding = "ACB";
pictures.rendered();
await turn();
out.resizedAndFlipped = count();
out.flipped = sent.at(-1).content.picture.winding;
// not shown (no size), or a host that asks for no pictures: nothing
size = { width: 1, height: 1 };
host.a = ["1", "1", "1"];
pictures.rendered();
await turn();
size = { width: 500, height: 300 };
host.send_pictures = false;
pictures.rendered();
await turn();
out.hiddenOrOff = count();
// stopped: nothing, and the controls' listeners are gone
host.send_pictures = true;
pictures.rendered();
pictures.stop();
await turn();
out.stopped = count();
out.listeners = Object.keys(listeners);
console.log(JSON.stringify(out));
