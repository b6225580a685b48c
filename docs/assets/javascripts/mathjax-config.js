/*
 * MathJax 3, served from this site (assets/vendor/mathjax/tex-svg-full.js).
 * Markdown pages wrap math in .arithmatex (pymdownx.arithmatex, generic mode);
 * notebook pages leave $...$ inside .jp-RenderedMarkdown / .jp-RenderedLatex,
 * so those classes are processed too and $ is a delimiter there.
 * When typesetting is done, <body data-math="typeset"> tells tests and readers so.
 */
window.MathJax = {
  tex: {
    inlineMath: [["\\(", "\\)"], ["$", "$"]],
    displayMath: [["\\[", "\\]"], ["$$", "$$"]],
    processEscapes: true,
    processEnvironments: true,
  },
  options: {
    ignoreHtmlClass: ".*|",
    processHtmlClass: "arithmatex|jp-RenderedMarkdown|jp-RenderedLatex|jp-RenderedHTMLCommon",
  },
  svg: { fontCache: "global" },
  startup: {
    pageReady: function () {
      return window.MathJax.startup.defaultPageReady().then(function () {
        document.body.setAttribute("data-math", "typeset");
      });
    },
  },
};
