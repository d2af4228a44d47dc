"""The exact steps' share of the element rows (:mod:`pounding.integrate.exact_steps`): links
folded into K and C, whose dashpots' dissipated energy each step gives apart, and cable
restrainers, stepped exactly while slack; and the floors' accelerations the exact steps'
event tests read.

A link whose law is linear and has no internal variable is part of the linear structure
(:func:`pounding.integrate.kernel_model.fold_linear_links`): the buildings it ties step as one
block of the exact propagator, whose columns also hold the links' dissipation form
(:class:`pounding.integrate.propagator.FreeStep`; :func:`block_link_work`,
:func:`two_floor_link_step` for a linked pair of one-storey buildings). A slack restrainer
exerts no force; its slack being taken up is tested after every exact step as a gap's
closing is (:func:`restrainer_taut_possible`), and the adaptive steps hand back to the
exact ones only where every row allows it (:func:`rows_allow_exact`).
"""

from __future__ import annotations

from numba import njit

from pounding.devices.laws import MAXWELL, RESTRAINER
from pounding.integrate.events import touch_possible
from pounding.integrate.layout import EL_FOLDED
from pounding.integrate.rhs import INLINE, NRT_FREE, ground_rest


@njit(**NRT_FREE)
def floor_rel_acc(j, y, ag, kg, n, fl):
    """Relative acceleration of floor j at state y (grid point kg of the ground components
    ``ag``) with every gap open and every storey linear: ``−(K u + C u̇)_j / m_j −
    Σ_g R_jg a_g`` (row j of the banded products of the floors ``fl``)."""
    bw = fl.bw
    s = 0.0
    for d in range(2 * bw + 1):
        col = j + d - bw
        if 0 <= col < n:
            s += fl.k_band[d, j] * y[col] + fl.c_band[d, j] * y[n + col]
    kb, cb = fl.k_band, fl.c_band
    for q in range(n, kb.shape[1]):  # (the entries outside the band)
        if int(kb[0, q]) == j:
            col = int(kb[1, q])
            s += kb[2, q] * y[col] + cb[2, q] * y[n + col]
    return -s * fl.m_inv[j] - fl.r[j, 0] * ag[kg, 0] - ground_rest(fl.r, j, ag, kg)


@njit(**INLINE)
def two_floor_link_step(p, n, x, x1, fops, g0, g1, a0, a1):
    """The exact step of a block of two floors tied by links whose dashpots dissipate (a
    linked pair of one-storey buildings) under one ground component, written out: writes
    ``x1`` of its floors; returns its two input-energy terms and the energy its links'
    dashpots dissipate over the step, less the ground's own terms (those of
    :func:`block_link_work`). The block sweep's twelve rows (:class:`pounding.integrate.
    propagator.FreeStep`), each a sum of four products; a third of the generic sweep's
    time for this block."""
    u0 = x[p]
    u1 = x[p + 1]
    v0 = x[n + p]
    v1 = x[n + p + 1]
    for ir in range(2):
        x1[p + ir] = (g0[p + ir, 0] * a0 + g1[p + ir, 0] * a1 + fops[p, ir] * u0
                      + fops[p + 1, ir] * u1 + fops[n + p, ir] * v0 + fops[n + p + 1, ir] * v1)
        x1[n + p + ir] = (g0[n + p + ir, 0] * a0 + g1[n + p + ir, 0] * a1
                          + fops[p, 2 + ir] * u0 + fops[p + 1, 2 + ir] * u1
                          + fops[n + p, 2 + ir] * v0 + fops[n + p + 1, 2 + ir] * v1)
    r = (fops[p, 4] * u0 + fops[p + 1, 4] * u1 + fops[n + p, 4] * v0
         + fops[n + p + 1, 4] * v1)
    s = (fops[p, 5] * u0 + fops[p + 1, 5] * u1 + fops[n + p, 5] * v0
         + fops[n + p + 1, 5] * v1)
    e = (u0 * (fops[p, 6] * u0 + fops[p + 1, 6] * u1 + fops[n + p, 6] * v0
               + fops[n + p + 1, 6] * v1)
         + u1 * (fops[p, 7] * u0 + fops[p + 1, 7] * u1 + fops[n + p, 7] * v0
                 + fops[n + p + 1, 7] * v1)
         + v0 * (fops[p, 8] * u0 + fops[p + 1, 8] * u1 + fops[n + p, 8] * v0
                 + fops[n + p + 1, 8] * v1)
         + v1 * (fops[p, 9] * u0 + fops[p + 1, 9] * u1 + fops[n + p, 9] * v0
                 + fops[n + p + 1, 9] * v1))
    e += (fops[p, 10] * u0 + fops[p + 1, 10] * u1 + fops[n + p, 10] * v0
          + fops[n + p + 1, 10] * v1) * a0
    e += (fops[p, 11] * u0 + fops[p + 1, 11] * u1 + fops[n + p, 11] * v0
          + fops[n + p + 1, 11] * v1) * a1
    return r, s, e


@njit(**INLINE)
def block_link_work(p, nb, n, ng, x, acc, ag, k):
    """The energy the links' dashpots folded into C dissipate over the exact step from grid
    point k in the block of floors ``p … p + nb − 1``, less its terms in the ground alone
    (:func:`ground_quadratic` of ``dev_aa``): ``zᵀ (Q_xx z) + Σ_g (2 Q_x,a0,g · z) a0_g +
    (2 Q_x,a1,g · z) a1_g`` from the block's sweep ``acc``
    (:class:`pounding.integrate.propagator.FreeStep`)."""
    nb2 = 2 * nb
    q = nb2 + 2 * ng  # where the dissipation form's numbers start
    e = 0.0
    for j in range(nb):
        e += x[p + j] * acc[q + j] + x[n + p + j] * acc[q + nb + j]
    for g in range(ng):
        e += acc[q + nb2 + 2 * g] * ag[k, g] + acc[q + nb2 + 2 * g + 1] * ag[k + 1, g]
    return e


@njit(**INLINE)
def ground_quadratic(qa, ag, k):
    """``Σ_gq qa[0,g,q] a0_g a0_q + qa[1,g,q] a0_g a1_q + qa[2,g,q] a1_g a1_q`` of the ground
    components at grid points k and k + 1."""
    e = 0.0
    ng = qa.shape[1]
    for g in range(ng):
        for q in range(ng):
            e += (qa[0, g, q] * ag[k, g] * ag[k, q] + qa[1, g, q] * ag[k, g] * ag[k + 1, q]
                  + qa[2, g, q] * ag[k + 1, g] * ag[k + 1, q])
    return e


@njit(**NRT_FREE)
def rows_allow_exact(y, n, el):
    """True if every element row lets the structure be linear at state y: a link folded
    into K and C, a linear Maxwell link (:mod:`pounding.integrate.exact_maxwell`; a model
    has exact steps with one only if it has no restrainer,
    :attr:`pounding.integrate.kernel_model.KernelModel.exact_allowed`), or a cable
    restrainer that is slack (its elastic elongation ``e = d − s₀ − z ≤ 0``: no force;
    :func:`pounding.devices.laws.restrainer_kinks`). A restrainer's
    slack taken up is then an event like a gap closing: the exact steps hand the step to
    the adaptive integrator (:func:`free_run`), which returns to them once every contact is
    open and every restrainer slack again."""
    par = el.params
    for s in range(el.lo.shape[0]):
        if par[s, EL_FOLDED] != 0.0:
            continue
        if el.code[s] == MAXWELL and par[s, 2] == 1.0:
            continue  # (a linear Maxwell link: its spring in the exact steps' state)
        if el.code[s] != RESTRAINER:
            return False
        lo = el.lo[s]
        d = y[el.hi[s]] - (y[lo] if lo >= 0 else 0.0)
        if d - par[s, 1] - y[2 * n + el.z_index[s]] > 0.0:
            return False
    return True


@njit(**INLINE)
def restrainer_taut_possible(s, x, x1, n, k, ag, fl, el, dt, graze_tol):
    """Can restrainer row s take up its slack inside the exact step from grid point k
    (state x) to k + 1 (x1)? :func:`pounding.integrate.events.touch_possible` of its
    elastic elongation ``e = d − s₀ − z`` (z, its plastic elongation, is constant while
    it is slack), its rate and acceleration at both ends — the test every gap takes."""
    par = el.params
    lo = el.lo[s]
    hi = el.hi[s]
    slack = par[s, 1] + x[2 * n + el.z_index[s]]
    e0 = x[hi] - x[lo] - slack
    e1 = x1[hi] - x1[lo] - slack
    r0 = x[n + hi] - x[n + lo]
    r1 = x1[n + hi] - x1[n + lo]
    if not (e1 > 0.0 or max(e0, e1) + 0.25 * dt * (abs(r0) + abs(r1)) > -graze_tol):
        return False
    q0 = floor_rel_acc(hi, x, ag, k, n, fl) - floor_rel_acc(lo, x, ag, k, n, fl)
    q1 = floor_rel_acc(hi, x1, ag, k + 1, n, fl) - floor_rel_acc(lo, x1, ag, k + 1, n, fl)
    return touch_possible(e0, r0, q0, e1, r1, q1, dt, graze_tol)
