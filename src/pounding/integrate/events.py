"""Events inside steps: where a gap closes or opens, where a closed contact turns from
approach to restitution, where a yielding storey's drift reverses, where an open gap comes
within the tolerance of closing; and the largest value of an interpolant inside a step
(peak contact forces, peak responses).

Events are first estimated from Hermite interpolants of each event function over the step
(:func:`find_event`), then located on actual Runge–Kutta steps by the Illinois method
(:func:`locate`): the step is re-taken to the estimated instant, the bracket shrunk, until
the event function is within :data:`~pounding.integrate.layout.EVENT_TOL` absolute
tolerances of zero on the 'after' side. The step the kernel accepts then ends exactly at the
event, so no step ever straddles a change of a contact's status or branch.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.codes import SLIP, V0
from pounding.contact.dispatch import (
    can_break,
    fracture_value,
    is_broken,
    law_releases,
    release_value,
)
from pounding.devices.laws import (
    DEVICE_MIN,
    RESTRAINER,
    has_rate_cusp,
    restrainer_kinks,
)
from pounding.integrate.dormand_prince import rk_step
from pounding.integrate.layout import (
    EL_LEVER,
    EL_ROCK,
    EV_DRIFT_MAX,
    EV_DRIFT_MIN,
    EV_FRACTURE,
    EV_GRAZE,
    EV_HINGE_HI,
    EV_HINGE_LO,
    EV_HINGE_TURN_DOWN,
    EV_HINGE_TURN_UP,
    EV_MAX_COMPRESSION,
    EV_ONSET,
    EV_REENGAGE,
    EV_RELEASE,
    EV_RELOADING,
    EV_SEPARATION,
    EV_SLACK,
    EV_TAUT,
    EV_YIELD,
    EVENT_TOL,
    HS_DIR,
    HS_HI,
    HS_LO,
    HS_R0,
    HS_R1,
    HS_TH0,
    HS_TH1,
    HS_WABS,
    I_NSTEPS,
    ROW_BLOCK,
)
from pounding.integrate.rhs import (
    G_END,
    NRT_FREE,
    element_drift,
    gap_row,
    ground_at,
    hinge_row,
)

UPWARD, DOWNWARD = np.bool_(True), np.bool_(False)
"""Directions of a crossing, NumPy booleans: numba would compile :func:`hermite_root` once
for each literal ``True`` and ``False`` (see the event kinds of
:mod:`pounding.integrate.layout`)."""


@njit(**NRT_FREE)
def hermite_root(g0, d0, g1, d1, h, upward):
    """First root in (0, h] of the cubic Hermite interpolant of g (values g0, g1; slopes d0,
    d1), crossing upward (g from ≤ 0 to > 0) if ``upward`` else downward. −1 if none.

    Also finds a root that lies between two same-signed ends (a grazing touch).
    """
    # sample the cubic densely enough to bracket the first crossing, then bisect
    nsamp = 16
    prev = g0
    s_prev = 0.0
    for k in range(1, nsamp + 1):
        s = k / nsamp
        h00 = 2 * s**3 - 3 * s**2 + 1
        h10 = s**3 - 2 * s**2 + s
        h01 = -2 * s**3 + 3 * s**2
        h11 = s**3 - s**2
        g = h00 * g0 + h10 * h * d0 + h01 * g1 + h11 * h * d1
        crossed = (prev <= 0.0 < g) if upward else (prev >= 0.0 > g)
        if crossed:
            lo = s_prev
            hi = s
            for _ in range(50):
                mid = 0.5 * (lo + hi)
                h00 = 2 * mid**3 - 3 * mid**2 + 1
                h10 = mid**3 - 2 * mid**2 + mid
                h01 = -2 * mid**3 + 3 * mid**2
                h11 = mid**3 - mid**2
                gm = h00 * g0 + h10 * h * d0 + h01 * g1 + h11 * h * d1
                if (gm > 0.0) == upward:
                    hi = mid
                else:
                    lo = mid
            return hi * h
        prev = g
        s_prev = s
    return -1.0


@njit(**NRT_FREE)
def hermite_max(f0, d0, f1, d1, h):
    """Largest value inside (0, h) of the cubic Hermite through (0, f0, slope d0) and
    (h, f1, slope d1), and where it is as a fraction of h; ``(−inf, 0)`` if the cubic has no
    interior maximum."""
    best = -np.inf
    where = 0.0
    if h <= 0.0:
        return best, where
    # p(s) = f0 + b1 s + b2 s² + b3 s³ on s in [0, 1]
    dlt = f1 - f0
    b1 = h * d0
    b2 = 3.0 * dlt - h * (2.0 * d0 + d1)
    b3 = h * (d0 + d1) - 2.0 * dlt
    # p'(s) = b1 + 2 b2 s + 3 b3 s² = 0
    qa = 3.0 * b3
    qb = 2.0 * b2
    r1 = -1.0
    r2 = -1.0
    if abs(qa) < 1e-300 * (abs(qb) + abs(b1) + 1e-300):
        if qb != 0.0:
            r1 = -b1 / qb
    else:
        disc = qb * qb - 4.0 * qa * b1
        if disc < 0.0:
            return best, where
        sq = np.sqrt(disc)
        r1 = (-qb + sq) / (2.0 * qa)
        r2 = (-qb - sq) / (2.0 * qa)
    for sr in (r1, r2):
        if 0.0 < sr < 1.0 and qb + 2.0 * qa * sr < 0.0:
            val = f0 + sr * (b1 + sr * (b2 + sr * b3))
            if val > best:
                best = val
                where = sr
    return best, where


@njit(**NRT_FREE)
def quintic_max(f0, d0, q0, f1, d1, q1, h):
    """Largest value inside (0, h) of the quintic Hermite interpolant through the values,
    first and second derivatives ``(f, ḟ, f̈)`` at both ends, and where it is as a fraction
    of h; ``(−inf, 0)`` if it has no interior maximum.

    With ``(u, u̇, ü)`` of a smooth motion its error is O(h⁶), against O(h⁴) for the cubic
    through ``(u, u̇)``: at a 10 ms output step a 0.1 m, 1 Hz oscillation is interpolated to
    about 10⁻¹⁰ m (the cubic: 10⁻⁷ m).
    """
    best = -np.inf
    where = 0.0
    if h <= 0.0:
        return best, where
    hd0 = h * d0
    hd1 = h * d1
    hq0 = h * h * q0
    hq1 = h * h * q1
    # p(s) = Σ c_k s^k on s in [0, 1]: the quintic Hermite basis in monomial form
    c1 = hd0
    c2 = 0.5 * hq0
    c3 = 10.0 * (f1 - f0) - 6.0 * hd0 - 4.0 * hd1 - 1.5 * hq0 + 0.5 * hq1
    c4 = -15.0 * (f1 - f0) + 8.0 * hd0 + 7.0 * hd1 + 1.5 * hq0 - hq1
    c5 = 6.0 * (f1 - f0) - 3.0 * hd0 - 3.0 * hd1 - 0.5 * hq0 + 0.5 * hq1
    nsamp = 16
    dprev = c1
    s_prev = 0.0
    for k in range(1, nsamp + 1):
        s = k / nsamp
        dp = c1 + s * (2.0 * c2 + s * (3.0 * c3 + s * (4.0 * c4 + s * 5.0 * c5)))
        if dprev > 0.0 >= dp:
            lo = s_prev
            hi = s
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                dm = c1 + mid * (2.0 * c2 + mid * (3.0 * c3 + mid * (4.0 * c4
                                                                     + mid * 5.0 * c5)))
                if dm > 0.0:
                    lo = mid
                else:
                    hi = mid
            sm = 0.5 * (lo + hi)
            if 0.0 < sm < 1.0:
                val = f0 + sm * (c1 + sm * (c2 + sm * (c3 + sm * (c4 + sm * c5))))
                if val > best:
                    best = val
                    where = sm
        dprev = dp
        s_prev = s
    return best, where


@njit(**NRT_FREE)
def event_value(kind, c, y, n, ct, el, hg):
    """Event function: δ of contact c (onset, separation), δ̇ (phase switches, the peak of
    an open gap's penetration), the unclipped force of a releasing law (release, engaging
    again), the drift rate of element row c (drift reversals), or of hinge row c its
    rotation less an end of its branch (the branch's ends) or its rate (reversals), or
    a shear key's penetration less its fracture deformation (fracture); ``ct``,
    ``el``, ``hg``: the contacts, element rows and hinge rows."""
    if kind == EV_DRIFT_MAX or kind == EV_DRIFT_MIN:
        return element_drift(c, el.lo[c], el.hi[c], el.params, y, n)[1]
    if EV_TAUT <= kind <= EV_YIELD:
        return restrainer_value(kind, c, y, n, el)
    if EV_HINGE_HI <= kind <= EV_HINGE_TURN_UP:
        th, th_rate = hinge_row(c, y, n, hg)
        if kind == EV_HINGE_HI:
            return th - hg.state[c, HS_HI]
        if kind == EV_HINGE_LO:
            return th - hg.state[c, HS_LO]
        return th_rate
    d, v = gap_row(c, y, n, ct.dof, ct.weight)
    if kind == EV_MAX_COMPRESSION or kind == EV_RELOADING or kind == EV_GRAZE:
        return v
    if kind == EV_RELEASE or kind == EV_REENGAGE:
        return release_value(ct.params[c, 0], ct.params[c, 1], d - ct.gap[c], v)
    if kind == EV_FRACTURE:
        return fracture_value(ct.params[c, 2], d - ct.gap[c])
    return d - ct.gap[c]


@njit(**NRT_FREE)
def restrainer_value(kind, c, y, n, el):
    """Event function [m] of restrainer row c at state y: its elastic elongation (the slack
    taken up or given back, ``EV_TAUT`` / ``EV_SLACK``) or its margin to yield
    (``EV_YIELD``), :func:`pounding.devices.laws.restrainer_kinks`."""
    par = el.params
    d = element_drift(c, el.lo[c], el.hi[c], par, y, n)[0]
    e, _, g, _ = restrainer_kinks(par[c, 0], par[c, 1], par[c, 2], par[c, 3], d, 0.0,
                                  y[2 * n + el.z_index[c]], 0.0)
    return g if kind == EV_YIELD else e


@njit(**NRT_FREE)
def restrainer_event(s, y0, k0, y1, k1, h, n, el, skip_c, skip_kind, best_t):
    """The first corner of restrainer row s inside a step (``(time, kind)``, or ``(−1, 0)``
    if none earlier than ``best_t``): the slack taken up (``EV_TAUT``) or given back
    (``EV_SLACK``), or yield (``EV_YIELD``), from the cubic Hermite of each event function
    (:func:`pounding.devices.laws.restrainer_kinks`) through its values and rates at the
    step's ends (``k0`` row 0: f(y0); ``k1`` row 6: f(y1))."""
    par = el.params
    zi = el.z_index[s]
    lo = el.lo[s]
    hi = el.hi[s]
    d0, r0 = element_drift(s, lo, hi, par, y0, n)
    d1, r1 = element_drift(s, lo, hi, par, y1, n)
    e0, er0, g0, gr0 = restrainer_kinks(par[s, 0], par[s, 1], par[s, 2], par[s, 3], d0, r0,
                                        y0[2 * n + zi], k0[0, 2 * n + zi])
    e1, er1, g1, gr1 = restrainer_kinks(par[s, 0], par[s, 1], par[s, 2], par[s, 3], d1, r1,
                                        y1[2 * n + zi], k1[6, 2 * n + zi])
    best_k: int | np.int64 = 0  # (the event kinds are NumPy integers)
    bound = 0.25 * h * (abs(er0) + abs(er1))  # the cubic stays within this of its ends
    if e0 <= 0.0:
        if max(e0, e1) + bound > 0.0 and not (s == skip_c and skip_kind == EV_TAUT):
            t = hermite_root(e0, er0, e1, er1, h, UPWARD)
            if e1 > 0.0 and t < 0.0:
                t = h
            if 0.0 < t < best_t:
                best_t, best_k = t, EV_TAUT
    else:
        if min(e0, e1) - bound <= 0.0 and not (s == skip_c and skip_kind == EV_SLACK):
            t = hermite_root(e0, er0, e1, er1, h, DOWNWARD)
            if e1 <= 0.0 and t < 0.0:
                t = h
            if 0.0 < t < best_t:
                best_t, best_k = t, EV_SLACK
        bound = 0.25 * h * (abs(gr0) + abs(gr1))
        if (g0 <= 0.0 and max(g0, g1) + bound > 0.0
                and not (s == skip_c and skip_kind == EV_YIELD)):
            t = hermite_root(g0, gr0, g1, gr1, h, UPWARD)
            if g1 > 0.0 and t < 0.0:
                t = h
            if 0.0 < t < best_t:
                best_t, best_k = t, EV_YIELD
    if best_k == 0:
        return -1.0, 0
    return best_t, best_k


@njit(**NRT_FREE)
def rate_event(r0, acc0, r1, acc1, h, best_t):
    """Time of a rate sign change in a step (−1 if none earlier than ``best_t``); the
    crossing direction is read from the end values."""
    if r0 > 0.0 and r1 <= 0.0:
        t = hermite_root(r0, acc0, r1, acc1, h, DOWNWARD)
    elif r0 < 0.0 and r1 >= 0.0:
        t = hermite_root(r0, acc0, r1, acc1, h, UPWARD)
    else:
        return -1.0
    if t < 0.0:
        t = h
    return t if t < best_t else -1.0


@njit(**NRT_FREE)
def touch_possible(d0, r0, q0, d1, r1, q1, h, tol):
    """Can an open gap close inside a step, from its penetration ``δ``, rate and
    acceleration at both ends? True if an end is closed, or the quintic Hermite of
    ``(δ, δ̇, δ̈)`` peaks inside the step within ``tol`` of zero. A cheap bound first: the
    quintic cannot rise more than ``h (|δ̇0| + |δ̇1|)/4 + h² (|δ̈0| + |δ̈1|)/8`` above its
    higher end."""
    if d1 > 0.0 or d0 > 0.0:
        return True
    bound = 0.25 * h * (abs(r0) + abs(r1)) + 0.125 * h * h * (abs(q0) + abs(q1))
    if max(d0, d1) + bound <= -tol:
        return False
    if not (r0 > 0.0 or r1 > 0.0):
        return False
    return quintic_max(d0, r0, q0, d1, r1, q1, h)[0] > -tol


@njit(**NRT_FREE)
def hinge_start(y0, n, hg):
    """Every hinge row's rotation and rate at ``y0`` into ``HS_TH0``, ``HS_R0`` (what
    :func:`find_event` reads)."""
    hst = hg.state
    for q in range(hst.shape[0]):
        th, rt = hinge_row(q, y0, n, hg)
        hst[q, HS_TH0] = th
        hst[q, HS_R0] = rt


@njit(**NRT_FREE)
def hinge_step_end(hg):
    """The rotations and rates :func:`find_event` left for the end of the step just
    accepted become those of the next step's start."""
    hst = hg.state
    for q in range(hst.shape[0]):
        hst[q, HS_TH0] = hst[q, HS_TH1]
        hst[q, HS_R0] = hst[q, HS_R1]


@njit(**NRT_FREE)
def find_event(y0, k0, y1, k1, h, n, ct, el, hg, committed, skip_c, skip_kind, graze_tol,
               grazed):
    """Earliest event in a step, from Hermite interpolants of every contact's δ and δ̇ and
    every yielding storey's drift rate (``k0``: row 0 is f(y0); ``k1``: row 6 is f(y1)).

    Returns (time estimate, contact or storey, kind): kind 1 onset, 2 separation, 3 maximum
    compression (δ̇: + → −), 4 reloading (δ̇: − → +), 5 / 6 a yielding storey's drift rate
    turning negative / positive (the drift reverses; for links, only a fluid damper's:
    :func:`pounding.devices.laws.has_rate_cusp`), 7 an open gap peaking within
    ``graze_tol`` [m] of closing (its peak is then located on real steps, :func:`locate`;
    skipped for a contact whose ``grazed`` flag is set: one already found not to touch),
    8 / 9 the unclipped force ``k δ + c δ̇`` of a releasing law turning negative / positive
    (released before δ = 0 / engaged again), 10 / 11 a frame's hinge rotation reaching the
    upper / lower end of its branch, 12 / 13 a hinge on a one-way branch reversing (its
    rate turning negative / positive), 14 / 15 / 16 a restrainer's slack taken up / given
    back / its yield (:func:`restrainer_event`), 17 a shear key breaking off (its penetration
    reaching its fracture deformation; a broken key's gap closing is not searched);
    (−1, −1, 0) if none. The hinges' rotations and rates
    at ``y0`` are read from their rows' ``HS_TH0``, ``HS_R0`` (the caller's: see
    :func:`hinge_start`), those at ``y1`` left in ``HS_TH1``, ``HS_R1``. ``ct``, ``el``, ``hg``: the
    contacts, element rows and hinge rows.
    """
    cdof, cw, cgap, ccode, cparams = ct
    s_lo = el.lo
    s_hi = el.hi
    s_code = el.code
    s_par = el.params
    best_t = 1e300
    best_c = -1
    best_k: int | np.int64 = 0  # the event kinds (EV_*) are NumPy integers
    for c in range(cgap.shape[0]):
        ds0, r0 = gap_row(c, y0, n, cdof, cw)
        ds1, r1 = gap_row(c, y1, n, cdof, cw)
        d0 = ds0 - cgap[c]
        d1 = ds1 - cgap[c]
        bound = 0.25 * h * (abs(r0) + abs(r1))  # the cubic stays within this of its ends
        acc0 = 0.0
        acc1 = 0.0
        for q0 in range(0, cdof.shape[1], ROW_BLOCK):
            for q in range(q0, q0 + ROW_BLOCK):
                acc0 += cw[c, q] * k0[0, n + cdof[c, q]]
                acc1 += cw[c, q] * k1[6, n + cdof[c, q]]
        if committed[c, V0] == 0.0:
            if max(d0, d1) + bound + 0.125 * h * h * (abs(acc0) + abs(acc1)) <= -graze_tol:
                continue
            if is_broken(ccode[c], committed[c, SLIP]):
                continue  # (a broken-off shear key: its gap closing is no impact)
            # A gap open at both ends whose rate turns from closing to opening peaks inside
            # the step: any touch there is a graze, decided at the peak located on real
            # steps. (The cubic's root is no estimate of it: the real gap may be closed for
            # far less than the step, and a root estimate outside that window found "no
            # touch" where there was one.)
            peak_inside = d0 <= 0.0 and d1 <= 0.0 and r0 > 0.0 and r1 <= 0.0
            if not (c == skip_c and skip_kind == EV_ONSET):
                t = -1.0 if peak_inside else hermite_root(d0, r0, d1, r1, h, UPWARD)
                if t > 0.0 and t < best_t:
                    best_t, best_c, best_k = t, c, EV_ONSET
                elif (t <= 0.0 and grazed[c] == 0.0 and r0 > 0.0 and r1 <= 0.0
                      and not (c == skip_c and skip_kind == EV_GRAZE)):
                    val, where = quintic_max(d0, r0, acc0, d1, r1, acc1, h)
                    if val > -graze_tol and where * h < best_t:
                        best_t, best_c, best_k = where * h, c, EV_GRAZE
        else:
            if not (c == skip_c and skip_kind == EV_SEPARATION) and min(d0, d1) - bound <= 0.0:
                t = hermite_root(d0, r0, d1, r1, h, DOWNWARD)
                if d1 <= 0.0 and t < 0.0:
                    t = h
                if t > 0.0 and t < best_t:
                    best_t, best_c, best_k = t, c, EV_SEPARATION
            kind = EV_MAX_COMPRESSION if r0 > 0.0 else EV_RELOADING
            if not (c == skip_c and skip_kind == kind):
                t = rate_event(r0, acc0, r1, acc1, h, best_t)
                if t >= 0.0:
                    best_t, best_c, best_k = t, c, kind
            kc = cparams[c, 0]
            cc = cparams[c, 1]
            if law_releases(ccode[c], kc, cc, cparams[c, 2]):
                g0 = release_value(kc, cc, d0, r0)
                g1 = release_value(kc, cc, d1, r1)
                kind = EV_RELEASE if g0 > 0.0 else EV_REENGAGE
                if not (c == skip_c and skip_kind == kind):
                    t = rate_event(g0, kc * r0 + cc * acc0, g1, kc * r1 + cc * acc1, h,
                                   best_t)
                    if t >= 0.0:
                        best_t, best_c, best_k = t, c, kind
            if (can_break(ccode[c], cparams[c, 2], committed[c, SLIP])
                    and not (c == skip_c and skip_kind == EV_FRACTURE)):
                # a shear key reaching its fracture deformation: it breaks off there
                g0 = fracture_value(cparams[c, 2], d0)
                g1 = fracture_value(cparams[c, 2], d1)
                if max(g0, g1) + bound > 0.0:
                    t = hermite_root(g0, r0, g1, r1, h, UPWARD)
                    if g1 > 0.0 and t < 0.0:
                        t = h
                    if 0.0 < t < best_t:
                        best_t, best_c, best_k = t, c, EV_FRACTURE
    for s in range(s_lo.shape[0]):
        if s_code[s] == RESTRAINER:
            t, kind = restrainer_event(s, y0, k0, y1, k1, h, n, el, skip_c, skip_kind, best_t)
            if t >= 0.0:
                best_t, best_c, best_k = t, s, kind
            continue
        if s_code[s] >= DEVICE_MIN and not has_rate_cusp(s_code[s], s_par[s, 1]):
            continue  # a link whose force is smooth where its rate reverses: no event
        r0 = element_drift(s, s_lo[s], s_hi[s], s_par, y0, n)[1]
        r1 = element_drift(s, s_lo[s], s_hi[s], s_par, y1, n)[1]
        kind = EV_DRIFT_MAX if r0 > 0.0 else EV_DRIFT_MIN
        if s == skip_c and skip_kind == kind:
            continue
        hi = s_hi[s]
        lo = s_lo[s]
        acc0 = k0[0, n + hi] - (k0[0, n + lo] if lo >= 0 else 0.0)
        acc1 = k1[6, n + hi] - (k1[6, n + lo] if lo >= 0 else 0.0)
        if s_par[s, EL_ROCK] >= 0.0:  # (a storey over a rocking footing)
            rk = int(s_par[s, EL_ROCK])
            acc0 -= s_par[s, EL_LEVER] * k0[0, n + rk]
            acc1 -= s_par[s, EL_LEVER] * k1[6, n + rk]
        t = rate_event(r0, acc0, r1, acc1, h, best_t)
        if t >= 0.0:
            best_t, best_c, best_k = t, s, kind
    # the plastic hinges of yielding frames: a rotation reaching an end of its branch, a
    # one-way branch's rotation reversing
    hdof = hg.dof
    hw = hg.weight
    hst = hg.state
    for q in range(hdof.shape[0]):
        # (θ and θ̇ at y0: the caller's, in HS_TH0 / HS_R0; those at y1 kept for it)
        th0 = hst[q, HS_TH0]
        r0 = hst[q, HS_R0]
        th1, r1 = hinge_row(q, y1, n, hg)
        hst[q, HS_TH1] = th1
        hst[q, HS_R1] = r1
        bound = 0.25 * h * (abs(r0) + abs(r1))  # the cubic stays within this of its ends
        # (after an event was located, skip_c >= 0: a hinge within the event tolerance past
        # the end of its branch at the shortened step's end is left to Python, which lands
        # every such hinge with the event's; located again, twin hinges — a symmetric
        # frame's — shortened the step in turn by fractions of that tolerance, ~60 times)
        near = graze_tol * hst[q, HS_WABS] if skip_c >= 0 else -1.0
        hi = hst[q, HS_HI]
        if (max(th0, th1) + bound > hi and not (q == skip_c and skip_kind == EV_HINGE_HI)
                and not (th1 > hi and th1 - hi <= near)):
            t = hermite_root(th0 - hi, r0, th1 - hi, r1, h, UPWARD)
            if th1 > hi and t < 0.0:
                t = h
            if t > 0.0 and t < best_t:
                best_t, best_c, best_k = t, q, EV_HINGE_HI
        lo = hst[q, HS_LO]
        if (min(th0, th1) - bound <= lo and not (q == skip_c and skip_kind == EV_HINGE_LO)
                and not (th1 <= lo and lo - th1 <= near)):
            t = hermite_root(th0 - lo, r0, th1 - lo, r1, h, DOWNWARD)
            if th1 <= lo and t < 0.0:
                t = h
            if t > 0.0 and t < best_t:
                best_t, best_c, best_k = t, q, EV_HINGE_LO
        way = hst[q, HS_DIR]
        if way != 0.0:
            kind = EV_HINGE_TURN_DOWN if way > 0.0 else EV_HINGE_TURN_UP
            if (way > 0.0) == (r0 > 0.0) and not (q == skip_c and skip_kind == kind):
                acc0 = 0.0
                acc1 = 0.0
                for q0 in range(0, hdof.shape[1], ROW_BLOCK):
                    for j in range(q0, q0 + ROW_BLOCK):
                        acc0 += hw[q, j] * k0[0, n + hdof[q, j]]
                        acc1 += hw[q, j] * k1[6, n + hdof[q, j]]
                t = rate_event(r0, acc0, r1, acc1, h, best_t)
                if t >= 0.0:
                    best_t, best_c, best_k = t, q, kind
    if best_c < 0:
        return -1.0, -1, 0
    return best_t, best_c, best_k


@njit(**NRT_FREE)
def locate(kind, ce, lo, hi, g_lo, g_hi, t_try, g_tol, dt, x, kx, px, gnd, s, fl, ct, el, hg,
           committed, sstate, lin, ks, ps, ks_b, ps_b, ytmp, y1, yb, atol, rtol, ws_i):
    """Locate an event bracketed in ``(lo, hi]`` (local times from the step start ``s``;
    event function ``g_lo`` on the 'before' side at lo, ``g_hi`` on the 'after' side at hi)
    on actual RK steps from ``x`` by the Illinois method, starting at ``t_try``.

    Leaves the step to the located instant in ``y1`` (stages in ``ks``, ``ps``) and returns
    ``(its length, its error norm)``. The 'after' side: g > 0 for events crossing upward
    (:func:`is_upward`), g ≤ 0 otherwise.
    """
    m = x.shape[0]
    n = fl.m_diag.shape[0]
    npw = ps.shape[1]
    upward = is_upward(kind)
    side = 0
    have_after = False
    err_after = 0.0
    for _ in range(60):
        ground_at(gnd, G_END, s + t_try)
        err = rk_step(x, kx, px, t_try, gnd, s, fl, ct, el, committed, sstate, lin, ks_b,
                      ps_b, ytmp, yb, atol, rtol)
        ws_i[I_NSTEPS] += 1
        g = event_value(kind, ce, yb, n, ct, el, hg)
        after = (g > 0.0) if upward else (g <= 0.0)
        if after:
            hi = t_try
            g_hi = g
            if side == 1:
                g_lo *= 0.5
            side = 1
            # keep this step: it may be the one we take
            have_after = True
            err_after = err
            for i in range(m):
                y1[i] = yb[i]
            for q in range(7):
                for i in range(m):
                    ks[q, i] = ks_b[q, i]
                for i in range(npw):
                    ps[q, i] = ps_b[q, i]
            if abs(g) <= EVENT_TOL * g_tol:
                break
        else:
            lo = t_try
            g_lo = g
            if side == -1:
                g_hi *= 0.5
            side = -1
        if hi - lo <= 1e-13 * dt + 1e-15:
            break
        denom = g_hi - g_lo
        t_try = (lo * g_hi - hi * g_lo) / denom if denom != 0.0 else 0.5 * (lo + hi)
        if not (lo < t_try < hi):
            t_try = 0.5 * (lo + hi)
    if not have_after:
        # the bracket's after end is the full step (or the grazing test)
        ground_at(gnd, G_END, s + hi)
        err_after = rk_step(x, kx, px, hi, gnd, s, fl, ct, el, committed, sstate, lin, ks, ps,
                            ytmp, y1, atol, rtol)
        ws_i[I_NSTEPS] += 1
    return hi, err_after


@njit(**NRT_FREE)
def is_upward(kind):
    """Does the event function of ``kind`` cross zero upward (onset, reloading, a drift
    minimum, a released contact engaging again, a hinge reaching the upper end of its
    branch or turning to rotate positively)?"""
    return (kind == EV_ONSET or kind == EV_RELOADING or kind == EV_DRIFT_MIN
            or kind == EV_REENGAGE or kind == EV_HINGE_HI or kind == EV_HINGE_TURN_UP
            or kind == EV_TAUT or kind == EV_YIELD or kind == EV_FRACTURE)


@njit(**NRT_FREE)
def event_tolerance(kind, ce, n, cparams, atol, hst):
    """Absolute tolerance of an event function: of a drift rate, a gap's rate, a gap, an
    unclipped force ``k δ + c δ̇`` (from the tolerances of δ and δ̇), or a hinge's rotation
    or its rate (those of the displacements and velocities times ``Σ |w|`` of its row,
    ``hst``: the hinge rows' states). Every displacement
    has one absolute tolerance (``atol[0]``) and every velocity another (``atol[n]``), so
    these are the tolerances of a DOF's motion, whichever DOFs a contact row or an element
    row joins."""
    if kind == EV_DRIFT_MAX or kind == EV_DRIFT_MIN:
        return atol[n]
    if kind == EV_HINGE_HI or kind == EV_HINGE_LO:
        return atol[0] * hst[ce, HS_WABS]
    if kind == EV_HINGE_TURN_DOWN or kind == EV_HINGE_TURN_UP:
        return atol[n] * hst[ce, HS_WABS]
    if kind == EV_MAX_COMPRESSION or kind == EV_RELOADING or kind == EV_GRAZE:
        return atol[n]
    if kind == EV_RELEASE or kind == EV_REENGAGE:
        return cparams[ce, 0] * atol[0] + cparams[ce, 1] * atol[n]
    return atol[0]
