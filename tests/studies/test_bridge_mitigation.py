"""Mitigation on a bridge: a bumper on a backwall (checked by the closed form of a deck
thrown at it and against the SciPy reference), devices beside a bridge in a model file, and
`pounding mitigate` comparing restrainers, a damper across the joint and backwall bumpers,
its bridge columns read off runs made apart."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding import ContactSpec, PoundingModel, ShearBuilding, simulate
from pounding.cli import main
from pounding.config import RunConfig
from pounding.devices import Bumper
from pounding.ground_motion import GroundMotion, el_centro
from pounding.integrate.reference import simulate_reference
from pounding.structure.bridge import Abutment, Bearing, Bridge, BridgeFrame, Pier
from pounding.structure.wall import MoatWall
from pounding.studies.mitigation import BRIDGE_MEASURES, run_mitigation

KV = ContactSpec("kelvin-voigt", k=1.0e9, e=0.6)
RUBBER = ContactSpec("hertzdamp", k_h=5e7, e=0.5)


def test_a_deck_thrown_at_a_backwall_pad_meets_it_at_the_gap_less_the_thickness() -> None:
    """A mass at rest thrown toward its wall at v0 vibrates freely, u(t) = v0/ω_d e^{−ζωt}
    sin ω_d t, until it meets the pad on the wall where u reaches g − t (bisection on the
    closed form); the bare contact moves to g − t + r t and keeps the wall's law."""
    m, T, zeta, v0, g, t_pad = 2e5, 0.5, 0.05, 0.5, 0.05, 0.02
    w = 2 * np.pi / T
    wd = w * np.sqrt(1 - zeta**2)
    lo, hi = 0.0, np.pi / (2 * wd)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        u = v0 / wd * np.exp(-zeta * w * mid) * np.sin(wd * mid)
        lo, hi = (mid, hi) if u < g - t_pad else (lo, mid)
    model = PoundingModel([ShearBuilding.sdof(m, period=T, damping_ratio=zeta)], [], KV,
                          walls=[MoatWall(height=3.0, gap=g, name="A2")],
                          devices=[Bumper(("A2", "B1F1"), t_pad, 0.7, RUBBER)])
    pad, bare = model.contacts
    assert (pad.label, bare.label) == ("B1F1-A2/bumper", "B1F1-A2")
    assert pad.gap == pytest.approx(g - t_pad) and bare.gap == pytest.approx(g - 0.3 * t_pad)
    assert pad.law == RUBBER.build(m, np.inf) and bare.law == KV.build(m, np.inf)
    still = GroundMotion(0.01, np.zeros(101), name="at rest")
    res = simulate(model, still, initial_velocity=np.array([v0]))
    first = res.impacts.sort_values("start").iloc[0]
    assert first["contact"] == "B1F1-A2/bumper"
    assert first["start"] == pytest.approx(lo, abs=1e-9)


def _bridge(devices=()) -> PoundingModel:
    f1 = BridgeFrame(2.0e6, [Pier(8.0, 5.0e7, 1.0e5)], Bearing.elastomeric(2.0e7, 1.0e5))
    f2 = BridgeFrame(3.0e6, [Pier(8.0, 8.0e7, 1.5e5)], Bearing.elastomeric(6.0e7))
    bridge = Bridge([f1, f2], [0.015], abutments=(Abutment(0.03), Abutment(0.03)))
    args = bridge.model_arguments()
    return PoundingModel(contact=KV, **(args | {"devices": list(devices)}))


@pytest.mark.slow  # a reference comparison (pyproject.toml: markers)
def test_backwall_pads_match_the_scipy_reference() -> None:
    """Pads on both backwalls of a two-frame bridge under El Centro × 1.5 (2 s): the kernel
    against the SciPy reference, impact for impact (pads and bare contacts struck), and the
    energy balance."""
    pads = [Bumper(("A1", "B1F1"), 0.02, 0.7, RUBBER), Bumper(("B2F1", "A2"), 0.02, 0.7, RUBBER)]
    model = _bridge(pads)
    gm = el_centro().scaled(1.5).trimmed(2.0)
    res, ref = simulate(model, gm), simulate_reference(model, gm)
    assert [c.label for c in model.contacts] == ["B1F1-B2F1", "A1-B1F1/bumper", "A1-B1F1",
                                                 "B2F1-A2/bumper", "B2F1-A2"]
    assert res.impacts_per_contact.tolist() == ref.impacts_per_contact.tolist()
    assert res.impacts_per_contact.min() > 0  # both pads struck, and the bare contacts
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * scale
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-5,
                               atol=1.0)
    assert res.energy_balance_error < 1e-8


@pytest.mark.parametrize(("floors", "message"), [
    (["A1", "A2"], "floors: give two floor labels like 'B1F3'"),
    (["A3", "B1F1"], "devices[0].floors: A3-B1F1 is not a floor-to-floor contact of this "
                     "model (contacts, with the walls: B1F1-B2F1, A1-B1F1, B2F1-A2)"),
])
def test_a_pad_on_no_wall_is_refused(floors, message) -> None:
    with pytest.raises(ValueError) as err:
        _bridge([Bumper(tuple(floors), 0.01, 0.5, RUBBER)])
    assert message in str(err.value)


BASE = '''name = "bridge"
[record]
bundled = "el_centro"
scale = 1.5
duration = 3.0
[contact]
law = "kelvin-voigt"
k = 1.0e9
e = 0.6
[bridge]
abutment_gaps = [0.03, 0.03]
[[bridge.frame]]
spans = [30.0]
deck_mass = 2.0e6
bearing = { type = "elastomeric", stiffness = 2.0e7, damping = 1.0e5 }
[[bridge.frame.pier]]
height = 8.0
stiffness = 5.0e7
mass = 1.0e5
[[bridge.frame]]
spans = [30.0]
deck_mass = 3.0e6
bearing = { type = "elastomeric", stiffness = 6.0e7 }
[[bridge.frame.pier]]
height = 8.0
stiffness = 8.0e7
mass = 1.5e5
[[bridge.joint]]
gap = 0.015
'''

PAD = '''type = "bumper"
thickness = 0.02
compression_limit = 0.7
rubber = { law = "hertzdamp", k_h = 5.0e7, e = 0.5 }'''

STUDY = f'''name = "bridge retrofit"
base = "bridge.toml"
[[option]]
name = "as built"
[[option]]
name = "cable restrainers"
[[option.device]]
type = "restrainer"
floors = ["B1F1", "B2F1"]
k = 1.76e7
slack = 0.005
[[option]]
name = "damper across the joint"
[[option.device]]
type = "viscous"
floors = "all"
c = 5.0e6
[[option]]
name = "bumpers at the backwalls"
[[option.device]]
floors = ["A1", "B1F1"]
{PAD}
[[option.device]]
floors = ["B2F1", "A2"]
{PAD}
'''


def test_mitigate_compares_bridge_retrofits(tmp_path: Path) -> None:
    """`pounding mitigate` on a bridge: each option's devices added to it; its seat
    openings and pier shears are those of the same runs made apart (the as-built bridge and
    the one with pads: the decks' displacements and the piers' forces read by hand)."""
    (tmp_path / "bridge.toml").write_text(BASE)
    (tmp_path / "study.toml").write_text(STUDY)
    out = run_mitigation(tmp_path / "study.toml", tmp_path / "out", figures=False)
    t = out.table.set_index("option")
    assert list(t.index) == ["as built", "cable restrainers", "damper across the joint",
                             "bumpers at the backwalls"]
    assert set(BRIDGE_MEASURES) <= set(t.columns)
    assert t["n_pad_impacts"].tolist()[:3] == [0, 0, 0] and t["n_pad_impacts"].iloc[3] > 0
    assert t["links_dissipated_J"].iloc[2] > 0 and t["peak_link_force_N"].iloc[1] > 0
    # the damper and the cables hold the joint: it opens less than as built
    assert t["peak_joint_opening_m"].iloc[1] < t["peak_joint_opening_m"].iloc[0]
    assert t["peak_joint_opening_m"].iloc[2] < t["peak_joint_opening_m"].iloc[0]
    for option, extra in (("as built", ""), ("bumpers at the backwalls",
                                             STUDY.split('name = "bumpers at the backwalls"')[1]
                                             .replace("option.device", "device"))):
        data = (tmp_path / "bridge.toml").read_text() + extra
        (tmp_path / "apart.toml").write_text(data)
        from pounding.config import load_config

        model, motion, solver = load_config(tmp_path / "apart.toml").build()
        res = simulate(model, motion, **solver)
        u1, u2 = res.displacement[:, 0], res.displacement[:, 2]  # the decks B1F1, B2F1
        openings = np.column_stack([u1, u2 - u1, -u2])
        assert t.loc[option, "peak_seat_opening_m"] == max(openings.max(), 0.0)
        assert t.loc[option, "peak_joint_opening_m"] == max((u2 - u1).max(), 0.0)
        k_pier = [5.0e7, 8.0e7]  # linear piers: shear k × cap drift
        caps = res.displacement[:, [1, 3]]
        shear = max(k * np.abs(caps[:, i]).max() for i, k in enumerate(k_pier))
        assert t.loc[option, "peak_pier_shear_N"] == pytest.approx(shear, rel=1e-12)
    assert np.isnan(t["peak_storey_shear_N"]).all()  # a bridge's frames have no storeys


def test_devices_beside_a_bridge_in_a_model_file(tmp_path: Path, capsys) -> None:
    """A bridge file takes [[device]] tables (a damper across the joint, a pad on a
    backwall); a bad one is refused in one line naming its key, exit 2, nothing written."""
    text = BASE + '\n[[device]]\ntype = "viscous"\nfloors = "all"\nc = 5.0e6\n'
    model, _, _ = RunConfig.model_validate(_toml(text), context={"base_dir": tmp_path}).build()
    assert [(link.kind, link.floors) for link in model.links] == [("viscous",
                                                                   ("B1F1", "B2F1"))]
    bad = BASE + '\n[[device]]\ntype = "viscous"\nfloors = ["B1F1", "B3F1"]\nc = 5.0e6\n'
    (tmp_path / "bad.toml").write_text(bad)
    capsys.readouterr()
    assert main(["run", str(tmp_path / "bad.toml"), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "device[0].floors: no floor B3F1 in this model" in err[0], err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


def _toml(text: str) -> dict:
    import tomllib

    return tomllib.loads(text)
