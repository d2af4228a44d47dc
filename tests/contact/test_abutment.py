"""The abutment backfill law (issue 28) and walls with a law of their own: the backbones
against their formulas written out here (Caltrans SDC in US units converted here; the
hyperbola of Shamsabadi et al. 2007), its hysteresis along a path (unloading at K, a
permanent set kept from one impact to the next, no tension), a deck striking a rigid
abutment against the elastic–perfectly-plastic closed form, the kernel against the SciPy
reference under El Centro, the energy balance, and a model file from the command line."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.contact import AbutmentBackfill
from pounding.ground_motion import GroundMotion, el_centro
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.wall import MoatWall

LBF = 4.4482216152605  # N (the pound-force, exact by definition of the lb and g_n)
KIP, INCH, FOOT = 1000.0 * LBF, 0.0254, 0.3048
KV = ContactSpec("kelvin-voigt", k=1.0e9, e=0.6)


def test_caltrans_backbone_is_the_sdc_formula_in_si():
    """K_abut = K_i w (h/5.5 ft), K_i = 50 kip/in/ft; P_bw = w h 5.0 ksf (h/5.5 ft), here
    computed in US units and converted at the end; elastic–perfectly-plastic."""
    w, h = 12.0, 2.1  # m
    w_ft, h_ft = w / FOOT, h / FOOT
    k_kip_in = 50.0 * w_ft * (h_ft / 5.5)
    p_kip = w_ft * h_ft * 5.0 * (h_ft / 5.5)
    law = AbutmentBackfill.caltrans(w, h)
    assert law.K == pytest.approx(k_kip_in * KIP / INCH, rel=1e-12)
    assert law.capacity == pytest.approx(p_kip * KIP, rel=1e-12)
    dy = law.capacity / law.K
    for d in (0.3 * dy, dy, 2.0 * dy, 10.0 * dy):
        assert law.backbone(d) == pytest.approx(min(law.K * d, law.capacity), rel=1e-12)
    # 50 kip/in/ft = 28,728 kN/m per m of width (the figure OpenSees examples use)
    assert 50.0 * KIP / INCH / FOOT == pytest.approx(2.8728e7, rel=1e-4)


def test_hyperbolic_backbone_is_shamsabadis_hyperbola():
    """F = δ/(A + B δ), A = 1/K_max, F(δ_ult) = F_ult; capped at F_ult past δ_ult; the same
    as OpenSees' HyperbolicGapMaterial envelope δ/(1/Kmax + Rf δ/Fult) with
    Rf = 1 − F_ult/(K_max δ_ult)."""
    k_max, f_ult, y_ult = 2.03e7 * 10.0, 3.26e5 * 10.0, 0.0764
    law = AbutmentBackfill.hyperbolic(k_max, f_ult, y_ult)
    a = 1.0 / k_max
    b = (1.0 - a * f_ult / y_ult) / f_ult
    rf = 1.0 - f_ult / (k_max * y_ult)
    for d in np.linspace(1e-5, y_ult, 7):
        expected = d / (a + b * d)
        assert law.backbone(d) == pytest.approx(expected, rel=1e-12)
        assert law.backbone(d) == pytest.approx(d / (1.0 / k_max + rf * d / f_ult), rel=1e-12)
    assert law.backbone(y_ult) == pytest.approx(f_ult, rel=1e-12)
    assert law.backbone(2.0 * y_ult) == f_ult
    # initial slope K_max
    assert law.backbone(1e-9) / 1e-9 == pytest.approx(k_max, rel=1e-6)


@pytest.mark.parametrize("law", [AbutmentBackfill.elastic_plastic(1.0e8, 1.0e6),
                                 AbutmentBackfill.hyperbolic(1.0e8, 1.0e6, 0.05)])
def test_push_then_cycles_unload_at_k_leave_a_set_and_never_pull(law):
    """Monotonic push: the backbone. Unloading: the line K (δ − set); zero force below the
    set (no tension); reloading along the same line back to the backbone; a second impact
    (the gap open in between) finds the set left by the first."""
    up = np.linspace(0.0, 0.04, 401)
    down = np.linspace(0.04, -0.01, 501)
    again = np.linspace(-0.01, 0.06, 701)
    d = np.concatenate([up, down[1:], again[1:]])
    rate = np.gradient(d)
    f = law.respond(d, rate)
    n1, n2 = up.size, up.size + down.size - 1
    np.testing.assert_allclose(f[:n1], [law.backbone(x) for x in up], rtol=1e-12, atol=0)
    f_top = law.backbone(0.04)
    set_1 = 0.04 - f_top / law.K
    expected_down = np.maximum(law.K * (down[1:] - set_1), 0.0)
    np.testing.assert_allclose(f[n1:n2], expected_down, rtol=1e-9, atol=1e-6)
    assert (f >= 0.0).all()
    # the gap opened (δ < 0) and the next impact starts at the set, not at δ = 0
    reload = again[1:]
    expected_re = np.where(reload <= 0.04, np.maximum(law.K * (reload - set_1), 0.0),
                           [law.backbone(x) for x in reload])
    np.testing.assert_allclose(f[n2:], expected_re, rtol=1e-9, atol=1e-6)
    assert f[n2:][reload < set_1].max() == 0.0 and set_1 > 0.0


def one_mass(spec: ContactSpec, v0: float, duration: float, rtol: float | None = None):
    """A free mass (1e6 kg, spring period 1e7 s) 10 mm from a rigid abutment, at v0."""
    sdof = ShearBuilding.sdof(1.0e6, period=1.0e7, damping_ratio=0.0, height=1.0)
    model = PoundingModel([sdof], [], ContactSpec("linear-spring", k=1.0),
                          walls=[MoatWall(1.0, 0.01, contact=spec)])
    quiet = GroundMotion(dt=0.01, accel=np.zeros(round(duration / 0.01) + 1))
    kw = {} if rtol is None else {"rtol": rtol}
    return simulate(model, quiet, duration=duration, initial_velocity=np.array([v0]), **kw)


@pytest.mark.parametrize("rtol, tol", [(None, 5e-6), (1e-11, 1e-8)])
def test_deck_on_a_rigid_abutment_matches_the_elastic_plastic_closed_form(rtol, tol):
    """m ẍ = −K x until F = F_y (a half-sine: x = (v0/ω) sin ωt, ω² = K/m), reached at
    δ_y = F_y/K with v1² = v0² − F_y²/(K m); then the plateau, a constant deceleration F_y/m
    over v1² m/(2 F_y); then unloading along K returns F_y²/(2K): the rebound velocity is
    F_y/sqrt(K m), the set δ_max − δ_y."""
    m, k, fy, v0 = 1.0e6, 1.0e9, 2.0e6, 0.5
    dy = fy / k
    v1 = math.sqrt(v0**2 - fy**2 / (k * m))
    delta_max = dy + m * v1**2 / (2.0 * fy)
    v_out = fy / math.sqrt(k * m)
    res = one_mass(ContactSpec("abutment", backbone="elastic-plastic", k=k, capacity=fy),
                   v0, 1.5, rtol)
    (row,) = res.impacts.itertuples()
    assert row.max_penetration == pytest.approx(delta_max, rel=tol)
    assert -res.velocity[-1, 0] == pytest.approx(v_out, rel=tol)
    assert row.restitution == pytest.approx(v_out / v0, rel=tol)
    assert row.peak_force == pytest.approx(fy, rel=1e-12)
    assert row.energy_dissipated == pytest.approx(0.5 * m * (v0**2 - v_out**2), rel=tol)
    assert res.energy_balance_error < 1e-8


@pytest.mark.parametrize("spec", [
    ContactSpec("abutment", backbone="caltrans", backwall_width=4.0, backwall_height=1.0),
    ContactSpec("abutment", backbone="hyperbolic", k=1.0e8, capacity=1.0e6, delta_ult=0.03),
], ids=["caltrans", "hyperbolic"])
def test_two_buildings_and_an_abutment_match_the_reference(spec):
    """Two SDOFs (the second a deck-like 1.5e6 kg) pound each other and the second strikes
    an abutment 10 mm away under El Centro × 1.5 (4 s): the backfill yields, keeps its set
    (later approaches stop short of it: zero force), and the kernel matches the SciPy
    reference to 1e-6 of the peaks; the energy balance closes to 1e-8."""
    b1 = ShearBuilding.sdof(1.0e6, period=1.0, damping_ratio=0.05, height=6.0)
    b2 = ShearBuilding.sdof(1.5e6, period=0.7, damping_ratio=0.05, height=6.0)
    model = PoundingModel([b1, b2], [0.02], KV, walls=[MoatWall(6.0, 0.01, contact=spec)])
    motion = el_centro().scaled(1.5)
    res = simulate(model, motion, duration=4.0)
    ref = simulate_reference(model, motion, duration=4.0, rtol=1e-10)
    wall = res.impacts[res.impacts["contact"] == "B2F1-W"]
    assert len(wall) >= 3 and (wall["peak_force"].iloc[2:] == 0.0).all()  # inside the set
    assert model.contacts[1].law == spec.build(1.0, 1.0)  # the wall's own law, not KV
    assert list(res.impacts_per_contact) == list(ref.impacts_per_contact)
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-6)
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * scale
    np.testing.assert_allclose(res.impacts["max_penetration"], ref.impacts["max_penetration"],
                               rtol=1e-6)
    assert res.energy_balance_error < 1e-8


ABUTMENT_FILE = """
name = "deck and abutment"
[record]
bundled = "el_centro"
pga_g = 0.5
[[building]]
name = "deck"
n_storeys = 1
mass = 1.5e6
period = 0.7
height = 6.0
[[wall]]
height = 6.0
gap = 0.01
name = "A2"
law = "abutment"
backbone = "caltrans"
backwall_width = 4.0
backwall_height = {h}
[solver]
duration = 3.0
"""


def test_a_model_file_with_an_abutment_wall_runs_from_the_cli(tmp_path: Path, capsys):
    path = tmp_path / "abutment.toml"
    path.write_text(ABUTMENT_FILE.format(h="1.0"), encoding="utf-8")
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--no-figures"]) == 0
    impacts = (tmp_path / "out" / "impacts.csv").read_text(encoding="utf-8")
    assert "B1F1-A2" in impacts


@pytest.mark.parametrize("change, message", [
    (("backwall_height = 1.0", "backwall_height = -1.0"), "wall[0].backwall_height"),
    (("backbone = \"caltrans\"", "backbone = \"parabolic\""), "wall[0].backbone"),
    (("backwall_width = 4.0", "k = 1.0e8"), "wall[0].k"),
    (("law = \"abutment\"", "law = \"hertz\""), "wall[0].backbone"),
    (("law = \"abutment\"\n", ""), "wall[0].backbone"),
])
def test_bad_abutment_input_is_one_line_naming_the_field(tmp_path: Path, capsys, change,
                                                         message):
    path = tmp_path / "bad.toml"
    path.write_text(ABUTMENT_FILE.format(h="1.0").replace(*change), encoding="utf-8")
    out = tmp_path / "out"
    capsys.readouterr()
    assert main(["run", str(path), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and "\n" not in err and "Traceback" not in err
    assert not out.exists()
