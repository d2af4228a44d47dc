"""The compiled kernel of the response spectra: peak responses of linear SDOF oscillators to
a ground acceleration that is linear between samples, exact to round-off.

Every compiled function lives in this one module, so numba's on-disk cache (keyed on this
file) can never hold a stale piece of it. Import it only inside functions: importing it
imports numba.

The method (``docs/spectra.md``):

* **samples** by the piecewise-exact recurrence of Nigam & Jennings (1969), BSSA 59(2),
  909–922: over a step ``h`` the state ``(u, u̇)`` of ``ü + 2ζω u̇ + ω² u = −a_g(t)`` moves
  by ``x_{i+1} = A x_i + B (a_i, a_{i+1})``, ``A`` and ``B`` from the exact solution for
  ``a_g`` linear over the step (:func:`step_coefficients`);
* **peaks between samples**: over a step every response ``y`` (displacement, absolute
  acceleration, or a rotated combination of two components) is
  ``y(τ) = L0 + L1 τ + e^{−στ} (P cos ω_d τ + Q sin ω_d τ)`` with ``σ = ζω``,
  ``ω_d = ω sqrt(1 − ζ²)``. A step can hold a larger peak than its two samples only if
  ``max(|y_i|, |y_{i+1}|) + M h²/8`` and ``max |L0 + L1 τ| + amp`` both exceed the peak so
  far (``M`` bounds ``|y''|`` on the step, ``amp`` the oscillating part); then the zeros of
  ``y''`` (closed form, ``π/ω_d`` apart) cut the step into pieces on which ``y'`` is
  monotone, and each sign change of ``y'`` is a stationary point of ``y``, located by
  safeguarded Newton iteration on the exact ``y'``;
* **long periods** (``ω h`` < 1): the closed forms of ``A``, ``B`` and of the split
  ``L0 + L1 τ + oscillation`` of the displacement cancel catastrophically as ``ω → 0``
  (``L0 ~ a_g/ω²`` while ``u`` tends to the ground displacement); the step and the
  displacement inside it are written instead with the unit responses ``h, h', I0, I1``
  summed as Taylor series (:func:`_unit_responses`), exact to round-off at any period, so
  Sd tends to the peak ground displacement of the record linear between samples as
  ``T → ∞`` (at T = 1e7 s the closed forms gave 8,491 m for El Centro, whose is 0.13 m).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

_NEWTON_ITERATIONS = 60
_END_PIECES = 4
"""Pieces searched at each end of a step's interval by :func:`_search` (all when there are
at most twice as many)."""


_SERIES_PHASE = 1.0
"""Below this ``ω τ`` the responses of a step are summed as Taylor series
(:func:`_unit_responses`); above it the closed forms lose at most one digit to cancellation."""

_SERIES_TERMS = 40


@njit(cache=True)
def _unit_responses(omega: float, zeta: float, t: float) -> tuple[float, float, float, float]:
    """``h(t)``, ``h'(t)``, ``I0(t)`` and ``I1(t)`` of the oscillator ``ω, ζ``.

    ``h(t) = e^{−σt} sin(ω_d t)/ω_d`` is the displacement after a unit impulse (the
    response at rest to ``ü + 2σu̇ + ω²u = δ(t)``), ``I0 = ∫₀ᵗ h`` the response to a unit
    step of force and ``I1 = ∫₀ᵗ I0`` to a unit ramp. Every response of a step with the
    ground acceleration linear over it is a combination of these four (Nigam & Jennings
    1969): from ``(u0, u̇0)`` under ``a_g = g0 + s τ``,
    ``u(τ) = u0 (h' + 2σh) + u̇0 h − g0 I0 − s I1`` and
    ``u̇(τ) = −ω² u0 h + u̇0 h' − g0 h − s I0``.

    The closed forms ``I0 = (1 − e^{−σt}(cos + σ/ω_d sin))/ω²`` and
    ``I1 = (t − h − 2σ I0)/ω²`` cancel catastrophically when ``ω t`` is small (a long
    period: at T = 1e7 s and a 0.01 s step nothing of ``I1`` is left), so below
    ``ω t`` = :data:`_SERIES_PHASE` they are summed as Taylor series from the derivatives of
    ``h`` at 0 (``h(0) = 0``, ``h'(0) = 1``, ``h⁽ᵏ⁺²⁾ = −2σ h⁽ᵏ⁺¹⁾ − ω² h⁽ᵏ⁾``), which
    converge like ``(ωt)ᵏ/k!``: exact to round-off at any period, ``ω → 0`` included
    (then ``u(τ) = u0 + u̇0 τ − g0 τ²/2 − s τ³/6``, the ground's own motion).
    """
    sig = zeta * omega
    x = omega * t
    if x < _SERIES_PHASE:
        # a_k = h^(k)(0) t^(k-1) / k!: h = t Σa_k, h' = Σ(k+1)a_(k+1), I0 = t²Σa_k/(k+1),
        # I1 = t³ Σ a_k/((k+1)(k+2))
        two_st = 2.0 * sig * t
        x2 = x * x
        a_prev = 0.0  # a_0
        a_cur = 1.0   # a_1
        h_sum = 1.0
        hd_sum = 1.0  # (0+1) a_1
        i0_sum = 0.5
        i1_sum = 1.0 / 6.0
        for k in range(1, _SERIES_TERMS):
            # a_(k+1) from a_k and a_(k-1)
            a_next = -two_st * a_cur / (k + 1) - x2 * a_prev / (k * (k + 1))
            h_sum += a_next
            hd_sum += (k + 1) * a_next
            i0_sum += a_next / (k + 2)
            i1_sum += a_next / ((k + 2) * (k + 3))
            # every sum is of order 1 (a_1 = 1): stop when two terms in a row are below
            # round-off (two: with ζ = 0 every other term is zero)
            if abs(a_next) * (k + 1) < 1e-17 and abs(a_cur) * k < 1e-17:
                break
            a_prev, a_cur = a_cur, a_next
        return t * h_sum, hd_sum, t * t * i0_sum, t * t * t * i1_sum
    wd = omega * math.sqrt(1.0 - zeta * zeta)
    e = math.exp(-sig * t)
    c = math.cos(wd * t)
    sn = math.sin(wd * t)
    w2 = omega * omega
    h = e * sn / wd
    hd = e * (c - sig / wd * sn)
    i0 = (1.0 - (hd + 2.0 * sig * h)) / w2
    i1 = (t - h - 2.0 * sig * i0) / w2
    return h, hd, i0, i1


@njit(cache=True)
def step_coefficients(omega: float, zeta: float, h: float) -> tuple[float, ...]:
    """``A`` (a11, a12, a21, a22) and ``B`` (b11, b12, b21, b22) of one exact step.

    ``u_{i+1} = a11 u_i + a12 v_i + b11 a_i + b12 a_{i+1}`` and likewise ``v`` with row 2;
    ``a`` is the ground acceleration. From the unit responses of :func:`_unit_responses`
    (Nigam & Jennings 1969, eqs 2.7, in a form that stays exact at long periods): with
    ``a_g = a_i (1 − τ/h) + a_{i+1} τ/h``, ``b11 = −(I0 − I1/h)``, ``b12 = −I1/h``,
    ``b21 = −(h(h) − I0/h)``, ``b22 = −I0/h``.
    """
    g, gd, i0, i1 = _unit_responses(omega, zeta, h)
    sig = zeta * omega
    a11 = gd + 2.0 * sig * g
    a12 = g
    a21 = -omega * omega * g
    a22 = gd
    b11 = -(i0 - i1 / h)
    b12 = -i1 / h
    b21 = -(g - i0 / h)
    b22 = -i0 / h
    return a11, a12, a21, a22, b11, b12, b21, b22


@njit(cache=True)
def _osc(l0: float, l1: float, p: float, q: float, sig: float, wd: float,
         t: float) -> float:
    """``l0 + l1 t + e^{−σt} (p cos ω_d t + q sin ω_d t)``."""
    return l0 + l1 * t + math.exp(-sig * t) * (p * math.cos(wd * t) + q * math.sin(wd * t))


@njit(cache=True)
def _root(l1: float, p1: float, q1: float, p2: float, q2: float, sig: float, wd: float,
          a: float, b: float, fa: float) -> float:
    """The zero of ``y' = l1 + e^{−στ}(p1 cos + q1 sin)`` in ``(a, b)``, where ``y'`` is
    monotone and changes sign; Newton on the exact ``y'`` and ``y''``, bisecting whenever a
    Newton step leaves the bracket."""
    t = 0.5 * (a + b)
    for _ in range(_NEWTON_ITERATIONS):
        f = _osc(l1, 0.0, p1, q1, sig, wd, t)
        if f == 0.0:
            return t
        if (f < 0.0) == (fa < 0.0):
            a, fa = t, f
        else:
            b = t
        d = _osc(0.0, 0.0, p2, q2, sig, wd, t)
        tn = t - f / d if d != 0.0 else 0.5 * (a + b)
        if not (a < tn < b):
            tn = 0.5 * (a + b)
        if abs(tn - t) <= 1e-15 * (abs(t) + b - a) or b - a <= 1e-15 * abs(b):
            return tn
        t = tn
    return t


@njit(cache=True)
def _search(l0: float, l1: float, p: float, q: float, sig: float, wd: float, lo: float,
            hi: float, best: float) -> float:
    """Largest ``|y|`` at the stationary points of ``y`` in ``(lo, hi)``, or ``best`` if
    none is larger.

    A fast oscillator (``ω_d (hi − lo)`` large: periods far below the record's step) has
    many pieces in the interval; the heights of its crests, ``L1 τ ± A e^{−στ}`` at
    ``τ`` a crest (up to a term smooth in ``τ``), are a convex function of ``τ``, so the
    largest is among the first or the last: only the first and last :data:`_END_PIECES`
    pieces are searched (at ``T = 1e-9 s`` and a 0.01 s step the interval holds 2e7).
    """
    p1 = -sig * p + wd * q
    q1 = -sig * q - wd * p
    p2 = -sig * p1 + wd * q1
    q2 = -sig * q1 - wd * p1
    if p2 == 0.0 and q2 == 0.0:  # y'' = 0: y' constant, no stationary point inside
        return best
    half = math.pi / wd
    # zeros of y'' = e^{−στ}(p2 cos ω_d τ + q2 sin ω_d τ): ω_d τ = atan2(−p2, q2) + kπ
    first = math.atan2(-p2, q2) / wd
    k = math.floor((lo - first) / half) + 1.0
    b0 = first + k * half  # the first zero after lo
    zeros = 0.0 if b0 >= hi else math.floor((hi - b0) / half) + 1.0
    n_pieces = zeros + 1.0
    for jj in range(2 * _END_PIECES):
        # the first pieces, then the last ones not among them (j counted as a float: an
        # interval may hold more than 2**63 pieces)
        if jj < _END_PIECES:
            j = float(jj)
            if j >= n_pieces:
                continue
        else:
            j = n_pieces - 2.0 * _END_PIECES + jj
            if j < _END_PIECES:
                continue
        a = lo if j == 0.0 else first + (k + j - 1.0) * half
        b = hi if j == n_pieces - 1.0 else min(first + (k + j) * half, hi)
        if not b > a:
            continue
        fa = _osc(l1, 0.0, p1, q1, sig, wd, a)
        fb = _osc(l1, 0.0, p1, q1, sig, wd, b)
        if (fa < 0.0) != (fb < 0.0) and fa != 0.0 and fb != 0.0:
            t = _root(l1, p1, q1, p2, q2, sig, wd, a, b, fa)
            y = abs(_osc(l0, l1, p, q, sig, wd, t))
            if y > best:
                best = y
    return best


@njit(cache=True)
def _ramp_response(u0: float, v0: float, g0: float, s: float, omega: float, zeta: float,
                   t: float) -> tuple[float, float, float]:
    """``y, y', y''`` at ``t`` of ``y(τ) = u0 (h' + 2σh) + v0 h − g0 I0 − s I1`` (the
    displacement from ``(u0, v0)`` under the ground acceleration ``g0 + s τ``), from the
    unit responses of :func:`_unit_responses`: exact at any period."""
    g, gd, i0, i1 = _unit_responses(omega, zeta, t)
    sig2 = 2.0 * zeta * omega
    w2 = omega * omega
    gdd = -sig2 * gd - w2 * g
    y = u0 * (gd + sig2 * g) + v0 * g - g0 * i0 - s * i1
    yd = -w2 * u0 * g + v0 * gd - g0 * g - s * i0
    ydd = -w2 * u0 * gd + v0 * gdd - g0 * gd - s * g
    return y, yd, ydd


@njit(cache=True)
def _search_slow(u0: float, v0: float, g0: float, s: float, pa: float, qa: float,
                 omega: float, zeta: float, wd: float, h: float, v1: float,
                 best: float) -> float:
    """Largest ``|y|`` at the stationary points of the displacement ``y`` of
    :func:`_ramp_response` inside a step of length ``h`` with ``ω h`` <
    :data:`_SERIES_PHASE` (a slow oscillator: the long periods), or ``best`` if none is
    larger.

    ``y'' = e^{−στ}(pa cos ω_d τ + qa sin ω_d τ)`` has at most one zero in the step
    (``ω_d h < 1 < π/2``), at ``τ = atan(−pa/qa)/ω_d`` when that is in ``(0, h)``; on each
    side ``y'`` is monotone, and a sign change of ``y'`` is located by safeguarded Newton
    iteration on the exact ``y'`` and ``y''``. ``v0`` and ``v1`` are ``y'`` at the ends
    (known from the step): where ``y''`` keeps its sign, a step whose ends have velocities
    of one sign holds no peak, and nothing is evaluated.
    """
    cut = h
    if qa != 0.0:
        tz = math.atan(-pa / qa) / wd
        if 0.0 < tz < h:
            cut = tz
    a = 0.0
    fa = v0
    ends = (cut, h) if cut < h else (h, h)
    for b in ends:
        if b <= a:
            continue
        fb = v1 if b == h else _ramp_response(u0, v0, g0, s, omega, zeta, b)[1]
        if (fa < 0.0) != (fb < 0.0) and fa != 0.0 and fb != 0.0:
            lo, hi, flo = a, b, fa
            t = 0.5 * (lo + hi)
            for _ in range(_NEWTON_ITERATIONS):
                _, f, d = _ramp_response(u0, v0, g0, s, omega, zeta, t)
                if f == 0.0:
                    break
                if (f < 0.0) == (flo < 0.0):
                    lo, flo = t, f
                else:
                    hi = t
                tn = t - f / d if d != 0.0 else 0.5 * (lo + hi)
                if not (lo < tn < hi):
                    tn = 0.5 * (lo + hi)
                if abs(tn - t) <= 1e-15 * (abs(t) + hi - lo) or hi - lo <= 1e-15 * abs(hi):
                    t = tn
                    break
                t = tn
            y = abs(_ramp_response(u0, v0, g0, s, omega, zeta, t)[0])
            if y > best:
                best = y
        a, fa = b, fb
    return best


@njit(cache=True)
def _step_peak(y0: float, y1: float, l0: float, l1: float, p: float, q: float, m: float,
               sig: float, wd: float, w: float, h: float, best: float) -> float:
    """The peak ``|y|`` so far after the step from ``y0`` to ``y1`` (both samples already
    counted in ``best``), searching inside the step only if its bounds allow a larger one.

    ``m`` bounds ``|y''|`` on the step; ``w = ω`` turns it into the amplitude of the
    oscillating part, ``m/ω²``.
    """
    top = max(abs(y0), abs(y1))
    if top + m * h * h * 0.125 <= best:
        return best
    amp = m / (w * w)
    end = l0 + l1 * h
    if max(abs(l0), abs(end)) + amp <= best:
        return best
    # only where |L0 + L1 τ| > best − amp can |y| exceed best: at most two sub-intervals
    thr = best - amp
    if thr <= 0.0 or l1 == 0.0:
        return _search(l0, l1, p, q, sig, wd, 0.0, h, best)
    t_pos = (thr - l0) / l1   # L0 + L1 τ = thr
    t_neg = (-thr - l0) / l1  # L0 + L1 τ = −thr
    if l1 > 0.0:  # above thr after t_pos, below −thr before t_neg
        if t_neg > 0.0:
            best = _search(l0, l1, p, q, sig, wd, 0.0, min(t_neg, h), best)
        if t_pos < h:
            best = _search(l0, l1, p, q, sig, wd, max(t_pos, 0.0), h, best)
    else:  # above thr before t_pos, below −thr after t_neg
        if t_pos > 0.0:
            best = _search(l0, l1, p, q, sig, wd, 0.0, min(t_pos, h), best)
        if t_neg < h:
            best = _search(l0, l1, p, q, sig, wd, max(t_neg, 0.0), h, best)
    return best


@njit(cache=True)
def _combined(wrow: np.ndarray, l0: np.ndarray, l1: np.ndarray, p: np.ndarray,
              q: np.ndarray) -> tuple[float, float, float, float]:
    """The linear and oscillating parts of one direction: each component's, weighted."""
    a = b = c = d = 0.0
    for k in range(wrow.size):
        a += wrow[k] * l0[k]
        b += wrow[k] * l1[k]
        c += wrow[k] * p[k]
        d += wrow[k] * q[k]
    return a, b, c, d


@njit(cache=True)
def peaks(accel: np.ndarray, h: float, omegas: np.ndarray, zetas: np.ndarray,
          weights: np.ndarray, absolute: bool) -> tuple[np.ndarray, np.ndarray]:
    """Peak relative displacement and (if ``absolute``) peak absolute acceleration of every
    oscillator, in every direction.

    Parameters
    ----------
    accel : (n_comp, n) array
        Ground acceleration [m/s²] of each horizontal component, linear between samples,
        the oscillator at rest at the first sample.
    h : float
        Time step [s].
    omegas, zetas : arrays
        Circular frequencies [rad/s] (> 0) and damping ratios [-] (0 ≤ ζ < 1).
    weights : (n_dir, n_comp) array
        Direction ``d`` responds to ``Σ_c weights[d, c] accel[c]`` (a rotation:
        ``cos θ, sin θ``); the responses are linear, so each component is integrated once.
    absolute : bool
        Also compute the peak absolute acceleration ``|ü + a_g| = |2ζω u̇ + ω² u|``.

    Returns
    -------
    sd, sa : (n_zeta, n_omega, n_dir) arrays
        Peak ``|u|`` [m] and peak absolute acceleration [m/s²] (zeros unless ``absolute``).
    """
    n_comp, n = accel.shape
    n_dir = weights.shape[0]
    nz, nw = zetas.size, omegas.size
    sd = np.zeros((nz, nw, n_dir))
    sa = np.zeros((nz, nw, n_dir))
    # per component: the state, and over the current step the next samples, the linear and
    # oscillating parts of u and of the absolute acceleration, and the bound on |ü|
    st = np.zeros((15, n_comp))
    u, v, un, vn, lu0, lu1, pu, qu, la0, la1, pa, qa, mc, g0c, sc = (
        st[0], st[1], st[2], st[3], st[4], st[5], st[6], st[7], st[8], st[9], st[10], st[11],
        st[12], st[13], st[14])
    for iz in range(nz):
        zeta = zetas[iz]
        for iw in range(nw):
            w = omegas[iw]
            w2 = w * w
            sig = zeta * w
            wd = w * math.sqrt(1.0 - zeta * zeta)
            a11, a12, a21, a22, b11, b12, b21, b22 = step_coefficients(w, zeta, h)
            # a slow oscillator (ω h small: the long periods): u's split into a linear part
            # and an oscillation (L0 ~ a_g/ω²) would cancel to nothing; its peaks inside a
            # step are found from the exact unit responses instead (_search_slow)
            slow = w * h < _SERIES_PHASE
            swing = min(1.0, wd * h)  # bounds |sin ω_d τ| over a step
            u[:] = 0.0
            v[:] = 0.0
            pk_u = np.zeros(n_dir)
            pk_a = np.zeros(n_dir)
            yu = np.zeros(n_dir)  # each direction's response at the step's start
            ya = np.zeros(n_dir)
            for i in range(n - 1):
                for c in range(n_comp):
                    g0 = accel[c, i]
                    g1 = accel[c, i + 1]
                    s = (g1 - g0) / h
                    un[c] = a11 * u[c] + a12 * v[c] + b11 * g0 + b12 * g1
                    vn[c] = a21 * u[c] + a22 * v[c] + b21 * g0 + b22 * g1
                    # ü = e^{−στ}(P cos + Q sin) over the step: no linear part
                    acc0 = -g0 - 2.0 * sig * v[c] - w2 * u[c]
                    jerk0 = -s - 2.0 * sig * acc0 - w2 * v[c]
                    la0[c] = g0
                    la1[c] = s
                    pa[c] = acc0
                    qa[c] = (jerk0 + sig * acc0) / wd
                    mc[c] = math.sqrt(pa[c] * pa[c] + qa[c] * qa[c])
                    g0c[c] = g0
                    sc[c] = s
                    if not slow:
                        # u = c0 + c1 τ + e^{−στ}(P cos + Q sin)
                        lu1[c] = -s / w2
                        lu0[c] = (-g0 - 2.0 * sig * lu1[c]) / w2
                        pu[c] = u[c] - lu0[c]
                        qu[c] = (v[c] - lu1[c] + sig * pu[c]) / wd
                for d in range(n_dir):
                    y1 = 0.0
                    m = 0.0
                    for c in range(n_comp):
                        y1 += weights[d, c] * un[c]
                        m += abs(weights[d, c]) * mc[c]
                    if abs(y1) > pk_u[d]:
                        pk_u[d] = abs(y1)
                    if slow:
                        # |ü| <= |P| + |Q| |sin ω_d τ| over the step (e^{−στ} <= 1)
                        m_step = 0.0
                        for c in range(n_comp):
                            m_step += abs(weights[d, c]) * (abs(pa[c]) + abs(qa[c]) * swing)
                        if max(abs(yu[d]), abs(y1)) + m_step * h * h * 0.125 > pk_u[d]:
                            y0_, v0_, g0_, s_ = _combined(weights[d], u, v, g0c, sc)
                            p_, q_, v1_, _ = _combined(weights[d], pa, qa, vn, vn)
                            pk_u[d] = _search_slow(y0_, v0_, g0_, s_, p_, q_, w, zeta, wd, h,
                                                   v1_, pk_u[d])
                    elif max(abs(yu[d]), abs(y1)) + m * h * h * 0.125 > pk_u[d]:
                        l0, l1, p, q = _combined(weights[d], lu0, lu1, pu, qu)
                        pk_u[d] = _step_peak(yu[d], y1, l0, l1, p, q, m, sig, wd, w, h,
                                             pk_u[d])
                    yu[d] = y1
                    if absolute:
                        # absolute acceleration = a_g + ü: linear a_g plus ü's oscillation
                        y1 = 0.0
                        for c in range(n_comp):
                            y1 -= weights[d, c] * (2.0 * sig * vn[c] + w2 * un[c])
                        if abs(y1) > pk_a[d]:
                            pk_a[d] = abs(y1)
                        if max(abs(ya[d]), abs(y1)) + w2 * m * h * h * 0.125 > pk_a[d]:
                            l0, l1, p, q = _combined(weights[d], la0, la1, pa, qa)
                            pk_a[d] = _step_peak(ya[d], y1, l0, l1, p, q, w2 * m, sig, wd, w,
                                                 h, pk_a[d])
                        ya[d] = y1
                for c in range(n_comp):
                    u[c] = un[c]
                    v[c] = vn[c]
            sd[iz, iw, :] = pk_u
            sa[iz, iw, :] = pk_a
    return sd, sa
