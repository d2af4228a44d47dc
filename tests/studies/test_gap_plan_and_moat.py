"""`pounding gap` for buildings in plan (two ground components, the corner points facing each
other) and for a base-isolated building beside a moat wall (the moat width it needs).

Before issue 24 both were refused (``1 ground component for a model whose influence matrix
R has 2 columns``; ``remove its 2 moat wall(s)``). The references are independent of the
study's code: a plain ``simulate()`` of the whole model at gaps too wide to close, read at
its output samples through :func:`pounding.structure.plan_row.point_history` (the façade
corners in plan) or the base slab's displacement (the moat); and runs with contact at the
needed gap plus or minus 1 mm: no impact, then impacts.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import load_config
from pounding.ground_motion import GroundMotionComponents
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure.plan_row import point_history
from pounding.studies import critical_gaps

ROOT = Path(__file__).resolve().parents[2]
TORSIONAL = ROOT / "examples" / "torsional_pair.toml"
MOAT = ROOT / "examples" / "isolated_moat_wall.toml"
SECONDS = 6.0
MARGIN = 1e-3
"""m: the run at the needed gap plus it has no impact, minus it has some."""


def _short(motion):
    if isinstance(motion, GroundMotionComponents):
        return GroundMotionComponents.of(*(c.trimmed(SECONDS) for c in motion.components))
    return motion.trimmed(SECONDS)


@pytest.fixture(scope="module")
def torsional():
    built = load_config(TORSIONAL).build()
    return built.model, _short(built.motion)


@pytest.fixture(scope="module")
def moat():
    built = load_config(MOAT).build()
    return built.model, _short(built.motion)


def _impacts(model: PoundingModel, motion) -> int:
    return int(simulate(model, motion, dt=0.001).impacts.shape[0])


def test_plan_gap_is_the_peak_approach_of_the_facing_corners(torsional) -> None:
    model, motion = torsional
    study = critical_gaps(model, [motion], dt=0.001)
    assert len(study.labels) == 6 and all("@y=" in label for label in study.labels)
    # independent: the whole model at a gap that never closes, the corners read at samples
    wide = dataclasses.replace(model, gaps=(10.0,))
    run = simulate(wide, motion, dt=0.001)
    assert run.impacts.shape[0] == 0
    left, right = model.buildings
    for k, label in enumerate(study.labels):
        floor = int(label.split("F")[1].split("@")[0]) - 1
        y = float(label.split("@y=")[1].split("-")[0])
        ul = point_history(run, 0, floor, left.plan.width, y - left.plan.site_y)
        ur = point_history(run, 1, floor, 0.0, y - right.plan.site_y)
        sampled = float(np.max(ul - ur))
        # the study refines between samples: never below the sampled peak, barely above
        assert sampled - 1e-9 <= study.critical[0, k] <= sampled + 2e-6, label


def test_plan_gap_separates_impact_from_none(torsional) -> None:
    model, motion = torsional
    needed = critical_gaps(model, [motion], dt=0.001).governing()[0]
    assert needed > 2 * MARGIN
    assert _impacts(dataclasses.replace(model, gaps=(needed + MARGIN,)), motion) == 0
    assert _impacts(dataclasses.replace(model, gaps=(needed - MARGIN,)), motion) > 0


def test_moat_width_is_the_peak_base_displacement_toward_each_wall(moat) -> None:
    model, motion = moat
    study = critical_gaps(model, [motion], dt=0.001)
    widths = study.governing_gaps()
    assert set(widths) == {"W-B1", "B1-W"}
    # independent: the building with no wall, its base slab (floor 1) read at samples
    alone = dataclasses.replace(model, walls=())
    base = simulate(alone, motion, dt=0.001).displacement[:, 0]
    assert widths["B1-W"] == pytest.approx(float(base.max()), abs=2e-6)   # toward the right
    assert widths["W-B1"] == pytest.approx(float(-base.min()), abs=2e-6)  # toward the left
    walls = model.walls
    wider = tuple(dataclasses.replace(w, gap=widths["W-B1" if w.side == "left" else "B1-W"]
                                      + MARGIN) for w in walls)
    narrower = tuple(dataclasses.replace(w, gap=widths["W-B1" if w.side == "left" else "B1-W"]
                                         - MARGIN) for w in walls)
    assert _impacts(dataclasses.replace(model, walls=wider), motion) == 0
    hit = simulate(dataclasses.replace(model, walls=narrower), motion, dt=0.001).impacts
    assert set(hit["contact"]) == {"W-B1F1", "B1F1-W"}


def test_plan_model_refuses_one_component_in_words(torsional) -> None:
    model, motion = torsional
    with pytest.raises(ValueError, match="buildings in plan, shaken along x and y"):
        critical_gaps(model, [motion.components[0]])


def test_cli_gap_answers_for_plan_and_moat_models(tmp_path: Path, capsys) -> None:
    for src in (TORSIONAL, MOAT):
        text = src.read_text(encoding="utf-8").replace(
            "[record]\n", f"[record]\nduration = {SECONDS}\n", 1)
        model = tmp_path / src.name
        model.write_text(text, encoding="utf-8")
        csv = tmp_path / f"{src.stem}.csv"
        assert main(["gap", str(model), "--csv", str(csv)]) == 0, capsys.readouterr().err
        out = capsys.readouterr().out
        if src == MOAT:
            assert "moat width needed" in out and "W-B1" in out and "B1-W" in out
        else:
            assert "B1F3@y=6-B2F3@y=6" in out and "governing critical gap" in out
            assert "3 floor(s) in plan" in out and "9 storey" not in out
        assert csv.is_file()


def test_the_gap_header_gives_an_isolated_building_its_period_on_sliding_or_yielded_bearings():
    """T1 of the building alone is of bearings at their initial stiffness (0.529 s for the
    example's friction pendulum, stuck); beside it the period an engineer knows it by:
    2π √(R/g) = 2.837 s for R = 2 m, and 2π √(M/k₂) for a bilinear isolator."""
    import math

    from pounding.cli.commands_gap import _isolated_period
    from pounding.hysteresis.isolators import BilinearIsolator
    from pounding.structure import ShearBuilding

    config = load_config(ROOT / "examples" / "isolated_moat_wall.toml")
    building = config.build()[0].buildings[0]
    assert _isolated_period(building) == (
        f" (bearings stuck; sliding: {2 * math.pi * math.sqrt(2.0 / 9.80665):.4g} s, 2π√(R/g))")
    assert "2.837 s" in _isolated_period(building)
    frame = ShearBuilding.uniform(3, mass=2e5, stiffness=2e8)
    iso = BilinearIsolator(2.0e8, 2.0e7, characteristic_strength=9.0e5)
    on_bearings = ShearBuilding.base_isolated(frame, base_mass=3e5, isolator=iso)
    total = 3 * 2e5 + 3e5
    assert _isolated_period(on_bearings) == (
        f" (bearings elastic; yielded: {2 * math.pi * math.sqrt(total / 2.0e7):.4g} s, "
        "2π√(M/k₂))")
    assert _isolated_period(frame) == ""
