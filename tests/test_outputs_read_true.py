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
