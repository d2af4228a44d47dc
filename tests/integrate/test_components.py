"""G ground components (an influence matrix R of shape (N, G)) and contact rows of any
width (issue 18): the kernel against the one-component run, superposition of separate
runs, ``scipy.signal.lsim`` of the state-space model, the SciPy reference with a contact
row of width 6, and the energy balance."""

from __future__ import annotations

from functools import cached_property

import numpy as np
import pytest
from scipy import signal

from pounding.ground_motion import GroundMotion, GroundMotionComponents, el_centro
from pounding.integrate import simulate
from pounding.integrate.propagator import state_matrix
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ModalDamping, ShearBuilding

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


class _Hooked(PoundingModel):
    """A PoundingModel with an influence matrix R of its own (``R``) and, if ``ROWS`` is
    set, contact rows of its own: ``ROWS(model) -> (dof, weight)`` of shape (n_c, W). The
    test's stand-in for the plan buildings of issue 18, which give these themselves."""

    R: np.ndarray | None = None
    ROWS = None

    @cached_property
    def system(self):  # noqa: ANN201
        s = super().system
        return s if self.R is None else s._replace(r=np.array(self.R, dtype=float))

    def contact_kinematics(self):  # noqa: ANN201
        if self.ROWS is None:
            return super().contact_kinematics()
        return type(self).ROWS(self)


def hooked(buildings, gaps, spec, R=None, rows=None) -> PoundingModel:  # noqa: ANN001
    cls = type("Hooked", (_Hooked,), {"R": None if R is None else np.asarray(R, dtype=float),
                                      "ROWS": staticmethod(rows) if rows else None})
    return cls(buildings, gaps, spec)


def sdof_pair() -> list[ShearBuilding]:
    return [ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05),
            ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.05)]


def shear_pair() -> list[ShearBuilding]:
    return [ShearBuilding.uniform(3, 3e5, 4e8),
            ShearBuilding.uniform(3, 2e5, 2e8, damping=ModalDamping(0.03))]


@pytest.fixture(scope="module")
def rec() -> GroundMotion:
    return el_centro().trimmed(6.0)


@pytest.fixture(scope="module")
def rec2(rec) -> GroundMotion:
    """A second, different record of the same step: a later window of El Centro, 0.7×."""
    a = el_centro().accel
    return GroundMotion(rec.dt, 0.7 * a[300: 300 + rec.npts], name="El Centro window")


def test_second_component_zero_equals_one_component(rec):
    """R = [r, q] under (a, 0) is the model with r under a, to round-off (the free steps
    come from a larger matrix exponential), impacts and all."""
    bs = shear_pair()
    one = PoundingModel(bs, [0.01], KV)
    n = one.n_dof
    two = hooked(bs, [0.01], KV, R=np.column_stack([np.ones(n), np.linspace(-1, 1, n)]))
    zero = GroundMotion(rec.dt, np.zeros(rec.npts), name="zero")
    r1 = simulate(one, rec)
    r2 = simulate(two, GroundMotionComponents.of(rec, zero))
    assert r1.n_impacts > 3 and r2.n_impacts == r1.n_impacts
    assert r2.ground.shape == (r1.ground.size, 2)
    np.testing.assert_array_equal(r2.ground[:, 0], r1.ground)
    ds = r2.to_dataset()
    assert ds["ground_acceleration"].dims == ("time", "ground_component")
    assert list(ds["ground_component"].values) == [rec.name, "zero"]
    for name in ("displacement", "abs_acceleration", "contact_force"):
        a, b = getattr(r1, name), getattr(r2, name)
        assert np.max(np.abs(a - b)) <= 1e-9 * np.abs(a).max(), name
    np.testing.assert_allclose(r2.peak_contact_force, r1.peak_contact_force, rtol=1e-9)
    np.testing.assert_allclose(r2.energy[-1], r1.energy[-1], rtol=1e-9, atol=1e-9 *
                               np.abs(r1.energy[-1]).max())


@pytest.mark.parametrize("free_stepping", ["exact", "rk"])
def test_uncoupled_pair_is_two_separate_runs(rec, rec2, free_stepping):
    """Two SDOF buildings that never touch, R = I: floor g moves under record g alone, as
    in the planar runs of each record (R = [1, 1]) by itself."""
    bs = sdof_pair()
    both = hooked(bs, [10.0], KV, R=np.eye(2))
    planar = PoundingModel(bs, [10.0], KV)
    res = simulate(both, GroundMotionComponents.of(rec, rec2), free_stepping=free_stepping)
    for g, r in enumerate((rec, rec2)):
        alone = simulate(planar, r, free_stepping=free_stepping)
        for name in ("displacement", "velocity", "abs_acceleration"):
            a, b = getattr(res, name)[:, g], getattr(alone, name)[:, g]
            assert np.max(np.abs(a - b)) <= 1e-9 * np.abs(b).max(), (name, g)
        np.testing.assert_allclose(res.peak_displacement[g], alone.peak_displacement[g],
                                   rtol=1e-9)


@pytest.mark.parametrize("free_stepping", ["exact", "rk"])
def test_coupled_linear_system_matches_lsim(rec, rec2, free_stepping):
    """A coupled linear system (two 3-storey buildings, gaps never closing) under two
    components through a full R: the state-space model ``ẋ = A x − [0; R] a_g`` solved by
    scipy.signal.lsim (exact for a piecewise-linear input)."""
    bs = shear_pair()
    n = 6
    R = np.column_stack([np.ones(n), np.array([0.4, 0.8, 1.2, -0.5, -1.0, -1.5])])
    model = hooked(bs, [10.0], KV, R=R)
    motion = GroundMotionComponents.of(rec, rec2)
    res = simulate(model, motion, free_stepping=free_stepping)
    s = model.system
    A = state_matrix(s.M, s.C, s.K)
    B = np.vstack([np.zeros((n, 2)), -R])
    sysd = signal.StateSpace(A, B, np.eye(2 * n), np.zeros((2 * n, 2)))
    _, _, x = signal.lsim(sysd, res.ground, res.time, interp=True)
    scale = np.abs(x[:, :n]).max()
    assert np.max(np.abs(res.displacement - x[:, :n])) < 1e-7 * scale
    vscale = np.abs(x[:, n:]).max()
    assert np.max(np.abs(res.velocity - x[:, n:])) < 1e-7 * vscale
    # absolute acceleration ü + R a_g = −M⁻¹(K u + C u̇): the rows of A x
    acc_abs = (A @ x.T).T[:, n:]
    assert np.max(np.abs(res.abs_acceleration - acc_abs)) < 1e-6 * np.abs(acc_abs).max()


def _rows_width_6(model: PoundingModel) -> tuple[np.ndarray, np.ndarray]:
    """Every contact (floor k of two 3-storey buildings) as a row of width 6: its penetration
    ``u_k + 0.2 u_k' + 0.05 u_j − (the same of the right building)`` (k' = k+1, j = k+2
    mod 3), as a façade point that moves with three floors of each building would."""
    cs = model.contacts
    dof = np.zeros((len(cs), 6), dtype=np.int64)
    w = np.zeros((len(cs), 6))
    for c in cs:
        k = c.left.upper  # floor k of both buildings (equal floor levels)
        k1, k2 = (k + 1) % 3, (k + 2) % 3
        dof[c.index] = [k, k1, k2, 3 + k, 3 + k1, 3 + k2]
        w[c.index] = [1.0, 0.2, 0.05, -1.0, -0.2, -0.05]
    return dof, w


@pytest.fixture(scope="module")
def wide_runs(rec, rec2):
    """The kernel and the SciPy reference on a pair of 3-storey buildings under two
    components through R, every contact a row of width 6."""
    bs = shear_pair()
    R = np.column_stack([np.ones(6), np.array([0.3, 0.6, 0.9, -0.2, -0.4, -0.6])])
    model = hooked(bs, [0.01], KV, R=R, rows=_rows_width_6)
    motion = GroundMotionComponents.of(rec.trimmed(4.0), rec2.trimmed(4.0))
    res = simulate(model, motion, rtol=1e-11)
    ref = simulate_reference(model, motion, rtol=1e-12)
    return model, res, ref


def test_contact_rows_of_width_6_match_reference(wide_runs):
    model, res, ref = wide_runs
    dof, _ = model.contact_kinematics()
    assert dof.shape[1] == 6
    assert ref.n_impacts > 3
    assert res.n_impacts == ref.n_impacts
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-6)
    np.testing.assert_allclose(res.impacts["start"], ref.impacts["start"], atol=1e-8)
    scale = np.abs(ref.displacement).max()
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-7 * scale


def test_energy_balance_closes_with_two_components(wide_runs):
    """Input energy −Σ∫ u̇ᵀ M R a_g dt against what the structure stores and dissipates,
    in both solvers; and the kernel's input energy against the trapezoid of its own
    histories."""
    model, res, ref = wide_runs
    assert res.energy_balance_error < 1e-6
    assert ref.energy_balance_error < 1e-6
    assert abs(res.energy[-1, 0] - ref.energy[-1, 0]) < 1e-6 * np.abs(ref.energy[:, 0]).max()
    s = model.system
    p_in = -np.einsum("ki,ij,jg,kg->k", res.velocity, s.M, s.r, res.ground)
    e_trap = np.concatenate([[0.0], np.cumsum(0.5 * (p_in[1:] + p_in[:-1]) * res.dt)])
    assert np.max(np.abs(e_trap - res.energy[:, 0])) < 1e-3 * np.abs(res.energy[:, 0]).max()


def test_component_count_must_match_R(rec, rec2):
    bs = sdof_pair()
    two = hooked(bs, [0.02], KV, R=np.eye(2))
    with pytest.raises(ValueError, match=r"^motion: 1 ground component for a model whose "
                                         r"influence matrix R has 2 columns"):
        simulate(two, rec)
    with pytest.raises(ValueError, match=r"2 ground components .* R has 1 column "):
        simulate(PoundingModel(bs, [0.02], KV), GroundMotionComponents.of(rec, rec2))
    with pytest.raises(ValueError, match="R has 2 columns"):
        simulate_reference(two, rec)


def test_components_pad_the_shorter_and_check_the_step(rec):
    short = rec.trimmed(2.0)
    both = GroundMotionComponents.of(rec, short)
    assert both.n_components == 2 and both.dt == rec.dt
    assert both.duration == rec.duration
    assert both.pgv == max(rec.pgv, short.pgv) and both.pga == rec.pga
    assert np.array_equal(both.accel[short.npts:, 1], np.zeros(rec.npts - short.npts))
    with pytest.raises(ValueError, match="component 1 .* dt = 0.02 s"):
        GroundMotionComponents.of(rec, GroundMotion(0.02, [0.0, 1.0], name="coarse"))
    with pytest.raises(ValueError, match="at least one"):
        GroundMotionComponents(())
