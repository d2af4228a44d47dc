"""A grazing approach is an impact, or not, whatever the output step — for every kind of
building: shear buildings floor to floor and floor to column, a building given as matrices,
buildings in plan under two components, a base-isolated building beside its moat wall, and
pairs joined by a link or carrying a bumper.

For each, the gap that the buildings would just reach is measured first, on a run whose gap
is too wide to close (the largest penetration, sampled every 0.1 ms, is a lower bound of the
true peak, within ~10⁻⁸ m of it). A gap 10⁻⁶ m narrower must then give exactly one impact
at output steps of 1, 5, 10 and 20 ms, and a gap 10⁻⁶ m wider none. Before the events of a
step were searched from the peak of the penetration, a grazing approach whose cubic onset
estimate fell outside the brief contact was taken for no contact at all (the 9 + 5 storey
9 + 5 storey pair below missed it at 5 ms)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from pounding import PoundingModel, simulate
from pounding.devices import Bumper, Link
from pounding.ground_motion import GroundMotion, GroundMotionComponents, el_centro
from pounding.hysteresis import FrictionPendulum
from pounding.model import ContactSpec
from pounding.structure import MatrixBuilding, ShearBuilding
from pounding.structure.plan import LateralElement, PlanBuilding
from pounding.structure.plan_row import PlanMatrixBuilding
from pounding.structure.wall import MoatWall

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
WIDE = 5.0
"""A gap [m] no floor closes."""


def _record(seconds: float) -> GroundMotion:
    m = el_centro()
    return GroundMotion(m.dt, m.accel[: int(round(seconds / m.dt)) + 1], name="El Centro")


def _shear_9_5(gap: float) -> PoundingModel:
    # stiff storeys of different stiffness and mass, floor to floor: the pair that missed
    # its graze at 5 ms
    return PoundingModel([ShearBuilding.uniform(9, 5.94e5, 3.15e10),
                          ShearBuilding.uniform(5, 2.56e5, 1.06e9)], [gap], KV)


def _shear_to_column(gap: float) -> PoundingModel:
    # storeys of 3.2 m beside storeys of 4.0 m: floors strike the neighbour's columns
    return PoundingModel([ShearBuilding.uniform(4, 3e5, 6e8, height=3.2),
                          ShearBuilding.uniform(3, 2e5, 9e8, height=4.0)], [gap], KV)


def _matrix(gap: float) -> PoundingModel:
    return PoundingModel([ShearBuilding.uniform(4, 3e5, 6e8),
                          MatrixBuilding.from_shear_building(ShearBuilding.uniform(4, 2e5, 1.5e9))],
                         [gap], KV)


def _plan(gap: float) -> PoundingModel:
    def plan(mass: float, k: float, site_y: float, ratio: float) -> PlanBuilding:
        return PlanBuilding(masses=[mass] * 2, heights=[3.5, 3.0], width=12.0, depth=10.0,
                            site_y=site_y, elements=[
                                LateralElement(6.0, 0.0, "x", [k, k]),
                                LateralElement(6.0, 10.0, "x", [ratio * k, ratio * k]),
                                LateralElement(0.0, 5.0, "y", [k, k]),
                                LateralElement(12.0, 5.0, "y", [k, k])])
    return PoundingModel([plan(2.5e5, 1.5e8, 0.0, 1.0), plan(2e5, 0.5e8, 4.0, 3.0)], [gap], KV)


def _isolated_in_moat(gap: float) -> PoundingModel:
    superstructure = ShearBuilding.uniform(3, 4e5, 1e9).with_period(0.4)
    isolated = ShearBuilding.base_isolated(superstructure, 5e5,
                                           FrictionPendulum(radius=2.0, mu=0.05))
    return PoundingModel([isolated], [], KV, walls=[MoatWall(height=1.0, gap=gap, side="left"),
                                                    MoatWall(height=1.0, gap=gap, side="right")])


def _linked(gap: float) -> PoundingModel:
    return PoundingModel([ShearBuilding.uniform(4, 3e5, 6e8), ShearBuilding.uniform(4, 2e5, 1.5e9)],
                         [gap], KV, devices=[Link(("B1F2", "B2F2"), "viscous", c=2e5)])


def _bumper(gap: float) -> PoundingModel:
    return PoundingModel([ShearBuilding.uniform(4, 3e5, 6e8), ShearBuilding.uniform(4, 2e5, 1.5e9)],
                         [gap], KV, devices=[Bumper(("B1F4", "B2F4"), thickness=0.005, compression_limit=0.7,
                                                    rubber=ContactSpec("hertzdamp", k_h=2e8,
                                                                       e=0.5))])


CASES: dict[str, tuple[Callable[[float], PoundingModel], float]] = {
    "shear, 9 + 5 storeys": (_shear_9_5, 2.5),
    "shear, floor to column": (_shear_to_column, 4.0),
    "matrix building": (_matrix, 4.0),
    "buildings in plan": (_plan, 4.0),
    "isolated in its moat": (_isolated_in_moat, 4.0),
    "linked": (_linked, 4.0),
    "bumper": (_bumper, 4.0),
}


def _motion(name: str, seconds: float) -> GroundMotion | GroundMotionComponents:
    rec = _record(seconds)
    if name == "buildings in plan":
        across = GroundMotion(rec.dt, 0.4 * rec.accel[::-1].copy(), name="El Centro reversed")
        return GroundMotionComponents([rec, across])
    return rec


@pytest.mark.parametrize("name", sorted(CASES))
def test_a_grazing_approach_is_found_at_every_output_step(name):
    build, seconds = CASES[name]
    motion = _motion(name, seconds)
    free = simulate(build(WIDE), motion, dt=1e-4)
    assert free.n_impacts == 0
    reach = WIDE + float(np.max(free.penetration))  # the gap the floors just reach [m]
    found = {}
    for excess in (1e-6, -1e-6):
        for dt in (1e-3, 5e-3, 1e-2, 2e-2):
            found[excess, dt] = simulate(build(reach - excess), motion, dt=dt).n_impacts
    assert found == {(excess, dt): (1 if excess > 0 else 0)
                     for excess in (1e-6, -1e-6) for dt in (1e-3, 5e-3, 1e-2, 2e-2)}


def test_the_cases_cover_every_building_kind():
    # each case is what its name says (so the parametrisation above tests what it claims)
    kinds = {name: build(0.05) for name, (build, _) in CASES.items()}
    labels = {name: [c.label for c in m.contacts] for name, m in kinds.items()}
    assert any("S" in label for label in labels["shear, floor to column"])  # B1S2@0.50-B2F1
    assert not any("S" in label for label in labels["shear, 9 + 5 storeys"])
    assert isinstance(kinds["matrix building"].buildings[1], MatrixBuilding)
    assert all(isinstance(b, PlanMatrixBuilding) for b in kinds["buildings in plan"].buildings)
    assert kinds["buildings in plan"].system.r.shape[1] == 2
    isolated = kinds["isolated in its moat"]
    assert len(isolated.walls) == 2 and isolated.is_inelastic
    assert len(kinds["linked"].links) == 1
    assert len(kinds["bumper"].contacts) == len(kinds["linked"].contacts) + 1
