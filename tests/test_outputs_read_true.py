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
        text = row["elevation"]
        assert len(text.partition(".")[2]) <= 6, text
    assert {row["elevation"] for row in rows if row["contact"] == "B1F10-B2F10"} == {"32.0"}
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
    """Between buildings the velocity ratio is no energy ratio (the units line says so);
    every finished impact's own loss, the contact's dissipated energy, is ≥ 0."""
    head, rows = _impacts(demo_run)
    assert "may exceed 1" in head and "not an energy ratio" in head
    assert "energy_dissipated = energy the contact element dissipated" in head
    done = [r for r in rows if r["energy_dissipated"]]
    assert len(done) > 10
    for r in done:
        assert float(r["energy_dissipated"]) >= 0.0, r
    summary = json.loads((demo_run / "summary.json").read_text())
    total = sum(float(r["energy_dissipated"]) for r in done)
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
    loss = float(rows[0]["energy_dissipated"])
    assert loss == pytest.approx(single.energy_dissipated, rel=1e-4)
    assert loss == pytest.approx(0.5 * m_eff * v0**2 * (1 - single.e**2), rel=1e-4)


# ------------------------------------------------------- the report's critical gap (item 1)
def _report_cells(html: str, section: str, label: str) -> list[str]:
    part = html[html.index(f'id="{section}"'):]
    row = re.search(rf"<tr><td>{re.escape(label)}</td>(.*?)</tr>", part, re.S)
    assert row, label
    return re.findall(r"<td[^>]*>(.*?)</td>", row.group(1))


def test_report_critical_gap_is_pounding_gaps(demo_run: Path, tmp_path: Path) -> None:
    """The report's critical gap of every contact equals `pounding gap`'s for the same model
    file, to the 4 significant digits the report prints (relative 5e-4) — also for the
    floors that never touched in a run where others did (the run's own largest approach of
    those is smaller: unconservative)."""
    import pandas as pd

    model = _short_demo(tmp_path)
    table = tmp_path / "gaps.csv"
    assert main(["gap", str(model), "--csv", str(table)]) == 0
    gaps = pd.read_csv(table, comment="#").set_index("contact")["max_m"]
    report = tmp_path / "report.html"
    assert main(["report", str(demo_run), "--out", str(report)]) == 0
    html = report.read_text(encoding="utf-8")
    _, rows = _impacts(demo_run)
    touched = {r["contact"] for r in rows}
    assert "B1F1-B2F1" not in touched and "B1F10-B2F10" in touched
    for label, expected in gaps.items():
        cells = _report_cells(html, "gap-check", label)
        assert float(cells[-1]) == pytest.approx(expected, rel=5e-4), label
    # the untouched floor's largest approach in this run is not its critical gap
    cells = _report_cells(html, "gap-check", "B1F1-B2F1")
    assert float(cells[5]) < 0.9 * gaps["B1F1-B2F1"]
