"""``assets/javascripts/trinormal-constants.js``: what the site's JavaScript reads from the package.

The output fields, the colour code, the input limits and messages, the verdicts, the
degeneracy tolerance, the precision range, the view's grid and range, the Check a
mesh page's constants and the printable model's: the hand-written JavaScript lists none
of them itself.
"""

from __future__ import annotations

import json
from typing import Any


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
    from trinormal.mesh_page import site_constants as mesh_page_constants
    from trinormal.tolerances import DEFAULT_TOL
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
        "tol": DEFAULT_TOL,
        "format": {"sci_above_log10": SCI_ABOVE_LOG10},
        "view": {"step": view["step"], "bounds": view["bounds"]},
        "mesh": mesh_page_constants(),
        "print": print_constants(),
    }


def print_constants() -> dict[str, Any]:
    """The printable model's sizes, shapes and messages (trinormal-printmodel.js reads them)."""
    from trinormal.printmodel import site_constants as print_site_constants

    return print_site_constants()


def constants_js() -> str:
    """``assets/javascripts/trinormal-constants.js``: :func:`site_constants` as one object."""
    body = json.dumps(site_constants(), ensure_ascii=False, indent=1)
    return (
        "/* Written at build time by docs/hooks/site_constants.py from the trinormal package\n"
        " * (trinormal.fields, .colors, .validation, .tolerances and .explorer): do not edit. */\n"
        f"window.TRINORMAL_CONSTANTS = {body};\n"
    )
