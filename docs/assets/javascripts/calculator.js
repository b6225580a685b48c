/*
 * The Calculator page: reads the nine coordinates, the winding and the precision,
 * computes with TrinormalCore (exact, the same strings as the Python package) on
 * every keystroke, draws the bar charts of N and of the unit normal and keeps the state
 * in the URL. The 3D view (explorer-site.js) follows the form through its input events
 * and writes into it when a vertex is dragged. An ES module (mkdocs.yml), so its names
 * stay its own.
 */
var FIELDS = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"];
/* Each output field's <output> id, from the package's field spec (trinormal.fields). */
var OUTPUTS = {};
window.TRINORMAL_CONSTANTS.fields.forEach(function (field) {
  OUTPUTS[field.key] = field.output_id;
});
var DEFAULTS = { a: ["0", "0", "0"], b: ["1", "0", "0"], c: ["0", "1", "0"], w: "ABC", p: 4 };
var DASH = "\u2014";
var SVG_NS = "http://www.w3.org/2000/svg";

/* The x, y, z colours of the package's colour code (trinormal.colors), for the page's scheme. */
function axisColors() {
  var palette = window.TRINORMAL_CONSTANTS.palette;
  var dark = document.body.getAttribute("data-md-color-scheme") === "slate";
  return ["x", "y", "z"].map(function (axis) {
    return dark ? palette[axis].dark : palette[axis].light;
  });
}

function $(id) {
  return document.getElementById(id);
}

/* One URL value "x,y,z": commas inside a coordinate are escaped as %2C. */
function encodePoint(values) {
  return values
    .map(function (s) {
      return encodeURIComponent(s).replace(/%2F/gi, "/");
    })
    .join(",");
}

function decodePart(s) {
  try {
    return decodeURIComponent(s.replace(/\+/g, " "));
  } catch (e) {
    return s;
  }
}

function readQuery() {
  var params = {};
  var q = window.location.search.replace(/^\?/, "");
  if (!q) return params;
  q.split("&").forEach(function (pair) {
    if (!pair) return;
    var i = pair.indexOf("=");
    var key = decodePart(i < 0 ? pair : pair.slice(0, i));
    params[key] = i < 0 ? "" : pair.slice(i + 1);
  });
  return params;
}

function stateFromUrl() {
  var params = readQuery();
  var state = { a: DEFAULTS.a.slice(), b: DEFAULTS.b.slice(), c: DEFAULTS.c.slice(), w: DEFAULTS.w, p: DEFAULTS.p };
  ["a", "b", "c"].forEach(function (key) {
    if (!(key in params)) return;
    var parts = params[key].split(",").map(decodePart);
    state[key] = [0, 1, 2].map(function (i) {
      return parts[i] === undefined ? "" : parts[i];
    });
  });
  if ("w" in params) {
    var w = decodePart(params.w).toUpperCase();
    if (w === "ABC" || w === "ACB") state.w = w;
  }
  if ("p" in params) {
    var p = decodePart(params.p).trim();
    try {
      state.p = window.TrinormalCore.checkPrecision(p);
    } catch (e) {
      /* a bad precision in a link keeps the default */
    }
  }
  return state;
}

function fillForm(state) {
  var pts = state.a.concat(state.b, state.c);
  FIELDS.forEach(function (id, i) {
    $(id).value = pts[i];
  });
  $("winding").value = state.w;
  $("precision").value = String(state.p);
}

function readForm() {
  var v = FIELDS.map(function (id) {
    return $(id).value;
  });
  return { a: v.slice(0, 3), b: v.slice(3, 6), c: v.slice(6, 9), w: $("winding").value, p: $("precision").value };
}

function writeUrl(state) {
  var query =
    "?a=" + encodePoint(state.a) +
    "&b=" + encodePoint(state.b) +
    "&c=" + encodePoint(state.c) +
    "&w=" + encodeURIComponent(state.w) +
    "&p=" + encodeURIComponent(String(state.p).trim());
  if (window.location.search !== query) {
    window.history.replaceState(null, "", window.location.pathname + query + window.location.hash);
  }
}

function setInvalid(field) {
  FIELDS.concat(["precision"]).forEach(function (id) {
    var el = $(id);
    if (id === field) el.setAttribute("aria-invalid", "true");
    else el.removeAttribute("aria-invalid");
  });
}

function fieldId(name) {
  // "B.y" -> "by"
  return name && name.length === 3 ? name.replace(".", "").toLowerCase() : name;
}

/* A new SVG element in `svg`, with its attributes and its text. */
function addSvg(svg, tag, attributes, text) {
  var el = document.createElementNS(SVG_NS, tag);
  Object.keys(attributes).forEach(function (name) {
    el.setAttribute(name, attributes[name]);
  });
  if (text !== undefined) el.textContent = text;
  svg.appendChild(el);
}

function clearChart(svg, message) {
  svg.replaceChildren();
  addSvg(svg, "text", { x: "50%", y: "50%", "text-anchor": "middle", class: "tn-chart-note" }, message);
}

/*
 * One bar chart: values in [-1, 1] drawn as signed bars, with the printed strings beside them.
 * names: the row labels; texts: the printed values.
 */
function drawBars(svg, values, names, texts) {
  svg.replaceChildren();
  var colors = axisColors();
  var width = 480;
  var rowH = 44;
  var left = 48;
  var mid = left + (width - left - 16) / 2;
  var half = (width - left - 16) / 2;
  addSvg(svg, "line", { x1: mid, x2: mid, y1: 4, y2: 3 * rowH + 4, class: "tn-chart-axis" });
  values.forEach(function (value, i) {
    var y = i * rowH + 10;
    addSvg(svg, "text", { x: 8, y: y + 20, class: "tn-chart-label" }, names[i]);
    var len = Math.min(Math.abs(value), 1) * half;
    addSvg(svg, "rect", { x: value < 0 ? mid - len : mid, y: y, width: Math.max(len, 0), height: 28, fill: colors[i] });
    var right = value >= 0;
    var anchor = right ? "end" : "start";
    addSvg(svg, "text", { x: right ? mid - 6 : mid + 6, y: y + 20, "text-anchor": anchor, class: "tn-chart-value" }, texts[i]);
  });
}

function labelled(names, parts) {
  return names
    .map(function (n, i) {
      return n + " = " + parts[i];
    })
    .join(", ");
}

/* One chart of the printed vector out[key], its bars drawn from `values` (none: undefined). */
function drawChart(svg, title, names, result, key, values) {
  if (!result.ok) {
    svg.setAttribute("aria-label", title + "no chart, the input is not readable.");
    clearChart(svg, "No chart: fix the input first.");
    return;
  }
  if (!values) {
    svg.setAttribute("aria-label", title + "none, the unit normal is undefined.");
    clearChart(svg, "No unit normal: the triangle is degenerate.");
    return;
  }
  var parts = result.out[key].slice(1, -1).split(", ");
  svg.setAttribute("aria-label", title + labelled(names, parts) + ".");
  drawBars(svg, values, names, parts);
}

/* N's chart, and the unit normal's on a fixed scale from -1 to 1 (none when it is undefined). */
function drawCharts(result) {
  var unit = result.ok && !result.degenerate && result.floats && result.floats.unit_normal;
  drawChart($("chart"), "Bar chart of the normal components: ", ["Nx", "Ny", "Nz"], result, "normal", result.chart);
  drawChart($("chart-unit"), "Bar chart of the unit normal components: ", ["x", "y", "z"], result, "unit_normal", unit);
}

/*
 * While a vertex is dragged in the 3D view the boxes change every frame; the address then
 * follows once the pointer rests for URL_QUIET ms (and always ends on the last value). Each
 * history update makes Chromium fetch the page's icon again, too much work to do on every
 * frame of a drag.
 */
var URL_QUIET = 200;
var urlTimer = 0;
function writeUrlSoon() {
  if (urlTimer) clearTimeout(urlTimer);
  urlTimer = setTimeout(function () {
    urlTimer = 0;
    writeUrl(readForm());
  }, URL_QUIET);
}

function update(pushUrl, fromView) {
  var state = readForm();
  if (pushUrl && fromView) writeUrlSoon();
  else if (pushUrl) writeUrl(state);
  var status = $("out-status");
  // the core checks the precision (the rule and message of trinormal.validation)
  var result = window.TrinormalCore.compute(state.a, state.b, state.c, state.w, String(state.p));
  Object.keys(OUTPUTS).forEach(function (key) {
    $(OUTPUTS[key]).textContent = result.ok ? result.out[key] : DASH;
  });
  status.textContent = result.status;
  status.setAttribute("data-state", !result.ok ? "error" : result.degenerate ? "degenerate" : "ok");
  setInvalid(result.ok ? null : fieldId(result.field));
  drawCharts(result);
  lastResult = result;
}

var lastResult = null;
var themeObserver = null;

/* Redraw the charts in the other scheme's colours when the reader switches palettes. */
function followTheme() {
  if (themeObserver) themeObserver.disconnect();
  themeObserver = new MutationObserver(function () {
    if (lastResult) drawCharts(lastResult);
  });
  themeObserver.observe(document.body, { attributes: true, attributeFilter: ["data-md-color-scheme"] });
}

function init() {
  if (!$("tn-calculator") || !window.TrinormalCore) return;
  fillForm(stateFromUrl());
  FIELDS.concat(["precision"]).forEach(function (id) {
    $(id).addEventListener("input", function (event) {
      // the 3D view marks the input events it sends while a vertex is moved
      update(true, !!(event.detail && event.detail.fromView));
    });
  });
  $("winding").addEventListener("change", function () {
    update(true);
  });
  $("tn-flip").addEventListener("click", function () {
    var sel = $("winding");
    sel.value = sel.value === "ABC" ? "ACB" : "ABC";
    update(true);
  });
  update(false);
  followTheme();
  $("tn-calculator").setAttribute("data-ready", "true");
}

window.TrinormalSite.onEachPage(init);
