"""Base isolation (issue 18): isolator laws against their closed forms, the isolated
building against an SDOF on the isolator law integrated by SciPy here, against the SciPy
reference under El Centro, and its energy balance."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear, BoucWen, respond_drift_path
from pounding.hysteresis.isolators import GRAVITY, BilinearIsolator, FrictionPendulum
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.isolation import SuperstructureDamping

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


@pytest.fixture(scope="module")
def elc():
    return el_centro()


# ---------------------------------------------------------------- laws: closed forms
def test_friction_pendulum_loop_is_pendulum_plus_friction():
    """Slow harmonic displacement of amplitude 0.2 m: on the sliding branches the force is
    (W/R) u ± μW (Zayas et al. 1990), sign of the velocity."""
    W, R, mu = 2.0e6, 2.5, 0.06
    fp = FrictionPendulum(radius=R, mu=mu, weight=W, yield_displacement=2e-4)
    t = np.linspace(0.0, 2.0, 8001)
    u = 0.2 * np.sin(2.0 * np.pi * t)
    f = respond_drift_path(fp.law(), fp.stiffness, u, substeps=50)
    v = np.gradient(u, t)
    # sliding: away from the turning points (the stick phase lasts a change of 2 Y)
    since_turn = np.zeros_like(u)
    last = u[0]
    for i in range(1, u.size):
        if np.sign(v[i]) != np.sign(v[i - 1]):
            last = u[i]
        since_turn[i] = abs(u[i] - last)
    sliding = (since_turn > 20 * fp.yield_displacement) & (t > 0.1)
    closed = W / R * u + np.sign(v) * mu * W
    err = np.abs(f - closed)[sliding]
    assert sliding.sum() > 6000
    assert err.max() < 1e-6 * mu * W
    # the loop's area is the friction work 4 μW A per cycle (less the stick corners)
    loop = np.trapezoid(f[t >= 1.0], u[t >= 1.0])
    assert loop == pytest.approx(4 * mu * W * 0.2, rel=2e-3)


def test_friction_pendulum_maps_to_bouc_wen_exactly():
    W, R, mu, Y = 3.0e6, 3.0, 0.05, 3e-4
    fp = FrictionPendulum(radius=R, mu=mu, weight=W, yield_displacement=Y)
    law = fp.law()
    k = fp.stiffness
    assert isinstance(law, BoucWen)
    assert law.alpha * k == pytest.approx(W / R, rel=1e-14)
    assert (1 - law.alpha) * law.yield_force == pytest.approx(mu * W, rel=1e-12)
    assert law.yield_force / k == pytest.approx(Y, rel=1e-14)
    assert fp.period == pytest.approx(2 * np.pi * np.sqrt(R / 9.80665))
    assert FrictionPendulum(radius=R, mu=mu, mass=W / GRAVITY,
                            yield_displacement=Y).stiffness == pytest.approx(k)


def test_bilinear_isolator_from_characteristic_strength():
    """Post-yield branch F = Q + k₂ u on first loading; F_y = Q k₁ / (k₁ − k₂)."""
    k1, k2, Q = 1.5e8, 1.2e7, 6.0e5
    iso = BilinearIsolator(k1, k2, characteristic_strength=Q)
    assert iso.yield_force == pytest.approx(Q * k1 / (k1 - k2))
    u = np.linspace(0.0, 0.25, 501)
    f = respond_drift_path(iso.law(), iso.stiffness, u)
    post = u > iso.yield_displacement
    np.testing.assert_allclose(f[post], Q + k2 * u[post], rtol=1e-12)
    np.testing.assert_allclose(f[~post], k1 * u[~post], rtol=1e-12)
    same = BilinearIsolator(k1, k2, yield_force=iso.yield_force)
    assert same.characteristic_strength == pytest.approx(Q)


@pytest.mark.parametrize("kwargs, match", [
    ({"radius": 2.0, "mu": 1.2, "weight": 1e6}, "mu must be in"),
    ({"radius": -2.0, "mu": 0.05, "weight": 1e6}, "radius must be"),
    ({"radius": 2.0, "mu": 0.05, "weight": 1e6, "mass": 1e5}, "not both"),
])
def test_friction_pendulum_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        FrictionPendulum(**kwargs)


def test_bad_yielding_storeys():
    b = ShearBuilding.uniform(3, 1e5, 1e8)
    with pytest.raises(ValueError, match="yielding_storeys: needs a storey_law"):
        dataclasses.replace(b, yielding_storeys=(0,))
    with pytest.raises(ValueError, match="storey index 3 is not in 0 … 2"):
        b.with_storey_law(Bilinear(yield_force=1e5), storeys=(3,))
    with pytest.raises(ValueError, match="yield_force: need one value or 2 .one per storey.*got 3"):
        b.with_storey_law(Bilinear(yield_force=(1e5, 2e5, 3e5)), storeys=(0, 2))


# ---------------------------------------------------------------- the isolated building
def isolated(isolator, n=5, k=4.0e8, m=3.0e5, base=4.0e5) -> ShearBuilding:
    sup = ShearBuilding.uniform(n, m, k, height=3.2, name="iso")
    return ShearBuilding.base_isolated(sup, base, isolator, base_height=1.0)


def test_only_the_isolator_is_a_kernel_row():
    b = isolated(FrictionPendulum(radius=2.0, mu=0.06))
    model = PoundingModel([ShearBuilding.sdof(2e5, period=0.4), b], [0.1], KV)
    lo, hi, code, prm, zi = model.storey_arrays()
    assert list(lo) == [-1] and list(hi) == [1] and list(zi) == [0]
    assert model.yielding_storeys == ((1, 0),)
    K = model.linear_stiffness()
    full = b.stiffness_matrix()
    expect = full.copy()
    expect[0, 0] -= b.stiffnesses[0]              # the isolator's k left out of K
    np.testing.assert_array_equal(K[1:, 1:], expect)
    assert prm[0, 0] == b.stiffnesses[0]


def test_superstructure_damping_acts_on_drifts_from_the_base():
    """A rigid-body motion of the whole building (every floor the same velocity) is not
    damped; the superstructure block is the fixed-base superstructure's C."""
    sup = ShearBuilding.uniform(4, 3e5, 4e8)
    b = ShearBuilding.base_isolated(sup, 4e5, BilinearIsolator(2e8, 2e7, yield_force=1e6),
                                    isolator_damping=3e4)
    C = b.damping_matrix()
    ones = np.ones(b.n)
    np.testing.assert_allclose(C @ ones, [3e4, 0, 0, 0, 0], atol=1e-6 * np.abs(C).max())
    np.testing.assert_allclose(C[1:, 1:], sup.damping_matrix(), rtol=1e-12)
    assert isinstance(b.damping, SuperstructureDamping)


def _fp_sdof(fp: FrictionPendulum, mass: float, motion, t_end: float):
    """M ü + (W/R) u + μW Z = −M a_g with Y Ż = u̇ (1 − |Z|ⁿ (γ + β sgn(u̇ Z))) (A = 1):
    the friction-pendulum SDOF of Constantinou et al. (1990), integrated here by SciPy."""
    W, R, mu, Y = fp.weight, fp.radius, fp.mu, fp.yield_displacement
    t_rec = motion.time
    a_rec = motion.accel

    def rhs(t, y):
        u, v, z = y
        ag = np.interp(t, t_rec, a_rec)
        s = np.sign(v * z)
        zdot = v * (1.0 - abs(z) ** fp.n * (fp.gamma + fp.beta * s)) / Y
        return [v, -(W / R * u + mu * W * z) / mass - ag, zdot]

    t_eval = np.arange(0.0, t_end + 1e-12, motion.dt)
    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0, 0.0], method="LSODA", t_eval=t_eval,
                    rtol=1e-9, atol=[1e-11, 1e-10, 1e-9], max_step=motion.dt / 2)
    assert sol.success
    return sol.t, sol.y[0]


def test_isolated_rigid_superstructure_is_the_friction_pendulum_sdof(elc):
    """A stiff superstructure slides as one mass on the bearing: its base displacement is the
    SDOF of the friction pendulum law, written and integrated independently here."""
    fp = FrictionPendulum(radius=1.5, mu=0.05)
    b = isolated(fp, n=2, k=2.0e11)
    model = PoundingModel([b], [], KV)
    res = simulate(model, elc, duration=8.0)
    t, u = _fp_sdof(fp.carrying(b.total_mass), b.total_mass, elc, 8.0)
    ub = np.interp(t, res.time, res.displacement[:, 0])
    scale = np.abs(u).max()
    assert scale > 0.02                                  # it slid, several centimetres
    assert np.max(np.abs(ub - u)) < 2e-3 * scale
    # the superstructure barely deforms
    assert np.abs(res.drift[:, 1:]).max() < 1e-3 * scale


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_isolated_building_matches_reference_bilinear(elc):
    """The kernel with one isolator row and the superstructure in K against the SciPy
    reference on the same building, and on the building whose superstructure storeys are
    bilinear laws that never yield (the same physics, every storey a law)."""
    iso = BilinearIsolator(1.2e8, 1.2e7, characteristic_strength=0.05 * 1.9e6 * GRAVITY)
    b = isolated(iso)
    fy = [iso.yield_force] + [1e15] * 5
    every = dataclasses.replace(b, storey_law=Bilinear(yield_force=tuple(fy),
                                                       hardening=iso.law().hardening),
                                yielding_storeys=None)
    res = simulate(PoundingModel([b], [], KV), elc, duration=8.0)
    ref = simulate_reference(PoundingModel([every], [], KV), elc, duration=8.0)
    same = simulate_reference(PoundingModel([b], [], KV), elc, duration=8.0)
    scale = np.abs(ref.displacement).max()
    assert np.max(np.abs(same.displacement - ref.displacement)) < 1e-6 * scale
    assert np.max(np.abs(res.displacement - same.displacement)) < 1e-4 * scale
    # the bearing yielded; it is no storey, so it has no storey ductility (res.bearings)
    assert res.bearings[0].peak_displacement > 5.0 * iso.yield_displacement
    assert np.all(np.isnan(res.ductility))
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-4 * scale
    assert np.max(np.abs(res.storey_shear - ref.storey_shear)) < 1e-4 * np.abs(
        ref.storey_shear).max()
    assert res.energy[-1, 6] == pytest.approx(ref.energy[-1, 6], rel=1e-4)
    assert res.energy_balance_error < 1e-6


@pytest.mark.slow  # a long reference comparison (pyproject.toml: markers)
def test_isolated_building_matches_reference_friction_pendulum(elc):
    """As above with the friction pendulum (Bouc–Wen); the reference's superstructure
    storeys are Bouc–Wen storeys of a yield force 10⁴ × their peak shear: their z stays
    below 10⁻⁴, so they differ from linear by |z|² < 10⁻⁸ of their shear."""
    fp = FrictionPendulum(radius=2.0, mu=0.05)
    b = isolated(fp)
    law = b.storey_law
    fy = (law.yield_force,) + (1e4 * 0.3 * b.total_mass * 9.81,) * 5
    every = dataclasses.replace(b, storey_law=dataclasses.replace(law, yield_force=fy),
                                yielding_storeys=None)
    res = simulate(PoundingModel([b], [], KV), elc, duration=8.0)
    ref = simulate_reference(PoundingModel([every], [], KV), elc, duration=8.0)
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.drift[:, 0]).max() > 0.02
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-4 * scale
    assert np.max(np.abs(res.storey_shear - ref.storey_shear)) < 1e-4 * np.abs(
        ref.storey_shear).max()
    assert res.energy_balance_error < 1e-6


def test_friction_pendulum_energy_balance_and_friction_work(elc):
    """The balance closes with the hysteretic column, which is the friction work
    μW ∫ Z du of the bearing (computed here from the output histories)."""
    fp = FrictionPendulum(radius=2.0, mu=0.06)
    b = isolated(fp)
    res = simulate(PoundingModel([b], [], KV), elc, duration=10.0, dt=0.002)
    assert res.energy_balance_error < 1e-6
    W = fp.carrying(b.total_mass).weight
    ub = res.displacement[:, 0]
    z = (res.storey_shear[:, 0] - W / fp.radius * ub) / (fp.mu * W)
    assert np.abs(z).max() == pytest.approx(1.0, abs=1e-6)     # sliding: |Z| → 1
    friction = fp.mu * W * np.trapezoid(z, ub)
    hyst = res.energy[-1, 6]
    assert hyst == pytest.approx(friction, rel=2e-3)
    assert hyst > 0.3 * res.energy[-1, 0]                        # the bearing dissipates
