"""The sacrificial shear key (issue 28): its law along a path (elastic to the capacity, a
plateau whose set outlasts the impact, no tension, broken for good at the fracture
deformation), a deck striking it against the closed form written out here (elastic half-
sine to yield, constant force to fracture: the time and velocity at failure, the energy
it takes), the kernel against the SciPy reference, and bad values refused in one line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.contact import ShearKey
from pounding.contact.shear_key import key_response
from pounding.ground_motion import GroundMotion
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.wall import MoatWall

K, FC, DU = 1.0e9, 2.0e6, 0.05  # N/m, N, m: δ_y = 2 mm


def test_path_elastic_plateau_set_no_tension_then_broken_for_good():
    """Up to 30 mm: k δ to F_c, then F_c (set δ − δ_y); back to 10 mm along k from the set;
    the gap opens (δ < 0); the next impact starts at the set; at δ_u the key breaks and
    pushes nothing after, however far or often the deck comes back."""
    law = ShearKey(K, FC, DU)
    up = np.linspace(0.0, 0.03, 301)
    down = np.linspace(0.03, -0.01, 401)[1:]
    again = np.linspace(-0.01, 0.07, 801)[1:]
    back = np.linspace(0.07, -0.02, 91)[1:]
    third = np.linspace(-0.02, 0.06, 81)[1:]
    d = np.concatenate([up, down, again, back, third])
    f = law.respond(d, np.gradient(d))
    n1, n2, n3 = up.size, up.size + down.size, up.size + down.size + again.size
    np.testing.assert_allclose(f[:n1], np.minimum(K * up, FC), rtol=1e-12)
    s1 = 0.03 - FC / K
    np.testing.assert_allclose(f[n1:n2], np.maximum(K * (down - s1), 0.0), rtol=1e-12,
                               atol=1e-6)
    before = again < DU
    np.testing.assert_allclose(f[n2:n3][before],
                               np.where(again[before] <= 0.03,
                                        np.maximum(K * (again[before] - s1), 0.0), FC),
                               rtol=1e-12, atol=1e-6)
    assert f[n2:n3][again < s1].max() == 0.0 and s1 > 0.0
    # the first sample past δ_u is the 'after' side of the fracture: committed broken there,
    # zero from the next sample on (the kernel drops the force at the located instant)
    first = int(np.argmax(again >= DU))
    assert (f[n2 + first + 1:] == 0.0).all()
    assert (f >= 0.0).all()
    assert law.backbone(0.001) == pytest.approx(1.0e6) and law.backbone(DU) == 0.0


def one_mass(spec: ContactSpec, v0: float, duration: float, rtol: float | None = None,
             reference: bool = False):
    """A free mass (1e6 kg on a spring of period 1e7 s) 10 mm from a rigid key, at v0."""
    sdof = ShearBuilding.sdof(1.0e6, period=1.0e7, damping_ratio=0.0, height=1.0)
    model = PoundingModel([sdof], [], ContactSpec("linear-spring", k=1.0),
                          walls=[MoatWall(1.0, 0.01, contact=spec)])
    quiet = GroundMotion(dt=0.01, accel=np.zeros(round(duration / 0.01) + 1))
    kw = {} if rtol is None else {"rtol": rtol}
    run = simulate_reference if reference else simulate
    return run(model, quiet, duration=duration, initial_velocity=np.array([v0]), **kw)


@pytest.mark.parametrize("du", [DU, FC / K], ids=["elastic-plastic", "elastic-brittle"])
def test_deck_released_into_the_key_matches_the_closed_form(du):
    """m ẍ = −k x to yield (x = (v0/ω) sin ωt: t_y = asin(F_c ω/(k v0))/ω, v_y² = v0² −
    F_c²/(k m)), then ẍ = −F_c/m to δ_u (v_f² = v_y² − 2 F_c (δ_u − δ_y)/m, after
    (v_y − v_f) m/F_c), then free flight at v_f. The impact ends at the fracture; the key's
    peak force is F_c; it took F_c (δ_u − δ_y/2) = ½ m (v0² − v_f²) from the deck."""
    m, v0, gap = 1.0e6, 1.2, 0.01
    spec = ContactSpec("shear-key", k=K, capacity=FC, fracture_displacement=du)
    law = spec.build(m, math.inf)
    dy = FC / K
    w = math.sqrt(K / m)
    t_y = math.asin(FC * w / (K * v0)) / w
    v_y = math.sqrt(v0**2 - FC**2 / (K * m))
    v_f = math.sqrt(v_y**2 - 2.0 * FC * (du - dy) / m)
    t_f = gap / v0 + t_y + (v_y - v_f) * m / FC
    cf = key_response(law, m, v0)
    assert cf["t_fracture"] == pytest.approx(t_f - gap / v0, rel=1e-14)
    assert cf["v_fracture"] == pytest.approx(v_f, rel=1e-14)
    res = one_mass(spec, v0, 0.1)
    (row,) = res.impacts.itertuples()
    assert row.start == pytest.approx(gap / v0, rel=1e-7)
    # (measured at the default rtol: the fracture instant 6e-8, v_f 8e-8 — the yield kink
    # lies inside a step — the key's work 1.0e-6; elastic-brittle, no kink: 1e-12)
    assert row.end == pytest.approx(t_f, rel=5e-7)  # the located fracture
    assert row.peak_force == pytest.approx(FC, rel=1e-9)
    assert res.velocity[-1, 0] == pytest.approx(v_f, rel=5e-7)
    assert res.contact_force[-1, 0] == 0.0
    e = dict(zip(("input", "kinetic", "strain", "damping", "work", "stored"),
                 res.energy[-1, :6]))
    assert e["stored"] == 0.0
    assert e["work"] == pytest.approx(FC * (du - 0.5 * dy), rel=5e-6)
    assert e["work"] == pytest.approx(0.5 * m * (v0**2 - v_f**2), rel=5e-6)
    assert law.dissipated_at_fracture == pytest.approx(FC * (du - 0.5 * dy), rel=1e-14)
    assert res.energy_balance_error < 1e-8


def test_a_key_too_strong_to_break_leaves_a_set_and_stays():
    """A deck at 0.35 m/s yields the key (plateau) but stops short of δ_u: it rebounds at
    F_c/√(k m) (the elastic energy F_c²/(2k) given back), the key keeps its set."""
    m, v0 = 1.0e6, 0.35
    spec = ContactSpec("shear-key", k=K, capacity=FC, fracture_displacement=DU)
    cf = key_response(spec.build(m, math.inf), m, v0)
    assert math.isnan(cf["t_fracture"]) and cf["delta_max"] < DU
    res = one_mass(spec, v0, 0.4, rtol=1e-11)
    (row,) = res.impacts.itertuples()
    assert row.max_penetration == pytest.approx(cf["delta_max"], rel=1e-8)
    assert -res.velocity[-1, 0] == pytest.approx(FC / math.sqrt(K * m), rel=1e-8)
    dissipated = res.energy[-1, 4] - res.energy[-1, 5]  # contact work less stored
    assert dissipated == pytest.approx(cf["dissipated"], rel=1e-8)


def test_kernel_matches_the_reference_through_the_fracture():
    """The same strike, kernel and SciPy reference (its own event at δ = δ_u): fracture
    time, displacements and peak force to 1e-6 of their scales."""
    spec = ContactSpec("shear-key", k=K, capacity=FC, fracture_displacement=DU)
    res = one_mass(spec, 1.2, 0.1)
    ref = one_mass(spec, 1.2, 0.1, rtol=1e-11, reference=True)
    assert len(res.impacts) == len(ref.impacts) == 1
    assert res.impacts["end"][0] == pytest.approx(ref.impacts["end"][0], rel=1e-6)
    peak = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * peak
    assert res.peak_contact_force[0] == pytest.approx(ref.peak_contact_force[0], rel=1e-9)


@pytest.mark.parametrize("kw, field", [
    ({"k": -1.0, "capacity": FC}, "k"),
    ({"k": K, "capacity": 0.0}, "capacity"),
    ({"k": K, "capacity": FC, "fracture_displacement": 0.001}, "fracture_displacement"),
    ({"k": K}, "capacity"),
    ({"k": K, "capacity": FC, "e": 0.5}, "e"),
])
def test_bad_values_are_refused_naming_the_field(kw, field):
    with pytest.raises(ValueError) as err:
        ContactSpec("shear-key", **kw)
    assert str(err.value).startswith(field)
    assert "\n" not in str(err.value)
