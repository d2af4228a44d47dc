"""Calibration to a target restitution and fitting to a force history.

References, independent of the code under test: a reduced-coordinate impact integrated
here with solve_ivp and force laws typed here (approach and restitution as separate
segments, release where a law that cannot pull reaches zero force); the closed forms of the
linear laws derived by hand; synthetic force histories made by these integrations (or by
the damped-oscillator closed form) with seeded Gaussian noise.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from pounding.contact import (
    BilinearImpact,
    Hertz,
    HuntCrossley,
    KelvinVoigt,
    ModifiedKelvinVoigt,
    NonlinearViscoelastic,
)
from pounding.contact.calibration import (
    calibrate,
    calibrate_bilinear,
    fit_impact,
    hertz_delta_max,
)
from pounding.contact.collision import simulate_collision

M1, M2 = 2.0e5, 3.0e5
M_EFF = M1 * M2 / (M1 + M2)
V0 = 0.5
K = 1.0e8
KH = 2.75e9


def own_impact(approach, restitution, m, v0, release=None):
    """m δ̈ = −F(δ, δ̇) from δ = 0, δ̇ = v0: ``approach`` until δ̇ = 0, then ``restitution``
    until δ = 0 or ``release`` (if given) falls through zero. Returns (e, solution list)."""
    opts = dict(method="DOP853", rtol=1e-12, atol=[1e-18, 1e-14], dense_output=True)

    def stop_v(_t, y):
        return y[1]

    stop_v.terminal, stop_v.direction = True, -1

    def stop_d(_t, y):
        return y[0]

    stop_d.terminal, stop_d.direction = True, -1
    s1 = solve_ivp(lambda t, y: [y[1], -approach(y[0], y[1]) / m], (0, 10.0), [0.0, v0],
                   events=stop_v, **opts)
    t1, y1 = s1.t_events[0][0], s1.y_events[0][0]
    events = [stop_d]
    if release is not None:
        def rel(_t, y):
            return release(y[0], y[1])

        rel.terminal, rel.direction = True, -1
        events.append(rel)
    s2 = solve_ivp(lambda t, y: [y[1], -restitution(y[0], y[1]) / m], (t1, t1 + 10.0),
                   [y1[0], 0.0], events=events, **opts)
    ends = [(te[0], ye[0]) for te, ye in zip(s2.t_events, s2.y_events) if len(te)]
    _, y_end = min(ends, key=lambda p: p[0])
    return -y_end[1] / v0, (s1, s2)


def own_e(law, m=M_EFF, v0=V0):
    """The e of ``law`` (by type and fields) from :func:`own_impact`."""
    if isinstance(law, KelvinVoigt):
        k, c = law.k, law.c
        if law.tension:
            f = lambda d, r: k * d + c * r  # noqa: E731
            return own_impact(f, f, m, v0)[0]
        f = lambda d, r: max(k * d + c * r, 0.0)  # noqa: E731
        return own_impact(f, f, m, v0, release=lambda d, r: k * d + c * r)[0]
    if isinstance(law, ModifiedKelvinVoigt):
        k, c = law.k, law.c
        return own_impact(lambda d, r: k * d + c * r, lambda d, r: k * d, m, v0)[0]
    if isinstance(law, HuntCrossley):
        kh, chi, n = law.k_h, law.chi, law.n
        f = lambda d, r: kh * max(d, 0) ** n * max(1 + chi * r / v0, 0.0)  # noqa: E731
        return own_impact(f, f, m, v0, release=lambda d, r: 1 + chi * r / v0)[0]
    if isinstance(law, NonlinearViscoelastic):
        kh, z, me = law.k_h, law.zeta, law.m_eff
        app = lambda d, r: kh * max(d, 0) ** 1.5 + 2 * z * math.sqrt(kh * math.sqrt(max(d, 0)) * me) * r  # noqa: E731
        return own_impact(app, lambda d, r: kh * max(d, 0) ** 1.5, m, v0)[0]
    raise TypeError(law)


# --------------------------------------------------------------------------- calibrate
@pytest.mark.parametrize("target", [0.3, 0.75])
@pytest.mark.parametrize("law", [
    KelvinVoigt(K, 1.0, tension=True),
    KelvinVoigt(K, 1.0, tension=False),
    ModifiedKelvinVoigt(K, 1.0),
    HuntCrossley(KH, 0.1),
    NonlinearViscoelastic(KH, 0.1, M_EFF),
], ids=["kv-tension", "kv-clip", "modified-kv", "hunt-crossley", "nonlinear-viscoelastic"])
def test_calibrate_reaches_target(law, target):
    cal = calibrate(law, target, M1, M2, V0)
    assert cal.parameter == law.damping_field
    assert cal.law.damping == cal.value
    assert cal.target_e == target
    assert cal.achieved_e == pytest.approx(target, abs=1e-6)
    # independent: the calibrated law integrated here
    assert own_e(cal.law) == pytest.approx(target, abs=2e-6)
    # stiffness untouched
    for f in ("k", "k_h"):
        if hasattr(law, f):
            assert getattr(cal.law, f) == getattr(law, f)


@pytest.mark.parametrize("target", [0.2, 0.6, 0.9])
def test_kelvin_voigt_closed_form_is_anagnostopoulos_and_root_finding_agrees(target):
    cal = calibrate(KelvinVoigt(K, 1.0, tension=True), target, M1, M2, V0)
    assert cal.method == "closed form"
    ln = math.log(target)
    c_hand = 2 * (-ln / math.sqrt(math.pi**2 + ln**2)) * math.sqrt(K * M_EFF)
    assert cal.value == pytest.approx(c_hand, rel=1e-12)
    c_root = brentq(lambda c: simulate_collision(KelvinVoigt(K, c, tension=True), M1, M2,
                                                      V0).e - target,
                    0.8 * c_hand, 1.25 * c_hand, xtol=1e-9 * c_hand, rtol=1e-12)
    assert cal.value == pytest.approx(c_root, rel=1e-6)


@pytest.mark.parametrize("target", [0.2, math.exp(-1.0), 0.6, 0.9])
def test_modified_kv_closed_form_agrees_with_root_finding(target):
    cal = calibrate(ModifiedKelvinVoigt(K, 1.0), target, M1, M2, V0)
    assert cal.method == "closed form"
    c_crit = 2 * math.sqrt(K * M_EFF)
    c_root = brentq(lambda c: simulate_collision(ModifiedKelvinVoigt(K, c), M1, M2, V0).e - target,
                    0.01 * c_crit, 20 * c_crit, xtol=1e-9 * c_crit, rtol=1e-12)
    assert cal.value == pytest.approx(c_root, rel=1e-6)
    zeta = cal.value / (2 * math.sqrt(K * M_EFF))
    if zeta < 1:  # by hand: e = exp(−ζ θ / sqrt(1 − ζ²)), θ = atan(sqrt(1 − ζ²)/ζ)
        s = math.sqrt(1 - zeta**2)
        assert math.exp(-zeta * math.atan2(s, zeta) / s) == pytest.approx(target, abs=1e-10)


def test_calibrate_independent_of_starting_damping():
    a = calibrate(HuntCrossley(KH, 0.01), 0.5, M1, M2, V0)
    b = calibrate(HuntCrossley(KH, 5.0), 0.5, M1, M2, V0)
    assert a.value == pytest.approx(b.value, rel=1e-5)


@pytest.mark.parametrize("target", [0.65, 0.8])
def test_calibrate_bilinear_reaches_target(target):
    cal = calibrate_bilinear(KH, target, M1, M2, V0)
    assert cal.achieved_e == pytest.approx(target, abs=1e-6)
    dm = (5 * M_EFF * V0**2 / (4 * KH)) ** 0.4          # Muthukumar: δm from elastic Hertz
    expected = BilinearImpact.from_hertz(KH, cal.value, dm)
    assert cal.law == expected
    assert simulate_collision(cal.law, M1, M2, V0).e == pytest.approx(target, abs=1e-6)


def test_calibrate_bilinear_out_of_reach_says_so():
    # sized at the elastic Hertz penetration the element cannot dissipate enough for e = 0.3
    with pytest.raises(ValueError, match="target_e=0.3 is out of reach"):
        calibrate_bilinear(KH, 0.3, M1, M2, V0)


def test_bilinear_from_hertz_elastic_limit_names_e_or_works():
    try:
        law = BilinearImpact.from_hertz(KH, 1.0, 1e-3)
    except ValueError as exc:
        assert str(exc).startswith("e")
    else:
        assert law.dissipated_energy(1e-3) == 0.0


def test_hertz_delta_max_by_energy_balance():
    dm = hertz_delta_max(KH, M_EFF, V0)
    # ½ m v0² = ∫0^δm k δ^1.5 dδ = (2/5) k δm^2.5
    assert 0.4 * KH * dm**2.5 == pytest.approx(0.5 * M_EFF * V0**2, rel=1e-13)


@pytest.mark.parametrize("args, match", [
    ((KelvinVoigt(K, 1.0), 1.0), "target_e"),
    ((KelvinVoigt(K, 1.0), 0.0), "target_e"),
    ((KelvinVoigt(K, 1.0), 1.2), "target_e"),
    ((KelvinVoigt(K, 1.0), float("nan")), "target_e"),
    ((Hertz(KH), 0.5), "law"),
    ((BilinearImpact.from_hertz(KH, 0.6, 1e-3), 0.5), "calibrate_bilinear"),
])
def test_calibrate_bad_inputs(args, match):
    with pytest.raises(ValueError, match=match):
        calibrate(*args, M1, M2, V0)


def test_calibrate_bad_masses():
    with pytest.raises(ValueError, match="m1"):
        calibrate(KelvinVoigt(K, 1.0), 0.5, -1.0, M2, V0)


# --------------------------------------------------------------------------- fit
def hc_history(kh, chi, t, m=M_EFF, v0=V0):
    """Force history of a Hunt–Crossley impact integrated here (zero after separation)."""
    f = lambda d, r: kh * max(d, 0) ** 1.5 * max(1 + chi * r / v0, 0.0)  # noqa: E731
    _, (s1, s2) = own_impact(f, f, m, v0, release=lambda d, r: 1 + chi * r / v0)
    t_end = s2.t[-1]
    out = np.zeros_like(t)
    for i, ti in enumerate(t):
        if ti < s1.t[-1]:
            y = s1.sol(ti)
        elif ti < t_end:
            y = s2.sol(ti)
        else:
            continue
        out[i] = f(y[0], y[1])
    return out, t_end


def kv_history(k, c, t, m=M_EFF, v0=V0):
    """Kelvin–Voigt (tension) closed form, F = kδ + cδ̇ for 0 ≤ t ≤ π/ω_d."""
    w = math.sqrt(k / m)
    z = c / (2 * math.sqrt(k * m))
    wd = w * math.sqrt(1 - z * z)
    d = (v0 / wd) * np.exp(-z * w * t) * np.sin(wd * t)
    r = v0 * np.exp(-z * w * t) * (np.cos(wd * t) - z * w / wd * np.sin(wd * t))
    return np.where(t <= math.pi / wd, k * d + c * r, 0.0), math.pi / wd


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_fit_recovers_hunt_crossley_from_noisy_history(seed):
    kh, chi = KH, 0.5
    _, t_end = hc_history(kh, chi, np.array([0.0]))
    t = np.linspace(0.0, 1.3 * t_end, 300)
    f, _ = hc_history(kh, chi, t)
    noisy = f + 0.02 * f.max() * np.random.default_rng(seed).standard_normal(t.size)
    fit = fit_impact(t, noisy, M1, M2, V0, law="hunt-crossley")
    assert fit.parameters["stiffness"] == pytest.approx(kh, rel=0.03)
    assert fit.parameters["chi"] == pytest.approx(chi, rel=0.03)
    assert fit.law.k_h == fit.parameters["stiffness"]
    assert fit.relative_residual == pytest.approx(0.02, rel=0.3)   # the noise level
    assert fit.achieved_e == pytest.approx(own_e(HuntCrossley(kh, chi)), abs=0.02)


def test_fit_recovers_kelvin_voigt_from_clean_history():
    k, c = K, 2 * 0.2 * math.sqrt(K * M_EFF)
    _, T = kv_history(k, c, np.array([0.0]))
    t = np.linspace(0.0, 1.3 * T, 300)
    f, _ = kv_history(k, c, t)
    fit = fit_impact(t, f, M1, M2, V0, law="kelvin-voigt")
    assert fit.parameters["stiffness"] == pytest.approx(k, rel=0.03)
    assert fit.parameters["c"] == pytest.approx(c, rel=0.03)


def test_fit_recovers_kelvin_voigt_from_noisy_history():
    k, c = K, 2 * 0.2 * math.sqrt(K * M_EFF)
    _, T = kv_history(k, c, np.array([0.0]))
    t = np.linspace(0.0, 1.3 * T, 300)
    f, _ = kv_history(k, c, t)
    for seed in (0, 1, 2):
        noisy = f + 0.02 * f.max() * np.random.default_rng(seed).standard_normal(t.size)
        fit = fit_impact(t, noisy, M1, M2, V0, law="kelvin-voigt")
        assert fit.parameters["stiffness"] == pytest.approx(k, rel=0.03)
        assert fit.parameters["c"] == pytest.approx(c, rel=0.03)


@pytest.mark.parametrize("kwargs, match", [
    (dict(t=np.linspace(0, 1, 10), force=np.ones(9)), "t and force"),
    (dict(t=np.linspace(0, 1, 4), force=np.ones(4)), "t and force"),
    (dict(t=np.linspace(0, 1, 10), force=np.r_[np.ones(9), np.nan]), "finite"),
    (dict(t=np.linspace(0, 1, 10), force=np.zeros(10)), "force"),
    (dict(t=np.linspace(0, 1, 10), force=np.ones(10), v0=0.0), "v0"),
    (dict(t=np.linspace(0, 1, 10), force=np.ones(10), law="bilinear-impact"), "law"),
])
def test_fit_bad_inputs(kwargs, match):
    args = dict(m1=M1, m2=M2, v0=V0)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        fit_impact(**args)


def test_cli_prints_laws_and_fits_with_units(tmp_path, capsys):
    """`pounding collide` and `calibrate` head their output with the law in words and units;
    `pounding fit` gives every quantity its unit."""
    import re

    from pounding.cli import main

    assert main(["collide", "--law", "nonlinear-viscoelastic", "--e", "0.65"]) == 0
    out = " ".join(capsys.readouterr().out.split())  # (rich wraps the title)
    # ζ = 0.368: the exact ζ of e = 0.65, the default since issue 24 (test_default_restitution
    # checks by an independent integration that it gives 0.65; Jankowski's eq 19 gave 0.373)
    assert "nonlinear viscoelastic (Jankowski): k_h = 2.75e9 N/m^1.5, ζ = 0.368" in out
    assert "NonlinearViscoelastic(" not in out and "k_h=" not in out
    assert main(["calibrate", "--law", "kelvin-voigt", "--e", "0.6"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Kelvin-Voigt (Anagnostopoulos): k = 9.30e8 N/m, c = ")
    assert re.search(r"\nc = [0-9.]+ N·s/m \(closed form\)", out)
    kh, chi = KH, 0.5
    _, t_end = hc_history(kh, chi, np.array([0.0]))
    t = np.linspace(0.0, 1.3 * t_end, 200)
    f, _ = hc_history(kh, chi, t)
    path = tmp_path / "force.csv"
    np.savetxt(path, np.column_stack([t, f]), delimiter=",")
    assert main(["fit", str(path), "--law", "hunt-crossley", "--m1", str(M1), "--m2", str(M2),
                 "--v0", str(V0)]) == 0
    rows = [ln.split("│")[1].strip() for ln in capsys.readouterr().out.splitlines()
            if ln.count("│") == 3]
    assert rows[:2] == ["stiffness k_h [N/m^1.5]", "damping χ [-]"]
    assert len(rows) == 5 and all(re.search(r"\[[^\]]+\]$", r) for r in rows), rows
