"""`pounding run` / `pounding demo` and :func:`pounding.run`: outputs, and never a
half-written output folder."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from matplotlib.figure import Figure

import pounding.run_file as run_mod
from pounding.cli import main
from pounding.config import dump_toml, parse_config
from pounding.integrate import simulate
from pounding.io.manifest import MANIFEST_FILE
from pounding.plot.loops import plot_hysteresis
from pounding.plot.response import plot_contact_forces, plot_displacements, plot_energy
from pounding.result import IMPACT_COLUMNS, IMPACTS_CSV_COLUMNS
from pounding.plot.registry import RUN_FIGURES
from pounding.run_file import FIGURE_FILES, OUTPUT_FILES, run, run_config

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "examples" / "seed_sdof_pair.toml"
# the files of a run of a model with linear storeys (no storey hysteresis figure)
ALL_FILES = sorted([*OUTPUT_FILES.values(),
                    *(name for key, name in FIGURE_FILES.items()
                      if key != "storey_figure" and RUN_FIGURES[key].bridge is not True)])
# ... and the manifest of the files a run wrote (what --overwrite may replace)
IN_FOLDER = sorted([MANIFEST_FILE, *ALL_FILES])


def short_model(tmp_path: Path, duration: float = 3.0, **changes: Any) -> Path:
    """The seed pair, simulated for ``duration`` s only (impacts start near 2 s)."""
    data = {
        "name": "short pair",
        "record": {"bundled": "el_centro"},
        "building": [{"mass": 2e5, "period": 0.5}, {"mass": 3e5, "period": 1.0}],
        "contact": {"law": "nonlinear-viscoelastic", "k_h": 2.75e9, "e": 0.65, "gap": 0.02},
        "solver": {"duration": duration},
        **changes,
    }
    path = tmp_path / "short.toml"
    path.write_text(dump_toml(data), encoding="utf-8")
    return path


def leftovers(folder: Path) -> list[str]:
    """Hidden temporary entries left in ``folder``."""
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


# ------------------------------------------------------------------------ the CLI
def test_run_seed_example_writes_everything(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "out"
    assert main(["run", str(SEED), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    for expected in ("impacts", "26", "peak contact force [kN]", "peak roof displacement [mm]",
                     "peak drift", "dissipated in contacts [kJ]", "energy-balance error",
                     "wall time [s]", "B1F1-B2F1", str(out)):
        assert expected in text, expected
    assert sorted(p.name for p in out.iterdir()) == IN_FOLDER
    assert leftovers(tmp_path) == []

    with xr.open_dataset(out / "timehistories.nc", engine="h5netcdf") as ds:
        assert ds["displacement"].attrs["units"] == "m"
        assert ds["contact_force"].attrs["units"] == "N"
        assert ds["energy"].attrs["units"] == "J"
        assert ds["time"].attrs["units"] == "s"
        assert ds.sizes["floor"] == 2 and ds.sizes["contact"] == 1
        assert float(ds["time"][-1]) == pytest.approx(39.99)
    imp = pd.read_csv(out / "impacts.csv")
    assert list(imp.columns) == [IMPACTS_CSV_COLUMNS[c] for c in ("contact", "elevation",
                                                                  *IMPACT_COLUMNS[1:])]
    assert len(imp) == 26 and (imp["contact"] == "B1F1-B2F1").all()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["n_impacts"] == 26 and summary["model"] == "seed SDOF pair"
    assert summary["energy_balance_error"] < 1e-6
    for key, name in FIGURE_FILES.items():
        if name != "storeys.png" and RUN_FIGURES[key].bridge is not True:
            assert (out / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not (out / "storeys.png").exists()  # linear storeys: no storey hysteresis
    assert not (out / "bridge.png").exists()  # no bridge
    # the copy of the model file runs again as it is
    assert main(["run", str(out / "model.toml"), "--out", str(tmp_path / "again"),
                 "--no-figures"]) == 0
    again = json.loads((tmp_path / "again" / "summary.json").read_text())
    assert again["n_impacts"] == 26
    assert again["peak_contact_force_N"] == summary["peak_contact_force_N"]


def test_existing_output_needs_overwrite(tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    model = short_model(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(model), "--out", str(out), "--no-figures"]) == 0
    first = (out / "summary.json").read_text()
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert "already exists" in err and "--overwrite" in err and len(err.splitlines()) == 1
    assert (out / "summary.json").read_text() == first
    assert not (out / "energy.png").exists()
    assert main(["run", str(model), "--out", str(out), "--overwrite"]) == 0
    assert (out / "energy.png").exists()
    assert leftovers(tmp_path) == []
    # a folder that is not an earlier output is never replaced
    other = tmp_path / "precious"
    other.mkdir()
    (other / "thesis.tex").write_text("x")
    assert main(["run", str(model), "--out", str(other), "--overwrite"]) == 2
    assert "has no manifest of pounding's files" in capsys.readouterr().err
    assert [p.name for p in other.iterdir()] == ["thesis.tex"]


@pytest.mark.parametrize("change, expected", [
    ({"building": [{"mass": -2e5, "period": 0.5}, {"mass": 3e5, "period": 1.0}]},
     "building[0].mass: must be in (0, 1e+12] kg (got -200000)"),
    ({"contact": {"law": "nope", "gap": 0.02}}, "contact.law: unknown law 'nope'"),
    ({"contact": {"law": "hertz", "k_h": 1e9, "gap": 0.02, "gapp": 1}},
     "contact.gapp: unknown key"),
    ({"contact": {"law": "hertz", "k_h": 1e9, "gaps": [0.02, 0.01]}},
     "contact.gaps: need 1 value(s) for 2 buildings (got 2: [0.02, 0.01])"),
    ({"record": {"file": "missing.AT2"}}, "record.file: no such file"),
])
def test_bad_model_exits_2_with_one_line_and_writes_nothing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], change: dict[str, Any],
        expected: str) -> None:
    model = short_model(tmp_path, **change)
    out = tmp_path / "deep" / "out"
    assert main(["run", str(model), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert err.startswith("error: ") and expected in err
    assert str(model) in err
    assert not (tmp_path / "deep").exists()
    assert leftovers(tmp_path) == []


def test_missing_model_file_exits_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", str(tmp_path / "none.toml"), "--out", str(tmp_path / "o")]) == 2
    assert "no such model file" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_sweep_file_given_to_run_says_to_use_sweep(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sweep = Path(__file__).resolve().parents[1] / "examples" / "sweep_gap_e.toml"
    assert main(["run", str(sweep), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert "this is a sweep file" in err and f"pounding sweep {sweep}" in err
    assert not (tmp_path / "o").exists()


def test_demo(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "demo"
    assert main(["demo", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "two 10-storey buildings" in text and "B1F10-B2F10" in text
    assert sorted(p.name for p in out.iterdir()) == IN_FOLDER
    summary = json.loads((out / "summary.json").read_text())
    assert summary["n_impacts"] > 10 and len(summary["peak_displacement_m"]) == 20


# ------------------------------------------------------------------------ failures mid-run
def test_failure_mid_run_leaves_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def failing(*args: Any, progress: Any = None, **kw: Any) -> Any:
        if progress is not None:
            progress(0.3)
        raise RuntimeError("integration failed at t = 1.2 s")

    monkeypatch.setattr(run_mod, "simulate", failing)
    out = tmp_path / "new" / "out"
    with pytest.raises(RuntimeError, match="integration failed"):
        run(short_model(tmp_path), out, progress=lambda done, total: None)
    assert not (tmp_path / "new").exists()
    assert leftovers(tmp_path) == []


def test_failure_while_writing_keeps_the_previous_output(tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    model = short_model(tmp_path)
    out = tmp_path / "out"
    run(model, out, figures=False)
    before = {p.name: p.read_bytes() for p in out.iterdir()}

    def broken(*args: Any, **kw: Any) -> Any:
        raise OSError("disk full")

    # fails after the data files are already written into the temporary folder
    monkeypatch.setattr(run_mod, "_write_figures", broken)
    with pytest.raises(OSError, match="disk full"):
        run(model, out, overwrite=True, figures=True)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert leftovers(tmp_path) == []

    monkeypatch.setattr(run_mod, "simulate", lambda *a, **k: (_ for _ in ()).throw(
        KeyboardInterrupt()))
    with pytest.raises(KeyboardInterrupt):
        run(model, out, overwrite=True)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert leftovers(tmp_path) == []


def test_run_returns_its_outputs(tmp_path: Path) -> None:
    calls: list[tuple[float, float]] = []
    res = run(short_model(tmp_path), tmp_path / "o",
              progress=lambda done, total: calls.append((done, total)))
    assert res.out_dir == tmp_path / "o"
    assert sorted(p.name for p in res.files.values()) == ALL_FILES
    assert all(p.is_file() for p in res.files.values())
    assert res.result.n_impacts >= 1 and res.wall_time > 0
    # seconds of ground motion simulated, of the run's duration; the last call: all done
    duration = float(res.result.time[-1])
    assert calls and calls[-1] == pytest.approx((duration, duration))
    assert all(0.0 <= d <= t == calls[-1][1] for d, t in calls)
    mode = (tmp_path / "o" / "summary.json").stat().st_mode & 0o777
    assert mode & 0o044  # readable by others as with an ordinary write (umask 022)


def test_out_must_be_a_folder_name(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="not a folder name"):
        run(short_model(tmp_path), ".")
    f = tmp_path / "file"
    f.write_text("x")
    with pytest.raises(ValueError, match="not a folder"):
        run(short_model(tmp_path), f, overwrite=True)


# ------------------------------------------------------------------------ figures
def _labels(fig: Figure) -> str:
    return " ".join(ax.get_xlabel() + " " + ax.get_ylabel() for ax in fig.axes)


def test_figures_have_units_and_handle_no_contacts(tmp_path: Path) -> None:
    cfg = parse_config({"record": {"bundled": "el_centro"},
                        "building": [{"n_storeys": 3, "mass": 1e5, "period": 0.4},
                                     {"n_storeys": 2, "mass": 1e5, "period": 0.3}],
                        "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65,
                                    "gap": 0.02},
                        "solver": {"duration": 3.0}})
    model, motion, solver = cfg.build()
    r = simulate(model, motion, **solver)
    # displacements in mm, forces and energies in a multiple of N and J, the ground in g
    for make, units in ((plot_displacements, [r"\[mm\]", r"\[s\]", r"\[g\]"]),
                        (plot_contact_forces, [r"\[[kMG]?N\]", r"\[s\]", r"\[g\]"]),
                        (plot_hysteresis, [r"\[[kMG]?N\]", r"\[mm\]"]),
                        (plot_energy, [r"\[[kMG]?J\]", r"\[s\]"])):
        fig = make(r)
        assert isinstance(fig, Figure)
        for u in units:
            assert re.search(u, _labels(fig)), (make.__name__, u)
    # displacement panels: roof and both contact floors of the 3-storey building
    legend = [t.get_text() for t in plot_displacements(r).axes[0].get_legend().get_texts()]
    assert legend == ["F1 (3 m)", "F2 (6 m)", "F3 (roof, 9 m)"]

    one = parse_config({"record": {"bundled": "el_centro", "duration": 1.0},
                        "building": [{"mass": 1e5, "period": 0.5}]})
    res = run_config(one, tmp_path / "single")
    assert sorted(p.name for p in res.out_dir.iterdir()) == IN_FOLDER
    assert res.result.n_impacts == 0


def test_hysteresis_draws_only_closed_part(tmp_path: Path) -> None:
    res = run(short_model(tmp_path, duration=6.0), tmp_path / "o", figures=False)
    fig = plot_hysteresis(res.result)
    xs = np.concatenate([seg[:, 0] for ax in fig.axes for coll in ax.collections
                         for seg in coll.get_segments()])
    xs = xs[np.isfinite(xs)]
    assert xs.size > 10 and (xs > 0).all()


def test_inelastic_example_runs_from_the_cli(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 5: the yielding 5-storey pair, as a user runs it (shortened to 8 s)."""
    src = ROOT / "examples" / "inelastic_5_storey.toml"
    model_file = tmp_path / "m.toml"
    model_file.write_text(src.read_text() + "duration = 8.0\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(model_file), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    for expected in ("ductility", "residual", "bilinear", "Bouc-Wen"):
        assert expected in text, expected
    summary = json.loads((out / "summary.json").read_text())
    assert summary["energy_balance_error"] < 1e-6
    assert summary["hysteretic_energy_J"] > 0.0
    assert max(summary["ductility_demand"].values()) > 1.0
    assert set(summary["residual_drift_m"]) == {f"B{b}F{j}" for b in (1, 2) for j in range(1, 6)}
    with xr.open_dataset(out / "timehistories.nc", engine="h5netcdf") as ds:
        assert ds["ductility"].attrs["units"] == "1"
        assert ds["residual_drift"].attrs["units"] == "m"
        assert "hysteretic" in [str(v) for v in ds["energy_term"].values]
    assert (out / "storeys.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["report", str(out)]) == 0
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "peak storey ductility" in page


def test_floor_to_column_example_runs_from_the_cli(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 5: the mismatched-floor pair, as a user runs it (shortened to 8 s)."""
    src = ROOT / "examples" / "floor_to_column.toml"
    model_file = tmp_path / "m.toml"
    model_file.write_text(src.read_text() + "duration = 8.0\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(model_file), "--out", str(out), "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "column shear" in text and "B1F4-B2S4@0.14" in text
    summary = json.loads((out / "summary.json").read_text())
    assert summary["energy_balance_error"] < 1e-6
    assert "B1F5-B2F4" not in summary["peak_column_shear_N"]      # slab to slab
    assert summary["peak_column_shear_N"]["B1F4-B2S4@0.14"] > 0.0
    # the gap check handles column contacts too
    assert main(["gap", str(model_file), "--duration", "8"]) == 0
    gap_text = capsys.readouterr().out
    assert "critical separation gap" in gap_text and "11.5" in gap_text   # a column level


def test_a_bar_stuck_at_zero_says_the_solver_is_compiling() -> None:
    from rich.progress import Progress

    from pounding.cli.running import COMPILE_NOTE_AFTER, _CompilingNote

    clock = [0.0]
    bar = Progress(get_time=lambda: clock[0])
    task_id = bar.add_task("simulating", total=1.0)
    task = bar.tasks[0]
    note = _CompilingNote()
    assert note.render(task).plain == ""  # just started
    clock[0] = COMPILE_NOTE_AFTER + 1.0
    assert "compiling the solver" in note.render(task).plain
    bar.update(task_id, completed=0.02)  # the first chunk is done: running, not compiling
    assert note.render(task).plain == ""


def test_summary_carries_periods_and_per_storey_peaks_with_times(tmp_path: Path,
                                                                 capsys: pytest.CaptureFixture[str]
                                                                 ) -> None:
    # two uniform 3-storey buildings: periods against the closed form of the uniform chain,
    # ω_j = 2 √(k/m) sin((2j − 1) π / (2 (2n + 1))) (docs/structures.md)
    data = {"name": "three storeys", "record": {"bundled": "el_centro"},
            "building": [{"n_storeys": 3, "mass": 2e5, "stiffness": 2.5e8},
                         {"n_storeys": 3, "mass": 3e5, "stiffness": 6e8}],
            "contact": {"law": "kelvin-voigt", "k": 9.3e8, "e": 0.65, "gap": 0.01},
            "solver": {"duration": 4.0}}
    model = tmp_path / "three.toml"
    model.write_text(dump_toml(data), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(model), "--out", str(out), "--no-figures"]) == 0
    text = capsys.readouterr().out
    for expected in ("T1, T2, T3 [s]", "Storeys: peaks and when", "drift ratio [%]",
                     "storey shear [kN]", "abs. acceleration [m/s²]", "at t [s]"):
        assert expected in text, expected
    s = json.loads((out / "summary.json").read_text())
    for b, (m, k) in zip(s["buildings"], ((2e5, 2.5e8), (3e5, 6e8))):
        j = np.arange(1, 4)
        omega = 2 * np.sqrt(k / m) * np.sin((2 * j - 1) * np.pi / 14)
        np.testing.assert_allclose(b["periods_s"], 2 * np.pi / omega, rtol=1e-12)
        assert [row["storey"] for row in b["storeys"]] == [1, 2, 3]
        for row in b["storeys"]:
            assert 0.0 < row["peak_drift_time_s"] <= 4.0
            assert row["peak_storey_shear_N"] == pytest.approx(
                k * row["peak_drift_m"], rel=1e-12)  # linear storeys: V = k d
            assert row["peak_drift_ratio"] == pytest.approx(row["peak_drift_m"] / 3.0)
    assert s["solver"]["peaks"] == "located inside solver steps"
    assert set(s["peak_drift_time_s"]) == {f"B{b}F{f}" for b in (1, 2) for f in (1, 2, 3)}
    assert s["peak_contact_force_time_s"] == pytest.approx(
        max(s["peak_contact_force_time_by_contact_s"].items(),
            key=lambda kv: s["peak_contact_force_by_contact_N"][kv[0]])[1])


def test_the_model_toml_of_one_storey_buildings_with_default_damping_runs_again(
        tmp_path: Path) -> None:
    # the default damping (5 % Rayleigh at modes 1 and 2) is written back as such; a building
    # with one mode was then refused on reading it ("modes[1]: must be in [1, 1]")
    model = tmp_path / "m.toml"
    model.write_text("""
[record]
bundled = "el_centro"
duration = 3.0
[[building]]
name = "portal"
[building.frame]
bays = [6.0]
storey_heights = [4.0]
column_EI = 2e8
beam_EI = 2e8
floor_mass = 4e4
column_hinge = { type = "elastic-plastic", k0 = 1e11, m_y = 3e5 }
beam_hinge = { type = "elastic-plastic", k0 = 1e11, m_y = 3e5 }
[[building]]
n_storeys = 1
mass = 5e4
period = 0.3
height = 4.0
[contact]
law = "kelvin-voigt"
k = 1e9
e = 0.65
gap = 0.01
""")
    out, again = tmp_path / "out", tmp_path / "again"
    assert main(["run", str(model), "--out", str(out), "--no-figures"]) == 0
    assert main(["run", str(out / "model.toml"), "--out", str(again), "--no-figures"]) == 0
    first, second = (json.loads((d / "summary.json").read_text()) for d in (out, again))
    assert first["n_impacts"] == second["n_impacts"] > 0
    assert first["peak_contact_force_N"] == second["peak_contact_force_N"]
    # differing ratios at two modes of a building with one: still refused, in one line
    bad = model.read_text().replace("n_storeys = 1", "n_storeys = 1\ndamping = { rayleigh = "
                                    "[0.05, 0.02], modes = [1, 2] }")
    model.write_text(bad)
    assert main(["run", str(model), "--out", str(tmp_path / "bad"), "--no-figures"]) == 2
    assert not (tmp_path / "bad").exists()


def test_an_impact_open_at_the_end_is_said_beside_the_contact_table(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # the seed pair's first impact lasts 1.979-2.048 s: a run ending at 2.0 s ends inside it;
    # the table's "dissipated" sums finished impacts, the run's total the energy so far
    model = short_model(tmp_path, duration=2.0)
    assert main(["run", str(model), "--out", str(tmp_path / "o"), "--no-figures"]) == 0
    out = capsys.readouterr().out
    assert "1 still open at the end, whose energy so far is in the run's total" in " ".join(
        out.split())
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["contact_dissipated_J"] > 0.0
