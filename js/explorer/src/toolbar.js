/*
 * The explorer's toolbar: reset the view, look along x, y or z, flip the order of the
 * vertices, show the parallelogram, show the unit normal. The last three are edits (see
 * edits.js); the others move the camera only. At the end, in a block of their own, the two
 * "Download for 3D printing" buttons (marks in letters or in braille; printing.js), which
 * sit beside the view rather than in the toolbar.
 */
import { element, setAttr, setText } from "./dom.js";
import { addPresentButtons } from "./present.js";

const ORDER = { ABC: "A→B→C", ACB: "A→C→B" };

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

/**
 * Fill `bar` with the buttons. view: { get(key), edit(changes), stage, reset(), onFullscreen(on) }
 * (reset: frame the triangle again; onFullscreen: after the view enters or leaves full screen). Returns { update() }: the buttons' words and pressed states
 * from the values.
 */
export function createToolbar(bar, { get, edit, stage, reset, onFullscreen }) {
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
  const resetButton = button("", "Reset view", reset);
  resetButton.append(element("span", "tnx-long", "Reset view"), element("span", "tnx-short", "Reset"));
  resetButton.title = "Reset view: frame the triangle and its arrows again";
  bar.append(
    resetButton,
    button("x", "View along the x axis", () => stage.along("x")),
    button("y", "View along the y axis", () => stage.along("y")),
    button("z", "View along the z axis", () => stage.along("z")),
    flip,
    para,
    unit,
  );

  // --- for the projector and worksheets (present.js): Full screen and Save picture, in the
  // view's corner so this toolbar keeps one row
  const root = bar.closest(".tn-view") || bar.parentElement;
  const removePresent = addPresentButtons({ root, stage, filename: "triangle.png", onFullscreen });

  function update() {
    const winding = get("winding") === "ACB" ? "ACB" : "ABC";
    setText(flip, `⇄ ${ORDER[winding]}`);
    setAttr(flip, "aria-label", `Flip the order of the vertices, now ${ORDER[winding]}`);
    setAttr(flip, "title", flip.getAttribute("aria-label"));
    setAttr(para, "aria-pressed", !!get("show_parallelogram"));
    setAttr(unit, "aria-pressed", !!get("show_unit_normal"));
  }

  return { update, dispose: removePresent };
}

// ------------------------------------------------------------------ 3D printing (printing.js)

/**
 * The "Download for 3D printing" buttons (corners marked in letters, or in braille) and their
 * status line, as a group of their own at the end of `host` (the column beside the view: the
 * toolbar above the view is full). print(marks, status): ask the host for the file.
 */
export function createPrintButtons(host, print) {
  const group = element("div", "tnx-print");
  group.setAttribute("role", "group");
  group.setAttribute("aria-label", "3D printing");
  const status = element("p", "tnx-print-status");
  status.setAttribute("role", "status");
  const letters = button("Download for 3D printing", null, () => print("letters", status));
  letters.title = "An STL file of the triangle as a plate, N as an arrow, U and V as ridges, A, B, C in letters";
  const braille = button("With braille marks", "Download for 3D printing with braille marks", () => print("braille", status));
  braille.title = "The same model with A, B and C marked in braille";
  group.append(letters, braille, status);
  host.append(group);
}
