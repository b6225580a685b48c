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
 * Speed (benchmarks/bench_mesh_view.py, 200 000 faces): the surface is one indexed mesh drawn in
 * one pass, its two sides coloured in the fragment shader (gl_FrontFacing), and a pick casts
 * the ray against a bounding volume hierarchy (three-mesh-bvh, built once per model, with the
 * faces kept in file order), not against every face.
 */
import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  FrontSide,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshLambertMaterial,
  Raycaster,
  Vector2,
  Vector3,
} from "three";
import { LineMaterial } from "three/addons/lines/LineMaterial.js";
import { LineSegments2 } from "three/addons/lines/LineSegments2.js";
import { LineSegmentsGeometry } from "three/addons/lines/LineSegmentsGeometry.js";
import { MeshBVH } from "three-mesh-bvh";
import { MeshoptSimplifier } from "meshoptimizer/simplifier";
import { createStage, DEFAULT_DIRECTION } from "../scene.js";
import { isDark, roleColor, surface, watchTheme } from "../theme.js";
import { touchGate } from "../touch.js";
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

/**
 * Up to this many faces to flip, each is outlined; above, only the rims of their patches (the
 * sides no other face to flip shares). An inside-out model has every face to flip: outlining
 * each of 200 000 faces drew 600 000 wide-line segments, seconds a frame on a software renderer,
 * and a picture all outline; its back colour already shows every face.
 */
const OUTLINE_EACH_UP_TO = 2000;

/**
 * Outlines of up to this many sides are drawn as wide lines at rest; more (the rims of a mesh
 * wound at random, say) as thin lines always: a software renderer draws each wide-line segment
 * as a draw of its own.
 */
const WIDE_SIDES_UP_TO = 6000;
/** While the camera turns, outlines of more sides than this are not drawn at all. */
const TURNING_SIDES_UP_TO = 30000;

/** The sides (3 * face + k) of the listed faces that no other listed face shares. */
function rimSides(faces, list, nVertices) {
  const first = new Map(); // an edge (either direction) -> the first side met on it, -1 once shared
  for (let i = 0; i < list.length; i++) {
    for (let k = 0; k < 3; k++) {
      const side = 3 * list[i] + k;
      const a = faces[side];
      const b = faces[3 * list[i] + ((k + 1) % 3)];
      const key = a < b ? a * nVertices + b : b * nVertices + a;
      first.set(key, first.has(key) ? -1 : side);
    }
  }
  return Int32Array.from([...first.values()].filter((side) => side >= 0)).sort();
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
/** At most this many vertices, spread over the model, frame the view (besides its extremes). */
const FRAMING_SAMPLE = 4096;

/**
 * The points the view keeps in sight: the vertices furthest along each axis and each diagonal
 * of the box, both ways, and an even sample of the rest (positions: x, y, z per vertex).
 */
function framingPoints(pos) {
  const n = pos.length / 3;
  const dirs = [];
  for (const sx of [-1, 0, 1]) for (const sy of [-1, 0, 1]) for (const sz of [-1, 0, 1]) if (sx || sy || sz) dirs.push([sx, sy, sz]);
  const best = dirs.map(() => [-Infinity, 0]);
  for (let i = 0; i < n; i++) {
    const x = pos[3 * i], y = pos[3 * i + 1], z = pos[3 * i + 2];
    for (let k = 0; k < dirs.length; k++) {
      const d = dirs[k];
      const along = d[0] * x + d[1] * y + d[2] * z;
      if (along > best[k][0]) best[k] = [along, i];
    }
  }
  const chosen = new Set(best.map((b) => b[1]));
  const step = Math.max(1, Math.ceil(n / FRAMING_SAMPLE));
  for (let i = 0; i < n; i += step) chosen.add(i);
  return [...chosen].map((i) => new Vector3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]));
}

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

/** A typed array over a binary buffer from the kernel (a DataView), copied if misaligned. */
function typed(Type, value) {
  if (!value) return new Type(0);
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) return value;
  const { buffer, byteOffset, byteLength } = value;
  if (byteOffset % Type.BYTES_PER_ELEMENT === 0) return new Type(buffer, byteOffset, byteLength / Type.BYTES_PER_ELEMENT);
  return new Type(buffer.slice(byteOffset, byteOffset + byteLength));
}

/** The mesh to draw: the host's "mesh" object (the site), or the kernel's buffers (Jupyter). */
function readMesh(model) {
  const mesh = model.get("mesh");
  if (mesh) return mesh;
  const positions = model.get("positions");
  if (!positions || !positions.byteLength) return null;
  return {
    positions: typed(Float64Array, positions),
    faces: typed(Uint32Array, model.get("faces")),
    flipped: typed(Int32Array, model.get("flipped")),
    boundary: typed(Int32Array, model.get("boundary")),
    non_manifold: typed(Int32Array, model.get("non_manifold")),
    arrow_faces: typed(Int32Array, model.get("arrow_faces")),
    arrow_normals: typed(Float32Array, model.get("arrow_normals")),
    vertex_normals: typed(Float32Array, model.get("vertex_normals")),
  };
}

/** Arrow segments (shaft and two barbs, 18 floats each) from points along unit directions. */
function arrowSegments(starts, dirs, length) {
  const n = starts.length / 3;
  const out = new Float32Array(18 * n);
  let w = 0;
  const d = new Vector3();
  const side = new Vector3();
  const up = new Vector3();
  for (let i = 0; i < n; i++) {
    d.set(dirs[3 * i], dirs[3 * i + 1], dirs[3 * i + 2]);
    if (!(d.lengthSq() > 0)) continue; // a degenerate face or a zero vertex normal: no arrow
    d.normalize();
    const x = starts[3 * i];
    const y = starts[3 * i + 1];
    const z = starts[3 * i + 2];
    const tx = x + d.x * length;
    const ty = y + d.y * length;
    const tz = z + d.z * length;
    up.set(Math.abs(d.z) < 0.9 ? 0 : 1, 0, Math.abs(d.z) < 0.9 ? 1 : 0);
    side.crossVectors(d, up).normalize().multiplyScalar(0.22 * length);
    const bx = tx - d.x * 0.35 * length;
    const by = ty - d.y * 0.35 * length;
    const bz = tz - d.z * 0.35 * length;
    out.set([x, y, z, tx, ty, tz, tx, ty, tz, bx + side.x, by + side.y, bz + side.z, tx, ty, tz, bx - side.x, by - side.y, bz - side.z], w);
    w += 18;
  }
  return out.subarray(0, w);
}

/** Every k-th index below n, so that at most `most` are taken. */
function sample(n, most) {
  const step = Math.max(1, Math.ceil(n / most));
  const out = new Int32Array(Math.ceil(n / step));
  for (let i = 0, j = 0; i < n; i += step, j++) out[j] = i;
  return out;
}

/** The median edge length of a sample of faces (display units): the arrows' length scale. */
function typicalEdge(pos, faces) {
  const picks = sample(faces.length / 3, 2000);
  const lengths = [];
  for (const f of picks) {
    const a = faces[3 * f];
    const b = faces[3 * f + 1];
    lengths.push(Math.hypot(pos[3 * a] - pos[3 * b], pos[3 * a + 1] - pos[3 * b + 1], pos[3 * a + 2] - pos[3 * b + 2]));
  }
  lengths.sort((p, q) => p - q);
  return lengths.length ? lengths[lengths.length >> 1] : 0.1;
}

/**
 * The surface's material: Lambert, both sides in one draw, the back side in its own colour
 * (gl_FrontFacing picks it per pixel). Drawing the model once instead of once per side halves
 * the vertex and triangle work of every frame. `side` becomes FrontSide to cull back faces.
 */
function twoSidedMaterial() {
  const material = new MeshLambertMaterial({ side: DoubleSide, flatShading: true, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  const backColor = { value: new Color() };
  material.onBeforeCompile = (shader) => {
    const line = "vec4 diffuseColor = vec4( diffuse, opacity );";
    if (!shader.fragmentShader.includes(line)) throw new Error("mesh view: three.js's Lambert shader changed");
    shader.uniforms.backDiffuse = backColor;
    shader.fragmentShader =
      "uniform vec3 backDiffuse;\n" + shader.fragmentShader.replace(line, "vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );");
  };
  material.customProgramCacheKey = () => "trinormal-two-sided";
  return { material, backColor: backColor.value };
}

/**
 * While the camera turns, a model of more than COARSE_ABOVE faces is drawn as a coarser copy of
 * about COARSE_FACES faces (meshoptimizer's simplify: edges collapsed where that changes the
 * shape least and turns no face over, so each side keeps its colour), and in full again as soon
 * as the pointer is released. On a software renderer the frame time grows with the faces
 * drawn, not the pixels (a 200 000-face model: about 130 ms a frame in full,
 * benchmarks/bench_mesh_view.py).
 */
const COARSE_ABOVE = 60000;
const COARSE_FACES = 30000;

/** The rows (3 floats) of `values` a compacted copy keeps: row i goes to row remap[i]. */
function keptRows(values, remap, unique) {
  const out = new Float32Array(3 * unique);
  for (let i = 0; i < remap.length; i++) {
    const j = remap[i];
    if (j === 0xffffffff) continue; // not used by the copy
    out[3 * j] = values[3 * i];
    out[3 * j + 1] = values[3 * i + 1];
    out[3 * j + 2] = values[3 * i + 2];
  }
  return out;
}

/** Most vertex-normal arrows drawn (a sample of the vertices on bigger models). */
const MAX_VERTEX_ARROWS = 1500;

let views = 0; // views made on this page: unique ids for their labels

function render({ model, el }) {
  const doc = el.ownerDocument || document;
  const canPick = model.get("picked") !== undefined; // the host answers a picked face
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
    "Drag to turn the model, scroll or pinch to zoom; on a touch screen, tap the view first, then drag; " +
      "from the keyboard, Tab to the view and use the arrow keys, + and −. " +
      "The side a face's normal points out of is drawn in the front colour; a face you see in the " +
      "back colour from outside is wound the other way." +
      (canPick ? " Click or tap a face, or type its number in the Face number box, to see its vertices, its exact normal and its area." : ""),
  );
  // the keyboard's way to pick a face: its number, or the faces to flip one after another
  const keys = element("form", "tnm-keys");
  keys.hidden = !canPick;
  const faceId = `tnm-face-${++views}`;
  const faceLabel = element("label", "tnm-face-label", "Face number");
  faceLabel.htmlFor = faceId;
  const faceInput = element("input", "tnm-face-input");
  Object.assign(faceInput, { id: faceId, type: "number", min: "0", step: "1", inputMode: "numeric", autocomplete: "off" });
  const showFace = element("button", "tnm-button", "Show face");
  showFace.type = "submit";
  const prevFlip = element("button", "tnm-button", "Previous face to flip");
  const nextFlip = element("button", "tnm-button", "Next face to flip");
  prevFlip.type = nextFlip.type = "button";
  keys.append(faceLabel, faceInput, showFace, prevFlip, nextFlip);
  const pickPanel = element("div", "tnm-pick");
  pickPanel.setAttribute("aria-live", "polite");
  pickPanel.setAttribute("aria-atomic", "true");
  pickPanel.hidden = true;
  root.append(toolbar, stageEl, legend, keys, pickPanel, hint);
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

  const { material: surfaceMaterial, backColor } = twoSidedMaterial();
  const lineMaterials = {
    flipped: new LineMaterial({ linewidth: 2.5 }),
    boundary: new LineMaterial({ linewidth: 4 }),
    non_manifold: new LineMaterial({ linewidth: 4 }),
  };
  let geometry = null;
  let meshes = [];
  let bvh = null; // the faces' bounding volume hierarchy, for picking: built once per model
  let bvhTimer = null; // cancels the BVH's scheduled build
  let coarse = null; // the coarser copy drawn while the camera turns (big models only)
  let turning = false; // the camera is turning: the coarser copy and thin outlines are drawn
  let lines = {};
  // the same outlines as plain 1-pixel lines, drawn instead while the camera turns: SwiftShader
  // draws an instanced wide line (LineSegments2) as one draw per segment, so 3 000 outlined
  // sides cost about 65 ms a frame there, and these about nothing
  const thinMaterials = { flipped: new LineBasicMaterial(), boundary: new LineBasicMaterial(), non_manifold: new LineBasicMaterial() };
  let thinLines = {};
  const arrowMaterials = { face: new LineBasicMaterial(), vertex: new LineBasicMaterial() };
  let arrows = {};
  let pickLine = null;
  const pickMaterial = new LineMaterial({ linewidth: 4 });
  const counts = { flipped: 0, boundary: 0, non_manifold: 0, face_arrows: 0, vertex_arrows: 0 };

  // The toggles: the model's keys when it has them (Jupyter), else state of this view (the site).
  const local = { cull: false, smooth: false, show_face_normals: true, show_vertex_normals: false };
  const flag = (key) => {
    const v = model.get(key);
    return v === undefined || v === null ? local[key] : Boolean(v);
  };
  function setFlag(key, value) {
    local[key] = value;
    if (model.get(key) === undefined || model.get(key) === null) applyFlags();
    else {
      model.set(key, value);
      model.save_changes();
    }
  }

  const palette = () => model.get("palette") || {};
  function applyColors() {
    const s = surface(dark);
    root.classList.toggle("tnm-dark", dark);
    stage.setBackground(s.background);
    surfaceMaterial.color = new Color(roleColor(palette(), "front", dark));
    backColor.set(roleColor(palette(), "back", dark));
    for (const [role, m] of Object.entries(lineMaterials)) m.color = new Color(roleColor(palette(), role, dark));
    for (const [role, m] of Object.entries(thinMaterials)) m.color = new Color(roleColor(palette(), role, dark));
    arrowMaterials.face.color = new Color(roleColor(palette(), "N", dark));
    arrowMaterials.vertex.color = new Color(s.text);
    pickMaterial.color = new Color(s.line);
    drawLegend();
    stage.requestRender();
  }

  const LEGEND = [
    ["front", "front of a face (its normal points out of this side)", "face"],
    ["back", "back of a face", "face"],
    ["flipped", "outline: a face to flip", "line"],
    ["boundary", "thick: an edge with one face (the rim of a hole)", "line"],
    ["non_manifold", "thick: an edge with three faces or more", "line"],
    ["face_arrows", "arrow from a face's centre: its unit normal", "arrow"],
    ["vertex_arrows", "arrow from a vertex: its vertex normal", "arrow"],
  ];
  function drawLegend() {
    legend.textContent = "";
    for (const [role, text, kind] of LEGEND) {
      if (kind === "line" && !counts[role]) continue;
      if (role === "face_arrows" && !(counts[role] && flag("show_face_normals"))) continue;
      if (role === "vertex_arrows" && !(counts[role] && flag("show_vertex_normals"))) continue;
      const item = element("li", "tnm-key");
      const swatch = element("span", "tnm-swatch tnm-swatch-" + (kind === "arrow" ? "line" : kind));
      const color = role === "face_arrows" ? roleColor(palette(), "N", dark) : role === "vertex_arrows" ? surface(dark).text : roleColor(palette(), role, dark);
      swatch.style.setProperty("--tnm-swatch", color);
      swatch.setAttribute("aria-hidden", "true");
      const rim = role === "flipped" && counts.flipped > OUTLINE_EACH_UP_TO;
      const count = rim ? ` (${counts[role]} faces)` : kind === "line" ? ` (${counts[role]})` : kind === "arrow" ? ` (${counts[role]} drawn)` : "";
      item.append(swatch, doc.createTextNode((rim ? "outline: the rim of each patch of faces to flip" : text) + count));
      legend.appendChild(item);
    }
  }

  function clear() {
    for (const m of meshes) scene.remove(m);
    for (const l of [...Object.values(lines), ...Object.values(thinLines)]) {
      scene.remove(l);
      l.geometry.dispose();
    }
    thinLines = {};
    turning = false;
    root.dataset.turning = "false";
    for (const a of Object.values(arrows)) {
      scene.remove(a);
      a.geometry.dispose();
    }
    if (geometry) geometry.dispose();
    if (coarse) {
      scene.remove(coarse);
      coarse.geometry.dispose();
      coarse = null;
    }
    if (bvhTimer) bvhTimer();
    bvh = bvhTimer = null;
    meshes = [];
    lines = {};
    arrows = {};
    geometry = null;
    clearPick();
  }

  function clearPick() {
    if (pickLine) {
      scene.remove(pickLine);
      pickLine.geometry.dispose();
      pickLine = null;
    }
  }

  let current = null; // { data, pos }: what is drawn
  function drawArrows(data, pos) {
    const length = 0.5 * typicalEdge(pos, data.faces);
    const af = data.arrow_faces || new Int32Array(0);
    const an = data.arrow_normals || new Float32Array(0);
    if (af.length && an.length === 3 * af.length) {
      const starts = new Float32Array(3 * af.length);
      for (let i = 0; i < af.length; i++) {
        for (let c = 0; c < 3; c++) {
          const v = data.faces[3 * af[i] + c];
          for (let k = 0; k < 3; k++) starts[3 * i + k] += pos[3 * v + k] / 3;
        }
      }
      arrows.face = arrowLines(arrowSegments(starts, an, length), arrowMaterials.face);
    }
    const vn = data.vertex_normals;
    if (vn && vn.length === pos.length) {
      const picks = sample(pos.length / 3, MAX_VERTEX_ARROWS);
      const starts = new Float32Array(3 * picks.length);
      const dirs = new Float32Array(3 * picks.length);
      picks.forEach((v, i) => {
        for (let k = 0; k < 3; k++) {
          starts[3 * i + k] = pos[3 * v + k];
          dirs[3 * i + k] = vn[3 * v + k];
        }
      });
      arrows.vertex = arrowLines(arrowSegments(starts, dirs, length), arrowMaterials.vertex);
    }
    counts.face_arrows = arrows.face ? arrows.face.geometry.getAttribute("position").count / 6 : 0;
    counts.vertex_arrows = arrows.vertex ? arrows.vertex.geometry.getAttribute("position").count / 6 : 0;
  }

  function arrowLines(segments, material) {
    const g = new BufferGeometry();
    g.setAttribute("position", new BufferAttribute(segments, 3));
    const l = new LineSegments(g, material);
    l.renderOrder = 2;
    scene.add(l);
    return l;
  }

  function applyFlags() {
    const cull = flag("cull");
    const smooth = flag("smooth");
    const side = cull ? FrontSide : DoubleSide;
    if (smooth && geometry && !geometry.getAttribute("normal")) geometry.computeVertexNormals();
    if (surfaceMaterial.side !== side || surfaceMaterial.flatShading === smooth) {
      surfaceMaterial.side = side;
      surfaceMaterial.flatShading = !smooth;
      surfaceMaterial.needsUpdate = true;
    }
    if (arrows.face) arrows.face.visible = flag("show_face_normals");
    if (arrows.vertex) arrows.vertex.visible = flag("show_vertex_normals");
    for (const [key, b] of Object.entries(buttons)) b.setAttribute("aria-pressed", String(flag(key)));
    faceButton.hidden = !arrows.face;
    vertexButton.hidden = !arrows.vertex;
    const faces = current ? current.data.faces.length / 3 : 0;
    keys.hidden = !canPick || !faces;
    faceLabel.textContent = faces ? `Face number (0 to ${faces - 1})` : "Face number";
    prevFlip.hidden = nextFlip.hidden = !(current && current.data.flipped && current.data.flipped.length);
    drawLegend();
    stage.requestRender();
  }

  function draw() {
    clear();
    const data = readMesh(model);
    current = null;
    if (!data || !data.positions || !data.faces) {
      counts.face_arrows = counts.vertex_arrows = 0;
      applyFlags();
      return;
    }
    const { offset, scale } = framing(data.positions);
    const pos = new Float32Array(data.positions.length);
    for (let i = 0; i < pos.length; i++) pos[i] = (data.positions[i] - offset[i % 3]) * scale;
    geometry = new BufferGeometry();
    geometry.setAttribute("position", new BufferAttribute(pos, 3));
    geometry.setIndex(new BufferAttribute(data.faces, 1));
    if (data.vertex_normals && data.vertex_normals.length === pos.length) {
      geometry.setAttribute("normal", new BufferAttribute(data.vertex_normals, 3));
    } // else three.js's own, made when smooth shading is first asked for (flat shading needs none)
    geometry.computeBoundingSphere();
    meshes = [new Mesh(geometry, surfaceMaterial)];
    scene.add(...meshes);
    // the picking structure, built when the page is next idle after the first picture (or at
    // the first pick, if that comes sooner)
    const idle = globalThis.requestIdleCallback || ((cb) => setTimeout(cb, 200));
    const cancelIdle = globalThis.cancelIdleCallback || clearTimeout;
    const id = idle(() => {
      bvhTimer = null;
      faceTree();
    }, { timeout: 3000 });
    bvhTimer = () => cancelIdle(id);
    const sets = {
      flipped: !data.flipped
        ? new Int32Array(0)
        : data.flipped.length > OUTLINE_EACH_UP_TO
          ? rimSides(data.faces, data.flipped, pos.length / 3)
          : allSides(data.flipped),
      boundary: data.boundary || new Int32Array(0),
      non_manifold: data.non_manifold || new Int32Array(0),
    };
    root.dataset.flippedSides = String(sets.flipped.length); // the sides outlined
    const zero = [0, 0, 0];
    for (const [role, sides] of Object.entries(sets)) {
      counts[role] = role === "flipped" ? (data.flipped ? data.flipped.length : 0) : sides.length;
      if (!sides.length) continue;
      const segments = sideSegments(pos, data.faces, sides, 1, zero);
      const thin = new BufferGeometry();
      thin.setAttribute("position", new BufferAttribute(segments, 3));
      const t = new LineSegments(thin, thinMaterials[role]);
      t.renderOrder = 1;
      t.userData.sides = sides.length;
      thinLines[role] = t;
      scene.add(t);
      if (sides.length > WIDE_SIDES_UP_TO) continue; // thin lines only, also at rest
      const g = new LineSegmentsGeometry();
      g.setPositions(segments);
      const l = new LineSegments2(g, lineMaterials[role]);
      l.renderOrder = 1;
      lines[role] = l;
      scene.add(l);
    }
    showOutlines();
    // keep the model in view, looking from where the trouble is: framed on its own vertices
    // (a sample and the extremes), not on its box, whose corners lie far outside a round model
    stage.framePoints(framingPoints(pos), true, startDirection(pos, data.faces, sets));
    if (data.faces.length / 3 > COARSE_ABOVE) buildCoarse(geometry, data.faces, pos);
    drawArrows(data, pos);
    current = { data, pos, offset, scale };
    updateResolution();
    applyFlags();
    root.dataset.faces = String(data.faces.length / 3);
    showPick();
  }

  /** The coarser copy of a big model, drawn while the camera turns (see COARSE_ABOVE). */
  function buildCoarse(full, faces, pos) {
    MeshoptSimplifier.ready.then(() => {
      if (geometry !== full || !MeshoptSimplifier.supported) return; // another model by now
      const index = new Uint32Array(faces.buffer, faces.byteOffset, faces.length);
      // simplify first: it refuses a collapse that turns a face over, so each side keeps its
      // colour (simplifySloppy's grid merging left specks of the wrong colour); 120 ms for
      // 200 000 faces. On a model wound every which way nearly every collapse turns a face over
      // (a torus with every other face reversed kept 160 000 of 200 000): there the colours are
      // speckled anyway, and the sloppy copy is taken
      let [kept] = MeshoptSimplifier.simplify(index, pos, 3, 3 * COARSE_FACES, 1);
      if (kept.length > 6 * COARSE_FACES) [kept] = MeshoptSimplifier.simplifySloppy(index, pos, 3, null, 3 * COARSE_FACES, 1);
      if (!kept.length) return;
      // only the vertices the copy uses (fewer vertices to transform every frame)
      const [remap, unique] = MeshoptSimplifier.compactMesh(kept);
      const g = new BufferGeometry();
      g.setAttribute("position", new BufferAttribute(keptRows(full.getAttribute("position").array, remap, unique), 3));
      g.setIndex(new BufferAttribute(kept, 1));
      g.boundingSphere = full.boundingSphere;
      coarse = new Mesh(g, surfaceMaterial);
      coarse.userData = { remap, unique, normal: null };
      coarse.visible = false;
      scene.add(coarse);
      root.dataset.coarseFaces = String(kept.length / 3);
    });
  }

  /** At rest the wide outlines (thin where there are none); while turning thin ones, if not too many. */
  function showOutlines() {
    for (const [role, t] of Object.entries(thinLines)) {
      if (lines[role]) lines[role].visible = !turning;
      t.visible = turning ? t.userData.sides <= TURNING_SIDES_UP_TO : !lines[role];
    }
  }

  /** While the camera turns: the coarser copy (if any) and thin outlines; else the model itself. */
  function showTurning(on) {
    if (!geometry || turning === on) return;
    turning = on;
    showOutlines();
    root.dataset.turning = String(on);
    stage.requestRender();
    if (!coarse) return;
    const normal = geometry.getAttribute("normal"); // smooth shading: the model's own normals
    const own = coarse.userData;
    if (normal && own.normal !== normal) {
      own.normal = normal;
      coarse.geometry.setAttribute("normal", new BufferAttribute(keptRows(normal.array, own.remap, own.unique), 3));
    }
    coarse.visible = on;
    for (const m of meshes) m.visible = !on;
  }
  let held = false; // the pointer is down on the view (OrbitControls' start .. end)
  stage.controls.addEventListener("start", () => {
    held = true;
  });
  stage.controls.addEventListener("change", () => {
    if (held) showTurning(true); // only once the camera actually moves: a click to pick stays full
  });
  stage.controls.addEventListener("end", () => {
    held = false;
    showTurning(false);
  });

  // ------------------------------------------------------------------ picking a face
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  let down = null;
  /** The faces' BVH; `indirect` keeps the index buffer (so face numbers) as the file has them. */
  function faceTree() {
    // leaves of ~32 faces: a build ~40 % faster than the default 10, a pick still well under 1 ms
    if (!bvh && geometry) bvh = new MeshBVH(geometry, { indirect: true, targetLeafSize: 32 });
    return bvh;
  }
  function facePicked(clientX, clientY) {
    if (!meshes.length || !faceTree()) return -1;
    const rect = stage.canvas.getBoundingClientRect();
    ndc.set(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, stage.camera);
    // the mesh is drawn untransformed: the world ray is the model's ray
    const hit = bvh.raycastFirst(raycaster.ray, flag("cull") ? FrontSide : DoubleSide);
    if (!hit) return -1;
    // where the ray met the face, in the model's own coordinates (the tests check it is on it)
    const { offset, scale } = current;
    root.dataset.pickPoint = hit.point.toArray().map((x, k) => x / scale + offset[k]).join(",");
    return hit.faceIndex;
  }
  function onDown(event) {
    down = event.button === 0 ? [event.clientX, event.clientY] : null;
  }
  function pick(face) {
    model.set("picked", face);
    model.save_changes();
    showPick();
  }
  function onUp(event) {
    if (!down || Math.hypot(event.clientX - down[0], event.clientY - down[1]) > 4) return;
    down = null;
    if (!canPick) return;
    const face = facePicked(event.clientX, event.clientY);
    if (face >= 0) pick(face);
  }
  stage.canvas.addEventListener("pointerdown", onDown);
  stage.canvas.addEventListener("pointerup", onUp);
  // the keyboard turns the model too: arrow keys turn it, + and − zoom, Home resets
  stageEl.tabIndex = 0;
  stageEl.setAttribute("role", "img");
  stageEl.setAttribute("aria-label", "The model in 3D. Arrow keys turn it, + and − zoom, Home resets the view.");
  stageEl.addEventListener("keydown", (event) => {
    const step = (event.shiftKey ? 45 : 15) * (Math.PI / 180);
    const keys = {
      ArrowLeft: () => stage.turn(-step, 0),
      ArrowRight: () => stage.turn(step, 0),
      ArrowUp: () => stage.turn(0, step),
      ArrowDown: () => stage.turn(0, -step),
      "+": () => stage.zoom(0.8),
      "=": () => stage.zoom(0.8),
      "-": () => stage.zoom(1.25),
      Home: () => stage.reset(),
    };
    const act = keys[event.key];
    if (!act || event.altKey || event.ctrlKey || event.metaKey) return;
    event.preventDefault(); // the page does not scroll
    act();
  });
  // a finger scrolls the page over the view until a tap turns it on (a tap also picks)
  const touch = touchGate({ root, stageEl, controls: stage.controls, canvas: stage.canvas, activeClass: "tnm-touch-active" });
  function pickTyped() {
    const text = faceInput.value.trim();
    if (!text || !faceInput.checkValidity()) {
      faceInput.reportValidity();
      return;
    }
    pick(Number(text)); // a face that does not exist gets the host's message
  }
  keys.addEventListener("submit", (event) => {
    event.preventDefault();
    pickTyped();
  });
  // Enter in the box, handled here: JupyterLab's notebook swallows the form's own submission
  faceInput.addEventListener("keydown", (event) => {
    if (event.key !== "Enter") return;
    event.preventDefault();
    pickTyped();
  });
  /** The next (step 1) or previous (-1) face to flip from the one picked, round the list. */
  function stepFlipped(step) {
    const list = current ? current.data.flipped : null;
    if (!list || !list.length) return;
    const at = model.get("picked");
    let i = step > 0 ? list.findIndex((f) => f > at) : list.findLastIndex((f) => f < at);
    if (i < 0) i = step > 0 ? 0 : list.length - 1;
    faceInput.value = String(list[i]);
    pick(list[i]);
  }
  prevFlip.addEventListener("click", () => stepFlipped(-1));
  nextFlip.addEventListener("click", () => stepFlipped(1));

  /** Outline the picked face and show the kernel's answer for it. */
  function showPick() {
    clearPick();
    const face = model.get("picked");
    if (current && Number.isInteger(face) && face >= 0 && face < current.data.faces.length / 3) {
      const g = new LineSegmentsGeometry();
      g.setPositions(sideSegments(current.pos, current.data.faces, allSides([face]), 1, [0, 0, 0]));
      pickLine = new LineSegments2(g, pickMaterial);
      pickLine.renderOrder = 3;
      scene.add(pickLine);
      root.dataset.picked = String(face);
      if (doc.activeElement !== faceInput) faceInput.value = String(face);
    } else {
      delete root.dataset.picked;
    }
    const sel = model.get("selection");
    pickPanel.textContent = "";
    pickPanel.hidden = !(sel && sel.rows && sel.rows.length);
    if (!pickPanel.hidden) {
      pickPanel.appendChild(element("p", "tnm-pick-title", sel.title || ""));
      const list = element("dl", "tnm-pick-rows");
      for (const [label, value] of sel.rows) list.append(element("dt", "", label), element("dd", "", value));
      pickPanel.appendChild(list);
    }
    stage.requestRender();
  }

  function updateResolution() {
    const { width, height } = stage.size();
    for (const m of Object.values(lineMaterials)) m.resolution.set(width, height);
    pickMaterial.resolution.set(width, height);
  }

  function toggle(key, text, title) {
    const b = element("button", "tnm-button", text);
    b.type = "button";
    b.setAttribute("aria-pressed", "false");
    b.title = title;
    b.addEventListener("click", () => setFlag(key, !flag(key)));
    return b;
  }
  const buttons = {
    cull: toggle("cull", "Cull back faces", "Hide the back of every face, as a game engine does: flipped faces vanish"),
    smooth: toggle("smooth", "Smooth shading", "Light each face with its corners' vertex normals blended, instead of one normal per face"),
    show_face_normals: toggle("show_face_normals", "Face normals", "Show each face's unit normal as an arrow from its centre"),
    show_vertex_normals: toggle("show_vertex_normals", "Vertex normals", "Show the vertex normals as arrows from the vertices"),
  };
  const faceButton = buttons.show_face_normals;
  const vertexButton = buttons.show_vertex_normals;
  faceButton.hidden = vertexButton.hidden = true;
  const reset = element("button", "tnm-button", "Reset view");
  reset.type = "button";
  reset.addEventListener("click", () => stage.reset());
  toolbar.append(reset, ...Object.values(buttons));

  const observer = new ResizeObserver(() => {
    updateResolution();
    stage.requestRender();
  });
  observer.observe(stageEl);
  const stopTheme = watchTheme((d) => {
    dark = d;
    applyColors();
  }, doc);
  const events = [
    ["change:mesh", draw],
    ["change:revision", draw],
    ["change:palette", applyColors],
    ["change:picked", showPick],
    ["change:selection", showPick],
    ...Object.keys(local).map((key) => ["change:" + key, applyFlags]),
  ];
  for (const [event, cb] of events) model.on(event, cb);
  applyColors();
  draw();
  return () => {
    for (const [event, cb] of events) model.off(event, cb);
    stage.canvas.removeEventListener("pointerdown", onDown);
    stage.canvas.removeEventListener("pointerup", onUp);
    touch.dispose();
    observer.disconnect();
    stopTheme();
    clear();
    surfaceMaterial.dispose();
    for (const m of [...Object.values(lineMaterials), ...Object.values(thinMaterials)]) m.dispose();
    for (const m of Object.values(arrowMaterials)) m.dispose();
    pickMaterial.dispose();
    stage.dispose();
    root.remove();
  };
}

export default { render };
