"""`pounding spectrum` through the CLI entry point: the table, the CSV (read back against
the API), the figure, RotD pairs, and bad input as one line with exit status 2 and nothing
written."""

from __future__ import annotations

import csv
import dataclasses
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.ground_motion import el_centro
from pounding.spectra import response_spectrum, rotd_spectrum
from pounding.units import G

ROOT = Path(__file__).resolve().parents[2]
# the bundled El Centro file, wherever pounding/data keeps it
ELC = next((ROOT / "src" / "pounding" / "data").rglob("elcentro_1940_IV_ELC9_180_PEER.AT2"))


def _rows(path: Path) -> list[dict[str, str]]:
    lines = path.read_text(encoding="utf-8").splitlines()
    assert not lines[0].startswith("#")  # the header first: pandas, Excel and R read it as is
    return list(csv.DictReader(lines))


def test_table_csv_and_plot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out_csv, png = tmp_path / "s.csv", tmp_path / "s.png"
    ec8 = tmp_path / "ec8.toml"
    ec8.write_text('eurocode8 = { agr = 0.3, ground_type = "C" }\n', encoding="utf-8")
    assert main(["spectrum", str(ELC), "--damping", "0.05,0.02", "--periods", "0.1:3:7",
                 "--csv", str(out_csv), "--plot", str(png), "--design", str(ec8)]) == 0
    out = capsys.readouterr().out
    ref = response_spectrum(el_centro(), np.geomspace(0.1, 3.0, 7), [0.05, 0.02])
    for text in ("PGA 0.3129 g", "Sd [m] ζ=5%", "PSA [g] ζ=2%", "Sa,abs [g] ζ=5%",
                 f"{ref.psa_g[0, 3]:.4f}", f"{ref.sa_abs_g[1, 6]:.4f}"):
        assert text in out, text
    rows = _rows(out_csv)
    assert list(rows[0]) == ["record", "damping", "period_s", "sd_m", "psv_m_s", "psa_g",
                             "sa_abs_g"]
    assert len(rows) == 14 and rows[0]["record"] == ELC.name
    got = np.array([[float(r[k]) for k in ("sd_m", "psv_m_s", "psa_g", "sa_abs_g")]
                    for r in rows]).reshape(2, 7, 4)
    for i, want in enumerate((ref.sd, ref.psv, ref.psa_g, ref.sa_abs_g)):
        np.testing.assert_allclose(got[:, :, i], want, rtol=1e-9)
    assert png.stat().st_size > 10_000


def test_rotd_pairs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    gm = el_centro()
    back = tmp_path / "back.txt"
    back.write_text("\n".join(repr(float(x)) for x in gm.accel[::-1]) + "\n", encoding="utf-8")
    out_csv = tmp_path / "r.csv"
    assert main(["spectrum", str(ELC), str(back), "--rotd", "--dt", "0.01", "--units", "m/s2",
                 "--periods", "0.2,1", "--csv", str(out_csv)]) == 2  # ELC states g
    assert "the header states units 'g' but units='m/s2' was given" in capsys.readouterr().err
    back.write_text("\n".join(repr(float(x) / G) for x in gm.accel[::-1]) + "\n",
                    encoding="utf-8")
    assert main(["spectrum", str(ELC), str(back), "--rotd", "--dt", "0.01", "--units", "g",
                 "--periods", "0.2,1", "--csv", str(out_csv)]) == 0
    out = capsys.readouterr().out
    for text in ("H1 ζ=5%", "GeoMean ζ=5%", "RotD50 ζ=5%", "RotD100 ζ=5%", "Boore 2010"):
        assert text in out, text
    rows = _rows(out_csv)
    assert list(rows[0]) == ["record", "measure", "damping", "period_s", "sd_m", "psv_m_s",
                             "psa_g"]
    assert [r["measure"] for r in rows[::2]] == ["H1", "H2", "GeoMean", "RotD50", "RotD100"]
    assert rows[0]["record"] == f"{ELC.name} + back.txt"
    r = rotd_spectrum(gm, dataclasses.replace(gm, accel=gm.accel[::-1].copy()), [0.2, 1.0])
    assert float(rows[9]["psa_g"]) == pytest.approx(r.psa_g(r.rotd100)[0, 1], rel=1e-9)


@pytest.mark.parametrize("args, message", [
    (["--periods", "0,1"], "--periods: every period must be finite and > 0 s (got 0)"),
    (["--periods", "-0.5:2:10"], "--periods: every period must be finite and > 0 s "
                                 "(got -0.5)"),
    (["--periods", "1:2"], "--periods: give FIRST:LAST:N"),
    (["--damping", "0.05,1"], "--damping: every damping ratio must be in [0, 1), a fraction "
                              "of critical (0.05 = 5 %) (got 1)"),
    (["--damping", "-0.02"], "(got -0.02)"),
    (["--damping", "5%"], "--damping: give comma-separated numbers (got '5%')"),
    (["--rotd"], "--rotd: give the records two at a time, the two horizontal components of "
                 "each motion (got 1 records)"),
    (["--design", "{tmp}/nope.toml"], "nope.toml: no such spectrum file"),
])
def test_bad_input_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                               args: list[str], message: str) -> None:
    out_csv, png = tmp_path / "s.csv", tmp_path / "s.png"
    argv = ["spectrum", str(ELC), *(a.format(tmp=tmp_path) for a in args),
            "--csv", str(out_csv), "--plot", str(png)]
    capsys.readouterr()
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and message in err[0], err
    assert not out_csv.exists() and not png.exists()


def test_missing_and_folder_records(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    capsys.readouterr()
    assert main(["spectrum", str(tmp_path / "none.AT2")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "none.AT2" in err[0]
    assert main(["spectrum", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: {tmp_path}: is a directory, not a record file"]
