"""The tables `pounding run` prints after a run: the run, its buildings, their storeys (and
the isolation bearings apart), the contacts and the links; of a bridge, its frames, piers,
bearings, joints and abutments, and restrainers instead (:mod:`pounding.cli.bridge_tables`).

One unit per quantity on the screen: displacements, drifts and gaps in mm, forces in kN (MN
when they reach 100 MN), energies in kJ (MJ), elevations in m. Names are printed as typed
(:func:`pounding.cli.tables.literal`), and the tables fit the terminal without cutting a
number (:func:`pounding.cli.tables.print_table`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from rich.text import Text

from pounding.cli.app import console
from pounding.cli.bridge_tables import bridge_forces, print_bridge_tables
from pounding.cli.tables import (
    Col,
    building_label,
    energy_scale,
    force_scale,
    number,
    print_table,
)
from pounding.result.columns import IMPACT_COLUMNS

__all__ = ["STOREY_ROWS", "print_run_summary"]

STOREY_ROWS = 30
"""Buildings with more storeys list only the ten of largest drift ratio."""


def _t(value: float) -> str:
    """A time [s]: three decimals; ``–`` for NaN."""
    return "–" if not np.isfinite(value) else f"{value:.3f}"


def _mm(value: float) -> str:
    return number(1e3 * value)


def print_run_summary(out: Any) -> None:
    """Print the tables of a finished run (``out``: :class:`pounding.RunOutput`)."""
    r = out.result
    model = r.model
    s = r.summary()
    bridge = r.bridge  # (None unless every building is a bridge frame)
    forces = [s["peak_contact_force_N"], *np.nan_to_num(r.peak_storey_shear, nan=0.0),
              *(x.peak_force for x in r.bearings),
              *(r.link_peak_force if model.links else []),
              *(bridge_forces(bridge) if bridge is not None else [])]
    ff, fu = force_scale(max(forces, default=0.0))
    fin = s["energy_final_J"]
    ef, eu = energy_scale(max(abs(fin["input"]), s["contact_dissipated_J"]))
    units = (ff, fu, ef, eu)

    rows: list[tuple[str | Text, Any]] = [
        ("record", Text(f"{r.motion.name}, PGA {r.motion.pga_g:.3f} g")),
        ("simulated / output step [s]", f"{s['duration_s']:g} / {r.dt:g}"),
        (("frames / joints / abutments / restrainers",
          f"{len(bridge.frames)} / {len(bridge.frames) - 1} / "
          f"{sum(x.kind == 'abutment' for x in bridge.seats)} / {len(bridge.restrainers)}")
         if bridge is not None else
         ("buildings / contacts", f"{len(model.buildings)} / {len(model.contacts)}"))]
    if model.contacts:
        rows.append(("contact law", model.contact.describe()))
    rows.append(("impacts", str(r.n_impacts)))
    t_peak = s["peak_contact_force_time_s"]
    rows.append((f"peak contact force [{fu}]", number(s["peak_contact_force_N"] * ff)
                 + (f" at {t_peak:.3f} s" if t_peak is not None else "")))
    rows.append((f"energy input [{eu}]", number(fin["input"] * ef)))
    rows.append((f"dissipated in contacts [{eu}]", number(s["contact_dissipated_J"] * ef)))
    if model.is_inelastic:
        what = ("bearings" if r.is_bearing.any() and len(model.yielding_storeys)
                == int(r.is_bearing.sum()) else "yielding storeys"
                + (" and bearings" if r.is_bearing.any() else ""))
        if not model.yielding_storeys:  # (a bridge's frames: their piers and bearings)
            what = "piers and bearings"
        rows.append((f"hysteretic, {what} [{eu}]", number(fin["hysteretic"] * ef)))
    if "hinge_hysteretic_energy_J" in s:
        rows.append((f"hysteretic, frames' plastic hinges [{eu}]",
                     number(s["hinge_hysteretic_energy_J"] * ef)))
    if model.links:
        rows.append((f"dissipated by links [{eu}]", number(s["links_dissipated_J"] * ef)))
    rows.append(("energy-balance error", f"{r.energy_balance_error:.2e} of peak input"))
    if r.stats.impact_overflow:
        rows.append((Text("impact table", style="red"),
                     Text("overflowed: some impacts not listed", style="red")))
    rows.append(("wall time [s]", f"{r.wall_time:.2f} integrating, {out.wall_time:.2f} total"))
    print_table(console, f"{model.name}: pounding run",
                [Col("quantity", "left", wrap=True), Col("value", "left", wrap=True)], rows,
                show_header=False)

    if bridge is not None:  # its frames, piers, bearings, joints and restrainers
        print_bridge_tables(r, units)
    else:
        _print_buildings(r, units)
        _print_bearings(r, units)
        _print_storeys(r, units)
        _print_plan_storeys(r, units)
        _print_hinges(s, units)
        _print_contacts(r, units)
        _print_links(r, units)
    _print_seats(s)
    console.print(Text.assemble("outputs in ", (str(out.out_dir), "bold"), ": ",
                                ", ".join(sorted(p.name for p in out.files.values()))))


def _storey_floors(r: Any, b: int) -> np.ndarray:
    """The building's floor DOFs (its own numbering) whose storey is a storey (a base
    slab's is its bearing), by elevation."""
    from pounding.structure.assembly import floor_dofs

    off = int(r.model.system.offsets[b])
    floors = floor_dofs(r.model.buildings[b])
    return np.array([j for j in floors if not r.is_bearing[off + j]], dtype=np.int64)


def _print_buildings(r: Any, units: tuple[float, str, float, str]) -> None:
    ff, fu, _, _ = units
    model = r.model
    plans = {ps.building: ps for ps in r.plan_storeys}
    cols = [Col("building", "left", wrap=True), Col("storeys"),
            Col("T1, T2, T3 [s]", wrap=True), Col("peak roof displacement [mm]"),
            Col("at t [s]"), Col("peak drift ratio [%]"), Col("at storey"),
            Col(f"peak storey shear [{fu}]"), Col("at storey")]
    inelastic = model.is_inelastic and any(
        not r.is_bearing[off + j] for off, bl in zip(model.system.offsets, model.buildings)
        for j in getattr(bl, "yielding", ()))
    if inelastic:
        cols += [Col("storey law", "left", wrap=True), Col("peak ductility"),
                 Col("at storey"), Col("largest residual drift [mm]"), Col("at storey")]
    rows = []
    for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets)):
        off = int(off)
        floors = _storey_floors(r, b)
        periods = ", ".join(f"{t:.3f}" for t in bl.modes().periods[:3])
        roof = off + int(floors[-1])
        ps = plans.get(b)
        if ps is not None:  # the larger of x and y, with its direction
            ratios = np.column_stack([ps.drift_ratio_x, ps.drift_ratio_y])
            k, d = np.unravel_index(int(np.nanargmax(ratios)), ratios.shape)
            drift = [number(100 * ratios[k, d], 3), f"{k + 1} {'xy'[d]}"]
            shears = np.column_stack([ps.shear_x, ps.shear_y])
            if ps.has_elements:
                k, d = np.unravel_index(int(np.nanargmax(shears)), shears.shape)
                shear = [number(shears[k, d] * ff), f"{k + 1} {'xy'[d]}"]
            else:
                shear = ["–", "(given by K)"]
            storeys = str(ps.elevation.size)
            way = int(ps.displacement_y[-1] > ps.displacement_x[-1])  # 0: x, 1: y
            roof_disp = f"{_mm((ps.displacement_x, ps.displacement_y)[way][-1])} {'xy'[way]}"
            roof_t = _t((ps.displacement_x_time, ps.displacement_y_time)[way][-1])
        else:
            ratio = r.peak_drift_ratio[off + floors]
            j = int(np.nanargmax(ratio))
            drift = [number(100 * ratio[j], 3), str(j + 1)]
            v = r.peak_storey_shear[off + floors]
            if np.isfinite(v).all():
                jv = int(np.argmax(v))
                shear = [number(v[jv] * ff), str(jv + 1)]
            else:
                shear = ["–", "(matrices)"]
            storeys = str(floors.size)
            roof_disp, roof_t = _mm(r.peak_displacement[roof]), _t(r.peak_displacement_time[roof])
        row = [building_label(b, bl.name), storeys, periods, roof_disp, roof_t, *drift, *shear]
        if inelastic:
            law = bl.storey_law
            yielding = [j for j in getattr(bl, "yielding", ()) if not r.is_bearing[off + j]]
            if law is None or not yielding:
                row += ["linear", "–", "", "–", ""]
            else:
                mu = r.ductility[off: off + bl.n]
                res = np.where(r.is_bearing[off: off + bl.n], 0.0,
                               r.residual_drift[off: off + bl.n])
                jr = int(np.argmax(np.abs(res)))
                jm = int(np.nanargmax(mu))
                row += [law.label, number(mu[jm], 3), str(list(floors).index(jm) + 1),
                        f"{1e3 * res[jr]:+.2f}", str(list(floors).index(jr) + 1)]
        rows.append(row)
    notes = (["in plan: the larger of x and y, at the centres of mass"] if plans else []) + \
        (["a frame's storey shears (as in plan) at the output steps"]
         if model.yielding_frames or any(getattr(bl, "frame", None) is not None
                                         for bl in model.buildings) else [])
    print_table(console, "Buildings (peaks located inside solver steps)", cols, rows,
                caption="; ".join(notes))


def _print_bearings(r: Any, units: tuple[float, str, float, str]) -> None:
    if not r.bearings:
        return
    ff, fu, _, _ = units
    cols = [Col("building", "left", wrap=True), Col("bearing", "left", wrap=True),
            Col("base slab at [m]"), Col("peak displacement [mm]"), Col("t [s]"),
            Col(f"peak force [{fu}]"), Col("t [s]"), Col("residual displacement [mm]")]
    rows = [[building_label(x.building, r.model.buildings[x.building].name), x.law,
             f"{x.elevation:g}", _mm(x.peak_displacement), _t(x.peak_displacement_time),
             number(x.peak_force * ff), _t(x.peak_force_time),
             f"{1e3 * x.residual_displacement:+.2f}"] for x in r.bearings]
    print_table(console, "Isolation bearings (under each base slab; not storeys)", cols, rows)


def _print_storeys(r: Any, units: tuple[float, str, float, str]) -> None:
    """Every storey's peaks with their times (the envelope figure, as numbers); a building
    of more than :data:`STOREY_ROWS` storeys shows the ten with the largest drift ratio."""
    from pounding.result import floor_name

    ff, fu, _, _ = units
    model = r.model
    plans = {ps.building for ps in r.plan_storeys}
    if len(plans) == len(model.buildings):
        return
    # the floor's name where storey k is not floor k (a base slab below, a matrix building)
    named = any(r.is_bearing[int(off)] or hasattr(bl, "labels")
                for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets))
                if b not in plans)
    cols = [Col("building", "left", wrap=True), Col("storey"),
            *([Col("floor", "left")] if named else []),
            Col("floor at [m]"), Col("displacement [mm]"), Col("t [s]"),
            Col("drift ratio [%]"), Col("t [s]"), Col(f"storey shear [{fu}]"), Col("t [s]"),
            Col("abs. acceleration [m/s²]"), Col("t [s]")]
    ratio = r.peak_drift_ratio
    shear, shear_t = r.peak_storey_shear, r.peak_storey_shear_time
    rows = []
    for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets)):
        if b in plans:
            continue
        off = int(off)
        floors = _storey_floors(r, b)
        ks: Sequence[int] = range(floors.size)
        if floors.size > STOREY_ROWS:
            ks = sorted(np.argsort(-ratio[off + floors])[:10])
        label = building_label(b, bl.name)
        for k in ks:
            j = int(floors[k])
            i = off + j
            has_shear = bool(np.isfinite(shear[i]))
            rows.append([label, str(int(k) + 1), *([floor_name(bl, j)] if named else []),
                         f"{bl.floor_levels[j]:g}",
                         _mm(r.peak_displacement[i]), _t(r.peak_displacement_time[i]),
                         number(100 * ratio[i], 3), _t(r.peak_drift_time[i]),
                         number(shear[i] * ff) if has_shear else "–",
                         _t(shear_t[i]) if has_shear else "–",
                         number(r.peak_abs_acceleration[i]),
                         _t(r.peak_abs_acceleration_time[i])])
        if floors.size > STOREY_ROWS:
            rows.append([label, "…", *[""] * (len(cols) - 2)])
    matrices = [building_label(b, bl.name)
                for b, (bl, off) in enumerate(zip(model.buildings, model.system.offsets))
                if hasattr(bl, "labels") and b not in plans
                and not np.isfinite(shear[int(off): int(off) + bl.n]).any()]
    soil = [building_label(b, bl.name) for b, bl in enumerate(model.buildings)
            if hasattr(bl, "foundation")]
    notes = ([f"{', '.join(matrices)} given as matrices: no storey shear (K has no storey "
              "stiffness); floor: the DOF's label"] if matrices else [])
    if soil:
        notes.append(f"{', '.join(soil)} on a flexible base: drift of the building's own "
                     "deformation (the footing's sway and rocking taken out), read at the output "
                     "steps; the footing: foundations in summary.json")
    print_table(console, "Storeys: peaks and when (all of them in summary.json)", cols, rows,
                keys=2, caption="; ".join(notes))


def _print_plan_storeys(r: Any, units: tuple[float, str, float, str]) -> None:
    """The storeys of the buildings in plan: along x and y at each floor's centre of mass,
    the floor's rotation, the storey shears and torque from the lateral elements."""
    if not r.plan_storeys:
        return
    ff, fu, _, _ = units
    cols = [Col("building", "left", wrap=True), Col("storey"), Col("floor at [m]"),
            Col("displacement x [mm]"), Col("displacement y [mm]"), Col("rotation [mrad]"),
            Col("drift ratio x [%]"), Col("drift ratio y [%]"), Col(f"shear x [{fu}]"),
            Col(f"shear y [{fu}]"), Col(f"torque [{fu}·m]"),
            Col("abs. acceleration x [m/s²]"), Col("abs. acceleration y [m/s²]")]
    rows = []
    given = []
    for ps in r.plan_storeys:
        bl = r.model.buildings[ps.building]
        label = building_label(ps.building, bl.name)
        if not ps.has_elements:
            given.append(label)
        for k in range(ps.elevation.size):
            rows.append([label, str(k + 1), f"{ps.elevation[k]:g}",
                         _mm(ps.displacement_x[k]), _mm(ps.displacement_y[k]),
                         number(1e3 * ps.rotation[k]), number(100 * ps.drift_ratio_x[k], 3),
                         number(100 * ps.drift_ratio_y[k], 3), number(ps.shear_x[k] * ff),
                         number(ps.shear_y[k] * ff), number(ps.torque[k] * ff),
                         number(ps.acceleration_x[k]), number(ps.acceleration_y[k])])
    print_table(console, "Storeys in plan: peaks at each floor's centre of mass (times in "
                "summary.json)", cols, rows, keys=2,
                caption="shears and torque from the lateral elements; torque about the "
                        "centre of mass of the floor above"
                        + (f"; {', '.join(given)} given by its stiffness matrix: no storey "
                           "forces" if given else ""))


MAX_HINGE_ROWS = 12
"""Hinges listed in the run's printout (all of them are in ``summary.json``)."""


def _print_hinges(s: dict[str, Any], units: tuple[float, str, float, str]) -> None:
    """The frames' hinges that yielded, the largest rotations first (``summary.json`` has
    every hinge)."""
    hinges = s.get("hinges") or []
    if not hinges:
        return
    ff, fu, ef, eu = units
    # yielded: turned past the law's yield rotation (a rounding-level hysteretic energy is
    # not yielding)
    moved = sorted((h for h in hinges if h["rotation_ductility"] > 1.0 + 1e-9),
                   key=lambda h: -h["peak_rotation_rad"])
    cols = [Col("hinge", "left"), Col("member", "left"), Col("x, y [m]"),
            Col("peak rotation [mrad]"), Col("at t [s]"), Col("residual [mrad]"),
            Col(f"peak moment [{fu}·m]"), Col(f"hysteretic [{eu}]")]
    rows = [(h["hinge"], h["member"], f"{h['x_m']:g}, {h['y_m']:g}",
             number(1e3 * h["peak_rotation_rad"]), _t(h["peak_rotation_time_s"]),
             number(1e3 * h["residual_rotation_rad"]), number(h["peak_moment_N_m"] * ff),
             number(h["hysteretic_energy_J"] * ef)) for h in moved[:MAX_HINGE_ROWS]]
    caption = (f"{len(moved)} of {len(hinges)} hinges yielded"
               + (f"; the {MAX_HINGE_ROWS} largest rotations shown" if len(moved) >
                  MAX_HINGE_ROWS else "") + "; every hinge in summary.json")
    if rows:
        print_table(console, "Plastic hinges that yielded (largest rotations first)", cols,
                    rows, caption=caption)
    else:
        console.print(f"Plastic hinges: none of the {len(hinges)} yielded", highlight=False)


def _print_contacts(r: Any, units: tuple[float, str, float, str]) -> None:
    model = r.model
    if not model.contacts:
        return
    ff, fu, ef, eu = units
    # (a column shear only where one is reported: not a frame's, whose columns share it)
    columns = any(c.struck is not None for c in model.contacts) and bool(
        np.isfinite(r.peak_column_shear).any())
    cols = [Col("contact", "left", wrap=True), Col("elevation [m]"), Col("gap [mm]"),
            Col("impacts"), Col(f"peak force [{fu}]"), Col("at t [s]"),
            Col(f"dissipated [{eu}]")]
    if columns:
        cols += [Col(f"peak column shear [{fu}]"), Col("÷ storey shear")]
    counts = r.impacts_per_contact
    dissipated = r.dissipated_per_contact
    pcf = r.peak_contact_force
    pcs = r.peak_column_shear if columns else None
    rows = []
    for c in model.contacts:
        hit = counts[c.index] > 0
        cells = [c.label, f"{c.elevation:g}", number(1e3 * c.gap), str(counts[c.index]),
                 number(pcf[c.index] * ff) if hit else "–",
                 _t(r.peak_contact_force_time[c.index]) if hit else "–",
                 number(dissipated[c.index] * ef) if hit else "–"]
        if pcs is not None:
            hit = hit and c.struck is not None and bool(np.isfinite(pcs[c.index]))
            cells += [number(pcs[c.index] * ff) if hit else "–",
                      f"{r.column_shear_ratio[c.index]:.2f}" if hit else "–"]
        rows.append(cells)
    rows_ = r.impact_array
    col = IMPACT_COLUMNS.index("energy_dissipated")
    still_open = int(np.count_nonzero(~np.isfinite(rows_[:, col]))) if rows_.size else 0
    print_table(console, "Contacts", cols, rows, caption=(
        f"dissipated: finished impacts; {still_open} still open at the end, whose energy so "
        "far is in the run's total" if still_open else ""))


def _print_links(r: Any, units: tuple[float, str, float, str]) -> None:
    model = r.model
    if not model.links:
        return
    ff, fu, ef, eu = units
    cols = [Col("link", "left", wrap=True), Col("law", "left", wrap=True),
            Col(f"peak force [{fu}]"), Col(f"dissipated [{eu}]")]
    rows = [[link.name, link.readable().split(": ", 1)[1], number(f * ff), number(e * ef)]
            for link, f, e in zip(model.links, r.link_peak_force, r.link_dissipated)]
    print_table(console, "Links between buildings", cols, rows)


def _seat_where(name: str, n_frames: int) -> str:
    """``"A1 (under B1's left end)"``, ``"J1 (between B1 and B2)"``."""
    if name == "A1":
        return "A1 (under B1's left end)"
    if name == "A2":
        return f"A2 (under B{n_frames}'s right end)"
    j = int(name[1:])
    return f"{name} (between B{j} and B{j + 1})"


def _print_seats(s: dict[str, Any]) -> None:
    """The seats of a bridge (summary ``seats``): width, the clause's minimum, peak opening
    and margin, in mm; a plain line for every seat lost or narrower than the minimum."""
    seats = s.get("seats")
    if not seats:
        return
    clauses = sorted({x["clause"] for x in seats if x["clause"] is not None})

    def mm(v: float | None) -> str:
        return "–" if v is None else number(1e3 * v)

    cols = [Col("seat", "left"), Col("width [mm]"), Col("required [mm]"),
            Col("peak opening [mm]"), Col("at t [s]"), Col("margin [mm]"),
            Col("state", "left")]
    rows = [[x["name"], mm(x["width_m"]), mm(x["required_m"]), mm(x["peak_opening_m"]),
             "–" if x["peak_opening_time_s"] is None else f"{x['peak_opening_time_s']:.3f}",
             mm(x["margin_m"]),
             Text("UNSEATED", style="bold red") if x["unseated"] else "seated"]
            for x in seats]
    caption = ("margin = width − peak opening; required: " + "; ".join(clauses)
               if clauses else "margin = width − peak opening; no clause checked")
    print_table(console, "Seats (peak openings at the output steps)", cols, rows,
                caption=caption)
    n = len(s.get("buildings", [])) or 1
    for x in seats:
        where = _seat_where(x["name"], n)
        if x["unseated"]:
            console.print(Text(
                f"Unseated at seat {where}: it opened {mm(x['peak_opening_m'])} mm at "
                f"{x['peak_opening_time_s']:.3f} s, more than its {mm(x['width_m'])} mm seat "
                f"(margin {mm(x['margin_m'])} mm): the deck resting there came off it.",
                style="bold red"))
        if x["meets_minimum"] is False:
            console.print(Text(
                f"Seat {where} is {mm(x['width_m'])} mm wide, narrower than the "
                f"{mm(x['required_m'])} mm {x['clause']} asks.", style="yellow"))

