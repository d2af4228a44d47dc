"""The real records against the values an independent parser wrote into SOURCES.md."""

from __future__ import annotations

import hashlib
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from pounding.ground_motion import bundled_records, el_centro, read_record
from pounding.units import G

RECORDS = Path(__file__).parent / "records"


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


def _git_blob_id(data: bytes) -> str:
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def test_sources_table_lists_every_record_file() -> None:
    files = sorted(p.name for p in RECORDS.iterdir()
                   if p.is_file() and p.name not in {"SOURCES.md", ".gitattributes"})
    assert sorted(SOURCES) == files
    assert len(files) == 10


@pytest.mark.parametrize("name", sorted(SOURCES))
def test_copy_is_byte_for_byte(name: str) -> None:
    """The test copies (line ends included) hash to the blob ids SOURCES.md gives."""
    assert _git_blob_id((RECORDS / name).read_bytes()) == SOURCES[name]["git blob"]


@pytest.mark.parametrize("name", sorted(SOURCES))
def test_record_matches_sources(name: str) -> None:
    row = SOURCES[name]
    gm = read_record(RECORDS / name)
    assert gm.npts == int(row["NPTS"])
    assert gm.dt == pytest.approx(float(row["DT s"]), rel=1e-9)
    assert gm.pga_g == pytest.approx(float(row["PGA g"]), rel=1e-3)
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
    """SOURCES.md: no header, m/s² inferred, first sample 0.061 m/s², PGA 8.27 m/s²."""
    gm = read_record(RECORDS / "northridge_1994_sylmar_county_2col_mps2.dat")
    assert gm.units_read == "m/s2 (assumed)"
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


# ------------------------------------------------------------------- bundled record
def test_bundled_el_centro_is_the_peer_file() -> None:
    data = resources.files("pounding").joinpath("data").joinpath(
        "elcentro_1940_IV_ELC9_180_PEER.AT2").read_bytes()
    bundled_sources = _sources_table(
        Path(str(resources.files("pounding").joinpath("data").joinpath("SOURCES.md"))))
    row = bundled_sources["elcentro_1940_IV_ELC9_180_PEER.AT2"]
    assert _git_blob_id(data) == row["git blob"] == \
        SOURCES["elcentro_1940_IV_ELC9_180_PEER.AT2"]["git blob"]
    assert "elcentro_1940_IV_ELC9_180_PEER.AT2" in bundled_records()

    gm = el_centro()
    assert gm.npts == 4000
    assert gm.dt == 0.01
    assert gm.pga_g == pytest.approx(0.3129, rel=1e-3)
    assert gm.units_read == "g"
    assert "El Centro" in gm.name
    reference = read_record(RECORDS / "elcentro_1940_IV_ELC9_180_PEER.AT2")
    np.testing.assert_array_equal(gm.accel, reference.accel)
