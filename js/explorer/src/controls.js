/*
 * The explorer's controls, drawn by the view itself: per coordinate a slider on the grid
 * (`step`, inside `bounds`) and a box holding its exact text, and the number of decimals.
 * They write nothing on their own: a learner's move becomes an edit naming the one
 * coordinate moved or typed (`edit({ ay: "2/7" })`), which the host applies (the kernel,
 * with the exact core) and answers with new values. So a value the host set (1/3, 2.35) is
 * shown as set and is never rounded back to the grid.
 */
import { gridIndex, gridText, parseCoordinate, readStep } from "./numbers.js";
import { element, setAttr, setHidden, setStyle } from "./dom.js";

/** An input or a select: typing in it is not a JupyterLab shortcut (see layout.js). */
function field(tag, className) {
  const e = element(tag, className);
  e.dataset.lmSuppressShortcuts = "true";
  return e;
}

/**
 * view: { get(key), edit(changes), color(role) } -> { el, update(), dispose() }
 */
export function createControls(parent, view) {
  const panel = element("div", "tnx-controls");
  panel.setAttribute("role", "group");
  panel.setAttribute("aria-label", "Coordinates");
  const rows = {};
  for (const p of "abc") {
    const row = element("div", "tnx-vertex-row");
    const name = element("span", "tnx-vertex-name", p.toUpperCase());
    // the three coordinates wrap inside their own box, so on a narrow screen y and z line up under x
    const coords = element("span", "tnx-coords");
    row.append(name, coords);
    rows[p] = { name, cells: [] };
    ["x", "y", "z"].forEach((q, i) => {
      const cell = element("span", "tnx-coord");
      const slider = field("input", "tnx-slider");
      slider.type = "range";
      slider.setAttribute("aria-label", `${p.toUpperCase()}.${q} slider`);
      const box = field("input", "tnx-exact");
      box.type = "text";
      box.spellcheck = false;
      box.autocomplete = "off";
      box.setAttribute("aria-label", `${p.toUpperCase()}.${q}, exact value: type a number such as 0.1, -2 or 1/3 and press Enter`);
      box.title = `${p.toUpperCase()}.${q}: type a number such as 0.1, -2 or 1/3 and press Enter`;
      cell.append(element("span", "tnx-axis-name", q), slider, box);
      coords.appendChild(cell);
      rows[p].cells.push({ slider, box });

      let frame = 0;
      slider.addEventListener("input", () => {
        // one edit per animation frame while the thumb moves
        if (frame) return;
        frame = requestAnimationFrame(() => {
          frame = 0;
          const grid = readStep(view.get("step"));
          const k = gridIndex(Number(slider.value), grid, view.get("bounds"));
          const text = gridText(k, grid);
          if (String((view.get(p) || [])[i] ?? "") === text) return;
          box.value = text;
          view.edit({ [p + q]: text }); // this coordinate only
        });
      });
      box.addEventListener("input", () => {
        box.dataset.dirty = "true";
      });
      // Enter sends what was typed (a box outside a form fires no change event on Enter),
      // and so does leaving the box
      const send = () => {
        if (!box.dataset.dirty) return;
        delete box.dataset.dirty;
        view.edit({ [p + q]: box.value });
      };
      box.addEventListener("change", send);
      box.addEventListener("keydown", (event) => {
        if (event.key === "Enter") send();
        else if (event.key === "Escape") {
          delete box.dataset.dirty;
          box.value = String((view.get(p) || [])[i] ?? "");
        }
      });
    });
    panel.appendChild(row);
  }
  const settings = element("div", "tnx-settings");
  const decimalsLabel = element("label", "tnx-decimals", "decimals ");
  const decimals = field("select");
  decimalsLabel.appendChild(decimals);
  decimals.addEventListener("change", () => view.edit({ precision: Number(decimals.value) }));
  settings.appendChild(decimalsLabel);
  panel.appendChild(settings);
  parent.appendChild(panel);

  function update() {
    setHidden(panel, view.get("show_controls") === false);
    const grid = readStep(view.get("step"));
    const [lo, hi] = (view.get("bounds") || [-5, 5]).map(Number);
    for (const p of "abc") {
      setStyle(rows[p].name, "color", view.color(p.toUpperCase()));
      const values = (view.get(p) || ["", "", ""]).map(String);
      rows[p].cells.forEach(({ slider, box }, i) => {
        setAttr(slider, "min", lo);
        setAttr(slider, "max", hi);
        setAttr(slider, "step", grid.value);
        const x = parseCoordinate(values[i]);
        // the thumb shows the value; the value itself stays the host's exact text
        if (Number.isFinite(x) && Number(slider.value) !== x) slider.value = String(x);
        setAttr(slider, "aria-valuetext", values[i]);
        if (!box.dataset.dirty && box.value !== values[i]) box.value = values[i];
      });
    }
    const [pMin, pMax] = view.get("precision_range") || [0, 15];
    if (decimals.options.length !== pMax - pMin + 1) {
      decimals.textContent = "";
      for (let n = pMin; n <= pMax; n++) decimals.appendChild(new Option(String(n), String(n)));
    }
    const p = String(view.get("precision") ?? 4);
    if (decimals.value !== p) decimals.value = p;
  }

  return {
    update,
    /** Forget what was typed but not sent in the boxes of `keys` ("bx"): the host set them. */
    reset(keys) {
      for (const p of "abc") {
        rows[p].cells.forEach(({ box }, i) => {
          if (keys.includes(p + "xyz"[i])) delete box.dataset.dirty;
        });
      }
    },
    dispose() {
      panel.remove();
    },
  };
}
