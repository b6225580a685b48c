/*
 * The mesh view described in words, under the view, in a polite live region that is also the
 * stage's accessible description: the model's name and size, its pieces, the faces to flip and
 * what is under the picked face (the host's readout of it, as printed in the panel). The name
 * and the pieces come from the host's "about" ({ name, pieces: the report's components }): the
 * site page's file name, or MeshView's about trait in a notebook (the file's name when it was
 * made from a MeshData); a host without it gets "The model" and the rest.
 */
import { element, setText } from "../dom.js";
import { injectStyle } from "../style.js";
import CSS from "../access.css";

/** Pieces and faces listed by number before "and N more". */
const LISTED = 8;

const counted = (n, one, many = one + "s") => `${n} ${n === 1 ? one : many}`;
const join = (words) => (words.length < 2 ? words.join("") : words.slice(0, -1).join(", ") + " and " + words[words.length - 1]);

/** A list of at most LISTED items said in words, with how many more there are. */
function listed(items) {
  const shown = items.slice(0, LISTED).map(String);
  if (items.length > LISTED) shown.push(`${items.length - LISTED} more`);
  return join(shown);
}

/** How a piece is (a component of the report): "closed, facing inward, 2 faces to flip" (flips: with them). */
function pieceState(piece, flips = true) {
  const how = [piece.closed ? "closed" : "open (it has a hole)"];
  if (piece.outward === false) how.push("facing inward");
  if (flips && piece.faces_to_flip) how.push(`${counted(piece.faces_to_flip, "face")} to flip`);
  return how.join(", ");
}

/**
 * The description of a mesh: about ({ name, pieces } or nothing), faces (how many), flipped (the
 * faces to flip), picked (the face picked, -1: none) and selection (the host's readout of it:
 * { face, title, rows }; said once it is the picked face's).
 */
export function describeMesh({ about, faces, flipped, picked, selection }) {
  if (!faces) return "No model is shown.";
  const name = about && about.name ? about.name : "The model";
  const pieces = about && Array.isArray(about.pieces) ? about.pieces : null;
  const parts = [`${name}: ${counted(faces, "face")}${pieces ? ` in ${counted(pieces.length, "piece")}` : ""}.`];
  if (pieces && pieces.length > 1) {
    const said = pieces.slice(0, LISTED).map((p, i) => `piece ${i + 1}, ${counted(p.faces, "face")}: ${pieceState(p)}`);
    if (pieces.length > LISTED) said.push(`${pieces.length - LISTED} more`);
    parts.push(`Its pieces: ${said.join("; ")}.`);
  } else if (pieces && pieces.length === 1) {
    parts.push(`The piece is ${pieceState(pieces[0], false)}.`); // its faces to flip: said next
  }
  const flips = flipped ? Array.from(flipped) : [];
  parts.push(flips.length ? `${flips.length === 1 ? "Face" : "Faces"} to flip (outlined): ${listed(flips)}.` : "No face needs flipping.");
  const rows = selection && selection.face === picked && Array.isArray(selection.rows) ? selection.rows : [];
  if (rows.length) parts.push(`Picked: ${selection.title}. ${rows.map(([label, value]) => `${label}: ${value}`).join("; ")}.`);
  return parts.join(" ");
}

/**
 * The description under the mesh view's stage (`stageEl`), its accessible description too.
 * Returns { update(facts), dispose() }; update takes describeMesh's facts.
 */
export function createMeshDescription(stageEl) {
  injectStyle(stageEl.ownerDocument || document, "trinormal-access-style", CSS);
  const text = element("p", "tnm-describe");
  text.id = `tnm-describe-${Math.random().toString(36).slice(2, 10)}`;
  text.setAttribute("role", "status");
  text.setAttribute("aria-live", "polite");
  stageEl.after(text);
  stageEl.setAttribute("aria-describedby", text.id);
  return {
    update: (facts) => setText(text, describeMesh(facts)),
    dispose: () => text.remove(),
  };
}
