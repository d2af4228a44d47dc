"""`pounding pushover` end to end: the portal example's files, bad input, the output folder's
safety, and frames in model files (`frame = {...}`)."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest

from pounding.cli import main
from pounding.config import load_config, load_pushover
from pounding.example_files import example_path

PORTAL = example_path("portal_pushover")


@pytest.fixture(autouse=True)
def _capture(capsys: pytest.CaptureFixture[str]) -> None:
    global _CAPSYS
    _CAPSYS = capsys


_CAPSYS: pytest.CaptureFixture[str]


def _run(*args: str) -> tuple[int, str]:
    """The command's exit status and what it printed (standard output and error)."""
    _CAPSYS.readouterr()
    code = main(list(args))
    got = _CAPSYS.readouterr()
    return code, got.out + got.err


def test_portal_example_writes_its_curve_and_reaches_four_mp_over_h(tmp_path: Path) -> None:
    code, out = _run("pushover", str(PORTAL), "--out", str(tmp_path / "p"))
    assert code == 0, out
    with open(tmp_path / "p" / "pushover.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0])[:4] == ["roof_displacement_m", "base_shear_N", "storey_1_drift_m",
                                 "storey_1_shear_N"]
    shear = np.array([float(r["base_shear_N"]) for r in rows])
    roof = np.array([float(r["roof_displacement_m"]) for r in rows])
    assert shear.max() == pytest.approx(4 * 300e3 / 4.0, rel=1e-9)  # 4 Mp / h
    assert roof[-1] == pytest.approx(0.2)
    summary = json.loads((tmp_path / "p" / "summary.json").read_text())
    assert summary["peak_base_shear_N"] == pytest.approx(300e3, rel=1e-9)
    assert summary["stopped"] == "target"
    assert summary["first_yield"]["hinges"] == [0, 2]  # the two column bases yield first
    hinges = list(csv.DictReader(open(tmp_path / "p" / "hinges.csv", newline="")))
    assert [h["yielded"] for h in hinges] == ["true"] * 4 + ["false"] * 2
    assert (tmp_path / "p" / "pushover.png").stat().st_size > 10_000


def test_options_override_the_file(tmp_path: Path) -> None:
    code, out = _run("pushover", str(PORTAL), "--out", str(tmp_path / "p"), "--to", "0.05",
                     "--pattern", "triangular", "--no-figures")
    assert code == 0, out
    summary = json.loads((tmp_path / "p" / "summary.json").read_text())
    assert summary["target_roof_displacement_m"] == 0.05
    assert summary["pattern"] == "triangular"
    assert not (tmp_path / "p" / "pushover.png").exists()


@pytest.mark.parametrize(("args", "says"), [
    (["--to", "-1"], "--to: the roof displacement must be finite and > 0 [m] (got -1.0)"),
    (["--to", "nan"], "--to: the roof displacement must be finite and > 0 [m] (got nan)"),
    (["--pattern", "sideways"], "--pattern: must be one of first-mode, uniform, triangular "
                                "(got 'sideways')"),
    (["--building", "tower"], "--building: no frame named 'tower' (frames: 'portal')"),
    (["--pattern", "first-mode"], "pattern: first-mode needs floor masses; portal has none"),
])
def test_bad_options_say_one_line_and_write_nothing(tmp_path: Path, args: list[str],
                                                    says: str) -> None:
    code, out = _run("pushover", str(PORTAL), "--out", str(tmp_path / "p"), *args)
    assert code == 2
    assert says in out
    assert not (tmp_path / "p").exists()


def test_a_folder_not_written_by_pounding_is_never_replaced(tmp_path: Path) -> None:
    mine = tmp_path / "p"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep")
    code, out = _run("pushover", str(PORTAL), "--out", str(mine), "--overwrite")
    assert code == 2 and "has no manifest" in out
    assert (mine / "notes.txt").read_text() == "keep"
    # an earlier pushover is replaced with --overwrite, and not without
    assert _run("pushover", str(PORTAL), "--out", str(tmp_path / "q"))[0] == 0
    code, out = _run("pushover", str(PORTAL), "--out", str(tmp_path / "q"))
    assert code == 2 and "already exists" in out
    assert _run("pushover", str(PORTAL), "--out", str(tmp_path / "q"), "--overwrite")[0] == 0


def _write(tmp_path: Path, text: str) -> Path:
    f = tmp_path / "m.toml"
    f.write_text(text, encoding="utf-8")
    return f


def test_bad_frame_keys_name_the_key(tmp_path: Path) -> None:
    f = _write(tmp_path, """
[[building]]
frame = { bays = [6.0], storey_heights = [4.0, 3.0], column_EI = [2e8, 2e8, 2e8], beam_EI = 2e8 }
""")
    with pytest.raises(ValueError, match=r"building\[0\]\.frame\.column_EI: need one value or 2 "
                                         r"\(one per storey\), got 3"):
        load_pushover(f)
    f = _write(tmp_path, """
[[building]]
[building.frame]
bays = [6.0]
storey_heights = [4.0]
column_EI = 2e8
beam_EI = 2e8
column_hinge = { type = "elastic-plastic", k0 = 1e11, m_y = -3e5 }
""")
    with pytest.raises(ValueError, match=r"building\[0\]\.frame\.column_hinge\.m_y"):
        load_pushover(f)


def test_full_form_matches_the_regular_form(tmp_path: Path) -> None:
    """The portal written node by node pushes exactly as the regular form does."""
    f = _write(tmp_path, """
[[building]]
name = "portal"
[building.frame]
nodes = [[0.0, 0.0], [6.0, 0.0], [0.0, 4.0], [6.0, 4.0]]
supports = [{ node = 0 }, { node = 1, fix = "fixed" }]
members = [
  { nodes = [0, 2], EI = 2.0e8, hinges = [{ type = "elastic-plastic", k0 = 1e11, m_y = 3e5 },
                                          { type = "elastic-plastic", k0 = 1e11, m_y = 3e5 }] },
  { nodes = [1, 3], EI = 2.0e8, hinges = [{ type = "elastic-plastic", k0 = 1e11, m_y = 3e5 },
                                          { type = "elastic-plastic", k0 = 1e11, m_y = 3e5 }] },
  { nodes = [2, 3], EI = 2.0e8, hinges = [{ type = "elastic-plastic", k0 = 1e11, m_y = 6e5 },
                                          { type = "elastic-plastic", k0 = 1e11, m_y = 6e5 }] },
]
[pushover]
target = 0.2
""")
    code, out = _run("pushover", str(f), "--out", str(tmp_path / "full"), "--no-figures")
    assert code == 0, out
    code, out = _run("pushover", str(PORTAL), "--out", str(tmp_path / "reg"), "--no-figures")
    full = np.loadtxt(tmp_path / "full" / "pushover.csv", delimiter=",", skiprows=1)
    reg = np.loadtxt(tmp_path / "reg" / "pushover.csv", delimiter=",", skiprows=1)
    assert full == pytest.approx(reg, rel=1e-9, abs=1e-9)


def test_an_elastic_frame_runs_and_pounds_as_its_condensed_matrices(tmp_path: Path) -> None:
    """A frame without hinges in a time history: its floors' condensed stiffness; its first
    period is the rigid-beam closed form when the beams are rigid."""
    f = _write(tmp_path, """
[record]
bundled = "el_centro"
[[building]]
name = "A"
frame = { bays = [6.0], height = 4.0, n_storeys = 1, column_EI = 2e8, beam_EI = 2e16, column_EA = 1e16, floor_mass = 1e5 }
[[building]]
name = "B"
n_storeys = 1
mass = 1e5
period = 0.5
height = 4.0
[contact]
law = "linear-spring"
k = 1e9
gap = 0.01
""")
    model, _, _ = load_config(f).build()
    frame = model.buildings[0]
    expected = 2 * math.pi / math.sqrt(2 * 12 * 2e8 / 4.0 ** 3 / 1e5)
    assert frame.modes().periods[0] == pytest.approx(expected, rel=1e-6)


def test_a_yielding_frame_runs_and_reports_its_hinges(tmp_path: Path) -> None:
    # (before: refused by `pounding run`, "time histories of yielding frames are not
    # available yet")
    f = _write(tmp_path, PORTAL.read_text().replace(
        'beam_hinge = { type = "elastic-plastic", k0 = 1.0e11, m_y = 6.0e5 }',
        'beam_hinge = { type = "elastic-plastic", k0 = 1.0e11, m_y = 6.0e5 }\n'
        'floor_mass = 5.0e4').replace("[pushover]", """
[record]
bundled = "el_centro"
scale = 3.0
duration = 4.0
[pushover]"""))
    code, out = _run("run", str(f), "--out", str(tmp_path / "r"), "--no-figures")
    assert code == 0, out
    # the printout: the hinges' hysteretic energy and the table of hinges that yielded
    assert "hysteretic, frames' plastic hinges [" in out
    flat = " ".join(out.split())  # (a narrow terminal wraps the titles)
    assert "4 of 6 hinges yielded" in flat, out
    summary = json.loads((tmp_path / "r" / "summary.json").read_text())
    hinges = {h["hinge"]: h for h in summary["hinges"]}
    assert list(hinges) == [f"B1H{h}" for h in range(1, 7)]
    # the sway mechanism: the four column hinges yield (300 kN·m), the beam's do not
    assert [hinges[f"B1H{h}"]["peak_moment_N_m"] for h in range(1, 5)] == \
        pytest.approx([300e3] * 4, rel=1e-8)  # (to the event tolerance of a rotation, × k0)
    assert all(hinges[f"B1H{h}"]["peak_rotation_rad"] > 1e-3 for h in range(1, 5))
    assert all(hinges[f"B1H{h}"]["peak_rotation_rad"] <= 3e-6 * (1 + 1e-9) for h in (5, 6))
    assert summary["hinge_hysteretic_energy_J"] > 0.0
    assert summary["energy_balance_error"] < 1e-8
    import xarray as xr

    with xr.open_dataset(tmp_path / "r" / "timehistories.nc") as ds:
        assert ds["hinge_rotation"].attrs["units"] == "rad"
        assert ds["hinge_moment"].attrs["units"] == "N m"
        assert float(abs(ds["hinge_moment"]).max()) == pytest.approx(300e3, rel=1e-8)


def test_the_report_of_a_pushover_folder_shows_the_curve(tmp_path: Path) -> None:
    from pounding.report import detect_kind, write_report

    assert _run("pushover", str(PORTAL), "--out", str(tmp_path / "p"))[0] == 0
    assert detect_kind(tmp_path / "p") == "pushover"
    html = write_report(tmp_path / "p").read_text(encoding="utf-8")
    assert "300 kN" in html and "250 kN at 5.346 mm" in html  # peak; first yield
    assert "data:image/png;base64," in html
    # pounding's own report is listed, so an earlier pushover folder stays replaceable
    assert _run("pushover", str(PORTAL), "--out", str(tmp_path / "p"), "--overwrite")[0] == 0


IMK_PORTAL = """
[[building]]
name = "portal"
[building.frame]
bays = [6.0]
storey_heights = [4.0]
column_EI = 2.0e8
beam_EI = 2.0e8
column_hinge = { type = "imk-bilinear", k0 = 1.0e11, m_y = 3.0e5, theta_p = 0.025, theta_pc = 0.15, theta_u = 0.12, Lambda = 1.0 }
beam_hinge = { type = "imk-peak-oriented", k0 = 1.0e11, m_y = 6.0e5, theta_p = 0.03, theta_pc = 0.2 }
[pushover]
target = 0.6
stop_below = 0.05
"""


def test_imk_hinges_in_a_model_file_push_through_capping_and_fracture(tmp_path: Path) -> None:
    """Column hinges cap at M_c = 1.1 M_y (default mc_my) and fracture at θ_u: the sway
    mechanism's peak lies between 4 M_y / h = 300 kN and 4 M_c / h = 330 kN (the bases cap
    and soften before the tops cap), and the push ends on the strength criterion."""
    from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented

    pf = load_pushover(_write(tmp_path, IMK_PORTAL))
    laws = [h.law for h in pf.frame.hinges]
    assert all(isinstance(law, IMKBilinear) for law in laws[:4])
    assert all(isinstance(law, IMKPeakOriented) for law in laws[4:])
    assert laws[0].theta_u == 0.12 and laws[0].lambda_ == 1.0
    code, out = _run("pushover", str(tmp_path / "m.toml"), "--out", str(tmp_path / "p"),
                     "--no-figures")
    assert code == 0, out
    summary = json.loads((tmp_path / "p" / "summary.json").read_text())
    assert 4 * 3e5 / 4.0 < summary["peak_base_shear_N"] <= 4 * 1.1 * 3e5 / 4.0 * (1 + 1e-12)
    assert summary["stopped"] == "strength"


@pytest.mark.parametrize(("change", "says"), [
    ("theta_p = 0.025, ", r"column_hinge\.theta_p: required for an imk-bilinear hinge"),
    ("Lambda = 1.0", r"column_hinge\.hardening: not a constant of imk-bilinear"),
    ("theta_u = 0.12, Lambda = 1.0", r"column_hinge\.Lambda_A: only for imk-peak-oriented"),
])
def test_imk_keys_are_checked(tmp_path: Path, change: str, says: str) -> None:
    replacement = {"theta_p = 0.025, ": "", "Lambda = 1.0": "hardening = 0.02",
                   "theta_u = 0.12, Lambda = 1.0": "Lambda_A = 1.0"}[change]
    text = IMK_PORTAL.replace(change, replacement, 1)
    with pytest.raises(ValueError, match=says):
        load_pushover(_write(tmp_path, text))


def test_a_frame_on_a_foundation_is_refused_and_nothing_written(tmp_path: Path) -> None:
    """A pushover is on a fixed base: a frame with ``foundation`` is refused in one line
    naming the field (exit 2, no folder), not pushed as if the footing were not there."""
    model = tmp_path / "soil.toml"
    model.write_text(PORTAL.read_text(encoding="utf-8").replace(
        "[building.frame]",
        'foundation = { length = 8.0, width = 6.0, mass = 1.5e5, inertia = 1.2e6, '
        'soil = { vs = 60.0, density = 1800.0, poisson = 0.33 } }\n\n[building.frame]', 1),
        encoding="utf-8")
    assert "foundation = {" in model.read_text(encoding="utf-8")
    code, out = _run("pushover", str(model), "--out", str(tmp_path / "p"))
    assert code == 2
    lines = [ln for ln in out.splitlines() if ln.strip()]
    assert len(lines) == 1 and "Traceback" not in out
    assert lines[0].endswith("building[0].foundation: a pushover is on a fixed base; remove "
                             "foundation to push the frame")
    assert not (tmp_path / "p").exists()
