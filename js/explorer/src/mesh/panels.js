/*
 * The text under the mesh view: the legend (what each colour, line and arrow drawn means, with
 * counts) and the host's answer for the picked face (its vertices, exact normal and area).
 */
import { element } from "../dom.js";
import { OUTLINE_EACH_UP_TO } from "./outlines.js";

const LEGEND = [
  ["front", "front of a face (its normal points out of this side)", "face"],
  ["back", "back of a face", "face"],
  ["flipped", "outline: a face to flip", "line"],
  ["boundary", "thick: an edge with one face (the rim of a hole)", "line"],
  ["non_manifold", "thick: an edge with three faces or more", "line"],
  ["face_arrows", "arrow from a face's centre: its unit normal", "arrow"],
  ["vertex_arrows", "arrow from a vertex: its vertex normal", "arrow"],
];

/**
 * Fill the legend (a list) with the items drawn now. counts: role -> how many (faces to flip,
 * edges, arrows drawn); shown(role): whether an arrow kind is on; colorOf(role): its colour.
 */
export function drawLegend(legend, { counts, shown, colorOf }) {
  legend.textContent = "";
  for (const [role, text, kind] of LEGEND) {
    if (kind === "line" && !counts[role]) continue;
    if (kind === "arrow" && !(counts[role] && shown(role))) continue;
    const item = element("li", "tnm-key");
    const swatch = element("span", "tnm-swatch tnm-swatch-" + (kind === "arrow" ? "line" : kind));
    swatch.style.setProperty("--tnm-swatch", colorOf(role));
    swatch.setAttribute("aria-hidden", "true");
    const rim = role === "flipped" && counts.flipped > OUTLINE_EACH_UP_TO;
    const count = rim ? ` (${counts[role]} faces)` : kind === "line" ? ` (${counts[role]})` : kind === "arrow" ? ` (${counts[role]} drawn)` : "";
    item.append(swatch, legend.ownerDocument.createTextNode((rim ? "outline: the rim of each patch of faces to flip" : text) + count));
    legend.appendChild(item);
  }
}

/** Show the host's answer for the picked face (sel: { title, rows: [[label, value, role]] }). */
export function showSelection(panel, sel) {
  panel.textContent = "";
  panel.hidden = !(sel && sel.rows && sel.rows.length);
  if (panel.hidden) return;
  panel.appendChild(element("p", "tnm-pick-title", sel.title || ""));
  const list = element("dl", "tnm-pick-rows");
  for (const [label, value] of sel.rows) list.append(element("dt", "", label), element("dd", "", value));
  panel.appendChild(list);
}
