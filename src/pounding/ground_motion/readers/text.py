"""Plain-text records: :func:`read_text`, one column of accelerations (with a given time
step) or two columns, time and acceleration."""

from __future__ import annotations

import os
from typing import Any

import numpy as np

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.readers.files import check_file, read_lines
from pounding.ground_motion.readers.numbers import parse_values
from pounding.ground_motion.readers.units import UnitsRequired, canonical_unit, to_si
from pounding.validation import positive

__all__ = ["read_text"]

_COLUMNS = {1: ("acceleration",), 2: ("time", "acceleration")}
"""What the values of a line are, by how many it holds."""


def read_text(path: str | os.PathLike[str], dt: float | None = None,
              units: str | None = None) -> GroundMotion:
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
        Unit of the acceleration column (any of :data:`pounding.units.ACCELERATION_UNITS`:
        ``"g"``, ``"m/s2"``, ``"cm/s2"``, ``"gal"``...). Required: a text file does not
        state its unit, and none is assumed (El Centro in g read as m/s² would be a record
        ten times too weak).

    Returns
    -------
    GroundMotion
        First sample at ``t = 0``: a time column that starts elsewhere is shifted and the
        start is kept in ``metadata["t0"]`` [s].

    Raises
    ------
    UnitsRequired
        (a ValueError) If ``units`` is not given, once the file has read as a record.
    ValueError
        Naming the file and line: a token that is not a number, a non-finite value, a row
        with a different number of columns, more than two columns, no data, one column
        and no ``dt``, or a non-uniform time column.
    """
    p = check_file(path)
    where = str(p)
    unit = None if units is None else canonical_unit(units, f"{where}: units")
    rows: list[list[float]] = []
    linenos: list[int] = []
    for i, line in enumerate(read_lines(p)):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        vals = parse_values(s, i + 1, where, _COLUMNS)
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
    if unit is None:  # the file read as a record: it needs only its unit
        raise UnitsRequired(where)
    return GroundMotion(dt=step, accel=to_si(accel, unit, where, linenos.__getitem__),
                        name=p.stem, source=where, units_read=unit, metadata=metadata)
