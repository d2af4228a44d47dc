"""A sweep of a building on a flexible base reports its storeys' drifts as the run does:
the building's own deformation (the footing's sway and rocking taken out), and no columns
for the footing's DOFs, which are no floors."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding.config import parse_config
from pounding.integrate import simulate
from pounding.studies.sweep import apply_overrides, load_results, load_sweep, run_sweep

MODEL = """
name = "yielding 3-storey on a footing"
[record]
bundled = "el_centro"
scale = 1.5
duration = 2.5
[[building]]
name = "on soil"
n_storeys = 3
mass = 3.0e5
period = 0.45
height = 3.2
damping = { ratio = 0.05 }
storey_law = { type = "bilinear", yield_drift_ratio = 0.004, hardening = 0.0 }
foundation = { radius = 4.0, mass = 3.0e5, inertia = 2.0e6, soil = { vs = 120.0, density = 1800.0, poisson = 0.33 } }
[contact]
law = "kelvin-voigt"
k = 9.3e8
e = 0.65
gap = 0.02
[solver]
dt = 0.005
"""


def test_a_sweep_reports_the_drifts_of_a_building_on_a_footing_as_the_run(
        tmp_path: Path) -> None:
    """The row's peak drift ratio and every storey's peak drift are the Result's (to 1e-12
    relative: the building's own deformation, read at the output steps, not its floors
    less the floor below, which hold the footing's sway and rocking — 50 % more in storey
    1 here), and the footing's sway and rocking have no per-floor columns."""
    base = tmp_path / "model.toml"
    base.write_text(MODEL, encoding="utf-8")
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text(f'base = "{base.as_posix()}"\nname = "fdn"\nout = "out"\n'
                          '[grid]\n"record.scale" = [1.5]\n', encoding="utf-8")
    sweep = load_sweep(sweep_file)
    run_sweep(sweep, scheduler="synchronous")
    row = load_results(sweep.out).iloc[0]
    assert row["status"] == "ok"
    data = apply_overrides(sweep.base, sweep.params, sweep.cases[0].values)
    model, motion, kw = parse_config(data).build()
    r = simulate(model, motion, **kw)
    assert float(row["peak_drift_ratio"]) == pytest.approx(
        float(np.nanmax(r.peak_drift_ratio)), rel=1e-12, abs=0.0)
    for j in range(3):
        assert float(row[f"peak_drift_m_B1F{j + 1}"]) == pytest.approx(
            float(r.peak_drift[j]), rel=1e-12, abs=0.0)
    # the floors' own relative drift (what the row held) is not that
    relative = np.abs(r.displacement[:, 0]).max()
    assert relative > 1.2 * float(row["peak_drift_m_B1F1"])
    names = list(row.index)
    assert not [c for c in names if "Fdn" in c or c.endswith(("_B1F4", "_B1F5", "_r"))]
    for measure in ("peak_displacement_m", "peak_drift_m", "peak_abs_accel_m_s2"):
        assert [c for c in names if c.startswith(measure + "_")] == \
            [f"{measure}_B1F{j}" for j in (1, 2, 3)]
    # the largest floor acceleration is the floors' (not the footing's rocking, in rad/s²)
    assert float(row["peak_floor_accel_m_s2"]) == max(
        float(row[f"peak_abs_accel_m_s2_B1F{j}"]) for j in (1, 2, 3))


def test_the_link_study_reads_the_roof_and_the_floors_of_a_building_on_a_footing() -> None:
    """``rms_displacement_B1`` is the roof's (floor 3; not the footing's rocking, the last
    DOF), and the largest displacement and acceleration are the floors' (in m and m/s²:
    the footing's rocking in rad is left out)."""
    import tomllib

    from pounding.studies.mitigation import measure_row
    from pounding.studies.optimal_link import RESPONSES

    model, motion, kw = parse_config(tomllib.loads(MODEL.replace("2.5", "1.0"))).build()
    r = simulate(model, motion, **kw)
    roof = r.displacement[:, 2]
    assert RESPONSES["rms_displacement_B1"](r) == np.sqrt(np.mean(roof ** 2))
    assert RESPONSES["peak_displacement"](r) == float(r.peak_displacement[:3].max())
    assert RESPONSES["peak_abs_acceleration"](r) == float(r.peak_abs_acceleration[:3].max())
    assert measure_row(r)["peak_abs_accel_m_s2"] == float(r.peak_abs_acceleration[:3].max())
