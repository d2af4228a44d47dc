"""Two record components at an incidence angle (pounding.ground_motion.incidence): the
rotation written out here with NumPy's own trigonometry."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest

from pounding.ground_motion import GroundMotion, el_centro, incidence
from pounding.ground_motion.incidence import at_incidence


def _pair() -> tuple[GroundMotion, GroundMotion]:
    rng = np.random.default_rng(3)
    return (GroundMotion(0.01, rng.normal(size=500), name="one"),
            GroundMotion(0.01, rng.normal(size=420), name="two"))


@pytest.mark.parametrize("angle", [0.0, 30.0, 90.0, 137.5, -45.0, 270.0])
def test_rotation_of_two_components(angle: float) -> None:
    a1, a2 = _pair()
    ax, ay = at_incidence(a1, a2, angle)
    b = math.radians(angle)
    x2 = np.concatenate([a2.accel, np.zeros(80)])
    assert np.allclose(ax.accel, np.cos(b) * a1.accel - np.sin(b) * x2, atol=1e-15)
    assert np.allclose(ay.accel, np.sin(b) * a1.accel + np.cos(b) * x2, atol=1e-15)
    # a rotation keeps the magnitude of the horizontal acceleration at every instant
    assert np.allclose(np.hypot(ax.accel, ay.accel), np.hypot(a1.accel, x2), rtol=1e-14)
    assert ax.dt == ay.dt == 0.01


def test_multiples_of_90_degrees_are_exact() -> None:
    a1, a2 = _pair()
    ax, ay = at_incidence(a1, a2, 0.0)
    assert np.array_equal(ax.accel, a1.accel) and np.array_equal(ay.accel[:420], a2.accel)
    ax, ay = at_incidence(a1, a2, 180.0)
    assert np.array_equal(ax.accel, -a1.accel)
    ax, ay = at_incidence(el_centro(), angle=0.0)
    assert np.array_equal(ax.accel, el_centro().accel) and not ay.accel.any()


def test_bad_input() -> None:
    a1, a2 = _pair()
    with pytest.raises(ValueError, match="time step 0.02 s differs"):
        at_incidence(a1, GroundMotion(0.02, a2.accel), 0.0)
    with pytest.raises(ValueError, match=r"angle must be a number of degrees in \[-360, 360\] "
                                         r"\(got nan\)"):
        at_incidence(a1, a2, float("nan"))
    with pytest.raises(ValueError, match=r"angle must be a number of degrees in \[-360, 360\] "
                                         r"\(got 1e\+300\)"):
        at_incidence(a1, a2, 1e300)  # its cosine would be rounding noise
    with pytest.raises(ValueError, match="first: expected a GroundMotion"):
        at_incidence(np.zeros(3), a2)  # type: ignore[arg-type]


def test_docstring_examples_run() -> None:
    failures, tried = doctest.testmod(incidence, verbose=False)
    assert tried > 0 and failures == 0
