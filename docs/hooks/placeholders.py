"""``{{ trinormal:NAME ARGS }}`` in a page: text written by the package at build time.

The guide's tables and worked example, single values, CLI sessions, the calculator's result
rows, the input limits, the mesh page's examples and limits, the notebook list: generated
from the package, so a page can never disagree with the code.
"""

from __future__ import annotations

import contextlib
import html
import io
import os
import re
import shlex
from collections.abc import Callable
from unittest import mock

from api_reference import mesh_api_markdown
from mkdocs.config.defaults import MkDocsConfig
from mkdocs.structure.pages import Page
from notebook_pages import notebook_paths, notebook_summary, notebook_title
from site_paths import MESH_EXAMPLES, relative_root

from trinormal import guide

PLACEHOLDER = re.compile(r"\{\{\s*trinormal:(\w+)((?:\s+[^}]*?)?)\s*\}\}")


def _mistakes(args: list[str], page: Page, config: MkDocsConfig) -> str:
    return "\n".join(f"- **{name[:1].upper()}{name[1:]}.** {text}" for name, text in guide.MISTAKES)


def _value(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``value KEY A B C [winding] [precision] [trim]``: one formatted output of the package."""
    from trinormal import triangle_normal

    key, a, b, c, *rest = args
    winding = rest[0] if rest else "ABC"
    precision = int(rest[1]) if len(rest) > 1 else 4
    trim = len(rest) > 2 and rest[2] == "trim"
    pa, pb, pc = (tuple(p.split(",")) for p in (a, b, c))
    return str(triangle_normal(pa, pb, pc, winding=winding).format(precision, trim=trim)[key])


def _cli(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """Run ``trinormal ARGS`` through the CLI's main() and show the session as a console block."""
    from trinormal.cli import main

    out, err = io.StringIO(), io.StringIO()
    with (
        # argparse wraps --help to the terminal: keep builds reproducible
        mock.patch.dict(os.environ, {"COLUMNS": "88"}),
        contextlib.redirect_stdout(out),
        contextlib.redirect_stderr(err),
    ):
        try:
            status = main(args)
        except SystemExit as exc:  # argparse's --help exits
            status = exc.code if isinstance(exc.code, int) else 0
    text = out.getvalue() + err.getvalue()
    lines = ["```console", "$ trinormal " + shlex.join(args), text.rstrip("\n")]
    if status:
        lines.append(f"$ echo $?\n{status}")
    lines.append("```")
    return "\n".join(lines)


def _notebook_list(args: list[str], page: Page, config: MkDocsConfig) -> str:
    rows = []
    for path in notebook_paths():
        title = notebook_title(path)
        summary = notebook_summary(path)
        download = (
            f'<a href="{path.stem}/{path.name}" download>download <code>{path.name}</code></a>'
        )
        rows.append(
            f"- **[{title}](notebooks/{path.name})** ({download})"
            + (f"  \n  {summary}" if summary else "")
        )
    return "\n".join(rows) or "*No notebooks yet.*"


def _config_url(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``config_url repo_url|site_url [suffix]``: a URL from mkdocs.yml (no page hard-codes one)."""
    key, *rest = args
    url = str(config[key] or "").rstrip("/")
    if not url:
        raise ValueError(f"{page.file.src_uri}: mkdocs.yml sets no {key}")
    return url + (rest[0] if rest else "")


def _result_rows(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``result_rows``: one row per field of ``FIELDS``, filled for the starting triangle."""
    from trinormal import triangle_normal
    from trinormal.fields import FIELDS

    start = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).format(4)
    inputs = "ax ay az bx by bz cx cy cz winding precision"
    rows = []
    for i, field in enumerate(FIELDS):
        linked = f' for="{inputs}"' if i == 0 else ""
        rows.append(
            f'<tr><th scope="row">{html.escape(field.page_label)}</th>'
            f'<td><output id="{field.output_id}"{linked}>'
            f"{html.escape(start[field.key])}</output></td></tr>"
        )
    return "\n".join(rows)


def _limit(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``limit NAME``: one of the package's input limits, such as ``MAX_PRECISION``."""
    from trinormal.validation import limits

    (name,) = args
    return str(limits()[name])


def _mesh_examples(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``mesh_examples``: a button (list item) per example model of the mesh page."""
    from trinormal.mesh_page import EXAMPLES
    from trinormal.printmodel import SAMPLE

    root = relative_root(page)
    return "\n".join(
        f'<li><button type="button" class="md-button" data-example="{root}{MESH_EXAMPLES}/'
        f'{html.escape(name)}">{html.escape(label)}</button></li>'
        for name, label in [*EXAMPLES, SAMPLE[:2]]  # the damaged models, then a printable one
    )


def _mesh_limit(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``mesh_limit NAME``: one of the mesh page's limits: a size in MB, a count grouped."""
    from trinormal.mesh_page import LIMITS, file_size

    (name,) = args
    if name == "max_bytes":
        return file_size(LIMITS[name])
    return f"{LIMITS[name]:,}".replace(",", "\u202f")


def _mesh_units(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``mesh_units NAME``: one threshold of the units hint (`trinormal.mesh.printing.UNITS`)."""
    from trinormal.mesh.printing import UNITS, shown

    (name,) = args
    return shown(UNITS[name])


def _mesh_weld(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``mesh_weld auto|near|cap_fraction``: a weld distance over the size, or the caps' share."""
    from trinormal.mesh_page import site_constants

    (name,) = args
    return repr(site_constants()["weld"][name])


HANDLERS: dict[str, Callable[[list[str], Page, MkDocsConfig], str]] = {
    "comparison_table": lambda *_: guide.comparison_table_markdown(escape_pipes=True),
    "precision_table": lambda *_: guide.precision_table_markdown(),
    "worked_example": lambda *_: guide.worked_example_markdown(),
    "mistakes": _mistakes,
    "normalising_table": lambda *_: guide.normalising_table_markdown(),
    "value": _value,
    "cli": _cli,
    "notebook_list": _notebook_list,
    "config_url": _config_url,
    "result_rows": _result_rows,
    "limit": _limit,
    "mesh_examples": _mesh_examples,
    "mesh_limit": _mesh_limit,
    "mesh_units": _mesh_units,
    "mesh_api": lambda args, *_: mesh_api_markdown(args),
    "mesh_weld": _mesh_weld,
}


def fill_placeholders(markdown: str, page: Page, config: MkDocsConfig) -> str:
    """Replace every ``{{ trinormal:NAME ARGS }}`` in a page with what :data:`HANDLERS` writes."""

    def replace(m: re.Match[str]) -> str:
        name, rest = m.group(1), m.group(2).strip()
        if name not in HANDLERS:
            raise KeyError(f"{page.file.src_uri}: unknown placeholder trinormal:{name}")
        return HANDLERS[name](shlex.split(rest), page, config)

    return PLACEHOLDER.sub(replace, markdown)
