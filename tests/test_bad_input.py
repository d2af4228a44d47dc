"""Bad input through the command line: one line per problem, each starting ``error:``,
exit status 2, nothing written — found before anything large is allocated; what a killed
run leaves behind is cleaned up by the next; the model file echoed into an output folder
states every default it took."""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import load_config
from pounding.integrate import simulate
from pounding.structure import ShearBuilding

BASE = ('[record]\nbundled = "el_centro"\n[[building]]\nmass = 2e5\nperiod = 0.5\n'
        '[[building]]\nmass = 3e5\nperiod = 1.0\n[contact]\nlaw = "kelvin-voigt"\n'
        'k = 9.3e8\ne = 0.65\ngap = 0.02\n')


def run_file(tmp_path: Path, text: str, capsys: pytest.CaptureFixture[str],
             *extra: str) -> tuple[int, list[str]]:
    model = tmp_path / "model.toml"
    model.write_text(text)
    capsys.readouterr()
    code = main(["run", str(model), "--out", str(tmp_path / "out"), "--no-figures", *extra])
    return code, capsys.readouterr().err.strip().splitlines()


@pytest.mark.parametrize("change, expected", [
    ("[solver]\ndt = 1e-12\n", r"solver: 39\.99 s at an output step of 1e-12 s is 4e\+13 "
                               r"output times; the histories would take .* GiB"),
    ("[solver]\nduration = 1e5\ndt = 1e-7\n", r"solver: 100000 s .* 1e\+12 output times"),
])
def test_runs_too_large_for_memory_are_refused_before_allocating(tmp_path, capsys, change,
                                                                 expected):
    code, err = run_file(tmp_path, BASE + change, capsys)
    assert code == 2 and len(err) == 1
    assert err[0].startswith("error: ") and __import__("re").search(expected, err[0])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.toml"]


@pytest.mark.parametrize("old, new, expected", [
    ("mass = 2e5\nperiod = 0.5", "n_storeys = 1000000000000000000\nmass = 2e5\nperiod = 0.5",
     "building[0].n_storeys: must be in [1, 10000] (got 1000000000000000000)"),
    ("mass = 2e5", "mass = 5e-324", "building[0].mass: must be at least 2.23e-308: smaller "
                                    "positive numbers are subnormal (got 4.94066e-324)"),
    ("mass = 2e5", "mass = 1e308", "building[0].mass: must be in (0, 1e+12] kg (got 1e+308)"),
    ("mass = 2e5\nperiod = 0.5", "mass = 1e12\nperiod = 1e-150",
     "building[0]: mass 1e+12 kg with period 1e-150 s gives a storey stiffness m (2π/T)² = "
     "inf N/m"),
])
def test_building_inputs_are_named_as_given(tmp_path, capsys, old, new, expected):
    code, err = run_file(tmp_path, BASE.replace(old, new, 1), capsys)
    assert code == 2 and len(err) == 1 and expected in err[0], err


def test_the_library_refuses_the_same_before_allocating():
    with pytest.raises(ValueError, match="n_storeys must be at most 10000"):
        ShearBuilding.uniform(10**18, 2e5, 1e8)
    with pytest.raises(ValueError, match=r"masses\[0\] must be at least"):
        ShearBuilding(masses=[5e-324], stiffnesses=[1e6], heights=[3.0])
    with pytest.raises(ValueError, match="mass 1e\\+308 kg with period 0.5 s"):
        ShearBuilding.sdof(1e308, period=0.5)
    model, motion, _ = load_config_text(BASE)
    with pytest.raises(ValueError, match="would take"):
        simulate(model, motion, dt=1e-12)


def load_config_text(text: str):  # noqa: ANN201
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "m.toml"
        p.write_text(text)
        return load_config(p).build()


@pytest.mark.parametrize("record, content, expected", [
    ('file = "rec.txt"\ndt = 0.01\nunits = "m/s2"', "0.1\n0.2\n1e309\n0.3\n",
     "{model}: record: {rec}: line 3: acceleration value 1e309 is not finite: it is "
     "beyond the largest float (1.8e+308) and reads as inf"),
    ('file = "rec.txt"\ndt = 0.01\nunits = "g"', "0.1\n1e308\n",
     "{model}: record: {rec}: line 2: acceleration value 1e+308 g is beyond the largest "
     "float (1.8e+308) in m/s2"),
    # a text record states no unit, and none is assumed: El Centro in g read as m/s2
    # would be ten times too weak
    ('file = "rec.txt"\ndt = 0.01', "0.0064\n0.31\n-0.2\n",
     "{model}: record.units: file = 'rec.txt' is a plain-text record, which does not state "
     "its acceleration unit; give units = \"g\" (or m/s2, cm/s2, gal, mm/s2, in/s2 or "
     "ft/s2)"),
    ('file = "rec.txt"', None,
     "{model}: record.file: '{rec}' is a directory, not a record file (got 'rec.txt'; "
     "relative paths start at the model file's folder)"),
    ('bundled = "el_centro"\nscale = 1e308', None,
     "{model}: record.scale: must be in [-1000, 1000] (got 1e+308)"),
])
def test_record_files_that_overflow_or_are_folders_are_one_line(tmp_path, capsys, record,
                                                                content, expected):
    rec = tmp_path / "rec.txt"
    if content is None:
        rec.mkdir()
    else:
        rec.write_text(content)
    code, err = run_file(tmp_path, BASE.replace('bundled = "el_centro"', record), capsys)
    assert code == 2 and err == ["error: " + expected.format(model=tmp_path / "model.toml",
                                                             rec=rec)], err
    assert not (tmp_path / "out").exists()


def test_gap_records_folder_is_named_a_folder(tmp_path, capsys):
    model = tmp_path / "model.toml"
    model.write_text(BASE)
    capsys.readouterr()
    assert main(["gap", str(model), "--records", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: --records: {tmp_path}: is a directory, not a record file"]


@pytest.mark.parametrize("argv, kind", [
    (["run", "{d}", "--out", "{d}/out"], "model file"),
    (["sweep", "{d}"], "sweep file"),
    (["gap", "{model}", "--design", "{d}"], "spectrum file"),
])
def test_a_folder_given_for_an_input_file_is_named_a_folder(tmp_path, capsys, argv, kind):
    folder = tmp_path / "inputs"
    folder.mkdir()
    model = tmp_path / "model.toml"
    model.write_text(BASE)
    capsys.readouterr()
    assert main([a.format(d=folder, model=model) for a in argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: {folder}: is a directory, not a {kind}"]
    assert list(folder.iterdir()) == []


def test_every_line_of_a_multi_error_message_starts_alike(tmp_path, capsys):
    code, err = run_file(tmp_path, BASE.replace("gap = 0.02", "gap = -1\nk_x = 3"), capsys)
    assert code == 2 and len(err) == 2
    assert all(line.startswith("error: ") and "model.toml: contact." in line for line in err)


def test_out_inside_a_file_is_one_line(tmp_path, capsys):
    (tmp_path / "afile").write_text("x")
    code, err = run_file(tmp_path, BASE, capsys, "--out", str(tmp_path / "afile" / "out"))
    assert code == 2 and len(err) == 1
    assert err[0] == (f"error: out: {tmp_path / 'afile' / 'out'} cannot be made: "
                      f"{tmp_path / 'afile'} is a file, not a folder; choose another --out")


def test_out_in_a_read_only_folder_is_one_line(tmp_path, capsys, read_only_folder):
    ro = read_only_folder  # (as root: /proc/sys; see conftest.py)
    code, err = run_file(tmp_path, BASE, capsys, "--out", str(ro / "out"))
    assert code == 2 and len(err) == 1 and err[0].startswith(f"error: out: cannot write in {ro}")


def test_a_killed_runs_leftovers_are_cleaned_by_the_next_run(tmp_path, capsys):
    # what `kill -9` during a run leaves: its temporary folder, named with its (dead) pid
    # and marked as pounding's (pounding.io.output_folder.make_temporary_folder)
    import json

    from pounding.io.manifest import TEMPORARY_MARKER

    def marked(name: str, pid: int, holds: list[str]) -> Path:
        folder = tmp_path / name
        folder.mkdir()
        (folder / TEMPORARY_MARKER).write_text(json.dumps({"pid": pid, "holds": holds}))
        return folder

    dead = 2**22 + 12345  # above the kernel's pid limit: never a live process
    stale = marked(f".out.tmp-{dead}-abcdefgh", dead, ["timehistories.nc"])
    (stale / "timehistories.nc").write_text("half written")
    live = marked(f".out.tmp-{os.getpid()}-efghijkl", os.getpid(), [])  # a run still going
    unmarked = tmp_path / f".out.tmp-{dead}-mnopqrst"  # not pounding's: left alone
    unmarked.mkdir()
    short = BASE + "[solver]\nduration = 1.0\n"
    code, _ = run_file(tmp_path, short, capsys)
    assert code == 0
    assert not stale.exists() and live.exists() and unmarked.exists()
    # killed while replacing an earlier output: that output is put back
    old = marked(f".out.old-{dead}-ijklmnop", dead, ["out"])
    os.replace(tmp_path / "out", old / "out")
    code, _ = run_file(tmp_path, short, capsys, "--overwrite")
    assert code == 0 and (tmp_path / "out" / "summary.json").is_file() and not old.exists()


def test_the_echoed_model_file_states_every_default_and_runs_the_same(tmp_path, capsys):
    code, _ = run_file(tmp_path, BASE + "[solver]\nduration = 3.0\n", capsys)
    assert code == 0
    echo = tomllib.loads((tmp_path / "out" / "model.toml").read_text())
    assert echo["solver"] == {"dt": 0.001, "duration": 3.0, "rtol": 1e-8, "h_max": 0.001}
    assert [b["damping"] for b in echo["building"]] == [{"ratio": 0.05}] * 2
    assert [b["height"] for b in echo["building"]] == [3.0, 3.0]
    assert [b["name"] for b in echo["building"]] == ["B1", "B2"]
    assert "formula" in echo["contact"] and echo["output"] == {"figures": True, "dpi": 150}
    again = tmp_path / "again"
    assert main(["run", str(tmp_path / "out" / "model.toml"), "--out", str(again),
                 "--no-figures"]) == 0
    a = np.loadtxt(tmp_path / "out" / "impacts.csv", delimiter=",", skiprows=1, usecols=(1, 2, 5))
    b = np.loadtxt(again / "impacts.csv", delimiter=",", skiprows=1, usecols=(1, 2, 5))
    assert np.array_equal(a, b)


@pytest.mark.parametrize("argv", [
    ["collide", "hunt-crossley", "--e", "0.65"],   # the law given as a positional
    ["collide", "--law", "hertz-ish"],             # a choice that is not one
])
def test_usage_errors_listing_choices_are_one_line(capsys, argv):
    capsys.readouterr()
    code = main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and err[0].startswith("error: pounding collide: "), err
    assert "hunt-crossley" in err[0] and "(see 'pounding collide --help')" in err[0]


def test_collide_without_e_names_the_option(capsys):
    capsys.readouterr()
    assert main(["collide", "--law", "hunt-crossley"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["error: --e: required for the hunt-crossley law (its coefficient of "
                   "restitution, e.g. --e 0.65)"]
    assert main(["collide", "--law", "hertz"]) == 0  # (undamped: no e)
