"""The bootstrap intervals of a fragility cover the truth about as often as they say, with
as few records as a suite has (the bundled suite: 9).

Suites of records are drawn from a known lognormal capacity; each suite's 90 % interval of
the median (from the capacities, and from the MLE on stripes of the same records) is
checked against the true median. The plain percentile interval covered it in about 85 % of
9-record suites (capacities) — too narrow — and the expanded percentile interval
(Hesterberg 2015) now used in about 90 %.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from pounding.studies.fragility.bootstrap import (
    expanded_confidence,
    fit_from_capacities,
    fit_from_stripes,
    percentile_interval,
    resample,
)

N_RECORDS = 9
TRIALS = 300
"""Suites drawn: the binomial standard deviation of a 90 % coverage is 1.7 %."""
THETA, BETA = 0.25, 0.35
LEVELS = np.geomspace(0.02, 1.0, 20)


def test_expanded_confidence_is_hesterbergs() -> None:
    # by hand: sqrt(9/8) t_8(0.95) = 1.06066 × 1.85955 = 1.97238; 2 Φ(1.97238) − 1 = 0.95143
    assert expanded_confidence(0.90, 9) == pytest.approx(0.95143, abs=2e-5)
    assert expanded_confidence(0.90, 10_000) == pytest.approx(0.90, abs=2e-4)
    assert expanded_confidence(0.90, 1) == 0.90


def test_nine_record_intervals_cover_the_median_about_90_percent_of_the_time() -> None:
    rng = np.random.default_rng(20261)
    plain = expanded_cap = expanded_stripes = 0
    for k in range(TRIALS):
        cap = np.exp(rng.normal(math.log(THETA), BETA, N_RECORDS))
        boot = resample(N_RECORDS, 400, k)
        est = fit_from_capacities(cap, np.zeros(N_RECORDS, bool), boot, 0.90)
        expanded_cap += est.median_ci[0] <= THETA <= est.median_ci[1]
        lo, hi = percentile_interval(est.medians, 0.90)
        plain += lo <= THETA <= hi
        exceed = (cap[:, None] <= LEVELS[None, :]).astype(float)
        est_s = fit_from_stripes(LEVELS, exceed, boot, 0.90)
        expanded_stripes += est_s.median_ci[0] <= THETA <= est_s.median_ci[1]
    # ±3 binomial standard deviations about 90 % (1.7 % each)
    assert 0.85 <= expanded_cap / TRIALS <= 0.95
    assert 0.84 <= expanded_stripes / TRIALS <= 0.95
    # the plain percentile interval runs short, by more than sampling error
    assert plain < expanded_cap
    assert stats.binomtest(plain, TRIALS, 0.90).pvalue < 0.05
