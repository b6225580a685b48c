"""Build hooks for the trinormal site: numbers from the package, notebooks, offline assets.

* ``{{ trinormal:NAME ARGS }}`` in a Markdown page is replaced at build time by
  text generated from the package (tables, the worked example, CLI sessions, the
  API reference), so a page can never disagree with the code.
* The Notebooks section of the navigation lists every ``notebooks/*.ipynb``.
* Notebook pages are post-processed: MathJax and widget loaders that point at a
  CDN are removed, and each widget output is
  replaced by a note, a picture of the explorer and its plain-text readout,
  because a static page has no kernel to drive the sliders.
* ``assets/images/explorer.png`` is drawn from :class:`trinormal.widgets.Explorer`.
* The 3D view (``trinormal/explorer/static/``: the bundle built from ``js/explorer/``
  and its licence file) is copied to ``assets/explorer/``, and
  ``assets/javascripts/trinormal-constants.js`` is written from the package: the
  output fields, the colour code, the input limits and messages, the precision range and
  the view's grid and range.
  On the explorer notebook's page the explorer's output becomes that live view.
* Pages with math (and only those) get KaTeX (``assets/vendor/katex/``, copied from
  npm by ``js/vendor/copy-vendor.mjs``) and ``assets/javascripts/math.js``; the search
  index gets its math as plain text (``on_post_build``).
"""

from __future__ import annotations

import ast
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
from typing import Any, TypeGuard

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
EXPLORER_STATIC = ROOT / "trinormal" / "explorer" / "static"
EXPLORER_ASSETS = "assets/explorer"
CONSTANTS_JS = "assets/javascripts/trinormal-constants.js"
MESH_EXAMPLES = "assets/meshes"

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


def mesh_view_note(text_plain: str) -> str:
    """HTML that stands in for a mesh view (``trinormal.mesh.widget.MeshView``) on the site."""
    return (
        '<div class="admonition note tn-widget-note">'
        '<p class="admonition-title">Interactive 3D view</p>'
        "<p>In JupyterLab this output is the 3D view of the mesh: turn it, switch culling, "
        "smooth shading and the normal arrows, and click a face to read its exact normal. A "
        "static web page has no Python kernel, so here you read the view's summary from the last "
        "run of the notebook. To look at a model in this browser, open "
        '<a href="../../mesh/">Check a mesh</a>.</p>'
        f'<pre class="tn-widget-readout">{html.escape(text_plain.strip())}</pre></div>'
    )


def picture_output(out: dict[str, Any]) -> dict[str, Any]:
    """A PNG output as an ``<img>`` with its alt text and display width.

    ``trinormal.plotting.show`` stores both in the output's metadata; the notebook
    template the site uses would drop them (and write "No description has been
    provided for this image").
    """
    data = out["data"]
    meta = out.get("metadata", {}).get("image/png", {})
    alt = str(meta.get("alt", "")).strip()
    if not alt:
        return out
    png = data["image/png"]
    png = "".join(png) if isinstance(png, list) else str(png)
    width = meta.get("width")
    size = f' width="{int(width)}"' if isinstance(width, int | float) else ""
    img = (
        f'<img src="data:image/png;base64,{png.strip()}" alt="{html.escape(alt)}"{size} '
        'style="max-width:100%;height:auto">'
    )
    return {"output_type": "display_data", "metadata": {}, "data": {"text/html": img}}


def static_notebook(path: Path) -> dict[str, Any]:
    """A copy of a notebook with every widget output replaced by a static note.

    On the explorer notebook's page the explorer's output is replaced by the live
    3D view instead (see :func:`explorer_outputs`), with the note as its fallback.
    """
    nb = json.loads(path.read_text(encoding="utf-8"))
    nb = copy.deepcopy(nb)
    live = explorer_outputs(nb, path)
    nb.get("metadata", {}).pop("widgets", None)
    for cell in nb.get("cells", []):
        outputs = cell.get("outputs")
        if not outputs:
            continue
        new = []
        for out in outputs:
            data = out.get("data") or {}
            if id(out) in live:
                new.append(
                    {
                        "output_type": "display_data",
                        "metadata": {},
                        "data": {"text/html": live_explorer_html(live[id(out)])},
                    }
                )
            elif "image/png" in data and isinstance(out.get("metadata"), dict):
                new.append(picture_output(out))
            elif WIDGET_VIEW in data or WIDGET_STATE in data:
                plain = data.get("text/plain", "")
                if isinstance(plain, list):
                    plain = "".join(plain)
                if re.fullmatch(r"\s*(?:[A-Z]\w*\(.*\))?\s*", plain, flags=re.S):
                    plain = ""  # a widget's repr, IntSlider(value=0), is noise, not a readout
                mesh_view = plain.startswith("Mesh view:")
                note = mesh_view_note(plain) if mesh_view else widget_note(plain)
                new.append(
                    {
                        "output_type": "display_data",
                        "metadata": {},
                        "data": {"text/html": note},
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


# --------------------------------------------------------------------------- the live 3D view

#: The keys of an ExplorerView's stored widget state that the site's view reads.
EXPLORER_KEYS = (
    "a",
    "b",
    "c",
    "winding",
    "precision",
    "step",
    "bounds",
    "show_parallelogram",
    "show_unit_normal",
)


def view_defaults() -> dict[str, Any]:
    """The view's grid step and coordinate range, as the package's ExplorerView sets them."""
    from trinormal.explorer.view import ExplorerView

    traits = ExplorerView.class_traits()
    return {
        "step": str(traits["step"].default()),
        "bounds": [float(x) for x in traits["bounds"].default()],
        "a": list(traits["a"].default()),
        "b": list(traits["b"].default()),
        "c": list(traits["c"].default()),
    }


def site_constants() -> dict[str, Any]:
    """Everything the site's hand-written JavaScript must not list itself."""
    from trinormal.colors import palette
    from trinormal.core import VERDICTS
    from trinormal.display import SCI_ABOVE_LOG10
    from trinormal.fields import fields_spec
    from trinormal.validation import MESSAGES, limits

    view = view_defaults()
    limit = limits()
    return {
        "fields": fields_spec(),
        "palette": palette(),
        "precision": {"min": limit["min_precision"], "max": limit["max_precision"]},
        "limits": limit,
        "messages": dict(MESSAGES),
        "verdicts": dict(VERDICTS),
        "format": {"sci_above_log10": SCI_ABOVE_LOG10},
        "view": {"step": view["step"], "bounds": view["bounds"]},
        "mesh": mesh_page_constants(),
    }


def mesh_page_constants() -> dict[str, Any]:
    """The mesh page's messages, limits, report rows and tolerance, from the package."""
    from trinormal.mesh_page import site_constants as mesh_constants

    return mesh_constants()


def constants_js() -> str:
    """``assets/javascripts/trinormal-constants.js``: :func:`site_constants` as one object."""
    body = json.dumps(site_constants(), ensure_ascii=False, indent=1)
    return (
        "/* Written at build time by docs/hooks/trinormal_site.py from the trinormal package\n"
        " * (trinormal.fields, .colors, .validation and .explorer): do not edit. */\n"
        f"window.TRINORMAL_CONSTANTS = {body};\n"
    )


def _widget_models(nb: dict[str, Any]) -> dict[str, Any]:
    meta = nb.get("metadata", {}).get("widgets", {}).get(WIDGET_STATE, {})
    models = meta.get("state", {}) if isinstance(meta, dict) else {}
    return models if isinstance(models, dict) else {}


def _is_explorer_view(model: Any) -> bool:
    if not isinstance(model, dict):
        return False
    state = model.get("state") or {}
    names = (str(state.get("_anywidget_id", "")), str(model.get("model_name", "")))
    if any(n.endswith("ExplorerView") for n in names):
        return True
    return model.get("model_module") == "anywidget" and {"a", "b", "c", "winding"} <= set(state)


def _find_explorer(models: dict[str, Any], model_id: str, seen: set[str]) -> dict[str, Any] | None:
    """The ExplorerView's state under a widget (itself or a child, at any depth)."""
    if model_id in seen or model_id not in models:
        return None
    seen.add(model_id)
    model = models[model_id]
    if _is_explorer_view(model):
        return dict(model.get("state") or {})
    state = model.get("state") or {}
    children = state.get("children") or []
    for child in children if isinstance(children, list) else []:
        if isinstance(child, str) and child.startswith("IPY_MODEL_"):
            found = _find_explorer(models, child[len("IPY_MODEL_") :], seen)
            if found is not None:
                return found
    return None


def _literal_kwargs(call: ast.Call) -> dict[str, Any]:
    found: dict[str, Any] = {}
    for kw in call.keywords:
        if kw.arg in EXPLORER_KEYS:
            with contextlib.suppress(ValueError, TypeError, SyntaxError):
                found[kw.arg] = ast.literal_eval(kw.value)
    return found


def _is_explorer_call(node: object) -> TypeGuard[ast.Call]:
    if not isinstance(node, ast.Call):
        return False
    name = getattr(node.func, "id", None) or getattr(node.func, "attr", None)
    return name == "Explorer"


def _explorer_shown(source: str, known: dict[str, dict[str, Any]]) -> dict[str, Any] | None:
    """What a cell shows of an explorer, from its source: the literal arguments, or None.

    ``known`` maps variable names to the explorers made so far (``ex = Explorer(...)``,
    updated by ``ex.set(...)``); the cell's assignments and calls update it. The cell shows
    an explorer when its last line is ``Explorer(...)``, a known name or an attribute of one
    (``ex``, ``ex.view``), or when it calls ``Explorer(...)`` anywhere (``display(...)``).
    """
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return None
    for stmt in tree.body:
        value = getattr(stmt, "value", None)
        if isinstance(stmt, ast.Assign) and _is_explorer_call(value):
            for target in stmt.targets:
                if isinstance(target, ast.Name):
                    known[target.id] = _literal_kwargs(value)
        elif (
            isinstance(stmt, ast.Expr)
            and isinstance(value, ast.Call)
            and isinstance(value.func, ast.Attribute)
            and value.func.attr == "set"
            and isinstance(value.func.value, ast.Name)
            and value.func.value.id in known
        ):
            known[value.func.value.id] = {
                **known[value.func.value.id],
                **_literal_kwargs(value),
            }
    last = tree.body[-1] if tree.body else None
    if isinstance(last, ast.Expr):
        node = last.value
        if _is_explorer_call(node):
            return _literal_kwargs(node)
        while isinstance(node, ast.Attribute):
            node = node.value
        if isinstance(node, ast.Name) and node.id in known:
            return dict(known[node.id])
    for node in ast.walk(tree):
        if _is_explorer_call(node):
            return _literal_kwargs(node)
    return None


def _view_init(values: dict[str, Any]) -> dict[str, Any]:
    """Initial values for the site's view: the explorer's own defaults, then ``values``."""
    from trinormal.explorer.state import coordinate_text

    init: dict[str, Any] = {k: v for k, v in view_defaults().items()}
    for key in EXPLORER_KEYS:
        if key not in values:
            continue
        value = values[key]
        if key in ("a", "b", "c"):
            try:
                value = [
                    coordinate_text(x, f"{key.upper()}.{'xyz'[i]}") for i, x in enumerate(value)
                ]
            except (TypeError, ValueError):
                continue
            if len(value) != 3:
                continue
        init[key] = value
    init["show_readout"] = True
    return init


def explorer_outputs(nb: dict[str, Any], path: Path) -> dict[int, dict[str, Any]]:
    """The outputs of a notebook that show an explorer, by ``id()``, with the view's initial values.

    An output shows an explorer when the widget it displays is, or contains, an
    ``ExplorerView`` in the notebook's stored widget state; its stored values
    start the live view. On the explorer notebook (``*explorer*.ipynb``) with no
    ExplorerView in its stored widget state (``make notebooks`` stores none), the first
    widget output of each cell that shows an explorer (see :func:`_explorer_shown`) is
    used, started from the literal arguments in the notebook's code (or the explorer's
    defaults).
    """
    models = _widget_models(nb)
    found: dict[int, dict[str, Any]] = {}
    has_view = any(_is_explorer_view(m) for m in models.values())
    is_explorer_notebook = "explorer" in path.stem and not has_view
    known: dict[str, dict[str, Any]] = {}
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "code":
            continue
        source = cell.get("source", "")
        source = "".join(source) if isinstance(source, list) else str(source)
        call = _explorer_shown(source, known) if is_explorer_notebook else None
        for out in cell.get("outputs") or []:
            data = out.get("data") or {}
            view = data.get(WIDGET_VIEW)
            if not isinstance(view, dict):
                continue
            state = _find_explorer(models, str(view.get("model_id", "")), set())
            if state is not None:
                found[id(out)] = _view_init(state)
            elif call is not None:
                found[id(out)] = _view_init(call)
                call = None  # one live view per cell
    return found


def live_explorer_html(init: dict[str, Any]) -> str:
    """The live 3D view (mounted by explorer-site.js), with the picture as its fallback."""
    data = html.escape(json.dumps(init, ensure_ascii=False), quote=True)
    return (
        f'<div class="tn-explorer-live" data-explorer="{data}">'
        '<p class="tn-explorer-caption">This is the notebook\'s explorer, live in your browser: '
        "turn the view, drag A, B or C, flip the order, show the parallelogram. There is no "
        "Python kernel here: this page computes with its own exact arithmetic, which prints the "
        "same numbers as the package. The notebook's sliders and text boxes are not shown.</p>"
        '<noscript><div class="admonition note tn-widget-note tn-explorer-fallback">'
        '<p class="admonition-title">Interactive widget</p>'
        "<p>With JavaScript on, this page shows the explorer live. Here is a picture of it.</p>"
        f'<p><img src="../../{EXPLORER_PNG}" alt="{html.escape(explorer_alt())}" '
        'width="720" loading="lazy"></p>'
        "</div></noscript></div>"
    )


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


def _normalising_table(args: list[str], page: Page, config: MkDocsConfig) -> str:
    from trinormal.guide import normalising_table_markdown

    return str(normalising_table_markdown())


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
    "normalising_table": _normalising_table,
    "value": _value,
    "cli": _cli,
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
    add_explorer_assets(files, config)
    return files


def add_explorer_assets(files: Files, config: MkDocsConfig) -> None:
    """The 3D view's bundle and licence under ``assets/explorer/``, and the constants file."""
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


def on_page_markdown(markdown: str, page: Page, config: MkDocsConfig, files: Files) -> str:
    def replace(m: re.Match[str]) -> str:
        name, rest = m.group(1), m.group(2).strip()
        if name not in HANDLERS:
            raise KeyError(f"{page.file.src_uri}: unknown placeholder trinormal:{name}")
        return HANDLERS[name](shlex.split(rest), page, config)

    return PLACEHOLDER.sub(replace, markdown)


# --------------------------------------------------------------------------- math and search
# KaTeX is added only to pages that have math; every other page loads no math engine.

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


def relative_root(page: Page) -> str:
    """The way from a page's URL back to the site root (``guide/method/`` -> ``../../``)."""
    return "../" * page.url.count("/")


def add_math_engine(output: str, page: Page) -> str:
    """Link KaTeX's stylesheet in the head and its scripts (deferred) at the end of the body."""
    root = relative_root(page)
    link = f'<link rel="stylesheet" href="{root}{KATEX}katex.min.css">'
    scripts = "".join(f'<script defer src="{root}{src}"></script>' for src in MATH_SCRIPTS)
    output = output.replace("</head>", link + "</head>", 1)
    end = output.rfind("</body>")
    return output[:end] + scripts + output[end:]


def on_post_page(output: str, page: Page, config: MkDocsConfig) -> str:
    if page_has_math(output, page):
        output = add_math_engine(output, page)
    return output


_SUPERSCRIPTS = str.maketrans("0123456789+-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻")
_SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_TEX_SYMBOLS = {
    "times": "×",
    "cdot": "·",
    "cdots": "⋯",
    "ldots": "…",
    "dots": "…",
    "theta": "θ",
    "alpha": "α",
    "beta": "β",
    "gamma": "γ",
    "epsilon": "ε",
    "varepsilon": "ε",
    "lambda": "λ",
    "pi": "π",
    "Rightarrow": "⇒",
    "rightarrow": "→",
    "to": "→",
    "approx": "≈",
    "le": "≤",
    "leq": "≤",
    "ge": "≥",
    "geq": "≥",
    "ne": "≠",
    "neq": "≠",
    "pm": "±",
    "infty": "∞",
    "perp": "⊥",
    "in": "∈",
    "lVert": "‖",
    "rVert": "‖",
    "|": "‖",
    "{": "{",
    "}": "}",
    "qquad": "  ",
    "quad": " ",
    ",": " ",
    ";": " ",
    ":": " ",
    "!": "",
    " ": " ",
    "\\": "; ",
}
_TEX_DROP = {"left", "right", "displaystyle", "big", "Big", "bigl", "bigr", "Bigl", "Bigr"}


def tex_to_text(tex: str) -> str:
    r"""TeX as readable plain text for search snippets.

    >>> tex_to_text(r"N = U \times V,\quad \hat n = N / |N|")
    'N = U × V, n̂ = N / |N|'
    >>> tex_to_text(r"\frac{|\mathbf{N}|^2}{4} = \sqrt{x_{1}^{2}}")
    '|N|²/4 = √(x₁²)'
    >>> tex_to_text(r"|U|\,|V|\,\sin\theta")
    '|U| |V| sin θ'
    """
    s = re.sub(r"\\(?:begin|end)\{[a-z*]+\}", " ", tex)
    for _ in range(6):  # innermost first: no braces inside the arguments
        s = re.sub(
            r"\\(?:mathbf|mathrm|mathit|text|textbf|operatorname|boldsymbol)\{([^{}]*)\}", r"\1", s
        )
        s = re.sub(r"\\(?:hat|widehat)\{([^{}]*)\}", "\\1\u0302", s)
        s = re.sub(r"\\vec\{([^{}]*)\}", "\\1\u20d7", s)
        s = re.sub(r"\\sqrt\{([^{}]*)\}", r"√(\1)", s)
        s = re.sub(
            r"\\[dt]?frac\{([^{}]*)\}\{([^{}]*)\}",
            lambda m: "/".join(p if re.fullmatch(r"[^ +\-]*", p) else f"({p})" for p in m.groups()),
            s,
        )
        s = re.sub(r"\^\{([0-9+\-]+)\}", lambda m: m.group(1).translate(_SUPERSCRIPTS), s)
        s = re.sub(r"_\{([0-9]+)\}", lambda m: m.group(1).translate(_SUBSCRIPTS), s)
    s = re.sub(r"\\hat\s*([A-Za-z])", "\\1\u0302", s)
    s = re.sub(r"\\(sin|cos|tan|log|exp|det)\s*(?=[\\A-Za-z])", r"\1 ", s)  # sin θ, not sinθ
    s = re.sub(r"\^([0-9])", lambda m: m.group(1).translate(_SUPERSCRIPTS), s)
    s = re.sub(r"_([0-9])", lambda m: m.group(1).translate(_SUBSCRIPTS), s)

    def command(m: re.Match[str]) -> str:
        name = m.group(1)
        if name in _TEX_DROP:
            return ""
        return _TEX_SYMBOLS.get(name, name)

    s = re.sub(r"\\([A-Za-z]+|.)", command, s)
    s = s.replace("&", "").replace("{", "").replace("}", "").replace("~", " ")
    return " ".join(s.split())


_SEARCH_MATH = re.compile(r"\\\((.+?)\\\)|\\\[(.+?)\\\]|\$\$(.+?)\$\$|\$([^$]+?)\$", re.S)
_SEARCH_CODE = re.compile(r"(<pre>.*?</pre>|<code>.*?</code>)", re.S)
_NOTEBOOK_PROMPT = re.compile(r"(?:In|Out)\xa0\[\d*\]:\s*(?:Copied!\s*)?")


def _math_as_text(m: re.Match[str]) -> str:
    tex = html.unescape(next(g for g in m.groups() if g is not None))
    return html.escape(tex_to_text(tex), quote=False)


def _drop_repeated_code(text: str) -> str:
    """Drop the flattened copy of a code cell that follows its ``<pre>`` in notebook text."""

    def repl(m: re.Match[str]) -> str:
        code, after = m.group(1), m.group(2)
        same = " ".join(after.split()) and " ".join(after.split()) == " ".join(code.split())
        return m.group(0)[: -len(after)] + " " if same else m.group(0)

    return re.sub(r"<pre>(.*?)</pre>([^<]*)", repl, text, flags=re.S)


def readable_search_text(text: str, notebook: bool = False) -> str:
    r"""Search-index text with its math as plain text (code left alone).

    >>> readable_search_text(r"<p>Then \(N = U \times V\).</p> <code>\(x\)</code>")
    '<p>Then N = U × V.</p> <code>\\(x\\)</code>'
    >>> readable_search_text("<pre>a = 1\n</pre> a = 1 <p>next</p>", notebook=True)
    '<pre>a = 1\n</pre> <p>next</p>'
    """
    if notebook:
        text = _drop_repeated_code(text)
    parts = _SEARCH_CODE.split(text)
    for i in range(0, len(parts), 2):  # the even parts are outside code
        part = parts[i]
        if notebook:
            part = _NOTEBOOK_PROMPT.sub("", part)
        parts[i] = _SEARCH_MATH.sub(_math_as_text, part)
    return "".join(parts)


def on_post_build(config: MkDocsConfig) -> None:
    index = Path(config.site_dir) / "search" / "search_index.json"
    if index.is_file():
        data = json.loads(index.read_text(encoding="utf-8"))
        for doc in data.get("docs", []):
            notebook = str(doc.get("location", "")).startswith("notebooks/")
            for key in ("title", "text"):
                if isinstance(doc.get(key), str):
                    doc[key] = readable_search_text(doc[key], notebook)
            if isinstance(doc.get("title"), str):
                doc["title"] = doc["title"].rstrip("¶").rstrip()  # a notebook heading's link mark
        index.write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")


def _config_url(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``config_url repo_url|site_url [suffix]``: a URL from mkdocs.yml (no page hard-codes one)."""
    key, *rest = args
    url = str(config[key] or "").rstrip("/")
    if not url:
        raise ValueError(f"{page.file.src_uri}: mkdocs.yml sets no {key}")
    return url + (rest[0] if rest else "")


HANDLERS["config_url"] = _config_url


def _result_rows(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``result_rows``: the calculator's results, one row per output field of the package.

    Each row's heading and ``<output>`` id come from ``trinormal.fields.FIELDS``; the
    values are the package's own for the page's starting triangle, so the table is
    right before any script runs.
    """
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
    """``mesh_examples``: one button per example model of the mesh page (list items)."""
    from trinormal.mesh_page import EXAMPLES

    root = relative_root(page)
    return "\n".join(
        f'<li><button type="button" class="md-button" data-example="{root}{MESH_EXAMPLES}/'
        f'{html.escape(name)}">{html.escape(label)}</button></li>'
        for name, label in EXAMPLES
    )


def _mesh_limit(args: list[str], page: Page, config: MkDocsConfig) -> str:
    """``mesh_limit NAME``: one of the mesh page's limits: a size in MB, a count grouped."""
    from trinormal.mesh_page import LIMITS, file_size

    (name,) = args
    if name == "max_bytes":
        return file_size(LIMITS[name])
    return f"{LIMITS[name]:,}".replace(",", "\u202f")


HANDLERS["mesh_examples"] = _mesh_examples
HANDLERS["mesh_limit"] = _mesh_limit
HANDLERS["result_rows"] = _result_rows
HANDLERS["limit"] = _limit
