"""Buildings in plan on flexible bases in time histories (the compiled kernel): the reduce-to
check against the row's flexible base, the massless footing's equilibrium (the storeys'
forces are the building's own deformation's), the energy balance with pounding under two
components, the soil's dashpot work, and a model file from the command line."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotionComponents, el_centro
from pounding.ground_motion.incidence import at_incidence
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.result.columns import ENERGY_NAMES
from pounding.structure import RayleighDamping, ShearBuilding
from pounding.structure.foundation import (
    Footing,
    Soil,
    flexible_base,
    plan_flexible_base,
)
from pounding.structure.plan import LateralElement, PlanBuilding

SOIL = Soil(150.0, 1800.0, 0.33)
SPEC = ContactSpec("kelvin-voigt", k=2e9, e=0.65)
RAYLEIGH = RayleighDamping.from_periods(0.5, 0.1)


def _symmetric(kx: list[float], ky: list[float], masses: list[float],
               heights: list[float]) -> PlanBuilding:
    hx, hy = np.asarray(kx) / 2, np.asarray(ky) / 2
    return PlanBuilding(masses=masses, heights=heights, width=20.0, depth=12.0,
                        damping=RAYLEIGH, elements=[
                            LateralElement(0.0, 0.0, "x", hx), LateralElement(0.0, 12.0, "x", hx),
                            LateralElement(0.0, 6.0, "y", hy), LateralElement(20.0, 6.0, "y", hy)])


def _eccentric(masses: list[float], heights: list[float], damping: RayleighDamping = RAYLEIGH,
               site_y: float = 0.0) -> PlanBuilding:
    """A 16 m × 12 m plan whose x frame at y = 12 m is four times the one at y = 0, its
    centres of mass off the plan's centre."""
    n = len(masses)
    return PlanBuilding(masses=masses, heights=heights, width=16.0, depth=12.0,
                        damping=damping, site_y=site_y,
                        mass_centres=[[7.0, 5.0]] * n, elements=[
                            LateralElement(8.0, 0.0, "x", 4e7), LateralElement(8.0, 12.0, "x", 1.6e8),
                            LateralElement(0.0, 6.0, "y", 1e8), LateralElement(16.0, 6.0, "y", 1e8)])


@pytest.mark.parametrize("footing", [Footing(radius=6.0),
                                     Footing(radius=6.0, mass=3.0e5, inertia=2.7e6)])
def test_a_symmetric_plan_shaken_along_x_is_the_row_flexible_base(footing: Footing) -> None:
    """Under the x component alone a symmetric plan on a disk moves along x as the row's
    flexible base of its x frames (floors, footing's sway and rocking) to 1e-10 of the
    peaks, and neither moves along y nor twists."""
    kx, ky = [3e8, 2e8, 1e8], [6e8, 5e8, 4e8]
    masses, heights = [3e5, 3e5, 2e5], [4.0, 3.0, 3.0]
    plan = plan_flexible_base(_symmetric(kx, ky, masses, heights), footing, SOIL)
    row = flexible_base(ShearBuilding(masses, kx, heights, damping=RAYLEIGH), footing, SOIL)
    record = el_centro().trimmed(8.0)
    rp = simulate(PoundingModel([plan], [], SPEC),
                  GroundMotionComponents(at_incidence(record, angle=0.0)), dt=0.005)
    rs = simulate(PoundingModel([row], [], SPEC), record, dt=0.005)
    labels = list(plan.labels)
    x_dofs = [labels.index(f"F{j + 1}x") for j in range(3)]
    x_dofs += [labels.index(k) for k in ("Fdn_x", "Fdn_ry") if k in labels]
    up, us = np.asarray(rp.displacement), np.asarray(rs.displacement)
    scale = np.abs(us).max()
    assert np.abs(up[:, x_dofs] - us).max() < 1e-10 * scale
    motion, reaction = plan.foundation.base_reactions(up, np.asarray(rp.velocity))
    sway, rocking, shear, moment = row.foundation.base_reactions(us, np.asarray(rs.velocity))
    assert np.abs(motion[:, 0] - sway).max() < 1e-10 * np.abs(sway).max()
    assert np.abs(motion[:, 3] - rocking).max() < 1e-10 * np.abs(rocking).max()
    assert np.abs(reaction[:, 0] - shear).max() < 1e-9 * np.abs(shear).max()
    assert np.abs(reaction[:, 3] - moment).max() < 1e-9 * np.abs(moment).max()
    others = np.setdiff1d(np.arange(plan.n), x_dofs)
    assert np.abs(up[:, others]).max() < 1e-14 * scale
    assert np.abs(motion[:, [1, 2, 4]]).max() < 1e-14 * scale
    # the storeys' drifts are the building's own deformation, as the row's
    d_row = rs.drift[:, :3]
    assert np.abs(rp.drift[:, x_dofs[:3]] - d_row).max() < 1e-10 * np.abs(d_row).max()
    assert rp.peak_drift[x_dofs[:3]] == pytest.approx(rs.peak_drift[:3], rel=1e-9)
    assert rp.peak_drift_ratio[x_dofs[:3]] == pytest.approx(rs.peak_drift_ratio[:3], rel=1e-9)


def test_the_massless_footing_balances_the_storey_forces() -> None:
    """One eccentric storey, undamped, on a massless rectangle with springs only (no
    dashpots), under both components at 30°: the footing's equilibrium at every step, with
    the storey's forces from its lateral elements (on the building's own deformation) and
    the soil's reactions: ``k_x u_fx = V_x``, ``k_y u_fy = V_y``, ``k_ry φ_y = h V_x``,
    ``k_rx φ_x = −h V_y``, ``k_t ψ = T − Y V_x + X V_y`` (``T`` about the centre of mass,
    ``(X, Y)`` from the footing's centre to it)."""
    b = _eccentric([4e5], [3.5], damping=RayleighDamping(0.0, mode_i=1, mode_j=3))
    fb = plan_flexible_base(b, Footing(length=16.0, width=12.0, dashpots=False), SOIL)
    assert fb.n == 3
    record = el_centro().trimmed(8.0)
    res = simulate(PoundingModel([fb], [], SPEC),
                   GroundMotionComponents(at_incidence(record, angle=30.0)), dt=0.005)
    _, reaction = fb.foundation.base_reactions(res.displacement, res.velocity)
    vx, vy, torque = res.storey_shear[:, 0], res.storey_shear[:, 1], res.storey_torque[:, 2]
    X, Y, h = 7.0 - 8.0, 5.0 - 6.0, 3.5
    for soil, storey in ((reaction[:, 0], vx), (reaction[:, 1], vy), (reaction[:, 3], h * vx),
                         (reaction[:, 2], -h * vy), (reaction[:, 4], torque - Y * vx + X * vy)):
        assert np.abs(soil - storey).max() < 1e-9 * np.abs(storey).max()
    # the drifts are the deformation's, not the floor's displacement relative to the ground
    q = fb.foundation.deformation(res.displacement)
    assert np.abs(res.drift[:, 0] - q[:, 0]).max() < 1e-15 + 1e-12 * np.abs(q[:, 0]).max()
    assert np.abs(res.drift[:, 1] - q[:, 1]).max() < 1e-15 + 1e-12 * np.abs(q[:, 1]).max()
    assert np.max(np.abs(res.displacement[:, 1])) > 1.1 * np.max(np.abs(q[:, 1]))


def test_energy_balances_with_pounding_and_the_dashpots_work() -> None:
    """An eccentric plan on a footing with mass and inertia (every DOF of it explicit)
    pounding against a symmetric one under both components: the energy balance closes; the
    contacts are named by floor (the footing's DOFs after the floors do not shift them), the
    plan storeys are its three floors. Without the building's own damping the summary's
    soil dashpot work is the damping energy (trapezoids on the output steps)."""
    record = el_centro().trimmed(10.0)
    motion = GroundMotionComponents(at_incidence(record, angle=60.0))
    a = plan_flexible_base(_eccentric([2e5] * 3, [3.5, 3.0, 3.0], site_y=6.0),
                           Footing(length=16.0, width=12.0, mass=2e5, inertia=4e6), SOIL)
    assert a.n == 14
    b = _symmetric([3.6e8, 3.0e8, 2.1e8], [3.6e8, 3.0e8, 2.1e8], [2.5e5] * 3, [3.5, 3.0, 3.0])
    model = PoundingModel([b, a], [0.005], SPEC)
    res = simulate(model, motion, dt=0.002)
    assert res.n_impacts > 0
    assert res.energy_balance_error < 1e-7
    names = [c.label for c in model.contacts]
    assert names[-1] == "B1F3@y=12-B2F3@y=12", names
    assert model.dof_labels()[-5:] == ["B2Fdn_x", "B2Fdn_y", "B2Fdn_rx", "B2Fdn_ry", "B2Fdn_t"]
    storeys = {ps.building: ps for ps in res.plan_storeys}
    assert storeys[1].drift_y.shape == (3,) and np.all(np.isfinite(storeys[1].torque))
    (row,) = res.summary()["foundations"]
    assert row["building"] == "B2" and row["peak_torsion_rad"] > 0
    assert row["peak_base_torque_N_m"] > 0 and row["peak_sway_y_m"] > 0
    undamped = _eccentric([2e5] * 3, [3.5, 3.0, 3.0],
                          damping=RayleighDamping(0.0, mode_i=1, mode_j=3))
    for footing in (Footing(radius=6.0), Footing(radius=6.0, mass=2e5, inertia=4e6)):
        fb = plan_flexible_base(undamped, footing, SOIL)
        alone = simulate(PoundingModel([fb], [], SPEC), motion, dt=0.002)
        (f,) = alone.summary()["foundations"]
        damping = alone.energy[-1, ENERGY_NAMES.index("damping")]
        assert f["soil_dashpot_work_J"] == pytest.approx(damping, rel=5e-4)


def test_a_plan_building_on_a_footing_from_the_command_line(tmp_path: Path) -> None:
    """`pounding run FILE --out DIR` of a model file with a building in plan on a footing
    (``foundation = {...}``) beside one on a fixed base: summary.json's ``foundations``
    reports the footing's five motions and the soil's five reactions, and the energy
    balance closes."""
    soil = 'soil = { vs = 150.0, density = 1800.0, poisson = 0.33 }'
    text = f"""name = "plan on a footing"
[record]
bundled = "el_centro"
second = "el_centro"
incidence = 30.0
duration = 6.0

[[building]]
name = "eccentric"
plan = {{ width = 16.0, depth = 12.0 }}
masses = [2.0e5, 2.0e5]
heights = [3.5, 3.0]
elements = [
  {{ x = 8.0, y = 0.0, direction = "x", stiffnesses = 4.0e7 }},
  {{ x = 8.0, y = 12.0, direction = "x", stiffnesses = 1.6e8 }},
  {{ x = 0.0, y = 6.0, direction = "y", stiffnesses = 1.0e8 }},
  {{ x = 16.0, y = 6.0, direction = "y", stiffnesses = 1.0e8 }},
]
foundation = {{ length = 16.0, width = 12.0, mass = 2.0e5, inertia = 4.0e6, {soil} }}

[[building]]
name = "stiff"
mass = 3.0e5
period = 0.3
height = 3.5

[contact]
law = "kelvin-voigt"
k = 1.0e9
e = 0.65
gap = 0.01
"""
    model_file = tmp_path / "plan_ssi.toml"
    model_file.write_text(text)
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "pounding", "run", str(model_file), "--out",
                           str(out), "--no-figures"], check=False, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    summary = json.loads((out / "summary.json").read_text())
    (f,) = summary["foundations"]
    assert f["building"] == "B1" and f["footing"]["centre_m"] == [8.0, 6.0]
    for key in ("sway_x_m", "sway_y_m", "rocking_about_x_rad", "rocking_about_y_rad",
                "torsion_rad", "base_shear_x_N", "base_shear_y_N", "base_moment_about_x_N_m",
                "base_moment_about_y_N_m", "base_torque_N_m"):
        assert math.isfinite(f[f"peak_{key}"]) and f[f"peak_{key}"] > 0, key
    G = 1800.0 * 150.0 ** 2
    assert f["k_torsion_N_m_rad"] == pytest.approx(G * 6.0 ** 3 * (4.25 * (8 / 6) ** 2.45
                                                                   + 4.06), rel=1e-12)
    assert summary["buildings"][0]["periods_s"] == pytest.approx(f["flexible_base_periods_s"])
    assert summary["energy_balance_error"] < 1e-7
