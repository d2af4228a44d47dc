"""Stochastic ground motions: the fully nonstationary model of Rezaeian & Der Kiureghian,
a time-modulated, time-varying filtered white noise, simulated from its six parameters.

* Rezaeian, S. & Der Kiureghian, A. (2008), "A stochastic ground motion model with
  separable temporal and spectral nonstationarities", *Earthquake Engng Struct. Dyn.*
  37:1565–1584 (the model);
* Rezaeian, S. & Der Kiureghian, A. (2010), "Simulation of synthetic ground motions for
  specified earthquake and site characteristics", *Earthquake Engng Struct. Dyn.*
  39:1155–1180 (its six parameters; predicted from M, R, Vs30 and the mechanism in
  :mod:`pounding.ground_motion.rezaeian2010`).

The acceleration is ``a(t) = q(t) Σ_i s_i(t) u_i`` (then high-passed), with ``u_i``
independent standard normal pulses at ``t_i = i dt``,
``s_i(t) = h(t − t_i; ω_f(t_i)) / sqrt(Σ_j h(t − t_j; ω_f(t_j))²)`` (the filtered noise
normalised to unit variance), ``h`` the impulse response of a linear oscillator of damping
``ζ_f`` whose frequency is the filter's at the pulse, ``ω_f(τ) = ω_mid + ω' (τ − t_mid)``,
and ``q`` the gamma-shaped modulating function ``q(t) = α1 t^(α2−1) e^(−α3 t)`` whose
cumulative Arias intensity is a gamma distribution: total ``I_a``, 5–95 % significant
duration ``D_5-95``, and ``t_mid`` when 45 % of ``I_a`` is reached. See ``docs/records.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from pounding.ground_motion.motion import FloatArray, GroundMotion
from pounding.units import G
from pounding.validation import in_range, positive

__all__ = ["HIGH_PASS_HZ", "MIN_FILTER_HZ", "ModelParameters", "modulating_shape",
           "simulate"]

HIGH_PASS_HZ = 0.2
"""Corner frequency of the critically damped high-pass filter applied last [Hz]."""

MIN_FILTER_HZ = 0.3
"""Lowest filter frequency [Hz]: ``ω_f(t)`` is held there where the linear law
``ω_mid + ω'(t − t_mid)`` would fall lower (a steep negative slope late in a long record
would otherwise make it vanish or change sign)."""


@dataclass(frozen=True)
class ModelParameters:
    """The six parameters of the model (Rezaeian & Der Kiureghian 2010, §2).

    Attributes
    ----------
    arias : float
        Arias intensity ``I_a = π/(2g) ∫ a² dt`` [m/s].
    d595 : float
        5–95 % significant duration [s].
    t_mid : float
        Time at which 45 % of ``I_a`` is reached [s].
    f_mid : float
        Filter frequency at ``t_mid``, ``ω_mid / 2π`` [Hz].
    f_slope : float
        Its rate of change, ``ω' / 2π`` [Hz/s].
    zeta_f : float
        Filter damping ratio [-].
    """

    arias: float
    d595: float
    t_mid: float
    f_mid: float
    f_slope: float
    zeta_f: float

    def __post_init__(self) -> None:
        positive("arias [m/s]", self.arias)
        positive("d595 [s]", self.d595)
        positive("t_mid [s]", self.t_mid)
        positive("f_mid [Hz]", self.f_mid)
        in_range("f_slope [Hz/s]", self.f_slope, -100.0, 100.0)
        in_range("zeta_f", self.zeta_f, 0.0, 1.0, low_open=True, high_open=True)

    def as_dict(self) -> dict[str, float]:
        """The parameters by name, SI units (Hz for the frequencies)."""
        return {"arias": self.arias, "d595": self.d595, "t_mid": self.t_mid,
                "f_mid": self.f_mid, "f_slope": self.f_slope, "zeta_f": self.zeta_f}


def modulating_shape(d595: float, t_mid: float) -> tuple[float, float]:
    """Shape ``k = 2α2 − 1`` and rate ``λ = 2α3`` [1/s] of the gamma distribution that the
    cumulative Arias intensity of ``q(t) = α1 t^(α2−1) e^(−α3 t)`` follows.

    ``∫_0^t q² dt ∝ P(k, λt)`` (the regularised lower incomplete gamma function), so
    ``D_5-95 = (P⁻¹(k, 0.95) − P⁻¹(k, 0.05)) / λ`` and ``t_mid = P⁻¹(k, 0.45) / λ``. Their
    ratio depends on ``k`` alone and rises with it: ``k`` is its root, then ``λ`` follows.
    """
    from scipy.optimize import brentq
    from scipy.special import gammaincinv

    d = positive("d595 [s]", d595)
    tm = positive("t_mid [s]", t_mid)

    def ratio(log_k: float) -> float:
        k = math.exp(log_k)
        width = gammaincinv(k, 0.95) - gammaincinv(k, 0.05)
        return math.log(gammaincinv(k, 0.45) / width) - math.log(tm / d)

    lo, hi = math.log(0.05), math.log(1e4)
    if not ratio(lo) < 0.0 < ratio(hi):
        raise ValueError(f"t_mid / d595 = {tm / d:g}: no gamma modulating function has it "
                         "(t_mid must be between about 1e-6 and 30 times d595)")
    k = math.exp(brentq(ratio, lo, hi, xtol=1e-12))
    rate = (gammaincinv(k, 0.95) - gammaincinv(k, 0.05)) / d
    return k, float(rate)


def _modulation(params: ModelParameters, n: int, dt: float) -> FloatArray:
    """``q`` at the samples, each the root-mean-square of the exact ``q`` over its step.

    ``q_i² dt = (2g/π) I_a [P(k, λ t_{i+1/2}) − P(k, λ t_{i−1/2})]``: the Arias intensity
    of the samples (``π/(2g) Σ q_i² dt`` for a unit-variance process) is ``I_a`` times the
    share of the gamma distribution inside the record, without the singularity of ``q`` at
    ``t = 0`` when ``α2 < 1``.
    """
    from scipy.special import gammainc

    k, rate = modulating_shape(params.d595, params.t_mid)
    edges = (np.arange(n + 1) - 0.5).clip(min=0.0) * dt
    share = np.diff(gammainc(k, rate * edges))
    return np.sqrt(2.0 * G / math.pi * params.arias * share / dt)


def _high_pass(accel: FloatArray, dt: float, corner_hz: float) -> FloatArray:
    """The acceleration ``ü`` of ``ü + 2ω_c u̇ + ω_c² u = a`` (a critically damped
    oscillator driven by ``a``: ``H(s) = s²/(s + ω_c)²``), by the bilinear transform."""
    from scipy.signal import bilinear, lfilter

    wc = 2.0 * math.pi * corner_hz
    b, a = bilinear([1.0, 0.0, 0.0], [1.0, 2.0 * wc, wc * wc], fs=1.0 / dt)
    return np.asarray(lfilter(b, a, accel), dtype=np.float64)


def simulate(params: ModelParameters, duration: float, dt: float,
             rng: np.random.Generator, *, high_pass_hz: float | None = HIGH_PASS_HZ,
             name: str = "stochastic") -> GroundMotion:
    """One realisation of the model.

    Parameters
    ----------
    params : ModelParameters
    duration : float
        Time of the last sample [s] (at least ``t_mid``).
    dt : float
        Time step [s] (at most 0.02: the pulses are white up to the Nyquist frequency).
    rng : numpy.random.Generator
        The source of the pulses: ``n`` standard normal draws, ``n`` the number of samples.
    high_pass_hz : float or None
        Corner of the critically damped high-pass filter [Hz]; None: none.
    name : str

    Returns
    -------
    GroundMotion
        In m/s²; ``metadata`` holds the parameters.
    """
    from pounding.ground_motion._stochastic_kernel import normalised_filtered_noise

    step = in_range("dt [s]", dt, 0.0, 0.02, low_open=True)
    end = positive("duration [s]", duration)
    if end < params.t_mid:
        raise ValueError(f"duration [s]: must be at least t_mid = {params.t_mid:g} s "
                         f"(got {end:g})")
    n = int(math.floor(end / step * (1.0 + 1e-12))) + 1
    t = np.arange(n) * step
    omega = 2.0 * math.pi * np.maximum(params.f_mid + params.f_slope * (t - params.t_mid),
                                       MIN_FILTER_HZ)
    noise = rng.standard_normal(n)
    unit = normalised_filtered_noise(noise, step, omega, params.zeta_f)
    accel = _modulation(params, n, step) * unit
    if high_pass_hz is not None:
        accel = _high_pass(accel, step, positive("high_pass_hz [Hz]", high_pass_hz))
    return GroundMotion(dt=step, accel=accel, name=name,
                        source="stochastic: Rezaeian & Der Kiureghian (2008, 2010)",
                        units_read="m/s2", metadata=params.as_dict())
