/*
 * The 3D view on the site: the explorer view (assets/explorer/explorer.js, built from the same
 * sources as JupyterLab's widget), driven by a small model object instead of a Python kernel. The model's `state` is computed
 * by TrinormalCore (exact, the same strings as the Python package); labels and colours come
 * from window.TRINORMAL_CONSTANTS, which the build writes from the package.
 *
 * Mount points:
 *   #tn-view inside the calculator: two-way synced with the form (typing moves the view,
 *     dragging a vertex or pressing keys writes the inputs, the results and the URL).
 *   .tn-explorer-live on the explorer notebook's page: a standalone view whose initial
 *     values are in its data-explorer attribute (JSON).
 */
const BUNDLE = new URL("../explorer/explorer.js", import.meta.url).href;
const KEYS = ["a", "b", "c", "winding", "precision"];

function constants() {
  return window.TRINORMAL_CONSTANTS;
}

/** The `state` the view draws and prints, from the exact core (see the view contract). */
export function computeState(a, b, c, winding, precision, maxPrecision) {
  const failed = (error, field) =>
    ({ ok: false, error, status: error, field, readout: readoutRows(null, winding), summary: error });
  let p;
  try {
    // the package's rule and message (trinormal.validation), at most maxPrecision when given
    p = window.TrinormalCore.checkPrecision(precision, "precision", maxPrecision);
  } catch (err) {
    if (!(err instanceof window.TrinormalCore.InputError)) throw err;
    return failed(err.message, "precision");
  }
  const r = window.TrinormalCore.compute(a, b, c, winding, p);
  if (!r.ok) return failed(r.status, r.field);
  const f = r.floats;
  return {
    ok: true,
    error: null,
    points: f.points,
    u: f.u,
    v: f.v,
    normal: f.normal,
    unit_normal: f.unit_normal,
    degenerate: r.degenerate,
    status: r.status,
    readout: readoutRows(r.out, winding),
    summary: r.degenerate ? r.status : `N = ${r.out.normal}, area ${r.out.area}.`,
  };
}

function readoutRows(out, winding) {
  return constants().fields.map((field) => ({
    key: field.key,
    label: winding === "ACB" ? field.label_acb : field.label,
    value: out ? out[field.key] : "—",
  }));
}

/**
 * A model with the part of anywidget's API the view uses (get, send, on, off) and its edit
 * protocol, the kernel's (trinormal.explorer.state.merge_edit): the view sends
 * { edit, seq, view, base }; the host's own changes (`update`) count as new versions and
 * record, per field, the version that set it (`set_at`; a vertex sets its three coordinates);
 * an edit keeps every field the host did not set after its base, and loses the others.
 * An edit names coordinates one by one ({ ay: "0.3" }); the model applies them to its own
 * values of the vertex, as the kernel does, so the other coordinates stay as they are now.
 * `state` follows a, b, c, winding and precision. `onEdit(changes)` receives an accepted edit
 * as whole values ({ a: ["0", "0.3", "0"], winding: "ACB" }); without it the model applies
 * the edit itself.
 */
export function createModel(initial, onEdit, maxPrecision) {
  const C = constants();
  const data = {
    a: ["0", "0", "0"],
    b: ["1", "0", "0"],
    c: ["0", "1", "0"],
    winding: "ABC",
    precision: 4,
    step: C.view.step,
    bounds: C.view.bounds,
    show_parallelogram: false,
    show_unit_normal: false,
    show_readout: true,
    show_controls: false,
    palette: C.palette,
    message: "",
    version: 0,
    set_at: {},
    last_edit: {},
    ...initial,
  };
  const events = modelEvents();
  let answering = false; // applying an edit: the changes answer it, they are no new version

  function emit(key) {
    events.emit(key, data[key]);
  }

  function same(x, y) {
    return JSON.stringify(x) === JSON.stringify(y);
  }

  function recompute() {
    data.state = computeState(data.a, data.b, data.c, data.winding, data.precision, maxPrecision);
    emit("state");
  }

  /** Change values: the host's own updates (a new version), or the answer to an edit. */
  function update(values) {
    const changed = Object.keys(values).filter((k) => !same(data[k], values[k]));
    for (const k of changed) data[k] = values[k];
    if (changed.length && !answering) {
      data.version += 1;
      const fields = changed.flatMap((k) => ("abc".includes(k) ? [..."xyz"].map((q) => k + q) : [k]));
      data.set_at = { ...data.set_at, ...Object.fromEntries(fields.map((k) => [k, data.version])) };
      changed.push("set_at", "version");
    }
    for (const k of changed) emit(k);
    if (changed.some((k) => KEYS.includes(k))) recompute();
    return changed.length > 0;
  }

  /** An edit as whole values: each coordinate it names put into the vertex's current values. */
  function wholeValues(edit) {
    const values = {};
    for (const [key, value] of Object.entries(edit)) {
      const m = /^([abc])([xyz])$/.exec(key);
      if (!m) {
        values[key] = value;
        continue;
      }
      const [, p, q] = m;
      if (!values[p]) values[p] = [...data[p]];
      values[p]["xyz".indexOf(q)] = value;
    }
    return values;
  }

  /**
   * "Download for 3D printing" (the view's printing.js): the STL of the drawn triangle, made by
   * trinormal-printmodel.js (the port of trinormal.printmodel), or the package's sentence why not.
   */
  function answerPrint(request) {
    const P = window.TrinormalPrintModel;
    const K = C.print;
    const marks = K.marks.includes(request.marks) ? request.marks : K.marks[0];
    const answer = { seq: request.seq, name: K.download_name.replace("{marks}", marks), error: "" };
    const st = data.state;
    let bytes = null;
    if (!st.ok) answer.error = st.error;
    else if (st.degenerate) answer.error = P.degenerate().message;
    else {
      try {
        bytes = P.stl(P.build(st.u, st.v, "A" + data.winding.slice(1), K.default_size, marks));
      } catch (err) {
        if (!(err instanceof P.PrintModelError)) throw err;
        answer.error = err.message;
      }
    }
    if (bytes) answer.done = K.messages.downloaded.replace("{name}", answer.name);
    events.custom({ printed: answer }, bytes ? [new DataView(bytes.buffer)] : []);
  }

  function send(content) {
    if (content && content.print && typeof content.print === "object") return answerPrint(content.print);
    if (!content || typeof content.edit !== "object") return;
    const ident = { view: String(content.view || ""), seq: content.seq || 0 };
    const base = Number.isInteger(content.base) ? content.base : -1;
    const overwritten = Object.keys(content.edit).filter((k) => (data.set_at[k] ?? 0) > base);
    const kept = Object.fromEntries(Object.entries(content.edit).filter(([k]) => !overwritten.includes(k)));
    const answer = { ...ident, stale: overwritten.length > 0, overwritten, error: "" };
    if (overwritten.length && !Object.keys(kept).length) {
      data.last_edit = { ...answer, ok: false };
      emit("last_edit");
      return;
    }
    answering = true;
    try {
      const values = wholeValues(kept);
      if (onEdit) onEdit(values);
      else update(values);
    } finally {
      answering = false;
    }
    data.last_edit = { ...answer, ok: true };
    emit("last_edit");
  }

  data.state = computeState(data.a, data.b, data.c, data.winding, data.precision, maxPrecision);
  return {
    get: (key) => data[key],
    send,
    on: events.on,
    off: events.off,
    update,
  };
}

/**
 * The change events of a model with anywidget's API, for this page's explorer and the mesh
 * page's view: the view listens with on("change:key", cb) and off, the host calls emit.
 */
export function modelEvents() {
  const listeners = new Map();
  return {
    emit(key, value) {
      for (const cb of [...(listeners.get("change:" + key) || [])]) cb({ name: key, new: value });
    },
    /** A custom message from the host, as anywidget delivers one: (content, buffers). */
    custom(content, buffers) {
      for (const cb of [...(listeners.get("msg:custom") || [])]) cb(content, buffers);
    },
    on(event, cb) {
      if (!listeners.has(event)) listeners.set(event, new Set());
      listeners.get(event).add(cb);
    },
    off(event, cb) {
      if (!event) listeners.clear();
      else if (!cb) listeners.delete(event);
      else listeners.get(event)?.delete(cb);
    },
  };
}

let bundle = null;
function loadView() {
  if (!bundle) bundle = import(BUNDLE).then((m) => m.default);
  return bundle;
}

// ------------------------------------------------------------------ the calculator

const FORM = { a: ["ax", "ay", "az"], b: ["bx", "by", "bz"], c: ["cx", "cy", "cz"] };

function readCalculator() {
  const $ = (id) => document.getElementById(id);
  const values = {};
  for (const [key, ids] of Object.entries(FORM)) values[key] = ids.map((id) => $(id).value);
  values.winding = $("winding").value;
  values.precision = $("precision").value;
  return values;
}

/** The bounds a drag may use: the view's default range, widened to hold the typed values. */
function boundsFor(values) {
  let [lo, hi] = constants().view.bounds;
  for (const key of ["a", "b", "c"]) {
    for (const s of values[key]) {
      const x = Number(s);
      if (Number.isFinite(x)) [lo, hi] = [Math.min(lo, Math.floor(x)), Math.max(hi, Math.ceil(x))];
    }
  }
  return [lo, hi];
}

async function mountCalculator(host) {
  const calc = document.getElementById("tn-calculator");
  const values = readCalculator();
  const model = createModel({ ...values, bounds: boundsFor(values), show_readout: false }, (changes) => {
    // the view moved a vertex or flipped the order: write the form, let the calculator update
    // (its input event comes back to sync() below while the edit is being answered)
    let last = null;
    for (const [key, value] of Object.entries(changes)) {
      if (FORM[key]) {
        FORM[key].forEach((id, i) => {
          const input = document.getElementById(id);
          if (input.value !== value[i]) {
            input.value = value[i];
            last = input;
          }
        });
      } else if (key === "winding") {
        const select = document.getElementById("winding");
        select.value = value;
        select.dispatchEvent(new Event("change", { bubbles: true }));
      } else if (key === "show_parallelogram" || key === "show_unit_normal") {
        model.update({ [key]: value });
      }
    }
    if (last) last.dispatchEvent(new CustomEvent("input", { bubbles: true, detail: { fromView: true } }));
  }, Number(document.getElementById("precision").max));
  const sync = () => {
    const now = readCalculator();
    model.update({ ...now, bounds: boundsFor(now) });
  };
  calc.addEventListener("input", sync);
  calc.addEventListener("change", sync);
  calc.addEventListener("click", (e) => {
    if (e.target.closest("#tn-flip")) sync();
  });
  const view = await loadView();
  host.textContent = "";
  const cleanup = view.render({ model, el: host });
  host.dataset.ready = "true";
  return cleanup;
}

// ------------------------------------------------------------------ the explorer notebook page

async function mountStandalone(host) {
  let initial = {};
  try {
    initial = JSON.parse(host.dataset.explorer || "{}");
  } catch (err) {
    // not JSON: the explorer's defaults
  }
  const model = createModel(initial, null);
  const view = await loadView();
  const fallback = host.querySelector(".tn-explorer-fallback");
  if (fallback) fallback.hidden = true;
  const mount = document.createElement("div");
  mount.className = "tn-explorer-mount";
  host.appendChild(mount);
  const cleanup = view.render({ model, el: mount });
  host.dataset.ready = "true";
  return cleanup;
}

let cleanups = [];
function init() {
  cleanups.forEach((f) => f && f());
  cleanups = [];
  if (!window.TrinormalCore || !window.TRINORMAL_CONSTANTS) return;
  const view = document.getElementById("tn-view");
  if (view && document.getElementById("tn-calculator")) {
    mountCalculator(view).then((f) => cleanups.push(f), (err) => console.error(err));
  }
  for (const host of document.querySelectorAll(".tn-explorer-live")) {
    mountStandalone(host).then((f) => cleanups.push(f), (err) => console.error(err));
  }
}

window.TrinormalSite.onEachPage(init);
