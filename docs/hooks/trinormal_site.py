"""The mkdocs hook of the trinormal site: each build event hands its work to a module beside it.

mkdocs loads this file (``hooks:`` in mkdocs.yml) with docs/hooks/ on ``sys.path``, so the
modules beside it import by their names; each is named for what it answers:

* ``placeholders`` — ``{{ trinormal:NAME ARGS }}`` in a page, written by the package;
* ``notebook_pages`` — the Notebooks section, each page without widgets or a CDN;
* ``live_explorer`` — the live view on the explorer notebook's page;
* ``explorer_picture`` — ``assets/images/explorer.png`` and its alt text;
* ``site_constants`` — ``assets/javascripts/trinormal-constants.js`` (the tests import
  ``site_constants`` and ``constants_js`` from this module);
* ``math_pages`` — KaTeX on the pages that have math, and only there;
* ``search_text`` — the search index with its math as plain text;
* ``api_reference`` — the API pages link every mention of a public name;
* ``site_paths`` — where files come from and go.

Here: the site's build of the 3D views (``trinormal/explorer/static/site-modules/``: one
module per view, their shared chunk and the licence file, built from ``js/explorer/``) is
copied to ``assets/explorer/``, with the constants file and the mesh page's example models.
"""

from __future__ import annotations

from typing import Any

from api_reference import link_public_names
from explorer_picture import explorer_png
from math_pages import add_math_engine, page_has_math
from mkdocs.config.defaults import MkDocsConfig
from mkdocs.structure.files import File, Files
from mkdocs.structure.pages import Page
from notebook_pages import install_notebook_filter, notebooks_nav
from placeholders import fill_placeholders
from search_text import readable_search_index
from site_constants import constants_js, site_constants
from site_paths import CONSTANTS_JS, EXPLORER_ASSETS, EXPLORER_PNG, EXPLORER_STATIC, MESH_EXAMPLES

__all__ = [
    "add_explorer_assets",
    "constants_js",
    "on_config",
    "on_env",
    "on_files",
    "on_page_markdown",
    "on_post_build",
    "on_post_page",
    "site_constants",
]


def on_config(config: MkDocsConfig) -> MkDocsConfig:
    install_notebook_filter()
    notebooks_nav(config.nav or [])
    return config


def on_files(files: Files, config: MkDocsConfig) -> Files:
    files.append(File.generated(config, EXPLORER_PNG, content=explorer_png()))
    add_explorer_assets(files, config)
    return files


def add_explorer_assets(files: Files, config: MkDocsConfig) -> None:
    """The 3D views' site modules and licence under ``assets/explorer/``, and the constants file."""
    site = EXPLORER_STATIC / "site-modules"  # the site's build of the views (js/explorer/build.mjs)
    static = sorted(p for p in site.glob("*") if p.is_file())
    if not any(p.name == "explorer.js" for p in static):
        raise FileNotFoundError(f"{site / 'explorer.js'} is missing: run `make js`")
    for path in static:
        files.append(
            File.generated(config, f"{EXPLORER_ASSETS}/{path.name}", abs_src_path=str(path))
        )
    files.append(File.generated(config, CONSTANTS_JS, content=constants_js()))
    from trinormal.mesh_page import EXAMPLES, example_file

    for name, _ in EXAMPLES:
        files.append(File.generated(config, f"{MESH_EXAMPLES}/{name}", content=example_file(name)))
    from trinormal.printmodel import SAMPLE, sample_file

    files.append(File.generated(config, f"{MESH_EXAMPLES}/{SAMPLE[0]}", content=sample_file()))


def on_page_markdown(markdown: str, page: Page, config: MkDocsConfig, files: Files) -> str:
    return fill_placeholders(markdown, page, config)


def on_env(env: Any, config: MkDocsConfig, files: Files) -> Any:
    link_public_names(config, files)
    return env


def on_post_page(output: str, page: Page, config: MkDocsConfig) -> str:
    if page_has_math(output, page):
        output = add_math_engine(output, page)
    return output


def on_post_build(config: MkDocsConfig) -> None:
    readable_search_index(config.site_dir)
