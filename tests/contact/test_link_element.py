"""The seed's link-element relations (eqs 1-15, Fig 2) against closed forms and quadrature."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, trapezoid

from pounding.contact import link_element as le

K = 1.0e8
M = 1.0e6
ZETA = 0.05
OMEGA_N = math.sqrt(K / M)
DELTA0 = 0.01


# --------------------------------------------------------------------------- eqs 1-2, 10
@pytest.mark.parametrize("omega", [OMEGA_N, 3.7, 41.0])
@pytest.mark.parametrize("c", [1.0e6, 2.5e4])
def test_ellipse_area_equals_quad_of_eq1(c, omega):
    """E_D = π c ω δ0² (eq 10) equals ∫ c δ̇² dt over a cycle by adaptive quadrature."""
    period = 2.0 * math.pi / omega
    val, _ = quad(lambda t: c * (omega * DELTA0 * math.cos(omega * t)) ** 2, 0.0, period,
                  epsrel=1e-13)
    assert le.ellipse_area(c, omega, DELTA0) == pytest.approx(val, rel=1e-11)


@pytest.mark.parametrize("phi", [0.0, 0.4, -2.0])
def test_dissipated_energy_eq1_sampled(phi):
    """eq 1 on a sampled history: with exact rate it is exact (periodic trapezoid); with
    np.gradient it converges to π c ω δ0² at second order."""
    c, w = 1.0e6, OMEGA_N
    loop = le.harmonic_loop(K, c, w, DELTA0, n=2001, phi=phi)
    exact = math.pi * c * w * DELTA0**2
    assert le.dissipated_energy(loop.t, loop.delta, c, rate=loop.rate) == pytest.approx(exact, rel=1e-12)
    assert le.dissipated_energy(loop.t, loop.delta, c) == pytest.approx(exact, rel=1e-5)
    # second-order convergence of the gradient-based estimate
    errs = []
    for n in (401, 801):
        lp = le.harmonic_loop(K, c, w, DELTA0, n=n, phi=phi)
        errs.append(abs(le.dissipated_energy(lp.t, lp.delta, c) - exact))
    assert errs[0] / errs[1] == pytest.approx(4.0, rel=0.05)


def test_dissipated_energy_matches_independent_trapezoid_on_nonharmonic_history():
    t = np.linspace(0.0, 0.3, 30001)
    delta = 0.002 * np.sin(20.0 * t) * np.exp(-3.0 * t) + 1e-4 * t**2
    rate = np.gradient(delta, t)
    c = 3.0e5
    ref = c * np.sum(0.5 * (rate[1:] ** 2 + rate[:-1] ** 2) * np.diff(t))
    assert le.dissipated_energy(t, delta, c, rate=rate) == pytest.approx(ref, rel=1e-12)


@pytest.mark.parametrize("phi", [0.0, 1.1])
def test_spring_work_over_a_cycle_is_zero(phi):
    loop = le.harmonic_loop(K, 1.0e6, OMEGA_N, DELTA0, n=1001, phi=phi)
    scale = 0.5 * K * DELTA0**2
    # exact rate: zero to rounding; np.gradient rate: one-sided ends leave O(h²) residue
    assert abs(le.spring_work(loop.t, loop.delta, K, rate=loop.rate)) < 1e-10 * scale
    assert abs(le.spring_work(loop.t, loop.delta, K)) < 1e-6 * scale


def test_spring_work_open_path_equals_half_k_delta_squared():
    """eq 2 is an exact differential: ∫ k δ δ̇ dt = ½ k (δ_end² − δ_start²)."""
    t = np.linspace(0.0, 0.25 * 2.0 * math.pi / OMEGA_N, 4001)  # quarter cycle, 0 -> δ0
    delta = DELTA0 * np.sin(OMEGA_N * t)
    expected = 0.5 * K * DELTA0**2
    assert le.spring_work(t, delta, K) == pytest.approx(expected, rel=1e-6)


# --------------------------------------------------------------------------- Fig 2 areas
@pytest.mark.parametrize("c,omega", [(1.0e6, OMEGA_N), (4.0e5, 25.0)])
def test_shoelace_area_of_loops_equals_eq10(c, omega):
    """The dashpot ellipse and the combined (sheared) loop both enclose π c ω δ0². A regular
    N-gon inscribed in an ellipse has area (N/2π) sin(2π/N) × the ellipse area."""
    n = 1441  # 1440 distinct vertices
    loop = le.harmonic_loop(K, c, omega, DELTA0, n=n)
    exact = math.pi * c * omega * DELTA0**2
    polygon = exact * (n - 1) / (2 * math.pi) * math.sin(2 * math.pi / (n - 1))
    assert le.loop_area(loop.delta, loop.f_dashpot) == pytest.approx(polygon, rel=1e-10)
    assert le.loop_area(loop.delta, loop.f_total) == pytest.approx(polygon, rel=1e-10)
    assert le.loop_area(loop.delta, loop.f_spring) == pytest.approx(0.0, abs=1e-9 * exact)


def test_loop_area_unit_square():
    assert le.loop_area([0, 1, 1, 0], [0, 0, 1, 1]) == pytest.approx(1.0)


def test_harmonic_loop_forces_are_eqs_3_to_5():
    c = 7.0e5
    loop = le.harmonic_loop(K, c, 12.0, DELTA0, n=101, phi=0.3)
    np.testing.assert_allclose(loop.delta, DELTA0 * np.sin(12.0 * loop.t - 0.3), rtol=0, atol=1e-15)
    np.testing.assert_allclose(loop.f_spring, K * loop.delta)
    np.testing.assert_allclose(loop.f_dashpot, c * loop.rate)
    np.testing.assert_allclose(loop.f_total, K * loop.delta + c * loop.rate)
    np.testing.assert_allclose(le.link_force(K, c, loop.delta, loop.rate), loop.f_total)
    assert loop.delta[0] == pytest.approx(loop.delta[-1], abs=1e-15)


# --------------------------------------------------------------------------- eqs 6-9
def test_f_d_points_satisfy_eq9():
    c, w = 1.0e6, 13.0
    loop = le.harmonic_loop(K, c, w, DELTA0, n=999, phi=0.7)
    # independently: (δ/δ0)² + (f_D/(c ω δ0))² − 1
    direct = (loop.delta / DELTA0) ** 2 + (loop.f_dashpot / (c * w * DELTA0)) ** 2 - 1.0
    assert np.max(np.abs(direct)) < 1e-12
    assert np.max(np.abs(le.ellipse_residual_eq9(loop.delta, loop.f_dashpot, c, w, DELTA0))) < 1e-12


def test_eq6_and_eq8_agree_on_the_upper_branch():
    c, w = 2.0e5, 9.0
    t = np.linspace(0.0, 2 * math.pi / w, 400)
    f6 = le.dashpot_force_eq6(t, c, w, DELTA0)
    d = le.harmonic_displacement(t, w, DELTA0)
    up = f6 >= 0
    np.testing.assert_allclose(le.dashpot_force_eq8(d[up], c, w, DELTA0), f6[up],
                               rtol=1e-9, atol=1e-9 * c * w * DELTA0)
    np.testing.assert_allclose(le.dashpot_force_eq8(d[~up], c, w, DELTA0, branch=-1), f6[~up],
                               rtol=1e-9, atol=1e-9 * c * w * DELTA0)
    # eq 8 as printed: the + root, c ω δ0 at δ = 0
    assert le.dashpot_force_eq8(0.0, c, w, DELTA0) == pytest.approx(c * w * DELTA0)


# --------------------------------------------------------------------------- eqs 11-12
def test_eq12_gives_zeta_back_through_eq11_at_resonance():
    c = le.damping_coefficient_viscous(K, ZETA, OMEGA_N)
    assert c == pytest.approx(2.0 * ZETA * math.sqrt(K * M))
    # eq 11 at ω = ω_n: π c ω δ0² = 2 π ζ k δ0²
    assert le.ellipse_area(c, OMEGA_N, DELTA0) == pytest.approx(
        le.dissipated_energy_eq11(ZETA, OMEGA_N, OMEGA_N, K, DELTA0), rel=1e-14)
    assert le.zeta_from_eq11(c, K, OMEGA_N, OMEGA_N) == pytest.approx(ZETA, rel=1e-14)


@pytest.mark.parametrize("omega", [0.3 * OMEGA_N, 2.2 * OMEGA_N])
def test_eq11_holds_with_eq12_at_any_frequency(omega):
    c = le.damping_coefficient_viscous(K, ZETA, OMEGA_N)
    assert le.ellipse_area(c, omega, DELTA0) == pytest.approx(
        le.dissipated_energy_eq11(ZETA, omega, OMEGA_N, K, DELTA0), rel=1e-14)
    assert le.zeta_from_eq11(c, K, omega, OMEGA_N) == pytest.approx(ZETA, rel=1e-14)


# --------------------------------------------------------------------------- eqs 13-15
def test_eq13_as_stated_hand_numbers():
    # ω = 10, ζ = 0.19: ω sqrt(1 − ζ) = 10 × 0.9 = 9 (not the damped relation 10 sqrt(1 − 0.0361))
    assert le.omega_n_eq13(10.0, 0.19) == pytest.approx(9.0, rel=1e-15)
    assert le.omega_n_eq13(10.0, 0.19) != pytest.approx(10.0 * math.sqrt(1 - 0.19**2))


def test_eq14_as_stated_hand_numbers():
    # k = 100, ζ = 0.19, ω = 10: 2·100·0.19 / (10 · 0.9) = 38/9
    assert le.c_eq14(100.0, 0.19, 10.0) == pytest.approx(38.0 / 9.0, rel=1e-15)
    # and it is eq 12 with ω_n from eq 13
    assert le.c_eq14(100.0, 0.19, 10.0) == pytest.approx(
        le.damping_coefficient_viscous(100.0, 0.19, le.omega_n_eq13(10.0, 0.19)), rel=1e-15)


def test_eq15_as_stated_hand_numbers():
    # k = 400, m = 25, ζ = 0.36: 2·0.36·sqrt(10000)/sqrt(0.64) = 72/0.8 = 90
    assert le.c_eq15(400.0, 25.0, 0.36) == pytest.approx(90.0, rel=1e-15)


@pytest.mark.parametrize("zeta", [0.0, 0.05, 0.3, 0.9])
def test_eq15_is_eq14_with_omega_sqrt_k_over_m(zeta):
    k, m = 3.0e7, 2.0e5
    assert le.c_eq15(k, m, zeta) == pytest.approx(le.c_eq14(k, zeta, math.sqrt(k / m)), rel=1e-14,
                                                  abs=1e-300)


@pytest.mark.parametrize("zeta", [0.05, 0.3])
def test_eq15_contradicts_eq13_when_omega_n_is_sqrt_k_over_m(zeta):
    """With ω_n = sqrt(k/m), eq 13 gives ω = ω_n/sqrt(1 − ζ) and eq 14 then gives 2ζ sqrt(km),
    not eq 15's 2ζ sqrt(km)/sqrt(1 − ζ)."""
    k, m = 3.0e7, 2.0e5
    omega = math.sqrt(k / m) / math.sqrt(1.0 - zeta)
    assert le.omega_n_eq13(omega, zeta) == pytest.approx(math.sqrt(k / m))
    c14 = le.c_eq14(k, zeta, omega)
    assert c14 == pytest.approx(2 * zeta * math.sqrt(k * m), rel=1e-14)
    assert le.c_eq15(k, m, zeta) / c14 == pytest.approx(1 / math.sqrt(1 - zeta), rel=1e-14)


# --------------------------------------------------------------------------- validation
@pytest.mark.parametrize("call,field", [
    (lambda: le.ellipse_area(-1.0, 1.0, 1.0), "c"),
    (lambda: le.ellipse_area(1.0, 0.0, 1.0), "omega"),
    (lambda: le.damping_coefficient_viscous(-5.0, 0.1, 1.0), "k"),
    (lambda: le.omega_n_eq13(1.0, 1.0), "zeta"),
    (lambda: le.c_eq15(1.0, -2.0, 0.1), "m"),
    (lambda: le.harmonic_loop(1.0, 1.0, 1.0, -0.1), "delta0"),
    (lambda: le.dissipated_energy([0, 1, 1], [0, 1, 2], 1.0), "t"),
    (lambda: le.spring_work([0, 1, 2], [0, 1], 1.0), "delta"),
    (lambda: le.dashpot_force_eq8(2.0, 1.0, 1.0, 1.0), "delta"),
])
def test_bad_input_names_the_field(call, field):
    with pytest.raises(ValueError, match=field):
        call()


# --------------------------------------------------------------------------- CLI
def test_cli_ellipse_writes_figure(tmp_path, capsys):
    from pounding.cli import commands_ellipse  # noqa: F401  (registers the command)
    from pounding.cli import main

    out = tmp_path / "fig2.png"
    assert main(["ellipse", "--plot", str(out)]) == 0
    assert out.exists() and out.stat().st_size > 1000
    text = capsys.readouterr().out
    # π · (2·1e8·0.05/10) · 10 · 0.01² = π·1e6·1e-3 J, every energy of the table in kJ
    assert "value [kJ]" in text and "3.14159" in text


def test_cli_ellipse_bad_input_exits_2(tmp_path):
    from pounding.cli import commands_ellipse  # noqa: F401
    from pounding.cli import main

    assert main(["ellipse", "--k", "-1"]) == 2
    assert main(["ellipse", "--c", "1", "--zeta", "0.1"]) == 2
    assert main(["ellipse", "--omega", "1", "--period", "2"]) == 2


def test_plot_hysteresis_ellipse_has_three_curves():
    from pounding.plot.ellipse import plot_hysteresis_ellipse

    fig = plot_hysteresis_ellipse(K, 1.0e6, OMEGA_N, DELTA0)
    ax = fig.axes[0]
    colors = [ln.get_color() for ln in ax.get_lines()]
    assert {"tab:blue", "tab:green", "tab:red"} <= set(colors)
    # δ in mm, the force in the multiple of N that reads 1-1000 (here ±1 MN), no offsets
    assert ax.get_xlabel() == "penetration δ [mm]" and ax.get_ylabel() == "force [MN]"
    red = next(ln for ln in ax.get_lines() if ln.get_color() == "tab:red")
    assert np.abs(red.get_xdata()).max() == pytest.approx(DELTA0 * 1e3, rel=1e-12)
    peak = np.hypot(K * DELTA0, 1.0e6 * OMEGA_N * DELTA0)  # |k δ + c δ̇| at its largest
    assert np.abs(red.get_ydata()).max() == pytest.approx(peak * 1e-6, rel=1e-4)
    fig.canvas.draw()
    assert ax.xaxis.get_offset_text().get_text() == ax.yaxis.get_offset_text().get_text() == ""
    assert any("J" in t.get_text() for t in ax.get_legend().get_texts())
