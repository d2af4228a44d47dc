"""The seed's derivation (eqs 21-39) step by step: which steps hold, which do not.

References are independent of the module: substitution into the equation as printed,
scipy quadrature / root finding, and a directly integrated ODE of the law the derivation
describes (linear spring, dashpot on approach only).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq

from pounding.contact import seed_derivation as sd
from pounding.contact.restitution import TABLE1_E, TABLE1_ZETA

K = 1.0e8
M = 5.0e4
SP = math.sqrt(math.pi)


# --------------------------------------------------------------------------- eqs 23-25
@pytest.mark.parametrize("zeta", [0.02, 1.0 / (4 * math.pi), 0.7, 8.74])
@pytest.mark.parametrize("vf", [0.1, 1.3])
def test_eq25_satisfies_eq24_equals_eq23(zeta, vf):
    """Substitute eq 25 into 2 π ζ k δmax² = ½ m δ̇_final²."""
    dmax = sd.delta_max_eq25(M, zeta, K, vf)
    assert 2 * math.pi * zeta * K * dmax**2 == pytest.approx(0.5 * M * vf**2, rel=1e-13)
    assert sd.dissipated_energy_eq23(zeta, K, dmax) == pytest.approx(
        sd.dissipated_energy_eq24(M, vf), rel=1e-13)
    assert dmax == pytest.approx(math.sqrt(M / (4 * math.pi * zeta * K)) * vf, rel=1e-15)


def test_eq25_agrees_with_an_elastic_spring_only_at_zeta_one_over_4pi():
    """Linear spring unloading elastically: ½ k δmax² = ½ m v_f², i.e. δmax = sqrt(m/k) v_f."""
    vf = 0.8
    z0 = sd.zeta_consistent_with_eq25()
    assert z0 == pytest.approx(1 / (4 * math.pi))
    assert sd.delta_max_eq25(M, z0, K, vf) == pytest.approx(math.sqrt(M / K) * vf, rel=1e-14)
    for z in (0.01, 0.2, 2.0):
        ratio = sd.delta_max_eq25(M, z, K, vf) / (math.sqrt(M / K) * vf)
        assert ratio == pytest.approx(1 / math.sqrt(4 * math.pi * z), rel=1e-14)


def _simulate_modified_kv(k, m, c, v0):
    """m δ̈ = −(k δ + c δ̇) while δ̇ > 0, −k δ while δ̇ < 0, until δ = 0. Returns
    (δmax, separation speed, dissipated energy ∫ c δ̇² dt over the approach)."""
    def approach(t, y):
        return [y[1], -(k * y[0] + c * y[1]) / m, c * y[1] ** 2]

    def at_max(t, y):
        return y[1]
    at_max.terminal = True
    at_max.direction = -1
    t_end = 50 * math.sqrt(m / k) + 50 * m / max(c, 1e-300) if c > 0 else 50 * math.sqrt(m / k)
    s1 = solve_ivp(approach, (0, t_end), [0.0, v0, 0.0], method="DOP853", rtol=1e-12,
                   atol=[1e-15, 1e-12, 1e-9], events=at_max)
    dmax = s1.y_events[0][0][0]

    def rebound(t, y):
        return [y[1], -k * y[0] / m]

    def at_zero(t, y):
        return y[0]
    at_zero.terminal = True
    at_zero.direction = -1
    s2 = solve_ivp(rebound, (0, 10 * math.sqrt(m / k)), [dmax, 0.0], method="DOP853",
                   rtol=1e-12, atol=[1e-15, 1e-12], events=at_zero)
    v_sep = -s2.y_events[0][0][1]
    return dmax, v_sep, s1.y_events[0][0][2]


@pytest.mark.parametrize("zeta", [0.05, 1 / (4 * math.pi), 0.3])
def test_eq25_against_a_simulated_collision(zeta):
    """For the law of eqs 30-31 (c = 2ζ sqrt(km), dashpot on approach only), eq 25 with the
    simulated separation speed predicts the simulated δmax only at ζ = 1/(4π)."""
    c = sd.damping_coefficient_eq30(K, M, zeta)
    dmax, v_sep, _ = _simulate_modified_kv(K, M, c, 1.0)
    assert v_sep == pytest.approx(math.sqrt(K / M) * dmax, rel=1e-9)  # elastic unloading
    pred = sd.delta_max_eq25(M, zeta, K, v_sep)
    if math.isclose(zeta, 1 / (4 * math.pi)):
        assert pred == pytest.approx(dmax, rel=1e-9)
    else:
        assert pred / dmax == pytest.approx(1 / math.sqrt(4 * math.pi * zeta), rel=1e-9)
        assert abs(pred / dmax - 1) > 0.2


# --------------------------------------------------------------------------- eqs 26-29
def test_eq28_satisfies_eq26():
    zeta, vf = 0.4, 0.9
    dmax = sd.delta_max_eq25(M, zeta, K, vf)
    d = np.linspace(0, dmax, 50)
    v = sd.velocity_eq28(d, M, zeta, K, vf)
    np.testing.assert_allclose(2 * math.pi * zeta * K * d**2 + 0.5 * M * v**2,
                               0.5 * M * vf**2, rtol=1e-12)
    assert v[0] == pytest.approx(vf) and v[-1] == pytest.approx(0.0, abs=1e-6 * vf)


def test_eq29_branch_end_points():
    zeta, v0, vf = 2.0, 1.5, 0.6
    dmax = sd.delta_max_eq25(M, zeta, K, vf)
    assert sd.velocity_eq29(0.0, M, zeta, K, vf, v0, "approach") == pytest.approx(v0)
    assert sd.velocity_eq29(dmax, M, zeta, K, vf, v0, "approach") == pytest.approx(0.0, abs=1e-7)
    assert sd.velocity_eq29(0.0, M, zeta, K, vf, v0, "rebound") == pytest.approx(-vf)
    # the approach branch written out from the printed formula
    d = 0.37 * dmax
    printed = math.sqrt(vf**2 - 4 * K * zeta * math.pi * d**2 / M) + (v0 - abs(vf)) * (dmax - d) / dmax
    assert sd.velocity_eq29(d, M, zeta, K, vf, v0) == pytest.approx(printed, rel=1e-14)


# --------------------------------------------------------------------------- eqs 30-35
@pytest.mark.parametrize("zeta,v0,vf", [(0.3, 1.0, 0.5), (8.74, 2.0, 1.0), (0.05, 0.7, 0.63)])
def test_eq35_equals_quad_of_eq31_with_eq29_profile(zeta, v0, vf):
    c = 2 * zeta * math.sqrt(K * M)  # eq 30
    dmax = math.sqrt(M / (4 * math.pi * zeta * K)) * vf  # eq 25

    def integrand(d):  # eq 31's integrand: the approach branch of eq 29, written out
        root = math.sqrt(max(vf**2 - 4 * zeta * math.pi * K * d**2 / M, 0.0))
        return root + (v0 - abs(vf)) * (dmax - d) / dmax

    ref = c * quad(integrand, 0, dmax, epsabs=0, epsrel=1e-13, limit=200)[0]
    res = sd.dissipated_energy_eq35(K, M, zeta, v0, vf)
    assert res.total == pytest.approx(ref, rel=1e-9)
    assert res.ellipse + res.wedge == pytest.approx(res.total, rel=1e-15)
    assert sd.dissipated_energy_eq31(K, M, zeta, v0, vf) == pytest.approx(ref, rel=1e-9)


def test_eq34_integral_is_quarter_circle():
    dmax = 0.0123
    val = quad(lambda d: math.sqrt(max(dmax**2 - d**2, 0.0)), 0, dmax, epsabs=0, epsrel=1e-13)[0]
    assert val == pytest.approx(0.25 * math.pi * dmax**2, rel=1e-10)


def test_eq34_coefficient():
    """2 ζ sqrt(k m) · sqrt(4 ζ π k / m) = 4 k sqrt(π) ζ^1.5 (eq 33 → eq 34)."""
    zeta = 0.77
    assert 2 * zeta * math.sqrt(K * M) * math.sqrt(4 * zeta * math.pi * K / M) == pytest.approx(
        4 * K * SP * zeta**1.5, rel=1e-14)


# --------------------------------------------------------------------------- eqs 36-39
@pytest.mark.parametrize("zeta,v0,vf", [(0.3, 1.0, 0.5), (8.74, 2.0, 1.0)])
def test_eq36_and_eq37_follow(zeta, v0, vf):
    e35 = sd.dissipated_energy_eq35(K, M, zeta, v0, vf).total
    assert sd.eq36_rhs(K, M, zeta, v0, vf) == pytest.approx(e35, rel=1e-13)
    assert sd.eq37_rhs(K, M, zeta, v0, vf) == pytest.approx(e35, rel=1e-13)


@pytest.mark.parametrize("zeta,v0,vf", [(0.3, 1.0, 0.5), (8.74, 2.0, 1.0), (1.0, 1.0, 0.2)])
def test_eq38_does_not_follow_from_eq37(zeta, v0, vf):
    per_mass = sd.eq37_rhs(K, M, zeta, v0, vf) / M
    assert sd.eq37_rhs_per_mass(zeta, v0, vf) == pytest.approx(per_mass, rel=1e-13)
    # eq 38 as printed, evaluated by hand
    printed = 0.25 * SP * zeta**0.5 * vf**2 + zeta**0.5 * (SP / math.pi) * (v0 - vf) * vf
    assert sd.eq38_rhs(zeta, v0, vf) == pytest.approx(printed, rel=1e-14)
    # first terms agree, second term of eq 38 is twice what eq 37 gives
    first = 0.25 * SP * zeta**0.5 * vf**2
    assert (sd.eq38_rhs(zeta, v0, vf) - first) == pytest.approx(2 * (per_mass - first), rel=1e-10)
    assert sd.eq38_rhs(zeta, v0, vf) != pytest.approx(per_mass, rel=1e-3)


@pytest.mark.parametrize("form", ["stated", "from_eq37"])
@pytest.mark.parametrize("e", [0.1, 0.35, 0.5, 0.8, 0.95])
def test_zeta_from_eq38_solves_it(form, e):
    """The closed-form solution equals a brentq root of the residual (δ̇_imp = δ̇_0 = 1,
    δ̇_final = e)."""
    z = sd.zeta_from_eq38(e, form=form)
    root = brentq(lambda s: sd.residual_eq38(s, e, 1.0, 1.0, e, form=form), 1e-12, 1e6,
                  xtol=1e-14, rtol=1e-13)
    assert z == pytest.approx(root, rel=1e-9)
    assert sd.residual_eq38(z, e, 2.0, 2.0, 2.0 * e, form=form) == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("e", [0.1, 0.3, 0.5, 0.7, 0.9])
def test_eq39_follows_from_neither_eq38_nor_eq37(e):
    z39 = sd.zeta_eq39(e)
    for form in ("stated", "from_eq37"):
        assert abs(sd.zeta_from_eq38(e, form=form) / z39 - 1) > 0.1
        assert abs(sd.residual_eq38(z39, e, 1.0, 1.0, e, form=form)) > 1e-3


def test_eq39_closed_forms_hand_computed_at_half():
    e = 0.5
    assert sd.zeta_eq39(e) == pytest.approx((0.75 / (0.5 * (0.5 * SP * 0.5 + 1 / SP - 0.5))) ** 2)
    assert sd.zeta_from_eq38(e) == pytest.approx(
        (0.75 / (0.5 * (0.5 * SP * 0.5 + 2 * 0.5 / SP))) ** 2)
    assert sd.zeta_from_eq38(e, form="from_eq37") == pytest.approx(
        (0.75 / (0.5 * (0.5 * SP * 0.5 + 0.5 / SP))) ** 2)
    assert sd.zeta_eq39(e) == pytest.approx(8.74, abs=0.005)
    assert sd.zeta_from_eq38(e) == pytest.approx(2.217, abs=0.001)
    assert sd.zeta_from_eq38(e, form="from_eq37") == pytest.approx(4.278, abs=0.001)


def test_eq39_reproduces_table1():
    z = np.asarray(sd.zeta_eq39(np.array(TABLE1_E)))
    # printed to two decimals, some truncated rather than rounded
    assert np.all(np.abs(z - np.array(TABLE1_ZETA)) < 0.0101)


def test_eq24_and_eq36_agree_only_at_e_one_over_sqrt2():
    v = 1.7
    e = 1 / math.sqrt(2)
    assert sd.dissipated_energy_eq24(M, e * v) == pytest.approx(
        sd.kinetic_energy_loss_eq36(M, e, v), rel=1e-14)
    for e2 in (0.3, 0.9):
        assert sd.dissipated_energy_eq24(M, e2 * v) != pytest.approx(
            sd.kinetic_energy_loss_eq36(M, e2, v), rel=1e-3)


def test_seed_prediction_residual_is_eq36():
    p = sd.seed_prediction(K, M, 0.5, 1.2)
    assert p.zeta == pytest.approx(sd.zeta_eq39(0.5))
    assert p.residual_eq36 == pytest.approx(
        sd.residual_eq36(K, M, p.zeta, 0.5, 1.2, 1.2, 0.6), rel=1e-12)
    assert p.energy_lost == pytest.approx(0.5 * M * (1 - 0.25) * 1.2**2)


@pytest.mark.parametrize("call,field", [
    (lambda: sd.delta_max_eq25(-1.0, 0.1, K, 1.0), "m"),
    (lambda: sd.delta_max_eq25(M, 0.0, K, 1.0), "zeta"),
    (lambda: sd.zeta_from_eq38(1.5), "e"),
    (lambda: sd.zeta_from_eq38(0.5, form="bogus"), "form"),
    (lambda: sd.velocity_eq29(0.0, M, 0.1, K, 1.0, 1.0, branch="up"), "branch"),
    (lambda: sd.velocity_eq28(1.0, M, 0.1, K, 1.0), "delta"),
])
def test_bad_input_names_the_field(call, field):
    with pytest.raises(ValueError, match=field):
        call()
