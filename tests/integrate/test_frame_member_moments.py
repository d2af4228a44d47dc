"""The members' end moments of a yielding frame in a run (``Result.member_end_moment``),
checked against what they must equal whatever computed them: at a member end with a hinge,
the hinge's moment (the zero-length spring and the member end carry one moment), and in the
portal, the storey's restoring force ``R = Σ_columns (M₁ + M₂)/h`` taken from the equation
of motion (``R = −M ü_abs − C u̇``)."""

from __future__ import annotations

import numpy as np
import pytest
from frame_kernel_models import KV, _portal, _three_storeys  # (this folder)

from pounding.ground_motion import el_centro
from pounding.hysteresis.hinges import BilinearHinge
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure.frame import regular_frame
from pounding.structure.frame_linear import frame_matrix_building


def _hinge_mismatch(frame_building, result) -> float:  # type: ignore[no-untyped-def]
    """Largest |member end moment − hinge moment| over the hinges and output steps [N·m]."""
    M = result.member_end_moment
    return max(float(np.max(np.abs(M[:, 2 * fh.element + fh.end] - result.hinge_moment[:, h])))
               for h, fh in enumerate(frame_building.frame.hinges))


def test_the_portal_s_column_end_moments_carry_its_restoring_force() -> None:
    b = frame_matrix_building(_portal())
    model = PoundingModel([b], [], KV)
    r = simulate(model, el_centro().scaled(3.0), duration=6.0)
    M = r.member_end_moment
    assert M.shape == (r.time.size, 6)
    assert model.member_end_labels() == ["B1E1i", "B1E1j", "B1E2i", "B1E2j", "B1E3i",
                                         "B1E3j"]
    restoring = -(r.abs_acceleration[:, 0] * b.masses[0]) - r.velocity @ b.damping_matrix()[0]
    columns = (M[:, 0] + M[:, 1] + M[:, 2] + M[:, 3]) / 4.0  # both columns, h = 4 m
    assert np.max(np.abs(columns - restoring)) <= 1e-8 * 3e5
    # the storey shear (from the frame's restoring force) is the columns' shear
    assert np.max(np.abs(r.storey_shear[:, 0] - columns)) <= 1e-8 * 3e5
    # the mechanism: every column end at Mp = 300 kN·m at some step, never beyond
    assert np.abs(M[:, :4]).max() == pytest.approx(3e5, rel=1e-9)
    assert _hinge_mismatch(b, r) <= 1e-8 * 3e5


@pytest.mark.parametrize("geometry", ["p-delta", "consistent"])
def test_a_hinged_member_end_carries_its_hinge_s_moment_under_gravity(geometry: str) -> None:
    if geometry == "p-delta":
        frame = _three_storeys("A", gravity=True)
    else:
        law = BilinearHinge(k0=1e11, m_y=3e5, hardening=0.03)
        frame = regular_frame([6.0, 6.0], [4.0, 3.5], column_EI=3e8, beam_EI=2.5e8,
                              column_hinge=law, beam_hinge=law, floor_mass=8e4,
                              beam_load=2e4, leaning_load=5e5, geometry="consistent",
                              name="A")
    b = frame_matrix_building(frame)
    r = simulate(PoundingModel([b], [], KV), el_centro().scaled(1.5), duration=4.0)
    assert r.stats.events > 10  # the hinges yielded
    scale = np.abs(r.hinge_moment).max()
    assert _hinge_mismatch(b, r) <= 1e-8 * scale
    # and with the beams' gravity load the end moments are not zero at rest (t = 0)
    assert np.abs(r.member_end_moment[0]).max() > 1e3
    # written to timehistories.nc with its labels and units
    ds = r.to_dataset()
    assert ds["member_end_moment"].attrs["units"] == "N m"
    assert list(ds["member_end"].values[:2]) == ["B1E1i", "B1E1j"]


def _shear_from_motion(b, r, off: int = 0) -> np.ndarray:  # type: ignore[no-untyped-def]
    """Each storey's shear from the equation of motion, not from the frame's restoring
    forces: the inertia and damping forces of the DOFs above the storey's foot
    (``V_j = −Σ_{above} (M ü_abs + C u̇)``, no contact)."""
    n = b.n
    force = -(r.abs_acceleration[:, off:off + n] * b.masses) \
        - r.velocity[:, off:off + n] @ b.damping_matrix().T
    z, lateral = b.elevations, b.r == 1.0
    floors = b.floor_dofs
    below = np.concatenate([[0.0], z[floors[:-1]]])
    return np.stack([force[:, lateral & (z > below[j] + 1e-6)].sum(axis=1)
                     for j in range(floors.size)], axis=1)


@pytest.mark.parametrize("kind", ["yielding", "elastic", "no rigid floors"])
def test_a_frame_s_storey_shears_balance_the_forces_above(kind: str) -> None:
    # storey shears from the frame's restoring forces (the run's configurations) against
    # the inertia and damping forces above each storey; with gravity and P-Delta
    law = BilinearHinge(k0=1e11, m_y=2.4e5, hardening=0.03)
    frame = regular_frame([6.0, 6.0], [4.0, 3.5, 3.5], column_EI=3e8, beam_EI=2.5e8,
                          column_hinge=None if kind == "elastic" else law,
                          beam_hinge=None if kind == "elastic" else law,
                          floor_mass=8e4, beam_load=2e4, leaning_load=5e5, beam_EA=5e9,
                          geometry="p-delta", diaphragm=kind != "no rigid floors", name="A")
    b = frame_matrix_building(frame)
    r = simulate(PoundingModel([b], [], KV), el_centro().scaled(1.5), duration=4.0)
    if kind != "elastic":
        assert r.stats.events > 10  # the hinges yielded
    expected = _shear_from_motion(b, r)
    got = r.storey_shear[:, list(b.floor_dofs)]
    # measured 2026-11-27: 7e-16 (yielding), 2e-16 (elastic), 2e-14 (no rigid floors)
    err = np.max(np.abs(got - expected)) / np.max(np.abs(expected))
    assert err < 1e-8, err
    assert r.peak_storey_shear[0] == pytest.approx(np.abs(expected[:, 0]).max(), rel=1e-8)
    assert np.isnan(r.column_shear).all()  # (no floor-to-column contact; a frame's: NaN)
