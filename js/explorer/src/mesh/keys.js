/*
 * The keyboard's ways into the mesh view: the arrow keys turn the model, + and − zoom, Home
 * resets the view; and a face is picked by its number, or the faces to flip one after another.
 */
import { element, listen } from "../dom.js";

let forms = 0; // face-number boxes made on this page: unique ids for their labels

/** The mesh view's stage, focusable and named: the arrow keys of turnWithKeys act on it. */
export function focusableStage(stageEl) {
  stageEl.tabIndex = 0;
  stageEl.setAttribute("role", "group"); // not "img": the Full screen and Save picture buttons sit inside it
  stageEl.setAttribute("aria-label", "The model in 3D. Arrow keys turn it, + and − zoom, Home resets the view.");
}

/**
 * Turn a view from the keyboard while its focused stage itself has the focus (not a control
 * inside it, such as a vertex whose arrow keys move it): arrow keys turn by 15° (Shift: 45°),
 * + and − zoom, Home resets the view. The drag's alternative for a reader without a pointer
 * (WCAG 2.5.7), in the explorer and the mesh view. Returns the function that stops it.
 */
export function turnWithKeys(stageEl, stage) {
  const onKey = (event) => {
    if (event.target !== stageEl || event.altKey || event.ctrlKey || event.metaKey) return;
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
    if (!keys[event.key]) return;
    event.preventDefault(); // the page does not scroll
    keys[event.key]();
  };
  return listen(stageEl, { keydown: onKey });
}

/**
 * The form that picks a face by its number: { form, update(faces, flipped), showPicked(face) }.
 * onPick(face) receives the number typed (a face that does not exist gets the host's message)
 * or the next or previous face to flip after picked() (flipped: their sorted list, or null).
 */
export function createFaceForm({ onPick, picked }) {
  const form = element("form", "tnm-keys");
  const id = `tnm-face-${++forms}`;
  const label = element("label", "tnm-face-label", "Face number");
  label.htmlFor = id;
  const input = element("input", "tnm-face-input");
  Object.assign(input, { id, type: "number", min: "0", step: "1", inputMode: "numeric", autocomplete: "off" });
  const show = element("button", "tnm-button tn-text-button", "Show face");
  show.type = "submit";
  const prev = element("button", "tnm-button tn-text-button", "Previous face to flip");
  const next = element("button", "tnm-button tn-text-button", "Next face to flip");
  prev.type = next.type = "button";
  form.append(label, input, show, prev, next);
  let flipped = null;

  function pickTyped() {
    const text = input.value.trim();
    if (!text || !input.checkValidity()) {
      input.reportValidity();
      return;
    }
    onPick(Number(text));
  }
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    pickTyped();
  });
  // Enter in the box, handled here: JupyterLab's notebook swallows the form's own submission
  input.addEventListener("keydown", (event) => {
    if (event.key !== "Enter") return;
    event.preventDefault();
    pickTyped();
  });

  /** The next (step 1) or previous (-1) face to flip from the one picked, round the list. */
  function stepFlipped(step) {
    if (!flipped || !flipped.length) return;
    const at = picked();
    let i = step > 0 ? flipped.findIndex((f) => f > at) : flipped.findLastIndex((f) => f < at);
    if (i < 0) i = step > 0 ? 0 : flipped.length - 1;
    input.value = String(flipped[i]);
    onPick(flipped[i]);
  }
  prev.addEventListener("click", () => stepFlipped(-1));
  next.addEventListener("click", () => stepFlipped(1));

  return {
    form,
    /** The model now shown: how many faces (0: none) and its faces to flip. */
    update(faces, flippedFaces) {
      flipped = flippedFaces || null;
      label.textContent = faces ? `Face number (0 to ${faces - 1})` : "Face number";
      prev.hidden = next.hidden = !(flipped && flipped.length);
    },
    /** Show the picked face's number in the box, unless the reader is typing there. */
    showPicked(face) {
      if (input.ownerDocument.activeElement !== input) input.value = String(face);
    },
  };
}
