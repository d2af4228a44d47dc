"""Sweeps over a bridge's keys: each case is built with its own joint gap, restrainer and
abutment gap (not another case's model), an item of a list can be swept, and the row's
columns per joint, abutment and restrainer are those of the run, read independently."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding.config import RunConfig
from pounding.integrate import simulate
from pounding.studies.sweep import apply_overrides, load_results, parse_sweep, run_sweep
from pounding.studies.sweep.bridge_measures import bridge_row
from pounding.studies.sweep.builder import CaseBuilder

CABLE = {"kind": "restrainer", "k": 1.76e7, "slack": 0.0127, "yield_force": 1.76e6}


def bridge_base(restrainer: bool = True, duration: float = 3.0) -> dict:
    """Two one-span frames on one pier each, a 20 mm joint, 30 mm abutment gaps."""
    frame = {"spans": [30.0], "deck_mass": 4.5e5,
             "bearing": {"type": "elastomeric", "stiffness": 2.0e7, "damping": 1.0e5},
             "pier": [{"height": 8.0, "stiffness": 4.0e7, "mass": 5.0e4}]}
    frame2 = frame | {"pier": [{"height": 8.0, "stiffness": 1.5e8, "mass": 5.0e4}]}
    joint: dict = {"gap": 0.02}
    if restrainer:
        joint["restrainer"] = dict(CABLE)
    return {"name": "bridge", "record": {"bundled": "el_centro", "scale": 2.0,
                                         "duration": duration},
            "contact": {"law": "kelvin-voigt", "k": 1.0e9, "e": 0.6},
            "bridge": {"frame": [frame, frame2], "joint": [joint],
                       "abutment_gaps": [0.03, 0.03]}}


def _build(data: dict, tmp_path: Path):
    return RunConfig.model_validate(data, context={"base_dir": tmp_path}).build()


def test_each_case_is_built_with_its_own_joint_gap(tmp_path: Path) -> None:
    """Cases of a grid over a joint's gap and the record: a case whose values were all
    seen in earlier cases must not take an earlier case's model (the bridge's keys shape
    the model; before, they were taken for solver options and the model of the first case
    was reused for every gap)."""
    params = ("bridge.joint.0.gap", "bridge.joint.0.restrainer.slack",
              "bridge.abutment_gaps.1", "record.scale")
    builder = CaseBuilder(bridge_base(), tmp_path, params)
    for values in [(0.01, 0.01, 0.03, 1.0), (0.01, 0.01, 0.03, 2.0), (0.05, 0.02, 0.04, 1.0),
                   (0.05, 0.02, 0.04, 2.0), (0.01, 0.01, 0.03, 2.0)]:
        model = builder.build(values).model
        assert model.gaps == (values[0],)
        assert model.links[0].slack == values[1]
        assert [w.gap for w in model.walls] == [0.03, values[2]]


def test_a_wall_case_is_built_with_its_own_gap(tmp_path: Path) -> None:
    """The same for a moat wall's gap (``wall``: also a table of the model)."""
    base = {"record": {"bundled": "el_centro", "duration": 1.0},
            "building": [{"n_storeys": 1, "mass": 1e5, "period": 0.5}],
            "contact": {"law": "linear-spring", "k": 1e8},
            "wall": [{"side": "right", "height": 3.0, "gap": 0.05}]}
    builder = CaseBuilder(base, tmp_path, ("wall.0.gap", "record.scale"))
    for values in [(0.05, 1.0), (0.05, 2.0), (0.1, 1.0), (0.1, 2.0)]:
        assert builder.build(values).model.walls[0].gap == values[0]


def test_an_item_of_a_list_is_set() -> None:
    """``bridge.abutment_gaps.1`` sets that item (was a TypeError out of the sweep: a list
    indexed by a string); ``*`` sets every item."""
    base = bridge_base()
    one = apply_overrides(base, ["bridge.abutment_gaps.1"], [0.07])
    assert one["bridge"]["abutment_gaps"] == [0.03, 0.07]
    every = apply_overrides(base, ["bridge.abutment_gaps.*"], [0.01])
    assert every["bridge"]["abutment_gaps"] == [0.01, 0.01]
    assert base["bridge"]["abutment_gaps"] == [0.03, 0.03]  # the base left as it was
    # a pier's stiffness replaces its EI (and fixity, columns), a deck's mass its mass per m
    pier = {"height": 8.0, "EI": 3.1e9, "fixity": "fixed", "columns": 2, "mass": 5e4}
    base["bridge"]["frame"][0]["pier"] = [pier]
    base["bridge"]["frame"][0]["deck_mass_per_length"] = 1.5e4
    del base["bridge"]["frame"][0]["deck_mass"]
    data = apply_overrides(base, ["bridge.frame.0.pier.0.stiffness",
                                  "bridge.frame.0.deck_mass"], [5e7, 4e5])
    assert data["bridge"]["frame"][0]["pier"][0] == {"height": 8.0, "mass": 5e4,
                                                     "stiffness": 5e7}
    assert data["bridge"]["frame"][0]["deck_mass"] == 4e5
    assert "deck_mass_per_length" not in data["bridge"]["frame"][0]


def test_bridge_columns_are_those_of_the_run(tmp_path: Path) -> None:
    """Per seat, the impacts and peak force of its contacts, its opening and closing read
    off the decks' displacements, and the restrainer's peak force read off its force."""
    model, motion, solver = _build(bridge_base(), tmp_path)
    res = simulate(model, motion, **solver)
    row = bridge_row(res)
    labels = [c.label for c in model.contacts]
    seat_of = {"B1F1-B2F1": "J1", "A1-B1F1": "A1", "B2F1-A2": "A2"}
    assert sorted(seat_of) == sorted(labels)
    struck = res.impact_array[:, 0].astype(int)
    for label, seat in seat_of.items():
        k = labels.index(label)
        assert row[f"n_impacts_{seat}"] == int(np.sum(struck == k))
        assert row[f"peak_impact_force_N_{seat}"] == res.peak_contact_force[k]
    u1, u2 = res.displacement[:, 0], res.displacement[:, 2]  # the decks: B1F1, B2F1
    assert [model.dof_labels()[i] for i in (0, 2)] == ["B1F1", "B2F1"]
    for seat, opening, closing in (("A1", u1, -u1), ("J1", u2 - u1, u1 - u2),
                                   ("A2", -u2, u2)):
        assert row[f"peak_opening_m_{seat}"] == max(opening.max(), 0.0)
        # located between output steps: at least the sampled peak, not much more
        assert 0.0 <= row[f"peak_closing_m_{seat}"] - closing.max() < 1e-5
    assert row["n_impacts_J1"] > 0 and row["peak_opening_m_J1"] > CABLE["slack"]
    assert row["peak_force_N_R1"] == np.abs(res.link_force[:, 0]).max() > 0


def test_the_closing_without_contact_is_the_gap_the_joint_needs(tmp_path: Path) -> None:
    """A run whose joint is never reached (a gap of 10 m) closes the joint by g_n; with
    the gap 1 % above g_n the decks never meet there, 1 % below they do."""
    base = bridge_base(restrainer=True)
    far = apply_overrides(base, ["bridge.joint.0.gap"], [10.0])
    model, motion, solver = _build(far, tmp_path)
    needed = bridge_row(simulate(model, motion, **solver))["peak_closing_m_J1"]
    assert 0.005 < needed < 1.0
    for factor, pounds in ((1.01, False), (0.99, True)):
        data = apply_overrides(base, ["bridge.joint.0.gap"], [factor * needed])
        model, motion, solver = _build(data, tmp_path)
        assert (bridge_row(simulate(model, motion, **solver))["n_impacts_J1"] > 0) is pounds


@pytest.mark.filterwarnings("ignore::DeprecationWarning")
def test_a_sweep_over_bridge_keys_writes_the_bridge_columns(tmp_path: Path) -> None:
    """A sweep (in this process) over the joint gap and the restrainer's slack: a row per
    case with its own values, the bridge's columns typed and in order."""
    sweep = parse_sweep({"base": bridge_base(duration=2.0),
                         "grid": {"bridge.joint.0.gap": [0.005, 0.05],
                                  "bridge.joint.0.restrainer.slack": [0.0, 0.03]}},
                        base_dir=tmp_path)
    out = run_sweep(sweep, tmp_path / "out", scheduler="synchronous")
    df = load_results(out.results)
    assert (df["status"] == "ok").all()
    bridge = [c for c in df.columns if c.endswith(("_A1", "_J1", "_A2", "_R1"))]
    assert bridge == ["n_impacts_A1", "n_impacts_J1", "n_impacts_A2",
                      "peak_impact_force_N_A1", "peak_impact_force_N_J1",
                      "peak_impact_force_N_A2", "peak_opening_m_A1", "peak_opening_m_J1",
                      "peak_opening_m_A2", "peak_closing_m_A1", "peak_closing_m_J1",
                      "peak_closing_m_A2", "peak_force_N_R1"]
    assert df.columns[-1] == "wall_time_s" and str(df["n_impacts_J1"].dtype) == "int64"
    # each case its own model: the narrow joint pounds more, the slack cable pulls less
    narrow, wide = df[df["bridge.joint.0.gap"] == 0.005], df[df["bridge.joint.0.gap"] == 0.05]
    assert narrow["n_impacts_J1"].sum() > wide["n_impacts_J1"].sum()
    taut = df[df["bridge.joint.0.restrainer.slack"] == 0.0]["peak_force_N_R1"].to_numpy()
    slack = df[df["bridge.joint.0.restrainer.slack"] == 0.03]["peak_force_N_R1"].to_numpy()
    assert np.all(taut != slack)
