"""The output folder of a study, beside the sweep's own files (``sweep.json``, ``parts/``,
``results.parquet`` — every run):

* ``fragility.json`` — the study in one file: intensity, levels, records, limit states with
  both fits and their intervals, the gap analysis, the runs that failed (and, with plastic
  hinges, those that collapsed);
* ``fragility.csv`` — one row per limit state, gap and method: median [g], β, intervals;
* ``counts.csv`` — runs and exceedances per limit state, gap and level;
* ``ida.csv`` — every run in readable units (record, level, gap, demands; with plastic
  hinges whether a hinge went past its IMK cap and whether the run stopped as its frame
  lost its strength: ``inf`` in the deformation demands of such a run);
* ``gap.csv`` — the gaps for the target probability and the code gaps at the gap level,
  each with its probability of pounding;
* ``needed_gaps.csv`` — the gap each record needs at each level [m]: a column
  ``gap_m_at_<level>_g`` per level (a bridge: at its joints, :mod:`.bridge`);
* ``seat_widths.csv`` — a bridge's seat width for the target probability of unseating at
  every level, from the records' largest seat opening (:func:`.bridge.seat_widths`);
* figures (:mod:`pounding.plot.fragility`): ``ida.png``, ``fragility.png``,
  ``pounding_vs_gap.png``, ``pounding_surface.png``.

Every file is written atomically, all of them moved into place together, each recorded
in the folder's manifest (:func:`write_outputs`), and depends only on the runs and the
study: a re-run writes the same bytes (figures aside: their metadata are fixed, their
pixels too on one machine).
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
from pathlib import Path
from typing import Any

import numpy as np

from pounding.result.demands import DEMANDS
from pounding.studies.fragility.analysis import FragilityAnalysis
from pounding.studies.fragility.bootstrap import FragilityEstimate
from pounding.studies.fragility.cases import StudyCases
from pounding.studies.fragility.fitting import (
    FIT_ALL,
    FIT_FAILED,
    FIT_NONE,
    FIT_OK,
    FIT_SEPARATED,
)
from pounding.studies.fragility.gap_probability import (
    pounding_probability,
    pounding_probability_fit,
)

__all__ = ["BRIDGE_TABLES", "FIGURES", "STUDY_FILE", "TABLES", "seat_rows", "write_outputs"]

STUDY_FILE = "fragility.json"
"""The file that makes a folder a fragility study's output."""

TABLES = ("fragility.csv", "counts.csv", "ida.csv", "gap.csv", "needed_gaps.csv")
BRIDGE_TABLES = ("seat_widths.csv",)
"""A bridge study's tables beside :data:`TABLES`."""
FIGURES = ("ida.png", "fragility.png", "pounding_vs_gap.png", "pounding_surface.png")

STATUS_TEXT = {FIT_OK: "fitted",
               FIT_NONE: "never exceeded: the median is above the highest level",
               FIT_ALL: "exceeded in every run: the median is below the lowest level",
               FIT_SEPARATED: "separated data: beta -> 0, the median lies between two levels",
               FIT_FAILED: "not fitted (too few exceedances, or no trend with the "
                           "intensity)"}


def _num(x: Any) -> Any:
    """A number for JSON: NaN → null, ±inf → "inf"/"-inf", NumPy scalars as Python."""
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        f = float(x)
        if math.isnan(f):
            return None
        if math.isinf(f):
            return "inf" if f > 0 else "-inf"
        return f
    return x


def _estimate(e: FragilityEstimate) -> dict[str, Any]:
    return {"median_g": _num(e.median), "beta": _num(e.beta),
            "median_ci_g": [_num(v) for v in e.median_ci],
            "beta_ci": [_num(v) for v in e.beta_ci], "status": STATUS_TEXT[e.status],
            "n_records": e.n_records, "bootstrap_failed": e.n_failed_boot}


def _flag(v: float) -> int | None:
    """A yes/no of a run as 1 / 0, None (an empty cell) where unknown."""
    return None if math.isnan(v) else int(v > 0.5)


def _csv(rows: list[list[Any]], header: list[str]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    for r in rows:
        w.writerow(["" if v is None else (f"{v:.6g}" if isinstance(v, float) else v)
                    for v in r])
    return buf.getvalue()


def summary(cases: StudyCases, a: FragilityAnalysis) -> dict[str, Any]:
    """The content of ``fragility.json``."""
    cfg = cases.config
    ga = a.gap
    ls = []
    for r in a.limit_states:
        d = DEMANDS[r.spec.demand]
        extra = ({"drift_limit_pct": r.spec.collapse_drift_percent}
                 if r.spec.demand == "collapse" else {})
        ls.append({"name": r.spec.label, "demand": r.spec.demand, "limit": r.spec.limit,
                   **extra, "unit": d.unit, "gap_m": r.gap, "n_runs": r.n_runs.tolist(),
                   "n_exceed": r.n_exceed.tolist(),
                   "capacity_g": [_num(v) for v in r.capacity],
                   "censored": r.censored.tolist(),
                   "msa_mle": _estimate(r.msa), "ida": _estimate(r.ida)})
    runs: dict[str, Any] = {"n": a.n_runs, "failed": a.n_failed, "failures": a.failures[:100]}
    if a.hinges is not None:
        runs.update(collapsed=len(a.hinges.collapses), collapses=a.hinges.collapses[:100])
    return {
        "kind": "fragility", "name": cfg.name, "description": cfg.description,
        "source": str(cases.source) if cases.source else None, "base": cfg.base,
        "intensity": {"measure": cfg.intensity.measure, "label": cases.im_label,
                      "period_s": cfg.intensity.period, "damping": cfg.intensity.damping,
                      "saavg_periods_s": list(cases.saavg_range) if cases.saavg_range else None,
                      "scaling": (cfg.suite.scaling.model_dump() if cfg.suite.scaling
                                  else "each record to the level"),
                      "target_g": cases.im_target},
        "levels_g": list(cases.levels), "records": cases.records,
        "records_applied": cases.record_note or "along the row (x), as recorded",
        "gaps_m": [g for g in cases.gaps], "building_periods_s": cases.periods,
        "limit_states": ls,
        "gap": {"at_g": ga.needed.at, "target_probability": ga.target,
                "needed_m": dict(zip(cases.records, [_num(v) for v in ga.needed.needed_at])),
                "lognormal_median_m": _num(ga.median), "lognormal_beta": _num(ga.beta),
                "gap_for_target_lognormal_m": _num(ga.gap_fit),
                "gap_for_target_lognormal_ci_m": [_num(v) for v in ga.gap_fit_ci],
                "gap_for_target_records_m": _num(ga.gap_empirical),
                "code_gaps_m": {k: _num(v) for k, v in ga.needed.code.items()},
                "scaled_from_gap_level": ga.needed.scaled, "check": ga.check,
                **({"uncoupled_runs_stopped": list(ga.needed.stopped[:100])}
                   if ga.needed.stopped else {})},
        **({"seats": _seats(cases, a)} if a.seats is not None else {}),
        "bootstrap": cfg.bootstrap.model_dump(),
        "runs": runs,
    }


def _seats(cases: StudyCases, a: FragilityAnalysis) -> dict[str, Any]:
    """A bridge's ``seats`` of ``fragility.json``: the seat width for the target
    probability of unseating at every level."""
    s = a.seats
    return {"what": "the seat width [m] a seat needs (every seat as wide) for the target "
                    "probability of unseating, from the records' largest seat opening",
            "gap_m": cases.gaps[0], "target_probability": s.target,
            "joint_gaps_m": list(cases.bridge.joint_gaps) if cases.gaps[0] is None else None,
            "levels_g": list(cases.levels),
            "lognormal_median_m": [_num(v) for v in s.median],
            "lognormal_beta": [_num(v) for v in s.beta],
            "width_for_target_lognormal_m": [_num(v) for v in s.width_fit],
            "width_for_target_lognormal_ci_m": [[_num(v) for v in s.width_fit_ci[0]],
                                                [_num(v) for v in s.width_fit_ci[1]]],
            "width_for_target_records_m": [_num(v) for v in s.width_records]}


def seat_rows(cases: StudyCases, a: FragilityAnalysis) -> list[list[Any]]:
    """The rows of ``seat_widths.csv``: per level, the lognormal fit of the records' largest
    seat opening and the seat width for the target probability of unseating."""
    s = a.seats
    return [[x, s.target, s.median[j], s.beta[j], s.width_fit[j], s.width_fit_ci[0, j],
             s.width_fit_ci[1, j], s.width_records[j]] for j, x in enumerate(cases.levels)]


def _fragility_rows(cases: StudyCases, a: FragilityAnalysis) -> list[list[Any]]:
    rows = []
    for r in a.limit_states:
        d = DEMANDS[r.spec.demand]
        for method, e in (("msa_mle", r.msa), ("ida", r.ida)):
            rows.append([r.spec.label, r.spec.demand, r.spec.limit, d.unit, r.gap, method,
                         cases.im_label, e.median, e.median_ci[0], e.median_ci[1], e.beta,
                         e.beta_ci[0], e.beta_ci[1], e.n_records,
                         int(np.sum(~r.censored)), STATUS_TEXT[e.status]])
    return rows


def _gap_rows(cases: StudyCases, a: FragilityAnalysis) -> list[list[Any]]:
    ga = a.gap
    at = ga.needed.needed_at
    rows: list[tuple[str, float, float, float]] = [
        (f"P = {ga.target:g}: lognormal fit", ga.gap_fit, *ga.gap_fit_ci),
        (f"P = {ga.target:g}: records", ga.gap_empirical, math.nan, math.nan)]
    rows += [(f"{k} (mean simulated peaks)", v, math.nan, math.nan)
             for k, v in ga.needed.code.items()]
    rows += [(f"simulated with contact: {1000 * g:g} mm", float(g), math.nan, math.nan)
             for g in cases.gaps if g is not None]
    out = []
    for name, g, lo, hi in rows:
        pe = float(pounding_probability(at, [g])[0]) if math.isfinite(g) else math.nan
        pf = float(pounding_probability_fit(ga.median, ga.beta, [g])[0]) \
            if math.isfinite(g) else math.nan
        out.append([name, ga.needed.at, g, lo, hi, pe, pf])
    return out


def write_outputs(cases: StudyCases, a: FragilityAnalysis, figures: bool = True) -> list[Path]:
    """Write the tables, ``fragility.json`` and (with ``figures``) the figures into
    ``cases.out``; returns the files written.

    All are written first into a temporary folder inside ``cases.out`` and moved into place
    together once complete, each recorded in the folder's manifest
    (:mod:`pounding.io.manifest`): a full disk leaves the files of an earlier analysis as
    they were. A file of the same name that pounding did not write is not replaced (one
    line, before any is moved).
    """
    from pounding.io.files import WriteFailed, write_text
    from pounding.io.manifest import Manifest
    from pounding.io.output_folder import make_temporary_folder, remove_temporary_folder

    out = cases.out
    man = Manifest(out)
    names = [*TABLES, *(BRIDGE_TABLES if a.seats is not None else ()), STUDY_FILE,
             *(FIGURES if figures else ())]
    for name in names:
        man.check_free(out / name)
    stage = make_temporary_folder(out, "fragility", "stage", holds=names)
    try:
        try:
            _write_all(cases, a, stage, figures, write_text)
        except WriteFailed as exc:
            raise exc.moved(stage, out) from None
        written = [out / name for name in names]
        for target in written:
            man.append([man.entry_of(target, stage / target.name)])
            os.replace(stage / target.name, target)
    finally:
        remove_temporary_folder(stage)
    if not figures:
        for name in FIGURES:  # no stale figure of an earlier run (only pounding's own)
            man.discard(out / name)
    return written


def _write_all(cases: StudyCases, a: FragilityAnalysis, out: Path, figures: bool,
               write_text: Any) -> None:
    """Write every file of :func:`write_outputs` into the folder ``out``."""
    fr = _fragility_rows(cases, a)
    write_text(out / "fragility.csv", _csv(fr, [
        "limit_state", "demand", "limit", "unit", "gap_m", "method", "intensity_measure",
        "median_g", "median_lo_g", "median_hi_g", "beta", "beta_lo", "beta_hi", "n_records",
        "n_records_exceeding", "status"]))
    counts = [[r.spec.label, r.gap, x, int(n), int(z), z / n if n else math.nan]
              for r in a.limit_states for x, n, z in zip(cases.levels, r.n_runs, r.n_exceed)]
    write_text(out / "counts.csv", _csv(counts, [
        "limit_state", "gap_m", "level_g", "n_runs", "n_exceed", "fraction"]))
    keys = list(a.demands)
    hinge_cols = ({"hinge_past_cap": a.hinges.past_cap,
                   "strength_lost": a.hinges.strength_lost} if a.hinges is not None else {})
    runs = []
    for gi, g in enumerate(cases.gaps):
        for ri, name in enumerate(cases.records):
            for li, x in enumerate(cases.levels):
                runs.append([name, x, g] + [a.demands[k][gi, ri, li] * DEMANDS[k].factor
                                            for k in keys]
                            + [_flag(v[gi, ri, li]) for v in hinge_cols.values()])
    write_text(out / "ida.csv", _csv(runs, ["record", "level_g", "gap_m"] + [
        f"{k}_{DEMANDS[k].unit}".replace("_-", "").replace("%", "pct") for k in keys]
        + list(hinge_cols)))
    write_text(out / "gap.csv", _csv(_gap_rows(cases, a), [
        "gap", "at_g", "gap_m", "gap_lo_m", "gap_hi_m", "p_pounding_records",
        "p_pounding_lognormal"]))
    ng = a.gap.needed
    write_text(out / "needed_gaps.csv", _csv(
        [[name] + list(row) for name, row in zip(cases.records, ng.needed)],
        ["record"] + [f"gap_m_at_{x:g}_g" for x in cases.levels]))
    if a.seats is not None:
        write_text(out / "seat_widths.csv", _csv(seat_rows(cases, a), [
            "level_g", "p_unseating", "opening_median_m", "opening_beta", "width_lognormal_m",
            "width_lo_m", "width_hi_m", "width_records_m"]))
    write_text(out / STUDY_FILE, json.dumps(summary(cases, a), indent=2, allow_nan=False) + "\n")
    if figures:
        from pounding.plot import save_figure
        from pounding.plot.fragility import (
            plot_fragility,
            plot_gap_probability,
            plot_gap_surface,
            plot_ida,
        )

        for name, fig in (("ida.png", plot_ida(a)), ("fragility.png", plot_fragility(a)),
                          ("pounding_vs_gap.png", plot_gap_probability(a)),
                          ("pounding_surface.png", plot_gap_surface(a))):
            save_figure(fig, out / name, dpi=130)
