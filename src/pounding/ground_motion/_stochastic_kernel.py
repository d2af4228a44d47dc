"""The compiled kernel of the stochastic ground motions: the time-varying filter of
Rezaeian & Der Kiureghian (2008) applied to discrete white noise, normalised to unit
variance. Import it only inside functions: importing it imports numba.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

MEMORY_DECAY = 20.0
"""A pulse is summed while ``ζ ω_min (t − τ)`` is below this: its filter response has decayed
by e⁻²⁰ ≈ 2e-9 beyond, below round-off of the sums it would join."""


@njit(cache=True)
def normalised_filtered_noise(noise: np.ndarray, dt: float, omega: np.ndarray,
                              zeta: float) -> np.ndarray:  # pragma: no cover - compiled
    """``Σ_i h(t_k − t_i; ω_i) u_i / sqrt(Σ_i h(t_k − t_i; ω_i)²)`` over ``t_i ≤ t_k``.

    ``h(τ; ω) = ω/sqrt(1 − ζ²) e^{−ζωτ} sin(ω sqrt(1 − ζ²) τ)`` is the unit-impulse
    response of the filter whose natural frequency is the one at the pulse's time
    (Rezaeian & Der Kiureghian 2008, eqs 2-3); ``noise`` holds the pulses ``u_i`` at
    ``t_i = i dt``, ``omega`` the filter frequency at each [rad/s]. The first sample,
    where every ``h`` is zero, is 0.
    """
    n = noise.size
    s = np.zeros(n)
    v = np.zeros(n)
    root = math.sqrt(1.0 - zeta * zeta)
    w_min = omega.min()
    memory = n if w_min <= 0.0 else min(n, int(MEMORY_DECAY / (zeta * w_min * dt)) + 2)
    for i in range(n - 1):
        # pulse i's response at t_i + j dt is Im(c z^j): z advances it one step
        w = omega[i]
        decay = math.exp(-zeta * w * dt)
        zr = decay * math.cos(w * root * dt)
        zi = decay * math.sin(w * root * dt)
        pr = w / root
        pi = 0.0
        for k in range(i + 1, min(n, i + memory)):
            pr, pi = pr * zr - pi * zi, pr * zi + pi * zr
            s[k] += pi * noise[i]
            v[k] += pi * pi
    out = np.zeros(n)
    for k in range(1, n):
        if v[k] > 0.0:
            out[k] = s[k] / math.sqrt(v[k])
    return out
