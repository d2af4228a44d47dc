"""Every ```python block of docs/structures.md and docs/buildings.md runs (in a fresh
namespace each)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[2] / "docs"
BLOCKS = [(name, i, block) for name in ("structures.md", "buildings.md")
          for i, block in enumerate(re.findall(r"```python\n(.*?)```",
                                               (DOCS / name).read_text(encoding="utf-8"),
                                               flags=re.S))]


def test_docs_have_examples() -> None:
    assert sum(name == "structures.md" for name, _, _ in BLOCKS) >= 4
    assert sum(name == "buildings.md" for name, _, _ in BLOCKS) >= 3


@pytest.mark.parametrize(("name", "index", "block"), BLOCKS,
                         ids=[f"{name}[{i}]" for name, i, _ in BLOCKS])
def test_doc_example_runs(name: str, index: int, block: str,
                          capsys: pytest.CaptureFixture[str]) -> None:
    exec(compile(block, f"{name}[block {index}]", "exec"), {})
