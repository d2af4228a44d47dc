"""The row of a case: the summary measures of a simulation, and their column types."""

from __future__ import annotations

import weakref
from typing import Any, NamedTuple

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
energy-balance error, largest storey drift / storey height over all storeys (of a building
on a flexible base: the drift of its own deformation, the footing's sway and rocking taken
out, as :attr:`pounding.result.Result.drift`), largest absolute floor acceleration over all
floors (of the per-floor columns), PGA of the
record as applied, whether the impact table overflowed; with yielding storeys the
hysteretic energy at the end, the largest storey ductility demand and the largest
|residual drift| (null, null and 0 for linear storeys; a frame with plastic hinges has its
hinges' hysteretic energy, no storey ductility and no residual drift computed: null; its
hinges' own measures are :data:`~pounding.studies.sweep.hinge_measures.HINGE_MEASURES`);
with floor-to-column contacts the
largest struck-column shear over its storey's peak shear (null without); with links between
buildings the energy they dissipated and the largest |force| of any (null without)."""

FLOOR_MEASURES: tuple[str, ...] = ("peak_displacement_m", "peak_drift_m", "peak_abs_accel_m_s2")
ROTATION_NAMES: dict[str, str] = {"peak_displacement_m": "peak_rotation_rad",
                                  "peak_drift_m": "peak_twist_rad",
                                  "peak_abs_accel_m_s2": "peak_abs_accel_rad_s2"}
"""The per-floor measures' names for a floor's rotation (a building in plan's ``θ``): its
peak rotation, the peak twist of the storey under it (``θ_j − θ_{j−1}``) and its peak
angular acceleration, in radians."""
"""Per-floor measures, one column per floor: ``<measure>_B1F1``, ``<measure>_B1F2``, …
(floor displacement relative to the ground, storey drift, absolute floor acceleration),
labelled as :meth:`pounding.model.PoundingModel.dof_labels` (a building in plan: ``_B1F1x``,
``_B1F1y``, and its rotation's under :data:`ROTATION_NAMES`). A footing's sway and rocking
(``B1Fdn``, ``B1Fdn_r``, …) are DOFs but no floors: they have no columns (they are in
``summary.json``'s ``foundations`` of a single run)."""


class _Layout(NamedTuple):
    """What a row needs of a model, whatever the run: column names, storey heights, the
    floor below each floor, and which measures apply."""

    floor_columns: tuple[tuple[str, ...], ...]
    """The per-floor column names, one tuple per :data:`FLOOR_MEASURES`."""
    dofs: np.ndarray
    """The DOFs that have per-floor columns (every DOF but a footing's), in their order."""
    translations: np.ndarray
    """Those of them that translate (in m; not a floor's rotation θ in rad)."""
    heights: np.ndarray
    """Storey height of every floor [m] (N,)."""
    below: np.ndarray
    """The floor below each floor (−1: the ground), as :func:`pounding.integrate.floor_below`."""
    flexible: bool
    """Whether some building stands on a flexible base (its storeys' drifts are those of its
    own deformation: :func:`pounding.result.foundations.flexible_base_drifts`)."""
    inelastic: bool
    """Whether any storey yields."""
    hinges: bool
    """Whether any frame has plastic hinges."""
    struck: bool
    """Whether any contact strikes a column (else no column shear applies)."""


_LAYOUTS: dict[int, _Layout] = {}
"""Layouts of the models alive, by the model's identity (an entry goes with its model; the
cases of a sweep that share a model share it: :mod:`.builder`)."""


def _layout(model: Any) -> _Layout:
    """The :class:`_Layout` of a model (remembered while the model lives)."""
    key = id(model)
    layout = _LAYOUTS.get(key)
    if layout is None:
        from pounding.result.foundations import footing_dofs
        from pounding.structure.plan_row import PlanMatrixBuilding

        labels = model.dof_labels()
        below = model.floor_below()  # −2: not a floor (a matrix building's rotation, say)
        heights = np.concatenate([b.heights for b in model.buildings]).astype(float)
        rotation = np.array([u == "rad" for u in model.dof_units()])
        for off, b in zip(model.system.offsets, model.buildings):
            if isinstance(b, PlanMatrixBuilding):
                # a floor in plan: its u_y and θ over the floor below's (its u_x is a floor
                # of floor_below), u_y's drift over the storey's height, θ's twist none
                n = b.plan.n_floors
                for c in (1, 2):
                    d = int(off) + c + 3 * np.arange(n)
                    below[d] = np.r_[-1, d[:-1]]
                    heights[d] = heights[d - c] if c == 1 else np.nan
        own = below == -2
        below[own] = np.flatnonzero(own)  # drift u − u = 0, over a NaN height: left out
        # an isolation bearing under a base slab is no storey: no drift ratio
        # (pounding.result.bearing_mask)
        from pounding.result import bearing_mask

        heights[bearing_mask(model)] = np.nan
        # a footing's sway and rocking are DOFs but no floors: no per-floor columns
        footings = footing_dofs(model)
        dofs = np.setdiff1d(np.arange(len(labels)), footings)
        layout = _Layout(tuple(tuple(f"{ROTATION_NAMES[name] if rotation[j] else name}_"
                                     f"{labels[j]}" for j in dofs)
                               for name in FLOOR_MEASURES), dofs,
                         np.setdiff1d(dofs, np.flatnonzero(rotation)), heights, below,
                         bool(footings.size), bool(model.is_inelastic),
                         bool(model.yielding_frames),
                         any(c.struck is not None for c in model.contacts))
        try:
            # the entry must go when the model does (before its id can be reused)
            weakref.finalize(model, _LAYOUTS.pop, key, None)
        except TypeError:
            return layout  # a model that cannot be weakly referenced is not remembered
        _LAYOUTS[key] = layout
    return layout


def result_row(result: Any) -> dict[str, Any]:
    """One row of :data:`MEASURES` and :data:`FLOOR_MEASURES` from a Result.

    The sampled peaks (storey drift and absolute acceleration at the output steps) are
    read in one pass over each history (:mod:`pounding.result.reductions`).

    Parameters
    ----------
    result : pounding.result.Result
        A finished simulation.

    Returns
    -------
    dict
        Column name → value (plain Python numbers; None where a measure does not apply).
    """
    from pounding.result import abs_max_columns, abs_max_drift

    layout = _layout(result.model)
    e = result.energy
    pcf = result.peak_contact_force
    drift = abs_max_drift(result.displacement, layout.below)
    if layout.flexible:
        # a building on a flexible base: its storeys' drifts are those of its own
        # deformation, the footing's sway and rocking taken out (as Result.drift), read at
        # the output steps (as Result.peak_drift reads them)
        from pounding.result.foundations import flexible_base_drifts

        floor = result.model.is_floor
        for cols, d in flexible_base_drifts(result.model, result.displacement):
            mine = floor[cols]
            drift[cols[mine]] = np.abs(d[:, mine]).max(axis=0)
    accel = abs_max_columns(result.abs_acceleration)
    inelastic = layout.inelastic
    shear_ratio = result.column_shear_ratio if layout.struck else None
    row: dict[str, Any] = {
        "n_impacts": int(result.n_impacts),
        "peak_contact_force_N": float(pcf.max()) if pcf.size else 0.0,
        "contact_dissipated_J": float(e[-1, 4] - e[-1, 5]),
        "energy_input_J": float(e[-1, 0]),
        "energy_balance_error": float(result.energy_balance_error),
        "peak_drift_ratio": float(np.nanmax(drift / layout.heights)),
        "peak_floor_accel_m_s2": float(accel[layout.translations].max()),
        "record_pga_g": float(result.motion.pga_g),
        "impact_overflow": bool(result.stats.impact_overflow),
        # not applicable → null (not NaN: a null compares equal, so tables stay comparable)
        "hysteretic_energy_J": float(e[-1, 6]) if inelastic or layout.hinges else None,
        "max_ductility": (float(np.nanmax(result.ductility))
                          if inelastic and np.isfinite(result.ductility).any() else None),
        "max_residual_drift_m": (float(np.max(np.abs(result.residual_drift))) if inelastic
                                 else None if layout.hinges else 0.0),
        "max_column_shear_ratio": (float(np.nanmax(shear_ratio))
                                   if shear_ratio is not None and np.isfinite(shear_ratio).any()
                                   else None),
        "links_dissipated_J": float(e[-1, 7]) if result.model.links else None,
        "peak_link_force_N": (float(result.link_peak_force.max()) if result.model.links
                              else None),
    }
    for names, values in zip(layout.floor_columns,
                             (result.peak_displacement, drift, accel)):
        for name, v in zip(names, values[layout.dofs].tolist()):
            row[name] = v
    return row
