/*
 * Math on the pages that have it: KaTeX, served from this site (assets/vendor/katex/).
 * The build hook adds KaTeX and this file only to pages with math; other pages load no math engine.
 *
 * Markdown pages wrap math in .arithmatex (pymdownx.arithmatex, generic mode): \( ... \) in a
 * <span>, \[ ... \] in a <div>. Notebook pages leave $...$ in .jp-RenderedMarkdown (Markdown cells)
 * and .jp-RenderedLatex (sympy's LaTeX outputs). Code (pre, code) is never touched.
 * When everything is rendered (fonts included), <body data-math="typeset"> tells tests so.
 */
(function () {
  "use strict";

  var OPTIONS = { throwOnError: false, strict: "ignore", output: "htmlAndMathml" };

  function renderArithmatex(el) {
    var tex = el.textContent.trim();
    var display = el.tagName === "DIV";
    var m = /^\\\(([\s\S]*)\\\)$/.exec(tex) || /^\\\[([\s\S]*)\\\]$/.exec(tex);
    if (m) tex = m[1];
    window.katex.render(tex, el, Object.assign({ displayMode: display }, OPTIONS));
  }

  function renderNotebook(el) {
    window.renderMathInElement(
      el,
      Object.assign(
        {
          delimiters: [
            { left: "$$", right: "$$", display: true },
            { left: "\\[", right: "\\]", display: true },
            { left: "\\(", right: "\\)", display: false },
            { left: "$", right: "$", display: false },
          ],
          ignoredTags: ["script", "noscript", "style", "textarea", "pre", "code", "option"],
        },
        OPTIONS,
      ),
    );
  }

  function render() {
    document.querySelectorAll(".md-content .arithmatex").forEach(renderArithmatex);
    document
      .querySelectorAll(".jp-RenderedMarkdown, .jp-RenderedLatex")
      .forEach(renderNotebook);
    // KaTeX's fonts load once the rendered math is laid out; only then do equations have their
    // final width. Then tell the scroll boxes (scrollboxes.js), tests and readers.
    void document.body.offsetWidth;
    document.fonts.ready.then(function () {
      document.body.setAttribute("data-math", "typeset");
      document.dispatchEvent(new CustomEvent("tn:layout"));
    });
  }

  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", render);
  } else {
    render();
  }
})();
