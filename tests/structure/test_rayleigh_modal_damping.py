"""Damping models: target ratios reproduced in the modes, checked through Φᵀ C Φ.

The modes are recomputed here with numpy's standard eigensolver on M^-1/2 K M^-1/2, not with
the package's own modal code.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.structure import ModalDamping, RayleighDamping, ShearBuilding, rayleigh_coefficients


def independent_modes(M: np.ndarray, K: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """ω ascending and M-orthonormal Φ via the symmetric standard problem."""
    s = 1.0 / np.sqrt(np.diag(M))  # M is diagonal for a shear building
    lam, v = np.linalg.eigh(s[:, None] * K * s[None, :])
    return np.sqrt(lam), s[:, None] * v


def modal_ratios(b: ShearBuilding) -> tuple[np.ndarray, np.ndarray]:
    M, K, C = b.mass_matrix(), b.stiffness_matrix(), b.damping_matrix()
    w, phi = independent_modes(M, K)
    Cn = phi.T @ C @ phi
    Mn = np.diag(phi.T @ M @ phi)
    return np.diag(Cn) / (2.0 * w * Mn), Cn


def building(damping) -> ShearBuilding:
    return ShearBuilding(masses=[3.0e5, 2.5e5, 2.5e5, 2.0e5, 1.5e5],
                         stiffnesses=[4.0e8, 3.5e8, 3.0e8, 2.5e8, 2.0e8],
                         heights=[4.0, 3.0, 3.0, 3.0, 3.0], damping=damping)


@pytest.mark.parametrize("mi, mj, zi, zj", [(1, 2, 0.05, 0.05), (1, 3, 0.05, 0.03),
                                            (2, 4, 0.03, 0.04), (3, 1, 0.04, 0.05)])
def test_rayleigh_reproduces_its_two_targets(mi: int, mj: int, zi: float, zj: float) -> None:
    b = building(RayleighDamping(zi, zj, mode_i=mi, mode_j=mj))
    zeta, Cn = modal_ratios(b)
    assert zeta[mi - 1] == pytest.approx(zi, rel=1e-10)
    assert zeta[mj - 1] == pytest.approx(zj, rel=1e-10)
    # classical damping: Φᵀ C Φ is diagonal
    off = Cn - np.diag(np.diag(Cn))
    assert np.max(np.abs(off)) < 1e-9 * np.max(np.abs(Cn))


def test_rayleigh_equal_ratios_matches_textbook_coefficients_and_curve() -> None:
    z = 0.05
    b = building(RayleighDamping(z))
    w, _ = independent_modes(b.mass_matrix(), b.stiffness_matrix())
    a0 = z * 2.0 * w[0] * w[1] / (w[0] + w[1])  # Chopra §11.4.1, equal ratios
    a1 = z * 2.0 / (w[0] + w[1])
    np.testing.assert_allclose(b.damping_matrix(), a0 * b.mass_matrix() + a1 * b.stiffness_matrix(),
                               rtol=1e-10)
    zeta, _ = modal_ratios(b)
    np.testing.assert_allclose(zeta, a0 / (2 * w) + a1 * w / 2, rtol=1e-10)
    assert np.all(zeta[2:] > z)  # stiffness term over-damps the higher modes


def test_rayleigh_coefficients_solve_the_two_by_two_system() -> None:
    wi, wj, zi, zj = 3.0, 17.0, 0.02, 0.06
    a0, a1 = rayleigh_coefficients(wi, wj, zi, zj)
    A = 0.5 * np.array([[1 / wi, wi], [1 / wj, wj]])
    np.testing.assert_allclose([a0, a1], np.linalg.solve(A, [zi, zj]), rtol=1e-12)


def test_rayleigh_by_periods_hits_the_ratios_at_those_periods() -> None:
    d = RayleighDamping.from_periods(1.5, 0.2, zeta_i=0.05, zeta_j=0.04)
    b = building(d)
    a0, a1 = d.coefficients(b.mass_matrix(), b.stiffness_matrix())
    for T, z in ((1.5, 0.05), (0.2, 0.04)):
        w = 2 * math.pi / T
        assert a0 / (2 * w) + a1 * w / 2 == pytest.approx(z, rel=1e-12)


@pytest.mark.parametrize("z", [0.0, 0.02, 0.05, 0.2])
def test_modal_damping_gives_zeta_in_every_mode(z: float) -> None:
    b = building(ModalDamping(z))
    zeta, Cn = modal_ratios(b)
    np.testing.assert_allclose(zeta, z, atol=1e-12)
    off = Cn - np.diag(np.diag(Cn))
    assert np.max(np.abs(off)) <= 1e-9 * max(np.max(np.abs(Cn)), 1.0)
    C = b.damping_matrix()
    np.testing.assert_allclose(C, C.T, atol=0.0)
    assert np.all(np.linalg.eigvalsh(C) >= -1e-9 * np.max(np.abs(C)))


@pytest.mark.parametrize("damping", [RayleighDamping(0.05), ModalDamping(0.05),
                                     RayleighDamping(0.05, mode_j=7)])
def test_sdof_damping_is_two_zeta_m_omega(damping) -> None:
    m, k = 2.0e5, 8.0e7
    b = ShearBuilding(masses=[m], stiffnesses=[k], heights=[3.0], damping=damping)
    c = 2.0 * 0.05 * m * math.sqrt(k / m)  # ζ = c / (2 m ω), Chopra §2.2
    np.testing.assert_allclose(b.damping_matrix(), [[c]], rtol=1e-12)


def test_sdof_rayleigh_with_two_ratios_is_refused() -> None:
    with pytest.raises(ValueError, match=r"zeta_j \(0.02\).*zeta_i \(0.05\)"):
        ShearBuilding(masses=[1.0], stiffnesses=[1.0], heights=[3.0],
                      damping=RayleighDamping(0.05, 0.02))


@pytest.mark.parametrize("kwargs, words", [
    (dict(zeta_i=-0.01), ["zeta_i", "-0.01"]),
    (dict(zeta_i=0.05, zeta_j=2.0), ["zeta_j", "2"]),
    (dict(zeta_i=0.05, mode_i=0), ["mode_i", "0"]),
    (dict(zeta_i=0.05, mode_j=1.5), ["mode_j", "1.5"]),
    (dict(zeta_i=0.05, mode_i=2, mode_j=2), ["mode_i", "mode_j", "2"]),
    (dict(zeta_i=0.05, period_i=1.0), ["period_i", "period_j"]),
    (dict(zeta_i=0.05, period_i=1.0, period_j=-0.1), ["period_j", "-0.1"]),
    (dict(zeta_i=0.05, period_i=0.5, period_j=0.5), ["omega_i", "omega_j"]),
    (dict(zeta_i=0.10, zeta_j=0.001, period_i=1.0, period_j=0.1), ["negative"]),
])
def test_rayleigh_bad_input(kwargs: dict, words: list[str]) -> None:
    with pytest.raises(ValueError) as info:
        RayleighDamping(**kwargs)
    for w in words:
        assert w in str(info.value)


def test_modal_damping_bad_ratio() -> None:
    with pytest.raises(ValueError, match=r"zeta.*nan"):
        ModalDamping(float("nan"))


def test_damping_matrix_rejects_malformed_matrices() -> None:
    with pytest.raises(ValueError, match="K"):
        ModalDamping(0.05).matrix(np.eye(2), np.eye(3))
    with pytest.raises(ValueError, match="positive definite"):
        ModalDamping(0.05).matrix(np.eye(2), np.zeros((2, 2)))
