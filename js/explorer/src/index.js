/*
 * The trinormal 3D view: an anywidget-style module, `export default { render }`.
 *
 * render({ model, el }) draws the triangle described by the model into `el` and returns a
 * cleanup function. It uses only model.get / send / on / off, so the same module runs in
 * JupyterLab (anywidget) and on the site (a small model fed by the site's exact core). The
 * host computes every printed string (`state`); the view draws.
 *
 * The view never writes the host's values. A learner's move (drag, arrow key, slider, typed
 * value, toolbar toggle) is sent as an identified edit naming only what the learner changed,
 *   model.send({ edit: { cx: "0.4", cy: "1.1" }, seq, view, base: version }),
 * made against the host's `version` (which counts the host's own changes). A coordinate is
 * named by its key ("ax" … "cz"), so two views of one explorer editing different coordinates
 * of one vertex at once do not undo each other. The host refuses an edit made against an
 * older version, so a late edit never overwrites what a cell set, and answers with its values
 * and `last_edit` ({ view, seq, ok }). Until that answer the view draws its own edit, per
 * coordinate (so a drag follows the pointer); a new `version` from the host ends a drag in
 * progress and drops whatever the view had not yet had answered.
 */
import { Vector3 } from "three";
import { Drawing } from "./geometry.js";
import { setupInteraction } from "./interaction.js";
import { LabelLayer } from "./labels.js";
import { niceCeil, parseCoordinate, parsePoint, powerOfTen, readStep, tickText } from "./numbers.js";
import { createControls } from "./controls.js";
import { createReadout } from "./readout.js";
import { createStage, DEFAULT_DIRECTION } from "./scene.js";
import { injectStyle } from "./style.js";
import CSS from "./style.css";
import { isDark, roleColor, surface, watchTheme } from "./theme.js";
import { element, setAttr, setHidden, setStyle, setText, toolbarElement } from "./dom.js";
import { touchGate } from "./touch.js";

const KEYS = [
  "a", "b", "c", "winding", "precision", "step", "bounds", "show_parallelogram", "show_unit_normal",
  "show_readout", "show_controls", "precision_range", "palette", "state", "message",
];
// a vertex's coordinates as edits name them: "a" -> ["ax", "ay", "az"]
const COORDS = { a: ["ax", "ay", "az"], b: ["bx", "by", "bz"], c: ["cx", "cy", "cz"] };
const COORDINATE = new Set(Object.values(COORDS).flat());
// what the view draws from its own edit until the host answers (a coordinate: when readable)
const DRAWN = new Set([...COORDINATE, "winding", "precision", "show_parallelogram", "show_unit_normal"]);
// N is drawn at its true length (in the axes' units) when that is about the longest edge
// (0.49 to 0.99 times it); otherwise it is scaled by a power of two into that range, so the
// triangle and N fit the picture together, and its label says so: "N/4", "2N" (as the
// matplotlib figure labels it). The unit normal likewise: "N/(4|N|)", "2N/|N|".
const N_AIM = 0.7; // the drawn length aimed at, times the longest edge (at most 0.99 of it: the triangle keeps its share of the frame)
const UNIT_AIM = 0.5;

/** The power of two that brings `length` nearest to `aim` on a log scale (1 when it is 0). */
function drawScale(length, aim) {
  if (!(length > 0) || !(aim > 0) || !Number.isFinite(length)) return 1;
  return 2 ** Math.round(Math.log2(aim / length));
}

/** How a vector of true `length` (display units) is drawn: its factor and its drawn length. */
function drawnAt(length, aim) {
  const factor = drawScale(length, aim);
  return { factor, length: length * factor };
}

const SUPERSCRIPT = "⁰¹²³⁴⁵⁶⁷⁸⁹";
function powerText(factor) {
  const k = Math.round(Math.log2(factor));
  if (Math.abs(k) <= 12) return String(2 ** Math.abs(k));
  return "2" + [...String(Math.abs(k))].map((d) => SUPERSCRIPT[Number(d)]).join("");
}

/** The label of N drawn `factor` times its length: "N", "N/4", "2N"; unit: "N/|N|", "N/(4|N|)", "2N/|N|". */
function scaledLabel(factor, unit = false) {
  if (factor === 1) return unit ? "N/|N|" : "N";
  const f = powerText(factor);
  if (factor < 1) return unit ? `N/(${f}|N|)` : `N/${f}`;
  return unit ? `${f}N/|N|` : `${f}N`;
}
const VERTEX_ANGLE = { A: (225 * Math.PI) / 180, B: (-30 * Math.PI) / 180, C: (90 * Math.PI) / 180 };
const ORDER = { ABC: "A→B→C", ACB: "A→C→B" };

/**
 * Where the camera first looks from: the usual oblique view, unless it sees the triangle
 * nearly edge-on or N nearly head-on; then the one of 24 views around the scene that sees
 * the front face at about 50 degrees, so the faces, N and the parallelogram can all be seen.
 */
function startDirection(normal) {
  if (!(normal.length() > 0)) return DEFAULT_DIRECTION.clone();
  const n = normal.clone().normalize();
  const cos = DEFAULT_DIRECTION.dot(n);
  if (cos >= 0.35 && cos <= 0.8) return DEFAULT_DIRECTION.clone();
  // aim for cos(angle to N) = 0.65: the front face well in view, N still clearly an arrow
  let best = DEFAULT_DIRECTION.clone();
  let miss = Math.abs(DEFAULT_DIRECTION.dot(n) - 0.65);
  for (const elevation of [20, 35, 55]) {
    for (let k = 0; k < 8; k++) {
      const az = ((k * 45 + 37) * Math.PI) / 180;
      const el = (elevation * Math.PI) / 180;
      const d = new Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
      const m = Math.abs(d.dot(n) - 0.65);
      if (m < miss - 1e-9) [best, miss] = [d, m];
    }
  }
  return best;
}

function button(text, label, onClick) {
  const b = element("button", "tnx-button", text);
  b.type = "button";
  if (label) {
    b.setAttribute("aria-label", label);
    b.title = label;
  }
  b.addEventListener("click", onClick);
  return b;
}

let views = 0;

function render({ model, el }) {
  injectStyle(el.ownerDocument || document, "trinormal-explorer-style", CSS);
  const viewId = `v${++views}-${Math.random().toString(36).slice(2, 8)}`;
  const root = element("div", "tn-view tnx-root");
  // keys pressed in the explorer (arrows on a vertex, typing a value) are the explorer's, not
  // JupyterLab's or Notebook 7's shortcuts: Lumino skips an element with this attribute (it
  // must be on the focused element itself, which a selector such as ":focus" matches)
  root.dataset.lmSuppressShortcuts = "true";
  const main = element("div", "tnx-main");
  const side = element("div", "tnx-side");
  const toolbar = toolbarElement("tnx-toolbar", "3D view");
  const stageEl = element("div", "tnx-stage");
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
  const hint = element(
    "p",
    "tnx-hint",
    "Drag empty space to turn the view, scroll or pinch to zoom; x, y, z look along an axis. " +
      "Drag A, B or C to move a point, or Tab to it and press the arrow keys (x, y) or " +
      "Page Up/Page Down (z). On a touch screen, tap the view first, then drag.",
  );
  main.append(toolbar, stageEl, message, error, legend);
  root.append(main, side);
  el.appendChild(root);
  const readout = createReadout(side);
  side.appendChild(hint);

  // ------------------------------------------------------------------ edits and their answers
  let seq = 0;
  let pending = {}; // key -> { value, seq }: the view's own edits the host has not answered yet
  /** The host's value of `key`, with the view's unanswered edits over it (a vertex: per coordinate). */
  function get(key) {
    const coords = COORDS[key];
    if (!coords || !coords.some((k) => k in pending)) return key in pending ? pending[key].value : model.get(key);
    const host = model.get(key) || ["", "", ""];
    return coords.map((k, i) => (k in pending ? pending[k].value : host[i]));
  }

  /** Send a learner's move to the host as an identified edit; draw it until the answer. */
  function edit(changes) {
    seq += 1;
    for (const [key, v] of Object.entries(changes)) {
      // a typed value the view cannot read ("abc") is not drawn: the host will refuse it
      const readable = !COORDINATE.has(key) || Number.isFinite(parseCoordinate(v));
      if (DRAWN.has(key) && readable) pending[key] = { value: v, seq };
    }
    model.send({ edit: changes, seq, view: viewId, base: model.get("version") ?? 0 });
  }

  let dark = isDark();
  const colors = (role) => {
    const s = surface(dark);
    switch (role) {
      case "edge":
      case "paraEdge":
      case "ring":
      case "unit":
        return s.text;
      case "para":
        return roleColor(get("palette"), "N", dark);
      case "line":
        return s.line;
      default:
        return roleColor(get("palette"), role, dark);
    }
  };
  const controls = createControls(root, { get, edit, color: (role) => colors(role) });

  let stage;
  try {
    stage = createStage(stageEl, { onRender: () => labels.layout(stage.camera, stage.size()) });
  } catch (err) {
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
    for (const key of KEYS) model.on("change:" + key, show);
    return () => {
      for (const key of KEYS) model.off("change:" + key, show);
      root.remove();
    };
  }
  const labels = new LabelLayer(stageEl);
  const drawing = new Drawing(stage.scene);

  // ------------------------------------------------------------------ toolbar
  const flip = button("", null, () => edit({ winding: get("winding") === "ACB" ? "ABC" : "ACB" }));
  const toggle = (key, text) => button(text, null, () => edit({ [key]: !get(key) }));
  const para = toggle("show_parallelogram", "");
  para.append(element("span", "tnx-long", "Parallelogram"), element("span", "tnx-short", "▱"));
  para.setAttribute("aria-label", "Parallelogram");
  const unit = toggle("show_unit_normal", "N/|N|");
  unit.setAttribute("aria-label", "Unit normal N/|N|");
  unit.title = "Show the unit normal N/|N|";
  para.title = "Show the parallelogram on U and V (area |N|)";
  // Named by its visible words ("Reset view", or "Reset" when narrow), so speech users can say them.
  const reset = button("", "Reset view", () => {
    if (frame) applyFrame(computeFrame(lastGood || dataPoints(), get("winding")), true);
    stage.reset();
  });
  reset.append(element("span", "tnx-long", "Reset view"), element("span", "tnx-short", "Reset"));
  reset.title = "Reset view: frame the triangle and its arrows again";
  toolbar.append(
    reset,
    button("x", "View along the x axis", () => stage.along("x")),
    button("y", "View along the y axis", () => stage.along("y")),
    button("z", "View along the z axis", () => stage.along("z")),
    flip,
    para,
    unit,
  );

  // ------------------------------------------------------------------ vertex labels
  const vertexEls = {};
  for (const name of "ABC") {
    const item = labels.label("v:" + name, "vertex", name);
    const e = item.el;
    e.dataset.vertex = name;
    e.tabIndex = 0;
    e.dataset.lmSuppressShortcuts = "true";
    e.setAttribute("role", "button");
    e.setAttribute("aria-roledescription", "movable point");
    e.setAttribute("aria-keyshortcuts", "ArrowLeft ArrowRight ArrowUp ArrowDown PageUp PageDown");
    vertexEls[name] = e;
  }
  for (const [id, text] of [["U", "U"], ["V", "V"], ["N", "N"], ["unit", "N/|N|"]]) labels.label("arrow:" + id, "arrow", text);
  for (const a of "xyz") labels.label("axis:" + a, "axis", a);

  // ------------------------------------------------------------------ geometry state
  let frame = null; // { S, offset: Vector3, includeOrigin, radius, L, t }
  let dragging = false;
  let lastGood = null; // last drawable points (data floats)
  let hostMoved = false; // the host (a cell, not this view) changed the triangle
  let display = null; // display-unit points of the last drawing
  let heads = {}; // display-unit arrow heads of the last drawing
  let scales = {}; // the power of two N and the unit normal are drawn at (their labels say it)

  function dataPoints() {
    const pts = [get("a"), get("b"), get("c")].map(parsePoint);
    if (pts.every(Boolean)) return pts;
    const st = get("state");
    if (st && st.ok && st.points) {
      const fromState = ["A", "B", "C"].map((k) => st.points[k]);
      if (fromState.every((p) => Array.isArray(p) && p.every(Number.isFinite))) return fromState;
    }
    return lastGood;
  }

  function computeFrame(pts, winding) {
    const ext = Math.max(...pts.flat().map(Math.abs));
    const edges = [
      [0, 1],
      [0, 2],
      [1, 2],
    ].map(([i, j]) => Math.hypot(...pts[i].map((x, k) => x - pts[j][k])));
    const size = Math.max(...edges);
    const includeOrigin = size === 0 ? true : ext <= 6 * size;
    const R = includeOrigin ? ext || size || 1 : size;
    const S = powerOfTen(R);
    const offset = includeOrigin
      ? new Vector3()
      : new Vector3(...[0, 1, 2].map((k) => Number(((pts[0][k] + pts[1][k] + pts[2][k]) / 3).toPrecision(3))));
    const disp = pts.map((p) => new Vector3(p[0] - offset.x, p[1] - offset.y, p[2] - offset.z).divideScalar(S));
    const extD = Math.max(...disp.map((p) => Math.max(Math.abs(p.x), Math.abs(p.y), Math.abs(p.z))));
    const t = niceCeil(Math.max(extD, 1e-9) / 1.5); // a labelled tick every t, grid lines every t/2
    const L = t * (Math.floor(extD / t + 1e-9) + 1.5);
    // the framed box: the points and the tips of N and the unit normal as drawn (the origin
    // and the axes are context: framing them too would make a triangle away from it small)
    const box = disp.slice();
    const [a, b, c] = disp;
    // N as drawn: A→C→B turns it over (framing the other side would leave its head out)
    const n = new Vector3().crossVectors(b.clone().sub(a), c.clone().sub(a));
    if (winding === "ACB") n.negate();
    const lMax = Math.max(a.distanceTo(b), a.distanceTo(c), b.distanceTo(c));
    const centroid = a.clone().add(b).add(c).divideScalar(3);
    if (n.length() > 0) {
      // n = U x V in display units is N / S^2: N's true length in display units is |n| * S
      box.push(centroid.clone().add(n.clone().setLength(drawnAt(n.length() * S, N_AIM * lMax).length)));
      if (get("show_unit_normal")) box.push(centroid.clone().add(n.clone().setLength(drawnAt(1 / S, UNIT_AIM * lMax).length)));
    }
    const lo = box[0].clone();
    const hi = box[0].clone();
    for (const p of box) {
      lo.min(p);
      hi.max(p);
    }
    const center = lo.clone().add(hi).multiplyScalar(0.5);
    const radius = Math.max(hi.distanceTo(lo) / 2, 1e-3);
    return { S, offset, includeOrigin, radius, center, box, L, t, start: startDirection(n) };
  }

  function applyFrame(next, moveCamera) {
    frame = next;
    if (moveCamera !== false) stage.framePoints(next.box, moveCamera, next.start);
    const r = frame.radius * 0.014;
    const ticks = drawing.setAxes(next.L, next.t, r * 0.5, colors, next.includeOrigin);
    drawing.setGrid(next.L, next.t, surface(dark), next.includeOrigin);
    labels.hide("tick:");
    ticks.forEach((tk, i) => {
      const id = `tick:${tk.axis}:${i}`;
      labels.label(id, "tick", tickText(tk.value * next.S));
      labels.place(id, tk.position, { offset: 16, angle: tk.axis === "z" ? 0 : -Math.PI / 2 });
    });
    for (const a of "xyz") {
      const tip = new Vector3(a === "x" ? next.L : 0, a === "y" ? next.L : 0, a === "z" ? next.L : 0);
      labels.place("axis:" + a, tip, { away: new Vector3(), offset: 18, visible: next.includeOrigin });
      setStyle(labels.items.get("axis:" + a).el, "color", colors(a));
    }
  }

  function sameUnits(a, b) {
    return a && b && a.S === b.S && a.includeOrigin === b.includeOrigin && a.offset.equals(b.offset);
  }

  function readoutValue(key) {
    const st = get("state");
    const row = st && st.ok !== false && Array.isArray(st.readout) ? st.readout.find((r) => r.key === key) : null;
    return row ? row.value : null;
  }

  function sync() {
    const pts = dataPoints();
    const st = get("state") || {};
    const winding = get("winding") === "ACB" ? "ACB" : "ABC";
    setText(flip, `⇄ ${ORDER[winding]}`);
    setAttr(flip, "aria-label", `Flip the order of the vertices, now ${ORDER[winding]}`);
    setAttr(flip, "title", flip.getAttribute("aria-label"));
    setAttr(para, "aria-pressed", !!get("show_parallelogram"));
    setAttr(unit, "aria-pressed", !!get("show_unit_normal"));
    readout.show(!!get("show_readout"));
    side.classList.toggle("tnx-no-readout", !get("show_readout"));
    if (get("show_readout")) readout.update(st);
    const problem = st.ok === false ? st.error || st.status : st.degenerate ? st.status : "";
    setHidden(message, !problem);
    setText(message, problem || "");
    setAttr(message, "data-state", st.ok === false ? "error" : "degenerate");
    const refused = model.get("message") || "";
    setHidden(error, !refused);
    setText(error, refused);
    controls.update();
    for (const name of "ABC") {
      const values = get(name.toLowerCase()) || [];
      setAttr(
        vertexEls[name],
        "aria-label",
        `Point ${name} at (${values.join(", ")}). Arrow keys move x and y, Page Up and Page Down move z.`,
      );
    }
    if (!pts) {
      drawing.root.visible = false;
      stage.requestRender();
      return;
    }
    drawing.root.visible = true;
    lastGood = pts;
    if (!dragging) {
      const next = computeFrame(pts, winding);
      if (!frame) applyFrame(next, true);
      else if (hostMoved) {
        // a new triangle from the host: frame it, facing it unless the user turned the view
        applyFrame(next, stage.atHome() ? true : "keep");
      } else if (!sameUnits(frame, next)) applyFrame(next, "keep"); // drawn in other units now
      else {
        // the learner's own move: the camera stays (nothing jumps); the axes may grow
        if (next.L !== frame.L || next.t !== frame.t) applyFrame({ ...next, center: frame.center, radius: frame.radius }, false);
        const shown = pts.map((p) => new Vector3(p[0] - frame.offset.x, p[1] - frame.offset.y, p[2] - frame.offset.z).divideScalar(frame.S));
        if (!stage.inView(shown)) applyFrame(next, "keep"); // a point left the view: step back
      }
    }
    hostMoved = false;
    const { S, offset } = frame;
    const [A, B, C] = pts.map((p) => new Vector3(p[0] - offset.x, p[1] - offset.y, p[2] - offset.z).divideScalar(S));
    const [P, Q] = winding === "ABC" ? [B, C] : [C, B];
    const centroid = A.clone().add(B).add(C).divideScalar(3);
    const U = P.clone().sub(A);
    const V = Q.clone().sub(A);
    const n = new Vector3().crossVectors(U, V);
    const nLen = n.length();
    const degenerate = !!st.degenerate || !(nLen > 0) || !Number.isFinite(nLen);
    const lMax = Math.max(U.length(), V.length(), P.distanceTo(Q), 1e-9); // the longest edge
    // n = U x V in display units is N / S^2: N's true length in display units is nLen * S
    let nDraw = new Vector3();
    let nFactor = 1;
    if (!degenerate) {
      const d = drawnAt(nLen * S, N_AIM * lMax);
      nFactor = d.factor;
      nDraw = n.clone().setLength(d.length);
    }
    let unitDraw = null;
    let unitFactor = 1;
    if (!degenerate && get("show_unit_normal")) {
      const d = drawnAt(1 / S, UNIT_AIM * lMax);
      unitFactor = d.factor;
      unitDraw = n.clone().setLength(d.length);
    }
    labels.label("arrow:N", "arrow", scaledLabel(nFactor));
    labels.label("arrow:unit", "arrow", scaledLabel(unitFactor, true));
    scales = { N: nFactor, unit: unitDraw ? unitFactor : null };
    const r = frame.radius * 0.014;
    const g = { A, B, C, P, Q, centroid, nDraw, unitDraw, degenerate, showParallelogram: !!get("show_parallelogram"), r };
    drawing.update(g);
    display = { A, B, C };
    heads = { U: P, V: Q, N: degenerate ? null : centroid.clone().add(nDraw), unit: unitDraw ? centroid.clone().add(unitDraw) : null };

    // labels: vertices beyond their points (and the arrow heads there), arrows beside their shafts
    for (const name of "ABC") {
      labels.place("v:" + name, g[name], { away: centroid, offset: 30, angle: VERTEX_ANGLE[name] });
      setStyle(vertexEls[name], "color", colors(name));
    }
    labels.place("arrow:U", A.clone().lerp(P, 0.5), { away: centroid, offset: 20, visible: U.length() > 0 });
    labels.place("arrow:V", A.clone().lerp(Q, 0.5), { away: centroid, offset: 20, visible: V.length() > 0 });
    const nTip = centroid.clone().add(nDraw);
    labels.place("arrow:N", nTip, { away: centroid, offset: 20, angle: 0, visible: !degenerate });
    labels.place("arrow:unit", unitDraw ? centroid.clone().add(unitDraw) : null, {
      away: centroid, offset: 20, angle: Math.PI, visible: !!unitDraw,
    });
    for (const [id, role] of [["U", "U"], ["V", "V"], ["N", "N"], ["unit", "unit"]]) {
      setStyle(labels.items.get("arrow:" + id).el, "color", colors(role));
    }
    const magnitude = readoutValue("magnitude");
    const area = readoutValue("area");
    const showAreas = g.showParallelogram && !degenerate && magnitude !== null && area !== null;
    setHidden(legend, !showAreas);
    if (showAreas) setText(legend, `Parallelogram on U and V: area |N| = ${magnitude}. Triangle: area |N|/2 = ${area}.`);
    stage.requestRender();
  }

  function repaint() {
    root.classList.toggle("tn-dark", dark);
    stage.setBackground(surface(dark).background);
    drawing.paint(colors);
    if (frame) {
      drawing.setGrid(frame.L, frame.t, surface(dark), frame.includeOrigin); // the grid's colours
      for (const a of "xyz") setStyle(labels.items.get("axis:" + a).el, "color", colors(a));
    }
    sync();
  }

  // touch: a finger scrolls the page over the view until a tap turns it on (touch.js)
  const touch = touchGate({ root, stageEl, controls: stage.controls, canvas: stage.canvas, activeClass: "tnx-touch-active" });

  const interaction = setupInteraction({
    touchActive: touch.active,
    container: stageEl,
    canvas: stage.canvas,
    camera: stage.camera,
    scale: () => frame?.S ?? 1,
    grid: () => readStep(get("step")),
    bounds: () => get("bounds"),
    values: (name) => (get(name.toLowerCase()) || ["", "", ""]).map(String),
    position: (name) => (display ? display[name] : null),
    write(changes) {
      edit(changes);
      flush();
    },
    dragging(on) {
      dragging = on;
      if (!on) sync();
    },
  });

  // changes are gathered and drawn once; a drag draws in the frame that moved the vertex
  let dirty = false;
  const onChange = () => {
    if (dirty) return;
    dirty = true;
    queueMicrotask(() => {
      if (!dirty) return;
      dirty = false;
      sync();
    });
  };
  const flush = () => {
    dirty = false;
    sync();
    stage.renderNow();
  };
  const onPalette = () => repaint();
  const handlers = {};
  for (const key of KEYS) {
    handlers[key] = key === "palette" ? onPalette : onChange;
    model.on("change:" + key, handlers[key]);
  }
  // the host answered an edit: what it answered is no longer drawn from the view's own copy
  handlers.last_edit = () => {
    const answer = model.get("last_edit") || {};
    if (answer.view !== viewId) return;
    for (const [key, p] of Object.entries(pending)) if (p.seq <= answer.seq) delete pending[key];
    onChange();
  };
  // the host changed its values itself (a cell ran): that is the truth from now on
  handlers.version = () => {
    interaction.cancel();
    pending = {};
    controls.reset();
    hostMoved = true;
    onChange();
  };
  model.on("change:last_edit", handlers.last_edit);
  model.on("change:version", handlers.version);
  const stopTheme = watchTheme((d) => {
    dark = d;
    repaint();
  });

  const centroidOf = (d) => d.A.clone().add(d.B).add(d.C).divideScalar(3);

  /** Where the vertices and arrow heads are on screen (px in the view), for tests and tools. */
  root.tnxProject = () => {
    if (!display || !frame) return null;
    const { width, height } = stage.size();
    stage.camera.updateMatrixWorld();
    const out = {};
    for (const [key, p] of Object.entries({ ...display, ...heads })) {
      if (!p) continue;
      const q = p.clone().project(stage.camera);
      out[key] = [((q.x + 1) / 2) * width, ((1 - q.y) / 2) * height];
    }
    const distance = stage.camera.position.distanceTo(stage.controls.target);
    // the arrows as drawn, in data units (display units times S), and their drawing scales
    const vector = (p) => (p && display ? p.clone().sub(centroidOf(display)).multiplyScalar(frame.S).toArray() : null);
    const drawn = { N: vector(heads.N), unit: vector(heads.unit), scales: { ...scales } };
    return { width, height, distance, points: out, drawn, values: ["a", "b", "c"].map((k) => (get(k) || []).map(String)) };
  };

  stage.resize();
  repaint();

  return () => {
    for (const key of KEYS) model.off("change:" + key, handlers[key]);
    model.off("change:last_edit", handlers.last_edit);
    model.off("change:version", handlers.version);
    touch.dispose();
    stopTheme();
    interaction();
    labels.dispose();
    drawing.dispose();
    stage.dispose();
    readout.dispose();
    controls.dispose();
    root.remove();
  };
}

export default { render };
