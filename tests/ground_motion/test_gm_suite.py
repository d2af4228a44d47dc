"""Record suites: from a folder, a list of files and the bundled records (whose values are
checked against their SOURCES.md in test_gm_records.py)."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from pounding.ground_motion import (
    RecordSuite,
    bundled_records,
    bundled_suite,
    load_bundled,
    read_record,
    read_suite,
)
from pounding.ground_motion.bundled import bundled_folder

FORMATS = Path(__file__).parent / "formats"
BUNDLED = Path(str(bundled_folder()))


# ------------------------------------------------------------------- the bundled suite
def test_bundled_suite_is_the_nine_records_in_manifest_order() -> None:
    suite = bundled_suite()
    assert suite.name == "bundled" and len(suite) == 9
    assert [Path(p).name for p in suite.paths] == bundled_records()
    for gm, path in zip(suite, suite.paths, strict=True):
        assert Path(path).is_file()  # a real file inside the installed package
        assert gm.name == Path(path).stem
    assert suite[0] is load_bundled("elcentro_1940_IV_ELC9_180_PEER")
    assert suite["tabas_1978_TAB_L1_RSN143.AT2"] is suite[5]


# ------------------------------------------------------------------- folders and lists
def _folder(tmp_path: Path) -> Path:
    folder = tmp_path / "my records"
    folder.mkdir()
    for name in ("TST0010101010000.NS", "CE99999_chan1_360.V2c", "CE99999_all.V2C"):
        shutil.copy(FORMATS / name, folder / name)
    shutil.copy(BUNDLED / "tabas_1978_TAB_L1_RSN143.AT2", folder / "a_tabas.AT2")
    (folder / "README.md").write_text("# my records\nfrom the network\n", encoding="utf-8")
    (folder / ".DS_Store").write_bytes(b"\x00\x01")
    (folder / "old").mkdir()
    return folder


def test_suite_from_folder_reads_every_record_and_reports_the_rest(tmp_path: Path) -> None:
    folder = _folder(tmp_path)
    suite = RecordSuite.from_folder(folder)
    assert suite.name == "my records"
    assert suite.names == ("CE99999_chan1_360", "TST0010101010000.NS", "a_tabas")
    assert [Path(p).name for p in suite.paths] == \
        ["CE99999_chan1_360.V2c", "TST0010101010000.NS", "a_tabas.AT2"]
    np.testing.assert_array_equal(suite["a_tabas"].accel,
                                  load_bundled("tabas_1978_TAB_L1_RSN143").accel)
    skipped = {Path(s.path).name: s.reason for s in suite.skipped}
    assert sorted(skipped) == ["CE99999_all.V2C", "README.md"]  # not hidden files, folders
    assert "holds 2 acceleration channels" in skipped["CE99999_all.V2C"]
    assert skipped["README.md"].startswith(f"{folder / 'README.md'}: not a record format "
                                           "pounding reads (")
    assert "from the network" not in skipped["README.md"]  # the file's text is never shown
    assert all("\n" not in s.reason for s in suite.skipped)


def test_suite_from_folder_with_no_record_is_one_line(tmp_path: Path) -> None:
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(ValueError, match=r"empty: no record files in this folder$"):
        RecordSuite.from_folder(empty)
    (empty / "notes.txt").write_text("to do\n", encoding="utf-8")
    with pytest.raises(ValueError) as info:
        RecordSuite.from_folder(empty)
    assert str(info.value) == (f"{empty}: none of its 1 files is a record pounding reads "
                               f"(first: {empty / 'notes.txt'}: not a record format pounding "
                               "reads (6 bytes; line 1, its first line that is not blank or a "
                               "'#' comment, is neither numbers nor a header of a format "
                               "read); it reads K-NET/KiK-net ASCII, "
                               "COSMOS V1/V2, PEER AT2, plain text (one column, two: "
                               "time, acceleration, or several with a column chosen))")
    with pytest.raises(FileNotFoundError, match="nowhere: no such folder"):
        RecordSuite.from_folder(tmp_path / "nowhere")
    with pytest.raises(NotADirectoryError, match="notes.txt: is a file, not a folder"):
        RecordSuite.from_folder(empty / "notes.txt")


def test_suite_from_paths_keeps_their_order_and_refuses_a_bad_one(tmp_path: Path) -> None:
    paths = [FORMATS / "TST0010101010000.NS", BUNDLED / "elcentro_1940_IV_ELC9_180_PEER.AT2"]
    suite = RecordSuite.from_paths(paths, name="two")
    assert suite.names == ("TST0010101010000.NS", "elcentro_1940_IV_ELC9_180_PEER")
    assert suite.paths == tuple(str(p) for p in paths)
    assert suite.skipped == ()
    with pytest.raises(ValueError, match=r"CE99999_all\.V2C: holds 2 acceleration channels"):
        RecordSuite.from_paths([*paths, FORMATS / "CE99999_all.V2C"])
    with pytest.raises(ValueError, match=r"record suite 'records': no record files given"):
        RecordSuite.from_paths([])
    with pytest.raises(FileNotFoundError, match="missing.AT2: no such file"):
        RecordSuite.from_paths([tmp_path / "missing.AT2"])


def test_suite_lookup_by_position_and_name() -> None:
    suite = RecordSuite.from_paths([FORMATS / "TST0010101010000.NS",
                                    FORMATS / "CE99999_chan1_360.V2c"])
    assert suite[1] is suite["CE99999_chan1_360"] is suite["CE99999_chan1_360.V2c"]
    assert list(suite) == [suite[0], suite[1]]
    with pytest.raises(KeyError, match=r"no record named 'x'; the records are "
                                       r"TST0010101010000\.NS, CE99999_chan1_360"):
        suite["x"]
    with pytest.raises(IndexError):
        suite[2]
    with pytest.raises(ValueError, match=r"record suite 'none': no record"):
        RecordSuite("none", (), ())


def test_read_suite_takes_bundled_a_folder_a_file_or_a_list(tmp_path: Path) -> None:
    assert read_suite("bundled").names == bundled_suite().names
    assert read_suite(_folder(tmp_path)).name == "my records"
    one = read_suite(FORMATS / "TST0010101010000.NS")
    assert one.name == "TST0010101010000" and len(one) == 1
    assert len(read_suite([FORMATS / "TST0010101010000.NS",
                           FORMATS / "CE99999_chan1_360.V2c"])) == 2
    with pytest.raises(ValueError, match=r"'bundled': dt is for record files"):
        read_suite("bundled", dt=0.01)
    with pytest.raises(ValueError, match=r"'bundled': units and column are for record files"):
        read_suite("bundled", units="g", column=2)
    text = tmp_path / "one.txt"
    text.write_text("0.1\n0.2\n", encoding="utf-8")
    gm = read_suite([text], dt=0.01, units="g")[0]
    assert gm.units_read == "g" and gm.dt == 0.01
    assert read_record(text, dt=0.01, units="g").accel.tolist() == gm.accel.tolist()
