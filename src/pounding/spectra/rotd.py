"""Orientation-independent spectra of two horizontal components: RotD50, RotD100 (Boore
2010) and the geometric mean of the two as-recorded spectra.

Boore, D. M. (2010), "Orientation-independent, nongeometric-mean measures of seismic
intensity from two horizontal components of motion", BSSA 100(4), 1830–1835: for each
oscillator, the displacement response to the motion along azimuth θ is
``u_θ(t) = u_1(t) cos θ + u_2(t) sin θ`` (the response is linear, so each component is
integrated once); RotDnn is the nn-th percentile over θ ∈ [0°, 180°) of ``max_t |u_θ(t)|``:
RotD50 the median, RotD100 the largest (ASCE 7-22 §11.4 / §21.2 take the maximum direction,
``RotD100``), RotD00 the smallest. ``PSA = ω² Sd`` for each.

The peak along every azimuth is located inside the steps as for a single component
(:mod:`pounding.spectra._kernel`). Units: Sd in m, PSA in m/s² (``*_g``: in g).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.ground_motion.motion import GroundMotion
from pounding.spectra.response import (
    check_damping,
    check_periods,
    compute_peaks,
    csv_text,
    default_periods,
)
from pounding.units import G
from pounding.validation import in_range

__all__ = ["CSV_COLUMNS", "MIN_ANGLE_STEP", "RotDSpectrum", "rotd_spectrum", "to_csv"]

FloatArray = NDArray[np.float64]

MIN_ANGLE_STEP = 0.01
"""Smallest azimuth increment [°]: 18,000 azimuths, a hundred times Boore's (2010) 1°; a
finer one only allocates (an increment of 1e-9° would be 1.8e11 azimuths a period)."""

CSV_COLUMNS = ("record", "measure", "damping", "period_s", "sd_m", "psv_m_s", "psa_g")
"""Columns of :func:`to_csv`; ``measure`` is H1, H2, GeoMean, RotD50 or RotD100."""


@dataclass(frozen=True, eq=False)
class RotDSpectrum:
    """Spectra of a pair of horizontal components, along every azimuth.

    Attributes
    ----------
    periods : (n_periods,) array
        Periods T [s].
    damping : (n_damping,) array
        Damping ratios ζ [-].
    angles_deg : (n_angles,) array
        Azimuths θ [°] from component 1 towards component 2, in [0, 180).
    sd_angles : (n_damping, n_periods, n_angles) array
        Peak ``|u_1 cos θ + u_2 sin θ|`` [m] along each azimuth.
    sd_components : (2, n_damping, n_periods) array
        Peak ``|u|`` [m] of each component as recorded.
    records : tuple of str
        Names of the two components.
    """

    periods: FloatArray
    damping: FloatArray
    angles_deg: FloatArray
    sd_angles: FloatArray
    sd_components: FloatArray
    records: tuple[str, str] = ("H1", "H2")

    @property
    def omega2(self) -> FloatArray:
        """``ω² = (2π/T)²`` [1/s²], shaped (n_periods,), turning Sd [m] into PSA [m/s²]."""
        return (2.0 * np.pi / self.periods) ** 2

    def rotd(self, percentile: float) -> FloatArray:
        """RotDnn of Sd [m], shaped (n_damping, n_periods): the ``percentile``-th percentile
        over the azimuths (linear interpolation between ranks; 50 is the median)."""
        p = in_range("percentile", percentile, 0.0, 100.0)
        return np.percentile(self.sd_angles, p, axis=2)

    @property
    def rotd50(self) -> FloatArray:
        """RotD50 of Sd [m]: the median over azimuths."""
        return self.rotd(50.0)

    @property
    def rotd100(self) -> FloatArray:
        """RotD100 of Sd [m]: the largest over azimuths (the maximum direction)."""
        return np.max(self.sd_angles, axis=2)

    @property
    def rotd00(self) -> FloatArray:
        """RotD00 of Sd [m]: the smallest over azimuths."""
        return np.min(self.sd_angles, axis=2)

    @property
    def geomean(self) -> FloatArray:
        """Geometric mean of the two as-recorded Sd [m]: ``sqrt(Sd_1 Sd_2)``."""
        return np.sqrt(self.sd_components[0] * self.sd_components[1])

    def psa_g(self, sd: FloatArray) -> FloatArray:
        """PSA [g] of an Sd array [m] shaped (..., n_periods): ``ω² Sd / g``."""
        return sd * self.omega2 / G

    @property
    def label(self) -> str:
        """``"<component 1> + <component 2>"``."""
        return f"{self.records[0]} + {self.records[1]}"

    def measures(self) -> dict[str, FloatArray]:
        """Sd [m] of each measure, (n_damping, n_periods): H1 and H2 (as recorded), GeoMean,
        RotD50, RotD100."""
        return {"H1": self.sd_components[0], "H2": self.sd_components[1],
                "GeoMean": self.geomean, "RotD50": self.rotd50, "RotD100": self.rotd100}

    def rows(self) -> list[tuple[str, str, float, float, float, float, float]]:
        """One row per measure, damping and period, in :data:`CSV_COLUMNS` order."""
        w = np.sqrt(self.omega2)
        return [(self.label, what, float(z), float(t), float(sd[k, j]), float(w[j] * sd[k, j]),
                 float(self.omega2[j] * sd[k, j] / G))
                for what, sd in self.measures().items()
                for k, z in enumerate(self.damping) for j, t in enumerate(self.periods)]


def to_csv(spectra: list[RotDSpectrum]) -> str:
    """CSV text of several pairs, :data:`CSV_COLUMNS`: ``measure`` H1, H2 as recorded,
    GeoMean = sqrt(H1 H2), RotD50/RotD100 (Boore 2010); damping as a fraction of critical,
    ``period_s`` [s], ``sd_m`` [m], ``psv_m_s`` [m/s], ``psa_g`` [g = 9.80665 m/s²]."""
    return csv_text(CSV_COLUMNS, [row for spec in spectra for row in spec.rows()])


def rotd_spectrum(motion1: GroundMotion, motion2: GroundMotion,
                  periods: ArrayLike | None = None, damping: ArrayLike = 0.05,
                  angle_step: float = 1.0) -> RotDSpectrum:
    """RotD50, RotD100 and the geometric mean of two horizontal components (Boore 2010).

    Parameters
    ----------
    motion1, motion2 : GroundMotion
        The two horizontal components, at right angles, with the same step and number of
        samples.
    periods : array_like, optional
        Periods [s], each > 0 (default 0.02–5 s, 100 log-spaced).
    damping : float or array_like
        Damping ratio(s), each in [0, 1) (default 0.05).
    angle_step : float
        Azimuth increment [°], from :data:`MIN_ANGLE_STEP` to 90; 180 must be a whole
        multiple of it (default 1°, as Boore 2010).

    Returns
    -------
    RotDSpectrum

    Raises
    ------
    ValueError
        If the two records differ in step or length, or for a bad period, damping ratio or
        angle step.
    """
    t = default_periods() if periods is None else check_periods(periods)
    z = check_damping(damping)
    if (motion1.npts != motion2.npts
            or not math.isclose(motion1.dt, motion2.dt, rel_tol=1e-9, abs_tol=0.0)):
        raise ValueError(f"records: the two components must have the same step and number "
                         f"of samples (got {motion1.npts} × {motion1.dt:g} s for "
                         f"{motion1.name!r}, {motion2.npts} × {motion2.dt:g} s for "
                         f"{motion2.name!r})")
    step = in_range("angle_step", angle_step, MIN_ANGLE_STEP, 90.0)
    n_angles = round(180.0 / step)
    if not math.isclose(n_angles * step, 180.0, rel_tol=1e-12):
        raise ValueError(f"angle_step: 180 must be a whole multiple of it (got {step:g})")
    angles = np.arange(n_angles, dtype=np.float64) * step
    rad = np.radians(angles)
    weights = np.vstack([np.eye(2), np.column_stack([np.cos(rad), np.sin(rad)])])
    accel = np.vstack([motion1.accel, motion2.accel])
    sd, _ = compute_peaks(accel, motion1.dt, t, z, weights, absolute=False)
    return RotDSpectrum(periods=t, damping=z, angles_deg=angles, sd_angles=sd[:, :, 2:],
                        sd_components=np.moveaxis(sd[:, :, :2], 2, 0),
                        records=(motion1.name, motion2.name))
