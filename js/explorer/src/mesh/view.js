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
 */
import {
  AmbientLight,
  BackSide,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  FrontSide,
  Mesh,
  MeshLambertMaterial,
  Vector3,
} from "three";
import { LineMaterial } from "three/addons/lines/LineMaterial.js";
import { LineSegments2 } from "three/addons/lines/LineSegments2.js";
import { LineSegmentsGeometry } from "three/addons/lines/LineSegmentsGeometry.js";
import { createStage, DEFAULT_DIRECTION } from "../scene.js";
import { isDark, roleColor, surface, watchTheme } from "../theme.js";
import CSS from "./style.css";

const STYLE_ID = "trinormal-mesh-style";

function injectStyle(doc) {
  if (doc.getElementById(STYLE_ID)) return;
  const style = doc.createElement("style");
  style.id = STYLE_ID;
  style.textContent = CSS;
  doc.head.appendChild(style);
}

function element(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

/** Segments (6 floats each) of the given face sides, in display units. */
function sideSegments(positions, faces, sides, scale, offset) {
  const out = new Float32Array(6 * sides.length);
  for (let i = 0; i < sides.length; i++) {
    const h = sides[i];
    const a = faces[h];
    const b = faces[h % 3 === 2 ? h - 2 : h + 1];
    for (let k = 0; k < 3; k++) {
      out[6 * i + k] = (positions[3 * a + k] - offset[k]) * scale;
      out[6 * i + 3 + k] = (positions[3 * b + k] - offset[k]) * scale;
    }
  }
  return out;
}

/** The three sides of each face in the list. */
function allSides(list) {
  const out = new Int32Array(3 * list.length);
  for (let i = 0; i < list.length; i++) for (let k = 0; k < 3; k++) out[3 * i + k] = 3 * list[i] + k;
  return out;
}

/** Centre and radius of the bounding box; a scale that brings the model to radius ~2. */
function framing(positions) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const x = positions[i + k];
      if (x < lo[k]) lo[k] = x;
      if (x > hi[k]) hi[k] = x;
    }
  }
  if (!(lo[0] <= hi[0])) return { offset: [0, 0, 0], scale: 1 };
  const offset = lo.map((l, k) => (l + hi[k]) / 2);
  const radius = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2;
  return { offset, scale: radius > 0 && Number.isFinite(radius) ? 2 / radius : 1 };
}

/**
 * Where the camera first looks from: towards what is wrong (the faces to flip, else the holes'
 * rims, else the fins), tilted a little so the view stays oblique; the usual view otherwise.
 */
function startDirection(pos, faces, sets) {
  const sides = sets.flipped.length ? sets.flipped : sets.boundary.length ? sets.boundary : sets.non_manifold;
  if (!sides.length) return DEFAULT_DIRECTION.clone();
  const c = new Vector3();
  for (let i = 0; i < sides.length; i++) {
    const v = faces[sides[i]];
    c.x += pos[3 * v];
    c.y += pos[3 * v + 1];
    c.z += pos[3 * v + 2];
  }
  c.divideScalar(sides.length);
  if (!(c.length() > 1e-6)) return DEFAULT_DIRECTION.clone();
  return c.normalize().multiplyScalar(3).add(DEFAULT_DIRECTION).normalize();
}

function render({ model, el }) {
  const doc = el.ownerDocument || document;
  injectStyle(doc);
  const root = element("div", "tnm-root");
  const toolbar = element("div", "tnm-toolbar");
  toolbar.setAttribute("role", "toolbar");
  toolbar.setAttribute("aria-label", "3D view of the mesh");
  const stageEl = element("div", "tnm-stage");
  const legend = element("ul", "tnm-legend");
  const hint = element(
    "p",
    "tnm-hint",
    "Drag to turn the model, scroll or pinch to zoom. The side a face's normal points out of is " +
      "drawn in the front colour; a face you see in the back colour from outside is wound the " +
      "other way.",
  );
  root.append(toolbar, stageEl, legend, hint);
  el.appendChild(root);

  let dark = isDark(doc);
  let stage;
  try {
    stage = createStage(stageEl, { onRender: () => {} });
  } catch (err) {
    stageEl.remove();
    root.appendChild(element("p", "tnm-nogl", "This browser cannot draw the 3D view (WebGL is not available). The report above does not need it."));
    return () => root.remove();
  }
  const scene = stage.scene;
  const ambient = new AmbientLight(0xffffff, 1.1);
  const light = new DirectionalLight(0xffffff, 1.9);
  light.position.set(0, 0, 1);
  stage.camera.add(light);
  scene.add(ambient, stage.camera);

  const front = new MeshLambertMaterial({ side: FrontSide, flatShading: true, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  const back = new MeshLambertMaterial({ side: BackSide, flatShading: true, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  const lineMaterials = {
    flipped: new LineMaterial({ linewidth: 2.5 }),
    boundary: new LineMaterial({ linewidth: 4 }),
    non_manifold: new LineMaterial({ linewidth: 4 }),
  };
  let geometry = null;
  let meshes = [];
  let lines = {};
  let cull = false;
  const counts = { flipped: 0, boundary: 0, non_manifold: 0 };

  const palette = () => model.get("palette") || {};
  function applyColors() {
    const s = surface(dark);
    root.classList.toggle("tnm-dark", dark);
    stage.setBackground(s.background);
    front.color = new Color(roleColor(palette(), "front", dark));
    back.color = new Color(roleColor(palette(), "back", dark));
    for (const [role, m] of Object.entries(lineMaterials)) m.color = new Color(roleColor(palette(), role, dark));
    drawLegend();
    stage.requestRender();
  }

  const LEGEND = [
    ["front", "front of a face (its normal points out of this side)", "face"],
    ["back", "back of a face", "face"],
    ["flipped", "outline: a face to flip", "line"],
    ["boundary", "thick: an edge with one face (the rim of a hole)", "line"],
    ["non_manifold", "thick: an edge with three faces or more", "line"],
  ];
  function drawLegend() {
    legend.textContent = "";
    for (const [role, text, kind] of LEGEND) {
      if (kind === "line" && !counts[role]) continue;
      const item = element("li", "tnm-key");
      const swatch = element("span", "tnm-swatch tnm-swatch-" + kind);
      swatch.style.setProperty("--tnm-swatch", roleColor(palette(), role, dark));
      swatch.setAttribute("aria-hidden", "true");
      item.append(swatch, doc.createTextNode(kind === "line" ? `${text} (${counts[role]})` : text));
      legend.appendChild(item);
    }
  }

  function clear() {
    for (const m of meshes) scene.remove(m);
    for (const l of Object.values(lines)) {
      scene.remove(l);
      l.geometry.dispose();
    }
    if (geometry) geometry.dispose();
    meshes = [];
    lines = {};
    geometry = null;
  }

  function draw() {
    clear();
    const data = model.get("mesh");
    if (!data || !data.positions || !data.faces) {
      stage.requestRender();
      return;
    }
    const { offset, scale } = framing(data.positions);
    const pos = new Float32Array(data.positions.length);
    for (let i = 0; i < pos.length; i++) pos[i] = (data.positions[i] - offset[i % 3]) * scale;
    geometry = new BufferGeometry();
    geometry.setAttribute("position", new BufferAttribute(pos, 3));
    geometry.setIndex(new BufferAttribute(data.faces, 1));
    meshes = [new Mesh(geometry, front), new Mesh(geometry, back)];
    meshes[1].visible = !cull;
    scene.add(...meshes);
    const sets = {
      flipped: data.flipped ? allSides(data.flipped) : new Int32Array(0),
      boundary: data.boundary || new Int32Array(0),
      non_manifold: data.non_manifold || new Int32Array(0),
    };
    const zero = [0, 0, 0];
    for (const [role, sides] of Object.entries(sets)) {
      counts[role] = role === "flipped" ? sides.length / 3 : sides.length;
      if (!sides.length) continue;
      const g = new LineSegmentsGeometry();
      g.setPositions(sideSegments(pos, data.faces, sides, 1, zero));
      const l = new LineSegments2(g, lineMaterials[role]);
      l.renderOrder = 1;
      lines[role] = l;
      scene.add(l);
    }
    // keep the corners of the model's box in view, looking from where the trouble is
    geometry.computeBoundingBox();
    const { min, max } = geometry.boundingBox;
    const corners = [];
    for (const x of [min.x, max.x]) for (const y of [min.y, max.y]) for (const z of [min.z, max.z]) corners.push(new Vector3(x, y, z));
    stage.framePoints(corners, true, startDirection(pos, data.faces, sets));
    updateResolution();
    drawLegend();
    stage.requestRender();
    root.dataset.faces = String(data.faces.length / 3);
  }

  function updateResolution() {
    const { width, height } = stage.size();
    for (const m of Object.values(lineMaterials)) m.resolution.set(width, height);
  }

  const cullButton = element("button", "tnm-button", "Cull back faces");
  cullButton.type = "button";
  cullButton.setAttribute("aria-pressed", "false");
  cullButton.title = "Hide the back of every face, as a game engine does: flipped faces vanish";
  cullButton.addEventListener("click", () => {
    cull = !cull;
    cullButton.setAttribute("aria-pressed", String(cull));
    if (meshes[1]) meshes[1].visible = !cull;
    stage.requestRender();
  });
  const reset = element("button", "tnm-button", "Reset view");
  reset.type = "button";
  reset.addEventListener("click", () => stage.reset());
  toolbar.append(reset, cullButton);

  const observer = new ResizeObserver(() => {
    updateResolution();
    stage.requestRender();
  });
  observer.observe(stageEl);
  const stopTheme = watchTheme((d) => {
    dark = d;
    applyColors();
  }, doc);
  model.on("change:mesh", draw);
  model.on("change:palette", applyColors);
  applyColors();
  draw();
  return () => {
    model.off("change:mesh", draw);
    model.off("change:palette", applyColors);
    observer.disconnect();
    stopTheme();
    clear();
    front.dispose();
    back.dispose();
    for (const m of Object.values(lineMaterials)) m.dispose();
    stage.dispose();
    root.remove();
  };
}

export default { render };
