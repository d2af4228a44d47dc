"""The walk-through of docs/assess.md, run as a user types it: code check → time history →
probability of pounding → retrofit, on ``examples/existing_pair.toml``.

Each step runs the command the page shows (in this process, through :func:`pounding.cli.main`)
and reads what it wrote; the numbers the page quotes are checked against those files, to the
digits the page shows, so the page cannot drift from what the commands print. The physics of
each step is checked elsewhere against independent references (tests/studies/test_code_check.py,
the fragility and mitigation suites); here the point is the chain and the page.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pandas as pd
import pytest

from pounding.cli import main

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
PAGE = (ROOT / "docs" / "assess.md").read_text(encoding="utf-8")
CODE_OPTIONS = ["--code", "asce7-22", "--sds", "1.0", "--sd1", "0.6", "--tl", "8",
                "--cd", "5.5", "--r", "8", "--ie", "1.0"]


def _page_row(first_cell: str) -> list[str]:
    """The cells of the page's table row that starts with ``first_cell``."""
    for line in PAGE.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and cells[0] == first_cell:
            return cells
    raise AssertionError(f"no row {first_cell!r} in docs/assess.md")


def test_the_page_shows_the_commands_it_runs() -> None:
    """The console lines of the page are the commands this test runs."""
    page = re.sub(r"\\\n\s*", "", PAGE)
    assert ("pounding code-check examples/existing_pair.toml " + " ".join(CODE_OPTIONS)
            + " --time-history --out results/existing-check") in page
    assert ("pounding run examples/existing_pair.toml --out results/existing "
            "--code-check results/existing-check") in page
    assert "pounding fragility examples/fragility_existing_pair.toml" in page
    assert "pounding mitigate examples/mitigation_existing_pair.toml" in page


@pytest.fixture(scope="module")
def checked(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Step 1: the code check with the time histories beside it, written to a folder."""
    out = tmp_path_factory.mktemp("assess") / "check"
    assert main(["code-check", str(EXAMPLES / "existing_pair.toml"), *CODE_OPTIONS,
                 "--time-history", "--out", str(out)]) == 0
    return out


def test_code_check_step(checked: Path) -> None:
    check = json.loads((checked / "code_check.json").read_text())
    assert check["ok"] is False
    for floor, level in enumerate(check["levels"], start=1):
        cells = _page_row(f"{floor} ({level['elevation_m']:.1f} m)")
        assert [float(c) for c in cells[1:5]] == pytest.approx(
            [level["left_mm"], level["right_mm"], level["required_mm"], level["gap_mm"]],
            abs=0.051)
        assert cells[5] == ("OK" if level["ok"] else "not OK")
    beside = check["time_history"]
    pair = beside["pairs"][0]
    assert (pair["records_pounding_at_own_gap"], pair["records_pounding_at_code_gap"]) == (9, 6)
    assert "all nine make the pair pound; with the code's gap six" in " ".join(PAGE.split())
    factor = {round(r["factor"], 3) for r in beside["records"]}
    assert factor == {0.888} and "(factor 0.888)" in PAGE
    for floor, level in enumerate(beside["levels"], start=1):
        cells = _page_row(str(floor))
        assert float(cells[1]) == pytest.approx(level["required_mm"], abs=0.051)
        assert float(cells[2]) == pytest.approx(level["mean_peak_closing_mm"], abs=0.051)
        assert cells[3] == f"{level['records_closing_past_required']} of 9"


def test_time_history_step(checked: Path, tmp_path: Path) -> None:
    out = tmp_path / "run"
    assert main(["run", str(EXAMPLES / "existing_pair.toml"), "--out", str(out),
                 "--no-figures", "--code-check", str(checked)]) == 0
    assert json.loads((out / "code_check.json").read_text()) == json.loads(
        (checked / "code_check.json").read_text())
    impacts = pd.read_csv(out / "impacts.csv")
    per_floor = impacts.groupby("contact").size()
    assert len(impacts) == 38
    assert "strike 38 times" in PAGE
    assert list(per_floor[["B1F1-B2F1", "B1F2-B2F2", "B1F3-B2F3", "B1F4-B2F4"]]) == [1, 5, 15, 17]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["peak_contact_force_N"] / 1e6 == pytest.approx(9.9, abs=0.05)


@pytest.mark.slow
def test_fragility_and_mitigation_steps(tmp_path: Path) -> None:
    frag = tmp_path / "fragility"
    assert main(["fragility", str(EXAMPLES / "fragility_existing_pair.toml"), "--out", str(frag),
                 "--no-figures", "--scheduler", "synchronous"]) == 0
    fits = pd.read_csv(frag / "fragility.csv").set_index(["demand", "method"])
    assert fits.loc[("pounding", "msa_mle"), "median_g"] == pytest.approx(0.13, abs=0.005)
    assert fits.loc[("pounding", "ida"), "median_g"] == pytest.approx(0.16, abs=0.005)
    assert fits.loc[("pounding", "ida"), "n_records_exceeding"] == 9
    assert fits.loc[("drift", "msa_mle"), "median_g"] == pytest.approx(0.55, abs=0.005)
    assert fits.loc[("drift", "ida"), "median_g"] == pytest.approx(0.53, abs=0.005)
    gap = pd.read_csv(frag / "gap.csv").set_index("gap")
    assert gap.loc["P = 0.1: lognormal fit", "gap_m"] * 1e3 == pytest.approx(180, abs=5)

    mitigation = tmp_path / "mitigation"
    assert main(["mitigate", str(EXAMPLES / "mitigation_existing_pair.toml"), "--out",
                 str(mitigation), "--no-figures"]) == 0
    rows = pd.read_csv(mitigation / "summary.csv").set_index("option")
    for option, row in rows.iterrows():
        cells = _page_row(str(option))
        shown = [row["n_impacts"], row["peak_impact_force_N"] / 1e3,
                 100 * row["peak_drift_ratio"], row["peak_abs_accel_m_s2"] / 9.80665]
        half_last_digit = [0.05, 0.5, 0.005, 0.005]     # the page's 17.7, 6101, 2.13, 1.87
        for cell, value, tol in zip(cells[1:5], shown, half_last_digit, strict=True):
            assert float(cell) == pytest.approx(value, abs=tol), (option, cell, value)


def test_a_check_of_another_model_is_refused_before_the_run(checked: Path, tmp_path: Path,
                                                             capsys: pytest.CaptureFixture[str]
                                                             ) -> None:
    """The existing pair's check beside a run of the two 10-storey buildings: their contacts
    share labels (B1F1-B2F1 …) but not elevations or gaps — one line, exit 2, no run (the
    report set one pair's code verdict beside another pair's response)."""
    out = tmp_path / "other"
    capsys.readouterr()
    assert main(["run", str(EXAMPLES / "two_10_storey.toml"), "--out", str(out),
                 "--no-figures", "--code-check", str(checked)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "is a check of another model" in err[0], err
    assert "3.4 m with a gap of 30 mm, this model's at 3.2 m with 40 mm" in err[0]
    assert not out.exists()


@pytest.mark.parametrize("study", ["sweep_gap_e.toml", "fragility_two_10_storey.toml"])
def test_a_study_refuses_a_check_of_another_base_model(checked: Path, tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str],
                                                      study: str) -> None:
    """A sweep or fragility study with the existing pair's check: its base model's contacts
    are at other elevations — one line, exit 2, before any run."""
    command = "fragility" if study.startswith("fragility") else "sweep"
    out = tmp_path / "study"
    capsys.readouterr()
    assert main([command, str(EXAMPLES / study), "--out", str(out), "--no-figures",
                 "--scheduler", "synchronous", "--code-check", str(checked)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "is a check of another model" in err[0], err
    assert not out.exists()
