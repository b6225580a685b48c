/*
 * Touch on a 3D view inside a page: a finger scrolls the page over the view until a tap turns
 * the view on (as maps do); a touch anywhere outside the view turns it off again. Two fingers
 * always zoom and turn it. Used by the explorer and the mesh view alike.
 */
import { TOUCH } from "three";
import { listen } from "./dom.js";

/** A tap: the finger lifted within this many px of where it went down, and this many ms. */
const TAP_PX = 10;
const TAP_MS = 600;

/**
 * { root, stageEl, controls, canvas, activeClass } -> { active() -> bool, dispose() }
 *
 * `root` gets `activeClass` while the view is on; taps count on `stageEl`; `controls` (three's
 * OrbitControls) turn the view with one finger only while it is on, and `canvas` lets the
 * browser scroll the page (touch-action: pan-y) while it is off.
 */
export function touchGate({ root, stageEl, controls, canvas, activeClass }) {
  let on = false;
  function set(value) {
    on = value;
    root.classList.toggle(activeClass, value);
    controls.touches.ONE = value ? TOUCH.ROTATE : null;
    canvas.style.touchAction = value ? "none" : "pan-y";
  }
  set(false);
  let tap = null;
  const onStart = (event) => {
    tap = event.pointerType === "touch" ? { x: event.clientX, y: event.clientY, t: performance.now(), id: event.pointerId } : null;
  };
  const onEnd = (event) => {
    if (!tap || event.pointerId !== tap.id) return;
    const still = Math.hypot(event.clientX - tap.x, event.clientY - tap.y) < TAP_PX && performance.now() - tap.t < TAP_MS;
    tap = null;
    if (still && !on) set(true);
  };
  const onOutside = (event) => {
    if (on && !root.contains(event.target)) set(false);
  };
  const doc = root.ownerDocument || document;
  const stops = [
    listen(stageEl, { pointerdown: onStart }, { capture: true }),
    listen(stageEl, { pointerup: onEnd }),
    listen(doc, { pointerdown: onOutside }, { capture: true }),
  ];
  return {
    active: () => on,
    dispose() {
      for (const stop of stops) stop();
    },
  };
}
