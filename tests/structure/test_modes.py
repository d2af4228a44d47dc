"""Modal analysis: orthogonality, Chopra's two-storey frame, effective masses."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.structure import ModalDamping, ShearBuilding, modes


def random_building(seed: int, n: int) -> ShearBuilding:
    rng = np.random.default_rng(seed)
    return ShearBuilding(masses=rng.uniform(1e4, 1e6, n), stiffnesses=rng.uniform(1e6, 1e9, n),
                         heights=rng.uniform(2.5, 5.0, n))


@pytest.mark.parametrize("seed, n", [(0, 1), (1, 2), (2, 4), (3, 8), (4, 15)])
def test_shapes_are_mass_orthonormal_and_periods_descend(seed: int, n: int) -> None:
    b = random_building(seed, n)
    r = modes(b)
    M, K = b.mass_matrix(), b.stiffness_matrix()
    np.testing.assert_allclose(r.shapes.T @ M @ r.shapes, np.eye(n), atol=1e-10)
    np.testing.assert_allclose(r.shapes.T @ K @ r.shapes / r.omegas[0] ** 2,
                               np.diag(r.omegas**2) / r.omegas[0] ** 2, atol=1e-8)
    assert np.all(np.diff(r.periods) < 0)
    assert np.all(r.shapes[-1, :] > 0)  # roof entry positive
    np.testing.assert_allclose(r.periods * r.frequencies, 1.0, rtol=1e-14)


@pytest.mark.parametrize("seed, n", [(5, 1), (6, 3), (7, 6), (8, 12)])
def test_effective_modal_masses_sum_to_total_mass(seed: int, n: int) -> None:
    b = random_building(seed, n)
    r = modes(b)
    assert np.sum(r.effective_masses) == pytest.approx(np.sum(b.masses), rel=1e-10)
    assert np.sum(r.effective_mass_ratios) == pytest.approx(1.0, rel=1e-10)
    # Σ Γₙ φₙ = ι (modal expansion of the influence vector)
    np.testing.assert_allclose(r.modal_contributions.sum(axis=1), np.ones(n), atol=1e-9)


def test_chopra_two_storey_participation_and_effective_masses() -> None:
    # m1 = 2m, m2 = m, k1 = 2k, k2 = k; with shapes (1/2, 1) and (−1, 1) by hand:
    # L₁ = 2m, M₁ = 3m/2 → Γ₁φ₁ = (2/3, 4/3), M₁* = 8m/3;
    # L₂ = −m, M₂ = 3m   → Γ₂φ₂ = (1/3, −1/3), M₂* = m/3.
    m, k = 2.0e5, 1.0e8
    b = ShearBuilding(masses=[2 * m, m], stiffnesses=[2 * k, k], heights=[3.0, 3.0])
    r = modes(b)
    np.testing.assert_allclose(r.modal_contributions[:, 0], [2 / 3, 4 / 3], rtol=1e-12)
    np.testing.assert_allclose(r.modal_contributions[:, 1], [1 / 3, -1 / 3], rtol=1e-12)
    np.testing.assert_allclose(r.effective_masses, [8 * m / 3, m / 3], rtol=1e-12)
    np.testing.assert_allclose(r.periods, 2 * np.pi / np.sqrt([k / (2 * m), 2 * k / m]),
                               rtol=1e-12)


def test_sdof_modal_quantities() -> None:
    m, k = 3.0e4, 1.2e7
    r = modes(ShearBuilding.sdof(m, stiffness=k))
    assert r.n_modes == 1
    assert r.shapes[0, 0] == pytest.approx(1 / np.sqrt(m), rel=1e-14)
    assert r.participation_factors[0] == pytest.approx(np.sqrt(m), rel=1e-14)
    assert r.effective_masses[0] == pytest.approx(m, rel=1e-14)
    assert r.damping_ratios[0] == pytest.approx(0.05, rel=1e-12)


def test_modal_damping_ratios_reported() -> None:
    b = ShearBuilding.uniform(6, 1e5, 1e8, damping=ModalDamping(0.03))
    np.testing.assert_allclose(modes(b).damping_ratios, 0.03, rtol=1e-10)
