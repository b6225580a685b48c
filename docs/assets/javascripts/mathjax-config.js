/*
 * MathJax 3, served from this site (assets/vendor/mathjax/tex-svg-full.js).
 * Markdown pages wrap math in .arithmatex (pymdownx.arithmatex, generic mode);
 * notebook pages leave $...$ inside .jp-RenderedMarkdown / .jp-RenderedLatex,
 * so $ is a delimiter as well. MathJax skips pre/code by default; the site's chrome and the
 * calculator are ignored explicitly. (Material's usual ignoreHtmlClass ".*|" would also ignore
 * the <p> children of a notebook's Markdown cell, leaving its math raw.)
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
    ignoreHtmlClass: "tex2jax_ignore|mathjax_ignore|md-header|md-footer|md-nav|md-sidebar|md-search|tn-calculator",
    processHtmlClass: "tex2jax_process|mathjax_process|arithmatex|jp-RenderedMarkdown|jp-RenderedLatex",
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
