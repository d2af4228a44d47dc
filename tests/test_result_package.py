"""The results package flows one way: each of its modules imports only those below it, and
none imports the package's front door (``pounding.result``), so they tie into no circle.

Every import counts, wherever it stands (module level, inside a function, under
TYPE_CHECKING), as ``ARCHITECTURE.md`` (layer 5, "one package, one way in") asks."""

from __future__ import annotations

import ast
from pathlib import Path

import pounding
import pounding.result

PACKAGE = Path(pounding.result.__file__).parent

ORDER = ("columns", "demands", "peaks", "reductions", "storeys", "foundations", "bridge_seats",
         "contact_response", "response", "storey_peaks", "bridge_peaks", "bridge_keys",
         "variables", "summary", "files", "display", "result")
"""The modules of :mod:`pounding.result`, bottom first: each may import only those before it."""


def imported_modules(path: Path) -> set[str]:
    """Every ``pounding.…`` module a file names in an import, wherever the import stands."""
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            out.add(node.module)
            out.update(f"{node.module}.{a.name}" for a in node.names)
    return {name for name in out if name.startswith("pounding.")}


def test_every_module_of_the_package_is_in_the_order() -> None:
    modules = {p.stem for p in PACKAGE.glob("*.py")} - {"__init__"}
    assert modules == set(ORDER)


def test_each_module_imports_only_those_below_it() -> None:
    for level, name in enumerate(ORDER):
        below = {f"pounding.result.{m}" for m in ORDER[:level]}
        named = imported_modules(PACKAGE / f"{name}.py")
        ours = {m for m in named if m == "pounding.result" or m.startswith("pounding.result.")}
        siblings = {m for m in ours if m.removeprefix("pounding.result.") in ORDER}
        assert "pounding.result" not in ours, f"{name} imports the package's front door"
        assert siblings <= below, (name, sorted(siblings - below))


def test_the_package_gives_the_result_the_api_returns() -> None:
    from pounding.result.response import Response

    assert pounding.Result is pounding.result.Result
    assert issubclass(pounding.Result, Response)
    for method in ("save", "summary", "to_dataset", "history_variables"):
        assert callable(getattr(pounding.Result, method)), method
