/*
 * Boxes that scroll sideways (a wide table, equation or notebook output on a narrow screen) can be
 * reached and scrolled with the keyboard: while a box overflows it gets tabindex="0", the region
 * role and a name saying what it holds. Checked on load, after the math is rendered
 * ("tn:layout", from math.js) and whenever the window or the article changes size.
 */
(function () {
  "use strict";

  function overflows(el) {
    var x = getComputedStyle(el).overflowX;
    return (x === "auto" || x === "scroll") && el.scrollWidth > el.clientWidth;
  }

  function label(el) {
    if (el.querySelector("table") || el.tagName === "TABLE") return "Table, scrolls sideways";
    if (el.querySelector(".katex") || el.classList.contains("katex-display")) {
      return "Equation, scrolls sideways";
    }
    if (el.closest(".jp-OutputArea-output")) return "Cell output, scrolls sideways";
    if (el.querySelector("pre, code") || el.tagName === "PRE") return "Code, scrolls sideways";
    return "Content, scrolls sideways";
  }

  function update() {
    // every box in the article (not the tokens inside code or equations)
    var boxes = document.querySelectorAll(
      "article *:not(pre *):not(.katex *), article .katex-display, article pre",
    );
    Array.prototype.forEach.call(boxes, function (el) {
      if (overflows(el)) {
        if (el.hasAttribute("tabindex")) return;
        var added = ["tabindex"];
        el.setAttribute("tabindex", "0");
        var generic = el.tagName !== "TABLE"; // a table keeps its own role
        if (generic && !el.hasAttribute("role")) {
          added.push("role");
          el.setAttribute("role", "region");
        }
        if (generic && !el.hasAttribute("aria-label")) {
          added.push("aria-label");
          el.setAttribute("aria-label", label(el));
        }
        el.setAttribute("data-tn-scroll", added.join(" "));
      } else if (el.hasAttribute("data-tn-scroll")) {
        el.getAttribute("data-tn-scroll").split(" ").forEach(function (a) {
          el.removeAttribute(a);
        });
        el.removeAttribute("data-tn-scroll");
      }
    });
    document.body.setAttribute("data-scrollboxes", "checked");
  }

  var timer = null;
  function later() {
    clearTimeout(timer);
    timer = setTimeout(update, 100);
  }

  if (document.readyState === "complete") update();
  else window.addEventListener("load", update);
  document.addEventListener("tn:layout", update);
  window.addEventListener("resize", later);
  // content drawn later by a script (a live view, a chart) changes the article's size
  var article = document.querySelector("article");
  if (article && window.ResizeObserver) new ResizeObserver(later).observe(article);
})();
