"""Compiled reductions of time histories to peaks: the largest ``|value|`` of every column,
of every storey drift, and of the energy-balance residual.

A history of a run is tens of thousands of rows by a few columns. NumPy reduces it one
operation and one temporary array at a time (and reduces a tall, narrow array along its
rows slowly); here each quantity is formed in one vectorised pass and its largest
magnitude found in another. Every function gives exactly what the NumPy expression in its
docstring gives, to the last bit: the same floating-point operations in the same order,
and maxima of magnitudes taken on their bit patterns, which for IEEE doubles with the sign
bit cleared order as the numbers do (so the compiler may vectorise the search, and a NaN,
whose pattern lies above infinity's, gives NaN as ``ndarray.max`` does).

Every compiled function lives in this one module, so numba's on-disk cache (keyed on this
file) can never hold a stale piece of it. Import it only inside functions: importing it
imports numba.
"""

from __future__ import annotations

import numpy as np
from numba import njit

_MAGNITUDE = np.int64(0x7FFF_FFFF_FFFF_FFFF)
"""Every bit of a double but its sign."""
_INFINITY = np.int64(0x7FF0_0000_0000_0000)
"""The bit pattern of +inf; larger patterns (sign cleared) are NaNs."""


@njit(cache=True)
def _from_bits(best: np.int64) -> float:
    """The magnitude whose pattern is ``best`` (NaN above infinity's)."""
    if best > _INFINITY:
        return np.nan
    return np.array([best]).view(np.float64)[0]


@njit(cache=True)
def _abs_max(x: np.ndarray) -> float:
    """``np.abs(x).max()`` of a contiguous 1-D float64 array (0.0 if it is empty)."""
    bits = x.view(np.int64)
    best = np.int64(0)
    for k in range(bits.size):
        b = bits[k] & _MAGNITUDE
        best = b if b > best else best
    return _from_bits(best)


@njit(cache=True)
def _abs_max_column(bits: np.ndarray, j: int) -> float:
    """``np.abs(a[:, j]).max()`` of the 2-D float64 array whose bits are ``bits``."""
    best = np.int64(0)
    for k in range(bits.shape[0]):
        b = bits[k, j] & _MAGNITUDE
        best = b if b > best else best
    return _from_bits(best)


@njit(cache=True)
def _abs_max_columns(a: np.ndarray) -> np.ndarray:
    bits = a.view(np.int64)
    out = np.zeros(a.shape[1])
    for j in range(a.shape[1]):
        out[j] = _abs_max_column(bits, j)
    return out


@njit(cache=True)
def _abs_max_drift(u: np.ndarray, below: np.ndarray) -> np.ndarray:
    nt, m = u.shape
    bits = u.view(np.int64)
    out = np.zeros(m)
    col = np.empty(nt)
    for j in range(m):
        b = below[j]
        if b >= 0:
            for k in range(nt):
                col[k] = u[k, j] - u[k, b]
            out[j] = _abs_max(col)
        else:
            out[j] = _abs_max_column(bits, j)
    return out


@njit(cache=True)
def _energy_residual_max(e: np.ndarray, e_input: np.ndarray) -> tuple[float, float]:
    nt = e.shape[0]
    e0 = e[0, 1] + e[0, 2]
    col = np.empty(nt)
    links = e.shape[1] > 7
    for k in range(nt):
        out = (((e[k, 1] + e[k, 2]) + e[k, 3]) + e[k, 4]) + e[k, 6]
        if links:
            out = out + e[k, 7]
        col[k] = (e0 + e[k, 0]) - out
    return _abs_max(col), _abs_max(e_input)


def abs_max_columns(a: np.ndarray) -> np.ndarray:
    """``np.abs(a).max(axis=0)`` of a 2-D array (zeros if it has no rows), as float64.

    Examples
    --------
    >>> abs_max_columns(np.array([[1.0, -4.0], [-3.0, 2.0]]))
    array([3., 4.])
    """
    return _abs_max_columns(np.ascontiguousarray(a, dtype=np.float64))


def abs_max_drift(u: np.ndarray, below: np.ndarray) -> np.ndarray:
    """The largest ``|u[:, j] − u[:, below[j]]|`` of every column ``j`` of a 2-D array,
    ``|u[:, j]|`` where ``below[j] < 0`` (zeros if it has no rows): the storey drifts of
    floor displacements, ``below`` as :func:`pounding.integrate.floor_below`.

    Examples
    --------
    >>> abs_max_drift(np.array([[1.0, 3.0], [-2.0, -1.0]]), np.array([-1, 0]))
    array([2., 2.])
    """
    return _abs_max_drift(np.ascontiguousarray(u, dtype=np.float64),
                          np.asarray(below, dtype=np.int64))


def energy_residual_max(e: np.ndarray) -> tuple[float, float]:
    """The largest departure from the energy balance and the largest input energy:
    ``(np.abs(closure).max(), np.abs(e[:, 0]).max())`` of the cumulative energies ``e``
    (columns :data:`pounding.result.ENERGY_NAMES`, at least one row), where
    ``closure = e0 + e[:, 0] − (e[:, 1] + e[:, 2] + e[:, 3] + e[:, 4] + e[:, 6] + e[:, 7])``
    (the links' column where there is one) and ``e0 = e[0, 1] + e[0, 2]``."""
    e = np.asarray(e, dtype=np.float64)
    # (a column of the kernel's Fortran-ordered energies is contiguous already)
    return _energy_residual_max(e, np.ascontiguousarray(e[:, 0]))
