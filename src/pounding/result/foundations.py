"""What a run reports of its buildings on flexible bases (soil–structure interaction,
:mod:`pounding.structure.foundation`): each footing's sway and rocking (in plan: along and
about both axes, and its torsion), the soil's base shear and moment (and torque) on it, and
the periods and impedances that made them; and the building's own deformation, from which
its storeys' drifts and forces follow."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from pounding.structure.matrices import MatrixBuilding

if TYPE_CHECKING:
    from pounding.structure.foundation import PlanFlexibleBaseBuilding

__all__ = ["flexible_base_drifts", "flexible_base_storeys", "footing_dofs", "foundation_summary",
           "plan_deformation"]


def _footing_kind(building: Any) -> str:
    """``"plan"`` for a building in plan on a flexible base, ``"row"`` for one in a row,
    ``""`` for any other. (A building on a flexible base is a matrix building: a row of
    shear buildings is answered without loading :mod:`pounding.structure.foundation`.)"""
    if not isinstance(building, MatrixBuilding):
        return ""
    from pounding.structure.foundation import (
        FlexibleBaseBuilding,
        PlanFlexibleBaseBuilding,
    )

    if isinstance(building, PlanFlexibleBaseBuilding):
        return "plan"
    return "row" if isinstance(building, FlexibleBaseBuilding) else ""


def _footing_local(building: Any) -> np.ndarray:
    """The footing's DOFs of one building on a flexible base (its DOFs after those of the
    building on it: a row building's sway and rocking, in plan its sways, rockings and
    torsion, those that are DOFs); empty for any other building."""
    if _footing_kind(building) == "plan":
        m = building.foundation.rigid.shape[0]  # (the floors' u_x, u_y, θ come first)
        return m + np.arange(sum(bool(e) for e in building.foundation.explicit))
    if _footing_kind(building) == "row":
        n0 = int(building.fixed_base.n)
        return np.arange(n0, int(building.n))
    return np.zeros(0, dtype=np.int64)


def footing_dofs(model: Any) -> np.ndarray:
    """The global DOFs of every footing of the model's buildings on a flexible base (its
    sway, rocking, torsion: DOFs of the model, but no floors), ascending; empty without
    one."""
    out = [int(off) + _footing_local(bl)
           for bl, off in zip(model.buildings, model.system.offsets)]
    return np.concatenate(out).astype(np.int64) if out else np.zeros(0, dtype=np.int64)


def plan_deformation(building: Any, displacement: np.ndarray) -> np.ndarray:
    """The floors' ``u_x, u_y, θ`` (nt, 3 n_floors) of a building in plan's own
    deformation from its DOF histories (nt, n): on a flexible base, less the footing's
    rigid motion (:meth:`pounding.structure.foundation.PlanFoundation.deformation`); on a
    fixed base, the floors' DOFs as they are."""
    if _footing_kind(building) == "plan":
        return building.foundation.deformation(displacement)
    return displacement[:, :3 * building.plan.n_floors]


def flexible_base_drifts(model: Any, displacement: np.ndarray
                         ) -> list[tuple[np.ndarray, np.ndarray]]:
    """For every building on a flexible base, its floors' columns (global DOFs) and the
    drifts of its own deformation there [m] (nt, n_floors)
    (:meth:`pounding.structure.foundation.Foundation.deformation_drifts`), from the
    displacement histories (nt, N); in plan, its ``u_x`` columns with the drifts along x
    and its ``u_y`` columns with those along y, at the centres of mass
    (:meth:`pounding.structure.foundation.PlanFoundation.deformation_drifts`)."""
    out = []
    for bl, off in zip(model.buildings, model.system.offsets):
        if _footing_kind(bl) == "plan":
            ix = int(off) + 3 * np.arange(bl.plan.n_floors)
            dx, dy = bl.foundation.deformation_drifts(
                displacement[:, int(off): int(off) + bl.n])
            out.append((np.r_[ix, ix + 1], np.hstack([dx, dy])))
        elif _footing_kind(bl) == "row":
            f = bl.floor_dofs
            d = bl.foundation.deformation_drifts(displacement[:, int(off): int(off) + bl.n],
                                                 bl.elevations[f])
            out.append((int(off) + f, d))
    return out


def flexible_base_storeys(building: Any) -> np.ndarray:
    """Storey stiffness [N/m] under every DOF of a building on a flexible base that was a
    shear building (its storey shears ``k_j`` times its deformation drifts), NaN elsewhere
    (the footing's DOFs; any other matrix building)."""
    n = int(building.n)
    out = np.full(n, np.nan)
    if _footing_kind(building) == "row":
        k = building.foundation.storey_stiffnesses
        if k is not None:
            out[building.floor_dofs] = k
    return out


def _peak(values: np.ndarray, dt: float) -> tuple[float, float]:
    k = int(np.argmax(np.abs(values)))
    return float(abs(values[k])), round(k * dt, 9)


def _soil_row(soil: Any) -> dict[str, Any]:
    """The soil of a foundation as the summary reports it."""
    return {"vs_small_strain_m_s": soil.shear_wave_velocity,
            "density_kg_m3": soil.density, "poisson": soil.poisson,
            "shaking_alpha_S": soil.shaking, "G_over_G0": soil.modulus_ratio,
            "shear_modulus_Pa": soil.shear_modulus,
            "material_damping_ratio": soil.damping_ratio}


_PLAN_KEYS = (("sway_x", "m", "base_shear_x", "N", "N_m", "N_s_m"),
              ("sway_y", "m", "base_shear_y", "N", "N_m", "N_s_m"),
              ("rocking_about_x", "rad", "base_moment_about_x", "N_m", "N_m_rad", "N_m_s_rad"),
              ("rocking_about_y", "rad", "base_moment_about_y", "N_m", "N_m_rad", "N_m_s_rad"),
              ("torsion", "rad", "base_torque", "N_m", "N_m_rad", "N_m_s_rad"))
"""For each of the footing's DOFs in plan (:data:`pounding.structure.foundation.plan_base.
FOOTING_DOFS`): its motion's name and unit, the soil's reaction's name and unit, and the
units of its spring and dashpot, as the summary's keys spell them."""


def _plan_row(r: Any, b: int, bl: PlanFlexibleBaseBuilding, off: int) -> dict[str, Any]:
    """The ``foundations`` row of building ``b`` in plan on a flexible base: its footing
    (its size and embedment [m], mass [kg], rocking and torsion inertias [kg·m²], which
    motions are DOFs, ``sway_x_dof`` … ``torsion_dof``, as a row building's ``sway_dof``
    and ``rocking_dof``; and its centre [m]), soil and five springs and dashpots, the
    periods, and the peaks of the footing's sway along x and y [m], rocking about x and y
    and torsion [rad], and of the soil's reactions on it: base shears [N], base moments
    about x and y and base torque [N·m] (``k y_f + c ẏ_f``), read at the output steps;
    and the work its dashpots took [J] (``∫ Σ c ẏ_f² dt``, trapezoids on the output
    steps)."""
    f = bl.foundation
    sl = slice(off, off + bl.n)
    motion, reaction = f.base_reactions(r.displacement[:, sl], r.velocity[:, sl])
    imp, ft = f.impedance, f.footing
    row: dict[str, Any] = {
        "building": f"B{b + 1}", "name": bl.name,
        "footing": ({"radius_m": ft.radius} if ft.radius is not None else
                    {"length_m": ft.length, "width_m": ft.width})
        | {"embedment_m": ft.embedment, "mass_kg": ft.mass,
           "rocking_inertia_about_x_kg_m2": f.inertias[0],
           "rocking_inertia_about_y_kg_m2": f.inertias[1],
           "torsion_inertia_kg_m2": f.inertias[2]}
        | {f"{name}_dof": bool(e) for (name, *_), e in zip(_PLAN_KEYS, f.explicit)}
        | {"centre_m": [f.centre[0], f.centre[1]]},
        "soil": _soil_row(f.soil)}
    for (name, _, _, _, k_unit, c_unit), k, c in zip(_PLAN_KEYS, imp.springs, imp.dashpots):
        row[f"k_{name}_{k_unit}"] = k
        row[f"c_{name}_{c_unit}"] = c
    row.update({
        "dashpots_at_rad_s": imp.omega,
        "fixed_base_periods_s": [float(t) for t in f.fixed_base_periods],
        "flexible_base_periods_s": [float(t) for t in bl.modes().periods],
        "peaks": "read at the output steps",
        "storey_drifts": "the building's own deformation (the footing's sway, rocking and "
                         "torsion taken out), read at the output steps"})
    v = f.footing_motion(r.velocity[:, sl])
    power = (v ** 2) @ np.asarray(imp.dashpots)
    row["soil_dashpot_work_J"] = float(np.trapezoid(power, dx=r.dt))
    for d, (name, unit, force, f_unit, _, _) in enumerate(_PLAN_KEYS):
        for key, values, u in ((name, motion[:, d], unit), (force, reaction[:, d], f_unit)):
            peak, t = _peak(values, r.dt)
            row[f"peak_{key}_{u}"] = peak
            row[f"peak_{key}_time_s"] = t
    return row


def foundation_summary(r: Any) -> dict[str, Any]:
    """``foundations`` of a run ``r`` (a :class:`pounding.result.Response`): for every
    building on a flexible base, its footing (with its embedment [m]), soil and
    impedance (springs, dashpots and the frequency they were taken at), its fixed- and
    flexible-base periods, and the peaks of the footing's sway [m], rocking [rad] and the
    soil's base shear [N] and moment [N·m] on it (``V = k_x u_f + c_x u̇_f``,
    ``M = k_φ φ + c_φ φ̇``), read at the output steps, and the work its dashpots took
    from the building [J] (radiation and soil damping: ``∫ (c_x u̇_f² + c_φ φ̇²) dt`` by the
    trapezoidal rule on the output steps; part of the energy balance's damping term);
    empty without one. A building in plan reports its footing's five motions and the
    soil's five reactions (:func:`_plan_row`)."""
    out = []
    for b, (bl, off) in enumerate(zip(r.model.buildings, r.model.system.offsets)):
        if _footing_kind(bl) == "plan":
            out.append(_plan_row(r, b, bl, int(off)))
            continue
        if _footing_kind(bl) != "row":
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
            "soil": _soil_row(soil),
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
