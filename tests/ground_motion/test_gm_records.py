"""The bundled real records (the one copy of them, in ``pounding/data/records``) against the
values an independent parser wrote into the SOURCES.md beside them, and their manifest: the
ten of the bundled suite and the Düzce pair of orthogonal components kept out of it."""

from __future__ import annotations

import hashlib
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from pounding.ground_motion import (
    bundled_companion,
    bundled_files,
    bundled_records,
    bundled_suite,
    el_centro,
    load_bundled,
    read_record,
)
from pounding.ground_motion.bundled import bundled_folder
from pounding.units import G

RECORDS = Path(str(bundled_folder()))


def _sources_table(path: Path) -> dict[str, dict[str, str]]:
    """The '## Records' table of a SOURCES.md as {file: {column: cell}}."""
    rows: dict[str, dict[str, str]] = {}
    header: list[str] | None = None
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("|"):
            header = None  # a table ends at the first line that is not a row
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] == "file":
            header = cells
        elif header is not None and not set(cells[0]) <= {"-"}:
            rows[cells[0]] = dict(zip(header, cells, strict=False))
    return rows


SOURCES = _sources_table(RECORDS / "SOURCES.md")
UNITS = {e["file"]: e["units"] for e in tomllib.loads(
    (RECORDS / "records.toml").read_text(encoding="utf-8"))["record"] if "units" in e}
"""The unit records.toml gives a file that states none (a text file needs one)."""
MANIFEST = tomllib.loads((RECORDS / "records.toml").read_text(encoding="utf-8"))["record"]


PAIR = ("kocaeli_1999_duzce_180_RSN1158.AT2", "kocaeli_1999_duzce_270_RSN1158.AT2")
"""The two orthogonal horizontal components of Düzce, Kocaeli 1999 (180 = N–S, 270 = E–W)."""


def _git_blob_id(data: bytes) -> str:
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def _blob(name: str) -> str:
    """The blob id of SOURCES.md's row (a note may follow the id in the cell)."""
    return SOURCES[name]["git blob"].split()[0]


def test_sources_table_lists_every_record_file() -> None:
    files = sorted(p.name for p in RECORDS.iterdir()
                   if p.is_file() and p.name not in {"SOURCES.md", "records.toml",
                                                     ".gitattributes"})
    assert sorted(SOURCES) == files == sorted(bundled_files())
    assert len(files) == 12


PEKNOLD = "elcentro_1940_NS_peknold_8F10.5.AT2"


def test_the_suite_is_nine_single_components_one_a_motion() -> None:
    """The Düzce pair and the Peknold El Centro (a second digitisation of the first
    record's motion) ship but are marked out of the bundled suite: nine records, no motion
    twice (no two of one earthquake and station), in their order."""
    assert bundled_records() == [e["file"] for e in MANIFEST if e.get("suite", True)]
    assert len(bundled_records()) == 9
    assert bundled_files() == [*bundled_records(), PEKNOLD, *PAIR]
    assert [e.get("suite") for e in MANIFEST if e["file"] in (PEKNOLD, *PAIR)] == [False] * 3
    assert [Path(p).name for p in bundled_suite().paths] == bundled_records()
    in_suite = [e for e in MANIFEST if e.get("suite", True)]
    motions = {(re.split(r"[ ,]+\d{4}", e["earthquake"])[0], e["station"].split()[0])
               for e in in_suite}
    assert len(motions) == len(in_suite)
    assert len({re.split(r"[ ,]+\d{4}", e["earthquake"])[0] for e in in_suite}) == 8


def test_pair_components_are_companions_on_one_time_base() -> None:
    """Each component names the other; same station and event, components 180 and 270
    (at right angles), the same NPTS, DT and start."""
    ns, ew = PAIR
    assert bundled_companion(ns) == ew and bundled_companion(Path(ew).stem) == ns
    assert all(bundled_companion(f) is None for f in bundled_records())
    with pytest.raises(ValueError, match=r"bundled record: unknown name 'nope'"):
        bundled_companion("nope")
    a, b = load_bundled(ns), load_bundled(ew)
    assert (a.npts, a.dt, a.time[0]) == (b.npts, b.dt, b.time[0]) == (5437, 0.005, 0.0)
    heads = [(RECORDS / f).read_bytes().split(b"\r\n")[1] for f in PAIR]
    assert heads == [b"Kocaeli Turkey, 8/17/1999, Duzce, 180",
                     b"Kocaeli Turkey, 8/17/1999, Duzce, 270"]
    assert abs(int(heads[0][-3:]) - int(heads[1][-3:])) == 90


def test_pair_rotd100_of_a_stiff_oscillator_is_the_vector_peak() -> None:
    """A 0.01 s oscillator follows the ground: its PSA along azimuth θ is the PGA of
    a₁ cos θ + a₂ sin θ, whose largest over θ is max_t |(a₁, a₂)| (Boore 2010), and each
    component's PSA is that component's PGA."""
    from pounding.spectra.rotd import rotd_spectrum

    a, b = (load_bundled(f) for f in PAIR)
    spec = rotd_spectrum(a, b, periods=[0.01])
    vector_peak = np.hypot(a.accel, b.accel).max() / G
    assert vector_peak == pytest.approx(0.4001, abs=1e-4)  # above both PGAs: 0.3119, 0.3642
    assert spec.psa_g(spec.rotd100)[0, 0] == pytest.approx(vector_peak, rel=5e-3)
    assert spec.psa_g(spec.sd_components)[:, 0, 0] == pytest.approx([a.pga_g, b.pga_g],
                                                                     rel=5e-3)


@pytest.mark.parametrize("name", PAIR)
def test_pair_layout_is_the_nga_files(name: str) -> None:
    """SOURCES.md: 83,972 bytes (the length of the source), CRLF after every one of 1092
    lines, the 4-line header, 15-character fields, the last line padded to 75."""
    raw = (RECORDS / name).read_bytes()
    assert len(raw) == 83972 and raw.endswith(b"\r\n") and b"\n" not in raw.replace(b"\r\n", b"")
    lines = raw.split(b"\r\n")[:-1]
    assert len(lines) == 1092
    assert lines[3].startswith(b"NPTS=   5437  DT=   .0050 SEC,")
    assert {len(line) for line in lines[3:]} == {75}
    assert lines[-1].rstrip() == lines[-1][:30]


@pytest.mark.parametrize("name", sorted(SOURCES))
def test_copy_is_byte_for_byte(name: str) -> None:
    """The bundled copies (line ends included) hash to the blob ids SOURCES.md gives."""
    assert _git_blob_id((RECORDS / name).read_bytes()) == _blob(name)


@pytest.mark.parametrize("name", sorted(SOURCES))
def test_record_matches_sources(name: str) -> None:
    row = SOURCES[name]
    gm = read_record(RECORDS / name, units=UNITS.get(name))
    assert gm.npts == int(row["NPTS"])
    assert gm.dt == pytest.approx(float(row["DT s"]), rel=1e-9)
    assert gm.pga_g == pytest.approx(float(row["PGA g"]), abs=5e-5)  # its 4 digits
    # SOURCES.md rounds PGV to whole cm/s; allow that plus a few per cent
    assert gm.pgv * 100.0 == pytest.approx(float(row["PGV≈ cm/s"]), rel=0.05)
    assert gm.time[0] == 0.0
    assert gm.duration == pytest.approx((gm.npts - 1) * gm.dt)


@pytest.mark.parametrize("name", [n for n in sorted(SOURCES) if n.endswith(".AT2")])
def test_at2_units_read_from_header(name: str) -> None:
    gm = read_record(RECORDS / name)
    assert gm.units_read == "g"  # every AT2 here states G or (g)
    assert gm.metadata["npts_header"] == gm.npts


def test_sylmar_text_record_units_and_first_sample() -> None:
    """SOURCES.md: no header, m/s² inferred, first sample 0.061 m/s², PGA 8.27 m/s²; the
    file states no unit, so it cannot be read without one."""
    name = "northridge_1994_sylmar_county_2col_mps2.dat"
    with pytest.raises(ValueError, match=r"a plain-text record does not state its "
                                         r"acceleration unit; give its units: g, m/s2"):
        read_record(RECORDS / name)
    gm = load_bundled(name)
    assert gm.units_read == "m/s2 (assumed)"  # the manifest's unit, reported as assumed
    assert gm.accel[0] == pytest.approx(0.06113)
    assert gm.pga == pytest.approx(8.27, abs=0.005)
    assert gm.metadata["t0"] == 0.0


def test_first_values_converted_from_g() -> None:
    """First value of the PEER El Centro file is -.6403182E-02 g (header line 5)."""
    gm = read_record(RECORDS / "elcentro_1940_IV_ELC9_180_PEER.AT2")
    assert gm.accel[0] == pytest.approx(-0.6403182e-02 * G, rel=1e-12)
    assert gm.accel[-1] == pytest.approx(0.9459335e-04 * G, rel=1e-12)


def test_peknold_last_value_without_trailing_newline() -> None:
    raw = (RECORDS / "elcentro_1940_NS_peknold_8F10.5.AT2").read_bytes()
    assert not raw.endswith(b"\n")  # the case this test is about
    gm = read_record(RECORDS / "elcentro_1940_NS_peknold_8F10.5.AT2")
    assert gm.npts == 1559
    assert gm.accel[-2] == pytest.approx(-0.00006 * G)
    assert gm.accel[-1] == 0.0


# ------------------------------------------------------------------- the bundled suite
def test_bundled_suite_reads_the_files_checked_above() -> None:
    for name, gm in zip(bundled_records(), bundled_suite(), strict=True):
        read = read_record(RECORDS / name, units=UNITS.get(name))
        np.testing.assert_array_equal(gm.accel, read.accel)
        assert gm.dt == read.dt


def test_bundled_provenance_agrees_with_sources_md() -> None:
    """The manifest's provenance is SOURCES.md's, and reaches each record's metadata."""
    assert [e["file"] for e in MANIFEST] == bundled_files()
    for entry in MANIFEST:
        gm = load_bundled(entry["file"])
        row = SOURCES[entry["file"]]
        assert entry["git_blob"] == _blob(entry["file"])
        assert entry["earthquake"] == row["earthquake"]
        assert entry["station"] == row["station, component"]
        _, path = (s.strip() for s in row["source (repo : path)"].split(":", 1))
        assert entry["source"].endswith(path.removeprefix("GMS/"))
        assert gm.metadata["provenance"] == {k: entry[k] for k in
                                             ("earthquake", "station", "source", "git_blob")}


def test_bundled_units_stated_or_assumed() -> None:
    """Every AT2 states g; the Sylmar file states nothing and is read as m/s² (inferred in
    SOURCES.md), which the bundled record reports as assumed."""
    for gm in map(load_bundled, bundled_files()):
        assert gm.units_read == ("m/s2 (assumed)" if gm.name.endswith("_mps2") else "g")


def test_el_centro_is_the_peer_file() -> None:
    gm = el_centro()
    assert gm.npts == 4000
    assert gm.dt == 0.01
    assert gm.pga_g == pytest.approx(0.3129, rel=1e-3)
    assert gm.units_read == "g"
    assert gm.name == "El Centro 1940 (Array #9, 180)"
    assert gm.source == "pounding/data/records/elcentro_1940_IV_ELC9_180_PEER.AT2 (bundled)"
    np.testing.assert_array_equal(gm.accel, bundled_suite()[0].accel)
    assert load_bundled("tabas_1978_TAB_L1_RSN143") is load_bundled("tabas_1978_TAB_L1_RSN143.AT2")
    with pytest.raises(ValueError, match=r"bundled record: unknown name 'nope'; choose one of "
                                         r"elcentro_1940_IV_ELC9_180_PEER\.AT2, "):
        load_bundled("nope")
