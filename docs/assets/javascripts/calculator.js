/*
 * The Calculator page: reads the nine coordinates, the winding and the precision,
 * computes with TrinormalCore (exact, the same strings as the Python package) on
 * every keystroke, draws the bar chart of N and keeps the state in the URL.
 */
(function () {
  "use strict";

  var FIELDS = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"];
  var OUTPUTS = {
    u: "out-u",
    v: "out-v",
    normal: "out-normal",
    magnitude: "out-magnitude",
    area: "out-area",
    unit_normal: "out-unit",
    plane: "out-plane",
  };
  var DEFAULTS = { a: ["0", "0", "0"], b: ["1", "0", "0"], c: ["0", "1", "0"], w: "ABC", p: 4 };
  var DASH = "\u2014";
  var SVG_NS = "http://www.w3.org/2000/svg";
  var COLORS = ["#D55E00", "#009E73", "#0072B2"]; // Okabe-Ito, as trinormal.plotting.AXIS_COLORS

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
      if (/^\d{1,2}$/.test(p) && Number(p) <= 10) state.p = Number(p);
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

  function readPrecision(text) {
    var s = String(text).trim();
    if (!/^\d{1,2}$/.test(s) || Number(s) > 10) return null;
    return Number(s);
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

  function clearChart(svg, message) {
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    var t = document.createElementNS(SVG_NS, "text");
    t.setAttribute("x", "50%");
    t.setAttribute("y", "50%");
    t.setAttribute("text-anchor", "middle");
    t.setAttribute("class", "tn-chart-note");
    t.textContent = message;
    svg.appendChild(t);
  }

  function drawChart(result) {
    var svg = $("chart");
    if (!result.ok) {
      svg.setAttribute("aria-label", "Bar chart of the normal components: no chart, the input is not readable.");
      clearChart(svg, "No chart: fix the input first.");
      return;
    }
    var parts = result.out.normal.slice(1, -1).split(", ");
    var names = ["Nx", "Ny", "Nz"];
    var label = names
      .map(function (n, i) {
        return n + " = " + parts[i];
      })
      .join(", ");
    svg.setAttribute("aria-label", "Bar chart of the normal components: " + label + ".");
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    var width = 480;
    var rowH = 44;
    var left = 48;
    var mid = left + (width - left - 16) / 2;
    var half = (width - left - 16) / 2;
    var axis = document.createElementNS(SVG_NS, "line");
    axis.setAttribute("x1", mid);
    axis.setAttribute("x2", mid);
    axis.setAttribute("y1", 4);
    axis.setAttribute("y2", 3 * rowH + 4);
    axis.setAttribute("class", "tn-chart-axis");
    svg.appendChild(axis);
    result.chart.forEach(function (value, i) {
      var y = i * rowH + 10;
      var name = document.createElementNS(SVG_NS, "text");
      name.setAttribute("x", 8);
      name.setAttribute("y", y + 20);
      name.setAttribute("class", "tn-chart-label");
      name.textContent = names[i];
      svg.appendChild(name);
      var len = Math.abs(value) * half;
      var bar = document.createElementNS(SVG_NS, "rect");
      bar.setAttribute("x", value < 0 ? mid - len : mid);
      bar.setAttribute("y", y);
      bar.setAttribute("width", Math.max(len, 0));
      bar.setAttribute("height", 28);
      bar.setAttribute("fill", COLORS[i]);
      svg.appendChild(bar);
      var text = document.createElementNS(SVG_NS, "text");
      var right = value >= 0;
      text.setAttribute("x", right ? mid - 6 : mid + 6);
      text.setAttribute("y", y + 20);
      text.setAttribute("text-anchor", right ? "end" : "start");
      text.setAttribute("class", "tn-chart-value");
      text.textContent = parts[i];
      svg.appendChild(text);
    });
  }

  function update(pushUrl) {
    var state = readForm();
    if (pushUrl) writeUrl(state);
    var status = $("out-status");
    var p = readPrecision(state.p);
    var result;
    if (p === null) {
      result = {
        ok: false,
        field: "precision",
        status: "Precision must be a whole number from 0 to 10, got " + JSON.stringify(String(state.p)),
      };
    } else {
      result = window.TrinormalCore.compute(state.a, state.b, state.c, state.w, p);
    }
    Object.keys(OUTPUTS).forEach(function (key) {
      $(OUTPUTS[key]).textContent = result.ok ? result.out[key] : DASH;
    });
    status.textContent = result.status;
    status.setAttribute("data-state", !result.ok ? "error" : result.degenerate ? "degenerate" : "ok");
    setInvalid(result.ok ? null : fieldId(result.field));
    drawChart(result);
  }

  function init() {
    if (!$("tn-calculator") || !window.TrinormalCore) return;
    fillForm(stateFromUrl());
    FIELDS.concat(["precision"]).forEach(function (id) {
      $(id).addEventListener("input", function () {
        update(true);
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
    $("tn-calculator").setAttribute("data-ready", "true");
  }

  if (window.document$ && typeof window.document$.subscribe === "function") {
    window.document$.subscribe(init);
  } else if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", init);
  } else {
    init();
  }
})();
