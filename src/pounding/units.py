"""Units. Everything inside ``pounding`` is SI: metre, kilogram, second, newton, joule.

Records stored in units of standard gravity are converted on reading with :data:`G`.

Outputs say their units: :func:`unit_of` and :func:`column_name` read the unit and a
readable name from the name of a results column or a model-file key (``peak_contact_force_N``
→ N, "peak contact force"; ``contact.e`` → -, "coefficient of restitution e");
:func:`format_value` writes a number with its unit in a few digits (``2.75e9 N/m^1.5``).
"""

from __future__ import annotations

import math
import numbers
import re

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


# =============================================================================== columns, keys
_SUFFIX_UNITS: tuple[tuple[str, str], ...] = (
    ("_m_s2", "m/s²"), ("_m_s", "m/s"), ("_N_m", "N/m"), ("_kg", "kg"), ("_Hz", "Hz"),
    ("_pct", "%"), ("_N", "N"), ("_J", "J"), ("_m", "m"), ("_s", "s"), ("_g", "g"),
)
"""Column-name suffix → unit, longest first (sweep results and summaries name their unit)."""

_NAME_UNITS: dict[str, str] = {
    "gap": "m", "gaps": "m", "k": "N/m", "k_h": "N/m^n", "e": "-", "zeta": "-", "chi": "-",
    "n": "-", "a": "-", "c": "N·s/m", "delta_m": "m", "mass": "kg", "masses": "kg",
    "period": "s", "stiffness": "N/m", "stiffnesses": "N/m", "height": "m", "heights": "m",
    "n_storeys": "-", "pga_g": "g", "scale": "-", "duration": "s", "dt": "s", "rtol": "-",
    "h_max": "s", "n_impacts": "-", "impacts": "-", "energy_balance_error": "-",
    "restitution": "-", "drift_ratio": "-", "case": "-", "touched": "-", "pounding": "-",
    "peak_drift_ratio": "-", "impact_overflow": "-", "case_index": "-", "max_ductility": "-",
    "max_column_shear_ratio": "-", "level_tolerance": "m", "slack": "m",
    "yield_force": "N", "abutment_gaps": "m",
}
"""Units of the columns and model-file keys whose name does not end in a unit."""

_KEY_NAMES: dict[str, str] = {
    "gap": "gap", "gaps": "gap", "e": "coefficient of restitution e",
    "k": "contact stiffness k", "k_h": "Hertz stiffness k_h", "c": "dashpot coefficient c",
    "zeta": "impact damping ratio ζ", "chi": "damping factor χ", "n": "Hertz exponent n",
    "delta_m": "assumed peak penetration δm", "a": "yield ratio a", "law": "contact law",
    "formula": "damping formula", "scale": "record scale factor", "pga_g": "record PGA",
    "file": "record", "bundled": "record", "mass": "floor mass", "masses": "floor masses",
    "stiffness": "storey stiffness", "stiffnesses": "storey stiffnesses",
    "period": "period T1", "height": "storey height", "heights": "storey heights",
    "n_storeys": "storeys", "rtol": "relative tolerance", "h_max": "largest step",
    "level_tolerance": "level tolerance", "slack": "restrainer slack",
    "yield_force": "yield force", "abutment_gaps": "abutment gap",
}
_RESTRAINER_NAMES: dict[str, str] = {"k": "stiffness k", "c": "dashpot c", "slack": "slack",
                                     "alpha": "exponent α", "hardening": "hardening ratio"}
"""Readable names of a bridge restrainer's keys (``bridge.joint.N.restrainer.<key>``)."""
"""Readable names of model-file keys (the last part of a sweep's parameter path)."""

_PATH_NAMES: dict[str, str] = {
    "record.duration": "record duration", "record.dt": "record step",
    "solver.duration": "duration simulated", "solver.dt": "output step",
}
"""Readable names of the keys whose meaning depends on their table."""

_MEASURE_NAMES: dict[str, str] = {
    "n_impacts": "impacts", "contact_dissipated": "energy dissipated in contacts",
    "energy_input": "input energy", "energy_balance_error": "energy-balance error",
    "record_pga": "record PGA", "impact_overflow": "impact table overflowed",
    "hysteretic_energy": "hysteretic energy", "max_ductility": "largest ductility demand",
    "max_residual_drift": "largest residual drift",
    "max_column_shear_ratio": "largest column shear over storey shear",
    "peak_abs_accel": "peak absolute acceleration",
    "peak_force": "peak force",
}
"""Readable names of sweep measures (``docs/sweep.md``) without their unit suffix, where
replacing ``_`` by a space does not do."""

_FLOOR = re.compile(r"_(B\d+F\d+|[AJ]\d+|R\d+[a-z]?)$")
"""The floor of a per-floor column, ``<measure>_B1F2``; or a bridge's seat or restrainer
(``<measure>_J1``, ``_A2``, ``_R1``: :mod:`pounding.studies.sweep.bridge_measures`)."""


def unit_of(column: str, units: dict[str, str] | None = None) -> str | None:
    """The unit of a results column or model-file key.

    Parameters
    ----------
    column : str
        A column name (``peak_contact_force_N``, ``peak_drift_m_B2F1``) or a parameter path
        (``contact.gap``, ``building.0.period``).
    units : dict, optional
        Units stated by the results file, by column; they win.

    Returns
    -------
    str or None
        The SI unit (``N``, ``m/s²``; ``-`` for a dimensionless number), None if not known
        or if the name already carries it in brackets.
    """
    if units and column in units:
        return units[column]
    parts = column.split(".")
    base = _FLOOR.sub("", parts[-2] if len(parts) > 2 and parts[-1].isdigit() else parts[-1])
    if base in _NAME_UNITS:
        return _NAME_UNITS[base]
    if re.search(r"\[([^\]]+)\]\s*$", column):
        return None  # the name already carries its unit
    for suffix, unit in _SUFFIX_UNITS:
        if base.endswith(suffix):
            return unit
    return None


def column_name(column: str) -> str:
    """A readable name of a results column or model-file key, without its unit.

    Parameters
    ----------
    column : str
        As for :func:`unit_of`.

    Returns
    -------
    str
        ``contact.gap`` → "gap", ``contact.e`` → "coefficient of restitution e",
        ``building.1.period`` → "B2 period T1", ``peak_contact_force_N`` → "peak contact
        force", ``peak_drift_m_B2F1`` → "peak drift B2F1", ``n_impacts`` → "impacts"; a name
        it does not know with ``_`` read as a space and its unit suffix dropped.
    """
    parts = column.split(".")
    if len(parts) > 1:  # a parameter path: table.key or building.N.key
        item = parts[-1] if parts[-1].isdigit() else None  # an item of a list
        key = parts[-2] if item is not None else parts[-1]
        name = (_PATH_NAMES.get(f"{parts[0]}.{key}") or _KEY_NAMES.get(key)
                or key.replace("_", " "))
        if parts[0] == "building" and len(parts) > 2:
            which = parts[1]
            name = (f"B{int(which) + 1} {name}" if which.isdigit()
                    else f"{name} (every building)" if which == "*" else name)
        if parts[0] == "bridge":  # joint N's gap or restrainer, abutment gap N
            if "restrainer" in parts[:-1]:
                name = "restrainer " + _RESTRAINER_NAMES.get(key, key.replace("_", " "))
            joint = parts.index("joint") + 1 if "joint" in parts else 0
            if joint and joint < len(parts):
                which = parts[joint]
                name = (f"J{int(which) + 1} {name}" if which.isdigit()
                        else f"{name} (every joint)" if which == "*" else name)
            elif item is not None and key == "abutment_gaps":
                name = f"A{int(item) + 1} {name}"
        return name
    m = _FLOOR.search(column)
    base = column[:m.start()] if m else column
    where = f" {m.group(1)}" if m else ""
    if base in _MEASURE_NAMES or base in _KEY_NAMES:
        return (_MEASURE_NAMES.get(base) or _KEY_NAMES[base]) + where
    if base not in _NAME_UNITS:
        for suffix, _ in _SUFFIX_UNITS:
            if base.endswith(suffix) and len(base) > len(suffix):
                base = base[:-len(suffix)]
                break
    return _MEASURE_NAMES.get(base, base.replace("_", " ")) + where


def format_value(value: float, unit: str = "", digits: int = 3) -> str:
    """A number in ``digits`` significant digits, with its unit.

    Parameters
    ----------
    value : float
        The number (SI).
    unit : str
        Its unit; empty or ``-`` (dimensionless) for none.
    digits : int
        Significant digits.

    Returns
    -------
    str
        Plain between 0.001 and 10,000 (``0.373``, ``1.5 s``), else with a short exponent
        (``2.75e9 N/m^1.5``, ``2.40e5 kg``); ``0``, ``nan``, ``inf`` as such.
    """
    v = float(value)
    if v == 0.0 or not math.isfinite(v):
        text = "0" if v == 0.0 else str(v)
    elif 1e-3 <= abs(v) < 1e4:
        text = f"{v:.{digits}g}"
        if "e" in text:  # 1000 … 9999 with fewer digits than places
            text = f"{v:.0f}"
    else:
        mantissa, exponent = f"{v:.{max(digits - 1, 0)}e}".split("e")
        text = f"{mantissa}e{int(exponent)}"
    return f"{text} {unit}" if unit and unit != "-" else text


MAX_ANGLE_DEG = 360.0
"""Largest |angle| [degrees] of a direction: one turn either way. Beyond it an angle is a
mistake (1e308 degrees names no direction: its cosine is rounding noise)."""


def direction_cosines(direction: str | float) -> tuple[float, float]:
    """``(cos β, sin β)`` of ``"x"``, ``"y"`` or an angle β [degrees] from the x axis, in
    [-360, 360], exact (0 or ±1) at multiples of 90° so that elements along the axes couple
    nothing."""
    if direction == "x":
        return 1.0, 0.0
    if direction == "y":
        return 0.0, 1.0
    if isinstance(direction, numbers.Real) and not isinstance(direction, bool) \
            and math.isfinite(direction) and abs(direction) <= MAX_ANGLE_DEG:
        quarter, rest = divmod(float(direction), 90.0)
        if rest == 0.0:
            return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
        beta = math.radians(float(direction))
        return math.cos(beta), math.sin(beta)
    raise ValueError(f"direction must be 'x', 'y' or an angle in [-360, 360] degrees (got "
                     f"{direction!r})")
