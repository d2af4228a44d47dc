"""Linear Maxwell links in the kernel's exact steps (:mod:`pounding.integrate.exact_maxwell`):
every output against the tight SciPy reference (``simulate_reference``, DOP853 at rtol
1e-11, the link law written out afresh) and against the same run stepped adaptively
throughout (``free_stepping="rk"``, the answer before the links were folded in); with big
gaps the exact route is the closer to the reference. A nonlinear Maxwell link (α ≠ 1) keeps
the adaptive steps."""

from __future__ import annotations

import numpy as np
import pytest

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
from pounding.devices import Link
from pounding.integrate.reference import simulate_reference

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
OUTPUTS = ("displacement", "velocity", "abs_acceleration", "link_force", "contact_force")
ENERGY = [0, 1, 2, 3, 4, 5, 7]  # input, kinetic, strain, viscous, contact work/stored, links


def _rel(a, b):
    scale = np.abs(b).max()
    return np.abs(a - b).max() / scale if scale > 0 else np.abs(a).max()


def _three_storey_pair(gap):
    blds = [ShearBuilding.uniform(3, 4e5, 6e8), ShearBuilding.uniform(3, 3e5, 9e8)]
    devices = [Link(("B1F3", "B2F3"), "maxwell", c=6e5, k=3e7),
               Link(("B2F1", "B1F1"), "maxwell", c=2e5, k=2e7),
               Link(("B1F2", "B2F2"), "kelvin", c=1e5, k=5e6)]
    return PoundingModel(blds, [gap], KV, devices=devices)


def test_maxwell_links_without_contact_are_stepped_exactly_closer_to_the_reference():
    """Gaps of 10 m: no adaptive step at all, and every output — histories, energies
    (the springs' in the strain, the dashpots' in the links' column), the located peaks —
    nearer the reference than the adaptive steps', which it also matches to their
    tolerance."""
    model = _three_storey_pair(10.0)
    gm = el_centro().trimmed(2.0)
    res = simulate(model, gm)
    rk = simulate(model, gm, free_stepping="rk")
    ref = simulate_reference(model, gm, rtol=1e-11)
    assert res.stats.rk_steps == 0 < rk.stats.rk_steps
    for name in OUTPUTS[:4]:
        ours, theirs, adaptive = (getattr(r, name) for r in (res, ref, rk))
        assert _rel(ours, theirs) < 1e-9, name
        assert _rel(ours, theirs) < _rel(adaptive, theirs), name
        assert _rel(ours, adaptive) < 1e-7, name
    e = np.s_[:, [0, 1, 2, 3, 7]]
    assert _rel(res.energy[e], ref.energy[e]) < 1e-10
    assert _rel(res.energy[e], ref.energy[e]) < _rel(rk.energy[e], ref.energy[e])
    assert res.energy[-1, 7] > 0.05 * res.energy[-1, 0] > 0.0
    assert res.energy_balance_error < 1e-10
    # located peaks (values; the times of flat crests are ill-conditioned)
    vals = np.s_[:, 0::2]
    assert _rel(res.located_peaks[vals], ref.located_peaks[vals]) < 1e-9
    assert res.link_dissipated == pytest.approx(ref.link_dissipated, rel=1e-6)


def test_maxwell_links_with_pounding_match_the_reference_and_the_adaptive_run():
    """A 10 mm gap: exact steps between the impacts, adaptive ones through them (the links'
    spring deformations handed over both ways); every output against the reference and
    against the run stepped adaptively throughout, to the tolerance's reach through the
    impacts' timing."""
    blds = [ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05),
            ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.05)]
    model = PoundingModel(blds, [0.01], KV,
                          devices=[Link(("B1F1", "B2F1"), "maxwell", c=5e5, k=1e7)])
    gm = el_centro().trimmed(4.0)
    res = simulate(model, gm)
    rk = simulate(model, gm, free_stepping="rk")
    ref = simulate_reference(model, gm, rtol=1e-11)
    assert res.n_impacts == rk.n_impacts == ref.n_impacts > 2
    assert res.stats.rk_steps < 0.2 * rk.stats.rk_steps
    for other in (ref, rk):
        for name in OUTPUTS:
            assert _rel(getattr(res, name), getattr(other, name)) < 1e-6, name
        assert _rel(res.energy[:, ENERGY], other.energy[:, ENERGY]) < 1e-6
        assert _rel(res.located_peaks[:, 0::2], other.located_peaks[:, 0::2]) < 1e-6
        assert res.peak_contact_force == pytest.approx(other.peak_contact_force, rel=1e-5)
    assert res.energy_balance_error < 1e-8
    # the links' energy (column 7) is apart from the buildings' viscous work (column 3)
    assert res.energy[-1, 7] > 0.05 * res.energy[-1, 3] > 0.0


def test_multi_storey_maxwell_links_with_pounding_match_the_adaptive_run():
    """Three-storey pair, Maxwell and Kelvin links, 5 mm gap: exact and adaptive steps
    alternate; every output against the adaptive run to its tolerance."""
    model = _three_storey_pair(0.005)
    gm = el_centro().trimmed(3.0)
    res = simulate(model, gm)
    rk = simulate(model, gm, free_stepping="rk")
    assert res.n_impacts == rk.n_impacts > 0
    assert res.stats.rk_steps < 0.5 * rk.stats.rk_steps
    for name in OUTPUTS:
        assert _rel(getattr(res, name), getattr(rk, name)) < 1e-6, name
    assert _rel(res.energy[:, ENERGY], rk.energy[:, ENERGY]) < 1e-6
    assert _rel(res.located_peaks[:, 0::2], rk.located_peaks[:, 0::2]) < 1e-6
    assert res.energy_balance_error < 1e-8


def test_a_nonlinear_maxwell_link_keeps_the_adaptive_steps():
    """α ≠ 1: the link is not linear, so not in the exact steps (an RK step at least every
    grid step); the same for "exact", refused in one line."""
    from pounding.integrate.kernel_model import kernel_model, maxwell_exact_rows

    blds = [ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05),
            ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.05)]
    model = PoundingModel(blds, [10.0], KV, devices=[
        Link(("B1F1", "B2F1"), "maxwell", c=5e5, k=1e7, alpha=0.5)])
    gm = el_centro().trimmed(0.5)
    km = kernel_model(model)
    assert maxwell_exact_rows(km) is None and not km.exact_allowed
    res = simulate(model, gm)
    assert res.stats.rk_steps >= res.time.size - 1
    with pytest.raises(ValueError, match="free_stepping"):
        simulate(model, gm, free_stepping="exact")


def test_maxwell_links_beside_a_restrainer_keep_the_adaptive_steps():
    """A restrainer's slack test in the exact steps reads the floors' accelerations without
    the Maxwell links' forces: such a model is stepped adaptively (and "exact" refused)."""
    from pounding.integrate.kernel_model import kernel_model, maxwell_exact_rows

    blds = [ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05),
            ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.05)]
    model = PoundingModel(blds, [10.0], KV, devices=[
        Link(("B1F1", "B2F1"), "maxwell", c=5e5, k=1e7),
        Link(("B1F1", "B2F1"), "restrainer", k=5e6, slack=0.05)])
    km = kernel_model(model)
    assert maxwell_exact_rows(km) is not None and not km.exact_allowed
    res = simulate(model, el_centro().trimmed(0.5))
    assert res.stats.rk_steps >= res.time.size - 1
    with pytest.raises(ValueError, match="restrainers"):
        simulate(model, el_centro().trimmed(0.5), free_stepping="exact")
