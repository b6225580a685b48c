"""Say which extra to install when a module's optional dependency is missing.

The core (`triangle_normal`, the CLI) needs only the standard library; the modules
beyond it need the ``notebooks`` extra. Importing one without it raises
`ModuleNotFoundError` (an `ImportError`) whose message names the module, the missing
package and the command that installs it.
"""

from __future__ import annotations

import importlib.util

#: The extra that brings every optional dependency.
EXTRA = "notebooks"


def missing_extra(error: ModuleNotFoundError, module: str) -> ModuleNotFoundError:
    """Turn a failed import of an optional dependency into an error naming the extra.

    An import that failed inside trinormal itself is returned unchanged: that is a
    bug, not a missing extra.

    Examples
    --------
    >>> try:
    ...     import not_a_real_package  # noqa: F401
    ... except ModuleNotFoundError as exc:
    ...     message = str(missing_extra(exc, "trinormal.mesh"))
    >>> for sentence in message.split(". "):
    ...     print(sentence)
    trinormal.mesh needs not_a_real_package, which is not installed
    Install the notebooks extra: pip install "trinormal[notebooks]"
    """
    name = (error.name or "").split(".")[0]
    if not name or name == "trinormal":
        return error
    return ModuleNotFoundError(
        f"{module} needs {name}, which is not installed. "
        f'Install the {EXTRA} extra: pip install "trinormal[{EXTRA}]"',
        name=name,
    )


def require(module: str, *packages: str) -> None:
    """Check that ``packages`` can be imported, without importing them.

    For a module that imports its dependency lazily, inside its functions: the
    missing extra is reported when the module is imported, not at the first call.

    Examples
    --------
    >>> require("trinormal.plotting", "math")
    >>> require("trinormal.plotting", "not_a_real_package")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ModuleNotFoundError: trinormal.plotting needs not_a_real_package, ... "trinormal[notebooks]"
    """
    for package in packages:
        if importlib.util.find_spec(package) is None:
            raise missing_extra(ModuleNotFoundError(name=package), module)
