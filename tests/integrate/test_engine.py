"""The time-history engine against closed forms, the SciPy reference, energy balance and the
single-collision analysis (issue 3, "Verification")."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.contact.collision import simulate_collision
from pounding.ground_motion import GroundMotion, el_centro, harmonic
from pounding.integrate import grid_step, simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ModalDamping, ShearBuilding

M1, T1, M2, T2 = 2.0e5, 0.5, 3.0e5, 1.0
KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
NLVE = ContactSpec("nonlinear-viscoelastic", k_h=2.75e9, e=0.65)


def sdof_pair(spec: ContactSpec, gap: float = 0.02) -> PoundingModel:
    return PoundingModel([ShearBuilding.sdof(M1, period=T1, damping_ratio=0.05),
                          ShearBuilding.sdof(M2, period=T2, damping_ratio=0.05)], [gap], spec)


def zero_motion(duration: float, dt: float = 0.01) -> GroundMotion:
    return GroundMotion(dt, np.zeros(int(round(duration / dt)) + 1), name="at rest")


# ---------------------------------------------------------------- without contact
def test_grid_step_divides_the_record_step():
    assert grid_step(0.01) == pytest.approx(0.001)
    assert grid_step(0.02, 0.003) == pytest.approx(0.02 / 7)
    assert grid_step(0.005, 0.01) == pytest.approx(0.005)


def test_free_vibration_matches_closed_form():
    # damped SDOF released from u0 (Chopra eq 2.2.4): exact propagation, any step
    m, T, zeta, u0 = 1.0e5, 0.8, 0.05, 0.03
    model = PoundingModel([ShearBuilding.sdof(m, period=T, damping_ratio=zeta)], [],
                          ContactSpec("linear-spring", k=1e8))
    res = simulate(model, zero_motion(5.0), initial_displacement=np.array([u0]))
    w = 2 * math.pi / T
    wd = w * math.sqrt(1 - zeta**2)
    t = res.time
    exact = np.exp(-zeta * w * t) * (u0 * np.cos(wd * t) + zeta * w * u0 / wd * np.sin(wd * t))
    assert np.max(np.abs(res.displacement[:, 0] - exact)) < 1e-12
    # energy: everything stored at t=0 goes to damping
    e = res.energy[-1]
    assert e[3] + e[1] + e[2] == pytest.approx(0.5 * (m * w**2) * u0**2, rel=1e-9)


def test_harmonic_steady_state_matches_closed_form():
    # steady-state amplitude of u for a_g = A sin Ωt: (A/ω²) / sqrt((1−β²)² + (2ζβ)²)
    m, T, zeta, A, f = 1.0e5, 0.5, 0.05, 1.0, 1.3
    model = PoundingModel([ShearBuilding.sdof(m, period=T, damping_ratio=zeta)], [],
                          ContactSpec("linear-spring", k=1e8))
    res = simulate(model, harmonic(A, f, 40.0, 0.001))
    w = 2 * math.pi / T
    beta = 2 * math.pi * f / w
    amp = (A / w**2) / math.sqrt((1 - beta**2) ** 2 + (2 * zeta * beta) ** 2)
    tail = res.displacement[res.time > 30.0, 0]
    assert np.max(np.abs(tail)) == pytest.approx(amp, rel=2e-4)


@pytest.mark.parametrize("free_stepping", ["exact", "rk"])
def test_uncoupled_floors_without_contact_match_reference(free_stepping):
    # a row of SDOF oscillators (no floor coupled to another: the kernel's floor-by-floor
    # branch, bandwidth 0) in both ways of stepping: every output against SciPy
    from pounding.integrate import kernel_model

    model = sdof_pair(KV, gap=1.0)
    assert kernel_model(model).floors.bw == 0  # the branch under test
    gm = el_centro()
    res = simulate(model, gm, duration=6.0, free_stepping=free_stepping)
    ref = simulate_reference(model, gm, duration=6.0)
    assert res.n_impacts == ref.n_impacts == 0
    for name in ("displacement", "velocity", "abs_acceleration"):
        a, b = getattr(res, name), getattr(ref, name)
        assert np.max(np.abs(a - b)) < 1e-6 * np.abs(b).max(), name
    # kinetic and strain energy from the histories themselves
    m = np.array([M1, M2])
    k = m * (2 * np.pi / np.array([T1, T2])) ** 2
    ek = 0.5 * (m * res.velocity**2).sum(axis=1)
    es = 0.5 * (k * res.displacement**2).sum(axis=1)
    np.testing.assert_allclose(res.energy[:, 1], ek, rtol=1e-9, atol=1e-9 * ek.max())
    np.testing.assert_allclose(res.energy[:, 2], es, rtol=1e-9, atol=1e-9 * es.max())
    assert res.energy_balance_error < 1e-6


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_mdof_without_contact_matches_reference():
    b1 = ShearBuilding.uniform(5, 3e5, 4e8)
    b2 = ShearBuilding.uniform(3, 2e5, 2e8, damping=ModalDamping(0.03))
    model = PoundingModel([b1, b2], [1.0], KV)  # gap too wide to close
    gm = el_centro()
    res = simulate(model, gm, duration=6.0)
    ref = simulate_reference(model, gm, duration=6.0)
    assert res.n_impacts == ref.n_impacts == 0
    scale = np.abs(ref.displacement).max()
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-7 * scale
    assert np.max(np.abs(res.abs_acceleration - ref.abs_acceleration)) < 1e-6 * np.abs(
        ref.abs_acceleration).max()


# ---------------------------------------------------------------- with contact
@pytest.fixture(scope="module")
def el_centro_8s() -> GroundMotion:
    return el_centro().trimmed(8.0)


@pytest.mark.parametrize("spec", [
    KV,
    NLVE,
    ContactSpec("kelvin-voigt", k=9.3e8, e=0.65, tension=False),
    ContactSpec("hertzdamp", k_h=2.75e9, e=0.65),
    ContactSpec("bilinear-impact", k_h=2.75e9, e=0.65, delta_m=0.003),
    ContactSpec("modified-kelvin-voigt", k=9.3e8, e=0.65),
], ids=lambda s: s.law + ("" if s.tension else "-clipped"))
def test_kernel_matches_reference_with_contact(spec, el_centro_8s):
    model = sdof_pair(spec)
    res = simulate(model, el_centro_8s)
    ref = simulate_reference(model, el_centro_8s)
    assert ref.n_impacts > 3
    assert res.n_impacts == ref.n_impacts
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=5e-4)
    np.testing.assert_allclose(res.peak_displacement, ref.peak_displacement, rtol=1e-3)
    np.testing.assert_allclose(res.impacts["start"], ref.impacts["start"], atol=1e-6)
    np.testing.assert_allclose(res.impacts["restitution"], ref.impacts["restitution"], rtol=1e-3,
                               atol=1e-4)
    np.testing.assert_allclose(res.impacts["energy_dissipated"], ref.impacts["energy_dissipated"],
                               rtol=1e-3)


@pytest.mark.parametrize("spec", [KV, NLVE, ContactSpec("modified-kelvin-voigt", k=9.3e8, e=0.65)],
                         ids=lambda s: s.law)
def test_steps_are_not_rejected_at_separation_or_maximum_compression(spec):
    """Inside a step a closed contact's law is continued smoothly past δ = 0 and past
    δ̇ = 0 (kernel._deriv), so the steps that reach separation or the approach/restitution
    switch are not rejected over and over for a kink in the force. Before that, the SDOF
    pair on El Centro had 298 (Kelvin–Voigt) and 195 (Jankowski) rejected steps for its
    27 / 26 impacts; what is left is mostly the first steps after each onset."""
    res = simulate(sdof_pair(spec), el_centro())
    assert res.n_impacts > 20
    assert res.stats.rejected <= 3 * res.n_impacts


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_ten_storey_pair_matches_reference():
    b1 = ShearBuilding.uniform(10, 4e5, 6e8)
    b2 = ShearBuilding.uniform(10, 3e5, 3e8)
    model = PoundingModel([b1, b2], [0.01], NLVE)
    gm = el_centro().trimmed(3.0)  # 5 impacts
    res = simulate(model, gm)
    ref = simulate_reference(model, gm)
    assert res.n_impacts == ref.n_impacts > 3
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-3,
                               atol=1e-3 * ref.peak_contact_force.max())
    np.testing.assert_allclose(res.peak_displacement, ref.peak_displacement, rtol=1e-3)


def test_results_converge_with_tolerance(el_centro_8s):
    # global error of the adaptive 5(4) pair falls about in proportion to rtol
    model = sdof_pair(NLVE)
    ref = simulate(model, el_centro_8s, rtol=1e-11)
    errs = []
    for rtol in (1e-5, 1e-7, 1e-9):
        r = simulate(model, el_centro_8s, rtol=rtol)
        errs.append(np.max(np.abs(r.displacement - ref.displacement)))
    order = [math.log10(errs[i] / errs[i + 1]) / 2 for i in range(2)]
    assert errs[0] > errs[1] > errs[2]
    assert min(order) > 0.6  # ≈ 1 decade of error per decade of tolerance


def test_result_does_not_depend_on_the_output_step(el_centro_8s):
    # steps without contact are exact and contacts are sub-stepped: the grid only samples
    model = sdof_pair(KV)
    a = simulate(model, el_centro_8s, dt=0.001)
    b = simulate(model, el_centro_8s, dt=0.005)
    assert a.n_impacts == b.n_impacts
    np.testing.assert_allclose(a.peak_contact_force, b.peak_contact_force, rtol=1e-5)
    np.testing.assert_allclose(a.displacement[::5], b.displacement, atol=1e-8)


def test_energy_balance_closes_on_a_real_record():
    model = sdof_pair(NLVE)
    res = simulate(model, el_centro())
    assert res.n_impacts > 10
    assert res.energy_balance_error < 5e-3
    assert res.energy_balance_error < 1e-6  # measured: ~1e-10
    # dissipated contact energy equals the sum over the impact table (all impacts closed)
    closed = res.impacts.dropna()
    assert res.contact_dissipated[-1] == pytest.approx(closed["energy_dissipated"].sum(), rel=1e-6)


def test_very_stiff_contact_is_stable_and_accurate():
    # k_h = 1e11 N/m^1.5, 40 times Jankowski's concrete value
    model = sdof_pair(ContactSpec("nonlinear-viscoelastic", k_h=1e11, e=0.5))
    gm = el_centro().trimmed(6.0)
    res = simulate(model, gm)
    ref = simulate_reference(model, gm)
    assert np.all(np.isfinite(res.displacement))
    assert res.n_impacts == ref.n_impacts > 3
    assert res.energy_balance_error < 1e-6
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=5e-4)
    np.testing.assert_allclose(res.impacts["max_penetration"], ref.impacts["max_penetration"],
                               rtol=1e-4)


@pytest.mark.parametrize("law,kw", [
    ("kelvin-voigt", {"k": 9.3e8}),
    ("nonlinear-viscoelastic", {"k_h": 2.75e9}),
    ("hunt-crossley", {"k_h": 2.75e9}),
    ("naderpour", {"k_h": 2.75e9}),
])
def test_single_collision_inside_the_engine_matches_collision_analysis(law, kw):
    # two almost free masses (T = 1000 s), no ground motion, the left one moving right
    spec = ContactSpec(law, e=0.6, **kw)
    model = PoundingModel([ShearBuilding.sdof(M1, period=1000.0, damping_ratio=0.0),
                           ShearBuilding.sdof(M2, period=1000.0, damping_ratio=0.0)],
                          [0.001], spec)
    v0 = 0.5
    res = simulate(model, zero_motion(0.3, 0.01), initial_velocity=np.array([v0, 0.0]))
    assert res.n_impacts == 1
    row = res.impacts.iloc[0]
    single = simulate_collision(model.contacts[0].law, M1, M2, v0)
    assert row["v0"] == pytest.approx(v0, rel=1e-6)
    assert row["restitution"] == pytest.approx(single.e, abs=2e-5)
    assert row["peak_force"] == pytest.approx(single.peak_force, rel=2e-4)
    assert row["max_penetration"] == pytest.approx(single.delta_max, rel=1e-5)
    assert row["end"] - row["start"] == pytest.approx(single.duration, rel=1e-4)


def test_bad_initial_state_is_refused():
    model = sdof_pair(KV)
    with pytest.raises(ValueError, match="initial_displacement"):
        simulate(model, zero_motion(1.0), initial_displacement=np.array([0.05, 0.0]))
    with pytest.raises(ValueError, match="initial_velocity"):
        simulate(model, zero_motion(1.0), initial_velocity=np.array([1.0]))


def test_exact_and_rk_free_stepping_agree(el_centro_8s):
    # the two ways of stepping between impacts give one answer (the RK path is the one every
    # contact uses anyway; "auto" picks by model size)
    b1 = ShearBuilding.uniform(4, 4e5, 6e8)
    b2 = ShearBuilding.uniform(3, 3e5, 3e8)
    model = PoundingModel([b1, b2], [0.01], NLVE)
    a = simulate(model, el_centro_8s, free_stepping="exact")
    b = simulate(model, el_centro_8s, free_stepping="rk")
    assert a.n_impacts == b.n_impacts > 0
    np.testing.assert_allclose(a.peak_contact_force, b.peak_contact_force, rtol=1e-4,
                               atol=1e-4 * a.peak_contact_force.max())
    assert np.max(np.abs(a.displacement - b.displacement)) < 1e-6 * np.abs(a.displacement).max()
    assert b.energy_balance_error < 1e-6


def test_free_stepping_is_validated():
    with pytest.raises(ValueError, match="free_stepping"):
        simulate(sdof_pair(KV), zero_motion(0.1), free_stepping="fast")


def test_free_vibration_after_the_record_does_not_depend_on_the_output_step():
    # after its last sample the record returns to zero over one record step, whatever dt
    model = sdof_pair(KV, gap=1.0)
    gm = el_centro().trimmed(4.0)
    a = simulate(model, gm, dt=0.001, duration=6.0)
    b = simulate(model, gm, dt=0.005, duration=6.0)
    ref = simulate_reference(model, gm, dt=0.005, duration=6.0)
    assert np.max(np.abs(a.displacement[::5] - b.displacement)) < 1e-10
    assert np.max(np.abs(b.displacement - ref.displacement)) < 1e-8


def test_energy_balance_counts_the_initial_energy():
    # no ground motion: all the energy is the initial kinetic energy, shared by the end
    # between viscous damping, contact dissipation and what is left
    model = sdof_pair(NLVE, gap=0.001)
    v0 = np.array([0.5, 0.0])
    res = simulate(model, zero_motion(3.0), initial_velocity=v0)
    assert res.n_impacts >= 1
    e0 = 0.5 * M1 * v0[0] ** 2
    assert res.energy[0, 1] == pytest.approx(e0, rel=1e-12)
    assert res.energy_balance_error < 1e-6
    end = res.energy[-1]
    assert end[1] + end[2] + end[3] + end[4] == pytest.approx(e0, rel=1e-6)


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_row_of_three_with_different_heights_matches_reference():
    # seed cases 2B and 2C together: short impacts between the upper floors too
    left = ShearBuilding.uniform(4, 3e5, 4e8)
    mid = ShearBuilding.uniform(2, 2e5, 2e8)
    right = ShearBuilding.uniform(3, 2.5e5, 5e8)
    model = PoundingModel([left, mid, right], [0.01, 0.01], NLVE)
    gm = el_centro().trimmed(5.0).scaled(1.5)
    res = simulate(model, gm)
    ref = simulate_reference(model, gm)
    assert res.n_impacts == ref.n_impacts > 5
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=5e-4)
    np.testing.assert_allclose(res.impacts["peak_force"], ref.impacts["peak_force"], rtol=1e-3)


@pytest.mark.parametrize("case", ["exact", "rk", "yielding"])
def test_every_output_row_is_written(case, el_centro_8s, monkeypatch):
    """simulate() allocates its histories uninitialised and relies on the kernel to write
    every row: allocate them full of NaN instead and no NaN may survive (contacts closing
    and opening, exact and adaptive stepping, yielding storeys, progress chunks)."""
    import pounding.integrate as integrate
    from pounding.hysteresis import Bilinear

    monkeypatch.setattr(integrate.np, "empty",
                        lambda shape, dtype=float, order="C": np.full(shape, np.nan, dtype=dtype,
                                                                      order=order))
    model = sdof_pair(KV)
    mode = "rk" if case == "rk" else "auto"
    if case == "yielding":
        left = ShearBuilding.sdof(M1, period=T1, damping_ratio=0.05).with_storey_law(
            Bilinear(yield_force=0.15 * M1 * 9.81, hardening=0.05))
        model = PoundingModel([left, ShearBuilding.sdof(M2, period=T2, damping_ratio=0.05)],
                              [0.02], KV)
    res = simulate(model, el_centro_8s, free_stepping=mode, progress=lambda f: None)
    assert res.n_impacts > 0
    for name in ("displacement", "velocity", "abs_acceleration", "penetration",
                 "contact_force", "energy"):
        assert np.all(np.isfinite(np.asarray(getattr(res, name)))), name
