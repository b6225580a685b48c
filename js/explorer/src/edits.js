/*
 * The explorer's edit protocol, on the view's side (the rule and the host's side:
 * trinormal/explorer/view.py and state.merge_edit).
 *
 * The view never writes the host's values. A learner's move (drag, arrow key, slider, typed
 * value, toolbar toggle) is sent as an identified edit naming only what the learner changed,
 *   model.send({ edit: { cx: "0.4", cy: "1.1" }, seq, view, base: version }),
 * made against the host's `version`; the host answers with its values and `last_edit`
 * ({ view, seq, ok, overwritten }). Until that answer the view draws its own edit, per
 * coordinate (so a drag follows the pointer); a new `version` drops only the edits of fields
 * the host set after them (index.js). While an edit waits for its answer longer than a busy
 * kernel's moment, the readout says so.
 */
import { parseCoordinate } from "./numbers.js";

// a vertex's coordinates as edits name them: "a" -> ["ax", "ay", "az"]
const COORDS = { a: ["ax", "ay", "az"], b: ["bx", "by", "bz"], c: ["cx", "cy", "cz"] };
const COORDINATE = new Set(Object.values(COORDS).flat());
// what the view draws from its own edit until the host answers (a coordinate: when readable)
const DRAWN = new Set([...COORDINATE, "winding", "precision", "show_parallelogram", "show_unit_normal"]);

/**
 * The edits of one view (`viewId`) of `model`:
 *   get(key): the host's value, with the view's unanswered edits over it (a vertex: per coordinate);
 *   edit(changes): send a learner's move as an identified edit, and draw it until the answer;
 *   answered(): the host's `last_edit` answered this view: drop the edits it answered (true when it was this view's);
 *   overwritten(): the host set values itself (a cell ran): drop the edits of the fields it set
 *     after they were made, and return those fields;
 *   waitingSince(): when the oldest edit still waiting for its answer was sent (ms), or null.
 */
export function createEdits(model, viewId, now = () => performance.now()) {
  let seq = 0;
  let pending = {}; // key -> { value, seq, base }: the view's own edits the host has not answered yet
  const unanswered = new Map(); // seq -> when it was sent

  function get(key) {
    const coords = COORDS[key];
    if (!coords || !coords.some((k) => k in pending)) return key in pending ? pending[key].value : model.get(key);
    const host = model.get(key) || ["", "", ""];
    return coords.map((k, i) => (k in pending ? pending[k].value : host[i]));
  }

  function edit(changes) {
    seq += 1;
    const base = model.get("version") ?? 0;
    for (const [key, v] of Object.entries(changes)) {
      // a typed value the view cannot read ("abc") is not drawn: the host will refuse it
      const readable = !COORDINATE.has(key) || Number.isFinite(parseCoordinate(v));
      if (DRAWN.has(key) && readable) pending[key] = { value: v, seq, base };
    }
    unanswered.set(seq, now());
    model.send({ edit: changes, seq, view: viewId, base });
  }

  function answered() {
    const answer = model.get("last_edit") || {};
    if (answer.view !== viewId) return false;
    for (const [key, p] of Object.entries(pending)) if (p.seq <= answer.seq) delete pending[key];
    for (const s of unanswered.keys()) if (s <= answer.seq) unanswered.delete(s);
    return true;
  }

  function overwritten() {
    const setAt = model.get("set_at") || {};
    const lost = Object.keys(pending).filter((key) => (setAt[key] ?? 0) > pending[key].base);
    for (const key of lost) delete pending[key];
    return lost;
  }

  function waitingSince() {
    return unanswered.size ? Math.min(...unanswered.values()) : null;
  }

  return { get, edit, answered, overwritten, waitingSince };
}
