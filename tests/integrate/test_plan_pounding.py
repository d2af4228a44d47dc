"""Buildings in plan pounding (issue 18): the reduce-to check against the planar pair, a
torsional pair striking at its corners against the SciPy reference under two components of
a real record, and the kinematics of the façade points written out by hand."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from pounding import PoundingModel, simulate
from pounding.ground_motion import GroundMotion, GroundMotionComponents, el_centro, load_bundled
from pounding.ground_motion.incidence import at_incidence
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec
from pounding.structure import RayleighDamping, ShearBuilding
from pounding.structure.plan import LateralElement, PlanBuilding
from pounding.structure.plan_row import PlanMatrixBuilding

RAYLEIGH = RayleighDamping.from_periods(0.5, 0.1)
"""The same Rayleigh coefficients whatever the modes (the plan building has more of them)."""


def symmetric(masses: list[float], kx: list[float], ky: list[float], width: float,
              depth: float, site_y: float = 0.0) -> PlanBuilding:
    """Frames at the four edges, each direction's stiffness shared equally: no eccentricity."""
    kx_, ky_ = np.asarray(kx) / 2, np.asarray(ky) / 2
    return PlanBuilding(masses=masses, heights=[4.0, 3.0, 3.0], width=width, depth=depth,
                        site_y=site_y, damping=RAYLEIGH, elements=[
                            LateralElement(0.0, 0.0, "x", kx_),
                            LateralElement(0.0, depth, "x", kx_),
                            LateralElement(0.0, depth / 2, "y", ky_),
                            LateralElement(width, depth / 2, "y", ky_)])


def torsional_pair() -> tuple[PlanBuilding, PlanBuilding, float]:
    """The pair of ``benchmarks/opensees_plan.py``: a symmetric 20 m × 12 m building and,
    offset 6 m along y, a 16 m × 12 m one whose x frame at plan y = 12 m is four times as
    stiff as the one at y = 0 (e_y = 3.6 m); the façades face each other over site y 6–12 m."""
    heights = [3.5, 3.0, 3.0]
    k = [1.8e8, 1.5e8, 1.05e8]
    left = PlanBuilding(masses=[2.5e5] * 3, heights=heights, width=20.0, depth=12.0,
                        elements=[LateralElement(10.0, 0.0, "x", k),
                                  LateralElement(10.0, 12.0, "x", k),
                                  LateralElement(0.0, 6.0, "y", k),
                                  LateralElement(20.0, 6.0, "y", k)])
    right = PlanBuilding(masses=[2.0e5] * 3, heights=heights, width=16.0, depth=12.0,
                         site_y=6.0, elements=[
                             LateralElement(8.0, 0.0, "x", [0.4e8, 0.33e8, 0.23e8]),
                             LateralElement(8.0, 12.0, "x", [1.6e8, 1.3e8, 0.9e8]),
                             LateralElement(0.0, 6.0, "y", [1.0e8, 0.8e8, 0.6e8]),
                             LateralElement(16.0, 6.0, "y", [1.0e8, 0.8e8, 0.6e8])])
    return left, right, 0.02


def window(g: GroundMotion, t0: float, t1: float) -> GroundMotion:
    """The record's samples from t0 to t1 [s] (a strong part, to keep the reference short)."""
    k0, k1 = round(t0 / g.dt), round(t1 / g.dt)
    return GroundMotion(g.dt, g.accel[k0: k1 + 1], name=g.name)


@pytest.mark.parametrize("law", [dict(law="linear-spring", k=9.3e8),
                                 dict(law="kelvin-voigt", k=9.3e8, c=2.0e6)])
def test_a_symmetric_pair_shaken_along_x_is_the_planar_pair(law: dict) -> None:
    """Symmetric plans under x shaking neither twist nor move along y; their floors meet at
    the two ends of the façades, two contacts in parallel: the planar pair of the same storey
    stiffnesses with one contact of twice the stiffness and damping. Same Rayleigh
    coefficients (the x block of the plan's K is the shear building's)."""
    law = dict(law)
    name = law.pop("law")
    a = symmetric([3e5] * 3, [3e8, 2e8, 1e8], [4e8, 3e8, 2e8], 20.0, 10.0)
    b = symmetric([2e5] * 3, [1e8] * 3, [2e8] * 3, 15.0, 10.0)
    plan = PoundingModel([a, b], gaps=[0.01], contact=ContactSpec(name, **law))
    sa = ShearBuilding([3e5] * 3, [3e8, 2e8, 1e8], [4.0, 3.0, 3.0], damping=RAYLEIGH)
    sb = ShearBuilding([2e5] * 3, [1e8] * 3, [4.0, 3.0, 3.0], damping=RAYLEIGH)
    planar = PoundingModel([sa, sb], gaps=[0.01],
                           contact=ContactSpec(name, **{k: 2 * v for k, v in law.items()}))
    record = el_centro().trimmed(12.0)
    rp = simulate(plan, GroundMotionComponents(at_incidence(record, angle=0.0)), rtol=1e-10)
    rs = simulate(planar, record, rtol=1e-10)
    up, us = np.asarray(rp.displacement), np.asarray(rs.displacement)
    scale = np.abs(us).max()
    assert np.abs(up[:, 0::3] - us).max() < 1e-9 * scale
    assert np.abs(up[:, 1::3]).max() == 0.0  # no y shaking, nothing couples y
    assert np.abs(up[:, 2::3]).max() < 1e-12 * scale / 10.0  # θ [rad], arms ≤ 10 m
    assert np.abs(np.asarray(rp.abs_acceleration)[:, 0::3]
                  - np.asarray(rs.abs_acceleration)).max() < 1e-8 * np.abs(
        np.asarray(rs.abs_acceleration)).max()
    peaks_plan = list(rp.contact_peaks.values())
    assert sum(p.impacts for p in peaks_plan) > 0
    for k, ps in enumerate(rs.contact_peaks.values()):
        for twin in peaks_plan[2 * k: 2 * k + 2]:  # the two ends of floor k's façade
            assert twin.impacts == ps.impacts
            assert twin.force == pytest.approx(ps.force / 2, rel=1e-8)


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_a_torsional_pair_strikes_at_its_corners_as_the_reference_does() -> None:
    """The eccentric building twists and strikes at corners under both horizontal
    components of the Düzce record (Kocaeli 1999) at 60°: the compiled kernel against the
    SciPy reference (DOP853, rtol 1e-10, every event located) on the same model."""
    left, right, gap = torsional_pair()
    h1 = load_bundled("kocaeli_1999_duzce_180_RSN1158")
    h2 = load_bundled("kocaeli_1999_duzce_270_RSN1158")
    motion = GroundMotionComponents(at_incidence(window(h1, 8.0, 10.4), window(h2, 8.0, 10.4),
                                                 60.0))
    model = PoundingModel([left, right], gaps=[gap],
                          contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    result = simulate(model, motion, rtol=1e-10)
    ref = simulate_reference(model, motion)
    peaks, ref_peaks = result.contact_peaks, ref.contact_peaks
    # both corners strike: the right building's at site y = 6 m, the left's at y = 12 m
    struck = {label for label, p in peaks.items() if p.impacts}
    assert {"B1F3@y=6-B2F3@y=6", "B1F3@y=12-B2F3@y=12"} <= struck
    for label, p in peaks.items():
        assert p.impacts == ref_peaks[label].impacts, label
        assert p.force == pytest.approx(ref_peaks[label].force, rel=1e-6, abs=1e-3), label
    u, ur = np.asarray(result.displacement), np.asarray(ref.displacement)
    assert np.abs(u - ur).max() < 1e-6 * np.abs(ur).max()
    assert np.abs(u[:, 2::3]).max() > 1e-3  # the floors twist by milliradians
    assert result.energy_balance_error < 1e-7


def test_facade_points_move_with_their_floors() -> None:
    """The penetration of each contact is the rigid-floor motion of its two façade points
    along x, written out here: u − (y − y_c) θ on each side."""
    left, right, gap = torsional_pair()
    model = PoundingModel([left, right], gaps=[gap],
                          contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    assert all(isinstance(b, PlanMatrixBuilding) for b in model.buildings)
    assert [c.label for c in model.contacts] == [
        f"B1F{j}@y={y}-B2F{j}@y={y}" for j in (1, 2, 3) for y in (6, 12)]
    rng = np.random.default_rng(5)
    u = rng.normal(size=(4, 18)) * np.tile([0.01, 0.01, 0.001], 6)
    delta = model.contact_penetration(u)
    for c in model.contacts:
        j = c.left.upper // 3
        y = 6.0 if "y=6" in c.label else 12.0
        ql, qr = u[:, 3 * j: 3 * j + 3], u[:, 9 + 3 * j: 9 + 3 * j + 3]
        x_left = ql[:, 0] - (y - 6.0) * ql[:, 2]  # left centre of mass at site y = 6
        x_right = qr[:, 0] - (y - 12.0) * qr[:, 2]  # right centre of mass at site y = 12
        assert np.allclose(delta[:, c.index], x_left - x_right - gap, rtol=1e-14, atol=1e-17)
    # the apparent mass of a corner: 1 / (1/m + arm²/I), I = m (a² + b²)/12
    c = model.contacts[0]
    m, inertia = 2.5e5, 2.5e5 * (20.0 ** 2 + 12.0 ** 2) / 12.0
    assert c.left.effective_mass(model.buildings[0].masses) == pytest.approx(
        1.0 / (1.0 / m + 0.0 / inertia))  # the left building's centre line: no arm
    m, inertia = 2.0e5, 2.0e5 * (16.0 ** 2 + 12.0 ** 2) / 12.0
    assert c.right.effective_mass(model.buildings[1].masses) == pytest.approx(
        1.0 / (1.0 / m + 6.0 ** 2 / inertia))


def test_a_plan_model_takes_two_components() -> None:
    left, right, gap = torsional_pair()
    model = PoundingModel([left, right], gaps=[gap],
                          contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    assert np.asarray(model.system.r).shape == (18, 2)
    with pytest.raises(ValueError, match="1 ground component for a model whose influence "
                                         "matrix R has 2 columns"):
        simulate(model, el_centro().trimmed(1.0))


def test_a_plan_building_beside_a_planar_one_meets_it_at_both_ends_of_its_facade() -> None:
    left, _, gap = torsional_pair()
    planar = ShearBuilding([2e5] * 3, [1e8] * 3, [3.5, 3.0, 3.0])
    model = PoundingModel([planar, left], gaps=[gap],
                          contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    assert [c.label for c in model.contacts][:2] == ["B1F1-B2F1@y=0", "B1F1-B2F1@y=12"]
    R = np.asarray(model.system.r)
    assert np.array_equal(R[:3], [[1, 0]] * 3)  # the planar building feels x only
    assert dataclasses.replace(left, site_y=3.0).as_matrix_building().plan.site_y == 3.0


def test_the_history_of_a_named_point_is_its_floors_rigid_motion() -> None:
    from pounding.structure.plan_row import point_history

    left, right, gap = torsional_pair()
    model = PoundingModel([left, right], gaps=[gap],
                          contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    h1 = load_bundled("kocaeli_1999_duzce_180_RSN1158")
    h2 = load_bundled("kocaeli_1999_duzce_270_RSN1158")
    result = simulate(model, GroundMotionComponents(
        at_incidence(window(h1, 8.0, 9.0), window(h2, 8.0, 9.0), 60.0)))
    u = np.asarray(result.displacement)
    # the right building's roof corner at plan (0, 0): centre of mass (8, 6)
    ux, uy, th = u[:, 15], u[:, 16], u[:, 17]
    assert np.allclose(point_history(result, 1, 2, 0.0, 0.0, "x"), ux + 6.0 * th, atol=1e-15)
    assert np.allclose(point_history(result, 1, 2, 0.0, 0.0, "y"), uy - 8.0 * th, atol=1e-15)
    assert np.array_equal(point_history(result, 1, 2, 8.0, 6.0, "x"), ux)
    with pytest.raises(ValueError, match="floor must be in"):
        point_history(result, 1, 3, 0.0, 0.0)
