"""A building in plan on a flexible base (:mod:`pounding.structure.foundation.plan_base`),
against closed forms and computations independent of the code under test:

* a symmetric plan on a disk is, along x, the row's flexible base of its x frames: the same
  matrices and periods (its x block), no torsion;
* a one-storey plan on a footing that only twists: the torsional period of the storey's
  torsional stiffness and the soil's in series (hand-derived; a footing inertia: the
  two-DOF closed form);
* the footing's rigid motion moves every point of every floor as a small rotation about
  the footing's centre does (cross product), and leaves the building undeformed (no force
  on the floors, the soil's springs on the footing);
* the torsion dashpot against the torsional cone's wave equation integrated numerically with
  its radiation condition (Wolf 1994); the torsion springs of the circle (16GR³/3) and of
  Pais & Kausel's rectangle (NIST GCR 12-917-21 Table 2-2a), the across-the-row rectangle;
* the model file: ``foundation`` accepted for a building in plan, refused for a frame and
  with a storey law (one line naming the field).
"""

from __future__ import annotations

import copy
import math
from typing import Any

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from pounding.config import parse_config
from pounding.structure import RayleighDamping, ShearBuilding
from pounding.structure.foundation import (
    FlexibleBaseBuilding,
    Footing,
    PlanFlexibleBaseBuilding,
    Soil,
    flexible_base,
    plan_flexible_base,
)
from pounding.structure.foundation.impedance import footing_dashpots, footing_torsion
from pounding.structure.plan import LateralElement, PlanBuilding

SOIL = Soil(150.0, 1800.0, 0.33)
G = 1800.0 * 150.0 ** 2
RAYLEIGH = RayleighDamping.from_periods(0.5, 0.1)
"""The same Rayleigh coefficients whatever the modes (the plan building has more of them)."""


def symmetric_plan(kx: list[float], ky: list[float], masses: list[float],
                   heights: list[float], width: float = 20.0, depth: float = 12.0
                   ) -> PlanBuilding:
    """Frames at the four edges, each direction's stiffness shared equally: the centres of
    mass and stiffness at the plan's centre."""
    hx, hy = np.asarray(kx) / 2, np.asarray(ky) / 2
    return PlanBuilding(masses=masses, heights=heights, width=width, depth=depth,
                        damping=RAYLEIGH, elements=[
                            LateralElement(0.0, 0.0, "x", hx),
                            LateralElement(0.0, depth, "x", hx),
                            LateralElement(0.0, depth / 2, "y", hy),
                            LateralElement(width, depth / 2, "y", hy)])


@pytest.mark.parametrize("footing", [Footing(radius=6.0),
                                     Footing(radius=6.0, mass=3.0e5, inertia=2.7e6)])
def test_a_symmetric_plan_on_a_disk_is_the_row_flexible_base_along_x(footing: Footing) -> None:
    """The x DOFs, the footing's sway along x and rocking about y of a symmetric plan on a
    disk are the row's flexible base of its x frames (a shear building): the same stiffness,
    damping and mass to 1e-12, its periods among the plan's, the same dashpots (taken at the
    same first mode: the x mode is the first, y and torsion stiffer); no coupling to y or
    torsion."""
    kx, ky = [3e8, 2e8, 1e8], [6e8, 5e8, 4e8]
    masses, heights = [3e5, 3e5, 2e5], [4.0, 3.0, 3.0]
    plan = plan_flexible_base(symmetric_plan(kx, ky, masses, heights), footing, SOIL)
    row = flexible_base(ShearBuilding(masses, kx, heights, damping=RAYLEIGH), footing, SOIL)
    assert isinstance(plan, PlanFlexibleBaseBuilding)
    labels = list(plan.labels)
    x_dofs = [labels.index(f"F{j + 1}x") for j in range(3)]
    if footing.mass > 0:
        assert labels[9:] == ["Fdn_x", "Fdn_y", "Fdn_rx", "Fdn_ry", "Fdn_t"]
        x_dofs += [labels.index("Fdn_x"), labels.index("Fdn_ry")]
    else:
        assert labels == [f"F{j}{c}" for j in (1, 2, 3) for c in "xyθ"]
    ix = np.ix_(x_dofs, x_dofs)
    others = np.setdiff1d(np.arange(plan.n), x_dofs)
    for A, B in ((plan.M, row.M), (plan.K, row.K), (plan.damping_matrix(), row.damping_matrix())):
        assert np.allclose(A[ix], B, rtol=0, atol=1e-12 * np.abs(B).max())
        assert np.abs(A[np.ix_(x_dofs, others)]).max() <= 1e-12 * np.abs(B).max()
    fi, ri = plan.foundation.impedance, row.foundation.impedance
    assert fi.omega == pytest.approx(ri.omega, rel=1e-12)
    assert fi.springs[0] == pytest.approx(ri.k_x, rel=1e-14)
    assert fi.springs[3] == pytest.approx(ri.k_r, rel=1e-14)
    assert fi.dashpots[0] == pytest.approx(ri.c_x, rel=1e-12)
    assert fi.dashpots[3] == pytest.approx(ri.c_r, rel=1e-12)
    # a disk is the same both ways: sway along y and rocking about x are those along x / y
    assert fi.springs[1] == fi.springs[0] and fi.springs[2] == fi.springs[3]
    periods = plan.modes().periods
    for t in row.modes().periods:
        assert np.min(np.abs(periods - t)) < 1e-10 * t


def _one_storey_torsion(footing_inertia: float) -> tuple[PlanBuilding, PlanFlexibleBaseBuilding]:
    b = symmetric_plan([2e8], [3e8], [4e5], [3.5], width=20.0, depth=10.0)
    fb = plan_flexible_base(b, Footing(radius=5.0), SOIL, inertias=(0.0, 0.0, footing_inertia))
    return b, fb


def test_the_torsional_period_is_the_storey_and_the_soil_in_series() -> None:
    """One storey, symmetric, on a massless disk: the torsional mode's period is
    ``2π √(I / k_s)`` with ``1/k_s = 1/k_θ + 1/k_t``, ``k_θ = Σ k_e d_e²`` the storey's
    torsional stiffness about the centre (frames at d = 5 m (x) and 10 m (y)) and
    ``k_t = 16 G R³/3``; with a footing inertia ``I_f`` about the vertical, the two roots of
    ``det([[k_θ, −k_θ], [−k_θ, k_θ + k_t]] − ω² diag(I, I_f)) = 0``."""
    I = 4e5 * (20.0 ** 2 + 10.0 ** 2) / 12.0
    k_theta = 2 * (1e8 * 5.0 ** 2) + 2 * (1.5e8 * 10.0 ** 2)
    k_t = 16.0 * G * 5.0 ** 3 / 3.0
    k_s = 1.0 / (1.0 / k_theta + 1.0 / k_t)
    b, fb = _one_storey_torsion(0.0)
    fixed = b.modes().periods
    assert np.min(np.abs(fixed - 2 * math.pi * math.sqrt(I / k_theta))) < 1e-12
    periods = fb.modes().periods
    expected = 2 * math.pi * math.sqrt(I / k_s)
    assert np.min(np.abs(periods - expected)) < 1e-10 * expected
    # with the footing's inertia about the vertical: ω⁴ I I_f − ω² (I (k_θ + k_t) + I_f k_θ)
    # + k_θ k_t = 0
    I_f = 0.3 * I
    _, fb = _one_storey_torsion(I_f)
    assert fb.labels[-1] == "Fdn_t" and fb.n == 4
    a, bq, c = I * I_f, -(I * (k_theta + k_t) + I_f * k_theta), k_theta * k_t
    disc = math.sqrt(bq * bq - 4 * a * c)
    periods = fb.modes().periods
    for w2 in ((-bq - disc) / (2 * a), (-bq + disc) / (2 * a)):
        t = 2 * math.pi / math.sqrt(w2)
        assert np.min(np.abs(periods - t)) < 1e-9 * t


def test_the_footings_rigid_motion_is_a_small_rotation_and_deforms_nothing() -> None:
    """An eccentric two-storey plan (mass centres off the footing's centre, given): the
    footing's motion y_f moves every corner of every floor by ``u_f + ω × r`` (ω = (φ_x,
    φ_y, ψ), r from the footing's centre at the ground; the horizontal part), written out
    here; the building so moved is not deformed: ``K_y [A y_f; y_f]`` is zero on the floors
    and the soil's springs on the footing."""
    b = PlanBuilding(masses=[3e5, 2e5], heights=[4.0, 3.0], width=16.0, depth=10.0,
                     mass_centres=[[6.0, 4.0], [9.0, 7.0]], elements=[
                         LateralElement(0.0, 0.0, "x", [1e8, 8e7]),
                         LateralElement(0.0, 10.0, "x", [3e8, 2e8]),
                         LateralElement(0.0, 5.0, "y", [2e8, 1e8]),
                         LateralElement(16.0, 5.0, "y", [2e8, 1e8])])
    centre = (7.0, 5.5)
    fb = plan_flexible_base(b, Footing(length=16.0, width=10.0, mass=1e5, inertia=1e6),
                            SOIL, centre=centre)
    assert fb.n == 11
    yf = np.array([0.01, -0.02, 3e-3, -2e-3, 4e-3])  # u_fx, u_fy, φ_x, φ_y, ψ
    x = fb.foundation.rigid @ yf
    for floor, z in enumerate(b.floor_levels):
        for px, py in ((0.0, 0.0), (16.0, 0.0), (16.0, 10.0), (0.0, 10.0)):
            r = np.array([px - centre[0], py - centre[1], z])
            expected = yf[:2] + np.cross(yf[2:], r)[:2]
            for k, direction in enumerate("xy"):
                got = b.point_displacement(x, floor, px, py, direction)
                assert got == pytest.approx(expected[k], abs=1e-15)
    y = np.r_[x, yf]
    force = fb.K @ y
    scale = np.abs(fb.K).max() * np.abs(y).max()
    assert np.abs(force[:6]).max() < 1e-12 * scale
    assert np.allclose(force[6:], np.asarray(fb.foundation.impedance.springs) * yf,
                       rtol=1e-10, atol=0)
    assert np.abs(fb.foundation.deformation(y[None, :])).max() < 1e-17


def test_torsion_dashpot_is_the_torsional_cone_wave_solution() -> None:
    """c_t(ω) = Im S(ω)/ω of a torsional cone (Wolf 1994), S from the cone's wave equation
    ϑ'' + (4/z) ϑ' + (ω/V_s)² ϑ = 0 (the disk at z has polar moment J (z/z0)⁴) integrated
    numerically from far away (the outgoing wave ~ e^{−iωz/V_s}(1 + iωz/V_s)/z³) back to
    z0 = (9π/32) r0: S = −G J ϑ'(z0)/ϑ(z0); its real part the cone's static stiffness
    3GJ/z0 = 16 G r0³/3 softened by ⅓ b0²/(1 + b0²). A rectangle: the disk of the same J."""
    for footing in (Footing(radius=5.0), Footing(length=16.0, width=10.0)):
        if footing.radius is not None:
            J = math.pi * 5.0 ** 4 / 2
        else:
            J = 16.0 * 10.0 * (16.0 ** 2 + 10.0 ** 2) / 12.0
        r0 = (2 * J / math.pi) ** 0.25
        z0 = 9 * math.pi / 32 * r0
        vs = SOIL.vs
        k_cone = 3 * G * J / z0
        assert k_cone == pytest.approx(16 * G * r0 ** 3 / 3, rel=1e-12)
        for omega in (2.0, 9.0, 40.0):
            kk = omega / vs
            z_far = z0 + 40.0 * (1.0 / kk + z0)
            g = np.exp(-1j * kk * z_far) * (1 + 1j * kk * z_far)
            th = g / z_far ** 3
            dth = np.exp(-1j * kk * z_far) * kk ** 2 * z_far / z_far ** 3 - 3 * g / z_far ** 4

            def rhs(z: float, y: np.ndarray, kk: float = kk) -> list[complex]:
                return [y[1], -4.0 / z * y[1] - kk ** 2 * y[0]]

            sol = solve_ivp(rhs, (z_far, z0), [th, dth], rtol=1e-11, atol=1e-30,
                            method="DOP853")
            S = -G * J * sol.y[1, -1] / sol.y[0, -1]
            b0 = kk * z0
            assert S.real == pytest.approx(k_cone * (1 - b0 ** 2 / (3 * (1 + b0 ** 2))),
                                           rel=1e-7)
            assert footing_torsion(footing, SOIL, omega)[1] == pytest.approx(S.imag / omega,
                                                                            rel=1e-7)


def test_torsion_springs_material_damping_and_the_rectangle_across_the_row() -> None:
    """k_t: 16 G R³/3 for a disk; G B³ [4.25 (L/B)^2.45 + 4.06] for a 2L × 2B rectangle,
    either way round (a square 8.31 G B³, within 5 % of the disk of the same polar moment:
    4.8 %); the soil's damping adds 2 β k_t/ω; no dashpots, none. Across the row, Pais &
    Kausel's k_y and k_xx (NIST GCR 12-917-21 Table 2-2a), written out here."""
    assert footing_torsion(Footing(radius=5.0), SOIL, 9.0)[0] == pytest.approx(
        16 * G * 125.0 / 3, rel=1e-14)
    L, B = 8.0, 5.0
    expected = G * B ** 3 * (4.25 * (L / B) ** 2.45 + 4.06)
    for ft in (Footing(length=16.0, width=10.0), Footing(length=10.0, width=16.0)):
        assert footing_torsion(ft, SOIL, 9.0)[0] == pytest.approx(expected, rel=1e-14)
    square = footing_torsion(Footing(length=10.0, width=10.0), SOIL, 9.0)[0]
    assert square == pytest.approx(8.31 * G * 125.0, rel=1e-12)
    R_same_J = (2 * (10.0 ** 4 / 6) / math.pi) ** 0.25
    disk = footing_torsion(Footing(radius=R_same_J), SOIL, 9.0)[0]
    assert 1.0 < square / disk < 1.05
    soft = Soil(150.0, 1800.0, 0.33, shaking=0.2)
    ft = Footing(radius=5.0)
    k_t, c_t = footing_torsion(ft, soft, 9.0)
    k_0, c_0 = footing_torsion(ft, Soil(soft.vs, 1800.0, 0.33), 9.0)
    assert k_t == pytest.approx(k_0, rel=1e-12)
    assert c_t - c_0 == pytest.approx(2 * 0.06 * k_t / 9.0, rel=1e-9)
    assert footing_torsion(Footing(radius=5.0, dashpots=False), SOIL, 9.0)[1] == 0.0
    # across the row: the plan's y sway and x rocking, Pais & Kausel's (L along x)
    b = symmetric_plan([2e8], [3e8], [4e5], [3.5], width=20.0, depth=10.0)
    fb = plan_flexible_base(b, Footing(length=16.0, width=10.0), SOIL)
    nu, a = 0.33, L / B
    springs = fb.foundation.impedance.springs
    assert springs[1] == pytest.approx(G * B / (2 - nu) * (6.8 * a ** 0.65 + 0.8 * a + 1.6),
                                       rel=1e-14)
    assert springs[2] == pytest.approx(G * B ** 3 / (1 - nu) * (3.2 * a + 0.8), rel=1e-14)
    assert springs[4] == pytest.approx(expected, rel=1e-14)
    c = fb.foundation.impedance.dashpots
    assert c[1] == pytest.approx(SOIL.density * SOIL.vs * 160.0, rel=1e-12)  # ρ V_s A
    assert c[2] == pytest.approx(footing_dashpots(Footing(length=10.0, width=16.0), SOIL,
                                                  fb.foundation.impedance.omega)[1], rel=1e-12)


def _plan_file() -> dict[str, Any]:
    soil = {"vs": 150.0, "density": 1800.0, "poisson": 0.33}
    return {"name": "plan on soil",
            "record": {"bundled": "el_centro"},
            "building": [{"plan": {"width": 20.0, "depth": 10.0}, "masses": [4e5],
                          "heights": [3.5], "foundation": {"radius": 5.0, "soil": soil},
                          "elements": [
                              {"x": 0.0, "y": 0.0, "direction": "x", "stiffnesses": 1e8},
                              {"x": 0.0, "y": 10.0, "direction": "x", "stiffnesses": 1e8},
                              {"x": 0.0, "y": 5.0, "direction": "y", "stiffnesses": 1.5e8},
                              {"x": 20.0, "y": 5.0, "direction": "y", "stiffnesses": 1.5e8}]}],
            "contact": {"law": "kelvin-voigt", "k": 1e9, "e": 0.5, "gap": 0.02}}


def _error_of(data: dict[str, Any]) -> str:
    with pytest.raises(ValueError) as info:
        parse_config(data, where="m.toml").build()
    return str(info.value)


def test_the_model_file_takes_a_foundation_under_a_building_in_plan() -> None:
    """``foundation = {...}`` in a [[building]] in plan makes a PlanFlexibleBaseBuilding
    (the footing centred under the plan); refused with a storey law (one line naming the
    field); a frame takes one too."""
    data = _plan_file()
    (b,) = parse_config(data, where="m.toml").build().model.buildings
    assert isinstance(b, PlanFlexibleBaseBuilding)
    assert b.foundation.centre == (10.0, 5.0) and b.n == 3
    assert b.foundation.impedance.springs[4] == pytest.approx(16 * G * 125.0 / 3, rel=1e-14)
    bad = copy.deepcopy(data)
    bad["building"][0]["storey_law"] = {"type": "bilinear", "yield_force": 1e6}
    message = _error_of(bad)
    assert "building[0].storey_law: not a key of a building in plan (a building in plan is " \
        "linear)" in message
    assert "\n" not in message
    frame = copy.deepcopy(data)
    frame["building"][0] = {"frame": {"bays": [5.0], "storey_heights": [4.0],
                                      "column_EI": 1.2e8, "beam_EI": 1.5e8,
                                      "floor_mass": 4.0e4},
                            "foundation": data["building"][0]["foundation"]}
    (fr,) = parse_config(frame, where="m.toml").build().model.buildings  # (frames take it too)
    assert isinstance(fr, FlexibleBaseBuilding) and fr.frame is not None
