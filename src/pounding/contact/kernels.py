"""The compiled trial of every contact law (contract step 4 of :mod:`pounding.contact.base`).

Each law is one scalar, pure function
``(p0, p1, p2, δ, δ̇, v0, slip, dmax) → (F, ∂F/∂δ, ∂F/∂δ̇, v0', slip', dmax')``: the law's
constants (:meth:`~pounding.contact.base.ContactLaw.params`, zero-padded to three), the
penetration [m] and its rate [m/s], and the committed state; it returns the force [N], both
tangents and the trial state. :func:`open_or_onset` is steps 2–3 of the contract, shared by
all of them. The one switch on a law's code, :func:`pounding.contact.dispatch.law_trial`,
calls these; the law classes (:mod:`pounding.contact.linear`, :mod:`pounding.contact.hertz`,
:mod:`pounding.contact.bilinear`) hold their constants and their Python side.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from pounding.contact.codes import V0_MIN

DELTA_TINY: float = 1e-300
"""Guard for δ^(n−1) and δ^(−3/4) in tangents at the very instant of contact [m]."""


@njit(cache=True, inline="always", error_model="numpy")
def open_or_onset(delta: float, rate: float, v0: float, slip: float, dmax: float
                  ) -> tuple[float, float, float]:
    """Steps 2–3 of the contract, shared by every law (scalar, pure).

    Parameters are the penetration [m], its rate [m/s] and the committed state
    ``(v0, slip, dmax)``. Returns the trial state ``(v0, slip, dmax)``: all zeros while the
    gap is open (``δ ≤ 0``), ``v0 = max(δ̇, V0_MIN)`` at onset, ``dmax`` updated.
    """
    if delta <= 0.0:
        return 0.0, 0.0, 0.0
    if v0 <= 0.0:
        v0 = max(rate, V0_MIN)
        slip = 0.0
        dmax = 0.0
    if delta > dmax:
        dmax = delta
    return v0, slip, dmax


# --------------------------------------------------------------------------- linear laws
@njit(cache=True, inline="always", error_model="numpy")
def linear_spring_trial(k, _p1, _p2, delta, rate, v0, slip, dmax):
    """Gap spring ``F = k δ`` (params: [k])."""
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    return k * delta, k, 0.0, v0, slip, dmax


@njit(cache=True, inline="always", error_model="numpy")
def kelvin_voigt_trial(k, c, tension, delta, rate, v0, slip, dmax):
    """Kelvin–Voigt ``F = k δ + c δ̇`` (params: [k, c, tension]).

    With ``tension == 1`` the dashpot may pull (F < 0) until ``δ = 0``; otherwise the force
    is clipped at zero and the bodies separate when it returns to zero.
    """
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    f = k * delta + c * rate
    if f < 0.0 and tension == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    return f, k, c, v0, slip, dmax


@njit(cache=True, inline="always", error_model="numpy")
def modified_kelvin_voigt_trial(k, c, _p2, delta, rate, v0, slip, dmax):
    """Modified Kelvin–Voigt: ``F = k δ + c δ̇`` approaching, ``F = k δ`` separating."""
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    if rate > 0.0:
        return k * delta + c * rate, k, c, v0, slip, dmax
    return k * delta, k, 0.0, v0, slip, dmax


# --------------------------------------------------------------------------- Hertz family
@njit(cache=True, inline="always", error_model="numpy")
def hertz_trial(k, n, _p2, delta, rate, v0, slip, dmax):
    """Hertz ``F = k_h δⁿ`` (params: [k_h, n])."""
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    f = k * delta**n
    return f, n * f / max(delta, DELTA_TINY), 0.0, v0, slip, dmax


@njit(cache=True, inline="always", error_model="numpy")
def hunt_crossley_trial(k, n, chi, delta, rate, v0, slip, dmax):
    """Hunt–Crossley ``F = k_h δⁿ (1 + χ δ̇ / v0)`` (params: [k_h, n, χ]), clipped at F ≥ 0."""
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    fe = k * delta**n
    factor = 1.0 + chi * rate / v0
    if factor <= 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    return (fe * factor, n * fe * factor / max(delta, DELTA_TINY), fe * chi / v0,
            v0, slip, dmax)


@njit(cache=True, inline="always", error_model="numpy")
def nonlinear_viscoelastic_trial(k, zeta, m, delta, rate, v0, slip, dmax):
    """Jankowski ``F = k_h δ^1.5 + c δ̇`` approaching, ``k_h δ^1.5`` separating, with
    ``c = 2 ζ sqrt(k_h sqrt(δ) m_eff)`` (params: [k_h, ζ, m_eff]).
    """
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    d = max(delta, DELTA_TINY)
    sd = np.sqrt(d)
    fe = k * d * sd
    ke = 1.5 * k * sd
    if rate > 0.0:
        c = 2.0 * zeta * np.sqrt(k * sd * m)
        return fe + c * rate, ke + 0.25 * c * rate / d, c, v0, slip, dmax
    return fe, ke, 0.0, v0, slip, dmax


# --------------------------------------------------------------------------- bilinear element
@njit(cache=True, inline="always", error_model="numpy")
def bilinear_impact_trial(k1, k2, dy, delta, rate, v0, slip, dmax):
    """Bilinear impact element (params: [K1, K2, δy]).

    Written as a spring ``K2`` in parallel with an elasto-plastic spring of stiffness
    ``K1 − K2`` whose force stays in ``[0, (K1 − K2) δy]``; ``slip`` is that spring's
    plastic offset. Loading follows K1 up to ``δy`` then K2; unloading follows K1 down to the
    line ``F = K2 δ`` through the gap point, then that line to zero force — the parallelogram
    loop of Muthukumar (2003). The return mapping is exact for any monotonic increment.
    """
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    kp = k1 - k2
    fy = kp * dy
    fp = kp * (delta - slip)
    if fp > fy:
        return k2 * delta + fy, k2, 0.0, v0, delta - dy, dmax
    if fp < 0.0:
        return k2 * delta, k2, 0.0, v0, delta, dmax
    return k2 * delta + fp, k1, 0.0, v0, slip, dmax


# --------------------------------------------------------------------------- abutment backfill
@njit(cache=True, inline="always", error_model="numpy")
def abutment_backbone(k, fu, yu, delta):
    """The backfill's backbone ``F = min(δ/(A + B δ), F_ult)`` and its slope, with
    ``A = 1/K`` and ``B = max(1/F_ult − 1/(K δ_ult), 0)`` (params ``[K, F_ult, δ_ult]``;
    :class:`pounding.contact.abutment.AbutmentBackfill`)."""
    b = max(1.0 / fu - 1.0 / (k * yu), 0.0)
    den = 1.0 + k * b * delta
    fb = k * delta / den
    if fb >= fu:
        return fu, 0.0
    return fb, k / (den * den)


@njit(cache=True, inline="always", error_model="numpy")
def abutment_trial(k, fu, yu, delta, rate, v0, slip, dmax):
    """Abutment backfill (params: [K, F_ult, δ_ult]; ``slip`` its permanent set).

    Loading follows the backbone (:func:`abutment_backbone`); unloading and reloading the
    line ``F = K (δ − set)``; no tension, so below the set the force is zero and the gap is
    larger by the set. Unlike every other law the set is *not* reset while the gap is open
    or at the onset of the next impact (:func:`pounding.contact.dispatch.keeps_set`). The
    return mapping ``F = max(min(K (δ − set), backbone(δ)), 0)`` is exact for any monotonic
    increment: the backbone's slope never exceeds ``K``.
    """
    if delta <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, slip, 0.0
    if v0 <= 0.0:
        v0 = max(rate, V0_MIN)
        dmax = 0.0
    if delta > dmax:
        dmax = delta
    fe = k * (delta - slip)
    if fe <= 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    fb, kb = abutment_backbone(k, fu, yu, delta)
    if fe >= fb:
        return fb, kb, 0.0, v0, delta - fb / k, dmax
    return fe, k, 0.0, v0, slip, dmax


# --------------------------------------------------------------------------- shear key
@njit(cache=True, inline="always", error_model="numpy")
def shear_key_trial(k, fc, du, delta, rate, v0, slip, dmax):
    """Sacrificial shear key (params: [k, F_c, δ_u]; ``slip`` its permanent set, ``+∞`` once
    it has broken off; :class:`pounding.contact.shear_key.ShearKey`).

    Elastic ``F = k (δ − set)`` up to the capacity ``F_c``, then perfectly plastic (the set
    grows to ``δ − F_c/k``); unloading and reloading at ``k``, no tension. When the
    penetration reaches the fracture deformation ``δ_u`` (``δ_u > 0``; 0: it never breaks)
    the key breaks off: the trial state says so (set ``+∞``) while the force stays on the
    intact branch, so the force drops only where the caller commits that state — at the
    located event (:func:`pounding.contact.dispatch.fracture_value`), never inside a step.
    A broken key pushes nothing, ever again. Like the abutment backfill, its set outlasts an
    impact (:func:`pounding.contact.dispatch.keeps_set`).
    """
    if delta <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, slip, 0.0
    if slip == np.inf:  # broken off: nothing, however far the deck goes
        return 0.0, 0.0, 0.0, v0, slip, max(dmax, delta)
    if v0 <= 0.0:
        v0 = max(rate, V0_MIN)
        dmax = 0.0
    if delta > dmax:
        dmax = delta
    broken = du > 0.0 and delta >= du
    fe = k * (delta - slip)
    if fe <= 0.0:
        return 0.0, 0.0, 0.0, v0, np.inf if broken else slip, dmax
    if fe >= fc:  # on the plateau: the set follows
        return fc, 0.0, 0.0, v0, np.inf if broken else delta - fc / k, dmax
    return fe, k, 0.0, v0, np.inf if broken else slip, dmax
