"""What structural damping does to the optimal link damper, as docs/mitigation.md says it.

The closed forms of :func:`pounding.devices.optimal.white_noise_optimum` are for undamped
oscillators. With damping ``2 ζ m_i ω_i`` in each oscillator the optimum of each response is
found here independently: the stationary covariance from SciPy's Lyapunov solver, minimised
over ``log c``. The optimum of ``E[x1²]`` falls, the others rise (the docs once said that
the optimum is lower, which holds for ``E[x1²]`` alone).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.linalg import solve_continuous_lyapunov
from scipy.optimize import minimize_scalar

from pounding.devices.optimal import white_noise_optimum

DOCS = Path(__file__).resolve().parents[2] / "docs" / "mitigation.md"


def _mean_square(response: str, m1: float, w1: float, m2: float, w2: float, c: float,
                 zeta: float) -> float:
    """Stationary mean square under unit two-sided white noise, damping ζ in each oscillator."""
    mass = np.diag([m1, m2])
    stiff = np.diag([m1 * w1**2, m2 * w2**2])
    damp = np.array([[c, -c], [-c, c]]) + np.diag([2 * zeta * m1 * w1, 2 * zeta * m2 * w2])
    inv = np.linalg.inv(mass)
    a = np.block([[np.zeros((2, 2)), np.eye(2)], [-inv @ stiff, -inv @ damp]])
    b = np.array([[0.0], [0.0], [-1.0], [-1.0]])
    p = solve_continuous_lyapunov(a, -2 * np.pi * b @ b.T)
    if response == "displacement_1":
        return float(p[0, 0])
    if response == "displacement_2":
        return float(p[1, 1])
    if response == "acceleration_1":  # absolute: the relative acceleration plus the ground's
        row = a[2]
        return float(row @ p @ row)
    weights = np.zeros((4, 4))
    weights[:2, :2], weights[2:, 2:] = stiff / 2, mass / 2
    return float(np.trace(weights @ p))


# response → the change of the optimum at ζ = 2 % and 5 % that the docs quote [%]
QUOTED = {"displacement_1": (-8.0, -20.0), "displacement_2": (12.0, 40.0),
          "acceleration_1": (2.0, 7.0), "energy": (0.3, 2.0)}


@pytest.mark.parametrize("response", sorted(QUOTED))
def test_damping_moves_the_optimum_as_the_docs_say(response: str) -> None:
    m1 = m2 = 1.0
    w1 = 2 * math.pi
    w2 = w1 / 2
    c0 = white_noise_optimum(m1, 2 * math.pi / w1, m2, 2 * math.pi / w2, response)
    for zeta, quoted in zip((0.02, 0.05), QUOTED[response]):
        best = minimize_scalar(
            lambda lc: _mean_square(response, m1, w1, m2, w2, math.exp(lc), zeta),
            bounds=(math.log(c0) - 3, math.log(c0) + 3), method="bounded",
            options={"xatol": 1e-9})
        change = 100 * (math.exp(best.x) / c0 - 1)
        # the docs round to whole per cent (0.3 % to a tenth): within half a unit
        assert change == pytest.approx(quoted, abs=0.05 if abs(quoted) < 1 else 0.5)
    # without damping the closed form is the optimum (to the search's tolerance)
    best0 = minimize_scalar(lambda lc: _mean_square(response, m1, w1, m2, w2, math.exp(lc), 0.0),
                            bounds=(math.log(c0) - 3, math.log(c0) + 3), method="bounded",
                            options={"xatol": 1e-9})
    assert math.exp(best0.x) == pytest.approx(c0, rel=1e-4)


def test_the_docs_quote_these_changes() -> None:
    text = " ".join(DOCS.read_text(encoding="utf-8").split())
    assert "8 % lower at ζ = 2 % and 20 % lower at 5 % for `E[x1²]`" in text
    assert "12 % and 40 % *higher* for `E[x2²]`" in text
    assert "2 % and 7 % higher for `E[ẍ1,abs²]`" in text
    assert "0.3 % and 2 % higher for the total energy" in text
