"""``[[device]]`` in model files and sweeps, through the command line."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pounding.cli import main
from pounding.config import parse_config
from pounding.devices import Bumper, Link
from pounding.studies.sweep import load_results, load_sweep, run_sweep

MODEL = """
name = "linked pair"
[record]
bundled = "el_centro"
duration = 4.0
[[building]]
mass = 2e5
period = 0.5
[[building]]
mass = 3e5
period = 1.0
[contact]
law = "nonlinear-viscoelastic"
k_h = 2.75e9
e = 0.65
gap = 0.02
[[device]]
type = "viscous"
floors = ["B1F1", "B2F1"]
c = 3e5
alpha = 0.5
[[device]]
type = "bumper"
floors = ["B1F1", "B2F1"]
thickness = 0.01
compression_limit = 0.7
rubber = { law = "hertzdamp", k_h = 5e7, e = 0.5 }
"""


def test_devices_in_a_model_file_build_the_model_and_round_trip(tmp_path: Path):
    cfg = parse_config(__import__("tomllib").loads(MODEL))
    model, _, _ = cfg.build()
    link, bumper = model.devices
    assert link == Link(("B1F1", "B2F1"), "viscous", c=3e5, alpha=0.5)
    assert isinstance(bumper, Bumper) and bumper.thickness == 0.01
    assert [c.label for c in model.contacts] == ["B1F1-B2F1/bumper", "B1F1-B2F1"]
    again = parse_config(__import__("tomllib").loads(cfg.to_toml(defaults=True)))
    assert again.build().model.devices == model.devices


def test_a_linked_run_reports_its_links(tmp_path: Path, capsys):
    f = tmp_path / "m.toml"
    f.write_text(MODEL)
    assert main(["run", str(f), "--out", str(tmp_path / "o"), "--no-figures"]) == 0
    out = capsys.readouterr().out
    assert "Links between buildings" in out and "dissipated by links [kJ]" in out
    s = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert s["links"][0]["name"] == "B1F1-B2F1"
    assert s["links_dissipated_J"] == pytest.approx(s["energy_final_J"]["links"])
    assert s["links"][0]["dissipated_J"] == pytest.approx(s["links_dissipated_J"], rel=1e-3)
    assert s["energy_balance_error"] < 1e-7


@pytest.mark.parametrize("body, line", [
    ('[[device]]\ntype = "viscous"\nfloors = ["B1F1", "B2F1"]\n',
     "device[0].c: required by a viscous device"),
    ('[[device]]\ntype = "viscous"\nfloors = ["B1F1", "B2F1"]\nc = 1e5\nk = 1e6\n',
     "device[0].k: not used by a viscous device"),
    ('[[device]]\ntype = "damper"\nfloors = ["B1F1", "B2F1"]\nc = 1e5\n', "device[0].type"),
    ('[[device]]\ntype = "kelvin"\nfloors = ["B1F1", "B2F9"]\nc = 1e5\nk = 1e6\n',
     "device[0].floors: no floor B2F9 in this model"),
    ('[[device]]\ntype = "bumper"\nfloors = ["B1F1", "B2F1"]\nthickness = 0.05\n'
     'compression_limit = 0.5\nrubber = { law = "hertz", k_h = 1e7 }\n',
     "device[0].thickness: the B1F1-B2F1 bumper (0.05 m) is thicker than its gap (0.02 m)"),
])
def test_bad_devices_get_one_line_naming_the_field(tmp_path: Path, capsys, body, line):
    base = MODEL.split("[[device]]")[0]
    f = tmp_path / "m.toml"
    f.write_text(base + body)
    assert main(["run", str(f), "--out", str(tmp_path / "o"), "--no-figures"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and line in err[0], err
    assert not (tmp_path / "o").exists()


def test_a_sweep_over_a_damper_coefficient(tmp_path: Path):
    (tmp_path / "m.toml").write_text(MODEL.replace("duration = 4.0", "duration = 3.0"))
    (tmp_path / "s.toml").write_text('base = "m.toml"\nname = "c"\nout = "out"\n[grid]\n'
                                     '"device.0.c" = [1e5, 1e6, 1e7]\n'
                                     '"record.scale" = [0.5, 1.0]\n')
    res = run_sweep(load_sweep(tmp_path / "s.toml"), scheduler="synchronous")
    df = load_results(res.results)
    assert list(df["status"]) == ["ok"] * 6
    assert df["links_dissipated_J"].notna().all()
    # a stiffer damper pulls the floors together: the link force grows with c (at each
    # scale: the cases that share a model share it, the others do not)
    for _, at_scale in df.groupby("record.scale"):
        assert at_scale.sort_values("device.0.c")["peak_link_force_N"].is_monotonic_increasing
    # each case is the run of its own model file
    from pounding import simulate
    from pounding.config import load_config

    cfg = load_config(tmp_path / "m.toml")
    row = df[(df["device.0.c"] == 1e7) & (df["record.scale"] == 1.0)].iloc[0]
    data = cfg.to_dict(resolve_paths=True)
    data["device"][0]["c"] = 1e7
    from pounding.config import parse_config

    model, motion, kw = parse_config(data, tmp_path).build()
    assert row["peak_link_force_N"] == simulate(model, motion, **kw).link_peak_force.max()


def test_floors_all_puts_a_device_at_every_shared_floor_level():
    import tomllib

    text = MODEL.split("[[device]]")[0].replace(
        "[[building]]\nmass = 2e5\nperiod = 0.5",
        "[[building]]\nn_storeys = 3\nmass = 2e5\nperiod = 0.5").replace(
        "[[building]]\nmass = 3e5\nperiod = 1.0",
        "[[building]]\nn_storeys = 2\nmass = 3e5\nperiod = 1.0")
    text += '[[device]]\ntype = "kelvin"\nfloors = "all"\nc = 1e5\nk = 1e6\n'
    model = parse_config(tomllib.loads(text)).build().model
    assert [lk.floors for lk in model.links] == [("B1F1", "B2F1"), ("B1F2", "B2F2")]
