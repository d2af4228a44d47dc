"""One entry point for every record format: :func:`read_record` picks the reader of a file
from its suffix, then from its first lines, and falls back to plain text; a file in none of
these formats is refused in one line that names the formats read (:data:`SUPPORTED`).

Each format is a :class:`RecordFormat` in :data:`FORMATS`, defined in its own module of
:mod:`pounding.ground_motion.readers` (:mod:`~pounding.ground_motion.readers.knet`,
:mod:`~pounding.ground_motion.readers.cosmos`, :mod:`~pounding.ground_motion.readers.at2`);
a new format adds its entry there.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers import at2, cosmos, knet
from pounding.ground_motion.readers.files import check_file, describe_size, read_lines
from pounding.ground_motion.readers.numbers import is_numeric_line
from pounding.ground_motion.readers.text import read_text

__all__ = ["FORMATS", "SUPPORTED", "RecordFormat", "needs_units", "read_record"]


@dataclass(frozen=True)
class RecordFormat:
    """A record file format that :func:`read_record` recognises.

    Parameters
    ----------
    name : str
        The format's name, e.g. ``"PEER AT2"``.
    suffixes : tuple of str
        File suffixes, lower case with the dot, that select the format whatever the content.
    sniff : callable
        ``sniff(lines) -> bool``: True if a file's text lines are in this format.
    read : callable
        ``read(path, *, dt, units) -> GroundMotion``, the format's reader.
    """

    name: str
    suffixes: tuple[str, ...]
    sniff: Callable[[list[str]], bool]
    read: Callable[..., GroundMotion]


FORMATS: tuple[RecordFormat, ...] = (
    RecordFormat("K-NET/KiK-net ASCII", knet.SUFFIXES, knet.looks_like_knet, knet.read_knet),
    RecordFormat("COSMOS V1/V2", cosmos.SUFFIXES, cosmos.looks_like_cosmos,
                 cosmos.read_cosmos),
    RecordFormat("PEER AT2", at2.SUFFIXES, at2.looks_like_at2, at2.read_at2),
)
"""The formats other than plain text, tried in this order (suffixes first, then content:
the first two are told by their first line alone)."""

SUPPORTED: str = ", ".join(
    [fmt.name for fmt in FORMATS]
    + ["plain text (one column, two: time, acceleration, or several with a column chosen)"])
"""The formats :func:`read_record` reads, for the message that refuses any other."""


def _format_of(p: Path) -> RecordFormat | None:
    """The format of file ``p`` by its suffix, else by its lines; None for plain text."""
    suffix = p.suffix.lower()
    for fmt in FORMATS:
        if suffix in fmt.suffixes:
            return fmt
    lines = read_lines(p)
    return next((fmt for fmt in FORMATS if fmt.sniff(lines)), None)


def read_record(path: str | os.PathLike[str], dt: float | None = None,
                units: str | None = None, *, column: int | None = None,
                time_column: int | None = None, channel: int | None = None) -> GroundMotion:
    """Read an acceleration record, choosing the reader from the suffix and content.

    A suffix of one of :data:`FORMATS` (any case: ``.AT2``; ``.NS``, ``.EW2``...; ``.V2``,
    ``.V2c``...) selects its reader; so does a first line ``Origin Time`` (K-NET/KiK-net),
    ``(Format v01.20 with 13 text lines)`` (COSMOS), or a header with ``NPTS``/``DT``
    (AT2). A file whose first line that is not blank or a ``#`` comment holds numbers alone
    is plain text (:func:`~pounding.ground_motion.readers.text.read_text`), which states
    no unit: it needs ``units`` (none is assumed). Any other file is refused: the message
    names it, its size and the formats read.

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s], for files that do not give one (see the readers).
    units : str, optional
        Acceleration unit for files that do not state one; required for plain text. For an
        AT2 header that states a different unit this is an error.
    column, time_column : int, optional
        For plain text only: the column of the acceleration and of the time, from 1
        (:func:`~pounding.ground_motion.readers.text.read_text`); a file of another format
        given either is refused.
    channel : int, optional
        For COSMOS only: which acceleration channel of a file that holds several, from 1
        (:func:`~pounding.ground_motion.readers.cosmos.read_cosmos`); a file of another
        format given one is refused.

    Raises
    ------
    UnitsRequired
        (a ValueError) For a plain-text file read without ``units``.
    ValueError
        As raised by the reader, naming the file and line; or, for a file in none of the
        formats, naming the file, its size and the formats read. No message shows any of
        the file's text.
    """
    p = check_file(path)
    fmt = _format_of(p)
    if fmt is not None:
        for key, value in (("column", column), ("time_column", time_column)):
            if value is not None:
                raise ValueError(f"{p}: {key} is for plain-text records; this is a "
                                 f"{fmt.name} file (got {key} = {value!r})")
        if fmt.read is cosmos.read_cosmos:
            return cosmos.read_cosmos(p, dt=dt, units=units, channel=channel)
        if channel is not None:
            raise ValueError(f"{p}: channel is for COSMOS files of several channels; this is "
                             f"a {fmt.name} file (got channel = {channel!r})")
        return fmt.read(p, dt=dt, units=units)
    _check_plain_text(p)
    if channel is not None:
        raise ValueError(f"{p}: channel is for COSMOS files of several channels; this is a "
                         f"plain-text file: choose its column with column (--column on the command "
                         f"line) (got channel = {channel!r})")
    return read_text(p, dt=dt, units=units, column=column, time_column=time_column)


def needs_units(path: str | os.PathLike[str]) -> bool:
    """True if ``path`` is a record that :func:`read_record` reads as plain text, which
    does not state its unit: it needs ``units``. False for any other file, including one
    that is not a record at all (reading it says why)."""
    try:
        p = check_file(path)
        if _format_of(p) is not None:
            return False
        _check_plain_text(p)
    except (ValueError, OSError):
        return False
    return True


def _check_plain_text(p: Path) -> None:
    """Refuse a file that is in none of :data:`FORMATS` and is not plain numbers either,
    naming it, its size and the formats read, and showing none of its text."""
    size = describe_size(p.stat().st_size)
    with p.open("rb") as f:
        if b"\0" in f.read(4096):
            raise ValueError(f"{p}: a binary file ({size}; miniSEED, SAC or the like), not a "
                             f"record format pounding reads; it reads {SUPPORTED}")
    for i, line in enumerate(read_lines(p)):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        if not is_numeric_line(s):
            raise ValueError(f"{p}: not a record format pounding reads ({size}; line {i + 1}, "
                             "its first line that is not blank or a '#' comment, is neither "
                             f"numbers nor a header of a format read); it reads {SUPPORTED}")
        return
