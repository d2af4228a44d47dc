"""`pounding mitigate`: the comparison of retrofit options, checked against runs made
directly with `simulate`, and its bad input."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pounding import simulate
from pounding.cli import main
from pounding.config import load_config
from pounding.devices import Link
from pounding.io.manifest import MANIFEST_FILE

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "two_10_storey.toml"

STUDY = f"""
name = "t"
base = "{BASE}"
records = ["el_centro"]
[[option]]
name = "bare gap"
[[option]]
name = "dashpots"
[[option.device]]
type = "viscous"
floors = "all"
c = 2.0e6
"""


def test_the_table_is_what_direct_runs_give(tmp_path: Path, capsys):
    study = tmp_path / "s.toml"
    study.write_text(STUDY)
    assert main(["mitigate", str(study), "--out", str(tmp_path / "o")]) == 0
    out = capsys.readouterr().out
    assert "bare gap" in out and "dashpots" in out
    runs = pd.read_csv(tmp_path / "o" / "runs.csv")
    assert {p.name for p in (tmp_path / "o").iterdir()} == {
        "runs.csv", "summary.csv", "study.toml", "mitigation.png", MANIFEST_FILE}
    model, motion, kw = load_config(BASE).build()
    bare = simulate(model, motion, **kw)
    row = runs.set_index("option").loc["bare gap"]
    assert row["n_impacts"] == bare.n_impacts
    assert row["peak_impact_force_N"] == pytest.approx(bare.peak_contact_force.max(), rel=1e-12)
    assert row["peak_drift_ratio"] == pytest.approx(np.max(bare.peak_drift_ratio), rel=1e-12)
    from dataclasses import replace

    links = [Link((c.left.label(), c.right.label()), "viscous", c=2e6) for c in model.contacts]
    linked = simulate(replace(model, devices=links), motion, **kw)
    row = runs.set_index("option").loc["dashpots"]
    assert row["links_dissipated_J"] == pytest.approx(linked.energy[-1, 7], rel=1e-12)
    assert row["peak_abs_accel_m_s2"] == pytest.approx(np.max(linked.peak_abs_acceleration),
                                                       rel=1e-12)
    # dashpots at every floor cut the impacts of this pair (El Centro, gap 40 mm)
    assert row["n_impacts"] < bare.n_impacts


@pytest.mark.parametrize("extra, line", [
    ('[[option]]\nname = "dashpots"\n', "s.toml: option[2].name: two options are called "
                                       "'dashpots'"),
    ('[[option]]\nname = "thick"\n[[option.device]]\ntype = "bumper"\nfloors = "all"\n'
     'thickness = 0.05\ncompression_limit = 0.5\nrubber = { law = "hertz", k_h = 1e8 }\n',
     "s.toml: option[2].device[0].thickness: the B1F1-B2F1 bumper (0.05 m) is thicker than "
     "its gap (0.04 m)"),
    ('[[option]]\nname = "x"\n[[option.device]]\ntype = "viscous"\nfloors = ["B1F20", '
     '"B2F1"]\nc = 1e6\n', "s.toml: option[2].device[0].floors: no floor B1F20 in this model"),
    ('[[option]]\nname = "x"\ncolour = "red"\n', "colour"),
])
def test_bad_studies_get_one_line(tmp_path: Path, capsys, extra, line):
    """Each line names the study file and the study's own key (not the model's)."""
    study = tmp_path / "s.toml"
    study.write_text(STUDY + extra)
    assert main(["mitigate", str(study), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and line in err[0], err
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("records, line", [
    ('["el_centro", "nope.at2"]', "s.toml: records[1]: 'nope.at2' is no such file ("),
    ("[]", "s.toml: records: must hold at least 1 value(s) (got 0: [])"),
])
def test_bad_records_are_named_as_the_study_gives_them(tmp_path: Path, capsys, records, line):
    study = tmp_path / "s.toml"
    study.write_text(STUDY.replace('records = ["el_centro"]', f"records = {records}"))
    assert main(["mitigate", str(study), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {tmp_path}/{line}"), err
    assert not (tmp_path / "o").exists()


def test_text_records_take_the_study_units_and_dt(tmp_path: Path, capsys):
    """A plain-text record states neither its unit nor (as one column) its step: the study's
    ``units`` and ``dt`` give them, and the run is the bundled El Centro's (the same samples
    written as text in g); without ``units`` the study is refused naming the key."""
    from pounding.ground_motion import el_centro
    from pounding.units import G

    elc = el_centro().trimmed(4.0)
    (tmp_path / "elc.txt").write_text("\n".join(f"{a / G:.17g}" for a in elc.accel) + "\n")
    one = STUDY.replace("[[option]]\nname = \"dashpots\"", "[[option]]\nname = \"unused\"")
    study = tmp_path / "s.toml"
    study.write_text(one.replace('records = ["el_centro"]',
                                 f'records = ["elc.txt"]\nunits = "g"\ndt = {elc.dt!r}'))
    assert main(["mitigate", str(study), "--out", str(tmp_path / "o")]) == 0
    runs = pd.read_csv(tmp_path / "o" / "runs.csv").set_index("option")
    model, _, kw = load_config(BASE).build()
    kw["duration"] = 4.0
    direct = simulate(model, elc, **kw)
    assert runs.loc["bare gap", "n_impacts"] == direct.n_impacts
    assert runs.loc["bare gap", "peak_drift_ratio"] == pytest.approx(
        np.max(direct.peak_drift_ratio), rel=1e-9)
    study.write_text(one.replace('records = ["el_centro"]',
                                 f'records = ["elc.txt"]\ndt = {elc.dt!r}'))
    capsys.readouterr()
    assert main(["mitigate", str(study), "--out", str(tmp_path / "p")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "records[0].units" in err[0], err
    assert not (tmp_path / "p").exists()
