"""The exact step of classically damped blocks from their modes (modal_propagator,
modal_steps): every form against the matrix-exponential route, one mode against the
textbook closed form, and a tall pair's run against the dense route."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.ground_motion import GroundMotion
from pounding.integrate import modal_propagator as mp
from pounding.integrate import propagator, simulate
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ModalDamping, ShearBuilding
from pounding.structure.damping import RayleighDamping

REL = 1e-12


def _rel(a, b):
    return float(np.abs(np.asarray(a) - np.asarray(b)).max() / np.abs(np.asarray(b)).max())


def _block(n: int, damping) -> tuple[np.ndarray, ...]:
    """M, C, K, r of one uniform n-storey building, T1 = 0.1 n s."""
    m = 2e5
    # ω1 = 2√(k/m) sin(π/(2(2n+1))) = 2π/T1
    k = m * (np.pi / (0.1 * n) / np.sin(np.pi / (2 * (2 * n + 1)))) ** 2
    b = ShearBuilding.uniform(n, m, k, damping=damping)
    s = PoundingModel([b, b], [10.0], ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)).system
    return s.M[:n, :n], s.C[:n, :n], s.K[:n, :n], s.r[:n]


@pytest.mark.parametrize(("damping", "h"), [(RayleighDamping(0.05), 1e-3),
                                            (ModalDamping(0.03), 2e-2)],
                         ids=["rayleigh-1ms", "modal-20ms"])
def test_modal_forms_equal_the_exponentials(damping, h):
    M, C, K, r = _block(24, damping)
    mb = mp.modal_block(M, C, K, r, h)
    assert mb is not None
    phi, g0, g1, q_in = mp.dense_forms(mb, M)
    ref = propagator.compute_propagator(M, C, K, r, h)
    assert _rel(phi, ref.phi) < REL
    assert _rel(g0, ref.gamma0) < REL
    assert _rel(g1, ref.gamma1) < REL
    assert _rel(q_in, propagator.step_input_form(M, C, K, r, h)) < REL
    # the FreeStep the kernel gets: modal block, its dense columns as the exponentials'
    fs = propagator.compute_free_step(M, C, K, r, h)
    dense = propagator.compute_free_step(M, C, K, r, h, modal_from=0)
    assert fs.modal.tolist() == [1] and dense.modal.tolist() == [0]
    for name in ("ops", "gamma0", "gamma1", "aa"):
        assert _rel(getattr(fs, name), getattr(dense, name)) < REL, name


def test_one_mode_is_the_nigam_jennings_recurrence():
    """E, γ0, γ1 of an underdamped mode equal the exact piecewise-linear recurrence
    (Nigam & Jennings 1969; Chopra, Dynamics of Structures, Table 5.2.1) with m = 1,
    k = ω², p = −Γ a_g."""
    w, zeta, gamma, h = 7.3, 0.05, 1.7, 0.04
    e, g0, g1, _ = mp.mode_steps(np.array([w * w]), np.array([2 * zeta * w]),
                                 np.array([gamma]), h)
    k = w * w
    wd = w * np.sqrt(1 - zeta * zeta)
    sq = np.sqrt(1 - zeta * zeta)
    ex = np.exp(-zeta * w * h)
    s, c = np.sin(wd * h), np.cos(wd * h)
    a = ex * (zeta / sq * s + c)
    b = ex * s / wd
    cc = (2 * zeta / (w * h) + ex * (((1 - 2 * zeta**2) / (wd * h) - zeta / sq) * s
                                     - (1 + 2 * zeta / (w * h)) * c)) / k
    d = (1 - 2 * zeta / (w * h) + ex * ((2 * zeta**2 - 1) / (wd * h) * s
                                        + 2 * zeta / (w * h) * c)) / k
    a_ = -ex * w / sq * s
    b_ = ex * (c - zeta / sq * s)
    c_ = (-1 / h + ex * ((w / sq + zeta / (h * sq)) * s + c / h)) / k
    d_ = (1 - ex * (zeta / sq * s + c)) / (k * h)
    np.testing.assert_allclose(e[0], [[a, b], [a_, b_]], rtol=1e-12, atol=0)
    np.testing.assert_allclose(g0[0], [-gamma * cc, -gamma * c_], rtol=1e-11, atol=0)
    np.testing.assert_allclose(g1[0], [-gamma * d, -gamma * d_], rtol=1e-11, atol=0)


@pytest.mark.parametrize("zeta", [1.0, 3.0, 0.0])
def test_critical_over_and_undamped_modes_equal_the_exponential(zeta):
    w, gamma, h = 11.0, -0.6, 0.01
    e, g0, g1, q = mp.mode_steps(np.array([w * w]), np.array([2 * zeta * w]),
                                 np.array([gamma]), h)
    one = np.ones((1, 1))
    ref = propagator.compute_propagator(one, 2 * zeta * w * one, w * w * one,
                                        np.array([gamma]), h)
    assert _rel(e[0], ref.phi) < REL
    assert _rel(g0[0], ref.gamma0) < REL and _rel(g1[0], ref.gamma1) < REL
    assert _rel(q[0], propagator.step_input_form(one, 2 * zeta * w * one, w * w * one,
                                                  np.array([gamma]), h)) < REL


def test_non_classical_damping_keeps_the_dense_route():
    M, C, K, r = _block(20, RayleighDamping(0.05))
    c_top = C.copy()
    c_top[-1, -1] += 0.3 * C[-1, -1]  # a damper in the top storey alone
    assert mp.classical_modes(M, C, K) is not None
    assert mp.classical_modes(M, c_top, K) is None
    assert mp.classical_modes(M, C, np.full_like(K, np.nan)) is None
    fs = propagator.compute_free_step(M, c_top, K, r, 0.01)
    assert fs.modal.tolist() == [0]
    ref = propagator.compute_propagator(M, c_top, K, r, 0.01)
    assert np.array_equal(fs.ops[:, :40], ref.phi.T)
    # two ground components, links' dashpots in the block, or a small block: dense too
    assert propagator.compute_free_step(M, C, K, np.column_stack([r, 0.5 * r]),
                                        0.01).modal.tolist() == [0]
    links = np.zeros_like(C)
    links[3, 3] = 1e5
    assert propagator.compute_free_step(M, C + links, K, r, 0.01,
                                        links).modal.tolist() == [0]
    M6, C6, K6, r6 = _block(6, RayleighDamping(0.05))
    assert propagator.compute_free_step(M6, C6, K6, r6, 0.01).modal.tolist() == [0]


def _pair(gap: float) -> PoundingModel:
    blds = []
    for name, t1 in (("left", 2.0), ("right", 3.0)):
        n = 20
        k = 2e5 * (np.pi / t1 / np.sin(np.pi / (2 * (2 * n + 1)))) ** 2
        blds.append(ShearBuilding.uniform(n, 2e5, k, name=name))
    return PoundingModel(blds, [gap], ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))


def _motion() -> GroundMotion:
    t = np.arange(0.0, 6.0, 0.01)
    return GroundMotion(0.01, 3.0 * np.sin(2 * np.pi * 0.7 * t) * np.exp(-0.3 * t),
                        name="decaying sine")


def _run(gap: float, modal: bool, monkeypatch, **kw):
    monkeypatch.setattr(mp, "MODAL_MIN_FLOORS", 16 if modal else 0)
    monkeypatch.setattr(propagator, "_FREE_CACHE", {})
    return simulate(_pair(gap), _motion(), dt=0.002, **kw)


def test_tall_pair_run_equals_the_dense_route(monkeypatch):
    """Two 20-storey buildings, every gap open: the modal route's histories, energies and
    located peaks equal the dense route's to 1e-12 of each quantity's largest value."""
    modal = _run(10.0, True, monkeypatch)
    dense = _run(10.0, False, monkeypatch)
    assert modal.n_impacts == dense.n_impacts == 0
    for name in ("displacement", "velocity", "abs_acceleration"):
        assert _rel(getattr(modal, name), getattr(dense, name)) < REL, name
    # located peaks: values to 1e-12 of each kind's largest; their times (where the
    # interpolant's rate vanishes: set by the rate's round-off over its curvature) to 1 ns
    pk_m, pk_d = np.asarray(modal.located_peaks), np.asarray(dense.located_peaks)
    for col in range(0, pk_d.shape[1], 2):
        assert _rel(pk_m[:, col], pk_d[:, col]) < REL, col
        assert np.abs(pk_m[:, col + 1] - pk_d[:, col + 1]).max() < 1e-9, col
    e_m, e_d = np.asarray(modal.energy), np.asarray(dense.energy)
    for col in range(e_d.shape[1]):
        scale = max(np.abs(e_d[:, col]).max(), 1e-300)
        assert np.abs(e_m[:, col] - e_d[:, col]).max() <= REL * scale, col


def test_modal_state_carries_over_calls_and_contacts(monkeypatch):
    """With impacts the modal state is rebuilt from the floors' after each contact, and
    kept from one call of the kernel to the next: the same run in calls of 1000 grid steps
    (a progress callback) is bit-identical, and it follows the dense route closely (the
    adaptive steps around impacts amplify round-off differences)."""
    seen = []
    modal = _run(0.01, True, monkeypatch)
    chunked = _run(0.01, True, monkeypatch, progress=seen.append)
    assert modal.n_impacts > 0 and len(seen) > 1
    for name in ("displacement", "velocity", "abs_acceleration", "contact_force", "energy"):
        assert np.array_equal(getattr(modal, name), getattr(chunked, name)), name
    dense = _run(0.01, False, monkeypatch)
    assert dense.n_impacts == modal.n_impacts
    assert _rel(modal.displacement, dense.displacement) < 1e-8
    assert _rel(modal.peak_contact_force, dense.peak_contact_force) < 1e-8


def test_modal_run_against_an_extended_precision_reference(monkeypatch):
    """The left building of a 16-storey pair (every gap open) against the same recurrence
    from mpmath's matrix exponential (25 digits), stepped in ``np.longdouble``: the modal
    route's displacements within 1e-12 of the largest (measured 4e-14 for 20 storeys over
    20 000 steps, where the dense route was 5e-13 off)."""
    import mpmath

    n, h = 16, 0.002
    blds = []
    for name, t1 in (("left", 1.6), ("right", 2.4)):
        k = 2e5 * (np.pi / t1 / np.sin(np.pi / (2 * (2 * n + 1)))) ** 2
        blds.append(ShearBuilding.uniform(n, 2e5, k, name=name))
    model = PoundingModel(blds, [10.0], ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    monkeypatch.setattr(mp, "MODAL_MIN_FLOORS", 16)
    monkeypatch.setattr(propagator, "_FREE_CACHE", {})
    res = simulate(model, _motion(), dt=h, duration=4.0)
    s = model.system
    f, _ = propagator._augmented(s.M[:n, :n], s.C[:n, :n], s.K[:n, :n], s.r[:n], h)
    with mpmath.workdps(25):
        e = mpmath.expm(mpmath.matrix(f.tolist()) * mpmath.mpf(h))
        el = np.array([[np.longdouble(mpmath.nstr(e[i, j], 22)) for j in range(2 * n + 2)]
                       for i in range(2 * n + 2)])
    phi = el[: 2 * n, : 2 * n]
    g1 = el[: 2 * n, 2 * n + 1] / np.longdouble(h)
    g0 = el[: 2 * n, 2 * n] - g1
    ag = np.asarray(res.ground, dtype=np.longdouble).reshape(-1)
    x = np.zeros(2 * n, dtype=np.longdouble)
    ref = np.zeros((ag.size, n))
    for i in range(ag.size - 1):
        x = phi @ x + g0 * ag[i] + g1 * ag[i + 1]
        ref[i + 1] = x[:n].astype(float)
    assert kernel_model_modal(model, h)
    assert _rel(np.asarray(res.displacement)[:, :n], ref) < REL


def kernel_model_modal(model: PoundingModel, h: float) -> bool:
    """Whether the model's exact step took the modal route."""
    from pounding.integrate.kernel_model import kernel_model

    return bool(kernel_model(model).free_steps[h].modal.all())
