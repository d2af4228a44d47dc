"""The equations of motion as the compiled kernel evaluates them: ``ẏ = f(y)`` for buildings
whose floors may strike each other, and the jerk (rate of the acceleration) the kernel uses
to locate acceleration peaks inside steps.

``y = [u (N), u̇ (N), z (one per Bouc–Wen storey)]``, displacements and velocities relative to
the ground; ``M ü + C u̇ + K u + V(storeys) − Σ contact forces = −M R a_g(t)``, M lumped
(diagonal), K and C banded, R the (N, G) influence matrix of the G ground components
``a_g`` (G = 1: a planar model under one record). Contact forces act on *contact rows*: the
penetration of contact c is ``δ = Σ_q w_cq u_(j_cq) − gap_c`` over the W DOFs and weights of
its row (``cdof``, ``cw`` of shape (n_c, W); W = 4 for floor-to-floor and floor-to-column
contacts of planar buildings, wider where a façade point moves with several DOFs).

The ground components ``a_g`` at the instant a function needs them are row ``G_NOW`` of the
(5, G) array ``gnd`` (:data:`G_A0`, :data:`G_A1`: the grid values at the ends of the current
grid step; :data:`G_SLOPE`: their slope; :data:`G_END`: their values at the end of the RK
step being taken). The first component is written out in the
expressions where G = 1 has always had it, and the others added after it, so that a G = 1
model computes bit for bit what it did before there were components.

Every function here is compiled with numba's reference counting off (they allocate
nothing); see :data:`NRT_FREE`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numba import njit

from pounding.contact.codes import V0
from pounding.contact.dispatch import (
    has_linear_spring,
    law_releases,
    law_trial,
    release_value,
    stored_energy,
)
from pounding.devices.laws import DEVICE_MIN, device_rate_terms, folded_dashpot
from pounding.hysteresis.base import D_C, V_C
from pounding.hysteresis.dispatch import storey_recoverable, storey_trial
from pounding.integrate.layout import (
    DELTA_EPS,
    EL_FOLDED,
    EL_LEVER,
    EL_ROCK,
    HS_A0,
    P_CONTACT,
    P_DAMP,
    P_DEVICE,
    P_INPUT,
    P_STOREY,
    RATE_SIDE,
    ROW_BLOCK,
    STATION_MASS,
)

G_A0, G_A1, G_SLOPE, G_END, G_NOW = range(5)
G_ROWS = 5
"""Rows of ``gnd`` (G_ROWS, G): the ground components at the start and end of the grid step,
their slope [m/s³], their values at the end of the RK step being taken and at the instant
being evaluated [m/s²]."""

NRT_FREE: dict[str, Any] = dict(cache=True, error_model="numpy", nogil=True, fastmath={"contract"},
                                _nrt=False, no_cpython_wrapper=True, no_cfunc_wrapper=True)
"""Options of the kernel's working functions. They allocate nothing (the scratch comes from
:func:`pounding.integrate.kernel.integrate_chunk`), so they run with numba's
reference-counting runtime off: no array passed to a call costs an atomic increment and
decrement. Sums are never reassociated (``fastmath`` allows only fused multiply-add), so
results do not depend on how arrays happen to be aligned in memory. Only other compiled
functions call them, so numba builds no wrapper to call them from Python (a cold compile
spent ~6 s of its ~50 s of CPU on those wrappers)."""

ENTRY: dict[str, Any] = {**NRT_FREE, "no_cpython_wrapper": False, "no_cfunc_wrapper": False}
"""Options of the kernel's entry point (:func:`pounding.integrate.kernel.integrate_chunk`):
those of the working functions, with the wrapper that Python calls it through."""

INLINE: dict[str, Any] = dict(cache=True, inline="always", error_model="numpy", fastmath={"contract"})
"""Options of the functions numba inlines where they are called: the right-hand side, inside
the Dormand–Prince step (a call would pass some twenty arrays as flattened structures, 35 ns
each time), and parts of the step loop that have a single call site. numba's inlining copies
and re-types the function at every call site, so small helpers (:func:`gap_row`, …) are
plain functions instead: LLVM inlines them without that cost (making them so cut a fresh
compile from 31 s to 26 s, with the kernel's time unchanged within the noise). LLVM's own
forced inlining (numba's ``forceinline``) instead compiled a cold start ~10 % faster with
results bit-identical, but the 10-storey pair's warm kernel ran 2× slower
(``benchmarks/bench_opensees.py --sections compare``, 2026-11-28)."""


@njit(**NRT_FREE)
def gap_row(c, y, n, cdof, cw):
    """``(Σ w u, Σ w u̇)`` of contact c: its penetration plus the gap, and its rate
    (:meth:`pounding.model.PoundingModel.contact_kinematics`)."""
    d = 0.0
    v = 0.0
    for q0 in range(0, cdof.shape[1], ROW_BLOCK):
        for q in range(q0, q0 + ROW_BLOCK):
            j = cdof[c, q]
            d += cw[c, q] * y[j]
            v += cw[c, q] * y[n + j]
    return d, v


@njit(**NRT_FREE)
def hinge_row(h, y, n, hg):
    """``(θ, θ̇)`` of hinge row h of a yielding frame: ``θ = Σ w u + a0`` over its frame's
    floors in the frame's current configuration (``hg``: the hinge rows,
    :class:`pounding.integrate.kernel_model.HingeRows`)."""
    hdof = hg.dof
    hw = hg.weight
    d = 0.0
    v = 0.0
    for q0 in range(0, hdof.shape[1], ROW_BLOCK):
        for q in range(q0, q0 + ROW_BLOCK):
            j = hdof[h, q]
            d += hw[h, q] * y[j]
            v += hw[h, q] * y[n + j]
    return d + hg.state[h, HS_A0], v


@njit(**NRT_FREE)
def ground_rest(r, i, a, j):
    """``Σ_{g ≥ 1} R[i, g] a[j, g]``: floor i's share of the ground components after the
    first, at row j of ``a`` (a grid row of the record, or a row of ``gnd``); 0 for G = 1."""
    s = 0.0
    for g in range(1, r.shape[1]):
        s += r[i, g] * a[j, g]
    return s


@njit(**INLINE)
def add_ground_rest(out, r, a, j, n):
    """``out[i] += Σ_{g ≥ 1} R[i, g] a[j, g]`` for every floor (nothing for G = 1): the
    ground components after the first, added to accelerations that hold the first.

    This and the other ground helpers are inlined where they are called: called, a helper
    that passes three arrays to do nothing (G = 1) cost the SDOF pair's contact steps 6 %."""
    for g in range(1, r.shape[1]):
        ag = a[j, g]
        for i in range(n):
            out[i] += r[i, g] * ag


@njit(**INLINE)
def ground_at(gnd, row, s):
    """``gnd[row] = gnd[G_A0] + gnd[G_SLOPE] s``: the ground components at local time s
    [s] of the grid step."""
    for g in range(gnd.shape[1]):
        gnd[row, g] = gnd[G_A0, g] + gnd[G_SLOPE, g] * s


@njit(**INLINE)
def ground_at_grid_end(gnd, row):
    """``gnd[row] = gnd[G_A1]``: the record's values at the grid step's end, bit for bit."""
    for g in range(gnd.shape[1]):
        gnd[row, g] = gnd[G_A1, g]


@njit(**INLINE)
def set_ground(gnd, row, a, j):
    """``gnd[row] = a[j]``: every component of row j of ``a``."""
    for g in range(gnd.shape[1]):
        gnd[row, g] = a[j, g]


@njit(**NRT_FREE)
def drift_of(lo, hi, y, n):
    """Drift and drift rate of the storey between DOF ``lo`` (−1: the ground) and ``hi``."""
    if lo >= 0:
        return y[hi] - y[lo], y[n + hi] - y[n + lo]
    return y[hi], y[n + hi]


@njit(**NRT_FREE)
def element_drift(s, lo, hi, par, y, n):
    """Drift and drift rate of element row ``s`` (DOFs ``lo`` and ``hi``, constants ``par``):
    :func:`drift_of`, less its lever times the rocking of a flexible base under it
    (``d = u[hi] − u[lo] − lever · φ``, :data:`pounding.integrate.layout.EL_ROCK`)."""
    d, dr = drift_of(lo, hi, y, n)
    rock = par[s, EL_ROCK]
    if rock >= 0.0:
        i = int(rock)
        lever = par[s, EL_LEVER]
        d -= lever * y[i]
        dr -= lever * y[n + i]
    return d, dr


@njit(**NRT_FREE)
def band_mv(kb, cb, y, n, bw, lin):
    """:func:`band_products`, called (the right-hand side, the jerk and the adaptive
    steps' outputs)."""
    band_products(kb, cb, y, n, bw, lin)


@njit(**INLINE)
def band_products(kb, cb, y, n, bw, lin):
    """``lin[0] = K y[:n]``, ``lin[1] = C y[n:2n]`` with K and C in band storage
    (``kb[d, i] = K[i, i + d − bw]``) plus their few entries outside the band (the
    columns after the n-th: ``[i, j, K_ij]``, :func:`pounding.integrate.kernel_model.
    kernel_bands`): O(N·bw + those), each row of the band summed in column order, and the
    loop over rows vectorises without reassociation. Inlined in the exact steps' outputs
    (a call cost a linked SDOF pair's exact step ~10 of its ~100 ns); the same sums,
    so the same numbers, as :func:`band_mv`'s."""
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
    for q in range(n, kb.shape[1]):
        i = int(kb[0, q])
        j = int(kb[1, q])
        lin[0, i] += kb[2, q] * y[j]
        lin[1, i] += cb[2, q] * y[n + j]


@njit(**NRT_FREE)
def law_call(code, p0, p1, p2, delta, rate, v0, slip, dmax):
    """:func:`pounding.contact.dispatch.law_trial`, called rather than inlined.

    numba's ``inline="always"`` copies and re-types a function at every call site; with every
    contact law inlined into the right-hand side and the step loop, all the laws were compiled
    many times over (a first run compiled for 240 s on 2 cores). Called, they compile once,
    with no measurable change in the kernel's time (docs/engine.md, "Compiled once").
    """
    return law_trial(code, p0, p1, p2, delta, rate, v0, slip, dmax)


@njit(**NRT_FREE)
def storey_call(code, par, s, d, dr, z, d_c, v_c):
    """:func:`pounding.hysteresis.dispatch.storey_trial`, called (see :func:`law_call`)."""
    return storey_trial(code, par, s, d, dr, z, d_c, v_c)


@njit(**NRT_FREE)
def first_unknown_law(ct, el):
    """The first contact (its index c) or element row (``n_c + s``) whose law code no
    compiled law implements, or −1: the dispatchers return the failure value NaN for such
    a code (never another law's force), here tried once at a probe point (contacts at
    unit constants and state, storeys and links at zero drift, rate and ``z``, where every
    law is finite)."""
    nc = ct.code.shape[0]
    for c in range(nc):
        if np.isnan(law_call(ct.code[c], 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0)[0]):
            return c
    for s in range(el.code.shape[0]):
        if np.isnan(storey_call(el.code[s], el.params, s, 0.0, 0.0, 0.0, 0.0, 0.0)[0]):
            return nc + s
    return -1


@njit(**NRT_FREE)
def recoverable_call(code, par, s, d, z, v):
    """:func:`pounding.hysteresis.dispatch.storey_recoverable`, called (see
    :func:`law_call`)."""
    return storey_recoverable(code, par, s, d, z, v)


@njit(**NRT_FREE)
def stored_call(code, p0, p1, p2, delta, slip):
    """:func:`pounding.contact.dispatch.stored_energy`, called (see :func:`law_call`)."""
    return stored_energy(code, p0, p1, p2, delta, slip)


@njit(**INLINE)
def deriv(y, y_start, gnd, fl, ct, el, committed, sstate, lin, dy, power, row):
    """dy = f(y) for the structure with contacts; power = [input, viscous, storey work,
    per-contact F δ̇]; the ground components at ``gnd[G_NOW]``.

    ``fl``, ``ct``, ``el``: the floors, contacts and element rows of the model
    (:class:`pounding.integrate.kernel_model.KernelArrays`). ``y_start``: the state at the
    start of the step (``y`` itself outside a step). Writes row ``row`` of ``dy`` and
    ``power`` (2-D arrays: no views in the hot loop). Contact forces and yielding storeys use
    their committed states (read only).

    Inlined at its one call site in the Dormand–Prince step (where a call would pass some
    twenty arrays as flattened structures, 35 ns a call); called through
    :func:`deriv_call` elsewhere.
    """
    n = fl.m_diag.shape[0]
    bw = fl.bw
    k_band = fl.k_band
    c_band = fl.c_band
    m_inv = fl.m_inv
    mr = fl.mr
    r = fl.r
    cdof, cw, cgap, ccode, cparams = ct
    s_lo, s_hi, s_code, s_par, s_zi = el.lo, el.hi, el.code, el.params, el.z_index
    nc = cgap.shape[0]
    # linear part: acc = −M⁻¹(K u + C v) − R a_g, K (linear storeys only) and C banded
    # (half-bandwidth bw), M diagonal (lumped floor masses): O(N·bw) work; the first ground
    # component here, the others after; input power −u̇ᵀ M R a_g
    ag = gnd[G_NOW, 0]
    p_in = 0.0
    p_d = 0.0
    if bw == 0:
        # no floor coupled to another (a row of SDOF oscillators): floor by floor
        for i in range(n):
            v = y[n + i]
            cv = c_band[0, i] * v
            dy[row, i] = v
            dy[row, n + i] = -(k_band[0, i] * y[i] + cv) * m_inv[i] - r[i, 0] * ag
            p_in -= v * mr[i, 0] * ag
            p_d += v * cv
    else:
        band_mv(k_band, c_band, y, n, bw, lin)
        for i in range(n):
            dy[row, i] = y[n + i]
            dy[row, n + i] = -(lin[0, i] + lin[1, i]) * m_inv[i] - r[i, 0] * ag
            p_in -= y[n + i] * mr[i, 0] * ag
            p_d += y[n + i] * lin[1, i]
    for g in range(1, r.shape[1]):
        ag = gnd[G_NOW, g]
        for i in range(n):
            dy[row, n + i] -= r[i, g] * ag
            p_in -= y[n + i] * mr[i, g] * ag
    power[row, P_INPUT] = p_in
    power[row, P_DAMP] = p_d
    # yielding frames: in their current configuration the restoring force of a frame's
    # floors is K u + f0 (K, its condensed tangent stiffness, in the band above); f0 here
    # (its work is a potential within a configuration: grid_outputs has it in closed form)
    frames = fl.f_rows
    if frames.shape[0] > 0:
        for q in range(frames.shape[0]):
            i = int(frames[q, 0])
            dy[row, n + i] -= frames[q, 1] * m_inv[i]
    # yielding storeys: shear V from the storey law, −V on the floor above, +V below; the
    # links between buildings (codes ≥ DEVICE_MIN) are rows of the same kind
    p_s = 0.0
    p_dev = 0.0
    p_fold = 0.0
    for s in range(s_lo.shape[0]):
        d, dr = element_drift(s, s_lo[s], s_hi[s], s_par, y, n)
        if s_par[s, EL_FOLDED] != 0.0:
            # a linear link folded into K and C (its force is in the banded products
            # above): its dashpot's power c ḋ², in C's, is the links' work, not the
            # buildings' viscous work
            p_fold += folded_dashpot(s_code[s], s_par[s, 0], s_par[s, 1]) * dr * dr
            continue
        zi = s_zi[s]
        z = y[2 * n + zi] if zi >= 0 else 0.0
        v, kt, zd = storey_call(s_code[s], s_par, s, d, dr, z, sstate[s, D_C], sstate[s, V_C])
        hi = s_hi[s]
        lo = s_lo[s]
        dy[row, n + hi] -= v * m_inv[hi]
        if lo >= 0:
            dy[row, n + lo] += v * m_inv[lo]
        if s_par[s, EL_ROCK] >= 0.0:  # the storey's moment V·lever on the rocking footing
            rk = int(s_par[s, EL_ROCK])
            dy[row, n + rk] += s_par[s, EL_LEVER] * v * m_inv[rk]
        if zi >= 0:
            dy[row, 2 * n + zi] = zd
        if s_code[s] >= DEVICE_MIN:
            p_dev += v * dr
        else:
            p_s += v * dr
    power[row, P_STOREY] = p_s
    power[row, P_DEVICE] = p_dev
    if p_fold != 0.0:
        power[row, P_DAMP] -= p_fold
        power[row, P_DEVICE] += p_fold
    for c in range(nc):
        dsum, rate = gap_row(c, y, n, cdof, cw)
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
            dsum_start, rate_start = gap_row(c, y_start, n, cdof, cw)
            if (rate_start > 0.0) != (rate > 0.0):
                rate_law = RATE_SIDE if rate_start > 0.0 else 0.0
            p2 = cparams[c, 2]
            engaged = True
            if law_releases(ccode[c], cparams[c, 0], cparams[c, 1], p2):
                # a law clipped at F = 0 keeps the side of the clip the step began on: no
                # force if released, else k δ + c δ̇ unclipped (as with tension, p2 = 1);
                # the crossing is a located event (EV_RELEASE, EV_REENGAGE)
                engaged = release_value(cparams[c, 0], cparams[c, 1],
                                        dsum_start - cgap[c], rate_start) > 0.0
                p2 = 1.0
            if engaged:
                f, kd, kr, _, _, _ = law_call(ccode[c], cparams[c, 0], cparams[c, 1], p2,
                                              max(delta, DELTA_EPS), rate_law,
                                              committed[c, V0], committed[c, 1],
                                              committed[c, 2])
                f += kr * (rate - rate_law)
                if delta < DELTA_EPS and has_linear_spring(ccode[c]):
                    f += kd * (delta - DELTA_EPS)
        power[row, P_CONTACT + c] = f * rate
        if f != 0.0:
            # the force pushes the left point left and the right point right, shared to
            # the floors with the point's weights (−w F on each)
            for q0 in range(0, cdof.shape[1], ROW_BLOCK):
                for q in range(q0, q0 + ROW_BLOCK):
                    j = cdof[c, q]
                    dy[row, n + j] -= cw[c, q] * f * m_inv[j]
    if r.shape[1] > 1:
        # several grounds (spatially varying ground; or two components in plan, with no
        # station): a ground station's DOF (mass STATION_MASS, pounding.integrate.stations)
        # moves as its record says whatever the contacts push (what they pushed, Σ w F, is
        # taken back here, out of the contact loop above, which stays as it is), and the
        # work its motion does through them is input. The stations are the last DOFs: a
        # model in plan stops at its last floor, at once
        m_diag = fl.m_diag
        p_g = 0.0
        j = n - 1
        while j >= 0 and m_diag[j] == STATION_MASS:
            free = 0.0
            for g in range(r.shape[1]):
                free -= r[j, g] * gnd[G_NOW, g]
            p_g += (free - dy[row, n + j]) * y[n + j]
            dy[row, n + j] = free
            j -= 1
        power[row, P_INPUT] += p_g


@njit(**NRT_FREE)
def deriv_call(y, y_start, gnd, fl, ct, el, committed, sstate, lin, dy, power, row):
    """:func:`deriv`, called: where the step loop needs f at a grid point or an event."""
    deriv(y, y_start, gnd, fl, ct, el, committed, sstate, lin, dy, power, row)


@njit(**NRT_FREE)
def jerk(x, dx, fl, ct, el, committed, sstate, lin, work, out):
    """Rate of the absolute floor accelerations [m/s³] at state ``x`` with ``dx = f(x)``.

    Differentiating the equations of motion along the motion (the ground term cancels:
    ``ü + R a_g = −M⁻¹(K u + C u̇ + V + F)``)::

        d/dt (ü + R a_g) = −M⁻¹ (K u̇ + C ü + V̇ + Ḟ)

    with the storey shears' rates ``V̇ = (∂V/∂d) ḋ`` (a link's plus ``(∂F/∂ḋ) d̈ + (∂F/∂z) ż``) and every closed contact's force rate
    ``Ḟ = (∂F/∂δ) δ̇ + (∂F/∂δ̇) δ̈`` from its law's tangents at the committed state.
    ``work``: scratch of length 2N; ``out``: (N,) written.
    """
    n = fl.m_diag.shape[0]
    m_inv = fl.m_inv
    cdof, cw, cgap, ccode, cparams = ct
    s_lo, s_hi, s_code, s_par, s_zi = el.lo, el.hi, el.code, el.params, el.z_index
    for i in range(n):
        work[i] = x[n + i]
        work[n + i] = dx[n + i]
    band_mv(fl.k_band, fl.c_band, work, n, fl.bw, lin)
    for i in range(n):
        out[i] = lin[0, i] + lin[1, i]
    for s in range(s_lo.shape[0]):
        if s_par[s, EL_FOLDED] != 0.0:
            continue  # (a linear link in K and C: its rate is in the banded products)
        d, dr = element_drift(s, s_lo[s], s_hi[s], s_par, x, n)
        zi = s_zi[s]
        z = x[2 * n + zi] if zi >= 0 else 0.0
        kt = storey_call(s_code[s], s_par, s, d, dr, z, sstate[s, D_C], sstate[s, V_C])[1]
        vdot = kt * dr
        if s_code[s] >= DEVICE_MIN:
            # a link's force also moves with its rate (dashpots) and its internal variable
            kr, kz = device_rate_terms(s_code[s], s_par[s, 0], s_par[s, 1], s_par[s, 2], dr)
            vdot += kr * element_drift(s, s_lo[s], s_hi[s], s_par, dx, n)[1]
            if zi >= 0:
                vdot += kz * dx[2 * n + zi]
        out[s_hi[s]] += vdot
        if s_lo[s] >= 0:
            out[s_lo[s]] -= vdot
        if s_par[s, EL_ROCK] >= 0.0:
            out[int(s_par[s, EL_ROCK])] -= s_par[s, EL_LEVER] * vdot
    for c in range(cgap.shape[0]):
        if committed[c, V0] > 0.0:
            dsum, rate = gap_row(c, x, n, cdof, cw)
            acc = gap_row(c, dx, n, cdof, cw)[1]
            _, kd, kr, _, _, _ = law_call(ccode[c], cparams[c, 0], cparams[c, 1],
                                          cparams[c, 2], max(dsum - cgap[c], DELTA_EPS), rate,
                                          committed[c, V0], committed[c, 1], committed[c, 2])
            fdot = kd * rate + kr * acc
            for q0 in range(0, cdof.shape[1], ROW_BLOCK):
                for q in range(q0, q0 + ROW_BLOCK):
                    out[cdof[c, q]] += cw[c, q] * fdot
    for i in range(n):
        out[i] = -out[i] * m_inv[i]
