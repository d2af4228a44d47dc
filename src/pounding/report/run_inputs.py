"""What was run: the model and record sections of the run page."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from pounding.report.format import (Block, Figure, Note, Pre, Table, kv_table, num, png_bytes,
                                    with_unit)
from pounding.report.run_bridge import bridge_model_tables
from pounding.report.run_folder import RunFolder

__all__ = ["CONTACT_UNITS", "model_section", "record_section"]

CONTACT_UNITS: dict[str, str] = {
    "k": "N/m", "k_h": "N/m^n", "e": "-", "c": "N·s/m", "zeta": "-", "chi": "-", "n": "-",
    "delta_m": "m", "a": "-", "gap": "m", "gaps": "m", "formula": "", "tension": "",
    "law": "",
}
"""Units of the keys of ``[contact]`` (``docs/running.md``)."""


def _range_text(values: Sequence[float], unit: str) -> str:
    v = np.asarray(values, dtype=float)
    if v.size == 0:
        return "–"
    if np.allclose(v, v[0]):
        return f"{num(v[0])} {unit}" + (f" × {v.size}" if v.size > 1 else "")
    return f"{num(v.min())} … {num(v.max())} {unit}"


def model_section(r: RunFolder) -> list[Block]:
    """The model: name, buildings, contact law and elements, solver options, model.toml."""
    parts: list[Block] = []
    desc = r.toml.get("description") or ""
    name = r.toml.get("name") or r.summary.get("model", "")
    parts.append(kv_table([("model name", str(name)), ("description", str(desc) or "–")]))
    bridge = bridge_model_tables(r.built.model) if r.built is not None else []
    if bridge:  # a bridge's frames, piers, bearings and restrainers, not storeys
        parts += bridge
    elif r.built is not None:
        model = r.built.model
        t = Table(("building", "name", "storeys", "height [m]", "total mass [kg]",
                   "floor masses [kg]", "storey stiffnesses [N/m]", "T1 [s]",
                   "first periods [s]", "damping"),
                  caption="Buildings, left to right")
        for b, bl in enumerate(model.buildings):
            try:
                periods = ", ".join(num(p) for p in bl.modes().periods[:3])
            except Exception:  # noqa: BLE001  (a display nicety only)
                periods = "–"
            plan = getattr(bl, "plan", None)
            iso = getattr(bl, "isolator", None)
            if plan is not None:  # a building in plan: floors of three DOFs, lateral elements
                storeys, masses = plan.n_floors, _range_text(plan.masses, "kg")
                stiffness = (f"{len(plan.elements)} lateral elements (frames, walls) in plan"
                             if plan.elements else "K given (3 DOFs a floor)")
                damping = plan.damping.readable()
            elif iso is not None:  # a base-isolated building: superstructure on a bearing
                from pounding.result import bearing_law

                storeys = bl.n - 1
                masses = (f"base slab {num(float(bl.masses[0]))} kg; floors "
                          + _range_text(bl.masses[1:], "kg"))
                stiffness = (_range_text(bl.stiffnesses[1:], "N/m") + "; on an isolation "
                             f"bearing: {bearing_law(iso)}")
                damping = bl.damping.readable()
            elif hasattr(bl, "stiffnesses"):
                storeys, masses = bl.n, _range_text(bl.masses, "kg")
                stiffness = _range_text(bl.stiffnesses, "N/m")
                damping = bl.damping.readable()
            else:  # a MatrixBuilding: its K couples the floors, no storey stiffness
                floors = [j for j in bl.floors]
                frame = getattr(bl, "frame", None)  # (a frame: each floor's whole mass)
                floor_mass = bl.masses[floors]
                if frame is not None:
                    at = np.isin(np.round(frame.levels - frame.base, 6),
                                 np.round(bl.elevations[floors], 6))
                    floor_mass = frame.floor_masses[at]
                storeys, masses = len(floors), _range_text(floor_mass, "kg")
                stiffness = (f"full K, {bl.n}×{bl.n}"
                             + (f" ({bl.sources['K']})" if "K" in bl.sources else ""))
                damping = (bl.damping.readable() if bl.damping is not None
                           else f"matrix C ({bl.sources.get('C', 'given')})")
            t.add(f"B{b + 1}", bl.name if bl.name and bl.name != f"B{b + 1}" else "–",
                  storeys, float(bl.total_height),
                  float(bl.total_mass), masses, stiffness, float(bl.fundamental_period),
                  periods, damping)
        parts.append(t)
    else:
        builds = r.toml.get("building", [])
        if builds:
            t = Table(("building", "as given in model.toml"),
                      caption="Buildings, left to right (model.toml, not rebuilt)")
            for b, entry in enumerate(builds):
                t.add(f"B{b + 1}", ", ".join(f"{k} = {v}" for k, v in entry.items()))
            parts.append(t)
        parts.append(Note(f"The model could not be rebuilt: {r.build_error}. Periods and "
                          "derived quantities are not shown.", "warn"))
    contact = r.toml.get("contact")
    if isinstance(contact, dict) and contact:
        items = [(with_unit(k, CONTACT_UNITS.get(k)), v if not isinstance(v, list)
                  else ", ".join(num(x) for x in v)) for k, v in contact.items()]
        parts.append(kv_table(items, caption="Contact law ([contact] of model.toml)"))
    if r.built is not None and r.built.model.contacts:
        t = Table(("contact", "elevation [m]", "gap [m]", "law"), caption="Contact elements")
        for c in r.built.model.contacts:
            t.add(c.label, c.elevation, c.gap, c.law.readable())
        parts.append(t)
    solver = r.toml.get("solver")
    if isinstance(solver, dict) and solver:
        su = {"dt": "s", "duration": "s", "rtol": "-", "h_max": "s"}
        parts.append(kv_table([(with_unit(k, su.get(k)), v) for k, v in solver.items()],
                              caption="Solver options ([solver] of model.toml)"))
    if r.toml_text is not None:
        parts.append(Pre(r.toml_text, summary="model.toml (as run)"))
    return parts


def record_section(r: RunFolder) -> list[Block]:
    """The record: name, source, step, duration, PGA, and the ground acceleration plotted."""
    ds = r.ds
    s = r.summary
    t = np.asarray(ds["time"].values, dtype=float)
    ag = np.asarray(ds["ground_acceleration"].values, dtype=float)
    items: list[tuple[str, Any]] = [("record", str(s.get("record", ds.attrs.get("record", ""))))]
    if r.built is not None:
        gm = r.built.motion
        # two components (buildings in plan): the site's x and y, rotated from the first's
        comps = getattr(gm, "components", (gm,))
        first = comps[0]
        items += [("source", first.source or "–"), ("units of the source", first.units_read),
                  ("record step [s]", gm.dt), ("record duration [s]", gm.duration),
                  ("PGA [g]" + (" (larger of x and y)" if len(comps) > 1 else ""), gm.pga_g),
                  ("PGA [m/s²]", gm.pga)]
        if len(comps) == 2:
            items += [("PGA of x, y [g]", ", ".join(f"{c.pga_g:.4g}" for c in comps))]
    else:
        items += [("PGA [g]", s.get("record_pga_g"))]
    items += [("simulated duration [s]", float(t[-1]) if t.size else None),
              ("output step [s]", s.get("output_step_s")),
              ("largest |ground acceleration| at output samples [m/s²]",
               float(np.abs(ag).max()) if ag.size else None)]
    rec = r.toml.get("record", {})
    for key, unit in (("duration", "s"), ("scale", "-"), ("pga_g", "g"), ("second", "-"),
                      ("second_file", "-"), ("incidence", "degrees")):
        if isinstance(rec, dict) and key in rec:
            items.append((f"record.{key} in model.toml [{unit}]", rec[key]))
    out: list[Block] = [kv_table(items)]
    if t.size:
        from matplotlib.figure import Figure as MplFigure

        fig = MplFigure(figsize=(10, 2.4))
        ax = fig.subplots()
        if ag.ndim == 2 and ag.shape[1] > 1:  # components along the site axes
            names = ["x", "y"] if ag.shape[1] == 2 else [str(g + 1) for g in range(ag.shape[1])]
            for g, name in enumerate(names):
                ax.plot(t, ag[:, g], color=f"C{g}", lw=0.6, label=name)
            ax.legend(loc="upper right", fontsize=8, ncols=len(names), frameon=False)
        else:
            ax.plot(t, ag, color="0.2", lw=0.6)
        ax.set_xlabel("time [s]")
        ax.set_ylabel("ground acceleration [m/s²]")
        ax.grid(True, alpha=0.3)
        ax.set_title(f"{s.get('record', '')}: ground acceleration over the simulated time",
                     fontsize=9, loc="left")
        fig.tight_layout()
        out.append(Figure(png_bytes(fig), "ground acceleration", "Ground acceleration [m/s²] "
                          "against time [s], at the output samples."))
    return out
