"""The probability of pounding against the separation gap, and the gap for a target
probability.

Until their first impact two neighbours move independently, so a record at a given
intensity *needs* a gap ``g_i``: the largest approach of the facing floors in a run without
contact (:func:`pounding.studies.gap.critical_gaps`; the buildings pound with any gap below
it, never with one above). Over a suite of records the probability of pounding with gap
``g`` at that intensity is

    P(pound | g, IM) = P(G > g),   empirically  #{i : g_i > g} / n,

and, taking ``G`` lognormal over records (``ln θ_g`` and ``β_g`` the mean and standard
deviation of ``ln g_i``, n − 1), ``P = 1 − Φ(ln(g/θ_g)/β_g)`` — a fragility in the gap
(Baker 2015's moments fit, eqs. 4–5, with the gap in place of the intensity). The gap for a
target probability ``p`` is the ``1 − p`` fractile of ``G``: ``θ_g exp(β_g Φ⁻¹(1 − p))``
from the fit, and from the records the smallest gap exceeded by at most ``⌊p n⌋`` of them
(the ``⌈n(1 − p)⌉``-th smallest ``g_i``, the inverted empirical CDF).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["empirical_gap", "gap_lognormal", "lognormal_gap", "pounding_probability",
           "pounding_probability_fit"]

FloatArray = NDArray[np.float64]


def pounding_probability(needed: ArrayLike, gaps: ArrayLike) -> FloatArray:
    """Fraction of records whose needed gap exceeds each gap: ``#{g_i > g} / n``.

    Parameters
    ----------
    needed : array_like, shape (n_records,) or (n_records, m)
        Needed (critical) gaps [m]; NaN entries are left out.
    gaps : array_like, shape (k,)
        Gaps [m].

    Returns
    -------
    ndarray, shape (k,) or (k, m)
    """
    g = np.asarray(needed, dtype=float)
    x = np.asarray(gaps, dtype=float)
    ok = np.isfinite(g)
    count = (g[None, ...] > x.reshape((-1,) + (1,) * g.ndim)) & ok[None, ...]
    with np.errstate(invalid="ignore", divide="ignore"):
        return count.sum(axis=1) / ok.sum(axis=0)


def gap_lognormal(needed: ArrayLike) -> tuple[float, float]:
    """θ_g and β_g of the needed gaps by moments of their logarithms (mean; standard
    deviation with n − 1). NaN when fewer than two records, or a needed gap is 0 (two
    neighbours that never approach: the lognormal does not apply)."""
    g = np.asarray(needed, dtype=float)
    g = g[np.isfinite(g)]
    if g.size < 2 or not np.all(g > 0):
        return math.nan, math.nan
    lg = np.log(g)
    return float(np.exp(lg.mean())), float(lg.std(ddof=1))


def pounding_probability_fit(median: float, beta: float, gaps: ArrayLike) -> FloatArray:
    """``1 − Φ(ln(g/θ_g)/β_g)``: the lognormal probability of pounding with gap ``g``."""
    from scipy.special import ndtr

    x = np.asarray(gaps, dtype=float)
    if not (math.isfinite(median) and math.isfinite(beta) and beta > 0):
        return np.full(x.shape, np.nan)
    with np.errstate(divide="ignore"):
        return ndtr(-(np.log(x) - math.log(median)) / beta)


def lognormal_gap(median: float, beta: float, p: float) -> float:
    """The gap [m] with probability ``p`` of pounding from the lognormal fit:
    ``θ_g exp(β_g Φ⁻¹(1 − p))``."""
    from scipy.special import ndtri

    _check_p(p)
    if not (math.isfinite(median) and math.isfinite(beta)):
        return math.nan
    return float(median * math.exp(beta * float(ndtri(1.0 - p))))


def empirical_gap(needed: ArrayLike, p: float) -> float:
    """The smallest gap [m] that at most ``⌊p n⌋`` of the ``n`` records exceed: the
    ``⌈n(1 − p)⌉``-th smallest needed gap (NaN entries left out). With ``p < 1/n`` it is
    the largest needed gap of the suite."""
    _check_p(p)
    g = np.sort(np.asarray(needed, dtype=float)[np.isfinite(needed)])
    if g.size == 0:
        return math.nan
    k = max(1, math.ceil(g.size * (1.0 - p) - 1e-9))
    return float(g[k - 1])


def _check_p(p: float) -> None:
    if not (isinstance(p, (int, float)) and 0.0 < p < 1.0):
        raise ValueError(f"target probability: must be between 0 and 1 (got {p!r})")
