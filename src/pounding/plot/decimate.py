"""Decimation of long histories for display, keeping every peak exactly.

A 40 s record at 1 ms is 40,000 samples a line, far more than the ~1,500 pixel columns a
figure has. Drawing them all costs time and changes nothing visible; dropping samples at a
fixed stride (``y[::k]``) is cheap but loses peaks. The "M4" rule of Jugel et al. (2014)
keeps, of every group of consecutive samples that falls into one pixel column, the first,
the last, the smallest and the largest: the line drawn through them covers the same pixels
as the full line, and every extreme value of the history is one of the kept samples.

Reference: U. Jugel, Z. Jerzak, G. Hackenbroich, V. Markl, "M4: a visualization-oriented
time series data aggregation", Proc. VLDB Endowment 7(10), 797–808, 2014.

NumPy only: importing this module does not import matplotlib.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["DISPLAY_PPI", "buckets_for_width", "envelope_indices", "union_indices"]

DISPLAY_PPI = 300
"""Buckets per inch of axes width: one or more per pixel column for PNGs up to 300 dpi (the
run figures are written at ``[output] dpi``, 150 by default). At any resolution every
bucket's extremes are kept, so peaks stay exact."""


def buckets_for_width(width_in: float, ppi: int = DISPLAY_PPI) -> int:
    """Number of buckets for an axes ``width_in`` inches wide (at least 1)."""
    return max(1, int(np.ceil(width_in * ppi)))


def envelope_indices(y: NDArray[np.float64], n_buckets: int) -> NDArray[np.intp]:
    """Indices of the samples of ``y`` to draw: first, last, argmin and argmax of each of
    ``n_buckets`` runs of consecutive samples (the M4 rule), sorted, without repeats.

    Parameters
    ----------
    y : numpy.ndarray, shape (n,)
        A history sampled at equal steps (the buckets are equal runs of samples, so with
        equal steps they are equal stretches of the time axis).
    n_buckets : int
        How many buckets; :func:`buckets_for_width` of the axes.

    Returns
    -------
    numpy.ndarray of int
        Increasing indices into ``y``; all of them (``arange(n)``) when ``n`` is at most
        ``4 n_buckets``. Always contains 0, ``n − 1``, ``argmin(y)`` and ``argmax(y)``.
        NaN samples are treated as neither smallest nor largest.
    """
    y = np.asarray(y, dtype=float)
    n = y.size
    if n <= 4 * max(n_buckets, 1):
        return np.arange(n)
    size = -(-n // n_buckets)  # ceil: samples per bucket
    n_full = n // size
    starts = np.arange(n_full) * size
    block = y[: n_full * size].reshape(n_full, size)
    nan = np.isnan(block)
    if nan.any():
        lo = np.where(nan, np.inf, block).argmin(axis=1)
        hi = np.where(nan, -np.inf, block).argmax(axis=1)
    else:
        lo = block.argmin(axis=1)
        hi = block.argmax(axis=1)
    parts = [starts, starts + lo, starts + hi, starts + size - 1]
    rest = n - n_full * size
    if rest:
        tail = y[n_full * size:]
        base = n_full * size
        extra = [base, n - 1, base + int(np.where(np.isnan(tail), np.inf, tail).argmin()),
                 base + int(np.where(np.isnan(tail), -np.inf, tail).argmax())]
        parts.append(np.asarray(extra))
    idx = np.concatenate(parts)
    idx.sort()
    keep = np.empty(idx.size, dtype=bool)
    keep[0] = True
    np.not_equal(idx[1:], idx[:-1], out=keep[1:])
    return idx[keep]


def union_indices(columns: NDArray[np.float64], n_buckets: int) -> NDArray[np.intp]:
    """:func:`envelope_indices` of every column of ``columns`` (shape (n, m)), merged: one
    set of samples that keeps the extremes of every column (for curves that must share
    their abscissae, such as the edges of stacked areas)."""
    columns = np.asarray(columns, dtype=float)
    if columns.ndim == 1:
        return envelope_indices(columns, n_buckets)
    return np.unique(np.concatenate([envelope_indices(columns[:, j], n_buckets)
                                     for j in range(columns.shape[1])]))
