"""A file given where a record, a matrix or a design spectrum belongs may be anything — a
password file, a key. Whatever the entry point (the Python readers, every command that
reads such files, a model file, a study file, a sweep's stored error column and its
report), pounding refuses it in one line that names the file, and never shows any of its
text: every file here carries a marker, and the marker must appear nowhere."""

from __future__ import annotations

import zipfile
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main

MARKER = "Zq7-MARKER-k9Xw"
ROOT = Path(__file__).resolve().parents[1]
TARGET = ROOT / "examples" / "spectrum_asce7_site.toml"
FORMATS = ROOT / "tests" / "ground_motion" / "formats"
PASSWD = f"{MARKER}:x:0:0:root:/root:/bin/bash\ndaemon:{MARKER}:1:1\n"


def _files(folder: Path) -> dict[str, Path]:
    """Files that are not what they are given as, each holding the marker; by the reader
    path each one takes."""
    texts = {
        # no format: refused by the reader dispatch
        "passwd.dat": PASSWD,
        # sniffed as AT2 (NPTS= in the first lines), bad values on the header and data lines
        "sniff_at2.txt": f"NPTS={MARKER}, DT={MARKER}\n{MARKER} 1 2\n",
        "sniff_at2_data.txt": f"NPTS= 3, DT= 0.01 SEC\n0.1 0.2\n0.3 {MARKER}\n",
        # sniffed as K-NET (first line 'Origin Time') and COSMOS (its title line)
        "sniff_knet.txt": f"Origin Time       {MARKER}\n" + f"{MARKER}\n" * 20,
        "sniff_cosmos.txt": (f"Corrected accel (Format v01.20 with 2 text lines) {MARKER}\n"
                             f"{MARKER}\n{MARKER}\n"),
        # a format forced by the suffix
        "forced.AT2": PASSWD,
        "forced.NS": PASSWD,
        "forced.V2": PASSWD,
        # numbers first, then the marker: a plain-text record with a bad line
        "late.txt": f"0.1\n0.2\n{MARKER}\n",
    }
    # real K-NET and COSMOS files with one header field or value replaced by the marker
    knet = (FORMATS / "TST0010101010000.NS").read_text(encoding="utf-8")
    cosmos = (FORMATS / "CE99999_chan1_360.V2c").read_text(encoding="utf-8")
    for name, text, old, new in (
            ("freq.NS", knet, "100Hz", MARKER), ("scale.NS", knet, "(gal)", f"({MARKER})"),
            ("scale2.NS", knet, "7845(gal)", MARKER), ("count.NS", knet, "9006", MARKER),
            ("units.V2c", cosmos, "units=cm/sec2(04)", f"units={MARKER}(11)"),
            ("value.V2c", cosmos, "1.250000E+00", f"1.25{MARKER}"),
            ("block.V2c", cosmos, "2 Comment line(s)", MARKER)):
        assert old in text
        texts[name] = text.replace(old, new, 1)
    out = {}
    for name, text in texts.items():
        out[name] = folder / name
        out[name].write_text(text, encoding="utf-8")
    return out


def _matrix_files(folder: Path) -> dict[str, Path]:
    out = {name: folder / name for name in ("m.csv", "m.txt", "m.npy", "m2.npy", "m.npz",
                                             "z.npz", "m.mtx", "m2.mtx")}
    out["m.csv"].write_text(PASSWD, encoding="utf-8")
    out["m.txt"].write_text(f"1 2\n2 {MARKER}\n", encoding="utf-8")
    out["m.npy"].write_text(PASSWD, encoding="utf-8")
    header = f"{{'descr': '<f8', 'fortran_order': False, 'shape': ({MARKER}), }}".encode()
    header += b" " * (127 - 10 - len(header) % 64) + b"\n"
    out["m2.npy"].write_bytes(b"\x93NUMPY\x01\x00" + len(header).to_bytes(2, "little")
                              + header)
    with zipfile.ZipFile(out["m.npz"], "w") as z:  # a zip of other files, named .npz
        z.writestr(f"{MARKER}.txt", PASSWD)
    with zipfile.ZipFile(out["z.npz"], "w") as z:  # an .npz whose array M is not .npy
        z.writestr("M.npy", PASSWD)
        z.writestr("K.npy", PASSWD)
    out["m.mtx"].write_text(f"%%MatrixMarket matrix {MARKER} real general\n2 2\n",
                            encoding="utf-8")
    out["m2.mtx"].write_text(f"%%MatrixMarket matrix array real general\n2 2\n1\n{MARKER}\n"
                             "1\n1\n", encoding="utf-8")
    return out


def _spectrum_files(folder: Path) -> list[Path]:
    files = [folder / "s.csv", folder / "s.toml", folder / "t.toml", folder / "u.csv"]
    files[0].write_text(PASSWD, encoding="utf-8")
    files[1].write_text(PASSWD, encoding="utf-8")
    files[2].write_text(f'"{MARKER}" = 1\n', encoding="utf-8")
    files[3].write_text(f"period_s,sa_g\n0,1\n1,{MARKER}\n", encoding="utf-8")
    return files


def _assert_hidden(exc: BaseException) -> None:
    text = f"{exc} {exc!r}"
    cause = exc.__cause__
    while cause is not None:  # a chained cause is printed with a traceback
        text += f" {cause} {cause!r}"
        cause = cause.__cause__
    assert MARKER not in text
    assert "\n" not in str(exc)


def test_the_python_readers_never_show_a_file(tmp_path: Path) -> None:
    from pounding.ground_motion import RecordSuite, read_at2, read_record, read_text
    from pounding.ground_motion.readers import read_cosmos, read_knet
    from pounding.spectra import DesignSpectrum
    from pounding.structure import read_matrix

    records = _files(tmp_path)
    for path in records.values():
        for read in (read_record, read_at2, read_knet, read_cosmos):
            for units in (None, "gal"):
                try:  # each reader on every file: the AT2 reader given dt takes a K-NET
                    read(path, dt=0.01, units=units)  # file's counts as data
                except ValueError as exc:
                    _assert_hidden(exc)
                    assert str(path) in str(exc)
                else:
                    assert read is read_at2 and path.suffix == ".NS"
        with pytest.raises(ValueError) as info:
            read_text(path, dt=0.01, units="gal")
        _assert_hidden(info.value)
    with pytest.raises(ValueError) as info:
        RecordSuite.from_folder(tmp_path, dt=0.01, units="gal")
    _assert_hidden(info.value)
    # the refusal of a file in no format: its name, its size and the formats read
    with pytest.raises(ValueError) as info:
        read_record(records["passwd.dat"])
    assert str(info.value).startswith(f"{records['passwd.dat']}: not a record format pounding "
                                      f"reads ({len(PASSWD)} bytes; line 1")
    assert "PEER AT2" in str(info.value)

    for path in _matrix_files(tmp_path).values():
        with pytest.raises(ValueError) as info:
            read_matrix(path, "M")
        _assert_hidden(info.value)
    for path in _spectrum_files(tmp_path):
        with pytest.raises(ValueError) as info:
            DesignSpectrum.from_file(path)
        _assert_hidden(info.value)


def _cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str]:
    capsys.readouterr()
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out + out.err


def _model(folder: Path, record: str, name: str = "model.toml") -> Path:
    text = (ROOT / "examples" / "seed_sdof_pair.toml").read_text(encoding="utf-8")
    path = folder / name
    path.write_text(text.replace('bundled = "el_centro"', record), encoding="utf-8")
    return path


def test_no_command_shows_a_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    files = _files(tmp_path)
    before = set(tmp_path.iterdir())
    model = _model(tmp_path, 'bundled = "el_centro"', "bundled.toml")
    for name in ("passwd.dat", "sniff_at2.txt", "late.txt", "freq.NS", "units.V2c"):
        path = files[name]
        for argv in (["record", str(path), "--units", "gal", "--dt", "0.01"],
                     ["spectrum", str(path), "--units", "gal", "--dt", "0.01"],
                     ["suite", str(path), "--design", str(TARGET), "--t1", "1",
                      "--units", "gal", "--dt", "0.01"],
                     ["gap", str(model), "--records", str(path), "--units", "gal", "--dt",
                      "0.01"],
                     ["run", str(_model(tmp_path, f'file = "{name}"\nunits = "gal"\ndt = 0.01',
                                        f"m_{name}.toml")), "--out", str(tmp_path / "r")]):
            code, text = _cli(capsys, *argv)
            assert code == 2 and MARKER not in text, (argv, text)
            assert len(text.strip().splitlines()) == 1 and name in text, (argv, text)
    for spectrum in _spectrum_files(tmp_path):
        for argv in (["spectrum", str(files["passwd.dat"]), "--design", str(spectrum),
                      "--plot", str(tmp_path / "p.png")],
                     ["suite", "--design", str(spectrum), "--t1", "1"]):
            code, text = _cli(capsys, *argv)
            assert code == 2 and MARKER not in text, (argv, text)
    # the second horizontal component of a model with buildings in plan
    plan = (ROOT / "examples" / "torsional_pair.toml").read_text(encoding="utf-8")
    second = 'second = "kocaeli_1999_duzce_270_RSN1158"'
    assert second in plan
    for name in ("passwd.dat", "sniff_at2.txt", "freq.NS"):
        m = tmp_path / f"plan_{name}.toml"
        m.write_text(plan.replace(second, f'second_file = "{name}"\nunits = "gal"\ndt = 0.01'),
                     encoding="utf-8")
        code, text = _cli(capsys, "run", str(m), "--out", str(tmp_path / "r"))
        assert code == 2 and MARKER not in text and name in text, (name, text)
        assert len(text.strip().splitlines()) == 1
    # a matrix file in a model file
    matrices = _matrix_files(tmp_path)
    for path in matrices.values():
        m = tmp_path / f"mat_{path.name}.toml"
        m.write_text(f'[record]\nbundled = "el_centro"\n[[building]]\nmatrices = {{ M = '
                     f'"{path.name}", K = "{path.name}" }}\nelevations = [3.0, 6.0]\n'
                     '[[building]]\nmass = 2e5\nperiod = 0.5\n[contact]\nlaw = '
                     '"kelvin-voigt"\nk = 9.3e8\ne = 0.65\ngap = 0.02\n', encoding="utf-8")
        code, text = _cli(capsys, "run", str(m), "--out", str(tmp_path / "r"))
        assert code == 2 and MARKER not in text, (path.name, text)
    made = set(tmp_path.iterdir()) - before
    assert all(p.suffix in (".toml", ".csv", ".npy", ".npz", ".mtx", ".txt") for p in made)
    assert not (tmp_path / "r").exists() and not (tmp_path / "p.png").exists()


def test_studies_never_store_or_show_a_file(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    files = _files(tmp_path)
    good = tmp_path / "good.txt"
    t = np.arange(0.0, 1.0, 0.01)
    np.savetxt(good, np.c_[t, 0.3 * np.sin(2 * np.pi * t)])
    _model(tmp_path, 'file = "good.txt"\nunits = "g"')
    (tmp_path / "frag.toml").write_text(
        'name = "frag"\nbase = "model.toml"\n[suite]\nfiles = ["passwd.dat"]\n'
        '[intensity]\nmeasure = "pga"\nlevels = [0.1, 0.2]\n[[limit_state]]\n'
        'demand = "pounding"\n', encoding="utf-8")
    (tmp_path / "mit.toml").write_text(
        'name = "mit"\nbase = "model.toml"\nrecords = ["passwd.dat"]\n[[option]]\n'
        'name = "bare gap"\n', encoding="utf-8")
    for argv in (["fragility", str(tmp_path / "frag.toml"), "--out", str(tmp_path / "f")],
                 ["mitigate", str(tmp_path / "mit.toml"), "--out", str(tmp_path / "m")]):
        code, text = _cli(capsys, *argv)
        assert code == 2 and MARKER not in text and "passwd.dat" in text, (argv, text)
        assert len(text.strip().splitlines()) == 1
    # a sweep stores each case's error in its table, and its report shows them
    (tmp_path / "sweep.toml").write_text(
        'name = "leak"\nbase = "model.toml"\n[grid]\n"record.file" = ['
        + ", ".join(f'"{p.name}"' for p in files.values()) + "]\n", encoding="utf-8")
    code, text = _cli(capsys, "sweep", str(tmp_path / "sweep.toml"), "--out",
                      str(tmp_path / "s"), "--scheduler", "synchronous")
    assert code == 0 and MARKER not in text, text
    code, text = _cli(capsys, "report", str(tmp_path / "s"))
    assert code == 0 and MARKER not in text
    import pandas as pd

    table = pd.read_parquet(tmp_path / "s" / "results.parquet")
    assert (table["status"] == "error").all() and len(table) == len(files)
    for path in (tmp_path / "s").rglob("*"):
        if path.is_file():
            assert MARKER.encode() not in path.read_bytes(), path


def test_a_broken_toml_file_is_named_with_its_position_not_its_keys(tmp_path: Path,
                                                                    capsys) -> None:
    """tomllib quotes a key declared twice (``Cannot declare ('k',) twice``): a model file,
    a study file and a spectrum file say where the file is broken, not what it holds."""
    broken = tmp_path / "m.toml"
    broken.write_text(f"[{MARKER}]\nx = 1\n[{MARKER}]\ny = 2\n")
    for argv in (["run", str(broken), "--out", str(tmp_path / "o")],
                 ["mitigate", str(broken), "--out", str(tmp_path / "o")],
                 ["suite", "--design", str(broken), "--t1", "1.0"]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert MARKER not in err and "(at line 3, column" in err, (argv, err)
    assert not (tmp_path / "o").exists()


def test_a_column_or_channel_chosen_never_shows_the_file(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    """The paths that choose a column of a text file or a channel of a COSMOS file: the
    marker in the column read, in a column not read, in a file of no format, in a COSMOS
    channel's orientation — never shown, from Python, a model file or a command."""
    from pounding.ground_motion import read_record, read_text

    files = {
        "read.txt": f"0 0.1 0.2\n0.01 {MARKER} 0.3\n",          # in the column read
        "other.txt": f"0 0.1 0.2\n0.01 0.2 {MARKER}\n",         # in a column not read
        "many.txt": f"0 0.1 0.2 0.3\n0.01 0.2 {MARKER} 0.4\n",  # several columns, no column
        "passwd.dat": PASSWD,
    }
    cosmos = (FORMATS / "CE99999_all.V2C").read_text(encoding="utf-8")
    assert "360 deg" in cosmos
    files["orient.V2C"] = cosmos.replace("360 deg", MARKER, 1)   # two channels, no choice
    paths = {}
    for name, text in files.items():
        paths[name] = tmp_path / name
        paths[name].write_text(text, encoding="utf-8")
    for name, path in paths.items():
        for kwargs in ({"column": 2}, {"column": 2, "time_column": 0, "dt": 0.01},
                       {"channel": 1}, {}):
            for read in (read_record, read_text):
                if read is read_text and "channel" in kwargs:
                    continue
                try:
                    read(path, units="g", **kwargs)
                except ValueError as exc:
                    _assert_hidden(exc)
                    assert str(path) in str(exc)
        for argv in (["record", str(path), "--units", "g", "--column", "2"],
                     ["record", str(path), "--units", "g", "--channel", "1"],
                     ["spectrum", str(path), "--units", "g", "--column", "2"],
                     ["suite", str(path), "--design", str(TARGET), "--t1", "1", "--units",
                      "g", "--column", "2"],
                     ["record", str(path), "--units", "g"]):
            code, text = _cli(capsys, *argv)
            assert MARKER not in text, (argv, text)
            if code != 0:
                assert code == 2 and len(text.strip().splitlines()) == 1, (argv, text)
        model = _model(tmp_path, f'file = "{name}"\nunits = "g"\ncolumn = 2', f"c_{name}.toml")
        code, text = _cli(capsys, "run", str(model), "--out", str(tmp_path / "r"))
        assert code == 2 and MARKER not in text and name in text, (name, text)
    # the COSMOS file's orientation is not shown where it is not an orientation
    code, text = _cli(capsys, "record", str(paths["orient.V2C"]))
    assert code == 2 and "holds 2 acceleration channels (1 ?; 2 90 deg)" in text, text
    assert not (tmp_path / "r").exists()
