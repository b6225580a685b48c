"""Where the site's files come from in the repository and where the build puts them."""

from __future__ import annotations

from pathlib import Path

from mkdocs.structure.pages import Page

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
#: The 3D view's bundle and its licence file, built from js/explorer/ (``make js``).
EXPLORER_STATIC = ROOT / "trinormal" / "explorer" / "static"
EXPLORER_PNG = "assets/images/explorer.png"
EXPLORER_ASSETS = "assets/explorer"
CONSTANTS_JS = "assets/javascripts/trinormal-constants.js"
MESH_EXAMPLES = "assets/meshes"


def relative_root(page: Page) -> str:
    """The way from a page's URL back to the site root (``guide/method/`` -> ``../../``)."""
    return "../" * page.url.count("/")
