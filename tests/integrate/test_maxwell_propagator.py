"""The exact propagator of buildings tied by linear Maxwell links (state extended by the
links' spring deformations, :mod:`pounding.integrate.maxwell_propagator`) against the tight
SciPy reference (``simulate_reference``, DOP853 at rtol 1e-11, the link law written out
afresh) and against a Gauss–Legendre quadrature of the links' dissipated power; the
kernel's adaptive answer for the same runs (``free_stepping="rk"``) is held to the same
reference, to show the exact route is the closer one with every gap open, and the kernel's
compiled exact steps give the plain stepper's answer."""

from __future__ import annotations

import numpy as np
import pytest

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
from pounding.devices import Link
from pounding.integrate.kernel_model import kernel_model
from pounding.integrate.maxwell_propagator import (
    compute_extended_propagator,
    extended_blocks,
    extended_step_forms,
    free_record,
    linear_maxwell_rows,
    maxwell_links,
)
from pounding.integrate.reference import simulate_reference

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)


def _operators(model):
    km = kernel_model(model)
    el = km.elements
    links = maxwell_links(el.lo, el.hi, el.code, el.params[:, :3])
    return km, np.diag(km.floors.m_diag), links


def _rel(a, b):
    return np.abs(a - b).max() / np.abs(b).max()


def _sdof_pair():
    return [ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05),
            ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.05)]


@pytest.mark.parametrize("case", ["sdof", "three-storey"])
def test_free_record_with_maxwell_links_matches_the_reference(case):
    """Gaps of 10 m (no impact): every output of the exact extended propagator — floors'
    displacements, velocities and absolute accelerations, the Maxwell links' forces, the
    energies (input, kinetic, strain with the links' springs, the buildings' viscous work
    inferred from the balance, the links' dissipated work) — against the reference, closer
    to it than the kernel's adaptive steps are. The three-storey pair also has a Kelvin
    link folded into K and C, whose dashpot's work joins the links' column."""
    if case == "sdof":
        blds = _sdof_pair()
        devices = [Link(("B1F1", "B2F1"), "maxwell", c=5e5, k=1e7)]
    else:
        blds = [ShearBuilding.uniform(3, 4e5, 6e8), ShearBuilding.uniform(3, 3e5, 9e8)]
        devices = [Link(("B1F3", "B2F3"), "maxwell", c=6e5, k=3e7),
                   Link(("B2F1", "B1F1"), "maxwell", c=2e5, k=2e7),
                   Link(("B1F2", "B2F2"), "kelvin", c=1e5, k=5e6)]
    model = PoundingModel(blds, [10.0], KV, devices=devices)
    gm = el_centro().trimmed(3.0 if case == "sdof" else 2.0)
    ref = simulate_reference(model, gm, dt=gm.dt, rtol=1e-11)
    rk = simulate(model, gm, dt=gm.dt, free_stepping="rk")
    kernel = simulate(model, gm, dt=gm.dt)  # (its exact steps: the same operators, compiled)
    assert ref.n_impacts == rk.n_impacts == kernel.n_impacts == 0
    km, M, links = _operators(model)
    rows = linear_maxwell_rows(km.elements.code, km.elements.params[:, :3])
    ag = np.interp(ref.time, gm.time, gm.accel)[:, None]
    out = free_record(M, km.C, km.K, km.floors.r, links, ag, gm.dt, km.C_links)

    pairs = [(out.displacement, "displacement", 1e-10), (out.velocity, "velocity", 1e-10),
             (out.acceleration, "abs_acceleration", 1e-9),
             (out.link_force, "link_force", 1e-9)]
    for ours, name, tol in pairs:
        theirs = getattr(ref, name)
        if name == "link_force":
            theirs = theirs[:, rows]
        err = _rel(ours, theirs)
        adaptive = getattr(rk, name)[:, rows] if name == "link_force" else getattr(rk, name)
        assert err < tol, (name, err)
        assert err < _rel(adaptive, theirs), name
        compiled = getattr(kernel, name)[:, rows] if name == "link_force" else getattr(kernel, name)
        assert _rel(compiled, ours) < 1e-11, name
    # energies: input, kinetic, strain, viscous (from the balance), links
    e_ref = ref.energy[:, [0, 1, 2, 3, 7]]
    assert _rel(out.energy, e_ref) < 1e-9
    assert _rel(out.energy, e_ref) < _rel(rk.energy[:, [0, 1, 2, 3, 7]], e_ref)
    assert out.energy[-1, 4] > 0.05 * out.energy[-1, 0] > 0.0
    assert out.energy[-1, 3] > 0.05 * out.energy[-1, 0]


def test_step_forms_match_a_quadrature_of_the_powers():
    """One step's input and dissipation forms against the 24-point Gauss–Legendre
    quadrature of the input power ``−u̇ᵀ M R a_g`` and of the links' ``Σ k² z² / c +
    u̇ᵀ C_links u̇`` along the exact solution, under two ground components."""
    blds = [ShearBuilding.uniform(2, 4e5, 6e8), ShearBuilding.uniform(2, 3e5, 9e8)]
    devices = [Link(("B1F2", "B2F2"), "maxwell", c=6e5, k=3e7),
               Link(("B1F1", "B2F1"), "viscous", c=2e5)]
    km, M, links = _operators(PoundingModel(blds, [0.02], KV, devices=devices))
    n = M.shape[0]
    R = np.column_stack([km.floors.r[:, 0], np.linspace(0.3, 1.0, n)])
    h = 4e-3
    rng = np.random.default_rng(3)
    x0 = rng.normal(size=2 * n + 1) * np.r_[np.full(n, 0.05), np.full(n, 0.4), 0.01]
    a0, a1 = np.array([1.7, -0.6]), np.array([-0.9, 2.2])
    q_in, q_links = extended_step_forms(M, km.C, km.K, R, links, h, km.C_links)
    y0 = np.r_[x0, a0, a1]
    xs, ws = np.polynomial.legendre.leggauss(24)
    w_in = w_links = 0.0
    for xi, wi in zip(xs, ws):
        t = 0.5 * h * (xi + 1.0)
        at = a0 + (a1 - a0) * t / h
        pr = compute_extended_propagator(M, km.C, km.K, R, links, t)
        x = pr.phi @ x0 + pr.gamma0 @ a0 + pr.gamma1 @ at
        v, z = x[n : 2 * n], x[2 * n :]
        w_in += 0.5 * h * wi * (-v @ M @ R @ at)
        w_links += 0.5 * h * wi * (np.sum(links.k ** 2 * z ** 2 / links.c)
                                   + v @ km.C_links @ v)
    assert y0 @ q_in @ y0 == pytest.approx(w_in, rel=1e-11)
    assert y0 @ q_links @ y0 == pytest.approx(w_links, rel=1e-11)
    # the link ties the two buildings into one block; without it they are two
    assert extended_blocks(M, km.C, km.K, links).tolist() == [0, n]
    plain = kernel_model(PoundingModel(blds, [0.02], KV))
    assert extended_blocks(M, plain.C, plain.K, links._replace(
        lo=links.lo[:0], hi=links.hi[:0])).tolist() == [0, 2, n]


def test_only_linear_maxwell_rows_are_taken():
    """A Maxwell link with a nonlinear dashpot (α ≠ 1) and other laws are not linear
    Maxwell rows; a linear one to the ground is refused."""
    from pounding.devices.laws import KELVIN, MAXWELL, VISCOUS

    code = np.array([MAXWELL, MAXWELL, KELVIN, VISCOUS])
    par = np.array([[1e7, 5e5, 1.0], [1e7, 5e5, 0.5], [1e7, 5e5, 0.0], [5e5, 1.0, 0.0]])
    assert linear_maxwell_rows(code, par).tolist() == [True, False, False, False]
    # a model without element rows has none
    assert linear_maxwell_rows(code[:0], np.zeros((0, 9))).size == 0
    links = maxwell_links(np.array([0, 0, 0, 0]), np.array([1, 1, 1, 1]), code, par)
    assert links.n_links == 1 and links.k.tolist() == [1e7] and links.c.tolist() == [5e5]
    with pytest.raises(ValueError, match="ground"):
        maxwell_links(np.array([-1]), np.array([1]), code[:1], par[:1])
