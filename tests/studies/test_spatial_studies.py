"""Spatially varying ground motion in model files and studies: ``[spatial]`` builds the
motions it says, a sweep over the apparent velocity is the runs it stands for, and the gap
study's critical gap (each building alone, plus the grounds' relative displacement) is the
gap at which the coupled run just stops pounding."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from pounding.config import parse_config
from pounding.contact.spec import ContactSpec
from pounding.ground_motion import el_centro
from pounding.ground_motion.spatial import SpatialMotion, wave_passage
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.studies.gap import critical_gaps


def pair() -> dict[str, Any]:
    return {
        "name": "wave passage",
        "record": {"bundled": "el_centro"},
        "building": [{"mass": 2e5, "period": 0.5, "height": 3.0},
                     {"mass": 3e5, "period": 1.0, "height": 3.0}],
        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65, "gap": 0.02},
        "spatial": {"positions": [0.0, 30.0], "apparent_velocity": 300.0},
    }


def test_spatial_table_builds_the_motions() -> None:
    _, motion, _ = parse_config(pair(), where="m.toml").build()
    assert isinstance(motion, SpatialMotion) and motion.delays == pytest.approx((0.0, 0.1))
    ec = el_centro()
    assert np.array_equal(motion.records[1].accel[10: 10 + ec.npts], ec.accel)
    data = pair()
    data["spatial"] = {"positions": [0.0, 30.0], "coherency": "luco-wong", "beta": 3e-4,
                       "seed": 5}
    _, m1, _ = parse_config(data, where="m.toml").build()
    _, m2, _ = parse_config(data, where="m.toml").build()
    assert np.array_equal(m1.records[1].accel, m2.records[1].accel)  # seeded
    assert np.array_equal(m1.records[0].accel, ec.accel)  # the record under building 1


@pytest.mark.parametrize("change, expected", [
    ({"positions": [0.0], "apparent_velocity": 300.0},
     "spatial.positions: need 2 value(s), one per building"),
    ({"positions": [0.0, 30.0]}, "spatial.apparent_velocity: required with coherency = "
                                 "\"none\""),
    ({"positions": [0.0, 30.0], "apparent_velocity": 0.0}, "spatial.apparent_velocity: must "
                                                           "not be 0 m/s"),
    ({"positions": [0.0, 30.0], "apparent_velocity": 300.0, "beta": 1e-4},
     "spatial.beta: only for coherency = \"luco-wong\""),
    ({"positions": [0.0, 30.0], "coherency": "abrahamson"}, "spatial.coherency"),
    ({"positions": [0.0, 30.0], "coherency": "luco-wong", "recorded_at": 2},
     "spatial.recorded_at: must be a building index in [0, 1] (got 2)"),
])
def test_bad_spatial_tables_are_one_line(change: dict[str, Any], expected: str) -> None:
    data = copy.deepcopy(pair())
    data["spatial"] = change
    with pytest.raises(ValueError) as info:
        parse_config(data, where="m.toml").build()
    assert expected in str(info.value) and "\n" not in str(info.value)


def test_a_sweep_over_the_apparent_velocity_is_its_runs(tmp_path: Path) -> None:
    """The sweep's cases share parts (the model once, the motion per velocity and scale):
    each case's result equals the same model file run alone."""
    import pandas as pd

    from pounding.config.toml import dump_toml
    from pounding.studies.sweep import run_sweep

    base = tmp_path / "wp.toml"
    base.write_text(dump_toml(pair()), encoding="utf-8")
    sweep = tmp_path / "sw.toml"
    sweep.write_text('name = "sw"\nbase = "wp.toml"\n[grid]\n'
                     '"spatial.apparent_velocity" = [100.0, 1000.0]\n'
                     '"record.scale" = [0.5, 1.0]\n', encoding="utf-8")
    res = run_sweep(sweep, out=tmp_path / "out", scheduler="synchronous")
    table = pd.read_parquet(res.results)
    assert res.n_errors == 0 and len(table) == 4
    for v, s, n in zip(table["spatial.apparent_velocity"], table["record.scale"],
                       table["n_impacts"]):
        data = pair()
        data["spatial"]["apparent_velocity"] = float(v)
        data["record"]["scale"] = float(s)
        model, motion, solver = parse_config(data, where="m.toml").build()
        assert simulate(model, motion, **solver).n_impacts == n


def test_the_critical_gap_includes_the_grounds_relative_displacement() -> None:
    """The gap study's critical gap under wave passage: the coupled run at 1.001 × that gap
    does not pound, at 0.99 × it does; the critical gap differs from the uniform one."""
    ec = el_centro().trimmed(12.0)
    a, b = ShearBuilding.sdof(2e5, period=0.5), ShearBuilding.sdof(3e5, period=1.0)
    spec = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
    model = PoundingModel([a, b], [0.02], spec)
    w = wave_passage(ec, [0.0, 30.0], 150.0)  # τ = 0.2 s
    crit = float(critical_gaps(model, w, dt=0.005).critical[0, 0])
    uniform = float(critical_gaps(model, ec, dt=0.005).critical[0, 0])
    assert abs(crit - uniform) > 0.05 * uniform
    above = simulate(PoundingModel([a, b], [1.001 * crit], spec), w, dt=0.005, duration=12.0)
    below = simulate(PoundingModel([a, b], [0.99 * crit], spec), w, dt=0.005, duration=12.0)
    assert above.n_impacts == 0 and below.n_impacts > 0


def test_each_building_its_own_record_scaled_with_the_first() -> None:
    """``records``: building 2 on its own record, multiplied by the factor that [record]'s
    pga_g gives building 1's."""
    data = pair()
    data["record"] = {"bundled": "el_centro", "pga_g": 0.5}
    data["spatial"] = {"records": [{"bundled": "el_centro", "duration": 20.0}]}
    _, motion, _ = parse_config(data, where="m.toml").build()
    ec = el_centro()
    factor = 0.5 / ec.pga_g
    assert motion.records[0].pga_g == pytest.approx(0.5, rel=1e-12)
    n = int(round(20.0 / ec.dt)) + 1
    assert np.allclose(motion.records[1].accel[:n], factor * ec.accel[:n], rtol=1e-14)
    assert not np.any(motion.records[1].accel[n:])  # (continued with zeros)
    for change, expected in (
            ({"records": [{"bundled": "el_centro"}, {"bundled": "el_centro"}]},
             "spatial.records: need 1 record(s), one for each building after the first"),
            ({"records": [{"bundled": "el_centro", "scale": 2.0}]},
             "spatial.records[0].scale: not here"),
            ({"records": [{"bundled": "el_centro"}], "positions": [0.0, 1.0]},
             "spatial.positions: not with records")):
        bad = pair()
        bad["spatial"] = change
        with pytest.raises(ValueError) as info:
            parse_config(bad, where="m.toml").build()
        assert expected in str(info.value), str(info.value)


def test_a_link_between_buildings_on_different_grounds_in_the_file() -> None:
    """A link across the pair under wave passage builds (no longer refused) and its
    elongation in the run includes the grounds' offset."""
    data = pair()
    data["device"] = [{"type": "viscous", "floors": ["B1F1", "B2F1"], "c": 1e6}]
    model, motion, kw = parse_config(data, where="m.toml").build()
    res = simulate(model, motion.trimmed(3.0), duration=3.0)
    assert res.link_ground is not None
    rel = res.displacement[:, 1] - res.displacement[:, 0]
    assert np.max(np.abs(res.link_displacement[:, 0] - rel)) > 1e-4  # (the grounds moved)


def walled() -> dict[str, Any]:
    """One building between two moat walls (a deck between abutments), each wall 40 m from
    the building along the row."""
    return {
        "name": "walls on their grounds",
        "record": {"bundled": "el_centro", "duration": 12.0},
        "building": [{"mass": 2e5, "period": 0.5, "height": 3.0}],
        "wall": [{"height": 3.0, "gap": 0.02, "side": "left"},
                 {"height": 3.0, "gap": 0.02, "side": "right"}],
        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65},
        "spatial": {"positions": [40.0], "apparent_velocity": 200.0,
                    "wall_positions": {"left": 0.0, "right": 80.0}},
    }


def test_walls_given_their_own_grounds_in_the_file() -> None:
    """``wall_positions``: the walls' records are the record delayed by their own travel
    times (the waves reach the left wall first: 0, 0.2 s the building, 0.4 s the right
    wall); a side without a wall, a side that is not one, and wall_positions with records are
    refused in one line naming the key."""
    model, motion, _ = parse_config(walled(), where="m.toml").build()
    assert isinstance(motion, SpatialMotion)
    assert motion.delays == pytest.approx((0.2,))
    assert dict(motion.wall_delays) == pytest.approx({"left": 0.0, "right": 0.4})
    ec = el_centro().trimmed(12.0)
    assert np.array_equal(motion.walls["left"].accel[: ec.npts], ec.accel)
    assert np.array_equal(motion.records[0].accel[20: 20 + ec.npts], ec.accel)
    assert motion.wall_stations() == {"left": 1, "right": 2}
    # or each wall its own record, scaled with the row's
    data = {**walled(), "record": {"bundled": "el_centro", "pga_g": 0.5}}
    data["spatial"] = {"records": [], "wall_records": {"right": {"bundled": "el_centro",
                                                                 "duration": 10.0}}}
    data["building"] = walled()["building"] * 2
    data["contact"] = {**walled()["contact"], "gap": 0.02}
    data["spatial"]["records"] = [{"bundled": "el_centro"}]
    _, motion, _ = parse_config(data, where="m.toml").build()
    factor = 0.5 / el_centro().pga_g
    n = int(round(10.0 / ec.dt)) + 1
    assert list(motion.walls) == ["right"]
    assert np.allclose(motion.walls["right"].accel[:n], factor * el_centro().accel[:n],
                       rtol=1e-14)
    for change, expected in (
            ({"wall": walled()["wall"][:1]},
             "spatial.wall_positions.right: the row has no wall on its right"),
            ({"spatial": {**walled()["spatial"], "wall_positions": {"top": 1.0}}},
             "spatial.wall_positions.top: a wall's side is left or right"),
            ({"building": walled()["building"] * 2, "contact": {**walled()["contact"], "gap": 0.02},
              "spatial": {"records": [{"bundled": "el_centro"}],
                          "wall_positions": {"left": 0.0}}},
             "spatial.wall_positions: with positions only")):
        bad = {**walled(), **change}
        with pytest.raises(ValueError) as info:
            parse_config(bad, where="m.toml").build()
        assert expected in str(info.value), str(info.value)


def test_the_critical_gap_to_a_wall_on_its_own_ground() -> None:
    """The gap study under walls on their own grounds: the critical gap to each wall adds
    the wall's ground to the building's; the coupled run with both gaps at 1.001 × theirs
    does not pound, with the left one at 0.99 × it pounds the left wall."""
    model, motion, _ = parse_config(walled(), where="m.toml").build()
    study = critical_gaps(model, motion, dt=0.005)
    crit = {name: float(v) for name, v in zip(study.gap_names, study.critical[0])}
    uniform = critical_gaps(model, motion.records[0], dt=0.005)
    assert abs(crit["W-B1"] - float(uniform.critical[0, 0])) > 0.05 * crit["W-B1"]
    a = ShearBuilding.sdof(2e5, period=0.5, height=3.0)
    spec = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)

    def run(left: float, right: float) -> Any:
        from pounding.structure.wall import MoatWall
        walls = [MoatWall(height=3.0, gap=left, side="left"),
                 MoatWall(height=3.0, gap=right, side="right")]
        return simulate(PoundingModel([a], [], spec, walls=walls), motion, dt=0.005,
                        duration=12.0)

    assert run(1.001 * crit["W-B1"], 1.001 * crit["B1-W"]).n_impacts == 0
    below = run(0.99 * crit["W-B1"], 1.001 * crit["B1-W"])
    assert below.n_impacts > 0 and set(below.impacts["contact"]) == {"W-B1F1"}
