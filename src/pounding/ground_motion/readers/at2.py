"""PEER strong-motion ``.AT2`` files: :func:`read_at2`, and :func:`looks_like_at2`, which
tells such a file by its header for :func:`pounding.ground_motion.readers.read_record`.

The format is that of the PEER ground-motion databases (the PEER strong-motion database and
NGA-West2): a few header lines ending in the number of points and the time step, then the
accelerations, any number per line.
"""

from __future__ import annotations

import bisect
import math
import os
import re
from typing import Any

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.files import check_file, read_lines
from pounding.ground_motion.readers.numbers import is_numeric_line, parse_values, to_float
from pounding.ground_motion.readers.step import resolve_dt
from pounding.ground_motion.readers.units import resolve_unit, to_si, units_in
from pounding.validation import positive

__all__ = ["SUFFIXES", "looks_like_at2", "read_at2"]

SUFFIXES: tuple[str, ...] = (".at2",)
"""File suffixes (lower case) that select :func:`read_at2` whatever the content."""

_RE_NPTS = re.compile(r"\bNPTS\s*[=:]\s*(\S*?)(?=[\s,;]|$)", re.IGNORECASE)
_RE_DT = re.compile(r"\bDT\s*[=:]\s*(\S*?)(?=[\s,;]|SEC|$)", re.IGNORECASE)
_RE_OLD = re.compile(r"^\s*(\S+)\s*,?\s+(\S+?)\s*,?\s+NPTS\s*,\s*DT\b", re.IGNORECASE)
_RE_BEGIN = re.compile(r"^\s*\*+\s*begin\s+data\s*\*+\s*$", re.IGNORECASE)
_RE_END = re.compile(r"^\s*\*+\s*end\s+data\s*\*+\s*$", re.IGNORECASE)
_RE_AT2_LINE = re.compile(r"^\s*(?:NPTS|DT)\s*[=:]", re.IGNORECASE)


def _header_int(token: str, where: str, lineno: int) -> int:
    value = to_float(token)
    if value is None:  # the text is not shown: the file may be anything
        raise ValueError(f"{where}: line {lineno}: NPTS "
                         f"{'has no value' if not token else 'is not a number'}; it must be "
                         "a whole number >= 1")
    if not (math.isfinite(value) and value == int(value) and value >= 1):
        raise ValueError(f"{where}: line {lineno}: NPTS must be a whole number >= 1 "
                         f"(got {value:g})")
    return int(value)


def _header_dt(token: str, where: str, lineno: int) -> float:
    value = to_float(token)
    if value is None:
        raise ValueError(f"{where}: line {lineno}: DT "
                         f"{'has no value' if not token else 'is not a number'}; it must be "
                         "the time step in seconds")
    return positive(f"{where}: line {lineno}: DT [s]", value)


def read_at2(path: str | os.PathLike[str], *, dt: float | None = None,
             units: str | None = None) -> GroundMotion:
    """Read a PEER strong-motion ``.AT2`` acceleration file.

    Accepted layouts (all seen in published files): the 4-line PEER header ending in
    ``NPTS=  4000, DT= .01000 SEC`` or the NGA-West2 ``NPTS=   7500  DT=   .0200 SEC,``
    (commas optional, either order); the older header whose last line reads
    ``7997 0.0050 NPTS, DT``; optional ``*** Begin data ***`` / ``*** End Data ***`` lines;
    any number of values per line, plain or E-notation (Fortran ``D`` exponents and fused
    fixed-width numbers such as ``-0.123E-02-0.456E-02`` too); LF, CRLF or CR line ends; a
    last line with or without a line end. The first value is at ``t = 0``.

    The acceleration unit is taken from the header ("UNITS OF G", "(g)", "cm/s/s",
    "CM/S^2", "m/s2", "gal"...). A file that states none is read as g, recorded as
    ``units_read = "g (assumed)"``.

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s] to use if the header has no ``DT``. If the header has one too, the
        two must agree (1e-6 relative).
    units : str, optional
        Unit of the values if the header states none. If it does, the two must agree.

    Returns
    -------
    GroundMotion
        Acceleration in m/s²; ``name`` is the file stem; ``metadata["header"]`` holds the
        header lines.

    Raises
    ------
    ValueError
        Naming the file and line: no ``DT``, a bad ``NPTS``/``DT`` value, a token that is
        not a number, a NaN or infinite value, no data, ``NPTS`` not equal to the number of
        values read, or units/dt that disagree with the header.
    """
    p = check_file(path)
    where = str(p)
    lines = read_lines(p)

    # The header ends at a '*** Begin data ***' line where there is one (so a header line
    # of numbers alone is still header), else at the first line of numbers alone.
    begin = next((i for i, line in enumerate(lines) if _RE_BEGIN.match(line)), None)
    header_end = begin if begin is not None else next(
        (i for i, line in enumerate(lines) if is_numeric_line(line)), len(lines))
    data_start = header_end if begin is None else begin + 1
    header = lines[:header_end]

    npts: int | None = None
    npts_line = 0
    dt_file: float | None = None
    dt_line = 0
    for i, line in enumerate(header):  # NPTS and DT anywhere in the header; the last wins
        lineno = i + 1
        old = _RE_OLD.match(line)
        if old:
            npts, npts_line = _header_int(old.group(1), where, lineno), lineno
            dt_file, dt_line = _header_dt(old.group(2), where, lineno), lineno
            continue
        m_n = _RE_NPTS.search(line)
        if m_n:
            npts, npts_line = _header_int(m_n.group(1), where, lineno), lineno
        m_d = _RE_DT.search(line)
        if m_d:
            dt_file, dt_line = _header_dt(m_d.group(1), where, lineno), lineno

    span = f"lines 1-{len(header)}" if header else "none before line 1"
    step = resolve_dt(dt_file, dt, where, stated_at=f"line {dt_line}: DT",
                      missing=f"no DT in the header ({span}); expected a line such as "
                              "'NPTS=  4000, DT= .01000 SEC' (or pass dt)")
    unit_file = next((u for u in map(units_in, header) if u is not None), None)
    unit, units_read = resolve_unit(unit_file, units, where, default="g")

    # ---- data
    values: list[float] = []
    starts: list[int] = []  # index in values of the first value of each data line
    linenos: list[int] = []  # and that line's number
    last_line = data_start
    end_line: int | None = None
    for i in range(data_start, len(lines)):
        line = lines[i]
        if _RE_END.match(line):
            end_line = i + 1
            break
        if not line.strip():
            continue
        starts.append(len(values))
        linenos.append(i + 1)
        values.extend(parse_values(line, i + 1, where))
        last_line = i + 1
    if not values:
        if data_start >= len(lines):
            raise ValueError(f"{where}: no data: no line of numbers after the header "
                             f"(lines 1-{len(lines)}); is this a record file?")
        raise ValueError(f"{where}: no data values after the header (line {data_start})")
    if npts is not None and npts != len(values):
        raise ValueError(f"{where}: line {npts_line}: NPTS = {npts} but {len(values)} values "
                         f"were read (lines {data_start + 1}-{last_line})")

    metadata: dict[str, Any] = {"header": tuple(header), "format": "PEER AT2"}
    if npts is not None:
        metadata["npts_header"] = npts
    if end_line is not None:
        metadata["end_marker_line"] = end_line
    accel = to_si(values, unit, where,
                  lambda k: linenos[bisect.bisect_right(starts, k) - 1])
    return GroundMotion(dt=step, accel=accel, name=p.stem, source=where,
                        units_read=units_read, metadata=metadata)


def looks_like_at2(lines: list[str]) -> bool:
    """True if one of the first lines starts with ``NPTS=``/``DT=``, is ``n dt NPTS, DT``
    or is a ``*** Begin data ***`` marker."""
    return any(_RE_AT2_LINE.match(line) or _RE_OLD.match(line) or _RE_BEGIN.match(line)
               for line in lines[:40])
