"""Units. Everything inside ``pounding`` is SI: metre, kilogram, second, newton, joule.

Records stored in units of standard gravity are converted on reading with :data:`G`.
"""

from __future__ import annotations

G: float = 9.80665
"""Standard gravity [m/s²] (CGPM 1901), used to convert accelerations given in g."""

ACCELERATION_UNITS: dict[str, float] = {
    "g": G,
    "m/s2": 1.0,
    "m/s^2": 1.0,
    "m/s²": 1.0,
    "cm/s2": 0.01,
    "cm/s^2": 0.01,
    "cm/s²": 0.01,
    "gal": 0.01,
    "mm/s2": 0.001,
    "mm/s^2": 0.001,
    "in/s2": 0.0254,
    "in/s^2": 0.0254,
    "ft/s2": 0.3048,
    "ft/s^2": 0.3048,
}
"""Factor that turns one unit of each named acceleration unit into m/s²."""


def acceleration_factor(unit: str) -> float:
    """Return the factor converting acceleration in ``unit`` to m/s².

    Raises
    ------
    ValueError
        If the unit is not known; the message names it and lists the known ones.
    """
    key = unit.strip().lower().replace(" ", "")
    if key not in ACCELERATION_UNITS:
        known = ", ".join(sorted(ACCELERATION_UNITS))
        raise ValueError(f"units: unknown acceleration unit {unit!r}; use one of {known}")
    return ACCELERATION_UNITS[key]
