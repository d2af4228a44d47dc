"""Committing contact and storey states at accepted steps (the trial/commit contract of
:mod:`pounding.contact.base` and :mod:`pounding.hysteresis.base`), and the impact table.

A law's state changes only here: at the end of an accepted adaptive step, and at a located
event — contact onset (``v0`` committed at the located instant, contract step 3), separation
(the impact's row closed: end time, restitution, dissipated energy), a clipped law's release
(its impact's end and restitution; the force evaluated again on the new branch) or engaging
again, a shear key breaking off (its impact's end; its force zero from there, and its gap
closing again no impact), or an ordinary step
through a contact (the law's trial state committed; the largest force inside the step taken
from the cubic Hermite of the force and its rate at the step's two ends, with its time).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.codes import DMAX, SLIP, STATE_SIZE, V0, V0_MIN
from pounding.contact.dispatch import is_broken, keeps_set
from pounding.hysteresis.base import D_C, V_C
from pounding.integrate.events import hermite_max
from pounding.integrate.layout import (
    EV_ONSET,
    EV_REENGAGE,
    EV_RELEASE,
    EV_SEPARATION,
    I_NEVENTS,
    I_NIMP,
    I_OVERFLOW,
    IMP_CONTACT,
    IMP_DMAX,
    IMP_E,
    IMP_END,
    IMP_ENERGY,
    IMP_PEAK,
    IMP_PEAK_TIME,
    IMP_START,
    IMP_V0,
    ROW_BLOCK,
)
from pounding.integrate.rhs import INLINE, element_drift, gap_row, law_call, storey_call


@njit(**INLINE)
def commit_storeys(x, n, el, sstate):
    """Commit every element row's (yielding storey's, link's) drift and force at state x
    (contract step 3 of :mod:`pounding.hysteresis.base`)."""
    s_lo, s_hi, s_code, s_par, s_zi = el.lo, el.hi, el.code, el.params, el.z_index
    for q in range(s_lo.shape[0]):
        d, dr = element_drift(q, s_lo[q], s_hi[q], s_par, x, n)
        zi = s_zi[q]
        sstate[q, V_C] = storey_call(s_code[q], s_par, q, d, dr,
                                     x[2 * n + zi] if zi >= 0 else 0.0,
                                     sstate[q, D_C], sstate[q, V_C])[0]
        sstate[q, D_C] = d


@njit(**INLINE)
def commit_contacts(x, dx, t_now, ev_c, ev_kind, n, ct, st, out):
    """Commit every contact's state at the end of an accepted step (state ``x``, ``dx =
    f(x)`` with the states of the step's start) at time ``t_now`` [s], handling the event
    ``(ev_c, ev_kind)`` that ended the step, if any: the contacts ``ct``, the run's state
    ``st`` and outputs ``out`` (:mod:`pounding.integrate.workspace`). Returns True if a
    contact opened, closed, or changed the branch of a clipped law (f must then be evaluated
    again)."""
    cdof, cw, cgap, ccode, cparams = ct
    committed = st.committed
    wc = st.contact_work
    w_start = st.work_at_onset
    imp_row = st.impact_row
    last_f = st.last_force
    ws_i = st.ws_i
    imp = out.impacts
    cpeak = out.peak_force
    cpeak_t = out.peak_force_time
    ccount = out.impact_count
    nc = cgap.shape[0]
    cap = imp.shape[0]
    state_changed = False
    for c in range(nc):
        dsum, rate = gap_row(c, x, n, cdof, cw)
        delta = dsum - cgap[c]
        if is_broken(ccode[c], committed[c, SLIP]) and committed[c, V0] == 0.0:
            continue  # a broken-off shear key: its gap closing again is no impact
        if (c == ev_c and ev_kind == EV_ONSET) or (committed[c, V0] == 0.0 and delta > 0.0):
            # contact onset (contract step 3): commit v0 at the located instant (or at the
            # end of a step whose other event, closer than the time resolution, ended it
            # with this gap already closed)
            committed[c, V0] = max(rate, V0_MIN)
            if not keeps_set(ccode[c]):  # (the abutment's backfill keeps its set)
                committed[c, SLIP] = 0.0
            committed[c, DMAX] = max(delta, 0.0)
            state_changed = True
            f0 = law_call(ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2],
                          max(delta, 1e-300), rate, committed[c, V0], committed[c, SLIP],
                          committed[c, DMAX])[0]
            row = ws_i[I_NIMP]
            if row < cap:
                imp[row, IMP_CONTACT] = c
                imp[row, IMP_START] = t_now
                imp[row, IMP_END] = np.nan
                imp[row, IMP_V0] = committed[c, V0]
                imp[row, IMP_PEAK] = f0
                imp[row, IMP_PEAK_TIME] = t_now
                imp[row, IMP_DMAX] = 0.0
                imp[row, IMP_E] = np.nan
                imp[row, IMP_ENERGY] = np.nan
                imp_row[c] = row
            else:
                ws_i[I_OVERFLOW] = 1
                imp_row[c] = -1
            ws_i[I_NIMP] += 1
            ccount[c] += 1
            if f0 > cpeak[c]:
                cpeak[c] = f0
                cpeak_t[c] = t_now
            w_start[c] = wc[c]
            last_f[c, 0] = t_now
            last_f[c, 1] = f0
            # dF/dt at δ = 0+ can be unbounded (Hertz-type laws): no interior peak is sought
            # in the first step, whose end value is kept instead
            last_f[c, 2] = np.nan
            ws_i[I_NEVENTS] += 1
        elif committed[c, V0] > 0.0:
            if (c == ev_c and ev_kind == EV_SEPARATION) or (c != ev_c and delta < 0.0
                                                            and rate < 0.0):
                # separation: close the impact's row, open the state. A contact other than
                # the step's event contact found parted at the step's end parted at the same
                # instant (within the event tolerance): were it earlier, it would have been
                # the event. (Two contacts that part together: the two corners of a floor
                # in plan, for one.)
                row = imp_row[c]
                if row >= 0:
                    if np.isnan(imp[row, IMP_END]):  # (not already ended by a release)
                        imp[row, IMP_END] = t_now
                        imp[row, IMP_E] = max(-rate, 0.0) / committed[c, V0]
                    imp[row, IMP_ENERGY] = wc[c] - w_start[c]
                imp_row[c] = -1
                kept = committed[c, SLIP] if keeps_set(ccode[c]) else 0.0
                for q in range(STATE_SIZE):
                    committed[c, q] = 0.0
                committed[c, SLIP] = kept  # a permanent set outlasts its impact
                state_changed = True
                ws_i[I_NEVENTS] += 1
            else:
                f, kd, kr, tv0, tslip, tdmax = law_call(
                    ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2], delta, rate,
                    committed[c, V0], committed[c, SLIP], committed[c, DMAX])
                # a shear key that breaks off here (at its located event, EV_FRACTURE):
                # its force drops to zero, its impact ends
                was_broken = is_broken(ccode[c], committed[c, SLIP])
                broke = is_broken(ccode[c], tslip) and not was_broken
                committed[c, V0] = tv0
                committed[c, SLIP] = tslip
                committed[c, DMAX] = tdmax
                # force rate at the step end, then the largest force inside the step from
                # the cubic Hermite of (F, dF/dt) at its two ends
                rel_acc = 0.0
                for q0 in range(0, cdof.shape[1], ROW_BLOCK):
                    for q in range(q0, q0 + ROW_BLOCK):
                        rel_acc += cw[c, q] * dx[n + cdof[c, q]]
                df1 = kd * rate + kr * rel_acc
                h = t_now - last_f[c, 0]
                fin, where = hermite_max(last_f[c, 1], last_f[c, 2], f, df1, h)
                if keeps_set(ccode[c]) and fin > cparams[c, 1]:
                    # the backfill's force has a kink where it meets its backbone (a
                    # plateau at the capacity): the cubic overshoots it, the force cannot
                    fin = cparams[c, 1]
                fmax = f
                t_max = t_now
                if fin > f:
                    fmax = fin
                    t_max = last_f[c, 0] + where * h
                if fmax > cpeak[c]:
                    cpeak[c] = fmax
                    cpeak_t[c] = t_max
                row = imp_row[c]
                if row >= 0 and not was_broken:  # (past its break a key's impact is over)
                    if delta > imp[row, IMP_DMAX]:
                        imp[row, IMP_DMAX] = delta
                    if fmax > imp[row, IMP_PEAK]:
                        imp[row, IMP_PEAK] = fmax
                        imp[row, IMP_PEAK_TIME] = t_max
                last_f[c, 0] = t_now
                last_f[c, 1] = f
                last_f[c, 2] = df1
                if broke:
                    state_changed = True
                    last_f[c, 1] = 0.0  # (from here on the key pushes nothing)
                    last_f[c, 2] = 0.0
                    if row >= 0 and np.isnan(imp[row, IMP_END]):
                        imp[row, IMP_END] = t_now
                if ev_c == c:
                    ws_i[I_NEVENTS] += 1
                    if ev_kind == EV_RELEASE or ev_kind == EV_REENGAGE:
                        # the clipped law changes branch here: f evaluated again on it.
                        # Its impact ends where the force does (the bodies part with the
                        # spring still compressed, as in the collision analysis), unless
                        # it engages again before δ = 0
                        state_changed = True
                        if row >= 0:
                            released = ev_kind == EV_RELEASE
                            imp[row, IMP_END] = t_now if released else np.nan
                            imp[row, IMP_E] = (max(-rate, 0.0) / committed[c, V0] if released
                                               else np.nan)
    return state_changed
