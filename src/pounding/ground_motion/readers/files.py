"""Opening a record file: :func:`check_file` (a file, not a missing path or a folder) and
:func:`read_lines` (its text lines, whatever the line ends and encoding)."""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["check_file", "read_lines"]


def read_lines(path: Path) -> list[str]:
    """The file's lines without line ends (LF, CRLF, CR CR LF or CR; last one optional)."""
    data = path.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    text = text.removeprefix("\ufeff")
    if "\n" in text:  # LF, CRLF or CR CR LF
        lines = [line.rstrip("\r") for line in text.split("\n")]
    else:  # classic Mac OS: CR only
        lines = text.split("\r")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def check_file(path: str | os.PathLike[str]) -> Path:
    p = Path(path)
    if not p.exists():
        raise FileNotFoundError(f"{p}: no such file")
    if p.is_dir():
        raise IsADirectoryError(f"{p}: is a directory, not a record file")
    return p
