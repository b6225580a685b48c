/*
 * For the projector and for worksheets, in both 3D views, two buttons in the view's top right
 * corner (as a video player has them, so the toolbar keeps one row): "Full screen" (or the f
 * key while the view has focus) makes the view fill the screen with its readout over it, Esc
 * returns; "Save picture" downloads the view as it is now, at twice its size on the screen,
 * with its labels, as a PNG.
 *
 * Full screen uses the browser's Fullscreen API on the view's root; where a page may not
 * (an iframe without permission), the root is pinned over the window instead and Esc or the
 * button returns. Either way the root carries the class tn-fullscreen, which the styles use.
 */
import { element, listen, saveBlob } from "./dom.js";

const SCALE = 2; // the saved picture's pixels per pixel of the view on the screen

/** The view's top right corner the buttons take (px, with a gap): labels keep out of it (base.css). */
export const CORNER = { width: 84, height: 44 };

const SVG = "http://www.w3.org/2000/svg";
// 24 x 24 outline icons: the four corners going out (full screen), coming in (exit), and an
// arrow down onto a tray (save)
const ICONS = {
  enter: "M4 9V4h5M15 4h5v5M20 15v5h-5M9 20H4v-5",
  exit: "M9 4v5H4M20 9h-5V4M15 20v-5h5M4 15h5v5",
  save: "M12 4v11M7 10l5 5 5-5M5 20h14",
};

/** Set `b`'s icon (an ICONS key) and its name, which is also its tooltip. */
function setIcon(b, icon, name) {
  b.setAttribute("aria-label", name);
  b.title = name;
  b.querySelector("path").setAttribute("d", ICONS[icon]);
}

/** An icon button (its name spoken and shown as a tooltip). */
function button(icon, name, onClick) {
  const b = element("button", "tn-present-button");
  b.type = "button";
  const svg = document.createElementNS(SVG, "svg");
  svg.setAttribute("viewBox", "0 0 24 24");
  svg.setAttribute("aria-hidden", "true");
  svg.setAttribute("focusable", "false");
  svg.appendChild(document.createElementNS(SVG, "path"));
  b.appendChild(svg);
  setIcon(b, icon, name);
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
function createFullscreen(root, onChange) {
  const doc = root.ownerDocument || document;
  let pinned = false; // full screen by pinning the root over the window (no Fullscreen API)
  const b = button("enter", "Full screen", () => toggle());
  b.setAttribute("aria-keyshortcuts", "f");

  const isOn = () => pinned || doc.fullscreenElement === root;
  function show() {
    const on = isOn();
    root.classList.toggle("tn-fullscreen", on);
    setIcon(b, on ? "exit" : "enter", on ? "Exit full screen" : "Full screen");
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

/**
 * The two buttons in the top right corner of the view's stage: Full screen (of `root`) and
 * Save picture (as `filename`). onFullscreen(on) runs after the view enters or leaves full
 * screen. Returns the function that removes them.
 */
export function addPresentButtons({ root, stage, filename, onFullscreen = () => {} }) {
  const group = element("div", "tn-present");
  group.setAttribute("role", "group");
  group.setAttribute("aria-label", "Picture");
  const fullscreen = createFullscreen(root, onFullscreen);
  group.append(fullscreen.button, button("save", "Save picture", async () => saveBlob(await pictureOf(stage), filename)));
  stage.canvas.parentElement.appendChild(group);
  return () => {
    fullscreen.dispose();
    group.remove();
  };
}
