"""The compiled reductions of histories equal their NumPy expressions to the last bit,
NaN, infinities, signed zeros, empty and Fortran-ordered arrays included."""

from __future__ import annotations

import numpy as np

from pounding.result import abs_max_columns, abs_max_drift, energy_residual_max


def _bits(x) -> bytes:
    return np.asarray(x, dtype=float).tobytes()


def _same(x, y) -> bool:
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    return _bits(np.where(np.isnan(x), 0.0, x)) == _bits(np.where(np.isnan(y), 0.0, y)) and \
        np.array_equal(np.isnan(x), np.isnan(y))


def _cases(rng):
    for trial in range(150):
        nt, m = int(rng.integers(1, 40)), int(rng.integers(1, 5))
        u = rng.standard_normal((nt, m)) * 10.0 ** rng.integers(-300, 300, size=(nt, m))
        if trial % 5 == 0:
            u[rng.integers(nt), rng.integers(m)] = np.nan
        if trial % 7 == 0:
            u[:] = -0.0
        if trial % 11 == 0:
            u[rng.integers(nt), rng.integers(m)] = -np.inf
        yield u


def test_column_and_drift_peaks_equal_numpy() -> None:
    rng = np.random.default_rng(1)
    for u in _cases(rng):
        m = u.shape[1]
        ref = np.array([np.abs(u[:, j]).max() for j in range(m)])
        assert _same(abs_max_columns(u), ref)
        assert _same(abs_max_columns(np.asfortranarray(u)), ref)
        below = np.arange(m) - 1
        below[0] = -1
        drift = np.array([np.abs(u[:, j] - u[:, below[j]]).max() if below[j] >= 0
                          else np.abs(u[:, j]).max() for j in range(m)])
        assert _same(abs_max_drift(u, below), drift)
    assert _same(abs_max_columns(np.zeros((0, 3))), np.zeros(3))


def test_energy_residual_equals_numpy() -> None:
    rng = np.random.default_rng(2)
    for trial in range(150):
        nt = int(rng.integers(1, 40))
        e = np.asfortranarray(rng.standard_normal((nt, 7)) * 1e6)
        if trial % 5 == 1:
            e[rng.integers(nt), rng.integers(7)] = np.nan
        e0 = e[0, 1] + e[0, 2]
        closure = e0 + e[:, 0] - (e[:, 1] + e[:, 2] + e[:, 3] + e[:, 4] + e[:, 6])
        ref = (np.abs(closure).max(), np.abs(e[:, 0]).max())
        assert _same(energy_residual_max(e), ref)
        assert _same(energy_residual_max(np.ascontiguousarray(e)), ref)
