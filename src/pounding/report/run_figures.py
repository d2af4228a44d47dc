"""The figures of the run page: the PNGs of the folder, or regenerated from the NetCDF."""

from __future__ import annotations

from typing import Any

import numpy as np

from pounding.report.format import Block, Figure, Note, png_bytes
from pounding.report.run_folder import RunFolder
from pounding.result import ENERGY_NAMES

__all__ = ["figures_section", "result_from"]


def figures_section(r: RunFolder, skip: tuple[str, ...] = ()) -> list[Block]:
    """Each figure a run of this model has (but the keys ``skip``, shown in a section of
    their own): the folder's PNG, else regenerated from ``timehistories.nc`` and
    ``impacts.csv`` when the model can be rebuilt, else a warning."""
    from pounding.plot.registry import RUN_FIGURES, figures_for

    parts: list[Block] = []
    result = None
    why_not = ""
    # the figures a run of this model has (no storey hysteresis without yielding storeys;
    # a bridge's in place of the storeys'); model unknown: those in the folder and those
    # every run of its kind (a bridge: summary.json has its block) has
    bridge = "bridge" in r.summary
    wanted = (figures_for(r.built.model) if r.built is not None else
              {k: f for k, f in RUN_FIGURES.items()
               if (r.folder / f.file).is_file()
               or (not f.yielding_only and f.bridge in (None, bridge))})
    for key, fig in wanted.items():
        if key in skip:
            continue
        name, caption = fig.file, fig.caption
        path = r.folder / name
        if path.is_file():
            parts.append(Figure(path.read_bytes(), caption, f"{caption} ({name} of the run)."))
            continue
        if result is None and not why_not:
            if r.built is None:
                why_not = r.build_error or "the model is unknown"
            else:
                try:
                    result = result_from(r)
                except (ValueError, KeyError) as exc:
                    why_not = f"the results could not be reloaded ({exc})"
        if result is not None:
            parts.append(Figure(png_bytes(fig.make(result)), caption,
                                f"{caption} (regenerated from timehistories.nc: {name} is not "
                                "in the folder)."))
        else:
            parts.append(Note(f"{caption}: {name} is not in the folder and could not be "
                              f"regenerated: {why_not}.", "warn"))
    return parts


def result_from(r: RunFolder) -> Any:
    """A :class:`pounding.result.Result` rebuilt from the folder (for figures it lacks);
    the folder's model must have been rebuilt (``r.built``)."""
    from pounding.result import IMPACT_COLUMNS, Result, SolverStats

    model, motion = r.built.model, r.built.motion
    ds = r.ds
    labels = [c.label for c in model.contacts]
    n_imp = len(r.impacts)
    arr = np.zeros((n_imp, len(IMPACT_COLUMNS)))
    if n_imp:
        arr[:, 0] = [labels.index(str(lb)) for lb in r.impacts["contact"]]
        for j, col in enumerate(IMPACT_COLUMNS[1:], start=1):
            arr[:, j] = r.impacts[col].to_numpy(dtype=float)
    sv = r.summary.get("solver", {}) or {}
    stats = SolverStats(solver=str(sv.get("name", "?")), rtol=float(sv.get("rtol") or 0.0),
                        rk_steps=int(sv.get("rk_steps") or 0),
                        rejected=int(sv.get("rejected") or 0),
                        events=int(sv.get("events") or 0),
                        impact_overflow=bool(sv.get("impact_table_overflow")),
                        wall_time=float(sv.get("wall_time_s") or 0.0))
    t = np.asarray(ds["time"].values, dtype=float)
    dt = float(r.summary.get("output_step_s") or (t[1] - t[0] if t.size > 1 else 1.0))

    def a(name: str) -> np.ndarray:
        return np.asarray(ds[name].values, dtype=float)

    energy = a("energy")
    if energy.shape[1] < len(ENERGY_NAMES):  # runs saved before the hysteretic column
        energy = np.pad(energy, ((0, 0), (0, len(ENERGY_NAMES) - energy.shape[1])))
    yielding = None
    if "element_force" in ds.variables:  # (every element row's force, a bridge's too)
        yielding = a("element_force")
    elif model.is_inelastic:
        offsets = model.system.offsets
        cols = [offsets[p] + j for p, j in model.yielding_storeys]
        yielding = a("storey_shear")[:, cols]
    from pounding.studies.between_steps import ground_fields

    grounds = ground_fields(motion, model, dt, t.size)  # (spatially varying ground)
    return Result(model=model, motion=motion, dt=dt, ground=a("ground_acceleration"),
                  displacement=a("displacement"), velocity=a("velocity"),
                  abs_acceleration=a("absolute_acceleration"), penetration=a("penetration"),
                  contact_force=a("contact_force"), energy=energy, impact_array=arr,
                  stats=stats, yielding_shear=yielding,
                  link_force=a("link_force") if "link_force" in ds.variables else None,
                  **grounds)  # type: ignore[arg-type]
