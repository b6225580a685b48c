/*
 * The picture in the stage: the labels, the frame (axes, grid and ticks in the units of
 * framing.js), the triangle with its arrows, and where they are on screen.
 *
 * `view` is the explorer's state (index.js): get, stage, labels, drawing, vertexEls, colors,
 * dark, and what the last drawing left: frame, lastGood, display, heads, scales.
 */
import { Vector3 } from "three";
import { Drawing } from "./geometry.js";
import { setStyle } from "./dom.js";
import { computeFrame, drawnArrows, sameUnits, showsTriangle, toDisplay } from "./framing.js";
import { LabelLayer } from "./labels.js";
import { parsePoint, tickText } from "./numbers.js";
import { scaledLabel } from "./scaling.js";
import { toScreen } from "./scene.js";
import { surface } from "./theme.js";

const VERTEX_ANGLE = { A: (225 * Math.PI) / 180, B: (-30 * Math.PI) / 180, C: (90 * Math.PI) / 180 };

/** The labels over the stage: { labels, vertexEls } (A, B and C are focusable, movable points). */
export function createLabels(stageEl, view) {
  const labels = new LabelLayer(stageEl, () => sizeToScreen(view));
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
  return { labels, vertexEls };
}

/** The triangle's points as data floats: the values, else the host's, else the last drawn. */
export function dataPoints(view) {
  const { get } = view;
  const pts = [get("a"), get("b"), get("c")].map(parsePoint);
  if (pts.every(Boolean)) return pts;
  const st = get("state");
  if (st && st.ok && st.points) {
    const fromState = ["A", "B", "C"].map((k) => st.points[k]);
    if (fromState.every((p) => Array.isArray(p) && p.every(Number.isFinite))) return fromState;
  }
  return view.lastGood;
}

/** The frame of these points as the view now draws them. */
export function frameOf(view, pts, winding = view.get("winding")) {
  const st = view.get("state") || {};
  return computeFrame(pts, winding, view.get("show_unit_normal"), !!st.degenerate);
}

// sizes on the screen, in px, whatever the zoom: an arrow's shaft radius, a vertex's marker
// radius (larger on a degenerate triangle's line, where the points are all there is)
const ARROW_PX = 2.4;
const VERTEX_PX = 6;
const DEGENERATE_VERTEX_PX = 8;
const AXIS_PX = 2;
const TICK_PX = 2.3;
const AXIS_NEAREST = 0.4;

/**
 * Size the 3D marks in screen pixels for the camera as it is now: the arrows and the axes by
 * their size at the target, each vertex's marker at its own depth. Runs before every picture.
 */
function sizeToScreen(view) {
  const { stage, drawing, frame, last } = view;
  if (!frame || !last) return;
  const r = ARROW_PX * stage.pixelAt(stage.controls.target);
  if (!(Math.abs(r / last.r - 1) < 0.01)) {
    last.r = r;
    drawing.update(last);
    drawing.setAxes(frame.L, frame.t, r * 0.5, view.colors, frame.includeOrigin);
  }
  const px = last.degenerate ? DEGENERATE_VERTEX_PX : VERTEX_PX;
  for (const name of "ABC") {
    const m = drawing.vertices[name];
    m.scale.setScalar(px * stage.pixelAt(m.position));
  }
  if (frame.includeOrigin) sizeAxes(view);
}

/**
 * Draw each axis as thin as AXIS_PX where it is nearest the camera. An axis that passes close
 * to the camera would swell into a bar across the picture there: the part of it nearer than
 * AXIS_NEAREST times the target's depth is left out (its arrowhead with it, when that is cut).
 */
function sizeAxes(view) {
  const { stage, drawing, frame } = view;
  const forward = stage.controls.target.clone().sub(stage.camera.position).normalize();
  const depthOf = (p) => p.clone().sub(stage.camera.position).dot(forward);
  const least = AXIS_NEAREST * depthOf(stage.controls.target);
  for (const a of "xyz") {
    const e = new Vector3(a === "x" ? 1 : 0, a === "y" ? 1 : 0, a === "z" ? 1 : 0);
    // the depth along the axis is linear: d(s) = d0 + k s for the point s e, s in [-L, L]
    const d0 = depthOf(new Vector3());
    const k = e.dot(forward);
    let [lo, hi] = [-frame.L, frame.L];
    if (Math.abs(k) > 1e-12) {
      const s = (least - d0) / k; // where the axis reaches the least depth
      if (k > 0) lo = Math.max(lo, s);
      else hi = Math.min(hi, s);
    } else if (d0 < least) hi = lo; // all of it too near
    const { arrow, ticks } = drawing.axes[a];
    const shown = hi > lo;
    const r = AXIS_PX * stage.pixelAt(e.clone().multiplyScalar(k > 0 ? lo : hi));
    Drawing.placeArrow(arrow, e.clone().multiplyScalar(lo), e.clone().multiplyScalar(hi), r, shown);
    arrow.head.visible = !(shown && hi < frame.L);
    for (const tick of ticks) {
      if (!tick.visible) continue;
      tick.scale.setScalar(depthOf(tick.position) < least ? 0 : TICK_PX * stage.pixelAt(tick.position));
    }
  }
}

/** Draw in the frame `next` (axes, grid, ticks); moveCamera as the stage's framePoints' `go`. */
export function applyFrame(view, next, moveCamera) {
  const { stage, drawing, labels, colors } = view;
  view.frame = next;
  if (moveCamera === false) stage.framePoints(next.box, false);
  else {
    // keep the learner's direction unless it would show the triangle edge-on (or along its line)
    const keep = moveCamera === "keep" && showsTriangle(stage.direction(), next);
    stage.framePoints(next.box, keep ? "keep" : true, next.start);
  }
  const r = ARROW_PX * stage.pixelAt(stage.controls.target);
  const ticks = drawing.setAxes(next.L, next.t, r * 0.5, colors, next.includeOrigin);
  drawing.setGrid(next.L, next.t, surface(view.dark), next.includeOrigin);
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

/**
 * Frame the points again after a change (not during a drag): the first drawing, a new
 * triangle from the host, a flip of the order, new units. The learner's own move (a typed
 * value, a slider, a key, the end of a drag) keeps the camera while everything framed stays
 * well inside the view, fills a fair part of it and is not seen edge-on; otherwise it frames
 * too, keeping the learner's direction.
 */
export function reframe(view, pts, winding) {
  const { stage } = view;
  if (!view.dragging) {
    const next = frameOf(view, pts, winding);
    const frame = view.frame;
    const flipped = view.drawnWinding && view.drawnWinding !== winding;
    if (!frame) applyFrame(view, next, true);
    else if (view.hostMoved || flipped) {
      // a new triangle from the host, or N turned over: frame it, facing its front unless the
      // user turned the view
      applyFrame(view, next, stage.atHome() ? true : "keep");
    } else if (!sameUnits(frame, next)) applyFrame(view, next, "keep"); // drawn in other units now
    else {
      const { inside, fill } = stage.spread(next.box);
      if (!inside || fill < 0.35 || !showsTriangle(stage.direction(), next)) applyFrame(view, next, "keep");
      else applyFrame(view, next, false); // the camera stays; the axes may grow
    }
    view.drawnWinding = winding;
  }
  view.hostMoved = false;
}

/** Place the vertex and arrow labels: vertices beyond their points, arrows beside their shafts. */
function placeLabels(view, g, U, V) {
  const { labels, vertexEls, colors } = view;
  const { A, P, Q, centroid, nDraw, unitDraw, degenerate } = g;
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
  for (const id of ["U", "V", "N", "unit"]) setStyle(labels.items.get("arrow:" + id).el, "color", colors(id));
}

/**
 * Draw the triangle `pts` (data floats) in `winding` with its arrows and labels, in the
 * current frame; `st` is the host's state. Returns true when the parallelogram is drawn.
 */
export function drawTriangle(view, pts, st, winding) {
  const { get, labels, frame } = view;
  const { S } = frame;
  const [A, B, C] = pts.map((p) => toDisplay(p, frame));
  const [P, Q] = winding === "ABC" ? [B, C] : [C, B];
  const centroid = A.clone().add(B).add(C).divideScalar(3);
  const U = P.clone().sub(A);
  const V = Q.clone().sub(A);
  const n = new Vector3().crossVectors(U, V);
  const nLen = n.length();
  const degenerate = !!st.degenerate || !(nLen > 0) || !Number.isFinite(nLen);
  const lMax = Math.max(U.length(), V.length(), P.distanceTo(Q), 1e-9); // the longest edge
  const { nDraw, nFactor, unitDraw, unitFactor } = drawnArrows(n, S, lMax, degenerate, get("show_unit_normal"));
  labels.label("arrow:N", "arrow", scaledLabel(nFactor));
  labels.label("arrow:unit", "arrow", scaledLabel(unitFactor, true));
  view.scales = { N: nFactor, unit: unitDraw ? unitFactor : null };
  const r = ARROW_PX * view.stage.pixelAt(view.stage.controls.target);
  const g = { A, B, C, P, Q, centroid, nDraw, unitDraw, degenerate, showParallelogram: !!get("show_parallelogram"), r };
  view.drawing.update(g);
  view.last = g; // redrawn at the screen's sizes before each picture (sizeToScreen)
  view.display = { A, B, C };
  view.heads = { U: P, V: Q, N: degenerate ? null : centroid.clone().add(nDraw), unit: unitDraw ? centroid.clone().add(unitDraw) : null };
  placeLabels(view, g, U, V);
  return g.showParallelogram && !degenerate;
}

/** Where the vertices and arrow heads are on screen (px in the view), for tests and tools. */
export function projection(view) {
  const { display, heads, frame, stage, get } = view;
  if (!display || !frame) return null;
  const { width, height } = stage.size();
  stage.camera.updateMatrixWorld();
  const out = {};
  for (const [key, p] of Object.entries({ ...display, ...heads })) {
    if (!p) continue;
    const q = toScreen(p, stage.camera, width, height);
    out[key] = [q.x, q.y];
  }
  const distance = stage.camera.position.distanceTo(stage.controls.target);
  // the arrows as drawn, in data units (display units times S), and their drawing scales
  const centroid = display.A.clone().add(display.B).add(display.C).divideScalar(3);
  const vector = (p) => (p ? p.clone().sub(centroid).multiplyScalar(frame.S).toArray() : null);
  const drawn = { N: vector(heads.N), unit: vector(heads.unit), scales: { ...view.scales } };
  return { width, height, distance, points: out, drawn, values: ["a", "b", "c"].map((k) => (get(k) || []).map(String)) };
}
