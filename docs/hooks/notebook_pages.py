"""The Notebooks section: every ``notebooks/*.ipynb``, rendered for a static, offline page.

The navigation lists every notebook; each page is the notebook with its widget outputs
replaced (a note, the explorer's picture and its readout, or the live 3D view on the
explorer notebook), its pictures given their alt text, and no loader of scripts from a CDN.
"""

from __future__ import annotations

import html
import json
import re
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

from explorer_picture import explorer_img
from live_explorer import WIDGET_STATE, WIDGET_VIEW, explorer_outputs, live_explorer_html
from site_paths import NOTEBOOKS


def notebook_paths() -> list[Path]:
    """Every notebook the site renders, in file-name order (01_, 02_, ...)."""
    return sorted(p for p in NOTEBOOKS.glob("*.ipynb") if not p.name.startswith("."))


def markdown_cells(path: Path) -> Iterator[str]:
    """The source of each Markdown cell of a notebook, in order."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    for cell in nb.get("cells", []):
        if cell.get("cell_type") == "markdown":
            yield "".join(cell.get("source", []))


def notebook_title(path: Path) -> str:
    """The first Markdown heading of a notebook, or its file name."""
    for source in markdown_cells(path):
        for line in source.splitlines():
            m = re.match(r"#\s+(.+)", line.strip())
            if m:
                return m.group(1).strip()
    return path.stem.replace("_", " ")


#: How every notebook's opening paragraph begins: what the reader will do, its summary.
WHAT_YOU_DO = "**What you'll do:**"


def notebook_summary(path: Path) -> str:
    """A notebook's summary, as one line of Markdown.

    Its "What you'll do" paragraph without the label, or else its first paragraph of
    plain text after the title.
    """
    for text in markdown_cells(path):
        paras = [p.strip() for p in re.split(r"\n\s*\n", text) if p.strip()]
        for p in paras:
            if p.startswith(WHAT_YOU_DO):
                p = p.removeprefix(WHAT_YOU_DO).strip()
                p = p[:1].upper() + p[1:]
            elif p.startswith(("#", "|", "-", "*", "$", "<", ">", "`")) or p[:2].isdigit():
                continue
            line = " ".join(p.split())
            return line if len(line) <= 240 else line[:237].rsplit(" ", 1)[0] + " …"
    return ""


def notebooks_nav(nav: list[Any]) -> None:
    """Append every notebook to the Notebooks section of ``nav`` (mkdocs.yml lists none)."""
    for item in nav:
        if isinstance(item, dict) and "Notebooks" in item:
            first = [e for e in item["Notebooks"] if not str(e).startswith("notebooks/")]
            item["Notebooks"] = first + [f"notebooks/{p.name}" for p in notebook_paths()]


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
        f"{explorer_img()}{readout}</div>"
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
    return html_output(img)


def html_output(text: str) -> dict[str, Any]:
    """A notebook output that shows ``text`` as HTML."""
    return {"output_type": "display_data", "metadata": {}, "data": {"text/html": text}}


def static_output(out: dict[str, Any], live: dict[int, dict[str, Any]]) -> dict[str, Any]:
    """One output as the static page shows it: ``live`` holds the explorers (by ``id()``)."""
    data = out.get("data") or {}
    if id(out) in live:
        return html_output(live_explorer_html(live[id(out)]))
    if "image/png" in data and isinstance(out.get("metadata"), dict):
        return picture_output(out)
    if WIDGET_VIEW not in data and WIDGET_STATE not in data:
        return out
    plain = data.get("text/plain", "")
    if isinstance(plain, list):
        plain = "".join(plain)
    if re.fullmatch(r"\s*(?:[A-Z]\w*\(.*\))?\s*", plain, flags=re.S):
        plain = ""  # a widget's repr, IntSlider(value=0), is noise, not a readout
    note = mesh_view_note if plain.startswith("Mesh view:") else widget_note
    return html_output(note(plain))


def static_notebook(path: Path) -> dict[str, Any]:
    """A copy of a notebook with every widget output replaced by a static note.

    On the explorer notebook's page the explorer's output is replaced by the live
    3D view instead (see :func:`explorer_outputs`), with the note as its fallback.
    """
    nb: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    live = explorer_outputs(nb, path)
    nb.get("metadata", {}).pop("widgets", None)
    for cell in nb.get("cells", []):
        if cell.get("outputs"):
            cell["outputs"] = [static_output(out, live) for out in cell["outputs"]]
    return nb


_CDN_SCRIPT = re.compile(
    r"<script[^>]*\bsrc=\"(?:https?:)?//[^\"]*\"[^>]*>\s*</script>"  # any external script
    r"|<script[^>]*\bsrc=\"\"[^>]*>\s*</script>"  # the empty MathJax URL
    r"|<script type=\"text/x-mathjax-config\">.*?</script>"  # MathJax 2 configuration
    r"|<script type=\"module\">(?:(?!</script>).)*?mermaid(?:(?!</script>).)*?</script>"
    r"|<!-- (?:Load mathjax|MathJax configuration|End of mathjax configuration) -->",
    flags=re.S,
)


def clean_notebook_html(body: str) -> str:
    """Remove loaders that would fetch scripts from another origin, and their comments."""
    return _CDN_SCRIPT.sub("", body)


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
        nb = static_notebook(path)
        with tempfile.TemporaryDirectory() as tmp:
            copy_path = Path(tmp) / path.name
            copy_path.write_text(json.dumps(nb), encoding="utf-8")
            body = original(str(copy_path), *args, **kwargs)
        return clean_notebook_html(body)

    nb2html._trinormal = True  # type: ignore[attr-defined]
    convert.nb2html = nb2html
