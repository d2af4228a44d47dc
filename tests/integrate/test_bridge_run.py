"""Bridges in time: a linear and a yielding two-frame bridge against the SciPy reference
and their energy balance, the piers' and bearings' outputs, and the ``[bridge]`` section of
a model file (the example runs; bad values are refused in one line, exit 2)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pounding.config.load import load_config, parse_config
from pounding.contact.spec import ContactSpec
from pounding.example_files import example_path
from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import PoundingModel
from pounding.structure.bridge import Abutment, Bearing, Bridge, BridgeFrame, Pier

KV = ContactSpec("kelvin-voigt", k=1.0e9, e=0.6)


def _bridge(pier_law=None, slider: bool = False) -> PoundingModel:
    f1 = BridgeFrame(2.0e6, [Pier(8.0, 5.0e7, 1.0e5, pier_law)],
                     Bearing.elastomeric(2.0e7, 1.0e5))
    b2 = Bearing.sliding(0.08, 1.5e7) if slider else Bearing.elastomeric(6.0e7)
    f2 = BridgeFrame(3.0e6, [Pier(8.0, 8.0e7, 1.5e5), Pier(6.0, 1.2e8, 1.0e5)], b2,
                     deck_elevation=8.0)
    return PoundingModel.from_bridge(
        Bridge([f1, f2], [0.015], abutments=(Abutment(0.03), Abutment(0.03))), KV)


def _compare(model: PoundingModel, scale: float, duration: float):
    record = el_centro().scaled(scale)
    res = simulate(model, record, duration=duration)
    ref = simulate_reference(model, record, duration=duration)
    return res, ref


@pytest.mark.slow  # a reference comparison (pyproject.toml: markers)
def test_linear_two_frame_bridge_matches_the_reference() -> None:
    """Two linear frames (elastomeric bearings) pounding across their joint and on the
    abutments: kernel and SciPy reference agree to 1e-6 of the peak displacement, impact
    for impact, and both balance energy to 1e-8."""
    res, ref = _compare(_bridge(), 1.5, 3.0)
    assert res.n_impacts == ref.n_impacts > 0
    assert set(np.flatnonzero(res.impacts_per_contact)) >= {0}  # (the joint is struck)
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * scale
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-5)
    assert res.energy_balance_error < 1e-8 and ref.energy_balance_error < 1e-8


@pytest.mark.slow
def test_yielding_pier_and_sliders_match_the_reference() -> None:
    """A bilinear pier (it yields) and sliding bearings (they slide), each with its own
    law in one model: kernel and reference agree; the pier's force never passes its
    bilinear envelope and the sliders' never pass μW."""
    law = Bilinear(yield_force=1.0e6, hardening=0.05)
    res, ref = _compare(_bridge(law, slider=True), 1.5, 3.0)
    assert res.n_impacts == ref.n_impacts > 0
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * scale
    np.testing.assert_allclose(res.element_force, ref.element_force, atol=2e-5 * 1.2e6)
    pier, sliders = res.element_force[:, 0], res.element_force[:, 1:]
    d = res.element_deformation[:, 0]
    assert np.abs(d).max() > 1.0e6 / 5.0e7  # (past its yield drift)
    assert np.all(np.abs(pier) <= 1.0e6 + 0.05 * 5.0e7 * np.abs(d) + 1e-6)
    assert np.abs(sliders).max() <= 0.08 * 1.5e7 * (1 + 1e-9)
    assert res.energy_balance_error < 1e-8


def test_bridge_elements_report_every_pier_and_bearing() -> None:
    """Result.bridge_elements lists the linear elements too: a linear pier's shear is
    k × its drift, a bearing's displacement the deck less its cap; the yielding pier's
    force its law's."""
    model = _bridge(Bilinear(yield_force=1.0e6, hardening=0.05))
    res = simulate(model, el_centro().scaled(1.5), duration=2.0)
    table = {e.label: e for e in res.bridge_elements}
    assert list(table) == ["B1P1", "B1Br1", "B2P1", "B2P2", "B2Br1", "B2Br2"]
    u = res.displacement
    assert table["B2P2"].peak_deformation == pytest.approx(np.abs(u[:, 4]).max(), rel=1e-12)
    assert table["B2P2"].peak_force == pytest.approx(1.2e8 * np.abs(u[:, 4]).max(), rel=1e-12)
    assert table["B2Br1"].peak_deformation == pytest.approx(np.abs(u[:, 2] - u[:, 3]).max())
    assert table["B1P1"].peak_force == pytest.approx(np.abs(res.element_force[:, 0]).max())
    assert table["B2P2"].height == 6.0 and table["B2Br1"].kind == "elastomeric"


def test_example_bridge_file_builds_the_bridge() -> None:
    """examples/bridge_two_frames.toml: two frames, one joint, two abutments; the pier of
    frame 1 from 2 × 12 EI/H³ and its bilinear law, frame 2's sliders carrying half the
    deck's weight each."""
    model = load_config(example_path("bridge_two_frames.toml")).build().model
    assert [c.label for c in model.contacts] == ["B1F1-B2F1", "A1-B1F1", "B2F1-A2"]
    f1 = model.buildings[0]
    assert f1.piers[0].stiffness == pytest.approx(2 * 12 * 3.1e9 / 9.0**3)
    assert f1.deck_mass == pytest.approx(72.0 * 1.7e4)
    assert model.element_labels() == ["B1P1", "B2Br1"]
    assert model.element_rows[1][1].params[1] == pytest.approx(0.06 * 60.0 * 1.7e4 * 9.80665)


def test_a_bridge_files_copy_names_no_floor_to_column() -> None:
    """The copy a run writes (model.toml) leaves out floor_to_column, which a bridge does not
    read (its contacts are deck to deck), and builds the same model."""
    cfg = load_config(example_path("bridge_two_frames.toml"))
    text = cfg.to_toml()
    assert "floor_to_column" not in text
    again = parse_config(__import__("tomllib").loads(text), where="model.toml").build().model
    assert [c.label for c in again.contacts] == ["B1F1-B2F1", "A1-B1F1", "B2F1-A2"]


BASE = """
[record]
bundled = "el_centro"
[contact]
law = "kelvin-voigt"
k = 1e9
e = 0.6
[bridge]
abutment_gaps = [0.05, 0.05]
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
    (("stiffness = 6e7", "stiffness = -6e7"), "bridge.frame[0].pier[0].stiffness"),
    (("stiffness = 6e7", "EI = 3e9"), "bridge.frame[0].pier[0].fixity: required with EI"),
    (('type = "elastomeric", stiffness = 3e7', 'type = "sliding", stiffness = 3e7'),
     "bridge.frame[0].bearing.stiffness: not a constant of a sliding bearing"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05]"), "bridge.abutment_gaps"),
    (("e = 0.6", "e = 0.6\ngap = 0.02"), "contact.gap: the gaps of a bridge"),
    (("deck_mass_per_length = 1.5e4", "deck_mass = 1e6\ndeck_mass_per_length = 1.5e4"),
     "bridge.frame[0].deck_mass_per_length: give"),
])
def test_bad_bridge_values_name_the_field(edit, message) -> None:
    import tomllib

    text = BASE.replace(*edit)
    assert text != BASE
    with pytest.raises(ValueError) as info:
        parse_config(tomllib.loads(text))
    assert message in str(info.value), str(info.value)


def test_bad_bridge_file_exits_2_in_one_line(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text(BASE + "\n[[bridge.joint]]\ngap = 0.02\n", encoding="utf-8")
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "pounding", "run", str(bad), "--out", str(out)],
                          capture_output=True, text=True, check=False, env={**__import__("os").environ,
                                                               "POUNDING_SKIP_BROWSER": "1"})
    assert done.returncode == 2
    lines = [ln for ln in done.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "bridge.joint" in lines[0] and "Traceback" not in done.stderr
    assert not out.exists()


TWO_FRAMES = BASE.replace("[bridge]\n", "[bridge]\nabutment_law = { law = \"abutment\", "
                          "backbone = \"caltrans\", backwall_width = 12.0, "
                          "backwall_height = 2.0 }\n") + """
[[bridge.frame]]
spans = [30.0]
deck_mass_per_length = 1.5e4
bearing = { type = "elastomeric", stiffness = 1e7 }
[[bridge.frame.pier]]
height = 8.0
stiffness = 2e7
mass = 1e5
[[bridge.joint]]
gap = 0.02
restrainer = { kind = "restrainer", k = 1.76e7, slack = 0.0127, yield_force = 1.76e6 }
"""


def test_a_bridge_with_cable_restrainers_and_backfill_abutments() -> None:
    """`[bridge]` with a cable restrainer across the joint and the Caltrans backfill at both
    abutments: the joint's link is the tension-only restrainer, the backwalls' contacts use
    the abutment law (its stiffness K_abut = K_i w h/h_ref written out here: 50 kip/in/ft
    = 2.8728e7 N/m per m, h_ref = 5.5 ft), and a run balances its energy."""
    import tomllib

    from pounding.devices.laws import RESTRAINER

    model, motion, _ = parse_config(tomllib.loads(TWO_FRAMES)).build()
    (link,) = model.links
    assert link.kind == "restrainer" and link.code == RESTRAINER
    walls = [c for c in model.contacts if c.label.startswith("A") or c.label.endswith("A2")]
    assert len(walls) == 2
    k_abut = 50 * 4448.2216152605 / 0.0254 / 0.3048 * 12.0 * 2.0 / (5.5 * 0.3048)
    for c in walls:
        assert type(c.law).__name__ == "AbutmentBackfill"
        assert c.law.K == pytest.approx(k_abut, rel=1e-6)
    res = simulate(model, motion.scaled(2.0), duration=6.0, dt=0.005)
    assert res.peak_contact_force[[c.index for c in walls]].max() > 0  # (backfill reached)
    assert res.link_peak_force.max() > 0  # (the cables went taut)
    # (1.2e-8 measured: the backfill's re-contact at its set is not a located event)
    assert res.energy_balance_error < 1e-7
    bad = TWO_FRAMES.replace("slack = 0.0127", "slack = 0.0127, c = 1e5")
    with pytest.raises(ValueError, match="bridge.joint\\[0\\].restrainer.c: a cable restrainer"):
        parse_config(tomllib.loads(bad))


def test_restrainers_keep_a_narrow_seat_from_unseating() -> None:
    """The two-frame bridge under El Centro × 2: without restrainers the joint opens by
    about 150 mm and a 100 mm seat is lost; with the cables it opens about 73 mm and the deck
    stays seated; at AASHTO LRFD's minimum support length (zone 4: 150 % of N with L the
    frame's 30 m deck, H its 8 m pier) it stays seated either way. The openings are the
    decks' relative displacements, written out here."""
    import tomllib

    from pounding.result.bridge_seats import seat_checks, seat_openings
    from pounding.structure.seat_width import aashto_lrfd_required_support_length

    need = aashto_lrfd_required_support_length(30.0, 8.0, 0.0, 4, 0.4)
    assert need == pytest.approx(1.5 * (0.2032 + 30.0 / 600 + 8.0 / 150), rel=1e-12)
    margins = {}
    for label, text in (("with", TWO_FRAMES),
                        ("without", TWO_FRAMES.replace("restrainer = {", "# restrainer = {"))):
        model, motion, _ = parse_config(tomllib.loads(text)).build()
        res = simulate(model, motion.scaled(2.0), duration=20.0, dt=0.005)
        names, openings = seat_openings(res)
        u = res.displacement
        decks = [0, model.system.offsets[1]]
        np.testing.assert_array_equal(openings[:, 1], u[:, decks[1]] - u[:, decks[0]])
        assert names == ["A1", "J1", "A2"]
        narrow = seat_checks(res, [None, 0.10, None], [None, need, None])
        at_code = seat_checks(res, [need] * 3, [need] * 3)
        margins[label] = narrow[0].margin_m
        assert narrow[0].seat == "J1" and not narrow[0].meets_minimum
        assert all(c.meets_minimum and not c.unseated for c in at_code)
    assert margins["without"] < -0.02 and margins["with"] > 0.02


SEATED = (TWO_FRAMES.replace('bundled = "el_centro"', 'bundled = "el_centro"\nscale = 2.0')
          .replace("[bridge]\n", "[bridge]\nabutment_seat_widths = [0.5, 0.5]\nseat_clause = "
                   "{ clause = \"aashto-lrfd\", seismic_zone = 4 }\n")
          .replace("[[bridge.joint]]\ngap = 0.02\n", "[[bridge.joint]]\ngap = 0.02\n"
                   "seat_width = 0.10\n")
          + "[solver]\nduration = 20.0\ndt = 0.005\n")
"""The two-frame bridge of the worked example with seats: 0.5 m at the abutments, 0.10 m at
the joint (narrower than AASHTO LRFD's zone-4 minimum), under El Centro × 2 for 20 s."""


def test_a_deck_unseats_without_restrainers_and_stays_seated_with_them(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The seats given in the model file, end to end: without restrainers `pounding run`
    reports the joint's seat lost (negative margin) in summary.json and in a plain line;
    with the cables the same seat keeps a positive margin (Result.seats). The peak opening
    is the decks' relative displacement written out here, the margin the width less it,
    the minimum AASHTO's 150 % of N with L = 30 m and H = 8 m."""
    import json
    import tomllib

    from pounding.cli import main
    from pounding.result import SEAT_FIELDS

    need = 1.5 * (0.2032 + 30.0 / 600.0 + 8.0 / 150.0)  # 0.4598 m at every seat
    without = SEATED.replace("restrainer = {", "# restrainer = {")
    model_file = tmp_path / "bridge.toml"
    model_file.write_text(without, encoding="utf-8")
    capsys.readouterr()
    assert main(["run", str(model_file), "--out", str(tmp_path / "out"), "--no-figures"]) == 0
    printed = " ".join(capsys.readouterr().out.split())
    seats = json.loads((tmp_path / "out" / "summary.json").read_text())["seats"]
    assert [s["name"] for s in seats] == ["A1", "J1", "A2"]
    assert all(tuple(s) == SEAT_FIELDS for s in seats)
    j1 = seats[1]
    # the same run in Python: the joint's opening is u(B2F1) - u(B1F1)
    model, motion, solver = parse_config(tomllib.loads(without)).build()
    res = simulate(model, motion, **solver)
    u = res.displacement
    opening = u[:, model.system.offsets[1]] - u[:, 0]
    assert j1["peak_opening_m"] == pytest.approx(opening.max(), rel=1e-9)
    assert j1["peak_opening_time_s"] == pytest.approx(res.time[np.argmax(opening)])
    assert j1["margin_m"] == pytest.approx(0.10 - opening.max(), rel=1e-9)
    assert j1["margin_m"] < -0.02 and j1["unseated"] is True
    assert j1["required_m"] == pytest.approx(need, rel=1e-12)
    assert j1["meets_minimum"] is False
    assert (j1["deck_length_m"], j1["pier_height_m"]) == (30.0, 8.0)
    assert j1["clause"].startswith("AASHTO LRFD Art. 4.7.4.4")
    a1 = seats[0]
    assert a1["peak_opening_m"] == pytest.approx(max(u[:, 0].max(), 0.0), rel=1e-9)
    assert not a1["unseated"] and a1["meets_minimum"] is True
    assert "Seats (peak openings at the output steps)" in printed
    assert "Unseated at seat J1 (between B1 and B2)" in printed
    assert "Seat J1 (between B1 and B2) is 100.0 mm wide, narrower than the 459.8 mm" in printed
    assert "Unseated at seat A1" not in printed
    assert [c.margin_m for c in res.seats] == pytest.approx([s["margin_m"] for s in seats])

    model, motion, solver = parse_config(tomllib.loads(SEATED)).build()
    kept = simulate(model, motion, **solver).seats
    assert kept[1].seat == "J1" and not kept[1].unseated and kept[1].margin_m > 0.02
    assert kept[1].peak_relative_displacement_m < j1["peak_opening_m"] - 0.05


def test_seats_appear_only_where_the_model_gives_widths() -> None:
    """No `seats` in the summary of a bridge without seat widths, nor of buildings; a seat
    without a clause has null requirement fields."""
    import tomllib

    model, motion, _ = parse_config(tomllib.loads(BASE)).build()
    res = simulate(model, motion, duration=1.0, dt=0.01)
    assert "seats" not in res.summary() and res.seats == []
    plain = BASE.replace("abutment_gaps = [0.05, 0.05]",
                         "abutment_gaps = [0.05, 0.05]\nabutment_seat_widths = [\"none\", 0.4]")
    model, motion, _ = parse_config(tomllib.loads(plain)).build()
    (a2,) = simulate(model, motion, duration=1.0, dt=0.01).summary()["seats"]
    assert a2["name"] == "A2" and a2["width_m"] == 0.4
    assert a2["required_m"] is a2["clause"] is a2["meets_minimum"] is None
    assert a2["margin_m"] == pytest.approx(0.4 - a2["peak_opening_m"])
    buildings = load_config(example_path("seed_sdof_pair.toml")).build()
    assert "seats" not in simulate(buildings.model, buildings.motion, duration=0.5).summary()


@pytest.mark.parametrize("edit, message", [
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, \"none\"]\n"
      "abutment_seat_widths = [0.5, 0.5]"),
     'bridge.abutment_seat_widths[1]: a seat 0.5 m wide at an end with no abutment'),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, -0.5]"), "bridge.abutment_seat_widths[1]"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "seat_clause = { clause = \"aashto-lrfd\", seismic_zone = 4 }"),
     "bridge.seat_clause: no seat has a width to check against it"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"aashto-lrfd\", "
      "seismic_zone = 1 }"), "bridge.seat_clause.acceleration_coefficient: required in "
                             "seismic zone 1"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"aashto-lrfd\", "
      "seismic_zone = 5 }"), "bridge.seat_clause.seismic_zone"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"aashto-lrfd\", "
      "seismic_zone = 4, skew = 90.0 }"), "bridge.seat_clause.skew"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"aashto-lrfd\", "
      "seismic_zone = 4, name = \"x\" }"),
     'bridge.seat_clause.name: not a key of clause = "aashto-lrfd"'),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"given\", name = "
      "\"Caltrans SDC\", required = [0.76] }"),
     "bridge.seat_clause.required: need 2 value(s), one per seat"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"given\", name = "
      "\"Caltrans SDC\", required = [0.76, \"none\"] }"),
     "bridge.seat_clause.required[1]: the seat has a width (0.5 m) but \"none\" here"),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"given\", "
      "required = [0.76, 0.76] }"), "bridge.seat_clause.name: required with clause = \"given\""),
    (("abutment_gaps = [0.05, 0.05]", "abutment_gaps = [0.05, 0.05]\n"
      "abutment_seat_widths = [0.5, 0.5]\nseat_clause = { clause = \"caltrans-sdc\" }"),
     "bridge.seat_clause.clause"),
])
def test_bad_seat_values_name_the_field(edit, message) -> None:
    import tomllib

    text = BASE.replace(*edit)
    assert text != BASE
    with pytest.raises(ValueError) as info:
        parse_config(tomllib.loads(text))
    assert message in str(info.value), str(info.value)


def test_a_bad_joint_seat_width_exits_2_in_one_line(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    from pounding.cli import main

    bad = tmp_path / "bad.toml"
    bad.write_text(TWO_FRAMES.replace("gap = 0.02\n", "gap = 0.02\nseat_width = -0.3\n"),
                   encoding="utf-8")
    capsys.readouterr()
    code = main(["run", str(bad), "--out", str(tmp_path / "out"), "--no-figures"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith("error: ") and "bridge.joint[0].seat_width" in err[0]
    assert "-0.3" in err[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]
