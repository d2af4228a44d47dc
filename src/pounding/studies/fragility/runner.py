"""Running a study: its sweep (on Dask, resumable), then the gap each record needs at each
level (:func:`pounding.studies.gap.critical_gaps`), then the analysis and the output folder.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.progress import Progress
from pounding.studies.fragility.plan import StudyPlan, plan_study

__all__ = ["FragilityOutcome", "NeededGaps", "needed_gaps", "run_study"]

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
        every level was simulated (yielding storeys).
    """

    levels: FloatArray
    needed: FloatArray
    at: float
    needed_at: FloatArray
    code: dict[str, float]
    scaled: bool


def needed_gaps(plan: StudyPlan) -> NeededGaps:
    """The gaps the records need, by simulation without contact
    (:func:`pounding.studies.gap.critical_gaps`), each record scaled exactly as its runs.

    For linear buildings one uncoupled run per building and record at ``at`` gives every
    level: the response to ``λ a_g(t)`` is ``λ`` times that to ``a_g(t)``, so the needed
    gap is proportional to the scale factor, which is proportional to the level. Buildings
    with yielding storeys are simulated at every level.
    """
    from pounding.studies.gap import critical_gaps

    at = float(plan.config.gap_at())
    levels = np.asarray(plan.levels, dtype=float)

    def study_at(level: float) -> Any:
        built = [plan.build(r, level) for r in range(len(plan.records))]
        model, _, solver = built[0]
        return critical_gaps(model, [b.motion for b in built], dt=solver["dt"],
                             duration=solver["duration"])

    gs = study_at(at)
    needed_at = gs.critical.max(axis=1)
    rules = gs.rules_from_peaks("mean")
    code = {k: float(np.max(v)) for k, v in rules.items()}
    inelastic = gs.model.is_inelastic
    if not inelastic:
        needed = needed_at[:, None] * (levels[None, :] / at)
    else:
        needed = np.column_stack([study_at(float(x)).critical.max(axis=1) for x in levels])
    return NeededGaps(levels, needed, at, needed_at, code, scaled=not inelastic)


@dataclass(frozen=True)
class FragilityOutcome:
    """What :func:`run_study` did: the plan, the sweep's outcome, the analysis, the files
    written and the seconds taken (whole study; the sweep; gaps; analysis and outputs)."""

    plan: StudyPlan
    sweep: Any
    analysis: Any
    files: list[Path]
    wall_time: float
    gap_time: float
    analysis_time: float

    @property
    def out_dir(self) -> Path:
        """The output folder."""
        return self.plan.out


def run_study(input: str | os.PathLike[str] | StudyPlan,
              out: str | os.PathLike[str] | None = None, *, overwrite: bool = False,
              figures: bool | None = None, progress: Progress | None = None,
              scheduler: str | None = None, n_workers: int | None = None,
              batch_size: int | None = None) -> FragilityOutcome:
    """Run a fragility study and write its folder.

    The first arguments are those of every runner, in the same order (:func:`pounding.run`).
    Its runs are a sweep (:func:`pounding.studies.sweep.run_sweep`): a second run of the
    same study does only the runs missing and redoes the analysis; ``overwrite`` starts
    afresh. Options not given are taken from the study's ``[run]`` table.

    Parameters
    ----------
    input : path-like or StudyPlan
        The study file (``docs/fragility.md``), or its plan (:func:`plan_study`).
    out : path-like, optional
        Output folder (default: ``out`` of the study file, relative to it, else ``<study
        file stem>-results`` in the current folder).
    overwrite : bool
        Start afresh: discard the runs saved in the folder (only files pounding wrote).
    figures : bool, optional
        Draw the figures (IDA, fragility, gap); default yes.
    progress : Progress, optional
        Called as ``progress(done, total)``: runs finished (before and during this call)
        and runs in all (:class:`pounding.progress.Progress`).
    scheduler, n_workers, batch_size
        As :func:`~pounding.studies.sweep.run_sweep` (defaults from ``[run]``).

    Raises
    ------
    ValueError
        Bad input, one line.
    pounding.studies.sweep.SweepInterrupted, pounding.studies.sweep.SweepStopped
        As :func:`~pounding.studies.sweep.run_sweep`: the runs finished are saved.
    """
    from pounding.studies.fragility.analysis import analyse
    from pounding.studies.fragility.outputs import write_outputs
    from pounding.studies.sweep import load_results, run_sweep

    start = time.perf_counter()
    plan = input if isinstance(input, StudyPlan) else plan_study(input, out=out)
    if out is not None:
        plan.out = Path(out)
    r = plan.config.run
    # the gaps first: a model the solver refuses (one line) is refused before the sweep
    # writes anything
    t0 = time.perf_counter()
    gaps = needed_gaps(plan)
    t1 = time.perf_counter()
    res = run_sweep(plan.sweep, plan.out, overwrite=overwrite, progress=progress,
                    scheduler=scheduler or r.scheduler, n_workers=n_workers or r.workers,
                    batch_size=batch_size)
    t2 = time.perf_counter()
    table = load_results(res.results)
    result = analyse(plan, table, gaps)
    files = write_outputs(plan, result, figures=True if figures is None else figures)
    t3 = time.perf_counter()
    return FragilityOutcome(plan, res, result, files, t3 - start, t1 - t0, t3 - t2)
