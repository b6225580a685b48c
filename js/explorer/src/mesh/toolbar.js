/*
 * The mesh view's toolbar: "Reset view" and four toggles (cull back faces, smooth shading, face
 * normals, vertex normals). A toggle is the model's key when the host has it (Jupyter: the
 * kernel keeps it), else state of this view (the site).
 */
import { element, toolbarElement } from "../dom.js";
import { addPresentButtons } from "../present.js";

/** The toggles and their values where the host has no such key. */
export const LOCAL_FLAGS = { cull: false, smooth: false, show_face_normals: true, show_vertex_normals: false };

const TOGGLES = [
  ["cull", "Cull back faces", "Hide the back of every face, as a game engine does: flipped faces vanish"],
  ["smooth", "Smooth shading", "Light each face with its corners' vertex normals blended, instead of one normal per face"],
  ["show_face_normals", "Face normals", "Show each face's unit normal as an arrow from its centre"],
  ["show_vertex_normals", "Vertex normals", "Show the vertex normals as arrows from the vertices"],
];

/**
 * The toggles' values: { get(key), set(key, value) }. set writes the model's key (and saves it),
 * or, where the model has none, this view's own value and calls onLocalChange().
 */
export function createFlags(model, onLocalChange) {
  const local = { ...LOCAL_FLAGS };
  const hosted = (key) => model.get(key) !== undefined && model.get(key) !== null;
  return {
    get: (key) => (hosted(key) ? Boolean(model.get(key)) : local[key]),
    set(key, value) {
      local[key] = value;
      if (!hosted(key)) onLocalChange();
      else {
        model.set(key, value);
        model.save_changes();
      }
    },
  };
}

/**
 * { flags, stage, root } -> { el, update(arrows), dispose() }; arrows.has(kind) says which arrow
 * toggles to show; root is the view's root (what full screen fills the screen with).
 */
export function createToolbar({ flags, stage, root }) {
  const el = toolbarElement("tnm-toolbar", "3D view of the mesh");
  const buttons = {};
  for (const [key, text, title] of TOGGLES) {
    const b = element("button", "tnm-button tn-text-button", text);
    b.type = "button";
    b.setAttribute("aria-pressed", "false");
    b.title = title;
    b.addEventListener("click", () => flags.set(key, !flags.get(key)));
    buttons[key] = b;
  }
  buttons.show_face_normals.hidden = buttons.show_vertex_normals.hidden = true;
  const reset = element("button", "tnm-button tn-text-button", "Reset view");
  reset.type = "button";
  reset.addEventListener("click", () => stage.reset());
  el.append(reset, ...Object.values(buttons));
  // for the projector and worksheets (../present.js): in the view's corner
  const removePresent = addPresentButtons({ root, stage, filename: "mesh.png" });
  return {
    el,
    dispose: removePresent,
    update(arrows) {
      for (const [key, b] of Object.entries(buttons)) b.setAttribute("aria-pressed", String(flags.get(key)));
      buttons.show_face_normals.hidden = !arrows.has("face");
      buttons.show_vertex_normals.hidden = !arrows.has("vertex");
    },
  };
}
