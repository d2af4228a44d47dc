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

__all__ = ["SIDESWAY_DRIFT", "FragilityAnalysis", "GapAnalysis", "HingeRuns",
           "LimitStateResult", "analyse", "collapse_exceedance", "demand_table"]

FloatArray = NDArray[np.float64]

_COLUMNS = {"pounding": "n_impacts", "impacts": "n_impacts",
            "impact_force": "peak_contact_force_N", "drift": "peak_drift_ratio",
            "acceleration": "peak_floor_accel_m_s2", "ductility": "max_ductility",
            "plastic_rotation": "peak_plastic_rotation_rad"}
"""The column of the sweep's table each demand is read from (SI units). ``collapse`` is
made of three: ``hinge_past_cap``, ``peak_drift_ratio`` and ``strength_lost``
(:func:`collapse_exceedance`)."""


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
    shape (n_gaps, n_records, n_levels), NaN for a failed run, +inf for a deformation of a
    run whose frame lost its strength (:func:`demand_table`)."""
    fractiles: dict[str, FloatArray]
    """16/50/84 % fractiles of each demand [SI]: (n_gaps, 3, n_levels)."""
    limit_states: list[LimitStateResult]
    gap: GapAnalysis
    n_runs: int
    n_failed: int
    failures: list[str]
    """One line per failed run: record, level, message."""
    hinges: HingeRuns | None = None
    """What the frames' plastic hinges did in every run (None: a model without them)."""
    seats: Any = None
    """A bridge's seat widths for the target probability of unseating at every level
    (:class:`~pounding.studies.fragility.bridge.SeatWidths`), from its runs at the first
    gap of :attr:`gaps` (the base model's joint gaps, else the first of ``[gap] values``);
    None for buildings."""

    def _repr_html_(self) -> str:
        """Jupyter's view: the fragilities, the gap for the target probability, the runs
        and the curves, inline (:func:`pounding.studies.fragility.display.fragility_html`)."""
        from pounding.studies.fragility.display import fragility_html

        return fragility_html(self)


@dataclass(frozen=True)
class HingeRuns:
    """The plastic hinges of every run of a study whose model has them, each array
    (n_gaps, n_records, n_levels): 1.0 / 0.0, NaN for a failed run (or, for ``past_cap``,
    a model without IMK hinges).

    Attributes
    ----------
    past_cap : ndarray
        A hinge went past its IMK capping (or ultimate) rotation
        (:mod:`pounding.studies.sweep.hinge_measures`).
    strength_lost : ndarray
        The run stopped because a frame lost its strength: a collapse, not a failed run.
    sidesway : ndarray
        The run went on but a storey drifted by more than :data:`SIDESWAY_DRIFT` of its
        height: a sidesway collapse followed past the model's meaning.
    collapses : list of str
        One line per run that collapsed so (either way): record, level, what happened.
    """

    past_cap: FloatArray
    strength_lost: FloatArray
    sidesway: FloatArray
    collapses: list[str]

    @property
    def collapsed(self) -> NDArray[np.bool_]:
        """Runs that stopped as a frame lost its strength or collapsed sideways."""
        return (self.strength_lost > 0.5) | (self.sidesway > 0.5)


SIDESWAY_DRIFT = 1.0
"""A peak storey drift ratio beyond which a run of a model with plastic hinges is a sidesway
collapse: the storey moved by more than its own height. A frame whose hinges have lost their
strength under gravity (P-Delta) keeps moving away, and the run goes on to displacements of
kilometres that mean nothing (the model's geometry is that of small displacements): its
deformation demands are +inf, its forces, accelerations and number of impacts left out
(NaN), as for a run that stopped; whether it pounded is kept."""


def _where(cases: StudyCases, r: int, li: int, g: int) -> str:
    """A run named by its record, level and gap."""
    return (f"{cases.records[r]} at {cases.levels[li]:g} g"
            + (f", gap {cases.gaps[g]:g} m" if cases.gaps[g] is not None else ""))


def demand_table(cases: StudyCases, table: Any
                 ) -> tuple[dict[str, FloatArray], list[str], HingeRuns | None]:
    """The demands of every run as arrays (n_gaps, n_records, n_levels) [SI], one line
    per failed run, and the hinges' part (None without plastic hinges).

    A run that stopped because a frame lost its strength (``strength_lost`` in the table),
    or a run of a model with plastic hinges whose peak storey drift ratio exceeds
    :data:`SIDESWAY_DRIFT`, is a collapse, not a failure: its deformation demands (those
    :attr:`~pounding.result.demands.Demand.exceeded_by_collapse`: drift, plastic rotation)
    are +inf — the flatline of its IDA curve (Vamvatsikos & Cornell 2002) — and the others
    NaN, as for a failed run."""
    ng, nr, nl = len(cases.gaps), len(cases.records), len(cases.levels)
    df = table.sort_values("case_index")
    bridge = getattr(cases, "bridge", None)  # (a bridge's runs without joint contact follow)
    n_runs = len(cases.rows) + len(getattr(cases, "needed_rows", ()))
    if len(df) != n_runs:
        raise ValueError(f"results: {len(df)} rows for {n_runs} runs of the study")
    df = df.iloc[:len(cases.rows)]
    ok = (df["status"] == "ok").to_numpy()
    idx = np.array(cases.rows)
    has_hinges = "strength_lost" in df.columns
    lost = (df["strength_lost"].fillna(False).to_numpy(dtype=bool) & ~ok if has_hinges
            else np.zeros(ok.shape, dtype=bool))
    drift = df["peak_drift_ratio"].to_numpy(dtype=float, na_value=np.nan)
    with np.errstate(invalid="ignore"):
        sidesway = ok & (drift > SIDESWAY_DRIFT) if has_hinges else np.zeros(ok.shape, bool)
    collapsed = lost | sidesway

    def grid(col: NDArray[np.float64]) -> FloatArray:
        a = np.full((ng, nr, nl), np.nan)
        a[idx[:, 2], idx[:, 0], idx[:, 1]] = col
        return a

    out: dict[str, FloatArray] = {}
    keys = ["pounding", "impacts", "impact_force", "drift", "acceleration"]
    if cases.sweep is not None and df["max_ductility"].notna().any():
        keys.append("ductility")
    if has_hinges:
        keys.append("plastic_rotation")
    for key in keys:
        col = df[_COLUMNS[key]].to_numpy(dtype=float, na_value=np.nan)
        if key == "pounding":
            col = np.where(np.isnan(col), np.nan, (col > 0).astype(float))
        # a sidesway collapse did pound or not (the buildings met, or never did), but its
        # other numbers are those of a motion past the model's meaning
        col = np.where(ok & (~sidesway | (key == "pounding")), col, np.nan)
        if DEMANDS[key].exceeded_by_collapse:
            col = np.where(collapsed, np.inf, col)
        out[key] = grid(col)
    if bridge is not None:  # a bridge: the largest opening of any seat
        from pounding.studies.fragility.bridge import joint_demand

        every = LimitStateSpec(demand="seat_opening", limit=0.0)
        out["seat_opening"] = grid(joint_demand(every, bridge, df))
    failures = [f"{_where(cases, r, li, g)}: {msg}"
                for (r, li, g), good, gone, msg in zip(cases.rows, ok, lost, df["error"])
                if not good and not gone]
    hinges = None
    if has_hinges:
        cap = df["hinge_past_cap"].to_numpy(dtype=float, na_value=np.nan)
        what = [msg if gone else f"peak storey drift ratio {100 * d:.3g} % (sidesway collapse)"
                for gone, d, msg in zip(lost, drift, df["error"])]
        hinges = HingeRuns(
            past_cap=grid(np.where(ok, cap, np.nan)),
            strength_lost=grid(np.where(ok | lost, lost.astype(float), np.nan)),
            sidesway=grid(np.where(ok | lost, sidesway.astype(float), np.nan)),
            collapses=[f"{_where(cases, r, li, g)}: {w}"
                       for (r, li, g), c, w in zip(cases.rows, collapsed, what) if c])
    return out, failures, hinges


def collapse_exceedance(drift: FloatArray, drift_limit: float,
                        past_cap: FloatArray | None = None,
                        strength_lost: FloatArray | None = None) -> FloatArray:
    """Whether each run collapsed (1.0), did not (0.0) or failed (NaN): a hinge past its IMK
    capping rotation, a peak storey drift ratio above ``drift_limit`` (a ratio, not %), or a
    run stopped because a frame lost its strength.

    Parameters
    ----------
    drift : ndarray
        Peak storey drift ratio of every run (+inf where the frame lost its strength, NaN
        where the run failed).
    drift_limit : float
        The drift ratio beyond which a run is a collapse.
    past_cap, strength_lost : ndarray, optional
        Of the same shape, 1.0 where a hinge went past its cap / the run stopped as its
        frame lost its strength (:class:`HingeRuns`); None without plastic hinges.
    """
    out = np.where(np.isnan(drift), np.nan, (drift > drift_limit).astype(float))
    if past_cap is not None:
        out = np.where(np.nan_to_num(past_cap, nan=0.0) > 0.5, 1.0, out)
    if strength_lost is not None:
        out = np.where(strength_lost > 0.5, 1.0, out)
    return out


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
    demands, failures, hinges = demand_table(cases, table)
    fractiles = {k: np.stack([ida_fractiles(v[g]) for g in range(v.shape[0])])
                 for k, v in demands.items()}
    bs = cfg.bootstrap
    # a record counts when one of its runs finished, or stopped as its frame collapsed
    ran = np.isfinite(demands["pounding"])
    if hinges is not None:
        ran |= hinges.collapsed
    has_run: NDArray[np.bool_] = np.any(ran, axis=(0, 2))
    n_kept = int(has_run.sum())
    if n_kept < 2:
        raise ValueError("runs: fewer than two records have a successful run; see the "
                         "errors in results.parquet")
    boot = resample(n_kept, bs.n, bs.seed)
    results: list[LimitStateResult] = []
    for gi, g in enumerate(cases.gaps):
        for ls in cfg.limit_state:
            d = DEMANDS[ls.demand]
            if ls.demand == "collapse":
                v = collapse_exceedance(
                    demands["drift"][gi], ls.collapse_drift_percent / 100.0,
                    *((hinges.past_cap[gi], hinges.strength_lost[gi]) if hinges else ()))
                v = v[has_run]
            elif ls.joint is not None:  # a bridge's demand at one joint or seat
                v = _at_joint(cases, table, ls)[gi][has_run]
            elif ls.demand not in demands:
                raise ValueError(f"limit_state: demand \"{ls.demand}\" has no value in the "
                                 "runs (ductility needs yielding storeys, a plastic rotation "
                                 "plastic hinges)")
            else:
                v = demands[ls.demand][gi][has_run]
            exceed = np.where(np.isnan(v), np.nan, (v > ls.limit_si).astype(float))
            n_runs, n_exc = exceedance_counts(exceed)
            cap, cen = capacities(levels, exceed if d.binary else v, ls.limit_si,
                                  binary=d.binary)
            results.append(LimitStateResult(
                ls, g, exceed, n_runs, n_exc, cap, cen,
                fit_from_stripes(levels, exceed, boot, bs.confidence),
                fit_from_capacities(cap, cen, boot, bs.confidence)))
    checked = demands
    seats = None
    if cases.bridge is not None:  # the gap analysis is the joints': pounding at a joint
        from pounding.studies.fragility.bridge import seat_widths

        checked = dict(demands, pounding=_at_joint(
            cases, table, LimitStateSpec(demand="pounding", joint="joints")))
        seats = seat_widths(demands["seat_opening"][0][has_run], cfg.gap.target, boot,
                            bs.confidence)
    gap = _gap_analysis(cases, gaps, checked, boot[:, :], has_run)
    return FragilityAnalysis(cases, levels, list(cases.records), list(cases.gaps), demands,
                             fractiles, results, gap, len(cases.rows), len(failures), failures,
                             hinges, seats)


def _at_joint(cases: StudyCases, table: Any, spec: LimitStateSpec) -> FloatArray:
    """A bridge's demand at the joints or seats a limit state names, every run:
    (n_gaps, n_records, n_levels) [SI], NaN for a failed run
    (:func:`~pounding.studies.fragility.bridge.joint_demand`)."""
    from pounding.studies.fragility.bridge import joint_demand

    df = table.sort_values("case_index").iloc[:len(cases.rows)]
    idx = np.array(cases.rows)
    a = np.full((len(cases.gaps), len(cases.records), len(cases.levels)), np.nan)
    a[idx[:, 2], idx[:, 0], idx[:, 1]] = joint_demand(spec, cases.bridge, df)
    return a


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
    if cases.bridge is not None:  # a bridge's: its joints' (``pounding``: at a joint)
        base_gaps = list(cases.bridge.joint_gaps)
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
