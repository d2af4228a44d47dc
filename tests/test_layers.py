"""The package flows one way: every module belongs to one layer (docs/architecture.md) and
imports only from its own layer or those below, and no modules import each other in a loop.

Every import counts, wherever it stands: at module level, inside a function or under
``TYPE_CHECKING`` (a lower layer that needs something from a higher one takes it as an
argument or reads it through a protocol). Read from the sources' syntax trees: nothing is
imported, so this takes a fraction of a second.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import pounding

ROOT = Path(pounding.__file__).parent

LAYERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("foundations", ("pounding.units", "pounding.allocator", "pounding.compiled_cache",
                     "pounding.validation", "pounding.io", "pounding.memo", "pounding.lazy",
                     "pounding.progress", "pounding.plausibility", "pounding.example_files")),
    ("physics", ("pounding.contact", "pounding.hysteresis", "pounding.devices",
                 "pounding.ground_motion", "pounding.structure", "pounding.spectra")),
    ("model", ("pounding.model",)),
    ("results", ("pounding.result",)),
    ("engine", ("pounding.integrate",)),
    ("model files", ("pounding.config",)),
    ("figures", ("pounding.plot",)),
    ("studies", ("pounding.studies", "pounding.run_file")),
    ("reports", ("pounding.report",)),
    ("interface", ("pounding.cli", "pounding.__main__", "pounding")),
)
"""Bottom first. The documented order, and why it is this one: docs/architecture.md."""

ROOT_ATTRIBUTES = {"pounding.__version__"}
"""What a module may read from the package root: Python loads the root before any of its
modules, and the root's own code imports nothing of pounding (its names load on first use),
so reading its version string ties no layer to the interface."""


def _module(path: Path) -> str:
    parts = ["pounding", *path.relative_to(ROOT).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _layer(module: str) -> int:
    """The index in :data:`LAYERS` of the longest prefix naming ``module``."""
    best, depth = -1, -1
    for index, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and len(prefix) > depth:
                best, depth = index, len(prefix)
    return best


def _imports(path: Path) -> set[str]:
    return _imports_of(path.read_text(encoding="utf-8"), _module(path),
                       is_package=path.name == "__init__.py")


def _imports_of(text: str, module: str, *, is_package: bool = False) -> set[str]:
    """Every pounding module the source ``text`` of ``module`` imports, anywhere in it:
    ``from a.b import c`` counts as ``a.b.c`` where that is a module, else as ``a.b``."""
    package = module if is_package else module.rpartition(".")[0]
    out: set[str] = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            out |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(up + ([base] if base else []))
            names = {f"{base}.{alias.name}" for alias in node.names}
            if base == "pounding" and names <= ROOT_ATTRIBUTES:
                continue
            modules = {n for n in names if n in SOURCES}
            out |= modules
            if modules != names:  # (``from a import b`` of a module b needs only a.b)
                out.add(base)
    return {m for m in out if m == "pounding" or m.startswith("pounding.")}


SOURCES: dict[str, Path] = {_module(p): p for p in sorted(ROOT.rglob("*.py"))}


def test_every_module_has_a_layer() -> None:
    assert [m for m in SOURCES if _layer(m) < 0] == []


@pytest.mark.parametrize("layer", [name for name, _ in LAYERS])
def test_a_layer_imports_only_itself_and_those_below(layer: str) -> None:
    index = [name for name, _ in LAYERS].index(layer)
    upward = []
    for module, path in SOURCES.items():
        if _layer(module) != index:
            continue
        for target in sorted(_imports(path)):
            if _layer(target) > index:
                upward.append(f"{module} -> {target} ({LAYERS[_layer(target)][0]})")
    assert upward == []


def test_no_modules_import_each_other_in_a_loop() -> None:
    """Tarjan's strongly connected components of the import graph: each must be one module
    (a package's ``__init__`` that names its own modules is counted like any module)."""
    edges = {m: {t for t in _imports(p) if t in SOURCES and t != m} for m, p in SOURCES.items()}
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    loops: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                loops.append(sorted(component))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    assert loops == []


def test_the_reader_sees_imports_in_functions_and_under_type_checking() -> None:
    text = ("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
            "    from pounding.result import Result\n"
            "def f():\n    from ..studies import gap\n    import pounding.plot\n"
            "from pounding import __version__\n")
    found = _imports_of(text, "pounding.contact.probe")
    assert found == {"pounding.result", "pounding.studies.gap", "pounding.plot"}
    assert all(_layer(m) > _layer("pounding.contact.probe") for m in found)
