/*
 * The "Check a mesh" page: choose or drop an OBJ, STL or PLY file, or an example; a Web Worker
 * (mesh-worker.js, running trinormal-mesh-*.js) reads it, checks it and fixes its winding, with a
 * progress bar; the page shows the report (its tables and sentences, written by TrinormalMesh
 * in the package's words, through TRINORMAL_CONSTANTS.mesh), the model in 3D (the mesh view, assets/explorer/mesh.js) and offers the
 * repaired file for download. A face picked in the view (a click, or its number typed) is
 * answered here as the kernel answers it in Jupyter: its three vertices, its exact normal and
 * its area from the calculator's core (TrinormalCore), with the package's wording
 * (TRINORMAL_CONSTANTS.mesh.selection, trinormal.mesh.selection). Nothing leaves the browser.
 */
import { modelEvents } from "./explorer-site.js"; // the calculator's 3D view, on every page

const WORKER = new URL("mesh-worker.js", import.meta.url).href;
const VIEW = new URL("../explorer/mesh.js", import.meta.url).href; // the mesh view (three.js in its shared chunk)

const $ = (id) => document.getElementById(id);

function constants() {
  return window.TRINORMAL_CONSTANTS || {};
}

// the package's words, as the mesh scripts (loaded before this module) fill them in
const message = (key, values) => window.TrinormalMesh.message(key, values);
const fill = (template, values) => window.TrinormalMesh.internal.fill(template, values);

/** A Web Worker with request ids: run(op, data, transfer, onProgress) -> Promise of the result. */
function createWorker() {
  const worker = new Worker(WORKER);
  let next = 1;
  const pending = new Map();
  worker.onmessage = (event) => {
    const { id, type } = event.data;
    const job = pending.get(id);
    if (!job) return;
    if (type === "progress") job.onProgress(event.data.stage, event.data.fraction);
    else {
      pending.delete(id);
      if (type === "done") job.resolve(event.data.result);
      else job.reject(new Error(event.data.message));
    }
  };
  let broken = null; // the worker failed to start: every job fails with this
  worker.onerror = (event) => {
    event.preventDefault();
    broken = new Error(message("internal", { detail: event.message || "the worker stopped" }));
    for (const job of pending.values()) job.reject(broken);
    pending.clear();
  };
  return {
    run(op, data, transfer, onProgress) {
      const id = next++;
      if (broken) return Promise.reject(broken);
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, onProgress: onProgress || (() => {}) });
        worker.postMessage({ op, id, ...data }, transfer || []);
      });
    },
    terminate: () => worker.terminate(),
  };
}

/** A tiny model with anywidget's API for the mesh view. */
function createModel(initial) {
  const data = { ...initial };
  const events = modelEvents();
  return {
    get: (key) => data[key],
    set(key, value) {
      data[key] = value;
      events.emit(key, value);
    },
    save_changes() {},
    on: events.on,
    off: events.off,
  };
}

/**
 * The readout of one face, as trinormal.mesh.selection.face_selection writes it in Python: the
 * corners' coordinates (their exact binary values), then the calculator's exact results.
 */
function faceSelection(res, face) {
  const sel = constants().mesh.selection;
  const t = sel.templates;
  const core = window.TrinormalCore;
  const nf = res.faces.length / 3;
  const problem = (text) => ({ face, title: text, rows: [[t.problem_label, text, ""]] });
  if (!Number.isInteger(face) || face < 0 || face >= nf) return problem(fill(t.no_face, { face, last: nf - 1 }));
  const corners = [0, 1, 2].map((k) => res.faces[3 * face + k]);
  const ratios = corners.map((v) => [0, 1, 2].map((k) => core.doubleRatio(res.positions[3 * v + k])));
  const texts = ratios.map((point) => point.map(([n, d]) => (d === 1n ? String(n) : `${n}/${d}`)));
  const result = core.compute(texts[0], texts[1], texts[2], "ABC", sel.precision);
  if (!result.ok) return problem(result.status);
  const labels = Object.fromEntries((constants().fields || []).map((f) => [f.key, f.label]));
  const rows = corners.map((v, i) => [
    fill(t.vertex, { name: "ABC"[i], index: v }),
    "(" + ratios[i].map(([n, d]) => core.formatSurd(n < 0n, n * n, d * d, sel.precision, false)).join(", ") + ")",
    "ABC"[i],
  ]);
  for (const key of sel.rows) {
    rows.push([labels[key] || key, key === "status" ? result.status : result.out[key], key === "normal" ? "N" : ""]);
  }
  if (res.flipped.includes(face)) {
    const fix = ($("tn-mesh-fix").textContent || "").trim();
    rows.push([t.flipped_label, fill(t.flipped, { fix }), "flipped"]);
  }
  return { face, title: fill(t.title, { face, a: corners[0], b: corners[1], c: corners[2] }), rows };
}

function cell(tag, text, attrs = {}) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

/** The table of pieces' headings, from the package (trinormal.mesh_page.PIECE_COLUMNS). */
function pieceHeadings() {
  $("tn-mesh-pieces-head").replaceChildren(...constants().mesh.columns.map(([, label]) => cell("th", label, { scope: "col" })));
}

/**
 * Fill the report's tables, notes and summary from the worker's report. The cells are
 * TrinormalMesh.table's, the words of trinormal.mesh_page.report_table.
 */
function renderReport(r) {
  const table = window.TrinormalMesh.table(r);
  const rows = table.rows.map(([key, label, text]) => {
    const tr = cell("tr", undefined, { "data-key": key });
    tr.append(cell("th", label, { scope: "row" }), cell("td", text));
    return tr;
  });
  $("tn-mesh-rows").replaceChildren(...rows);
  const pieces = $("tn-mesh-pieces");
  pieces.textContent = "";
  // each cell carries its column's heading: on a phone the table is a list of cards
  const heads = constants().mesh.columns.map(([, label]) => label);
  for (const [number, ...values] of table.pieces) {
    const tr = document.createElement("tr");
    tr.append(
      cell("th", number, { scope: "row", "data-label": heads[0] }),
      ...values.map((text, k) => cell("td", text, { "data-label": heads[k + 1] })),
    );
    pieces.appendChild(tr);
  }
  const none = message("no_answer");
  const dash = table.pieces.some((piece) => piece.includes(none));
  const dashNote = $("tn-mesh-pieces-note");
  dashNote.textContent = dash ? message("pieces_dash") : "";
  dashNote.hidden = !dash;
  // beside "Fix winding": what it mends and what it leaves
  const others = ["degenerate_faces", "duplicate_faces", "reversed_duplicate_faces", "boundary_edges", "non_manifold_edges"];
  const fixNote = $("tn-mesh-fix-note");
  fixNote.textContent = others.some((k) => (r[k] || []).length)
    ? message("fix_only_winding")
    : r.faces_to_flip.length ? "" : message("fix_nothing");
  fixNote.hidden = !fixNote.textContent;
  $("tn-mesh-summary").replaceChildren(...window.TrinormalMesh.summary(r).map((line) => cell("li", line)));
}

/**
 * The 3D view of the checked model in #tn-mesh-view, on `model`: the returned showModel(res) draws
 * a result (a model above the page's limit once the reader asks), mounting the view once.
 */
function createViewHost(model) {
  let view = null; // the mounted view's cleanup
  async function showModel(res) {
    const host = $("tn-mesh-view");
    const limit = window.TrinormalMesh.LIMITS.max_view_faces;
    const nf = res.faces.length / 3;
    if (nf > limit && !host.dataset.asked) {
      // a big model is drawn when the reader asks: its first frame can take seconds
      if (view) {
        view();
        view = null;
      }
      host.textContent = "";
      host.dataset.ready = "false";
      const note = cell("p", message("view_big", { count: window.TrinormalMesh.grouped(nf) }), { class: "tn-mesh-view-note" });
      const draw = cell("button", message("view_draw"), { type: "button", class: "md-button", id: "tn-mesh-draw" });
      draw.addEventListener("click", () => {
        host.dataset.asked = "true";
        showModel(res);
      });
      host.append(note, draw);
      return;
    }
    delete host.dataset.asked;
    model.set("picked", -1);
    // what the view's description names: the file and its pieces (the report's components)
    model.set("about", { name: res.name, pieces: res.report.components });
    model.set("mesh", {
      positions: res.positions,
      faces: res.faces,
      flipped: res.flipped,
      boundary: res.boundary,
      non_manifold: res.non_manifold,
    });
    if (!view) {
      const module = await import(VIEW);
      host.textContent = "";
      view = module.default.render({ model, el: host });
    }
    host.dataset.ready = "true";
  }
  return showModel;
}

/** The repaired file's name: "-fixed" before the extension. */
function fixedName(name) {
  const m = /^(.*?)(\.[^.]*)?$/.exec(name);
  return `${m[1]}-fixed${m[2] || ""}`;
}

/** Offer the repaired file ({ bytes, name }) for download. */
function saveFile(fixedFile) {
  const blob = new Blob([fixedFile.bytes], { type: "application/octet-stream" });
  const url = URL.createObjectURL(blob);
  const a = document.createElement("a");
  a.href = url;
  a.download = fixedFile.name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** A file dropped anywhere on the box goes to onFile (the file input stays the keyboard's way in). */
function acceptDrops(root, drop, onFile) {
  root.addEventListener("dragover", (e) => {
    e.preventDefault();
    drop.dataset.over = "true";
  });
  root.addEventListener("dragleave", () => {
    drop.dataset.over = "false";
  });
  root.addEventListener("drop", (e) => {
    e.preventDefault();
    drop.dataset.over = "false";
    onFile(e.dataTransfer && e.dataTransfer.files[0]);
  });
}

/** The worker's progress on `bar`: reading is the first half of the bar, checking the second. */
function progressOn(bar) {
  return (stage, fraction) => {
    const value = stage === "read" ? fraction / 2 : 0.5 + fraction / 2;
    bar.value = Math.round(value * 100);
    bar.setAttribute("aria-valuetext", `${bar.value} %`);
  };
}

/** The example buttons: each fetches its file (from this site) and opens it. */
function openExamples(root, open, onError) {
  for (const b of root.querySelectorAll("button[data-example]")) {
    b.addEventListener("click", async () => {
      const url = new URL(b.dataset.example, document.baseURI);
      try {
        const response = await fetch(url);
        if (!response.ok) throw new Error(String(response.status));
        open(url.pathname.split("/").pop(), await response.arrayBuffer());
      } catch (err) {
        onError(err);
      }
    });
  }
}

function mount(root) {
  const input = $("tn-mesh-file");
  const status = $("tn-mesh-status");
  const bar = $("tn-mesh-progress");
  const barBox = $("tn-mesh-progress-box");
  const result = $("tn-mesh-result");
  const fixButton = $("tn-mesh-fix");
  const download = $("tn-mesh-download");
  const weldButton = $("tn-mesh-weld");
  const drop = $("tn-mesh-drop");
  const worker = createWorker();
  let current = null; // the last result from the worker
  let fixedFile = null;
  let busy = false;
  const model = createModel({ palette: constants().palette || {}, mesh: null, picked: -1, selection: {} });
  // a face picked in the view: answered as the kernel answers it in Jupyter
  model.on("change:picked", () => {
    const face = model.get("picked");
    const shown = model.get("mesh");
    model.set("selection", face === -1 || !shown ? {} : faceSelection(shown, face));
  });

  function setStatus(text, state = "ok") {
    status.textContent = text;
    status.dataset.state = state;
  }

  const progress = progressOn(bar);

  function setBusy(on) {
    busy = on;
    root.dataset.busy = String(on);
    barBox.hidden = !on;
    input.disabled = on;
    for (const b of root.querySelectorAll("button")) b.disabled = on || (b === download && !fixedFile) || (b === fixButton && !canFix()) || (b === weldButton && !nearMiss());
  }

  /** The distance text of the report's near miss (the weld control's), or null. */
  function nearMiss() {
    const near = current && current.report.near_miss;
    return near ? window.TrinormalMesh.internal.roundDistance(near.distance, false)[1] : null;
  }

  function canFix() {
    return !!current && current.report.faces_to_flip.length > 0;
  }

  const showView = createViewHost(model);

  function showResult(res, note) {
    current = res;
    result.hidden = false;
    $("tn-mesh-name").textContent = res.name;
    const kind = res.format.toUpperCase() + (res.format === "obj" ? "" : res.binary ? " (binary)" : " (ASCII)");
    $("tn-mesh-format").textContent = kind;
    renderReport(res.report);
    root.dataset.report = JSON.stringify(res.report);
    const distance = nearMiss();
    weldButton.hidden = !distance;
    weldButton.style.display = distance ? "" : "none"; // .md-button's display overrides [hidden]
    if (distance) weldButton.textContent = message("weld", { distance });
    setStatus(note || "", "ok");
    return showView(res);
  }

  async function open(name, buffer) {
    if (busy) return;
    fixedFile = null;
    setBusy(true);
    bar.value = 0;
    setStatus(message("reading", { name }));
    try {
      const res = await worker.run("open", { name, buffer }, [buffer], (stage, f) => {
        if (stage === "check" && f === 0) setStatus(message("checking", { name }));
        progress(stage, f);
      });
      const shown = showResult(res, res.notes.join(" ")); // what the reader forgave, if anything
      setBusy(false);
      root.dataset.state = "done";
      await shown;
    } catch (err) {
      refuse(err.message);
      setBusy(false);
    }
  }

  /** No report to show: the reason in the status line. */
  function refuse(reason) {
    current = null;
    result.hidden = true;
    root.dataset.state = "error";
    setStatus(reason, "error");
  }

  /** One step of the worker on the file shown ("fix" or "weld"), then its report. */
  async function step(kind, working, done, state) {
    setBusy(true);
    bar.value = 50;
    setStatus(working);
    try {
      const res = await worker.run(kind, {}, [], progress);
      if (kind === "fix") {
        fixedFile = { bytes: res.file, name: fixedName(current.name) };
        res.name = fixedFile.name; // the report below is the repaired file's
      }
      const shown = showResult(res, done);
      setBusy(false);
      root.dataset.state = state;
      if (kind === "fix") download.focus(); // the next step; the status above is read out (aria-live)
      await shown;
    } catch (err) {
      setBusy(false);
      setStatus(err.message, "error");
    }
  }

  function fix() {
    if (busy || !canFix()) return;
    const faces = window.TrinormalMesh.counted(current.report.faces_to_flip.length, "face");
    step("fix", message("fixing"), message("fixed", { faces }), "fixed");
  }

  function weld() {
    const distance = nearMiss();
    if (busy || !distance) return;
    step("weld", message("welding", { distance }), message("welded", { distance }), "welded");
  }

  // A file beyond the page's limit is refused on its size alone, before any of it is read.
  async function openFile(file) {
    if (!file || busy) return;
    const tooLarge = window.TrinormalMesh.sizeProblem(file.name, file.size);
    if (tooLarge) {
      fixedFile = null;
      refuse(tooLarge);
      return;
    }
    open(file.name, await file.arrayBuffer());
  }

  pieceHeadings();
  input.addEventListener("change", () => openFile(input.files && input.files[0]));
  fixButton.addEventListener("click", fix);
  weldButton.addEventListener("click", weld);
  download.addEventListener("click", () => fixedFile && saveFile(fixedFile));
  openExamples(root, open, (err) => setStatus(message("internal", { detail: err.message }), "error"));
  acceptDrops(root, drop, openFile);
  setBusy(false);
  root.dataset.ready = "true";
}

function init() {
  const root = $("tn-mesh");
  if (root && window.TrinormalMesh && !root.dataset.ready) mount(root);
}

if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
else init();
