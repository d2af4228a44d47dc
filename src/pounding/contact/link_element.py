"""The seed paper's link element: a spring and a dashpot in parallel (seed eqs 1–15).

Naderpour, Khatami & Barros (2015), COMPDYN, section "Dissipated energy in viscous damping
and rate independent damping". Every function cites the equation it implements, written
*exactly as the paper states it*; where the paper's algebra is wrong or inconsistent the
docstring says so and the function still computes the stated formula (the reading that a
correct derivation would give is offered beside it, never instead of it).

Notation (SI): ``δ`` penetration [m], ``δ̇`` its rate [m/s], ``k`` spring stiffness [N/m],
``c`` dashpot coefficient [N·s/m], ``ω`` circular frequency of the harmonic motion [rad/s],
``ω_n`` natural circular frequency [rad/s], ``ζ`` damping ratio [-], ``δ0`` amplitude [m].

Summary of the paper's algebra (see ``docs/seed_paper.md``)
-----------------------------------------------------------
* Eqs 1–12 are the textbook (Chopra, *Dynamics of Structures*, §3.8) energy relations of a
  Kelvin–Voigt element under harmonic motion; they are correct. Eq 8 keeps only the
  ``+`` root of eq 7 (the upper half of the ellipse); eq 9 restores both halves.
* Eq 13 writes ``ω_n = ω sqrt(1 − ζ)``. This is not the damped-frequency relation
  ``ω_D = ω_n sqrt(1 − ζ²)``, nor anything from rate-independent damping (whose textbook form
  is ``E_D = π η k δ0²`` with ``c = η k / ω``).
* Eq 14 is eq 12 with eq 13 substituted — that step is algebraically right.
* Eq 15 follows from eq 14 only if ``ω = sqrt(k/m)``. If ``ω_n = sqrt(k/m)`` (the usual
  meaning), eq 13 instead gives ``ω = sqrt(k/m)/sqrt(1 − ζ)`` and eq 14 then reduces to
  ``c = 2 ζ sqrt(k m)`` with no ``1/sqrt(1 − ζ)`` factor. Eqs 13 and 15 are consistent with
  each other only at ``ζ = 0``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import trapezoid

from pounding.validation import finite, in_range, non_negative, positive

FloatArray = NDArray[np.float64]

__all__ = [
    "HarmonicLoop",
    "c_eq14",
    "c_eq15",
    "damping_coefficient_viscous",
    "dashpot_force",
    "dashpot_force_eq6",
    "dashpot_force_eq8",
    "dissipated_energy",
    "dissipated_energy_eq11",
    "ellipse_area",
    "ellipse_residual_eq9",
    "harmonic_displacement",
    "harmonic_loop",
    "link_force",
    "loop_area",
    "omega_n_eq13",
    "spring_force",
    "spring_work",
    "zeta_from_eq11",
]


def _out(x: FloatArray) -> FloatArray | float:
    return float(x) if np.ndim(x) == 0 else x


def _history(t: ArrayLike, delta: ArrayLike, rate: ArrayLike | None
             ) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Validate a sampled history and return ``(t, δ, δ̇)``; δ̇ by ``np.gradient`` if absent."""
    tt = np.asarray(t, dtype=float)
    dd = np.asarray(delta, dtype=float)
    if tt.ndim != 1 or tt.size < 3:
        raise ValueError(f"t must be a 1-D array of at least 3 samples (got shape {tt.shape})")
    if dd.shape != tt.shape:
        raise ValueError(f"delta must have the shape of t {tt.shape} (got {dd.shape})")
    if not np.all(np.isfinite(tt)):
        raise ValueError("t must be finite (got a non-finite sample)")
    if not np.all(np.isfinite(dd)):
        raise ValueError("delta must be finite (got a non-finite sample)")
    steps = np.diff(tt)
    if np.any(steps <= 0.0):
        bad = float(steps[steps <= 0.0][0])
        raise ValueError(f"t must be strictly increasing (got a step of {bad:g} s)")
    if rate is None:
        rr = np.gradient(dd, tt, edge_order=2)
    else:
        rr = np.asarray(rate, dtype=float)
        if rr.shape != tt.shape:
            raise ValueError(f"rate must have the shape of t {tt.shape} (got {rr.shape})")
        if not np.all(np.isfinite(rr)):
            raise ValueError("rate must be finite (got a non-finite sample)")
    return tt, dd, rr


# --------------------------------------------------------------------------- eqs 1-5
def dissipated_energy(t: ArrayLike, delta: ArrayLike, c: float,
                      rate: ArrayLike | None = None) -> float:
    """Energy dissipated by the dashpot along a sampled history (seed eq 1).

    ``E_D = ∫ f_D dδ = ∫ (c δ̇) δ̇ dt = ∫ c δ̇² dt``, integrated over the samples with the
    trapezoid rule.

    Parameters
    ----------
    t : array_like, shape (n,)
        Strictly increasing instants [s], n ≥ 3.
    delta : array_like, shape (n,)
        Penetration δ at those instants [m].
    c : float
        Dashpot coefficient [N·s/m], ≥ 0.
    rate : array_like, shape (n,), optional
        δ̇ [m/s]; if omitted it is ``np.gradient(delta, t, edge_order=2)`` (second order).

    Returns
    -------
    float
        ``E_D`` [J].
    """
    cc = non_negative("c", c)
    tt, _, rr = _history(t, delta, rate)
    return float(cc * trapezoid(rr * rr, tt))


def spring_work(t: ArrayLike, delta: ArrayLike, k: float, rate: ArrayLike | None = None) -> float:
    """Work done on the spring along a sampled history (seed eq 2).

    ``E_S = ∫ f_S dδ = ∫ (k δ) δ̇ dt``, integrated with the trapezoid rule. The exact value
    is ``½ k (δ_end² − δ_start²)``: zero over any closed cycle (the spring stores and returns
    energy; it dissipates none, as the paper says of the blue line of Fig 2).

    Parameters are those of :func:`dissipated_energy` with ``k`` [N/m] > 0 in place of ``c``.

    Returns
    -------
    float
        ``E_S`` [J].
    """
    kk = positive("k", k)
    tt, dd, rr = _history(t, delta, rate)
    return float(kk * trapezoid(dd * rr, tt))


def spring_force(k: float, delta: ArrayLike) -> FloatArray | float:
    """Spring force ``f_S = k δ`` [N] (seed eq 3, first part)."""
    kk = positive("k", k)
    return _out(kk * np.asarray(delta, dtype=float))


def dashpot_force(c: float, rate: ArrayLike) -> FloatArray | float:
    """Dashpot force ``f_D = c δ̇`` [N] (seed eq 3, second part)."""
    cc = non_negative("c", c)
    return _out(cc * np.asarray(rate, dtype=float))


def link_force(k: float, c: float, delta: ArrayLike, rate: ArrayLike) -> FloatArray | float:
    """Link-element force ``f = f_S + f_D = k δ + c δ̇`` [N] (seed eqs 4–5).

    This is the Kelvin–Voigt law (:class:`pounding.contact.KelvinVoigt`) without the
    contact condition: the formula alone, for any sign of δ.
    """
    d = np.asarray(delta, dtype=float)
    r = np.asarray(rate, dtype=float)
    return _out(np.asarray(spring_force(k, d)) + np.asarray(dashpot_force(c, r)))


# --------------------------------------------------------------------------- eqs 6-9
def harmonic_displacement(t: ArrayLike, omega: float, delta0: float,
                          phi: float = 0.0) -> FloatArray | float:
    """The paper's assumed motion ``δ = δ0 sin(ω t − φ)`` [m] (text before seed eq 6)."""
    w = positive("omega", omega)
    d0 = positive("delta0", delta0)
    p = finite("phi", phi)
    return _out(d0 * np.sin(w * np.asarray(t, dtype=float) - p))


def dashpot_force_eq6(t: ArrayLike, c: float, omega: float, delta0: float,
                      phi: float = 0.0) -> FloatArray | float:
    """Dashpot force in time under harmonic motion (seed eq 6).

    ``f_D = c δ̇(t) = c ω δ0 cos(ω t − φ)`` [N].
    """
    cc = non_negative("c", c)
    w = positive("omega", omega)
    d0 = positive("delta0", delta0)
    p = finite("phi", phi)
    return _out(cc * w * d0 * np.cos(w * np.asarray(t, dtype=float) - p))


def dashpot_force_eq8(delta: ArrayLike, c: float, omega: float, delta0: float,
                      branch: int = 1) -> FloatArray | float:
    """Dashpot force as a function of the penetration (seed eqs 7–8).

    ``f_D = c ω sqrt(δ0² − δ²)`` as the paper writes it (eq 8). Eq 7 takes the square root
    of ``cos²``, so eq 8 is only the ``+`` root — the upper half of the ellipse, where δ̇ > 0.
    ``branch=-1`` gives the lower half (δ̇ < 0), which the paper's eq 9 includes.

    Parameters
    ----------
    delta : array_like
        Penetration(s) with ``|δ| ≤ δ0`` [m].
    c, omega, delta0 : float
        Dashpot coefficient [N·s/m], circular frequency [rad/s], amplitude [m].
    branch : {+1, -1}
        Sign of the root; +1 (default) is eq 8 as printed.
    """
    cc = non_negative("c", c)
    w = positive("omega", omega)
    d0 = positive("delta0", delta0)
    if branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1 (got {branch!r})")
    d = np.asarray(delta, dtype=float)
    if np.any(np.abs(d) > d0 * (1.0 + 1e-12)):
        worst = float(d.flat[int(np.argmax(np.abs(d)))])
        raise ValueError(f"delta must satisfy |delta| <= delta0 = {d0:g} (got {worst:g})")
    return _out(branch * cc * w * np.sqrt(np.clip(d0 * d0 - d * d, 0.0, None)))


def ellipse_residual_eq9(delta: ArrayLike, f_d: ArrayLike, c: float, omega: float,
                         delta0: float) -> FloatArray | float:
    """Left side of seed eq 9 minus 1: ``(δ/δ0)² + (f_D/(c ω δ0))² − 1``.

    Zero at every point of the dashpot ellipse (the green curve of Fig 2).
    """
    cc = positive("c", c)
    w = positive("omega", omega)
    d0 = positive("delta0", delta0)
    d = np.asarray(delta, dtype=float)
    f = np.asarray(f_d, dtype=float)
    return _out((d / d0) ** 2 + (f / (cc * w * d0)) ** 2 - 1.0)


# --------------------------------------------------------------------------- eqs 10-12
def ellipse_area(c: float, omega: float, delta0: float) -> float:
    """Energy dissipated per cycle of harmonic motion: ``E_D = π c ω δ0²`` [J] (seed eq 10).

    The area of the dashpot ellipse of eq 9 (semi-axes δ0 and c ω δ0), and equally of the
    combined, rotated loop ``f = k δ + c δ̇`` (a shear of the ellipse, which keeps its area).
    """
    cc = non_negative("c", c)
    w = positive("omega", omega)
    d0 = positive("delta0", delta0)
    return float(np.pi * cc * w * d0 * d0)


def dissipated_energy_eq11(zeta: float, omega: float, omega_n: float, k: float,
                           delta0: float) -> float:
    """Right side of seed eq 11: ``E_D = 2 π ζ (ω/ω_n) k δ0²`` [J].

    Equal to eq 10 exactly when ``c = 2 k ζ / ω_n`` (eq 12), for any ω.
    """
    z = non_negative("zeta", zeta)
    w = positive("omega", omega)
    wn = positive("omega_n", omega_n)
    kk = positive("k", k)
    d0 = positive("delta0", delta0)
    return float(2.0 * np.pi * z * (w / wn) * kk * d0 * d0)


def damping_coefficient_viscous(k: float, zeta: float, omega_n: float) -> float:
    """Viscous damping coefficient ``c = 2 k ζ / ω_n`` [N·s/m] (seed eq 12).

    Solving eq 11 for ``c`` (ω cancels). With ``ω_n = sqrt(k/m)`` it is the familiar
    ``c = 2 ζ sqrt(k m)``.
    """
    kk = positive("k", k)
    z = non_negative("zeta", zeta)
    wn = positive("omega_n", omega_n)
    return float(2.0 * kk * z / wn)


def zeta_from_eq11(c: float, k: float, omega: float, omega_n: float) -> float:
    """Damping ratio that makes seed eq 11 hold, solved from ``π c ω δ0² = 2 π ζ (ω/ω_n) k δ0²``.

    δ0 and ω cancel: ``ζ = c ω_n / (2 k)``, the inverse of eq 12. Evaluated in the unsimplified
    form ``π c ω / (2 π (ω/ω_n) k)`` so that a test of it is a test of eq 11.
    """
    cc = non_negative("c", c)
    kk = positive("k", k)
    w = positive("omega", omega)
    wn = positive("omega_n", omega_n)
    return float(np.pi * cc * w / (2.0 * np.pi * (w / wn) * kk))


# --------------------------------------------------------------------------- eqs 13-15
def omega_n_eq13(omega: float, zeta: float) -> float:
    """Natural frequency as the paper states it: ``ω_n = ω sqrt(1 − ζ)`` (seed eq 13).

    **Algebra problem.** This is not the damped-frequency relation, which reads
    ``ω_D = ω_n sqrt(1 − ζ²)`` (ζ squared; the damped frequency on the left). Nor is it a
    rate-independent-damping relation: in that model (Chopra §3.10) ``E_D = π η k δ0²`` and
    the equivalent viscous coefficient is ``c = η k / ω``. Computed as stated; requires
    ``0 ≤ ζ < 1``.
    """
    w = positive("omega", omega)
    z = in_range("zeta", zeta, 0.0, 1.0, high_open=True)
    return float(w * np.sqrt(1.0 - z))


def c_eq14(k: float, zeta: float, omega: float) -> float:
    """Damping coefficient ``c = 2 k ζ / (ω sqrt(1 − ζ))`` [N·s/m] (seed eq 14).

    Eq 12 with ω_n from eq 13 — that substitution is correct, but it inherits eq 13's
    problem. Requires ``0 ≤ ζ < 1``.
    """
    kk = positive("k", k)
    z = in_range("zeta", zeta, 0.0, 1.0, high_open=True)
    w = positive("omega", omega)
    return float(2.0 * kk * z / (w * np.sqrt(1.0 - z)))


def c_eq15(k: float, m: float, zeta: float) -> float:
    """Damping coefficient ``c = 2 ζ sqrt(k m) / sqrt(1 − ζ)`` [N·s/m] (seed eq 15).

    **Algebra problem.** Eq 15 follows from eq 14 only if the *excitation* frequency is
    ``ω = sqrt(k/m)``. If, as usual, ``ω_n = sqrt(k/m)``, eq 13 makes
    ``ω = sqrt(k/m) / sqrt(1 − ζ)`` and eq 14 collapses to ``c = 2 ζ sqrt(k m)`` — the
    ``1/sqrt(1 − ζ)`` factor cancels. So eqs 13 and 15 agree only at ζ = 0. Computed as
    stated; requires ``0 ≤ ζ < 1``.

    Parameters
    ----------
    k : float
        Stiffness [N/m].
    m : float
        Mass [kg] (the effective mass ``m1 m2 / (m1 + m2)`` in a collision).
    zeta : float
        Damping ratio.
    """
    kk = positive("k", k)
    mm = positive("m", m)
    z = in_range("zeta", zeta, 0.0, 1.0, high_open=True)
    return float(2.0 * z * np.sqrt(kk * mm) / np.sqrt(1.0 - z))


# --------------------------------------------------------------------------- Fig 2
class HarmonicLoop(NamedTuple):
    """One cycle of the link element under ``δ = δ0 sin(ω t − φ)`` (seed Fig 2).

    Attributes (arrays of one length; the first and last samples coincide, closing the loop)
    ----------
    t : time [s], from 0 to 2π/ω.
    delta : penetration δ [m].
    rate : δ̇ [m/s], exact (eq 6 divided by c).
    f_spring : ``f_S = k δ`` [N] — the straight line (blue).
    f_dashpot : ``f_D = c δ̇`` [N] — the ellipse of eq 9 (green).
    f_total : ``f = f_S + f_D`` [N] — the rotated ellipse (red), eqs 4–5.
    """

    t: FloatArray
    delta: FloatArray
    rate: FloatArray
    f_spring: FloatArray
    f_dashpot: FloatArray
    f_total: FloatArray


def harmonic_loop(k: float, c: float, omega: float, delta0: float, n: int = 721,
                  phi: float = 0.0) -> HarmonicLoop:
    """Sample one cycle of the seed's Fig 2 (eqs 3–9).

    Parameters
    ----------
    k : float
        Spring stiffness [N/m], > 0.
    c : float
        Dashpot coefficient [N·s/m], ≥ 0.
    omega : float
        Circular frequency [rad/s], > 0.
    delta0 : float
        Amplitude [m], > 0.
    n : int
        Number of samples over the cycle, endpoints included (≥ 5).
    phi : float
        Phase φ [rad].
    """
    kk = positive("k", k)
    cc = non_negative("c", c)
    w = positive("omega", omega)
    d0 = positive("delta0", delta0)
    p = finite("phi", phi)
    if int(n) != n or n < 5:
        raise ValueError(f"n must be an integer >= 5 (got {n!r})")
    t = np.linspace(0.0, 2.0 * np.pi / w, int(n))
    delta = d0 * np.sin(w * t - p)
    rate = w * d0 * np.cos(w * t - p)
    f_s = kk * delta
    f_d = cc * rate
    return HarmonicLoop(t, delta, rate, f_s, f_d, f_s + f_d)


def loop_area(x: ArrayLike, y: ArrayLike) -> float:
    """Area enclosed by a closed polygon (shoelace formula), in units of ``x·y``.

    For a force–penetration loop the area is the energy dissipated per cycle [J]. The
    polygon is closed automatically (last point joined to the first). Returns ``|area|``.
    """
    xx = np.asarray(x, dtype=float)
    yy = np.asarray(y, dtype=float)
    if xx.ndim != 1 or xx.shape != yy.shape or xx.size < 3:
        raise ValueError(f"x and y must be 1-D arrays of one length >= 3 "
                         f"(got shapes {xx.shape} and {yy.shape})")
    return float(0.5 * abs(np.dot(xx, np.roll(yy, -1)) - np.dot(yy, np.roll(xx, -1))))
