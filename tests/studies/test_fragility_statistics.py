"""The statistics of fragility studies against computations that share no code with them:
statsmodels' binomial GLM with a probit link, SciPy's general optimiser on likelihoods
written out here, closed forms, hand counts, and synthetic lognormal data."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from scipy import stats
from scipy.optimize import minimize

from pounding.studies.fragility import (
    capacities,
    censored_lognormal_mle,
    empirical_gap,
    exceedance_counts,
    fit_lognormal_mle,
    gap_lognormal,
    ida_fractiles,
    ida_moments,
    lognormal_cdf,
    lognormal_gap,
    pounding_probability,
    pounding_probability_fit,
    probit_mle,
)
from pounding.studies.fragility import fitting
from pounding.studies.fragility.bootstrap import (
    fit_from_capacities,
    fit_from_stripes,
    percentile_interval,
    resample,
)

# Baker's example of multiple-stripe data (8 levels of Sa [g], 40 ground motions each, the
# number of collapses at each): the data set of the example of his fn_mle_pc MATLAB function
# for Baker, J. W. (2015), "Efficient analytical fragility function fitting using dynamic
# structural analysis", Earthquake Spectra 31(1), 579-599, as found in a public port of that
# example. The paper's own estimates for it could not be found in the material searched, so
# the fit is checked against two independent maximisations of the same likelihood.
BAKER_IM = [0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0]
BAKER_N = 40
BAKER_Z = [0, 0, 0, 4, 6, 13, 12, 16]


def _statsmodels_probit(im, n, z):
    import statsmodels.api as sm  # the test extra installs it: a missing one is a failure

    x = sm.add_constant(np.log(np.asarray(im, dtype=float)))
    n = np.broadcast_to(np.asarray(n, dtype=float), np.shape(z))
    y = np.column_stack([z, n - np.asarray(z, dtype=float)])
    res = sm.GLM(y, x, family=sm.families.Binomial(link=sm.families.links.Probit())).fit(
        tol=1e-14, maxiter=200)
    c0, c1 = res.params
    return math.exp(-c0 / c1), 1.0 / c1


def _scipy_binomial(im, n, z):
    im, z = np.asarray(im, dtype=float), np.asarray(z)

    def nll(p):
        if p[1] <= 0:
            return np.inf
        return -np.sum(stats.binom.logpmf(z, n, stats.norm.cdf(np.log(im / p[0]) / p[1])))

    r = minimize(nll, [np.median(im), 0.4], method="Nelder-Mead",
                 options={"xatol": 1e-11, "fatol": 1e-13, "maxiter": 20000})
    return r.x


def test_baker_example_against_statsmodels_and_scipy():
    theta, beta = fit_lognormal_mle(BAKER_IM, BAKER_N, BAKER_Z)
    t_sm, b_sm = _statsmodels_probit(BAKER_IM, BAKER_N, BAKER_Z)
    t_sp, b_sp = _scipy_binomial(BAKER_IM, BAKER_N, BAKER_Z)
    assert theta == pytest.approx(t_sm, rel=1e-7) and beta == pytest.approx(b_sm, rel=1e-7)
    assert theta == pytest.approx(t_sp, rel=1e-6) and beta == pytest.approx(b_sp, rel=1e-6)
    assert (round(theta, 4), round(beta, 4)) == (1.0761, 0.4292)


def _random_stripes(seed: int):
    rng = np.random.default_rng(seed)
    k = int(rng.integers(4, 12))
    im = np.sort(rng.uniform(0.05, 2.0, k))
    n = rng.integers(5, 50, k)
    z = rng.binomial(n, stats.norm.cdf(np.log(im / rng.uniform(0.3, 1.5)) / rng.uniform(0.2,
                                                                                          0.8)))
    return im, n, z


def _overlap(im, n, z) -> bool:
    """A finite MLE exists iff the data overlap: some level with an exceedance lies strictly
    below some level with a run that does not exceed; otherwise the data are (quasi-)
    completely separated and the likelihood grows without bound as β → 0 (Albert & Anderson
    1984)."""
    return bool(np.min(im[z > 0]) < np.max(im[n - z > 0]))


@pytest.mark.parametrize("seed", range(6))
def test_random_stripes_against_statsmodels(seed):
    im, n, z = _random_stripes(seed)
    assert _overlap(im, n, z)  # these draws were chosen to have a finite MLE
    med, beta, status = probit_mle(im, n, z)
    assert status[0] == fitting.FIT_OK
    t_sm, b_sm = _statsmodels_probit(im, n, z)
    assert med[0] == pytest.approx(t_sm, rel=1e-6) and beta[0] == pytest.approx(b_sm, rel=1e-6)


def test_a_random_draw_without_a_finite_mle_is_reported_as_separated():
    """Seed 9 draws 7 stripes where every run exceeds but one of the 44 at the lowest level:
    no level with an exceedance lies below one with a run that does not (quasi-complete
    separation), so there is no finite MLE: status FIT_SEPARATED, β = 0 and θ at that level,
    and fit_lognormal_mle refuses the data in one line."""
    im, n, z = _random_stripes(9)
    assert not _overlap(im, n, z)
    assert list(n - z) == [1, 0, 0, 0, 0, 0, 0]
    med, beta, status = probit_mle(im, n, z)
    assert status[0] == fitting.FIT_SEPARATED and beta[0] == 0.0
    assert med[0] == pytest.approx(im[0], rel=1e-12)
    with pytest.raises(ValueError, match="separated"):
        fit_lognormal_mle(im, n, z)


def test_mle_recovers_a_known_lognormal_within_sampling_error():
    theta, beta = 0.6, 0.35
    im = np.array([0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 1.0, 1.2, 1.5])
    rng = np.random.default_rng(7)
    n = 400
    z = rng.binomial(n, stats.norm.cdf(np.log(im / theta) / beta))
    t, b = fit_lognormal_mle(im, n, z)
    # standard errors from the Fisher information of the probit GLM (4000 runs): ~1 %, ~4 %
    assert abs(math.log(t / theta)) < 0.03 and abs(b / beta - 1.0) < 0.10


def test_degenerate_counts_are_refused_in_one_line():
    with pytest.raises(ValueError, match="no run exceeds"):
        fit_lognormal_mle([0.1, 0.2], 10, [0, 0])
    with pytest.raises(ValueError, match="every run exceeds"):
        fit_lognormal_mle([0.1, 0.2], 10, [10, 10])
    with pytest.raises(ValueError, match="separated"):
        fit_lognormal_mle([0.1, 0.2, 0.3], 10, [0, 4, 10])
    with pytest.raises(ValueError, match="n_exceed: more exceedances than runs"):
        fit_lognormal_mle([0.1, 0.2], 10, [0, 11])
    with pytest.raises(ValueError, match="im: every level must be a positive number"):
        fit_lognormal_mle([0.0, 0.2], 10, [0, 1])
    med, beta, status = probit_mle([0.1, 0.2, 0.3], 10, [[0, 4, 10], [0, 0, 0], [10, 10, 10]])
    assert list(status) == [fitting.FIT_SEPARATED, fitting.FIT_NONE, fitting.FIT_ALL]
    assert med[0] == pytest.approx(0.2) and beta[0] == 0.0
    assert math.isinf(med[1]) and med[2] == 0.0


def test_lognormal_cdf_limits():
    assert lognormal_cdf(0.5, 0.5, 0.3) == pytest.approx(0.5)
    assert lognormal_cdf(1.0, 0.5, 0.3) == pytest.approx(stats.norm.cdf(math.log(2) / 0.3))
    assert list(lognormal_cdf([0.4, 0.5, 0.6], 0.5, 0.0)) == [0.0, 0.5, 1.0]
    assert lognormal_cdf(10.0, np.inf, 0.3) == 0.0 and lognormal_cdf(1e-3, 0.0, 0.3) == 1.0


# ----------------------------------------------------------------------- IDA capacities
def test_ida_moments_are_baker_eqs_4_and_5():
    c = [0.31, 0.45, 0.52, 0.6, 0.88]
    t, b = ida_moments(c)
    assert t == pytest.approx(stats.gmean(c), rel=1e-14)
    assert b == pytest.approx(np.std(np.log(c), ddof=1), rel=1e-14)


def test_censored_mle_against_scipy():
    rng = np.random.default_rng(3)
    v = np.exp(rng.normal(math.log(0.5), 0.4, 12))
    cen = v > 0.65
    v = np.where(cen, 0.65, v)
    y = np.log(v)

    def nll(p):
        if p[1] <= 0:
            return np.inf
        return -(stats.norm.logpdf(y[~cen], p[0], p[1]).sum()
                 + stats.norm.logsf(y[cen], p[0], p[1]).sum())

    ref = minimize(nll, [y.mean(), y.std()], method="Nelder-Mead",
                   options={"xatol": 1e-11, "fatol": 1e-13, "maxiter": 20000}).x
    med, beta, status = censored_lognormal_mle(v, cen)
    assert cen.sum() >= 2 and status[0] == fitting.FIT_OK
    assert math.log(med[0]) == pytest.approx(ref[0], abs=1e-7)
    assert beta[0] == pytest.approx(ref[1], rel=1e-6)
    # no censoring: the moments (n - 1)
    m2, b2, _ = censored_lognormal_mle([0.3, 0.5, 0.7], [False] * 3)
    assert (m2[0], b2[0]) == pytest.approx(ida_moments([0.3, 0.5, 0.7]), rel=1e-14)
    m3, _, s3 = censored_lognormal_mle([1.0, 1.0], [True, True])
    assert math.isinf(m3[0]) and s3[0] == fitting.FIT_NONE


def test_capacities_by_hand():
    levels = [0.1, 0.2, 0.3, 0.4]
    edp = [[0.002, 0.004, 0.008, 0.012],     # crosses 0.005 between 0.2 and 0.3
           [0.007, 0.009, 0.011, 0.02],      # above at the first level: from (0, 0)
           [0.001, 0.002, 0.003, 0.004],     # never: censored at 0.4
           [0.002, np.nan, 0.006, 0.009]]    # a failed run is left out of the curve
    cap, cen = capacities(levels, edp, 0.005)
    assert cap[0] == pytest.approx(0.2 + (0.005 - 0.004) / (0.008 - 0.004) * 0.1)
    assert cap[1] == pytest.approx(0.1 * 0.005 / 0.007)
    assert cap[2] == 0.4 and cen[2] and not cen[0]
    assert cap[3] == pytest.approx(0.1 + (0.005 - 0.002) / (0.006 - 0.002) * 0.2)
    b, bc = capacities(levels, [[0, 0, 1, 1], [0, 1, 0, 1], [0, 0, 0, 0]], 0.5, binary=True)
    assert list(b) == [0.3, 0.2, 0.4] and list(bc) == [False, False, True]
    n, z = exceedance_counts([[0, 1, np.nan], [1, 1, 1]])
    assert list(n) == [2, 2, 1] and list(z) == [1, 2, 1]


def test_fractiles_are_numpys_type_7_per_stripe():
    rng = np.random.default_rng(0)
    e = rng.lognormal(size=(10, 4))
    e[3, 2] = np.nan
    f = ida_fractiles(e)
    for j in range(4):
        col = e[:, j][np.isfinite(e[:, j])]
        assert list(f[:, j]) == pytest.approx(list(np.quantile(col, [0.16, 0.5, 0.84])))
    # 10 records: (n - 1) q = 1.44, so the 16 % fractile is 44 % of the way from the 2nd
    # to the 3rd smallest demand
    s = np.sort(e[:, 0])
    assert f[0, 0] == pytest.approx(s[1] + 0.44 * (s[2] - s[1]))


# ----------------------------------------------------------------------- bootstrap
def test_bootstrap_is_reproducible_with_its_seed():
    rng = np.random.default_rng(11)
    levels = np.array([0.1, 0.2, 0.3, 0.4, 0.5])
    cap = rng.lognormal(math.log(0.3), 0.3, 10)
    exceed = (cap[:, None] < levels[None, :]).astype(float)
    a = fit_from_stripes(levels, exceed, resample(10, 300, 5))
    b = fit_from_stripes(levels, exceed, resample(10, 300, 5))
    c = fit_from_stripes(levels, exceed, resample(10, 300, 6))
    grid = np.linspace(0.05, 0.6, 30)
    assert np.array_equal(a.band(grid)[0], b.band(grid)[0]) and a.median_ci == b.median_ci
    assert a.median_ci != c.median_ci
    assert a.median_ci[0] <= a.median <= a.median_ci[1]


def test_bootstrap_intervals_cover_the_truth_about_as_often_as_they_say():
    # 200 synthetic suites of 20 records from a known lognormal; 90 % percentile intervals
    # of the IDA median should cover it in about 90 % of them (binomial sd 2 %; the
    # percentile interval of a median from 20 records runs a little short)
    theta, beta = 0.4, 0.35
    rng = np.random.default_rng(2024)
    hits = 0
    trials = 200
    for k in range(trials):
        cap = np.exp(rng.normal(math.log(theta), beta, 20))
        est = fit_from_capacities(cap, np.zeros(20, bool), resample(20, 400, k), 0.90)
        hits += est.median_ci[0] <= theta <= est.median_ci[1]
    assert 0.80 <= hits / trials <= 0.97


def test_percentile_interval_is_made_of_order_statistics():
    v = np.arange(1.0, 101.0)
    assert percentile_interval(v, 0.90) == (5.0, 95.0)
    lo, hi = percentile_interval(np.r_[v, np.inf, np.nan], 0.98)
    assert (lo, hi) == (2.0, 100.0)


# ----------------------------------------------------------------------- gap
def test_pounding_probability_by_hand_count():
    needed = np.array([0.12, 0.30, 0.18, 0.25, 0.09])
    p = pounding_probability(needed, [0.0, 0.1, 0.18, 0.2, 0.3])
    # > 0: all 5; > 0.1: 4 (not 0.09); > 0.18: 2 (0.30, 0.25; 0.18 itself is not above)
    assert list(p) == [1.0, 0.8, 0.4, 0.4, 0.0]
    # the gap for 20 %: at most 1 of 5 records may exceed it -> the 4th smallest
    assert empirical_gap(needed, 0.2) == 0.25
    assert empirical_gap(needed, 0.1) == 0.30   # below 1/n: the largest
    assert empirical_gap(np.linspace(0.1, 1.0, 10), 0.1) == pytest.approx(0.9)
    t, b = gap_lognormal(needed)
    assert t == pytest.approx(stats.gmean(needed)) and b == pytest.approx(
        np.std(np.log(needed), ddof=1))
    assert lognormal_gap(t, b, 0.1) == pytest.approx(
        stats.lognorm.ppf(0.9, b, scale=t), rel=1e-12)
    assert pounding_probability_fit(t, b, [lognormal_gap(t, b, 0.1)])[0] == pytest.approx(0.1)
    assert math.isnan(gap_lognormal([0.0, 0.1])[0])


def test_docstring_example():
    failures, tried = doctest.testmod(fitting, verbose=False)
    assert tried >= 2 and failures == 0


def test_no_resamples_gives_no_interval() -> None:
    """``[bootstrap] n = 0`` (documented: no intervals): the percentile interval of zero
    resamples is NaN, for one quantity and for a curve (it used to fail reshaping an empty
    array, and the study with it)."""
    from pounding.studies.fragility.bootstrap import percentile_interval

    lo, hi = percentile_interval(np.zeros(0))
    assert np.isnan(lo) and np.isnan(hi)
    lo, hi = percentile_interval(np.zeros((0, 5)))
    assert lo.shape == hi.shape == (5,) and np.all(np.isnan(lo)) and np.all(np.isnan(hi))
    lo, hi = percentile_interval(np.array([[1.0, 2.0], [3.0, 4.0]]), 0.5)
    assert lo.tolist() == [1.0, 2.0] and hi.tolist() == [3.0, 4.0]


def test_counts_without_a_trend_are_no_fit() -> None:
    """The same fraction at every level (8 of 9 records pound at every level: one record
    never does): the likelihood's maximum is at β → ∞, θ → 0, so there is no fragility.
    It used to be reported as fitted (θ = 1e-300 g, β = 9e15; overflow warnings printed by
    the study); now it is not fitted, in one line, without a warning."""
    import warnings

    from pounding.studies.fragility.fitting import FIT_FAILED, MAX_BETA, probit_mle

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        med, beta, status = probit_mle([0.25, 0.5, 1.0], [9, 9, 9], [[8, 8, 8], [3, 3, 3]])
    assert status.tolist() == [FIT_FAILED, FIT_FAILED] and np.isnan(med).all()
    with pytest.raises(ValueError, match=r"^n_exceed: the likelihood could not be maximised, "
                                         r"or the counts show no trend with the intensity"):
        fit_lognormal_mle([0.25, 0.5, 1.0], 9, [8, 8, 8])
    # a shallow but real trend is still fitted (β below the bound)
    theta, beta = fit_lognormal_mle([0.1, 1.0, 10.0, 100.0], 100, [20, 35, 52, 68])
    assert 1.0 < beta < MAX_BETA and 1.0 < theta < 100.0
