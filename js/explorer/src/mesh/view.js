/*
 * The 3D view of a whole mesh: an anywidget-style module, `export default { render }`, like the
 * triangle explorer beside it (../index.js), sharing its stage (../scene.js) and colours.
 *
 * render({ model, el }) reads model.get("mesh"):
 *   { positions: Float64Array or Float32Array (3 per vertex), faces: Uint32Array (3 per triangle),
 *     flipped: Int32Array (faces to flip), boundary, non_manifold: Int32Array (one face side
 *     3 * face + k per edge, the edge from corner k to corner k + 1) }
 * and model.get("palette") ({role: {light, dark}}, trinormal.colors.palette()). The side of a
 * face its normal points out of is drawn in the "front" colour, the other side in "back";
 * faces to flip are outlined, boundary and non-manifold edges drawn thick, each in its role's
 * colour. It returns a cleanup function.
 *
 * In Jupyter (trinormal.mesh.widget.MeshView, an anywidget) there is no "mesh" key: the same
 * arrays come as binary buffers (DataViews) in "positions", "faces", "flipped", "boundary" and
 * "non_manifold", with "revision" bumped after each new mesh, and also:
 *   arrow_faces (Int32, a sample of faces) and arrow_normals (Float32, their unit normals):
 *     drawn as short arrows from each face's centre (degenerate faces have zero rows);
 *   vertex_normals (Float32, 3 per vertex, from the kernel): smooth shading and vertex arrows;
 *   cull, smooth, show_face_normals, show_vertex_normals (bool): the toolbar's toggles;
 *   picked (int): the view writes the face clicked or typed (-1: none), and the kernel answers
 *   with selection ({title, rows: [[label, value, role]]}: the face's vertices, exact normal and
 *   area, as the package's formatter prints them), shown under the view.
 * A host without the toggles' keys (the site) gets them as local state, three.js's own vertex
 * normals for smooth shading, and no arrows. The site's page answers "picked" with "selection"
 * itself, from its own exact core (docs/assets/javascripts/mesh-page.js).
 *
 * The parts, each in its own module: data.js (the host's arrays), framing.js (where the camera
 * looks), surface.js (the two-sided surface), outlines.js (faults and the picked face),
 * arrows.js (normals), lod.js (a coarser copy while the camera turns), picking.js (a click
 * picks a face), keys.js (the keyboard's ways), toolbar.js (toggles), panels.js (legend and
 * the picked face's readout), describe.js (the view in words: the model, its pieces, the faces
 * to flip and the picked face, from the host's optional "about": { name, pieces }). This file
 * lays them out and keeps them in step with the model.
 */
import { AmbientLight, DirectionalLight } from "three";
import { element } from "../dom.js";
import { createStage } from "../scene.js";
import { injectStyle } from "../style.js";
import { isDark, roleColor, surface as surfaceColors, watchTheme } from "../theme.js";
import { touchGate } from "../touch.js";
import { createArrows } from "./arrows.js";
import { displayPositions, readMesh } from "./data.js";
import { createMeshDescription } from "./describe.js";
import { framingPoints, MARGIN, startDirection } from "./framing.js";
import { createFaceForm, focusableStage, turnWithKeys } from "./keys.js";
import { createLod } from "./lod.js";
import { createOutlines, faultSides } from "./outlines.js";
import { drawLegend, showSelection } from "./panels.js";
import { createPicking } from "./picking.js";
import { createSurface } from "./surface.js";
import { createFlags, createToolbar, LOCAL_FLAGS } from "./toolbar.js";
import CSS from "./style.css";

const NO_COUNTS = { flipped: 0, boundary: 0, non_manifold: 0, face_arrows: 0, vertex_arrows: 0 };

function hint(canPick) {
  return element(
    "p",
    "tnm-hint",
    "Drag to turn the model, scroll or pinch to zoom; on a touch screen, tap the view first, then drag; " +
      "from the keyboard, Tab to the view and use the arrow keys, + and −. " +
      "The side a face's normal points out of is drawn in the front colour; a face you see in the " +
      "back colour from outside is wound the other way." +
      (canPick ? " Click or tap a face, or type its number in the Face number box, to see its vertices, its exact normal and its area." : ""),
  );
}

/** The view's HTML: the stage, the legend, the face-number form, the picked face's readout, the hint. */
function layout(canPick, faceForm) {
  const root = element("div", "tn-view tnm-root");
  const stageEl = element("div", "tnm-stage tn-stage");
  const legend = element("ul", "tnm-legend");
  const panel = element("div", "tnm-pick"); // said by the description (describe.js), which is live
  panel.hidden = true;
  faceForm.form.hidden = !canPick;
  root.append(stageEl, legend, faceForm.form, panel, hint(canPick));
  return { root, stageEl, legend, panel };
}

/** A colour of the host's palette for a role, in the current scheme. */
function colorOf(view, role) {
  return roleColor(view.model.get("palette") || {}, role, view.dark);
}

function redrawLegend(view) {
  drawLegend(view.legend, {
    counts: view.counts,
    shown: (role) => view.flags.get(role === "face_arrows" ? "show_face_normals" : "show_vertex_normals"),
    colorOf: (role) => (role === "face_arrows" ? colorOf(view, "N") : role === "vertex_arrows" ? surfaceColors(view.dark).text : colorOf(view, role)),
  });
}

function applyColors(view) {
  const s = surfaceColors(view.dark);
  view.root.classList.toggle("tn-dark", view.dark);
  view.stage.setBackground(s.background);
  view.surface.setColors(colorOf(view, "front"), colorOf(view, "back"));
  view.outlines.setColors((role) => colorOf(view, role), s.line);
  view.arrows.setColors(colorOf(view, "N"), s.text);
  redrawLegend(view);
  view.stage.requestRender();
}

/** The toggles' effects, the toolbar's and the face form's state, the legend. */
function applyFlags(view) {
  const { flags, current } = view;
  view.surface.shade(flags.get("cull"), flags.get("smooth"));
  view.arrows.show("face", flags.get("show_face_normals"));
  view.arrows.show("vertex", flags.get("show_vertex_normals"));
  view.toolbar.update(view.arrows);
  const faces = current ? current.data.faces.length / 3 : 0;
  view.faceForm.form.hidden = !view.canPick || !faces;
  view.faceForm.update(faces, current && current.data.flipped);
  redrawLegend(view);
  view.stage.requestRender();
}

function updateResolution(view) {
  const { width, height } = view.stage.size();
  view.outlines.setResolution(width, height);
}

function clearModel(view) {
  for (const part of [view.surface, view.outlines, view.arrows, view.lod, view.picking]) part.clear();
  view.current = null;
  view.counts = NO_COUNTS;
}

/** Draw the model's mesh (or nothing, when it has none), looking from where the trouble is. */
function drawModel(view) {
  clearModel(view);
  const { root, stage } = view;
  const data = readMesh(view.model);
  if (!data || !data.positions || !data.faces) {
    applyFlags(view);
    describe(view);
    return;
  }
  const { pos, offset, scale } = displayPositions(data.positions);
  view.surface.draw(pos, data.faces, data.vertex_normals);
  view.picking.schedule();
  const sets = faultSides(data, pos.length / 3);
  root.dataset.flippedSides = String(sets.flipped.length); // the sides outlined
  view.outlines.draw(pos, data.faces, sets);
  view.outlines.show(false);
  stage.framePoints(framingPoints(pos), true, startDirection(pos, data.faces, sets));
  view.lod.draw(data.faces, pos);
  view.arrows.draw(data, pos);
  view.counts = {
    flipped: data.flipped ? data.flipped.length : 0,
    boundary: sets.boundary.length,
    non_manifold: sets.non_manifold.length,
    face_arrows: view.arrows.count("face"),
    vertex_arrows: view.arrows.count("vertex"),
  };
  view.current = { data, pos, offset, scale };
  updateResolution(view);
  applyFlags(view);
  root.dataset.faces = String(data.faces.length / 3);
  showPick(view);
}

/** Outline the picked face and show the host's answer for it. */
function showPick(view) {
  const { model, current, root } = view;
  view.outlines.clearPicked();
  const face = model.get("picked");
  if (current && Number.isInteger(face) && face >= 0 && face < current.data.faces.length / 3) {
    view.outlines.showPicked(current.pos, current.data.faces, face);
    root.dataset.picked = String(face);
    view.faceForm.showPicked(face);
  } else {
    delete root.dataset.picked;
  }
  showSelection(view.panel, model.get("selection"));
  describe(view);
  view.stage.requestRender();
}

/** The view in words under it (describe.js): the model, its pieces, the faces to flip, the picked face. */
function describe(view) {
  const { model, current } = view;
  view.description.update({
    about: model.get("about"),
    faces: current ? current.data.faces.length / 3 : 0,
    flipped: current ? current.data.flipped : null,
    picked: model.get("picked"),
    selection: model.get("selection"),
  });
}

function render({ model, el }) {
  const doc = el.ownerDocument || document;
  const canPick = model.get("picked") !== undefined; // the host answers a picked face
  injectStyle(doc, "trinormal-mesh-style", CSS);
  const faceForm = createFaceForm({ onPick: pick, picked: () => model.get("picked") });
  const { root, stageEl, legend, panel } = layout(canPick, faceForm);
  el.appendChild(root);
  let stage;
  try {
    stage = createStage(stageEl, { onRender: () => {}, margin: MARGIN });
  } catch (err) {
    stageEl.remove();
    root.appendChild(element("p", "tnm-nogl", "This browser cannot draw the 3D view (WebGL is not available). The report above does not need it."));
    return () => root.remove();
  }
  const light = new DirectionalLight(0xffffff, 1.9);
  light.position.set(0, 0, 1);
  stage.camera.add(light);
  stage.scene.add(new AmbientLight(0xffffff, 1.1), stage.camera);

  const view = { model, root, stage, legend, panel, faceForm, canPick, dark: isDark(doc), current: null, counts: NO_COUNTS };
  view.description = createMeshDescription(stageEl);
  view.flags = createFlags(model, () => applyFlags(view));
  view.surface = createSurface(stage.scene);
  view.outlines = createOutlines(stage.scene);
  view.arrows = createArrows(stage.scene);
  view.lod = createLod({ stage, surface: view.surface, outlines: view.outlines, root });
  const culled = () => view.flags.get("cull");
  view.picking = createPicking({ stage, surface: view.surface, root, canPick, culled, frame: () => view.current, onPick: pick });
  view.toolbar = createToolbar({ flags: view.flags, stage, root });
  root.prepend(view.toolbar.el);
  function pick(face) {
    model.set("picked", face);
    model.save_changes();
    showPick(view);
  }

  focusableStage(stageEl);
  const stopKeys = turnWithKeys(stageEl, stage);
  // a finger scrolls the page over the view until a tap turns it on (a tap also picks)
  const touch = touchGate({ root, stageEl, controls: stage.controls, canvas: stage.canvas, activeClass: "tnm-touch-active" });
  const observer = new ResizeObserver(() => {
    updateResolution(view);
    stage.requestRender();
  });
  observer.observe(stageEl);
  const stopTheme = watchTheme((dark) => {
    view.dark = dark;
    applyColors(view);
  }, doc);
  const draw = () => drawModel(view);
  const flagsChanged = () => applyFlags(view);
  const colorsChanged = () => applyColors(view);
  const pickChanged = () => showPick(view);
  const events = [
    ["change:mesh", draw],
    ["change:revision", draw],
    ["change:palette", colorsChanged],
    ["change:picked", pickChanged],
    ["change:selection", pickChanged],
    ["change:about", pickChanged],
    ...Object.keys(LOCAL_FLAGS).map((key) => ["change:" + key, flagsChanged]),
  ];
  for (const [event, cb] of events) model.on(event, cb);
  applyColors(view);
  draw();
  return () => {
    for (const [event, cb] of events) model.off(event, cb);
    stopKeys();
    view.toolbar.dispose();
    touch.dispose();
    observer.disconnect();
    stopTheme();
    for (const part of [view.picking, view.lod, view.surface, view.outlines, view.arrows]) part.dispose();
    stage.dispose();
    view.description.dispose();
    root.remove();
  };
}

export default { render };
