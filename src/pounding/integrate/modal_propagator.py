"""The exact step of a classically damped block from its modes.

A block of floors whose damping is classical — ``Ψᵀ C Ψ`` diagonal in the mass-normalised
modes Ψ of ``K ψ = ω² M ψ`` (Rayleigh and modal damping; Caughey & O'Kelly 1965, J. Appl.
Mech. 32(3):583–588) — splits into independent modes ``q̈_j + c_j q̇_j + ω_j² q_j = −Γ_j a_g``
with ``u = Ψ q``, ``Γ = Ψᵀ M r`` (Chopra, *Dynamics of Structures*, 4th ed., §12.4 and §13.1).
Over a step h on which a_g is linear, each mode's state ``s_j = [q_j, q̇_j]`` then steps
exactly as a single-degree-of-freedom oscillator does (Nigam & Jennings 1969, BSSA
59(2):909–922; Chopra §5.2):

    s_j(h) = E_j s_j(0) + γ0_j a0 + γ1_j a1,

and the input energy ``∫ −u̇ᵀ M r a_g dt = Σ_j ∫ −Γ_j q̇_j a_g dt`` is a sum of one quadratic
form a mode in ``[s_j(0), a0, a1]``. Each mode's ``E_j``, ``γ0_j``, ``γ1_j`` and input form
come from the exponential of its 4 × 4 augmented matrix and of the 8 × 8 matrix of Van
Loan's integral (the constructions of :mod:`pounding.integrate.propagator`, one mode at a
time; Van Loan 1978, IEEE TAC 23(3):395–404), all modes in one batched call: exact for any
damping ratio (under-, critically and over-damped modes alike, and rigid-body modes), where
a closed form per mode would lose digits near ζ = 1. The dense operators of the block
(:class:`pounding.integrate.propagator.FreeStep`) follow by transforming back, O(n³) in
products instead of the exponentials of 2n + 2 and 4n + 4 square matrices; the kernel steps
such a block in modal coordinates (:mod:`pounding.integrate.modal_steps`): 2 n² products a
step instead of the dense sweep's 4 n².

Only one ground component (G = 1) and blocks without link dashpots take this route; any
other block keeps the dense one.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.integrate.modal_steps import (
    MODE_E,
    MODE_G0,
    MODE_G1,
    MODE_W0,
    MODE_W1,
    TABLE,
)

MODAL_MIN_FLOORS: int = 16
"""Blocks of at least this many floors whose damping is classical are stepped in modal
coordinates. Smaller blocks keep the dense propagator, whose results stay bit-identical to
what they were before the modal route existed (there the dense sweep costs at most a
microsecond a step)."""

CLASSICAL_TOL: float = 1e-12
"""Damping counts as classical when every off-diagonal entry of ``Ψᵀ C Ψ`` is at most this
times its largest diagonal entry (round-off of a Rayleigh damping is ~n·10⁻¹⁶), and K and C
are symmetric to the same relative tolerance."""


class ModalBlock(NamedTuple):
    """A classically damped block's modes and each mode's exact step (one ground component).

    ``psi`` (n, n): mass-normalised mode shapes (columns), ``Ψᵀ M Ψ = I``; ``omega2``,
    ``c`` (n,): ``ω_j²`` [1/s²] and the modal damping ``c_j = ψ_jᵀ C ψ_j`` [1/s]; ``gamma``
    (n,): participation ``Γ_j = ψ_jᵀ M r`` [kg^½]; ``e`` (n, 2, 2), ``g0``, ``g1`` (n, 2):
    each mode's step; ``q_in`` (n, 4, 4): each mode's input-energy form in
    ``[q_j, q̇_j, a0, a1]`` [J per (m/s²)² and kg^½·m …]."""

    psi: NDArray[np.float64]
    omega2: NDArray[np.float64]
    c: NDArray[np.float64]
    gamma: NDArray[np.float64]
    e: NDArray[np.float64]
    g0: NDArray[np.float64]
    g1: NDArray[np.float64]
    q_in: NDArray[np.float64]


def _symmetric(a: NDArray[np.float64], tol: float) -> bool:
    scale = float(np.abs(a).max()) if a.size else 0.0
    return bool(np.abs(a - a.T).max() <= tol * scale) if scale > 0.0 else True


def classical_modes(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                    tol: float = CLASSICAL_TOL
                    ) -> tuple[NDArray[np.float64], NDArray[np.float64],
                               NDArray[np.float64]] | None:
    """``(Ψ, ω², c)`` of a block with diagonal positive M, symmetric K and C and classical
    damping (every off-diagonal entry of ``Ψᵀ C Ψ`` at most ``tol`` times its largest
    diagonal one); None for any other block (which keeps the dense route).

    The modes solve ``M^{-½} K M^{-½} v = ω² v`` (a symmetric eigenproblem), ``Ψ = M^{-½} V``.
    """
    m = np.diag(M)
    if not all(np.all(np.isfinite(a)) for a in (M, C, K)):
        return None  # (the dense route says where the numbers overflow)
    if (np.count_nonzero(M - np.diag(m)) or not np.all(m > 0.0)
            or not _symmetric(K, tol) or not _symmetric(C, tol)):
        return None
    s = 1.0 / np.sqrt(m)
    ks = s[:, None] * K * s[None, :]
    try:
        _, v = np.linalg.eigh(0.5 * (ks + ks.T))
    except np.linalg.LinAlgError:
        return None
    psi = s[:, None] * v
    omega2 = _rayleigh_quotients(psi, K, m)
    cm = psi.T @ C @ psi
    diag = np.diag(cm).copy()
    scale = float(np.abs(diag).max())
    off = np.abs(cm - np.diag(diag))
    if scale > 0.0 and float(off.max()) > tol * scale:
        return None
    if scale == 0.0 and float(off.max()) > 0.0:
        return None
    return psi, omega2, diag


def _rayleigh_quotients(psi: NDArray[np.float64], K: NDArray[np.float64],
                        m: NDArray[np.float64]) -> NDArray[np.float64]:
    """``ω_j² = ψ_jᵀ K ψ_j / ψ_jᵀ M ψ_j`` summed in extended precision where the platform
    has it (``np.longdouble``). The symmetric eigensolver's ω² carry an absolute error
    ~ε‖K̃‖, relative ε ω_max²/ω_j² in the lowest modes (10⁻¹² for 100 storeys), a phase
    error that grows with time; the quotient of its eigenvectors (error ε ω_max²/gap) is
    second-order accurate in them, and summed in extended precision leaves ~10⁻¹⁵."""
    pl = psi.astype(np.longdouble)
    num = np.einsum("ij,ij->j", pl, K.astype(np.longdouble) @ pl)
    den = np.einsum("ij,i,ij->j", pl, m.astype(np.longdouble), pl)
    return np.asarray(num / den, dtype=np.float64)


def mode_steps(omega2: NDArray[np.float64], c: NDArray[np.float64],
               gamma: NDArray[np.float64], h: float
               ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64],
                          NDArray[np.float64]]:
    """Each mode's exact step ``(E, γ0, γ1)`` over h [s] with linear a_g and its input-energy
    form in ``[q, q̇, a0, a1]`` (shapes (n, 2, 2), (n, 2), (n, 2), (n, 4, 4)).

    Mode j's ``y = [q, q̇, a, ȧ]`` obeys ``ẏ = F y``, ``F = [[0, 1, 0, 0], [−ω², −c, −Γ, 0],
    [0, 0, 0, 1], [0, 0, 0, 0]]``: ``e^{Fh}`` holds E and the two input columns (γ1 = e₁₃/h,
    γ0 = e₁₂ − γ1, as :func:`pounding.integrate.propagator.compute_propagator`); the input
    power ``−Γ q̇ a`` is ``yᵀ W y`` and its integral ``y0ᵀ (∫ e^{Fᵀs} W e^{Fs} ds) y0`` the
    upper-right block of ``exp([[−Fᵀ, W], [0, F]] h)`` premultiplied by ``e^{Fh}ᵀ`` (Van Loan
    1978, §4; W scaled to F's size first, as
    :func:`pounding.integrate.propagator._van_loan_integral`)."""
    from scipy.linalg import expm

    nm = omega2.size
    f = np.zeros((nm, 4, 4))
    f[:, 0, 1] = 1.0
    f[:, 1, 0] = -omega2
    f[:, 1, 1] = -c
    f[:, 1, 2] = -gamma
    f[:, 2, 3] = 1.0
    e = expm(f * h)
    g1 = e[:, :2, 3] / h
    g0 = e[:, :2, 2] - g1
    w = np.zeros((nm, 4, 4))
    w[:, 1, 2] = w[:, 2, 1] = -0.5 * gamma
    wn = 0.5 * np.abs(gamma)
    fn = np.maximum(np.abs(f).max(axis=(1, 2)), 1.0 / h)
    scale = np.where(wn > 0.0, fn / np.where(wn > 0.0, wn, 1.0), 0.0)
    big = np.zeros((nm, 8, 8))
    big[:, :4, :4] = -np.transpose(f, (0, 2, 1))
    big[:, :4, 4:] = w * scale[:, None, None]
    big[:, 4:, 4:] = f
    eb = expm(big * h)
    integral = np.einsum("kji,kjl->kil", eb[:, 4:, 4:], eb[:, :4, 4:])
    integral /= np.where(scale > 0.0, scale, np.inf)[:, None, None]
    integral = 0.5 * (integral + np.transpose(integral, (0, 2, 1)))
    t = np.eye(4)  # [q, q̇, a, ȧ] = T [q, q̇, a0, a1]
    t[3, 2] = -1.0 / h
    t[3, 3] = 1.0 / h
    q_in = np.einsum("ji,kjl,lm->kim", t, integral, t)
    return np.ascontiguousarray(e[:, :2, :2]), g0, g1, q_in


def modal_block(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                r: NDArray[np.float64], h: float) -> ModalBlock | None:
    """The :class:`ModalBlock` of a block (M, C, K, influence vector ``r`` (n,) or (n, 1))
    for a step h [s], or None if its damping is not classical (:func:`classical_modes`) or
    it has more than one ground component."""
    rm = np.asarray(r, dtype=float).reshape(M.shape[0], -1)
    if rm.shape[1] != 1:
        return None
    modes = classical_modes(M, C, K)
    if modes is None:
        return None
    psi, omega2, c = modes
    gamma = psi.T @ (M @ rm[:, 0])
    e, g0, g1, q_in = mode_steps(omega2, c, gamma, h)
    return ModalBlock(psi, omega2, c, gamma, e, g0, g1, q_in)


def mode_table(mb: ModalBlock, M: NDArray[np.float64]) -> NDArray[np.float64]:
    """The rows the kernel reads for a modal block (:mod:`pounding.integrate.modal_steps`):
    row j = ``[ψ_j (n), (M ψ_j) (n), E_j, γ0_j, γ1_j, w0_j, w1_j]`` (:data:`MODE_E` … after
    the ``2 n`` shape entries; ``w = 2 Q[s, a]``, the linear input-energy terms)."""
    n = mb.psi.shape[0]
    table = np.zeros((n, 2 * n + TABLE))
    table[:, :n] = mb.psi.T
    table[:, n : 2 * n] = (M @ mb.psi).T
    t = table[:, 2 * n :]
    t[:, MODE_E : MODE_E + 4] = mb.e.reshape(n, 4)
    t[:, MODE_G0 : MODE_G0 + 2] = mb.g0
    t[:, MODE_G1 : MODE_G1 + 2] = mb.g1
    t[:, MODE_W0 : MODE_W0 + 2] = 2.0 * mb.q_in[:, :2, 2]
    t[:, MODE_W1 : MODE_W1 + 2] = 2.0 * mb.q_in[:, :2, 3]
    return table


def dense_forms(mb: ModalBlock, M: NDArray[np.float64]
                ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64],
                           NDArray[np.float64]]:
    """The block's dense propagator and input form from its modes: ``(Φ, γ0, γ1, Q_in)``
    as :func:`pounding.integrate.propagator.compute_propagator` and
    :func:`pounding.integrate.propagator.step_input_form` give them (γ's (2n,), Q_in
    (2n + 2, 2n + 2)), by ``x = S⁻¹ s`` with ``S⁻¹ = diag(Ψ, Ψ)``, ``S = diag(Ψᵀ M, Ψᵀ M)``."""
    psi = mb.psi
    n = psi.shape[0]
    left = psi.T @ M  # Ψᵀ M = Ψ⁻¹
    phi = np.empty((2 * n, 2 * n))
    for a in range(2):
        for b in range(2):
            phi[a * n : (a + 1) * n, b * n : (b + 1) * n] = (psi * mb.e[:, a, b]) @ left
    g0 = np.concatenate([psi @ mb.g0[:, 0], psi @ mb.g0[:, 1]])
    g1 = np.concatenate([psi @ mb.g1[:, 0], psi @ mb.g1[:, 1]])
    # Q_phys = S'ᵀ Q_modal S' with S' = diag(S, 1, 1); the modes' [s_j, s_j] blocks sit on
    # the diagonal of Q_modal, in the order [q (n), q̇ (n), a0, a1]
    qm = np.zeros((2 * n + 2, 2 * n + 2))
    idx = np.arange(n)
    for a in range(2):
        for b in range(2):
            qm[a * n + idx, b * n + idx] = mb.q_in[:, a, b]
        qm[a * n + idx, 2 * n :] = mb.q_in[:, a, 2:]
        qm[2 * n :, a * n + idx] = mb.q_in[:, 2:, a].T
    qm[2 * n :, 2 * n :] = mb.q_in[:, 2:, 2:].sum(axis=0)
    s = np.zeros((2 * n + 2, 2 * n + 2))
    s[:n, :n] = left
    s[n : 2 * n, n : 2 * n] = left
    s[2 * n, 2 * n] = s[2 * n + 1, 2 * n + 1] = 1.0
    q_in = s.T @ qm @ s
    return phi, g0, g1, 0.5 * (q_in + q_in.T)


class BlockForms(NamedTuple):
    """What :func:`pounding.integrate.propagator.compute_free_step` takes from a modal
    block: its dense forms (:func:`dense_forms`) and the kernel's table (:func:`mode_table`)."""

    phi: NDArray[np.float64]
    gamma0: NDArray[np.float64]
    gamma1: NDArray[np.float64]
    q_in: NDArray[np.float64]
    table: NDArray[np.float64]


def block_forms(M: NDArray[np.float64], C: NDArray[np.float64], K: NDArray[np.float64],
                r: NDArray[np.float64], h: float) -> BlockForms | None:
    """:class:`BlockForms` of a block whose damping is classical, else None
    (:func:`modal_block`). Computed with one BLAS thread: its products are small (n ≲ a few
    hundred), and on a busy 2-core machine a second thread's waiting made the 50-storey
    pair's set-up 30–60× slower (0.35–0.59 s against 8.5 ms, 2026-11-28 at load 9); one
    thread also makes the forms' bits the same whatever the machine's thread setting."""
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=1, user_api="blas"):
        mb = modal_block(M, C, K, r, h)
        if mb is None:
            return None
        phi, g0, g1, q_in = dense_forms(mb, M)
        return BlockForms(phi, g0, g1, q_in, mode_table(mb, M))
