"""A record of several series in one file: a text file ``t, NS, EW, V`` read for one
column (``read_text``/``read_record`` ``column``, ``time_column``; ``[record] column`` of a
model file; ``--column``/``--time-column`` of the commands that read records), and a COSMOS
file of several channels read for one from the command line (``--channel``). The values
read are compared with the numbers written; every refusal is one line that names the file
and the choice, never the file's text."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import load_config
from pounding.ground_motion import RecordSuite, read_record, read_suite, read_text
from pounding.units import G

ROOT = Path(__file__).resolve().parents[2]
FORMATS = ROOT / "tests" / "ground_motion" / "formats"
COSMOS_CGS = FORMATS / "CE99999_all.V2C"  # two acceleration channels: 360 deg, 90 deg
COSMOS_CH2_G = [0.0, 0.0125, -0.025, 0.05, -0.2, 0.3, -0.15, 0.075, -0.0375, 0.0, 0.01, -0.01]
TARGET = ROOT / "examples" / "spectrum_asce7_site.toml"

T = 0.5 + 0.01 * np.arange(200)                   # starts at 0.5 s: shifted to 0
NS = 0.30 * np.sin(2 * np.pi * 1.5 * T)
EW = 0.20 * np.sin(2 * np.pi * 0.7 * T + 0.3)
UP = 0.10 * np.cos(2 * np.pi * 3.0 * T)


@pytest.fixture()
def station(tmp_path: Path) -> Path:
    path = tmp_path / "station.txt"
    with path.open("w", encoding="utf-8") as f:
        f.write("# t [s], NS, EW, V [g]\n")
        for row in zip(T, NS, EW, UP, strict=True):
            f.write(", ".join(f"{v:.17g}" for v in row) + "\n")
    return path


def test_each_column_of_a_four_column_file(station: Path) -> None:
    for column, values in ((2, NS), (3, EW), (4, UP)):
        gm = read_text(station, units="g", column=column)
        np.testing.assert_allclose(gm.accel, values * G, rtol=1e-15)
        assert gm.dt == 0.01 and gm.npts == 200 and gm.metadata["t0"] == 0.5
        assert gm.name == f"station (column {column})"
        assert (gm.metadata["columns"], gm.metadata["column"], gm.metadata["time_column"]
                ) == (4, column, 1)
    # read_record and a suite pass the choice on
    np.testing.assert_array_equal(read_record(station, units="g", column=3).accel, EW * G)
    suite = RecordSuite.from_paths([station, station], units="g", column=4)
    assert [m.name for m in suite] == ["station (column 4)"] * 2
    assert read_suite(station, units="g", column=2)[0].pga_g == pytest.approx(0.3, rel=1e-3)


def test_the_time_column_anywhere_or_none(tmp_path: Path) -> None:
    middle = tmp_path / "middle.txt"
    np.savetxt(middle, np.c_[NS, T, EW])          # NS, t, EW
    gm = read_text(middle, units="g", column=3, time_column=2)
    np.testing.assert_allclose(gm.accel, EW * G, rtol=1e-15)
    assert gm.dt == 0.01
    gm = read_text(middle, units="g", column=1, time_column=2)
    np.testing.assert_allclose(gm.accel, NS * G, rtol=1e-15)
    none = tmp_path / "none.txt"
    np.savetxt(none, np.c_[NS, EW, UP])            # no time column: dt given
    gm = read_text(none, units="g", column=1, dt=0.02)
    assert gm.dt == 0.02 and "t0" not in gm.metadata and gm.metadata["time_column"] == 0
    np.testing.assert_allclose(gm.accel, NS * G, rtol=1e-15)
    with pytest.raises(ValueError, match=r"none\.txt: no time column \(the acceleration in "
                                         r"column 2 of 3\); give the time step dt"):
        read_text(none, units="g", column=2, time_column=0)
    # two columns keep their meaning: time, acceleration; or the first alone with dt
    two = tmp_path / "two.txt"
    np.savetxt(two, np.c_[T, NS])
    np.testing.assert_array_equal(read_text(two, units="g").accel,
                                  read_text(two, units="g", column=2).accel)
    assert read_text(two, units="g").name == "two"
    np.testing.assert_allclose(read_text(two, units="g", column=1, dt=0.01).accel, T * G)


def test_bad_choices_are_one_line(station: Path) -> None:
    with pytest.raises(ValueError, match=r"station\.txt: line 2: 4 columns; say which is the "
                                         r"acceleration with column"):
        read_text(station, units="g")
    with pytest.raises(ValueError, match=r"station\.txt: column = 5, but the file has 4 "
                                         r"column\(s\) \(line 2\)"):
        read_text(station, units="g", column=5)
    with pytest.raises(ValueError, match=r"station\.txt: time_column = 7, but the file has 4"):
        read_text(station, units="g", column=2, time_column=7)
    with pytest.raises(ValueError, match=r"column and time_column are both 2"):
        read_text(station, units="g", column=2, time_column=2)
    for bad in (0, -1, 2.0, True, "2"):
        with pytest.raises(ValueError, match=r"^column: a column number, an integer from 1"):
            read_text(station, units="g", column=bad)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^time_column: a column number, an integer from 0"):
        read_text(station, units="g", column=2, time_column=-1)
    # a choice for another format is refused, naming the format
    at2 = ROOT / "src" / "pounding" / "data" / "records" / "tabas_1978_TAB_L1_RSN143.AT2"
    with pytest.raises(ValueError, match=r"TAB_L1_RSN143\.AT2: column is for plain-text "
                                         r"records; this is a PEER AT2 file \(got column = 2\)"):
        read_record(at2, column=2)
    with pytest.raises(ValueError, match=r"channel is for COSMOS files of several channels; "
                                         r"this is a PEER AT2 file"):
        read_record(at2, channel=1)
    with pytest.raises(ValueError, match=r"station\.txt: channel is for COSMOS files .* "
                                         r"plain-text file"):
        read_record(station, units="g", channel=2)
    with pytest.raises(ValueError, match=r"time_column is for plain-text records; this is a "
                                         r"COSMOS V1/V2 file"):
        read_record(COSMOS_CGS, time_column=1)
    # a COSMOS channel through read_record
    two = read_record(COSMOS_CGS, channel=2)
    np.testing.assert_allclose(two.accel, np.array(COSMOS_CH2_G) * G, rtol=1e-15)


def _model(folder: Path, record: str) -> Path:
    text = (ROOT / "examples" / "seed_sdof_pair.toml").read_text(encoding="utf-8")
    path = folder / "model.toml"
    path.write_text(text.replace('bundled = "el_centro"', record), encoding="utf-8")
    return path


def test_a_model_file_reads_the_column_it_names(station: Path, capsys) -> None:
    folder = station.parent
    cfg = load_config(_model(folder, 'file = "station.txt"\nunits = "g"\ncolumn = 3'))
    _, motion, _ = cfg.build()
    np.testing.assert_allclose(motion.accel, EW * G, rtol=1e-15)
    for record, message in (
            ('file = "station.txt"\nunits = "g"', "station.txt: line 2: 4 columns; say which "
                                                  "is the acceleration with column"),
            ('file = "station.txt"\nunits = "g"\ncolumn = 9', "column = 9, but the file has "
                                                              "4 column(s)"),
            ('file = "station.txt"\nunits = "g"\ncolumn = 2.0', "record.column: must be an "
                                                                "integer (got 2.0)"),
            ('file = "station.txt"\nunits = "g"\ncolumn = 0', "record.column:"),
            ('bundled = "el_centro"\ncolumn = 2', "record.column: only with file = ..."),
            ('bundled = "el_centro"\nchannel = 1', "record.channel: only with file = ...")):
        model = _model(folder, record)
        assert main(["run", str(model), "--out", str(folder / "out"), "--no-figures"]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and message in err[0], (record, err)
        assert not (folder / "out").exists()


def test_the_commands_take_column_time_column_and_channel(station: Path, capsys) -> None:
    folder = station.parent
    assert main(["record", str(station), "--units", "g", "--column", "2"]) == 0
    assert "0.3000" in capsys.readouterr().out          # PGA of the N–S column [g]
    assert main(["record", str(station), "--units", "g"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "4 columns; say which is the acceleration" in err[0]
    assert main(["record", str(COSMOS_CGS), "--channel", "2"]) == 0
    assert "0.3000" in capsys.readouterr().out          # channel 2's peak: 0.3 g
    assert main(["record", str(COSMOS_CGS)]) == 2
    assert "--channel N on the command line" in capsys.readouterr().err
    assert main(["spectrum", str(station), "--units", "g", "--column", "4", "--periods",
                 "0.5,1", "--csv", str(folder / "s.csv")]) == 0
    capsys.readouterr()
    assert "station.txt (column 4)" in (folder / "s.csv").read_text(encoding="utf-8")
    assert main(["suite", str(station), "--units", "g", "--column", "3", "--design",
                 str(TARGET), "--t1", "1"]) == 0
    assert "station (column 3)" in capsys.readouterr().out
    assert main(["gap", str(ROOT / "examples" / "seed_sdof_pair.toml"), "--records",
                 str(station), "--units", "g", "--column", "2", "--time-column", "1"]) == 0
    capsys.readouterr()
    assert main(["record", str(station), "--units", "g", "--column", "0"]) == 2
    assert "--column" in capsys.readouterr().err
