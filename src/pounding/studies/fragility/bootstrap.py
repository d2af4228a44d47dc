"""Confidence in a fragility fit: the nonparametric bootstrap over records.

The records of a suite are the sample; everything computed from them — counts of
exceedance at every stripe, capacities, needed gaps — is recomputed for ``B`` resamples of
the records drawn with replacement, and the spread of the estimates gives percentile
intervals (Efron, B. (1979). Bootstrap methods: another look at the jackknife. *Ann.
Statist.* 7(1), 1–26; Efron & Tibshirani (1993), *An Introduction to the Bootstrap*, ch. 13:
the percentile interval). Resampling records, not runs, keeps each record's runs at every
level together, as they are correlated (the same record scaled).

With the few records of a suite the plain percentile interval is too narrow: its spread is
that of a sample of n divided by n rather than n − 1, and it takes normal quantiles where
Student's t applies. Measured by simulation (records drawn from a known lognormal, 300 suites,
1000 resamples), a nominal 90 % interval of the median covered the truth in 85 % of suites
of 9 or 10 records (capacities) and in 78–86 % (the MLE on stripes). The intervals are
therefore *expanded percentile intervals* (Hesterberg, T. C. (2015). What teachers should
know about the bootstrap: resampling in the undergraduate statistics curriculum. *The
American Statistician* 69(4), 371–386): the percentiles of a wider nominal confidence
``c' = 2 Φ(sqrt(n/(n − 1)) t_{n−1}((1 + c)/2)) − 1`` (:func:`expanded_confidence`; 95.1 %
for 90 % at n = 9), which covered the truth in 91 % (capacities) and 84–91 % (stripes) of
the same suites; at 20 records 89 % and 88–90 %.

The resamples are drawn from ``numpy.random.Generator(PCG64(seed))``: the same seed gives
the same intervals, on any machine.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.studies.fragility.fitting import (
    FIT_OK,
    FIT_SEPARATED,
    censored_lognormal_mle,
    lognormal_cdf,
    probit_mle,
)
from pounding.studies.fragility.ida import exceedance_counts

__all__ = ["DEFAULT_BOOT", "DEFAULT_CONFIDENCE", "DEFAULT_SEED", "FragilityEstimate",
           "expanded_confidence", "fit_from_capacities", "fit_from_stripes",
           "percentile_interval", "resample"]

FloatArray = NDArray[np.float64]

DEFAULT_BOOT = 1000
"""Bootstrap resamples unless told otherwise (Efron & Tibshirani 1993 suggest ≥ 1000 for
percentile intervals)."""

DEFAULT_SEED = 2015
"""Seed of the resampling unless told otherwise."""

DEFAULT_CONFIDENCE = 0.90
"""Two-sided confidence of the intervals and bands unless told otherwise."""


def resample(n_records: int, n_boot: int = DEFAULT_BOOT, seed: int = DEFAULT_SEED
             ) -> NDArray[np.int64]:
    """Indices of ``n_boot`` resamples of ``n_records`` records drawn with replacement,
    shape (n_boot, n_records), from PCG64 seeded with ``seed``."""
    gen = np.random.Generator(np.random.PCG64(int(seed)))
    return gen.integers(0, int(n_records), size=(int(n_boot), int(n_records)))


def expanded_confidence(confidence: float, n_records: int) -> float:
    """The nominal confidence whose percentile interval has about ``confidence`` coverage
    with ``n_records`` records: ``2 Φ(sqrt(n/(n − 1)) t_{n−1}((1 + c)/2)) − 1`` (Hesterberg
    2015, the expanded percentile interval; module docstring). ``confidence`` itself for
    fewer than 2 records (no t quantile).

    Examples
    --------
    >>> round(expanded_confidence(0.90, 9), 4)
    0.9514
    """
    from scipy import stats

    c = float(confidence)
    n = int(n_records)
    if n < 2:
        return c
    z = np.sqrt(n / (n - 1.0)) * stats.t.ppf((1.0 + c) / 2.0, n - 1)
    return float(2.0 * stats.norm.cdf(z) - 1.0)


def percentile_interval(values: ArrayLike, confidence: float = DEFAULT_CONFIDENCE,
                        axis: int = 0) -> tuple[FloatArray, FloatArray]:
    """The percentile interval: the ``(1 − c)/2`` and ``(1 + c)/2`` empirical quantiles
    (inverted CDF: order statistics, so infinite values are kept as they are) of the
    finite-or-infinite values along ``axis``; NaN values (fits that failed) are left out."""
    a = np.asarray(values, dtype=float)
    a = np.moveaxis(a, axis, 0)
    lo_q, hi_q = (1.0 - confidence) / 2.0, (1.0 + confidence) / 2.0
    lo = np.full(a.shape[1:], np.nan)
    hi = np.full(a.shape[1:], np.nan)
    # (no resamples at all, [bootstrap] n = 0: every interval NaN)
    flat = a.reshape(a.shape[0], int(np.prod(a.shape[1:], dtype=np.int64)))
    for k in range(flat.shape[1]):
        col = flat[:, k]
        col = col[~np.isnan(col)]
        if col.size:
            lo.reshape(-1)[k] = np.quantile(col, lo_q, method="inverted_cdf")
            hi.reshape(-1)[k] = np.quantile(col, hi_q, method="inverted_cdf")
    return lo, hi


@dataclass(frozen=True)
class FragilityEstimate:
    """A lognormal fragility with its bootstrap intervals.

    Attributes
    ----------
    median, beta : float
        θ [IM units] and β of the fit to all records (see :mod:`.fitting` for the limits:
        ``median = inf`` never exceeded, ``beta = 0`` separated data).
    status : int
        :data:`~pounding.studies.fragility.fitting.FIT_OK` and the others.
    median_ci, beta_ci : (float, float)
        Expanded percentile intervals over the bootstrap resamples (percentiles at
        :func:`expanded_confidence` of ``confidence`` and ``n_records``).
    medians, betas : ndarray, shape (n_boot,)
        The bootstrap estimates (for bands).
    n_records : int
        Records with at least one successful run.
    n_failed_boot : int
        Resamples whose fit failed (left out of the intervals).
    confidence : float
        The coverage asked for (the percentiles taken are those of
        :func:`expanded_confidence`).
    """

    median: float
    beta: float
    status: int
    median_ci: tuple[float, float]
    beta_ci: tuple[float, float]
    medians: FloatArray
    betas: FloatArray
    n_records: int
    n_failed_boot: int
    confidence: float

    def probability(self, im: ArrayLike) -> FloatArray:
        """The fitted fragility ``Φ(ln(im/θ)/β)`` at ``im``."""
        return lognormal_cdf(im, self.median, self.beta)

    def band(self, im: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Pointwise expanded percentile band of the bootstrap fragilities at ``im`` (the
        curves of every resample evaluated there)."""
        x = np.atleast_1d(np.asarray(im, dtype=float))
        curves = lognormal_cdf(x[None, :], self.medians[:, None], self.betas[:, None])
        return percentile_interval(curves, expanded_confidence(self.confidence,
                                                               self.n_records), axis=0)


def _estimate(med: FloatArray, beta: FloatArray, status: NDArray[np.int64], n_records: int,
              confidence: float) -> FragilityEstimate:
    """Row 0 is the fit to all records, the others the resamples."""
    bm, bb, bs = med[1:], beta[1:], status[1:]
    failed = ~np.isin(bs, (FIT_OK, FIT_SEPARATED)) & np.isnan(bm)
    wide = expanded_confidence(confidence, n_records)
    m_lo, m_hi = percentile_interval(np.where(failed, np.nan, bm), wide)
    b_lo, b_hi = percentile_interval(np.where(failed | np.isnan(bb), np.nan, bb), wide)
    return FragilityEstimate(float(med[0]), float(beta[0]), int(status[0]),
                             (float(m_lo), float(m_hi)), (float(b_lo), float(b_hi)),
                             np.where(failed, np.nan, bm), bb, n_records, int(failed.sum()),
                             float(confidence))


def fit_from_stripes(levels: ArrayLike, exceed: ArrayLike, boot: NDArray[np.int64],
                     confidence: float = DEFAULT_CONFIDENCE) -> FragilityEstimate:
    """The MLE fragility of the counts at every stripe (Baker 2015, eq. 11), for all
    records and for each bootstrap resample of them.

    Parameters
    ----------
    levels : array_like, shape (n_levels,)
        Intensities of the stripes.
    exceed : array_like, shape (n_records, n_levels)
        1 where the run exceeded the limit state, 0 where not, NaN where it failed.
    boot : ndarray of int, shape (n_boot, n_records)
        Resamples (:func:`resample`).
    """
    e = np.asarray(exceed, dtype=float)
    n_all, z_all = exceedance_counts(e)
    ok = np.isfinite(e)
    n_b = ok[boot].sum(axis=1)
    z_b = np.where(ok, e, 0.0)[boot].sum(axis=1)
    n = np.vstack([n_all[None, :], n_b])
    z = np.vstack([z_all[None, :], z_b])
    med, beta, status = probit_mle(levels, n, z)
    return _estimate(med, beta, status, int(ok.any(axis=1).sum()), confidence)


def fit_from_capacities(capacity: ArrayLike, censored: ArrayLike, boot: NDArray[np.int64],
                        confidence: float = DEFAULT_CONFIDENCE) -> FragilityEstimate:
    """The IDA fragility of the records' capacities (moments of ln IM, Baker 2015 eqs.
    4–5; with right-censoring by MLE: :func:`censored_lognormal_mle`), for all records and
    for each bootstrap resample.

    Parameters
    ----------
    capacity, censored : array_like, shape (n_records,)
        From :func:`pounding.studies.fragility.ida.capacities`; every capacity finite
        (leave out records without a successful run before resampling).
    boot : ndarray of int, shape (n_boot, n_records)
    """
    c = np.asarray(capacity, dtype=float)
    cen = np.asarray(censored, dtype=bool)
    if not np.all(np.isfinite(c)):
        raise ValueError("capacity: every record needs a capacity (leave out records "
                         "without a successful run)")
    vals = np.vstack([c[None, :], c[boot]])
    cens = np.vstack([cen[None, :], cen[boot]])
    med, beta, status = censored_lognormal_mle(vals, cens)
    return _estimate(med, beta, status, int(c.size), confidence)
