"""K-NET and KiK-net ASCII files (NIED, Japan): :func:`read_knet`, and
:func:`looks_like_knet`, which tells such a file by its first line for
:func:`pounding.ground_motion.readers.read_record`.

The format is NIED's "K-NET ASCII format" (the KiK-net files use it too): 17 header lines,
each a label in columns 1-18 and its value from column 19 (``Origin Time``, ``Lat.``,
``Long.``, ``Depth. (km)``, ``Mag.``, ``Station Code``, ``Station Lat.``, ``Station
Long.``, ``Station Height(m)``, ``Record Time``, ``Sampling Freq(Hz)``, ``Duration
Time(s)``, ``Dir.``, ``Scale Factor``, ``Max. Acc. (gal)``, ``Last Correction``,
``Memo.``), then the recorded integer counts, 8 a line. The acceleration in gal is
``counts × numerator / denominator`` of the scale factor (``7845(gal)/8223790``), less the
mean of the whole record: NIED's header maximum (``Max. Acc.``) is that of the record so
corrected, and so is what this reader returns.
"""

from __future__ import annotations

import bisect
import os
import re
from typing import Any

import numpy as np

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.files import check_file, read_lines
from pounding.ground_motion.readers.numbers import parse_values, to_float
from pounding.ground_motion.readers.step import resolve_dt
from pounding.ground_motion.readers.units import canonical_unit, resolve_unit, to_si
from pounding.units import ACCELERATION_UNITS

__all__ = ["SUFFIXES", "looks_like_knet", "read_knet"]

SUFFIXES: tuple[str, ...] = (".ns", ".ew", ".ud", ".ns1", ".ew1", ".ud1", ".ns2", ".ew2",
                             ".ud2")
"""NIED's file suffixes (lower case): the component, and for KiK-net 1 (borehole) or 2
(surface). They select :func:`read_knet` whatever the content."""

_LABELS: tuple[tuple[str, str, str], ...] = (
    ("origin_time", "Origin Time", r"origin\s+time"),
    ("lat", "Lat.", r"lat\."),
    ("lon", "Long.", r"long?\."),
    ("depth_km", "Depth. (km)", r"depth\.\s*\(km\)"),
    ("magnitude", "Mag.", r"mag\."),
    ("station", "Station Code", r"station\s+code"),
    ("station_lat", "Station Lat.", r"station\s+lat\."),
    ("station_lon", "Station Long.", r"station\s+long?\."),
    ("station_height_m", "Station Height(m)", r"station\s+height\s*\(m\)"),
    ("record_time", "Record Time", r"record\s+time"),
    ("sampling_freq", "Sampling Freq(Hz)", r"sampling\s+freq\s*\(hz\)"),
    ("duration_s", "Duration Time(s)", r"duration\s+time\s*\(s\)"),
    ("direction", "Dir.", r"dir\."),
    ("scale_factor", "Scale Factor", r"scale\s+factor"),
    ("max_acc_gal", "Max. Acc. (gal)", r"max\.?\s*acc\.\s*\(gal\)"),
    ("last_correction", "Last Correction", r"last\s+correction"),
    ("memo", "Memo.", r"memo\."),
)
"""The 17 header lines in order: metadata key, label as NIED writes it, and the label's
pattern (NIED writes both ``Lon.`` and ``Long.``, ``Max Acc.`` and ``Max. Acc.``)."""
_RE_LABELS = [re.compile(r"^\s*" + pattern + r"(.*)$", re.IGNORECASE)
              for _, _, pattern in _LABELS]
_LINE = {key: i + 1 for i, (key, _, _) in enumerate(_LABELS)}
"""Line number of each header field."""
_RE_FREQ = re.compile(r"^\s*([0-9.]+)\s*(?:hz)?\s*$", re.IGNORECASE)
_RE_SCALE = re.compile(r"^\s*([0-9.eE+-]+)\s*\(\s*([^)]*?)\s*\)\s*/\s*([0-9.eE+-]+)\s*$")

KIKNET_CHANNELS: dict[str, str] = {
    "1": "NS1 (borehole)", "2": "EW1 (borehole)", "3": "UD1 (borehole)",
    "4": "NS2 (surface)", "5": "EW2 (surface)", "6": "UD2 (surface)",
}
"""KiK-net writes the channel number in ``Dir.``: 1-3 the borehole sensor, 4-6 the surface
one (NIED's KiK-net format notes)."""


def looks_like_knet(lines: list[str]) -> bool:
    """True if the file starts with NIED's first header label, ``Origin Time``."""
    return bool(lines) and _RE_LABELS[0].match(lines[0]) is not None


def read_knet(path: str | os.PathLike[str], *, dt: float | None = None,
              units: str | None = None) -> GroundMotion:
    """Read a K-NET or KiK-net ASCII acceleration file (NIED).

    The counts are multiplied by the header's scale factor (``7845(gal)/8223790``: gal per
    count) and the mean of the whole record is subtracted, as NIED documents; the result
    is converted from gal to m/s². The time step is 1 / ``Sampling Freq(Hz)``; the first
    sample is at ``t = 0`` (NIED's ``Record Time`` includes the logger's 15 s trigger
    delay; it is kept, as written, in the metadata).

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s]; must agree (1e-6 relative) with the sampling frequency in the file.
    units : str, optional
        Must agree with the unit of the scale factor (gal).

    Returns
    -------
    GroundMotion
        ``name`` is the file name (NIED's three components share a stem); ``metadata``
        holds the event (``origin_time``, ``lat``, ``lon``, ``depth_km``, ``magnitude``),
        the station (``station``, ``station_lat``, ``station_lon``, ``station_height_m``),
        the ``component``, the header's ``max_acc_gal`` and ``scale_factor`` as written, the
        ``mean_removed`` (in the scale factor's unit, gal) and the ``header`` lines.

    Raises
    ------
    ValueError
        Naming the file and line: a header line that is not the one expected there, a
        sampling frequency or scale factor that is not a positive number, a count that is
        not a number, no data, or dt/units that disagree with the file.
    """
    p = check_file(path)
    where = str(p)
    lines = read_lines(p)
    n_header = len(_LABELS)
    if len(lines) < n_header:
        raise ValueError(f"{where}: a K-NET file has {n_header} header lines; this one has "
                         f"{len(lines)} lines in all")
    fields: dict[str, str] = {}
    for i, ((key, label, _), regex) in enumerate(zip(_LABELS, _RE_LABELS, strict=True)):
        m = regex.match(lines[i])
        if m is None:
            raise ValueError(f"{where}: line {i + 1}: expected the K-NET header label "
                             f"{label!r} there (line {i + 1} does not start with it)")
        fields[key] = m.group(1).strip()

    freq_line = _LINE["sampling_freq"]
    m_freq = _RE_FREQ.match(fields["sampling_freq"])
    freq = to_float(m_freq.group(1)) if m_freq else None
    if freq is None or not 0.0 < freq < float("inf"):
        got = "not a number" if freq is None else f"got {freq:g} Hz"
        raise ValueError(f"{where}: line {freq_line}: Sampling Freq(Hz) must be a positive "
                         f"number such as '100Hz' ({got})")
    step = resolve_dt(1.0 / freq, dt, where, stated_at=f"line {freq_line}: 1/Sampling Freq",
                      missing="")

    scale_line = _LINE["scale_factor"]
    m_scale = _RE_SCALE.match(fields["scale_factor"])
    num = to_float(m_scale.group(1)) if m_scale else None
    den = to_float(m_scale.group(3)) if m_scale else None
    if (m_scale is None or num is None or den is None
            or not (0.0 < num < float("inf") and 0.0 < den < float("inf"))):
        got = (f"got {num:g}/{den:g}" if num is not None and den is not None
               else "not in that form")
        raise ValueError(f"{where}: line {scale_line}: Scale Factor must read like "
                         f"'7845(gal)/8223790', two positive numbers ({got})")
    unit_file = _scale_unit(m_scale.group(2), where, scale_line)
    unit, units_read = resolve_unit(unit_file, units, where, default=unit_file)

    counts: list[float] = []
    starts: list[int] = []
    linenos: list[int] = []
    for i in range(n_header, len(lines)):
        if not lines[i].strip():
            continue
        starts.append(len(counts))
        linenos.append(i + 1)
        counts.extend(parse_values(lines[i], i + 1, where))
    if not counts:
        raise ValueError(f"{where}: no data: no counts after the {n_header} header lines")

    with np.errstate(over="ignore", invalid="ignore"):
        scaled = np.asarray(counts, dtype=np.float64) * (num / den)  # in the scale's unit
        mean = float(np.mean(scaled))
    if not np.isfinite(mean):
        raise ValueError(f"{where}: line {scale_line}: the counts times the scale factor "
                         f"{num:g}/{den:g} go beyond the largest float")
    accel = to_si(scaled - mean, unit, where,
                  lambda k: linenos[bisect.bisect_right(starts, k) - 1])

    direction = fields["direction"]
    kiknet = direction in KIKNET_CHANNELS or p.suffix[-1:] in ("1", "2")
    metadata: dict[str, Any] = {
        "format": "KiK-net ASCII" if kiknet else "K-NET ASCII",
        "header": tuple(lines[:n_header]),
        **fields,
        "component": KIKNET_CHANNELS.get(direction, direction),
        "sampling_hz": freq,
        "mean_removed": mean,
    }
    for key in ("lat", "lon", "depth_km", "magnitude", "station_lat", "station_lon",
                "station_height_m", "duration_s", "max_acc_gal"):
        value = to_float(fields[key])
        if value is not None:
            metadata[key] = value
    return GroundMotion(dt=step, accel=accel, name=p.name, source=where,
                        units_read=units_read, metadata=metadata)



def _scale_unit(text: str, where: str, line: int) -> str:
    """The unit of the Scale Factor (``gal`` in ``7845(gal)/8223790``), a key of
    :data:`pounding.units.ACCELERATION_UNITS`; refused without showing the file's text."""
    try:
        return canonical_unit(text, "")
    except ValueError:
        raise ValueError(f"{where}: line {line}: the Scale Factor's unit (in parentheses) is "
                         "not an acceleration unit pounding converts (one of "
                         f"{', '.join(ACCELERATION_UNITS)})") from None
