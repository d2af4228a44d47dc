"""The headline numbers of a run (``summary.json`` and the printed summary), each key naming
its unit: impacts, peak contact forces, every floor's and storey's peaks with their times,
each building's periods, energies, and the solver's statistics."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from pounding.result.bridge_peaks import bridge_summary
from pounding.result.bridge_seats import seat_summary
from pounding.result.bridge_keys import key_summary
from pounding.result.columns import ENERGY_NAMES, rounded_length
from pounding.result.foundations import foundation_summary
from pounding.result.storey_peaks import bearing_peaks, plan_storeys
from pounding.result.variables import hinge_table

if TYPE_CHECKING:
    from pounding.result.response import Response

__all__ = ["bearing_summary", "building_summary", "hinge_summary", "inelastic_summary",
           "seats_summary", "summarize"]


def summarize(r: Response) -> dict[str, Any]:
    """Headline numbers (JSON-ready), each key naming its unit.

    Per-floor peaks are keyed by floor label (``B1F3``: building 1, floor 3 — of a matrix
    building, its DOF 3; of a building in plan, floor and direction, ``B1F3x``; the drift
    and shear of a floor are those of the storey below it) and located inside solver
    steps, each with its time (``…_time_s``); only floors are listed (a matrix building's
    other DOFs, rotations say, are in the NetCDF file). The storey shear of a matrix
    building is null: its ``K`` has no storey stiffness (a building in plan with lateral
    elements has its shears, from them). The drift, drift ratio and shear under a base
    slab are not listed: that is the isolation bearing, in ``bearings`` (its law,
    displacement and force); nor are a bridge deck's (its piers' drifts, shears, ductility
    and residual drift, and its bearings', are in ``bridge``, frame by frame). ``buildings`` repeats them building by building, storey by
    storey (floors by elevation), with the building's natural periods — the table an
    engineer reads first; a building in plan adds, storey by storey, the peaks along y,
    the rotation and the torque.
    """
    pcf = r.peak_contact_force
    labels = r.model.dof_labels()
    floor = r.model.is_floor
    # a base slab's "storey" is its bearing (bearing_summary); a bridge deck stands on piers
    # and bearings, whose drifts and forces are the bridge block's (bridge_summary)
    storey = floor & ~r.is_bearing & ~bridge_decks(r)
    contacts = r.model.contacts

    def by_floor(values: NDArray[np.float64]) -> dict[str, float]:
        return {lb: float(v) for lb, v, f in zip(labels, values, floor) if f}

    def by_storey(values: NDArray[np.float64]) -> dict[str, float]:
        return {lb: float(v) for lb, v, f in zip(labels, values, storey) if f}

    return {
        "model": r.model.name,
        "record": r.motion.name,
        "record_pga_g": r.motion.pga_g,
        "contact_law": r.model.contact.describe() if contacts else None,
        "duration_s": float(r.time[-1]),
        "output_step_s": r.dt,
        "n_impacts": r.n_impacts,
        "peak_contact_force_N": float(pcf.max()) if pcf.size else 0.0,
        "peak_contact_force_time_s": (float(r.peak_contact_force_time[int(np.argmax(pcf))])
                                      if pcf.size and pcf.max() > 0 else None),
        "peak_contact_force_by_contact_N": {c.label: float(f) for c, f in zip(contacts, pcf)},
        "peak_contact_force_time_by_contact_s": {
            c.label: float(t) for c, t in zip(contacts, r.peak_contact_force_time)},
        "impacts_by_contact": {c.label: int(k) for c, k in
                               zip(contacts, r.impacts_per_contact)},
        "peak_displacement_m": by_floor(r.peak_displacement),
        "peak_displacement_time_s": by_floor(r.peak_displacement_time),
        "peak_drift_m": by_storey(r.peak_drift),
        "peak_drift_time_s": by_storey(r.peak_drift_time),
        "peak_drift_ratio": by_storey(r.peak_drift_ratio),
        "peak_storey_shear_N": by_storey(r.peak_storey_shear),
        "peak_storey_shear_time_s": by_storey(r.peak_storey_shear_time),
        "peak_abs_acceleration_m_s2": by_floor(r.peak_abs_acceleration),
        "peak_abs_acceleration_time_s": by_floor(r.peak_abs_acceleration_time),
        "buildings": building_summary(r),
        "energy_final_J": {name: float(v) for name, v in zip(ENERGY_NAMES, r.energy[-1])},
        "contact_dissipated_J": float(r.contact_dissipated[-1]),
        "energy_balance_error": r.energy_balance_error,
        **rotation_summary(r),
        **bearing_summary(r),
        **inelastic_summary(r),
        **device_summary(r),
        **hinge_summary(r),
        **foundation_summary(r),
        **spatial_summary(r),
        **bridge_summary(r),
        **seats_summary(r),
        **key_summary(r),
        "solver": {"name": r.stats.solver, "rtol": r.stats.rtol, "rk_steps": r.stats.rk_steps,
                   "rejected": r.stats.rejected, "events": r.stats.events,
                   "impact_table_overflow": r.stats.impact_overflow,
                   "wall_time_s": r.stats.wall_time,
                   "peaks": ("located inside solver steps" if r.located_peaks is not None
                             else "read at the output steps")},
    }

def floor_rotations(r: Response) -> list[tuple[int, int, str, float, float]]:
    """The peak rotation of every floor of the buildings in plan: ``(building, floor,
    label, peak |θ| [rad], time [s])``, building and floor 0-based, ``label`` the floor's θ
    DOF as ``B2F3θ`` (building 2, floor 3); located inside solver steps as the other peaks
    (:attr:`pounding.result.Result.peak_displacement` of the θ DOFs)."""
    from pounding.structure.plan_row import PlanMatrixBuilding

    out = []
    peak, time = r.peak_displacement, r.peak_displacement_time
    for b, (bl, off) in enumerate(zip(r.model.buildings, r.model.system.offsets)):
        if not isinstance(bl, PlanMatrixBuilding):
            continue
        plan = bl.plan
        for k in range(plan.n_floors):
            j = plan.dof(k, "θ")
            out.append((b, k, f"B{b + 1}{bl.labels[j]}", float(peak[off + j]),
                        float(time[off + j])))
    return out


def seats_summary(r: Response) -> dict[str, Any]:
    """``seats``: each seat of a bridge with a width, its requirement, peak opening and
    margin (:func:`pounding.result.bridge_seats.seat_summary`), if the model gives seat
    widths."""
    seats = seat_summary(r)
    return {} if seats is None else {"seats": seats}


def rotation_summary(r: Response) -> dict[str, Any]:
    """``peak_floor_rotation_mrad`` and ``peak_floor_rotation_time_s`` by floor
    (:func:`floor_rotations`), if some building is in plan."""
    rows = floor_rotations(r)
    if not rows:
        return {}
    return {"peak_floor_rotation_mrad": {lb: 1e3 * v for _, _, lb, v, _ in rows},
            "peak_floor_rotation_time_s": {lb: t for _, _, lb, _, t in rows}}


def bridge_decks(r: Response) -> NDArray[np.bool_]:
    """True for every DOF of a bridge frame (:class:`~pounding.structure.bridge.frame.
    BridgeFrame`, along or across the axis): its deck has no storey; its piers' and
    bearings' peaks are the ``bridge`` block's."""
    import sys

    # (a model with a bridge frame has imported its module: a run of buildings need not)
    frames = sys.modules.get("pounding.structure.bridge.frame")
    return np.concatenate([np.full(bl.n, frames is not None
                                   and isinstance(bl, frames.BridgeFrame))
                           for bl in r.model.buildings])


def building_summary(r: Response) -> list[dict[str, Any]]:
    """Per building: its natural periods and, storey by storey (floors by elevation; a
    matrix building's DOF label as ``label``), the peaks and times. A base-isolated
    building lists its superstructure's storeys (storey 1 above the base slab; the bearing
    under the slab is in ``bearings``: :func:`bearing_summary`); a building in plan adds
    along y (centres of mass), the floor's rotation and the storey torque, its storey
    shears from its lateral elements."""
    from pounding.structure import MatrixBuilding
    from pounding.structure.assembly import floor_dofs

    out = []
    quantities = (("peak_displacement_m", r.peak_displacement),
                  ("peak_displacement_time_s", r.peak_displacement_time),
                  ("peak_drift_m", r.peak_drift),
                  ("peak_drift_time_s", r.peak_drift_time),
                  ("peak_drift_ratio", r.peak_drift_ratio),
                  ("peak_storey_shear_N", r.peak_storey_shear),
                  ("peak_storey_shear_time_s", r.peak_storey_shear_time),
                  ("peak_abs_acceleration_m_s2", r.peak_abs_acceleration),
                  ("peak_abs_acceleration_time_s", r.peak_abs_acceleration_time))
    storey_keys = ("peak_drift_m", "peak_drift_time_s", "peak_drift_ratio",
                   "peak_storey_shear_N", "peak_storey_shear_time_s")
    decks = bridge_decks(r)
    plans = {ps.building: ps for ps in plan_storeys(r)}
    bearings = bearing_peaks(r)
    bearing = r.is_bearing
    for b, (bl, off) in enumerate(zip(r.model.buildings, r.model.system.offsets)):
        storeys = []
        matrices = isinstance(bl, MatrixBuilding)  # (a building in plan too)
        labels = bl.labels if isinstance(bl, MatrixBuilding) else ()
        ps = plans.get(b)
        for k, j in enumerate(j for j in floor_dofs(bl) if not bearing[off + j]):
            row: dict[str, Any] = {"storey": k + 1}
            if ps is not None:
                row.update(floor=f"F{j // 3 + 1}", label=labels[j])
            elif matrices:
                row.update(floor=f"F{j + 1}", label=labels[j])
            elif bearing[off]:
                row["floor"] = f"F{j + 1}"  # floor 1 is the base slab
            row.update({"floor_elevation_m": rounded_length(bl.floor_levels[j]),
                        "height_m": rounded_length(bl.heights[j])})
            row.update({key: float(v[off + j]) for key, v in quantities
                        if not (decks[off + j] and key in storey_keys)})
            if ps is not None:
                f = j // 3
                row.update({
                    "peak_displacement_y_m": float(ps.displacement_y[f]),
                    "peak_displacement_y_time_s": float(ps.displacement_y_time[f]),
                    "peak_drift_y_m": float(ps.drift_y[f]),
                    "peak_drift_y_time_s": float(ps.drift_y_time[f]),
                    "peak_drift_ratio_y": float(ps.drift_ratio_y[f]),
                    "peak_storey_shear_y_N": float(ps.shear_y[f]),
                    "peak_storey_shear_y_time_s": float(ps.shear_y_time[f]),
                    "peak_storey_torque_N_m": float(ps.torque[f]),
                    "peak_storey_torque_time_s": float(ps.torque_time[f]),
                    "peak_abs_acceleration_y_m_s2": float(ps.acceleration_y[f]),
                    "peak_abs_acceleration_y_time_s": float(ps.acceleration_y_time[f]),
                    "peak_rotation_mrad": 1e3 * float(ps.rotation[f]),
                    "peak_rotation_time_s": float(ps.rotation_time[f])})
            storeys.append(row)
        given = ({"given_as": "plan", "n_dof": bl.n,
                  "directions": "x, y: along the site axes at each floor's centre of mass; "
                                "θ: the floor's rotation; torque about the centre of mass "
                                "of the floor above"} if ps is not None
                 else {"given_as": "matrices", "n_dof": bl.n} if matrices else {})
        if bearing[off]:
            given = {"isolated_on": next(x.law for x in bearings if x.building == b),
                     "base_slab_elevation_m": rounded_length(bl.floor_levels[0])}
        out.append({"building": f"B{b + 1}", "name": bl.name, "n_storeys": len(storeys),
                    **given,
                    "periods_s": [float(t) for t in bl.modes().periods],
                    "storeys": storeys})
    return out


def spatial_summary(r: Response) -> dict[str, Any]:
    """``spatial``: under a spatially varying motion
    (:class:`~pounding.ground_motion.spatial.SpatialMotion`), how the buildings' motions were
    made, and each building's record with its delay [s] and its PGA [g] (and each end wall's
    on a ground of its own, ``walls``); empty otherwise."""
    from pounding.ground_motion.spatial import SpatialMotion

    m = r.motion
    if not isinstance(m, SpatialMotion):
        return {}
    out: dict[str, Any] = {
        "how": m.description or "one record per building",
        "buildings": [{"building": f"B{b + 1}", "record": rec.name, "delay_s": d,
                       "pga_g": rec.pga_g}
                      for b, (rec, d) in enumerate(zip(m.records, m.delays))]}
    if m.walls:
        out["walls"] = [{"side": side, "record": rec.name, "delay_s": m.wall_delays[side],
                         "pga_g": rec.pga_g} for side, rec in m.walls.items()]
    return {"spatial": out}


def bearing_summary(r: Response) -> dict[str, Any]:
    """``bearings``: the isolation bearing of every base-isolated building — its law in
    words, the base slab it carries, its peak displacement [m] (located inside solver
    steps) and force [N] with their times, and its residual displacement [m]; reported
    here, apart from the storeys above it."""
    bearings = bearing_peaks(r)
    if not bearings:
        return {}
    labels = r.model.dof_labels()
    return {"bearings": [{"building": f"B{x.building + 1}", "base_slab": labels[x.dof],
                          "law": x.law, "kind": x.kind,
                          "base_slab_elevation_m": rounded_length(x.elevation),
                          "peak_displacement_m": x.peak_displacement,
                          "peak_displacement_time_s": x.peak_displacement_time,
                          "peak_force_N": x.peak_force,
                          "peak_force_time_s": x.peak_force_time,
                          "residual_displacement_m": x.residual_displacement}
                         for x in bearings]}

def inelastic_summary(r: Response) -> dict[str, Any]:
    out: dict[str, Any] = {}
    labels = r.model.dof_labels()
    deck = bridge_decks(r)  # (its piers' ductility and residual drift: the bridge block)
    if r.model.is_inelastic:
        out["hysteretic_energy_J"] = float(r.energy[-1, 6])
        if not deck.all():
            out["ductility_demand"] = {lb: float(v) for lb, v, d in
                                       zip(labels, r.ductility, deck) if np.isfinite(v) and not d}
    if (r.model.is_inelastic or r.model.yielding_frames) and not deck.all():
        out["residual_drift_m"] = {lb: float(v) for lb, v, bearing, floor, d in
                                   zip(labels, r.residual_drift, r.is_bearing,
                                       r.model.is_floor, deck) if floor and not bearing
                                   and not d}
    struck = [c for c in r.model.contacts if c.struck is not None]
    if struck:
        pcs = r.peak_column_shear
        out["peak_column_shear_N"] = {c.label: float(pcs[c.index]) for c in struck}
        ratio = r.column_shear_ratio
        out["column_shear_over_storey_shear"] = {c.label: float(ratio[c.index])
                                                 for c in struck}
    return out


def device_summary(r: Response) -> dict[str, Any]:
    """The devices: each link's law, peak force and energy dissipated; each bumper."""
    out: dict[str, Any] = {}
    links = r.model.links
    if links:
        peak = r.link_peak_force
        diss = r.link_dissipated
        out["links"] = [{"name": lk.name, "floors": list(lk.floors), "law": lk.readable(),
                         "peak_force_N": float(f), "dissipated_J": float(e)}
                        for lk, f, e in zip(links, peak, diss)]
        out["links_dissipated_J"] = float(r.energy[-1, 7])
    from pounding.devices import Bumper

    bumpers = [d for d in r.model.devices if isinstance(d, Bumper)]
    if bumpers:
        out["bumpers"] = [{"contact": b.label, "pad": b.readable()} for b in bumpers]
    return out



def hinge_summary(r: Response) -> dict[str, Any]:
    """The plastic hinges of the yielding frames (none: nothing): each hinge's place, law,
    peak rotation [rad] (at its events and the output steps) with its time, its ductility
    (peak rotation over the law's yield rotation), residual rotation (unloaded to zero
    moment at the end) [rad], peak moment [N·m], hysteretic energy [J] and whether it
    reached its capping point or fractured (``capped``); their total
    hysteretic energy [J]; and the damping the frames were given."""
    rows = hinge_table(r)
    if not rows:
        return {}
    return {
        "hinges": [{"hinge": h.label, "building": f"B{h.building + 1}", "member": h.member,
                    "element": h.element + 1, "end": h.end + 1, "x_m": h.x, "y_m": h.y,
                    "law": h.law, "peak_rotation_rad": h.peak_rotation,
                    "peak_rotation_time_s": h.peak_rotation_time,
                    "rotation_ductility": h.peak_rotation / h.yield_rotation,
                    "residual_rotation_rad": h.residual_rotation,
                    "peak_moment_N_m": h.peak_moment, "hysteretic_energy_J": h.dissipated,
                    "capped": h.capped}
                   for h in rows],
        "hinge_hysteretic_energy_J": float(sum(h.dissipated for h in rows)),
        "peak_hinge_rotation_rad": float(max(h.peak_rotation for h in rows)),
        "frame_damping": {f"B{b + 1}": f"{_readable(bl.damping)} built on the frame's "
                          "elastic condensed stiffness (hinges at their elastic stiffness, "
                          "not their tangent: Zareian & Medina 2010), held constant"
                          for b, bl in r.model.yielding_frames},
    }


def _readable(damping: Any) -> str:
    return damping.readable() if hasattr(damping, "readable") else str(damping)
