"""COSMOS strong-motion files, Volume 1 and 2 (uncorrected and corrected acceleration):
:func:`read_cosmos`, and :func:`looks_like_cosmos`, which tells such a file by its first
line for :func:`pounding.ground_motion.readers.read_record`.

The format is the COSMOS Strong Motion Data Format, version 1.20 (COSMOS Strong Motion
Programs Board, 2001), used by CESMD, CGS and the USGS. A file is one or more series, each
self-contained:

* a text header whose first line states its length,
  ``Corrected acceleration    (Format v01.20 with 13 text lines) ...``; line 2 names the
  event, line 5 the station (``Code:CE-1759``), line 9 the channel's orientation;
* ``100 Integer-header values follow on  10 lines, Format= (10I8)`` and those values:
  ``Int(1)`` the processing stage (0 raw counts, 1 V1, 2 V2), ``Int(3)`` the units code;
* ``100 Real-header values follow on  17 lines, Format= (6F13.6)`` and those values:
  ``Real(62)`` the sampling interval in **milliseconds**, ``Real(64)`` and ``Real(65)`` the
  peak value and its time;
* ``N Comment line(s) follow, each starting with a "|":`` and those lines;
* ``8000 acceleration pts, approx  40 secs, units=cm/sec2 (04), Format=(8F10.5)`` and the
  values;
* ``End-of-data for Chan  1 acceleration``.

Units codes (the format's Table 2) read as acceleration: 2 g, 4 cm/s², 7 in/s², 10 gal.
A V2 file from CGS may follow each acceleration series with its velocity and displacement
series; they are passed over, and ``channel`` counts acceleration series only.
"""

from __future__ import annotations

import bisect
import os
import re
from dataclasses import dataclass
from typing import Any

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.files import check_file, read_lines
from pounding.ground_motion.readers.numbers import parse_values
from pounding.ground_motion.readers.step import resolve_dt
from pounding.ground_motion.readers.units import resolve_unit, to_si, units_in

__all__ = ["SUFFIXES", "UNIT_CODES", "looks_like_cosmos", "read_cosmos"]

SUFFIXES: tuple[str, ...] = (".v1", ".v2", ".v1c", ".v2c")
"""File suffixes (lower case) that select :func:`read_cosmos` whatever the content."""

UNIT_CODES: dict[int, str] = {2: "g", 4: "cm/s2", 7: "in/s2", 10: "gal"}
"""COSMOS units codes (Table 2 of the format) of acceleration, as units pounding converts."""

_RAW_COUNTS = 50
"""The units code of raw counts (a Volume 0 file)."""

_RE_TITLE = re.compile(r"\(\s*format\s+v\s*(\d+\.\d+)\s+with\s+(\d+)\s+text\s+lines?\s*\)",
                       re.IGNORECASE)
_RE_BLOCK = re.compile(r"^\s*(\d+)\s+(integer|real)[- ]header\s+values?\s+follow",
                       re.IGNORECASE)
_RE_COMMENTS = re.compile(r"^\s*(\d+)\s+comment\s+lines?", re.IGNORECASE)
_RE_DATA = re.compile(r"^\s*(\d+)\s+([a-z][a-z ]*?)\s+(?:pts|points)\b(.*)$", re.IGNORECASE)
_RE_DATA_UNITS = re.compile(r"units?\s*=\s*([^,(]*?)\s*\(\s*(\d+)\s*\)", re.IGNORECASE)
_RE_END = re.compile(r"^\s*end[- ]of[- ]data\b", re.IGNORECASE)
_RE_NO_VALUE = re.compile(r"unknown/unspecified\s*:?\s*([+-]?\d+)", re.IGNORECASE)
_RE_STATION = re.compile(r"\bcode\s*:\s*(\S+)", re.IGNORECASE)
_RE_COMPONENT = re.compile(r"\bsta\s+chan\s*[^:\s]*\s*:\s*(.*?)\s*(?:\(|location:|$)",
                           re.IGNORECASE)


@dataclass(frozen=True)
class _Series:
    """One series of a COSMOS file as read: its headers and values, with line numbers."""

    first_line: int
    text: tuple[str, ...]
    ints: tuple[float, ...]
    reals: tuple[float, ...]
    real_lines: tuple[int, ...]
    comments: tuple[str, ...]
    kind: str
    npts: int
    data_line: int
    units_text: str
    units_code: int | None
    values: tuple[float, ...]
    value_lines: tuple[int, ...]
    value_starts: tuple[int, ...]


def looks_like_cosmos(lines: list[str]) -> bool:
    """True if the first line that is not blank states ``(Format v01.20 with 13 text
    lines)`` or the like."""
    first = next((line for line in lines if line.strip()), "")
    return _RE_TITLE.search(first) is not None


def read_cosmos(path: str | os.PathLike[str], *, dt: float | None = None,
                units: str | None = None, channel: int | None = None) -> GroundMotion:
    """Read the acceleration of a COSMOS Volume 1 or Volume 2 file (format v1.20).

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s], for a file whose real header leaves ``Real(62)`` (the sampling
        interval) unknown; if it states one the two must agree (1e-6 relative).
    units : str, optional
        Must agree with the units code of the series.
    channel : int, optional
        Which acceleration series to read, counting from 1, in a file that holds several
        (velocity and displacement series are not counted). Needed for such a file.

    Returns
    -------
    GroundMotion
        Acceleration in m/s²; ``name`` is the file stem (with the channel for a file of
        several); ``metadata`` holds the ``event`` (text line 2), ``station`` (the code on
        line 5), ``component`` (line 9, e.g. ``"360 deg"``), ``peak_header`` and
        ``peak_time_header`` (``Real(64)``, ``Real(65)``; in the file's units and s),
        ``npts_header``, the ``header`` and ``comments`` lines, and the ``channel``.

    Raises
    ------
    ValueError
        Naming the file and line: a header block out of place, a value that is not a
        number, fewer or more values than a block states, raw counts (Volume 0), units that
        are not an acceleration, no acceleration series, several and no ``channel``, no
        sampling interval and no ``dt``, or dt/units that disagree with the file.
    """
    p = check_file(path)
    where = str(p)
    lines = read_lines(p)
    acceleration = [s for s in _read_series(lines, where) if s.kind.startswith("acc")]
    if not acceleration:
        raise ValueError(f"{where}: no acceleration series in this COSMOS file (only "
                         "velocity, displacement or spectra)")
    if channel is None and len(acceleration) > 1:
        listing = "; ".join(f"{k} {_orientation(_component(s))}"
                            for k, s in enumerate(acceleration, start=1))
        raise ValueError(f"{where}: holds {len(acceleration)} acceleration channels "
                         f"({listing}); read one with channel = N (read_cosmos(path, "
                         "channel=N), --channel N on the command line, channel = N in a "
                         "model file's [record])")
    k = 1 if channel is None else channel
    if not 1 <= k <= len(acceleration):
        raise ValueError(f"{where}: channel must be 1 to {len(acceleration)} (got {channel})")
    s = acceleration[k - 1]
    no_value = _no_value(s.text)

    code = s.units_code if s.units_code is not None else _known(s.ints, 2, no_value)
    code = None if code is None else int(code)
    if code == _RAW_COUNTS or _known(s.ints, 0, no_value) == 0:
        raise ValueError(f"{where}: line {s.data_line}: raw counts (COSMOS Volume 0), not "
                         "an acceleration; read the Volume 1 or 2 file of this record")
    unit_file = UNIT_CODES.get(code) if code is not None else units_in(s.units_text)
    if unit_file is None:
        known = ", ".join(f"{c} {u}" for c, u in UNIT_CODES.items())
        stated = f"units code {code}" if code is not None else "the units stated"
        raise ValueError(f"{where}: line {s.data_line}: {stated} on the data line are not "
                         f"an acceleration unit pounding converts (codes {known})")
    unit, units_read = resolve_unit(unit_file, units, where, default=unit_file)

    msec = _known(s.reals, 61, no_value)
    dt_file = msec / 1000.0 if msec is not None and msec > 0.0 else None
    dt_line = s.real_lines[61] if len(s.real_lines) > 61 else s.first_line
    step = resolve_dt(dt_file, dt, where,
                      stated_at=f"line {dt_line}: Real(62), the sampling interval,",
                      missing=f"line {dt_line}: no sampling interval in the real header "
                              "(Real(62), in ms, is unknown); pass dt")

    stage = _known(s.ints, 0, no_value)
    metadata: dict[str, Any] = {
        "format": "COSMOS" + ("" if stage is None else f" V{int(stage)}"),
        "header": s.text,
        "event": " ".join(s.text[1].split()) if len(s.text) > 1 else "",
        "station": _station(s),
        "component": _component(s),
        "comments": s.comments,
        "npts_header": s.npts,
        "channel": k,
    }
    for key, index in (("peak_header", 63), ("peak_time_header", 64)):
        value = _known(s.reals, index, no_value)
        if value is not None:
            metadata[key] = value
    accel = to_si(s.values, unit, where, lambda j: _line_of(s.value_lines, s.value_starts, j))
    name = p.stem if len(acceleration) == 1 else f"{p.stem} (channel {k})"
    return GroundMotion(dt=step, accel=accel, name=name, source=where,
                        units_read=units_read, metadata=metadata)


def _read_series(lines: list[str], where: str) -> list[_Series]:
    """Every series of the file, in order."""
    out: list[_Series] = []
    i = 0
    n = len(lines)
    while True:
        while i < n and not lines[i].strip():
            i += 1
        if i >= n:
            return out
        title = _RE_TITLE.search(lines[i])
        if title is None:
            raise ValueError(f"{where}: line {i + 1}: expected the first text header line of a "
                             "COSMOS series, such as 'Corrected acceleration (Format v01.20 "
                             "with 13 text lines)'; this line is not one")
        first = i
        n_text = int(title.group(2))
        if i + n_text > n:
            raise ValueError(f"{where}: line {i + 1}: states {n_text} text header lines but "
                             f"the file ends at line {n}")
        text = tuple(lines[i:i + n_text])
        i += n_text
        ints, _, i = _block(lines, i, where, "integer")
        reals, real_lines, i = _block(lines, i, where, "real")
        m = _RE_COMMENTS.match(lines[i]) if i < n else None
        if m is None:
            raise ValueError(f"{where}: line {i + 1}: expected the line 'N Comment line(s) "
                             f"follow, ...'; {_at(lines, i)}")
        n_comments = int(m.group(1))
        comments = tuple(lines[i + 1:i + 1 + n_comments])
        i += 1 + n_comments
        m = _RE_DATA.match(lines[i]) if i < n else None
        if m is None:
            raise ValueError(f"{where}: line {i + 1}: expected the data line such as '8000 "
                             "acceleration pts, approx 40 secs, units=cm/sec2 (04), "
                             f"Format=(8F10.5)'; {_at(lines, i)}")
        npts, kind, rest = int(m.group(1)), m.group(2).strip().lower(), m.group(3)
        data_line = i + 1
        u = _RE_DATA_UNITS.search(rest)
        units_text = u.group(1) if u else rest
        units_code = int(u.group(2)) if u else None
        values, value_lines, value_starts, i = _values(lines, i + 1, where, npts, data_line)
        if i < n and _RE_END.match(lines[i]):
            i += 1
        out.append(_Series(first + 1, text, ints, reals, real_lines, comments, kind, npts,
                           data_line, units_text, units_code, values, value_lines,
                           value_starts))


def _block(lines: list[str], i: int, where: str,
           which: str) -> tuple[tuple[float, ...], tuple[int, ...], int]:
    """The integer or real header block at line index ``i``: its values, the line number
    of each, and the index of the line after it."""
    m = _RE_BLOCK.match(lines[i]) if i < len(lines) else None
    if m is None or m.group(2).lower() != which:
        raise ValueError(f"{where}: line {i + 1}: expected the line 'N {which.title()}-header "
                         f"values follow on M lines, ...'; {_at(lines, i)}")
    values, line_numbers, starts, end = _values(lines, i + 1, where, int(m.group(1)), i + 1)
    return values, tuple(_line_of(line_numbers, starts, j) for j in range(len(values))), end


def _line_of(line_numbers: tuple[int, ...], starts: tuple[int, ...], j: int) -> int:
    """The line number of value ``j``, from the number of each line read and the index of
    its first value."""
    return line_numbers[bisect.bisect_right(starts, j) - 1]


def _values(lines: list[str], i: int, where: str, count: int,
            stated_on: int) -> tuple[tuple[float, ...], tuple[int, ...], tuple[int, ...], int]:
    """``count`` values from line index ``i`` on: the values, the number of each line read
    and the index of its first value, and the index of the line after them."""
    values: list[float] = []
    line_numbers: list[int] = []
    starts: list[int] = []
    first = i
    while len(values) < count:
        if i >= len(lines) or not _numeric_start(lines[i]):
            raise ValueError(f"{where}: line {stated_on}: states {count} values but "
                             f"{len(values)} were read (lines {first + 1}-{i})")
        starts.append(len(values))
        line_numbers.append(i + 1)
        values.extend(parse_values(lines[i], i + 1, where))
        i += 1
    if len(values) > count:
        raise ValueError(f"{where}: line {stated_on}: states {count} values but line {i} "
                         f"takes them to {len(values)}")
    return tuple(values), tuple(line_numbers), tuple(starts), i


def _numeric_start(line: str) -> bool:
    """True if a line can hold values: its first token starts like a number."""
    tokens = line.split()
    return bool(tokens) and (tokens[0][0].isdigit() or tokens[0][0] in "+-.")


def _no_value(text: tuple[str, ...]) -> float:
    """The integer the text header's last line gives for an unknown value (-999 if none)."""
    for line in reversed(text):
        m = _RE_NO_VALUE.search(line)
        if m:
            return float(m.group(1))
    return -999.0


def _known(values: tuple[float, ...], index: int, no_value: float) -> float | None:
    """``values[index]``, or None if the block is shorter or it is the unknown value."""
    if index >= len(values) or values[index] == no_value:
        return None
    return values[index]


def _station(s: _Series) -> str:
    m = _RE_STATION.search(s.text[4]) if len(s.text) > 4 else None
    return m.group(1) if m else ""


_RE_ORIENTATION = re.compile(r"\d{1,3}(?:\.\d{1,2})?\s*deg|up|down|vertical|[NSEW]\d{0,2}[NSEW]?",
                             re.IGNORECASE)
"""What an orientation looks like: only such a text of the file is shown in a message."""


def _orientation(component: str) -> str:
    """The channel's orientation for a message ("360 deg", "Up"), or "?" for any other
    text (a message never shows what a file holds beyond what it was read for)."""
    return component if _RE_ORIENTATION.fullmatch(component) else "?"


def _component(s: _Series) -> str:
    m = _RE_COMPONENT.search(s.text[8]) if len(s.text) > 8 else None
    return m.group(1) if m else ""


def _at(lines: list[str], i: int) -> str:
    """What is at line index ``i``, for a message, without its text (the file may be
    anything)."""
    return "this line is not it" if i < len(lines) else "the file ends there"
