"""Build hooks for the trinormal site: numbers from the package, notebooks, offline assets.

* ``{{ trinormal:NAME ARGS }}`` in a Markdown page is replaced at build time by
  text generated from the package (tables, the worked example, CLI sessions, the
  API reference), so a page can never disagree with the code.
* The Notebooks section of the navigation lists every ``notebooks/*.ipynb``.
* Notebook pages are post-processed: MathJax and widget loaders that point at a
  CDN are removed (the site loads its own MathJax), and each widget output is
  replaced by a note, a picture of the explorer and its plain-text readout,
  because a static page has no kernel to drive the sliders.
* ``assets/images/explorer.png`` is drawn from :class:`trinormal.widgets.Explorer`.
"""

from __future__ import annotations

import contextlib
import copy
import html
import io
import json
import logging
import os
import re
import shlex
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

from mkdocs.config.defaults import MkDocsConfig
from mkdocs.structure.files import File, Files
from mkdocs.structure.pages import Page

log = logging.getLogger("mkdocs.hooks.trinormal")

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
EXPLORER_PNG = "assets/images/explorer.png"
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"
PLACEHOLDER = re.compile(r"\{\{\s*trinormal:(\w+)((?:\s+[^}]*?)?)\s*\}\}")

# --------------------------------------------------------------------------- notebooks


def notebook_paths() -> list[Path]:
    """Every notebook the site renders, in file-name order (01_, 02_, ...)."""
    return sorted(p for p in NOTEBOOKS.glob("*.ipynb") if not p.name.startswith("."))


def notebook_title(path: Path) -> str:
    """The first Markdown heading of a notebook, or its file name."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "markdown":
            continue
        source = "".join(cell.get("source", []))
        for line in source.splitlines():
            m = re.match(r"#\s+(.+)", line.strip())
            if m:
                return m.group(1).strip()
    return path.stem.replace("_", " ")


def notebook_summary(path: Path) -> str:
    """The first paragraph after the title of a notebook, as one line of Markdown."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "markdown":
            continue
        text = "".join(cell.get("source", []))
        paras = [p.strip() for p in re.split(r"\n\s*\n", text) if p.strip()]
        for p in paras:
            if p.startswith(("#", "|", "-", "*", "$", "<", ">", "`")) or p[:2].isdigit():
                continue
            line = " ".join(p.split())
            return line if len(line) <= 240 else line[:237].rsplit(" ", 1)[0] + " …"
        if paras:
            continue
    return ""


def widget_note(text_plain: str) -> str:
    """HTML that stands in for one widget output on the static site."""
    readout = ""
    if text_plain.strip():
        readout = (
            "<p>The readout when the notebook was last run:</p>"
            f'<pre class="tn-widget-readout">{html.escape(text_plain.rstrip())}</pre>'
        )
    return (
        '<div class="admonition note tn-widget-note">'
        '<p class="admonition-title">Interactive widget</p>'
        "<p>In JupyterLab this output is interactive: drag a slider, flip the vertex order or "
        "change the decimal places, and the numbers and the figure follow. A static web page has "
        "no Python kernel to compute with, so here you see a picture of the explorer instead. "
        'For a live version in this browser, open the <a href="../../calculator/">Calculator</a>.'
        "</p>"
        f'<p><img src="../../{EXPLORER_PNG}" alt="{html.escape(explorer_alt())}" '
        'width="720" loading="lazy"></p>'
        f"{readout}</div>"
    )


def static_notebook(path: Path) -> dict[str, Any]:
    """A copy of a notebook with every widget output replaced by a static note."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    nb = copy.deepcopy(nb)
    nb.get("metadata", {}).pop("widgets", None)
    for cell in nb.get("cells", []):
        outputs = cell.get("outputs")
        if not outputs:
            continue
        new = []
        for out in outputs:
            data = out.get("data") or {}
            if WIDGET_VIEW in data or WIDGET_STATE in data:
                plain = data.get("text/plain", "")
                if isinstance(plain, list):
                    plain = "".join(plain)
                if re.fullmatch(r"\s*(?:[A-Z]\w*\(.*\))?\s*", plain, flags=re.S):
                    plain = ""  # a widget's repr, IntSlider(value=0), is noise, not a readout
                new.append(
                    {
                        "output_type": "display_data",
                        "metadata": {},
                        "data": {"text/html": widget_note(plain)},
                    }
                )
            else:
                new.append(out)
        cell["outputs"] = new
    return nb


_CDN_SCRIPT = re.compile(
    r"<script[^>]*\bsrc=\"(?:https?:)?//[^\"]*\"[^>]*>\s*</script>"  # any external script
    r"|<script[^>]*\bsrc=\"\"[^>]*>\s*</script>"  # the empty MathJax URL
    r"|<script type=\"text/x-mathjax-config\">.*?</script>"  # MathJax 2 configuration
    r"|<script type=\"module\">(?:(?!</script>).)*?mermaid(?:(?!</script>).)*?</script>",
    flags=re.S,
)


def clean_notebook_html(body: str) -> str:
    """Remove loaders that would fetch scripts from another origin."""
    body = _CDN_SCRIPT.sub("", body)
    body = re.sub(r"<!-- Load mathjax -->|<!-- MathJax configuration -->", "", body)
    body = body.replace("<!-- End of mathjax configuration -->", "")
    return body


def install_notebook_filter() -> None:
    """Wrap mkdocs-jupyter's converter so notebooks are rendered through the filters above."""
    from mkdocs_jupyter import plugin as nbplugin

    convert = nbplugin.convert
    if getattr(convert.nb2html, "_trinormal", False):
        return
    original: Callable[..., str] = convert.nb2html

    def nb2html(nb_path: str, *args: Any, **kwargs: Any) -> str:
        path = Path(nb_path)
        kwargs["custom_mathjax_url"] = ""
        if path.suffix != ".ipynb":
            return clean_notebook_html(original(nb_path, *args, **kwargs))
        nb = static_notebook(path)
        with tempfile.TemporaryDirectory() as tmp:
            copy_path = Path(tmp) / path.name
            copy_path.write_text(json.dumps(nb), encoding="utf-8")
            body = original(str(copy_path), *args, **kwargs)
        return clean_notebook_html(body)

    nb2html._trinormal = True  # type: ignore[attr-defined]
    convert.nb2html = nb2html


# --------------------------------------------------------------------------- the explorer picture

_explorer_cache: dict[str, Any] = {}


def _explorer() -> Any:
    if "ex" not in _explorer_cache:
        import matplotlib

        matplotlib.use("Agg")
        from trinormal.widgets import Explorer

        _explorer_cache["ex"] = Explorer(a=(0, 0, 0), b=(2, 0, 0), c=(0, 1, 1), precision=4)
    return _explorer_cache["ex"]


def explorer_png() -> bytes:
    """The explorer's figure for a tilted triangle, drawn by the package."""
    return bytes(_explorer().to_png())


def explorer_alt() -> str:
    """The package's own description of that figure."""
    return str(_explorer().alt_text)


# --------------------------------------------------------------------------- placeholders


def _comparison_table(args: list[str], page: Page, config: MkDocsConfig) -> str:
    from trinormal.guide import comparison_table_markdown

    return str(comparison_table_markdown(escape_pipes=True))


def _precision_table(args: list[str], page: Page, config: MkDocsConfig) -> str:
    from trinormal.guide import precision_table_markdown

    return str(precision_table_markdown())


def _worked_example(args: list[str], page: Page, config: MkDocsConfig) -> str:
    from trinormal.guide import worked_example_markdown

    return str(worked_example_markdown())


def _mistakes(args: list[str], page: Page, config: MkDocsConfig) -> str:
    from trinormal.guide import MISTAKES

    return "\n".join(f"- **{name[:1].upper()}{name[1:]}.** {text}" for name, text in MISTAKES)


def _value(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``value KEY A B C [winding] [precision] [trim]``: one formatted output of the package."""
    from trinormal import triangle_normal

    key, a, b, c, *rest = args
    winding = rest[0] if rest else "ABC"
    precision = int(rest[1]) if len(rest) > 1 else 4
    trim = len(rest) > 2 and rest[2] == "trim"
    pts = [tuple(p.split(",")) for p in (a, b, c)]
    return str(triangle_normal(*pts, winding=winding).format(precision, trim=trim)[key])


def _cli(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """Run ``trinormal ARGS`` through the CLI's main() and show the session as a console block."""
    from trinormal.cli import main

    out, err = io.StringIO(), io.StringIO()
    columns = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "88"  # argparse wraps --help to the terminal: keep builds reproducible
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(args)
        except SystemExit as exc:  # argparse's --help exits
            status = exc.code if isinstance(exc.code, int) else 0
        finally:
            if columns is None:
                os.environ.pop("COLUMNS", None)
            else:
                os.environ["COLUMNS"] = columns
    text = out.getvalue() + err.getvalue()
    lines = ["```console", "$ trinormal " + shlex.join(args), text.rstrip("\n")]
    if status:
        lines.append(f"$ echo $?\n{status}")
    lines.append("```")
    return "\n".join(lines)


def _api(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """One mkdocstrings section per public module of the package."""
    titles = {
        "core": "The exact core",
        "display": "Display formatting",
        "tolerances": "Tolerances",
        "symbolic": "Symbolic derivations",
        "mesh": "Meshes",
        "plotting": "Plotting",
        "widgets": "The explorer widget",
        "guide": "The guide's numbers",
        "exercises": "Exercises",
        "cli": "Command line",
    }
    order = list(titles)
    mods = sorted(
        (p.stem for p in (ROOT / "trinormal").glob("*.py") if not p.stem.startswith("_")),
        key=lambda m: (order.index(m) if m in order else len(order), m),
    )
    parts = []
    for mod in mods:
        title = titles.get(mod, mod)
        parts.append(f"## {title}: `trinormal.{mod}`\n\n::: trinormal.{mod}\n")
    return "\n".join(parts)


def _notebook_list(args: list[str], page: Page, config: MkDocsConfig) -> str:
    rows = []
    for path in notebook_paths():
        title = notebook_title(path)
        summary = notebook_summary(path)
        link = f"notebooks/{path.name}"
        href = f"{path.stem}/{path.name}"
        download = f'<a href="{href}" download>download <code>{path.name}</code></a>'
        rows.append(
            f"- **[{title}]({link})** ({download})" + (f"  \n  {summary}" if summary else "")
        )
    if not rows:
        return "*No notebooks yet.*"
    return "\n".join(rows)


def _explorer_alt(args: list[str], page: Page, config: MkDocsConfig) -> str:
    return explorer_alt().replace("[", "(").replace("]", ")")


HANDLERS: dict[str, Callable[[list[str], Page, MkDocsConfig], str]] = {
    "explorer_alt": _explorer_alt,
    "comparison_table": _comparison_table,
    "precision_table": _precision_table,
    "worked_example": _worked_example,
    "mistakes": _mistakes,
    "value": _value,
    "cli": _cli,
    "api": _api,
    "notebook_list": _notebook_list,
}


# --------------------------------------------------------------------------- mkdocs events


def on_config(config: MkDocsConfig) -> MkDocsConfig:
    install_notebook_filter()
    nav = config.nav or []
    for item in nav:
        if isinstance(item, dict) and "Notebooks" in item:
            first = [e for e in item["Notebooks"] if not str(e).startswith("notebooks/")]
            item["Notebooks"] = first + [f"notebooks/{p.name}" for p in notebook_paths()]
    return config


def on_files(files: Files, config: MkDocsConfig) -> Files:
    files.append(File.generated(config, EXPLORER_PNG, content=explorer_png()))
    return files


def on_page_markdown(markdown: str, page: Page, config: MkDocsConfig, files: Files) -> str:
    def replace(m: re.Match[str]) -> str:
        name, rest = m.group(1), m.group(2).strip()
        if name not in HANDLERS:
            raise KeyError(f"{page.file.src_uri}: unknown placeholder trinormal:{name}")
        return HANDLERS[name](shlex.split(rest), page, config)

    return PLACEHOLDER.sub(replace, markdown)
