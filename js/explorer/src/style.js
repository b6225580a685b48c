/*
 * The view's CSS (style.css, bundled as a string by build.mjs) is injected once per
 * document, so the bundle stays one file. Text is at least 14 px; the colours of the
 * roles come from the host's palette at run time.
 */
import CSS from "./style.css";

const ID = "trinormal-explorer-style";

export function injectStyle(doc = document) {
  if (doc.getElementById(ID)) return;
  const style = doc.createElement("style");
  style.id = ID;
  style.textContent = CSS;
  doc.head.appendChild(style);
}
