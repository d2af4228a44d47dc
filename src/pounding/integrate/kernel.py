"""The one compiled time stepper (numba) for buildings that pound.

Two regimes, one kernel:

1. **All gaps open.** The structure is linear and the ground acceleration is linear between
   grid points, so each grid step is taken with the exact propagator of
   :mod:`pounding.integrate.propagator` (``x ← Φ x + Γ0 a_k + Γ1 a_{k+1}``), block by
   block (the buildings are uncoupled while the gaps are open). The input energy over the
   step is an exact quadratic form in ``(x, a_k, a_{k+1})`` (Van Loan integral,
   :func:`pounding.integrate.propagator.step_energy_forms`), evaluated in the same sweep
   over the operator's columns as Φ x; the viscous work of the step is the input work less
   the change of kinetic and strain energy, exactly (nothing else stores or dissipates).
   After each step every gap is checked for closing at the step end *and inside it* (an
   interior maximum of the cubic Hermite interpolant of δ), so no touch is missed.
2. **Any contact closed (or about to close).** The step is re-taken with an adaptive
   Dormand–Prince 5(4) integrator (Dormand & Prince 1980, J. Comput. Appl. Math.
   6(1):19–26; coefficients as in Hairer, Nørsett & Wanner, *Solving ODEs I*, Table 5.2)
   whose steps land exactly on grid points. Events are located on actual RK steps by the
   Illinois method: a gap closing (``δ = 0`` upward: contact onset, where ``v0`` is
   committed — contract step 3), reopening (``δ = 0`` downward: separation), and the
   rate ``δ̇`` changing sign inside a contact (approach ↔ restitution, where laws switch
   branch). Contact states are committed only at accepted step ends and events (contract
   step 4). Energies (input, viscous, contact work per contact) are integrated with the
   same RK weights, so they are as accurate as the motion.

Floating point: no reassociation (``fastmath`` allows only fused multiply-add), so results
do not depend on how arrays happen to be aligned in memory — a sweep's cases are
bit-identical whichever process runs them.

The kernel advances a chunk of grid steps ``[k0, k1)`` and keeps everything it needs between
chunks in a workspace, so the caller can show progress on long runs.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.base import DMAX, SLIP, STATE_SIZE, V0, V0_MIN
from pounding.contact.dispatch import has_linear_spring, law_trial, stored_energy
from pounding.hysteresis.base import D_C, V_C
from pounding.hysteresis.dispatch import storey_recoverable, storey_trial

_NRT_FREE = dict(cache=True, error_model="numpy", nogil=True, fastmath={"contract"},
                 _nrt=False)
"""Options of the kernel's working functions. They allocate nothing (the scratch comes from
:func:`integrate_chunk`), so they run with numba's reference-counting runtime off: no array
passed to a call costs an atomic increment and decrement. (When introduced this took the
SDOF pair's right-hand side from 120 ns to 20 ns; with every right-hand side now inlined
into the step, turning the runtime back on changes the kernel's time by no more than the
run-to-run noise: docs/engine.md.)"""

# Dormand–Prince 5(4) tableau
_C2, _C3, _C4, _C5 = 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0
_A21 = 1.0 / 5.0
_A31, _A32 = 3.0 / 40.0, 9.0 / 40.0
_A41, _A42, _A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
_A51, _A52, _A53, _A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
_A61, _A62, _A63, _A64, _A65 = (9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0,
                                -5103.0 / 18656.0)
_B1, _B3, _B4, _B5, _B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
_E1, _E3, _E4, _E5, _E6, _E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0,
                                -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0)
_DP_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [_A21, 0.0, 0.0, 0.0, 0.0, 0.0],
    [_A31, _A32, 0.0, 0.0, 0.0, 0.0],
    [_A41, _A42, _A43, 0.0, 0.0, 0.0],
    [_A51, _A52, _A53, _A54, 0.0, 0.0],
    [_A61, _A62, _A63, _A64, _A65, 0.0],
    [_B1, 0.0, _B3, _B4, _B5, _B6]])
"""Rows 1 … 5: the stages' a coefficients; row 6: the fifth-order weights b (b2 = 0)."""
_DP_C = np.array([0.0, _C2, _C3, _C4, _C5, 1.0, 1.0])

EVENT_TOL: float = 1000.0
"""An event is located once its function (δ, δ̇ or a drift rate) is within this many
absolute tolerances of zero on an actual RK step: 2×10⁻¹⁰ m of penetration for the default
rtol and a 20 mm gap, far below anything that moves a contact force or an impact's start;
tighter only costs RK steps (measured: about 5 % of them for the SDOF pair)."""

DELTA_EPS: float = 1e-300
"""Penetration at which a closed contact is evaluated when δ ≤ 0 inside a step [m]."""

RATE_SIDE: float = 1e-300
"""A closing rate [m/s] just above zero: where a law is evaluated on its approach branch
at δ̇ = 0 (see :func:`_deriv`)."""

# Columns of the impact table
IMP_CONTACT, IMP_START, IMP_END, IMP_V0, IMP_PEAK, IMP_DMAX, IMP_E, IMP_ENERGY = range(8)
IMP_COLUMNS = 8

# Columns of the energy history
(E_INPUT, E_KINETIC, E_STRAIN, E_DAMPING, E_CONTACT_WORK, E_CONTACT_STORED,
 E_HYSTERETIC) = range(7)
ENERGY_COLUMNS = 7

# Columns of the power rows (input, viscous, yielding storeys, then one per contact)
P_INPUT, P_DAMP, P_STOREY = range(3)
P_CONTACT = 3

# Event kinds
EV_ONSET, EV_SEPARATION, EV_MAX_COMPRESSION, EV_RELOADING = 1, 2, 3, 4
EV_DRIFT_MAX, EV_DRIFT_MIN = 5, 6

# Workspace scalars (ws_f) and integers (ws_i)
W_H, W_E_INPUT, W_E_DAMP, W_E_STOREY, W_ERR_OLD = range(5)
WS_F_SIZE = 5
WS_I_SIZE = 7
I_MODE, I_NIMP, I_OVERFLOW, I_NSTEPS, I_NREJECT, I_NEVENTS, I_FAILED = range(7)


@njit(cache=True, inline="always", error_model="numpy", fastmath={"contract"})
def _gap(c, y, n, cdof, cw):
    """``(Σ w u, Σ w u̇)`` of contact c: its penetration plus the gap, and its rate
    (:meth:`pounding.model.PoundingModel.contact_kinematics`)."""
    d = 0.0
    v = 0.0
    for q in range(4):
        j = cdof[c, q]
        d += cw[c, q] * y[j]
        v += cw[c, q] * y[n + j]
    return d, v


@njit(cache=True, inline="always", error_model="numpy", fastmath={"contract"})
def _drift(s, y, n, s_lo, s_hi):
    """Drift and drift rate of yielding storey s (``u_upper − u_lower``, ground = 0)."""
    hi = s_hi[s]
    lo = s_lo[s]
    if lo >= 0:
        return y[hi] - y[lo], y[n + hi] - y[n + lo]
    return y[hi], y[n + hi]


@njit(cache=True, inline="always", error_model="numpy", fastmath={"contract"})
def _band_mv(kb, cb, y, n, bw, lin):
    """``lin[0] = K u``, ``lin[1] = C u̇`` for ``y = [u, u̇, …]`` with K and C in band storage
    (``kb[d, i] = K[i, i + d − bw]``): O(N·bw), each row summed in column order, and the
    loop over rows vectorises without reassociation."""
    for i in range(n):
        lin[0, i] = 0.0
        lin[1, i] = 0.0
    for d in range(2 * bw + 1):
        off = d - bw
        lo = max(0, -off)
        hi = min(n, n - off)
        for i in range(lo, hi):
            lin[0, i] += kb[d, i] * y[i + off]
            lin[1, i] += cb[d, i] * y[n + i + off]


@njit(**_NRT_FREE)
def _law_out_of_line(code, p0, p1, p2, delta, rate, v0, slip, dmax):
    """:func:`pounding.contact.dispatch.law_trial`, called rather than inlined.

    numba's ``inline="always"`` copies and re-types a function at every call site; with every
    contact law inlined into the right-hand side and the step loop, all the laws were compiled
    many times over (a first run compiled for 240 s on 2 cores). Called, they compile once,
    with no measurable change in the kernel's time (docs/engine.md, "Compiled once").
    """
    return law_trial(code, p0, p1, p2, delta, rate, v0, slip, dmax)


@njit(**_NRT_FREE)
def _storey_out_of_line(code, par, s, d, dr, z, d_c, v_c):
    """:func:`pounding.hysteresis.dispatch.storey_trial`, called rather than inlined in
    :func:`_deriv`, for the reason given in :func:`_law_out_of_line`."""
    return storey_trial(code, par, s, d, dr, z, d_c, v_c)


@njit(cache=True, inline="always", error_model="numpy", fastmath={"contract"})
def _deriv(y, y_start, ag, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap, ccode, cparams,
           committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin, dy, power, row):
    """dy = f(y) for the structure with contacts; power = [input, viscous, storey work,
    per-contact F δ̇].

    ``y = [u (n), u̇ (n), z (one per Bouc–Wen storey)]``; ``y_start``: the state at the
    start of the step (``y`` itself outside a step). Writes row ``row`` of ``dy`` and
    ``power`` (2-D arrays: no views in the hot loop); ``m_inv``: 1 / floor mass. Contact
    forces and yielding storeys use their committed states (read only).
    """
    nc = cgap.shape[0]
    # linear part: acc = −M⁻¹(K u + C v) − r a_g, K (linear storeys only) and C banded
    # (half-bandwidth bw), M diagonal (lumped floor masses): O(N·bw) work
    p_in = 0.0
    p_d = 0.0
    if bw == 0:
        # no floor coupled to another (a row of SDOF oscillators): floor by floor
        for i in range(n):
            v = y[n + i]
            cv = c_band[0, i] * v
            dy[row, i] = v
            dy[row, n + i] = -(k_band[0, i] * y[i] + cv) * m_inv[i] - r[i] * ag
            p_in -= v * mr[i] * ag
            p_d += v * cv
    else:
        _band_mv(k_band, c_band, y, n, bw, lin)
        for i in range(n):
            dy[row, i] = y[n + i]
            dy[row, n + i] = -(lin[0, i] + lin[1, i]) * m_inv[i] - r[i] * ag
            p_in -= y[n + i] * mr[i] * ag
            p_d += y[n + i] * lin[1, i]
    power[row, P_INPUT] = p_in
    power[row, P_DAMP] = p_d
    # yielding storeys: shear V from the storey law, −V on the floor above, +V below
    p_s = 0.0
    for s in range(s_lo.shape[0]):
        d, dr = _drift(s, y, n, s_lo, s_hi)
        zi = s_zi[s]
        z = y[2 * n + zi] if zi >= 0 else 0.0
        v, kt, zd = _storey_out_of_line(s_code[s], s_par, s, d, dr, z, sstate[s, D_C],
                                          sstate[s, V_C])
        hi = s_hi[s]
        lo = s_lo[s]
        dy[row, n + hi] -= v * m_inv[hi]
        if lo >= 0:
            dy[row, n + lo] += v * m_inv[lo]
        if zi >= 0:
            dy[row, 2 * n + zi] = zd
        p_s += v * dr
    power[row, P_STOREY] = p_s
    for c in range(nc):
        dsum, rate = _gap(c, y, n, cdof, cw)
        delta = dsum - cgap[c]
        # Inside a step the contact keeps its committed status: an open contact pushes
        # nothing even where δ > 0; a closed one goes on past δ = 0, and past δ̇ = 0 keeps
        # the approach or restitution branch the step began on, its law continued smoothly
        # (below). Status and branch change only at located events, so every
        # step integrates a smooth right-hand side: no jump or kink in a force inside a
        # step to spoil the error estimate and have the step rejected.
        f = 0.0
        if committed[c, V0] > 0.0:
            # the law at max(δ, DELTA_EPS), on the δ̇ branch the step began on (at RATE_SIDE
            # for approach, 0 for restitution), continued linearly: in δ̇ with ∂F/∂δ̇ (every
            # law here is linear in δ̇ on a branch), and in δ with ∂F/∂δ for the laws with
            # a linear spring. A Hertz spring's force and stiffness both vanish at δ = 0,
            # so its limit there is already smooth (and its ∂F/∂δ, unbounded at δ = 0
            # while approaching, is not used). Where nothing is crossed this is the law.
            rate_law = rate
            rate_start = _gap(c, y_start, n, cdof, cw)[1]
            if (rate_start > 0.0) != (rate > 0.0):
                rate_law = RATE_SIDE if rate_start > 0.0 else 0.0
            f, kd, kr, _, _, _ = _law_out_of_line(ccode[c], cparams[c, 0], cparams[c, 1],
                                                  cparams[c, 2], max(delta, DELTA_EPS),
                                                  rate_law, committed[c, V0],
                                                  committed[c, SLIP], committed[c, DMAX])
            f += kr * (rate - rate_law)
            if delta < DELTA_EPS and has_linear_spring(ccode[c]):
                f += kd * (delta - DELTA_EPS)
        power[row, P_CONTACT + c] = f * rate
        if f != 0.0:
            # the force pushes the left point left and the right point right, shared to
            # the floors with the point's weights (−w F on each)
            for q in range(4):
                j = cdof[c, q]
                dy[row, n + j] -= cw[c, q] * f * m_inv[j]


@njit(**_NRT_FREE)
def _rk_step(y0, k1, p1, h, ag0, dag, s0, ag_end, n, bw, k_band, c_band, m_inv, mr, r, cdof,
             cw, cgap, ccode, cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin,
             ks, ps, ytmp, y1, atol, rtol):
    """One Dormand–Prince step of size h from y0 (k1, p1: derivative and power at y0).

    ``ag0 + dag * s`` is the ground acceleration at local time s; s0 is the local start;
    ``ag_end`` the value at the step end (given, so that a step ending on a grid point uses
    the record value there bit for bit, and its last stage is the next step's first).
    Writes y1 and the stage derivatives/powers (ks, ps: 7 rows); returns the error norm.
    Row 6 of ks/ps is f at y1 (first-same-as-last).
    """
    m = y0.shape[0]
    for i in range(m):
        ks[0, i] = k1[0, i]
    for i in range(ps.shape[1]):
        ps[0, i] = p1[0, i]
    # stages 1 … 5 at y0 + h Σ a_sq k_q, then the solution y1 (row 6: the b weights) and f
    # there; one call site of _deriv, so that it is compiled into the step once, not six times
    for st in range(1, 7):
        yt = y1 if st == 6 else ytmp
        for i in range(m):
            acc = _DP_A[st, 0] * ks[0, i]
            for q in range(1, st):
                acc += _DP_A[st, q] * ks[q, i]
            yt[i] = y0[i] + h * acc
        ag_st = ag_end if st >= 5 else ag0 + dag * (s0 + _DP_C[st] * h)
        _deriv(yt, y0, ag_st, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap, ccode,
               cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin, ks, ps, st)
    err = 0.0
    for i in range(m):
        e = h * (_E1 * ks[0, i] + _E3 * ks[2, i] + _E4 * ks[3, i] + _E5 * ks[4, i]
                 + _E6 * ks[5, i] + _E7 * ks[6, i])
        sc = atol[i] + rtol * max(abs(y0[i]), abs(y1[i]))
        err += (e / sc) ** 2
    return np.sqrt(err / m)


@njit(**_NRT_FREE)
def _hermite_root(g0, d0, g1, d1, h, upward):
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


@njit(**_NRT_FREE)
def _hermite_max(f0, d0, f1, d1, h):
    """Largest value inside (0, h) of the cubic Hermite through (0, f0, slope d0) and
    (h, f1, slope d1); −inf if it has no interior maximum."""
    best = -np.inf
    if h <= 0.0:
        return best
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
            return best
        sq = np.sqrt(disc)
        r1 = (-qb + sq) / (2.0 * qa)
        r2 = (-qb - sq) / (2.0 * qa)
    for sr in (r1, r2):
        if 0.0 < sr < 1.0 and qb + 2.0 * qa * sr < 0.0:
            val = f0 + sr * (b1 + sr * (b2 + sr * b3))
            if val > best:
                best = val
    return best


@njit(**_NRT_FREE)
def _event_value(kind, c, y, n, cdof, cw, cgap, s_lo, s_hi):
    """Event function: δ of contact c (onset/separation), δ̇ (phase switches), or the drift
    rate of yielding storey c (drift reversals)."""
    if kind == EV_DRIFT_MAX or kind == EV_DRIFT_MIN:
        return _drift(c, y, n, s_lo, s_hi)[1]
    d, v = _gap(c, y, n, cdof, cw)
    if kind == EV_MAX_COMPRESSION or kind == EV_RELOADING:
        return v
    return d - cgap[c]


@njit(**_NRT_FREE)
def _rate_event(r0, acc0, r1, acc1, h, best_t):
    """Time of a rate sign change in a step (−1 if none earlier than ``best_t``); the
    crossing direction is read from the end values."""
    if r0 > 0.0 and r1 <= 0.0:
        t = _hermite_root(r0, acc0, r1, acc1, h, False)
    elif r0 < 0.0 and r1 >= 0.0:
        t = _hermite_root(r0, acc0, r1, acc1, h, True)
    else:
        return -1.0
    if t < 0.0:
        t = h
    return t if t < best_t else -1.0


@njit(**_NRT_FREE)
def _find_event(y0, k0, y1, k1, h, n, cdof, cw, cgap, committed, s_lo, s_hi, skip_c,
                skip_kind):
    # k0: row 0 is f(y0); k1: row 6 is f(y1)
    """Earliest event in a step, from the Hermite interpolants of every contact's δ and δ̇
    and every yielding storey's drift rate.

    Returns (time estimate, contact or storey, kind): kind 1 onset, 2 separation, 3 maximum
    compression (δ̇: + → −), 4 reloading (δ̇: − → +), 5 / 6 a yielding storey's drift rate
    turning negative / positive (the drift reverses); (−1, −1, 0) if none.
    """
    best_t = 1e300
    best_c = -1
    best_k = 0
    for c in range(cgap.shape[0]):
        ds0, r0 = _gap(c, y0, n, cdof, cw)
        ds1, r1 = _gap(c, y1, n, cdof, cw)
        d0 = ds0 - cgap[c]
        d1 = ds1 - cgap[c]
        bound = 0.25 * h * (abs(r0) + abs(r1))  # the cubic stays within this of its ends
        if committed[c, V0] == 0.0:
            if max(d0, d1) + bound <= 0.0:
                continue
            if not (c == skip_c and skip_kind == EV_ONSET):
                t = _hermite_root(d0, r0, d1, r1, h, True)
                if t > 0.0 and t < best_t:
                    best_t, best_c, best_k = t, c, EV_ONSET
        else:
            if not (c == skip_c and skip_kind == EV_SEPARATION) and min(d0, d1) - bound <= 0.0:
                t = _hermite_root(d0, r0, d1, r1, h, False)
                if d1 <= 0.0 and t < 0.0:
                    t = h
                if t > 0.0 and t < best_t:
                    best_t, best_c, best_k = t, c, EV_SEPARATION
            acc0 = 0.0
            acc1 = 0.0
            for q in range(4):
                acc0 += cw[c, q] * k0[0, n + cdof[c, q]]
                acc1 += cw[c, q] * k1[6, n + cdof[c, q]]
            kind = EV_MAX_COMPRESSION if r0 > 0.0 else EV_RELOADING
            if not (c == skip_c and skip_kind == kind):
                t = _rate_event(r0, acc0, r1, acc1, h, best_t)
                if t >= 0.0:
                    best_t, best_c, best_k = t, c, kind
    for s in range(s_lo.shape[0]):
        r0 = _drift(s, y0, n, s_lo, s_hi)[1]
        r1 = _drift(s, y1, n, s_lo, s_hi)[1]
        kind = EV_DRIFT_MAX if r0 > 0.0 else EV_DRIFT_MIN
        if s == skip_c and skip_kind == kind:
            continue
        hi = s_hi[s]
        lo = s_lo[s]
        acc0 = k0[0, n + hi] - (k0[0, n + lo] if lo >= 0 else 0.0)
        acc1 = k1[6, n + hi] - (k1[6, n + lo] if lo >= 0 else 0.0)
        t = _rate_event(r0, acc0, r1, acc1, h, best_t)
        if t >= 0.0:
            best_t, best_c, best_k = t, s, kind
    if best_c < 0:
        return -1.0, -1, 0
    return best_t, best_c, best_k


@njit(cache=True, inline="always", error_model="numpy", fastmath={"contract"})
def _one_floor_step(p, n, x, x1, fops, g0, g1, a0, a1):
    """The exact step of a one-floor block p (the block sweep of :func:`_free_run`, written
    out): writes ``x1[p]``, ``x1[n + p]``; returns the block's two input-energy terms."""
    u = x[p]
    v = x[n + p]
    x1[p] = g0[p] * a0 + g1[p] * a1 + fops[p, 0] * u + fops[n + p, 0] * v
    x1[n + p] = g0[n + p] * a0 + g1[n + p] * a1 + fops[p, 1] * u + fops[n + p, 1] * v
    return (fops[p, 2] * u + fops[n + p, 2] * v, fops[p, 3] * u + fops[n + p, 3] * v)


@njit(**_NRT_FREE)
def _free_run(k, k1, dt, ag, blk, fops, g0, g1, faa, bw, k_band, c_band, m_diag, m_inv, cdof,
              cw, cgap, x, x1, acc, lin, gd, gr, gd1, gr1, wc, ws_f, u_out, v_out, acc_out,
              pen_out, e_out):
    """Exact grid steps from grid point ``k`` while every gap stays open (regime 1 of the
    module docstring), writing the outputs of each; returns the grid point whose step
    closes a gap (that step not taken: the caller re-takes it with RK) or ``k1``.

    A small function of its own, so that its loop compiles tight. ``gd``, ``gr``: every
    contact's δ and δ̇ at grid point k (updated); the other arrays as in
    :func:`integrate_chunk` (``m_inv``: 1 / floor mass; ``x1``, ``acc``, ``lin``, ``gd1``,
    ``gr1``: scratch).
    """
    n = m_diag.shape[0]
    m = 2 * n
    nc = cgap.shape[0]
    nblk = blk.shape[0] - 1
    e_in = ws_f[W_E_INPUT]
    e_d = ws_f[W_E_DAMP]
    e_h = ws_f[W_E_STOREY]
    e_prev = e_out[k, E_KINETIC] + e_out[k, E_STRAIN]
    wsum = 0.0  # contact work does not change while every gap is open
    for c in range(nc):
        wsum += wc[c]
    while k < k1:
        a0 = ag[k]
        a1 = ag[k + 1]
        # block by block (FreeStep): acc = [Φ_b z, w_in · z] in one sweep over the
        # columns of the block operator (each row accumulates in a fixed order)
        lin_i0 = 0.0
        lin_i1 = 0.0
        if nblk == n:
            # every floor a block of its own (a row of SDOF oscillators): no block loop
            for i in range(n):
                w0, w1 = _one_floor_step(i, n, x, x1, fops, g0, g1, a0, a1)
                lin_i0 += w0
                lin_i1 += w1
        else:
            for b in range(nblk):
                p = blk[b]
                nb = blk[b + 1] - p
                if nb == 1:
                    w0, w1 = _one_floor_step(p, n, x, x1, fops, g0, g1, a0, a1)
                    lin_i0 += w0
                    lin_i1 += w1
                    continue
                nb2 = 2 * nb
                rows = nb2 + 2
                for ir in range(nb):
                    acc[ir] = g0[p + ir] * a0 + g1[p + ir] * a1
                    acc[nb + ir] = g0[n + p + ir] * a0 + g1[n + p + ir] * a1
                acc[nb2] = 0.0
                acc[nb2 + 1] = 0.0
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
        # does any gap close at the step end or inside it (interior maximum of the cubic
        # Hermite of δ)? Then the step is not taken.
        for c in range(nc):
            d0 = gd[c]
            r0 = gr[c]
            ds1, r1 = _gap(c, x1, n, cdof, cw)
            d1 = ds1 - cgap[c]
            gd1[c] = d1
            gr1[c] = r1
            # cheap bound first: the cubic cannot rise above this
            if d1 > 0.0 or (max(d0, d1) + 0.25 * dt * (abs(r0) + abs(r1)) > 0.0
                            and _hermite_root(d0, r0, d1, r1, dt, True) > 0.0):
                ws_f[W_E_INPUT] = e_in
                ws_f[W_E_DAMP] = e_d
                return k
        # input energy over the step: an exact quadratic form
        e_step = (a0 * lin_i0 + a1 * lin_i1
                  + (faa[0] * a0 * a0 + faa[1] * a0 * a1 + faa[2] * a1 * a1))
        e_in += e_step
        for i in range(m):
            x[i] = x1[i]
        # outputs at grid point k + 1; no contact force, no yielding storey: absolute
        # acceleration ü + r a_g = −M⁻¹(K u + C u̇)
        o = k + 1
        ek = 0.0
        es = 0.0
        if bw == 0:
            # no floor coupled to another (a row of SDOF oscillators): K u and C u̇ floor
            # by floor, fused with the outputs (the products of _band_mv, rounded alike up
            # to a fused multiply-add, without its generic band loops and scratch stores: a
            # third of an exact step's cost)
            for i in range(n):
                u = x[i]
                v = x[n + i]
                ku = k_band[0, i] * u
                u_out[o, i] = u
                v_out[o, i] = v
                acc_out[o, i] = -(ku + c_band[0, i] * v) * m_inv[i]
                ek += 0.5 * m_diag[i] * v * v
                es += 0.5 * u * ku
        else:
            _band_mv(k_band, c_band, x, n, bw, lin)
            for i in range(n):
                u_out[o, i] = x[i]
                v_out[o, i] = x[n + i]
                acc_out[o, i] = -(lin[0, i] + lin[1, i]) * m_inv[i]
            for i in range(n):
                ek += 0.5 * m_diag[i] * x[n + i] * x[n + i]
                es += 0.5 * x[i] * lin[0, i]
        # nothing but the viscous dampers takes energy out (every gap open, linear
        # storeys): the step's viscous work is the input work less the change of kinetic
        # and strain energy, exactly
        e_d += e_step - ((ek + es) - e_prev)
        e_prev = ek + es
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
        k += 1
    ws_f[W_E_INPUT] = e_in
    ws_f[W_E_DAMP] = e_d
    return k


@njit(**_NRT_FREE)
def _recoverable_out_of_line(code, par, s, d, z, v):
    """:func:`pounding.hysteresis.dispatch.storey_recoverable`, called (see
    :func:`_law_out_of_line`)."""
    return storey_recoverable(code, par, s, d, z, v)


@njit(**_NRT_FREE)
def _stored_out_of_line(code, p0, p1, p2, delta, slip):
    """:func:`pounding.contact.dispatch.stored_energy`, called (see :func:`_law_out_of_line`)."""
    return stored_energy(code, p0, p1, p2, delta, slip)


@njit(**_NRT_FREE)
def _deriv_out_of_line(y, y_start, ag, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap,
                       ccode, cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin,
                       dy, power, row):
    """:func:`_deriv`, called: where :func:`_advance` needs f(x) at a grid point or event."""
    _deriv(y, y_start, ag, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap, ccode, cparams,
           committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin, dy, power, row)


@njit(cache=True, error_model="numpy", nogil=True, fastmath={"contract"})
def integrate_chunk(k0, k1, dt, ag, exact_free, blk, fops, g0, g1, faa, bw, k_band, c_band,
                    m_diag, mr, r, cdof, cw, cgap, ccode, cparams, s_lo, s_hi, s_code, s_par,
                    s_zi, rtol, atol, h_max, x, committed, sstate, wc, w_start, imp_row, last_f,
                    ws_f, ws_i, u_out, v_out, acc_out, pen_out, f_out, vs_out, e_out, imp,
                    cpeak, ccount):
    """Advance grid steps ``k0 … k1−1`` (times ``k·dt``), writing outputs at ``k+1``.

    Parameters (all arrays are updated in place)
    ----------
    dt : float
        Grid step [s]. ``ag`` (nt,) ground acceleration at grid points [m/s²].
    exact_free : bool
        Take steps without contact with the exact propagator (cost O(N²) a step, cheapest
        for small models); otherwise with the adaptive RK (O(N·bw) a stage).
    blk, fops, g0, g1, faa
        The exact step over dt (:class:`pounding.integrate.propagator.FreeStep`: blocks,
        block operators, Γ0, Γ1, input-energy coefficients of a_g²; unused unless
        ``exact_free``).
    bw, k_band, c_band, m_diag, mr, r
        Half-bandwidth of K and C; K of the linear storeys [N/m] and C [N·s/m] in band
        storage (``(2 bw + 1, N)``, :func:`pounding.integrate.band_storage`); lumped floor
        masses [kg], M r, r.
    cdof, cw, cgap, ccode, cparams
        Contacts: DOFs and signed weights of the two contact points (n_c, 4), gap [m], law
        code, law constants.
    s_lo, s_hi, s_code, s_par, s_zi
        Yielding storeys: DOF below (−1 ground) and above, storey-law code and constants,
        index of the storey's ``z`` among the extra states (−1: none). Empty for linear
        buildings (then ``exact_free`` may be true).
    rtol : float; atol : (2N,)
        RK tolerances. ``h_max`` caps RK steps [s].
    x : (2N + n_z,)
        State [u, u̇, z] at grid point k0 (relative to the ground; z of Bouc–Wen storeys).
    committed : (n_c, STATE_SIZE)
        Committed contact states.
    sstate : (n_s, 2)
        Committed drift [m] and shear [N] of every yielding storey.
    wc, w_start : (n_c,)
        Cumulative contact work [J], and its value at each open impact's start.
    imp_row : (n_c,) int
        Row of each contact's open impact in ``imp`` (−1 if none).
    last_f : (n_c, 4)
        Per closed contact: time, force and force rate dF/dt at the start of the current
        step, for locating the peak force inside each step (cubic Hermite); and the first
        step accepted after the contact's last onset [s] (0: none yet), where the next
        onset's steps start.
    ws_f, ws_i
        Workspace scalars (proposed RK step, cumulative input, viscous and storey work) and
        counters (mode, impacts, table overflow, RK steps, rejections, events, failure).
    u_out, v_out, acc_out : (nt, N); pen_out, f_out : (nt, n_c) (f_out zero on entry);
    vs_out : (nt, n_s);
    e_out : (nt, 7); imp : (cap, 8)
        Outputs (vs_out: shear of every yielding storey).
    cpeak, ccount : (n_c,)
        Peak force [N] and number of impacts of every contact (kept even if the impact
        table overflows).
    """
    m = x.shape[0]
    nc = cgap.shape[0]
    npw = P_CONTACT + nc
    # scratch: RK stages and powers (main and bracketing steps), f at the step start,
    # trial states, the exact step's sweep, K u / C u̇, and every contact's δ, δ̇ at the
    # current state (gd, gr) and at the end of a trial exact step (gd1, gr1); 1 / m
    _advance(k0, k1, dt, ag, exact_free, blk, fops, g0, g1, faa, bw, k_band, c_band, m_diag,
             mr, r, cdof, cw, cgap, ccode, cparams, s_lo, s_hi, s_code, s_par, s_zi, rtol,
             atol, h_max, x, committed, sstate, wc, w_start, imp_row, last_f, ws_f, ws_i,
             u_out, v_out, acc_out, pen_out, f_out, vs_out, e_out, imp, cpeak, ccount,
             np.zeros((7, m)), np.zeros((7, npw)), np.zeros((7, m)), np.zeros((7, npw)),
             np.zeros((1, m)), np.zeros((1, npw)), np.zeros(m), np.zeros(m), np.zeros(m),
             np.zeros(m), np.zeros(2 * m + 4), np.zeros((2, r.shape[0])), np.zeros(nc),
             np.zeros(nc), np.zeros(nc), np.zeros(nc), 1.0 / m_diag)


@njit(**_NRT_FREE)
def _advance(k0, k1, dt, ag, exact_free, blk, fops, g0, g1, faa, bw, k_band, c_band,
                    m_diag, mr, r, cdof, cw, cgap, ccode, cparams, s_lo, s_hi, s_code, s_par,
                    s_zi, rtol, atol, h_max, x, committed, sstate, wc, w_start, imp_row, last_f,
                    ws_f, ws_i, u_out, v_out, acc_out, pen_out, f_out, vs_out, e_out, imp,
                    cpeak, ccount,
             ks, ps, ks_b, ps_b, kx, px, ytmp, y1, yb, x1, acc, lin, gd, gr, gd1, gr1, m_inv):
    """:func:`integrate_chunk`'s work, with its scratch arrays given."""
    n = r.shape[0]
    m = x.shape[0]
    nc = cgap.shape[0]
    ns = s_lo.shape[0]
    npw = P_CONTACT + nc
    cap = imp.shape[0]
    for c in range(nc):
        dsum, gr[c] = _gap(c, x, n, cdof, cw)
        gd[c] = dsum - cgap[c]

    onset_c = -1  # contact whose onset ended the last accepted step (−1: none)
    kx_at = -1  # grid point at which kx holds f(x) (its last RK step's FSAL stage), or −1
    k = k0
    while k < k1:
        if ws_i[I_MODE] == 0:
            # exact steps while every gap stays open; stops at the step in which one closes
            k = _free_run(k, k1, dt, ag, blk, fops, g0, g1, faa, bw, k_band, c_band, m_diag, m_inv,
                          cdof, cw, cgap, x, x1, acc, lin, gd, gr, gd1, gr1, wc, ws_f, u_out,
                          v_out, acc_out, pen_out, e_out)
            if k >= k1:
                break
            ws_i[I_MODE] = 1
        t_k = k * dt
        a0 = ag[k]
        a1 = ag[k + 1]
        dag = (a1 - a0) / dt
        if ws_i[I_MODE] == 1:
            # ---------------- adaptive RK with events, landing on t_k + dt
            s = 0.0
            h = min(ws_f[W_H], dt, h_max)
            if kx_at != k:
                # (else the last step of the previous grid step ended here, evaluating
                # f(x, ag[k]) as its last stage: the same numbers)
                _deriv_out_of_line(x, x, a0, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap, ccode,
                       cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate, lin, kx,
                       px, 0)
            kx_at = -1
            on_grid = False
            while s < dt:
                last = False
                if s + h >= dt * (1.0 - 1e-12):
                    h = dt - s
                    last = True
                a_end = a1 if last else a0 + dag * (s + h)
                err = _rk_step(x, kx, px, h, a0, dag, s, a_end, n, bw, k_band, c_band, m_inv,
                               mr, r, cdof, cw, cgap, ccode, cparams, committed, s_lo, s_hi,
                               s_code, s_par, s_zi, sstate, lin, ks, ps, ytmp, y1, atol, rtol)
                ws_i[I_NSTEPS] += 1
                if err > 1.0 or not np.isfinite(err):
                    ws_i[I_NREJECT] += 1
                    fac = 0.9 * err ** -0.2 if np.isfinite(err) else 0.1
                    h *= max(0.1, fac)
                    ws_f[W_H] = h
                    if h < 1e-14 * dt:
                        ws_i[I_FAILED] = 1  # step size underflow
                        return
                    continue
                # events inside the accepted step?
                h_try = h
                fac_try = min(5.0, max(0.2, 0.9 * err ** -0.2)) if err > 0.0 else 5.0
                h_acc = h
                te, ce, kind = _find_event(x, kx, y1, ks, h, n, cdof, cw, cgap, committed, s_lo,
                                           s_hi, -1, 0)
                ev_c = -1
                ev_kind = 0
                while ce >= 0:
                    # locate on real RK steps by the Illinois method, keeping the 'after' side
                    g_lo = _event_value(kind, ce, x, n, cdof, cw, cgap, s_lo, s_hi)
                    g_hi = _event_value(kind, ce, y1, n, cdof, cw, cgap, s_lo, s_hi)
                    upward = kind == EV_ONSET or kind == EV_RELOADING or kind == EV_DRIFT_MIN
                    lo = 0.0
                    hi = h_acc
                    side_ok = (g_hi > 0.0) if upward else (g_hi <= 0.0)
                    if kind == 2 and g_hi == 0.0:
                        side_ok = True
                    found_hi = side_ok
                    if not side_ok:
                        # grazing: both ends on the 'before' side; test the estimate
                        err = _rk_step(x, kx, px, te, a0, dag, s, a0 + dag * (s + te), n, bw,
                                       k_band, c_band, m_inv, mr, r, cdof, cw, cgap, ccode,
                                       cparams, committed, s_lo, s_hi, s_code, s_par, s_zi,
                                       sstate, lin, ks_b, ps_b, ytmp, yb, atol, rtol)
                        g_te = _event_value(kind, ce, yb, n, cdof, cw, cgap, s_lo, s_hi)
                        if (g_te > 0.0) == upward and g_te != 0.0:
                            hi = te
                            g_hi = g_te
                            found_hi = True
                    if not found_hi:
                        break  # the interpolant's touch was not real
                    t_try = te if (te > lo and te < hi) else 0.5 * (lo + hi)
                    if kind == EV_DRIFT_MAX or kind == EV_DRIFT_MIN:
                        g_tol = atol[n + s_hi[ce]]
                    elif kind == EV_MAX_COMPRESSION or kind == EV_RELOADING:
                        g_tol = atol[n + cdof[ce, 0]]
                    else:
                        g_tol = atol[cdof[ce, 0]]
                    side = 0
                    have_after = False
                    for _ in range(60):
                        err = _rk_step(x, kx, px, t_try, a0, dag, s, a0 + dag * (s + t_try),
                                       n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap,
                                       ccode, cparams, committed, s_lo, s_hi, s_code, s_par,
                                       s_zi, sstate, lin, ks_b, ps_b, ytmp, yb, atol, rtol)
                        ws_i[I_NSTEPS] += 1
                        g = _event_value(kind, ce, yb, n, cdof, cw, cgap, s_lo, s_hi)
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
                        err_after = _rk_step(x, kx, px, hi, a0, dag, s, a0 + dag * (s + hi), n,
                                             bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap,
                                             ccode, cparams, committed, s_lo, s_hi, s_code,
                                             s_par, s_zi, sstate, lin, ks, ps, ytmp, y1, atol,
                                             rtol)
                        ws_i[I_NSTEPS] += 1
                    err = err_after
                    h_acc = hi
                    ev_c = ce
                    ev_kind = kind
                    last = False
                    # any other event earlier in this shorter step?
                    te, ce, kind = _find_event(x, kx, y1, ks, h_acc, n, cdof, cw, cgap,
                                               committed, s_lo, s_hi, ev_c, ev_kind)
                # ---- accept the step [s, s + h_acc]
                ws_f[W_ERR_OLD] = max(err, 1e-4)
                if onset_c >= 0:
                    # the first step accepted after this contact's onset: where the next
                    # onset of the contact will start (no rejections from a free-flight step)
                    last_f[onset_c, 3] = h_acc
                    onset_c = -1
                ws_f[W_E_INPUT] += h_acc * (_B1 * ps[0, 0] + _B3 * ps[2, 0] + _B4 * ps[3, 0]
                                            + _B5 * ps[4, 0] + _B6 * ps[5, 0])
                ws_f[W_E_DAMP] += h_acc * (_B1 * ps[0, 1] + _B3 * ps[2, 1] + _B4 * ps[3, 1]
                                           + _B5 * ps[4, 1] + _B6 * ps[5, 1])
                if ns > 0:
                    ws_f[W_E_STOREY] += h_acc * (_B1 * ps[0, 2] + _B3 * ps[2, 2]
                                                 + _B4 * ps[3, 2] + _B5 * ps[4, 2]
                                                 + _B6 * ps[5, 2])
                for c in range(nc):
                    q = P_CONTACT + c
                    wc[c] += h_acc * (_B1 * ps[0, q] + _B3 * ps[2, q] + _B4 * ps[3, q]
                                      + _B5 * ps[4, q] + _B6 * ps[5, q])
                for i in range(m):
                    x[i] = y1[i]
                s_new = dt if last else s + h_acc
                on_grid = last
                t_now = t_k + s_new
                # commit the yielding storeys (contract step 3 of pounding.hysteresis.base)
                for q in range(ns):
                    d, dr = _drift(q, x, n, s_lo, s_hi)
                    zi = s_zi[q]
                    sstate[q, V_C] = _storey_out_of_line(s_code[q], s_par, q, d, dr,
                                                  x[2 * n + zi] if zi >= 0 else 0.0,
                                                  sstate[q, D_C], sstate[q, V_C])[0]
                    sstate[q, D_C] = d
                was_event = ev_c >= 0
                if ev_kind == EV_DRIFT_MAX or ev_kind == EV_DRIFT_MIN:
                    ws_i[I_NEVENTS] += 1
                    ev_c = -1  # a storey, not a contact: the contact loop must not see it
                    ev_kind = 0
                # commit contact states at the step end; handle the event
                state_changed = False
                for c in range(nc):
                    dsum, rate = _gap(c, x, n, cdof, cw)
                    delta = dsum - cgap[c]
                    if c == ev_c and ev_kind == EV_ONSET:
                        # contact onset (contract step 3): commit v0 at the located instant
                        committed[c, V0] = max(rate, V0_MIN)
                        committed[c, SLIP] = 0.0
                        committed[c, DMAX] = max(delta, 0.0)
                        state_changed = True
                        f0 = _law_out_of_line(ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2],
                                       max(delta, 1e-300), rate, committed[c, V0],
                                       committed[c, SLIP], committed[c, DMAX])[0]
                        row = ws_i[I_NIMP]
                        if row < cap:
                            imp[row, IMP_CONTACT] = c
                            imp[row, IMP_START] = t_now
                            imp[row, IMP_END] = np.nan
                            imp[row, IMP_V0] = committed[c, V0]
                            imp[row, IMP_PEAK] = f0
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
                        w_start[c] = wc[c]
                        last_f[c, 0] = t_now
                        last_f[c, 1] = f0
                        # dF/dt at δ = 0+ can be unbounded (Hertz-type laws): no interior
                        # peak is sought in the first step, whose end value is kept instead
                        last_f[c, 2] = np.nan
                        ws_i[I_NEVENTS] += 1
                    elif committed[c, V0] > 0.0:
                        if c == ev_c and ev_kind == EV_SEPARATION:
                            # separation: close the impact's row, open the state
                            row = imp_row[c]
                            if row >= 0:
                                imp[row, IMP_END] = t_now
                                imp[row, IMP_E] = max(-rate, 0.0) / committed[c, V0]
                                imp[row, IMP_ENERGY] = wc[c] - w_start[c]
                            imp_row[c] = -1
                            for q in range(STATE_SIZE):
                                committed[c, q] = 0.0
                            state_changed = True
                            ws_i[I_NEVENTS] += 1
                        else:
                            f, kd, kr, tv0, tslip, tdmax = _law_out_of_line(
                                ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2], delta,
                                rate, committed[c, V0], committed[c, SLIP], committed[c, DMAX])
                            committed[c, V0] = tv0
                            committed[c, SLIP] = tslip
                            committed[c, DMAX] = tdmax
                            # force rate at the step end, then the largest force inside the
                            # step from the cubic Hermite of (F, dF/dt) at its two ends
                            rel_acc = 0.0
                            for q in range(4):
                                rel_acc += cw[c, q] * ks[6, n + cdof[c, q]]
                            df1 = kd * rate + kr * rel_acc
                            fmax = max(f, _hermite_max(last_f[c, 1], last_f[c, 2], f, df1,
                                                       t_now - last_f[c, 0]))
                            if fmax > cpeak[c]:
                                cpeak[c] = fmax
                            row = imp_row[c]
                            if row >= 0:
                                if delta > imp[row, IMP_DMAX]:
                                    imp[row, IMP_DMAX] = delta
                                if fmax > imp[row, IMP_PEAK]:
                                    imp[row, IMP_PEAK] = fmax
                            last_f[c, 0] = t_now
                            last_f[c, 1] = f
                            last_f[c, 2] = df1
                            if ev_c == c:
                                ws_i[I_NEVENTS] += 1
                if state_changed:
                    a_end = a1 if last else a0 + dag * s_new
                    _deriv_out_of_line(x, x, a_end, n, bw, k_band, c_band, m_inv, mr, r, cdof, cw, cgap,
                           ccode, cparams, committed, s_lo, s_hi, s_code, s_par, s_zi, sstate,
                           lin, kx, px, 0)
                else:
                    for i in range(m):
                        kx[0, i] = ks[6, i]
                    for i in range(npw):
                        px[0, i] = ps[6, i]
                # next step size (PI-free elementary controller); a step cut short by the
                # grid does not shrink the proposal, one cut by an event restarts from it
                if was_event:
                    ws_f[W_H] = h_try
                    if ev_kind == EV_ONSET:
                        onset_c = ev_c
                        if last_f[ev_c, 3] > 0.0:
                            ws_f[W_H] = min(h_try, last_f[ev_c, 3])
                elif last:
                    ws_f[W_H] = max(ws_f[W_H], h_acc * fac_try)
                else:
                    ws_f[W_H] = h_acc * fac_try
                h = ws_f[W_H]
                h = min(h, h_max)
                s = s_new
            if on_grid:
                kx_at = k + 1
            # back to exact stepping once every contact is open
            any_closed = False
            for c in range(nc):
                if committed[c, V0] > 0.0:
                    any_closed = True
            if not any_closed and exact_free:
                ws_i[I_MODE] = 0
        # ---------------- outputs at grid point k + 1
        o = k + 1
        _band_mv(k_band, c_band, x, n, bw, lin)
        for i in range(n):
            u_out[o, i] = x[i]
            v_out[o, i] = x[n + i]
            acc_out[o, i] = kx[0, n + i] + r[i] * a1
        ek = 0.0
        es = 0.0
        for i in range(n):
            ek += 0.5 * m_diag[i] * x[n + i] * x[n + i]
            es += 0.5 * x[i] * lin[0, i]
        recov = 0.0
        for q in range(ns):
            vs_out[o, q] = sstate[q, V_C]
            zi = s_zi[q]
            recov += _recoverable_out_of_line(s_code[q], s_par, q, sstate[q, D_C],
                                        x[2 * n + zi] if zi >= 0 else 0.0, sstate[q, V_C])
        wsum = 0.0
        stored = 0.0
        for c in range(nc):
            dsum, rate = _gap(c, x, n, cdof, cw)
            delta = dsum - cgap[c]
            gd[c] = delta
            gr[c] = rate
            pen_out[o, c] = delta
            f = 0.0
            if committed[c, V0] > 0.0:
                f = _law_out_of_line(ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2], delta, rate,
                              committed[c, V0], committed[c, SLIP], committed[c, DMAX])[0]
                stored += _stored_out_of_line(ccode[c], cparams[c, 0], cparams[c, 1], cparams[c, 2],
                                        delta, committed[c, SLIP])
            f_out[o, c] = f
            wsum += wc[c]
        e_out[o, E_INPUT] = ws_f[W_E_INPUT]
        e_out[o, E_KINETIC] = ek
        e_out[o, E_STRAIN] = es + recov
        e_out[o, E_DAMPING] = ws_f[W_E_DAMP]
        e_out[o, E_CONTACT_WORK] = wsum
        e_out[o, E_CONTACT_STORED] = stored
        e_out[o, E_HYSTERETIC] = ws_f[W_E_STOREY] - recov
        k += 1
