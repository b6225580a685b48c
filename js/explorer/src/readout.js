/*
 * The readout panel: the host's rows (label and value, in FIELDS order), the status
 * sentence, and a polite live region with the one-line summary for screen readers.
 * Every string comes from `state`: the view prints nothing it computed itself. While the
 * view's edits wait for a busy kernel, the status says so (the host's `waiting` text) and the
 * rows, which are the host's last numbers, are marked as not current.
 */
import { element, setAttr, setHidden, setText } from "./dom.js";

/**
 * A value as spans (a vector's components; a plane's terms), so a line can break only
 * between them, never inside a number.
 */
function setValue(cell, text) {
  if (cell.dataset.text === text) return;
  cell.dataset.text = text;
  cell.textContent = "";
  // a vector stays on one line (on a narrow screen it may break between components)
  const vector = String(text).startsWith("(");
  const home = vector ? cell.appendChild(element("span", "tnx-vector")) : cell;
  const parts = String(text).split(/(?<=,) | (?=[+=−-] )/);
  parts.forEach((part, i) => {
    home.appendChild(element("span", "tnx-part", part));
    if (i < parts.length - 1) home.appendChild(document.createTextNode(" "));
  });
}

export function createReadout(parent) {
  const panel = element("section", "tnx-readout");
  panel.setAttribute("aria-label", "Readout");
  const table = element("table", "tnx-table"); // a class, so a page's styles for plain tables leave it alone
  const body = element("tbody");
  table.appendChild(body);
  const status = element("p", "tnx-status");
  const live = element("p", "tnx-summary");
  live.setAttribute("aria-live", "polite");
  live.setAttribute("role", "status");
  panel.append(table, status, live);
  parent.appendChild(panel);
  let timer = 0;

  function update(state) {
    const rows = Array.isArray(state?.readout) ? state.readout : [];
    while (body.rows.length > rows.length) body.deleteRow(-1);
    rows.forEach((row, i) => {
      const tr = body.rows[i] || body.insertRow();
      if (tr.cells.length === 0) {
        const th = element("th");
        th.scope = "row";
        tr.append(th, element("td", "tnx-value"));
      }
      setAttr(tr, "data-key", row.key);
      setText(tr.cells[0], row.label);
      setValue(tr.cells[1], state.ok === false ? "—" : row.value);
    });
    setText(status, (state?.ok === false ? state.error : state?.status) || "");
    setAttr(status, "data-state", state?.ok === false ? "error" : state?.degenerate ? "degenerate" : "ok");
    // announce an error once the values settle (a drag changes them every frame); what the view
    // shows is announced by the description (describe.js), so a good state says nothing here
    clearTimeout(timer);
    const text = state?.ok === false ? state.error || "" : "";
    timer = setTimeout(() => {
      if (live.textContent !== text) live.textContent = text;
    }, 350);
  }

  /** `text`: what to say while edits wait for the host ("" when they do not). Call after update. */
  function waiting(text) {
    setAttr(panel, "aria-busy", text ? "true" : "false");
    table.classList.toggle("tnx-waiting", !!text);
    if (text) {
      setText(status, text);
      setAttr(status, "data-state", "waiting");
    }
  }

  return {
    update,
    waiting,
    show(on) {
      setHidden(panel, !on);
    },
    dispose() {
      clearTimeout(timer);
      panel.remove();
    },
  };
}
