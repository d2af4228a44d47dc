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
* :data:`RESTRAINER` ``(k, s₀, F_y, b)``: a cable restrainer across a bridge's expansion
  joint (DesRoches & Fenves 2000, J. Struct. Eng. 126(4); Caltrans SDC 2.0 §7.2.6; OpenSees
  ``ElasticPPGap`` in tension, or ``Steel01`` in series with a gap): tension only, with a
  slack ``s₀`` [m], elastic ``k`` [N/m], yielding at ``F_y`` [N] with hardening ``b k``
  (0 ≤ b < 1), unloading elastic, never in compression. Its internal variable ``z`` [m] is
  the cable's plastic elongation ``s_p``: a yielded cable is longer, its slack ``s₀ + s_p``.
  With the elastic elongation ``e = d − s₀ − z`` and the isotropic hardening modulus
  ``H = b k / (1 − b)``::

      F = 0                   e ≤ 0 (slack)
      F = k e                 0 < k e < F_y + H z (taut, elastic)
      F = F_y + H z           otherwise (yielding), ż = (1 − b) max(ḋ, 0)

  so that while it yields ``Ḟ = H ż = b k ḋ``: the bilinear backbone ``F_y + b k (d − s₀ −
  F_y/k)``. The two corners of the law — the slack taken up or given back (``e = 0``) and
  yield (:func:`restrainer_kinks`) — are events of the kernel: no step straddles them.
  Unloading from yield needs none (the force's rate is continuous there, ``b k ḋ → 0``).

Energy (contract step 5): the recoverable energy is the springs' ``½ k d²`` (Kelvin),
``½ k z²`` (Maxwell) or the cable's ``F²/(2k)`` (restrainer); a link's work less it is what
the link has dissipated (a restrainer's: ``∫ F ż dt``, its plastic work).
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
RESTRAINER: int = 13

DEVICE_CODES: dict[int, str] = {VISCOUS: "viscous", KELVIN: "Kelvin", MAXWELL: "Maxwell",
                                RESTRAINER: "restrainer"}
"""The codes the compiled link laws implement; every function here returns NaN for any
other code (no law stands in for an unknown one)."""


@njit(cache=True, inline="always", error_model="numpy")
def device_trial(code, p0, p1, p2, p3, d, rate, z):
    """``(F, ∂F/∂d, ż)`` of a link at relative displacement ``d`` [m], rate ``ḋ`` [m/s] and
    internal variable ``z`` [m] (Maxwell, restrainer; 0 otherwise). A restrainer's ``∂F/∂d``
    is its tangent along the motion (``k`` taut, ``b k`` yielding, 0 slack): with ``ż`` of
    the yield branch folded in, ``Ḟ = (∂F/∂d) ḋ``."""
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
    if code == RESTRAINER:
        e = d - p1 - z
        if e <= 0.0:
            return 0.0, 0.0, 0.0
        f = p0 * e
        f_yield = p2 + hardening_modulus(p0, p3) * z
        if f < f_yield:
            return f, p0, 0.0
        if rate > 0.0:
            return f_yield, p3 * p0, (1.0 - p3) * rate
        return f_yield, p0, 0.0
    return np.nan, np.nan, np.nan


@njit(cache=True, inline="always", error_model="numpy")
def hardening_modulus(k, b):
    """``H = b k / (1 − b)`` [N/m]: the growth of a restrainer's yield force per metre of
    plastic elongation that gives the bilinear backbone's slope ``b k`` (0 ≤ b < 1)."""
    return b * k / (1.0 - b)


@njit(cache=True, inline="always", error_model="numpy")
def restrainer_kinks(p0, p1, p2, p3, d, rate, z, zdot):
    """The two event functions of a restrainer [m] and their rates [m/s]: the elastic
    elongation ``e = d − s₀ − z`` (0 where the slack is taken up or given back) and the
    margin to yield ``e − (F_y + H z)/k`` (0 where it yields), from ``d``, ``ḋ``, ``z``,
    ``ż``. ``(e, ė, g, ġ)``; ``g = −inf`` for a cable that never yields (``F_y = inf``)."""
    e = d - p1 - z
    e_rate = rate - zdot
    if not p2 < np.inf:
        return e, e_rate, -np.inf, 0.0
    h_k = p3 / (1.0 - p3)  # H / k
    return e, e_rate, e - p2 / p0 - h_k * z, e_rate - h_k * zdot

def linear_link_constants(code: int, p0: float, p1: float) -> tuple[float, float] | None:
    """``(k, c)`` [N/m, N·s/m] of a link whose force is linear in ``d`` and ``ḋ`` and which
    has no internal variable — Kelvin ``(p0, p1)``, a viscous dashpot with α = 1 ``(0,
    p0)`` — so that its spring and dashpot can join the structure's K and C (the time
    stepper steps them exactly, :func:`pounding.integrate.kernel_model.fold_linear_links`);
    None for any other law (a fluid damper, Maxwell, a restrainer)."""
    if code == KELVIN:
        return p0, p1
    if code == VISCOUS and p1 == 1.0:
        return 0.0, p0
    return None


@njit(cache=True, inline="always", error_model="numpy")
def folded_dashpot(code, p0, p1):
    """The dashpot ``c`` [N·s/m] of a link folded into K and C (:func:`linear_link_constants`):
    its dissipated power is ``c ḋ²``."""
    return p1 if code == KELVIN else p0


SLOPE_RATE_FLOOR: float = 1e-3
"""Relative velocity [m/s] below which a fluid damper's slope ``α c |ḋ|^(α−1)`` (unbounded at
``ḋ = 0`` for α < 1) is taken at this velocity in the force's rate (:func:`device_rate_terms`),
which the kernel uses only to locate acceleration peaks inside steps."""


@njit(cache=True, inline="always", error_model="numpy")
def has_rate_cusp(code, p1):
    """True for a fluid damper (α ≠ 1): its force has an unbounded slope where its rate
    reverses, and the kernel ends a step there (an event, as at a yielding storey's drift
    reversal). Linear, Kelvin and Maxwell links are smooth there: no event (a restrainer's
    corners are events of their own, :func:`restrainer_kinks`)."""
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
    if code == RESTRAINER:
        return 0.0, 0.0  # (its ∂F/∂d is the tangent along the motion, ż included)
    return np.nan, np.nan


@njit(cache=True, inline="always", error_model="numpy")
def device_stored(code, p0, p1, p2, p3, d, z):
    """Recoverable (spring) energy of a link [J]: a restrainer's ``F²/(2k)``."""
    if code == KELVIN:
        return 0.5 * p0 * d * d
    if code == MAXWELL:
        return 0.5 * p0 * z * z
    if code == VISCOUS:
        return 0.0
    if code == RESTRAINER:
        f = device_trial(code, p0, p1, p2, p3, d, 0.0, z)[0]
        return 0.5 * f * f / p0
    return np.nan


def relaxation_time(k: float, c: float) -> float:
    """``c / k`` [s]: how fast a linear Maxwell link forgets (its spring relaxes through the
    dashpot)."""
    return c / k if k > 0 else math.inf
