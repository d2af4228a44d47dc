"""Bumpers: a pad in the gap. Checked by kinematics (where the pad and the bottomed-out
building contact start to act, by hand) and against the SciPy reference."""

from __future__ import annotations

import numpy as np
import pytest

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
from pounding.devices import Bumper
from pounding.ground_motion import GroundMotion
from pounding.integrate.reference import simulate_reference

NLVE = ContactSpec("nonlinear-viscoelastic", k_h=2.75e9, e=0.65)
RUBBER = ContactSpec("hertzdamp", k_h=5e7, e=0.5)


def _pair(gap: float, bumper: Bumper | None) -> PoundingModel:
    return PoundingModel([ShearBuilding.sdof(2e5, period=0.5, damping_ratio=0.05),
                          ShearBuilding.sdof(3e5, period=1.0, damping_ratio=0.05)], [gap],
                         NLVE, devices=[bumper] if bumper else [])


def test_the_pad_and_the_moved_building_contact_sit_where_the_geometry_puts_them():
    model = _pair(0.05, Bumper(("B2F1", "B1F1"), thickness=0.02, compression_limit=0.6,
                               rubber=RUBBER))
    pad, building = model.contacts
    assert (pad.label, building.label) == ("B1F1-B2F1/bumper", "B1F1-B2F1")
    # pad: gap 50 − 20 = 30 mm; building contact once the pad is squeezed by 0.6 × 20 mm
    assert pad.gap == pytest.approx(0.03) and building.gap == pytest.approx(0.042)
    assert pad.law == RUBBER.build(2e5, 3e5)
    assert building.law == _pair(0.05, None).contacts[0].law


def test_a_floor_thrown_at_the_pad_first_meets_it_at_the_gap_less_the_thickness():
    # at rest, floor 1 thrown right at v0: free vibration u(t) = v0/ω_d e^{−ζωt} sin ω_d t;
    # the pad is first touched where u reaches g − t (by hand, bisection on the closed form)
    m, T, zeta, v0, g, t_pad = 2e5, 0.5, 0.05, 0.5, 0.05, 0.02
    w = 2 * np.pi / T
    wd = w * np.sqrt(1 - zeta**2)
    lo, hi = 0.0, np.pi / (2 * wd)
    u = lambda t: v0 / wd * np.exp(-zeta * w * t) * np.sin(wd * t)  # noqa: E731
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if u(mid) < g - t_pad else (lo, mid)
    model = PoundingModel([ShearBuilding.sdof(m, period=T, damping_ratio=zeta),
                           ShearBuilding.sdof(1e9, period=1.0, damping_ratio=0.05)], [g], NLVE,
                          devices=[Bumper(("B1F1", "B2F1"), t_pad, 0.7, RUBBER)])
    still = GroundMotion(0.01, np.zeros(101), name="at rest")
    res = simulate(model, still, initial_velocity=np.array([v0, 0.0]))
    first = res.impacts.sort_values("start").iloc[0]
    assert first["contact"] == "B1F1-B2F1/bumper"
    assert first["start"] == pytest.approx(lo, abs=1e-9)


@pytest.mark.parametrize("limit", [0.3, 0.9])
def test_a_bumped_pair_matches_the_scipy_reference(limit):
    model = _pair(0.01, Bumper(("B1F1", "B2F1"), 0.006, limit, RUBBER))
    gm = el_centro().trimmed(4.0)
    res = simulate(model, gm)
    ref = simulate_reference(model, gm)
    assert res.n_impacts == ref.n_impacts > 0
    assert np.allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-5, atol=1.0)
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() / scale < 1e-6
    assert res.energy_balance_error < 1e-7


def test_a_soft_pad_lowers_the_peak_impact_force():
    gm = el_centro().trimmed(8.0)
    bare = simulate(_pair(0.01, None), gm)
    padded = simulate(_pair(0.01, Bumper(("B1F1", "B2F1"), 0.008, 0.9, RUBBER)), gm)
    assert padded.peak_contact_force.max() < bare.peak_contact_force.max()


@pytest.mark.parametrize("kw, match", [
    (dict(thickness=0.0, compression_limit=0.5), "thickness: must be finite and > 0"),
    (dict(thickness=0.01, compression_limit=1.0), "compression_limit: must be between 0 and 1"),
])
def test_bad_bumpers_are_refused(kw, match):
    with pytest.raises(ValueError, match=match):
        Bumper(("B1F1", "B2F1"), rubber=RUBBER, **kw)


def test_a_bumper_thicker_than_its_gap_or_outside_a_contact_is_refused():
    with pytest.raises(ValueError, match=r"^devices\[0\].thickness: the B1F1-B2F1 bumper "
                                         r"\(0.03 m\) is thicker than its gap \(0.02 m\)$"):
        _pair(0.02, Bumper(("B1F1", "B2F1"), 0.03, 0.5, RUBBER))
    with pytest.raises(ValueError, match=r"devices\[0\].floors: B1F2-B2F1 is not a "
                                         r"floor-to-floor contact of this model"):
        _pair(0.02, Bumper(("B1F2", "B2F1"), 0.01, 0.5, RUBBER))
