"""Studies of yielding frames: the sweep table's hinge columns against closed forms (a
portal's sway mechanism, the published IMK backbone), the fragility demands
``plastic_rotation`` and ``collapse`` end to end through ``pounding fragility`` against
counts recomputed from runs made directly, a run that stops as its frame loses its strength,
and mitigation and gap studies on a frame model."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pounding.cli import main
from pounding.config import load_config, parse_config
from pounding.ground_motion import GroundMotion
from pounding.integrate import simulate
from pounding.structure.frame_configuration import FrameCollapse
from pounding.studies.sweep.hinge_measures import HINGE_MEASURES, hinge_row

ROOT = Path(__file__).resolve().parents[2]
RECORDS = ROOT / "src" / "pounding" / "data" / "records"

H, MY, K0 = 4.0, 3.0e5, 1.0e9  # portal: storey height [m], column hinge M_y [N·m], k0 [N·m/rad]


def _portal(law: dict) -> object:
    """A one-bay portal (span 6 m, h = 4 m, columns EI = 2e8 N·m², a beam 1e6 times as
    stiff: the column ends turn alike) with hinges at the four column ends, 1e5 kg, beside a
    shear building 1 m away (never struck)."""
    data = {"name": "portal", "record": {"bundled": "el_centro"},
            "building": [{"name": "portal", "damping": {"ratio": 0.02},
                          "frame": {"bays": [6.0], "storey_heights": [H], "column_EI": 2.0e8,
                                    "beam_EI": 2.0e14, "floor_mass": 1.0e5,
                                    "column_hinge": law}},
                         {"name": "other", "mass": 1.0e5, "period": 0.5, "height": H}],
            "contact": {"law": "kelvin-voigt", "k": 1.0e9, "e": 0.65, "gap": 1.0}}
    model, _, _ = parse_config(data).build()
    return model


def _pulse() -> GroundMotion:
    """A half-sine pulse of 6 m/s² over 0.15 s, then 2.85 s of rest: one excursion into
    the sway mechanism, then free vibration that does not yield again."""
    dt = 0.002
    t = np.arange(0.0, 3.0, dt)
    return GroundMotion(dt=dt, accel=np.where(t < 0.15, 6.0 * np.sin(np.pi * t / 0.15), 0.0),
                        name="pulse")


def test_plastic_rotation_of_a_portal_mechanism_is_its_sway_beyond_yield() -> None:
    """Elastic–perfectly-plastic hinges: the four column hinges yield together at the sway
    mechanism, V = 4 M_p / h at u_y = V / K (K the frame's elastic lateral stiffness), and
    every displacement beyond turns them rigidly, so each column's two hinges carry
    θ_p,base + θ_p,top = 2 (u_peak − u_y) / h, each at |θ| = θ_p + M_p / k0."""
    model = _portal({"type": "elastic-plastic", "k0": K0, "m_y": MY})
    r = simulate(model, _pulse(), dt=0.001)
    row = hinge_row(r)
    u_peak = float(r.peak_displacement[0])
    stiffness = float(model.buildings[0].K[0, 0])
    plastic = 2.0 * (u_peak - 4.0 * MY / H / stiffness) / H
    assert u_peak > 3.0 * 4.0 * MY / H / stiffness  # well into the mechanism
    rot = r.hinge_peak_rotation
    moment_part = MY / K0
    # hinges 1, 2: the first column's base and top; 3, 4: the second's
    for base, top in ((0, 1), (2, 3)):
        assert (rot[base] - moment_part) + (rot[top] - moment_part) == pytest.approx(
            plastic, rel=1e-6)
    assert row["peak_plastic_rotation_rad"] == pytest.approx(max(rot) - moment_part, rel=1e-6)
    assert row["peak_plastic_rotation_rad"] == pytest.approx(plastic / 2.0, rel=1e-4)
    assert row["peak_hinge_rotation_rad"] == max(rot)
    assert row["hinge_past_cap"] is None and row["strength_lost"] is False  # no IMK law


@pytest.mark.parametrize("theta_p, past", [(0.003, True), (0.02, False)])
def test_past_cap_is_the_imk_backbones_capping_rotation(theta_p: float, past: bool) -> None:
    """IMK hinges without cyclic deterioration, one excursion: the moment at the peak
    rotation lies on the published backbone (Lignos & Krawinkler 2011, Fig. 1) — on the
    post-capping branch M_c − (M_c/θ_pc)(θ − θ_c) beyond θ_c = θ_y + θ_p, on the hardening
    branch M_y + (M_c − M_y)(θ − θ_y)/θ_p before — and the row says past the cap exactly
    then."""
    theta_pc, mc = 0.05, 1.1 * MY
    model = _portal({"type": "imk-bilinear", "k0": K0, "m_y": MY, "theta_p": theta_p,
                     "theta_pc": theta_pc, "mc_my": 1.1, "kappa": 0.4})
    r = simulate(model, _pulse(), dt=0.001)
    theta_y = MY / K0
    theta_c = theta_y + theta_p
    for h in range(4):
        th = float(r.hinge_peak_rotation[h])
        m = abs(float(np.interp(r.hinge_peak_rotation_time[h], r.time, r.hinge_moment[:, h])))
        backbone = (mc - mc / theta_pc * (th - theta_c) if th > theta_c
                    else MY + (mc - MY) * (th - theta_y) / theta_p)
        assert m == pytest.approx(backbone, rel=1e-3)
        assert (th > theta_c) is past
    assert hinge_row(r)["hinge_past_cap"] is past


# -------------------------------------------------------------- a frame that loses its strength
FRAME = """name = "imk frame"
[record]
bundled = "el_centro"
duration = 4.0

[[building]]
name = "frame"
damping = {{ rayleigh = [0.05, 0.05], modes = [1, 2] }}

[building.frame]
bays = [6.0]
storey_heights = [3.5, 3.5]
column_EI = 1.0e8
beam_EI = 1.0e8
floor_mass = 4.0e4
leaning_load = 2.0e5
geometry = "p-delta"
column_hinge = {{ type = "imk-bilinear", k0 = 1.0e10, m_y = 2.0e5, theta_p = {tp}, theta_pc = 0.10, theta_u = {tu}, kappa = 0.4, Lambda = 0.3 }}
beam_hinge = {{ type = "imk-bilinear", k0 = 1.0e10, m_y = 1.5e5, theta_p = {tp}, theta_pc = 0.10, theta_u = {tu}, kappa = 0.4, Lambda = 0.3 }}

[[building]]
name = "shear"
masses = [4.0e4, 4.0e4]
stiffnesses = [3.0e7, 3.0e7]
heights = [3.5, 3.5]
damping = {{ ratio = 0.05 }}

[contact]
law = "kelvin-voigt"
k = 1.0e9
e = 0.65
gap = 0.03
"""
THETA_P, THETA_U = 0.02, 0.05  # rad, both hinge laws
RECORD_FILES = ["elcentro_1940_IV_ELC9_180_PEER.AT2", "northridge_1994_newhall_360_RSN1044.AT2",
                "kocaeli_1999_izmit_090_RSN1165.AT2"]
LEVELS = [0.3, 0.8, 1.5, 3.0]  # g, PGA
STUDY = f"""name = "imk frames"
base = "frame.toml"
[suite]
files = {json.dumps([str(RECORDS / f) for f in RECORD_FILES])}
duration = 4.0
[intensity]
measure = "pga"
levels = {LEVELS}
[[limit_state]]
demand = "drift"
limit = 2.0
[[limit_state]]
demand = "plastic_rotation"
limit = 0.04
[[limit_state]]
demand = "collapse"
[bootstrap]
n = 50
[run]
scheduler = "synchronous"
"""


@pytest.fixture(scope="module")
def frame_study(tmp_path_factory):
    folder = tmp_path_factory.mktemp("frames")
    (folder / "frame.toml").write_text(FRAME.format(tp=THETA_P, tu=THETA_U))
    (folder / "study.toml").write_text(STUDY)
    out = folder / "out"
    assert main(["fragility", str(folder / "study.toml"), "--out", str(out),
                 "--no-figures"]) == 0
    return folder, out, _by_hand(folder)


def _by_hand(folder: Path) -> dict:
    """Every run of the study made directly (the record scaled to the level, ``simulate``):
    its peak storey drift ratio from the displacements, its peak plastic rotation
    ``max |θ − M/k0|`` over the output samples, whether a hinge's largest rotation on a
    side passed min(θ_y + θ_p, θ_u) from the model file's constants, or None where the frame
    stopped as it lost its strength."""
    from pounding.studies.fragility import study_cases

    cases = study_cases(folder / "study.toml")
    k0 = 1.0e10
    caps = {2.0e5: min(2.0e5 / k0 + THETA_P, THETA_U), 1.5e5: min(1.5e5 / k0 + THETA_P, THETA_U)}
    out = {}
    for r in range(len(RECORD_FILES)):
        for li, x in enumerate(LEVELS):
            model, motion, solver = cases.build(r, x)
            try:
                res = simulate(model, motion, **solver)
            except FrameCollapse:  # its hinges' moments cascading, or a storey swayed away
                out[r, li] = None
                continue
            u = res.displacement
            drift = max(np.abs(u[:, 0]).max(), np.abs(u[:, 1] - u[:, 0]).max(),
                        np.abs(u[:, 2]).max(), np.abs(u[:, 3] - u[:, 2]).max()) / 3.5
            theta, moment = res.hinge_rotation, res.hinge_moment
            plastic = float(np.abs(theta - moment / k0).max())
            cap = np.array([caps[fh.law.m_y] for _, b in model.yielding_frames
                            for fh in b.frame.hinges])
            past = bool(np.any(theta.max(axis=0) > cap) or np.any(-theta.min(axis=0) > cap))
            out[r, li] = (drift, plastic, past)
    return out


def test_frame_fragility_counts_are_those_of_the_runs_made_directly(frame_study):
    folder, out, runs = frame_study
    assert sum(v is None for v in runs.values()) >= 1  # a frame lost its strength
    assert any(v is not None and v[2] for v in runs.values())  # a hinge passed its cap
    assert any(v is not None and not v[2] for v in runs.values())
    exceed = {
        "peak storey drift ratio > 2 %": lambda v: v is None or v[0] > 0.02,
        "peak plastic hinge rotation > 0.04 rad": lambda v: v is None or v[1] > 0.04,
        "collapse (drift > 10 % or a hinge past its cap)":
            lambda v: v is None or v[0] > 0.10 or v[2],
    }
    # no sampled value within 0.5 % of a limit: the counts cannot hinge on sampling
    for v in runs.values():
        if v is not None:
            assert abs(v[0] / 0.02 - 1) > 5e-3 and abs(v[1] / 0.04 - 1) > 5e-3
    counts = pd.read_csv(out / "counts.csv")
    data = json.loads((out / "fragility.json").read_text())
    for name, rule in exceed.items():
        mine = counts[counts["limit_state"] == name]
        assert list(mine["n_runs"]) == [3] * len(LEVELS)
        assert list(mine["n_exceed"]) == [sum(rule(runs[r, li]) for r in range(3))
                                          for li in range(len(LEVELS))], name
    # the collapse capacity of a record (binary): the first level at which it collapsed
    ls = next(x for x in data["limit_states"] if x["demand"] == "collapse")
    assert ls["drift_limit_pct"] == 10.0 and ls["limit"] is None
    first = [next((LEVELS[li] for li in range(len(LEVELS))
                   if exceed["collapse (drift > 10 % or a hinge past its cap)"](runs[r, li])),
                  LEVELS[-1]) for r in range(3)]
    assert ls["capacity_g"] == first
    # collapsed: stopped as the frame lost its strength, or a storey drifted beyond its height
    assert data["runs"]["failed"] == 0 and data["runs"]["collapsed"] == sum(
        v is None or v[0] > 1.0 for v in runs.values())


def test_the_table_and_ida_csv_hold_the_hinges_of_every_run(frame_study):
    folder, out, runs = frame_study
    from pounding.studies.sweep import load_results

    table = load_results(out).sort_values("case_index")
    assert set(HINGE_MEASURES) <= set(table.columns)
    ida = pd.read_csv(out / "ida.csv")
    assert list(ida.columns[-3:]) == ["plastic_rotation_rad", "hinge_past_cap", "strength_lost"]
    for k, (r, li) in enumerate((r, li) for r in range(3) for li in range(len(LEVELS))):
        v, row, line = runs[r, li], table.iloc[k], ida.iloc[k]
        if v is None:
            assert row["status"] == "error" and row["strength_lost"]
            assert math.isinf(line["plastic_rotation_rad"]) and math.isinf(line["drift_pct"])
            assert line["strength_lost"] == 1
            continue
        assert row["status"] == "ok" and not row["strength_lost"]
        # the table's and by hand: both at the output steps
        assert row["peak_plastic_rotation_rad"] == pytest.approx(v[1], rel=1e-12)
        if v[0] > 1.0:  # sidesway collapse: a deformation beyond meaning, +inf in ida.csv
            assert math.isinf(line["plastic_rotation_rad"]) and math.isinf(line["drift_pct"])
            assert np.isnan(line["impact_force_MN"])
            continue
        assert line["plastic_rotation_rad"] == pytest.approx(v[1], rel=1e-5)
        assert bool(row["hinge_past_cap"]) is v[2] and line["hinge_past_cap"] == int(v[2])
        assert row["peak_drift_ratio"] == pytest.approx(v[0], rel=2e-3)
        assert row["hysteretic_energy_J"] > 0.0 and pd.isna(row["max_residual_drift_m"])


def test_needed_gaps_of_yielding_frames_are_simulated_and_agree_with_the_runs(frame_study):
    """The uncoupled response of a yielding frame is not proportional to the record: its
    needed gaps are simulated at every level, and then every run with contact pounds exactly
    when its needed gap exceeds the gap (runs whose uncoupled frame lost its strength are
    left out)."""
    _, out, _ = frame_study
    gap = json.loads((out / "fragility.json").read_text())["gap"]
    assert gap["scaled_from_gap_level"] is False
    check = gap["check"]["0.03"]
    assert check["agree"] == check["runs"] >= 10


# ------------------------------------------------------------------------ bad study files
@pytest.mark.parametrize("base, state, message", [
    ("seed_sdof_pair.toml", 'demand = "plastic_rotation"\nlimit = 0.03',
     '"plastic_rotation" needs a frame with plastic hinges'),
    ("seed_sdof_pair.toml", 'demand = "collapse"',
     '"collapse" needs yielding storeys or a frame with plastic hinges'),
    ("frames_pounding.toml", 'demand = "collapse"\nlimit = 0.1',
     'limit_state[0].limit: demand "collapse" is yes or no; it takes no limit (got 0.1)'),
    ("frames_pounding.toml", 'demand = "drift"\nlimit = 1.0\ndrift_limit = 5.0',
     'limit_state[0].drift_limit: only for demand "collapse" (got 5)'),
    ("frames_pounding.toml", 'demand = "plastic_rotation"',
     'limit_state[0].limit: required for demand "plastic_rotation"'),
    ("frames_pounding.toml", 'demand = "plastic_rotation"\nlimit = 2.0',
     'limit_state[0].limit: must be in [0, 1] rad'),
])
def test_a_demand_the_model_cannot_have_is_one_line(tmp_path, capsys, base, state, message):
    study = tmp_path / "s.toml"
    study.write_text(f'base = "{ROOT / "examples" / base}"\n[suite]\nbundled = true\n'
                     f'[intensity]\nmeasure = "pga"\nlevels = [0.1, 0.2]\n'
                     f'[[limit_state]]\n{state}\n')
    assert main(["fragility", str(study), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0], err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]


def test_a_run_whose_frame_loses_its_strength_is_a_collapse_in_the_table(tmp_path):
    """The frame of the study's base model at 3.2 × El Centro: its hinges fracture in a
    cascade and the run stops; the row is an error with ``strength_lost`` true (hinge
    columns of a model without hinges: absent)."""
    from pounding.studies.sweep.execute import run_case

    (tmp_path / "frame.toml").write_text(FRAME.format(tp=THETA_P, tu=0.15).replace(
        "theta_u = 0.15, kappa = 0.4, Lambda = 0.3", "theta_u = 0.15, kappa = 0.4, Lambda = 1.0"))
    base = load_config(tmp_path / "frame.toml").to_dict(resolve_paths=True)
    row, _ = run_case(base, tmp_path, ["record.duration", "record.scale"], [6.0, 32.0])
    # (it stops as soon as the frame has collapsed: sideways, or as its moments cascade)
    assert row["status"] == "error" and ("fractures cascading" in row["error"]
                                         or "collapsed sideways" in row["error"])
    assert row["strength_lost"] is True and row["peak_plastic_rotation_rad"] is None
    seed = load_config(ROOT / "examples" / "seed_sdof_pair.toml").to_dict(resolve_paths=True)
    row, _ = run_case(seed, ROOT / "examples", ["record.scale"], [1.0])
    assert not set(HINGE_MEASURES) & set(row)


def test_the_hysteretic_energy_of_a_frame_is_its_hinges(tmp_path):
    """A sweep's ``hysteretic_energy_J`` of yielding frames is the sum of their hinges'
    hysteretic energies (was null: frames have no yielding storeys)."""
    from pounding.studies.sweep.execute import run_case

    base = load_config(ROOT / "examples" / "frames_pounding.toml").to_dict(resolve_paths=True)
    row, _ = run_case(base, ROOT / "examples", ["record.duration"], [3.0])
    cfg = load_config(ROOT / "examples" / "frames_pounding.toml")
    data = cfg.to_dict(resolve_paths=True)
    data["record"]["duration"] = 3.0
    model, motion, solver = parse_config(data).build()
    res = simulate(model, motion, **solver)
    assert row["hysteretic_energy_J"] == pytest.approx(float(np.sum(res.hinge_dissipated)),
                                                       rel=1e-9)
    assert row["hysteretic_energy_J"] > 1e3 and row["max_residual_drift_m"] is None


# ------------------------------------------------------------------- mitigation and gap
def test_mitigation_of_frames_reports_their_storey_shear(tmp_path, capsys):
    """Frames stand in the row as matrices; their storey shears come from their restoring
    forces (was: none, NaN in the table)."""
    base = tmp_path / "frames.toml"
    text = (ROOT / "examples" / "frames_pounding.toml").read_text()
    base.write_text(text.replace("scale = 1.5", "scale = 1.5\nduration = 3.0"))
    study = tmp_path / "m.toml"
    study.write_text(f'base = "{base}"\n[[option]]\nname = "bare gap"\n[[option]]\n'
                     'name = "dashpots"\n[[option.device]]\ntype = "viscous"\nfloors = "all"\n'
                     'c = 2.0e6\n')
    assert main(["mitigate", str(study), "--out", str(tmp_path / "o")]) == 0
    runs = pd.read_csv(tmp_path / "o" / "runs.csv").set_index("option")
    model, motion, kw = load_config(base).build()
    bare = simulate(model, motion, **kw)
    assert runs.loc["bare gap", "peak_storey_shear_N"] == pytest.approx(
        np.nanmax(bare.peak_storey_shear), rel=1e-12)
    assert runs.loc["bare gap", "peak_storey_shear_N"] > 1e5
    assert runs.loc["bare gap", "n_impacts"] == bare.n_impacts
    assert runs.loc["bare gap", "peak_drift_ratio"] == pytest.approx(
        np.nanmax(bare.peak_drift_ratio), rel=1e-12)


def test_gap_study_of_frames_is_the_approach_of_a_run_without_contact():
    """Yielding frames simulated alone by the gap study need the gap a run of the pair with
    the gap out of reach (1 m) shows: the largest approach of the facing floors."""
    from pounding.studies.gap import critical_gaps

    data = load_config(ROOT / "examples" / "frames_pounding.toml").to_dict(resolve_paths=True)
    data["record"]["duration"] = 3.0
    data["contact"]["gap"] = 1.0
    model, motion, solver = parse_config(data).build()
    gs = critical_gaps(model, [motion], dt=solver["dt"], duration=solver["duration"])
    run = simulate(model, motion, **solver)
    assert run.n_impacts == 0
    u = run.displacement
    labels = model.dof_labels()
    for j, c in enumerate(model.contacts):
        left = labels.index(c.left.label())
        right = labels.index(c.right.label())
        approach = float(np.max(u[:, left] - u[:, right]))
        # the gap study maximises between samples (Hermite): at least the sampled maximum —
        # of its own runs; the pair's run is another integration (its adaptive steps cut by
        # both frames' events), equal to the run's tolerance (rtol 1e-8): 1.4e-9 m apart on
        # 28 mm under OPENBLAS_CORETYPE=Haswell (2026-11-27)
        assert gs.critical[0, j] == pytest.approx(max(approach, 0.0), rel=1e-4, abs=1e-7)
        assert gs.critical[0, j] >= approach - 1e-6 * abs(approach) - 1e-12


def test_a_collapse_is_the_flatline_of_the_ida_curve():
    """A run that collapsed (+inf) exceeds any limit; where it is a record's first
    exceedance its capacity is that level (as for a yes/no demand); a fractile reaching into
    the collapsed runs is +inf, one below them the type-7 interpolation by hand."""
    from pounding.studies.fragility.analysis import collapse_exceedance
    from pounding.studies.fragility.ida import capacities, ida_fractiles

    levels = [0.2, 0.4, 0.8]
    edp = np.array([[0.01, np.inf, np.inf],     # collapses at 0.4 before reaching 0.02
                    [0.01, 0.015, 0.03],        # crosses 0.02 by interpolation
                    [0.01, np.nan, np.inf]])    # a failed run, then a collapse
    cap, cen = capacities(levels, edp, 0.02)
    assert cap.tolist() == pytest.approx([0.4, 0.4 + (0.02 - 0.015) / 0.015 * 0.4, 0.8],
                                         rel=1e-12)
    assert not cen.any()
    f = ida_fractiles(edp, (0.16, 0.5, 0.84))
    assert f[:, 0] == pytest.approx([0.01, 0.01, 0.01])
    # level 0.4: {0.015, inf}: 16 % at h = 0.16 → 0.015 + 0.16 (inf − 0.015) = inf
    assert np.isinf(f[:, 1]).all()
    # level 0.8: {0.03, inf, inf}: h = 0.32 → inf; with four runs {0.01, 0.02, 0.03, inf}
    four = np.array([[0.01], [0.02], [0.03], [np.inf]])
    g = ida_fractiles(four, (0.16, 0.5, 0.84))
    assert g[:2, 0] == pytest.approx([0.01 + 0.48 * 0.01, 0.02 + 0.5 * 0.01], rel=1e-12)
    assert np.isinf(g[2, 0])
    drift = np.array([[0.05, np.nan, np.inf, 0.12]])
    assert collapse_exceedance(drift, 0.10).tolist()[0][:1] == [0.0]
    got = collapse_exceedance(drift, 0.10, past_cap=np.array([[1.0, np.nan, np.nan, 0.0]]),
                              strength_lost=np.array([[0.0, np.nan, 1.0, 0.0]]))
    assert got[0, 0] == 1.0 and np.isnan(got[0, 1]) and got[0, 2] == 1.0 and got[0, 3] == 1.0


def test_collapsed_runs_in_the_demand_table():
    """From a sweep's table: a run stopped as its frame lost its strength and a run whose
    storey drifted beyond its height (sidesway collapse) have +inf deformation demands and
    no forces; the sidesway run keeps whether it pounded; a run that failed otherwise is
    NaN throughout and listed as failed."""
    from types import SimpleNamespace

    from pounding.studies.fragility.analysis import collapse_exceedance, demand_table

    cases = SimpleNamespace(gaps=[None], records=["a", "b"], levels=[0.1, 0.2],
                            rows=[(0, 0, 0), (0, 1, 0), (1, 0, 0), (1, 1, 0)], sweep=None)
    nan = float("nan")
    table = pd.DataFrame({
        "case_index": [0, 1, 2, 3], "status": ["ok", "error", "ok", "error"],
        "error": [None, "frame: its hinges' moments keep jumping (fractures cascading) ...",
                  None, "solver: something else"],
        "n_impacts": [0, None, 3, None], "peak_contact_force_N": [0.0, nan, 1e15, nan],
        "peak_drift_ratio": [0.01, nan, 5.0, nan], "peak_floor_accel_m_s2": [1.0, nan, 1e9, nan],
        "max_ductility": [nan] * 4, "peak_hinge_rotation_rad": [0.006, nan, 5.0, nan],
        "peak_plastic_rotation_rad": [0.005, nan, 5.0, nan],
        "hinge_past_cap": [False, None, True, None], "strength_lost": [False, True, False, None]})
    demands, failures, hinges = demand_table(cases, table)
    inf = math.inf
    assert demands["drift"][0].tolist() == [[0.01, inf], [inf, pytest.approx(nan, nan_ok=True)]]
    assert demands["plastic_rotation"][0, :, 1].tolist()[0] == inf
    assert demands["plastic_rotation"][0, 1, 0] == inf
    assert np.isnan(demands["impact_force"][0, 1, 0]) and np.isnan(demands["impact_force"][0, 0, 1])
    assert demands["pounding"][0, 1, 0] == 1.0 and np.isnan(demands["impacts"][0, 1, 0])
    assert failures == ["b at 0.2 g: solver: something else"]
    assert [c.split(":")[0] for c in hinges.collapses] == ["a at 0.2 g", "b at 0.1 g"]
    assert "sidesway collapse" in hinges.collapses[1]
    got = collapse_exceedance(demands["drift"][0], 0.10, hinges.past_cap[0],
                              hinges.strength_lost[0])
    assert got[0].tolist() == [0.0, 1.0] and got[1, 0] == 1.0 and np.isnan(got[1, 1])


def test_the_frame_fragility_example_is_a_study_of_90_runs(tmp_path):
    from pounding.studies.fragility import study_cases

    cases = study_cases(ROOT / "examples" / "fragility_imk_frame.toml", out=tmp_path / "o")
    assert len(cases.sweep.cases) == 90 and len(cases.records) == 9
    assert [ls.demand for ls in cases.config.limit_state] == [
        "pounding", "plastic_rotation", "drift", "collapse"]
    assert cases.periods[0] == pytest.approx(0.55, abs=0.005)  # Sa(0.55 s): the frame's T1
    assert not (tmp_path / "o").exists()
