/*
 * For the projector and for worksheets, in both 3D views: "Full screen" (or the f key while
 * the view has focus) makes the view fill the screen with its readout over it, Esc returns;
 * "Save picture" downloads the view as it is now, at twice its size on the screen, with its
 * labels, as a PNG.
 *
 * Full screen uses the browser's Fullscreen API on the view's root; where a page may not
 * (an iframe without permission), the root is pinned over the window instead and Esc or the
 * button returns. Either way the root carries the class tn-fullscreen, which the styles use.
 */
import { element, listen } from "./dom.js";

const SCALE = 2; // the saved picture's pixels per pixel of the view on the screen

/** A toolbar button (`cls`: the view's button class). */
function button(cls, text, title, onClick) {
  const b = element("button", cls, text);
  b.type = "button";
  b.title = title;
  b.addEventListener("click", onClick);
  return b;
}

/** True when a key pressed on `target` is typing (a text box, a menu), not a command to the view. */
function typing(target) {
  const tag = (target && target.tagName) || "";
  return tag === "INPUT" || tag === "TEXTAREA" || tag === "SELECT" || !!(target && target.isContentEditable);
}

/**
 * The full-screen toggle of `root` (the view's root element): { button, toggle(), dispose() }.
 * `onChange(on)` runs after the view enters or leaves full screen.
 */
export function createFullscreen(root, cls, onChange = () => {}) {
  const doc = root.ownerDocument || document;
  let pinned = false; // full screen by pinning the root over the window (no Fullscreen API)
  const b = button(cls, "Full screen", "Full screen (f): the view fills the screen; Esc returns", () => toggle());
  b.setAttribute("aria-pressed", "false");
  b.setAttribute("aria-keyshortcuts", "f");

  const isOn = () => pinned || doc.fullscreenElement === root;
  function show() {
    const on = isOn();
    root.classList.toggle("tn-fullscreen", on);
    b.setAttribute("aria-pressed", String(on));
    b.textContent = on ? "Exit full screen" : "Full screen";
    onChange(on);
  }
  function pin(on) {
    pinned = on;
    show();
  }
  function toggle() {
    if (pinned) return pin(false);
    if (doc.fullscreenElement === root) return void doc.exitFullscreen();
    if (!root.requestFullscreen) return pin(true);
    root.requestFullscreen().catch(() => pin(true));
  }
  const stopDoc = listen(doc, {
    fullscreenchange: show,
    keydown: (event) => {
      if (pinned && event.key === "Escape") pin(false);
    },
  });
  const stopRoot = listen(root, {
    keydown: (event) => {
      if (event.key !== "f" || event.altKey || event.ctrlKey || event.metaKey || typing(event.target)) return;
      event.preventDefault();
      event.stopPropagation(); // the f key is the view's here, not the notebook's
      toggle();
    },
  });
  return {
    button: b,
    toggle,
    dispose() {
      if (doc.fullscreenElement === root) doc.exitFullscreen();
      stopDoc();
      stopRoot();
    },
  };
}

/** Draw one HTML label (its box, border and text as the page shows them) onto `ctx`, in the stage's px. */
function drawLabel(ctx, el, stageBox) {
  const box = el.getBoundingClientRect();
  if (!box.width || !box.height) return;
  const css = getComputedStyle(el);
  const x = box.left - stageBox.left;
  const y = box.top - stageBox.top;
  const radius = Math.min(parseFloat(css.borderTopLeftRadius) || 0, box.width / 2, box.height / 2);
  ctx.beginPath();
  ctx.roundRect(x, y, box.width, box.height, radius);
  if (css.backgroundColor && css.backgroundColor !== "rgba(0, 0, 0, 0)") {
    ctx.fillStyle = css.backgroundColor;
    ctx.fill();
  }
  const border = parseFloat(css.borderTopWidth) || 0;
  if (border) {
    ctx.lineWidth = border;
    ctx.strokeStyle = css.borderTopColor;
    ctx.stroke();
  }
  ctx.fillStyle = css.color;
  ctx.font = `${css.fontWeight} ${css.fontSize} ${css.fontFamily}`;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.fillText(el.textContent, x + box.width / 2, y + box.height / 2);
}

/**
 * The view as a PNG (a Blob) at SCALE times its size on the screen: the stage's 3D picture
 * drawn again at that resolution, with the visible labels over it.
 */
export function pictureOf(stage) {
  const { renderer, canvas } = stage;
  const { width, height } = stage.size();
  const ratio = renderer.getPixelRatio();
  const out = element("canvas");
  out.width = width * SCALE;
  out.height = height * SCALE;
  const ctx = out.getContext("2d");
  renderer.setPixelRatio(SCALE);
  renderer.setSize(width, height, false);
  try {
    stage.renderNow(); // the drawing buffer is read in the same task, before it is cleared
    ctx.drawImage(canvas, 0, 0, out.width, out.height);
  } finally {
    renderer.setPixelRatio(ratio);
    renderer.setSize(width, height, false);
    stage.renderNow();
  }
  ctx.scale(SCALE, SCALE);
  const stageBox = canvas.parentElement.getBoundingClientRect();
  const labels = [...canvas.parentElement.querySelectorAll(".tnx-label")].filter((el) => !el.hidden);
  for (const el of labels.sort((p, q) => (Number(getComputedStyle(p).zIndex) || 0) - (Number(getComputedStyle(q).zIndex) || 0))) {
    drawLabel(ctx, el, stageBox);
  }
  return new Promise((resolve) => out.toBlob(resolve, "image/png"));
}

/** The "Save picture" button: downloads pictureOf(stage) as `filename`. */
export function createSaveButton(stage, cls, filename) {
  return button(cls, "Save picture", "Save the view as a PNG picture, twice the size shown, for a worksheet", async () => {
    const blob = await pictureOf(stage);
    const url = URL.createObjectURL(blob);
    const a = element("a");
    a.href = url;
    a.download = filename;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 0);
  });
}
