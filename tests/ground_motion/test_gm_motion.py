"""GroundMotion: validation, peaks and integrals against closed forms, scaling, sampling."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.ground_motion import GroundMotion, el_centro, harmonic, ricker, sine_pulse
from pounding.units import G


# ------------------------------------------------------------------- validation
@pytest.mark.parametrize(("kwargs", "message"), [
    ({"dt": 0.0, "accel": [1.0]}, r"dt must be > 0 \(got 0\)"),
    ({"dt": -0.01, "accel": [1.0]}, r"dt must be > 0 \(got -0\.01\)"),
    ({"dt": float("nan"), "accel": [1.0]}, r"dt must be finite"),
    ({"dt": 0.01, "accel": []}, r"accel must hold at least one value"),
    ({"dt": 0.01, "accel": [0.0, float("nan")]}, r"accel must be finite \(got nan at index 1\)"),
    ({"dt": 0.01, "accel": [0.0, float("inf")]}, r"accel must be finite \(got inf at index 1\)"),
    ({"dt": 0.01, "accel": [[0.0, 1.0]]}, r"accel must be one-dimensional"),
    ({"dt": 0.01, "accel": ["a"]}, r"accel must be an array of numbers"),
])
def test_invalid_motion_names_field(kwargs: dict, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        GroundMotion(name="bad", **kwargs)


def test_motion_is_immutable() -> None:
    gm = GroundMotion(dt=0.01, accel=[1.0, 2.0])
    with pytest.raises(ValueError):
        gm.accel[0] = 5.0
    with pytest.raises(AttributeError):
        gm.dt = 0.02  # type: ignore[misc]
    assert gm.accel.dtype == np.float64


def test_time_npts_duration() -> None:
    gm = GroundMotion(dt=0.02, accel=np.zeros(51))
    assert gm.npts == 51
    assert gm.duration == pytest.approx(1.0)
    np.testing.assert_allclose(gm.time[[0, 1, -1]], [0.0, 0.02, 1.0])


# ------------------------------------------------------------------- closed forms
def test_harmonic_pga_pgv_velocity_closed_form() -> None:
    A, f = 2.0, 1.0  # m/s², Hz
    w = 2.0 * math.pi * f
    gm = harmonic(A, f, duration=2.0, dt=0.001)
    assert gm.npts == 2001
    assert gm.pga == pytest.approx(A, rel=1e-12)  # a sample falls on t = 0.25 s
    assert gm.pga_g == pytest.approx(A / G, rel=1e-12)
    # v(t) = A/ω (1 − cos ωt); PGV = 2A/ω at t = 0.5 s; trapezoid error ~ (ω dt)²/12
    np.testing.assert_allclose(gm.velocity(), A / w * (1.0 - np.cos(w * gm.time)),
                               atol=1e-5 * A / w)
    assert gm.pgv == pytest.approx(2.0 * A / w, rel=1e-5)
    # u(t) = A/ω (t − sin(ωt)/ω): grows linearly, no baseline correction
    np.testing.assert_allclose(gm.displacement(),
                               A / w * (gm.time - np.sin(w * gm.time) / w), atol=1e-5)
    assert gm.pgd == pytest.approx(A / w * 2.0, rel=1e-4)


def test_sine_pulse_closed_form() -> None:
    A, T = 3.0, 0.5
    gm = sine_pulse(A, T, dt=0.0005, duration=1.5)
    assert gm.duration == pytest.approx(1.5)
    assert gm.accel_at(1.0) == 0.0
    assert gm.pgv == pytest.approx(A * T / math.pi, rel=1e-5)
    v = gm.velocity()
    assert abs(v[-1]) < 1e-6 * A * T  # the pulse returns the ground to rest
    assert gm.displacement()[-1] == pytest.approx(A * T**2 / (2.0 * math.pi), rel=1e-4)
    assert sine_pulse(A, T, dt=0.01).duration == pytest.approx(T)


def test_ricker_closed_form() -> None:
    A, f = 1.5, 2.0
    gm = ricker(A, f, dt=0.0005, duration=2.0)
    t0 = 1.5 / f
    a = (math.pi * f) ** 2
    tau = gm.time - t0
    exact_v = A * (tau * np.exp(-a * tau**2) + t0 * math.exp(-a * t0**2))
    np.testing.assert_allclose(gm.velocity(), exact_v, atol=1e-6)
    assert gm.pga == pytest.approx(A, rel=1e-12)  # a sample falls on t0
    assert gm.pgv == pytest.approx(A * math.exp(-0.5) / (math.sqrt(2.0) * math.pi * f),
                                   rel=1e-3)


# ------------------------------------------------------------------- scaling
def test_scaled_and_scaled_to_pga() -> None:
    gm = el_centro()
    s = gm.scaled_to_pga(0.5)
    assert s.pga_g == pytest.approx(0.5, rel=1e-12)
    assert s.pgv == pytest.approx(gm.pgv * 0.5 / gm.pga_g, rel=1e-12)
    assert s.dt == gm.dt and s.name == gm.name
    assert s.metadata["scale_factor"] == pytest.approx(0.5 / gm.pga_g)
    assert gm.pga_g == pytest.approx(0.3129, rel=1e-3)  # original untouched
    twice = gm.scaled(2.0).scaled(1.5)
    np.testing.assert_allclose(twice.accel, 3.0 * gm.accel)
    assert twice.metadata["scale_factor"] == pytest.approx(3.0)
    with pytest.raises(ValueError, match=r"pga_g must be > 0 \(got -1\)"):
        gm.scaled_to_pga(-1.0)
    with pytest.raises(ValueError, match="all zeros"):
        GroundMotion(dt=0.01, accel=[0.0, 0.0]).scaled_to_pga(0.3)
    with pytest.raises(ValueError, match="scale factor must be finite"):
        gm.scaled(float("inf"))


# ------------------------------------------------------------------- sampling
def test_accel_at_interpolates_and_is_zero_outside() -> None:
    gm = GroundMotion(dt=0.1, accel=[0.0, 1.0, -1.0])
    assert gm.accel_at(0.05) == pytest.approx(0.5)
    assert gm.accel_at(0.15) == pytest.approx(0.0)
    assert gm.accel_at(0.175) == pytest.approx(-0.5)
    assert gm.accel_at(0.2) == pytest.approx(-1.0)
    assert gm.accel_at(0.2001) == 0.0  # after the end
    assert gm.accel_at(-0.01) == 0.0
    out = gm.accel_at(np.array([[0.1, 0.3]]))
    assert isinstance(out, np.ndarray) and out.shape == (1, 2)
    np.testing.assert_allclose(out, [[1.0, 0.0]])
    assert isinstance(gm.accel_at(0.1), float)


def test_trimmed() -> None:
    gm = harmonic(1.0, 1.0, duration=2.0, dt=0.01)
    short = gm.trimmed(1.0)
    assert short.npts == 101
    assert short.duration == pytest.approx(1.0)
    np.testing.assert_array_equal(short.accel, gm.accel[:101])
    assert gm.trimmed(0.0).npts == 1
    assert gm.trimmed(5.0).npts == gm.npts
    with pytest.raises(ValueError, match="t_end must be >= 0"):
        gm.trimmed(-1.0)


def test_synthetic_inputs_validate() -> None:
    with pytest.raises(ValueError, match=r"frequency_hz \[Hz\] must be > 0"):
        harmonic(1.0, 0.0, 1.0, 0.01)
    with pytest.raises(ValueError, match=r"dt \[s\] must be > 0"):
        sine_pulse(1.0, 0.5, dt=0.0)
    with pytest.raises(ValueError, match=r"period \[s\] must be > 0"):
        sine_pulse(1.0, -0.5, dt=0.01)


def test_arias_time_is_the_husid_curves_closed_form():
    """A constant acceleration builds Arias intensity linearly (t_f = f T); a ramp a = t as
    t³ (t_f = f^(1/3) T); a record of zeros has none (0)."""
    dt, end = 0.001, 20.0
    t = np.arange(0.0, end + dt / 2, dt)
    flat = GroundMotion(dt, np.full(t.size, 2.0))
    for f in (0.05, 0.5, 0.95):
        assert flat.arias_time(f) == pytest.approx(f * end, rel=1e-12)
    ramp = GroundMotion(dt, t)
    for f in (0.05, 0.95):  # the trapezoidal rule's error on t³: O(dt²)
        assert ramp.arias_time(f) == pytest.approx(f ** (1 / 3) * end, rel=1e-5)
    assert GroundMotion(dt, np.zeros(10)).arias_time(0.95) == 0.0
    with pytest.raises(ValueError, match="fraction"):
        flat.arias_time(1.5)
