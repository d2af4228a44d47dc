"""Plain-text records: :func:`read_text`, one column of accelerations (with a given time
step), two columns, time and acceleration, or several columns (``t, NS, EW, V``) of which
``column`` is read."""

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


class _ColumnNames(dict[int, tuple[str, ...]]):
    """What the values of a line are, by how many it holds (for the messages): time,
    acceleration, or ``column k`` for one that is not read."""

    def __init__(self, column: int | None, time_column: int | None) -> None:
        super().__init__()
        self.column, self.time_column = column, time_column

    def __bool__(self) -> bool:  # empty, yet it names every count of values
        return True

    def get(self, n: int, default: object = ()) -> tuple[str, ...]:
        acc, tcol = _layout(n, self.column, self.time_column)
        return tuple("acceleration" if k == acc else "time" if k == tcol else f"column {k}"
                     for k in range(1, n + 1))


def _layout(n: int, column: int | None, time_column: int | None) -> tuple[int, int]:
    """(acceleration column, time column) of a line of ``n`` values, from 1; time column 0:
    none. The defaults: one column is the acceleration; two are time, acceleration; with
    ``column`` given, the time is column 1 of a file of several columns unless
    ``column`` is 1 (then there is none)."""
    acc = column if column is not None else (1 if n == 1 else 2)
    if time_column is not None:
        return acc, time_column
    return acc, (1 if n > 1 and acc != 1 else 0)


def read_text(path: str | os.PathLike[str], dt: float | None = None,
              units: str | None = None, *, column: int | None = None,
              time_column: int | None = None) -> GroundMotion:
    """Read a plain-text record: one column of accelerations, two columns time and
    acceleration, or any number of columns with the acceleration's chosen by ``column``.

    Blank lines and lines starting with ``#`` are skipped; values may be separated by
    spaces, tabs or commas; every line holds the same number of values.

    Parameters
    ----------
    path : path-like
        The file.
    dt : float, optional
        Time step [s]. Required without a time column. With one the step is taken from
        it, which must be uniform (every step within 1e-6 relative of the mean); a ``dt``
        given as well must agree with it.
    units : str
        Unit of the acceleration column (any of :data:`pounding.units.ACCELERATION_UNITS`:
        ``"g"``, ``"m/s2"``, ``"cm/s2"``, ``"gal"``...). Required: a text file does not
        state its unit, and none is assumed (El Centro in g read as m/s² would be a record
        ten times too weak).
    column : int, optional
        The column of the acceleration, counted from 1 (a file ``t, NS, EW, V``: 2 for
        N–S). Default: the only column of a one-column file, the second of a two-column
        one; required for more columns.
    time_column : int, optional
        The column of the time, counted from 1, or 0: none (then ``dt`` is required).
        Default: none for a one-column file; column 1 of a file of several columns, unless
        ``column`` is 1.

    Returns
    -------
    GroundMotion
        First sample at ``t = 0``: a time column that starts elsewhere is shifted and the
        start is kept in ``metadata["t0"]`` [s]. ``metadata`` also holds ``columns`` (how
        many the file has), ``column`` and ``time_column`` (as read; 0: none). The name is
        the file stem, with the column for a file of more than two columns
        (``"motion (column 3)"``).

    Raises
    ------
    UnitsRequired
        (a ValueError) If ``units`` is not given, once the file has read as a record.
    ValueError
        Naming the file and line (never showing its text): a token that is not a number, a
        non-finite value, a row with a different number of columns, more than two columns
        and no ``column``, a ``column`` or ``time_column`` the file does not have (or the
        same one for both), no data, no time column and no ``dt``, or a non-uniform time
        column.
    """
    p = check_file(path)
    where = str(p)
    unit = None if units is None else canonical_unit(units, f"{where}: units")
    if column is not None:
        column = _column_number("column", column, 1)
    if time_column is not None:
        time_column = _column_number("time_column", time_column, 0)
    names = _ColumnNames(column, time_column)
    rows: list[list[float]] = []
    linenos: list[int] = []
    for i, line in enumerate(read_lines(p)):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        vals = parse_values(s, i + 1, where, names)
        if rows and len(vals) != len(rows[0]):
            raise ValueError(f"{where}: line {i + 1}: {len(vals)} column(s) but line "
                             f"{linenos[0]} has {len(rows[0])}")
        if not rows and len(vals) > 2 and column is None:
            raise ValueError(f"{where}: line {i + 1}: {len(vals)} columns; say which is the "
                             "acceleration with column (from 1: [record] column in a model "
                             "file, --column on the command line) and, if the time is not "
                             "the first, which is with time_column (0: none, then give dt)")
        rows.append(vals)
        linenos.append(i + 1)
    if not rows:
        raise ValueError(f"{where}: no data values (only blank or '#' comment lines)")
    data = np.asarray(rows, dtype=np.float64)
    n = data.shape[1]
    acc, tcol = _layout(n, column, time_column)
    for key, k in (("column", acc), ("time_column", tcol)):
        if k > n:
            raise ValueError(f"{where}: {key} = {k}, but the file has {n} column(s) "
                             f"(line {linenos[0]})")
    if acc == tcol:
        raise ValueError(f"{where}: column and time_column are both {acc}: the acceleration "
                         "and the time must be different columns")
    metadata: dict[str, Any] = {"format": "text", "columns": n, "column": acc,
                                "time_column": tcol}
    if tcol == 0:
        if dt is None:
            what = ("one column of accelerations and no time column" if n == 1 else
                    f"no time column (the acceleration in column {acc} of {n})")
            raise ValueError(f"{where}: {what}; give the time step dt")
        step = positive("dt [s]", dt)
    else:
        t = data[:, tcol - 1]
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
    accel = data[:, acc - 1]
    if unit is None:  # the file read as a record: it needs only its unit
        raise UnitsRequired(where)
    name = p.stem if n <= 2 else f"{p.stem} (column {acc})"
    return GroundMotion(dt=step, accel=to_si(accel, unit, where, linenos.__getitem__),
                        name=name, source=where, units_read=unit, metadata=metadata)


def _column_number(key: str, value: object, low: int) -> int:
    """A column number: an integer from ``low`` (bool and float refused)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise ValueError(f"{key}: a column number, an integer from {low} (got {value!r})")
    return int(value)
