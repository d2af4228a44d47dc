"""The contact-core documentation stays runnable and complete.

* every law and formula page has a ```python example (they run, with every other block of
  the docs, in tests/test_docs_examples.py);
* every law name of :data:`pounding.contact.factory.LAW_NAMES` and every key of
  :data:`pounding.contact.FORMULAS` has a page;
* relative links between these pages point to files that exist.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from pounding.contact import FORMULAS
from pounding.contact.factory import LAW_NAMES

DOCS = Path(__file__).resolve().parents[1] / "docs"
PAGES = sorted([DOCS / "index.md", DOCS / "audit.md", DOCS / "collision.md",
                *(DOCS / "laws").glob("*.md"), *(DOCS / "formulas").glob("*.md")])
FENCE = re.compile(r"^```python[ \t]*\n(.*?)^```[ \t]*$", re.DOTALL | re.MULTILINE)
LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")

LAW_ALIASES = {"hertzdamp": "hunt-crossley"}
"""Law names documented on another law's page (the page must mention the name)."""


def _blocks() -> list[tuple[str, str]]:
    out = []
    for page in PAGES:
        for i, m in enumerate(FENCE.finditer(page.read_text(encoding="utf-8"))):
            out.append((f"{page.relative_to(DOCS)}#{i + 1}", m.group(1)))
    return out


BLOCKS = _blocks()


def test_pages_and_examples_exist() -> None:
    assert (DOCS / "index.md").is_file()
    assert len(BLOCKS) >= len(LAW_NAMES) + len(FORMULAS)


@pytest.mark.parametrize("name", LAW_NAMES)
def test_every_law_has_a_page(name: str) -> None:
    page = DOCS / "laws" / f"{LAW_ALIASES.get(name, name)}.md"
    assert page.is_file(), f"no page for law {name!r}: expected {page}"
    assert f"`{name}`" in page.read_text(encoding="utf-8")


@pytest.mark.parametrize("key", list(FORMULAS))
def test_every_formula_has_a_page(key: str) -> None:
    page = DOCS / "formulas" / f"{key}.md"
    assert page.is_file(), f"no page for formula {key!r}: expected {page}"
    assert f'FORMULAS["{key}"]' in page.read_text(encoding="utf-8")


def test_index_links_every_page() -> None:
    index = (DOCS / "index.md").read_text(encoding="utf-8")
    targets = {l for l in LINK.findall(index)}
    for page in PAGES:
        if page.name != "index.md":
            assert str(page.relative_to(DOCS)) in targets, f"index.md does not link {page.name}"
    for other in ("ground_motion.md", "structures.md", "seed_paper.md"):
        assert other in targets


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(DOCS)) for p in PAGES])
def test_relative_links_resolve(page: Path) -> None:
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.DOTALL)
    text = re.sub(r"`[^`\n]*`", "", text)
    for target in LINK.findall(text):
        if "://" in target:
            continue
        assert (page.parent / target).exists(), f"{page.name}: broken link {target}"
