"""From the sweep's table to the answers: IDA curves and their fractiles, counts of
exceedance at every stripe, the fragility of every limit state by both fits with bootstrap
intervals, and the probability of pounding against the gap with the gap for a target
probability beside the code gaps.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.result.demands import DEMANDS
from pounding.studies.fragility.bootstrap import (
    FragilityEstimate,
    expanded_confidence,
    fit_from_capacities,
    fit_from_stripes,
    percentile_interval,
    resample,
)
from pounding.studies.fragility.cases import StudyCases
from pounding.studies.fragility.gap_probability import (
    empirical_gap,
    gap_lognormal,
    lognormal_gap,
    pounding_probability,
    pounding_probability_fit,
)
from pounding.studies.fragility.gaps import NeededGaps
from pounding.studies.fragility.ida import capacities, exceedance_counts, ida_fractiles
from pounding.studies.fragility.study import LimitStateSpec

__all__ = ["FragilityAnalysis", "GapAnalysis", "LimitStateResult", "analyse",
           "demand_table"]

FloatArray = NDArray[np.float64]

_COLUMNS = {"pounding": "n_impacts", "impacts": "n_impacts",
            "impact_force": "peak_contact_force_N", "drift": "peak_drift_ratio",
            "acceleration": "peak_floor_accel_m_s2", "ductility": "max_ductility"}
"""The column of the sweep's table each demand is read from (SI units)."""


@dataclass(frozen=True)
class LimitStateResult:
    """One limit state at one gap: what exceeded where, and both fits.

    Attributes
    ----------
    spec : LimitStateSpec
    gap : float or None
        The gap of the runs [m] (None: the base model's).
    exceed : (n_records, n_levels)
        1 exceeded, 0 not, NaN failed run.
    n_runs, n_exceed : (n_levels,)
        Counts at each stripe.
    capacity, censored : (n_records,)
        Each record's IDA capacity [g] and whether it never exceeded.
    msa, ida : FragilityEstimate
        The stripe MLE and the IDA fit, with bootstrap intervals.
    """

    spec: LimitStateSpec
    gap: float | None
    exceed: FloatArray
    n_runs: NDArray[np.int64]
    n_exceed: NDArray[np.int64]
    capacity: FloatArray
    censored: NDArray[np.bool_]
    msa: FragilityEstimate
    ida: FragilityEstimate


@dataclass(frozen=True)
class GapAnalysis:
    """The probability of pounding against the gap (module
    :mod:`~pounding.studies.fragility.gap_probability`).

    Attributes
    ----------
    needed : NeededGaps
    median, beta : float
        Lognormal fit of the needed gaps at ``needed.at`` (θ_g [m], β_g).
    target : float
        The target probability.
    gap_fit, gap_empirical : float
        The gap [m] for the target probability: from the fit and from the records.
    gap_fit_ci : (float, float)
        Bootstrap interval of ``gap_fit``.
    grid : (n_grid,)
        Gaps [m] of the curves and the surface.
    p_empirical, p_fit : (n_grid,)
        P(pounding | gap) at ``needed.at``.
    p_band : ((n_grid,), (n_grid,))
        Bootstrap band of ``p_fit``.
    surface_empirical, surface_fit : (n_grid, n_levels)
        P(pounding | gap, level).
    check : dict
        For each gap run with contact (uniform gaps only): runs where the simulation with
        contact pounded, and how many of them agree with ``needed > gap``.
    """

    needed: NeededGaps
    median: float
    beta: float
    target: float
    gap_fit: float
    gap_empirical: float
    gap_fit_ci: tuple[float, float]
    grid: FloatArray
    p_empirical: FloatArray
    p_fit: FloatArray
    p_band: tuple[FloatArray, FloatArray]
    surface_empirical: FloatArray
    surface_fit: FloatArray
    check: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class FragilityAnalysis:
    """Everything a study computed from its runs (:func:`analyse`)."""

    cases: StudyCases
    levels: FloatArray
    records: list[str]
    gaps: list[float | None]
    demands: dict[str, FloatArray]
    """Demand [SI] per key of :data:`~pounding.result.demands.DEMANDS` shown:
    shape (n_gaps, n_records, n_levels), NaN for a failed run."""
    fractiles: dict[str, FloatArray]
    """16/50/84 % fractiles of each demand [SI]: (n_gaps, 3, n_levels)."""
    limit_states: list[LimitStateResult]
    gap: GapAnalysis
    n_runs: int
    n_failed: int
    failures: list[str]
    """One line per failed run: record, level, message."""


def demand_table(cases: StudyCases, table: Any) -> tuple[dict[str, FloatArray], list[str]]:
    """The demands of every run as arrays (n_gaps, n_records, n_levels) [SI], and one line
    per failed run."""
    ng, nr, nl = len(cases.gaps), len(cases.records), len(cases.levels)
    df = table.sort_values("case_index")
    if len(df) != len(cases.rows):
        raise ValueError(f"results: {len(df)} rows for {len(cases.rows)} runs of the study")
    ok = (df["status"] == "ok").to_numpy()
    idx = np.array(cases.rows)
    out: dict[str, FloatArray] = {}
    keys = ["pounding", "impacts", "impact_force", "drift", "acceleration"]
    if cases.sweep is not None and df["max_ductility"].notna().any():
        keys.append("ductility")
    for key in keys:
        col = df[_COLUMNS[key]].to_numpy(dtype=float, na_value=np.nan)
        if key == "pounding":
            col = np.where(np.isnan(col), np.nan, (col > 0).astype(float))
        a = np.full((ng, nr, nl), np.nan)
        a[idx[:, 2], idx[:, 0], idx[:, 1]] = np.where(ok, col, np.nan)
        out[key] = a
    failures = [f"{cases.records[r]} at {cases.levels[li]:g} g"
                + (f", gap {cases.gaps[g]:g} m" if cases.gaps[g] is not None else "")
                + f": {msg}"
                for (r, li, g), good, msg in zip(cases.rows, ok, df["error"]) if not good]
    return out, failures


def analyse(cases: StudyCases, table: Any, gaps: NeededGaps) -> FragilityAnalysis:
    """The whole analysis of a study from the sweep's table and the needed gaps.

    Parameters
    ----------
    cases : StudyCases
    table : pandas.DataFrame
        The sweep's ``results.parquet``.
    gaps : NeededGaps
        From :func:`pounding.studies.fragility.gaps.needed_gaps`.
    """
    cfg = cases.config
    levels = np.asarray(cases.levels, dtype=float)
    demands, failures = demand_table(cases, table)
    fractiles = {k: np.stack([ida_fractiles(v[g]) for g in range(v.shape[0])])
                 for k, v in demands.items()}
    bs = cfg.bootstrap
    has_run: NDArray[np.bool_] = np.any(np.isfinite(demands["pounding"]), axis=(0, 2))
    n_kept = int(has_run.sum())
    if n_kept < 2:
        raise ValueError("runs: fewer than two records have a successful run; see the "
                         "errors in results.parquet")
    boot = resample(n_kept, bs.n, bs.seed)
    results: list[LimitStateResult] = []
    for gi, g in enumerate(cases.gaps):
        for ls in cfg.limit_state:
            d = DEMANDS[ls.demand]
            if ls.demand not in demands:
                raise ValueError(f"limit_state: demand \"{ls.demand}\" has no value in the "
                                 "runs (ductility needs yielding storeys)")
            v = demands[ls.demand][gi][has_run]
            exceed = np.where(np.isnan(v), np.nan, (v > ls.limit_si).astype(float))
            n_runs, n_exc = exceedance_counts(exceed)
            cap, cen = capacities(levels, exceed if d.binary else v, ls.limit_si,
                                  binary=d.binary)
            results.append(LimitStateResult(
                ls, g, exceed, n_runs, n_exc, cap, cen,
                fit_from_stripes(levels, exceed, boot, bs.confidence),
                fit_from_capacities(cap, cen, boot, bs.confidence)))
    gap = _gap_analysis(cases, gaps, demands, boot[:, :], has_run)
    return FragilityAnalysis(cases, levels, list(cases.records), list(cases.gaps), demands,
                             fractiles, results, gap, len(cases.rows), len(failures), failures)


def _gap_analysis(cases: StudyCases, ng: NeededGaps, demands: dict[str, FloatArray],
                  boot: NDArray[np.int64], has_run: NDArray[np.bool_]) -> GapAnalysis:
    cfg = cases.config
    p = cfg.gap.target
    at_needed = ng.needed_at[has_run]
    conf = expanded_confidence(cfg.bootstrap.confidence, at_needed.size)
    med, beta = gap_lognormal(at_needed)
    gap_fit = lognormal_gap(med, beta, p)
    gap_emp = empirical_gap(at_needed, p)
    top = float(np.nanmax(ng.needed)) if np.isfinite(ng.needed).any() else 0.0
    top = max(top, float(np.nanmax(list(ng.code.values()))), 1e-3) * 1.05
    grid = np.linspace(0.0, top, 211)
    p_emp = pounding_probability(at_needed, grid)
    p_fit = pounding_probability_fit(med, beta, grid)
    fits = [gap_lognormal(at_needed[b]) for b in boot]
    gaps_b = np.array([lognormal_gap(m, s, p) for m, s in fits]) if fits else np.zeros(0)
    lo, hi = percentile_interval(gaps_b, conf) if gaps_b.size else (np.nan, np.nan)
    curves = (np.array([pounding_probability_fit(m, s, grid) for m, s in fits])
              if fits else np.full((1, grid.size), np.nan))
    band = percentile_interval(curves, conf, axis=0)
    needed = ng.needed[has_run]
    s_emp = pounding_probability(needed, grid)
    s_fit = np.column_stack([pounding_probability_fit(*gap_lognormal(needed[:, j]), grid)
                             for j in range(needed.shape[1])])
    return GapAnalysis(ng, med, beta, p, gap_fit, gap_emp, (float(lo), float(hi)), grid,
                       p_emp, p_fit, band, s_emp, s_fit, _check(cases, needed, demands,
                                                                has_run))


def _check(cases: StudyCases, needed: FloatArray, demands: dict[str, FloatArray],
           has_run: NDArray[np.bool_]) -> dict[str, Any]:
    """Runs with contact against the needed gaps: pounding iff the needed gap exceeds the
    gap (uniform gaps only)."""
    out: dict[str, Any] = {}
    base_gaps = [float(x) for x in cases.sweep.base.get("contact", {}).get("gaps", [])] or \
        [float(cases.sweep.base.get("contact", {}).get("gap", np.nan))]
    for gi, g in enumerate(cases.gaps):
        value = g if g is not None else (base_gaps[0] if len(set(base_gaps)) == 1 else None)
        if value is None or not np.isfinite(value):
            continue
        pounded = demands["pounding"][gi][has_run]
        ok = np.isfinite(pounded) & np.isfinite(needed)
        predicted = needed > value
        out[f"{value:g}"] = {"gap_m": value, "runs": int(ok.sum()),
                             "pounded": int(np.sum(pounded[ok] > 0.5)),
                             "agree": int(np.sum((pounded[ok] > 0.5) == predicted[ok]))}
    return out
