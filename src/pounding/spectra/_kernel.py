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
  safeguarded Newton iteration on the exact ``y'``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

_NEWTON_ITERATIONS = 60


@njit(cache=True)
def step_coefficients(omega: float, zeta: float, h: float) -> tuple[float, ...]:
    """``A`` (a11, a12, a21, a22) and ``B`` (b11, b12, b21, b22) of one exact step.

    ``u_{i+1} = a11 u_i + a12 v_i + b11 a_i + b12 a_{i+1}`` and likewise ``v`` with row 2;
    ``a`` is the ground acceleration. From the particular solution ``c0 + c1 τ`` of the
    linear forcing plus the free vibration (Nigam & Jennings 1969, eqs 2.7).
    """
    sig = zeta * omega
    wd = omega * math.sqrt(1.0 - zeta * zeta)
    w2 = omega * omega
    e = math.exp(-sig * h)
    c = math.cos(wd * h)
    s = math.sin(wd * h)
    a11 = e * (c + sig / wd * s)
    a12 = e * s / wd
    a21 = -w2 * e * s / wd
    a22 = e * (c - sig / wd * s)
    # unit ground acceleration at the start (p = -a = -1 + τ/h), then at the end (-τ/h)
    c1 = (1.0 / h) / w2
    c0 = (-1.0 - 2.0 * sig * c1) / w2
    b11 = c0 + c1 * h - a11 * c0 - a12 * c1
    b21 = c1 - a21 * c0 - a22 * c1
    c1 = (-1.0 / h) / w2
    c0 = (-2.0 * sig * c1) / w2
    b12 = c0 + c1 * h - a11 * c0 - a12 * c1
    b22 = c1 - a21 * c0 - a22 * c1
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
    none is larger."""
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
    nxt = first + k * half
    a = lo
    fa = _osc(l1, 0.0, p1, q1, sig, wd, a)
    while a < hi:
        b = min(nxt, hi)
        fb = _osc(l1, 0.0, p1, q1, sig, wd, b)
        if (fa < 0.0) != (fb < 0.0) and fa != 0.0 and fb != 0.0:
            t = _root(l1, p1, q1, p2, q2, sig, wd, a, b, fa)
            y = abs(_osc(l0, l1, p, q, sig, wd, t))
            if y > best:
                best = y
        a, fa = b, fb
        nxt += half
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
    st = np.zeros((13, n_comp))
    u, v, un, vn, lu0, lu1, pu, qu, la0, la1, pa, qa, mc = (
        st[0], st[1], st[2], st[3], st[4], st[5], st[6], st[7], st[8], st[9], st[10], st[11],
        st[12])
    for iz in range(nz):
        zeta = zetas[iz]
        for iw in range(nw):
            w = omegas[iw]
            w2 = w * w
            sig = zeta * w
            wd = w * math.sqrt(1.0 - zeta * zeta)
            a11, a12, a21, a22, b11, b12, b21, b22 = step_coefficients(w, zeta, h)
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
                    if max(abs(yu[d]), abs(y1)) + m * h * h * 0.125 > pk_u[d]:
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
