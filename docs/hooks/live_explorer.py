"""The live 3D view on the explorer notebook's page, in place of the widget's stored output.

Which outputs of a notebook show an explorer (from the stored widget state, or else from the
notebook's code), the values the live view starts from, and its HTML (mounted by
``assets/javascripts/explorer-site.js``, with the picture as its fallback).
"""

from __future__ import annotations

import ast
import contextlib
import html
import json
from pathlib import Path
from typing import Any, TypeGuard

from explorer_picture import explorer_img
from site_constants import view_defaults

WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"

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
    """The literal arguments of the explorer a cell shows (its last line, or any call), or None.

    ``known`` (variable name -> arguments so far, from ``ex = Explorer(...)`` and
    ``ex.set(...)``) is updated by the cell's statements.
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
    for each in ast.walk(tree):
        if _is_explorer_call(each):
            return _literal_kwargs(each)
    return None


def _view_init(values: dict[str, Any]) -> dict[str, Any]:
    """Initial values for the site's view: the explorer's own defaults, then ``values``."""
    from trinormal.explorer.state import coordinate_text

    init = dict(view_defaults())
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
    init["show_controls"] = True  # the notebook's text (and its exercises) use the boxes
    return init


def explorer_outputs(nb: dict[str, Any], path: Path) -> dict[int, dict[str, Any]]:
    """The outputs of a notebook that show an explorer, by ``id()``, with the view's initial values.

    An output whose widget is, or contains, a stored ``ExplorerView`` starts from its stored
    values. On the explorer notebook (``*explorer*.ipynb``) with no stored ExplorerView
    (``make notebooks`` stores none), the first widget output of each cell that shows an
    explorer starts from the literal arguments in the code (see :func:`_explorer_shown`).
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
        "turn the view, drag A, B or C, type exact values in the boxes under it, flip the order, "
        "show the parallelogram. There is no Python kernel here: this page computes with its "
        "own exact arithmetic, which prints the same numbers as the package; the notebook's "
        "code cells do not run.</p>"
        '<noscript><div class="admonition note tn-widget-note tn-explorer-fallback">'
        '<p class="admonition-title">Interactive widget</p>'
        "<p>With JavaScript on, this page shows the explorer live. Here is a picture of it.</p>"
        f"{explorer_img()}</div></noscript></div>"
    )
