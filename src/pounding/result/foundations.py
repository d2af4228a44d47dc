"""What a run reports of its buildings on flexible bases (soil–structure interaction,
:mod:`pounding.structure.foundation`): each footing's sway and rocking, the soil's base shear
and moment on it, and the periods and impedances that made them."""

from __future__ import annotations

from typing import Any

import numpy as np

from pounding.structure.foundation import FlexibleBaseBuilding

__all__ = ["flexible_base_drifts", "flexible_base_storeys", "foundation_summary"]


def flexible_base_drifts(model: Any, displacement: np.ndarray
                         ) -> list[tuple[np.ndarray, np.ndarray]]:
    """For every building on a flexible base, its floors' columns (global DOFs) and the
    drifts of its own deformation there [m] (nt, n_floors)
    (:meth:`pounding.structure.foundation.Foundation.deformation_drifts`), from the
    displacement histories (nt, N)."""
    out = []
    for bl, off in zip(model.buildings, model.system.offsets):
        if isinstance(bl, FlexibleBaseBuilding):
            f = bl.floor_dofs
            d = bl.foundation.deformation_drifts(displacement[:, int(off): int(off) + bl.n],
                                                 bl.elevations[f])
            out.append((int(off) + f, d))
    return out


def flexible_base_storeys(building: object) -> np.ndarray:
    """Storey stiffness [N/m] under every DOF of a building on a flexible base that was a
    shear building (its storey shears ``k_j`` times its deformation drifts), NaN elsewhere
    (the footing's DOFs; any other matrix building)."""
    n = int(getattr(building, "n"))
    out = np.full(n, np.nan)
    if isinstance(building, FlexibleBaseBuilding):
        k = building.foundation.storey_stiffnesses
        if k is not None:
            out[building.floor_dofs] = k
    return out


def _peak(values: np.ndarray, dt: float) -> tuple[float, float]:
    k = int(np.argmax(np.abs(values)))
    return float(abs(values[k])), round(k * dt, 9)


def foundation_summary(r: Any) -> dict[str, Any]:
    """``foundations`` of a run ``r`` (a :class:`pounding.result.Response`): for every
    building on a flexible base, its footing (with its embedment [m]), soil and
    impedance (springs, dashpots and the frequency they were taken at), its fixed- and
    flexible-base periods, and the peaks of the footing's sway [m], rocking [rad] and the
    soil's base shear [N] and moment [N·m] on it (``V = k_x u_f + c_x u̇_f``,
    ``M = k_φ φ + c_φ φ̇``), read at the output steps, and the work its dashpots took
    from the building [J] (radiation and soil damping: ``∫ (c_x u̇_f² + c_φ φ̇²) dt`` by the
    trapezoidal rule on the output steps; part of the energy balance's damping term);
    empty without one."""
    out = []
    for b, (bl, off) in enumerate(zip(r.model.buildings, r.model.system.offsets)):
        if not isinstance(bl, FlexibleBaseBuilding):
            continue
        f = bl.foundation
        sl = slice(int(off), int(off) + bl.n)
        sway, rocking, shear, moment = f.base_reactions(r.displacement[:, sl],
                                                        r.velocity[:, sl])
        imp, soil, ft = f.impedance, f.soil, f.footing
        row: dict[str, Any] = {
            "building": f"B{b + 1}", "name": bl.name,
            "footing": ({"radius_m": ft.radius} if ft.radius is not None else
                        {"length_m": ft.length, "width_m": ft.width})
            | {"embedment_m": ft.embedment, "mass_kg": ft.mass,
               "rocking_inertia_kg_m2": ft.inertia,
               "sway_dof": f.explicit[0], "rocking_dof": f.explicit[1]},
            "soil": {"vs_small_strain_m_s": soil.shear_wave_velocity,
                     "density_kg_m3": soil.density, "poisson": soil.poisson,
                     "shaking_alpha_S": soil.shaking, "G_over_G0": soil.modulus_ratio,
                     "shear_modulus_Pa": soil.shear_modulus,
                     "material_damping_ratio": soil.damping_ratio},
            "k_sway_N_m": imp.k_x, "k_rocking_N_m_rad": imp.k_r,
            "c_sway_N_s_m": imp.c_x, "c_rocking_N_m_s_rad": imp.c_r,
            "dashpots_at_rad_s": imp.omega,
            "fixed_base_periods_s": [float(t) for t in f.fixed_base_periods],
            "flexible_base_periods_s": [float(t) for t in bl.modes().periods],
            "peaks": "read at the output steps",
            "storey_drifts": "the building's own deformation (the footing's sway and rocking "
                             "taken out), read at the output steps"}
        v = r.velocity[:, sl] @ f.recovery.T
        power = imp.c_x * v[:, 0] ** 2 + imp.c_r * v[:, 1] ** 2
        row["soil_dashpot_work_J"] = float(np.trapezoid(power, dx=r.dt))
        for key, values, unit in (("sway", sway, "m"), ("rocking", rocking, "rad"),
                                  ("base_shear", shear, "N"), ("base_moment", moment, "N_m")):
            peak, t = _peak(values, r.dt)
            row[f"peak_{key}_{unit}"] = peak
            row[f"peak_{key}_time_s"] = t
        out.append(row)
    return {"foundations": out} if out else {}
