"""The acceleration unit of a record file: stated in its header, given by the caller, or assumed.

:func:`units_in` finds the unit a header line states ("UNITS OF G", "(g)", "cm/s/s",
"CM/S^2", "m/s2", "gal"...); :func:`canonical_unit` checks a unit given by the caller
against :data:`pounding.units.ACCELERATION_UNITS`; :func:`resolve_unit` settles the unit of
a file from what it states, what the caller gives and the format's default;
:data:`ASSUMED` marks a unit that was not stated but assumed; :func:`to_si` converts the
values read to m/s².
"""

from __future__ import annotations

import re
import sys
from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from pounding.units import ACCELERATION_UNITS, acceleration_factor

__all__ = ["ASSUMED", "UNIT_NAMES", "UnitsRequired", "canonical_unit", "resolve_unit",
           "same_unit", "to_si", "units_in"]

UNIT_NAMES = "g, m/s2, cm/s2, gal, mm/s2, in/s2 or ft/s2"
"""The acceleration units a record may be in, for a message (each also written with ``^2``
or ``²``: :data:`pounding.units.ACCELERATION_UNITS`)."""


class UnitsRequired(ValueError):
    """A record file that does not state its acceleration unit (plain text) was read without
    one. ``path`` is the file; callers that know the name of the setting (``record.units``
    of a model file, ``--units`` of a command) may say it."""

    def __init__(self, path: str) -> None:
        self.path = path
        super().__init__(f"{path}: a plain-text record does not state its acceleration unit; "
                         f"give its units: {UNIT_NAMES}")

    def named(self, setting: str) -> ValueError:
        """The same refusal naming the setting that gives the unit (``"--units"``)."""
        return ValueError(f"{setting}: {self.path} is a plain-text record, which does not "
                          f"state its acceleration unit; give {setting} {UNIT_NAMES}")


ASSUMED = " (assumed)"
"""Suffix added to :attr:`GroundMotion.units_read` when the file did not state its units."""

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


def units_in(line: str) -> str | None:
    """The acceleration unit a header line states, or None (earliest mention wins)."""
    low = line.lower()
    best: tuple[int, str] | None = None
    for pattern, unit in _UNIT_PATTERNS:
        m = pattern.search(low)
        if m and (best is None or m.start() < best[0]):
            best = (m.start(), unit)
    return None if best is None else best[1]


def canonical_unit(unit: str, where: str) -> str:
    """Check ``unit`` is known and return its lookup key (``"CM/S^2"`` -> ``"cm/s^2"``)."""
    try:
        acceleration_factor(unit)
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    return unit.strip().lower().replace(" ", "")


def same_unit(a: str, b: str) -> bool:
    return ACCELERATION_UNITS[a] == ACCELERATION_UNITS[b]


def resolve_unit(stated: str | None, given: str | None, where: str,
                 default: str) -> tuple[str, str]:
    """The unit to read a file's values in, and what to report as read.

    Parameters
    ----------
    stated : str or None
        The unit the file states (a key of :data:`pounding.units.ACCELERATION_UNITS`).
    given : str or None
        The unit the caller gives, for a file that states none.
    where : str
        The file, for the message.
    default : str
        The format's convention for a file that states none and is given none; it is
        reported with :data:`ASSUMED` appended.

    Returns
    -------
    tuple of str
        ``(unit, units_read)``.

    Raises
    ------
    ValueError
        If ``given`` is not a known unit, or differs from the ``stated`` one: a file's own
        statement is never overridden silently.
    """
    if given is not None:
        given_unit = canonical_unit(given, "units")
        if stated is not None and not same_unit(given_unit, stated):
            raise ValueError(f"{where}: the header states units {stated!r} but units="
                             f"{given!r} was given")
    if stated is not None:
        return stated, stated
    if given is not None:
        return given_unit, given_unit
    return default, default + ASSUMED


def to_si(values: Sequence[float] | NDArray[np.float64], unit: str, where: str,
          line_of: Callable[[int], int]) -> NDArray[np.float64]:
    """Accelerations read in ``unit``, in m/s² (:func:`pounding.units.acceleration_factor`).

    Parameters
    ----------
    values : sequence of float
        The values as read, all finite.
    unit : str
        Their unit, a key of :data:`pounding.units.ACCELERATION_UNITS`.
    where : str
        The file, for the message.
    line_of : callable
        ``line_of(i)``: the line number of value ``i`` in the file, for the message.

    Raises
    ------
    ValueError
        Naming the file, the line and the value, for a value finite in ``unit`` but beyond
        the largest float in m/s² (e.g. 1e308 g), which would overflow to infinity.
    """
    raw = np.asarray(values, dtype=np.float64)
    with np.errstate(over="ignore"):
        out = raw * acceleration_factor(unit)
    bad = ~np.isfinite(out)
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{where}: line {line_of(i)}: acceleration value {raw[i]:.9g} {unit} "
                         f"is beyond the largest float ({sys.float_info.max:.3g}) in m/s2")
    return out
