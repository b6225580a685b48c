/*
 * Writes to the page that change it only when the value is new. The view re-applies its whole
 * state on every change (a drag: every frame); writing an attribute, a text or a style to the
 * value it already has still makes the browser recompute styles and repaint, which on a
 * software renderer (SwiftShader) was a measurable part of every drag frame
 * (benchmarks/bench_view.py).
 */

/** Set an element's text, if it differs. */
export function setText(el, text) {
  const s = String(text);
  if (el.textContent !== s) el.textContent = s;
}

/** Set an attribute, if it differs. */
export function setAttr(el, name, value) {
  const s = String(value);
  if (el.getAttribute(name) !== s) el.setAttribute(name, s);
}

/** Show or hide an element (its `hidden` attribute), if that changes. */
export function setHidden(el, hidden) {
  if (el.hidden !== !!hidden) el.hidden = !!hidden;
}

const written = new WeakMap(); // el -> { style property: the value last written }

/** Set one inline style property, if it differs from what was written last. */
export function setStyle(el, name, value) {
  let styles = written.get(el);
  if (!styles) written.set(el, (styles = {}));
  if (styles[name] === value) return;
  styles[name] = value;
  el.style[name] = value;
}
