"""Exact grid steps of a classically damped block in modal coordinates (compiled).

A block that :func:`pounding.integrate.propagator.compute_free_step` marked modal
(``FreeStep.modal[b] = 1``) carries its modal state ``s_j = [q_j, q̇_j]`` through a run of
exact steps (:func:`pounding.integrate.exact_steps.free_run`) in the scratch ``qm``
(:class:`pounding.integrate.workspace.KernelScratch`, rows :data:`Q0` …). Each step is
one 2 × 2 update a mode (:mod:`pounding.integrate.modal_propagator`) and the floors'
``u = Ψ q``, ``u̇ = Ψ q̇``: 2 n_b² products against the dense sweep's 4 n_b², each row of Ψ
read once for both. Sums run in a fixed order (the inner loops over floors vectorise
without reassociation), so a run's results do not depend on memory alignment.
"""

from __future__ import annotations

from numba import njit

from pounding.integrate.rhs import NRT_FREE

TABLE = 12
"""Numbers a mode's row of the table holds after its shape ψ_j and its mass-weighted shape
M ψ_j (:func:`pounding.integrate.modal_propagator.mode_table`)."""
MODE_E = 0  #: E00, E01, E10, E11: the mode's 2 × 2 exponential, row by row
MODE_G0 = 4  #: γ0 of q and q̇
MODE_G1 = 6  #: γ1 of q and q̇
MODE_W0 = 8  #: linear input-energy terms of a0: coefficients of q and q̇ (2 Q[s, a0])
MODE_W1 = 10  #: and of a1


Q0 = 0  #: row of ``qm``: the modal displacements q at the step's start (their floors' order)
QD0 = 1  #: the modal velocities q̇ at the step's start
Q1 = 2  #: q at the step's end
QD1 = 3  #: q̇ at the step's end
SUM_U = 4  #: Ψ q, summed mode by mode (scratch)
SUM_V = 5  #: Ψ q̇
QM_ROWS = 6
"""Rows of the modal scratch ``qm`` (QM_ROWS, N + 1); ``qm[0, N]``: the grid point whose
state rows Q0, QD0 hold (−1: none)."""


@njit(**NRT_FREE)
def modal_enter(p, nb, x, fmodes, qm):
    """The modal state of block p (``nb`` floors) from the floors' state ``x`` (N floors):
    ``q = Ψᵀ M u``, ``q̇ = Ψᵀ M u̇`` (row j of the block's table holds ``M ψ_j`` after
    ``ψ_j``), written to rows :data:`Q0`, :data:`QD0` of ``qm``."""
    n = qm.shape[1] - 1
    for j in range(nb):
        su = 0.0
        sv = 0.0
        for i in range(nb):
            w = fmodes[p + j, nb + i]
            su += w * x[p + i]
            sv += w * x[n + p + i]
        qm[Q0, p + j] = su
        qm[QD0, p + j] = sv


@njit(**NRT_FREE)
def modal_block_step(p, nb, fmodes, qm, x1, a0, a1):
    """The exact step of modal block p under ground accelerations ``a0``, ``a1`` at the
    step's ends: writes the modal state at its end (rows :data:`Q1`, :data:`QD1` of
    ``qm``) and the floors' ``x1[p … p + nb − 1]``, ``x1[N + p …]``; returns the block's two
    linear input-energy terms ``(w0 · s, w1 · s)`` of the state at the step's start.

    ``u = Ψ q`` is summed mode after mode, four modes a pass over the floors (each floor's
    sum in the same order as one mode a pass, with a quarter of the loads and stores of
    the sums); the loop over floors vectorises without reassociation."""
    n = qm.shape[1] - 1
    c0 = 2 * nb
    lin0 = 0.0
    lin1 = 0.0
    for j in range(nb):
        row = p + j
        d = qm[Q0, row]
        v = qm[QD0, row]
        lin0 += fmodes[row, c0 + MODE_W0] * d + fmodes[row, c0 + MODE_W0 + 1] * v
        lin1 += fmodes[row, c0 + MODE_W1] * d + fmodes[row, c0 + MODE_W1 + 1] * v
        qm[Q1, row] = (fmodes[row, c0 + MODE_E] * d + fmodes[row, c0 + MODE_E + 1] * v
                       + fmodes[row, c0 + MODE_G0] * a0 + fmodes[row, c0 + MODE_G1] * a1)
        qm[QD1, row] = (fmodes[row, c0 + MODE_E + 2] * d + fmodes[row, c0 + MODE_E + 3] * v
                        + fmodes[row, c0 + MODE_G0 + 1] * a0
                        + fmodes[row, c0 + MODE_G1 + 1] * a1)
    su = qm[SUM_U]
    sv = qm[SUM_V]
    for i in range(nb):
        su[i] = 0.0
        sv[i] = 0.0
    j = 0
    while j + 4 <= nb:
        r = p + j
        d0 = qm[Q1, r]
        d1 = qm[Q1, r + 1]
        d2 = qm[Q1, r + 2]
        d3 = qm[Q1, r + 3]
        v0 = qm[QD1, r]
        v1 = qm[QD1, r + 1]
        v2 = qm[QD1, r + 2]
        v3 = qm[QD1, r + 3]
        for i in range(nb):
            s0 = fmodes[r, i]
            s1 = fmodes[r + 1, i]
            s2 = fmodes[r + 2, i]
            s3 = fmodes[r + 3, i]
            su[i] = su[i] + s0 * d0 + s1 * d1 + s2 * d2 + s3 * d3
            sv[i] = sv[i] + s0 * v0 + s1 * v1 + s2 * v2 + s3 * v3
        j += 4
    while j < nb:
        r = p + j
        d0 = qm[Q1, r]
        v0 = qm[QD1, r]
        for i in range(nb):
            s0 = fmodes[r, i]
            su[i] = su[i] + s0 * d0
            sv[i] = sv[i] + s0 * v0
        j += 1
    for i in range(nb):
        x1[p + i] = su[i]
        x1[n + p + i] = sv[i]
    return lin0, lin1


@njit(**NRT_FREE)
def modal_commit(p, nb, qm):
    """The step of modal block p taken: its end state becomes the next step's start."""
    for j in range(nb):
        qm[Q0, p + j] = qm[Q1, p + j]
        qm[QD0, p + j] = qm[QD1, p + j]
