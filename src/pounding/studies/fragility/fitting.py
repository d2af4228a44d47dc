"""Lognormal fragility functions fitted to dynamic-analysis results.

A fragility function is the probability that a limit state is exceeded at intensity ``x``,
taken lognormal (Baker 2015, eq. 1)::

    P(LS | IM = x) = Φ( ln(x / θ) / β ),

with median ``θ`` (in the units of the intensity measure) and dispersion ``β``. Two fits:

* **from stripes** (multiple-stripe analysis, or the stripes of an IDA):
  :func:`fit_lognormal_mle` maximises the binomial likelihood of the counts ``z_j`` of
  exceedance among ``n_j`` runs at each level ``x_j`` (Baker 2015, eqs. 10–11)::

      ln L = Σ_j [ ln C(n_j, z_j) + z_j ln Φ(ln(x_j/θ)/β) + (n_j − z_j) ln(1 − Φ(ln(x_j/θ)/β)) ].

  Written with ``c0 = −ln θ / β`` and ``c1 = 1/β`` this is the log-likelihood of a binomial
  GLM with probit link on ``ln x``, which is concave in ``(c0, c1)``: Newton's method with
  step halving finds its unique maximum (:func:`probit_mle`, vectorised over bootstrap
  samples). The MLE does not exist where the data are separated (every exceedance at a
  higher level than every non-exceedance): then ``β → 0`` and only an interval for ``θ`` is
  known, which :func:`probit_mle` reports by its status.

* **from IDA** (the intensity at which each record first exceeds the limit, its
  *capacity*): the capacities are taken lognormal; with every record exceeding the limit
  within the levels run, ``ln θ`` is the mean of ``ln IM_i`` and ``β`` their standard
  deviation (Baker 2015, eqs. 4–5, ``n − 1`` in the denominator); records that never
  exceed it are right-censored at the highest level and the normal likelihood of
  ``ln IM`` with censoring is maximised instead (:func:`censored_lognormal_mle`; Tobit
  model in Olsen's (1978) parameters ``(μ/σ, 1/σ)``, in which it is concave).

References
----------
Baker, J. W. (2015). Efficient analytical fragility function fitting using dynamic
structural analysis. *Earthquake Spectra* 31(1), 579–599. doi:10.1193/021113EQS025M.
Olsen, R. J. (1978). Note on the uniqueness of the maximum likelihood estimator for the
Tobit model. *Econometrica* 46(5), 1211–1215.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["FIT_OK", "FIT_NONE", "FIT_ALL", "FIT_SEPARATED", "FIT_FAILED", "MAX_BETA",
           "censored_lognormal_mle", "fit_lognormal_mle", "ida_moments", "lognormal_cdf",
           "probit_mle"]

FloatArray = NDArray[np.float64]

FIT_OK, FIT_NONE, FIT_ALL, FIT_SEPARATED, FIT_FAILED = 0, 1, 2, 3, 4
"""Status of a fit: fitted; no run exceeds (θ above every level: +inf); every run exceeds
(θ below every level: 0); separated data (β → 0, θ between the two levels that separate
them); not fitted (too few data, no trend with the intensity, or the iteration did not
converge)."""

_MAX_ITER = 200
_TOL = 1e-12

MAX_BETA = 10.0
"""The largest β of a fit on the stripes: beyond it the counts show no trend with the
intensity (a fraction about the same at every level: over a factor 10 of the intensity the
fitted probability moves by less than Φ(ln 10/20) − Φ(−ln 10/20) = 0.092), whose maximum
of the likelihood lies at β → ∞ with θ → 0 or ∞; such a fit is :data:`FIT_FAILED`, not a
median and a β that mean nothing."""


def lognormal_cdf(x: ArrayLike, median: ArrayLike, beta: ArrayLike) -> FloatArray:
    """``Φ(ln(x/θ)/β)``, also at the limits: ``θ = inf`` → 0, ``θ = 0`` → 1, ``β = 0`` → a
    step at ``θ`` (½ at ``x = θ``); NaN where ``θ`` or ``β`` is NaN.

    Parameters
    ----------
    x : array_like
        Intensities (> 0), broadcast against ``median`` and ``beta``.
    median, beta : array_like
        θ (≥ 0, may be inf) and β (≥ 0).
    """
    from scipy.special import ndtr

    x = np.asarray(x, dtype=float)
    th = np.asarray(median, dtype=float)
    b = np.asarray(beta, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        lx = np.log(x)
        lt = np.log(th)
        step = np.where(lx > lt, 1.0, np.where(lx < lt, 0.0, 0.5))
        smooth = ndtr((lx - lt) / np.where(b > 0, b, 1.0))
        out = np.where(b > 0, smooth, step)
    out = np.where(np.isposinf(th), 0.0, np.where(th == 0.0, 1.0, out))
    return np.where(np.isnan(th) | np.isnan(b), np.nan, out)


# ============================================================================ stripes (MLE)
def _probit_terms(eta: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """``ln Φ(η)``, ``ln Φ(−η)`` and the inverse Mills ratios ``φ/Φ(η)``, ``φ/Φ(−η)``,
    computed in logs so that they hold far in the tails."""
    from scipy.special import log_ndtr

    lp, lq = log_ndtr(eta), log_ndtr(-eta)
    lphi = -0.5 * eta * eta - 0.5 * np.log(2.0 * np.pi)
    return lp, lq, np.exp(lphi - lp), np.exp(lphi - lq)


def _binomial_loglik(c0: FloatArray, c1: FloatArray, x: FloatArray, n: FloatArray,
                     z: FloatArray) -> FloatArray:
    eta = c0[:, None] + c1[:, None] * x[None, :]
    lp, lq, _, _ = _probit_terms(eta)
    return np.sum(np.where(z > 0, z * lp, 0.0) + np.where(n - z > 0, (n - z) * lq, 0.0), axis=1)


def probit_mle(im: ArrayLike, n_runs: ArrayLike, n_exceed: ArrayLike
               ) -> tuple[FloatArray, FloatArray, NDArray[np.int64]]:
    """Maximum-likelihood lognormal fragility from counts at stripes, for many data sets.

    The binomial likelihood of Baker (2015, eq. 11) maximised over ``(c0, c1) = (−ln θ/β,
    1/β)`` by Newton's method with step halving (the log-likelihood is concave there, so the
    maximum found is the maximum). Rows are independent data sets (e.g. bootstrap samples).

    Parameters
    ----------
    im : array_like, shape (k,)
        Intensity levels (> 0).
    n_runs, n_exceed : array_like, shape (k,) or (m, k)
        Runs and exceedances at each level (``0 ≤ n_exceed ≤ n_runs``; a level with no run
        is ignored).

    Returns
    -------
    median, beta : ndarray, shape (m,)
        θ [IM units] and β; for a status other than :data:`FIT_OK`: ``(inf, nan)`` no
        exceedance, ``(0, nan)`` all exceed, ``(θ*, 0)`` separated data with ``θ*`` the
        geometric mean of the two levels that separate them, ``(nan, nan)`` failed (or no
        trend with the intensity: β beyond :data:`MAX_BETA`).
    status : ndarray of int, shape (m,)
        :data:`FIT_OK`, :data:`FIT_NONE`, :data:`FIT_ALL`, :data:`FIT_SEPARATED` or
        :data:`FIT_FAILED`.
    """
    x = np.log(np.asarray(im, dtype=float))
    n = np.atleast_2d(np.asarray(n_runs, dtype=float))
    z = np.atleast_2d(np.asarray(n_exceed, dtype=float))
    n, z = np.broadcast_arrays(n, z)
    m = n.shape[0]
    med = np.full(m, np.nan)
    beta = np.full(m, np.nan)
    status = np.full(m, FIT_FAILED, dtype=np.int64)
    inf = np.inf
    # separation: every exceedance at or above every non-exceedance → no finite MLE
    x_exc = np.where(z > 0, x[None, :], inf).min(axis=1)
    x_non = np.where(n - z > 0, x[None, :], -inf).max(axis=1)
    none = z.sum(axis=1) == 0
    every = (n - z).sum(axis=1) == 0
    sep = (x_exc >= x_non) & ~none & ~every
    med[none], status[none] = inf, FIT_NONE
    med[every], status[every] = 0.0, FIT_ALL
    med[sep] = np.exp(0.5 * (x_exc[sep] + x_non[sep]))
    beta[sep], status[sep] = 0.0, FIT_SEPARATED
    todo = ~(none | every | sep)
    if todo.any():
        c0, c1, ok = _newton_probit(x, n[todo], z[todo])
        trend = ok & (c1 > 1.0 / MAX_BETA)  # (no trend: β → ∞, :data:`MAX_BETA`)
        b = np.where(trend, 1.0 / np.where(trend, c1, 1.0), np.nan)
        with np.errstate(over="ignore"):
            t = np.where(trend, np.exp(-c0 * b), np.nan)
        med[todo], beta[todo] = t, b
        status[todo] = np.where(np.isfinite(b), FIT_OK, FIT_FAILED)
    return med, beta, status


def _newton_probit(x: FloatArray, n: FloatArray, z: FloatArray
                   ) -> tuple[FloatArray, FloatArray, NDArray[np.bool_]]:
    """Newton's method on the probit log-likelihood, vectorised over the rows."""
    from scipy.special import ndtri

    # start: weighted least squares of probit((z + ½)/(n + 1)) on ln x
    y = ndtri((z + 0.5) / (n + 1.0))
    sw = n.sum(axis=1)
    xm = (n * x).sum(axis=1) / sw
    ym = (n * y).sum(axis=1) / sw
    sxx = (n * (x - xm[:, None]) ** 2).sum(axis=1)
    sxy = (n * (x - xm[:, None]) * (y - ym[:, None])).sum(axis=1)
    c1 = np.where(sxx > 0, sxy / np.where(sxx > 0, sxx, 1.0), 1.0)
    c1 = np.where(c1 > 0.1, c1, 2.5)

    def derivatives(c0: FloatArray, c1: FloatArray) -> tuple[FloatArray, ...]:
        eta = c0[:, None] + c1[:, None] * x[None, :]
        _, _, a, b = _probit_terms(eta)
        g = z * a - (n - z) * b
        h = -z * a * (a + eta) - (n - z) * b * (b - eta)
        return (g.sum(axis=1), (g * x).sum(axis=1), h.sum(axis=1), (h * x).sum(axis=1),
                (h * x * x).sum(axis=1))

    return _newton(ym - c1 * xm, c1, lambda c0, c1: _binomial_loglik(c0, c1, x, n, z),
                   derivatives, positive_second=False)


def _newton(p0: FloatArray, p1: FloatArray, loglik: Any, derivatives: Any,
            positive_second: bool) -> tuple[FloatArray, FloatArray, NDArray[np.bool_]]:
    """Newton's method for a concave log-likelihood of two parameters, vectorised over the
    rows, with step halving so that no step lowers it. ``derivatives(p0, p1)`` gives the
    gradient ``(g0, g1)`` and the Hessian ``(h00, h01, h11)``; with ``positive_second`` the
    second parameter is kept above 0. Returns the parameters and whether they converged."""
    m = p0.size
    ll = loglik(p0, p1)
    done = np.zeros(m, dtype=bool)
    for _ in range(_MAX_ITER):
        with np.errstate(over="ignore", invalid="ignore"):  # (a row gone astray: bad)
            g0, g1, h00, h01, h11 = derivatives(p0, p1)
            det = h00 * h11 - h01 * h01
        with np.errstate(divide="ignore", invalid="ignore"):
            d0 = -(h11 * g0 - h01 * g1) / det
            d1 = -(h00 * g1 - h01 * g0) / det
        bad = ~(np.isfinite(d0) & np.isfinite(d1))
        d0, d1 = np.where(bad | done, 0.0, d0), np.where(bad | done, 0.0, d1)
        step = np.ones(m)
        for _ in range(60):  # step halving: never decrease the likelihood
            t0, t1 = p0 + step * d0, p1 + step * d1
            allowed = t1 > 0 if positive_second else np.ones(m, dtype=bool)
            new = np.where(allowed, loglik(t0, np.where(allowed, t1, 1.0)), -np.inf)
            worse = ~(new >= ll - 1e-12 * np.abs(ll))
            if not worse.any():
                break
            step = np.where(worse, 0.5 * step, step)
        p0, p1, ll = t0, t1, np.where(np.isfinite(new), new, ll)
        small = (np.abs(step * d0) <= _TOL * (1.0 + np.abs(p0))) & \
                (np.abs(step * d1) <= _TOL * (1.0 + np.abs(p1)))
        done |= small | bad
        if done.all():
            break
    ok = done & np.isfinite(p0) & np.isfinite(p1)
    return p0, p1, (ok & (p1 > 0)) if positive_second else ok


def fit_lognormal_mle(im: ArrayLike, n_runs: ArrayLike, n_exceed: ArrayLike
                      ) -> tuple[float, float]:
    """Lognormal fragility ``(median, beta)`` by maximum likelihood from stripe counts.

    Maximises the binomial likelihood of Baker (2015, *Earthquake Spectra* 31(1), eq. 11)
    over θ and β (:func:`probit_mle`): at each intensity ``im[j]``, ``n_exceed[j]`` of
    ``n_runs[j]`` runs exceeded the limit state. Usable on any table of counts.

    Parameters
    ----------
    im : array_like, shape (k,)
        Intensity levels (> 0, any units: θ comes out in the same).
    n_runs : int or array_like, shape (k,)
        Runs at each level (one number for all).
    n_exceed : array_like, shape (k,)
        Runs that exceeded the limit at each level.

    Returns
    -------
    median : float
        θ, the intensity with 50 % probability of exceedance.
    beta : float
        β, the standard deviation of ln IM of the fitted lognormal.

    Raises
    ------
    ValueError
        Bad input (one line naming the argument), or data with no finite MLE: no
        exceedance at all, exceedance in every run, separated data (β → 0), or no trend
        with the intensity (β beyond :data:`MAX_BETA`).

    Examples
    --------
    >>> theta, beta = fit_lognormal_mle([0.2, 0.4, 0.6, 0.8], 10, [0, 3, 6, 9])
    >>> round(theta, 3), round(beta, 3)
    (0.513, 0.378)
    """
    x, n, z = _check_counts(im, n_runs, n_exceed)
    med, beta, status = probit_mle(x, n, z)
    s = int(status[0])
    if s == FIT_NONE:
        raise ValueError("n_exceed: no run exceeds the limit state, so the median is above "
                         f"every level (highest {x.max():g}) and cannot be estimated")
    if s == FIT_ALL:
        raise ValueError("n_exceed: every run exceeds the limit state, so the median is "
                         f"below every level (lowest {x.min():g}) and cannot be estimated")
    if s == FIT_SEPARATED:
        raise ValueError("n_exceed: the data are separated (every exceedance at a higher "
                         "level than every non-exceedance): the likelihood grows as beta -> "
                         f"0 with the median near {med[0]:.4g}; no finite estimate")
    if s != FIT_OK:
        raise ValueError("n_exceed: the likelihood could not be maximised, or the counts "
                         f"show no trend with the intensity (beta beyond {MAX_BETA:g}) (got "
                         f"counts {z.tolist()} of {n.tolist()})")
    return float(med[0]), float(beta[0])


def _check_counts(im: ArrayLike, n_runs: ArrayLike, n_exceed: ArrayLike
                  ) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The three arrays of :func:`fit_lognormal_mle`, checked; levels without runs dropped."""
    x = np.atleast_1d(np.asarray(im, dtype=float))
    z = np.atleast_1d(np.asarray(n_exceed, dtype=float))
    if x.ndim != 1 or x.size == 0:
        raise ValueError(f"im: a non-empty list of intensity levels (got {im!r})")
    if not (np.all(np.isfinite(x)) and np.all(x > 0)):
        raise ValueError(f"im: every level must be a positive number (got {x.tolist()})")
    if z.shape != x.shape:
        raise ValueError(f"n_exceed: one count per level, {x.size} (got {z.size})")
    n = np.broadcast_to(np.asarray(n_runs, dtype=float), x.shape).copy()
    for name, v in (("n_runs", n), ("n_exceed", z)):
        if not (np.all(np.isfinite(v)) and np.all(v >= 0) and np.all(v == np.round(v))):
            raise ValueError(f"{name}: counts must be whole numbers >= 0 (got {v.tolist()})")
    if np.any(z > n):
        raise ValueError(f"n_exceed: more exceedances than runs at a level (got {z.tolist()} "
                         f"of {n.tolist()})")
    keep = n > 0
    if not keep.any():
        raise ValueError("n_runs: no level has a run")
    return x[keep], n[keep], z[keep]


# ============================================================================ IDA capacities
def ida_moments(capacity: ArrayLike) -> tuple[float, float]:
    """θ and β of IDA capacities by moments of ``ln IM`` (Baker 2015, eqs. 4–5).

    ``ln θ = mean(ln IM_i)``, ``β = sqrt(Σ (ln(IM_i/θ))² / (n − 1))``.

    Parameters
    ----------
    capacity : array_like, shape (n,)
        The intensity at which each record first exceeds the limit (> 0), n ≥ 2.
    """
    c = np.asarray(capacity, dtype=float)
    if c.ndim != 1 or c.size < 2 or not np.all(c > 0):
        raise ValueError(f"capacity: at least two positive intensities (got {c.tolist()})")
    lc = np.log(c)
    return float(np.exp(lc.mean())), float(lc.std(ddof=1))


def censored_lognormal_mle(values: ArrayLike, censored: ArrayLike
                           ) -> tuple[FloatArray, FloatArray, NDArray[np.int64]]:
    """Lognormal θ, β of IDA capacities, some right-censored, for many data sets.

    Rows are data sets (e.g. bootstrap samples of the records). Where no value of a row is
    censored the moments of :func:`ida_moments` are used (``n − 1``); otherwise the
    likelihood ``Π_unc φ(z_i)/σ · Π_cen (1 − Φ(z_i))``, ``z_i = (ln v_i − μ)/σ``, is
    maximised by Newton's method in Olsen's parameters ``(μ/σ, 1/σ)``, where it is concave.

    Parameters
    ----------
    values : array_like, shape (n,) or (m, n)
        Capacities (> 0); for a censored record the level up to which it did not exceed.
    censored : array_like of bool, same shape
        True where the record never exceeded the limit (right-censored).

    Returns
    -------
    median, beta : ndarray, shape (m,)
    status : ndarray of int, shape (m,)
        :data:`FIT_OK`; :data:`FIT_NONE` where every record is censored (θ = inf);
        :data:`FIT_FAILED` with fewer than two exceeding records (or no convergence).
    """
    y = np.log(np.atleast_2d(np.asarray(values, dtype=float)))
    cen = np.atleast_2d(np.asarray(censored, dtype=bool))
    y, cen = np.broadcast_arrays(y, cen)
    m, k = y.shape
    med, beta = np.full(m, np.nan), np.full(m, np.nan)
    status = np.full(m, FIT_FAILED, dtype=np.int64)
    n_unc = (~cen).sum(axis=1)
    allc = n_unc == 0
    med[allc], status[allc] = np.inf, FIT_NONE
    plain = (n_unc == k) & (k >= 2)
    if plain.any():
        med[plain] = np.exp(y[plain].mean(axis=1))
        beta[plain] = y[plain].std(axis=1, ddof=1)
        status[plain] = FIT_OK
    todo = (~plain) & (n_unc >= 2)
    if todo.any():
        mu, sig, ok = _newton_tobit(y[todo], cen[todo])
        med[todo] = np.where(ok, np.exp(mu), np.nan)
        beta[todo] = np.where(ok, sig, np.nan)
        status[todo] = np.where(ok, FIT_OK, FIT_FAILED)
    # a zero spread (equal capacities) is a step, as separated stripes are
    status[(status == FIT_OK) & ~(beta > 0)] = FIT_SEPARATED
    return med, beta, status


def _tobit_loglik(a: FloatArray, r: FloatArray, y: FloatArray, cen: NDArray[np.bool_]
                  ) -> FloatArray:
    from scipy.special import log_ndtr

    zz = r[:, None] * y - a[:, None]
    unc = np.log(np.where(r > 0, r, np.nan))[:, None] - 0.5 * zz * zz
    return np.sum(np.where(cen, log_ndtr(-zz), unc), axis=1)


def _newton_tobit(y: FloatArray, cen: NDArray[np.bool_]
                  ) -> tuple[FloatArray, FloatArray, NDArray[np.bool_]]:
    """Newton's method on the right-censored normal log-likelihood in ``(a, r) = (μ/σ,
    1/σ)``, vectorised over the rows; returns μ, σ and whether it converged."""
    from scipy.special import log_ndtr

    unc = ~cen
    nu = unc.sum(axis=1)
    mu0 = np.where(unc, y, 0.0).sum(axis=1) / nu
    var0 = np.where(unc, (y - mu0[:, None]) ** 2, 0.0).sum(axis=1) / np.maximum(nu - 1, 1)
    r0 = 1.0 / np.sqrt(np.where(var0 > 0, var0, 0.25))
    lphi0 = -0.5 * np.log(2.0 * np.pi)

    def derivatives(a: FloatArray, r: FloatArray) -> tuple[FloatArray, ...]:
        zz = r[:, None] * y - a[:, None]
        lam = np.exp(lphi0 - 0.5 * zz * zz - log_ndtr(-zz))  # φ(z)/(1 − Φ(z))
        k2 = lam * (lam - zz)
        return (np.where(cen, lam, zz).sum(axis=1),
                np.where(cen, -lam * y, -zz * y).sum(axis=1) + nu / r,
                np.where(cen, -k2, -1.0).sum(axis=1),
                np.where(cen, k2 * y, y).sum(axis=1),
                np.where(cen, -k2 * y * y, -y * y).sum(axis=1) - nu / (r * r))

    a, r, ok = _newton(mu0 * r0, r0, lambda a, r: _tobit_loglik(a, r, y, cen), derivatives,
                       positive_second=True)
    return a / r, 1.0 / r, ok
