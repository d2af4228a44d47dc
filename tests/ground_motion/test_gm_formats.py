"""K-NET/KiK-net and COSMOS readers, OpenSees' 7-line AT2 layout, and files in no format read.

The fixtures in ``formats/`` were written for these tests following the format documents
(see ``formats/README.md``); every expected value below is computed by hand from the numbers
written in them, never by the reader under test.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.ground_motion import load_bundled, read_at2, read_cosmos, read_knet, read_record
from pounding.ground_motion.bundled import bundled_folder
from pounding.units import G

FORMATS = Path(__file__).parent / "formats"
KNET = FORMATS / "TST0010101010000.NS"
KIKNET = FORMATS / "TSTH010007210339.NS2"
COSMOS_ONE = FORMATS / "CE99999_chan1_360.V2c"
COSMOS_CGS = FORMATS / "CE99999_all.V2C"

KNET_COUNTS = [8009, 9006, 7998, 8001, 8009, 8007, 8002, 8005,
               8006, 8003, 8003, 8005, 8005, 8003, 8001, 8004,
               8008, 8004, 6915, 8006]
KIKNET_COUNTS = [-2471, -2466, -2462, -2464, -2472, -2478, -2473, -2457,
                 -2446, -2450, -2462, -2468, -2466, -2465, -2472, -2481,
                 -2483, -2482, -2479, -2480, -2488, -2499, -2505, -2500, -2990]
COSMOS_ACC_CM = [0.0, 1.25, -2.5, 10.0, 49.03325, -98.0665, 60.5, -30.25, 12.0, -6.0,
                 3.0, -1.5, 0.75, -0.375, 0.1875, 0.0, 2.0, -2.0, 1.0, 0.0]
COSMOS_CH2_G = [0.0, 0.0125, -0.025, 0.05, -0.2, 0.3, -0.15, 0.075, -0.0375, 0.0, 0.01, -0.01]


def _copy(src: Path, dest: Path, old: str = "", new: str = "") -> Path:
    text = src.read_bytes().decode("latin-1")
    if old:
        assert old in text, old
        text = text.replace(old, new, 1)
    dest.write_bytes(text.encode("latin-1"))
    return dest


# ------------------------------------------------------------------- K-NET / KiK-net
def test_knet_counts_times_scale_less_mean() -> None:
    """gal = (count - mean) x 7845/8223790; the 20 counts of the fixture sum to 20 x 8000."""
    assert sum(KNET_COUNTS) == 20 * 8000
    gm = read_knet(KNET)
    expected = [float(Fraction((c - 8000) * 7845, 8223790) / 100) for c in KNET_COUNTS]
    np.testing.assert_allclose(gm.accel, expected, rtol=1e-12, atol=1e-17)
    # count 9006 is 1006 above the mean: 1006 x 7845 / 8223790 = 0.959663 gal
    assert gm.accel[1] * 100 == pytest.approx(0.959663, abs=5e-7)
    assert gm.npts == 20 and gm.dt == 0.01  # 100 Hz
    assert gm.units_read == "gal"
    # NIED's Max. Acc. is that of the record less its mean: 1085 x 7845 / 8223790 = 1.035
    assert gm.pga * 100 == pytest.approx(gm.metadata["max_acc_gal"], abs=5e-4)
    assert gm.metadata["mean_removed"] == pytest.approx(8000 * 7845 / 8223790, rel=1e-12)
    assert gm.name == "TST0010101010000.NS"
    assert gm.metadata["format"] == "K-NET ASCII"
    assert gm.metadata["station"] == "TST001" and gm.metadata["component"] == "N-S"
    assert gm.metadata["origin_time"] == "2001/01/01 00:00:00"
    assert gm.metadata["magnitude"] == 6.1 and gm.metadata["depth_km"] == 40.0


def test_kiknet_crlf_lon_and_channel_number() -> None:
    """KiK-net: 200 Hz, Dir. 4 (surface N-S), 'Lon.' and 'Max Acc.' spellings, CRLF."""
    gm = read_record(KIKNET)
    mean = Fraction(sum(KIKNET_COUNTS), len(KIKNET_COUNTS))  # -2494.36 counts
    expected = [float((c - mean) * Fraction(2000, 8388608) / 100) for c in KIKNET_COUNTS]
    np.testing.assert_allclose(gm.accel, expected, rtol=1e-12, atol=1e-18)
    assert gm.npts == 25 and gm.dt == 0.005
    assert gm.pga * 100 == pytest.approx(gm.metadata["max_acc_gal"], abs=5e-6)
    assert gm.metadata["format"] == "KiK-net ASCII"
    assert gm.metadata["component"] == "NS2 (surface)"
    assert gm.metadata["station_lon"] == 140.1814


def test_knet_is_recognised_by_its_first_line_whatever_the_name(tmp_path: Path) -> None:
    """The issue's case: a K-NET file used to fail with "line 1: 'Origin' is not a number"."""
    gm = read_record(_copy(KNET, tmp_path / "record.txt"))
    np.testing.assert_array_equal(gm.accel, read_knet(KNET).accel)


@pytest.mark.parametrize("name, old, new, message", [
    ("x.NS", "Sampling Freq(Hz)", "Sampling Rate(Hz)",
     r"x\.NS: line 11: expected the K-NET header label 'Sampling Freq\(Hz\)' there \(line "
     r"11 does not start with it\)$"),
    ("s.NS", "7845(gal)/8223790", "7845(gal)",
     r"s\.NS: line 14: Scale Factor must read like '7845\(gal\)/8223790', two positive "
     r"numbers \(not in that form\)$"),
    ("f.NS", "100Hz", "0Hz",
     r"f\.NS: line 11: Sampling Freq\(Hz\) must be a positive number such as '100Hz' "
     r"\(got 0 Hz\)$"),
    ("c.NS", "8004\n", "x8\n", r"c\.NS: line 19: item 8 of 8 on the line is not a number "
                                r"\(expected numbers separated by spaces, tabs or commas\)$"),
])
def test_knet_bad_input_names_file_and_line(tmp_path: Path, name: str, old: str, new: str,
                                            message: str) -> None:
    with pytest.raises(ValueError, match=message):
        read_knet(_copy(KNET, tmp_path / name, old, new))


def test_knet_dt_and_units_must_agree_with_the_file() -> None:
    with pytest.raises(ValueError, match=r"line 11: 1/Sampling Freq = 0\.01 s in the file but "
                                         r"dt = 0\.02 s was given"):
        read_knet(KNET, dt=0.02)
    with pytest.raises(ValueError, match=r"header states units 'gal' but units='g'"):
        read_knet(KNET, units="g")
    assert read_knet(KNET, dt=0.01, units="cm/s2").npts == 20  # agreeing values are fine


def test_knet_matches_obspy(obspy) -> None:  # noqa: ANN001 (conftest.py)
    """ObsPy's reader (obspy.io.nied.knet; the peers extra): calib x counts, less the mean."""
    tr = obspy.read(str(KNET))[0]
    theirs = tr.data * tr.stats.calib
    np.testing.assert_allclose(read_knet(KNET).accel, theirs - theirs.mean(), rtol=0,
                               atol=1e-15)
    assert tr.stats.delta == read_knet(KNET).dt


# ------------------------------------------------------------------- COSMOS
def test_cosmos_v2_single_channel() -> None:
    """USGS layout: 5F15.6 real header, 'units=cm/sec2(04),Format=(1E15.6)'."""
    gm = read_record(COSMOS_ONE)
    np.testing.assert_allclose(gm.accel, np.array(COSMOS_ACC_CM) / 100, rtol=1e-15)
    assert gm.npts == 20
    assert gm.dt == 0.01  # Real(62) = 10.000000 ms
    assert gm.units_read == "cm/s2"
    assert gm.pga == pytest.approx(0.980665, rel=1e-15)  # 98.0665 cm/s2 = 0.1 g
    assert gm.pga_g == pytest.approx(0.1, rel=1e-14)
    # Real(64) and Real(65): the peak -98.0665 cm/s2 at 0.05 s, sample 5
    assert gm.metadata["peak_header"] == -98.0665 == COSMOS_ACC_CM[5]
    assert gm.metadata["peak_time_header"] == pytest.approx(5 * gm.dt)
    assert gm.metadata["format"] == "COSMOS V2"
    assert gm.metadata["station"] == "CE-99999"
    assert gm.metadata["component"] == "360 deg"
    assert gm.metadata["event"].startswith("Record of test0001 Earthquake of Thu Jan 1, 2015")
    assert gm.name == "CE99999_chan1_360"


def test_cosmos_cgs_file_of_two_channels_with_velocity_and_displacement() -> None:
    """CGS layout: 6F13.6 real header; channel 1 acceleration, velocity, displacement, then
    channel 2 acceleration in g at 5 ms. Only acceleration series count as channels."""
    with pytest.raises(ValueError, match=r"CE99999_all\.V2C: holds 2 acceleration channels "
                                         r"\(1 360 deg; 2 90 deg\); read one with "
                                         r"channel = N \(read_cosmos\(path, channel=N\), "
                                         r"--channel N on the command line"):
        read_record(COSMOS_CGS)
    one = read_cosmos(COSMOS_CGS, channel=1)
    np.testing.assert_array_equal(one.accel, read_cosmos(COSMOS_ONE).accel)
    two = read_cosmos(COSMOS_CGS, channel=2)
    np.testing.assert_allclose(two.accel, np.array(COSMOS_CH2_G) * G, rtol=1e-15)
    assert two.dt == 0.005 and two.units_read == "g" and two.npts == 12
    assert two.metadata["component"] == "90 deg" and two.name == "CE99999_all (channel 2)"
    with pytest.raises(ValueError, match=r"channel must be 1 to 2 \(got 3\)"):
        read_cosmos(COSMOS_CGS, channel=3)


@pytest.mark.parametrize("name, old, new, message", [
    ("v0.V2c", "cm/sec2(04)", "counts(50)",
     r"v0\.V2c: line 49: raw counts \(COSMOS Volume 0\), not an acceleration"),
    ("n.V2c", "      20 acc", "      21 acc",
     r"n\.V2c: line 49: states 21 values but 20 were read \(lines 50-69\)"),
    ("i.V2c", "Integer-header", "Int-header",
     r"i\.V2c: line 14: expected the line 'N Integer-header values follow on M lines, "
     r"\.\.\.'"),
    ("u.V2c", "cm/sec2(04)", "mg(11)",
     r"u\.V2c: line 49: units code 11 on the data line are not an acceleration unit "
     r"pounding converts \(codes 2 g, 4 cm/s2, 7 in/s2, 10 gal\)$"),
])
def test_cosmos_bad_input_names_file_and_line(tmp_path: Path, name: str, old: str, new: str,
                                              message: str) -> None:
    with pytest.raises(ValueError, match=message):
        read_cosmos(_copy(COSMOS_ONE, tmp_path / name, old, new))


def test_cosmos_time_step_from_real_62_or_given(tmp_path: Path) -> None:
    no_dt = _copy(COSMOS_ONE, tmp_path / "dt.V2c", "     10.000000", "   -999.000000")
    with pytest.raises(ValueError, match=r"dt\.V2c: line 38: no sampling interval in the "
                                         r"real header \(Real\(62\), in ms, is unknown\); "
                                         r"pass dt"):
        read_cosmos(no_dt)
    assert read_cosmos(no_dt, dt=0.01).dt == 0.01
    with pytest.raises(ValueError, match=r"line 38: Real\(62\), the sampling interval, = "
                                         r"0\.01 s in the file but dt = 0\.02 s was given"):
        read_cosmos(COSMOS_ONE, dt=0.02)


# ------------------------------------------------------------------- AT2: OpenSees' layout
VERIFICATION_HEADER = [  # OpenSees EXAMPLES/verification/elCentro.at2's layout (SOURCES.md)
    "PACIFIC EARTHQUAKE ENGINEERING RESEARCH CENTER STRONG MOTION DATA",
    "Data for El Centro 1940 North South Component (Peknold Version)",
    "as used in Chopra, Dynamics of Structures",
    "1559 points at equal spacing of 0.02 sec",
    "Points are listed in the format of 8F10.5",
    "The units are (g)",
    "1559 0.02 NPTS, DT",
]


def _peknold_data_lines() -> list[str]:
    """The data lines of the bundled plain-layout Peknold file (its header is 4 lines)."""
    plain = bundled_folder().joinpath("elcentro_1940_NS_peknold_8F10.5.AT2")
    return plain.read_text(encoding="utf-8").splitlines()[4:]


def test_at2_seven_line_header_with_markers_reads_as_the_plain_file(tmp_path: Path) -> None:
    """The same data in OpenSees' verification layout: a 7-line header ending in
    '1559 0.02 NPTS, DT', '*** Begin data ***' and '*** End Data ***'."""
    path = tmp_path / "elCentro.at2"
    path.write_text("\n".join([*VERIFICATION_HEADER, "*** Begin data ***",
                               *_peknold_data_lines(), "*** End Data ***"]) + "\n",
                    encoding="utf-8")
    gm = read_record(path)
    plain = load_bundled("elcentro_1940_NS_peknold_8F10.5")
    assert gm.npts == plain.npts == 1559
    assert gm.dt == plain.dt == 0.02
    np.testing.assert_array_equal(gm.accel, plain.accel)
    assert gm.units_read == "g"
    assert gm.metadata["header"] == tuple(VERIFICATION_HEADER)
    assert gm.metadata["end_marker_line"] == 8 + 195 + 1


def test_at2_header_line_of_numbers_before_the_begin_marker(tmp_path: Path) -> None:
    """With a Begin marker the header runs up to it, so a header line of numbers alone (here
    a date) is header, and NPTS/DT are found on any header line, not only the first five."""
    lines = ["STRONG MOTION RECORD", "05 18 1940", "COMPONENT S00E", "UNITS OF G", "", "",
             "", "", "NPTS=  9, DT= .02000 SEC", "*** Begin data ***",
             _peknold_data_lines()[0], "   0.01234", "*** End Data ***"]
    gm = read_at2(_write(tmp_path / "dated.at2", lines))
    assert gm.npts == 9 and gm.dt == 0.02
    assert gm.accel[-1] == pytest.approx(0.01234 * G)


def _write(path: Path, lines: list[str]) -> Path:
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


# ------------------------------------------------------------------- no format read
SUPPORTED = ("it reads K-NET/KiK-net ASCII, COSMOS V1/V2, PEER AT2, plain text (one "
             "column, two: time, acceleration, or several with a column chosen)")


def test_file_in_no_format_is_refused_naming_the_formats(tmp_path: Path) -> None:
    esm = _write(tmp_path / "esm.asc", ["EVENT_NAME: ITALY", "EVENT_ID: IT-1997-0006",
                                        "0.1", "0.2"])
    with pytest.raises(ValueError) as info:
        read_record(esm)
    assert str(info.value) == (f"{esm}: not a record format pounding reads (49 bytes; line "
                               "1, its first line that is not blank or a '#' comment, is "
                               "neither numbers nor a header of a format read); "
                               f"{SUPPORTED}")
    binary = tmp_path / "record.mseed"
    binary.write_bytes(b"000001D \x00\x01\x02" * 20)
    with pytest.raises(ValueError, match=r"record\.mseed: a binary file \(220 bytes; "
                                         r"miniSEED, SAC or the like\), not a record format "
                                         r"pounding reads"):
        read_record(binary)
    # a plain-text file with a bad value further down keeps its own message
    with pytest.raises(ValueError, match=r"late\.txt: line 3: item 1 of 2 on the line is not "
                                         r"a number"):
        read_record(_write(tmp_path / "late.txt", ["# t a", "0 1", "oops 2"]))


def test_cli_refuses_such_a_file_in_one_line(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    esm = _write(tmp_path / "esm.asc", ["EVENT_NAME: ITALY", "0.1"])
    assert main(["record", str(esm)]) == 2
    err = capsys.readouterr().err.strip()
    assert err == (f"error: {esm}: not a record format pounding reads (22 bytes; line 1, "
                   "its first line that is not blank or a '#' comment, is neither numbers "
                   f"nor a header of a format read); {SUPPORTED}")


def test_cli_reads_knet_and_cosmos(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["record", str(KNET), str(COSMOS_ONE)]) == 0
    out = capsys.readouterr().out
    # PGA [g]: 1.035025 gal / 980.665 = 0.0011; 98.0665 cm/s2 = 0.1 g
    for expected in ("TST0010101010000.NS", "0.0011", "gal", "CE99999_chan1_360.V2c",
                     "0.1000", "cm/s2"):
        assert expected in out
