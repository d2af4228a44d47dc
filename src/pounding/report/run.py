"""The run page: its sections in order, the headline numbers and the impact table.

The model and record sections are in :mod:`pounding.report.run_inputs`, the figures in
:mod:`pounding.report.run_figures`, the interactive animation in
:mod:`pounding.report.run_animation`, the energy balance and gap check in
:mod:`pounding.report.run_checks`, a bridge's section in :mod:`pounding.report.run_bridge`.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np

from pounding.report.format import Block, Cards, Note, PageSection, Table, kv_table, num
from pounding.report.page import render_page
from pounding.report.run_animation import animation_section
from pounding.report.run_bridge import BRIDGE_FIGURE, bridge_section
from pounding.report.run_checks import energy_section, gap_check_section
from pounding.report.run_figures import figures_section
from pounding.report.run_folder import RunFolder, read_run
from pounding.report.run_inputs import model_section, record_section
from pounding.result import peak_abs

__all__ = ["IMPACT_HEADERS", "MAX_IMPACT_ROWS", "render_run"]

MAX_IMPACT_ROWS = 500
"""At most this many impacts are listed (all of them are in ``impacts.csv``)."""

IMPACT_HEADERS: dict[str, str] = {
    "contact": "contact", "elevation": "elevation [m]", "start": "start [s]", "end": "end [s]",
    "v0": "impact velocity v0 [m/s]", "peak_force": "peak force [N]",
    "max_penetration": "max penetration [m]",
    "restitution": "separation ÷ approach speed [-]",
    "energy_dissipated": "energy dissipated by the contact [J]",
}
"""Headers of the columns of ``impacts.csv``, with their units."""


def render_run(folder: Path, code_check: Any = None) -> str:
    """The HTML text of the report of the run folder ``folder`` (with a "Code check"
    section for ``code_check``, a :class:`~pounding.report.code_check.CodeCheckFile`: the
    check's levels beside the run's peak closing).

    Raises
    ------
    ValueError
        A file of the folder is unreadable (:func:`pounding.report.run_folder.read_run`).
    """
    r = read_run(folder)
    name = str(r.summary.get("model") or r.toml.get("name") or folder.name)
    record = str(r.summary.get("record") or "")
    pga = r.summary.get("record_pga_g")
    sub = (f"Run report — record {record}"
           + (f", PGA {pga:.3f} g" if isinstance(pga, (int, float)) else "")
           + f"; folder {folder.resolve().name}")
    bridge = bridge_section(r)  # (a bridge's run only)
    sections = [
        PageSection("summary", "Headline numbers", _headline_section(r)),
        *([PageSection("bridge", "Bridge", bridge)] if bridge else []),
        PageSection("model", "Model", model_section(r)),
        PageSection("record", "Record", record_section(r)),
        PageSection("figures", "Figures",
                    figures_section(r, skip=(BRIDGE_FIGURE,) if bridge else ())),
        PageSection("animation", "Animation", animation_section(r)),  # the animate view
        PageSection("impacts", "Impact table", _impacts_section(r)),
        PageSection("energy", "Energy balance", energy_section(r)),
        PageSection("gap-check", "Gap check", gap_check_section(r)),
    ]
    if code_check is not None:
        from pounding.report.code_check import code_check_section

        sections.append(code_check_section(code_check, r))
    return render_page(f"{name}: pounding run report", sub, sections, folder)


def _building_index(label: str) -> int:
    """0-based building of a ``building`` coordinate (``B2``) or a DOF label (``B2F3``)."""
    m = re.match(r"B(\d+)", label)
    return int(m.group(1)) - 1 if m else 0


def _headline_section(r: RunFolder) -> list[Block]:
    s = r.summary
    solver = s.get("solver", {}) or {}
    e_err = s.get("energy_balance_error")
    pdisp = [v for v in (s.get("peak_displacement_m", {}) or {}).values() if v is not None]
    # a building in plan: along y too (its floor labels above are along x)
    pdisp += [row["peak_displacement_y_m"] for b in s.get("buildings", []) or []
              for row in b.get("storeys", []) if row.get("peak_displacement_y_m") is not None]
    bridge = isinstance(s.get("bridge"), dict)
    out: list[Block] = [Cards([
        ("impacts", num(s.get("n_impacts"))),
        ("peak contact force [N]", num(s.get("peak_contact_force_N"))),
        (f"largest {'deck' if bridge else 'floor'} displacement [m]",
         num(max(pdisp)) if pdisp else "–"),
        ("dissipated in contacts [J]", num(s.get("contact_dissipated_J"))),
        ("energy-balance error [of peak input]", f"{e_err:.2e}" if isinstance(e_err, float)
         else "–"),
    ])]
    pcf = s.get("peak_contact_force_by_contact_N", {}) or {}
    if pcf:
        t = Table(("contact", "impacts", "peak contact force [N]", "dissipated [J]"),
                  caption="Per contact")
        for label, f in pcf.items():
            rows = r.impacts_of(label)
            n = len(rows)
            diss = float(np.nansum(rows["energy_dissipated"])) if n else 0.0
            t.add(label, n, f, diss)
        out.append(t)
    if not bridge:  # (a bridge's frames, piers and bearings: the Bridge section)
        out.append(_response_table(r))
        out += _bearing_tables(r)
        out += _plan_tables(r)
    items = [("solver", solver.get("name")), ("relative tolerance rtol [-]", solver.get("rtol")),
             ("adaptive steps through contacts", solver.get("rk_steps")),
             ("rejected steps", solver.get("rejected")),
             ("contact events (closings and openings)", solver.get("events")),
             ("impact table overflowed", solver.get("impact_table_overflow")),
             ("integration wall time [s]", solver.get("wall_time_s"))]
    out.append(kv_table([(k, v) for k, v in items if v is not None],
                        caption="Solver statistics"))
    if solver.get("impact_table_overflow"):
        out.append(Note("The impact table overflowed: some impacts are not listed.", "warn"))
    return out


def _response_table(r: RunFolder) -> Table:
    ds = r.ds
    labels = [str(x) for x in ds["floor"].values]
    owners = ([str(x) for x in ds["building"].values] if "building" in ds.coords
              else labels)
    disp = peak_abs(ds["displacement"].values)
    drift = peak_abs(np.nan_to_num(ds["drift"].values))
    acc = (peak_abs(ds["absolute_acceleration"].values)
           if "absolute_acceleration" in ds else np.full(len(labels), np.nan))
    elev = (np.asarray(ds["floor_elevation"].values, dtype=float)
            if "floor_elevation" in ds.coords else np.full(len(labels), np.nan))
    kind = ([str(x) for x in ds["storey_kind"].values] if "storey_kind" in ds.coords
            else None)
    inelastic = "ductility" in ds
    plan = "storey_torque" in ds or any(
        b.get("given_as") == "plan" for b in r.summary.get("buildings", []) or [])
    cols: tuple[str, ...] = (
        "building", "storeys", "peak roof displacement [m]", "peak storey drift [m]",
        "at storey", "peak drift ratio [%]", "peak absolute floor acceleration [m/s²]")
    if inelastic:
        cols += ("peak storey ductility [-]", "largest residual drift [m]")
    t = Table(cols, caption="Peak response of each building (absolute values over the run, "
              "at the output samples of timehistories.nc; summary.json and the printed tables "
              "locate them inside solver steps)"
              + ("; ductility = peak drift / yield drift (NaN: linear storeys), residual "
                 "drift after elastic unloading" if inelastic else "")
              + ("; of an isolated building, its storeys above the base slab (the bearing "
                 "is in the next table)" if kind is not None and "bearing" in kind else "")
              + ("; of a building in plan, along x at the floors' centres of mass (both "
                 "directions storey by storey below)" if plan else ""))
    groups: dict[int, list[int]] = {}
    for i, owner in enumerate(owners):
        groups.setdefault(_building_index(owner), []).append(i)
    heights = (np.asarray(ds["storey_height"].values, dtype=float)
               if "storey_height" in ds.coords else None)
    for b, idx in sorted(groups.items()):
        floors = idx
        if heights is not None:  # floors only (NaN: a DOF that is not a floor)
            floors = [i for i in idx if np.isfinite(heights[i])]
            floors.sort(key=lambda i: elev[i])
        storeys = [i for i in floors if kind is None or kind[i] == "storey"]
        d = drift[storeys]
        j = int(np.argmax(d))
        if heights is not None:
            h = heights[storeys[j]]
        else:
            h = elev[storeys[j]] - (elev[storeys[j] - 1] if j > 0 else 0.0)
        ratio = 100.0 * d[j] / h if h > 0 else float("nan")
        name = ""
        if r.built is not None and b < len(r.built.model.buildings):
            name = r.built.model.buildings[b].name
        label = f"B{b + 1}" + (f" ({name})" if name and name != f"B{b + 1}" else "")
        row = [label, len(storeys), float(disp[floors[-1]]), float(d[j]), j + 1, ratio,
               float(acc[floors].max())]
        if inelastic:
            mu = np.asarray(ds["ductility"].values, dtype=float)[storeys]
            res = np.asarray(ds["residual_drift"].values, dtype=float)[storeys]
            row += [float(np.nanmax(mu)) if np.isfinite(mu).any() else float("nan"),
                    float(res[int(np.argmax(np.abs(res)))])]
        t.add(*row)
    return t


def _bearing_tables(r: RunFolder) -> list[Block]:
    """The isolation bearings (summary.json ``bearings``), apart from the storeys."""
    bearings = r.summary.get("bearings") or []
    if not bearings:
        return []
    t = Table(("building", "bearing", "base slab at [m]", "peak displacement [mm]", "at t [s]",
               "peak force [kN]", "at t [s]", "residual displacement [mm]"),
              caption="Isolation bearings: under each base slab, not storeys (no drift ratio "
                      "or ductility)")
    for x in bearings:
        t.add(str(x.get("building")), str(x.get("law")), x.get("base_slab_elevation_m"),
              1e3 * float(x.get("peak_displacement_m") or np.nan),
              x.get("peak_displacement_time_s"), 1e-3 * float(x.get("peak_force_N") or np.nan),
              x.get("peak_force_time_s"), 1e3 * float(x.get("residual_displacement_m")
                                                      or 0.0))
    return [t]


def _plan_tables(r: RunFolder) -> list[Block]:
    """Storey by storey, each building in plan (summary.json ``buildings``): along x and y
    at the floors' centres of mass, rotation, storey shears and torque."""
    out: list[Block] = []
    for b in r.summary.get("buildings", []) or []:
        if b.get("given_as") != "plan":
            continue
        t = Table(("storey", "floor at [m]", "displacement x [mm]", "displacement y [mm]",
                   "rotation [mrad]", "drift ratio x [%]", "drift ratio y [%]",
                   "storey shear x [kN]", "storey shear y [kN]", "storey torque [kN·m]"),
                  caption=f"{b.get('building')} in plan, storey by storey: at each floor's "
                          "centre of mass; shears and torque from the lateral elements, the "
                          "torque about the centre of mass of the floor above")

        def get(row: dict, key: str, factor: float) -> float:
            v = row.get(key)
            return float("nan") if v is None else factor * float(v)

        for row in b.get("storeys", []):
            t.add(row.get("storey"), row.get("floor_elevation_m"),
                  get(row, "peak_displacement_m", 1e3), get(row, "peak_displacement_y_m", 1e3),
                  get(row, "peak_rotation_mrad", 1.0), get(row, "peak_drift_ratio", 100.0),
                  get(row, "peak_drift_ratio_y", 100.0), get(row, "peak_storey_shear_N", 1e-3),
                  get(row, "peak_storey_shear_y_N", 1e-3),
                  get(row, "peak_storey_torque_N_m", 1e-3))
        out.append(t)
    return out


def _impacts_section(r: RunFolder) -> list[Block]:
    imp = r.impacts
    if not len(imp):
        why = ("no impacts.csv in the folder" if not (r.folder / "impacts.csv").is_file()
               else "no impact: the gap never closed")
        return [Note(f"No impacts listed ({why}).")]
    cols = list(imp.columns)
    t = Table(["#"] + [IMPACT_HEADERS.get(c, c) for c in cols], cls="impacts", scroll=True)
    for i, (_, row) in enumerate(imp.head(MAX_IMPACT_ROWS).iterrows()):
        t.add(i + 1, *[row[c] for c in cols])
    out: list[Block] = []
    if len(imp) > MAX_IMPACT_ROWS:
        out.append(Note(f"First {MAX_IMPACT_ROWS} of {len(imp)} impacts; all are in "
                        "impacts.csv."))
    else:
        out.append(Note(f"{len(imp)} impact(s), in time order per the solver's impact table "
                        "(impacts.csv). Separation ÷ approach speed is −δ̇ at separation / "
                        "v0 (the column restitution of impacts.csv): the law's coefficient "
                        "of restitution only for free bodies; between buildings the ground "
                        "and the storeys push the floors during the impact, so it is no "
                        "energy ratio and may exceed 1. The impact's own loss is the energy "
                        "dissipated by the contact (≥ 0). An impact still open at the end "
                        "has no end, ratio or energy (–)."))
    out.append(t)
    if r.impacts_units:
        out.append(Note(f"Units as stated in impacts.csv: {r.impacts_units}"))
    return out
