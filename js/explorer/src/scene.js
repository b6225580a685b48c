/*
 * The stage: renderer, camera (z up), orbit controls, resizing and rendering on demand.
 */
import { Color, PerspectiveCamera, Scene, Vector3, WebGLRenderer } from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

export const DEFAULT_DIRECTION = new Vector3(1.0, 0.75, 0.65).normalize();
const FOV = 40;
const UP = new Vector3(0, 0, 1);
// px kept free at each side of the view beyond the framed points: a vertex label sits 30 px
// beyond its point and is about 34 px wide
export const LABEL_MARGIN = 44;

/**
 * True when WebGL runs on the CPU (SwiftShader, llvmpipe: no usable GPU). Multisampling then
 * costs more than it gives, so the view turns it off and keeps its frame rate.
 */
function softwareRendering() {
  try {
    const gl = document.createElement("canvas").getContext("webgl2");
    if (!gl) return false;
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
    gl.getExtension("WEBGL_lose_context")?.loseContext();
    return /swiftshader|llvmpipe|softpipe|software/i.test(name);
  } catch (err) {
    return false;
  }
}

/** The camera's axes looking from `direction` (z towards the camera, x to the right, y up). */
function basis(up, direction) {
  const z = direction.clone().normalize();
  const x = new Vector3().crossVectors(up, z);
  if (x.lengthSq() < 1e-12) x.set(1, 0, 0);
  x.normalize();
  return { x, y: new Vector3().crossVectors(z, x), z };
}

/** The direction the camera can look from (straight above or below: tilted a hair, so "up" stays z). */
function usable(direction) {
  const d = direction.clone().normalize();
  if (Math.abs(d.z) > 0.999) d.set(0, -1e-3, Math.sign(d.z)).normalize();
  return d;
}

/**
 * The centre of the points' axis-aligned box and half its diagonal (at least 1e-3, so a
 * single point still has a size to frame): what the camera is fitted around.
 */
export function boundingSphere(points) {
  const lo = points[0].clone();
  const hi = points[0].clone();
  for (const p of points) {
    lo.min(p);
    hi.max(p);
  }
  return { center: lo.clone().add(hi).multiplyScalar(0.5), radius: Math.max(hi.distanceTo(lo) / 2, 1e-3) };
}

/**
 * Where the camera looks from `direction` (a z-up perspective camera of FOV degrees) so that
 * every one of `points` (display units) projects inside a view of `width` x `height` px with
 * `margin` px to spare on each side (LABEL_MARGIN: for the labels beyond the points and the
 * arrow heads): { target, distance, direction }. The target centres the points' picture, not just
 * their box; the distance is exact for the perspective camera. A pure function of its inputs.
 */
export function fitCamera(points, direction, { width, height }, margin = LABEL_MARGIN) {
  const d = usable(direction);
  const { x, y, z } = basis(UP, d);
  const { center, radius } = boundingSphere(points);
  const xs = points.map((p) => p.clone().sub(center).dot(x));
  const ys = points.map((p) => p.clone().sub(center).dot(y));
  const target = center
    .clone()
    .addScaledVector(x, (Math.min(...xs) + Math.max(...xs)) / 2)
    .addScaledVector(y, (Math.min(...ys) + Math.max(...ys)) / 2);
  const w = Math.max(width, 1);
  const h = Math.max(height, 1);
  const tanV = Math.tan(((FOV / 2) * Math.PI) / 180);
  const tanH = (tanV * w) / h;
  const sx = Math.max(0.4, 1 - (2 * margin) / w);
  const sy = Math.max(0.4, 1 - (2 * margin) / h);
  let distance = 1e-6;
  for (const p of points) {
    const q = p.clone().sub(target);
    const depth = q.dot(z);
    distance = Math.max(distance, depth + Math.abs(q.dot(x)) / (tanH * sx), depth + Math.abs(q.dot(y)) / (tanV * sy));
  }
  // never so close that a point is near the camera
  return { target, distance: Math.max(distance * 1.02, radius * 1.2), direction: d };
}

/** The size of one screen pixel, in display units, at `depth` in front of the camera. */
export function pixelAt(depth, height) {
  return (2 * Math.tan(((FOV / 2) * Math.PI) / 180) * depth) / Math.max(height, 1);
}

/** Where `point` (display units) is in the camera's picture of `width` x `height` px: { x, y, z } (z beyond ±1: not in front). */
export function toScreen(point, camera, width, height) {
  const q = point.clone().project(camera);
  return { x: ((q.x + 1) / 2) * width, y: ((1 - q.y) / 2) * height, z: q.z };
}

/**
 * Turn the camera about the controls' target, as a drag does: `around` radians about the up
 * axis (z), `over` radians towards it (stopping short of straight above or below).
 */
function turnCamera(camera, controls, around, over) {
  const offset = camera.position.clone().sub(controls.target);
  const r = offset.length();
  const azimuth = Math.atan2(offset.y, offset.x) + around;
  const limit = Math.PI / 2 - 0.01;
  const elevation = Math.max(-limit, Math.min(limit, Math.asin(Math.max(-1, Math.min(1, offset.z / r))) + over));
  offset.set(Math.cos(elevation) * Math.cos(azimuth), Math.cos(elevation) * Math.sin(azimuth), Math.sin(elevation)).multiplyScalar(r);
  camera.position.copy(controls.target).add(offset);
}

/** Move the camera `factor` times its distance from the controls' target (below 1: closer). */
function zoomCamera(camera, controls, factor) {
  const offset = camera.position.clone().sub(controls.target).multiplyScalar(factor);
  const r = Math.min(Math.max(offset.length(), camera.near * 2), camera.far / 2);
  camera.position.copy(controls.target).addScaledVector(offset.normalize(), r);
}

/**
 * How `points` (display units) sit in the camera's picture of `width` x `height` px: inside
 * (every point in front of the camera and at least half LABEL_MARGIN from each side) and fill
 * (their spread over the room LABEL_MARGIN leaves, 1 when framed exactly).
 */
function spreadInView(camera, points, width, height) {
  camera.updateMatrixWorld();
  const m = LABEL_MARGIN / 2;
  const q = points.map((p) => toScreen(p, camera, width, height));
  const xs = q.map((s) => s.x);
  const ys = q.map((s) => s.y);
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const inside = q.every((s) => s.z < 1) && x0 >= m && y0 >= m && x1 <= width - m && y1 <= height - m;
  const room = [Math.max(width - 2 * LABEL_MARGIN, 1), Math.max(height - 2 * LABEL_MARGIN, 1)];
  return { inside, fill: Math.max((x1 - x0) / room[0], (y1 - y0) / room[1]) };
}

/** The renderer, its canvas in `container`, the scene, the camera (z up) and the orbit controls. */
function createParts(container) {
  const renderer = new WebGLRenderer({ antialias: !softwareRendering() });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  const canvas = renderer.domElement;
  canvas.className = "tnx-canvas";
  container.appendChild(canvas);

  const scene = new Scene();
  const camera = new PerspectiveCamera(FOV, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  camera.position.copy(DEFAULT_DIRECTION).multiplyScalar(6);

  const controls = new OrbitControls(camera, canvas);
  controls.enableDamping = false;
  controls.zoomToCursor = false;
  return { renderer, canvas, scene, camera, controls };
}

/**
 * The camera's projection for the view's size: with an inset (`free` px covered at the right,
 * by the readout in full screen) the picture's centre moves into the part left free, at the
 * same scale (a view offset of a camera as wide as the view and the inset together).
 */
function projectCamera(camera, width, height, free) {
  camera.aspect = (width + free) / height;
  if (free) camera.setViewOffset(width + free, height, free, 0, width, height);
  else camera.clearViewOffset();
  camera.updateProjectionMatrix();
}

/**
 * The stage in `container`; `onRender` runs before each picture is drawn. It renders on
 * demand (requestRender), keeps a home framing (framePoints, reset, along) and follows the
 * container's size.
 */
export function createStage(container, { onRender, margin = LABEL_MARGIN }) {
  const { renderer, canvas, scene, camera, controls } = createParts(container);
  let frame = 0;
  let width = 1;
  let height = 1;
  let inset = 0; // px at the right of the view that the picture keeps free (setInset)
  // where the camera goes home to: the points it keeps in view (display units), the direction
  // it looks from now and the one "Reset view" looks from
  const home = { points: [new Vector3()], direction: DEFAULT_DIRECTION.clone(), start: DEFAULT_DIRECTION.clone() };
  let atHome = true; // the camera is where reset or a view button put it (the user has not moved it)

  function draw() {
    frame = 0;
    onRender();
    renderer.render(scene, camera);
  }

  function requestRender() {
    if (!frame) frame = requestAnimationFrame(draw);
  }

  /** Draw at once (from inside an animation frame, so the picture is in this frame). */
  function renderNow() {
    if (frame) cancelAnimationFrame(frame);
    draw();
  }

  /** The inset as the view's size allows it (at most half the view). */
  function freeInset() {
    return Math.min(inset, Math.floor(width / 2));
  }

  /** Keep `px` at the right of the view free (the readout over it in full screen), and frame again. */
  function setInset(px) {
    const next = Math.max(0, Math.round(px));
    if (next === inset) return;
    inset = next;
    refit();
  }

  /** After a new size or inset: project again, and frame home again while the camera is there. */
  function refit() {
    projectCamera(camera, width, height, freeInset());
    if (atHome) look(home.direction);
    requestRender();
  }

  function resize() {
    const w = Math.max(1, Math.round(container.clientWidth));
    const h = Math.max(1, Math.round(container.clientHeight));
    if (w === width && h === height) return;
    width = w;
    height = h;
    renderer.setSize(w, h, false);
    refit();
  }

  const observer = new ResizeObserver(resize);
  observer.observe(container);
  controls.addEventListener("change", requestRender);
  controls.addEventListener("start", () => {
    atHome = false;
  });

  /**
   * Remember a framing (the points to keep in view) as home. go: true moves the camera there
   * along the start direction, "keep" along its current direction, false leaves it.
   */
  function framePoints(points, go = true, start = null) {
    if (start) home.start.copy(start);
    home.points = points.map((p) => p.clone());
    if (go === "keep") look(camera.position.clone().sub(controls.target));
    else if (go) look(home.start);
  }

  /** Look at home's centre from a direction (unit vector), at home's distance. */
  function look(direction) {
    home.direction.copy(direction);
    atHome = true;
    const { target, distance, direction: d } = fitCamera(home.points, direction, { width: width - freeInset(), height }, margin);
    camera.near = distance / 200;
    camera.far = distance * 50;
    camera.updateProjectionMatrix();
    controls.target.copy(target);
    camera.position.copy(target).addScaledVector(d, distance);
    camera.lookAt(target);
    controls.update();
    requestRender();
  }

  /** Move the camera by hand (a key), as the user: it is no longer at home. */
  function moveBy(move) {
    move();
    atHome = false;
    controls.update();
  }

  return {
    renderer,
    canvas,
    scene,
    camera,
    controls,
    requestRender,
    renderNow,
    resize,
    framePoints,
    /** How points (display units) sit in the picture: { inside, fill } (see spreadInView). */
    spread: (points) => spreadInView(camera, points, width - freeInset(), height),
    setInset,
    /** Where the camera looks from (a unit vector from the target towards the camera). */
    direction: () => camera.position.clone().sub(controls.target).normalize(),
    /** The size of one screen pixel, in display units, at `point` (display units). */
    pixelAt: (point) => {
      const forward = controls.target.clone().sub(camera.position).normalize();
      return pixelAt(Math.max(point.clone().sub(camera.position).dot(forward), camera.near), height);
    },
    reset: () => look(home.start),
    /** Turn about the target: `around` radians about z, `over` towards it. For the keyboard. */
    turn: (around, over) => moveBy(() => turnCamera(camera, controls, around, over)),
    /** Move `factor` times the distance from the target (below 1: closer). For the keyboard. */
    zoom: (factor) => moveBy(() => zoomCamera(camera, controls, factor)),
    atHome: () => atHome,
    // along x: y to the right; along y: x to the right; along z: from above, x right, y up
    along: (axis) => look(new Vector3(axis === "x" ? 1 : 0, axis === "y" ? -1 : 0, axis === "z" ? 1 : 0)),
    setBackground: (color) => {
      scene.background = new Color(color);
      requestRender();
    },
    size: () => ({ width, height }),
    dispose() {
      if (frame) cancelAnimationFrame(frame);
      observer.disconnect();
      controls.dispose();
      renderer.dispose();
      renderer.forceContextLoss?.();
      canvas.remove();
    },
  };
}
