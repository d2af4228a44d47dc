"""Frames with plastic hinges in the compiled kernel (:mod:`pounding.integrate.frame_run`):
checked against the elastic matrix-building path, the portal's mechanism load 4 Mp/h,
OpenSeesPy converging as its step shrinks, the energy balance with the hinges' hysteretic
energy, and pounding beside a shear building."""

from __future__ import annotations

import math

import numpy as np
import pytest
from frame_kernel_models import (  # (this folder)
    KV,
    MASS,
    MP_COLUMN,
    _portal,
    _three_storeys,
)

from pounding.ground_motion import GroundMotion, el_centro
from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic, moment_path
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import MatrixBuilding, ShearBuilding
from pounding.structure.frame import regular_frame
from pounding.structure.frame_linear import FrameBuilding, frame_matrix_building


def _restoring_force(r, building: MatrixBuilding) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The frame's restoring force on its floors [N] (nt, n_f), from the equation of motion:
    ``R = −M ü_abs − C u̇`` (no contact)."""
    return -(r.abs_acceleration * building.masses) - r.velocity @ building.damping_matrix().T


def test_the_frame_building_carries_its_frame_and_gravity_state() -> None:
    b = frame_matrix_building(_portal())
    assert isinstance(b, FrameBuilding) and b.has_hinges and len(b.hinges) == 6
    model = PoundingModel([b], [], KV)
    assert model.yielding_frames == ((0, b),)
    assert model.hinge_labels() == [f"B1H{h}" for h in range(1, 7)]
    # the elastic portal's lateral stiffness, 24 EI/h³ (12ρ + 1)/(12ρ + 4) with ρ = 1/3,
    # less the hinges' flexibility (k0 = 1e11, 500 times a column's 4EI/h)
    assert b.K[0, 0] == pytest.approx(24 * 2e8 / 4.0 ** 3 * 5 / 8, rel=5e-3)


def test_a_frame_whose_hinges_never_yield_runs_as_its_matrix_building() -> None:
    # gravity, P-Delta and a leaning column; hinges far too strong to yield: the frame is its
    # condensed matrices (the constant force of its gravity state is round-off)
    strong = frame_matrix_building(_three_storeys("A", strength=1e6, gravity=True))
    plain = MatrixBuilding(M=strong.M, K=strong.K, C=strong.damping_matrix(),
                           labels=strong.labels, elevations=strong.elevations, name="A")
    other = ShearBuilding.uniform(3, 1e5, 8e7, height=3.6)
    motion = el_centro()
    got = simulate(PoundingModel([strong, other], [0.01], KV), motion, duration=4.0)
    rk = simulate(PoundingModel([plain, other], [0.01], KV), motion, duration=4.0,
                  free_stepping="rk")
    exact = simulate(PoundingModel([plain, other], [0.01], KV), motion, duration=4.0)
    assert got.n_impacts == rk.n_impacts == exact.n_impacts > 0
    scale = np.max(np.abs(rk.displacement))
    assert np.max(np.abs(got.displacement - rk.displacement)) <= 1e-10 * scale
    assert np.max(np.abs(got.contact_force - rk.contact_force)) <= 1e-8 * np.max(rk.contact_force)
    assert np.max(np.abs(got.displacement - exact.displacement)) <= 1e-6 * scale
    assert got.energy_balance_error < 1e-8
    assert np.all(np.abs(got.hinge_moment) < 1e6 * 2.5e5)  # (no hinge near its yield)


def test_the_portal_carries_four_mp_over_h_while_its_mechanism_moves() -> None:
    b = frame_matrix_building(_portal())
    r = simulate(PoundingModel([b], [], KV), el_centro().scaled(3.0), duration=6.0)
    R = _restoring_force(r, b)[:, 0]
    mechanism = 4 * MP_COLUMN / 4.0  # 300 kN
    assert np.max(np.abs(R)) <= mechanism * (1 + 1e-9)
    moments = r.hinge_moment
    plastic = np.all(np.isclose(np.abs(moments[:, :4]), MP_COLUMN, rtol=1e-12, atol=0), axis=1)
    assert plastic.sum() > 50  # the sway mechanism moves for a while
    assert np.abs(R[plastic]) == pytest.approx(mechanism, rel=1e-7)
    # the beam's stay elastic: at the joints they carry the column tops' moments, at most
    # Mp (and the event tolerance of a hinge's rotation times k0: 3e-4 N·m measured)
    assert np.max(np.abs(moments[:, 4:])) <= MP_COLUMN * (1 + 1e-8)
    # statics of the portal at every output step: the storey shear is the columns' end
    # moments over the height, R = Σ M / h (a check of the condensation and of the hinge
    # rows against each other: 8e-7 N measured)
    assert np.max(np.abs(R - np.sum(moments[:, :4], axis=1) / 4.0)) < 1e-6 * mechanism
    # every hinge moment is its law's along the rotation history (EPP: |M| ≤ Mp)
    assert np.max(np.abs(moments)) <= 6e5
    assert r.hinge_peak_rotation[0] > 10 * 3e-6 and r.hinge_residual_rotation[0] != 0.0
    assert r.energy_balance_error < 1e-9


def test_the_hinges_hysteretic_energy_is_their_work_less_their_recoverable_energy() -> None:
    b = frame_matrix_building(_portal())
    r = simulate(PoundingModel([b], [], KV), el_centro().scaled(3.0), duration=6.0)
    theta, moment = r.hinge_rotation, r.hinge_moment
    # ∫ M dθ by the trapezoidal rule on the output steps (exact along a branch), less the
    # recoverable energy M²/(2 k0) at the end
    work = np.sum(0.5 * (moment[1:] + moment[:-1]) * np.diff(theta, axis=0), axis=0)
    hysteretic = work - moment[-1] ** 2 / (2 * 1e11)
    assert r.hinge_dissipated == pytest.approx(hysteretic, rel=1e-3, abs=1e-3)
    assert r.energy[-1, 6] == pytest.approx(np.sum(r.hinge_dissipated), rel=1e-12)
    assert r.energy[-1, 6] > 0.3 * r.energy[-1, 0]  # the hinges dissipate much of the input
    # the moments follow the hinge law along the rotations (the law replayed sample by
    # sample; a reversal between two samples shifts its plastic offset by at most
    # k0 θ̈ dt²/8, here under 1 % of Mp)
    for h in range(4):
        replay = moment_path(ElasticPlastic(k0=1e11, m_y=MP_COLUMN), theta[:, h])
        assert np.max(np.abs(replay - moment[:, h])) < 0.01 * MP_COLUMN


def test_the_answer_does_not_depend_on_the_output_step() -> None:
    b = frame_matrix_building(_portal())
    model = PoundingModel([b], [], KV)
    fine = simulate(model, el_centro().scaled(3.0), duration=5.0, dt=1e-3)
    coarse = simulate(model, el_centro().scaled(3.0), duration=5.0, dt=5e-3)
    assert coarse.peak_displacement == pytest.approx(fine.peak_displacement, rel=1e-7)
    assert coarse.hinge_peak_rotation == pytest.approx(fine.hinge_peak_rotation, rel=1e-7)
    assert coarse.hinge_residual_rotation == pytest.approx(fine.hinge_residual_rotation,
                                                           rel=1e-6, abs=1e-12)
    assert coarse.displacement[-1] == pytest.approx(fine.displacement[-1], rel=1e-6)


def test_a_frame_at_rest_under_its_gravity_loads_stays_at_rest() -> None:
    b = frame_matrix_building(_three_storeys("A", gravity=True))
    still = GroundMotion(0.01, np.zeros(200), name="none")
    r = simulate(PoundingModel([b], [], KV), still)
    assert np.max(np.abs(r.displacement)) < 1e-12
    assert np.max(np.abs(r.hinge_rotation - r.hinge_rotation[0])) < 1e-15


def test_a_yielding_frame_pounds_a_shear_building_and_the_energy_closes() -> None:
    frame = frame_matrix_building(_three_storeys("A", strength=0.8, gravity=True))
    stiff = ShearBuilding.uniform(3, 1.5e5, 4e8, height=4.0, name="B")
    r = simulate(PoundingModel([frame, stiff], [0.01], KV), el_centro().scaled(1.5),
                 duration=6.0)
    assert r.n_impacts > 0 and np.all(np.isfinite(r.displacement))
    assert np.max(np.abs(r.hinge_moment)) > 0.8 * 2.5e5  # hinges yield
    assert np.sum(r.hinge_dissipated) > 0.0
    assert r.energy_balance_error < 1e-8
    assert np.isfinite(r.peak_contact_force).all() and r.peak_contact_force.max() > 0.0


def test_exact_stepping_is_refused_for_a_yielding_frame() -> None:
    model = PoundingModel([frame_matrix_building(_portal())], [], KV)
    with pytest.raises(ValueError, match="free_stepping: 'exact'.*plastic hinges"):
        simulate(model, el_centro(), duration=0.1, free_stepping="exact")


def _opensees_portal(ag: np.ndarray, record_dt: float, dt: float, duration: float,
                     damping: float) -> tuple[np.ndarray, bool]:
    """The portal in OpenSeesPy (zeroLength ElasticPP hinges between each joint and its
    member ends, elastic beam-columns, a beam rigid axially for the rigid floor, the floor's
    mass at one top joint, mass-proportional damping equal to the kernel's C, Newmark
    average acceleration with Newton): the floor's displacement at every step, and whether
    every step converged."""
    ops = pytest.importorskip("openseespy.opensees")
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, (x, y) in enumerate([(0, 0), (6, 0), (0, 4), (6, 4)], start=1):
        ops.node(tag, x, y)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ends = {11: 1, 12: 3, 13: 2, 14: 4, 15: 3, 16: 4}  # member end: its joint
    for end, joint in ends.items():
        ops.node(end, *ops.nodeCoord(joint))
        ops.equalDOF(joint, end, 1, 2)
    ops.uniaxialMaterial("ElasticPP", 1, 1e11, MP_COLUMN / 1e11)
    ops.uniaxialMaterial("ElasticPP", 2, 1e11, 6e5 / 1e11)
    for i, (end, joint) in enumerate(ends.items()):
        ops.element("zeroLength", 100 + i, joint, end, "-mat", 1 if end < 15 else 2, "-dir", 6)
    ops.geomTransf("Linear", 1)
    E = 2e11
    ops.element("elasticBeamColumn", 1, 11, 12, 1e12 / E, E, 2e8 / E, 1)
    ops.element("elasticBeamColumn", 2, 13, 14, 1e12 / E, E, 2e8 / E, 1)
    # (the floor made rigid by the beam's axial stiffness: an equalDOF between the joints
    # chained to the member ends' equalDOFs is mis-handled by the Transformation handler,
    # which then reports a 24 % stiffer frame)
    ops.element("elasticBeamColumn", 3, 15, 16, 1e16 / E, E, 2e8 / E, 1)
    ops.mass(3, MASS, 0.0, 0.0)
    ops.timeSeries("Path", 1, "-dt", record_dt, "-values", *ag)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.rayleigh(damping / MASS, 0.0, 0.0, 0.0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    n = int(round(duration / dt))
    u = np.zeros(n + 1)
    for k in range(n):
        if ops.analyze(1, dt) != 0:
            return u[: k + 1], False
        u[k + 1] = ops.nodeDisp(3, 1)
    ops.wipe()
    return u, True


def test_opensees_converges_toward_the_kernel_on_the_yielding_portal() -> None:
    b = frame_matrix_building(_portal())
    motion = el_centro().scaled(3.0)
    duration = 4.0  # the mechanism forms at 2.2 s and the frame is left leaning
    r = simulate(PoundingModel([b], [], KV), motion, duration=duration)
    peak, final = r.peak_displacement[0], r.displacement[-1, 0]
    assert r.hinge_peak_rotation[0] > 1e-3  # well past yield (3e-6 rad)
    errors = []
    for dt in (1e-3, 5e-4, 2.5e-4):
        u, converged = _opensees_portal(motion.accel, motion.dt, dt, duration,
                                        float(b.damping_matrix()[0, 0]))
        assert converged, dt
        errors.append((abs(np.max(np.abs(u)) - peak) / peak, abs(u[-1] - final) / abs(final)))
    peak_err, final_err = np.array(errors).T
    # OpenSees' error shrinks with its step toward the kernel's answer
    assert peak_err[0] > peak_err[1] > peak_err[2] and final_err[0] > final_err[2]
    assert peak_err[2] < 1e-5 and final_err[2] < 1e-4
    assert math.isfinite(final)


def test_hinges_yielded_by_gravity_start_on_their_plastic_branch_and_stay_at_rest() -> None:
    # beam hinges of 200 kN·m under wL²/12 = 300 kN·m of gravity (hardening 2 %): they
    # yield before the shaking starts, each on a branch that holds one way only
    frame = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                          column_hinge=BilinearHinge(k0=1e11, m_y=1e6, hardening=0.02),
                          beam_hinge=BilinearHinge(k0=1e11, m_y=2e5, hardening=0.02),
                          floor_mass=MASS, beam_load=1e5, name="sagging")
    b = frame_matrix_building(frame)
    assert abs(b.gravity_state.hinges[4].moment) > 2e5
    model = PoundingModel([b], [], KV)
    still = simulate(model, GroundMotion(0.01, np.zeros(100), name="none"))
    assert np.max(np.abs(still.displacement)) < 1e-12
    shaken = simulate(model, el_centro(), duration=3.0)
    assert shaken.energy_balance_error < 1e-9
    assert np.all(np.isfinite(shaken.hinge_moment))


def test_a_yielding_frame_given_an_initial_displacement_is_refused_in_one_line() -> None:
    model = PoundingModel([frame_matrix_building(_portal())], [], KV)
    with pytest.raises(ValueError, match=r"^initial_displacement: frame 'portal' \(building "
                                         r"B1\) starts displaced"):
        simulate(model, el_centro(), duration=0.1, initial_displacement=[0.01])
    moving = simulate(model, el_centro(), duration=1.0, initial_velocity=[0.3])
    assert moving.displacement[1, 0] > 0.0 and moving.energy_balance_error < 1e-9
