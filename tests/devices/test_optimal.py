"""The optimal link damper: closed forms against the stationary covariance solved by SciPy
(Lyapunov equation, independent of the closed forms), an exact hand value, and the search
on a simulated white-noise record against the closed form."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.linalg import solve_continuous_lyapunov
from scipy.optimize import minimize_scalar

from pounding import ContactSpec, PoundingModel, ShearBuilding
from pounding.devices import Link
from pounding.devices.optimal import OPTIMUM_RESPONSES, white_noise_optimum
from pounding.ground_motion import GroundMotion
from pounding.studies.optimal_link import optimal_link_coefficient


def _mean_square(response, m1, w1, m2, w2, c):
    """Stationary mean square of a response under unit two-sided white noise (S0 = 1)."""
    k1, k2 = m1 * w1**2, m2 * w2**2
    a = np.array([[0, 0, 1, 0], [0, 0, 0, 1],
                  [-k1 / m1, 0, -c / m1, c / m1], [0, -k2 / m2, c / m2, -c / m2]])
    b = np.array([[0.0], [0.0], [-1.0], [-1.0]])
    p = solve_continuous_lyapunov(a, -2 * np.pi * b @ b.T)
    acc1 = np.array([-k1 / m1, 0, -c / m1, c / m1])
    return {"displacement_1": p[0, 0], "displacement_2": p[1, 1],
            "acceleration_1": acc1 @ p @ acc1,
            "energy": 0.5 * (k1 * p[0, 0] + k2 * p[1, 1] + m1 * p[2, 2] + m2 * p[3, 3])}[response]


@pytest.mark.parametrize("response", OPTIMUM_RESPONSES)
@pytest.mark.parametrize("m1, t1, m2, t2", [(2e5, 0.5, 3e5, 1.0), (1.0, 1.0, 0.5, 1 / 0.75),
                                            (6e5, 0.8, 4e5, 1.3)])
def test_closed_form_is_the_minimum_of_the_stationary_covariance(response, m1, t1, m2, t2):
    w1, w2 = 2 * math.pi / t1, 2 * math.pi / t2
    c = white_noise_optimum(m1, t1, m2, t2, response)
    res = minimize_scalar(lambda lc: _mean_square(response, m1, w1, m2, w2, math.exp(lc)),
                          bracket=(math.log(c) - 2, math.log(c) + 2), tol=1e-10)
    assert math.exp(res.x) == pytest.approx(c, rel=1e-4)


def test_an_exact_hand_value():
    # m1 = 1, ω1 = 5, m2 = 3, ω2 = 9: c = 1 · 3 · |25 − 81| / (5 · 4^1.5) = 168 / 40 = 4.2
    assert white_noise_optimum(1.0, 2 * math.pi / 5, 3.0, 2 * math.pi / 9) == pytest.approx(
        4.2, rel=1e-14)


def test_the_search_on_a_white_noise_record_finds_the_closed_form():
    # 400 s of sampled white noise on two undamped oscillators without contact: the RMS
    # roof displacement of B1 is least near the closed-form c (finite record: ~3 % here)
    rng = np.random.default_rng(2015)
    dt = 0.005
    gm = GroundMotion(dt, rng.normal(0.0, 1.0, int(400 / dt)), name="white noise")
    b1 = ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.0)
    b2 = ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.0)
    model = PoundingModel([b1, b2], [100.0], ContactSpec("kelvin-voigt", k=9.3e8, e=0.65),
                          devices=[Link(("B1F1", "B2F1"), "viscous", c=1e5)])
    opt = optimal_link_coefficient(model, gm, response="rms_displacement_B1",
                                   bounds=(1e4, 1e8), dt=dt, xatol=0.02)
    assert opt.c == pytest.approx(white_noise_optimum(2e5, 0.5, 3e5, 1.0), rel=0.10)
    assert opt.response == min(v for _, v in opt.evaluated)


@pytest.mark.parametrize("kw, match", [
    (dict(response="rms"), "response: 'rms' is not one of"),
    (dict(period2=0.5), "period2: equal periods"),
    (dict(m1=0.0), "m1: must be finite and > 0"),
])
def test_bad_input_is_refused(kw, match):
    args = dict(m1=2e5, period1=0.5, m2=3e5, period2=1.0) | kw
    with pytest.raises(ValueError, match=match):
        white_noise_optimum(**args)
