"""ShearBuilding: matrices against hand-written ones, periods against closed forms, validation."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.structure import ModalDamping, RayleighDamping, ShearBuilding


def test_stiffness_matrix_three_storeys_by_hand() -> None:
    k1, k2, k3 = 3.0e7, 2.0e7, 1.0e7
    b = ShearBuilding(masses=[1.0, 1.0, 1.0], stiffnesses=[k1, k2, k3], heights=[4.0, 3.0, 3.0])
    expected = np.array([[k1 + k2, -k2, 0.0],
                         [-k2, k2 + k3, -k3],
                         [0.0, -k3, k3]])
    np.testing.assert_array_equal(b.stiffness_matrix(), expected)


def test_mass_matrix_influence_and_geometry() -> None:
    b = ShearBuilding(masses=[3.0, 2.0, 1.0], stiffnesses=[1.0, 1.0, 1.0], heights=[4.0, 3.0, 3.5])
    np.testing.assert_array_equal(b.mass_matrix(), np.diag([3.0, 2.0, 1.0]))
    np.testing.assert_array_equal(b.influence_vector(), np.ones(3))
    np.testing.assert_allclose(b.floor_levels, [4.0, 7.0, 10.5])
    assert b.total_height == pytest.approx(10.5)
    assert b.total_mass == pytest.approx(6.0)
    assert b.n == 3


def test_single_storey_stiffness_matrix_is_k() -> None:
    b = ShearBuilding(masses=[5.0], stiffnesses=[7.0], heights=[3.0])
    np.testing.assert_array_equal(b.stiffness_matrix(), [[7.0]])


def test_matrices_are_float64_contiguous_and_independent_copies() -> None:
    b = ShearBuilding.uniform(4, 1.0e5, 1.0e8)
    for A in (b.mass_matrix(), b.stiffness_matrix(), b.damping_matrix()):
        assert A.dtype == np.float64 and A.flags.c_contiguous and A.flags.writeable
    K = b.stiffness_matrix()
    K[0, 0] = -1.0
    assert b.stiffness_matrix()[0, 0] == 2.0e8
    with pytest.raises(ValueError):
        b.masses[0] = 1.0  # stored arrays are read-only


@pytest.mark.parametrize("m, k", [(1.0, 1.0), (2.5e5, 3.0e7), (1.0e3, 4.0e4)])
def test_sdof_period_is_two_pi_sqrt_m_over_k(m: float, k: float) -> None:
    b = ShearBuilding.sdof(m, stiffness=k)
    assert b.fundamental_period == pytest.approx(2.0 * math.pi * math.sqrt(m / k), rel=1e-12)


def test_sdof_from_period_gives_k_from_omega_squared() -> None:
    b = ShearBuilding.sdof(2.0e5, period=0.8)
    assert b.stiffnesses[0] == pytest.approx(2.0e5 * (2.0 * math.pi / 0.8) ** 2, rel=1e-14)
    assert b.fundamental_period == pytest.approx(0.8, rel=1e-12)
    assert isinstance(b.damping, ModalDamping)


@pytest.mark.parametrize("n", [1, 2, 3, 5, 10])
def test_uniform_building_frequencies_closed_form(n: int) -> None:
    # fixed-free uniform chain: ω_j = 2 √(k/m) sin((2j−1)π / (2(2n+1)))
    m, k = 1.2e5, 9.0e7
    b = ShearBuilding.uniform(n, m, k)
    j = np.arange(1, n + 1)
    omega = 2.0 * np.sqrt(k / m) * np.sin((2 * j - 1) * np.pi / (2 * (2 * n + 1)))
    np.testing.assert_allclose(b.modes().omegas, omega, rtol=1e-10)
    np.testing.assert_allclose(b.modes().periods, 2.0 * np.pi / omega, rtol=1e-10)


def test_chopra_two_storey_frame() -> None:
    # m1 = 2m, m2 = m, k1 = 2k, k2 = k  →  ω₁² = k/(2m), ω₂² = 2k/m
    # (Chopra, Dynamics of Structures, the two-storey shear frame of Ch. 10);
    # shapes φ₁ ∝ (1/2, 1), φ₂ ∝ (−1, 1).
    m, k = 1.0e5, 5.0e7
    b = ShearBuilding(masses=[2 * m, m], stiffnesses=[2 * k, k], heights=[3.0, 3.0])
    r = b.modes()
    np.testing.assert_allclose(r.omegas**2, [k / (2 * m), 2 * k / m], rtol=1e-12)
    np.testing.assert_allclose(r.shapes[:, 0] / r.shapes[1, 0], [0.5, 1.0], rtol=1e-12)
    np.testing.assert_allclose(r.shapes[:, 1] / r.shapes[1, 1], [-1.0, 1.0], rtol=1e-12)


def test_with_period_scales_stiffness_and_keeps_shapes() -> None:
    b = ShearBuilding(masses=[3e5, 2e5, 1e5], stiffnesses=[6e7, 4e7, 2e7], heights=[3.0] * 3)
    c = b.with_period(0.7)
    assert c.fundamental_period == pytest.approx(0.7, rel=1e-12)
    np.testing.assert_allclose(c.stiffnesses / b.stiffnesses,
                               (b.fundamental_period / 0.7) ** 2, rtol=1e-12)
    np.testing.assert_allclose(c.modes().shapes, b.modes().shapes, atol=1e-12)


def test_equality_is_by_value() -> None:
    a = ShearBuilding.uniform(3, 1.0, 2.0, name="x")
    assert a == ShearBuilding(masses=[1.0] * 3, stiffnesses=[2.0] * 3, heights=[3.0] * 3,
                              name="x")
    assert a != ShearBuilding.uniform(3, 1.0, 2.0, name="y")


# --------------------------------------------------------------------------- validation
GOOD = dict(masses=[1.0, 1.0], stiffnesses=[1.0, 1.0], heights=[3.0, 3.0])


@pytest.mark.parametrize("field, value, words", [
    ("masses", [1.0, -2.0], ["masses[1]", "-2"]),
    ("masses", [0.0, 1.0], ["masses[0]", "0"]),
    ("stiffnesses", [1.0, float("nan")], ["stiffnesses[1]", "nan"]),
    ("heights", [3.0, 0.0], ["heights[1]", "0"]),
    ("heights", [3.0, float("inf")], ["heights[1]", "inf"]),
    ("stiffnesses", [1.0, 1.0, 1.0], ["stiffnesses", "3"]),
    ("heights", [3.0], ["heights", "1"]),
    ("masses", [], ["masses"]),
    ("masses", [[1.0, 1.0]], ["masses", "shape"]),
    ("masses", ["a", "b"], ["masses", "'a'"]),
    ("damping", 0.05, ["damping", "0.05"]),
    ("name", 3, ["name", "3"]),
])
def test_bad_fields_raise_naming_field_and_value(field: str, value: object,
                                                 words: list[str]) -> None:
    kwargs = dict(GOOD, **{field: value})
    with pytest.raises(ValueError) as info:
        ShearBuilding(**kwargs)  # type: ignore[arg-type]
    for w in words:
        assert w in str(info.value)


@pytest.mark.parametrize("kwargs, words", [
    (dict(mass=1.0), ["stiffness", "period"]),
    (dict(mass=1.0, stiffness=1.0, period=1.0), ["stiffness", "period"]),
    (dict(mass=-1.0, stiffness=1.0), ["mass", "-1"]),
    (dict(mass=1.0, period=0.0), ["period", "0"]),
    (dict(mass=1.0, stiffness=1.0, damping_ratio=1.5), ["zeta", "1.5"]),
    (dict(mass=1.0, stiffness=1.0, height=-3.0), ["height", "-3"]),
])
def test_sdof_bad_input(kwargs: dict, words: list[str]) -> None:
    with pytest.raises(ValueError) as info:
        ShearBuilding.sdof(**kwargs)
    for w in words:
        assert w in str(info.value)


@pytest.mark.parametrize("n", [0, -2, 2.0, True, "3"])
def test_uniform_bad_storey_count(n: object) -> None:
    with pytest.raises(ValueError, match="n_storeys"):
        ShearBuilding.uniform(n, 1.0, 1.0)  # type: ignore[arg-type]


def test_damping_that_does_not_fit_the_building_fails_at_construction() -> None:
    with pytest.raises(ValueError, match=r"mode_j .*3.* \(got 5\)"):
        ShearBuilding.uniform(3, 1.0, 1.0, damping=RayleighDamping(0.05, mode_j=5))
