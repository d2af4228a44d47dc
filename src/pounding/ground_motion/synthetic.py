"""Closed-form ground accelerations for tests and checks, each with an exact velocity:
:func:`harmonic` (a sinusoid), :func:`sine_pulse` (one full sine cycle) and :func:`ricker`
(a Ricker wavelet, the second derivative of a Gaussian). See ``docs/ground_motion.md``.
"""

from __future__ import annotations

import math

import numpy as np

from pounding.ground_motion.motion import FloatArray, GroundMotion
from pounding.validation import finite, non_negative, positive

__all__ = ["harmonic", "ricker", "sine_pulse"]


def _samples(duration: float, dt: float) -> FloatArray:
    d = non_negative("duration [s]", duration)
    step = positive("dt [s]", dt)
    n = int(math.floor(d / step * (1.0 + 1e-12) + 1e-9)) + 1
    return np.arange(n, dtype=np.float64) * step


def harmonic(amplitude: float, frequency_hz: float, duration: float, dt: float,
             phase: float = 0.0) -> GroundMotion:
    """A sinusoidal ground acceleration ``a(t) = A sin(2π f t + φ)``.

    Parameters
    ----------
    amplitude : float
        ``A`` [m/s²].
    frequency_hz : float
        ``f`` [Hz], > 0.
    duration : float
        Time of the last sample [s] (samples at ``0, dt, ...`` up to ``duration``).
    dt : float
        Time step [s].
    phase : float
        ``φ`` [rad].

    Notes
    -----
    For ``φ = 0`` the exact velocity is ``v(t) = A/ω (1 − cos ωt)`` with ``ω = 2πf``, so the
    PGV over at least half a period is ``2A/ω`` [m/s].
    """
    a = finite("amplitude [m/s²]", amplitude)
    f = positive("frequency_hz [Hz]", frequency_hz)
    ph = finite("phase [rad]", phase)
    t = _samples(duration, dt)
    return GroundMotion(dt=float(dt), accel=a * np.sin(2.0 * np.pi * f * t + ph),
                        name=f"harmonic {f:g} Hz", source="synthetic: harmonic",
                        units_read="m/s2",
                        metadata={"amplitude": a, "frequency_hz": f, "phase": ph})


def sine_pulse(amplitude: float, period: float, dt: float,
               duration: float | None = None) -> GroundMotion:
    """One full sine cycle ``a(t) = A sin(2π t / T)`` for ``0 ≤ t ≤ T``, then rest.

    Parameters
    ----------
    amplitude : float
        ``A`` [m/s²].
    period : float
        ``T`` [s], > 0.
    dt : float
        Time step [s].
    duration : float, optional
        Time of the last sample [s]; default ``T``.

    Notes
    -----
    Exact velocity ``v(t) = A T/(2π) (1 − cos(2πt/T))``: PGV ``A T / π`` at ``t = T/2``,
    and ``v = 0`` after the pulse; the displacement ends at ``A T² / (2π)``.
    """
    a = finite("amplitude [m/s²]", amplitude)
    T = positive("period [s]", period)
    t = _samples(T if duration is None else duration, dt)
    acc = np.where(t <= T * (1.0 + 1e-12), a * np.sin(2.0 * np.pi * t / T), 0.0)
    return GroundMotion(dt=float(dt), accel=acc, name=f"sine pulse T={T:g} s",
                        source="synthetic: sine pulse", units_read="m/s2",
                        metadata={"amplitude": a, "period": T})


def ricker(amplitude: float, peak_frequency_hz: float, dt: float, duration: float,
           t0: float | None = None) -> GroundMotion:
    """A Ricker wavelet ``a(t) = A (1 − 2τ²π²f²) exp(−τ²π²f²)``, ``τ = t − t0``.

    Parameters
    ----------
    amplitude : float
        ``A``, the peak acceleration [m/s²] (at ``t = t0``).
    peak_frequency_hz : float
        ``f`` [Hz], > 0.
    dt : float
        Time step [s].
    duration : float
        Time of the last sample [s].
    t0 : float, optional
        Centre [s]; default ``1.5 / f``.

    Notes
    -----
    Exact velocity ``v(t) = A [τ e^{−π²f²τ²} − τ₀ e^{−π²f²τ₀²}]`` with ``τ₀ = −t0``; when
    the start is far in the tail, PGV ``= A e^{−1/2} / (√2 π f)`` at ``τ = ±1/(√2 π f)``.
    """
    a = finite("amplitude [m/s²]", amplitude)
    f = positive("peak_frequency_hz [Hz]", peak_frequency_hz)
    centre = 1.5 / f if t0 is None else finite("t0 [s]", t0)
    t = _samples(duration, dt)
    x = (np.pi * f * (t - centre)) ** 2
    return GroundMotion(dt=float(dt), accel=a * (1.0 - 2.0 * x) * np.exp(-x),
                        name=f"Ricker {f:g} Hz", source="synthetic: Ricker wavelet",
                        units_read="m/s2",
                        metadata={"amplitude": a, "peak_frequency_hz": f, "t0": centre})
