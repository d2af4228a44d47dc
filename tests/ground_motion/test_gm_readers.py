"""Readers on small synthesised files: every header variant, units, line ends and bad input.

Expected values are the numbers written into each file, converted by hand.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pounding.ground_motion import read_at2, read_record, read_text
from pounding.ground_motion.readers import UnitsRequired
from pounding.units import G

PEER_HEADER = (
    "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\n"
    "IMPERIAL VALLEY 5/19/40 0439, EL CENTRO ARRAY #9, 180 (USGS STATION 117)\n"
    "ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.2 Hz LP=15.0 Hz\n"
)
VALUES_G = [0.01, -0.02, 0.03, -0.04, 0.05, -0.25, 0.07]


def _write(tmp_path: Path, name: str, text: str | bytes) -> Path:
    path = tmp_path / name
    if isinstance(text, str):
        text = text.encode("utf-8")
    path.write_bytes(text)
    return path


def _data_lines(values: list[float], per_line: int = 5, fmt: str = "{:15.7E}") -> str:
    rows = [values[i:i + per_line] for i in range(0, len(values), per_line)]
    return "".join("".join(fmt.format(v) for v in row) + "\n" for row in rows)


# ------------------------------------------------------------------- header variants
@pytest.mark.parametrize("npts_line", [
    "NPTS=  7, DT= .01000 SEC",            # PEER
    "NPTS=      7  DT=   .0100 SEC,",      # NGA-West2, trailing comma
    "NPTS=      7  DT=   .0100 SEC",       # NGA-West2, no comma (Newhall)
    "DT= 0.01 SEC, NPTS= 7",               # reversed order
    "NPTS=7,DT=1.0E-02SEC",                # packed
])
def test_npts_dt_line_variants(tmp_path: Path, npts_line: str) -> None:
    path = _write(tmp_path, "r.AT2", PEER_HEADER + npts_line + "\n" + _data_lines(VALUES_G))
    gm = read_at2(path)
    assert gm.npts == 7
    assert gm.dt == pytest.approx(0.01, rel=1e-12)
    np.testing.assert_allclose(gm.accel, np.array(VALUES_G) * G, rtol=1e-12)
    assert gm.units_read == "g"
    assert gm.metadata["header"][-1] == npts_line


def test_crlf_and_no_trailing_newline(tmp_path: Path) -> None:
    text = PEER_HEADER + "NPTS=      7  DT=   .0200 SEC,      \n" + _data_lines(VALUES_G)
    crlf = text.replace("\n", "\r\n").rstrip("\r\n")  # CRLF, last line without an end
    assert not crlf.endswith("\n")
    gm = read_at2(_write(tmp_path, "crlf.AT2", crlf))
    assert gm.npts == 7 and gm.dt == pytest.approx(0.02)
    np.testing.assert_allclose(gm.accel, np.array(VALUES_G) * G, rtol=1e-12)


def test_cr_cr_lf_line_ends_keep_line_numbers(tmp_path: Path) -> None:
    text = PEER_HEADER + "NPTS= 7, DT= .01 SEC\n" + _data_lines(VALUES_G)
    bad = (text + "   oops\n").replace("\n", "\r\r\n")
    with pytest.raises(ValueError, match=r"crcrlf\.AT2: line 7: the line is not a number"):
        read_at2(_write(tmp_path, "crcrlf.AT2", bad))
    ok = (PEER_HEADER + "NPTS= 7, DT= .01 SEC\n" + _data_lines(VALUES_G)).replace("\n", "\r\r\n")
    assert read_at2(_write(tmp_path, "ok.AT2", ok)).npts == 7


def test_eight_values_per_line_plain_fixed_width(tmp_path: Path) -> None:
    values = [0.0063, 0.00364, -0.00128, 0.0136, 0.3188, -0.024, 0.00416, 0.02779, -0.00063]
    text = ("Data for El Centro 1940 North South Component (Peknold Version)\n"
            "9 points at equal spacing of 0.02 sec Points are listed in the format of 8F10.5\n"
            "The units are (g)\n"
            "NPTS=  9, DT= .02000 SEC\n" + _data_lines(values, 8, "{:10.5f}").rstrip("\n"))
    gm = read_at2(_write(tmp_path, "peknold.AT2", text))
    assert gm.npts == 9 and gm.dt == 0.02
    assert gm.pga_g == pytest.approx(0.3188, rel=1e-12)
    assert gm.units_read == "g"


def test_old_seven_line_header_with_begin_end_markers(tmp_path: Path) -> None:
    text = ("PACIFIC ENGINEERING AND ANALYSIS STRONG-MOTION DATA\n"
            "  IMPERIAL VALLEY EARTHQUAKE MAY 18, 1940 - 2037 PST\n"
            "  EL CENTRO SITE IMPERIAL VALLEY IRRIGATION DISTRICT COMP S00E\n"
            "  ACCELEROGRAM BANDPASS FILTERED WITH RAMPS AT .10-.125 AND 23.0-25.0 CYC/SEC\n"
            "  UNITS ARE G\n"
            "  NOTE: TEST FILE\n"
            "    7   0.0050   NPTS, DT\n"
            "*** Begin data ***\n" + _data_lines(VALUES_G, 5, "{:12.6f}") +
            "*** End Data ***\n"
            "anything after the end marker is ignored\n")
    gm = read_at2(_write(tmp_path, "old.at2", text))
    assert gm.npts == 7
    assert gm.dt == 0.005
    np.testing.assert_allclose(gm.accel, np.array(VALUES_G) * G, rtol=1e-12)
    assert gm.units_read == "g"
    assert len(gm.metadata["header"]) == 7


def test_old_header_without_markers(tmp_path: Path) -> None:
    text = ("FN-ROTATED TEST RECORD\n" * 6 + "7 0.0050 NPTS, DT\n"
            + _data_lines(VALUES_G, 5, "{:.6E}  "))
    gm = read_at2(_write(tmp_path, "oak.AT2", text))
    assert gm.npts == 7 and gm.dt == 0.005
    assert gm.units_read == "g (assumed)"  # no unit in this header
    np.testing.assert_allclose(gm.accel, np.array(VALUES_G) * G, rtol=1e-12)


def test_fortran_fused_numbers_and_d_exponent(tmp_path: Path) -> None:
    text = PEER_HEADER + "NPTS= 5, DT= .01 SEC\n" \
        "-0.123E-02-0.456E-02 0.500D-01\n" "0.00630-0.00364\n"
    gm = read_at2(_write(tmp_path, "fused.AT2", text))
    np.testing.assert_allclose(gm.accel / G, [-0.123e-2, -0.456e-2, 0.05, 0.0063, -0.00364],
                               rtol=1e-12)


# ------------------------------------------------------------------- units
@pytest.mark.parametrize(("units_line", "factor", "units_read"), [
    ("ACCELERATION TIME SERIES IN UNITS OF G", G, "g"),
    ("The units are (g)", G, "g"),
    ("ACCELERATION IN CM/S/S", 0.01, "cm/s2"),
    ("Acceleration units: CM/S^2", 0.01, "cm/s2"),
    ("acceleration (cm/sec/sec)", 0.01, "cm/s2"),
    ("Units: gal", 0.01, "gal"),
    ("accel in m/s2", 1.0, "m/s2"),
    ("ACCELERATION [m/s^2]", 1.0, "m/s2"),
    ("ACCELERATION HISTORY (NO UNITS GIVEN HERE)", G, "g (assumed)"),
])
def test_units_from_header(tmp_path: Path, units_line: str, factor: float,
                           units_read: str) -> None:
    text = "TEST RECORD\n" + units_line + "\nNPTS= 3, DT= .01 SEC\n 1.5 -2.0 0.25\n"
    gm = read_at2(_write(tmp_path, "u.AT2", text))
    assert gm.units_read == units_read
    np.testing.assert_allclose(gm.accel, np.array([1.5, -2.0, 0.25]) * factor, rtol=1e-12)


def test_given_units_fill_in_but_may_not_contradict(tmp_path: Path) -> None:
    bare = _write(tmp_path, "bare.AT2", "NPTS= 2, DT= .01 SEC\n 100.0 -50.0\n")
    gm = read_at2(bare, units="cm/s^2")
    assert gm.units_read == "cm/s^2"
    np.testing.assert_allclose(gm.accel, [1.0, -0.5])
    stated = _write(tmp_path, "g.AT2", "IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n 0.1 -0.2\n")
    assert read_at2(stated, units="g").pga == pytest.approx(0.2 * G)
    with pytest.raises(ValueError, match=r"g\.AT2: the header states units 'g'.*'m/s2'"):
        read_at2(stated, units="m/s2")
    with pytest.raises(ValueError, match="unknown acceleration unit 'furlong'"):
        read_at2(bare, units="furlong")


# ------------------------------------------------------------------- bad AT2 files
def test_npts_mismatch_names_file_and_line(tmp_path: Path) -> None:
    path = _write(tmp_path, "short.AT2",
                  PEER_HEADER + "NPTS=  8, DT= .01000 SEC\n" + _data_lines(VALUES_G))
    with pytest.raises(ValueError, match=r"short\.AT2: line 4: NPTS = 8 but 7 values"):
        read_at2(path)


def test_missing_dt(tmp_path: Path) -> None:
    path = _write(tmp_path, "nodt.AT2", PEER_HEADER + "NPTS=  7\n" + _data_lines(VALUES_G))
    with pytest.raises(ValueError, match=r"nodt\.AT2: no DT in the header \(lines 1-4\)"):
        read_at2(path)
    # a dt given by the caller fills the gap
    assert read_at2(path, dt=0.01).dt == 0.01


def test_dt_given_must_agree_with_header(tmp_path: Path) -> None:
    path = _write(tmp_path, "dt.AT2", "NPTS= 2, DT= .01 SEC\n 0.1 0.2\n")
    with pytest.raises(ValueError, match=r"dt\.AT2: line 1: DT = 0\.01 s in the file"):
        read_at2(path, dt=0.02)


@pytest.mark.parametrize(("npts_line", "message"), [
    ("NPTS=  7, DT= abc SEC",
     r"bad\.AT2: line 4: DT is not a number; it must be the time step in seconds$"),
    ("NPTS=  7, DT= -0.01 SEC", r"bad\.AT2: line 4: DT \[s\] must be > 0 \(got -0\.01\)"),
    ("NPTS=  7, DT= 0 SEC", r"bad\.AT2: line 4: DT \[s\] must be > 0 \(got 0\)"),
    ("NPTS=  7.5, DT= .01 SEC", r"bad\.AT2: line 4: NPTS must be a whole number"),
])
def test_bad_header_values(tmp_path: Path, npts_line: str, message: str) -> None:
    path = _write(tmp_path, "bad.AT2", PEER_HEADER + npts_line + "\n" + _data_lines(VALUES_G))
    with pytest.raises(ValueError, match=message):
        read_at2(path)


def test_non_number_token_names_line_and_place(tmp_path: Path) -> None:
    data = _data_lines(VALUES_G).splitlines()
    data[1] = data[1] + "   0.1x3"
    path = _write(tmp_path, "token.AT2",
                  PEER_HEADER + "NPTS=  8, DT= .01 SEC\n" + "\n".join(data) + "\n")
    with pytest.raises(ValueError, match=r"token\.AT2: line 6: item 3 of 3 on the line is not a "
                                         r"number"):
        read_at2(path)


@pytest.mark.parametrize("bad", ["NaN", "nan", "inf", "-Infinity"])
def test_non_finite_value(tmp_path: Path, bad: str) -> None:
    path = _write(tmp_path, "nan.AT2",
                  PEER_HEADER + "NPTS=  3, DT= .01 SEC\n  0.1  0.2\n  " + bad + "\n")
    with pytest.raises(ValueError, match=r"nan\.AT2: line 6: acceleration value .* not finite"):
        read_at2(path)


@pytest.mark.parametrize("bad, shown", [
    ("1e309", "1e309"),                      # overflows to inf when read
    ("-2.5E+400", "-2.5E+400"),
    ("1D309", "1D309"),                      # Fortran exponent
    ("0.1E+00-0.2E+309", "-0.2E+309"),       # the second number of a fused run
])
def test_a_value_beyond_the_largest_float_is_named_as_written(tmp_path: Path, bad: str,
                                                              shown: str) -> None:
    path = _write(tmp_path, "big.AT2",
                  PEER_HEADER + f"NPTS=  4, DT= .01 SEC\n  0.1  0.2\n  {bad}  0.3\n")
    with pytest.raises(ValueError) as err:
        read_at2(path)
    assert str(err.value) == (f"{path}: line 6: acceleration value {shown} is not finite: it "
                              "is beyond the largest float (1.8e+308) and reads as "
                              f"{'-inf' if shown.startswith('-') else 'inf'}")


def test_a_value_that_overflows_in_si_units_names_file_and_line(tmp_path: Path) -> None:
    # finite in g, beyond the largest float in m/s²: no RuntimeWarning (an error in the tests)
    path = _write(tmp_path, "g.AT2", PEER_HEADER + "NPTS=  5, DT= .01 SEC\n  0.1  0.2\n"
                                                   "  0.3\n  0.4  1e308\n")
    with pytest.raises(ValueError, match=r"g\.AT2: line 7: acceleration value 1e\+308 g is "
                                         r"beyond the largest float \(1\.8e\+308\) in m/s2$"):
        read_at2(path)
    text = _write(tmp_path, "g.txt", "# accel [g]\n0.1\n-1.5e308\n")
    with pytest.raises(ValueError, match=r"g\.txt: line 3: acceleration value -1\.5e\+308 g"):
        read_text(text, dt=0.01, units="g")


def test_empty_data(tmp_path: Path) -> None:
    path = _write(tmp_path, "empty.AT2", PEER_HEADER + "NPTS=  0, DT= .01 SEC\n")
    with pytest.raises(ValueError, match=r"empty\.AT2: line 4: NPTS must be a whole number"):
        read_at2(path)
    path = _write(tmp_path, "empty2.AT2", PEER_HEADER + "NPTS=  3, DT= .01 SEC\n\n  \n")
    with pytest.raises(ValueError, match=r"empty2\.AT2: no data"):
        read_at2(path)


def test_missing_file_and_folder(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError, match="nothing.AT2"):
        read_at2(tmp_path / "nothing.AT2")
    with pytest.raises(IsADirectoryError):
        read_record(tmp_path)


# ------------------------------------------------------------------- text files
def test_two_column_text_takes_dt_and_shifts_time(tmp_path: Path) -> None:
    text = "# time [s]  accel [g]\n\n1.00, 0.1\n1.02, -0.3\n# a comment\n1.04, 0.2\n"
    gm = read_text(_write(tmp_path, "two.csv", text), units="g")
    assert gm.dt == pytest.approx(0.02, rel=1e-12)
    assert gm.metadata["t0"] == 1.0
    assert gm.time[0] == 0.0
    assert gm.units_read == "g"
    np.testing.assert_allclose(gm.accel, np.array([0.1, -0.3, 0.2]) * G, rtol=1e-12)


def test_one_column_text_needs_dt(tmp_path: Path) -> None:
    path = _write(tmp_path, "one.txt", "1.0\n-2.0\n3.0")  # no trailing newline
    with pytest.raises(ValueError, match=r"one\.txt: one column .* give the time step dt"):
        read_text(path)
    gm = read_text(path, dt=0.005, units="cm/s2")
    assert gm.npts == 3 and gm.dt == 0.005
    np.testing.assert_allclose(gm.accel, [0.01, -0.02, 0.03])


def test_text_non_uniform_time_names_line(tmp_path: Path) -> None:
    text = "# t a\n0.00 0.1\n0.01 0.2\n0.02 0.3\n0.0305 0.4\n0.04 0.5\n"
    with pytest.raises(ValueError, match=r"uneven\.dat: line 5: time step 0\.0105 s"):
        read_text(_write(tmp_path, "uneven.dat", text))


def test_text_bad_rows(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"cols\.dat: line 2: 1 column\(s\) but line 1 has 2"):
        read_text(_write(tmp_path, "cols.dat", "0.0 1.0\n2.0\n"))
    with pytest.raises(ValueError, match=r"three\.dat: line 1: 3 columns; say which is the "
                                         r"acceleration with column"):
        read_text(_write(tmp_path, "three.dat", "0.0 1.0 2.0\n"))
    with pytest.raises(ValueError, match=r"nan\.dat: line 3: acceleration value nan"):
        read_text(_write(tmp_path, "nan.dat", "0.0 1.0\n0.1 2.0\n0.2 nan\n"), dt=None)
    with pytest.raises(ValueError, match=r"word\.dat: line 2: item 1 of 2 on the line is not a number"):
        read_text(_write(tmp_path, "word.dat", "# header\ntime accel\n0 1\n"))
    with pytest.raises(ValueError, match=r"blank\.dat: no data values"):
        read_text(_write(tmp_path, "blank.dat", "# only a comment\n\n"))


def test_text_names_the_column_of_a_value_that_is_not_finite(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"t\.dat: line 2: time value 1e309 is not finite"):
        read_text(_write(tmp_path, "t.dat", "0.0 1.0\n1e309 2.0\n"))
    with pytest.raises(ValueError, match=r"a\.dat: line 2: acceleration value 1e309 is not"):
        read_text(_write(tmp_path, "a.dat", "0.0 1.0\n0.1 1e309\n"))
    with pytest.raises(ValueError, match=r"one\.dat: line 1: acceleration value inf is not"):
        read_text(_write(tmp_path, "one.dat", "inf\n"), dt=0.01)


# ------------------------------------------------------------------- dispatch
def test_read_record_picks_reader_by_suffix_and_content(tmp_path: Path) -> None:
    at2_no_suffix = _write(tmp_path, "record.txt",
                           PEER_HEADER + "NPTS=  7, DT= .01 SEC\n" + _data_lines(VALUES_G))
    assert read_record(at2_no_suffix).units_read == "g"
    text = _write(tmp_path, "values.txt", "0.5\n-1.5\n")
    with pytest.raises(UnitsRequired, match=r"values\.txt: a plain-text record does not "
                                            r"state its acceleration unit; give its units: g, "
                                            r"m/s2, cm/s2, gal, mm/s2, in/s2 or ft/s2$"):
        read_record(text, dt=0.01)  # none is assumed
    with pytest.raises(UnitsRequired):
        read_text(text, dt=0.01)
    gm = read_record(text, dt=0.01, units="m/s2")
    assert gm.units_read == "m/s2"
    np.testing.assert_allclose(gm.accel, [0.5, -1.5])
    gm_g = read_record(text, dt=0.01, units="g")
    assert gm_g.units_read == "g"
    np.testing.assert_allclose(gm_g.accel, [0.5 * G, -1.5 * G])


# ------------------------------------------------------------------ sizes a file declares
def test_counts_a_header_declares_allocate_nothing(tmp_path: Path) -> None:
    """NPTS and COSMOS's counts are compared with what was read, never allocated from."""
    at2 = _write(tmp_path, "n.AT2", PEER_HEADER + "NPTS= 1000000000000, DT= .01 SEC\n"
                 + _data_lines(VALUES_G))
    with pytest.raises(ValueError, match=r"n\.AT2: line 4: NPTS = 1000000000000 but 7 values "
                                         r"were read \(lines 5-6\)$"):
        read_at2(at2)
    formats = Path(__file__).parent / "formats"
    text = (formats / "CE99999_chan1_360.V2c").read_text(encoding="utf-8")
    cosmos = _write(tmp_path, "n.V2c", text.replace("      20 acceleration pts",
                                                    "1000000000000 acceleration pts", 1))
    with pytest.raises(ValueError, match=r"n\.V2c: line 49: states 1000000000000 values but "
                                         r"20 were read \(lines 50-69\)$"):
        read_record(cosmos)
    # the integer header's count: its values run on into the next block, which is refused
    cosmos = _write(tmp_path, "n.V2c", text.replace("100 Integer-header",
                                                    "1000000000000 Integer-header", 1))
    with pytest.raises(ValueError, match=r"n\.V2c: line 25: item 2 of 9 on the line is not a "
                                         r"number"):
        read_record(cosmos)


def test_a_file_too_large_or_not_a_file_is_refused_before_reading(tmp_path: Path) -> None:
    big = tmp_path / "big.txt"
    with big.open("wb") as f:  # sparse: takes no disk space
        f.truncate(300 * 1024 * 1024)
    with pytest.raises(ValueError, match=r"big\.txt: 315 MB, larger than any record file "
                                         r"pounding reads \(at most 268 MB\)$"):
        read_record(big)
    with pytest.raises(ValueError, match=r"^/dev/zero: not a regular file \(a device, pipe or "
                                         r"socket\), not a record file$"):
        read_record("/dev/zero")
