"""Incremental dynamic analysis: each record's curve of a demand against the intensity,
their fractiles, and the intensity at which each record first exceeds a limit.

Vamvatsikos, D. & Cornell, C. A. (2002). Incremental dynamic analysis. *Earthquake Eng.
Struct. Dyn.* 31(3), 491–514: an IDA curve is a record's engineering demand (EDP) against
the intensity measure (IM) it is scaled to; the curves of a suite are summarised by their
16 %, 50 % and 84 % fractiles, and a limit state's capacity on a curve is the IM where the
curve first crosses the limit.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["FRACTILES", "capacities", "exceedance_counts", "ida_fractiles"]

FloatArray = NDArray[np.float64]

FRACTILES: tuple[float, ...] = (0.16, 0.50, 0.84)
"""The fractiles of IDA curves reported (Vamvatsikos & Cornell 2002, §7)."""


def ida_fractiles(edp: ArrayLike, q: Sequence[float] = FRACTILES) -> FloatArray:
    """Fractiles of the demand at each level over the records (stripe by stripe).

    Parameters
    ----------
    edp : array_like, shape (n_records, n_levels)
        Demand of each record at each level; NaN for a run that failed (left out); +inf for
        a run that collapsed (the flatline of its IDA curve).
    q : sequence of float
        Fractiles in [0, 1].

    Returns
    -------
    ndarray, shape (len(q), n_levels)
        ``numpy.nanquantile`` with linear interpolation between order statistics
        (Hyndman & Fan's type 7): with 10 records the 16 % fractile lies between the
        second and third smallest demand. NaN at a level with no run; +inf where the
        fractile reaches into the collapsed runs (Vamvatsikos & Cornell 2002, §7: the
        fractile curve flattens there).
    """
    a = np.asarray(edp, dtype=float)
    out = np.full((len(q), a.shape[1]), np.nan)
    has = ~np.isnan(a).all(axis=0)
    if has.any():
        with np.errstate(invalid="ignore"):  # inf − inf, where a fractile lies among +inf
            out[:, has] = np.nanquantile(a[:, has], list(q), axis=0)
    for j in np.flatnonzero(has & np.isinf(a).any(axis=0)):
        out[:, j] = _fractiles_with_infinity(a[:, j], q)
    return out


def _fractiles_with_infinity(values: FloatArray, q: Sequence[float]) -> FloatArray:
    """Type-7 fractiles of a stripe holding +inf: between two order statistics by linear
    interpolation, +inf where either of the two is infinite (unless the fractile falls on
    the finite one exactly)."""
    v = np.sort(values[~np.isnan(values)])
    h = (v.size - 1) * np.asarray(q, dtype=float)
    lo = np.floor(h).astype(int)
    hi = np.ceil(h).astype(int)
    frac = h - lo
    out = np.empty(h.size)
    for k in range(h.size):
        a, b = v[lo[k]], v[hi[k]]
        out[k] = a if frac[k] == 0.0 else (np.inf if np.isinf(b) else a + frac[k] * (b - a))
    return out


def capacities(levels: ArrayLike, edp: ArrayLike, limit: float, *, binary: bool = False
               ) -> tuple[FloatArray, NDArray[np.bool_]]:
    """The intensity at which each record first exceeds ``limit`` on its IDA curve.

    The curve of a record is its demand at the levels run (sorted by intensity), starting
    from ``(0, 0)``: no shaking, no demand. Its capacity is where it first exceeds the
    limit: for a continuous demand (drift, acceleration, force, ductility) the linear
    interpolation between the last level at or below the limit and the first above it;
    for a binary one (pounding or not: ``binary=True``) the first level at which it is
    exceeded (the capacity lies between that level and the one before). A record that
    never exceeds it up to the highest level is right-censored there. Later levels at
    which the curve comes back below the limit ("resurrection") are ignored: the first
    exceedance counts. Failed runs (NaN) are left out of the curve. A run that collapsed
    (+inf: the curve's flatline) exceeds any limit; where it is the first exceedance the
    capacity is its level, as for a binary demand (the collapse lies between that level
    and the one before).

    Parameters
    ----------
    levels : array_like, shape (n_levels,)
        Intensities (> 0), any order.
    edp : array_like, shape (n_records, n_levels)
        Demands (for ``binary``: 1 where exceeded, 0 where not); NaN for a failed run,
        +inf for one that collapsed.
    limit : float
        Exceedance is ``edp > limit`` (for ``binary``: ``edp > 0.5``).

    Returns
    -------
    capacity : ndarray, shape (n_records,)
        IM of first exceedance; for a censored record the highest level run; NaN for a
        record without any successful run.
    censored : ndarray of bool, shape (n_records,)
        True where the record never exceeded the limit.
    """
    x = np.asarray(levels, dtype=float)
    e = np.atleast_2d(np.asarray(edp, dtype=float))
    order = np.argsort(x, kind="stable")
    x, e = x[order], e[:, order]
    lim = 0.5 if binary else float(limit)
    cap = np.full(e.shape[0], np.nan)
    cen = np.zeros(e.shape[0], dtype=bool)
    for i, row in enumerate(e):
        ok = ~np.isnan(row)
        xs, ys = x[ok], row[ok]
        if xs.size == 0:
            continue
        above = np.flatnonzero(ys > lim)
        if above.size == 0:
            cap[i], cen[i] = xs[-1], True
            continue
        j = int(above[0])
        if binary or np.isinf(ys[j]):
            cap[i] = xs[j]
            continue
        x0, y0 = (0.0, 0.0) if j == 0 else (xs[j - 1], ys[j - 1])
        y0 = min(y0, lim)  # the curve starts at or below the limit
        cap[i] = x0 + (lim - y0) / (ys[j] - y0) * (xs[j] - x0)
    return cap, cen


def exceedance_counts(exceed: ArrayLike) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Runs and exceedances at each level from a records × levels table.

    Parameters
    ----------
    exceed : array_like, shape (n_records, n_levels)
        1.0 where the run exceeded the limit, 0.0 where not, NaN where it failed.

    Returns
    -------
    n_runs, n_exceed : ndarray of int, shape (n_levels,)
    """
    a = np.asarray(exceed, dtype=float)
    ok = np.isfinite(a)
    return ok.sum(axis=0).astype(np.int64), np.where(ok, a, 0.0).sum(axis=0).astype(np.int64)
