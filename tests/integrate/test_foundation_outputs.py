"""What the outputs call a building on a flexible base's DOFs and footing: its footing's
DOFs labelled ``Fdn``, ``Fdn_r`` (in plan ``Fdn_x`` … ``Fdn_t``) whatever the building,
their units (a rocking in rad), the NetCDF file's coordinates and words, and the
``foundations`` rows of summary.json of a row building and of one in plan, keyed alike."""

from __future__ import annotations

import io

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotionComponents, el_centro
from pounding.ground_motion.incidence import at_incidence
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.result.files import write_netcdf
from pounding.result.variables import history_variables
from pounding.structure import MatrixBuilding, ShearBuilding
from pounding.structure.foundation import (
    Footing,
    Soil,
    flexible_base,
    plan_flexible_base,
)
from pounding.structure.plan import LateralElement, PlanBuilding

SOIL = Soil(150.0, 1800.0, 0.33)
KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
SHEAR = ShearBuilding.uniform(3, 3e5, 3.5e8, height=3.2)


def _plan() -> PlanBuilding:
    return PlanBuilding(masses=[4e5, 4e5], heights=[3.5, 3.5], width=20.0, depth=10.0,
                        elements=[LateralElement(0.0, 0.0, "x", 5e7),
                                  LateralElement(0.0, 10.0, "x", 5e7),
                                  LateralElement(0.0, 5.0, "y", 5e7),
                                  LateralElement(20.0, 5.0, "y", 5e7)])


@pytest.mark.parametrize(("footing", "extra", "units"), [
    (Footing(radius=4.0, mass=3e5, inertia=2e6), ["Fdn", "Fdn_r"], ["m", "rad"]),
    (Footing(radius=4.0, inertia=2e6), ["Fdn_r"], ["rad"]),
    (Footing(radius=4.0), [], []),
], ids=["sway-and-rocking", "rocking", "condensed"])
def test_a_footing_under_a_shear_or_matrix_building_has_its_own_labels(
        footing: Footing, extra: list[str], units: list[str]) -> None:
    """The footing's DOFs are ``B1Fdn``/``B1Fdn_r`` (not ``B1F4``/``B1F5``, which read as
    floors) for a shear building and for one given as matrices, as for a frame or a
    building in plan; the rocking is in rad; the neighbour's floors follow unchanged."""
    matrices = MatrixBuilding(M=SHEAR.mass_matrix(), K=SHEAR.stiffness_matrix(),
                              C=SHEAR.damping_matrix(), elevations=SHEAR.floor_levels,
                              labels=("a", "b", "roof"),
                              name="matrices")
    for b in (SHEAR, matrices):
        model = PoundingModel([flexible_base(b, footing, SOIL), SHEAR], [0.01], KV)
        assert model.dof_labels() == (["B1F1", "B1F2", "B1F3"] + [f"B1{x}" for x in extra]
                                      + ["B2F1", "B2F2", "B2F3"])
        assert model.dof_units() == ["m"] * 3 + units + ["m"] * 3


def test_the_units_of_a_plan_footing_and_its_floors() -> None:
    """In plan: the floors' θ and the footing's rockings and torsion are in rad, the rest
    in m."""
    fb = plan_flexible_base(_plan(), Footing(length=20.0, width=10.0, mass=1e5, inertia=1e6),
                            SOIL)
    model = PoundingModel([fb], [], KV)
    assert model.dof_labels() == ["B1F1x", "B1F1y", "B1F1θ", "B1F2x", "B1F2y", "B1F2θ",
                                  "B1Fdn_x", "B1Fdn_y", "B1Fdn_rx", "B1Fdn_ry", "B1Fdn_t"]
    assert model.dof_units() == ["m", "m", "rad"] * 2 + ["m", "m", "rad", "rad", "rad"]


def test_the_netcdf_file_names_the_footing_and_says_its_units_and_drift() -> None:
    """The file's ``floor`` coordinate has ``B1Fdn``, ``B1Fdn_r``; ``dof_unit`` says the
    rocking is in rad; the drift's description says a building on a flexible base's drift
    is its own deformation (not floor less floor below), and the values are those."""
    import h5netcdf

    fb = flexible_base(SHEAR, Footing(radius=4.0, mass=3e5, inertia=2e6), SOIL)
    r = simulate(PoundingModel([fb], [], KV), el_centro().trimmed(1.0), dt=0.01)
    buf = io.BytesIO()
    write_netcdf(history_variables(r), buf)
    buf.seek(0)
    with h5netcdf.File(buf, "r") as f:
        floors = [x.decode() if isinstance(x, bytes) else str(x) for x in f["floor"][:]]
        units = [x.decode() if isinstance(x, bytes) else str(x) for x in f["dof_unit"][:]]
        assert floors == ["B1F1", "B1F2", "B1F3", "B1Fdn", "B1Fdn_r"]
        assert units == ["m", "m", "m", "m", "rad"]
        drift = f["drift"]
        assert "flexible base: of its own deformation" in drift.attrs["long_name"]
        u = r.displacement
        z = np.asarray(SHEAR.floor_levels)
        own = u[:, :3] - u[:, 3:4] - z[None, :] * u[:, 4:5]
        expected = np.diff(np.column_stack([np.zeros(len(u)), own]), axis=1)
        np.testing.assert_allclose(drift[:, :3], expected, rtol=0.0,
                                   atol=1e-12 * np.abs(u).max())
        assert "rad where dof_unit is rad" in f["displacement"].attrs["long_name"]


def test_the_foundations_rows_of_a_row_and_a_plan_building_are_keyed_alike() -> None:
    """An embedded footing under a building in plan says its embedment (3 m), and its
    footing's keys are the row building's with the axis where the plan has two:
    ``rocking_inertia_kg_m2`` → ``rocking_inertia_about_x/y_kg_m2``, ``sway_dof`` →
    ``sway_x_dof``/``sway_y_dof``, ``rocking_dof`` → ``rocking_about_x/y_dof`` (as
    ``k_sway_N_m`` → ``k_sway_x_N_m``), plus the plan's own (centre, torsion)."""
    footing = Footing(length=20.0, width=10.0, embedment=3.0, mass=1e5, inertia=1e6)
    record = el_centro().trimmed(0.5)
    row = simulate(PoundingModel([flexible_base(SHEAR, footing, SOIL)], [], KV), record,
                   dt=0.01).summary()["foundations"][0]["footing"]
    plan = simulate(PoundingModel([plan_flexible_base(_plan(), footing, SOIL)], [], KV),
                    GroundMotionComponents(at_incidence(record, angle=30.0)),
                    dt=0.01).summary()["foundations"][0]["footing"]
    assert row["embedment_m"] == plan["embedment_m"] == 3.0

    def in_plan(key: str) -> list[str]:
        if key.startswith("rocking_"):
            stem = key.removeprefix("rocking_")
            if stem == "dof":
                return ["rocking_about_x_dof", "rocking_about_y_dof"]
            return [f"rocking_{stem.removesuffix('_kg_m2')}_about_{a}_kg_m2" for a in "xy"]
        if key.startswith("sway_"):
            return [f"sway_{a}_{key.removeprefix('sway_')}" for a in "xy"]
        return [key]

    expected = {k for key in row for k in in_plan(key)}
    assert expected <= set(plan), expected - set(plan)
    assert set(plan) - expected == {"centre_m", "torsion_inertia_kg_m2", "torsion_dof"}
    assert plan["rocking_inertia_about_y_kg_m2"] == 1e6
    assert all(plan[f"{k}_dof"] is True for k in ("sway_x", "sway_y", "rocking_about_x",
                                                  "rocking_about_y", "torsion"))
