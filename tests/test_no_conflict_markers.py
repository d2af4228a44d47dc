"""No file of the repository holds a merge's conflict markers (one reached README.md once,
staged with the rest of a merge, and no other test read that line)."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MARKER = re.compile(r"^(<{7} |>{7} )", re.MULTILINE)
TEXT = {".py", ".md", ".toml", ".txt", ".j2", ".cfg", ".yml", ".yaml", ".sh", ".csv"}


def test_no_conflict_markers() -> None:
    skip = {".git", ".venv", "node_modules", "__pycache__", ".mypy_cache", ".ruff_cache"}
    found = []
    for path in ROOT.rglob("*"):
        if path.suffix not in TEXT or skip.intersection(path.relative_to(ROOT).parts):
            continue
        if not path.is_file():
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        found += [f"{path.relative_to(ROOT)}:{text.count(chr(10), 0, m.start()) + 1}"
                  for m in MARKER.finditer(text)]
    assert not found, found
