"""Exact discrete-time propagation of the linear structure between impacts.

While every gap is open the buildings are linear: ``ẋ = A x + B a_g(t)`` with
``x = [u, u̇]``, ``A = [[0, I], [−M⁻¹K, −M⁻¹C]]`` and ``B = [0, −r]``. The ground
acceleration of a record is linear between its samples, so over one step ``h`` on which
``a_g`` is linear the solution is exactly

    x(h) = Φ x(0) + Γ0 a_g(0) + Γ1 a_g(h)

with ``Φ = e^{Ah}`` and Γ0, Γ1 from one matrix exponential of the augmented system
``d/dt [x, a, ȧ] = [[A, B, 0], [0, 0, 1], [0, 0, 0]] [x, a, ȧ]`` (Van Loan 1978, IEEE TAC
23(3):395–404; the same idea as Nigam & Jennings' exact piecewise-linear method for SDOF,
BSSA 59(2):909–922, 1969). The time-history kernel uses it for every step without
contact; it is exact to round-off whatever the step.
"""

from __future__ import annotations

from typing import NamedTuple

import hashlib

import numpy as np
import scipy.linalg
from numpy.typing import NDArray


class Propagator(NamedTuple):
    """``x(h) = phi @ x(0) + gamma0 * a_g(0) + gamma1 * a_g(h)`` for one step ``h`` [s]."""

    phi: NDArray[np.float64]
    gamma0: NDArray[np.float64]
    gamma1: NDArray[np.float64]


def state_matrix(M: NDArray[np.float64], C: NDArray[np.float64],
                 K: NDArray[np.float64]) -> NDArray[np.float64]:
    """First-order system matrix ``A = [[0, I], [−M⁻¹K, −M⁻¹C]]`` (2N × 2N)."""
    n = M.shape[0]
    minv = np.linalg.inv(M)
    a = np.zeros((2 * n, 2 * n))
    a[:n, n:] = np.eye(n)
    a[n:, :n] = -minv @ K
    a[n:, n:] = -minv @ C
    return a


_CACHE: dict[bytes, Propagator] = {}
_CACHE_SIZE = 64


def propagator(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
               r: NDArray[np.float64], h: float) -> Propagator:
    """Exact propagator of the linear structure over a step ``h`` [s] with linear ``a_g``
    (see :func:`compute_propagator`), remembered per structure and step: a sweep over gaps,
    restitution or records reuses one matrix exponential. The arrays are read-only."""
    key = hashlib.sha1(b"".join(np.ascontiguousarray(a, dtype=float).tobytes()
                                for a in (M, C, K, r)) + repr((M.shape, float(h))).encode()).digest()
    hit = _CACHE.get(key)
    if hit is None:
        hit = compute_propagator(M, C, K, r, h)
        for a in hit:
            a.setflags(write=False)
        if len(_CACHE) >= _CACHE_SIZE:
            _CACHE.pop(next(iter(_CACHE)))
        _CACHE[key] = hit
    return hit


def compute_propagator(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                       r: NDArray[np.float64], h: float) -> Propagator:
    """Exact propagator of the linear structure over a step ``h`` [s] with linear ``a_g``.

    Parameters
    ----------
    M, C, K : ndarray (N, N)
        Mass [kg], damping [N·s/m], stiffness [N/m].
    r : ndarray (N,)
        Influence vector.
    h : float
        Step [s].
    """
    n = M.shape[0]
    a = state_matrix(M, C, K)
    z = np.zeros((2 * n + 2, 2 * n + 2))
    z[: 2 * n, : 2 * n] = a
    z[n : 2 * n, 2 * n] = -r
    z[2 * n, 2 * n + 1] = 1.0
    e = scipy.linalg.expm(z * h)
    phi = np.ascontiguousarray(e[: 2 * n, : 2 * n])
    e12 = e[: 2 * n, 2 * n]
    e13 = e[: 2 * n, 2 * n + 1]
    return Propagator(phi, np.ascontiguousarray(e12 - e13 / h), np.ascontiguousarray(e13 / h))
