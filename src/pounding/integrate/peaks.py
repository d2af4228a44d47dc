"""Peaks of the response located inside steps, as the kernel steps.

For every floor the kernel keeps the largest |displacement|, |storey drift| (the storey
below the floor) and |absolute acceleration| with their times (columns
:data:`~pounding.integrate.layout.PK_U` …). After each step — exact or adaptive, whose ends
never straddle an event — the end values are compared, and an extremum inside the step is
taken from an interpolant through both ends:

* displacement and drift: the quintic Hermite of ``(u, u̇, ü)`` (error O(h⁶));
* absolute acceleration: in exact steps the quintic Hermite of ``(a, ȧ, ä)``, the jerk and
  its rate from the differentiated equations of motion (error O(h⁶)); in adaptive steps,
  which are error-controlled and short, the cubic Hermite of ``(a, ȧ)``
  (:func:`pounding.integrate.rhs.jerk`; error O(h⁴)). In exact steps of coupled floors the
  jerk costs a banded product (its rate, one per floor of the band), so there the samples
  of |a| are tested first and the derivatives computed only in the two steps beside a
  sampled peak (the continuous peak lies in one of them).

A smooth quantity takes its largest magnitude where its rate is zero, or at the ends of the
run; so a step is examined only where the rate changes sign inside it (then its end value
and the interpolant's extremum are compared with the peak so far), and the values at t = 0,
at the end of the run and just after every event (where the acceleration may jump or turn
a corner: :func:`track_point`) are compared as they are. Tracking costs three sign tests a
floor and step.
"""

from __future__ import annotations

from numba import njit

from pounding.integrate.events import hermite_max, quintic_max
from pounding.integrate.layout import PK_A, PK_D, PK_U
from pounding.integrate.rhs import INLINE, NRT_FREE, ground_rest


@njit(**NRT_FREE)
def update_quintic(pk, i, col, t0, h, f0, d0, q0, f1, d1, q1):
    """Peak of |f| over one step (value and time in ``pk[i, col]``, ``pk[i, col + 1]``)
    from its values, rates and second rates at both ends, if its rate changes sign."""
    if (d0 > 0.0) == (d1 > 0.0):
        return  # |f| is monotonic over the step: no peak inside or at its end
    a1 = abs(f1)
    if a1 > pk[i, col]:
        pk[i, col] = a1
        pk[i, col + 1] = t0 + h
    bound = (max(abs(f0), a1) + 0.25 * h * (abs(d0) + abs(d1))
             + 0.125 * h * h * (abs(q0) + abs(q1)))
    if bound <= pk[i, col]:
        return
    if d0 > 0.0 or d1 < 0.0:
        val, s = quintic_max(f0, d0, q0, f1, d1, q1, h)
        if val > pk[i, col]:
            pk[i, col] = val
            pk[i, col + 1] = t0 + s * h
    if d0 < 0.0 or d1 > 0.0:
        val, s = quintic_max(-f0, -d0, -q0, -f1, -d1, -q1, h)
        if val > pk[i, col]:
            pk[i, col] = val
            pk[i, col + 1] = t0 + s * h


@njit(**NRT_FREE)
def update_cubic(pk, i, col, t0, h, f0, d0, f1, d1):
    """Peak of |f| over one step from its values and rates at both ends (cubic Hermite),
    if its rate changes sign."""
    if (d0 > 0.0) == (d1 > 0.0):
        return
    a1 = abs(f1)
    if a1 > pk[i, col]:
        pk[i, col] = a1
        pk[i, col + 1] = t0 + h
    if max(abs(f0), a1) + 0.25 * h * (abs(d0) + abs(d1)) <= pk[i, col]:
        return
    if d0 > 0.0 or d1 < 0.0:
        val, s = hermite_max(f0, d0, f1, d1, h)
        if val > pk[i, col]:
            pk[i, col] = val
            pk[i, col + 1] = t0 + s * h
    if d0 < 0.0 or d1 > 0.0:
        val, s = hermite_max(-f0, -d0, -f1, -d1, h)
        if val > pk[i, col]:
            pk[i, col] = val
            pk[i, col + 1] = t0 + s * h


@njit(**INLINE)
def track_step(t0, h, n, below, x0, arel0, aabs0, j0, x1, arel1, aabs1, j1, pk, with_acc):
    """Update every floor's peaks over the step ``[t0, t0 + h]`` from the states ``x``
    (``[u, u̇, …]``), relative accelerations ``arel``, absolute accelerations ``aabs`` and
    (if ``with_acc``: the accelerations are searched too) jerks ``j`` at its two ends.
    ``below[i]``: the DOF of the floor below floor i (−1: the ground). Inlined: the sign
    tests are all most steps cost."""
    for i in range(n):
        lo = below[i]
        v0 = x0[n + i]
        v1 = x1[n + i]
        dr0 = v0 - x0[n + lo] if lo >= 0 else v0
        dr1 = v1 - x1[n + lo] if lo >= 0 else v1
        if (v0 > 0.0) != (v1 > 0.0):
            update_quintic(pk, i, PK_U, t0, h, x0[i], v0, arel0[i], x1[i], v1, arel1[i])
        if (dr0 > 0.0) != (dr1 > 0.0):
            if lo >= 0:
                update_quintic(pk, i, PK_D, t0, h, x0[i] - x0[lo], dr0, arel0[i] - arel0[lo],
                               x1[i] - x1[lo], dr1, arel1[i] - arel1[lo])
            else:
                update_quintic(pk, i, PK_D, t0, h, x0[i], v0, arel0[i], x1[i], v1, arel1[i])
        if with_acc and (j0[i] > 0.0) != (j1[i] > 0.0):
            update_cubic(pk, i, PK_A, t0, h, aabs0[i], j0[i], aabs1[i], j1[i])


@njit(**NRT_FREE)
def track_floor(t0, h, n, i, below, x0, x1, ag, k, r, aabs0, aabs1, pk):
    """The displacement and drift peaks of floor i over an exact step ``[t0, t0 + h]``
    (called where its velocity or drift rate changes sign) from the states ``x0``, ``x1``
    at its ends (grid points k and k + 1 of the ground components ``ag``) and the absolute
    accelerations."""
    lo = below[i]
    v0 = x0[n + i]
    v1 = x1[n + i]
    a0 = ag[k, 0]
    a1 = ag[k + 1, 0]
    ar0 = aabs0[i] - r[i, 0] * a0 - ground_rest(r, i, ag, k)
    ar1 = aabs1[i] - r[i, 0] * a1 - ground_rest(r, i, ag, k + 1)
    if (v0 > 0.0) != (v1 > 0.0):
        update_quintic(pk, i, PK_U, t0, h, x0[i], v0, ar0, x1[i], v1, ar1)
    if lo >= 0:
        dr0 = v0 - x0[n + lo]
        dr1 = v1 - x1[n + lo]
        if (dr0 > 0.0) != (dr1 > 0.0):
            update_quintic(pk, i, PK_D, t0, h, x0[i] - x0[lo], dr0,
                           ar0 - (aabs0[lo] - r[lo, 0] * a0 - ground_rest(r, lo, ag, k)),
                           x1[i] - x1[lo], dr1,
                           ar1 - (aabs1[lo] - r[lo, 0] * a1 - ground_rest(r, lo, ag, k + 1)))
    elif (v0 > 0.0) != (v1 > 0.0):
        update_quintic(pk, i, PK_D, t0, h, x0[i], v0, ar0, x1[i], v1, ar1)


@njit(**NRT_FREE)
def track_uncoupled_step(t0, h, i, u0, v0, aa0, u1, v1, aa1, ag, j, r, k, c, m_inv, pk):
    """The peaks of floor i, a one-storey building of stiffness k and damping c, over an
    exact step from ``t0`` (grid point j of the ground components ``ag``; called where a
    test of :func:`pounding.integrate.exact_steps.free_run` found one may lie): its
    relative accelerations and jerks ``−(k u̇ + c ü)/m`` at both ends, then the quintic for
    displacement and drift (the same here) and for the absolute acceleration (with its jerk
    and second derivative)."""
    ar0 = aa0 - r[i, 0] * ag[j, 0] - ground_rest(r, i, ag, j)
    ar1 = aa1 - r[i, 0] * ag[j + 1, 0] - ground_rest(r, i, ag, j + 1)
    if (v0 > 0.0) != (v1 > 0.0):
        update_quintic(pk, i, PK_U, t0, h, u0, v0, ar0, u1, v1, ar1)
        update_quintic(pk, i, PK_D, t0, h, u0, v0, ar0, u1, v1, ar1)
    j0 = -(k * v0 + c * ar0) * m_inv
    j1 = -(k * v1 + c * ar1) * m_inv
    if (j0 > 0.0) == (j1 > 0.0):
        return
    # the second derivative −(k ü + c u⃛)/m, u⃛ = jerk − R ȧ_g over the step
    slope = (r[i, 0] * (ag[j + 1, 0] - ag[j, 0]) + ground_rest(r, i, ag, j + 1)
             - ground_rest(r, i, ag, j)) / h
    update_quintic(pk, i, PK_A, t0, h, aa0, j0, -(k * ar0 + c * (j0 - slope)) * m_inv,
                   aa1, j1, -(k * ar1 + c * (j1 - slope)) * m_inv)


@njit(**NRT_FREE)
def track_exact_step(t0, h, i, k, k_entry, fl, x0, x1, ag, v_out, acc_out, pk):
    """The peaks of floor i over the exact step from grid point k (time ``t0``) to k + 1,
    where a sign test of :func:`pounding.integrate.exact_steps.free_run` found one may lie:
    displacement and drift from the states, acceleration from the samples k − 1, k, k + 1
    of the outputs (the step before k only if it was exact too, ``k − 1 ≥ k_entry``);
    ``fl`` the floors (:class:`pounding.integrate.kernel_model.Floors`)."""
    o = k + 1
    n = fl.m_diag.shape[0]
    track_floor(t0, h, n, i, fl.below, x0, x1, ag, k, fl.r, acc_out[k], acc_out[o], pk)
    if k >= 1:
        ak = abs(acc_out[k, i])
        if ak >= abs(acc_out[k - 1, i]) and ak >= abs(acc_out[o, i]) and ak > 0.0:
            acc_peak_between(i, k, o, t0, h, ag, v_out, acc_out, fl, pk)
            if k - 1 >= k_entry:
                acc_peak_between(i, k - 1, k, t0 - h, h, ag, v_out, acc_out, fl, pk)


@njit(**NRT_FREE)
def row_jerk(i, j, ag, v_out, acc_out, fl):
    """Jerk of floor i at output row j of an exact step [m/s³]:
    ``−(K u̇ + C ü)_i / m_i`` from the outputs (no contact closed, no yielding storey)."""
    n = fl.m_diag.shape[0]
    bw = fl.bw
    k_band = fl.k_band
    c_band = fl.c_band
    r = fl.r
    s = 0.0
    for d in range(2 * bw + 1):
        col = i + d - bw
        if 0 <= col < n:
            s += k_band[d, i] * v_out[j, col] + c_band[d, i] * (acc_out[j, col]
                                                                 - r[col, 0] * ag[j, 0]
                                                                 - ground_rest(r, col, ag, j))
    for q in range(n, k_band.shape[1]):  # (the entries outside the band)
        if int(k_band[0, q]) == i:
            col = int(k_band[1, q])
            s += k_band[2, q] * v_out[j, col] + c_band[2, q] * (acc_out[j, col]
                                                                - r[col, 0] * ag[j, 0]
                                                                - ground_rest(r, col, ag, j))
    return -s * fl.m_inv[i]


@njit(**NRT_FREE)
def row_snap(i, j, j0, j1, h, ag, v_out, acc_out, fl):
    """Second time derivative of floor i's absolute acceleration at output row j, the end
    ``j0`` or ``j1`` of an exact step of length h [m/s⁴]: ``−(K ü + C u⃛)_i / m_i`` with the
    relative ``ü`` and ``u⃛ = jerk − R ȧ_g`` (``ȧ_g`` the ground's slope over the step: the
    one-sided value inside it, the ground being linear there)."""
    n = fl.m_diag.shape[0]
    bw = fl.bw
    k_band = fl.k_band
    c_band = fl.c_band
    r = fl.r
    s = 0.0
    for d in range(2 * bw + 1):
        col = i + d - bw
        if 0 <= col < n:
            rel = acc_out[j, col] - r[col, 0] * ag[j, 0] - ground_rest(r, col, ag, j)
            slope = (r[col, 0] * (ag[j1, 0] - ag[j0, 0])
                     + ground_rest(r, col, ag, j1) - ground_rest(r, col, ag, j0)) / h
            u3 = row_jerk(col, j, ag, v_out, acc_out, fl) - slope
            s += k_band[d, i] * rel + c_band[d, i] * u3
    for q in range(n, k_band.shape[1]):  # (the entries outside the band)
        if int(k_band[0, q]) == i:
            col = int(k_band[1, q])
            rel = acc_out[j, col] - r[col, 0] * ag[j, 0] - ground_rest(r, col, ag, j)
            slope = (r[col, 0] * (ag[j1, 0] - ag[j0, 0])
                     + ground_rest(r, col, ag, j1) - ground_rest(r, col, ag, j0)) / h
            u3 = row_jerk(col, j, ag, v_out, acc_out, fl) - slope
            s += k_band[2, q] * rel + c_band[2, q] * u3
    return -s * fl.m_inv[i]


@njit(**NRT_FREE)
def acc_peak_between(i, j0, j1, t0, h, ag, v_out, acc_out, fl, pk):
    """The absolute-acceleration peak of floor i inside the exact step from output row
    ``j0`` (time ``t0``) to ``j1``, from the quintic Hermite of the acceleration, its jerk
    and its second derivative (error O(h⁶); the cubic through the acceleration and the
    jerk was 6×10⁻⁵ off at a 10 ms step where higher modes ring after an impact)."""
    jk0 = row_jerk(i, j0, ag, v_out, acc_out, fl)
    jk1 = row_jerk(i, j1, ag, v_out, acc_out, fl)
    if (jk0 > 0.0) == (jk1 > 0.0):
        return  # |a| monotonic over the step (update_quintic's first test, before the snap)
    update_quintic(pk, i, PK_A, t0, h, acc_out[j0, i], jk0,
                   row_snap(i, j0, j0, j1, h, ag, v_out, acc_out, fl),
                   acc_out[j1, i], jk1,
                   row_snap(i, j1, j0, j1, h, ag, v_out, acc_out, fl))


@njit(**NRT_FREE)
def track_point(t, n, below, x, aabs, pk):
    """Update every floor's peaks with its values at one instant: t = 0, the end of the run,
    and every event (where the acceleration may jump or turn a corner; after a jump, the
    value just after it)."""
    for i in range(n):
        if abs(x[i]) > pk[i, PK_U]:
            pk[i, PK_U] = abs(x[i])
            pk[i, PK_U + 1] = t
        d = x[i] - x[below[i]] if below[i] >= 0 else x[i]
        if abs(d) > pk[i, PK_D]:
            pk[i, PK_D] = abs(d)
            pk[i, PK_D + 1] = t
        if abs(aabs[i]) > pk[i, PK_A]:
            pk[i, PK_A] = abs(aabs[i])
            pk[i, PK_A + 1] = t
