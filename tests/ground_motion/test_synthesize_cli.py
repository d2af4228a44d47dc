"""`pounding synthesize`: the records written read back as the generator makes them, the
median spectrum written is the records' own, the same seed writes the same files, and bad
values are one line, exit 2, nothing written."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from pounding.cli import main
from pounding.ground_motion import read_record
from pounding.ground_motion.rezaeian2010 import Scenario, stochastic_motion
from pounding.spectra import response_spectrum
from pounding.units import G

ARGS = ["synthesize", "-m", "6.5", "-r", "15", "--vs30", "400", "--mechanism", "reverse",
        "-n", "3", "--seed", "4", "--time-step", "0.02"]


def test_the_records_read_back_and_the_median_is_theirs(tmp_path):
    out = tmp_path / "suite"
    assert main([*ARGS, "--out", str(out)]) == 0
    files = sorted(out.glob("*.AT2"))
    assert len(files) == 3
    psa = []
    for i, f in enumerate(files):
        gm = read_record(f)
        own = stochastic_motion(Scenario(6.5, 15.0, 400.0, "reverse"), 4, i, dt=0.02)
        assert gm.dt == pytest.approx(0.02) and gm.npts == own.npts
        np.testing.assert_allclose(gm.accel, own.accel, atol=5e-8 * own.pga + 1e-12)
        psa.append(response_spectrum(gm, [0.2, 1.0]).psa[0] / G)
    with (out / "spectrum.csv").open() as fh:
        rows = {float(r["period_s"]): r for r in csv.DictReader(fh)}
    median = np.exp(np.log(np.array(psa)).mean(axis=0))
    assert float(rows[0.2]["median_psa_g"]) == pytest.approx(median[0], rel=1e-6)
    assert float(rows[1.0]["median_psa_g"]) == pytest.approx(median[1], rel=1e-6)
    assert {r["damping"] for r in rows.values()} == {"0.05"}  # the medians' damping, said
    with (out / "parameters.csv").open() as fh:
        assert len(list(csv.DictReader(fh))) == 3


def test_the_same_seed_writes_the_same_files(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    assert main([*ARGS, "--out", str(a)]) == 0
    assert main([*ARGS, "--out", str(b)]) == 0
    for f in sorted(a.glob("*.AT2")) + [a / "spectrum.csv", a / "parameters.csv"]:
        assert f.read_bytes() == (b / f.name).read_bytes()


@pytest.mark.parametrize(("change", "message"), [
    (["-m", "10"], "--magnitude"),
    (["-r", "0"], "--distance"),
    (["--vs30", "50"], "--vs30"),
    (["--time-step", "0.05"], "--time-step"),
    (["-n", "0"], "--count"),
    (["--mechanism", "normal"], "--mechanism"),
])
def test_bad_values_are_one_line(tmp_path, capsys, change, message):
    assert main([*ARGS, *change, "--out", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_an_existing_folder_is_not_replaced_without_overwrite(tmp_path, capsys):
    out = tmp_path / "mine"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    assert main([*ARGS, "--out", str(out)]) == 2
    assert main([*ARGS, "--out", str(out), "--overwrite"]) == 2
    assert [p.name for p in out.iterdir()] == ["notes.txt"]
