/*
 * The views' CSS (base.css, which both share, and each view's own sheet, bundled as strings
 * by build.mjs) is injected once per document, so a bundle stays one file. Text is at least
 * 14 px; the colours of the roles come from the host's palette at run time.
 */
import BASE from "./base.css";

/** Add a view's sheet (`css`, under the element id `id`) and the shared base, each once. */
export function injectStyle(doc, id, css) {
  for (const [key, text] of [["trinormal-view-base", BASE], [id, css]]) {
    if (doc.getElementById(key)) continue;
    const style = doc.createElement("style");
    style.id = key;
    style.textContent = text;
    doc.head.appendChild(style);
  }
}
