"""Sweep faults and bad input through the command line: each ends in one line on standard
error (exit status 2 for bad input), without a traceback or a half-written output."""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

from pounding.cli import main
from pounding.studies.sweep import MAX_CASES, load_results, load_sweep, parse_sweep, run_sweep

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "seed_sdof_pair.toml"


def _write(tmp: Path, body: str, name: str = "sweep.toml") -> Path:
    p = tmp / name
    p.write_text(f'base = "{BASE}"\nname = "f"\nout = "out"\n' + body, encoding="utf-8")
    return p


def sweep_cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    capsys.readouterr()
    code = main(["sweep", *argv])
    return code, capsys.readouterr().err.strip().splitlines()


# ------------------------------------------------------------------ refused before running
def test_a_grid_of_1e12_cases_is_refused_before_any_case_is_made(tmp_path, capsys):
    values = ", ".join(str(i) for i in range(1000))
    path = _write(tmp_path, "[grid]\n" + "".join(
        f'"{p}" = [{values}]\n' for p in ("contact.gap", "contact.e", "record.scale",
                                           "solver.rtol")))
    start = time.perf_counter()
    code, err = sweep_cli(capsys, str(path), "--scheduler", "synchronous")
    assert time.perf_counter() - start < 10
    assert code == 2 and len(err) == 1, err
    assert err[0] == (f"error: {path}: [grid] gives 1,000,000,000,000 cases (1,000 × 1,000 × "
                      f"1,000 × 1,000 values), more than the {MAX_CASES:,} a sweep may have; "
                      "split it into several sweeps or sample it with [random]")
    assert not (tmp_path / "out").exists()
    with pytest.raises(ValueError, match=r"\[random\] gives 1,000,000,000,000 cases"):
        parse_sweep({"base": str(BASE), "random": {"n": 10**12, "seed": 1,
                                                   "contact.gap": [0.0, 0.05]}})


def test_a_case_too_large_for_memory_is_refused_with_the_check_of_pounding_run(tmp_path,
                                                                               capsys):
    path = _write(tmp_path, '[grid]\n"contact.gap" = [0.01, 0.02]\n'
                            '"solver.dt" = [1e-3, 1e-12]\n')
    code, err = sweep_cli(capsys, str(path), "--scheduler", "synchronous")
    assert code == 2 and len(err) == 1, err
    assert re.fullmatch(rf"error: {re.escape(str(path))}: grid\.solver\.dt = 1e-12: solver: "
                        r"39\.99 s at an output step of 1e-12 s is 4e\+13 output times; the "
                        r"histories would take .* GiB .*", err[0]), err[0]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("table, expected", [
    ('[grid]\n"contact.gap" = ["abc", "def"]\n"contact.e" = [0.5, 0.6]\n',
     'grid.contact.gap = "abc": contact.gap: must be a number (got \'abc\')'),
    ('[list]\n"contact.e" = [0.5, 0.6]\n"record.scale" = [1.0, true]\n',
     "list.record.scale = true: record.scale: must be a number (got True)"),
    ('[random]\nn = 20\nseed = 1\n"contact.gap" = [0.0, 0.05]\n'
     '"contact.law" = { choice = ["hertz", 3] }\n',
     "random.contact.law = 3: contact.law: must be a string (in quotes) (got 3)"),
    ('[grid]\n"contact" = [{ law = "hertz", k_h = 1e9, gap = 0.01, k_x = 1 }]\n',
     "grid.contact = "),
])
def test_a_value_of_the_wrong_type_is_refused_before_any_case_runs(tmp_path, capsys, table,
                                                                   expected):
    code, err = sweep_cli(capsys, str(_write(tmp_path, table)), "--scheduler", "synchronous")
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith(f"error: {tmp_path / 'sweep.toml'}: {expected}"), err[0]
    assert not (tmp_path / "out").exists()


def test_a_value_out_of_range_is_still_an_error_in_its_row(tmp_path):
    sweep = load_sweep(_write(tmp_path, '[grid]\n"contact.e" = [0.5, 1.5]\n'
                                        '"record.duration" = [2.0]\n'))
    df = load_results(run_sweep(sweep, scheduler="synchronous").results)
    assert list(df["status"]) == ["ok", "error"]
