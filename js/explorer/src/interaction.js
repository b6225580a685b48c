/*
 * Moving a vertex: by dragging its label or its point (in the plane through it that faces
 * the camera), or with the keyboard on its focused label. Values are snapped to the grid
 * (`step`) and clamped to `bounds`. What is written names only the coordinates the user
 * moved ({ ax: "0.3", az: "-1.2" }): an axis the user did not move is not written at all,
 * so it keeps its exact text, and an edit made meanwhile elsewhere (another view of the
 * same explorer) to another coordinate of the vertex stands.
 * Dragging anywhere else is left to the orbit controls.
 */
import { Plane, Raycaster, Vector2, Vector3 } from "three";
import { listen } from "./dom.js";
import { gridIndex, gridText, onGridAt, parseCoordinate } from "./numbers.js";
import { toScreen } from "./scene.js";

const PICK_PX = 22;

/** The key of a vertex's coordinate in an edit: ("A", 1) -> "ay". */
const coordinateKey = (name, axis) => name.toLowerCase() + "xyz"[axis];
const KEYS = {
  ArrowRight: [0, 1],
  ArrowLeft: [0, -1],
  ArrowUp: [1, 1],
  ArrowDown: [1, -1],
  PageUp: [2, 1],
  PageDown: [2, -1],
};

/** The vertex whose point is within PICK_PX of the pointer, nearest first (null: none). */
function pick(view, clientX, clientY) {
  const rect = view.canvas.getBoundingClientRect();
  let best = null;
  let bestD = PICK_PX;
  for (const name of "ABC") {
    const p = view.position(name);
    if (!p) continue;
    const q = toScreen(p, view.camera, rect.width, rect.height);
    const d = Math.hypot(rect.left + q.x - clientX, rect.top + q.y - clientY);
    if (d < bestD) [best, bestD] = [name, d];
  }
  return best;
}

/**
 * What a drag moved by `delta` (data units) writes: the axes it has moved (drag.moved, which
 * this adds to), each snapped to the grid and clamped to the bounds, where they differ from
 * the values `now`.
 */
function dragChanges(drag, delta, grid, bounds, now) {
  const changes = {};
  drag.strings.forEach((s, i) => {
    let next = s; // not moved along this axis (or clamped back to where it was): its exact text
    const d = delta.getComponent(i);
    if (Math.abs(d) >= grid.value / 2) {
      const k = gridIndex(drag.start[i] + d, grid, bounds);
      if (!onGridAt(drag.start[i], k, grid)) next = gridText(k, grid);
    }
    if (next !== s) drag.moved.add(i);
    // an axis the drag moved is written, also back to its first text; no other axis is
    if (drag.moved.has(i) && next !== now[i]) changes[coordinateKey(drag.name, i)] = next;
  });
  return changes;
}

/** What an arrow or page key on vertex `name` writes (one grid step along its axis), or null. */
function keyChange(view, name, key) {
  const [axis, sign] = KEYS[key];
  const now = view.values(name)[axis];
  const grid = view.grid();
  let x = parseCoordinate(now);
  if (!Number.isFinite(x)) x = (view.position(name)?.getComponent(axis) ?? 0) * view.scale();
  const k = gridIndex(x + sign * grid.value, grid, view.bounds());
  if (onGridAt(x, k, grid)) return null; // at the edge of the range: nothing moves, nothing is written
  const text = gridText(k, grid);
  return text !== now ? { [coordinateKey(name, axis)]: text } : null;
}

/**
 * view: { container, canvas, camera, size(), scale(), grid(), bounds(), values(name),
 *         position(name) -> display Vector3, write(changes), dragging(bool),
 *         touchActive() -> bool }
 * `changes` maps coordinate keys ("ax" … "cz") to their new text.
 * Returns a cleanup function; its .cancel() ends a drag in progress without writing.
 */
export function setupInteraction(view) {
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  const plane = new Plane();
  let drag = null;
  let pending = null;
  let frame = 0;

  /** Where the ray through a point of the screen meets the drag's plane (null: it does not). */
  function hitPlane(clientX, clientY) {
    const rect = view.canvas.getBoundingClientRect();
    ndc.set(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, view.camera);
    return raycaster.ray.intersectPlane(plane, new Vector3());
  }

  function start(name, event) {
    const origin = view.position(name);
    if (!origin) return false;
    const normal = view.camera.getWorldDirection(new Vector3());
    plane.setFromNormalAndCoplanarPoint(normal, origin);
    const hit = hitPlane(event.clientX, event.clientY);
    if (!hit) return false;
    const strings = view.values(name).slice();
    drag = {
      name,
      pointerId: event.pointerId,
      hit,
      strings,
      moved: new Set(), // the axes this drag has moved: only they are written
      start: strings.map((s, i) => {
        const x = parseCoordinate(s);
        return Number.isFinite(x) ? x : origin.getComponent(i) * view.scale();
      }),
    };
    view.container.setPointerCapture(event.pointerId);
    view.container.classList.add("tnx-dragging");
    view.dragging(true, name);
    return true;
  }

  function apply() {
    frame = 0;
    if (!drag || !pending) return;
    const hit = hitPlane(pending.clientX, pending.clientY);
    pending = null;
    if (!hit) return;
    const delta = hit.sub(drag.hit).multiplyScalar(view.scale());
    const changes = dragChanges(drag, delta, view.grid(), view.bounds(), view.values(drag.name));
    if (Object.keys(changes).length) view.write(changes);
  }

  function onPointerDown(event) {
    if (drag || event.button > 0) return;
    // a finger on an inactive view scrolls the page (see index.js: a tap activates the view)
    if (event.pointerType === "touch" && view.touchActive && !view.touchActive()) return;
    const target = event.target.closest?.("[data-vertex]");
    const name = target ? target.dataset.vertex : event.target === view.canvas ? pick(view, event.clientX, event.clientY) : null;
    if (!name) return;
    if (start(name, event)) {
      event.preventDefault();
      event.stopPropagation(); // the orbit controls do not see this press
      if (target) target.focus({ preventScroll: true });
    }
  }

  function onPointerMove(event) {
    if (!drag) {
      if (event.target === view.canvas && event.buttons === 0) {
        view.canvas.style.cursor = pick(view, event.clientX, event.clientY) ? "grab" : "";
      }
      return;
    }
    if (event.pointerId !== drag.pointerId) return;
    event.preventDefault();
    pending = { clientX: event.clientX, clientY: event.clientY };
    if (!frame) frame = requestAnimationFrame(apply);
  }

  function end(pointerId) {
    const name = drag.name;
    drag = null;
    pending = null;
    view.container.classList.remove("tnx-dragging");
    if (view.container.hasPointerCapture?.(pointerId)) view.container.releasePointerCapture(pointerId);
    view.dragging(false, name);
  }

  function onPointerUp(event) {
    if (!drag || event.pointerId !== drag.pointerId) return;
    if (pending) {
      cancelAnimationFrame(frame);
      frame = 0;
      if (event.type !== "pointercancel") apply();
    }
    end(event.pointerId);
  }

  /** The host set new values: the drag ends where it is, and writes nothing more. */
  function cancel() {
    if (!drag) return;
    if (frame) cancelAnimationFrame(frame);
    frame = 0;
    end(drag.pointerId);
  }

  function onKeyDown(event) {
    const target = event.target.closest?.("[data-vertex]");
    if (!target || !(event.key in KEYS) || event.altKey || event.ctrlKey || event.metaKey) return;
    event.preventDefault();
    const changes = keyChange(view, target.dataset.vertex, event.key);
    if (changes) view.write(changes);
  }

  const c = view.container;
  const stopCapture = listen(c, { pointerdown: onPointerDown }, { capture: true });
  const stop = listen(c, { pointermove: onPointerMove, pointerup: onPointerUp, pointercancel: onPointerUp, keydown: onKeyDown });
  const dispose = () => {
    if (frame) cancelAnimationFrame(frame);
    stopCapture();
    stop();
  };
  dispose.cancel = cancel;
  return dispose;
}
