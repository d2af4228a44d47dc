"""The checks of the run page: the energy balance and the gap check."""

from __future__ import annotations

import numpy as np

from pounding.report.format import Block, Note, Table, kv_table
from pounding.report.run_folder import RunFolder

__all__ = ["ENERGY_DESCRIPTIONS", "critical_gaps_of", "energy_section", "gap_check_section"]

ENERGY_DESCRIPTIONS: dict[str, str] = {
    "input": "input energy −∫u̇ᵀMr·a_g dt",
    "kinetic": "kinetic energy ½u̇ᵀMu̇ (relative to the ground)",
    "strain": "elastic strain energy ½uᵀKu (plus the recoverable energy of yielding storeys)",
    "damping": "dissipated by structural (viscous) damping ∫u̇ᵀCu̇ dt",
    "contact_work": "work of the contact forces ∫ΣF·δ̇ dt",
    "contact_stored": "elastic energy still stored in closed contacts",
    "hysteretic": "hysteretic energy of yielding storeys and isolation bearings (their work "
                  "less what they would give back)",
    "links": "dissipated by the links between buildings (their springs' energy is in strain)",
}
"""What each term of the energy balance (``energy_term`` of ``timehistories.nc``) is."""


def energy_section(r: RunFolder) -> list[Block]:
    """Each cumulative energy at the end and at its largest, and the closure of the balance."""
    ds = r.ds
    e = np.asarray(ds["energy"].values, dtype=float)
    names = [str(x) for x in ds["energy_term"].values]
    col = {n: e[:, i] for i, n in enumerate(names)}
    t = Table(("term", "final value [J]", "largest |value| during the run [J]", "meaning"),
              caption="Energy balance: cumulative energies at the end of the run")
    for n in names:
        t.add(n, float(col[n][-1]), float(np.abs(col[n]).max()), ENERGY_DESCRIPTIONS.get(n, ""))
    out: list[Block] = [t]
    needed = ("input", "kinetic", "strain", "damping", "contact_work")
    if all(k in col for k in needed):
        zero = np.zeros_like(col["input"])
        # every term of the balance E_0 + input = kinetic + strain + damping + hysteretic
        # + contact_work + links (result.ENERGY_NAMES); a term the file does not have is 0
        spent = ("kinetic", "strain", "damping", "hysteretic", "contact_work", "links")
        present = [k for k in spent if k in col]
        e0 = float(col["kinetic"][0] + col["strain"][0])
        total = sum((col[k] for k in present), zero)
        closure = e0 + col["input"] - total
        scale = max(float(np.abs(col["input"]).max()), e0, 1e-300)
        diss = col["contact_work"] - col.get("contact_stored", 0.0)
        terms = " + ".join(present)
        items = [
            ("dissipated in contacts = contact_work − contact_stored, final [J]",
             float(diss[-1])),
            (f"{terms}, final [J]", float(total[-1])),
            ("energy at the start E_0 = kinetic + strain at t = 0 [J]", e0),
            (f"closure E_0 + input − ({terms}), final [J]", float(closure[-1])),
            ("largest |closure| during the run [J]", float(np.abs(closure).max())),
            ("largest |closure| / larger of largest |input| and E_0 [-]",
             float(np.abs(closure).max() / scale)),
            ("energy_balance_error in summary.json [-]", r.summary.get("energy_balance_error")),
        ]
        if col["input"][-1] > 0:
            share = [("structural damping", col["damping"][-1]), ("contacts", diss[-1])]
            if "hysteretic" in col and np.any(col["hysteretic"]):
                share.append(("hysteresis (yielding storeys, bearings)", col["hysteretic"][-1]))
            if "links" in col and np.any(col["links"]):
                share.append(("links between buildings", col["links"][-1]))
            share.append(("kinetic + strain (still in motion)",
                          col["kinetic"][-1] + col["strain"][-1]))
            items += [(f"share of the final input: {k} [%]", 100.0 * float(v) / col["input"][-1])
                      for k, v in share]
        out.append(kv_table(items, caption="Closure"))
    return out


def critical_gaps_of(r: RunFolder) -> tuple[dict[str, float], str]:
    """The critical gap of every contact [m] by label, as ``pounding gap`` computes it from
    the same model file (:func:`pounding.studies.gap.critical_gaps`: each building alone,
    no contact, the model's record, output step and duration), and a sentence on where it
    comes from; ``({}, why)`` where it cannot be computed.

    A run in which some floors touched is no run without contact: every floor of both
    buildings moves differently once any of them has struck, so the largest approach of
    floors that never touched in it is not their critical gap (it was 26–31 % below it for
    the demo's lowest floors). Only a run in which nothing touched is such a run; then its
    largest approach at the output samples is used where the gap study cannot be run."""
    if r.built is None:
        return {}, f"the model could not be rebuilt ({r.build_error})"
    from pounding.studies.gap import critical_gaps

    model, motion, solver = r.built
    try:
        study = critical_gaps(model, motion, dt=solver.get("dt"),
                              duration=solver.get("duration"))
    except (ValueError, TypeError) as exc:  # (a model or record the study does not take)
        return {}, f"the gap study cannot be run for this model ({exc})"
    gaps = {label: float(g) for label, g in zip(study.labels, study.critical[0])}
    return gaps, (f"as pounding gap computes it from model.toml: each building simulated "
                  f"alone (no contact) under the run's record for {study.durations[0]:g} s, "
                  "the largest u_left − u_right refined between output samples")


def gap_check_section(r: RunFolder) -> list[Block]:
    """One row per contact: its gap, whether it closed, the largest relative displacement,
    and the critical gap (``pounding gap``'s, from runs without contact)."""
    ds = r.ds
    if "contact" not in ds.dims or ds.sizes["contact"] == 0:
        return [Note("No contacts: a single building, nothing to check.")]
    floors = [str(x) for x in ds["floor"].values]
    u = np.asarray(ds["displacement"].values, dtype=float)
    pen = np.asarray(ds["penetration"].values, dtype=float)
    contacts = [str(x) for x in ds["contact"].values]
    elev = (np.asarray(ds["contact_elevation"].values, dtype=float)
            if "contact_elevation" in ds.coords else np.full(len(contacts), np.nan))
    gaps_model = {}
    if r.built is not None:
        gaps_model = {c.label: c.gap for c in r.built.model.contacts}
    critical, how = critical_gaps_of(r)
    rows = []
    for i, label in enumerate(contacts):
        left, _, right = label.partition("-")
        if label in gaps_model:  # the model's own gap: u_left − u_right = δ + gap exactly
            rel = None  # (a label names floors, not always the DOFs struck: a frame's
            gap_from_nc = float("nan")  # column line, a column point)
        elif left in floors and right in floors:
            rel = u[:, floors.index(left)] - u[:, floors.index(right)]
            gap_from_nc = float(np.median(rel - pen[:, i]))
        else:  # labels not parseable: penetration + gap with the model's gap
            rel = None
            gap_from_nc = float("nan")
        gap = gaps_model.get(label, gap_from_nc)
        if rel is None:
            rel = pen[:, i] + gap
        hits = r.impacts_of(label)
        n = len(hits)
        peak_pen = float(pen[:, i].max())
        if n:
            peak_pen = max(peak_pen, float(np.nanmax(hits["max_penetration"])))
        touched = n > 0 or peak_pen > 0
        rows.append((label, float(elev[i]), gap, touched, n, peak_pen, float(rel.max())))
    untouched_run = not any(row[3] for row in rows)
    if not critical and untouched_run:
        critical = {row[0]: max(row[6], 0.0) for row in rows}
        how = ("from this run, in which no contact closed (so it is a run without contact), "
               "the largest u_left − u_right at the output samples")
    t = Table(("contact", "elevation [m]", "gap [m]", "touched", "impacts",
               "peak penetration [m]", "max(u_left − u_right) in this run [m]",
               "gap − max(u_left − u_right) [m]", "critical gap (no contact) [m]"),
              caption="Gap check, one row per contact element")
    for label, z, gap, touched, n, peak_pen, max_rel in rows:
        t.add(label, z, gap, "yes" if touched else "no", n,
              peak_pen if touched else "– (never closed)", max_rel, gap - max_rel,
              critical.get(label, "– (see note)"))
    return [
        t,
        Note("Displacements are positive to the right, so the gap between a floor of the "
             "left building and the floor of its right neighbour closes when "
             "u_left − u_right reaches the gap; the penetration is "
             "δ = u_left − u_right − gap (timehistories.nc). max(u_left − u_right) is "
             "taken over the output samples; "
             "the peak penetration also uses the impact table (resolved between samples)."),
        Note("Critical gap: the smallest gap that avoids contact under this record, "
             "max(u_left − u_right) of a run in which the buildings never touch"
             + (f"; here {how}." if critical else f"; not shown: {how}, and contacts closed "
                "in this run.")
             + " It is not read from this run where anything touched: once some floors "
             "strike, every floor of both buildings moves differently (where they touched, "
             "max(u_left − u_right) = gap + peak penetration is bounded by the impacts; "
             "where they did not, it is not what they would do without contact)."),
    ]
