"""The exact step between impacts: block split, block propagator, exact step energies."""

from __future__ import annotations

import numpy as np

from pounding.integrate.propagator import (
    compute_free_step,
    compute_propagator,
    independent_blocks,
    state_matrix,
    step_energy_forms,
)
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ModalDamping, ShearBuilding


def _pair() -> PoundingModel:
    b1 = ShearBuilding.uniform(3, 3e5, 4e8)
    b2 = ShearBuilding.uniform(2, 2e5, 2e8, damping=ModalDamping(0.03))
    return PoundingModel([b1, b2], [0.02], ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))


def test_blocks_follow_the_coupling():
    k = np.zeros((5, 5))
    k[0, 1] = k[1, 0] = 1.0
    k[2, 4] = k[4, 2] = 1.0
    assert independent_blocks(k).tolist() == [0, 2, 5]
    assert independent_blocks(np.eye(3)).tolist() == [0, 1, 2, 3]
    s = _pair().system
    assert independent_blocks(s.M, s.C, s.K).tolist() == [0, 3, 5]


def _apply(fs, x0, a0, a1, M, K):
    """State, input energy and viscous work after one step, in plain numpy, the way the
    kernel does it: viscous work = input work − change of kinetic and strain energy.
    ``a0``, ``a1``: the G ground components at the step's ends (scalars for G = 1)."""
    n = x0.size // 2
    a0, a1 = np.atleast_1d(a0), np.atleast_1d(a1)
    ng = a0.size
    x1 = np.zeros_like(x0)
    e_in = a0 @ fs.aa[0] @ a0 + a0 @ fs.aa[1] @ a1 + a1 @ fs.aa[2] @ a1
    for b in range(fs.blk.size - 1):
        p, q = fs.blk[b], fs.blk[b + 1]
        nb = q - p
        glob = np.r_[p:q, n + p : n + q]
        z = x0[glob]
        acc = z @ fs.ops[glob, : 2 * nb + 2 * ng]
        x1[glob] = acc[: 2 * nb] + fs.gamma0[glob] @ a0 + fs.gamma1[glob] @ a1
        e_in += acc[2 * nb :: 2] @ a0 + acc[2 * nb + 1 :: 2] @ a1

    def stored(x):
        return 0.5 * x[n:] @ M @ x[n:] + 0.5 * x[:n] @ K @ x[:n]

    return x1, e_in, e_in - (stored(x1) - stored(x0))


def test_free_step_matches_propagator_and_quadrature():
    s = _pair().system
    M, C, K, r = s.M, s.C, s.K, s.r
    n = r.size
    h = 2e-3
    fs = compute_free_step(M, C, K, r, h)
    rng = np.random.default_rng(3)
    x0 = rng.normal(size=2 * n) * np.r_[np.full(n, 0.05), np.full(n, 0.4)]
    a0, a1 = 1.7, -0.9
    x1, e_in, e_d = _apply(fs, x0, a0, a1, M, K)
    full = compute_propagator(M, C, K, r, h)
    ref = full.phi @ x0 + full.gamma0 * a0 + full.gamma1 * a1
    assert np.max(np.abs(x1 - ref)) < 1e-13 * np.max(np.abs(ref))
    # energies by 24-point Gauss–Legendre on the exact solution (the integrands are smooth)
    mr = M @ r
    xs, ws = np.polynomial.legendre.leggauss(24)
    q_in = q_d = 0.0
    for xi, wi in zip(xs, ws):
        t = 0.5 * h * (xi + 1.0)
        pr = compute_propagator(M, C, K, r, t)
        at = a0 + (a1 - a0) * t / h
        v = (pr.phi @ x0 + pr.gamma0 * a0 + pr.gamma1 * at)[n:]
        q_in += 0.5 * h * wi * (-(v @ mr) * at)
        q_d += 0.5 * h * wi * (v @ C @ v)
    assert abs(e_in - q_in) < 1e-12 * abs(q_in)
    # the viscous work from the balance (the kernel's way) and from the Van Loan form
    assert abs(e_d - q_d) < 1e-9 * abs(q_d)
    y0 = np.r_[x0, a0, a1]
    assert abs(y0 @ step_energy_forms(M, C, K, r, h)[1] @ y0 - q_d) < 1e-12 * abs(q_d)
    assert np.allclose(state_matrix(M, C, K).shape, (2 * n, 2 * n))


def test_free_step_with_two_ground_components():
    """R with two columns (the second floor-dependent): the block step equals the full
    propagator of the two-input system, its input energy the quadrature of
    ``−u̇ᵀ M R a_g`` on the exact solution, and the viscous work from the balance the Van
    Loan form; and a step under (a, 0) equals the one-column step under a."""
    s = _pair().system
    M, C, K, r = s.M, s.C, s.K, s.r
    n = r.size
    R = np.column_stack([r, np.linspace(0.2, 1.0, n)])
    h = 2e-3
    fs = compute_free_step(M, C, K, R, h)
    assert fs.gamma0.shape == (2 * n, 2) and fs.aa.shape == (3, 2, 2)
    rng = np.random.default_rng(5)
    x0 = rng.normal(size=2 * n) * np.r_[np.full(n, 0.05), np.full(n, 0.4)]
    a0, a1 = np.array([1.7, -0.6]), np.array([-0.9, 2.2])
    x1, e_in, e_d = _apply(fs, x0, a0, a1, M, K)
    full = compute_propagator(M, C, K, R, h)
    ref = full.phi @ x0 + full.gamma0 @ a0 + full.gamma1 @ a1
    assert np.max(np.abs(x1 - ref)) < 1e-13 * np.max(np.abs(ref))
    mr = M @ R
    xs, ws = np.polynomial.legendre.leggauss(24)
    q_in = q_d = 0.0
    for xi, wi in zip(xs, ws):
        t = 0.5 * h * (xi + 1.0)
        pr = compute_propagator(M, C, K, R, t)
        at = a0 + (a1 - a0) * t / h
        v = (pr.phi @ x0 + pr.gamma0 @ a0 + pr.gamma1 @ at)[n:]
        q_in += 0.5 * h * wi * (-(v @ mr) @ at)
        q_d += 0.5 * h * wi * (v @ C @ v)
    assert abs(e_in - q_in) < 1e-12 * abs(q_in)
    assert abs(e_d - q_d) < 1e-9 * abs(q_d)
    y0 = np.r_[x0, a0, a1]
    assert abs(y0 @ step_energy_forms(M, C, K, R, h)[1] @ y0 - q_d) < 1e-12 * abs(q_d)
    # the second component zero: the one-column step
    one = _apply(compute_free_step(M, C, K, r, h), x0, 1.7, -0.9, M, K)
    two = _apply(fs, x0, np.array([1.7, 0.0]), np.array([-0.9, 0.0]), M, K)
    assert np.max(np.abs(one[0] - two[0])) < 1e-14 * np.max(np.abs(one[0]))
    assert abs(one[1] - two[1]) < 1e-13 * abs(one[1])


def test_free_step_splits_off_the_work_of_link_dashpots():
    """Links folded into K and C (:func:`pounding.integrate.kernel_model.fold_linear_links`)
    tie the two buildings into one block, and the block's extra columns give the energy the
    links' dashpots dissipate over the step: the 24-point Gauss–Legendre quadrature of
    ``u̇ᵀ C_links u̇`` on the exact solution, under one and two ground components."""
    from pounding.devices.laws import KELVIN, VISCOUS
    from pounding.integrate.kernel_model import fold_linear_links

    s = _pair().system
    M, n = s.M, s.M.shape[0]
    # a Kelvin link between the top floors, a dashpot between floors 1
    K, C, c_links = fold_linear_links(s.K, s.C, np.array([2, 0]), np.array([4, 3]),
                                      np.array([KELVIN, VISCOUS]),
                                      np.array([[3e7, 2e5], [4e5, 1.0]]))
    assert c_links[2, 4] == -2e5 and c_links[0, 3] == -4e5 and K[2, 4] == -3e7
    assert np.array_equal(C - c_links, s.C)
    h = 2e-3
    rng = np.random.default_rng(7)
    x0 = rng.normal(size=2 * n) * np.r_[np.full(n, 0.05), np.full(n, 0.4)]
    for R, a0, a1 in ((s.r[:, None], np.array([1.7]), np.array([-0.9])),
                      (np.column_stack([s.r, np.linspace(0.2, 1.0, n)]),
                       np.array([1.7, -0.6]), np.array([-0.9, 2.2]))):
        ng = a0.size
        fs = compute_free_step(M, C, K, R, h, c_links)
        assert fs.blk.tolist() == [0, n] and fs.rows.tolist() == [4 * n + 4 * ng]
        # the kernel's sweep over the block's columns, then its dissipation form
        acc = x0 @ fs.ops[:, : fs.rows[0]]
        q = 2 * n + 2 * ng
        e_links = (x0 @ acc[q : q + 2 * n] + acc[q + 2 * n :: 2] @ a0
                   + acc[q + 2 * n + 1 :: 2] @ a1
                   + a0 @ fs.dev_aa[0] @ a0 + a0 @ fs.dev_aa[1] @ a1 + a1 @ fs.dev_aa[2] @ a1)
        xs, ws = np.polynomial.legendre.leggauss(24)
        q_links = 0.0
        for xi, wi in zip(xs, ws):
            t = 0.5 * h * (xi + 1.0)
            pr = compute_propagator(M, C, K, R, t)
            at = a0 + (a1 - a0) * t / h
            v = (pr.phi @ x0 + pr.gamma0 @ a0 + pr.gamma1 @ at)[n:]
            q_links += 0.5 * h * wi * (v @ c_links @ v)
        assert abs(e_links - q_links) < 1e-11 * abs(q_links)
        # and the state and input energy as without the split
        plain = compute_free_step(M, C, K, R, h)
        assert np.array_equal(fs.ops[:, : 2 * n + 2 * ng], plain.ops[:, : 2 * n + 2 * ng])


def test_band_storage_reproduces_the_matrix():
    """The kernel's banded products read K and C from band storage: every entry of the band
    lands where ``out[d, i] = a[i, i + d − bw]`` says, and nothing else is kept."""
    from pounding.integrate import band_storage, half_bandwidth

    s = _pair().system
    for a in (s.K, s.C):
        bw = half_bandwidth(a)
        band = band_storage(a, bw)
        n = a.shape[0]
        back = np.zeros_like(a)
        for d in range(2 * bw + 1):
            for i in range(n):
                j = i + d - bw
                if 0 <= j < n:
                    back[i, j] = band[d, i]
                else:
                    assert band[d, i] == 0.0
        assert np.array_equal(back, a)


def test_record_grid_is_remembered_read_only():
    from pounding.ground_motion import GroundMotion
    from pounding.integrate.grid import ground_on_grid
    from pounding.integrate.grid import ground_on_grid_memo as _ground_on_grid_memo

    gm = GroundMotion(0.01, np.sin(np.arange(50) * 0.3), name="memo")
    a = _ground_on_grid_memo(gm, 0.005, 0.3)
    assert a is _ground_on_grid_memo(gm, 0.005, 0.3)
    assert not a.flags.writeable
    assert np.array_equal(a, ground_on_grid(gm, 0.005, 0.3))
    assert _ground_on_grid_memo(gm, 0.01, 0.3).size != a.size


def test_kernel_model_is_assembled_once_per_model_and_forgotten_with_it():
    import gc

    from pounding.integrate import band_storage, kernel_model
    from pounding.integrate.kernel_model import _KERNEL_MODELS

    model = _pair()
    km = kernel_model(model)
    assert kernel_model(model) is km
    # the arrays are the model's own, assembled independently here
    sys_ = model.system
    fl, ct = km.floors, km.contacts
    assert np.array_equal(fl.k_band, band_storage(sys_.K, fl.bw))
    assert np.array_equal(fl.c_band, band_storage(sys_.C, fl.bw))
    assert np.array_equal(fl.m_diag, np.diag(sys_.M))
    assert np.array_equal(fl.mr, (sys_.M @ sys_.r)[:, None])  # M R, R of one column
    assert np.array_equal(ct.gap, [c.gap for c in model.contacts])
    # writeable, so numba keeps one compiled signature (the kernel never writes them)
    assert all(a.flags.writeable for a in (fl.k_band, fl.c_band, fl.m_diag, ct.params))
    key = id(model)
    assert key in _KERNEL_MODELS
    del model, km
    gc.collect()
    assert key not in _KERNEL_MODELS


def test_start_at_rest_shortcut_matches_the_general_start():
    from pounding.ground_motion import GroundMotion
    from pounding.integrate import simulate

    model = _pair()
    gm = GroundMotion(0.01, 3.0 * np.sin(np.arange(200) * 0.25), name="shortcut")
    a = simulate(model, gm, dt=0.005)
    b = simulate(model, gm, dt=0.005, initial_displacement=np.zeros(5),
                 initial_velocity=np.zeros(5))
    assert a.stats.rk_steps > 0 and len(a.impacts) > 0  # the gap does close
    for name in ("displacement", "velocity", "abs_acceleration", "penetration",
                 "contact_force", "energy"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert np.array_equal(a.penetration[0], [-0.02, -0.02])  # two shared floors


def test_start_at_rest_shortcut_matches_the_general_start_with_yielding_storeys():
    # what the shortcut skips for yielding storeys: their committed state and Bouc–Wen z
    from pathlib import Path

    from pounding.config import load_config
    from pounding.integrate import simulate

    path = Path(__file__).resolve().parents[2] / "examples" / "inelastic_5_storey.toml"
    model, motion, _ = load_config(path).build()
    assert model.is_inelastic
    n = model.n_dof
    a = simulate(model, motion, duration=4.0)
    b = simulate(model, motion, duration=4.0, initial_displacement=np.zeros(n),
                 initial_velocity=np.zeros(n))
    for name in ("displacement", "velocity", "abs_acceleration", "penetration",
                 "contact_force", "energy", "yielding_shear", "final_z"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def test_exact_and_rk_stepping_share_one_compiled_kernel():
    # the unused exact-step arrays of an RK-stepped run are read-only like a real
    # FreeStep's, so numba does not compile the kernel a second time (37–56 s on 2 cores).
    # (Counts the signatures of the whole test process: any test that hands the kernel
    # other array types fails it too, which is meant.)
    from pounding.ground_motion import GroundMotion
    from pounding.integrate import simulate
    from pounding.integrate.kernel import integrate_chunk

    gm = GroundMotion(0.01, np.sin(np.arange(30) * 0.3), name="one signature")
    simulate(_pair(), gm, free_stepping="exact")
    simulate(_pair(), gm, free_stepping="rk")
    assert len(integrate_chunk.signatures) == 1, integrate_chunk.signatures
