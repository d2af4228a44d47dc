"""What a run reports reads as what it is (issue 24, "Engineering outputs that mislead"):
elevations as given, each impact's own energy loss beside its velocity ratio, the report's
critical gap equal to `pounding gap`'s, numbers never cut at 80 columns, user text printed
literally, isolation bearings apart from storeys, buildings in plan labelled by floor and
direction with their storey shears."""

from __future__ import annotations

import csv
import json
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import dump_toml

ROOT = Path(__file__).resolve().parents[1]
DEMO = ROOT / "examples" / "two_10_storey.toml"
DEMO_SECONDS = 4.0
"""The demo's record cut to its first 4 s: the roofs first strike at 2.46 s, and the lower
floors (F1, F2) never touch while the upper ones do."""


def _short_demo(folder: Path, seconds: float = DEMO_SECONDS) -> Path:
    data = tomllib.loads(DEMO.read_text(encoding="utf-8"))
    data.setdefault("solver", {})["duration"] = seconds
    path = folder / "demo_short.toml"
    path.write_text(dump_toml(data), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def demo_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """`pounding run` of the demo model over its first 4 s, without figures."""
    base = tmp_path_factory.mktemp("demo")
    model = _short_demo(base)
    out = base / "out"
    assert main(["run", str(model), "--out", str(out), "--no-figures"]) == 0
    return out


# ------------------------------------------------------------------ elevations (item 3)
def test_elevations_read_as_given(demo_run: Path) -> None:
    """Floor elevations are sums of 3.2 m storeys (3.2 × 10 = 31.999999999999996 in floating
    point): impacts.csv, summary.json and the NetCDF coordinates hold 32.0."""
    import xarray as xr

    rows = list(csv.DictReader(line for line in
                               (demo_run / "impacts.csv").read_text().splitlines()
                               if not line.startswith("#")))
    assert rows
    for row in rows:
        text = row["elevation_m"]
        assert len(text.partition(".")[2]) <= 6, text
    assert {row["elevation_m"] for row in rows if row["contact"] == "B1F10-B2F10"} == {"32.0"}
    summary = json.loads((demo_run / "summary.json").read_text())
    levels = [s["floor_elevation_m"] for s in summary["buildings"][0]["storeys"]]
    assert levels == pytest.approx([3.2 * k for k in range(1, 11)], abs=1e-12)
    assert levels[-1] == 32.0 and levels[-2] == 28.8 and levels[-3] == 25.6
    assert all(s["height_m"] == 3.2 for s in summary["buildings"][0]["storeys"])
    with xr.open_dataset(demo_run / "timehistories.nc", engine="h5netcdf") as ds:
        assert float(ds["floor_elevation"].values[9]) == 32.0
        assert float(ds["contact_elevation"].values[-1]) == 32.0


# ------------------------------------------------------- impacts.csv, each impact (item 2)
def _impacts(folder: Path) -> tuple[str, list[dict[str, str]]]:
    lines = (folder / "impacts.csv").read_text(encoding="utf-8").splitlines()
    return lines[0], list(csv.DictReader(line for line in lines if not line.startswith("#")))


def test_impacts_csv_says_what_its_ratio_is_and_each_loss_is_not_negative(demo_run: Path
                                                                         ) -> None:
    """Every column of impacts.csv names its unit (what the velocity ratio is, docs/running.md
    says: it is no energy ratio between buildings); every finished impact's own loss, the
    contact's dissipated energy, is ≥ 0."""
    head, rows = _impacts(demo_run)
    assert head.split(",") == ["contact", "elevation_m", "start_s", "end_s", "v0_m_s",
                               "peak_force_N", "peak_force_time_s", "max_penetration_m",
                               "restitution", "energy_dissipated_J"]
    done = [r for r in rows if r["energy_dissipated_J"]]
    assert len(done) > 10
    for r in done:
        assert float(r["energy_dissipated_J"]) >= 0.0, r
    summary = json.loads((demo_run / "summary.json").read_text())
    total = sum(float(r["energy_dissipated_J"]) for r in done)
    assert total == pytest.approx(summary["contact_dissipated_J"], rel=1e-6)


@pytest.mark.parametrize("law,kw", [("kelvin-voigt", {"k": 9.3e8}),
                                    ("nonlinear-viscoelastic", {"k_h": 2.75e9})])
def test_free_bodies_impact_reaches_the_laws_restitution(tmp_path: Path, law: str,
                                                         kw: dict[str, float]) -> None:
    """Two free masses, no ground motion: impacts.csv's ratio is the e the law achieves and
    the impact's loss ½ m_eff v0² (1 − e²), as the single-collision analysis gives them."""
    from pounding import PoundingModel, ShearBuilding, simulate
    from pounding.contact.collision import simulate_collision
    from pounding.ground_motion import GroundMotion
    from pounding.model import ContactSpec

    m1, m2, v0 = 2.0e5, 3.0e5, 0.4
    model = PoundingModel([ShearBuilding.sdof(m1, period=1e3, damping_ratio=0.0),
                           ShearBuilding.sdof(m2, period=1e3, damping_ratio=0.0)], [0.0],
                          ContactSpec(law, e=0.65, **kw))
    res = simulate(model, GroundMotion(0.01, np.zeros(31), name="no shaking"),
                   initial_velocity=np.array([v0, 0.0]))
    res.save(tmp_path)
    _, rows = _impacts(tmp_path)
    assert len(rows) == 1
    single = simulate_collision(model.contacts[0].law, m1, m2, v0)
    assert float(rows[0]["restitution"]) == pytest.approx(single.e, abs=2e-5)
    m_eff = m1 * m2 / (m1 + m2)
    loss = float(rows[0]["energy_dissipated_J"])
    assert loss == pytest.approx(single.energy_dissipated, rel=1e-4)
    assert loss == pytest.approx(0.5 * m_eff * v0**2 * (1 - single.e**2), rel=1e-4)


# ------------------------------------------------------- the report's critical gap (item 1)
def test_report_critical_gap_is_pounding_gaps(demo_run: Path, tmp_path: Path) -> None:
    """The report's critical gap of every contact equals `pounding gap`'s for the same model
    file, to the 4 significant digits the report prints (relative 5e-4) — also for the
    floors that never touched in a run where others did (the run's own largest approach of
    those is smaller: unconservative)."""
    import pandas as pd

    from pounding.report.format import num
    from pounding.report.run_checks import gap_check_section
    from pounding.report.run_folder import read_run

    model = _short_demo(tmp_path)
    table = tmp_path / "gaps.csv"
    assert main(["gap", str(model), "--csv", str(table)]) == 0
    gaps = pd.read_csv(table).set_index("contact")["max_m"]
    _, rows = _impacts(demo_run)
    touched = {r["contact"] for r in rows}
    assert "B1F1-B2F1" not in touched and "B1F10-B2F10" in touched
    # the report's gap check, as the page prints its cells (num: 4 significant digits)
    check = gap_check_section(read_run(demo_run))[0]
    assert check.headers[-1] == "critical gap (no contact) [m]"
    printed = {row[0]: [num(c) for c in row[1:]] for row in check.rows}
    assert set(printed) == set(gaps.index)
    for label, expected in gaps.items():
        assert float(printed[label][-1]) == pytest.approx(expected, rel=5e-4), label
    # the untouched floor's largest approach in this run is not its critical gap
    assert float(printed["B1F1-B2F1"][5]) < 0.9 * gaps["B1F1-B2F1"]


# ------------------------------------------------------- helpers: a model file, shortened
def _example(name: str, folder: Path, seconds: float, **changes: object) -> Path:
    """Example ``name`` simulated for ``seconds`` only, with top-level ``changes``."""
    data = tomllib.loads((ROOT / "examples" / f"{name}.toml").read_text(encoding="utf-8"))
    data.setdefault("solver", {})["duration"] = seconds
    data.update(changes)
    for building in data.get("building", []):  # matrix files: beside the example
        for key, value in (building.get("matrices") or {}).items():
            building["matrices"][key] = str(ROOT / "examples" / value)
    path = folder / f"{name}.toml"
    path.write_text(dump_toml(data), encoding="utf-8")
    return path


def _run_at(width: int, model: Path, out: Path, capsys: pytest.CaptureFixture[str],
            monkeypatch: pytest.MonkeyPatch, *more: str) -> str:
    """`pounding run` printed on a console ``width`` columns wide."""
    from pounding.cli.app import console

    monkeypatch.setattr(console, "width", width)
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(out), "--no-figures", *more]) == 0
    return capsys.readouterr().out


# ------------------------------------------------ the run tables at 80 columns (item 8)
CASES = {"two_10_storey": 4.0, "torsional_pair": 10.0, "isolated_moat_wall": 7.0,
         "matrix_building": 4.0}


@pytest.mark.parametrize("width", [80, 160])
@pytest.mark.parametrize("name", list(CASES))
def test_run_tables_never_cut_a_number(name: str, width: int, tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str],
                                       monkeypatch: pytest.MonkeyPatch) -> None:
    """At 80 and 160 columns: no line wider than the console, no "…" anywhere, every peak
    of summary.json printed whole in the one unit of its quantity (mm, kN, kJ), no force or
    energy with an exponent."""
    from pounding.cli.tables import energy_scale, force_scale, number

    out = tmp_path / "out"
    text = _run_at(width, _example(name, tmp_path, CASES[name]), out, capsys, monkeypatch)
    lines = text.splitlines()
    assert max(len(line) for line in lines) <= width
    assert "…" not in text
    # results in the unit of their quantity, no exponent (the law's constants in the head
    # table, such as k_h = 2.75e+09 N/m^1.5, are given as the model file gives them)
    head_end = next(i for i, line in enumerate(lines) if line.startswith("└"))
    results = [line for line in lines[head_end:]] + [
        line for line in lines[:head_end] if re.search(r"force|energy|dissipated", line)]
    assert not re.search(r"\d\.?\d*e\+\d", "\n".join(results)), "an exponent"
    s = json.loads((out / "summary.json").read_text())
    ff, fu = force_scale(max(s["peak_contact_force_N"], *(
        v or 0.0 for v in s["peak_storey_shear_N"].values()),
        *(b["peak_force_N"] for b in s.get("bearings", []))))
    assert fu == "kN" and f"[{fu}]" in text and "[mm]" in text
    assert "[N]" not in text and "[J]" not in text and "displacement [m]" not in text
    words = set(re.findall(r"[-+]?\d[\d.]*", text))
    assert number(s["peak_contact_force_N"] * ff) in words
    ef, _ = energy_scale(s["energy_final_J"]["input"])
    assert number(s["energy_final_J"]["input"] * ef) in words
    for b in s["buildings"]:
        for row in b["storeys"]:
            assert number(1e3 * row["peak_displacement_m"]) in words, (b["building"], row)


# ------------------------------------------------ user text printed literally (item 7)
ODD = ":x: [bold]B[/bold] [link=https://e.x]L[/link]"


def test_names_are_printed_as_typed(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                    monkeypatch: pytest.MonkeyPatch) -> None:
    """Markup and emoji codes in the model's and buildings' names print as typed, in `run`
    and `gap`: no emoji, no hyperlink, no bold, the brackets kept."""
    data = tomllib.loads((ROOT / "examples" / "seed_sdof_pair.toml").read_text("utf-8"))
    data["name"] = f"model {ODD}"
    for b, building in enumerate(data["building"]):
        building["name"] = f"{ODD} {b}"
    data.setdefault("solver", {})["duration"] = 3.0
    model = tmp_path / "odd.toml"
    model.write_text(dump_toml(data), encoding="utf-8")
    text = _run_at(160, model, tmp_path / "out", capsys, monkeypatch)
    assert main(["gap", str(model)]) == 0
    text += capsys.readouterr().out
    for token in (":x:", "[bold]B[/bold]", "[link=https://e.x]L[/link]"):
        assert text.count(token) >= 5, token
    assert "❌" not in text and "\x1b]8;" not in text and "\x1b[1m" not in text
    assert " B1 B1" not in text


def test_an_unnamed_building_is_not_named_twice(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str],
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    """A building without a name takes the name "B1" in the model file: the tables say
    "B1", not "B1 B1"."""
    data = tomllib.loads((ROOT / "examples" / "seed_sdof_pair.toml").read_text("utf-8"))
    for building in data["building"]:
        building.pop("name", None)
    data.setdefault("solver", {})["duration"] = 2.0
    model = tmp_path / "unnamed.toml"
    model.write_text(dump_toml(data), encoding="utf-8")
    text = _run_at(160, model, tmp_path / "out", capsys, monkeypatch)
    assert "B1 B1" not in text and "B2 B2" not in text and "│ B1 " in text


# ------------------------------------------------ isolation bearings apart (item 4)
def test_an_isolation_bearing_is_reported_as_a_bearing(tmp_path: Path,
                                                       capsys: pytest.CaptureFixture[str],
                                                       monkeypatch: pytest.MonkeyPatch
                                                       ) -> None:
    """The friction pendulum under the base slab of isolated_moat_wall.toml is a bearing
    (law, displacement, force), not storey 1 of the building with a drift ratio of 16 % and
    a ductility of 328: summary.json, the printed tables, the NetCDF file, the report and
    the envelope figure keep it apart, and the storeys are the superstructure's."""
    import xarray as xr

    from pounding.config import load_config
    from pounding.plot.envelope import plot_envelopes
    from pounding.run_file import run_config  # noqa: F401  (the same run as the CLI's)
    from pounding import simulate

    out = tmp_path / "out"
    model = _example("isolated_moat_wall", tmp_path, 7.0)
    text = _run_at(160, model, out, capsys, monkeypatch)
    s = json.loads((out / "summary.json").read_text())
    (bearing,) = s["bearings"]
    assert bearing["kind"] == "friction pendulum" and "μ = 0.05" in bearing["law"]
    assert bearing["base_slab"] == "B1F1" and bearing["peak_displacement_m"] > 0.1
    assert "B1F1" not in s["peak_drift_ratio"] and "B1F1" not in s["peak_storey_shear_N"]
    assert "B1F1" in s["peak_displacement_m"]  # the base slab is a floor
    assert max(s["peak_drift_ratio"].values()) < 0.03          # the superstructure's
    assert s["ductility_demand"] == {}                         # linear superstructure
    b = s["buildings"][0]
    assert b["n_storeys"] == 5 and b["isolated_on"] == bearing["law"]
    assert [row["floor"] for row in b["storeys"]] == ["F2", "F3", "F4", "F5", "F6"]
    assert "Isolation bearings" in text and "friction pendulum" in text
    assert "Bouc-Wen" not in text and "ductility" not in text
    with xr.open_dataset(out / "timehistories.nc", engine="h5netcdf") as ds:
        assert list(ds["storey_kind"].values) == ["bearing"] + ["storey"] * 5
        np.testing.assert_array_equal(ds["bearing_displacement"].values[:, 0],
                                      ds["drift"].values[:, 0])
        assert ds["bearing_force"].attrs["units"] == "N"
        assert "friction pendulum" in str(ds["bearing_law"].values[0])
        assert np.isnan(ds["ductility"].values[0])
    from pounding.report.run import _bearing_tables
    from pounding.report.run_folder import read_run

    from pounding.report.run_checks import energy_section

    folder = read_run(out)
    (table,) = _bearing_tables(folder)
    assert "Isolation bearings" in table.caption and table.rows[0][1] == bearing["law"]
    # the report's energy closure counts the bearings' hysteresis (not a closure error)
    closure = dict(energy_section(folder)[1].rows)
    ratio = closure["largest |closure| / larger of largest |input| and E_0 [-]"]
    assert ratio < 1e-6 and ratio == pytest.approx(s["energy_balance_error"], rel=1e-6)
    # the envelope's drift ratio is the superstructure's: largest below 3 %, not 16 %
    built = load_config(model).build()
    r = simulate(built.model, built.motion, **built.solver)
    fig = plot_envelopes(r)
    drift_panel = fig.axes[1]
    drawn = [ln for ln in drift_panel.get_lines() if str(ln.get_label()).startswith("B1")]
    assert drawn and max(float(np.max(ln.get_xdata())) for ln in drawn) < 3.0
    assert min(float(np.min(ln.get_ydata())) for ln in drawn) == pytest.approx(1.0)
    assert "isolation bearing" in " ".join(t.get_text() for t in drift_panel.texts)
    # the studies' measures of the same run: the superstructure's drift ratio, no ductility
    from pounding.studies.optimal_link import RESPONSES
    from pounding.studies.sweep.measures import result_row

    row = result_row(r)
    assert row["peak_drift_ratio"] == pytest.approx(max(s["peak_drift_ratio"].values()),
                                                    rel=1e-2)
    assert row["max_ductility"] is None
    assert RESPONSES["peak_drift_ratio"](r) == pytest.approx(row["peak_drift_ratio"], rel=1e-2)


# ------------------------------------------------ buildings in plan (item 5)
def test_plan_storey_forces_by_hand() -> None:
    """One storey 20 m × 10 m, frames along x at y = 0 and 10 m, along y at x = 0 and 20 m
    (the one at x = 20 m twice as stiff), mass centre off the middle: the element forces
    from rigid-floor kinematics, k (u_x − (y_e − y_c) θ) along x and k (u_y + (x_e − x_c) θ)
    along y, summed into V_x, V_y and their moment about the centre of mass T — which is
    also K q, the restoring force of the one floor."""
    from pounding.result import plan_storey_forces
    from pounding.structure.plan import LateralElement, PlanBuilding

    kx, ky = 5e7, 5e7
    plan = PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0,
                        mass_centres=[[9.0, 6.0]], elements=[
                            LateralElement(0.0, 0.0, "x", kx), LateralElement(0.0, 10.0, "x", kx),
                            LateralElement(0.0, 5.0, "y", ky),
                            LateralElement(20.0, 5.0, "y", 2 * ky)])
    rng = np.random.default_rng(7)
    q = rng.normal(scale=[0.01, 0.01, 0.001], size=(5, 3))
    ux, uy, th = q[:, 0], q[:, 1], q[:, 2]
    xc, yc = 9.0, 6.0
    fx = [kx * (ux - (ye - yc) * th) for ye in (0.0, 10.0)]
    fy = [k * (uy + (xe - xc) * th) for xe, k in ((0.0, ky), (20.0, 2 * ky))]
    vx_hand, vy_hand = fx[0] + fx[1], fy[0] + fy[1]
    t_hand = (-fx[0] * (0.0 - yc) - fx[1] * (10.0 - yc)
              + fy[0] * (0.0 - xc) + fy[1] * (20.0 - xc))
    vx, vy, tq = plan_storey_forces(plan, q)
    np.testing.assert_allclose(vx[:, 0], vx_hand, rtol=1e-12)
    np.testing.assert_allclose(vy[:, 0], vy_hand, rtol=1e-12)
    np.testing.assert_allclose(tq[:, 0], t_hand, rtol=1e-12)
    restoring = q @ plan.stiffness_matrix().T
    np.testing.assert_allclose(np.column_stack([vx[:, 0], vy[:, 0], tq[:, 0]]), restoring,
                               rtol=1e-10, atol=1e-6)


def test_a_building_in_plan_is_labelled_by_floor_and_direction(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """torsional_pair.toml (3 storeys, 9 DOFs a building): summary keys, NetCDF floors and
    legends name floors and directions as the contacts do (F3 x, not the DOF number F7);
    storey shears along x and y and the torque are reported, the base storey's equal to
    the sum of every floor's elastic restoring force (aligned centres of mass); the report
    gives the plan's damping, not "matrix C (given)"."""
    import xarray as xr

    from pounding import simulate
    from pounding.config import load_config
    from pounding.plot.response import plot_displacements

    out = tmp_path / "out"
    model = _example("torsional_pair", tmp_path, 10.0)
    text = _run_at(160, model, out, capsys, monkeypatch)
    s = json.loads((out / "summary.json").read_text())
    assert list(s["peak_displacement_m"]) == [f"B{b}F{k}x" for b in (1, 2) for k in (1, 2, 3)]
    assert all(v is not None and v > 0 for v in s["peak_storey_shear_N"].values())
    rows = s["buildings"][1]["storeys"]
    assert [row["floor"] for row in rows] == ["F1", "F2", "F3"]
    assert [row["label"] for row in rows] == ["F1x", "F2x", "F3x"]
    for row in rows:
        for key in ("peak_storey_shear_N", "peak_storey_shear_y_N", "peak_storey_torque_N_m",
                    "peak_drift_ratio_y", "peak_displacement_y_m", "peak_rotation_mrad"):
            assert row[key] > 0.0, key
    assert "Storeys in plan" in text and "[kN·m]" in text and "F7" not in text
    with xr.open_dataset(out / "timehistories.nc", engine="h5netcdf") as ds:
        assert list(ds["floor"].values[:4]) == ["B1F1x", "B1F1y", "B1F1θ", "B1F2x"]
        assert ds["storey_torque"].attrs["units"] == "N m"
    # the base storey carries every floor's restoring force (centres of mass aligned)
    built = load_config(model).build()
    r = simulate(built.model, built.motion, **built.solver)
    plan = built.model.buildings[1].plan
    off = int(built.model.system.offsets[1])
    u = np.asarray(r.displacement[:, off: off + 9])
    restoring = u @ plan.stiffness_matrix().T
    scale = np.abs(restoring[:, 0::3]).sum(axis=1).max()
    np.testing.assert_allclose(r.storey_shear[:, off], restoring[:, 0::3].sum(axis=1),
                               atol=1e-9 * scale)
    np.testing.assert_allclose(r.storey_shear[:, off + 1], restoring[:, 1::3].sum(axis=1),
                               atol=1e-9 * scale)
    np.testing.assert_allclose(r.storey_torque[:, off + 2], restoring[:, 2::3].sum(axis=1),
                               atol=1e-9 * scale * 20.0)
    fig = plot_displacements(r)
    legend = [t.get_text() for ax in fig.axes if ax.get_legend() for t in
              ax.get_legend().get_texts()]
    assert "F3 x (roof, 9.5 m)" in legend and not any(t.startswith("F7") for t in legend)
    from pounding.report.run import _plan_tables
    from pounding.report.run_folder import read_run
    from pounding.report.run_inputs import model_section

    folder = read_run(out)
    buildings = next(t for t in model_section(folder) if getattr(t, "caption", "")
                     == "Buildings, left to right")
    damping = [row[-1] for row in buildings.rows]
    assert damping == ["Rayleigh, ζ = 0.05 at modes 1 and 3"] * 2  # not "matrix C (given)"
    assert [t.caption.split(",")[0] for t in _plan_tables(folder)] == [
        "B1 in plan", "B2 in plan"]
    # the headline's largest floor displacement is along y here, not the largest along x
    from pounding.report.format import num
    from pounding.report.run import _headline_section

    cards = dict(_headline_section(folder)[0].items)
    largest = max(row["peak_displacement_y_m"] for b in s["buildings"] for row in b["storeys"])
    assert largest > max(s["peak_displacement_m"].values())
    assert cards["largest floor displacement [m]"] == num(largest)


# ------------------------------------------------ matrix buildings (item 6)
def test_a_matrix_building_is_labelled_by_its_own_labels(tmp_path: Path) -> None:
    """A matrix building with a rotation between its two floors (labels L1, θ1, L2): the
    legends name its floors by its labels (L2, not the DOF number F3), the summary lists
    only its floors, its storey shear is null and said to be missing, not zero."""
    from pounding import PoundingModel, ShearBuilding, simulate
    from pounding.ground_motion import el_centro
    from pounding.model import ContactSpec
    from pounding.plot.response import plot_displacements
    from pounding.structure import MatrixBuilding

    k = 4e8
    frame = MatrixBuilding(M=np.diag([3e5, 2e4, 3e5]),
                           K=[[2 * k, 0.1 * k, -k], [0.1 * k, 0.5 * k, 0.1 * k],
                              [-k, 0.1 * k, k]],
                           labels=["L1", "θ1", "L2"], elevations=[3.0, 3.0, 6.0],
                           floors=["L1", "L2"], name="frame")
    shear = ShearBuilding.uniform(2, 3e5, 6e8, height=3.0, name="shear")
    model = PoundingModel([frame, shear], [0.005], ContactSpec("kelvin-voigt", k=9e8, e=0.65))
    r = simulate(model, el_centro().trimmed(3.0))
    s = r.summary()
    assert list(s["peak_drift_ratio"]) == ["B1F1", "B1F3", "B2F1", "B2F2"]
    assert [row["label"] for row in s["buildings"][0]["storeys"]] == ["L1", "L2"]
    assert s["peak_storey_shear_N"]["B1F3"] != s["peak_storey_shear_N"]["B1F3"]  # NaN
    legend = [t.get_text() for ax in plot_displacements(r).axes if ax.get_legend()
              for t in ax.get_legend().get_texts()]
    assert "L2 (roof, 6 m)" in legend and not any(t.startswith("F3") for t in legend)
