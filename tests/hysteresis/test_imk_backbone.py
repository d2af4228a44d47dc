"""The modified IMK hinge laws on a monotonic path: the published backbone point by point, and
bad constants.

The backbone (Lignos & Krawinkler 2011, J. Struct. Eng. 137(11), Fig. 1) is written out here
again, independently of :mod:`pounding.hysteresis.imk`, with ``θ_y = M_y/K_e``,
``M_c = (M_c/M_y) M_y``, ``θ_c = θ_y + θ_p``::

    M = K_e θ                          0   <= θ <= θ_y
    M = M_y + (M_c − M_y)/θ_p (θ − θ_y)   θ_y <= θ <= θ_c
    M = M_c − M_c/θ_pc (θ − θ_c)       until it reaches κ M_y
    M = κ M_y                          until θ_u, then 0 (fracture)

for each side with its own constants (negative side: rotation and moment negated).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.hysteresis.hinges import moment_path
from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented

K0 = 1.2e8  # N·m/rad
POS = {"m_y": 3.0e5, "theta_p": 0.025, "theta_pc": 0.12, "theta_u": 0.16, "mc_my": 1.12,
       "kappa": 0.35}
NEG = {"m_y": 2.4e5, "theta_p": 0.018, "theta_pc": 0.09, "theta_u": 0.11, "mc_my": 1.06,
       "kappa": 0.2}


def _law(cls: type[IMKBilinear | IMKPeakOriented]) -> IMKBilinear | IMKPeakOriented:
    return cls(k0=K0, m_y=POS["m_y"], theta_p=POS["theta_p"], theta_pc=POS["theta_pc"],
               theta_u=POS["theta_u"], mc_my=POS["mc_my"], kappa=POS["kappa"],
               m_y_neg=NEG["m_y"], theta_p_neg=NEG["theta_p"], theta_pc_neg=NEG["theta_pc"],
               theta_u_neg=NEG["theta_u"], mc_my_neg=NEG["mc_my"], kappa_neg=NEG["kappa"],
               lambda_=0.8, c=1.2)  # cyclic deterioration on: a monotonic path never uses it


def published_backbone(theta: float, side: dict[str, float]) -> float:
    """Lignos & Krawinkler (2011) backbone of one side at a rotation ``theta >= 0``."""
    my, mc = side["m_y"], side["mc_my"] * side["m_y"]
    theta_y = my / K0
    theta_c = theta_y + side["theta_p"]
    if theta >= side["theta_u"]:
        return 0.0
    if theta <= theta_y:
        return K0 * theta
    if theta <= theta_c:
        return my + (mc - my) / side["theta_p"] * (theta - theta_y)
    return max(mc - mc / side["theta_pc"] * (theta - theta_c), side["kappa"] * my)


def backbone_rotations(side: dict[str, float]) -> list[float]:
    """Sample rotations: each characteristic point, and points between them."""
    theta_y = side["m_y"] / K0
    theta_c = theta_y + side["theta_p"]
    theta_r = theta_c + side["theta_pc"] * (1.0 - side["kappa"] / side["mc_my"])
    marks = [0.0, 0.5 * theta_y, theta_y, 0.5 * (theta_y + theta_c), theta_c,
             0.5 * (theta_c + theta_r), theta_r, 0.5 * (theta_r + side["theta_u"]),
             side["theta_u"] * (1 - 1e-9), side["theta_u"], 1.2 * side["theta_u"]]
    assert theta_r < side["theta_u"]
    return marks


@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
@pytest.mark.parametrize("sign", [1, -1])
def test_monotonic_backbone_point_by_point(cls: type, sign: int) -> None:
    side = POS if sign > 0 else NEG
    rotations = backbone_rotations(side)
    law = _law(cls)
    moments = moment_path(law, [sign * t for t in rotations])
    expected = [sign * published_backbone(t, side) for t in rotations]
    np.testing.assert_allclose(moments, expected, rtol=1e-12, atol=1e-9 * side["m_y"])
    # yield, capping, residual: the published points themselves
    theta_y = side["m_y"] / K0
    assert moments[2] == pytest.approx(sign * side["m_y"], rel=1e-12)
    assert moments[4] == pytest.approx(sign * side["mc_my"] * side["m_y"], rel=1e-12)
    assert moments[6] == pytest.approx(sign * side["kappa"] * side["m_y"], rel=1e-12)
    assert moments[-2] == 0.0 and moments[-1] == 0.0  # at and beyond θ_u
    assert theta_y > 0.0


@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
@pytest.mark.parametrize("sign", [1, -1])
def test_branches_are_the_backbone_segments(cls: type, sign: int) -> None:
    """branch() gives the exact tangents and breakpoints of the monotonic backbone."""
    side = POS if sign > 0 else NEG
    my, mc = side["m_y"], side["mc_my"] * side["m_y"]
    theta_y = my / K0
    theta_c = theta_y + side["theta_p"]
    theta_r = theta_c + side["theta_pc"] * (1.0 - side["kappa"] / side["mc_my"])
    expected = [(K0, theta_y), ((mc - my) / side["theta_p"], theta_c),
                (-mc / side["theta_pc"], theta_r), (0.0, side["theta_u"])]
    law = _law(cls)
    state = law.start()
    for k_t, end in expected:
        br = law.branch(state, sign)
        assert br.k_t == pytest.approx(k_t, rel=1e-12)
        assert br.theta_end == pytest.approx(sign * end, rel=1e-12)
        state = law.moved(state, br.theta_end)
    assert state.moment == 0.0  # fractured at θ_u
    assert law.branch(state, sign).k_t == 0.0


def test_symmetric_defaults_and_peak_oriented_equals_bilinear_monotonically() -> None:
    a = IMKBilinear(k0=K0, m_y=3e5, theta_p=0.02, theta_pc=0.1)
    b = IMKPeakOriented(k0=K0, m_y=3e5, theta_p=0.02, theta_pc=0.1)
    path = np.linspace(0.0, 0.3, 61)
    np.testing.assert_array_equal(moment_path(a, path), -moment_path(a, -path))
    np.testing.assert_array_equal(moment_path(a, path), moment_path(b, path))
    assert a.sides[1] == a.sides[-1]
    assert math.isinf(a.theta_u) and moment_path(a, [0.0, 10.0])[-1] == pytest.approx(0.4 * 3e5)


@pytest.mark.parametrize(("field", "value"), [
    ("theta_p", 0.0), ("theta_pc", -0.1), ("theta_u", math.nan), ("mc_my", 0.9),
    ("kappa", 1.0), ("kappa", -0.1), ("lambda_", -1.0), ("lambda_k", -0.5), ("c", 0.0),
    ("c_s", math.inf), ("d_pos", 1.5), ("d_neg", -0.1), ("m_y_neg", 0.0),
    ("theta_p_neg", math.inf), ("kappa_neg", 2.0), ("theta_u_neg", 0.001),
    ("mc_my", 10.0), ("theta_p", "wide"),
])
@pytest.mark.parametrize("cls", [IMKBilinear, IMKPeakOriented])
def test_bad_constants_name_the_field_and_value(cls: type, field: str, value: object) -> None:
    kwargs: dict[str, object] = {"k0": K0, "m_y": 3e5, "theta_p": 0.02, "theta_pc": 0.1}
    kwargs[field] = value
    with pytest.raises(ValueError) as err:
        cls(**kwargs)
    message = str(err.value)
    assert "\n" not in message
    assert f"{cls.label}.{field}:" in message
    assert repr(value) in message


def test_bad_peak_oriented_only_constants() -> None:
    with pytest.raises(ValueError, match=r"imk-peak-oriented\.lambda_a: .*\(got -2\.0\)"):
        IMKPeakOriented(k0=K0, m_y=3e5, theta_p=0.02, theta_pc=0.1, lambda_a=-2.0)
    with pytest.raises(ValueError, match=r"imk-peak-oriented\.c_a: .*\(got 0\)"):
        IMKPeakOriented(k0=K0, m_y=3e5, theta_p=0.02, theta_pc=0.1, c_a=0)
    with pytest.raises(ValueError, match=r"imk-bilinear\.k0: .*\(got -1\.0\)"):
        IMKBilinear(k0=-1.0, m_y=3e5, theta_p=0.02, theta_pc=0.1)
