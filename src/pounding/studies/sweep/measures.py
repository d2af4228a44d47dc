"""The row of a case: the summary measures of a simulation, and their column types."""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["FLOOR_MEASURES", "MEASURES", "result_row"]

MEASURES: dict[str, str] = {
    "n_impacts": "int64",
    "peak_contact_force_N": "float64",
    "contact_dissipated_J": "float64",
    "energy_input_J": "float64",
    "energy_balance_error": "float64",
    "peak_drift_ratio": "float64",
    "peak_floor_accel_m_s2": "float64",
    "record_pga_g": "float64",
    "impact_overflow": "bool",
    "hysteretic_energy_J": "float64",
    "max_ductility": "float64",
    "max_residual_drift_m": "float64",
    "max_column_shear_ratio": "float64",
    "links_dissipated_J": "float64",
    "peak_link_force_N": "float64",
}
"""Measures of every case (column → type): impacts (all contacts), largest contact force,
energy dissipated in the contacts and put in by the ground at the end, relative
energy-balance error, largest storey drift / storey height over all storeys, largest
absolute floor acceleration over all floors (of the per-floor columns), PGA of the
record as applied, whether the impact table overflowed; with yielding storeys the
hysteretic energy at the end, the largest storey ductility demand and the largest
|residual drift| (null, null and 0 for linear storeys); with floor-to-column contacts the
largest struck-column shear over its storey's peak shear (null without); with links between
buildings the energy they dissipated and the largest |force| of any (null without)."""

FLOOR_MEASURES: tuple[str, ...] = ("peak_displacement_m", "peak_drift_m", "peak_abs_accel_m_s2")
"""Per-floor measures, one column per floor: ``<measure>_B1F1``, ``<measure>_B1F2``, …
(floor displacement relative to the ground, storey drift, absolute floor acceleration)."""


def _sampled_peak_drift(result: Any) -> np.ndarray:
    """Largest |storey drift| of every storey at the output steps [m] (N,): what
    ``peak_abs(result.drift)`` gives, column by column, without the drift history (a
    first floor's drift is its displacement)."""
    u = result.displacement
    out = np.zeros(u.shape[1])
    if u.shape[0]:
        for off, b in zip(result.model.system.offsets, result.model.buildings):
            out[off] = np.abs(u[:, off]).max()
            for j in range(off + 1, off + b.n):
                out[j] = np.abs(u[:, j] - u[:, j - 1]).max()
    return out


def result_row(result: Any) -> dict[str, Any]:
    """One row of :data:`MEASURES` and :data:`FLOOR_MEASURES` from a Result.

    Parameters
    ----------
    result : pounding.result.Result
        A finished simulation.

    Returns
    -------
    dict
        Column name → value (plain Python numbers; None where a measure does not apply).
    """
    labels = result.model.dof_labels()
    e = result.energy
    pcf = result.peak_contact_force
    from pounding.result import peak_abs

    drift = _sampled_peak_drift(result)
    accel = peak_abs(result.abs_acceleration)
    heights = np.concatenate([b.heights for b in result.model.buildings])
    row: dict[str, Any] = {
        "n_impacts": int(result.n_impacts),
        "peak_contact_force_N": float(pcf.max()) if pcf.size else 0.0,
        "contact_dissipated_J": float(e[-1, 4] - e[-1, 5]),
        "energy_input_J": float(e[-1, 0]),
        "energy_balance_error": float(result.energy_balance_error),
        "peak_drift_ratio": float(np.max(drift / heights)),
        "peak_floor_accel_m_s2": float(np.max(accel)),
        "record_pga_g": float(result.motion.pga_g),
        "impact_overflow": bool(result.stats.impact_overflow),
        # not applicable → null (not NaN: a null compares equal, so tables stay comparable)
        "hysteretic_energy_J": float(e[-1, 6]) if result.model.is_inelastic else None,
        "max_ductility": (float(np.nanmax(result.ductility)) if result.model.is_inelastic
                          else None),
        "max_residual_drift_m": float(np.max(np.abs(result.residual_drift))),
        "max_column_shear_ratio": (float(np.nanmax(result.column_shear_ratio))
                                   if np.isfinite(result.column_shear_ratio).any() else None),
        "links_dissipated_J": float(e[-1, 7]) if result.model.links else None,
        "peak_link_force_N": (float(result.link_peak_force.max()) if result.model.links
                              else None),
    }
    floor = {
        "peak_displacement_m": result.peak_displacement,
        "peak_drift_m": drift,
        "peak_abs_accel_m_s2": accel,
    }
    for name in FLOOR_MEASURES:
        for lb, v in zip(labels, floor[name]):
            row[f"{name}_{lb}"] = float(v)
    return row
