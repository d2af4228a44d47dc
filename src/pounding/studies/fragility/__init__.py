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
(the study file), :mod:`.plan` (the study as a sweep), :mod:`.runner` (running it; the gaps
the records need), :mod:`.analysis` (the answers) and :mod:`.outputs` (the folder).
"""

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
from pounding.studies.fragility.ida import capacities, exceedance_counts, ida_fractiles
from pounding.studies.fragility.plan import StudyPlan, plan_study
from pounding.studies.fragility.runner import FragilityOutcome, NeededGaps, needed_gaps, run_study
from pounding.studies.fragility.study import DEMANDS, StudyConfig, load_study, parse_study

__all__ = [
    "DEMANDS",
    "FragilityOutcome",
    "NeededGaps",
    "StudyConfig",
    "StudyPlan",
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
    "plan_study",
    "pounding_probability",
    "pounding_probability_fit",
    "probit_mle",
    "run_study",
]
