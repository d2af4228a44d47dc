"""The exact steps' share of linear Maxwell links (a spring in series with a linear dashpot,
:data:`pounding.devices.laws.MAXWELL` with α = 1): their blocks' step with the links'
spring deformations ``z`` in the state, and what the exact steps read of the links besides
K and C — their forces on the floors (the floors' accelerations), their springs' energy,
and the jerk and its rate the acceleration peaks between samples need.

A block of floors that such links tie is stepped with the extended propagator of
:func:`pounding.integrate.maxwell_propagator.compute_free_step_maxwell` (state ``[u_b, u̇_b,
z_b]``); the link's force is ``F = k z`` (floor ``hi`` receives ``−F``, floor ``lo``
``+F``) and ``ż = ḋ − F/c``. The adaptive steps integrate the same law
(:func:`pounding.devices.laws.device_trial`) with ``z`` in the same place of the state, so
the two hand over at any grid point.
"""

from __future__ import annotations

from numba import njit

from pounding.devices.laws import MAXWELL
from pounding.integrate.layout import PK_A
from pounding.integrate.peaks import row_jerk, row_snap, track_floor, update_quintic
from pounding.integrate.rhs import INLINE, NRT_FREE, ground_rest


@njit(**INLINE)
def is_linear_maxwell(el, q):
    """True if element row q is a linear Maxwell link (α = 1)."""
    return el.code[q] == MAXWELL and el.params[q, 2] == 1.0


@njit(**INLINE)
def maxwell_block_step(b, p, nb, n, mxb, el, x, x1, acc, fops, g0, g1, a0, a1):
    """The exact step of block b (floors ``p … p + nb − 1``) whose state holds the spring
    deformations of its ``m_b`` linear Maxwell links (``mxb[b]``, :class:`pounding.integrate.
    propagator.FreeStep`): writes ``x1`` of its floors and links; returns its two
    input-energy terms of the (one) ground component and the energy its links' dashpots
    dissipate over the step, less the ground's own terms (``dev_aa``)."""
    mb = mxb[b, 0]
    if nb == 2 and mb == 1:
        return two_floor_maxwell_step(p, n, 2 * n + el.z_index[mxb[b, 1]], x, x1, fops, g0,
                                      g1, a0, a1)
    sb = 2 * nb + mb
    rows = 2 * sb + 4
    for ir in range(nb):
        acc[ir] = g0[p + ir, 0] * a0 + g1[p + ir, 0] * a1
        acc[nb + ir] = g0[n + p + ir, 0] * a0 + g1[n + p + ir, 0] * a1
    for l in range(mb):
        gi = 2 * n + el.z_index[mxb[b, 1 + l]]
        acc[2 * nb + l] = g0[gi, 0] * a0 + g1[gi, 0] * a1
    for ir in range(sb, rows):
        acc[ir] = 0.0
    for j in range(nb):
        xu = x[p + j]
        xv = x[n + p + j]
        for ir in range(rows):
            acc[ir] = acc[ir] + fops[p + j, ir] * xu + fops[n + p + j, ir] * xv
    for l in range(mb):
        gi = 2 * n + el.z_index[mxb[b, 1 + l]]
        xz = x[gi]
        for ir in range(rows):
            acc[ir] = acc[ir] + fops[gi, ir] * xz
    e = 0.0
    q = sb + 2  # where the dissipation form's numbers start
    for j in range(nb):
        e += x[p + j] * acc[q + j] + x[n + p + j] * acc[q + nb + j]
    for l in range(mb):
        e += x[2 * n + el.z_index[mxb[b, 1 + l]]] * acc[q + 2 * nb + l]
    e += acc[2 * sb + 2] * a0 + acc[2 * sb + 3] * a1
    for ir in range(nb):
        x1[p + ir] = acc[ir]
        x1[n + p + ir] = acc[nb + ir]
    for l in range(mb):
        x1[2 * n + el.z_index[mxb[b, 1 + l]]] = acc[2 * nb + l]
    return acc[sb], acc[sb + 1], e


@njit(**INLINE)
def _row5(fops, ir, p, n, gi, u0, u1, v0, v1, z):
    return (fops[p, ir] * u0 + fops[p + 1, ir] * u1 + fops[n + p, ir] * v0
            + fops[n + p + 1, ir] * v1 + fops[gi, ir] * z)


@njit(**INLINE)
def two_floor_maxwell_step(p, n, gi, x, x1, fops, g0, g1, a0, a1):
    """:func:`maxwell_block_step` of a block of two floors ``p``, ``p + 1`` tied by one
    linear Maxwell link whose z is state entry ``gi`` (a linked pair of one-storey
    buildings), written out: its fourteen rows, each a sum of five products."""
    u0 = x[p]
    u1 = x[p + 1]
    v0 = x[n + p]
    v1 = x[n + p + 1]
    z = x[gi]
    x1[p] = g0[p, 0] * a0 + g1[p, 0] * a1 + _row5(fops, 0, p, n, gi, u0, u1, v0, v1, z)
    x1[p + 1] = (g0[p + 1, 0] * a0 + g1[p + 1, 0] * a1
                 + _row5(fops, 1, p, n, gi, u0, u1, v0, v1, z))
    x1[n + p] = (g0[n + p, 0] * a0 + g1[n + p, 0] * a1
                 + _row5(fops, 2, p, n, gi, u0, u1, v0, v1, z))
    x1[n + p + 1] = (g0[n + p + 1, 0] * a0 + g1[n + p + 1, 0] * a1
                     + _row5(fops, 3, p, n, gi, u0, u1, v0, v1, z))
    x1[gi] = g0[gi, 0] * a0 + g1[gi, 0] * a1 + _row5(fops, 4, p, n, gi, u0, u1, v0, v1, z)
    w0 = _row5(fops, 5, p, n, gi, u0, u1, v0, v1, z)
    w1 = _row5(fops, 6, p, n, gi, u0, u1, v0, v1, z)
    e = (u0 * _row5(fops, 7, p, n, gi, u0, u1, v0, v1, z)
         + u1 * _row5(fops, 8, p, n, gi, u0, u1, v0, v1, z)
         + v0 * _row5(fops, 9, p, n, gi, u0, u1, v0, v1, z)
         + v1 * _row5(fops, 10, p, n, gi, u0, u1, v0, v1, z)
         + z * _row5(fops, 11, p, n, gi, u0, u1, v0, v1, z))
    e += _row5(fops, 12, p, n, gi, u0, u1, v0, v1, z) * a0
    e += _row5(fops, 13, p, n, gi, u0, u1, v0, v1, z) * a1
    return w0, w1, e


@njit(**NRT_FREE)
def maxwell_floor_force(j, y, n, el):
    """``(L F)_j`` [N]: the linear Maxwell links' forces on floor j at state y, as they
    enter ``M ü + C u̇ + K u + L F = −M R a_g`` (``+F`` at a link's ``hi`` floor)."""
    s = 0.0
    for q in range(el.lo.shape[0]):
        if is_linear_maxwell(el, q) and (el.hi[q] == j or el.lo[q] == j):
            f = el.params[q, 0] * y[2 * n + el.z_index[q]]
            s += f if el.hi[q] == j else -f
    return s


@njit(**INLINE)
def maxwell_outputs(y, n, el, lin, vs_out, o):
    """At the state y after an exact step (output row o): adds the linear Maxwell links'
    forces to ``lin[1]`` (``C u̇ + L F``, which with ``lin[0] = K u`` gives the floors'
    absolute accelerations), writes each link's force ``k z`` to ``vs_out[o]``, returns
    their springs' energy ``Σ ½ k z²`` [J]."""
    e = 0.0
    for q in range(el.lo.shape[0]):
        if is_linear_maxwell(el, q):
            z = y[2 * n + el.z_index[q]]
            f = el.params[q, 0] * z
            lin[1, el.hi[q]] += f
            lin[1, el.lo[q]] -= f
            vs_out[o, q] = f
            e += 0.5 * f * z
    return e


@njit(**NRT_FREE)
def maxwell_stored(y, n, el):
    """``Σ ½ k z²`` [J] of the linear Maxwell links at state y."""
    e = 0.0
    for q in range(el.lo.shape[0]):
        if is_linear_maxwell(el, q):
            z = y[2 * n + el.z_index[q]]
            e += 0.5 * el.params[q, 0] * z * z
    return e


@njit(**INLINE)
def maxwell_copy_z(x, x1, n, el):
    """``x ← x1`` for the linear Maxwell links' spring deformations."""
    for q in range(el.lo.shape[0]):
        if is_linear_maxwell(el, q):
            i = 2 * n + el.z_index[q]
            x[i] = x1[i]


@njit(**NRT_FREE)
def _rel_acc(i, j, ag, acc_out, r):
    return acc_out[j, i] - r[i, 0] * ag[j, 0] - ground_rest(r, i, ag, j)


@njit(**NRT_FREE)
def maxwell_jerk(i, j, v_out, vs_out, fl, el):
    """The linear Maxwell links' share of floor i's jerk at output row j [m/s³]:
    ``−(L Ḟ)_i / m_i`` with ``Ḟ = k ż = k (ḋ − F/c)`` from the outputs."""
    s = 0.0
    for q in range(el.lo.shape[0]):
        if is_linear_maxwell(el, q) and (el.hi[q] == i or el.lo[q] == i):
            hi = el.hi[q]
            lo = el.lo[q]
            zdot = v_out[j, hi] - v_out[j, lo] - vs_out[j, q] / el.params[q, 1]
            f = el.params[q, 0] * zdot
            s += f if hi == i else -f
    return -s * fl.m_inv[i]


@njit(**NRT_FREE)
def full_jerk(i, j, ag, v_out, acc_out, vs_out, fl, el):
    """Floor i's jerk at output row j of an exact step with linear Maxwell links [m/s³]:
    :func:`pounding.integrate.peaks.row_jerk` and :func:`maxwell_jerk`."""
    return row_jerk(i, j, ag, v_out, acc_out, fl) + maxwell_jerk(i, j, v_out, vs_out, fl, el)


@njit(**NRT_FREE)
def full_snap(i, j, j0, j1, h, ag, v_out, acc_out, vs_out, fl, el):
    """The rate of floor i's jerk at output row j (an end of the exact step ``j0 → j1``)
    [m/s⁴]: :func:`pounding.integrate.peaks.row_snap` (``−(K ü + C u⃛)_i / m_i`` with the
    jerks of K and C alone), with C times the links' share of the neighbours' jerks and the
    links' own ``−(L F̈)_i / m_i``, ``F̈ = k (d̈ − Ḟ/c)``."""
    s = row_snap(i, j, j0, j1, h, ag, v_out, acc_out, fl)
    n = fl.m_diag.shape[0]
    bw = fl.bw
    c_band = fl.c_band
    extra = 0.0
    for d in range(2 * bw + 1):
        col = i + d - bw
        if 0 <= col < n and c_band[d, i] != 0.0:
            extra += c_band[d, i] * maxwell_jerk(col, j, v_out, vs_out, fl, el)
    for q in range(n, c_band.shape[1]):  # (the entries outside the band)
        if int(c_band[0, q]) == i:
            extra += c_band[2, q] * maxwell_jerk(int(c_band[1, q]), j, v_out, vs_out, fl, el)
    r = fl.r
    for q in range(el.lo.shape[0]):
        if is_linear_maxwell(el, q) and (el.hi[q] == i or el.lo[q] == i):
            hi = el.hi[q]
            lo = el.lo[q]
            k = el.params[q, 0]
            c = el.params[q, 1]
            zdot = v_out[j, hi] - v_out[j, lo] - vs_out[j, q] / c
            f2 = k * (_rel_acc(hi, j, ag, acc_out, r) - _rel_acc(lo, j, ag, acc_out, r)
                      - k * zdot / c)
            extra += f2 if hi == i else -f2
    return s - extra * fl.m_inv[i]


@njit(**NRT_FREE)
def acc_peak_between_maxwell(i, j0, j1, t0, h, ag, v_out, acc_out, vs_out, fl, el, pk):
    """:func:`pounding.integrate.peaks.acc_peak_between` of a model with linear Maxwell
    links: the quintic Hermite of floor i's absolute acceleration over the exact step from
    output row ``j0`` (time ``t0``) to ``j1``, its jerk and the jerk's rate with the links'
    shares (:func:`full_jerk`, :func:`full_snap`)."""
    jk0 = full_jerk(i, j0, ag, v_out, acc_out, vs_out, fl, el)
    jk1 = full_jerk(i, j1, ag, v_out, acc_out, vs_out, fl, el)
    if (jk0 > 0.0) == (jk1 > 0.0):
        return
    update_quintic(pk, i, PK_A, t0, h, acc_out[j0, i], jk0,
                   full_snap(i, j0, j0, j1, h, ag, v_out, acc_out, vs_out, fl, el),
                   acc_out[j1, i], jk1,
                   full_snap(i, j1, j0, j1, h, ag, v_out, acc_out, vs_out, fl, el))


@njit(**NRT_FREE)
def track_exact_step_maxwell(t0, h, i, k, k_entry, fl, el, x0, x1, ag, v_out, acc_out,
                             vs_out, pk):
    """:func:`pounding.integrate.peaks.track_exact_step` of a model with linear Maxwell
    links (the acceleration peaks by :func:`acc_peak_between_maxwell`)."""
    o = k + 1
    n = fl.m_diag.shape[0]
    track_floor(t0, h, n, i, fl.below, x0, x1, ag, k, fl.r, acc_out[k], acc_out[o], pk)
    if k >= 1:
        ak = abs(acc_out[k, i])
        if ak >= abs(acc_out[k - 1, i]) and ak >= abs(acc_out[o, i]) and ak > 0.0:
            acc_peak_between_maxwell(i, k, o, t0, h, ag, v_out, acc_out, vs_out, fl, el, pk)
            if k - 1 >= k_entry:
                acc_peak_between_maxwell(i, k - 1, k, t0 - h, h, ag, v_out, acc_out, vs_out,
                                         fl, el, pk)
