"""A sweep's row for buildings in plan: drifts along y (they were 0), a floor's rotation
under names in radians (they were under ``_m``), the peak floor acceleration over
translations only (an angular acceleration in rad/s² is no m/s²), and the row's peak drift
ratio the Result's own."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding.config.load import load_config
from pounding.integrate import simulate
from pounding.studies.sweep.measures import result_row

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def run():
    model, motion, _ = load_config(ROOT / "examples" / "torsional_pair.toml").build()
    return simulate(model, motion, duration=4.0)


def test_drifts_along_y_are_the_results(run) -> None:
    """Every floor's y drift in the row is the largest |u_y − u_y below| at the output
    steps, written out here from the displacements; the row's peak drift ratio is the
    Result's, which now counts the y direction (over the storey's height) — to the sampling
    of the output steps (the Result locates the x drifts' peaks inside solver steps)."""
    row = result_row(run)
    u = run.displacement
    for b, off in enumerate(run.model.system.offsets):
        n = run.model.buildings[b].plan.n_floors
        iy = int(off) + 1 + 3 * np.arange(n)
        drift = np.abs(np.diff(u[:, iy], axis=1, prepend=0.0)).max(axis=0)
        got = [row[f"peak_drift_m_B{b + 1}F{j + 1}y"] for j in range(n)]
        np.testing.assert_allclose(got, drift, rtol=1e-12)
        assert min(got) > 0
        np.testing.assert_allclose(run.peak_drift[iy], drift, rtol=1e-12)
    assert row["peak_drift_ratio"] == pytest.approx(float(np.nanmax(run.peak_drift_ratio)),
                                                    rel=1e-4)


def test_rotations_are_named_in_radians_and_left_out_of_the_floor_acceleration(run) -> None:
    row = result_row(run)
    assert not [k for k in row if k.endswith("θ") and ("_m_" in k or "m_s2" in k)]
    assert row["peak_rotation_rad_B2F3θ"] == run.peak_displacement[17] > 0
    translations = [i for i, unit in enumerate(run.model.dof_units()) if unit == "m"]
    assert row["peak_floor_accel_m_s2"] == pytest.approx(
        float(np.abs(run.abs_acceleration[:, translations]).max()), rel=1e-12)
