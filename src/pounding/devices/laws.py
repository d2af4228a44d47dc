"""Force laws of the link devices that join floors of neighbouring buildings, compiled.

A link acts at all times, in both directions, between two floors: ``d = u_b − u_a`` is the
relative displacement of floor b (of the building on the right) to floor a [m], ``ḋ`` its
rate [m/s]. The force ``F`` [N] resists ``d`` and ``ḋ`` like a storey's shear: floor b
receives ``−F``, floor a ``+F``. Links are integrated by the kernel exactly as a yielding
storey is (:mod:`pounding.hysteresis.base`, contract steps 3–5): the same element rows, law
codes from :data:`DEVICE_MIN` up, and a Maxwell link's spring deformation is its internal
variable ``z``, integrated with the motion.

Laws (constants ``p0, p1, p2``):

* :data:`VISCOUS` ``(c, α, –)``: ``F = c |ḋ|^α sgn ḋ`` — a linear dashpot (α = 1) or a
  fluid viscous damper (α < 1; Constantinou & Symans 1993; OpenSees ``Viscous``).
* :data:`KELVIN` ``(k, c, –)``: spring and dashpot in parallel, ``F = k d + c ḋ``.
* :data:`MAXWELL` ``(k, c, α)``: spring and dashpot in series, ``F = k z`` with the spring's
  deformation ``z`` [m] following ``ż = ḋ − sgn F (|F|/c)^{1/α}`` (the dashpot's rate; OpenSees
  ``ViscousDamper`` with no gap, Akcelyan, Lignos & Hikino 2018; α = 1 is the linear
  Maxwell model).

Energy (contract step 5): the recoverable energy is the springs' ``½ k d²`` (Kelvin) or
``½ k z²`` (Maxwell); a link's work less it is what the link has dissipated.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

DEVICE_MIN: int = 10
"""Element law codes from here on are link devices (below: storey laws)."""

VISCOUS: int = 10
KELVIN: int = 11
MAXWELL: int = 12

DEVICE_CODES: dict[int, str] = {VISCOUS: "viscous", KELVIN: "Kelvin", MAXWELL: "Maxwell"}
"""The codes the compiled link laws implement; every function here returns NaN for any
other code (no law stands in for an unknown one)."""


@njit(cache=True, inline="always", error_model="numpy")
def device_trial(code, p0, p1, p2, d, rate, z):
    """``(F, ∂F/∂d, ż)`` of a link at relative displacement ``d`` [m], rate ``ḋ`` [m/s] and
    internal variable ``z`` [m] (Maxwell; 0 otherwise)."""
    if code == VISCOUS:
        if p1 == 1.0:
            return p0 * rate, 0.0, 0.0
        a = abs(rate)
        f = p0 * a ** p1 if a > 0.0 else 0.0
        return (f if rate > 0.0 else -f), 0.0, 0.0
    if code == KELVIN:
        return p0 * d + p1 * rate, p0, 0.0
    if code == MAXWELL:
        # F = k z; the dashpot carries F at the rate (|F| / c)^(1/α)
        f = p0 * z
        if p2 == 1.0:
            v_dash = f / p1
        else:
            v_dash = (abs(f) / p1) ** (1.0 / p2)
            if f < 0.0:
                v_dash = -v_dash
        return f, 0.0, rate - v_dash
    return np.nan, np.nan, np.nan


SLOPE_RATE_FLOOR: float = 1e-3
"""Relative velocity [m/s] below which a fluid damper's slope ``α c |ḋ|^(α−1)`` (unbounded at
``ḋ = 0`` for α < 1) is taken at this velocity in the force's rate (:func:`device_rate_terms`),
which the kernel uses only to locate acceleration peaks inside steps."""


@njit(cache=True, inline="always", error_model="numpy")
def has_rate_cusp(code, p1):
    """True for a fluid damper (α ≠ 1): its force has an unbounded slope where its rate
    reverses, and the kernel ends a step there (an event, as at a yielding storey's drift
    reversal). Linear, Kelvin and Maxwell links are smooth there: no event."""
    return code == VISCOUS and p1 != 1.0


@njit(cache=True, inline="always", error_model="numpy")
def device_rate_terms(code, p0, p1, p2, rate):
    """``(∂F/∂ḋ, ∂F/∂z)``: with :func:`device_trial`'s ``∂F/∂d`` they give the force's rate
    ``Ḟ = (∂F/∂d) ḋ + (∂F/∂ḋ) d̈ + (∂F/∂z) ż``. A fluid damper's ``∂F/∂ḋ`` is unbounded where
    ``ḋ`` changes sign (the kernel ends a step there): it is taken at
    ``|ḋ| ≥`` :data:`SLOPE_RATE_FLOOR`, so the cubic through the acceleration and this rate
    at a step's ends (pounding.integrate.peaks) does not overshoot the cusp."""
    if code == VISCOUS:
        if p1 == 1.0:
            return p0, 0.0
        a = max(abs(rate), SLOPE_RATE_FLOOR)
        return p1 * p0 * a ** (p1 - 1.0), 0.0
    if code == KELVIN:
        return p1, 0.0
    if code == MAXWELL:
        return 0.0, p0
    return np.nan, np.nan


@njit(cache=True, inline="always", error_model="numpy")
def device_stored(code, p0, p1, p2, d, z):
    """Recoverable (spring) energy of a link [J]."""
    if code == KELVIN:
        return 0.5 * p0 * d * d
    if code == MAXWELL:
        return 0.5 * p0 * z * z
    if code == VISCOUS:
        return 0.0
    return np.nan


def relaxation_time(k: float, c: float) -> float:
    """``c / k`` [s]: how fast a linear Maxwell link forgets (its spring relaxes through the
    dashpot)."""
    return c / k if k > 0 else math.inf
