"""Probability of pounding: incremental dynamic analysis, fragility curves, and the gap for
a target probability (``pounding fragility``, ``docs/fragility.md``).

A study scales every record of a suite to a series of intensity levels (PGA, Sa(T1) or the
average spectral acceleration over a period range), runs each case through the sweep
machinery (:mod:`pounding.studies.sweep`: on Dask, resumable, bit-identical) and answers:

* how the demands grow with the intensity — IDA curves per record and their 16/50/84 %
  fractiles (Vamvatsikos & Cornell 2002);
* how likely each limit state is at each intensity — lognormal fragility functions fitted by
  maximum likelihood to the counts at every stripe (Baker 2015) and from each record's IDA
  capacity, with bootstrap intervals over records (Efron 1979);
* how likely the two buildings are to pound with a given gap, and which gap brings that
  probability down to a target, beside the ABS / SRSS / DDC code gaps.

The modules, one concept each: :mod:`.fitting` (the fits: :func:`fit_lognormal_mle`),
:mod:`.ida` (IDA curves, capacities, fractiles), :mod:`.bootstrap` (intervals),
:mod:`.gap_probability` (P(pounding | gap) and the gap for a probability), :mod:`.study`
(the study file), :mod:`.cases` (the study's runs as a sweep), :mod:`.gaps` (the gaps the
records need), :mod:`.bridge` (a bridge's joints and seats: the seat width for a probability
of unseating), :mod:`.analysis` (the answers), :mod:`.outputs` (the folder) and
:mod:`.runner` (running it all).

Names are imported on first use (PEP 562): ``import pounding.studies.fragility.fitting``
(to fit a fragility curve) loads neither the sweep machinery nor the model, SciPy's
integrators or numba.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    "StudyCases": "pounding.studies.fragility.cases",
    "study_cases": "pounding.studies.fragility.cases",
    "censored_lognormal_mle": "pounding.studies.fragility.fitting",
    "fit_lognormal_mle": "pounding.studies.fragility.fitting",
    "ida_moments": "pounding.studies.fragility.fitting",
    "lognormal_cdf": "pounding.studies.fragility.fitting",
    "probit_mle": "pounding.studies.fragility.fitting",
    "empirical_gap": "pounding.studies.fragility.gap_probability",
    "gap_lognormal": "pounding.studies.fragility.gap_probability",
    "lognormal_gap": "pounding.studies.fragility.gap_probability",
    "pounding_probability": "pounding.studies.fragility.gap_probability",
    "pounding_probability_fit": "pounding.studies.fragility.gap_probability",
    "NeededGaps": "pounding.studies.fragility.gaps",
    "bridge_needed_gaps": "pounding.studies.fragility.gaps",
    "needed_gaps": "pounding.studies.fragility.gaps",
    "SeatWidths": "pounding.studies.fragility.bridge",
    "seat_widths": "pounding.studies.fragility.bridge",
    "capacities": "pounding.studies.fragility.ida",
    "exceedance_counts": "pounding.studies.fragility.ida",
    "ida_fractiles": "pounding.studies.fragility.ida",
    "FragilityOutcome": "pounding.studies.fragility.runner",
    "run_study": "pounding.studies.fragility.runner",
    "DEMANDS": "pounding.result.demands",
    "StudyConfig": "pounding.studies.fragility.study",
    "load_study": "pounding.studies.fragility.study",
    "parse_study": "pounding.studies.fragility.study",
}
"""Public name → the module that defines it."""


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.studies.fragility.cases import StudyCases, study_cases
    from pounding.studies.fragility.fitting import (
        censored_lognormal_mle,
        fit_lognormal_mle,
        ida_moments,
        lognormal_cdf,
        probit_mle,
    )
    from pounding.studies.fragility.gap_probability import (
        empirical_gap,
        gap_lognormal,
        lognormal_gap,
        pounding_probability,
        pounding_probability_fit,
    )
    from pounding.studies.fragility.bridge import SeatWidths, seat_widths
    from pounding.studies.fragility.gaps import NeededGaps, bridge_needed_gaps, needed_gaps
    from pounding.studies.fragility.ida import capacities, exceedance_counts, ida_fractiles
    from pounding.studies.fragility.runner import FragilityOutcome, run_study
    from pounding.result.demands import DEMANDS
    from pounding.studies.fragility.study import StudyConfig, load_study, parse_study

__all__ = [
    "DEMANDS",
    "FragilityOutcome",
    "NeededGaps",
    "SeatWidths",
    "StudyConfig",
    "StudyCases",
    "bridge_needed_gaps",
    "capacities",
    "censored_lognormal_mle",
    "empirical_gap",
    "exceedance_counts",
    "fit_lognormal_mle",
    "gap_lognormal",
    "ida_fractiles",
    "ida_moments",
    "load_study",
    "lognormal_cdf",
    "lognormal_gap",
    "needed_gaps",
    "parse_study",
    "pounding_probability",
    "pounding_probability_fit",
    "probit_mle",
    "run_study",
    "seat_widths",
    "study_cases",
]
