"""Opening a record file: :func:`check_file` (a regular file of a size a record can have,
not a missing path, a folder or a device) and :func:`read_lines` (its text lines, whatever
the line ends and encoding).

Nothing here, nor in any reader, ever puts a file's text in a message: a file given as a
record may be anything (a password file, a key), and a message is printed, logged and
stored in a study's results. Messages name the file, its size, the line and the problem.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

__all__ = ["MAX_RECORD_BYTES", "check_file", "describe_size", "read_lines"]

MAX_RECORD_BYTES: int = 256 * 1024 * 1024
"""The largest record file read [bytes]: 256 MiB, some 20 million values of text, far
beyond any recorded motion (an hour sampled at 200 Hz is about 11 MB); a guard against
reading a disk image or a log file whole."""


def describe_size(n_bytes: int) -> str:
    """A file size for a message: ``"1 byte"``, ``"812 bytes"``, ``"3.4 MB"``."""
    if n_bytes == 1:
        return "1 byte"
    if n_bytes < 10_000:
        return f"{n_bytes} bytes"
    for unit, scale in (("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if n_bytes >= scale:
            return f"{n_bytes / scale:.3g} {unit}"
    return f"{n_bytes} bytes"  # pragma: no cover


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
    """``path`` as a :class:`~pathlib.Path`, if it is a regular file of at most
    :data:`MAX_RECORD_BYTES`.

    Raises
    ------
    FileNotFoundError
        If nothing is there.
    IsADirectoryError
        If it is a folder.
    ValueError
        If it is a device, a pipe or a socket (``/dev/zero`` would be read for ever), or
        larger than :data:`MAX_RECORD_BYTES`.
    """
    p = Path(path)
    if not p.exists():
        raise FileNotFoundError(f"{p}: no such file")
    if p.is_dir():
        raise IsADirectoryError(f"{p}: is a directory, not a record file")
    mode = p.stat().st_mode
    if not stat.S_ISREG(mode):
        raise ValueError(f"{p}: not a regular file (a device, pipe or socket), not a record "
                         "file")
    size = p.stat().st_size
    if size > MAX_RECORD_BYTES:
        raise ValueError(f"{p}: {describe_size(size)}, larger than any record file pounding "
                         f"reads (at most {describe_size(MAX_RECORD_BYTES)})")
    return p
