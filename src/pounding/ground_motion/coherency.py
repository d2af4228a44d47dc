"""Incoherent ground motion: motions at nearby stations simulated from a recorded one with a
coherency model, seeded and reproducible.

Two stations ``ξ`` apart do not feel the same motion: beyond the delay of wave passage the
waves scatter and arrive from an extended source, and the motions lose coherence with
distance and frequency. The *coherency* of the motions at stations j and k,

    γ_jk(ω) = S_jk(ω) / √(S_jj(ω) S_kk(ω)),

is modelled as a real, decaying *lagged coherency* ``|γ|(ξ, ω)`` times the phase of wave
passage ``e^{−iω (x_j − x_k)/V}`` (Der Kiureghian 1996, "A coherency model for spatially
varying ground motions", *Earthq. Eng. Struct. Dyn.* 25(1):99–111). Two lagged coherency
models:

* Harichandran & Vanmarcke (1986), "Stochastic variation of earthquake ground motion in space
  and time", *J. Eng. Mech.* 112(2):154–174, fitted to event 20 of the SMART-1 array::

      |γ|(ξ, f) = A e^{−2ξ(1 − A + αA)/(α θ(f))} + (1 − A) e^{−2ξ(1 − A + αA)/θ(f)},
      θ(f) = k [1 + (f/f0)^b]^{−1/2},

  ``A = 0.736``, ``α = 0.147``, ``k = 5210 m``, ``f0 = 1.09 Hz``, ``b = 2.78``;
* Luco & Wong (1986), "Response of a rigid foundation to a spatially random ground motion",
  *Earthq. Eng. Struct. Dyn.* 14(6):891–908: ``|γ|(ξ, ω) = e^{−(β ω ξ)²}``, ``β = α/V_s``
  [s/m] (α the incoherence parameter, V_s the shear-wave velocity; 2e-4 to 3e-4 s/m for
  common sites, 2.5e-4 by default).

**Conditional simulation** (Vanmarcke & Fenton 1991, "Conditioned simulation of local fields
of earthquake ground motion", *Struct. Saf.* 10:247–264; Konakli & Der Kiureghian 2012,
"Simulation of spatially varying ground motions including incoherence, wave-passage and
differential site-response effects", *Earthq. Eng. Struct. Dyn.* 41:495–513). The record at
station 0 is kept as it is; at every frequency of its discrete Fourier transform ``A_0`` the
other stations' coefficients are drawn from their Gaussian distribution given ``A_0``,

    A_r = γ_r0 A_0 + √S L z,   L Lᴴ = Γ_rr − γ_r0 γ_r0ᴴ,   S = |A_0|²,

``Γ_rr`` the coherency matrix of the simulated stations, ``z`` independent standard complex
normal numbers. So, over many seeds, every station has the record's Fourier amplitudes in
the mean square (``E|A_r|² = S``) and every pair the target coherency (``E[A_r A_k*] =
γ_rk S``), so the same energy (Σ a² dt) as the record in the mean; at distance 0 without
wave passage the simulated motion *is* the record. The record is padded with zeros first —
before it by the longest advance of a station upstream of the recorded one, after it by the
longest delay downstream — so no arrival wraps around the transform; every motion is on
that one time axis (the recorded station's starts with the leading zeros).

The simulation is stationary: the incoherent part is spread over the whole (padded) record
rather than following the record's envelope in time (Konakli & Der Kiureghian 2012 treat
that non-stationarity with time windows; not done here), and the motions are not
baseline-corrected.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.ground_motion.motion import GroundMotion
from pounding.ground_motion.spatial import SpatialMotion
from pounding.validation import choice, finite

__all__ = ["COHERENCY_MODELS", "coherent_motions", "harichandran_vanmarcke", "luco_wong",
           "lagged_coherency"]

HV_SMART1_EVENT20 = {"A": 0.736, "alpha": 0.147, "k": 5210.0, "f0": 1.09, "b": 2.78}
"""Harichandran & Vanmarcke's constants for event 20 of SMART-1 (k [m], f0 [Hz])."""

LUCO_WONG_BETA = 2.5e-4
"""Luco & Wong's ``α/V_s`` [s/m] by default."""

COHERENCY_MODELS = ("harichandran-vanmarcke", "luco-wong")

ROUNDING = 1e-12
"""Eigenvalues of a conditional coherency matrix (entries of order 1) below this are zero."""


def harichandran_vanmarcke(distance: ArrayLike, frequency: ArrayLike,
                           A: float = 0.736, alpha: float = 0.147, k: float = 5210.0,
                           f0: float = 1.09, b: float = 2.78) -> NDArray[np.float64]:
    """Harichandran & Vanmarcke's lagged coherency at ``distance`` [m] and ``frequency``
    [Hz] (module docstring; broadcast).

    Examples
    --------
    >>> float(harichandran_vanmarcke(0.0, 5.0))
    1.0
    >>> round(float(harichandran_vanmarcke(100.0, 1.09)), 4)
    0.9002
    """
    xi = np.abs(np.asarray(distance, dtype=float))
    f = np.abs(np.asarray(frequency, dtype=float))
    theta = k / np.sqrt(1.0 + (f / f0) ** b)
    c = 2.0 * xi * (1.0 - A + alpha * A)
    return np.asarray(A * np.exp(-c / (alpha * theta)) + (1.0 - A) * np.exp(-c / theta))


def luco_wong(distance: ArrayLike, omega: ArrayLike,
              beta: float = LUCO_WONG_BETA) -> NDArray[np.float64]:
    """Luco & Wong's lagged coherency ``e^{−(β ω ξ)²}`` at ``distance`` [m] and circular
    frequency ``omega`` [rad/s], ``β = α/V_s`` [s/m] (broadcast).

    Examples
    --------
    >>> round(float(luco_wong(100.0, 2 * 3.141592653589793 * 2.0)), 4)
    0.906
    """
    xi = np.asarray(distance, dtype=float)
    w = np.asarray(omega, dtype=float)
    return np.asarray(np.exp(-(beta * w * xi) ** 2))


def lagged_coherency(model: str, distance: ArrayLike, omega: ArrayLike,
                     **params: float) -> NDArray[np.float64]:
    """``|γ|`` of coherency model ``model`` (:data:`COHERENCY_MODELS`) at ``distance`` [m]
    and circular frequency ``omega`` [rad/s]; ``params`` its constants."""
    name = choice("coherency", model, COHERENCY_MODELS)
    if name == "luco-wong":
        return luco_wong(distance, omega, **params)
    return harichandran_vanmarcke(distance, np.asarray(omega) / (2.0 * np.pi), **params)


def coherent_motions(record: GroundMotion, positions: Sequence[float], *,
                     coherency: str = "harichandran-vanmarcke",
                     apparent_velocity: float | None = None, recorded_at: int = 0,
                     seed: int = 0, **params: float) -> SpatialMotion:
    """Motions at stations ``positions`` [m] along the row, one a building, the record at
    station ``recorded_at`` and the others simulated from it (module docstring) with lagged
    coherency ``coherency`` (its constants ``params``) and, if ``apparent_velocity`` [m/s]
    is given, the phase of waves travelling along the row at that velocity (positive:
    toward +x). ``seed`` makes the simulation reproducible.

    Returns
    -------
    SpatialMotion
        Every motion on one time axis: the record padded with zeros before it by the
        longest advance of a station upstream of the recorded one and after it by the
        longest delay downstream (so no arrival wraps around the discrete Fourier
        transform, whose lines the statistics of the module docstring hold for), and each
        station's delay [s] on that axis (the recorded station's: its leading zeros).

    Raises
    ------
    ValueError
        Bad positions, model or velocity (one line naming it).
    """
    x = np.asarray(positions, dtype=float)
    if x.ndim != 1 or x.size < 1 or not np.all(np.isfinite(x)):
        raise ValueError(f"positions [m] must be finite numbers, one a building (got "
                         f"{positions!r})")
    if not 0 <= recorded_at < x.size:
        raise ValueError(f"recorded_at must be a building index in [0, {x.size - 1}] (got "
                         f"{recorded_at})")
    choice("coherency", coherency, COHERENCY_MODELS)
    slowness = 0.0
    if apparent_velocity is not None:
        v = finite("apparent_velocity [m/s]", apparent_velocity)
        if v == 0.0:
            raise ValueError("apparent_velocity [m/s] must not be 0 (waves that never arrive)")
        slowness = 1.0 / v
    # each station's arrival after the recorded one's [s] (negative: upstream, earlier)
    tau = (x - x[recorded_at]) * slowness
    front = int(np.ceil(max(0.0, -float(tau.min())) / record.dt - 1e-9))
    back = int(np.ceil(max(0.0, float(tau.max())) / record.dt - 1e-9))
    n = front + record.npts + back
    a0 = np.concatenate([np.zeros(front), record.accel, np.zeros(back)])
    spec0 = np.fft.rfft(a0)
    omega = 2.0 * np.pi * np.fft.rfftfreq(n, record.dt)
    others = [j for j in range(x.size) if j != recorded_at]
    m = len(others)
    sims = np.zeros((m, spec0.size), dtype=complex)
    rng = np.random.default_rng(seed)
    if m:
        z = (rng.standard_normal((spec0.size, m)) + 1j * rng.standard_normal((spec0.size, m))
             ) / np.sqrt(2.0)

        def gamma(j: int, k: int) -> NDArray[np.complex128]:
            mag = lagged_coherency(coherency, x[j] - x[k], omega, **params)
            return mag * np.exp(-1j * omega * (x[j] - x[k]) * slowness)

        g_r0 = np.array([gamma(j, recorded_at) for j in others]).T  # (F, m)
        G_rr = np.moveaxis(np.array([[gamma(j, k) for k in others] for j in others]), -1, 0)
        cov = G_rr - g_r0[:, :, None] * g_r0[:, None, :].conj()  # (F, m, m)
        # (positive semi-definite up to rounding: its square root by eigenvalues, those
        # within rounding of zero taken as zero — a fully coherent station is then exact)
        w, V = np.linalg.eigh(0.5 * (cov + np.conj(np.swapaxes(cov, 1, 2))))
        L = V * np.sqrt(np.where(w > ROUNDING, w, 0.0))[:, None, :]
        sims = (g_r0 * spec0[:, None] + np.abs(spec0)[:, None]
                * np.einsum("fij,fj->fi", L, z)).T  # (m, F)
        # (the mean and the Nyquist lines of a real signal are real)
        sims[:, 0] = sims[:, 0].real
        if n % 2 == 0:
            sims[:, -1] = sims[:, -1].real
    records: list[GroundMotion] = []
    k = 0
    for j in range(x.size):
        if j == recorded_at:
            accel = a0
            name = record.name
        else:
            accel = np.fft.irfft(sims[k], n)
            k += 1
            name = f"{record.name} simulated at {x[j]:g} m"
        records.append(GroundMotion(record.dt, accel, name, record.source, "m/s2",
                                    record.metadata))
    how = (f"{coherency} coherency"
           + (f", apparent velocity {apparent_velocity:g} m/s" if apparent_velocity else "")
           + f", conditioned on the record at {x[recorded_at]:g} m, seed {seed}")
    return SpatialMotion(records, description=how, delays=front * record.dt + tau)
