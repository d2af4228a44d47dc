"""Yielding storeys in the time-history engine (issue 5): against the independent SciPy
reference (rate-form bilinear, Bouc–Wen coded afresh), energy balance with hysteretic
energy, residual drift against the building at rest, ductility."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear, BoucWen
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ShearBuilding

G = 9.81
KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


def yielding_sdof(law) -> PoundingModel:
    b = ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05).with_storey_law(law)
    return PoundingModel([b], [], KV)


LAWS = {
    "bilinear": Bilinear(yield_force=0.15 * 2e5 * G, hardening=0.05),
    "epp": Bilinear(yield_force=0.15 * 2e5 * G, hardening=0.0),
    "bouc-wen": BoucWen(yield_force=0.15 * 2e5 * G, alpha=0.05, n=2.0),
}


@pytest.fixture(scope="module")
def elc():
    return el_centro()


@pytest.mark.parametrize("name", list(LAWS))
def test_yielding_sdof_matches_reference(name, elc):
    model = yielding_sdof(LAWS[name])
    res = simulate(model, elc, duration=8.0)
    ref = simulate_reference(model, elc, duration=8.0)
    scale = np.abs(ref.displacement).max()
    assert res.ductility[0] > 2.0                     # it did yield, well past the yield drift
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-4 * scale
    assert np.max(np.abs(res.storey_shear - ref.storey_shear)) < 1e-4 * np.abs(
        ref.storey_shear).max()
    assert res.residual_drift[0] == pytest.approx(ref.residual_drift[0], rel=1e-3, abs=1e-6)
    assert res.energy[-1, 6] == pytest.approx(ref.energy[-1, 6], rel=1e-4)
    assert res.energy_balance_error < 1e-6
    assert ref.energy_balance_error < 1e-6


def test_bilinear_shear_stays_inside_its_band(elc):
    law = LAWS["bilinear"]
    model = yielding_sdof(law)
    res = simulate(model, elc, duration=10.0)
    k = model.buildings[0].stiffnesses[0]
    fy = model.buildings[0].yield_forces[0]
    band = np.abs(res.storey_shear[:, 0] - 0.05 * k * res.drift[:, 0])
    assert band.max() <= 0.95 * fy * (1 + 1e-9)
    assert band.max() >= 0.95 * fy * (1 - 1e-9)        # and reached it


def test_residual_drift_is_where_the_building_comes_to_rest(elc):
    """Run 30 s past the record: the storey settles at the residual drift."""
    model = yielding_sdof(LAWS["epp"])
    short = simulate(model, elc, duration=20.0)
    long = simulate(model, elc, duration=60.0)
    assert abs(long.velocity[-1, 0]) < 1e-6
    assert long.drift[-1, 0] == pytest.approx(long.residual_drift[0], abs=1e-8)
    assert abs(short.residual_drift[0]) > 1e-3        # a real permanent offset
    # after 20 s the elastic unloading estimate already points at the final rest position
    assert short.residual_drift[0] == pytest.approx(long.drift[-1, 0], rel=0.2)


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_inelastic_pair_with_pounding_matches_reference_and_balances(elc):
    """Two 3-storey buildings, one bilinear, one Bouc–Wen, pounding at every floor."""
    a = ShearBuilding.uniform(3, 3e5, 3.5e8, height=3.2).with_storey_law(
        Bilinear(yield_drift=0.004 * 3.2, hardening=0.05))
    b = ShearBuilding.uniform(3, 2.5e5, 1.5e8, height=3.2).with_storey_law(
        BoucWen(yield_drift=0.006 * 3.2, alpha=0.05, n=1.5))
    model = PoundingModel([a, b], [0.01], KV)
    res = simulate(model, elc, duration=6.0)
    ref = simulate_reference(model, elc, duration=6.0)
    assert res.n_impacts == ref.n_impacts > 0
    assert np.nanmax(res.ductility) > 1.0
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-3)
    scale = np.abs(ref.displacement).max()
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-3 * scale
    assert res.energy_balance_error < 5e-3 and ref.energy_balance_error < 5e-3
    assert res.energy_balance_error < 1e-6


def test_yielding_model_refuses_exact_stepping(elc):
    with pytest.raises(ValueError, match="free_stepping"):
        simulate(yielding_sdof(LAWS["bilinear"]), elc, duration=1.0, free_stepping="exact")


def test_linear_storeys_through_the_law_path_equal_the_matrix_path(elc):
    """A bilinear storey that never yields is the linear storey: same response."""
    lin = PoundingModel([ShearBuilding.uniform(3, 2e5, 2e8)], [], KV)
    big = PoundingModel([ShearBuilding.uniform(3, 2e5, 2e8).with_storey_law(
        Bilinear(yield_force=1e12, hardening=0.0))], [], KV)
    r1 = simulate(lin, elc, duration=5.0, free_stepping="rk")
    r2 = simulate(big, elc, duration=5.0)
    assert np.max(np.abs(r1.displacement - r2.displacement)) < 1e-7 * np.abs(r1.displacement).max()
    np.testing.assert_allclose(r2.storey_shear, r1.storey_shear, rtol=0,
                               atol=1e-6 * np.abs(r1.storey_shear).max())
    assert abs(r2.energy[-1, 6]) < 1e-9 * r2.energy[-1, 0]   # no hysteretic energy
    assert np.all(r2.residual_drift == pytest.approx(0.0, abs=1e-12))
