"""The "Code check" section of the reports (issue 29, docs/report.md): ``pounding run /
sweep ... --code-check DIR`` keep the check in the output folder and ``pounding report``
shows it; ``pounding report FOLDER --code-check DIR`` shows DIR's. The section's numbers
are checked against the check's own file and, for a run, the run's peak closing against
``max(u_left − u_right)`` read from its time histories (the displacements, not the
penetration the section reads). A folder or file pounding did not write is one line,
exit 2, nothing written."""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

import numpy as np
import pytest
from model_documents import two_storey_pair

from pounding.cli import main

MODEL = two_storey_pair(extra="[solver]\nduration = 4.0\n")
ASCE = ["--code", "asce7-22", "--sds", "1.0", "--sd1", "0.6", "--tl", "8", "--cd", "5.5",
        "--r", "8", "--ie", "1.25", "--combination", "srss"]
ROW = re.compile(r"<tr><td>(B1F\d-B2F\d)</td>(.*?)</tr>")


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    base = tmp_path_factory.mktemp("cc")
    model = base / "model.toml"
    model.write_text(MODEL, encoding="utf-8")
    check = base / "check"
    assert main(["code-check", str(model), *ASCE, "--suite", str(_record()),
                 "--duration", "3", "--out", str(check)]) == 0
    run = base / "run"
    assert main(["run", str(model), "--out", str(run), "--code-check", str(check)]) == 0
    return model, check, run


def _record() -> Path:
    return (Path(__file__).resolve().parents[1] / "src" / "pounding" / "data" / "records"
            / "elcentro_1940_IV_ELC9_180_PEER.AT2")


def _section(page: str) -> str:
    start = page.index('<section id="code-check">')
    return page[start:page.index("</section>", start)]


def _cells(row: str) -> list[str]:
    return [html.unescape(c) for c in re.findall(r"<td[^>]*>(.*?)</td>", row)]


def test_the_run_keeps_the_check_and_its_report_shows_it(folders):
    from pounding.io.manifest import Manifest

    _, check, run = folders
    kept = run / "code_check.json"
    assert kept.read_bytes() == (check / "code_check.json").read_bytes()
    assert Manifest(run).is_ours(kept)
    assert main(["report", str(run)]) == 0
    section = _section((run / "report.html").read_text(encoding="utf-8"))
    data = json.loads(kept.read_text(encoding="utf-8"))
    rows: dict[str, list[str]] = {}
    for label, rest in ROW.findall(section):  # the check's table first (then the suite's)
        rows.setdefault(label, _cells(f"<td>{label}</td>" + rest))
    assert set(rows) == {"B1F1-B2F1", "B1F2-B2F2"}
    assert all(len(cells) == 11 for cells in rows.values())

    import xarray as xr

    with xr.open_dataset(run / "timehistories.nc", engine="h5netcdf") as ds:
        floors = [str(x) for x in ds["floor"].values]
        u = np.asarray(ds["displacement"].values)
    for level in data["levels"]:
        cells = rows[level["contact"]]
        # floor, elevation, left, right, required, gap, check, clause, run gap, closing, touched
        assert float(cells[4]) == pytest.approx(level["required_mm"], rel=1e-3)
        assert float(cells[5]) == pytest.approx(level["gap_mm"], rel=1e-3)
        assert cells[6] == ("OK" if level["ok"] else "not OK") and cells[7] == level["clause"]
        left, right = level["contact"].split("-")
        closing = 1e3 * float(np.max(u[:, floors.index(left)] - u[:, floors.index(right)]))
        assert float(cells[9]) == pytest.approx(closing, rel=1e-3, abs=1e-3)
        assert cells[10] == ("yes" if closing > 50.0 else "no")
    assert "ASCE/SEI 7-22 §12.12" in section and "not OK" in section
    assert html.escape(data["time_history"]["verdicts"][0], quote=True) in section


def test_report_code_check_option_and_a_page_without_one(folders, tmp_path):
    import shutil

    _, check, kept = folders
    run = tmp_path / "run"  # the run without the check it kept
    shutil.copytree(kept, run)
    (run / "code_check.json").unlink()
    (run / "report.html").unlink(missing_ok=True)
    assert main(["report", str(run)]) == 0
    assert 'id="code-check"' not in (run / "report.html").read_text(encoding="utf-8")
    page = tmp_path / "page.html"
    assert main(["report", str(run), "--code-check", str(check), "--html", str(page)]) == 0
    assert "57.78" in _section(page.read_text(encoding="utf-8"))
    assert not (run / "code_check.json").exists()  # the report only reads


def test_a_sweep_page_shows_the_check(folders, tmp_path):
    from test_report import sweep_folder

    _, check, _ = folders
    folder = sweep_folder(tmp_path / "sweep")
    page = tmp_path / "sweep.html"
    assert main(["report", str(folder), "--code-check", str(check), "--html", str(page)]) == 0
    section = _section(page.read_text(encoding="utf-8"))
    assert "57.78" in section and "peak closing in this run" not in section


def _edited(check: Path, tmp_path: Path) -> Path:
    import shutil

    copy = tmp_path / "edited"
    shutil.copytree(check, copy)
    path = copy / "code_check.json"
    path.write_text(path.read_text(encoding="utf-8").replace("57.7", "47.7"), encoding="utf-8")
    return copy


@pytest.mark.parametrize("bad", ["run folder", "edited", "missing"])
def test_a_folder_pounding_code_check_did_not_write_is_one_line(folders, tmp_path, capsys,
                                                                bad):
    model, check, run = folders
    given = {"run folder": run, "edited": _edited(check, tmp_path),
             "missing": tmp_path / "nowhere"}[bad]
    out = tmp_path / "out"
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(out), "--code-check", str(given)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--code-check" in err[0], err
    assert not out.exists()
    page = tmp_path / "page.html"
    assert main(["report", str(run), "--code-check", str(given), "--html", str(page)]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    assert not page.exists()


def test_a_changed_check_in_the_run_folder_is_refused(folders, tmp_path, capsys):
    import shutil

    _, _, run = folders
    copy = tmp_path / "run"
    shutil.copytree(run, copy)
    kept = copy / "code_check.json"
    kept.write_text(kept.read_text(encoding="utf-8").replace('"OK"', '"ok"') + " ",
                    encoding="utf-8")
    capsys.readouterr()
    assert main(["report", str(copy), "--html", str(tmp_path / "x.html")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "code_check.json" in err[0], err
    assert not (tmp_path / "x.html").exists()


@pytest.mark.parametrize(("change", "field"), [
    (lambda d: d["levels"][0].update(required_mm="57"), "levels[0].required_mm"),
    (lambda d: d.pop("levels"), "levels"),
    (lambda d: d.update(code=3), "code"),
])
def test_a_check_file_of_the_wrong_shape_is_one_line(change, field, tmp_path):
    """Even a file its manifest vouches for is checked before use (a manifest can be
    rewritten too)."""
    from pounding.io.manifest import Manifest
    from pounding.report.code_check import read_code_check

    folder = tmp_path / "check"
    data = {"code": "asce7-22", "title": "t", "levels": [
        {"pair": "B1-B2", "contact": "B1F1-B2F1", "elevation_m": 3.0, "left_mm": 1.0,
         "right_mm": 1.0, "required_mm": 1.4, "gap_mm": 50.0, "ok": True, "clause": "c"}]}
    change(data)
    manifest = Manifest(folder)
    manifest.start("code-check")
    manifest.write_text(folder / "code_check.json", json.dumps(data))
    with pytest.raises(ValueError, match=rf"^--code-check: .*code_check.json: {re.escape(field)}"):
        read_code_check(folder)


def test_a_sweep_keeps_the_check(folders, tmp_path):
    from pounding.io.manifest import Manifest

    model, check, _ = folders
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(f'name = "tiny"\nbase = "{model.as_posix()}"\n[grid]\n'
                     '"contact.gap" = [0.04, 0.06]\n', encoding="utf-8")
    out = tmp_path / "sweep"
    assert main(["sweep", str(sweep), "--out", str(out), "--no-figures", "--scheduler",
                 "synchronous", "--code-check", str(check)]) == 0
    assert Manifest(out).is_ours(out / "code_check.json")
    assert main(["report", str(out)]) == 0
    assert "57.78" in _section((out / "report.html").read_text(encoding="utf-8"))


def test_the_parameters_row_reads_as_numbers_with_their_names():
    """ASCE 7-22's ELF parameters (a building's own values nested) on one line: 4
    significant digits, large ones whole, unset ones left out (not a Python repr)."""
    from pounding.report.code_check import parameters_text

    params = {"sds_g": 1.0, "s1_g": None, "procedure": "elf", "same_property": True,
              "records": 7, "samples": 40000,
              "buildings": {"office": {"T_s": 0.9499999999999983, "C_s": 0.07894736842105277,
                                       "C_s_by": "eq. 12.8-3", "W_kN": 34323.275}}}
    assert parameters_text(params) == (
        "sds_g = 1, procedure = elf, same_property = True, records = 7, samples = 40,000, "
        "office (T_s = 0.95, C_s = 0.07895, C_s_by = eq. 12.8-3, W_kN = 34,323)")
