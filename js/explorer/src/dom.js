/*
 * Small helpers for the views' HTML. `element` makes one; the others write to the page only
 * when the value is new. The view re-applies its whole state on every change (a drag: every
 * frame), and writing an attribute, a text or a style to the value it already has still makes
 * the browser recompute styles and repaint.
 */

/** A new element of the document with a class and a text (either may be left out). */
export function element(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

/** Add listeners ({ type: handler }, with `options`) to a target; returns the function that removes them. */
export function listen(target, handlers, options) {
  const pairs = Object.entries(handlers);
  for (const [type, handler] of pairs) target.addEventListener(type, handler, options);
  return () => {
    for (const [type, handler] of pairs) target.removeEventListener(type, handler, options);
  };
}

/** A toolbar (the ARIA pattern: its buttons are one group, named by `label`). */
export function toolbarElement(className, label) {
  const bar = element("div", className);
  bar.setAttribute("role", "toolbar");
  bar.setAttribute("aria-label", label);
  return bar;
}

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

/** Give `blob` to the browser as a download called `name` (a click on a link made for it). */
export function saveBlob(blob, name, doc = document) {
  const url = URL.createObjectURL(blob);
  const a = doc.createElement("a");
  a.href = url;
  a.download = name;
  a.hidden = true;
  doc.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 0);
}
