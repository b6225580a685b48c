/*
 * The trinormal 3D view: an anywidget-style module, `export default { render }`.
 *
 * render({ model, el }) draws the triangle described by the model into `el` and returns a
 * cleanup function. It uses only model.get / send / on / off, so the same module runs in
 * JupyterLab (anywidget) and on the site (a small model fed by the site's exact core). The
 * host computes every printed string (`state`); the view draws. The view never writes the
 * host's values: a learner's move is an identified edit, answered by the host (edits.js).
 *
 * The parts, each in its own module: layout.js (the HTML), edits.js (the edit protocol),
 * controls.js (sliders and exact text boxes), toolbar.js, scene.js (the stage: camera and
 * rendering), framing.js (the units and the box the camera keeps in view), scaling.js (how
 * long N is drawn), picture.js (axes, triangle, arrows and labels), panels.js (readout,
 * messages, legend), interaction.js (moving a vertex), touch.js, access.js (the view in words
 * and in sound, for a reader who cannot see it), topng.js (its picture for the kernel). This file builds them and
 * keeps them in step with the model.
 */
import { addAccess, SETTLE_MS } from "./access.js";
import { createControls } from "./controls.js";
import { createEdits } from "./edits.js";
import { Drawing } from "./geometry.js";
import { setupInteraction } from "./interaction.js";
import { createLayout, showWithoutWebGL } from "./layout.js";
import { createPrinting } from "./printing.js";
import { readStep } from "./numbers.js";
import { updateLegend, updatePanels } from "./panels.js";
import { applyFrame, createLabels, dataPoints, drawTriangle, frameOf, projection, reframe } from "./picture.js";
import { createStage } from "./scene.js";
import { injectStyle } from "./style.js";
import CSS from "./style.css";
import { isDark, roleColor, surface, watchTheme } from "./theme.js";
import { createPrintButtons, createToolbar } from "./toolbar.js";
import { setStyle } from "./dom.js";
import { sendPictures } from "./topng.js";
import { touchGate } from "./touch.js";

const KEYS = [
  "a", "b", "c", "winding", "precision", "step", "bounds", "show_parallelogram", "show_unit_normal",
  "show_readout", "show_controls", "precision_range", "palette", "state", "message",
];

/** The colour of a role (a vertex, an axis, an arrow, a line) in the host's palette and the scheme. */
function colorOf(view, role) {
  const s = surface(view.dark);
  switch (role) {
    case "edge":
    case "paraEdge":
    case "ring":
    case "unit":
      return s.text;
    case "para":
      return roleColor(view.get("palette"), "N", view.dark);
    case "line":
      return s.line;
    default:
      return roleColor(view.get("palette"), role, view.dark);
  }
}

/** Bring the toolbar, the panels and the picture to the values (the host's, with the view's edits). */
function sync(view) {
  const pts = dataPoints(view);
  const st = view.get("state") || {};
  const winding = view.get("winding") === "ACB" ? "ACB" : "ABC";
  view.toolbar.update();
  updatePanels(view, st);
  view.readout.waiting(view.waiting ? view.model.get("waiting") || "" : "");
  view.drawing.root.visible = !!pts;
  if (pts) {
    view.lastGood = pts;
    reframe(view, pts, winding);
    updateLegend(view, drawTriangle(view, pts, st, winding));
  }
  view.stage.requestRender();
}

/** Draw everything again in the scheme's colours (light or dark) and the host's palette. */
function repaint(view) {
  const { frame, drawing, labels } = view;
  view.root.classList.toggle("tn-dark", view.dark);
  view.stage.setBackground(surface(view.dark).background);
  drawing.paint(view.colors);
  if (frame) {
    drawing.setGrid(frame.L, frame.t, surface(view.dark), frame.includeOrigin); // the grid's colours
    for (const a of "xyz") setStyle(labels.items.get("axis:" + a).el, "color", view.colors(a));
  }
  sync(view);
}

// how long an edit may wait for its answer before the readout says the kernel is busy (ms):
// longer than a kernel's answer during a drag, short enough to see before reading the numbers
const WAIT_MS = 400;

/**
 * Whether the view's edits have waited longer than WAIT_MS for the host (a cell is running):
 * the readout then says so instead of showing the host's last numbers as current. Checked
 * after every edit and answer; `changed` redraws when it turns on or off.
 */
function watchWaiting(view, edits, changed) {
  let timer = 0;
  function check() {
    clearTimeout(timer);
    const since = edits.waitingSince();
    const due = since === null ? Infinity : since + WAIT_MS - performance.now();
    const waiting = due <= 0;
    if (waiting !== view.waiting) {
      view.waiting = waiting;
      changed();
    }
    if (!waiting && due !== Infinity) timer = setTimeout(check, due);
  }
  check.stop = () => clearTimeout(timer);
  return check;
}

/**
 * Follow the model: changes are gathered and drawn once (a drag draws in the frame that moved
 * the vertex, through view.flush); an answer to an edit drops what it answered; a new version
 * from the host drops the edits of the fields it set since they were made, and ends a drag of
 * a vertex it set. Returns the function that stops.
 */
function followModel(view, edits, interaction) {
  const { model } = view;
  let dirty = false;
  const onChange = () => {
    if (dirty) return;
    dirty = true;
    queueMicrotask(() => {
      if (!dirty) return;
      dirty = false;
      sync(view);
    });
  };
  view.flush = () => {
    dirty = false;
    sync(view);
    view.stage.renderNow();
  };
  const handlers = {};
  for (const key of KEYS) handlers[key] = key === "palette" ? () => repaint(view) : onChange;
  const waiting = watchWaiting(view, edits, onChange);
  view.checkWaiting = waiting;
  // the host answered an edit: what it answered is no longer drawn from the view's own copy
  handlers.last_edit = () => {
    if (edits.answered()) onChange();
    waiting();
  };
  // the host changed its values itself (a cell ran): what it set is the truth from now on;
  // the view's edits of everything else stay (the host keeps them too)
  let seen = model.get("version") ?? 0;
  handlers.version = () => {
    const setAt = model.get("set_at") || {};
    const set = Object.keys(setAt).filter((key) => setAt[key] > seen);
    seen = model.get("version") ?? 0;
    edits.overwritten();
    if (view.dragged && set.some((key) => key[0] === view.dragged.toLowerCase())) interaction.cancel();
    view.controls.reset(set);
    view.hostMoved = true;
    onChange();
  };
  for (const [key, handler] of Object.entries(handlers)) model.on("change:" + key, handler);
  return () => {
    waiting.stop();
    for (const [key, handler] of Object.entries(handlers)) model.off("change:" + key, handler);
  };
}

let views = 0;

function render({ model, el }) {
  injectStyle(el.ownerDocument || document, "trinormal-explorer-style", CSS);
  const viewId = `v${++views}-${Math.random().toString(36).slice(2, 8)}`;
  const parts = createLayout(el);
  const edits = createEdits(model, viewId);
  const { get } = edits;
  const edit = (changes) => {
    edits.edit(changes);
    view.checkWaiting?.();
  };
  const view = {
    ...parts,
    model,
    get,
    dark: isDark(),
    frame: null, // { S, offset: Vector3, includeOrigin, box, L, t, ... } (framing.js)
    dragging: false,
    dragged: null, // the vertex being dragged ("A", "B", "C"), or null
    waiting: false, // the view's edits have waited long for the host (a busy kernel)
    lastGood: null, // last drawable points (data floats)
    hostMoved: false, // the host (a cell, not this view) changed the triangle
    display: null, // display-unit points of the last drawing
    heads: {}, // display-unit arrow heads of the last drawing
    scales: {}, // the power of two N and the unit normal are drawn at (their labels say it)
  };
  view.colors = (role) => colorOf(view, role);
  view.controls = createControls(parts.root, { get, edit, color: view.colors });

  try {
    view.stage = createStage(parts.stageEl, {
      onRender: () => {
        view.labels.layout(view.stage.camera, view.stage.size());
        view.pictures?.rendered();
      },
    });
  } catch (err) {
    return showWithoutWebGL(parts, { model, controls: view.controls, keys: KEYS });
  }
  const { stage } = view;
  Object.assign(view, createLabels(parts.stageEl, view));
  view.drawing = new Drawing(stage.scene);
  const printing = createPrinting(model);
  view.toolbar = createToolbar(parts.toolbarEl, {
    get,
    edit,
    stage,
    reset: () => {
      if (view.frame) applyFrame(view, frameOf(view, view.lastGood || dataPoints(view)), true);
      stage.reset();
    },
    onFullscreen(on) {
      // the readout floats over the view's right side: the picture keeps that part free
      sync(view);
      view.stage.setInset(on ? parts.side.offsetWidth + 24 : 0);
    },
  });
  createPrintButtons(parts.side, printing.request);

  // touch: a finger scrolls the page over the view until a tap turns it on (touch.js)
  const touch = touchGate({ root: parts.root, stageEl: parts.stageEl, controls: stage.controls, canvas: stage.canvas, activeClass: "tnx-touch-active" });
  const interaction = setupInteraction({
    touchActive: touch.active,
    container: parts.stageEl,
    canvas: stage.canvas,
    camera: stage.camera,
    scale: () => view.frame?.S ?? 1,
    grid: () => readStep(get("step")),
    bounds: () => get("bounds"),
    values: (name) => (get(name.toLowerCase()) || ["", "", ""]).map(String),
    position: (name) => (view.display ? view.display[name] : null),
    write(changes) {
      edit(changes);
      view.flush();
    },
    dragging(on, name) {
      view.dragging = on;
      view.dragged = on ? name : null;
      if (!on) sync(view);
    },
  });
  const stopModel = followModel(view, edits, interaction);
  const stopTheme = watchTheme((d) => {
    view.dark = d;
    repaint(view);
  });
  /** Where the vertices and arrow heads are on screen (px in the view), for tests and tools. */
  parts.root.tnxProject = () => projection(view);

  stage.resize();
  repaint(view);
  // for a reader who cannot see the picture: the description and the Listen button (access.js)
  const stopAccess = addAccess(view);
  // the picture for the kernel's ex.to_png(), sent each time it settles (topng.js)
  view.pictures = sendPictures(view, { settleMs: SETTLE_MS });

  return () => {
    view.pictures.stop();
    stopAccess();
    stopModel();
    view.toolbar.dispose();
    printing.stop();
    touch.dispose();
    stopTheme();
    interaction();
    view.labels.dispose();
    view.drawing.dispose();
    stage.dispose();
    parts.readout.dispose();
    view.controls.dispose();
    parts.root.remove();
  };
}

export default { render };
