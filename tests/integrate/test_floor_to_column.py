"""Floor-to-column pounding (issue 5, seed case 2B with floors that do not line up)."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.ground_motion import el_centro
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactPoint, ContactSpec, PoundingModel, contact_points
from pounding.structure import ShearBuilding

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


@pytest.fixture(scope="module")
def elc():
    return el_centro()


def mismatched(spec: ContactSpec = KV, gap: float = 0.01) -> PoundingModel:
    """4 storeys of 3.0 m beside 3 storeys of 3.6 m: no floor lines up below 10.8 m."""
    a = ShearBuilding.uniform(4, 3e5, 4e8, height=3.0, name="A")
    b = ShearBuilding.uniform(3, 3e5, 1.5e8, height=3.6, name="B")
    return PoundingModel([a, b], [gap], spec)


def test_contact_points_of_mismatched_floors():
    m = mismatched()
    labels = [c.label for c in m.contacts]
    # slabs of A at 3, 6, 9 m strike B's columns; B's slabs at 3.6, 7.2 m strike A's; B's roof
    # at 10.8 m strikes A's 4th storey (9–12 m); A's roof at 12 m is above B: no contact
    assert labels == ["B1F1-B2S1@0.83", "B1S2@0.20-B2F1", "B1F2-B2S2@0.67",
                      "B1S3@0.40-B2F2", "B1F3-B2S3@0.50", "B1S4@0.60-B2F3"]
    for c in m.contacts:
        assert (c.struck is None) == c.is_floor_to_floor
    # floor_to_column=False: no slab lines up, so no contact at all
    assert PoundingModel(m.buildings, [0.01], KV, floor_to_column=False).contacts == ()


def test_force_sharing_is_equal_and_opposite_and_consistent():
    m = mismatched()
    dof, w = m.contact_kinematics()
    # the shares of F on the left building add up to −F, on the right to +F (equal and
    # opposite) — except in a ground storey, whose foundation takes the share (1 − ξ) F
    def total(pt: ContactPoint) -> float:
        return pt.xi if (not pt.is_floor and pt.lower < 0) else 1.0
    np.testing.assert_allclose(w[:, :2].sum(axis=1), [total(c.left) for c in m.contacts],
                               rtol=0, atol=1e-15)
    np.testing.assert_allclose(w[:, 2:].sum(axis=1), [-total(c.right) for c in m.contacts],
                               rtol=0, atol=1e-15)
    assert m.contacts[0].right.lower == -1 and w[0, 2:].sum() == pytest.approx(-3.0 / 3.6)
    # and the same weights interpolate the point's displacement (virtual work)
    pt = ContactPoint(1, 1, 0.25)
    assert pt.floor_weights() == [(0, 0.75), (1, 0.25)]
    u = np.array([[0.01, 0.03]])
    assert pt.of(u)[0] == pytest.approx(0.75 * 0.01 + 0.25 * 0.03)
    # a column point of the ground storey has one floor; apparent mass 1/Σ w²/m
    g = ContactPoint(0, 0, 0.5)
    assert g.floor_weights() == [(0, 0.5)]
    assert g.effective_mass(np.array([2e5])) == pytest.approx(8e5)
    assert pt.effective_mass(np.array([1e5, 1e5])) == pytest.approx(1e5 / (0.75**2 + 0.25**2))


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_mismatched_pair_matches_reference_and_balances_energy(elc):
    m = mismatched()
    res = simulate(m, elc, duration=6.0)
    ref = simulate_reference(m, elc, duration=6.0)
    assert res.n_impacts == ref.n_impacts > 0
    hit = ref.peak_contact_force > 0
    assert np.any([not m.contacts[j].is_floor_to_floor for j in np.flatnonzero(hit)])
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-3)
    scale = np.abs(ref.displacement).max()
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-3 * scale
    # energy-consistent sharing: the balance closes to round-off, not just to 0.5 %
    assert res.energy_balance_error < 1e-7


@pytest.mark.parametrize("eps", [1e-3, 1e-5])
def test_column_contact_tends_to_floor_contact_as_floors_line_up(eps, elc):
    """A 1-storey building's roof against a 2-storey neighbour whose first floor is eps
    higher: the roof strikes the column just below that floor; as eps → 0 the results
    approach the floor-to-floor case, and at eps = 0 they are the floor-to-floor case."""
    low = ShearBuilding.sdof(2e5, period=0.4, height=3.0)

    def tall(h1: float) -> ShearBuilding:
        return ShearBuilding(masses=[3e5, 3e5], stiffnesses=[4e8, 4e8], heights=[h1, 3.0])

    exact = PoundingModel([low, tall(3.0)], [0.01], KV, level_tolerance=1e-9)
    near = PoundingModel([low, tall(3.0 + eps)], [0.01], KV, level_tolerance=1e-9)
    assert exact.contacts[0].is_floor_to_floor
    assert near.contacts[0].label == f"B1F1-B2S1@{3.0 / (3.0 + eps):.2f}"
    assert not near.contacts[0].is_floor_to_floor
    r0 = simulate(exact, elc, duration=6.0)
    r1 = simulate(near, elc, duration=6.0)
    assert r1.n_impacts == r0.n_impacts > 0
    rel = eps / 3.0
    assert abs(r1.peak_contact_force[0] / r0.peak_contact_force[0] - 1) < 50 * rel
    assert np.max(np.abs(r1.displacement - r0.displacement)) < 50 * rel * np.abs(
        r0.displacement).max()
    # lined up exactly: the floor-to-column construction is the floor-to-floor contact
    with_columns = PoundingModel([low, tall(3.0)], [0.01], KV, floor_to_column=True)
    without = PoundingModel([low, tall(3.0)], [0.01], KV, floor_to_column=False)
    ra, rb = simulate(with_columns, elc, duration=6.0), simulate(without, elc, duration=6.0)
    np.testing.assert_array_equal(ra.displacement, rb.displacement)
    np.testing.assert_array_equal(ra.contact_force, rb.contact_force)


def test_column_shear_demand(elc):
    m = mismatched()
    res = simulate(m, elc, duration=6.0)
    cs = res.column_shear
    for c in m.contacts:
        pt = c.struck
        assert pt is not None
        k = int(np.argmax(res.contact_force[:, c.index]))
        f = res.contact_force[k, c.index]
        if f <= 0:
            continue
        p = f if pt is c.right else -f
        v = res.storey_shear[k, m.system.offsets[pt.building] + pt.upper]
        below, above = v + (1 - pt.xi) * p, v - pt.xi * p
        assert below - above == pytest.approx(p)            # the column carries P locally
        assert cs[k, c.index] == pytest.approx(max(abs(below), abs(above)))
        assert cs[k, c.index] >= max(pt.xi, 1 - pt.xi) * f - abs(v) - 1e-6
    ds = res.to_dataset()
    assert ds["column_shear"].attrs["units"] == "N"
    assert set(res.summary()["peak_column_shear_N"]) == {c.label for c in m.contacts}
    # a struck column carries at least its storey's shear; more where it was hit hard
    ratio = res.column_shear_ratio
    assert np.all(ratio >= 1.0 - 1e-12)
    assert ratio[int(np.argmax(res.peak_contact_force))] > 1.0


def test_level_tolerance_is_validated():
    with pytest.raises(ValueError, match="level_tolerance"):
        PoundingModel(mismatched().buildings, [0.01], KV, level_tolerance=-1.0)


def test_contact_points_above_the_lower_roof_are_skipped():
    a = ShearBuilding.uniform(2, 1e5, 1e8, height=3.0)
    b = ShearBuilding.uniform(5, 1e5, 1e8, height=1.0)
    rows = contact_points(a, b)
    # b's floors at 1, 2, 4, 5 m... only those below a's roof (6 m); 3 m lines up
    assert [round(r[0], 6) for r in rows] == [1.0, 2.0, 3.0, 4.0, 5.0]
