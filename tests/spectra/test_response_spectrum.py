"""Response spectra of records (``pounding.spectra.response``) checked against computations
that share no code with it: SciPy ``solve_ivp`` on El Centro, closed forms of Chopra's
*Dynamics of Structures*, high-precision step coefficients (mpmath), and the plain
NumPy/SciPy reference (``pounding.spectra.reference``, matrix exponentials and Hermite
maxima) on many oscillators."""

from __future__ import annotations

import csv
import math

import mpmath
import numpy as np
import pytest
from scipy.optimize import minimize_scalar
from spectra_ivp import ivp_peaks

from pounding.ground_motion import GroundMotion, el_centro
from pounding.spectra.reference import reference_peaks
from pounding.spectra.response import (
    default_periods,
    parse_damping,
    parse_periods,
    response_spectrum,
    to_csv,
)
from pounding.units import G


@pytest.mark.parametrize("period, zeta", [(0.05, 0.05), (0.2, 0.3), (0.5, 0.02),
                                          (1.0, 0.05), (3.0, 0.0)])
def test_el_centro_against_solve_ivp(period: float, zeta: float) -> None:
    """The whole 40 s record; the issue asks for 1e-4, the agreement is ~1e-10."""
    gm = el_centro()
    u, a = ivp_peaks(gm.accel, gm.dt, period, zeta)
    r = response_spectrum(gm, [period], [zeta])
    assert r.sd[0, 0] == pytest.approx(u, rel=1e-9)
    assert r.sa_abs[0, 0] == pytest.approx(a, rel=1e-9)
    w = 2 * math.pi / period
    assert r.psa[0, 0] == pytest.approx(w * w * u, rel=1e-9)
    assert r.psv[0, 0] == pytest.approx(w * u, rel=1e-9)


@pytest.mark.parametrize("duration, periods", [
    (8.0, [0.03, 0.1, 0.3, 0.5, 1.0, 2.0, 5.0, 10.0]),
    (2.5, [0.004, 0.013]),  # 2.5 and 0.77 steps a period: several oscillations a step
])
def test_kernel_against_the_plain_reference(duration: float, periods: list[float]) -> None:
    """60 oscillators from 0.004 s to 10 s, undamped to ζ = 0.99, on the strong first
    seconds of El Centro (the shortest periods on fewer seconds: the reference's sub-steps
    are ω h/0.05 a step). The reference's Hermite maxima are within max_phase⁴/384 = 1.6e-8
    (relative) of exact."""
    gm = el_centro().trimmed(duration)
    damping = [0.0, 0.02, 0.05, 0.2, 0.7, 0.99]
    sd, sa = reference_peaks(gm.accel, gm.dt, periods, damping)
    r = response_spectrum(gm, periods, damping)
    np.testing.assert_allclose(r.sd, sd, rtol=2e-8)
    np.testing.assert_allclose(r.sa_abs, sa, rtol=2e-8)


def test_step_with_rise_time_peak_between_samples() -> None:
    """Chopra §4.5 (eq. 4.5.4): an undamped oscillator under a force rising linearly over
    t_r, then constant, peaks at u_st (1 + |sin(π t_r/T)|/(π t_r/T)). With t_r = 0.3 s,
    T = 1 s and samples 0.1 s apart the peak falls at t = t_r/2 + T/2 = 0.65 s, between
    samples; the samples alone fall short by 1.6 %."""
    a0, tr, period, dt = 2.0, 0.3, 1.0, 0.1
    t = np.arange(0.0, 3.0 + dt / 2, dt)
    gm = GroundMotion(dt, np.minimum(t / tr, 1.0) * a0)
    w = 2 * math.pi / period
    rd = 1 + abs(math.sin(math.pi * tr / period)) / (math.pi * tr / period)
    r = response_spectrum(gm, [period], [0.0])
    assert r.sd[0, 0] == pytest.approx(a0 / w ** 2 * rd, rel=1e-12)
    assert r.sa_abs[0, 0] == pytest.approx(a0 * rd, rel=1e-12)  # ζ = 0: |a_abs| = ω²|u|

    def u_closed(time: float) -> float:  # eq. 4.5.3, t ≥ t_r
        return -a0 / w ** 2 * (1 - (math.sin(w * time) - math.sin(w * (time - tr))) / (w * tr))

    samples = max(abs(u_closed(x)) for x in t if x >= tr)
    assert samples < 0.985 * r.sd[0, 0]


def test_damped_ramp_closed_form() -> None:
    """A ramp a_g = r t is linear, so every step is exact whatever dt. The closed form is
    the particular solution u_p = −(r/ω²)(t − 2ζ/ω) plus the free vibration that starts it
    from rest; its maxima are found with SciPy (Brent) on the closed form."""
    rate, period, zeta, dt, dur = 1.5, 0.7, 0.1, 0.25, 3.0
    w = 2 * math.pi / period
    sig, wd = zeta * w, w * math.sqrt(1 - zeta ** 2)
    c0, c1 = 2 * zeta * rate / w ** 3, -rate / w ** 2
    p, q = -c0, (-c1 - sig * c0) / wd

    def u(t: float) -> float:
        return c0 + c1 * t + math.exp(-sig * t) * (p * math.cos(wd * t) + q * math.sin(wd * t))

    def a_abs(t: float) -> float:
        h = 1e-4  # a_abs = −(2ζω u̇ + ω² u), u̇ by central differences of the closed form
        return -(2 * sig * (u(t + h) - u(t - h)) / (2 * h) + w * w * u(t))

    gm = GroundMotion(dt, rate * np.arange(0.0, dur + dt / 2, dt))
    r = response_spectrum(gm, [period], [zeta])
    # |u| grows with t (the ramp): its largest value is at the end
    assert r.sd[0, 0] == pytest.approx(abs(u(dur)), rel=1e-12)
    # the absolute acceleration overshoots r t early on: the largest of its local maxima
    grid = np.linspace(0.0, dur, 3001)
    vals = np.abs([a_abs(x) for x in grid])
    k = int(np.argmax(vals))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    best = minimize_scalar(lambda x: -abs(a_abs(x)), bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-12})
    assert r.sa_abs[0, 0] == pytest.approx(max(-best.fun, vals.max()), rel=1e-7)


def test_short_periods_tend_to_the_pga() -> None:
    """T → 0: the oscillator follows the ground, u ≈ −a_g/ω², so PSA → PGA (and the
    absolute acceleration too)."""
    gm = el_centro()
    r = response_spectrum(gm, [1e-4, 1e-3], [0.05])
    np.testing.assert_allclose(r.psa[0] / gm.pga, 1.0, atol=3e-4)
    np.testing.assert_allclose(r.sa_abs[0] / gm.pga, 1.0, atol=3e-4)
    assert r.psa[0, 0] == pytest.approx(gm.pga, rel=1e-4)


def _peak_ground_displacement(accel: np.ndarray, dt: float) -> float:
    """max |u_g| of the record linear between samples, from rest: per step the cubic
    ``u_i + v_i τ + a_i τ²/2 + s τ³/6``, its samples and its stationary points inside the
    step (numpy; no code of the kernel)."""
    a = np.asarray(accel, dtype=float)
    s = np.diff(a) / dt
    v = np.concatenate([[0.0], np.cumsum(dt * (a[1:] + a[:-1]) / 2)])
    u = np.concatenate([[0.0], np.cumsum(dt * v[:-1] + dt * dt * (a[:-1] / 3 + a[1:] / 6))])
    best = float(np.max(np.abs(u)))
    for i in range(s.size):  # v_i + a_i τ + s τ²/2 = 0
        for tau in np.roots([s[i] / 2, a[i], v[i]]) if s[i] else [-v[i] / a[i]]:
            if np.isreal(tau) and 0.0 < tau.real < dt:
                t = tau.real
                best = max(best, abs(u[i] + v[i] * t + a[i] * t * t / 2 + s[i] * t ** 3 / 6))
    return best


def test_long_periods_tend_to_the_peak_ground_displacement() -> None:
    """T → ∞: the oscillator stays put while the ground moves, u → −u_g, so Sd → the peak
    ground displacement of the record linear between samples (computed above, apart). The
    spring and the dashpot pull u back from −u_g by a fraction of order (ω t_end)² and
    2ζ ω t_end (t_end = 40 s for El Centro): 6e-10 and 2.5e-6 at T = 1e7 s. The closed
    forms gave Sd = 8,491 m at T = 1e7 s and 1.4e10 m at 1e9 s."""
    gm = el_centro()
    pgd = _peak_ground_displacement(gm.accel, gm.dt)
    assert pgd == pytest.approx(0.1303, abs=1e-4)
    periods, zetas = np.array([1e5, 1e7, 1e9]), np.array([0.0, 0.05])
    r = response_spectrum(gm, periods, zetas)
    wt = 2 * np.pi / periods * gm.duration
    bound = pgd * (wt[None, :] ** 2 + 2 * zetas[:, None] * wt[None, :] + 1e-12)
    assert np.all(np.abs(r.sd - pgd) <= bound), (r.sd - pgd) / bound
    assert np.all(np.abs(r.sd[:, 1:] - pgd) <= 3e-6 * pgd)
    np.testing.assert_allclose(r.psv, r.sd * 2 * np.pi / r.periods, rtol=1e-14)
    assert np.all(r.psa_g < 1e-9)


def test_periods_far_below_the_step_give_the_pga() -> None:
    """T ≪ dt: the oscillator follows the ground, u = −a_g/ω² to (ω h)⁻¹, so PSA and the
    peak absolute acceleration are the PGA (damped: the start's free vibration dies out)."""
    gm = el_centro()
    r = response_spectrum(gm, [1e-9, 1e-6], [0.05])
    np.testing.assert_allclose(r.psa[0] / gm.pga, 1.0, rtol=1e-6)
    np.testing.assert_allclose(r.sa_abs[0] / gm.pga, 1.0, rtol=1e-6)
    np.testing.assert_allclose(r.sd[0], gm.pga / (2 * np.pi / r.periods) ** 2, rtol=1e-6)


def test_undamped_periods_far_below_the_step_in_a_moment() -> None:
    """Undamped, the free vibration the record's first sample starts (a_g(0) ≠ 0 at rest:
    amplitude |a_g(0)|/ω²) never dies, and a step holds ω h/π ≈ 2e7 half-cycles at
    T = 1e-9 s: PSA → PGA + |a_g(0)| (El Centro: 0.3129 + 0.0064 g), found from the first
    and last half-cycles of a step alone (it took ten minutes, cycle by cycle)."""
    import time

    gm = el_centro()
    start = time.perf_counter()
    r = response_spectrum(gm, [1e-9, 1e-6], [0.0])
    assert time.perf_counter() - start < 5.0
    np.testing.assert_allclose(r.psa[0], gm.pga + abs(gm.accel[0]), rtol=1e-6)


def test_the_issues_period_range_from_the_command_line(tmp_path, capsys) -> None:
    """`pounding spectrum --periods 1e-9:1e9:10` printed Sd = 8,491 m at T = 1e7 s."""
    from pathlib import Path

    from pounding.cli import main

    record = Path(__file__).resolve().parents[2] / "src" / "pounding" / "data" / "records" \
        / "elcentro_1940_IV_ELC9_180_PEER.AT2"
    out = tmp_path / "s.csv"
    assert main(["spectrum", str(record), "--periods", "1e-9:1e9:10", "--csv", str(out)]) == 0
    with out.open(encoding="utf-8") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    gm = el_centro()
    pgd = _peak_ground_displacement(gm.accel, gm.dt)
    assert float(rows[0]["psa_g"]) == pytest.approx(gm.pga_g, rel=1e-6)   # T = 1e-9 s
    assert float(rows[-2]["sd_m"]) == pytest.approx(pgd, rel=3e-6)        # T = 1e7 s
    assert float(rows[-1]["sd_m"]) == pytest.approx(pgd, rel=1e-8)        # T = 1e9 s
    capsys.readouterr()
    for spec, got in (("1e-9:1e10:3", "1e+10"), ("1e-10,1", "1e-10")):
        assert main(["spectrum", str(record), "--periods", spec]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert err == [f"error: --periods: every period must be from 1e-09 s to 1e+09 s (got "
                       f"{got}): beyond, the oscillator follows the ground or stays put and "
                       "its response no longer changes"], err


def test_step_coefficients_against_high_precision_arithmetic() -> None:
    """The step (A, B) against the closed-form solution evaluated with mpmath at 120 digits
    (enough for its cancellation at T = 1e9 s), each matrix to its largest entry: 1e-13 at
    every period, the long ones included (the closed forms in floating point lost
    2 log10(T/(2π h)) digits: all of them by T = 1e7 s)."""
    from pounding.spectra._kernel import step_coefficients

    mpmath.mp.dps = 120

    def exact(w: float, z: float, h: float) -> list[float]:
        w, z, h = mpmath.mpf(w), mpmath.mpf(z), mpmath.mpf(h)
        sig, wd = z * w, w * mpmath.sqrt(1 - z * z)
        e, c, s = mpmath.exp(-sig * h), mpmath.cos(wd * h), mpmath.sin(wd * h)
        a = [e * (c + sig / wd * s), e * s / wd, -w * w * e * s / wd, e * (c - sig / wd * s)]
        b = []
        for p0, p1 in ((-1, 1 / h), (0, -1 / h)):
            c1 = p1 / w ** 2
            c0 = (p0 - 2 * sig * c1) / w ** 2
            b.append((c0 + c1 * h - a[0] * c0 - a[1] * c1, c1 - a[2] * c0 - a[3] * c1))
        return [float(x) for x in (*a, b[0][0], b[1][0], b[0][1], b[1][1])]

    for period, zeta, h in [(0.01, 0.05, 0.01), (0.5, 0.0, 0.01), (1.0, 0.999, 0.005),
                            (5.0, 0.05, 0.01), (20.0, 0.05, 0.005), (0.0628, 0.05, 0.01),
                            (0.0629, 0.0, 0.01), (1e3, 0.05, 0.01), (1e7, 0.05, 0.01),
                            (1e9, 0.0, 0.005), (1e9, 0.999, 0.02)]:
        w = 2 * math.pi / period
        got = np.array(step_coefficients(w, zeta, h))
        want = np.array(exact(w, zeta, h))
        for block in (slice(0, 4), slice(4, 8)):  # A, then B, each to its largest entry
            err = np.max(np.abs(got[block] - want[block])) / np.max(np.abs(want[block]))
            assert err < 1e-13, (period, zeta, h, err)


def test_shapes_units_and_csv() -> None:
    gm = el_centro()
    r = response_spectrum(gm, damping=[0.02, 0.05, 0.1])
    assert r.sd.shape == r.psv.shape == r.psa.shape == r.sa_abs.shape == (3, 100)
    np.testing.assert_array_equal(r.periods, default_periods())
    assert r.periods[0] == pytest.approx(0.02) and r.periods[-1] == pytest.approx(5.0)
    np.testing.assert_allclose(r.psa_g, r.psa / G)
    # ζ = 0: the absolute acceleration is −ω² u exactly, so sa_abs = PSA
    r0 = response_spectrum(gm, [0.3, 2.0], [0.0])
    np.testing.assert_allclose(r0.sa_abs, r0.psa, rtol=1e-13)
    text = to_csv([r0])
    lines = text.splitlines()
    assert lines[0] == "record,damping,period_s,sd_m,psv_m_s,psa_g,sa_abs_g"
    rows = list(csv.reader(lines[1:]))
    assert len(rows) == 2 and rows[0][:3] == [gm.name, "0", "0.3"]  # the name has a comma
    assert float(rows[1][5]) == pytest.approx(r0.psa_g[0, 1], rel=1e-9)


def test_period_and_damping_specs() -> None:
    np.testing.assert_allclose(parse_periods("0.05:4:300"), np.geomspace(0.05, 4, 300))
    np.testing.assert_allclose(parse_periods("0.1, 0.5,1"), [0.1, 0.5, 1.0])
    np.testing.assert_allclose(parse_damping("0.05,0.02"), [0.05, 0.02])
    np.testing.assert_allclose(parse_periods("2:2:1"), [2.0])


@pytest.mark.parametrize("call, message", [
    (lambda gm: response_spectrum(gm, [0.5, 0.0]), "periods: every period must be finite "
                                                   "and > 0 s (got 0)"),
    (lambda gm: response_spectrum(gm, [-1.0]), "(got -1)"),
    (lambda gm: response_spectrum(gm, [float("nan")]), "(got nan)"),
    (lambda gm: response_spectrum(gm, [1.0], [0.05, 1.0]), "damping: every damping ratio "
                                                           "must be in [0, 1)"),
    (lambda gm: response_spectrum(gm, [1.0], -0.01), "(got -0.01)"),
    (lambda gm: parse_periods("0.05:4"), "periods: give FIRST:LAST:N"),
    (lambda gm: parse_periods("4:0.05:10"), "LAST must be larger than FIRST"),
    (lambda gm: parse_periods("0:4:10"), "(got 0)"),
    (lambda gm: parse_periods("0.1,,2"), "comma-separated numbers (got '0.1,,2')"),
    (lambda gm: parse_damping("5%"), "damping: give comma-separated numbers (got '5%')"),
    (lambda gm: response_spectrum(gm, [1.0, 1e300]), "periods: every period must be from "
                                                      "1e-09 s to 1e+09 s (got 1e+300)"),
    (lambda gm: response_spectrum(gm, [1e-300]), "(got 1e-300)"),
])
def test_bad_periods_and_damping_are_named(call, message) -> None:  # noqa: ANN001
    with pytest.raises(ValueError) as info:
        call(el_centro())
    assert message in str(info.value) and "\n" not in str(info.value)
