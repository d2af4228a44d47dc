"""RotD50, RotD100 and the geometric mean (``pounding.spectra.rotd``; Boore 2010, BSSA
100(4)) checked against closed forms in the azimuth and against a brute-force computation
that rotates the records and runs the plain reference on each azimuth."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pounding.ground_motion import GroundMotion, el_centro
from pounding.spectra.reference import reference_peaks
from pounding.spectra.response import response_spectrum
from pounding.spectra.rotd import rotd_spectrum
from pounding.units import G

PERIODS = [0.1, 0.4, 1.0, 3.0]


def _pair(duration: float | None = None) -> tuple[GroundMotion, GroundMotion]:
    """El Centro and, as a second component, El Centro played backwards (a different
    signal with the same step and length)."""
    gm = el_centro() if duration is None else el_centro().trimmed(duration)
    back = dataclasses.replace(gm, accel=gm.accel[::-1].copy(), name="El Centro reversed")
    return gm, back


def test_ordering_and_components() -> None:
    h1, h2 = _pair()
    r = rotd_spectrum(h1, h2, PERIODS, [0.02, 0.05])
    one = response_spectrum(h1, PERIODS, [0.02, 0.05])
    two = response_spectrum(h2, PERIODS, [0.02, 0.05])
    np.testing.assert_allclose(r.sd_components[0], one.sd, rtol=1e-12)
    np.testing.assert_allclose(r.sd_components[1], two.sd, rtol=1e-12)
    # azimuths 0° and 90° are the components themselves
    np.testing.assert_allclose(r.sd_angles[:, :, 0], one.sd, rtol=1e-12)
    np.testing.assert_allclose(r.sd_angles[:, :, 90], two.sd, rtol=1e-12)
    assert np.all(r.rotd100 >= np.maximum(one.sd, two.sd) * (1 - 1e-12))
    assert np.all((r.rotd00 <= r.rotd50) & (r.rotd50 <= r.rotd100))
    np.testing.assert_allclose(r.geomean, np.sqrt(one.sd * two.sd), rtol=1e-12)
    np.testing.assert_allclose(r.psa_g(r.rotd50), r.rotd50 * (2 * np.pi / r.periods) ** 2 / G)
    assert r.angles_deg.size == 180 and r.angles_deg[-1] == 179


@pytest.mark.parametrize("alpha", [1.0, 0.4, -2.5, 0.0])
def test_a_component_and_a_scaled_copy(alpha: float) -> None:
    """a_2 = α a_1 gives u_θ = (cos θ + α sin θ) u_1, so along θ the peak is
    |cos θ + α sin θ| Sd_1: RotD100 = sqrt(1 + α²) Sd_1 where atan α is on the grid (α = 1:
    √2 at 45°), and RotD50 = Sd_1 times the median of |cos θ + α sin θ| over the grid."""
    gm = el_centro().trimmed(15.0)
    copy = dataclasses.replace(gm, accel=alpha * gm.accel)
    r = rotd_spectrum(gm, copy, PERIODS, 0.05)
    sd1 = response_spectrum(gm, PERIODS, 0.05).sd[0]
    theta = np.radians(np.arange(180.0))
    factor = np.abs(np.cos(theta) + alpha * np.sin(theta))
    np.testing.assert_allclose(r.sd_angles[0], np.outer(sd1, factor), rtol=1e-11, atol=1e-15)
    np.testing.assert_allclose(r.rotd50[0], np.median(factor) * sd1, rtol=1e-11)
    np.testing.assert_allclose(r.rotd100[0], factor.max() * sd1, rtol=1e-11)
    if alpha == 1.0:
        np.testing.assert_allclose(r.rotd100[0], np.sqrt(2) * sd1, rtol=1e-11)
    if alpha == 0.0:  # a_2 = 0: |cos θ| Sd_1; |cos θ| at 0..179° has the median cos 45°
        np.testing.assert_allclose(r.rotd50[0], np.cos(np.radians(45.0)) * sd1, rtol=1e-11)


def test_against_rotated_records_and_the_plain_reference() -> None:
    """Brute force on 4 s of the pair: rotate the records, a_θ = a_1 cos θ + a_2 sin θ, and
    run the plain reference (matrix exponentials, Hermite maxima) on each azimuth."""
    h1, h2 = _pair(4.0)
    step = 15.0
    r = rotd_spectrum(h1, h2, PERIODS, [0.05], angle_step=step)
    for k, theta in enumerate(np.radians(r.angles_deg)):
        rotated = np.cos(theta) * h1.accel + np.sin(theta) * h2.accel
        sd, _ = reference_peaks(rotated, h1.dt, PERIODS, [0.05])
        np.testing.assert_allclose(r.sd_angles[0, :, k], sd[0], rtol=2e-8)


@pytest.mark.parametrize("change, message", [
    (lambda gm: gm.trimmed(10.0), "records: the two components must have the same step and "
                                  "number of samples (got 4000 × 0.01 s for"),
    (lambda gm: dataclasses.replace(gm, dt=0.02), "4000 × 0.02 s"),
])
def test_components_must_match(change, message) -> None:  # noqa: ANN001
    gm = el_centro()
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace("×", "×")):
        rotd_spectrum(gm, change(gm), [1.0])


def test_bad_angle_step() -> None:
    gm = el_centro().trimmed(1.0)
    with pytest.raises(ValueError, match=r"angle_step: 180 must be a whole multiple of it "
                                         r"\(got 7\)"):
        rotd_spectrum(gm, gm, [1.0], angle_step=7.0)
    with pytest.raises(ValueError, match=r"angle_step must be in \[0\.01, 90\] \(got 0\)"):
        rotd_spectrum(gm, gm, [1.0], angle_step=0.0)
    # a whole divisor of 180 that would be 1.8e11 azimuths a period: refused, not allocated
    with pytest.raises(ValueError, match=r"angle_step must be in \[0\.01, 90\] \(got 1e-09\)"):
        rotd_spectrum(gm, gm, [1.0], angle_step=1e-9)
