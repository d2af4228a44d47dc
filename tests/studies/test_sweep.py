"""Parameter sweeps: file format, case ids, errors per case, resume after SIGKILL,
bit-identical tables, plots."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest

from pounding.config import load_config
from pounding.integrate import simulate
from pounding.studies.sweep import (
    NONDETERMINISTIC_COLUMNS,
    apply_overrides,
    case_id,
    load_results,
    load_sweep,
    parse_sweep,
    run_sweep,
)

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "seed_sdof_pair.toml"
EXE = Path(sys.executable).parent / "pounding"


def _write(tmp: Path, body: str, name: str = "sweep.toml") -> Path:
    p = tmp / name
    p.write_text(f'base = "{BASE}"\n' + body, encoding="utf-8")
    return p


GRID = """
name = "t"
out = "out"
[grid]
"contact.gap" = [0.0, 0.01, 0.02, 0.04]
"contact.e" = [0.5, 0.8, 1.5]
"record.duration" = [2.0, 3.0]
"""


def _deterministic(path: Path):
    t = pq.read_table(path)
    return t.drop_columns(list(NONDETERMINISTIC_COLUMNS))


def test_grid_ids_and_errors_in_rows(tmp_path: Path) -> None:
    sweep = load_sweep(_write(tmp_path, GRID))
    assert len(sweep.cases) == 24
    assert sweep.params == ("contact.gap", "contact.e", "record.duration")
    assert sweep.cases[0].id == case_id(sweep.params, (0.0, 0.5, 2.0))
    assert case_id(["a", "b"], [1, 2]) == case_id(["b", "a"], [2, 1])
    res = run_sweep(sweep, scheduler="synchronous")
    df = load_results(res.results)
    assert list(df["case_index"]) == list(range(24))
    assert df["case_id"].is_unique
    bad = df[df["contact.e"] == 1.5]
    assert (bad["status"] == "error").all()
    assert bad["error"].str.contains("contact.e: must be in (0, 1] (got 1.5)", regex=False).all()
    assert res.n_errors == 8
    ok = df[df["status"] == "ok"]
    assert ok["n_impacts"].notna().all() and (ok["peak_drift_m_B2F1"] > 0).all()


def test_row_matches_plain_run(tmp_path: Path) -> None:
    """The per-process memo (records, propagators) changes nothing: same numbers bitwise."""
    sweep = load_sweep(_write(tmp_path, GRID))
    run_sweep(sweep, scheduler="synchronous")
    df = load_results(sweep.out)
    cfg = load_config(BASE)
    for i in (1, 6, 19):
        data = apply_overrides(sweep.base, sweep.params, sweep.cases[i].values)
        from pounding.config import parse_config
        model, gm, kw = parse_config(data).build()
        r = simulate(model, gm, **kw)
        row = df.iloc[i]
        assert row["n_impacts"] == r.n_impacts
        assert row["peak_contact_force_N"] == float(r.peak_contact_force.max())
        assert row["peak_abs_accel_m_s2_B1F1"] == float(np.abs(r.abs_acceleration[:, 0]).max())
        assert row["energy_balance_error"] == r.energy_balance_error
    assert cfg is not None


def test_bad_base_and_bad_path_fail_fast(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="contact.gapp: unknown key 'gapp'; did you mean 'gap'"):
        parse_sweep({"base": str(BASE), "grid": {"contact.gapp": [0.1]}})
    with pytest.raises(ValueError, match="building.5.period"):
        parse_sweep({"base": str(BASE), "grid": {"building.5.period": [0.1]}})
    bad = tmp_path / "bad.toml"
    bad.write_text(BASE.read_text().replace("period = 0.5", "period = -0.5"))
    with pytest.raises(ValueError,
                       match=r"building\[0\].period: must be in \(0, 100\] s \(got -0.5\)"):
        parse_sweep({"base": str(bad), "grid": {"contact.gap": [0.1]}})
    with pytest.raises(ValueError, match="exactly one of"):
        parse_sweep({"base": str(BASE)})


def test_list_random_star_and_law(tmp_path: Path) -> None:
    s = parse_sweep({"base": str(BASE), "list": {"contact.gap": [0.01, 0.02, 0.01],
                                                 "contact.e": [0.5, 0.6, 0.5]}})
    assert len(s.cases) == 2 and s.duplicates == 1
    r1 = parse_sweep({"base": str(BASE), "random": {"n": 5, "seed": 3,
                                                    "contact.gap": [0.0, 0.05],
                                                    "record.scale": {"log": [0.5, 2.0]},
                                                    "contact.law": {"choice": ["hertz",
                                                                               "nonlinear-viscoelastic"]}}})
    r2 = parse_sweep({"base": str(BASE), "random": {"n": 5, "seed": 3,
                                                    "contact.gap": [0.0, 0.05],
                                                    "record.scale": {"log": [0.5, 2.0]},
                                                    "contact.law": {"choice": ["hertz",
                                                                               "nonlinear-viscoelastic"]}}})
    assert [c.values for c in r1.cases] == [c.values for c in r2.cases]
    d = apply_overrides(s.base, ("building.*.period", "contact.law"), (0.7, "hertz"))
    assert [b["period"] for b in d["building"]] == [0.7, 0.7]
    assert "e" not in d["contact"] and d["contact"]["k_h"] == 2.75e9


def test_cli_plot(tmp_path: Path) -> None:
    from pounding.cli import main

    sweep = load_sweep(_write(tmp_path, GRID))
    run_sweep(sweep, scheduler="synchronous")
    assert main(["plot", str(sweep.out), "--x", "contact.gap", "--y", "contact.e",
                 "--plot", str(tmp_path / "h.png")]) == 0
    assert main(["plot", str(sweep.out / "results.parquet"), "--x", "contact.gap", "--y",
                 "record.duration", "--kind", "lines", "-m", "n_impacts",
                 "--plot", str(tmp_path / "l.png")]) == 0
    assert (tmp_path / "h.png").stat().st_size > 0 and (tmp_path / "l.png").stat().st_size > 0
    assert main(["plot", str(sweep.out), "--x", "nope"]) == 2


KILL = """
name = "k"
out = "{out}"
batch_size = 3
[grid]
"contact.gap" = [0.0, 0.005, 0.01, 0.02, 0.03, 0.04]
"contact.e" = [0.5, 0.65, 0.8]
"record.scale" = [0.8, 0.9, 1.0, 1.1, 1.2]
"record.duration" = [20.0]
"""


def test_sigkill_resume_is_lossless_and_identical(tmp_path: Path) -> None:
    """Kill a Dask sweep (whole process group, SIGKILL) mid-way; the re-run runs only the
    missing cases and ends with the clean run's table, bit for bit."""
    clean = load_sweep(_write(tmp_path, KILL.format(out="clean"), "clean.toml"))
    run_sweep(clean, scheduler="synchronous")
    path = _write(tmp_path, KILL.format(out="killed"), "killed.toml")
    parts = tmp_path / "killed" / "parts"
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    proc = subprocess.Popen([str(EXE), "sweep", str(path), "--workers", "1"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True, env=env)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            if parts.is_dir() and len(list(parts.glob("part-*.parquet"))) >= 2:
                break
            if proc.poll() is not None:
                break
            time.sleep(0.05)
        os.killpg(proc.pid, signal.SIGKILL)
    finally:
        proc.wait(timeout=30)
    n_parts = len(list(parts.glob("part-*.parquet")))
    assert n_parts >= 2
    assert not (tmp_path / "killed" / "results.parquet").exists(), "killed too late"
    res = run_sweep(load_sweep(path), scheduler="synchronous")
    assert 0 < res.n_run < res.n_cases
    a, b = _deterministic(clean.out / "results.parquet"), _deterministic(res.results)
    assert a.equals(b)
    assert load_results(res.results)["case_id"].is_unique
    assert len(load_results(res.results)) == 90


def test_two_dask_runs_bit_identical(tmp_path: Path) -> None:
    a = load_sweep(_write(tmp_path, KILL.format(out="a"), "a.toml"))
    b = load_sweep(_write(tmp_path, KILL.format(out="b"), "b.toml"))
    ra = run_sweep(a, n_workers=2, batch_size=7)
    rb = run_sweep(b, scheduler="synchronous")
    assert _deterministic(ra.results).equals(_deterministic(rb.results))
    da = load_results(ra.results, deterministic=True)
    db = load_results(rb.results, deterministic=True)
    assert da.equals(db)
    # a finished sweep started again runs nothing and rewrites the same table
    rc = run_sweep(a)
    assert rc.n_run == 0 and pq.read_table(rc.results).equals(pq.read_table(ra.results))


def test_sweep_over_yield_strength_reports_ductility(tmp_path: Path) -> None:
    """Issue 5 in a parameter study: weaker storeys yield more, and the table says so."""
    base = ROOT / "examples" / "inelastic_5_storey.toml"
    p = tmp_path / "sweep.toml"
    p.write_text(f'base = "{base}"\nname = "y"\nout = "out"\n[grid]\n'
                 '"building.0.storey_law.yield_drift_ratio" = [0.003, 0.006, 0.5]\n'
                 '"record.duration" = [6.0]\n', encoding="utf-8")
    res = run_sweep(load_sweep(p), scheduler="synchronous")
    df = load_results(res.results)
    assert (df["status"] == "ok").all()
    assert (df["energy_balance_error"] < 1e-6).all()
    mu = df["max_ductility"].to_numpy()
    assert mu[0] > mu[1] > 1.0                        # building 1 weaker: more demand
    assert df["hysteretic_energy_J"].iloc[0] > df["hysteretic_energy_J"].iloc[2] > 0.0
    assert df["max_column_shear_ratio"].isna().all()  # floors line up: no column contact


def test_a_case_scaling_the_record_replaces_the_bases_other_way_of_scaling_it():
    # a base scaled to Sa(T1) swept over record.scale (or back): the case's key wins and
    # the base's alternative goes, with the keys that belong to it
    base = {"record": {"bundled": "el_centro", "sa_g": 0.5, "sa_period": 1.0,
                       "sa_damping": 0.02}}
    assert apply_overrides(base, ("record.scale",), (2.0,)) == {
        "record": {"bundled": "el_centro", "scale": 2.0}}
    assert apply_overrides({"record": {"bundled": "el_centro", "pga_g": 0.3}},
                           ("record.sa_g", "record.sa_period"), (0.5, 1.0)) == {
        "record": {"bundled": "el_centro", "sa_g": 0.5, "sa_period": 1.0}}
    assert base["record"]["sa_g"] == 0.5  # the base is left as it was
