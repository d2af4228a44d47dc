"""Spectrum-compatible records: a real record modified in the time domain with wavelets
until its 5 % pseudo-acceleration spectrum matches a target (:func:`match_record`).

The method is the nonstationary spectral matching of Lilhanand & Tseng (1988) and
Abrahamson (1992) in the form of Al Atik, L. & Abrahamson, N. (2010), "An improved method
for nonstationary spectral matching", *Earthquake Spectra* 26(3), 601–617 (the method of
RspMatch09):

* at each matching period T_i the oscillator's response to the record peaks at t_i with
  sign p_i; the misfit is ``ΔR_i = p_i (Q_i − PSA_i)``, Q_i the target;
* a wavelet f_j is added per period, centred so that oscillator j's response to it peaks at
  t_j: the improved tapered cosine wavelet (their eqs 14, 16, 17)
  ``f_j(t) = cos(ω'_j τ) exp(−(τ/γ_j)²)``, ``τ = t − t_j + Δt_j``,
  ``ω'_j = ω_j sqrt(1 − ζ²)``, ``Δt_j = atan(sqrt(1 − ζ²)/ζ)/ω'_j``,
  ``γ_j = 1.178 f_j^−0.93`` (f_j in Hz);
* the amplitudes b solve the linearised system ``C b = ΔR``, ``C_ij`` the pseudo-acceleration
  of oscillator i at t_i under wavelet j; the record becomes ``a + Σ b_j f_j``, and the
  iteration repeats until the spectrum is within the tolerance.

The Gaussian-tapered cosine integrates to almost nothing (its Fourier transform at zero
frequency is ``γ sqrt(π) exp(−(ω'γ)²/4)``), but not exactly, and not at all where a
wavelet is cut by the record's ends. Each wavelet here is therefore corrected so that the
record's final velocity and displacement — by the trapezoidal rule twice, as
:meth:`pounding.ground_motion.GroundMotion.displacement` computes them — are unchanged to
round-off: the Gaussian envelope g and ``τ g`` are subtracted in the amounts that cancel
both (a 2×2 solve). Adding wavelets thus adds no baseline drift. See ``docs/records.md``.

Units: periods in s, accelerations in m/s² (PSA reported in g), damping as a fraction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.ground_motion.motion import GroundMotion
from pounding.spectra.design import DesignSpectrum
from pounding.units import G

__all__ = ["MatchResult", "arias_intensity", "corrected_wavelet",
           "match_record", "sdof_displacements"]

FloatArray = NDArray[np.float64]


def arias_intensity(motion: GroundMotion) -> float:
    """Arias intensity ``I_a = π/(2g) ∫ a² dt`` [m/s] (Arias 1970), the integral by the
    trapezoidal rule on the samples."""
    a2 = np.asarray(motion.accel, dtype=float) ** 2
    return float(math.pi / (2.0 * G) * motion.dt * (a2.sum() - 0.5 * (a2[0] + a2[-1])))


def _step_filters(omega: float, zeta: float, h: float) -> tuple[FloatArray, ...]:
    """The exact step of the oscillator (Nigam & Jennings 1969, via
    :func:`pounding.spectra._kernel.step_coefficients`) as a linear filter on the
    acceleration samples, and the state matrices of the first step."""
    from pounding.spectra._kernel import step_coefficients

    a11, a12, a21, a22, b11, b12, b21, b22 = step_coefficients(omega, zeta, h)
    # u_{k} = tr u_{k-1} − det u_{k-2} + c0 a_k + c1 a_{k-1} + c2 a_{k-2}: eliminate v from
    # x_{k+1} = A x_k + B0 a_k + B1 a_{k+1} (x = (u, v), B0 = (b11, b21), B1 = (b12, b22))
    num = np.array([b12, b11 - a22 * b12 + a12 * b22, -a22 * b11 + a12 * b21])
    den = np.array([1.0, -(a11 + a22), a11 * a22 - a12 * a21])
    return num, den, np.array([b11, b12])


def sdof_displacements(accel: ArrayLike, dt: float, period: float,
                       damping: float = 0.05) -> FloatArray:
    """Relative displacements u [m] at the samples of the oscillator ``ü + 2ζωu̇ + ω²u =
    −a_g``, at rest at the first sample, for each row of ``accel`` (…, n) [m/s²]: the exact
    step for an acceleration linear between samples, run as a recursive filter
    (:func:`scipy.signal.lfilter`) along the last axis."""
    from scipy.signal import lfilter

    a = np.asarray(accel, dtype=float)
    num, den, first = _step_filters(2.0 * math.pi / period, damping, dt)
    u = np.zeros_like(a)
    if a.shape[-1] < 2:
        return u
    u[..., 1] = first[0] * a[..., 0] + first[1] * a[..., 1]
    if a.shape[-1] > 2:
        # the filter's state from (u1, u0) and (a1, a0): scipy's lfiltic, for any shape
        z0 = num[1] * a[..., 1] + num[2] * a[..., 0] - den[1] * u[..., 1] - den[2] * u[..., 0]
        z1 = num[2] * a[..., 1] - den[2] * u[..., 1]
        zi = np.stack([z0, z1], axis=-1)
        u[..., 2:], _ = lfilter(num, den, a[..., 2:], axis=-1, zi=zi)
    return u


def _final_drift(x: FloatArray, dt: float) -> FloatArray:
    """Final velocity and displacement of each row of ``x`` (…, n), by the trapezoidal
    rule twice from rest (:meth:`GroundMotion.velocity`, :meth:`GroundMotion.displacement`)."""
    v = np.zeros_like(x)
    v[..., 1:] = np.cumsum(0.5 * dt * (x[..., 1:] + x[..., :-1]), axis=-1)
    d_end = np.sum(0.5 * dt * (v[..., 1:] + v[..., :-1]), axis=-1)
    return np.stack([v[..., -1], d_end], axis=-1)


def corrected_wavelet(time: FloatArray, peak_time: float, period: float,
                      damping: float = 0.05) -> FloatArray:
    """The improved tapered cosine wavelet of Al Atik & Abrahamson (2010, eqs 14, 16, 17)
    for the oscillator of ``period`` [s] whose response is to peak at ``peak_time`` [s],
    corrected to add no final velocity or displacement (module docstring).

    ``f(t) = cos(ω' τ) e^{−(τ/γ)²} − e^{−(τ/γ)²}(c0 + c1 τ/γ)``, ``τ = t − t_j + Δt_j``,
    with c0, c1 such that the trapezoidal velocity and displacement of f at the last
    sample are zero. Unit amplitude (dimensionless; scaled by the solve).
    """
    t = np.asarray(time, dtype=float)
    omega = 2.0 * math.pi / period
    root = math.sqrt(1.0 - damping * damping)
    omega_d = omega * root
    shift = math.atan2(root, damping) / omega_d          # Δt_j, eq. 14
    gamma = 1.178 * (1.0 / period) ** -0.93               # γ_j [s], eq. 17
    tau = t - peak_time + shift
    envelope = np.exp(-(tau / gamma) ** 2)
    wave = np.cos(omega_d * tau) * envelope               # eq. 16
    basis = np.stack([envelope, envelope * tau / gamma])
    dt = float(t[1] - t[0]) if t.size > 1 else 1.0
    m = _final_drift(basis, dt)                          # (2 basis, 2 drifts)
    c = np.linalg.lstsq(m.T, _final_drift(wave, dt), rcond=None)[0]
    return wave - c @ basis


@dataclass(frozen=True, eq=False)
class MatchResult:
    """A matched record and how it was reached.

    Attributes
    ----------
    motion : GroundMotion
        The matched record [m/s²].
    original : GroundMotion
        The record as given.
    scale_factor : float
        The factor the record was scaled by before matching (the geometric mean of
        target/PSA over the matching periods).
    periods : (n,) array
        The check periods [s] (``n_check`` log-spaced over the range).
    target_g, original_g, matched_g : (n,) arrays
        Target, original and matched PSA [g] at ``periods`` (exact spectra,
        :func:`pounding.spectra.response_spectrum`).
    max_misfit : float
        ``max |matched/target − 1|`` over ``periods``.
    iterations : int
        Iterations done.
    tolerance : float
        The tolerance asked.
    period_range : (float, float)
        The matched range [s].
    damping : float
        Damping ratio of the spectra.
    """

    motion: GroundMotion
    original: GroundMotion
    scale_factor: float
    periods: FloatArray
    target_g: FloatArray
    original_g: FloatArray
    matched_g: FloatArray
    max_misfit: float
    iterations: int
    tolerance: float
    period_range: tuple[float, float]
    damping: float

    @property
    def converged(self) -> bool:
        """Whether ``max_misfit <= tolerance``."""
        return self.max_misfit <= self.tolerance

    def measures(self) -> dict[str, tuple[float, float]]:
        """(original, matched) of PGA [g], PGV [m/s], PGD [m], Arias intensity [m/s], final
        velocity [m/s] and final displacement [m] (trapezoidal rule, no baseline
        correction)."""
        out: dict[str, tuple[float, float]] = {}
        for key, fn in (("PGA [g]", lambda m: m.pga_g), ("PGV [m/s]", lambda m: m.pgv),
                        ("PGD [m]", lambda m: m.pgd),
                        ("Arias intensity [m/s]", arias_intensity),
                        ("final velocity [m/s]", lambda m: float(m.velocity()[-1])),
                        ("final displacement [m]", lambda m: float(m.displacement()[-1]))):
            out[key] = (float(fn(self.original)), float(fn(self.motion)))
        return out


def _check_inputs(period_range: tuple[float, float], damping: float, tolerance: float,
                  n_periods: int, n_check: int, iterations: int) -> tuple[float, float]:
    from pounding.spectra.response import check_damping, check_periods

    try:
        lo, hi = (float(x) for x in period_range)
    except (TypeError, ValueError):
        raise ValueError(f"range: give two periods LO,HI in s (got {period_range!r})") from None
    check_periods([lo, hi], "range")
    if not hi > lo:
        raise ValueError(f"range: HI must be larger than LO (got {lo:g},{hi:g})")
    check_damping([damping], "damping")
    if not (math.isfinite(tolerance) and 0.0 < tolerance < 1.0):
        raise ValueError(f"tolerance: a fraction in (0, 1), 0.1 = ±10 % (got {tolerance!r})")
    for name, n, low in (("periods", n_periods, 2), ("check", n_check, 2),
                         ("iterations", iterations, 1)):
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not \
                low <= int(n) <= 10_000:
            raise ValueError(f"{name}: an integer from {low} to 10000 (got {n!r})")
    return lo, hi


def match_record(motion: GroundMotion, target: DesignSpectrum,
                 period_range: tuple[float, float] = (0.05, 4.0), *, damping: float = 0.05,
                 tolerance: float = 0.10, n_periods: int = 60, n_check: int = 200,
                 iterations: int = 30, gain: float = 1.0,
                 regularisation: float = 0.1) -> MatchResult:
    """Modify ``motion`` with wavelets until its PSA is within ``tolerance`` of ``target``
    at ``n_check`` log-spaced periods over ``period_range`` (Al Atik & Abrahamson 2010;
    module docstring).

    Parameters
    ----------
    motion : GroundMotion
        The seed record [m/s²].
    target : DesignSpectrum
        The target spectrum (its table must cover the range).
    period_range : (float, float)
        Periods matched [s], ``LO < HI`` (default 0.05–4 s).
    damping : float
        Damping ratio of the spectra (default 0.05; the target's own damping).
    tolerance : float
        Largest ``|PSA/target − 1|`` accepted over the check periods (default 0.10).
    n_periods : int
        Matching periods, log-spaced over the range (one wavelet each per iteration).
    n_check : int
        Periods the result is checked at (log-spaced over the range, both ends included).
    iterations : int
        Most iterations.
    gain : float
        Fraction of the linearised correction applied each iteration (0 < gain ≤ 1).

    Returns
    -------
    MatchResult
        Whether or not it converged (:attr:`MatchResult.converged`).

    Raises
    ------
    ValueError
        One line naming the bad argument, or a target that does not cover the range.
    """
    from pounding.spectra.response import response_spectrum
    from pounding.spectra.scaling import _target_on

    lo, hi = _check_inputs(period_range, damping, tolerance, n_periods, n_check, iterations)
    if not (math.isfinite(gain) and 0.0 < gain <= 1.0):
        raise ValueError(f"gain: a fraction in (0, 1] (got {gain!r})")
    if motion.npts < 8:
        raise ValueError(f"record: {motion.name!r} has {motion.npts} samples; matching needs "
                         "a real record")
    if hi > 0.5 * motion.duration:
        raise ValueError(f"range: HI = {hi:g} s is more than half the record's duration "
                         f"({motion.duration:g} s); a wavelet of that period does not fit")
    base = np.geomspace(lo, hi, int(n_periods))
    ratio = (hi / lo) ** (1.0 / (int(n_periods) - 1))
    t_match = base
    t_check = np.geomspace(lo, hi, int(n_check))
    q_match = _target_on(target, t_match) * G
    q_check = _target_on(target, t_check) * G

    def psa(accel: FloatArray, periods: FloatArray) -> FloatArray:
        m = GroundMotion(motion.dt, accel, name=motion.name)
        return response_spectrum(m, periods, damping).psa[0]

    original = np.asarray(motion.accel, dtype=float)
    original_check = psa(original, t_check)
    scale = float(np.exp(np.mean(np.log(q_match / psa(original, t_match)))))
    accel = original * scale
    time = motion.time
    omegas2 = (2.0 * math.pi / t_match) ** 2

    def misfit(a: FloatArray) -> tuple[float, float, FloatArray]:
        s = psa(a, t_check)
        return (float(np.max(np.abs(s / q_check - 1.0))),
                float(np.sqrt(np.mean(np.log(s / q_check) ** 2))), s)

    worst, rms, matched = misfit(accel)
    best = (worst, accel, matched)  # the closest record met: the iteration is not monotone
    done = 0
    while worst > tolerance and done < iterations:
        done += 1
        if done > 1:  # shift the grid by a fraction of its spacing each iteration, so the
            # periods between matching periods are matched in their turn
            offset = (done * 0.618034) % 1.0 - 0.5
            t_match = np.clip(base * ratio ** offset, lo, hi)
            q_match = _target_on(target, t_match) * G
            omegas2 = (2.0 * math.pi / t_match) ** 2
        u = np.stack([sdof_displacements(accel, motion.dt, p, damping) for p in t_match])
        peak = np.argmax(np.abs(u), axis=1)
        sign = np.sign(u[np.arange(t_match.size), peak])
        exact = psa(accel, t_match)
        delta = sign * (q_match - exact)
        wavelets = np.stack([corrected_wavelet(time, time[k], p, damping)
                             for k, p in zip(peak, t_match, strict=True)])
        c = np.empty((t_match.size, t_match.size))
        for i, p in enumerate(t_match):
            c[i] = omegas2[i] * sdof_displacements(wavelets, motion.dt, p, damping)[:, peak[i]]
        # damped least squares (Tikhonov): wavelets of neighbouring periods whose
        # oscillators peak at nearly the same time make C nearly singular
        ridge = regularisation * float(np.mean(np.abs(np.diag(c))))
        b = np.linalg.solve(c.T @ c + ridge ** 2 * np.eye(c.shape[1]), c.T @ delta)
        step = gain
        for _ in range(6):  # backtrack: take a smaller step while it makes matters worse
            trial = accel + step * (b @ wavelets)
            trial_worst, trial_rms, trial_matched = misfit(trial)
            if trial_rms < rms:
                break
            step *= 0.5
        accel, worst, rms, matched = trial, trial_worst, trial_rms, trial_matched
        if worst < best[0]:
            best = (worst, accel, matched)
    worst, accel, matched = best

    result = MatchResult(
        motion=GroundMotion(motion.dt, accel, name=f"{motion.name}-matched",
                            source=motion.source, units_read="m/s2",
                            metadata={"matched_to": target.name}),
        original=motion, scale_factor=scale, periods=t_check, target_g=q_check / G,
        original_g=original_check / G, matched_g=matched / G, max_misfit=worst,
        iterations=done, tolerance=float(tolerance), period_range=(lo, hi),
        damping=float(damping))
    return result
