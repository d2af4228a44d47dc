"""Flexible bases (soil–structure interaction): the footing's springs and dashpots and the
building on them, against closed forms and independent computations.

* the flexible-base period against Veletsos & Meek (1974): ``T̃ = T √(1 + k/k_x + k h²/k_φ)``;
* the effective damping of a massless footing's building against the replacement oscillator
  (Wolf 1985; first order in the damping), and both against the exact complex root of the
  springs-and-dashpots-in-series oscillator (solved here, not by the model);
* the rocking cone's dashpot against the cone's wave equation integrated numerically with
  its radiation condition (Wolf 1994);
* Pais & Kausel's rectangle: a square's two directions agree, and the disk of the same area
  (sway) or moment of inertia (rocking) within 2 %;
* EN 1998-5 Table 4.1: G/G0 ≈ (Vs/Vs0)² row by row.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from pounding.structure import ModalDamping, ShearBuilding
from pounding.structure.foundation import (
    FlexibleBaseBuilding,
    Footing,
    Soil,
    en1998_5_reduction,
    flexible_base,
    footing_dashpots,
    footing_stiffness,
)
from pounding.structure.foundation.impedance import rocking_wave_velocity
from pounding.structure.foundation.soil import EN1998_5_TABLE_4_1

SOIL = Soil(150.0, 1800.0, 0.33)
G = 1800.0 * 150.0 ** 2


def test_the_issue_example_period_is_veletsos_meek() -> None:
    """1.0e6 kg, T = 0.5 s, h = 10 m on a massless disk R = 5 m: T̃ to rounding."""
    m, T, h, R, nu = 1.0e6, 0.5, 10.0, 5.0, 0.33
    k = m * (2 * math.pi / T) ** 2
    k_x = 8 * G * R / (2 - nu)
    k_th = 8 * G * R ** 3 / (3 * (1 - nu))
    expected = T * math.sqrt(1 + k / k_x + k * h ** 2 / k_th)
    fb = flexible_base(ShearBuilding.sdof(m, period=T, height=h), Footing(radius=R), SOIL)
    assert isinstance(fb, FlexibleBaseBuilding) and fb.n == 1
    assert fb.modes().periods[0] == pytest.approx(expected, rel=1e-12)
    assert fb.foundation.fixed_base_periods[0] == pytest.approx(T, rel=1e-12)
    assert fb.foundation.impedance.k_x == pytest.approx(k_x, rel=1e-14)
    assert fb.foundation.impedance.k_r == pytest.approx(k_th, rel=1e-14)


def _series_root(m: float, k: float, c: float, springs: list[tuple[float, float, float]],
                 guess: float) -> complex:
    """The complex frequency ω of free vibration e^{iωt} of a mass m on a spring-dashpot
    (k, c) in series with the soil's (k_i, c_i, lever_i): −ω² m + K̃(ω) = 0."""
    def residual(v: np.ndarray) -> list[float]:
        w = complex(v[0], v[1])
        flex = 1.0 / (k + 1j * w * c) + sum(lever ** 2 / (ki + 1j * w * ci)
                                            for ki, ci, lever in springs)
        res = -w * w * m + 1.0 / flex
        return [res.real / k, res.imag / k]

    sol = fsolve(residual, [guess, 0.05 * guess], xtol=1e-12)
    return complex(sol[0], sol[1])


@pytest.mark.parametrize("shaking", [None, 0.2])
def test_effective_damping_is_the_replacement_oscillator(shaking: float | None) -> None:
    """ζ̃ of the massless footing's building (its condensed C) equals the replacement
    oscillator's ζ(T/T̃)³ + ζ_x(T_x/T̃)² + ζ_φ(T_φ/T̃)² to rounding, and the exact root of
    the series system within the first-order formula's O(ζ²) error; a footing with a tiny
    mass and inertia (explicit DOFs) has the exact root as its first complex mode."""
    soil = Soil(150.0, 1800.0, 0.33, shaking=shaking)
    m, T, h, zeta = 1.0e6, 0.5, 10.0, 0.05
    b = ShearBuilding.sdof(m, period=T, height=h, damping_ratio=zeta)
    fb = flexible_base(b, Footing(radius=5.0), soil)
    imp = fb.foundation.impedance
    k = m * (2 * math.pi / T) ** 2
    w_t = 2 * math.pi / fb.modes().periods[0]
    T_t = 2 * math.pi / w_t
    zeta_model = fb.damping_matrix()[0, 0] / (2 * m * w_t)
    T_x = 2 * math.pi * math.sqrt(m / imp.k_x)
    T_r = 2 * math.pi * math.sqrt(m * h ** 2 / imp.k_r)
    z_x = w_t * imp.c_x / (2 * imp.k_x)
    z_r = w_t * imp.c_r / (2 * imp.k_r)
    formula = zeta * (T / T_t) ** 3 + z_x * (T_x / T_t) ** 2 + z_r * (T_r / T_t) ** 2
    assert zeta_model == pytest.approx(formula, rel=1e-12)
    assert imp.omega == pytest.approx(w_t, rel=1e-12)
    # the exact complex root of the same springs and dashpots in series
    c = 2 * zeta * m * (2 * math.pi / T)
    w = _series_root(m, k, c, [(imp.k_x, imp.c_x, 1.0), (imp.k_r, imp.c_r, h)], w_t)
    zeta_exact = w.imag / abs(w)
    assert zeta_exact == pytest.approx(formula, abs=3 * formula ** 2)
    # explicit DOFs with a tiny footing mass and inertia: the same root (the dashpots'
    # frequency is the building's first mode either way; take the same impedance)
    tiny = flexible_base(b, Footing(radius=5.0, mass=1.0, inertia=1.0), soil)
    assert tiny.n == 3 and tiny.labels == ("F1", "Fdn", "Fdn_r")
    M, K, C = tiny.mass_matrix(), tiny.stiffness_matrix(), tiny.damping_matrix()
    C[1, 1] += imp.c_x - tiny.foundation.impedance.c_x
    C[2, 2] += imp.c_r - tiny.foundation.impedance.c_r
    n = 3
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -np.linalg.solve(M, K)
    A[n:, n:] = -np.linalg.solve(M, C)
    lam = np.linalg.eigvals(A)
    near = lam[np.argmin(np.abs(np.abs(lam) - abs(w)))]
    assert abs(near) == pytest.approx(abs(w), rel=1e-4)
    assert -near.real / abs(near) == pytest.approx(zeta_exact, rel=1e-3)


def test_rocking_cone_dashpot_is_the_cone_wave_solution() -> None:
    """c_φ(ω) = Im S(ω)/ω of a rocking cone (Wolf 1994), S from the cone's wave equation
    θ'' + (4/z) θ' + (ω/c)² θ = 0 integrated numerically from far away (the outgoing wave
    ~ e^{−iωz/c}/z²) back to the apex distance z0: S = −ρ c² I θ'(z0)/θ(z0)."""
    R = 5.0
    ft = Footing(radius=R, dashpots=True)
    for soil in (SOIL, Soil(150.0, 1800.0, 0.45)):
        c = rocking_wave_velocity(soil)
        I_b = math.pi * R ** 4 / 4
        z0 = 9 * math.pi / 32 * (1 - soil.poisson) * R * (c / soil.vs) ** 2
        k_r = footing_stiffness(ft, soil)[1]
        assert 3 * soil.density * c ** 2 * I_b / z0 == pytest.approx(k_r, rel=1e-12)
        for omega in (2.0, 9.0, 40.0):
            kk = omega / c
            z_far = z0 + 40.0 * (1.0 / kk + z0)

            def outgoing(z: float) -> tuple[complex, complex]:
                g = np.exp(-1j * kk * z) * (1 + 1j * kk * z)
                th = g / z ** 3
                dth = np.exp(-1j * kk * z) * kk ** 2 * z / z ** 3 - 3 * g / z ** 4
                return th, dth

            th, dth = outgoing(z_far)  # (a far field start: the exact outgoing solution)

            def rhs(z: float, y: np.ndarray) -> list[complex]:
                return [y[1], -4.0 / z * y[1] - kk ** 2 * y[0]]

            sol = solve_ivp(rhs, (z_far, z0), [th, dth], rtol=1e-11, atol=1e-30,
                            method="DOP853")
            th0, dth0 = sol.y[0, -1], sol.y[1, -1]
            S = -soil.density * c ** 2 * I_b * dth0 / th0
            c_r = footing_dashpots(ft, soil, omega)[1]
            assert c_r == pytest.approx(S.imag / omega, rel=1e-7)
            assert S.real == pytest.approx(k_r * (1 - (kk * z0) ** 2 / (3 * (1 + (kk * z0) ** 2))),
                                           rel=1e-7)


def test_sway_dashpot_and_material_damping() -> None:
    """c_x = ρ V_s A; the soil's damping adds 2 β k / ω to each dashpot."""
    ft = Footing(radius=5.0)
    c_x, c_r = footing_dashpots(ft, SOIL, 9.0)
    assert c_x == pytest.approx(1800.0 * 150.0 * math.pi * 25.0, rel=1e-14)
    soft = Soil(150.0, 1800.0, 0.33, shaking=0.2)
    k_x, k_r = footing_stiffness(ft, soft)
    assert k_x == pytest.approx(0.5 * footing_stiffness(ft, SOIL)[0], rel=1e-14)
    c_x2, c_r2 = footing_dashpots(ft, soft, 9.0)
    bare = footing_dashpots(Footing(radius=5.0), Soil(150.0 * math.sqrt(0.5), 1800.0, 0.33), 9.0)
    assert c_x2 == pytest.approx(bare[0] + 2 * 0.06 * k_x / 9.0, rel=1e-12)
    assert c_r2 == pytest.approx(bare[1] + 2 * 0.06 * k_r / 9.0, rel=1e-12)
    assert footing_dashpots(Footing(radius=5.0, dashpots=False), SOIL, 9.0) == (0.0, 0.0)


def test_rectangles_square_symmetry_and_the_equivalent_disk() -> None:
    """Pais & Kausel: a square is the same both ways, and within 2 % of the disk of the same
    area (sway) and of the same moment of inertia (rocking)."""
    a = 8.0
    sq = Footing(length=a, width=a)
    k_x, k_r = footing_stiffness(sq, SOIL)
    assert k_x == pytest.approx(footing_stiffness(Footing(length=a, width=a * (1 + 1e-12)),
                                                  SOIL)[0], rel=1e-9)
    assert k_r == pytest.approx(footing_stiffness(Footing(length=a * (1 - 1e-12), width=a),
                                                  SOIL)[1], rel=1e-9)
    r_area = a / math.sqrt(math.pi)
    r_inertia = (a ** 4 / 12 * 4 / math.pi) ** 0.25
    assert k_x == pytest.approx(footing_stiffness(Footing(radius=r_area), SOIL)[0], rel=0.02)
    assert k_r == pytest.approx(footing_stiffness(Footing(radius=r_inertia), SOIL)[1], rel=0.02)
    # longer along the row: stiffer in rocking than across, softer in sway (Gazetas 1991:
    # the longitudinal K_x = K_y − 0.2/(0.75 − ν) G L (1 − B/L), below the lateral K_y)
    long_ = footing_stiffness(Footing(length=2 * a, width=a), SOIL)
    wide = footing_stiffness(Footing(length=a, width=2 * a), SOIL)
    assert long_[1] > 2.5 * wide[1] and long_[0] < wide[0]
    nu = SOIL.poisson
    for ratio in (1.0, 1.5, 2.0, 3.0, 4.0):
        L, B = ratio * a / 2, a / 2
        k_lat = 2 * G * L / (2 - nu) * (2 + 2.5 * (B / L) ** 0.85)  # Gazetas, across L
        k_lon = k_lat - 0.2 / (0.75 - nu) * G * L * (1 - B / L)  # Gazetas, along L
        along = footing_stiffness(Footing(length=2 * L, width=2 * B), SOIL)[0]
        across = footing_stiffness(Footing(length=2 * B, width=2 * L), SOIL)[0]
        assert along == pytest.approx(k_lon, rel=0.035), ratio
        assert across == pytest.approx(k_lat, rel=0.035), ratio


def test_en1998_5_table_4_1() -> None:
    """The table's rows, and G/G0 close to (Vs/Vs0)² (the table's own consistency)."""
    for alpha, beta, v_ratio, g_ratio in EN1998_5_TABLE_4_1:
        assert en1998_5_reduction(alpha) == (g_ratio, beta)
        assert g_ratio == pytest.approx(v_ratio ** 2, abs=0.015)
    with pytest.raises(ValueError, match="shaking"):
        en1998_5_reduction(0.35)


def test_flexible_base_mdof_stiffness_is_the_transformed_one() -> None:
    """A 3-storey building on a footing with mass: K_y = Tᵀ K T + soil, written out here
    entry by entry from the deformations, and its fixed-base damping acting on them."""
    b = ShearBuilding(masses=[2e5, 2e5, 1.5e5], stiffnesses=[3e8, 2.5e8, 2e8],
                      heights=[4.0, 3.0, 3.0], damping=ModalDamping(0.04))
    fb = flexible_base(b, Footing(radius=6.0, mass=4e5, inertia=3e6), SOIL)
    imp = fb.foundation.impedance
    z = np.array([4.0, 7.0, 10.0])
    k = np.array([3e8, 2.5e8, 2e8])
    # energy ½ Σ k_j (x_j − x_{j−1} − (z_j − z_{j−1}) φ)² (x_0 = u_f, z_0 = 0) + soil
    K = np.zeros((5, 5))
    zb = np.r_[0.0, z]
    for j in range(3):
        g = np.zeros(5)
        g[j] += 1.0
        if j:
            g[j - 1] -= 1.0
        else:
            g[3] -= 1.0
        g[4] -= zb[j + 1] - zb[j]
        K += k[j] * np.outer(g, g)
    K[3, 3] += imp.k_x
    K[4, 4] += imp.k_r
    assert np.allclose(fb.stiffness_matrix(), K, rtol=1e-13, atol=1e-6)
    assert np.array_equal(np.diag(fb.mass_matrix()), [2e5, 2e5, 1.5e5, 4e5, 3e6])
    assert list(fb.influence_vector()) == [1, 1, 1, 1, 0]
    # rigid-body motion of the whole (sway + rocking together) deforms nothing
    rigid = np.r_[1.0 + 0.01 * z, 1.0, 0.01]
    assert np.allclose(fb.damping_matrix() @ rigid, [0, 0, 0, imp.c_x, imp.c_r * 0.01],
                       atol=1e-6 * imp.c_x)


def test_refusals() -> None:
    b = ShearBuilding.sdof(1e6, period=0.5)
    with pytest.raises(ValueError, match="radius"):
        Footing(radius=-1.0)
    with pytest.raises(ValueError, match="not both"):
        Footing(radius=1.0, length=2.0, width=2.0)
    with pytest.raises(ValueError, match="poisson"):
        Soil(150.0, 1800.0, 0.5)
    from pounding.hysteresis.bilinear import Bilinear

    yielding = b.with_storey_law(Bilinear(yield_force=1e6))
    with pytest.raises(ValueError, match="foundation.mass: a yielding building's footing"):
        flexible_base(yielding, Footing(radius=5.0), SOIL)
    with pytest.raises(ValueError, match="foundation.inertia: a yielding building's footing"):
        flexible_base(yielding, Footing(radius=5.0, mass=1e5), SOIL)
