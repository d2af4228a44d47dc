"""Links between buildings against independent solutions.

A linked pair without contact is a linear system (linear dashpot, Kelvin and linear Maxwell
links): checked against SciPy's exact first-order-hold solution of its state-space form
(``scipy.signal.lsim``: matrix exponential, the record linear between samples), written
here from the masses, stiffnesses and link constants alone. A fluid viscous damper (α < 1)
is checked against the plain SciPy reference (``simulate_reference``); each link's work
closes the energy balance.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
from pounding.devices import Link
from pounding.integrate.reference import simulate_reference

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
M1, T1, M2, T2 = 2e5, 0.5, 3e5, 1.0


def _pair() -> tuple[ShearBuilding, ShearBuilding]:
    return (ShearBuilding.sdof(M1, period=T1, damping_ratio=0.05),
            ShearBuilding.sdof(M2, period=T2, damping_ratio=0.05))


def _state_space(link: Link, b1: ShearBuilding, b2: ShearBuilding):
    """x = [u1, u2, v1, v2(, z)]; input a_g; outputs u1, u2."""
    m = np.array([M1, M2])
    k = np.array([b1.stiffness_matrix()[0, 0], b2.stiffness_matrix()[0, 0]])
    c = np.array([b1.damping_matrix()[0, 0], b2.damping_matrix()[0, 0]])
    n = 5 if link.kind == "maxwell" else 4
    A = np.zeros((n, n))
    A[0, 2] = A[1, 3] = 1.0
    for i in range(2):
        A[2 + i, i] = -k[i] / m[i]
        A[2 + i, 2 + i] = -c[i] / m[i]
    # link force F (on floor 2: −F, on floor 1: +F), d = u2 − u1
    if link.kind == "maxwell":
        kl, cl = link.k, link.c
        # F = kl z, ż = ḋ − kl z / cl
        A[2, 4] += kl / m[0]
        A[3, 4] -= kl / m[1]
        A[4, 2], A[4, 3], A[4, 4] = -1.0, 1.0, -kl / cl
    else:
        kl = link.k or 0.0
        cl = link.c
        for row, sgn, mi in ((2, 1.0, m[0]), (3, -1.0, m[1])):
            # sgn·F / m with F = kl (u2 − u1) + cl (v2 − v1)
            A[row, 0] -= sgn * kl / mi
            A[row, 1] += sgn * kl / mi
            A[row, 2] -= sgn * cl / mi
            A[row, 3] += sgn * cl / mi
    B = np.zeros((n, 1))
    B[2, 0] = B[3, 0] = -1.0
    C = np.zeros((2, n))
    C[0, 0] = C[1, 1] = 1.0
    return signal.StateSpace(A, B, C, np.zeros((2, 1)))


@pytest.mark.parametrize("link", [
    Link(("B1F1", "B2F1"), "viscous", c=5e5),
    Link(("B2F1", "B1F1"), "kelvin", c=3e5, k=4e6),
    Link(("B1F1", "B2F1"), "maxwell", c=5e5, k=1e7),
], ids=["viscous", "kelvin", "maxwell"])
def test_linked_pair_without_contact_matches_linear_state_space(link):
    b1, b2 = _pair()
    gm = el_centro().trimmed(8.0)
    model = PoundingModel([b1, b2], [10.0], KV, devices=[link])
    res = simulate(model, gm, dt=gm.dt)
    t = res.time
    a_g = np.interp(t, gm.time, gm.accel)
    _, y, _ = signal.lsim(_state_space(link, b1, b2), a_g, t, interp=True)
    scale = np.abs(y).max()
    assert res.n_impacts == 0
    # a linear link is stepped exactly: without internal state folded into K and C, a
    # Maxwell link with its spring's deformation in the exact step's state
    assert res.stats.rk_steps == 0
    assert np.abs(res.displacement - y).max() / scale < 1e-6
    # the link's work closes the energy balance, and the per-link estimate sums to it
    assert res.energy_balance_error < 1e-7
    assert res.energy[-1, 7] > 0.1 * res.energy[-1, 0]
    assert res.link_dissipated.sum() == pytest.approx(res.energy[-1, 7], rel=1e-3)


@pytest.mark.parametrize("link", [
    Link(("B1F1", "B2F1"), "kelvin", c=2e5, k=1e7),
    Link(("B1F1", "B2F1"), "viscous", c=2e5),
], ids=["kelvin", "viscous"])
def test_linear_links_stepped_exactly_between_impacts_match_the_reference(link):
    """A linear link folded into K and C: exact steps between the impacts, adaptive ones
    through them; every output against the SciPy reference, the links' energy (column 7)
    kept apart from the buildings' viscous work (column 3), and against the same run stepped
    adaptively throughout."""
    model = PoundingModel(list(_pair()), [0.01], KV, devices=[link])
    gm = el_centro().trimmed(4.0)
    res = simulate(model, gm)
    rk = simulate(model, gm, free_stepping="rk")
    ref = simulate_reference(model, gm, rtol=1e-11)
    assert res.n_impacts == rk.n_impacts == ref.n_impacts > 0
    assert res.stats.rk_steps < 0.2 * rk.stats.rk_steps

    def rel(a, b):
        return np.abs(a - b).max() / np.abs(b).max()

    for other, tol in ((ref, 1e-6), (rk, 1e-6)):
        assert rel(res.displacement, other.displacement) < tol
        assert rel(res.link_force, other.link_force) < tol
        assert rel(res.energy[:, [0, 1, 2, 3, 7]], other.energy[:, [0, 1, 2, 3, 7]]) < tol
        assert res.link_dissipated == pytest.approx(other.link_dissipated, rel=tol)
        assert res.peak_contact_force == pytest.approx(other.peak_contact_force, rel=1e-5)
    assert res.energy[-1, 7] > 0.05 * res.energy[-1, 3] > 0.0
    assert res.energy_balance_error < 1e-8


def test_large_linked_blocks_are_stepped_by_rk_under_auto():
    """A block tied by folded links sweeps a second quadratic form in its exact step: beyond
    EXACT_LINKED_BLOCK_MAX floors in one block, "auto" chooses the adaptive steps (measured
    the faster there); "exact" may still be asked for."""
    from pounding.integrate.kernel_model import (
        EXACT_LINKED_BLOCK_MAX,
        choose_free_stepping,
        kernel_model,
    )

    half = EXACT_LINKED_BLOCK_MAX // 2
    for n, auto in ((half, True), (half + 1, False)):
        pair = [ShearBuilding.uniform(n, 6e5, 8e8), ShearBuilding.uniform(n, 4e5, 1.2e9)]
        links = [Link((f"B1F{i}", f"B2F{i}"), "viscous", c=1e6) for i in (1, n)]
        km = kernel_model(PoundingModel(pair, [0.04], KV, devices=links))
        assert km.linked_block == 2 * n
        assert choose_free_stepping("auto", km.n, km.floors.bw, km.linked_block) is auto
        assert choose_free_stepping("exact", km.n, km.floors.bw, km.linked_block)
    assert kernel_model(PoundingModel(list(_pair()), [0.04], KV)).linked_block == 0


def test_the_link_force_history_is_its_law_on_the_motion():
    link = Link(("B1F1", "B2F1"), "kelvin", c=3e5, k=4e6)
    model = PoundingModel(list(_pair()), [10.0], KV, devices=[link])
    res = simulate(model, el_centro().trimmed(5.0))
    f = link.force(res.link_displacement, res.link_velocity)
    assert np.abs(res.link_force - f).max() <= 1e-9 * np.abs(f).max()


def test_the_peak_link_force_is_the_largest_force_of_each_link_in_its_history():
    """``link_peak_force`` (read column by column) against a plain Python maximum of each
    link's |F| over the output steps, for three links of three laws, bit for bit."""
    blds = [ShearBuilding.uniform(3, 3e5, 4e8), ShearBuilding.uniform(3, 2e5, 3e8)]
    links = [Link(("B1F1", "B2F1"), "viscous", c=3e5),
             Link(("B1F2", "B2F2"), "kelvin", c=2e5, k=5e6),
             Link(("B1F3", "B2F3"), "maxwell", c=4e5, k=2e7)]
    res = simulate(PoundingModel(blds, [0.01], KV, devices=links), el_centro().trimmed(4.0))
    f = res.link_force
    expected = [max(abs(float(v)) for v in f[:, j]) for j in range(f.shape[1])]
    assert res.link_peak_force.tolist() == expected
    assert min(expected) > 0.0


def test_fluid_viscous_damper_with_pounding_matches_the_scipy_reference():
    # (α = 0.6: with smaller α the damper locks the floors together for long stretches,
    # where its slope c α |ḋ|^(α−1) makes the equations stiff and the explicit reference
    # crawls; the kernel's own energy balance is checked at α = 0.3 below)
    link = Link(("B1F1", "B2F1"), "viscous", c=4e5, alpha=0.6)
    model = PoundingModel(list(_pair()), [0.01], KV, devices=[link])
    gm = el_centro().trimmed(4.0)
    res = simulate(model, gm)
    ref = simulate_reference(model, gm, rtol=1e-9)
    assert res.n_impacts == ref.n_impacts > 0
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() / scale < 1e-5
    assert res.peak_contact_force.max() == pytest.approx(ref.peak_contact_force.max(), rel=1e-4)
    assert res.energy[-1, 7] == pytest.approx(ref.energy[-1, 7], rel=1e-5)
    assert res.energy_balance_error < 1e-7 and ref.energy_balance_error < 1e-6


@pytest.mark.parametrize("kw, match", [
    (dict(floors=("B1F1",), kind="viscous", c=1.0), "floors: give two floor labels"),
    (dict(floors=("B1F1", "B1F2"), kind="viscous", c=1.0), "one building"),
    (dict(floors=("B1F1", "X2"), kind="viscous", c=1.0), "floors: 'X2' is not a floor label"),
    (dict(floors=("B1F1", "B2F1"), kind="friction", c=1.0), "kind: 'friction' is not"),
    (dict(floors=("B1F1", "B2F1"), kind="viscous", c=-1.0), "c: must be finite and > 0"),
    (dict(floors=("B1F1", "B2F1"), kind="viscous", c=1.0, k=1.0), "k: a viscous link"),
    (dict(floors=("B1F1", "B2F1"), kind="maxwell", c=1.0), "k: a maxwell link needs"),
    (dict(floors=("B1F1", "B2F1"), kind="kelvin", c=1.0, k=1.0, alpha=0.5), "alpha: a kelvin"),
    (dict(floors=("B1F1", "B2F1"), kind="viscous", c=1.0, alpha=0.0), "alpha: must be in"),
])
def test_bad_links_are_refused_naming_the_field(kw, match):
    with pytest.raises(ValueError, match=match):
        Link(**kw)


def test_a_link_to_a_floor_that_does_not_exist_is_refused():
    with pytest.raises(ValueError, match=r"devices\[0\].floors: no floor B2F3 in this model "
                                         r"\(B1: 1 floor, B2: 1 floor\)"):
        PoundingModel(list(_pair()), [0.02], KV,
                      devices=[Link(("B1F1", "B2F3"), "viscous", c=1e5)])


def test_a_strongly_nonlinear_fluid_damper_closes_the_energy_balance():
    link = Link(("B1F1", "B2F1"), "viscous", c=4e5, alpha=0.3)
    model = PoundingModel(list(_pair()), [0.01], KV, devices=[link])
    res = simulate(model, el_centro().trimmed(10.0))
    assert res.energy_balance_error < 1e-6
    f = link.force(res.link_displacement, res.link_velocity)
    assert np.abs(res.link_force - f).max() <= 1e-9 * np.abs(f).max()


def test_located_acceleration_peaks_with_a_fluid_damper_match_a_fine_sampling():
    # the damper's slope is unbounded where its rate reverses: the acceleration has a cusp
    # there, which must not throw the peak located inside a step off (it did: 850 g)
    link = Link(("B1F1", "B2F1"), "viscous", c=4e5, alpha=0.5)
    model = PoundingModel(list(_pair()), [10.0], KV, devices=[link])
    gm = el_centro().trimmed(6.0)
    located = simulate(model, gm).peak_abs_acceleration
    fine = np.abs(simulate(model, gm, dt=2e-5).abs_acceleration).max(axis=0)
    assert located == pytest.approx(fine, rel=1e-5)
