"""Exact grid steps while every gap is open (regime 1 of :mod:`pounding.integrate.kernel`).

With every contact open and every storey linear, the structure is linear and the ground
acceleration is linear over a grid step, so the step is taken with the exact propagator of
:mod:`pounding.integrate.propagator` (``x ← Φ x + Γ0 a_k + Γ1 a_{k+1}``, Γ0 and Γ1 of shape
(2N, G) for the G ground components), block by block (the buildings are uncoupled while the
gaps are open). The input energy over the step is an exact quadratic form in
``(x, a_k, a_{k+1})`` (Van Loan integral), evaluated in the same sweep over the operator's
columns as Φ x (the first ground component; the others after, :func:`ground_rest_step`);
the viscous work of the step is the input work less the change of kinetic and strain
energy, exactly. A block tied by linear Maxwell links carries their springs' deformations in
its state (:mod:`pounding.integrate.exact_maxwell`): their forces join the floors'
accelerations, their springs' energy the strain energy, their dashpots' the links' energy.

After each step every gap is checked for closing at the step end and inside it, from the
quintic Hermite of its ``(δ, δ̇, δ̈)`` at both ends (:func:`pounding.integrate.events.
touch_possible`): a gap that could come within the event tolerance of closing hands the
step to the adaptive integrator, which locates the touch — or finds there is none — on
real steps. So whether a grazing approach is an impact does not depend on the output step.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.devices.laws import device_trial
from pounding.hysteresis.base import V_C
from pounding.integrate.events import touch_possible
from pounding.integrate.exact_links import (
    block_link_work,
    floor_rel_acc,
    ground_quadratic,
    restrainer_taut_possible,
    two_floor_link_step,
)
from pounding.integrate.exact_maxwell import (
    acc_peak_between_maxwell,
    is_linear_maxwell,
    maxwell_block_step,
    maxwell_copy_z,
    maxwell_floor_force,
    maxwell_outputs,
    maxwell_stored,
    track_exact_step_maxwell,
)
from pounding.integrate.layout import (
    E_CONTACT_STORED,
    E_CONTACT_WORK,
    E_DAMPING,
    E_DEVICE,
    E_HYSTERETIC,
    E_INPUT,
    E_KINETIC,
    E_STRAIN,
    EL_FOLDED,
    PK_A,
    ROW_BLOCK,
    W_E_DAMP,
    W_E_DEVICE,
    W_E_INPUT,
    W_E_STOREY,
    W_PEAK_MARGIN,
)
from pounding.integrate.modal_steps import modal_block_step, modal_commit, modal_enter
from pounding.integrate.peaks import (
    acc_peak_between,
    track_exact_step,
    track_uncoupled_step,
)
from pounding.integrate.rhs import NRT_FREE, band_products, gap_row


@njit(**NRT_FREE)
def one_floor_step(p, n, x, x1, fops, g0, g1, a0, a1):
    """The exact step of a one-floor block p (the block sweep of :func:`free_run`, written
    out) under the first ground component: writes ``x1[p]``, ``x1[n + p]``; returns the
    block's two input-energy terms of that component."""
    u = x[p]
    v = x[n + p]
    x1[p] = g0[p, 0] * a0 + g1[p, 0] * a1 + fops[p, 0] * u + fops[n + p, 0] * v
    x1[n + p] = g0[n + p, 0] * a0 + g1[n + p, 0] * a1 + fops[p, 1] * u + fops[n + p, 1] * v
    return (fops[p, 2] * u + fops[n + p, 2] * v, fops[p, 3] * u + fops[n + p, 3] * v)


@njit(**NRT_FREE)
def ground_rest_step(k, n, ag, blk, fops, g0, g1, faa, x, x1):
    """The ground components after the first over the exact step from grid point k:
    adds ``Γ0[:, g] a_k,g + Γ1[:, g] a_k+1,g`` to ``x1`` and returns their input energy
    over the step (the linear terms ``w_in · z`` of each block, and every term of the
    quadratic form in the grid values that involves one of them). Nothing for G = 1."""
    ng = g0.shape[1]
    e = 0.0
    for g in range(1, ng):
        b0 = ag[k, g]
        b1 = ag[k + 1, g]
        for i in range(2 * n):
            x1[i] += g0[i, g] * b0 + g1[i, g] * b1
        for b in range(blk.shape[0] - 1):
            p = blk[b]
            nb = blk[b + 1] - p
            col = 2 * nb + 2 * g
            for j in range(nb):
                u = x[p + j]
                v = x[n + p + j]
                e += ((fops[p + j, col] * u + fops[n + p + j, col] * v) * b0
                      + (fops[p + j, col + 1] * u + fops[n + p + j, col + 1] * v) * b1)
    for g in range(ng):
        for q in range(ng):
            if g + q > 0:
                e += (faa[0, g, q] * ag[k, g] * ag[k, q] + faa[1, g, q] * ag[k, g] * ag[k + 1, q]
                      + faa[2, g, q] * ag[k + 1, g] * ag[k + 1, q])
    return e


@njit(**NRT_FREE)
def free_run(k, k1, run, fl, ct, el, fs, graze_tol, st, out, sc):
    """Exact grid steps from grid point ``k`` while every gap stays open, writing the
    outputs and peaks of each; returns the grid point whose step could close a gap (that
    step not taken: the caller re-takes it with RK) or ``k1``, or ``−(k + 1)`` if the step
    from grid point k left the state or the input energy not finite (a stiffness, mass or
    record value far outside any building's: checked once a step, on the viscous work,
    which sums every entry of the state and the input).

    A small function of its own, so that its loop compiles tight. ``sc.gd``, ``sc.gr``:
    every contact's δ and δ̇ at grid point k (updated as the steps go); ``graze_tol`` [m]:
    how near zero a gap's peak inside a step must come to hand the step over; the model's
    floors ``fl`` and contacts ``ct``, the exact step ``fs``, the run's inputs, state,
    outputs and scratch as in :func:`pounding.integrate.kernel.integrate_chunk` (``x1``,
    ``acc``, ``lin``, ``gd1``, ``gr1``: scratch). Peaks: uncoupled floors compute their
    jerk with the outputs (two multiplications); coupled floors test the samples of |ü|
    and compute the jerk only beside a sampled peak
    (:func:`pounding.integrate.peaks.acc_peak_between`).
    """
    dt = run.dt
    ag = run.ag
    blk, fops, g0, g1, faa, frows, dev_aa, fmodal, fmodes, mxb = fs
    bw = fl.bw
    k_band = fl.k_band
    c_band = fl.c_band
    m_diag = fl.m_diag
    m_inv = fl.m_inv
    r = fl.r
    below = fl.below
    cdof = ct.dof
    cw = ct.weight
    cgap = ct.gap
    x = st.x
    wc = st.contact_work
    ws_f = st.ws_f
    x1, acc, lin, gd, gr, gd1, gr1 = sc.x1, sc.acc, sc.lin, sc.gd, sc.gr, sc.gd1, sc.gr1
    u_out, v_out, acc_out, pen_out = out.u, out.v, out.acc, out.pen
    e_out = out.energy
    pk = out.peaks
    n = m_diag.shape[0]
    nc = cgap.shape[0]
    nblk = blk.shape[0] - 1
    k_entry = k
    e_in = ws_f[W_E_INPUT]
    e_d = ws_f[W_E_DAMP]
    e_h = ws_f[W_E_STOREY]
    e_dev = ws_f[W_E_DEVICE]
    s_lo, s_hi, s_code, s_par = el.lo, el.hi, el.code, el.params
    sstate = st.storeys
    vs_out = out.element_force
    ns = s_lo.shape[0]
    # blocks whose columns hold the dissipation form of links' dashpots folded into C
    links_dissipate = False
    # blocks whose state holds linear Maxwell links' spring deformations
    # (pounding.integrate.exact_maxwell): their force and springs' energy in the outputs
    has_mx = False
    for b in range(nblk):
        if frows[b] > 2 * (blk[b + 1] - blk[b]) + 2:
            links_dissipate = True
        if mxb[b, 0] > 0:
            has_mx = True
    mx_stored = maxwell_stored(x, n, el) if has_mx else 0.0
    # blocks stepped in modal coordinates (modal_steps): their modal state, unless the
    # last call of this run left it at grid point k (the state then unchanged since), from
    # the floors' state
    qm = sc.modal
    any_modal = False
    for b in range(nblk):
        if fmodal[b] != 0:
            any_modal = True
    if any_modal and qm[0, n] != k:
        for b in range(nblk):
            if fmodal[b] != 0:
                modal_enter(blk[b], blk[b + 1] - blk[b], x, fmodes, qm)
    qm[0, n] = -1.0
    e_prev = e_out[k, E_KINETIC] + e_out[k, E_STRAIN]
    wsum = 0.0  # contact work does not change while every gap is open
    for c in range(nc):
        wsum += wc[c]
    ng = g0.shape[1]
    while k < k1:
        # the first ground component in the block sweep, the others after it
        # (ground_rest_step)
        a0 = ag[k, 0]
        a1 = ag[k + 1, 0]
        # block by block (FreeStep): acc = [Φ_b z, w_in · z] in one sweep over the
        # columns of the block operator (each row accumulates in a fixed order)
        lin_i0 = 0.0
        lin_i1 = 0.0
        e_links = 0.0
        if nblk == n and not any_modal:
            # every floor a block of its own (a row of SDOF oscillators): no block loop
            for i in range(n):
                w0, w1 = one_floor_step(i, n, x, x1, fops, g0, g1, a0, a1)
                lin_i0 += w0
                lin_i1 += w1
        else:
            for b in range(nblk):
                p = blk[b]
                nb = blk[b + 1] - p
                if fmodal[b] != 0:
                    w0, w1 = modal_block_step(p, nb, fmodes, qm, x1, a0, a1)
                    lin_i0 += w0
                    lin_i1 += w1
                    continue
                if nb == 1:
                    w0, w1 = one_floor_step(p, n, x, x1, fops, g0, g1, a0, a1)
                    lin_i0 += w0
                    lin_i1 += w1
                    continue
                nb2 = 2 * nb
                rows = frows[b]
                if has_mx and mxb[b, 0] > 0:
                    w0, w1, e_b = maxwell_block_step(b, p, nb, n, mxb, el, x, x1, acc, fops,
                                                     g0, g1, a0, a1)
                    lin_i0 += w0
                    lin_i1 += w1
                    e_links += e_b
                    continue
                if nb == 2 and rows == 12 and ng == 1:
                    # (a linked pair of one-storey buildings: written out)
                    w0, w1, e_b = two_floor_link_step(p, n, x, x1, fops, g0, g1, a0, a1)
                    lin_i0 += w0
                    lin_i1 += w1
                    e_links += e_b
                    continue
                for ir in range(nb):
                    acc[ir] = g0[p + ir, 0] * a0 + g1[p + ir, 0] * a1
                    acc[nb + ir] = g0[n + p + ir, 0] * a0 + g1[n + p + ir, 0] * a1
                for ir in range(nb2, rows):
                    acc[ir] = 0.0
                # columns of floor j's displacement and velocity together; the loop over rows
                # vectorises without reassociation
                for j in range(nb):
                    xu = x[p + j]
                    xv = x[n + p + j]
                    for ir in range(rows):
                        acc[ir] = acc[ir] + fops[p + j, ir] * xu + fops[n + p + j, ir] * xv
                for ir in range(nb):
                    x1[p + ir] = acc[ir]
                    x1[n + p + ir] = acc[nb + ir]
                lin_i0 += acc[nb2]
                lin_i1 += acc[nb2 + 1]
                if rows > nb2 + 2:
                    e_links += block_link_work(p, nb, n, ng, x, acc, ag, k)
        e_rest = 0.0
        if ng > 1:
            e_rest = ground_rest_step(k, n, ag, blk, fops, g0, g1, faa, x, x1)
        # could any gap close at the step end, or come within graze_tol of closing inside
        # it? Then the step is not taken. (A cheap bound on the cubic through δ, δ̇ first;
        # the quintic through δ, δ̇, δ̈ only where that cannot rule a touch out.)
        touch = False
        for c in range(nc):
            ds1, r1 = gap_row(c, x1, n, cdof, cw)
            d1 = ds1 - cgap[c]
            gd1[c] = d1
            gr1[c] = r1
            if d1 > 0.0 or max(gd[c], d1) + 0.25 * dt * (abs(gr[c]) + abs(r1)) > -graze_tol:
                q0 = 0.0
                q1 = 0.0
                for qb in range(0, cdof.shape[1], ROW_BLOCK):
                    for q in range(qb, qb + ROW_BLOCK):
                        j = cdof[c, q]
                        q0 += cw[c, q] * floor_rel_acc(j, x, ag, k, n, fl)
                        q1 += cw[c, q] * floor_rel_acc(j, x1, ag, k + 1, n, fl)
                        if has_mx:
                            q0 -= cw[c, q] * maxwell_floor_force(j, x, n, el) * m_inv[j]
                            q1 -= cw[c, q] * maxwell_floor_force(j, x1, n, el) * m_inv[j]
                if touch_possible(gd[c], gr[c], q0, d1, r1, q1, dt, graze_tol):
                    touch = True
                    break
        # a slack restrainer whose slack could be taken up: the same (its force, zero
        # while slack, is not in the exact step; none beside Maxwell links)
        if not touch and not has_mx:
            for q in range(ns):
                if s_par[q, EL_FOLDED] == 0.0 and restrainer_taut_possible(q, x, x1, n, k, ag,
                                                                            fl, el, dt,
                                                                            graze_tol):
                    touch = True
                    break
        if touch:
            ws_f[W_E_INPUT] = e_in
            ws_f[W_E_DAMP] = e_d
            ws_f[W_E_DEVICE] = e_dev
            if (bw != 0 or has_mx) and k - 1 >= k_entry:
                # the last exact step's acceleration peaks, whose test needed the sample
                # after it
                for i in range(n):
                    if has_mx:
                        acc_peak_between_maxwell(i, k - 1, k, (k - 1) * dt, dt, ag, v_out,
                                                 acc_out, vs_out, fl, el, pk)
                    else:
                        acc_peak_between(i, k - 1, k, (k - 1) * dt, dt, ag, v_out, acc_out,
                                         fl, pk)
            return k
        if any_modal:  # (the step is taken)
            for b in range(nblk):
                if fmodal[b] != 0:
                    modal_commit(blk[b], blk[b + 1] - blk[b], qm)
        # input energy over the step: an exact quadratic form
        e_step = (a0 * lin_i0 + a1 * lin_i1
                  + (faa[0, 0, 0] * a0 * a0 + faa[1, 0, 0] * a0 * a1 + faa[2, 0, 0] * a1 * a1))
        e_step += e_rest
        e_in += e_step
        if links_dissipate:
            e_links += ground_quadratic(dev_aa, ag, k)
        # outputs at grid point k + 1: no contact force, no yielding storey, so the absolute
        # acceleration is ü + r a_g = −M⁻¹(K u + C u̇); and the peaks over the step: a
        # floor's step is examined only where its velocity or drift rate changes sign, or
        # its acceleration comes within the margin of its peak so far
        # (pounding.integrate.peaks), the jerk being −M⁻¹(K u̇ + C ü)
        o = k + 1
        t0 = k * dt
        keep = 1.0 - ws_f[W_PEAK_MARGIN]
        ek = 0.0
        es = 0.0
        if bw == 0 and not has_mx:
            # no floor coupled to another (a row of SDOF oscillators, each a building of
            # one storey): floor by floor, without the generic band loops, and every value
            # at the step's start recomputed from its outputs rather than kept in scratch
            for i in range(n):
                kk = k_band[0, i]
                cc = c_band[0, i]
                mi = m_inv[i]
                u0 = x[i]
                v0 = x[n + i]
                u = x1[i]
                v = x1[n + i]
                ku = kk * u
                aa = -(ku + cc * v) * mi
                u_out[o, i] = u
                v_out[o, i] = v
                acc_out[o, i] = aa
                ek += 0.5 * m_diag[i] * v * v
                es += 0.5 * u * ku
                x[i] = u
                x[n + i] = v
                # peaks: where the velocity changes sign (displacement = drift of a one-storey
                # building), or an end's acceleration comes within the margin of the peak
                # so far (nothing between two samples further below can beat it)
                lim = keep * pk[i, PK_A]
                if ((v0 > 0.0) != (v > 0.0)) | (abs(aa) >= lim) | (abs(acc_out[k, i]) >= lim):
                    track_uncoupled_step(t0, dt, i, u0, v0, acc_out[k, i], u, v, aa, ag, k,
                                         r, kk, cc, mi, pk)
        else:
            band_products(k_band, c_band, x1, n, bw, lin)
            mx_stored1 = maxwell_outputs(x1, n, el, lin, vs_out, o) if has_mx else 0.0
            for i in range(n):
                u = x1[i]
                v = x1[n + i]
                aa = -(lin[0, i] + lin[1, i]) * m_inv[i]
                u_out[o, i] = u
                v_out[o, i] = v
                acc_out[o, i] = aa
                ek += 0.5 * m_diag[i] * v * v
                es += 0.5 * u * lin[0, i]
            # the peaks: displacement and drift where the velocity or the drift rate changes
            # sign; acceleration where |a| peaks among the samples k − 1, k, k + 1 within
            # the margin of the peak so far (its extremum then lies in one of the two steps
            # beside k, where the jerk is computed from the outputs: for coupled floors a
            # banded product). The tests first, in a loop without calls or branches; the
            # rare floors they flag after.
            km1 = k - 1 if k >= 1 else 0
            anyhit = 0.0
            for i in range(n):
                v0 = x[n + i]
                v = x1[n + i]
                lo = below[i]
                vlo0 = x[n + lo] if lo >= 0 else 0.0
                vlo1 = x1[n + lo] if lo >= 0 else 0.0
                ak = abs(acc_out[k, i])
                hit = (((v0 > 0.0) != (v > 0.0)) | ((v0 - vlo0 > 0.0) != (v - vlo1 > 0.0))
                       | ((ak >= abs(acc_out[km1, i])) & (ak >= abs(acc_out[o, i]))
                          & (ak >= keep * pk[i, PK_A]) & (ak > 0.0) & (k >= 1)))
                flag = 1.0 if hit else 0.0
                acc[i] = flag
                anyhit += flag
            if anyhit > 0.0:
                for i in range(n):
                    if acc[i] != 0.0:
                        if has_mx:
                            track_exact_step_maxwell(t0, dt, i, k, k_entry, fl, el, x, x1, ag,
                                                     v_out, acc_out, vs_out, pk)
                        else:
                            track_exact_step(t0, dt, i, k, k_entry, fl, x, x1, ag, v_out,
                                             acc_out, pk)
            for i in range(2 * n):
                x[i] = x1[i]
            if has_mx:
                # the links' springs: their energy is strain energy, and their work since the
                # step's start (the dashpot's share apart) is the links' too
                maxwell_copy_z(x, x1, n, el)
                es += mx_stored1
                e_dev += mx_stored1 - mx_stored
                mx_stored = mx_stored1
        if ns > 0:
            # the links' forces: those folded into K and C their law's ``k d + c ḋ`` at the
            # step's end (as the adaptive steps commit it), any other row its committed
            # force (a slack restrainer's zero); written out here, where a call cost the
            # SDOF pair's linked exact steps more than the rest of them
            for q in range(ns):
                if has_mx and is_linear_maxwell(el, q):
                    continue  # (its force k z written with the accelerations)
                if s_par[q, EL_FOLDED] != 0.0:
                    lo = s_lo[q]
                    hi = s_hi[q]
                    vs_out[o, q] = device_trial(s_code[q], s_par[q, 0], s_par[q, 1],
                                                s_par[q, 2], s_par[q, 3], x1[hi] - x1[lo],
                                                x1[n + hi] - x1[n + lo], 0.0)[0]
                else:
                    vs_out[o, q] = sstate[q, V_C]
        # nothing but the viscous dampers takes energy out (every gap open, linear
        # storeys): the step's viscous work is the input work less the change of kinetic
        # and strain energy, exactly — the links' dashpots' share of it their own
        e_d += e_step - ((ek + es) - e_prev)
        if links_dissipate:
            e_d -= e_links
            e_dev += e_links
        e_prev = ek + es
        if not abs(e_d) < np.inf:
            # the state (every entry of it is in ek + es) or the input stopped being a
            # finite number: stop here (the caller reports it)
            ws_f[W_E_INPUT] = e_in
            ws_f[W_E_DAMP] = e_d
            ws_f[W_E_DEVICE] = e_dev
            return -(k + 1)
        for c in range(nc):
            gd[c] = gd1[c]
            gr[c] = gr1[c]
            pen_out[o, c] = gd1[c]
        # (f_out[o] stays as allocated, zero: its pages are not even touched while every
        # gap is open, and writing the outputs is about half of an exact step's cost)
        e_out[o, E_INPUT] = e_in
        e_out[o, E_KINETIC] = ek
        e_out[o, E_STRAIN] = es
        e_out[o, E_DAMPING] = e_d
        e_out[o, E_CONTACT_WORK] = wsum
        e_out[o, E_CONTACT_STORED] = 0.0
        e_out[o, E_HYSTERETIC] = e_h
        if ns > 0:
            # (a slack restrainer's cables hold nothing; a Maxwell link's spring holds the
            # part of its work that is not yet dissipated)
            e_out[o, E_DEVICE] = e_dev - mx_stored if has_mx else e_dev
        k += 1
    ws_f[W_E_INPUT] = e_in
    ws_f[W_E_DAMP] = e_d
    ws_f[W_E_DEVICE] = e_dev
    if any_modal:
        qm[0, n] = k  # (the modal state is that of grid point k: the next call goes on)
    return k
