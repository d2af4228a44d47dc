"""A fragility study of buildings in plan (issue 24: refused with "expected a GroundMotion
(got GroundMotionComponents)"). Each record of the suite shakes the buildings along the
base model's incidence, and the gap each record needs is the peak approach of the facing
corners, checked against a plain simulation of the case's model at a gap that never closes
(read through point_history, independent of the gap study's code)."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from pounding.integrate import simulate
from pounding.structure.plan_row import point_history
from pounding.studies.fragility import study_cases
from pounding.studies.fragility.gaps import needed_gaps

ROOT = Path(__file__).resolve().parents[2]

STUDY = '''name = "torsional"
base = "torsional_pair.toml"
[suite]
files = ["{a}", "{b}"]
duration = 4.0
[intensity]
measure = "pga"
levels = [0.2, 0.4]
[[limit_state]]
demand = "pounding"
[gap]
at = 0.4
target = 0.1
'''


@pytest.fixture(scope="module")
def cases(tmp_path_factory):
    from pounding.ground_motion.bundled import bundled_folder

    folder = tmp_path_factory.mktemp("plan")
    (folder / "torsional_pair.toml").write_text(
        (ROOT / "examples" / "torsional_pair.toml").read_text(encoding="utf-8"),
        encoding="utf-8")
    records = Path(str(bundled_folder()))
    a = records / "elcentro_1940_IV_ELC9_180_PEER.AT2"
    b = records / "northridge_1994_newhall_360_RSN1044.AT2"
    study = folder / "study.toml"
    study.write_text(STUDY.format(a=a.as_posix(), b=b.as_posix()), encoding="utf-8")
    return study_cases(study)


def test_records_shake_along_the_base_models_incidence(cases) -> None:
    assert "incidence 60°" in cases.record_note and "is not used" in cases.record_note
    built = cases.build(0, 0.4)
    x, y = (c.accel for c in built.motion.components)
    # the record scaled to PGA 0.4 g, then turned: |a| = sqrt(a_x² + a_y²)
    assert np.hypot(x, y).max() / 9.80665 == pytest.approx(0.4, rel=1e-9)
    moving = np.abs(x) > 1e-6
    np.testing.assert_allclose(y[moving] / x[moving], math.tan(math.radians(60.0)), rtol=1e-9)


def test_needed_gap_is_the_peak_approach_of_the_facing_corners(cases) -> None:
    gaps = needed_gaps(cases)  # refused before
    for r in range(len(cases.records)):
        model, motion, solver = cases.build(r, gaps.at)
        run = simulate(dataclasses.replace(model, gaps=(10.0,)), motion, dt=solver["dt"],
                       duration=solver["duration"])
        assert run.impacts.shape[0] == 0
        left, right = model.buildings
        approach = max(
            float(np.max(point_history(run, 0, f, left.plan.width, y - left.plan.site_y)
                         - point_history(run, 1, f, 0.0, y - right.plan.site_y)))
            for f in range(3) for y in (6.0, 12.0))
        assert approach - 1e-9 <= gaps.needed_at[r] <= approach + 2e-6
