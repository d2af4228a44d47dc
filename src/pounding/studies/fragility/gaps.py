"""The gap each record needs at each level, by simulation without contact
(:func:`pounding.studies.gap.critical_gaps`): what the gap analysis of a study
(:mod:`.analysis`) starts from. :mod:`.runner` computes it before the sweep.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.studies.fragility.cases import StudyCases

__all__ = ["NeededGaps", "bridge_needed_gaps", "needed_gaps"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class NeededGaps:
    """The gap each record needs at each level, and the code gaps at the gap level.

    Attributes
    ----------
    levels : (n_levels,)
        Intensities [g] (the study's levels).
    needed : (n_records, n_levels)
        Smallest uniform gap [m] with which the record at that level causes no impact: the
        largest critical gap over every contact level of the model.
    at : float
        The intensity of the gap analysis [g], and
    needed_at : (n_records,)
        each record's needed gap there [m].
    code : dict
        ``ABS``, ``SRSS``, ``DDC`` [m] at ``at``: the rules from the mean peak
        displacements of the records (:meth:`~pounding.studies.gap.GapStudy.rules_from_peaks`),
        largest over the contact levels.
    scaled : bool
        True where the needed gaps at the levels were scaled from those at ``at`` (linear
        buildings: the uncoupled response is proportional to the record), False where
        every level was simulated (yielding storeys, frames with plastic hinges).
    stopped : tuple of str
        One line per record and level whose uncoupled runs stopped (a frame that lost its
        strength): its needed gap is NaN, left out of the gap analysis.
    """

    levels: FloatArray
    needed: FloatArray
    at: float
    needed_at: FloatArray
    code: dict[str, float]
    scaled: bool
    stopped: tuple[str, ...] = ()


def needed_gaps(cases: StudyCases) -> NeededGaps:
    """The gaps the records need, by simulation without contact
    (:func:`pounding.studies.gap.critical_gaps`), each record scaled exactly as its runs.

    For linear buildings one uncoupled run per building and record at ``at`` gives every
    level: the response to ``λ a_g(t)`` is ``λ`` times that to ``a_g(t)``, so the needed
    gap is proportional to the scale factor, which is proportional to the level. Buildings
    with yielding storeys and frames with plastic hinges are simulated at every level; a
    record whose uncoupled run stops there (a frame that lost its strength, or any other
    error of the run) needs an unknown gap (NaN, :attr:`NeededGaps.stopped`), unless every
    record stops at ``at``: then the first error is raised.
    """
    at = float(cases.config.gap_at())
    levels = np.asarray(cases.levels, dtype=float)
    gs, needed_at, stopped = _study_at(cases, at)
    rules = gs.rules_from_peaks("mean")
    code = {k: float(np.max(v)) for k, v in rules.items()}
    inelastic = gs.model.is_inelastic or bool(gs.model.yielding_frames)
    if not inelastic:
        needed = needed_at[:, None] * (levels[None, :] / at)
    else:
        columns = []
        for x in levels:
            _, column, more = _study_at(cases, float(x), every_record_may_stop=True)
            columns.append(column)
            stopped += more
        needed = np.column_stack(columns)
    return NeededGaps(levels, needed, at, needed_at, code, scaled=not inelastic,
                      stopped=tuple(stopped))


def _study_at(cases: StudyCases, level: float, every_record_may_stop: bool = False
              ) -> tuple[Any, FloatArray, list[str]]:
    """The gap study of every record at ``level`` (:func:`pounding.studies.gap.critical_gaps`),
    each record's needed gap [m] (NaN where its runs stopped) and one line per record whose
    runs stopped. The study holds the records that ran (None if none did)."""
    from pounding.studies.gap import critical_gaps

    built = [cases.build(r, level) for r in range(len(cases.records))]
    model, _, solver = built[0]
    kw = {"dt": solver["dt"], "duration": solver["duration"]}
    try:
        gs = critical_gaps(model, [b.motion for b in built], **kw)
        return gs, gs.critical.max(axis=1), []
    except ValueError as first:
        if len(built) == 1 and not every_record_may_stop:
            raise
        error = first
    needed = np.full(len(built), np.nan)
    stopped: list[str] = []
    for r, b in enumerate(built):  # record by record: which ones stop
        try:
            needed[r] = critical_gaps(model, [b.motion], **kw).critical.max()
        except ValueError as exc:
            stopped.append(f"{cases.records[r]} at {level:g} g, without contact: {exc}")
    ran = [b.motion for b, ok in zip(built, np.isfinite(needed)) if ok]
    if not ran:
        if every_record_may_stop:
            return None, needed, stopped
        raise error
    return critical_gaps(model, ran, **kw), needed, stopped


def bridge_needed_gaps(cases: StudyCases, table: Any) -> NeededGaps:
    """The gap a bridge's joints need at each level, from the runs without joint contact
    that follow the study's runs in its sweep's table (:mod:`.bridge`): the largest closing
    of any expansion joint in a run where no joint is reached. With every joint's gap above
    it the decks never meet at a joint (the run with contact is that run until they first
    meet); with one below, they do.

    Returns
    -------
    NeededGaps
        ``needed`` (n_records, n_levels) [m]: the largest closing of any expansion joint,
        NaN where the run failed (listed in ``stopped``) or closed a joint by half of
        :data:`NO_CONTACT_GAP` or more; ``code``: ABS, SRSS, DDC at the gap level, largest
        over the joints; ``scaled`` False.
    """
    from pounding.studies.fragility.bridge import NO_CONTACT_GAP
    from pounding.studies.separation_rules import code_gaps, cqc_correlation

    layout = cases.bridge
    df = table.sort_values("case_index").iloc[len(cases.rows):]
    if len(df) != len(cases.needed_rows):
        raise ValueError(f"results: {len(df)} rows without joint contact for "
                         f"{len(cases.needed_rows)} such runs of the study")
    ok = (df["status"] == "ok").to_numpy()
    closing = np.column_stack([df[f"peak_closing_m_J{j + 1}"].to_numpy(dtype=float,
                                                                     na_value=np.nan)
                               for j in range(layout.n_joints)]).max(axis=1)
    reached = ok & (closing >= 0.5 * NO_CONTACT_GAP)
    closed_by = closing.copy()  # (what a run that reached a joint closed it by: its message)
    closing = np.where(ok & ~reached, closing, np.nan)
    nr, nl = len(cases.records), len(cases.needed_levels)
    idx = np.array(cases.needed_rows)
    grid = np.full((nr, nl), np.nan)
    grid[idx[:, 0], idx[:, 1]] = closing
    at = float(cases.config.gap_at())
    ia = cases.needed_levels.index(at)
    stopped = [f"{cases.records[r]} at {cases.needed_levels[li]:g} g, without joint contact: "
               + (str(msg) if not good else f"a joint closed by {c:.3g} m")
               for (r, li), good, far, msg, c in zip(cases.needed_rows, ok, reached,
                                                     df["error"], closed_by)
               if not good or far]
    # the code gaps of every joint from the decks' mean peaks at the gap level
    at_rows = (idx[:, 1] == ia) & ok
    peaks = [df[f"peak_displacement_m_{d}"].to_numpy(dtype=float, na_value=np.nan)[at_rows]
             for d in layout.decks]
    code = {"ABS": np.nan, "SRSS": np.nan, "DDC": np.nan}
    if at_rows.any():
        u = np.array([p.mean() for p in peaks])
        rho = [cqc_correlation(layout.periods[j], layout.periods[j + 1], layout.zetas[j],
                               layout.zetas[j + 1]) for j in range(layout.n_joints)]
        rules = code_gaps(u[:-1], u[1:], rho)
        code = {k: float(np.max(v)) for k, v in rules.items()}
    levels = np.asarray(cases.levels, dtype=float)
    return NeededGaps(levels, grid[:, :len(levels)], at, grid[:, ia], code, scaled=False,
                      stopped=tuple(stopped))
