"""The physics layer flows one way: the contact laws, structures and devices name no higher
layer, and no two of their modules (nor the model above them) import each other in a loop.

Every import counts, wherever it stands: at module level, inside a function or under
``TYPE_CHECKING`` (a lower layer that needs something from a higher one takes it as an
argument). Read from the sources' syntax trees: nothing is imported, so this is quick.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import pounding

ROOT = Path(pounding.__file__).parent
PHYSICS = ("contact", "structure", "devices")
HIGHER = ("pounding.model", "pounding.integrate", "pounding.result", "pounding.summary",
          "pounding.outputs", "pounding.studies", "pounding.plot", "pounding.report",
          "pounding.cli", "pounding.config", "pounding.run_file")


def _module(path: Path) -> str:
    parts = ["pounding", *path.relative_to(ROOT).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path) -> set[str]:
    """Every module ``path`` imports (``from a.b import c`` counts as ``a.b`` and
    ``a.b.c``), anywhere in it."""
    module = _module(path)
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(up + ([base] if base else []))
            out.add(base)
            out |= {f"{base}.{alias.name}" for alias in node.names}
    return out


def _sources() -> dict[str, Path]:
    files = [p for pkg in PHYSICS for p in sorted((ROOT / pkg).rglob("*.py"))]
    return {_module(p): p for p in [*files, ROOT / "model.py"]}


@pytest.mark.parametrize("package", PHYSICS)
def test_the_physics_layer_names_no_higher_layer(package: str) -> None:
    for path in sorted((ROOT / package).rglob("*.py")):
        upward = sorted(m for m in _imports(path)
                        if any(m == h or m.startswith(h + ".") for h in HIGHER))
        assert not upward, f"{_module(path)} imports {upward}"


def test_no_import_circle_in_the_physics_layer_and_the_model() -> None:
    sources = _sources()
    edges = {mod: {m for m in _imports(path) if m in sources and m != mod}
             for mod, path in sources.items()}

    def reaches(start: str, goal: str) -> list[str] | None:
        """A path of imports from ``start`` to ``goal`` (depth first), or None."""
        stack, seen = [(start, [start])], {start}
        while stack:
            node, trail = stack.pop()
            for nxt in sorted(edges[node]):
                if nxt == goal:
                    return [*trail, nxt]
                if nxt not in seen:
                    seen.add(nxt)
                    stack.append((nxt, [*trail, nxt]))
        return None

    circles = [loop for mod in sorted(edges) if (loop := reaches(mod, mod))]
    assert not circles, "import circles: " + "; ".join(" -> ".join(c) for c in circles)
