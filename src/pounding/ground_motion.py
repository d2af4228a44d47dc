"""Ground motions: acceleration records, their readers and synthetic inputs.

A :class:`GroundMotion` is a uniformly sampled horizontal ground acceleration in m/s² whose
first sample is at ``t = 0``. It is built by a reader, which converts the file's units to SI
on reading (:func:`pounding.units.acceleration_factor`), or by a synthetic generator:

* :func:`read_at2` -- PEER strong-motion ``.AT2`` files (every header variant in common use);
* :func:`read_text` -- plain one-column (with ``dt``) or two-column time/acceleration text;
* :func:`read_record` -- either of the above, chosen by suffix and content;
* :func:`el_centro`, :func:`load_bundled`, :func:`bundled_records` -- the records shipped in
  ``pounding/data`` (see ``pounding/data/SOURCES.md`` for their provenance);
* :func:`harmonic`, :func:`sine_pulse`, :func:`ricker` -- closed-form inputs for tests.

Every reader raises :class:`ValueError` naming the file, the line and the bad value. See
``docs/ground_motion.md``.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.units import ACCELERATION_UNITS, G, acceleration_factor
from pounding.validation import finite, non_negative, positive

__all__ = [
    "GroundMotion",
    "bundled_records",
    "el_centro",
    "harmonic",
    "load_bundled",
    "read_at2",
    "read_record",
    "read_text",
    "ricker",
    "sine_pulse",
]

FloatArray = NDArray[np.float64]

ASSUMED = " (assumed)"
"""Suffix added to :attr:`GroundMotion.units_read` when the file did not state its units."""


# ======================================================================== the record
@dataclass(frozen=True, eq=False)
class GroundMotion:
    """A uniformly sampled ground acceleration record, in SI units.

    Parameters
    ----------
    dt : float
        Time step [s], > 0.
    accel : array_like
        Ground acceleration [m/s²], one value per step, first sample at ``t = 0``. Stored
        as a read-only float64 array; every value must be finite and there must be at least
        one.
    name : str
        Short name used in tables and plot titles.
    source : str
        Where the record came from: a file path or a description.
    units_read : str
        The acceleration unit of the source (``"g"``, ``"cm/s2"``, ``"m/s2"``...). A unit
        that was not stated in the file but assumed carries the suffix ``" (assumed)"``.
    metadata : dict
        Anything else read with the record, e.g. ``"header"``: the header lines of an AT2
        file.

    Raises
    ------
    ValueError
        If ``dt`` is not a positive finite number, or ``accel`` is empty, not 1-D or holds
        a non-finite value; the message names the field and the value.
    """

    dt: float
    accel: FloatArray
    name: str = "record"
    source: str = ""
    units_read: str = "m/s2"
    metadata: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        label = f"ground motion {self.name!r}"
        object.__setattr__(self, "dt", positive(f"{label}: dt", self.dt))
        try:
            arr = np.array(self.accel, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"{label}: accel must be an array of numbers") from None
        if arr.ndim != 1:
            raise ValueError(f"{label}: accel must be one-dimensional (got shape {arr.shape})")
        if arr.size == 0:
            raise ValueError(f"{label}: accel must hold at least one value (got none)")
        bad = ~np.isfinite(arr)
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(f"{label}: accel must be finite (got {arr[i]} at index {i})")
        arr.setflags(write=False)
        object.__setattr__(self, "accel", arr)
        object.__setattr__(self, "metadata", dict(self.metadata))

    # ------------------------------------------------------------------ sampling
    @property
    def npts(self) -> int:
        """Number of samples."""
        return int(self.accel.size)

    @property
    def time(self) -> FloatArray:
        """Sample times [s]: ``0, dt, 2 dt, ..., (npts - 1) dt``."""
        return np.arange(self.npts, dtype=np.float64) * self.dt

    @property
    def duration(self) -> float:
        """Time of the last sample [s], ``(npts - 1) dt``."""
        return (self.npts - 1) * self.dt

    # ------------------------------------------------------------------ peaks
    @property
    def pga(self) -> float:
        """Peak ground acceleration, ``max |a|`` [m/s²]."""
        return float(np.max(np.abs(self.accel)))

    @property
    def pga_g(self) -> float:
        """Peak ground acceleration in units of standard gravity [g]."""
        return self.pga / G

    @functools.cached_property
    def pgv(self) -> float:
        """Peak ground velocity, ``max |v|`` [m/s], from :meth:`velocity` (computed once:
        the record is read-only)."""
        return float(np.max(np.abs(self.velocity())))

    @property
    def pgd(self) -> float:
        """Peak ground displacement, ``max |u|`` [m], from :meth:`displacement`.

        With no baseline correction this drifts for most recorded motions; use it as an
        indication only.
        """
        return float(np.max(np.abs(self.displacement())))

    def velocity(self) -> FloatArray:
        """Ground velocity [m/s] at :attr:`time`, by the trapezoidal rule from ``v(0) = 0``.

        No baseline correction or filtering is applied.
        """
        return _cumtrapz(self.accel, self.dt)

    def displacement(self) -> FloatArray:
        """Ground displacement [m] at :attr:`time`: :meth:`velocity` integrated likewise."""
        return _cumtrapz(self.velocity(), self.dt)

    # ------------------------------------------------------------------ evaluation
    @overload
    def accel_at(self, t: float) -> float: ...

    @overload
    def accel_at(self, t: ArrayLike) -> FloatArray | float: ...

    def accel_at(self, t: ArrayLike) -> FloatArray | float:
        """Ground acceleration [m/s²] at time(s) ``t`` [s], by linear interpolation.

        The ground is at rest outside the record: the result is 0 for ``t < 0`` and for
        ``t > duration``.

        Parameters
        ----------
        t : float or array_like
            Time(s) [s].

        Returns
        -------
        float or ndarray
            A float for a scalar ``t``, else an array of the same shape.
        """
        tt = np.asarray(t, dtype=np.float64)
        x = tt / self.dt
        out = np.interp(x, np.arange(self.npts, dtype=np.float64), self.accel,
                        left=0.0, right=0.0)
        return float(out) if out.ndim == 0 else out

    # ------------------------------------------------------------------ new records
    def scaled(self, factor: float) -> GroundMotion:
        """Return this record with every acceleration multiplied by ``factor`` [-]."""
        f = finite("scale factor", factor)
        return dataclasses.replace(self, accel=self.accel * f,
                                   metadata={**self.metadata,
                                             "scale_factor": self.metadata.get(
                                                 "scale_factor", 1.0) * f})

    def scaled_to_pga(self, pga_g: float) -> GroundMotion:
        """Return this record scaled so that its PGA is ``pga_g`` [g].

        Raises
        ------
        ValueError
            If ``pga_g`` is not > 0, or the record is all zeros.
        """
        target = positive("pga_g", pga_g)
        if self.pga == 0.0:
            raise ValueError(f"ground motion {self.name!r}: cannot scale to pga_g={target:g}: "
                             "the record is all zeros")
        return self.scaled(target * G / self.pga)

    def trimmed(self, t_end: float) -> GroundMotion:
        """Return the samples at times ``t <= t_end`` [s] (at least the first one)."""
        te = non_negative("t_end", t_end)
        n = min(self.npts, int(math.floor(te / self.dt * (1.0 + 1e-12) + 1e-9)) + 1)
        return dataclasses.replace(self, accel=self.accel[:n])


def _cumtrapz(y: FloatArray, dt: float) -> FloatArray:
    out = np.zeros_like(y, dtype=np.float64)
    if y.size > 1:
        out[1:] = np.cumsum(0.5 * dt * (y[1:] + y[:-1]))
    return out


# ======================================================================== units
_NUM = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][+-]?\d+)?"
_PER_S2 = r"\s*/\s*s(?:ec)?\s*(?:/\s*s(?:ec)?\b|\^?\s*2\b|\*\*\s*2\b|²)"
_UNIT_PATTERNS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"(?<![a-z])cm" + _PER_S2), "cm/s2"),
    (re.compile(r"(?<![a-z])mm" + _PER_S2), "mm/s2"),
    (re.compile(r"(?<![a-z])m" + _PER_S2), "m/s2"),
    (re.compile(r"(?<![a-z])in(?:ch|ches)?" + _PER_S2), "in/s2"),
    (re.compile(r"(?<![a-z])ft" + _PER_S2), "ft/s2"),
    (re.compile(r"(?<![a-z])gals?(?![a-z])"), "gal"),
    (re.compile(r"\bunits?\s*(?:of|in|are|is|=|:)?\s*\(?\s*g(?![a-z0-9/'])"), "g"),
    (re.compile(r"\(\s*g\s*\)"), "g"),
    (re.compile(r"\b(?:in|of)\s+g(?![a-z0-9/'])\s*(?:[.,;)]|$)"), "g"),
]


def _units_in(line: str) -> str | None:
    """The acceleration unit a header line states, or None (earliest mention wins)."""
    low = line.lower()
    best: tuple[int, str] | None = None
    for pattern, unit in _UNIT_PATTERNS:
        m = pattern.search(low)
        if m and (best is None or m.start() < best[0]):
            best = (m.start(), unit)
    return None if best is None else best[1]


def _canonical_unit(unit: str, where: str) -> str:
    """Check ``unit`` is known and return its lookup key (``"CM/S^2"`` -> ``"cm/s^2"``)."""
    try:
        acceleration_factor(unit)
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    return unit.strip().lower().replace(" ", "")


def _same_unit(a: str, b: str) -> bool:
    return ACCELERATION_UNITS[a] == ACCELERATION_UNITS[b]


# ======================================================================== tokenising
_FUSED_PIECE = re.compile(_NUM)


def _to_float(token: str) -> float | None:
    """A token as a float (Fortran ``D`` exponents allowed), or None."""
    try:
        return float(token)
    except ValueError:
        pass
    if "d" in token or "D" in token:
        try:
            return float(token.replace("d", "e").replace("D", "e"))
        except ValueError:
            return None
    return None


def _split_fused(token: str) -> list[float] | None:
    """Split a Fortran fixed-width run such as ``-0.123E-02-0.456E-02`` into its numbers.

    Accepted only if the pieces cover the token exactly, every piece has a decimal point
    and every piece after the first starts with a sign (the only way two numbers fuse).
    """
    pieces = [m.group(0) for m in _FUSED_PIECE.finditer(token)]
    if len(pieces) < 2 or "".join(pieces) != token:
        return None
    if any("." not in p for p in pieces) or any(p[0] not in "+-" for p in pieces[1:]):
        return None
    values = [_to_float(p) for p in pieces]
    return None if any(v is None for v in values) else values  # type: ignore[return-value]


def _parse_values(line: str, lineno: int, where: str) -> list[float]:
    """Every number on a data line; raise naming the line for a bad or non-finite token."""
    tokens = line.replace(",", " ").split()
    try:
        values = [float(t) for t in tokens]
    except ValueError:
        values = []
        for tok in tokens:
            v = _to_float(tok)
            if v is not None:
                values.append(v)
                continue
            fused = _split_fused(tok)
            if fused is None:
                raise ValueError(f"{where}: line {lineno}: {tok!r} is not a number") from None
            values.extend(fused)
    for v in values:
        if not math.isfinite(v):
            raise ValueError(f"{where}: line {lineno}: acceleration value {v} is not finite")
    return values


def _is_numeric_line(line: str) -> bool:
    tokens = line.replace(",", " ").split()
    return bool(tokens) and all(
        _to_float(t) is not None or _split_fused(t) is not None for t in tokens)


def _read_lines(path: Path) -> list[str]:
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


def _check_file(path: str | os.PathLike[str]) -> Path:
    p = Path(path)
    if not p.exists():
        raise FileNotFoundError(f"{p}: no such file")
    if p.is_dir():
        raise IsADirectoryError(f"{p}: is a directory, not a record file")
    return p


# ======================================================================== AT2
_RE_NPTS = re.compile(r"\bNPTS\s*[=:]\s*(\S*?)(?=[\s,;]|$)", re.IGNORECASE)
_RE_DT = re.compile(r"\bDT\s*[=:]\s*(\S*?)(?=[\s,;]|SEC|$)", re.IGNORECASE)
_RE_OLD = re.compile(r"^\s*(\S+)\s*,?\s+(\S+?)\s*,?\s+NPTS\s*,\s*DT\b", re.IGNORECASE)
_RE_BEGIN = re.compile(r"^\s*\*+\s*begin\s+data\s*\*+\s*$", re.IGNORECASE)
_RE_END = re.compile(r"^\s*\*+\s*end\s+data\s*\*+\s*$", re.IGNORECASE)


def _header_int(token: str, where: str, lineno: int) -> int:
    try:
        value = float(token)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value == int(value) and value >= 1):
        raise ValueError(f"{where}: line {lineno}: NPTS must be a whole number >= 1 "
                         f"(got {token!r})")
    return int(value)


def _header_dt(token: str, where: str, lineno: int) -> float:
    value = _to_float(token)
    if value is None:
        raise ValueError(f"{where}: line {lineno}: DT must be a number (got {token!r})")
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
    p = _check_file(path)
    where = str(p)
    lines = _read_lines(p)

    npts: int | None = None
    npts_line = 0
    dt_file: float | None = None
    dt_line = 0
    data_start: int | None = None  # index into lines
    for i, line in enumerate(lines):
        lineno = i + 1
        if _RE_BEGIN.match(line):
            data_start = i + 1
            break
        old = _RE_OLD.match(line)
        if old:
            npts, npts_line = _header_int(old.group(1), where, lineno), lineno
            dt_file, dt_line = _header_dt(old.group(2), where, lineno), lineno
            continue
        if _is_numeric_line(line):
            data_start = i
            break
        m_n = _RE_NPTS.search(line)
        if m_n:
            npts, npts_line = _header_int(m_n.group(1), where, lineno), lineno
        m_d = _RE_DT.search(line)
        if m_d:
            dt_file, dt_line = _header_dt(m_d.group(1), where, lineno), lineno
    if data_start is None:
        data_start = len(lines)
    header = lines[:data_start]
    if _RE_BEGIN.match(header[-1] if header else ""):
        header = header[:-1]

    # ---- time step
    if dt_file is None:
        if dt is None:
            span = f"lines 1-{len(header)}" if header else "none before line 1"
            raise ValueError(f"{where}: no DT in the header ({span}); expected a line such as "
                             "'NPTS=  4000, DT= .01000 SEC' (or pass dt)")
        step = positive("dt [s]", dt)
    else:
        step = dt_file
        if dt is not None:
            given = positive("dt [s]", dt)
            if abs(given - dt_file) > 1e-6 * dt_file:
                raise ValueError(f"{where}: line {dt_line}: DT = {dt_file:g} s in the file "
                                 f"but dt = {given:g} s was given")

    # ---- units
    unit_file: str | None = None
    for line in header:
        unit_file = _units_in(line)
        if unit_file is not None:
            break
    if units is not None:
        given_unit = _canonical_unit(units, "units")
        if unit_file is not None and not _same_unit(given_unit, unit_file):
            raise ValueError(f"{where}: the header states units {unit_file!r} but units="
                             f"{units!r} was given")
    if unit_file is not None:
        unit, units_read = unit_file, unit_file
    elif units is not None:
        unit = units_read = _canonical_unit(units, "units")
    else:
        unit, units_read = "g", "g" + ASSUMED

    # ---- data
    values: list[float] = []
    last_line = data_start
    end_line: int | None = None
    for i in range(data_start, len(lines)):
        line = lines[i]
        if _RE_END.match(line):
            end_line = i + 1
            break
        if not line.strip():
            continue
        values.extend(_parse_values(line, i + 1, where))
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
    accel = np.asarray(values, dtype=np.float64) * acceleration_factor(unit)
    return GroundMotion(dt=step, accel=accel, name=p.stem, source=where,
                        units_read=units_read, metadata=metadata)


# ======================================================================== text
def read_text(path: str | os.PathLike[str], dt: float | None = None,
              units: str = "m/s2") -> GroundMotion:
    """Read a plain-text record: one column of accelerations, or two columns time, accel.

    Blank lines and lines starting with ``#`` are skipped; values may be separated by
    spaces, tabs or commas.

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s]. Required for one column. For two columns the step is taken from the
        time column, which must be uniform (every step within 1e-6 relative of the mean);
        a ``dt`` given as well must agree with it.
    units : str
        Unit of the acceleration column (default ``"m/s2"``; any of
        :data:`pounding.units.ACCELERATION_UNITS`).

    Returns
    -------
    GroundMotion
        First sample at ``t = 0``: a time column that starts elsewhere is shifted and the
        start is kept in ``metadata["t0"]`` [s].

    Raises
    ------
    ValueError
        Naming the file and line: a token that is not a number, a non-finite value, a row
        with a different number of columns, more than two columns, no data, one column
        and no ``dt``, or a non-uniform time column.
    """
    p = _check_file(path)
    where = str(p)
    unit = _canonical_unit(units, f"{where}: units")
    rows: list[list[float]] = []
    linenos: list[int] = []
    for i, line in enumerate(_read_lines(p)):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        vals = _parse_values(s, i + 1, where)
        if len(vals) > 2:
            raise ValueError(f"{where}: line {i + 1}: expected 1 column (accel) or 2 columns "
                             f"(time, accel), got {len(vals)}")
        if rows and len(vals) != len(rows[0]):
            raise ValueError(f"{where}: line {i + 1}: {len(vals)} column(s) but line "
                             f"{linenos[0]} has {len(rows[0])}")
        rows.append(vals)
        linenos.append(i + 1)
    if not rows:
        raise ValueError(f"{where}: no data values (only blank or '#' comment lines)")
    data = np.asarray(rows, dtype=np.float64)
    metadata: dict[str, Any] = {"format": "text", "columns": data.shape[1]}
    if data.shape[1] == 1:
        if dt is None:
            raise ValueError(f"{where}: one column of accelerations and no time column; "
                             "give the time step dt")
        step = positive("dt [s]", dt)
        accel = data[:, 0]
    else:
        t = data[:, 0]
        if t.size < 2:
            raise ValueError(f"{where}: line {linenos[0]}: a time column needs at least two "
                             "rows to give the time step")
        steps = np.diff(t)
        step = float((t[-1] - t[0]) / (t.size - 1))
        if not step > 0.0:
            raise ValueError(f"{where}: line {linenos[1]}: time must increase "
                             f"(got {t[0]:g} then {t[1]:g})")
        bad = np.abs(steps - step) > 1e-6 * step
        if np.any(bad):
            k = int(np.flatnonzero(bad)[0])
            raise ValueError(f"{where}: line {linenos[k + 1]}: time step {steps[k]:.9g} s "
                             f"(from t = {t[k]:.9g} to {t[k + 1]:.9g}) differs from the mean "
                             f"step {step:.9g} s; the time column must be uniform")
        if dt is not None:
            given = positive("dt [s]", dt)
            if abs(given - step) > 1e-6 * step:
                raise ValueError(f"{where}: the time column gives dt = {step:.9g} s but dt = "
                                 f"{given:g} s was given")
        step = float(f"{step:.12g}")  # 59.98 / 2999 -> 0.02, not 0.019999999999999997
        metadata["t0"] = float(t[0])
        accel = data[:, 1]
    return GroundMotion(dt=step, accel=accel * acceleration_factor(unit), name=p.stem,
                        source=where, units_read=unit, metadata=metadata)


# ======================================================================== dispatch
_RE_AT2_LINE = re.compile(r"^\s*(?:NPTS|DT)\s*[=:]", re.IGNORECASE)


def _looks_like_at2(lines: list[str]) -> bool:
    """True if one of the first lines starts with ``NPTS=``/``DT=``, is ``n dt NPTS, DT``
    or is a ``*** Begin data ***`` marker."""
    return any(_RE_AT2_LINE.match(line) or _RE_OLD.match(line) or _RE_BEGIN.match(line)
               for line in lines[:40])


def read_record(path: str | os.PathLike[str], dt: float | None = None,
                units: str | None = None) -> GroundMotion:
    """Read an acceleration record, choosing the reader from the suffix and content.

    A ``.AT2`` suffix (any case), or a header with ``NPTS``/``DT``, selects
    :func:`read_at2`; anything else :func:`read_text`. For a text file read without
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
    p = _check_file(path)
    if p.suffix.lower() == ".at2" or _looks_like_at2(_read_lines(p)):
        return read_at2(p, dt=dt, units=units)
    if units is None:
        gm = read_text(p, dt=dt, units="m/s2")
        return dataclasses.replace(gm, units_read="m/s2" + ASSUMED)
    return read_text(p, dt=dt, units=units)


# ======================================================================== bundled
_DATA = "data"
_EL_CENTRO = "elcentro_1940_IV_ELC9_180_PEER.AT2"


def bundled_records() -> list[str]:
    """File names of the records shipped in ``pounding/data`` (provenance in its SOURCES.md)."""
    return list(_bundled_names())


@functools.lru_cache(maxsize=1)
def _bundled_names() -> tuple[str, ...]:
    folder = resources.files("pounding").joinpath(_DATA)
    return tuple(sorted(f.name for f in folder.iterdir()
                        if f.is_file() and f.name.lower().endswith(".at2")))


@functools.lru_cache(maxsize=16)
def load_bundled(name: str) -> GroundMotion:
    """Read a bundled record by file name (see :func:`bundled_records`); the stem works too.

    Cached: the data ship with the package and a GroundMotion is immutable."""
    names = bundled_records()
    match = [n for n in names if name in (n, Path(n).stem)]
    if not match:
        raise ValueError(f"bundled record: unknown name {name!r}; choose one of "
                         f"{', '.join(names)}")
    res = resources.files("pounding").joinpath(_DATA).joinpath(match[0])
    with resources.as_file(res) as file:
        gm = read_at2(file)
    return dataclasses.replace(gm, source=f"pounding/data/{match[0]} (bundled)")


@functools.lru_cache(maxsize=1)
def el_centro() -> GroundMotion:
    """Imperial Valley 1940, El Centro Array #9, component 180 (PEER; bundled).

    4000 samples at 0.01 s, PGA 0.3129 g. Provenance: ``pounding/data/SOURCES.md``.
    """
    gm = load_bundled(_EL_CENTRO)
    return dataclasses.replace(gm, name="El Centro 1940 (Array #9, 180)")


# ======================================================================== synthetic
def _samples(duration: float, dt: float) -> FloatArray:
    d = non_negative("duration [s]", duration)
    step = positive("dt [s]", dt)
    n = int(math.floor(d / step * (1.0 + 1e-12) + 1e-9)) + 1
    return np.arange(n, dtype=np.float64) * step


def harmonic(amplitude: float, frequency_hz: float, duration: float, dt: float,
             phase: float = 0.0) -> GroundMotion:
    """A sinusoidal ground acceleration ``a(t) = A sin(2π f t + φ)``.

    Parameters
    ----------
    amplitude : float
        ``A`` [m/s²].
    frequency_hz : float
        ``f`` [Hz], > 0.
    duration : float
        Time of the last sample [s] (samples at ``0, dt, ...`` up to ``duration``).
    dt : float
        Time step [s].
    phase : float
        ``φ`` [rad].

    Notes
    -----
    For ``φ = 0`` the exact velocity is ``v(t) = A/ω (1 − cos ωt)`` with ``ω = 2πf``, so the
    PGV over at least half a period is ``2A/ω`` [m/s].
    """
    a = finite("amplitude [m/s²]", amplitude)
    f = positive("frequency_hz [Hz]", frequency_hz)
    ph = finite("phase [rad]", phase)
    t = _samples(duration, dt)
    return GroundMotion(dt=float(dt), accel=a * np.sin(2.0 * np.pi * f * t + ph),
                        name=f"harmonic {f:g} Hz", source="synthetic: harmonic",
                        units_read="m/s2",
                        metadata={"amplitude": a, "frequency_hz": f, "phase": ph})


def sine_pulse(amplitude: float, period: float, dt: float,
               duration: float | None = None) -> GroundMotion:
    """One full sine cycle ``a(t) = A sin(2π t / T)`` for ``0 ≤ t ≤ T``, then rest.

    Parameters
    ----------
    amplitude : float
        ``A`` [m/s²].
    period : float
        ``T`` [s], > 0.
    dt : float
        Time step [s].
    duration : float, optional
        Time of the last sample [s]; default ``T``.

    Notes
    -----
    Exact velocity ``v(t) = A T/(2π) (1 − cos(2πt/T))``: PGV ``A T / π`` at ``t = T/2``,
    and ``v = 0`` after the pulse; the displacement ends at ``A T² / (2π)``.
    """
    a = finite("amplitude [m/s²]", amplitude)
    T = positive("period [s]", period)
    t = _samples(T if duration is None else duration, dt)
    acc = np.where(t <= T * (1.0 + 1e-12), a * np.sin(2.0 * np.pi * t / T), 0.0)
    return GroundMotion(dt=float(dt), accel=acc, name=f"sine pulse T={T:g} s",
                        source="synthetic: sine pulse", units_read="m/s2",
                        metadata={"amplitude": a, "period": T})


def ricker(amplitude: float, peak_frequency_hz: float, dt: float, duration: float,
           t0: float | None = None) -> GroundMotion:
    """A Ricker wavelet ``a(t) = A (1 − 2τ²π²f²) exp(−τ²π²f²)``, ``τ = t − t0``.

    Parameters
    ----------
    amplitude : float
        ``A``, the peak acceleration [m/s²] (at ``t = t0``).
    peak_frequency_hz : float
        ``f`` [Hz], > 0.
    dt : float
        Time step [s].
    duration : float
        Time of the last sample [s].
    t0 : float, optional
        Centre [s]; default ``1.5 / f``.

    Notes
    -----
    Exact velocity ``v(t) = A [τ e^{−π²f²τ²} − τ₀ e^{−π²f²τ₀²}]`` with ``τ₀ = −t0``; when
    the start is far in the tail, PGV ``= A e^{−1/2} / (√2 π f)`` at ``τ = ±1/(√2 π f)``.
    """
    a = finite("amplitude [m/s²]", amplitude)
    f = positive("peak_frequency_hz [Hz]", peak_frequency_hz)
    centre = 1.5 / f if t0 is None else finite("t0 [s]", t0)
    t = _samples(duration, dt)
    x = (np.pi * f * (t - centre)) ** 2
    return GroundMotion(dt=float(dt), accel=a * (1.0 - 2.0 * x) * np.exp(-x),
                        name=f"Ricker {f:g} Hz", source="synthetic: Ricker wavelet",
                        units_read="m/s2",
                        metadata={"amplitude": a, "peak_frequency_hz": f, "t0": centre})
