"""One grid step taken by the adaptive integrator (regime 2 of
:mod:`pounding.integrate.kernel`): Dormand–Prince steps that land exactly on the grid point,
cut short at every located event, with states committed at each accepted step.

Step-size control is the elementary controller (``h ← h · min(5, max(0.2, 0.9 err^−1/5))``,
Hairer, Nørsett & Wanner I, §II.4); a step cut short by the grid does not shrink the
proposal, one cut by an event restarts from it, and the first step after a contact's onset
starts from the size the previous impact of that contact began with. The work is bounded:
the run stops (and reports why) when a step falls below 10⁻¹⁴ of the grid step or the
number of RK steps exceeds its budget (``ws_i[I_STEP_BUDGET]``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.codes import V0
from pounding.devices.laws import DEVICE_MIN
from pounding.hysteresis.base import D_C, V_C
from pounding.integrate.commit import commit_contacts, commit_storeys
from pounding.integrate.dormand_prince import rk_step, weighted_sum
from pounding.integrate.events import (
    event_tolerance,
    event_value,
    find_event,
    hinge_start,
    hinge_step_end,
    is_upward,
    locate,
)
from pounding.integrate.exact_links import rows_allow_exact
from pounding.integrate.frame_outputs import frame_outputs
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
    EV_DRIFT_MAX,
    EV_DRIFT_MIN,
    EV_GRAZE,
    EV_HINGE_HI,
    EV_HINGE_TURN_UP,
    EV_ONSET,
    EV_SEPARATION,
    EV_TAUT,
    EV_YIELD,
    FAIL_BUDGET,
    FAIL_NONFINITE,
    FAIL_UNDERFLOW,
    I_CALL_STEPS,
    I_FAIL_STEP,
    I_FAILED,
    I_NEVENTS,
    I_NREJECT,
    I_NSTEPS,
    I_ONSET_C,
    I_STEP_BUDGET,
    I_STOP,
    I_STOP_ROW,
    P_CONTACT,
    P_DAMP,
    P_DEVICE,
    P_INPUT,
    P_STOREY,
    PK_A,
    STOP_HINGE,
    W_E_DAMP,
    W_E_DEVICE,
    W_E_INPUT,
    W_E_STOREY,
    W_ERR_OLD,
    W_H,
    W_RESUME_S,
)
from pounding.integrate.peaks import track_point, track_step
from pounding.integrate.rhs import (
    G_A0,
    G_A1,
    G_END,
    G_NOW,
    G_SLOPE,
    INLINE,
    NRT_FREE,
    add_ground_rest,
    band_mv,
    deriv_call,
    gap_row,
    ground_at,
    ground_at_grid_end,
    jerk,
    law_call,
    recoverable_call,
    stored_call,
)

# per-contact memory (columns of last_f)
LF_TIME, LF_FORCE, LF_RATE, LF_ONSET_STEP, LF_GRAZED = range(5)


@njit(**NRT_FREE)
def adaptive_run(k, k1, run, km, graze_tol, st, out, sc):
    """Grid steps from k with adaptive RK steps and events, writing the outputs of each,
    while a contact is closed (or to ``k1`` if not ``run.exact``). The model's arrays
    ``km``, the run's inputs, state, outputs and scratch as in
    :func:`pounding.integrate.kernel.integrate_chunk`; ``graze_tol`` [m]: how near zero an
    open gap's peak must come to be located. At entry ``sc.kx`` (row 0) holds f(x) at
    ``ag[k]`` (``ag``: (nt, G), the ground components on the grid; ``gnd``: (G_ROWS, G)
    scratch, :data:`pounding.integrate.rhs.G_A0` …); on return x, ``kx``, ``arel0``, ``gd``
    and ``gr`` are those of the grid point reached (``jk``, ``jk1``: scratch for jerks).

    Returns the grid point reached, or −1 if the integration failed (``ws_i[I_FAILED]``
    says why); also returns at the first grid point after ``ws_i[I_CALL_STEPS]`` RK steps
    in all. One call for a whole contact episode.

    A yielding frame's hinge event ends the call right after the step to it is accepted
    (``ws_i[I_STOP] = STOP_HINGE``, the hinge row in ``ws_i[I_STOP_ROW]``), for Python to
    give the frame its next configuration: the grid step in progress is returned, and the
    local time reached in it left in ``ws_f[W_RESUME_S]``, where the next call resumes
    (at the grid point's end, the grid step is finished first and 0 is left there).
    """
    fl, ct, el, hg = km.floors, km.contacts, km.elements, km.hinges
    dt = run.dt
    ag = run.ag
    rtol = run.rtol
    atol = run.atol
    h_max = run.h_max
    r = fl.r
    below = fl.below
    cdof, cw, cgap, _, cparams = ct
    x = st.x
    committed = st.committed
    sstate = st.storeys
    wc = st.contact_work
    last_f = st.last_force
    ws_f = st.ws_f
    ws_i = st.ws_i
    pk = out.peaks
    kx, px, ks, ps, ks_b, ps_b, ytmp, y1, yb = (sc.kx, sc.px, sc.ks, sc.ps, sc.ks_b, sc.ps_b,
                                                sc.ytmp, sc.y1, sc.yb)
    lin, work, arel0, jk, jk1, aabs0, aabs1, gd, gr, gnd = (sc.lin, sc.work, sc.arel0, sc.jk,
                                                            sc.jk1, sc.aabs0, sc.aabs1, sc.gd,
                                                            sc.gr, sc.gnd)
    n = r.shape[0]
    m = x.shape[0]
    nc = cgap.shape[0]
    ns = el.lo.shape[0]
    npw = P_CONTACT + nc
    stop_at_grid = False
    # the hinge rows' θ, θ̇ at x are in their HS_TH0 / HS_R0 (find_event); False at entry:
    # Python may have given a frame its next configuration
    hinges_at_x = False
    while k < k1:
        # ---------------- grid step k → k + 1: RK steps landing on t_k + dt
        t_k = k * dt
        for g in range(gnd.shape[1]):
            gnd[G_A0, g] = ag[k, g]
            gnd[G_A1, g] = ag[k + 1, g]
            gnd[G_SLOPE, g] = (gnd[G_A1, g] - gnd[G_A0, g]) / dt
        a0 = ag[k, 0]
        s = ws_f[W_RESUME_S]
        h = min(ws_f[W_H], dt, h_max)
        if s > 0.0:
            # resumed inside the grid step after a hinge event (kx: f there)
            ws_f[W_RESUME_S] = 0.0
            ground_at(gnd, G_NOW, s)
            for i in range(n):
                aabs0[i] = kx[0, n + i] + r[i, 0] * gnd[G_NOW, 0]
            add_ground_rest(aabs0, r, gnd, G_NOW, n)
        else:
            for i in range(n):
                aabs0[i] = kx[0, n + i] + r[i, 0] * a0
            add_ground_rest(aabs0, r, ag, k, n)
        while s < dt:
            last = False
            if s + h >= dt * (1.0 - 1e-12):
                h = dt - s
                last = True
            if last:
                ground_at_grid_end(gnd, G_END)
            else:
                ground_at(gnd, G_END, s + h)
            err = rk_step(x, kx, px, h, gnd, s, fl, ct, el, committed, sstate, lin, ks, ps,
                          ytmp, y1, atol, rtol)
            ws_i[I_NSTEPS] += 1
            if ws_i[I_NSTEPS] > ws_i[I_STEP_BUDGET]:
                ws_i[I_FAILED] = FAIL_BUDGET
                ws_i[I_FAIL_STEP] = k
                return -1
            if err > 1.0 or not np.isfinite(err):
                ws_i[I_NREJECT] += 1
                fac = 0.9 * err ** -0.2 if np.isfinite(err) else 0.1
                h *= max(0.1, fac)
                ws_f[W_H] = h
                if h < 1e-14 * dt:
                    # (a step that is not a finite number however short: the state or the
                    # forces overflow)
                    ws_i[I_FAILED] = FAIL_UNDERFLOW if np.isfinite(err) else FAIL_NONFINITE
                    ws_i[I_FAIL_STEP] = k
                    return -1
                continue
            # events inside the accepted step?
            h_try = h
            fac_try = min(5.0, max(0.2, 0.9 * err ** -0.2)) if err > 0.0 else 5.0
            h_acc = h
            # a contact found, on real steps, not to touch is not searched again until it
            # recedes (its rate negative at a step's start)
            for c in range(nc):
                if last_f[c, LF_GRAZED] != 0.0 and gap_row(c, x, n, cdof, cw)[1] < 0.0:
                    last_f[c, LF_GRAZED] = 0.0
            # (the literals −1 and 0 give find_event a compiled version of its own here,
            # unlike the typed constants of layout; np.int64(−1) and np.int64(0) instead
            # change the last bits of some runs, through the compiler's fused multiply-adds)
            if not hinges_at_x:
                hinge_start(x, n, hg)
                hinges_at_x = True
            te, ce, kind = find_event(x, kx, y1, ks, h, n, ct, el, hg, committed, -1, 0,
                                      graze_tol, last_f[:, LF_GRAZED])
            searched_y1 = True  # (the hinges' θ, θ̇ at y1 are in HS_TH1 / HS_R1)
            ev_c = -1
            ev_kind = 0
            h_before = h_acc
            false_events = 0
            while ce >= 0:
                if ws_i[I_NSTEPS] > ws_i[I_STEP_BUDGET]:
                    ws_i[I_FAILED] = FAIL_BUDGET
                    ws_i[I_FAIL_STEP] = k
                    return -1
                # locate on real RK steps by the Illinois method, keeping the 'after' side
                g_lo = event_value(kind, ce, x, n, ct, el, hg)
                g_hi = event_value(kind, ce, y1, n, ct, el, hg)
                upward = is_upward(kind)
                lo = 0.0
                hi = h_acc
                side_ok = (g_hi > 0.0) if upward else (g_hi <= 0.0)
                if kind == EV_SEPARATION and g_hi == 0.0:
                    side_ok = True
                found_hi = side_ok
                if not side_ok:
                    # grazing: both ends on the 'before' side; test the estimate
                    ground_at(gnd, G_END, s + te)
                    err = rk_step(x, kx, px, te, gnd, s, fl, ct, el, committed, sstate, lin,
                                  ks_b, ps_b, ytmp, yb, atol, rtol)
                    ws_i[I_NSTEPS] += 1
                    g_te = event_value(kind, ce, yb, n, ct, el, hg)
                    if (g_te > 0.0) == upward and g_te != 0.0:
                        hi = te
                        g_hi = g_te
                        found_hi = True
                if not found_hi:
                    # the interpolant's crossing was not real: any other event in the step
                    # (once; after a located event the search already skips that one)
                    if ev_c >= 0 or false_events > 0:
                        break
                    false_events += 1
                    te, ce, kind = find_event(x, kx, y1, ks, h_acc, n, ct, el, hg, committed, ce,
                                              kind, graze_tol, last_f[:, LF_GRAZED])
                    searched_y1 = True
                    continue
                t_try = te if (te > lo and te < hi) else 0.5 * (lo + hi)
                g_tol = event_tolerance(kind, ce, n, cparams, atol, hg.state)
                h_acc, err = locate(kind, ce, lo, hi, g_lo, g_hi, t_try, g_tol, dt, x, kx, px,
                                    gnd, s, fl, ct, el, hg, committed, sstate, lin, ks, ps,
                                    ks_b, ps_b, ytmp, y1, yb, atol, rtol, ws_i)
                searched_y1 = False
                if kind == EV_GRAZE:
                    # the step now ends at the peak of the gap's penetration: closed there?
                    d_peak = gap_row(ce, y1, n, cdof, cw)[0] - cgap[ce]
                    if d_peak > 0.0:
                        # yes: the gap closed before the peak; locate that onset in (0, h_acc]
                        g_lo = gap_row(ce, x, n, cdof, cw)[0] - cgap[ce]
                        h_acc, err = locate(EV_ONSET, ce, 0.0, h_acc, g_lo, d_peak,
                                            0.5 * h_acc, event_tolerance(EV_ONSET, ce, n,
                                                                         cparams, atol,
                                                                         hg.state),
                                            dt, x, kx, px, gnd, s, fl, ct, el, hg,
                                            committed, sstate, lin, ks, ps, ks_b, ps_b, ytmp,
                                            y1, yb, atol, rtol, ws_i)
                        kind = EV_ONSET
                        searched_y1 = False
                    else:
                        # no: accept the step to the peak, and do not search this gap again
                        # until it recedes
                        last_f[ce, LF_GRAZED] = 1.0
                        ws_i[I_NEVENTS] += 1
                ev_c = ce
                ev_kind = kind
                last = False
                if h_acc >= h_before:
                    # Two events closer than the time resolution (contacts touching at
                    # once from rest at a zero gap): locating one no longer shortens the
                    # step. Accept it; a contact it leaves open but penetrated starts its
                    # impact at the step's end (commit_contacts).
                    break
                h_before = h_acc
                # any other event earlier in this shorter step?
                te, ce, kind = find_event(x, kx, y1, ks, h_acc, n, ct, el, hg, committed, ev_c,
                                          ev_kind, graze_tol, last_f[:, LF_GRAZED])
                searched_y1 = True
            if ev_kind == EV_GRAZE:
                ev_c = -1  # nothing happened at the peak of a gap that stayed open
                ev_kind = 0
            # ---- accept the step [s, s + h_acc]
            ws_f[W_ERR_OLD] = max(err, 1e-4)
            onset_c = ws_i[I_ONSET_C]
            if onset_c >= 0:
                # the first step accepted after this contact's onset: where the next onset of
                # the contact will start (no rejections from a free-flight step)
                last_f[onset_c, LF_ONSET_STEP] = h_acc
                ws_i[I_ONSET_C] = -1
            ws_f[W_E_INPUT] += weighted_sum(ps, P_INPUT, h_acc)
            ws_f[W_E_DAMP] += weighted_sum(ps, P_DAMP, h_acc)
            if ns > 0:
                ws_f[W_E_STOREY] += weighted_sum(ps, P_STOREY, h_acc)
                ws_f[W_E_DEVICE] += weighted_sum(ps, P_DEVICE, h_acc)
            for c in range(nc):
                wc[c] += weighted_sum(ps, P_CONTACT + c, h_acc)
            s_new = dt if last else s + h_acc
            t_now = t_k + s_new
            if last:
                ground_at_grid_end(gnd, G_NOW)
            else:
                ground_at(gnd, G_NOW, s_new)
            a_now = gnd[G_NOW, 0]
            # peaks over the step, from both ends (the states of its start still committed)
            for i in range(n):
                aabs1[i] = ks[6, n + i] + r[i, 0] * a_now
            add_ground_rest(aabs1, r, gnd, G_NOW, n)
            # (the jerk at both ends only where an acceleration comes within half of its
            # peak so far: an error-controlled step is a small fraction of the fastest
            # period, so its interior cannot rise that far above its ends)
            near = False
            for i in range(n):
                lim = 0.5 * pk[i, PK_A]
                if abs(aabs0[i]) >= lim or abs(aabs1[i]) >= lim:
                    near = True
            if near:
                jerk(x, kx[0], fl, ct, el, committed, sstate, lin, work, jk)
                jerk(y1, ks[6], fl, ct, el, committed, sstate, lin, work, jk1)
            track_step(t_k + s, h_acc, n, below, x, kx[0, n:], aabs0, jk, y1, ks[6, n:], aabs1,
                       jk1, pk, near)
            for i in range(m):
                x[i] = y1[i]
            if searched_y1:
                hinge_step_end(hg)  # (the next step starts where this one ended)
            else:
                hinges_at_x = False
            if ns > 0:
                commit_storeys(x, n, el, sstate)
            was_event = ev_c >= 0
            hinge_event = EV_HINGE_HI <= ev_kind <= EV_HINGE_TURN_UP
            if (ev_kind == EV_DRIFT_MAX or ev_kind == EV_DRIFT_MIN or hinge_event
                    or EV_TAUT <= ev_kind <= EV_YIELD):  # (a restrainer's corner)
                ws_i[I_NEVENTS] += 1
                if hinge_event:
                    ws_i[I_STOP_ROW] = ev_c
                ev_c = -1  # a storey or a hinge, not a contact: the contact loop must not
                ev_kind = 0  # see it
            # commit contact states at the step end; handle the event
            state_changed = commit_contacts(x, ks[6], t_now, ev_c, ev_kind, n, ct, st, out)
            if state_changed:
                deriv_call(x, x, gnd, fl, ct, el, committed, sstate, lin, kx, px, 0)
                for i in range(n):
                    aabs0[i] = kx[0, n + i] + r[i, 0] * a_now
                add_ground_rest(aabs0, r, gnd, G_NOW, n)
            else:
                for i in range(m):
                    kx[0, i] = ks[6, i]
                for i in range(npw):
                    px[0, i] = ps[6, i]
                for i in range(n):
                    aabs0[i] = aabs1[i]
            if was_event:
                # a corner or a jump of the acceleration: its values at the event (after a jump,
                # also just before it: the step's end value)
                track_point(t_now, n, below, x, aabs1, pk)
                if state_changed:
                    track_point(t_now, n, below, x, aabs0, pk)
            # next step size; a step cut short by the grid does not shrink the proposal, one
            # cut by an event restarts from it
            if was_event:
                ws_f[W_H] = h_try
                if ev_kind == EV_ONSET:
                    ws_i[I_ONSET_C] = ev_c
                    if last_f[ev_c, LF_ONSET_STEP] > 0.0:
                        ws_f[W_H] = min(h_try, last_f[ev_c, LF_ONSET_STEP])
            elif last:
                ws_f[W_H] = max(ws_f[W_H], h_acc * fac_try)
            else:
                ws_f[W_H] = h_acc * fac_try
            h = min(ws_f[W_H], h_max)
            s = s_new
            if hinge_event:
                # back to Python, which moves the frame's hinges and gives it its next
                # configuration; the next call resumes here
                if s < dt:
                    ws_i[I_STOP] = STOP_HINGE
                    ws_f[W_RESUME_S] = s
                    return k
                stop_at_grid = True
        for i in range(n):
            arel0[i] = kx[0, n + i]
        grid_outputs(k + 1, ag, x, kx, fl, ct, el, hg, st, out, lin)
        # every entry of the state, and every work integrated, is in one of the energies:
        # one test a grid step that none stopped being a finite number
        e_sum = 0.0
        for col in range(out.energy.shape[1]):
            e_sum += out.energy[k + 1, col]
        if not abs(e_sum) < np.inf:
            ws_i[I_FAILED] = FAIL_NONFINITE
            ws_i[I_FAIL_STEP] = k
            return -1
        k += 1
        if stop_at_grid:
            ws_i[I_STOP] = STOP_HINGE  # (the event at the grid point: resume there)
            break
        if run.exact and not any_closed(committed) and rows_allow_exact(x, n, el):
            break  # back to exact stepping once every contact is open (and restrainer slack)
        if ws_i[I_NSTEPS] >= ws_i[I_CALL_STEPS]:
            break  # this call's share of RK steps is done: back to the caller
    for c in range(cgap.shape[0]):
        dsum, gr[c] = gap_row(c, x, r.shape[0], cdof, cw)
        gd[c] = dsum - cgap[c]
    return k


@njit(**INLINE)
def grid_outputs(o, ag, x, kx, fl, ct, el, hg, st, out, lin):
    """Write the outputs of grid point ``o`` (ground components ``ag[o]``) from the state
    ``x`` and ``kx = f(x)`` after an adaptive grid step (the model's floors, contacts and
    element rows ``fl``, ``ct``, ``el``, its hinge rows ``hg``; the run's state ``st`` and
    outputs ``out``)."""
    r = fl.r
    m_diag = fl.m_diag
    cdof, cw, cgap, ccode, cparams = ct
    s_lo, s_code, s_par, s_zi = el.lo, el.code, el.params, el.z_index
    committed = st.committed
    sstate = st.storeys
    wc = st.contact_work
    ws_f = st.ws_f
    u_out, v_out, acc_out, pen_out, f_out, vs_out, e_out = out[:7]
    n = r.shape[0]
    band_mv(fl.k_band, fl.c_band, x, n, fl.bw, lin)
    a_o = ag[o, 0]
    for i in range(n):
        u_out[o, i] = x[i]
        v_out[o, i] = x[n + i]
        acc_out[o, i] = kx[0, n + i] + r[i, 0] * a_o
    add_ground_rest(acc_out[o], r, ag, o, n)
    ek = 0.0
    es = 0.0
    for i in range(n):
        ek += 0.5 * m_diag[i] * x[n + i] * x[n + i]
        es += 0.5 * x[i] * lin[0, i]
    recov = 0.0
    recov_dev = 0.0
    for q in range(s_lo.shape[0]):
        vs_out[o, q] = sstate[q, V_C]
        if s_par[q, EL_FOLDED] != 0.0:
            continue  # (a linear link in K: its spring's energy is in es)
        zi = s_zi[q]
        e_q = recoverable_call(s_code[q], s_par, q, sstate[q, D_C],
                               x[2 * n + zi] if zi >= 0 else 0.0, sstate[q, V_C])
        if s_code[q] >= DEVICE_MIN:
            recov_dev += e_q
        else:
            recov += e_q
    wsum = 0.0
    stored = 0.0
    for c in range(cgap.shape[0]):
        dsum, rate = gap_row(c, x, n, cdof, cw)
        delta = dsum - cgap[c]
        pen_out[o, c] = delta
        f = 0.0
        if committed[c, V0] > 0.0:
            f = law_call(ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2], delta, rate,
                         committed[c, V0], committed[c, 1], committed[c, 2])[0]
            stored += stored_call(ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2],
                                  delta, committed[c, 1])
        f_out[o, c] = f
        wsum += wc[c]
    e_hinge = 0.0
    if fl.f_rows.shape[0] > 0:
        # (called, not inlined: inlined, its loops cost the SDOF pair's contact steps 5 %)
        e_frame, e_hinge = frame_outputs(o, x, n, fl, hg, out.hinge_rotation,
                                         out.hinge_moment)
        es += e_frame
    e_out[o, E_INPUT] = ws_f[W_E_INPUT]
    e_out[o, E_KINETIC] = ek
    e_out[o, E_STRAIN] = es + recov + recov_dev
    e_out[o, E_DAMPING] = ws_f[W_E_DAMP]
    e_out[o, E_CONTACT_WORK] = wsum
    e_out[o, E_CONTACT_STORED] = stored
    e_out[o, E_HYSTERETIC] = ws_f[W_E_STOREY] - recov
    if fl.f_rows.shape[0] > 0:
        e_out[o, E_HYSTERETIC] += e_hinge
    e_out[o, E_DEVICE] = ws_f[W_E_DEVICE] - recov_dev


@njit(**NRT_FREE)
def any_closed(committed):
    """True while any contact is closed."""
    for c in range(committed.shape[0]):
        if committed[c, V0] > 0.0:
            return True
    return False
