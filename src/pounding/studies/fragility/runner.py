"""Running a study: the gap each record needs at each level (:mod:`.gaps`), its sweep (on
Dask, resumable), then the analysis (:mod:`.analysis`) and the output folder
(:mod:`.outputs`). The top of the package: nothing in it imports the runner.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pounding.progress import Progress
from pounding.studies.fragility.gaps import bridge_needed_gaps, needed_gaps
from pounding.studies.fragility.cases import StudyCases, study_cases

__all__ = ["FragilityOutcome", "run_study"]


@dataclass(frozen=True)
class FragilityOutcome:
    """What :func:`run_study` did: the cases, the sweep's outcome, the analysis, the files
    written and the seconds taken (whole study; the sweep; gaps; analysis and outputs)."""

    cases: StudyCases
    sweep: Any
    analysis: Any
    files: list[Path]
    wall_time: float
    gap_time: float
    analysis_time: float

    @property
    def out_dir(self) -> Path:
        """The output folder."""
        return self.cases.out

    def _repr_html_(self) -> str:
        """Jupyter's view: the fragilities, the gap for the target probability, the runs
        and the curves, inline (:func:`pounding.studies.fragility.display.fragility_html`)."""
        from pounding.studies.fragility.display import fragility_html

        return fragility_html(self.analysis, [("folder", str(self.out_dir)),
                                              ("wall time [s]", self.wall_time)])


def run_study(input: str | os.PathLike[str] | StudyCases,
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
    input : path-like or StudyCases
        The study file (``docs/fragility.md``), or its cases (:func:`study_cases`).
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
    cases = input if isinstance(input, StudyCases) else study_cases(input, out=out)
    if out is not None:
        cases.out = Path(out)
    r = cases.config.run
    # the gaps first: a model the solver refuses (one line) is refused before the sweep
    # writes anything
    # (a bridge's: from its runs without joint contact, cases of the sweep itself)
    t0 = time.perf_counter()
    gaps = needed_gaps(cases) if cases.bridge is None else None
    t1 = time.perf_counter()
    res = run_sweep(cases.sweep, cases.out, overwrite=overwrite, progress=progress,
                    scheduler=scheduler or r.scheduler, n_workers=n_workers or r.workers,
                    batch_size=batch_size)
    t2 = time.perf_counter()
    table = load_results(res.results)
    if gaps is None:
        gaps = bridge_needed_gaps(cases, table)
    result = analyse(cases, table, gaps)
    files = write_outputs(cases, result, figures=True if figures is None else figures)
    t3 = time.perf_counter()
    return FragilityOutcome(cases, res, result, files, t3 - start, t1 - t0, t3 - t2)
