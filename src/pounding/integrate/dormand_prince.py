"""One adaptive step of the Dormand–Prince 5(4) pair, as the kernel takes it through contacts.

Dormand & Prince (1980), J. Comput. Appl. Math. 6(1):19–26; coefficients as in Hairer,
Nørsett & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., Table 5.2 (p. 178).
The fifth-order solution is propagated (local extrapolation); the embedded fourth-order one
gives the error estimate; the last stage is f at the new point (first same as last).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.integrate.rhs import G_END, G_NOW, INLINE, NRT_FREE, deriv, ground_at

# Dormand–Prince 5(4) tableau
C2, C3, C4, C5 = 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = (9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0,
                           -5103.0 / 18656.0)
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0,
                          -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0)
DP_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [A21, 0.0, 0.0, 0.0, 0.0, 0.0],
    [A31, A32, 0.0, 0.0, 0.0, 0.0],
    [A41, A42, A43, 0.0, 0.0, 0.0],
    [A51, A52, A53, A54, 0.0, 0.0],
    [A61, A62, A63, A64, A65, 0.0],
    [B1, 0.0, B3, B4, B5, B6]])
"""Rows 1 … 5: the stages' a coefficients; row 6: the fifth-order weights b (b2 = 0)."""
DP_C = np.array([0.0, C2, C3, C4, C5, 1.0, 1.0])
"""Stage times as fractions of the step."""


@njit(**NRT_FREE)
def rk_step(y0, k1, p1, h, gnd, s0, fl, ct, el, committed, sstate, lin, ks, ps, ytmp, y1,
            atol, rtol):
    """One Dormand–Prince step of size h from y0 (k1, p1: derivative and power at y0) of
    the model's floors, contacts and element rows ``fl``, ``ct``, ``el``
    (:class:`pounding.integrate.kernel_model.KernelArrays`).

    ``gnd[G_A0] + gnd[G_SLOPE] * s`` are the ground components at local time s (from the
    grid point); s0 is the local start; ``gnd[G_END]`` their values at the step's end, set
    by the caller (at a grid point the record's values bit for bit, so that the step's last
    stage is the next step's first). The stages' ground components are written to
    ``gnd[G_NOW]``.
    Writes y1 and the stage derivatives/powers (ks, ps: 7 rows); returns the error norm
    (RMS of the error over ``atol + rtol |y|``). Row 6 of ks/ps is f at y1.
    """
    m = y0.shape[0]
    for i in range(m):
        ks[0, i] = k1[0, i]
    for i in range(ps.shape[1]):
        ps[0, i] = p1[0, i]
    # stages 1 … 5 at y0 + h Σ a_sq k_q, then the solution y1 (row 6: the b weights) and f
    # there; one call site of the right-hand side, so that it is compiled into the step
    # once, not six times (docs/engine.md, "Compiled once")
    for st in range(1, 7):
        # the stage's point y0 + h Σ a_sq k_q, written out for each stage (a branch a stage,
        # always taken the same way, costs less than a loop over the tableau)
        if st == 1:
            for i in range(m):
                ytmp[i] = y0[i] + h * (A21 * ks[0, i])
        elif st == 2:
            for i in range(m):
                ytmp[i] = y0[i] + h * (A31 * ks[0, i] + A32 * ks[1, i])
        elif st == 3:
            for i in range(m):
                ytmp[i] = y0[i] + h * (A41 * ks[0, i] + A42 * ks[1, i] + A43 * ks[2, i])
        elif st == 4:
            for i in range(m):
                ytmp[i] = y0[i] + h * (A51 * ks[0, i] + A52 * ks[1, i] + A53 * ks[2, i]
                                       + A54 * ks[3, i])
        elif st == 5:
            for i in range(m):
                ytmp[i] = y0[i] + h * (A61 * ks[0, i] + A62 * ks[1, i] + A63 * ks[2, i]
                                       + A64 * ks[3, i] + A65 * ks[4, i])
        else:
            for i in range(m):
                y1[i] = y0[i] + h * (B1 * ks[0, i] + B3 * ks[2, i] + B4 * ks[3, i]
                                     + B5 * ks[4, i] + B6 * ks[5, i])
        yt = y1 if st == 6 else ytmp
        if st >= 5:
            for g in range(gnd.shape[1]):
                gnd[G_NOW, g] = gnd[G_END, g]
        else:
            ground_at(gnd, G_NOW, s0 + DP_C[st] * h)
        deriv(yt, y0, gnd, fl, ct, el, committed, sstate, lin, ks, ps, st)
    err = 0.0
    for i in range(m):
        e = h * (E1 * ks[0, i] + E3 * ks[2, i] + E4 * ks[3, i] + E5 * ks[4, i]
                 + E6 * ks[5, i] + E7 * ks[6, i])
        sc = atol[i] + rtol * max(abs(y0[i]), abs(y1[i]))
        err += (e / sc) ** 2
    return np.sqrt(err / m)


@njit(**INLINE)
def weighted_sum(ps, q, h):
    """``h Σ b_i ps[i, q]``: the integral over an accepted step of power column q."""
    return h * (B1 * ps[0, q] + B3 * ps[2, q] + B4 * ps[3, q] + B5 * ps[4, q] + B6 * ps[5, q])
