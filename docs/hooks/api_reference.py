"""The API reference shows public names only, and links every mention of one.

* :class:`PublicOnly`, a griffe extension (mkdocs.yml, mkdocstrings' ``extensions``): a
  default written with a private name (``expected=_MISSING``) is shown as its ``repr``, as
  ``help()`` shows it; an attribute's value written with one (``self._compute(...)``) is
  not shown at all.
* :func:`link_public_names` (the hook's ``on_env``, before autorefs resolves the links):
  inline code naming a public name (```FIELDS```, ```TriangleNormal.format(4)```) links to
  where autorefs knows it is documented, without a cross-reference in the docstring.

This module imports no module beside it: griffe loads it by its path, on its own.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import re
from typing import Any

from griffe import Attribute, Expr, ExprName, Extension, Function
from mkdocs.config.defaults import MkDocsConfig
from mkdocs.structure.files import Files

#: The package whose names are linked.
PACKAGE = "trinormal"
#: A dotted name at the start of inline code (``a.b.c``), then what follows it.
_MENTION = re.compile(r"([A-Za-z]\w*(?:\.[A-Za-z]\w*)*)(.*)", re.S)
#: Inline code holding only text, not already in a link, a heading, a code block or a reference.
_CODE = re.compile(r"<code>([^<>]+)</code>")
_SKIP = re.compile(r"<(pre|a|h[1-6]|autoref)\b[^>]*>.*?</\1>", re.S)
#: The objects a page documents: mkdocstrings' object headings and their ids.
_DOCUMENTED = re.compile(rf'\bid="({PACKAGE}(?:\.\w+)*)"')


def _is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def names_private(code: str | Expr | None) -> bool:
    """True when a default or value, as griffe read it from the source, uses a private name.

    >>> names_private("_MISSING"), names_private("MAX_PRECISION"), names_private(None)
    (True, False, False)
    """
    if code is None:
        return False
    if isinstance(code, str):
        return any(_is_private(part) for part in re.findall(r"(?<![\w'\"])[A-Za-z_]\w*", code))
    return any(
        isinstance(part, ExprName) and _is_private(part.name) for part in code.iterate(flat=True)
    )


def _runtime_default(func: Function, parameter: str) -> str:
    """A parameter's default as Python shows it: the ``repr`` of the object itself."""
    obj: Any = importlib.import_module(func.module.path)
    for part in func.path[len(func.module.path) + 1 :].split("."):
        obj = getattr(obj, part)
    return repr(inspect.signature(obj).parameters[parameter].default)


class PublicOnly(Extension):
    """A griffe extension: no private name in a signature's defaults or an attribute's value."""

    def on_function_instance(self, *, func: Function, **kwargs: Any) -> None:
        for parameter in func.parameters:
            if names_private(parameter.default):
                parameter.default = _runtime_default(func, parameter.name)

    def on_attribute_instance(self, *, attr: Attribute, **kwargs: Any) -> None:
        if names_private(attr.value):
            attr.value = None


def _candidates(name: str, modules: list[str]) -> list[str]:
    """The identifiers a mention may mean, the likeliest first.

    >>> _candidates("TriangleNormal.format", ["trinormal.fields"])
    ['trinormal.TriangleNormal.format', 'trinormal.fields.TriangleNormal.format']
    >>> _candidates("trinormal.mesh.check", [])
    ['trinormal.mesh.check']
    """
    if name == PACKAGE or name.startswith(PACKAGE + "."):
        return [name]
    return [f"{PACKAGE}.{name}"] + [f"{module}.{name}" for module in modules]


def _linked(html: str, resolve: Any) -> str:
    """``html`` with each inline-code mention that ``resolve`` knows wrapped in an autoref."""
    skip = [m.span() for m in _SKIP.finditer(html)]
    out, at = [], 0
    for m in _CODE.finditer(html):
        if any(start <= m.start() < end for start, end in skip):
            continue
        mention = _MENTION.fullmatch(m.group(1).strip())
        if mention is None or (mention.group(2) and mention.group(2)[0] not in "(["):
            continue
        name = mention.group(1)
        if any(_is_private(part) for part in name.split(".")):
            continue
        identifier = resolve(name)
        if identifier is None:
            continue
        out.append(html[at : m.start()])
        out.append(f'<autoref identifier="{identifier}">{m.group(0)}</autoref>')
        at = m.end()
    out.append(html[at:])
    return "".join(out)


def _is_module(identifier: str) -> bool:
    try:
        return importlib.util.find_spec(identifier) is not None
    except ImportError:  # a class or function: its parent is a module, not a package
        return False


def _known(autorefs: Any, identifier: str, from_url: str) -> bool:
    """True when autorefs can link ``identifier`` (documented on some page)."""
    try:
        autorefs.get_item_url(identifier, from_url)
    except KeyError:
        return False
    return True


def link_public_names(config: MkDocsConfig, files: Files) -> None:
    """Link every mention of a documented public name on the API pages (``api/``).

    A mention is inline code that starts with a name (``name``, ``module.name``,
    ``Class.member``, optionally called or indexed); it is tried as a name of the package,
    then of each module the page documents, then of every documented module.
    """
    autorefs = config.plugins["autorefs"]
    pages = [f.page for f in files if f.page and f.page.content and f.src_uri.startswith("api/")]
    everywhere = sorted({m for p in pages for m in _DOCUMENTED.findall(p.content or "")})
    modules = [m for m in everywhere if _is_module(m)]

    for page in pages:
        html = page.content or ""
        own = [m for m in _DOCUMENTED.findall(html) if m in modules]
        order = own + [m for m in modules if m not in own]

        def resolve(name: str, order: list[str] = order, url: str = page.url) -> str | None:
            return next((c for c in _candidates(name, order) if _known(autorefs, c, url)), None)

        page.content = _linked(html, resolve)


#: The modules of trinormal.mesh whose names its API pages list (each name on one page).
MESH_PARTS = ("io", "normals", "topology", "report", "printing", "repair", "shapes")


def _owner(name: str, obj: Any) -> str:
    """The module of trinormal.mesh that defines a name it exports."""
    home = getattr(obj, "__module__", None)
    for part in MESH_PARTS:
        module = importlib.import_module(f"{PACKAGE}.mesh.{part}")
        if home is not None and (home == module.__name__ or home.startswith(module.__name__ + ".")):
            return part  # defined in the module or in a module of its package (io/mesh_data.py)
        if home is None and vars(module).get(name) is obj:
            return part
    raise LookupError(f"{PACKAGE}.mesh.{name} is defined in none of {MESH_PARTS}")


def mesh_api_markdown(parts: list[str]) -> str:
    """One page of the mesh API: what ``parts`` answer, a table of their names, then each name.

    ``trinormal.mesh`` exports more names than one page holds; each page lists the names of
    ``trinormal.mesh.__all__`` that the given modules define, in that order, documented as
    ``trinormal.mesh.NAME`` (the name a reader imports).
    """
    mesh = importlib.import_module(f"{PACKAGE}.mesh")
    unknown = set(parts) - set(MESH_PARTS)
    if unknown:
        raise ValueError(f"mesh_api: no such part {sorted(unknown)}; parts are {MESH_PARTS}")
    names = [n for n in mesh.__all__ if _owner(n, getattr(mesh, n)) in parts]
    intro = []
    for part in parts:
        doc = inspect.getdoc(importlib.import_module(f"{PACKAGE}.mesh.{part}")) or ""
        intro.append(doc.split("\n\n")[0].replace("\n", " "))
    rows = []
    for name in names:
        obj = getattr(mesh, name)
        first = inspect.getdoc(obj) if callable(obj) else None
        summary = (first or "a constant").split("\n\n")[0].replace("\n", " ").replace("|", "\\|")
        rows.append(f"| [`{name}`][{PACKAGE}.mesh.{name}] | {summary} |")
    blocks = [f"::: {PACKAGE}.mesh.{name}" for name in names]
    table = ["| name | what it answers |", "|---|---|", *rows]
    return "\n\n".join([" ".join(intro), "\n".join(table), *blocks])
