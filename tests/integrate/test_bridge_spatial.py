"""A bridge on spatially varying ground: each frame on its own ground, each abutment on its
own, cable restrainers across the joint. The seats' openings and closings are read with the
grounds' relative displacement: wherever a joint or backwall contact is closed, the seat's
closing (−opening) is its gap plus the contact's penetration, which the kernel computes from
the contact rows with the stations' displacements — an independent reading; the sweep's
columns agree; the energy balance closes with the grounds' work."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import el_centro
from pounding.ground_motion.spatial import wave_passage
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.result.bridge_seats import seat_openings
from pounding.structure.bridge import Abutment, Bearing, Bridge, BridgeFrame, Pier, Restrainer

KV = ContactSpec("kelvin-voigt", k=1.0e9, e=0.6)
CABLES = {"kind": "restrainer", "k": 2.0e7, "slack": 0.01, "yield_force": 6.0e5,
          "hardening": 0.02}


@pytest.fixture(scope="module")
def run():
    f1 = BridgeFrame(1.2e6, [Pier(9.0, 1.0e8, 1.2e5)], Bearing.elastomeric(4.0e7, 2.0e5))
    f2 = BridgeFrame(1.0e6, [Pier(9.0, 3.0e8, 1.0e5)], Bearing.elastomeric(1.5e8, 1.0e5))
    bridge = Bridge([f1, f2], [0.02], abutments=(Abutment(0.04), Abutment(0.04)),
                    restrainers=(Restrainer(0, CABLES),))
    model = PoundingModel.from_bridge(bridge, KV)
    # the frames' middles at 30 and 90 m, the abutments at 0 and 120 m; 300 m/s
    motion = wave_passage(el_centro().scaled(1.5).trimmed(6.0), [30.0, 90.0, 0.0, 120.0],
                          300.0).with_walls(["left", "right"])
    return simulate(model, motion, duration=6.0)


def test_seat_closings_are_the_contacts_gaps_plus_penetrations(run) -> None:
    res = run
    assert res.building_ground is not None and set(res.wall_ground) == {"left", "right"}
    names, openings = seat_openings(res)
    labels = [c.label for c in res.model.contacts]
    seats = {"A1": "A1-B1F1", "J1": "B1F1-B2F1", "A2": "B2F1-A2"}
    struck = 0
    for s, name in enumerate(names):
        c = labels.index(seats[name])
        pen = res.penetration[:, c]
        closed = res.contact_force[:, c] > 0.0
        struck += int(closed.any())
        if closed.any():
            gap = res.model.contacts[c].gap
            np.testing.assert_allclose(-openings[closed, s], gap + pen[closed], rtol=0,
                                       atol=1e-9)
    assert struck == 3  # (every seat's contact acted)
    # the grounds matter: the openings without them differ by more than a millimetre
    u = res.displacement[:, [0, 2]]
    assert np.max(np.abs(openings[:, 1] - (u[:, 1] - u[:, 0]))) > 1e-3
    assert res.energy_balance_error < 1e-8


def test_the_sweep_columns_read_the_same(run) -> None:
    from pounding.studies.sweep.bridge_measures import bridge_row

    row = bridge_row(run)
    names, openings = seat_openings(run)
    for s, name in enumerate(names):
        assert row[f"peak_opening_m_{name}"] == pytest.approx(max(openings[:, s].max(), 0.0),
                                                              rel=1e-12)
        # the closing, located between output steps, at least the sampled one
        assert row[f"peak_closing_m_{name}"] >= (-openings[:, s]).max() - 1e-12
        assert row[f"peak_closing_m_{name}"] < (-openings[:, s]).max() + 2e-3


def test_a_report_rebuilds_the_grounds_of_a_run_on_spatially_varying_ground(
        tmp_path) -> None:
    """The Result a report rebuilds from a run folder (for its figures) has the grounds'
    displacements again: its seats' peak openings are summary.json's (they were those of the
    decks relative to their own grounds: J1 99 mm against 171 mm)."""
    import json
    import subprocess
    import sys
    from pathlib import Path

    from pounding.example_files import example_path
    from pounding.report.run_figures import result_from
    from pounding.report.run_folder import read_run

    text = Path(example_path("bridge_two_frames.toml")).read_text()
    text = text.replace("duration = 12.0", "duration = 6.0")
    text += ("\n[spatial]\npositions = [36.0, 102.0]\n"
             "wall_positions = { left = 0.0, right = 132.0 }\napparent_velocity = 200.0\n")
    model_file = tmp_path / "b.toml"
    model_file.write_text(text)
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "pounding", "run", str(model_file), "--out",
                           str(out), "--no-figures"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    seats = {s["name"]: s for s in json.loads((out / "summary.json").read_text())["seats"]}
    rebuilt = result_from(read_run(out))
    assert rebuilt.building_ground is not None
    names, openings = seat_openings(rebuilt)
    for s, name in enumerate(names):
        assert max(openings[:, s].max(), 0.0) == pytest.approx(seats[name]["peak_opening_m"],
                                                               rel=1e-9, abs=1e-12)
