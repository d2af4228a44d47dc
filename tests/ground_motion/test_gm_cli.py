"""`pounding record` through the CLI entry point, and the record figure."""

from __future__ import annotations

from pathlib import Path

import pytest

from pounding.cli import main
from pounding.ground_motion import harmonic
from pounding.ground_motion.bundled import bundled_folder
from pounding.plot.record import plot_record

RECORDS = Path(str(bundled_folder()))
ELC = RECORDS / "elcentro_1940_IV_ELC9_180_PEER.AT2"
SYLMAR = RECORDS / "northridge_1994_sylmar_county_2col_mps2.dat"
PEKNOLD = RECORDS / "elcentro_1940_NS_peknold_8F10.5.AT2"


def test_record_prints_table(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["record", str(ELC)]) == 0
    assert main(["record", str(SYLMAR), "--units", "m/s2"]) == 0
    out = capsys.readouterr().out
    # PGA [g] and points as in SOURCES.md; PGV [m/s] ≈ 30 and 129 cm/s
    for expected in ("0.3129", "4000", "0.8431", "3000", "0.297", "1.289"):
        assert expected in out


def test_a_text_record_needs_units(capsys: pytest.CaptureFixture[str]) -> None:
    """A text file states no unit and none is assumed (El Centro in g read as m/s2 would
    be ten times too weak): each command that reads records refuses it in one line."""
    from pounding.cli import main as cli

    target = Path(__file__).resolve().parents[2] / "examples" / "spectrum_asce7_site.toml"
    for argv in (["record", str(SYLMAR)], ["spectrum", str(SYLMAR)],
                 ["suite", str(SYLMAR), "--design", str(target), "--t1", "1"]):
        capsys.readouterr()
        assert cli(argv) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert err == [f"error: --units: {SYLMAR} is a plain-text record, which does not "
                       "state its acceleration unit; give --units g, m/s2, cm/s2, gal, mm/s2, "
                       "in/s2 or ft/s2"], argv


def test_record_bundled_lists_the_twelve_records(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["record", "--bundled"]) == 0
    out = capsys.readouterr().out
    # PGA [g] of each as in SOURCES.md: the nine of the suite, the Peknold El Centro (out of
    # the suite), then the Düzce pair
    for expected in ("0.3129", "0.3188", "0.5904", "0.8431", "0.5700", "0.4190", "0.8540",
                     "0.7252", "0.2302", "0.4783", "0.3119", "0.3642", "m/s2 (assumed)",
                     "18000", "kocaeli_1999_duzce_180_RSN1158.AT2",
                     "kocaeli_1999_duzce_270_RSN1158.AT2"):
        assert expected in out
    assert out.count(".AT2") + out.count(".dat") == 12
    assert main(["record", str(ELC), "--bundled"]) == 0
    assert capsys.readouterr().out.count("0.3129") == 2
    assert main(["record"]) == 2
    assert capsys.readouterr().err.strip() == ("error: record: give record FILEs, or "
                                               "--bundled for the records shipped with "
                                               "pounding")


def test_record_plot_one_file_and_several(tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    one = tmp_path / "elc.svg"
    assert main(["record", str(ELC), "--plot", str(one)]) == 0
    assert one.read_text(encoding="utf-8").lstrip().startswith("<?xml")
    folder = tmp_path / "figs"
    assert main(["record", str(ELC), str(PEKNOLD), "--plot", str(folder)]) == 0
    pngs = sorted(p.name for p in folder.iterdir())
    assert pngs == ["elcentro_1940_IV_ELC9_180_PEER.png", "elcentro_1940_NS_peknold_8F10.5.png"]
    assert all((folder / p).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs)


def test_record_text_with_dt_and_units(tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "one.txt"
    path.write_text("0.0\n50.0\n-98.0665\n", encoding="utf-8")  # cm/s²: PGA 0.1 g
    assert main(["record", str(path), "--dt", "0.01", "--units", "cm/s2"]) == 0
    assert "0.1000" in capsys.readouterr().out


def test_record_bad_file_exits_2_with_one_line(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "bad.AT2"
    bad.write_text("IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n 0.1 0.2\n", encoding="utf-8")
    assert main(["record", str(ELC), str(bad)]) == 2
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert "bad.AT2" in err and "line 2" in err and "NPTS = 3 but 2 values" in err
    assert "Traceback" not in err
    assert len(err.splitlines()) == 1
    assert "0.3129" not in captured.out  # nothing printed before the error
    assert main(["record", str(tmp_path / "missing.AT2")]) == 2


def test_plot_record_labels() -> None:
    fig = plot_record(harmonic(1.0, 2.0, duration=1.0, dt=0.01))
    axes = fig.get_axes()
    assert [ax.get_ylabel() for ax in axes] == ["acceleration [g]", "velocity [m/s]",
                                              "displacement [mm]"]
    assert axes[-1].get_xlabel() == "time [s]"
    assert "harmonic 2 Hz" in fig.texts[0].get_text()


@pytest.mark.parametrize("name, text, expected", [
    ("big.txt", "0.1\n0.2\n1e309\n0.3\n",
     "big.txt: line 3: acceleration value 1e309 is not finite: it is beyond the largest "
     "float (1.8e+308) and reads as inf"),
    ("big.AT2", "NPTS= 4, DT= .01 SEC\n 0.1 0.2\n 1e309 0.3\n",
     "big.AT2: line 3: acceleration value 1e309 is not finite"),
    ("g.AT2", "IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n 0.1 0.2\n 1e308\n",
     "g.AT2: line 4: acceleration value 1e+308 g is beyond the largest float"),
])
def test_record_value_beyond_the_largest_float_is_one_line_with_file_and_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], name: str, text: str,
        expected: str) -> None:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    capsys.readouterr()
    assert main(["record", str(path), "--dt", "0.01"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {path}: ") and expected in err[0], err


def test_record_directory_is_named_a_directory(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "records"
    folder.mkdir()
    capsys.readouterr()
    assert main(["record", str(folder)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: {folder}: is a directory, not a record file"]


def test_record_components_of_one_station_plot_side_by_side(tmp_path: Path,
                                                             capsys: pytest.CaptureFixture[str]
                                                             ) -> None:
    # K-NET names the components of one record X.NS, X.EW, X.UD: one stem, so the figures
    # take the whole file names
    knet = Path(__file__).parent / "formats" / "TST0010101010000.NS"
    for comp in ("NS", "EW"):
        (tmp_path / f"TST0010101010000.{comp}").write_bytes(knet.read_bytes())
    files = [str(tmp_path / f"TST0010101010000.{c}") for c in ("NS", "EW")]
    assert main(["record", *files, "--plot", str(tmp_path / "figs")]) == 0
    assert sorted(p.name for p in (tmp_path / "figs").iterdir()) == [
        "TST0010101010000.EW.png", "TST0010101010000.NS.png"]
