"""One entry point for every record format: :func:`read_record` picks the reader of a file
from its suffix, then from its first lines, and falls back to plain text.

Each format is a :class:`RecordFormat` in :data:`FORMATS`, defined in its own module of
:mod:`pounding.ground_motion.readers` (today :mod:`~pounding.ground_motion.readers.at2`);
a new format adds its entry there.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers import at2
from pounding.ground_motion.readers.files import check_file, read_lines
from pounding.ground_motion.readers.units import ASSUMED
from pounding.ground_motion.readers.text import read_text

__all__ = ["FORMATS", "RecordFormat", "read_record"]


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
    RecordFormat("PEER AT2", at2.SUFFIXES, at2.looks_like_at2, at2.read_at2),
)
"""The formats other than plain text, tried in this order (suffixes first, then content)."""


def _format_of(p: Path) -> RecordFormat | None:
    """The format of file ``p`` by its suffix, else by its lines; None for plain text."""
    suffix = p.suffix.lower()
    for fmt in FORMATS:
        if suffix in fmt.suffixes:
            return fmt
    lines = read_lines(p)
    return next((fmt for fmt in FORMATS if fmt.sniff(lines)), None)


def read_record(path: str | os.PathLike[str], dt: float | None = None,
                units: str | None = None) -> GroundMotion:
    """Read an acceleration record, choosing the reader from the suffix and content.

    A ``.AT2`` suffix (any case), or a header with ``NPTS``/``DT``, selects
    :func:`~pounding.ground_motion.readers.at2.read_at2`; anything else
    :func:`~pounding.ground_motion.readers.text.read_text`. For a text file read without
    ``units`` the values are taken as m/s² and ``units_read`` says ``"m/s2 (assumed)"``.

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s], for files that do not give one (see the readers).
    units : str, optional
        Acceleration unit for files that do not state one. For an AT2 header that states a
        different unit this is an error.

    Raises
    ------
    ValueError
        As raised by the reader, naming the file and line.
    """
    p = check_file(path)
    fmt = _format_of(p)
    if fmt is not None:
        return fmt.read(p, dt=dt, units=units)
    if units is None:
        gm = read_text(p, dt=dt, units="m/s2")
        return dataclasses.replace(gm, units_read="m/s2" + ASSUMED)
    return read_text(p, dt=dt, units=units)
