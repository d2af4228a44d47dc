"""Exact grid steps of uncoupled floors (a row of one-storey buildings) while every gap is
open: :func:`pounding.integrate.exact_steps.free_run`'s loop for the one model shape where
every floor is a block of its own — no band (``bw = 0``), no modal or Maxwell block, one
ground component, no element row (no link, no restrainer) — and the only path that shape
takes.

The same arithmetic as the generic loop, expression by expression (so the same bits), in a
function whose loop holds only what this shape needs: numba's generic loop keeps every
block kind's arrays and flags live across the step, and the shape's step is a few
multiplications a floor. The energies that stay constant while every gap is open (contact
work and stored energy, the storeys' hysteretic energy) are written once the run of exact
steps ends, as a contiguous fill of their columns, instead of step by step.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.integrate.events import touch_possible
from pounding.integrate.exact_links import floor_rel_acc
from pounding.integrate.layout import (
    E_CONTACT_STORED,
    E_CONTACT_WORK,
    E_DAMPING,
    E_HYSTERETIC,
    E_INPUT,
    E_KINETIC,
    E_STRAIN,
    PK_A,
    ROW_BLOCK,
    W_E_DAMP,
    W_E_INPUT,
    W_E_STOREY,
    W_PEAK_MARGIN,
)
from pounding.integrate.peaks import track_uncoupled_step
from pounding.integrate.rhs import INLINE, NRT_FREE, gap_row


@njit(**INLINE)
def is_uncoupled(blk, fmodal, mxb, frows, n, bw, ng, ns):
    """Does the exact step's model have the shape :func:`uncoupled_run` steps: every floor a
    block of its own (of the plain form: not modal, no Maxwell link, no link's dissipation
    rows), K and C diagonal, one ground component, no element row?"""
    if blk.shape[0] - 1 != n or bw != 0 or ng != 1 or ns != 0:
        return False
    for b in range(n):
        if fmodal[b] != 0 or mxb[b, 0] > 0 or frows[b] > 4:
            return False
    return True


@njit(**NRT_FREE)
def fill_constant_energies(e_out, o0, o1, wsum, e_h):
    """Rows ``o0 … o1 − 1`` of the energies that do not change while every gap is open and
    every storey is linear: the contact work ``wsum``, the contacts' stored energy (zero) and
    the storeys' hysteretic energy ``e_h`` (each column contiguous: a fill)."""
    for o in range(o0, o1):
        e_out[o, E_CONTACT_WORK] = wsum
    for o in range(o0, o1):
        e_out[o, E_CONTACT_STORED] = 0.0
    for o in range(o0, o1):
        e_out[o, E_HYSTERETIC] = e_h


@njit(**NRT_FREE)
def search_peaks(steps, nq, k_entry, x0, n, dt, keep, u_out, v_out, acc_out, ag, fl, pk):
    """The peaks of the exact steps listed in ``steps[:nq]`` (``k n + i``: floor i's step
    from grid point k, in the order taken), each examined as :func:`_uncoupled_steps`'
    test asks (its velocity changes sign, or an end's acceleration comes within the margin
    ``1 − keep`` of the peak so far): the test again, with the peaks found since, then
    :func:`pounding.integrate.peaks.track_uncoupled_step`. The step's start from the
    outputs, or from ``x0``, the state at grid point ``k_entry``, where the run began."""
    for q in range(nq):
        k = steps[q] // n
        i = steps[q] - k * n
        if k == k_entry:
            u0 = x0[i]
            v0 = x0[n + i]
        else:
            u0 = u_out[k, i]
            v0 = v_out[k, i]
        o = k + 1
        v = v_out[o, i]
        aa = acc_out[o, i]
        lim = keep * pk[i, PK_A]
        if ((v0 > 0.0) != (v > 0.0)) | (abs(aa) >= lim) | (abs(acc_out[k, i]) >= lim):
            track_uncoupled_step(k * dt, dt, i, u0, v0, acc_out[k, i], u_out[o, i], v, aa, ag,
                                 k, fl.r, fl.k_band[0, i], fl.c_band[0, i], fl.m_inv[i], pk)


@njit(**NRT_FREE)
def uncoupled_run(k, k1, run, fl, ct, fs, graze_tol, st, out, sc):
    """:func:`pounding.integrate.exact_steps.free_run` for uncoupled floors
    (:func:`is_uncoupled`): the same arguments (no element rows), the same return value
    and outputs, bit for bit. The floors' peaks are searched in batches
    (:func:`search_peaks`) of the steps a cheap test flags, listed in ``sc.peak_steps``, so
    that the loop calls nothing while no gap nears closing; ``sc.work`` keeps the state the
    run began from."""
    dt = run.dt
    ag = run.ag
    fops, g0, g1, faa = fs[1], fs[2], fs[3], fs[4]
    k_band = fl.k_band
    c_band = fl.c_band
    m_diag = fl.m_diag
    m_inv = fl.m_inv
    cdof = ct.dof
    cw = ct.weight
    cgap = ct.gap
    x = st.x
    ws_f = st.ws_f
    x1, gd, gr, gd1, gr1 = sc.x1, sc.gd, sc.gr, sc.gd1, sc.gr1
    u_out, v_out, acc_out, pen_out = out.u, out.v, out.acc, out.pen
    e_out = out.energy
    pk = out.peaks
    n = m_diag.shape[0]
    nc = cgap.shape[0]
    e_in = ws_f[W_E_INPUT]
    e_d = ws_f[W_E_DAMP]
    e_prev = e_out[k, E_KINETIC] + e_out[k, E_STRAIN]
    keep = 1.0 - ws_f[W_PEAK_MARGIN]
    faa0 = faa[0, 0, 0]
    faa1 = faa[1, 0, 0]
    faa2 = faa[2, 0, 0]
    k_entry = k
    wsum = 0.0  # contact work does not change while every gap is open
    for c in range(nc):
        wsum += st.contact_work[c]
    x0 = sc.work
    for i in range(2 * n):
        x0[i] = x[i]
    flagged = sc.peak_steps
    full = flagged.shape[0] - n  # (room for one more step's floors)
    nq = 0
    res = k1
    while k < k1:
        if nq > 0:
            search_peaks(flagged, nq, k_entry, x0, n, dt, keep, u_out, v_out, acc_out, ag, fl,
                         pk)
            nq = 0
        while k < k1 and nq <= full:
            a0 = ag[k, 0]
            a1 = ag[k + 1, 0]
            lin_i0 = 0.0
            lin_i1 = 0.0
            for p in range(n):
                # (exact_steps.one_floor_step)
                u = x[p]
                v = x[n + p]
                x1[p] = g0[p, 0] * a0 + g1[p, 0] * a1 + fops[p, 0] * u + fops[n + p, 0] * v
                x1[n + p] = (g0[n + p, 0] * a0 + g1[n + p, 0] * a1 + fops[p, 1] * u
                             + fops[n + p, 1] * v)
                w0 = fops[p, 2] * u + fops[n + p, 2] * v
                w1 = fops[p, 3] * u + fops[n + p, 3] * v
                lin_i0 += w0
                lin_i1 += w1
            # could any gap close at the step end, or come within graze_tol of closing
            # inside it? (free_run's test)
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
                    if touch_possible(gd[c], gr[c], q0, d1, r1, q1, dt, graze_tol):
                        touch = True
                        break
            if touch:
                res = k
                break
            # input energy over the step: an exact quadratic form
            e_step = (a0 * lin_i0 + a1 * lin_i1
                      + (faa0 * a0 * a0 + faa1 * a0 * a1 + faa2 * a1 * a1))
            e_step += 0.0  # (free_run's other ground components: none)
            e_in += e_step
            o = k + 1
            ek = 0.0
            es = 0.0
            for i in range(n):
                # (free_run's loop for bw = 0)
                kk = k_band[0, i]
                cc = c_band[0, i]
                mi = m_inv[i]
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
                # the step's peaks are searched later (search_peaks) if its velocity
                # changes sign or an end's acceleration comes within the margin of the
                # peak so far (the search, finding more, only raises the peak)
                lim = keep * pk[i, PK_A]
                if ((v0 > 0.0) != (v > 0.0)) | (abs(aa) >= lim) | (abs(acc_out[k, i]) >= lim):
                    flagged[nq] = k * n + i
                    nq += 1
            e_d += e_step - ((ek + es) - e_prev)
            e_prev = ek + es
            if not abs(e_d) < np.inf:
                res = -(k + 1)
                break
            for c in range(nc):
                gd[c] = gd1[c]
                gr[c] = gr1[c]
                pen_out[o, c] = gd1[c]
            e_out[o, E_INPUT] = e_in
            e_out[o, E_KINETIC] = ek
            e_out[o, E_STRAIN] = es
            e_out[o, E_DAMPING] = e_d
            k += 1
        if res != k1:
            break
    search_peaks(flagged, nq, k_entry, x0, n, dt, keep, u_out, v_out, acc_out, ag, fl, pk)
    ws_f[W_E_INPUT] = e_in
    ws_f[W_E_DAMP] = e_d
    # the rows written: up to grid point k (a step that could close a gap, or stopped by a
    # value not finite, writes no energy)
    fill_constant_energies(e_out, k_entry + 1, k + 1, wsum, ws_f[W_E_STOREY])
    return res
