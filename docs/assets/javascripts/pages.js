/*
 * Runs a script's set-up on every page: with Material's instant navigation (its document$
 * observable) after each page it shows, else once the document is parsed. calculator.js and
 * explorer-site.js mount through it; it comes before them in mkdocs.yml.
 */
(function () {
  "use strict";

  function onEachPage(init) {
    if (window.document$ && typeof window.document$.subscribe === "function") {
      window.document$.subscribe(init);
    } else if (document.readyState === "loading") {
      document.addEventListener("DOMContentLoaded", init);
    } else {
      init();
    }
  }

  window.TrinormalSite = { onEachPage: onEachPage };
})();
