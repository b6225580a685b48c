// The view's side of the explorer's edit protocol (js/explorer/src/edits.js), run by Node
// from tests/test_explorer.py: a fake model plays the kernel; prints one JSON line of results.
import { createEdits } from "../js/explorer/src/edits.js";

const host = { a: ["0", "0", "0"], b: ["1", "0", "0"], c: ["0", "1", "0"], version: 3, set_at: {}, last_edit: {} };
const sent = [];
const model = { get: (key) => host[key], send: (content) => sent.push(content) };
let clock = 1000;
const edits = createEdits(model, "v1", () => clock);
const out = {};

// a drag of B is sent while the kernel is busy
edits.edit({ bx: "1.5", by: "0.5" });
clock += 50;
edits.edit({ bx: "1.7" });
out.sent = sent.map((m) => [m.seq, m.base, m.view, Object.keys(m.edit)]);
out.waitingSince = edits.waitingSince();
// the cell sets C (a new version): B's edits stay drawn, nothing is dropped
Object.assign(host, { c: ["-1/3", "2/3", "0.25"], version: 4, set_at: { cx: 4, cy: 4, cz: 4 } });
out.lostToC = edits.overwritten();
out.drawnB = edits.get("b");
out.drawnC = edits.get("c");
// an edit of C made before a cell set C again loses to the cell
edits.edit({ cz: "2" }); // base 4
Object.assign(host, { c: ["0", "0", "1"], version: 5, set_at: { cx: 5, cy: 5, cz: 5 } });
out.lostToC2 = edits.overwritten();
out.drawnC2 = edits.get("c");
// the kernel answers the first two edits: the third still waits
Object.assign(host, { b: ["1.7", "0.5", "0"], last_edit: { view: "v1", seq: 2, ok: true } });
out.answeredOwn = edits.answered();
out.stillWaiting = edits.waitingSince();
host.last_edit = { view: "v2", seq: 9, ok: true };
out.answeredOther = edits.answered();
host.last_edit = { view: "v1", seq: 3, ok: false, overwritten: ["cz"] };
edits.answered();
out.doneWaiting = edits.waitingSince();
out.drawnB2 = edits.get("b");
console.log(JSON.stringify(out));
