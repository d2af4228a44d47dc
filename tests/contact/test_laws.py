"""The contact laws against the contract of pounding.contact.base and their formulas.

References, independent of the code under test: each law's force re-typed from FORMULAS.md
and evaluated by hand; central finite differences of the force for the tangents; the
parallelogram of Muthukumar's bilinear element constructed vertex by vertex (area by the
shoelace formula); the work ∫F dδ along closed load-unload paths by the trapezoid rule.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from pounding.contact import (
    LAWS,
    BilinearImpact,
    Hertz,
    HuntCrossley,
    KelvinVoigt,
    LinearSpring,
    ModifiedKelvinVoigt,
    NonlinearViscoelastic,
)
from pounding.contact.calibration import fit_impact
from pounding.validation import choice

K = 1.0e8          # N/m
C = 2.0e6          # N s/m
KH = 2.75e9        # N/m^1.5
M_EFF = 1.2e5      # kg
V0 = 0.5           # m/s
V0_MIN = 1e-6      # the contract's floor on the recorded impact velocity (base.py docstring)


def make_laws():
    return {
        "linear-spring": LinearSpring(K),
        "kv-tension": KelvinVoigt(K, C, tension=True),
        "kv-clip": KelvinVoigt(K, C, tension=False),
        "modified-kv": ModifiedKelvinVoigt(K, C),
        "hertz": Hertz(KH),
        "hunt-crossley": HuntCrossley(KH, 0.6),
        "nonlinear-viscoelastic": NonlinearViscoelastic(KH, 0.4, M_EFF),
        "bilinear": BilinearImpact.from_hertz(KH, 0.6, 2e-3),
    }


LAWS_UNDER_TEST = make_laws()
LAW_IDS = sorted(LAWS_UNDER_TEST)


def in_contact(v0=V0, dmax=0.0, slip=0.0):
    """A committed in-contact state [v0, slip, dmax] written from the contract."""
    return np.array([v0, slip, dmax])


# --------------------------------------------------------------------------- open gap
@pytest.mark.parametrize("name", LAW_IDS)
@pytest.mark.parametrize("delta", [0.0, -1e-9, -3e-3])
@pytest.mark.parametrize("rate", [-2.0, 0.0, 0.7])
@pytest.mark.parametrize("committed", [None, "contact"])
def test_open_gap_is_force_free_and_forgets(name, delta, rate, committed):
    law = LAWS_UNDER_TEST[name]
    state = None if committed is None else in_contact(dmax=1e-3, slip=2e-4)
    f, kd, kr, out = law.trial(delta, rate, state)
    assert (f, kd, kr) == (0.0, 0.0, 0.0)
    assert np.all(out == 0.0)


# --------------------------------------------------------------------------- onset
@pytest.mark.parametrize("name", LAW_IDS)
@pytest.mark.parametrize("rate, recorded", [(0.37, 0.37), (2.5, 2.5), (0.0, V0_MIN), (-0.4, V0_MIN)])
def test_onset_records_impact_velocity(name, rate, recorded):
    law = LAWS_UNDER_TEST[name]
    res = law.trial(1e-4, rate)
    assert res.state[0] == recorded
    assert res.state[2] == 1e-4          # largest penetration so far
    # a second trial from that committed state keeps v0, whatever the new rate
    res2 = law.trial(2e-4, -0.1, res.state)
    assert res2.state[0] == recorded
    assert res2.state[2] == 2e-4


# --------------------------------------------------------------------------- trial is pure
@pytest.mark.parametrize("name", LAW_IDS)
def test_trial_never_mutates_committed(name):
    law = LAWS_UNDER_TEST[name]
    for committed in (np.zeros(3), in_contact(dmax=5e-4), in_contact(dmax=2e-3, slip=1.8e-3)):
        for delta, rate in [(-1e-3, 0.3), (1e-4, 0.5), (1e-3, -0.3), (3e-3, 0.1)]:
            before = committed.copy()
            out = law.trial(delta, rate, committed).state
            np.testing.assert_array_equal(committed, before)
            assert out is not committed


# --------------------------------------------------------------------------- tangents
TANGENT_POINTS = [
    # (delta, rate, committed state)
    (1.0e-4, 0.4, in_contact()),
    (1.3e-3, 0.4, in_contact()),
    (1.3e-3, -0.25, in_contact(dmax=1.3e-3)),
    (7.0e-4, -0.45, in_contact(dmax=2e-3)),
]


@pytest.mark.parametrize("name", LAW_IDS)
@pytest.mark.parametrize("delta, rate, state", TANGENT_POINTS)
def test_tangents_match_central_differences(name, delta, rate, state):
    law = LAWS_UNDER_TEST[name]
    f, kd, kr, _ = law.trial(delta, rate, state)

    def force(d, r):
        return law.trial(d, r, state).force

    hd, hr = 1e-6 * delta, 1e-6 * abs(rate)
    fd_d = (force(delta + hd, rate) - force(delta - hd, rate)) / (2 * hd)
    fd_r = (force(delta, rate + hr) - force(delta, rate - hr)) / (2 * hr)
    scale_d = max(abs(kd), abs(f) / delta, 1.0)
    scale_r = max(abs(kr), abs(f) / abs(rate), 1.0)
    assert kd == pytest.approx(fd_d, rel=1e-5, abs=1e-7 * scale_d)
    assert kr == pytest.approx(fd_r, rel=1e-5, abs=1e-7 * scale_r)


@pytest.mark.parametrize("delta, state, slope", [
    (1.0e-4, in_contact(), "K1"),                       # elastic loading below δy
    (1.3e-3, in_contact(), "K2"),                       # post-yield loading
    (1.9e-3, in_contact(dmax=2e-3, slip=1.8e-3), "K1"),  # elastic unloading from δm
    (1.0e-3, in_contact(dmax=2e-3, slip=1.8e-3), "K2"),  # on the line F = K2 δ
])
def test_bilinear_tangents_on_each_branch(delta, state, slope):
    law = LAWS_UNDER_TEST["bilinear"]
    f, kd, kr, _ = law.trial(delta, -0.1, state)
    h = 1e-7
    fd = (law.trial(delta + h, -0.1, state).force - law.trial(delta - h, -0.1, state).force) / (2 * h)
    assert kd == pytest.approx(getattr(law, slope), rel=1e-12)
    assert fd == pytest.approx(kd, rel=1e-6)
    assert kr == 0.0


# --------------------------------------------------------------------------- by hand
def test_linear_spring_by_hand():
    f, kd, kr, _ = LinearSpring(K).trial(2e-3, 0.3)
    assert (f, kd, kr) == pytest.approx((K * 2e-3, K, 0.0))


@pytest.mark.parametrize("tension", [True, False])
def test_kelvin_voigt_compression_by_hand(tension):
    f, kd, kr, _ = KelvinVoigt(K, C, tension).trial(1e-3, 0.2, in_contact())
    assert f == pytest.approx(K * 1e-3 + C * 0.2, rel=1e-14)
    assert (kd, kr) == (K, C)


def test_kelvin_voigt_tension_pulls_and_clip_does_not():
    delta, rate = 1e-3, -0.2          # kδ + cδ̇ = 1e5 − 4e5 = −3e5 N
    f, kd, kr, _ = KelvinVoigt(K, C, tension=True).trial(delta, rate, in_contact())
    assert f == pytest.approx(-3.0e5, rel=1e-14)
    assert (kd, kr) == (K, C)
    f, kd, kr, _ = KelvinVoigt(K, C, tension=False).trial(delta, rate, in_contact())
    assert (f, kd, kr) == (0.0, 0.0, 0.0)


@pytest.mark.parametrize("rate", [0.0, -1e-12, -0.3])
def test_modified_kelvin_voigt_has_no_dashpot_when_separating(rate):
    f, kd, kr, _ = ModifiedKelvinVoigt(K, C).trial(1e-3, rate, in_contact())
    assert (f, kd, kr) == (K * 1e-3, K, 0.0)
    f, kd, kr, _ = ModifiedKelvinVoigt(K, C).trial(1e-3, 0.3, in_contact())
    assert f == pytest.approx(K * 1e-3 + C * 0.3, rel=1e-14)
    assert kr == C


@pytest.mark.parametrize("rate", [0.0, -1e-12, -0.3])
def test_nonlinear_viscoelastic_has_no_dashpot_when_separating(rate):
    law = NonlinearViscoelastic(KH, 0.4, M_EFF)
    f, kd, kr, _ = law.trial(1e-3, rate, in_contact())
    assert f == pytest.approx(KH * 1e-3**1.5, rel=1e-14)
    assert kd == pytest.approx(1.5 * KH * math.sqrt(1e-3), rel=1e-14)
    assert kr == 0.0


@pytest.mark.parametrize("delta, rate", [(1e-3, 0.3), (4e-4, 1.7), (2.2e-3, 1e-3)])
def test_jankowski_dashpot_eq18_by_hand(delta, rate):
    zeta = 0.4
    law = NonlinearViscoelastic(KH, zeta, M_EFF)
    c = 2 * zeta * math.sqrt(KH * math.sqrt(delta) * M_EFF)          # seed eq 18
    f, kd, kr, _ = law.trial(delta, rate, in_contact())
    assert f == pytest.approx(KH * delta**1.5 + c * rate, rel=1e-13)
    assert kr == pytest.approx(c, rel=1e-13)


@pytest.mark.parametrize("rate", [0.45, 0.1, -0.2, -0.4])
def test_hunt_crossley_by_hand(rate):
    chi, v0, delta = 0.6, 0.5, 1.1e-3
    f, kd, kr, _ = HuntCrossley(KH, chi).trial(delta, rate, in_contact(v0=v0))
    assert f == pytest.approx(KH * delta**1.5 * (1 + chi * rate / v0), rel=1e-13)
    assert kr == pytest.approx(KH * delta**1.5 * chi / v0, rel=1e-13)


def test_hunt_crossley_cannot_pull():
    # 1 + χ δ̇/v0 = 1 − 3·0.3/0.5 < 0: clipped to zero force
    f, kd, kr, _ = HuntCrossley(KH, 3.0).trial(1e-3, -0.3, in_contact(v0=0.5))
    assert (f, kd, kr) == (0.0, 0.0, 0.0)


def test_hertz_by_hand():
    f, kd, kr, _ = Hertz(KH).trial(1.7e-3, -0.3, in_contact())
    assert f == pytest.approx(KH * 1.7e-3**1.5, rel=1e-14)
    assert kd == pytest.approx(1.5 * KH * 1.7e-3**0.5, rel=1e-14)
    assert kr == 0.0


def test_respond_commits_v0_of_first_contact_sample():
    """Hunt–Crossley along a path: v0 is the rate at the first sample with δ > 0."""
    chi = 0.6
    d = np.array([-1e-4, 0.0, 2e-4, 6e-4, 8e-4, 5e-4, 1e-4, -1e-5])
    r = np.array([0.6, 0.55, 0.5, 0.3, 0.0, -0.25, -0.4, -0.45])
    f = HuntCrossley(KH, chi).respond(d, r)
    v0 = 0.5
    expected = [0.0 if di <= 0 else max(KH * di**1.5 * (1 + chi * ri / v0), 0.0) for di, ri in zip(d, r)]
    np.testing.assert_allclose(f, expected, rtol=1e-13)


def test_respond_rejects_mismatched_shapes():
    with pytest.raises(ValueError, match="delta and rate"):
        Hertz(KH).respond(np.zeros(3), np.zeros(4))


# --------------------------------------------------------------------------- bilinear loop
def test_bilinear_from_hertz_constants_by_hand():
    kh, e, dm, a = KH, 0.6, 2e-3, 0.1
    law = BilinearImpact.from_hertz(kh, e, dm, a)
    dE = kh * dm**2.5 * (1 - e * e) / 2.5
    keff = kh * math.sqrt(dm)
    assert law.K1 == pytest.approx(keff + dE / (a * dm**2), rel=1e-14)
    assert law.K2 == pytest.approx(keff - dE / ((1 - a) * dm**2), rel=1e-14)
    assert law.delta_y == pytest.approx(a * dm, rel=1e-15)
    assert law.dissipated_energy(dm) == pytest.approx(dE, rel=1e-12)


@pytest.mark.parametrize("e, a", [(0.6, 0.1), (0.8, 0.2), (0.45, 0.05)])
def test_bilinear_parallelogram_loop(e, a):
    """Drive respond() 0 → δm → 0 and check the parallelogram of Muthukumar (2003)."""
    dm = 2e-3
    law = BilinearImpact.from_hertz(KH, e, dm, a)
    K1, K2, dy = law.K1, law.K2, law.delta_y
    n = 2000
    up = np.linspace(0.0, dm, n + 1)
    down = up[::-1][1:]
    d = np.concatenate([up, down])
    r = np.concatenate([np.full(up.size, 0.3), np.full(down.size, -0.2)])
    f = law.respond(d, r)
    fu, fd = f[: up.size], f[up.size:]

    # loading: K1 up to δy, then K2
    load = np.where(up <= dy, K1 * up, K1 * dy + K2 * (up - dy))
    np.testing.assert_allclose(fu, load, rtol=1e-12, atol=1e-9 * load.max())
    fm = K1 * dy + K2 * (dm - dy)
    # peak force is the Hertz force at δm (K_eff δm), a property of the sizing
    assert fm == pytest.approx(KH * dm**1.5, rel=1e-12)
    # unloading: K1 down to the line F = K2 δ through the gap point, then along it
    unload = np.maximum(fm - K1 * (dm - down), K2 * down)
    np.testing.assert_allclose(fd, unload, rtol=1e-12, atol=1e-9 * fm)
    assert f[-1] == 0.0

    # loop area: shoelace of the hand-built vertices, and trapezoid of the sampled loop
    du = (K1 * dm - fm) / (K1 - K2)              # where unloading meets F = K2 δ
    verts = np.array([(0, 0), (dy, K1 * dy), (dm, fm), (du, K2 * du)])
    x, y = verts[:, 0], verts[:, 1]
    shoelace = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    dE = KH * dm**2.5 * (1 - e * e) / 2.5       # Muthukumar's ΔE
    assert shoelace == pytest.approx(dE, rel=1e-12)
    work = np.trapezoid(f, d)                    # ∮ F dδ along the path
    assert work == pytest.approx(dE, rel=1e-5)


def test_bilinear_below_yield_is_elastic():
    law = BilinearImpact.from_hertz(KH, 0.6, 2e-3)
    d = np.concatenate([np.linspace(0, 0.5 * law.delta_y, 50), np.linspace(0.5 * law.delta_y, 0, 50)])
    r = np.concatenate([np.full(50, 0.1), np.full(50, -0.1)])
    np.testing.assert_allclose(law.respond(d, r), law.K1 * d, rtol=1e-13)


# --------------------------------------------------------------------------- energy
@pytest.mark.parametrize("name", LAW_IDS)
@pytest.mark.parametrize("dm, T", [(1e-3, 0.05), (3e-3, 0.01)])
def test_no_energy_created_over_a_closed_impact(name, dm, T):
    """W = ∮ F dδ = ∫ F δ̇ dt ≥ 0 along δ = δm sin(πt/T) (trapezoid, fine grid)."""
    law = LAWS_UNDER_TEST[name]
    t = np.linspace(0.0, T, 20001)
    d = dm * np.sin(np.pi * t / T)
    r = dm * np.pi / T * np.cos(np.pi * t / T)
    d[-1] = 0.0
    f = law.respond(d, r)
    w = np.trapezoid(f * r, t)
    scale = np.max(np.abs(f)) * dm
    assert w >= -1e-6 * scale
    if name in ("linear-spring", "hertz"):
        assert abs(w) <= 1e-6 * scale
    else:
        assert w > 1e-4 * scale


def test_kelvin_voigt_tension_work_is_dashpot_work():
    """∮ (kδ + cδ̇) dδ = c ∫ δ̇² dt = c δm² π² / (2T) on a half-sine path."""
    dm, T = 1e-3, 0.05
    t = np.linspace(0.0, T, 40001)
    d = dm * np.sin(np.pi * t / T)
    r = dm * np.pi / T * np.cos(np.pi * t / T)
    d[-1] = 0.0
    f = KelvinVoigt(K, C, tension=True).respond(d, r)
    w = np.trapezoid(f * r, t)
    assert w == pytest.approx(C * dm**2 * np.pi**2 / (2 * T), rel=1e-4)


# --------------------------------------------------------------------------- validation
@pytest.mark.parametrize("build, name, shown", [
    (lambda: LinearSpring(0.0), "k", "0"),
    (lambda: LinearSpring(-1e8), "k", "-1e+08"),
    (lambda: KelvinVoigt(-5.0, C), "k", "-5"),
    (lambda: KelvinVoigt(K, -3.0), "c", "-3"),
    (lambda: KelvinVoigt(K, float("nan")), "c", "nan"),
    (lambda: ModifiedKelvinVoigt(K, -3.0), "c", "-3"),
    (lambda: Hertz(-2.0), "k_h", "-2"),
    (lambda: HuntCrossley(KH, -0.1), "chi", "-0.1"),
    (lambda: NonlinearViscoelastic(KH, -0.1, M_EFF), "zeta", "-0.1"),
    (lambda: NonlinearViscoelastic(KH, 0.3, 0.0), "m_eff", "0"),
    (lambda: KelvinVoigt.from_zeta(K, -0.2, 1e5, 2e5), "zeta", "-0.2"),
    (lambda: ModifiedKelvinVoigt.from_zeta(K, -0.2, 1e5, 2e5), "zeta", "-0.2"),
    (lambda: BilinearImpact(1e8, 2e8, 1e-4), "K2", "2e+08"),
    (lambda: BilinearImpact(1e8, 1e8, 1e-4), "K2", "1e+08"),
    (lambda: BilinearImpact(-1e8, 0.0, 1e-4), "K1", "-1e+08"),
    (lambda: BilinearImpact(1e8, 1e7, -1e-4), "delta_y", "-0.0001"),
    (lambda: BilinearImpact.from_hertz(KH, 0.6, -1e-3), "delta_m", "-0.001"),
    (lambda: BilinearImpact.from_hertz(KH, 1.3, 1e-3), "e", "1.3"),
])
def test_bad_parameters_raise_naming_parameter_and_value(build, name, shown):
    with pytest.raises(ValueError) as info:
        build()
    msg = str(info.value)
    assert msg.startswith(name)
    assert f"got {shown}" in msg


def test_unknown_law_name_raises_naming_it():
    assert set(LAWS) >= {"kelvin-voigt", "hertz", "bilinear-impact"}
    with pytest.raises(ValueError, match="law: unknown value 'nope'"):
        choice("law", "nope", LAWS)
    with pytest.raises(ValueError, match="'nope'"):
        fit_impact(np.linspace(0, 1, 10), np.ones(10), 1e5, 1e5, 0.5, law="nope")


def test_from_restitution_rejects_wrong_kind_of_formula():
    with pytest.raises(ValueError, match="formula"):
        KelvinVoigt.from_restitution(K, 0.5, 1e5, 2e5, formula="gonthier")
    with pytest.raises(ValueError, match="formula"):
        HuntCrossley.from_restitution(KH, 0.5, formula="jankowski")


def test_damping_accessors():
    law = KelvinVoigt(K, C)
    assert law.damping == C
    assert law.with_damping(3.0).c == 3.0
    with pytest.raises(ValueError, match="c"):
        law.with_damping(-1.0)
    with pytest.raises(ValueError, match="no damping"):
        Hertz(KH).damping


def test_readable_names_every_field_with_its_unit():
    """``readable()``: the law, its source, every field with its unit in three significant
    digits (the report's "Contact elements" and the headers of `pounding collide` and
    `pounding calibrate`); ``describe()`` keeps the exact values."""
    law = NonlinearViscoelastic(2.75e9, 0.3728356652600535, 239999.99999999997)
    assert law.readable() == ("nonlinear viscoelastic (Jankowski): k_h = 2.75e9 N/m^1.5, "
                              "ζ = 0.373, m_eff = 2.40e5 kg")
    assert "0.3728356652600535" in law.describe()
    assert KelvinVoigt(9.3e8, 4967715.508553788).readable() == (
        "Kelvin-Voigt (Anagnostopoulos): k = 9.30e8 N/m, c = 4.97e6 N·s/m, no tension")
    assert HuntCrossley(KH, 0.433125, n=1.6).readable() == (
        "Hunt-Crossley: k_h = 2.75e9 N/m^1.6, χ = 0.433, n = 1.6")
    for name, law in make_laws().items():
        text = law.readable()
        assert text.startswith(law.label) and "=" in text and "e+" not in text, name
        for field in (f.name for f in dataclasses.fields(law)):
            value = getattr(law, field)
            if isinstance(value, bool):
                continue
            unit = law.field_unit(field)
            assert unit, (name, field)  # every field has its unit ("-": none)
            assert (unit == "-") or f" {unit}" in text, (name, field, text)


@pytest.mark.parametrize("name", LAW_IDS)
@pytest.mark.parametrize("delta", [2e-4, 1e-3])
def test_secant_stiffness_is_the_compiled_backbone_over_delta(name, delta):
    # The Python secant stiffness (which sets the contact period checked before a run)
    # against the compiled law's force at zero rate, loading from a fresh onset: F / δ.
    law = LAWS_UNDER_TEST[name]
    force = law.trial(delta, 0.0).force
    assert law.secant_stiffness(delta) == pytest.approx(force / delta, rel=1e-12)
