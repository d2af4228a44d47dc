"""`pounding fragility` end to end on a small study: the runs (a sweep), their intensity,
the needed gaps against the runs with contact, resuming, the CLI's conventions, the
report, and the intensity measures Sa_avg and the scaled suite."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.ground_motion import bundled_records, load_bundled
from pounding.spectra import DesignSpectrum, response_spectrum, sa_avg, scale_suite
from pounding.spectra.scaling import saavg_periods, scale_to_saavg
from pounding.studies.fragility import run_study, study_cases
from pounding.studies.gap import critical_gaps
from pounding.studies.sweep import load_results

ROOT = Path(__file__).resolve().parents[2]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
TARGET = ROOT / "examples" / "spectrum_asce7_site.toml"

STUDY = f'''name = "small <study>"
base = "{SEED}"
out = "small-results"
[suite]
bundled = true
duration = 4.0
[intensity]
measure = "sa"
period = 1.0
levels = [0.1, 0.3, 0.6, 1.0]
[[limit_state]]
demand = "pounding"
[[limit_state]]
demand = "drift"
limit = 1.0
[gap]
at = 0.5
target = 0.2
values = [0.01, 0.05]
[bootstrap]
n = 200
[run]
scheduler = "synchronous"
'''


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    study = folder / "study.toml"
    study.write_text(STUDY)
    return study, run_study(study)


def test_the_runs_are_a_sweep_of_records_by_levels_by_gaps(small):
    study, res = small
    cases = res.cases
    assert res.sweep.n_cases == 9 * 4 * 2 and res.sweep.n_errors == 0  # the bundled suite: 9
    table = load_results(res.sweep.results)
    assert list(table.columns[2:5]) == ["record.bundled", "record.sa_g", "contact.gap"]
    for (r, li, g), (_, row) in zip(cases.rows, table.iterrows()):
        assert row["record.sa_g"] == cases.levels[li] and row["contact.gap"] == cases.gaps[g]
        assert row["record.bundled"] == cases.records[r]
    # a record as the runs scale it has Sa(1.0 s, 5 %) equal to the level
    _, motion, _ = cases.build(3, 0.6)
    assert response_spectrum(motion, [1.0], 0.05).psa_g[0, 0] == pytest.approx(0.6, rel=1e-9)
    names = {p.name for p in cases.out.iterdir()}
    assert {"results.parquet", "sweep.json", "fragility.json", "fragility.csv", "gap.csv",
            "counts.csv", "ida.csv", "needed_gaps.csv", "ida.png", "fragility.png",
            "pounding_vs_gap.png", "pounding_surface.png"} <= names


def test_every_csv_reads_with_plain_read_csv(small):
    """One header row, no comment line, the unit in each column's name: every table of the
    folder reads with ``pandas.read_csv(path)`` alone, numbers as numbers."""
    import pandas as pd

    _, res = small
    text = {"limit_state", "demand", "unit", "method", "intensity_measure", "status",
            "record", "gap"}
    for name in ("fragility.csv", "counts.csv", "ida.csv", "gap.csv", "needed_gaps.csv"):
        df = pd.read_csv(res.out_dir / name)
        assert len(df) > 0 and not str(df.columns[0]).startswith("#"), name
        for column in set(df.columns) - text:
            assert pd.api.types.is_numeric_dtype(df[column]), (name, column)
    levels = pd.read_csv(res.out_dir / "needed_gaps.csv").columns[1:]
    assert list(levels) == ["gap_m_at_0.1_g", "gap_m_at_0.3_g", "gap_m_at_0.6_g",
                            "gap_m_at_1_g"]


def test_needed_gaps_agree_with_every_run_with_contact(small):
    _, res = small
    check = res.analysis.gap.check
    assert set(check) == {"0.01", "0.05"}
    for c in check.values():
        assert c["runs"] == 36 and c["agree"] == 36
    assert 0 < check["0.01"]["pounded"] and check["0.05"]["pounded"] < 36


def test_needed_gaps_scale_with_the_level_for_linear_buildings(small):
    _, res = small
    cases, ng = res.cases, res.analysis.gap.needed
    assert ng.scaled
    built = [cases.build(r, 0.3) for r in range(len(cases.records))]
    direct = critical_gaps(built[0].model, [b.motion for b in built],
                           dt=built[0].solver["dt"]).critical.max(axis=1)
    assert ng.needed[:, 1] == pytest.approx(direct, rel=1e-9)


def test_the_gap_for_the_target_probability_by_hand(small):
    _, res = small
    ga = res.analysis.gap
    g = np.sort(ga.needed.needed_at)
    assert ga.gap_empirical == g[7]     # 20 % of 9 records: at most 1 above (⌈0.8 × 9⌉ = 8th)
    lg = np.log(g)
    from scipy.stats import norm

    assert ga.gap_fit == pytest.approx(math.exp(lg.mean() + lg.std(ddof=1) * norm.ppf(0.8)))
    data = json.loads((res.cases.out / "fragility.json").read_text())
    assert data["gap"]["gap_for_target_records_m"] == pytest.approx(g[7])
    assert set(data["gap"]["code_gaps_m"]) == {"ABS", "SRSS", "DDC"}


def test_jupyter_shows_the_study_with_its_numbers_units_and_curves(small, tmp_path,
                                                                   monkeypatch):
    """``_repr_html_`` of the outcome and its analysis: the numbers of fragility.json, with
    units, and the fragility curves inline; nothing written."""
    import base64
    import html
    import re

    _, res = small
    before = sorted(p.name for p in res.cases.out.rglob("*"))
    monkeypatch.chdir(tmp_path)
    text = res._repr_html_()
    assert res.analysis._repr_html_().startswith('<div class="pounding-fragility">')
    assert sorted(p.name for p in res.cases.out.rglob("*")) == before
    assert list(tmp_path.iterdir()) == []
    data = json.loads((res.cases.out / "fragility.json").read_text())
    cells = [[html.unescape(c) for c in re.findall(r"<t[dh][^>]*>(.*?)</t[dh]>", row)]
             for row in re.findall(r"<tr>(.*?)</tr>", text)]
    head = {r[0]: r[1] for r in cells if len(r) == 2}
    assert int(head["runs"]) == data["runs"]["n"] and int(head["failed runs"]) == 0
    key = "gap for P(pounding) = 0.2 at 0.5 g, lognormal fit [mm]"
    assert float(head[key]) == pytest.approx(data["gap"]["gap_for_target_lognormal_m"] * 1e3,
                                             rel=5e-4)
    states = [r for r in cells if len(r) == 7 and r[0] != "limit state"]
    assert len(states) == 2 * len(data["limit_states"])
    checked = 0
    for ls in data["limit_states"]:
        for method, fit in (("stripes (MLE)", "msa_mle"), ("IDA capacities", "ida")):
            gap = f"{ls['gap_m'] * 1e3:g} mm"
            row = next(r for r in states if r[:3] == [ls["name"], gap, method])
            if ls[fit]["median_g"] is None:  # never exceeded: no number shown
                assert row[3] == "–"
                continue
            assert float(row[3]) == pytest.approx(ls[fit]["median_g"], rel=5e-4)
            assert float(row[5]) == pytest.approx(ls[fit]["beta"], rel=5e-4)
            checked += 1
    assert checked >= 4
    assert "median θ [g]" in text and "[mm]" in text and "[s]" in text
    png = re.findall(r'<img [^>]*src="data:image/png;base64,([^"]+)"', text)
    assert len(png) == 1 and base64.b64decode(png[0]).startswith(b"\x89PNG")


def test_a_second_run_does_no_run_and_writes_the_same_files(small):
    study, res = small
    before = {n: (res.cases.out / n).read_bytes() for n in ("fragility.json", "fragility.csv",
                                                          "gap.csv", "ida.csv")}
    again = run_study(study, figures=False)
    assert again.sweep.n_run == 0
    for n, b in before.items():
        assert (res.cases.out / n).read_bytes() == b, n
    assert not (res.cases.out / "ida.png").exists()


def test_cli_runs_resumes_and_reports(small, tmp_path, capsys):
    study, res = small
    out = tmp_path / "cli"
    assert main(["fragility", str(study), "--out", str(out), "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "stripes, MLE" in text and "DDC" in text
    check = tmp_path / "check"  # a code check kept in the study's folder (issue 29)
    assert main(["code-check", str(SEED), "--code", "en1998-1", "--agr", "0.3",
                 "--ground-type", "C", "--spectrum-type", "1", "--q", "3", "--out",
                 str(check)]) == 0
    capsys.readouterr()
    assert main(["fragility", str(study), "--out", str(out), "--no-figures", "--code-check",
                 str(check)]) == 0
    assert "0 run now" in capsys.readouterr().out
    assert (out / "code_check.json").read_bytes() == (check / "code_check.json").read_bytes()
    assert main(["report", str(out)]) == 0
    section = (out / "report.html").read_text().split('<section id="code-check">')[1]
    required = json.loads((check / "code_check.json").read_text())["levels"][0]["required_mm"]
    assert "EN 1998-1:2004 §4.4.2.7" in section and f"{required:.4g}" in section
    assert main(["report", str(res.cases.out)]) == 0
    html = (res.cases.out / "report.html").read_text()
    assert "small &lt;study&gt;: pounding fragility report" in html
    assert "<study>" not in html and "Probability of pounding" in html
    assert 'id="code-check"' not in html


def _snapshot(folder: Path) -> dict[str, bytes | None]:
    return {p.relative_to(folder).as_posix(): (p.read_bytes() if p.is_file() else None)
            for p in sorted(folder.rglob("*"))}


def test_overwrite_refuses_a_study_folder_holding_a_file_of_the_users(small, capsys):
    study, res = small
    out = res.cases.out
    mine = out / "notes.txt"
    mine.write_text("mine")
    try:
        before = _snapshot(out)
        capsys.readouterr()
        assert main(["fragility", str(study), "--overwrite"]) == 2
        assert capsys.readouterr().err.strip().splitlines() == [
            f"error: out: not replacing {out}: it holds notes.txt (not a file pounding wrote); "
            "move it away or choose another --out"]
        assert _snapshot(out) == before
    finally:
        mine.unlink()


def test_a_full_disk_while_writing_the_analysis_keeps_the_earlier_files(small, tmp_path,
                                                                        monkeypatch):
    import copy
    import errno
    import shutil

    from matplotlib.figure import Figure

    from pounding.io.files import WriteFailed
    from pounding.studies.fragility.outputs import write_outputs

    study, res = small
    cases = copy.copy(res.cases)
    cases.out = Path(shutil.copytree(res.cases.out, tmp_path / "out"))
    for name in ("ida.png", "fragility.png", "pounding_vs_gap.png", "pounding_surface.png"):
        (cases.out / name).unlink(missing_ok=True)
    before = _snapshot(cases.out)
    calls = []

    def full(self, fname, **kw):
        calls.append(fname)
        if len(calls) == 2:  # the first figure is written, the second meets a full disk
            raise OSError(errno.ENOSPC, "No space left on device")
        Path(fname).write_bytes(b"\x89PNG")

    monkeypatch.setattr(Figure, "savefig", full)
    with pytest.raises(WriteFailed) as info:
        write_outputs(cases, res.analysis, figures=True)
    assert str(info.value) == (f"cannot write {cases.out / 'fragility.png'}: no space left on "
                               "device")
    assert _snapshot(cases.out) == before  # not one file of the new analysis, nothing left


@pytest.mark.parametrize("old, new, message", [
    ('name = "small <study>"', 'name = "../up"', "name: a label, not a path"),
    ('out = "small-results"', 'out = "../up"', "out: '../up' is not a folder inside the study "
                                               "file's folder"),
])
def test_a_study_writes_only_in_its_folder_unless_told(tmp_path, capsys, old, new, message):
    folder = tmp_path / "a"
    folder.mkdir()
    study = folder / "study.toml"
    study.write_text(STUDY.replace(old, new))
    capsys.readouterr()
    assert main(["fragility", str(study)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["a", "study.toml"]


@pytest.mark.parametrize("change, message", [
    ("[suite]\nbundled = true\nbundle = 1", "suite.bundle: unknown key (got 1); did you mean "
                                              "'bundled'?"),
    ('[[limit_state]]\ndemand = "ductility"\nlimit = 2.0', "needs yielding storeys"),
    ("[intensity]\nmeasure = \"sa\"\nlevels = [0.1, 0.2]", "intensity.period: measure"),
])
def test_bad_study_is_one_line_and_writes_nothing(tmp_path, capsys, change, message):
    text = STUDY
    head = change.split("\n", 1)[0]
    if head in ("[suite]", "[intensity]"):
        start = text.index(head)
        end = text.index("\n[", start + 1)
        text = text[:start] + change + text[end:]
    else:
        text += change + "\n"
    study = tmp_path / "bad.toml"
    study.write_text(text)
    assert main(["fragility", str(study)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert not (tmp_path / "small-results").exists()


# ----------------------------------------------------------------------- Sa_avg, scaled suite
def test_sa_avg_is_the_geometric_mean_of_the_spectrum():
    gm = load_bundled(bundled_records()[0]).trimmed(10.0)
    periods = saavg_periods((0.2, 3.0), 10)
    assert list(periods) == pytest.approx(list(np.linspace(0.2, 3.0, 10)))
    psa = response_spectrum(gm, periods, 0.05).psa_g[0]
    assert sa_avg(gm, (0.2, 3.0)) == pytest.approx(float(np.prod(psa) ** 0.1), rel=1e-12)
    assert sa_avg(scale_to_saavg(gm, 0.5, (0.2, 3.0)), (0.2, 3.0)) == pytest.approx(0.5,
                                                                                    rel=1e-12)


def test_saavg_and_pga_studies_scale_each_record_to_the_level(tmp_path):
    for measure, extra, key in (("saavg", "", "record.saavg_g"), ("pga", "", "record.pga_g")):
        text = STUDY.replace('measure = "sa"\nperiod = 1.0', f'measure = "{measure}"{extra}')
        study = tmp_path / f"{measure}.toml"
        study.write_text(text)
        cases = study_cases(study)
        assert cases.sweep.params[1] == key
        _, motion, _ = cases.build(2, 0.3)
        if measure == "pga":
            assert motion.pga_g == pytest.approx(0.3, rel=1e-12)
        else:
            # default range: 0.2 T1 of the stiffer to 3 T1 of the more flexible building
            assert cases.saavg_range == pytest.approx((0.1, 3.0), rel=1e-6)
            assert sa_avg(motion, cases.saavg_range) == pytest.approx(0.3, rel=1e-9)


def test_a_code_scaled_suite_keeps_its_spread_about_the_target(tmp_path):
    text = STUDY.replace("duration = 4.0", "duration = 4.0\nscaling = { target = "
                         f'"{TARGET}", period = 1.0, method = "code" }}')
    study = tmp_path / "scaled.toml"
    study.write_text(text)
    cases = study_cases(study)
    motions = [load_bundled(f).trimmed(4.0) for f in bundled_records()]
    target = DesignSpectrum.from_file(TARGET)
    factors = scale_suite(motions, target, 1.0, method="code").factors
    assert list(cases.factors) == pytest.approx(list(factors), rel=1e-12)
    assert cases.im_target == pytest.approx(float(target.sa_g(1.0)), rel=1e-12)
    assert cases.sweep.params[:2] == ("record.bundled", "record.scale")
    _, motion, _ = cases.build(4, 0.6)
    expected = motions[4].scaled(factors[4] * 0.6 / cases.im_target)
    assert np.array_equal(motion.accel, expected.accel)
