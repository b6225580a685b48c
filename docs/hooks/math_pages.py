"""KaTeX on the pages that have math, and only there; every other page loads no math engine.

KaTeX is served from the site itself (``assets/vendor/katex/``, copied from npm by
``js/vendor/copy-vendor.mjs``), with ``assets/javascripts/math.js`` to start it.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

from mkdocs.structure.pages import Page
from site_paths import relative_root

KATEX = "assets/vendor/katex/"

MATH_SCRIPTS = (KATEX + "katex.min.js", KATEX + "auto-render.min.js", "assets/javascripts/math.js")

_TEX_IN_MARKDOWN = re.compile(r"\$|\\\(|\\\[")


def notebook_has_math(path: Path) -> bool:
    """True when a notebook has TeX in a Markdown cell or a ``text/latex`` output (sympy)."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    for cell in nb.get("cells", []):
        if cell.get("cell_type") == "markdown" and _TEX_IN_MARKDOWN.search(
            "".join(cell.get("source", []))
        ):
            return True
        if any("text/latex" in (o.get("data") or {}) for o in cell.get("outputs", [])):
            return True
    return False


def page_has_math(output: str, page: Page) -> bool:
    """True when the rendered page holds math for KaTeX to render."""
    if 'class="arithmatex"' in output:
        return True
    src = page.file.abs_src_path
    return bool(src and src.endswith(".ipynb") and notebook_has_math(Path(src)))


def add_math_engine(output: str, page: Page) -> str:
    """Link KaTeX's stylesheet in the head and its scripts (deferred) at the end of the body."""
    root = relative_root(page)
    link = f'<link rel="stylesheet" href="{root}{KATEX}katex.min.css">'
    scripts = "".join(f'<script defer src="{root}{src}"></script>' for src in MATH_SCRIPTS)
    output = output.replace("</head>", link + "</head>", 1)
    end = output.rfind("</body>")
    return output[:end] + scripts + output[end:]
