"""A bridge across its axis (issue 28): decks on their piers held by shear keys at the
abutments and joints, and abutment piles beside the backfill along the axis. Checked
against closed forms written out here (a deck swinging between two elastic keys: the time
in contact per excursion and the period; a deck striking a backfill with piles behind it),
against the SciPy reference (keys yielding and breaking off), and from the model file (the
example runs with ``pounding run``; bad values are refused in one line, exit 2)."""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config.load import parse_config
from pounding.contact.spec import ContactSpec
from pounding.example_files import example_path
from pounding.ground_motion import GroundMotion
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.bridge import (
    Bearing,
    BridgeFrame,
    Pier,
    ShearKeys,
    TransverseBridge,
    abutment_piles,
)
from pounding.structure.stops import Stop
from pounding.structure.wall import MoatWall


def quiet(duration: float, dt: float = 0.05) -> GroundMotion:
    return GroundMotion(dt=dt, accel=np.zeros(round(duration / dt) + 1))


def test_keys_are_one_sided_stops_and_decks_never_meet() -> None:
    """Two frames: no deck-to-deck contact (an infinite gap); a key each side at each
    abutment and each way at the joint, δ = ±u − gap against the ground, ±(u1 − u2) − gap
    between the decks."""
    f = BridgeFrame(1.0e6, [Pier(8.0, 5.0e7, 1.0e5)], Bearing.elastomeric(4.0e7))
    keys = ShearKeys.of(0.02, 5.0e8, 1.5e6, 0.05)
    joint = ShearKeys.of(0.01, 3.0e8, 1.0e6)
    model = PoundingModel.from_bridge(TransverseBridge((f, f), (keys, keys), (joint,)),
                                      keys.law)
    assert [c.label for c in model.contacts] == [
        "B1F1-A1+y/key", "A1-y-B1F1/key", "B2F1-A2+y/key", "A2-y-B2F1/key",
        "B1F1-B2F1/key", "B2F1-B1F1/key"]
    u = np.array([0.03, 0.0, -0.04, 0.0])  # deck 1 +30 mm, deck 2 −40 mm
    np.testing.assert_allclose(model.contact_penetration(u),
                               [0.01, -0.05, -0.06, 0.02, 0.06, -0.08], atol=1e-15)
    assert math.isinf(model.gaps[0])
    # without keys: a bridge free across its axis, no contact at all
    assert PoundingModel.from_bridge(TransverseBridge((f, f)), keys.law).contacts == ()


@pytest.mark.parametrize("gap", [0.001, 0.02])
def test_deck_between_elastic_keys_period_while_in_contact(gap: float) -> None:
    """A deck on piers (SDOF, k_p) between two keys (k, never yielding), released at u = 0
    with v0: free, u = (v0/ω_p) sin ω_p t, to the gap at t1 = asin(g ω_p/v0)/ω_p with
    v1² = v0² − ω_p² g²; against the key, ω_c² = (k_p + k)/m about u_e = k g/(k_p + k),
    leaving it after τ_c = 2 atan2(v1/ω_c, g k_p/(k_p + k))/ω_c; the period 4 t1 + 2 τ_c.
    The impacts' located starts and ends give both."""
    m, kp, k, v0 = 1.0e6, 4.0e7, 3.0e8, 0.3
    deck = ShearBuilding.sdof(m, stiffness=kp, damping_ratio=0.0, height=9.0)
    key = ContactSpec("shear-key", k=k, capacity=1.0e9)
    model = PoundingModel([deck], [], key, stops=[
        Stop(0, 0, +1, gap, key, name="A1+y"), Stop(0, 0, -1, gap, key, name="A1-y")])
    wp, wc = math.sqrt(kp / m), math.sqrt((kp + k) / m)
    t1 = math.asin(gap * wp / v0) / wp
    v1 = math.sqrt(v0**2 - (wp * gap) ** 2)
    tau = 2.0 * math.atan2(v1 / wc, gap * kp / (kp + k)) / wc
    period = 4.0 * t1 + 2.0 * tau
    res = simulate(model, quiet(3.0 * period), duration=3.0 * period,
                   initial_velocity=np.array([v0]))
    imp = res.impacts
    plus = imp[imp["contact"] == "B1F1-A1+y/key"]
    minus = imp[imp["contact"] == "A1-y-B1F1/key"]
    assert len(plus) == 3 and len(minus) >= 2
    np.testing.assert_allclose(plus["end"] - plus["start"], tau, rtol=1e-10)  # (2e-12)
    np.testing.assert_allclose(minus["end"] - minus["start"], tau, rtol=1e-10)
    np.testing.assert_allclose(np.diff(plus["start"]), period, rtol=1e-10)
    assert plus["start"].iloc[0] == pytest.approx(t1, rel=1e-10)
    # (the elastic keys take nothing: the balance closes, the contacts dissipate nothing)
    assert res.energy[-1, 4] - res.energy[-1, 5] == pytest.approx(0.0, abs=1e-6 * 0.5 * m * v0**2)


def _two_frames() -> PoundingModel:
    f1 = BridgeFrame(1.2e6, [Pier(9.0, 6.0e7, 1.2e5)], Bearing.elastomeric(8.0e7, 2.0e5))
    f2 = BridgeFrame(1.0e6, [Pier(6.0, 9.0e7, 1.0e5)], Bearing.elastomeric(8.0e7, 2.0e5))
    keys = ShearKeys.of(0.005, 5.0e8, 1.5e6, 0.02)
    joint = ShearKeys.of(0.005, 3.0e8, 1.0e6, 0.02)
    return PoundingModel.from_bridge(TransverseBridge((f1, f2), (keys, keys), (joint,)),
                                     keys.law)


def test_keys_yielding_and_breaking_off_match_the_reference() -> None:
    """Two frames released with decks moving apart (1.0 and −0.8 m/s) into their keys: every
    key yields and breaks off (the fracture located by the kernel and by the reference's
    own event). Impacts, failure instants, peak forces and displacements agree to 1e-6 of
    their scales (measured 3e-8 of the peak displacement); both balance their energy."""
    model = _two_frames()
    v = np.array([1.0, 0.0, -0.8, 0.0])
    res = simulate(model, quiet(0.7), duration=0.7, initial_velocity=v, rtol=1e-10)
    ref = simulate_reference(model, quiet(0.7), duration=0.7, initial_velocity=v, rtol=1e-10)
    assert list(res.impacts["contact"]) == list(ref.impacts["contact"])
    assert len(res.impacts) == 6
    keys, keys_ref = res.shear_keys, ref.shear_keys
    assert [k.failed for k in keys] == [True] * 6 == [k.failed for k in keys_ref]
    for k, kr in zip(keys, keys_ref):
        assert k.failure_time_s == pytest.approx(kr.failure_time_s, rel=1e-6)
        assert k.peak_force_N == pytest.approx(kr.peak_force_N, rel=1e-9)
        assert k.peak_force_N == k.capacity_N and k.peak_deformation_m == 0.02
    peak = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * peak
    assert np.abs(res.contact_force - ref.contact_force).max() < 1e-6 * 1.5e6
    assert res.energy_balance_error < 1e-8 and ref.energy_balance_error < 1e-8
    # each key broke at δ_u: it took F_c (δ_u − δ_y/2) of the deck's energy
    took = res.energy[-1, 4] - res.energy[-1, 5]
    expected = sum(c.law.dissipated_at_fracture for c in model.contacts)
    assert took == pytest.approx(expected, rel=1e-6)


def test_piles_beside_the_backfill_match_the_closed_form() -> None:
    """A deck (free mass) at v0 strikes an elastic–perfectly-plastic backfill (K, F_y) with
    piles (k_p) in parallel behind the same gap: stiffness K + k_p to the backfill's yield
    at δ_y, then k_p alone on top of F_y; at the stop ½ m v0² = ½ (K + k_p) δ_y² +
    F_y (δ_m − δ_y) + ½ k_p (δ_m² − δ_y²). The backfill's contact peaks at F_y, the
    piles' (``…/piles``) at k_p δ_m."""
    m, kb, fy, v0 = 1.0e6, 1.0e9, 2.0e6, 0.5
    piles = abutment_piles(3)
    kp = piles.k
    sdof = ShearBuilding.sdof(m, period=1.0e7, damping_ratio=0.0, height=1.0)
    wall = MoatWall(1.0, 0.01, contact=ContactSpec("abutment", backbone="elastic-plastic",
                                                    k=kb, capacity=fy), piles=piles)
    model = PoundingModel([sdof], [], ContactSpec("linear-spring", k=1.0), walls=[wall])
    assert [c.label for c in model.contacts] == ["B1F1-W", "B1F1-W/piles"]
    dy = fy / kb
    # 0.5 kp d² + fy d + c = 0 for the largest penetration d
    c0 = 0.5 * (kb + kp) * dy**2 - fy * dy - 0.5 * kp * dy**2 - 0.5 * m * v0**2
    dm = (-fy + math.sqrt(fy**2 - 2.0 * kp * c0)) / kp
    res = simulate(model, quiet(0.3, 0.01), duration=0.3, initial_velocity=np.array([v0]),
                   rtol=1e-11)
    backfill, pile = res.impacts.iloc[0], res.impacts.iloc[1]
    assert backfill.max_penetration == pytest.approx(dm, rel=1e-8)
    assert backfill.peak_force == pytest.approx(fy, rel=1e-12)
    assert pile.peak_force == pytest.approx(kp * dm, rel=1e-8)
    assert kp == pytest.approx(3 * 40.0 * 4448.2216152605 / 0.0254, rel=1e-12)  # 3 × 40 kip/in
    assert res.energy_balance_error < 1e-8


def test_example_runs_from_the_command_line(tmp_path: Path) -> None:
    """examples/bridge_transverse.toml with ``pounding run``: the six keys' contacts, their
    states in summary.json (four of them break off under El Centro at 0.5 g; each broken
    one reached δ_u = 50 mm at the abutments, 40 mm at the joint)."""
    out = tmp_path / "run"
    assert main(["run", str(example_path("bridge_transverse.toml")), "--out", str(out),
                 "--no-figures"]) == 0
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    keys = summary["shear_keys"]
    assert list(keys) == ["B1F1-A1+y/key", "A1-y-B1F1/key", "B2F1-A2+y/key", "A2-y-B2F1/key",
                          "B1F1-B2F1/key", "B2F1-B1F1/key"]
    broken = {label for label, k in keys.items() if k["failed"]}
    assert broken == {"B1F1-A1+y/key", "A1-y-B1F1/key", "A2-y-B2F1/key", "B1F1-B2F1/key"}
    for label in broken:
        assert keys[label]["peak_deformation_m"] == (0.05 if "A" in label else 0.04)
        assert keys[label]["set_m"] is None and keys[label]["failure_time_s"] > 0.0
    for label in set(keys) - broken:
        assert keys[label]["set_m"] == pytest.approx(
            keys[label]["peak_deformation_m"] - keys[label]["capacity_N"]
            / (5.0e8 if "A" in label else 3.0e8), rel=1e-12)
    assert summary["energy_balance_error"] < 1e-8


BASE = """
[record]
bundled = "el_centro"
[bridge]
direction = "transverse"
abutment_keys = { gap = 0.02, k = 5e8, capacity = 1.5e6, fracture_displacement = 0.05 }
[[bridge.frame]]
spans = [30.0]
deck_mass_per_length = 1.5e4
bearing = { type = "elastomeric", stiffness = 3e7 }
[[bridge.frame.pier]]
height = 8.0
stiffness = 6e7
mass = 1e5
"""


@pytest.mark.parametrize("edit, message", [
    (("capacity = 1.5e6", "capacity = -1.5e6"), "bridge.abutment_keys.capacity"),
    (("fracture_displacement = 0.05", "fracture_displacement = 0.001"),
     "bridge.abutment_keys.fracture_displacement: the key yields at capacity/k"),
    (('direction = "transverse"', 'direction = "sideways"'), "bridge.direction"),
    (("[bridge]\n", "[bridge]\nabutment_gaps = [0.05, 0.05]\n"),
     "bridge.abutment_gaps: a key of the longitudinal model"),
    (("[bridge]\n", "[contact]\nlaw = \"linear-spring\"\nk = 1e9\n[bridge]\n"),
     "contact: a bridge across its axis has no [contact] table"),
    (('direction = "transverse"\n', ""), "bridge.abutment_keys: shear keys hold the decks "
                                         "across the axis"),
    (("mass = 1e5\n", "mass = 1e5\n[[bridge.joint]]\ngap = 0.02\n"),
     "bridge.joint[0].gap: a key of the longitudinal model"),
])
def test_bad_transverse_values_name_the_field(edit, message) -> None:
    text = BASE.replace(*edit)
    assert text != BASE
    with pytest.raises(ValueError) as info:
        parse_config(tomllib.loads(text))
    assert message in str(info.value), str(info.value)


def test_abutment_piles_from_the_model_file() -> None:
    """``abutment_piles`` along the axis: a ``…/piles`` contact behind each abutment's gap,
    3 × 40 kip/in by default (linear), or elastic–perfectly-plastic with a yield force a
    pile."""
    long = BASE.replace('direction = "transverse"\n', "").replace(
        "abutment_keys = { gap = 0.02, k = 5e8, capacity = 1.5e6, fracture_displacement = 0.05 }",
        "abutment_gaps = [0.05, 0.04]\nabutment_piles = { count = 3 }") + \
        '[contact]\nlaw = "linear-spring"\nk = 1e9\n'
    model = parse_config(tomllib.loads(long)).build().model
    assert [c.label for c in model.contacts] == ["A1-B1F1", "A1-B1F1/piles", "B1F1-A2",
                                                 "B1F1-A2/piles"]
    assert [c.gap for c in model.contacts] == [0.05, 0.05, 0.04, 0.04]
    piles = model.contacts[1].law
    assert type(piles).__name__ == "LinearSpring"
    assert piles.k == pytest.approx(3 * 40.0 * 4448.2216152605 / 0.0254, rel=1e-12)
    yielding = long.replace("count = 3", "count = 3, stiffness = 5e6, yield_force = 1.5e5")
    law = parse_config(tomllib.loads(yielding)).build().model.contacts[1].law
    assert (type(law).__name__, law.k, law.capacity, law.fracture_displacement) == (
        "ShearKey", 1.5e7, 4.5e5, None)


def test_bad_piles_and_a_bad_file_exit_2_in_one_line(tmp_path: Path, capsys) -> None:
    """``abutment_piles`` with no pile, and a key table's unknown key, from the command
    line: exit status 2, one line naming the field and value, nothing written."""
    long = BASE.replace('direction = "transverse"\n', "").replace(
        "abutment_keys = { gap = 0.02, k = 5e8, capacity = 1.5e6, fracture_displacement = 0.05 }",
        'abutment_gaps = [0.05, 0.05]\nabutment_piles = { count = 0 }') + \
        '[contact]\nlaw = "linear-spring"\nk = 1e9\n'
    with pytest.raises(ValueError, match=r"bridge.abutment_piles.count"):
        parse_config(tomllib.loads(long))
    bad = tmp_path / "bad.toml"
    bad.write_text(BASE.replace("capacity = 1.5e6", "capacity = 1.5e6, brittle = true"),
                   encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(bad), "--out", str(out)]) == 2
    err = [ln for ln in capsys.readouterr().err.splitlines() if ln.strip()]
    assert len(err) == 1 and "bridge.abutment_keys.brittle" in err[0], err
    assert "Traceback" not in err[0] and not out.exists()


def test_the_contact_figure_draws_the_keys_and_no_infinite_gap() -> None:
    """A transverse run's contact-force figure: one panel for the keys (every key there), no
    panel for the decks' joint (an infinite gap they never close); and no seat figure."""
    import matplotlib

    matplotlib.use("Agg")
    from pounding.ground_motion import el_centro
    from pounding.integrate import simulate
    from pounding.plot.registry import is_bridge_model
    from pounding.plot.response import plot_contact_forces

    model = _two_frames()
    res = simulate(model, el_centro().scaled(0.5), duration=2.0)
    fig = plot_contact_forces(res)
    titles = [ax.get_title(loc="left") for ax in fig.axes]
    assert not any("inf mm" in t for t in titles), titles
    keys = [t for t in titles if t.startswith("shear keys")]
    assert len(keys) == 1
    assert not is_bridge_model(model)


def test_a_broken_keys_impact_records_no_penetration_past_its_fracture() -> None:
    """A key's impact ends where it breaks off: its row's largest penetration is the fracture
    deformation (0.02 m), not how far the deck went on past the broken key (it was 0.05–0.09
    m), in the kernel's table and the reference's."""
    from pounding.ground_motion import el_centro
    from pounding.integrate import simulate
    from pounding.integrate.reference import simulate_reference

    model = _two_frames()
    record = el_centro().scaled(1.5).trimmed(4.0)
    for res in (simulate(model, record, duration=4.0),
                simulate_reference(model, record, duration=4.0)):
        broken = [k for k in res.shear_keys if k.failed]
        assert broken, "no key broke: the check would be empty"
        rows = res.impact_array
        assert rows.size and np.all(rows[:, 6] <= 0.02 + 1e-9), rows[:, 6].max()
