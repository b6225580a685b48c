/*
 * HTML labels over the canvas: the vertices A, B and C (focusable, draggable, with
 * data-vertex), the arrows U, V, N and the unit normal, the axes and their ticks.
 * Each frame they are placed by projecting their 3D anchor to the screen; vertex
 * labels are pushed away from the triangle's centre so they sit beyond the arrow heads.
 */
import { setHidden } from "./dom.js";
import { CORNER } from "./present.js";
import { toScreen } from "./scene.js";

/**
 * The y of a label centred at (x, y), `w` x `h` half-size, moved down below the buttons in
 * the view's top right corner (present.js) when it would sit under them.
 */
function clearOfCorner(x, y, w, h, size) {
  const under = x + w > size.width - CORNER.width && y - h < CORNER.height;
  return under && size.height > CORNER.height + 2 * h + 4 ? CORNER.height + h + 2 : y;
}

export class LabelLayer {
  /** Labels over `container`; `beforeLayout()` runs before each layout (the marks' sizing). */
  constructor(container, beforeLayout = null) {
    this.beforeLayout = beforeLayout;
    this.el = document.createElement("div");
    this.el.className = "tnx-labels";
    container.appendChild(this.el);
    this.items = new Map();
  }

  /** Create (or return) a label. kind: "vertex", "arrow", "axis", "tick". */
  label(id, kind, text) {
    let item = this.items.get(id);
    if (!item) {
      const el = document.createElement("div");
      el.className = "tnx-label tnx-" + kind;
      this.el.appendChild(el);
      item = { el, kind, anchor: null, away: null, offset: 0, visible: true, text: null };
      this.items.set(id, item);
    }
    if (text !== undefined && item.text !== text) {
      item.el.textContent = text;
      item.text = text;
      item.half = null; // its size is measured again when next shown
    }
    return item;
  }

  /** Anchor a label at a 3D point; `away` is a 3D point it is pushed away from (or a fixed angle). */
  place(id, anchor, { away = null, offset = 0, angle = null, visible = true } = {}) {
    const item = this.items.get(id);
    if (!item) return;
    item.anchor = anchor ? anchor.clone() : null;
    item.away = away ? away.clone() : null;
    item.offset = offset;
    item.angle = angle;
    item.visible = visible && !!anchor;
  }

  hide(prefix) {
    for (const [id, item] of this.items) if (id.startsWith(prefix)) item.visible = false;
  }

  /** Move every label to its projected place. */
  layout(camera, size) {
    if (this.beforeLayout) this.beforeLayout();
    const placed = [];
    for (const item of this.items.values()) {
      const p = item.visible && item.anchor ? toScreen(item.anchor, camera, size.width, size.height) : null;
      if (!p || p.z > 1 || p.z < -1) {
        setHidden(item.el, true); // not shown, or behind the camera
        continue;
      }
      let x = p.x;
      let y = p.y;
      if (item.offset) {
        let ux = 0;
        let uy = 0;
        if (item.away) {
          const q = toScreen(item.away, camera, size.width, size.height);
          ux = p.x - q.x;
          uy = p.y - q.y;
        }
        const len = Math.hypot(ux, uy);
        if (len < 8 && item.angle !== null) {
          ux = Math.cos(item.angle);
          uy = -Math.sin(item.angle);
        } else if (len < 1e-6) {
          ux = 0;
          uy = -1;
        } else {
          ux /= len;
          uy /= len;
        }
        x += ux * item.offset;
        y += uy * item.offset;
      }
      // vertex labels that would sit on top of each other (points close on screen) fan out
      if (item.kind === "vertex") {
        for (const other of placed) {
          if (Math.hypot(other.x - x, other.y - y) < 30 && item.angle !== null) {
            x = p.x + Math.cos(item.angle) * item.offset * 1.4;
            y = p.y - Math.sin(item.angle) * item.offset * 1.4;
          }
        }
        // keep the whole label inside the view, so it can always be grabbed
        x = Math.min(Math.max(x, 20), size.width - 20);
        y = Math.min(Math.max(y, 20), size.height - 20);
        y = clearOfCorner(x, y, 20, 20, size);
        placed.push({ x, y });
      }
      setHidden(item.el, false);
      if (item.kind === "arrow") {
        // keep an arrow's label ("N/2", "N/|N|") wholly inside the view; measured once per text
        if (!item.half || !item.half.w) item.half = { w: item.el.offsetWidth / 2, h: item.el.offsetHeight / 2 };
        const { w, h } = item.half;
        if (size.width > 2 * w + 4) x = Math.min(Math.max(x, w + 2), size.width - w - 2);
        if (size.height > 2 * h + 4) y = Math.min(Math.max(y, h + 2), size.height - h - 2);
        y = clearOfCorner(x, y, w, h, size);
      }
      item.el.style.transform = `translate(${x.toFixed(1)}px, ${y.toFixed(1)}px) translate(-50%, -50%)`;
    }
  }

  dispose() {
    this.el.remove();
    this.items.clear();
  }
}
