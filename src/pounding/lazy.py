"""Names of a package imported on first use (PEP 562), so that importing a package, or one
of its modules, loads no more than it needs.

A package lists its public names and the module that defines each, and takes the two
module-level functions from here::

    _EXPORTS = {"Result": "pounding.result.result", ...}
    __getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["lazy_exports"]


def lazy_exports(namespace: dict[str, Any], exports: Mapping[str, str]
                 ) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """The ``__getattr__`` and ``__dir__`` of a package whose names load on first use.

    Parameters
    ----------
    namespace : dict
        The package's ``globals()``: a name once imported is stored there, so later
        look-ups do not come back to ``__getattr__``.
    exports : mapping
        Public name → the module that defines it.

    Returns
    -------
    (__getattr__, __dir__)
        ``__getattr__(name)`` imports ``name`` from its module (an AttributeError naming the
        package for a name it does not have); ``__dir__()`` lists the package's names.
    """
    package = namespace["__name__"]

    def __getattr__(name: str) -> Any:
        module = exports.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(module), name)
        namespace[name] = value  # later look-ups do not come back here
        return value

    def __dir__() -> list[str]:
        return sorted(set(namespace) | set(exports))

    return __getattr__, __dir__
