"""Sweep faults and bad input through the command line: each ends in one line on standard
error (exit status 2 for bad input, 130 for Ctrl-C, 1 for a lost scheduler), without a
traceback or a half-written output; the cases saved are kept and a resume is bit-identical."""

from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from pounding.cli import main
from pounding.studies.sweep import (
    MAX_CASES,
    SweepInterrupted,
    load_results,
    load_sweep,
    parse_sweep,
    run_sweep,
)

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "seed_sdof_pair.toml"
BIN = Path(sys.executable).parent
EXE = BIN / "pounding"


def _write(tmp: Path, body: str, name: str = "sweep.toml") -> Path:
    p = tmp / name
    p.write_text(f'base = "{BASE}"\nname = "f"\nout = "out"\n' + body, encoding="utf-8")
    return p


def sweep_cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    capsys.readouterr()
    code = main(["sweep", *argv])
    return code, capsys.readouterr().err.strip().splitlines()


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


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
     "list.record.scale = true: record.scale: must be a number (got true)"),
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


def test_out_under_a_file_is_one_line_as_for_pounding_run(tmp_path, capsys):
    (tmp_path / "afile").write_text("x")
    out = tmp_path / "afile" / "out"
    code, err = sweep_cli(capsys, str(_write(tmp_path, '[grid]\n"contact.gap" = [0.01]\n')),
                          "--out", str(out), "--scheduler", "synchronous")
    assert code == 2 and err == [f"error: out: {out} cannot be made: {tmp_path / 'afile'} is "
                                 "a file, not a folder; choose another --out"]


def test_out_in_a_read_only_folder_is_one_line_as_for_pounding_run(tmp_path, capsys,
                                                                   read_only_folder):
    ro = read_only_folder  # (as root: /proc/sys; see conftest.py)
    code, err = sweep_cli(capsys, str(_write(tmp_path, '[grid]\n"contact.gap" = [0.01]\n')),
                          "--out", str(ro / "out"), "--scheduler", "synchronous")
    assert code == 2 and len(err) == 1 and err[0].startswith(f"error: out: cannot write in {ro}")


# ------------------------------------------------------------------ no scheduler
def test_no_scheduler_at_the_address_fails_fast_and_writes_nothing(tmp_path, capsys,
                                                                    monkeypatch):
    from pounding.studies.sweep import cluster

    assert cluster.SCHEDULER_TIMEOUT == 10.0  # (the wait a user meets; 1 s here)
    monkeypatch.setattr("pounding.studies.sweep.cluster.SCHEDULER_TIMEOUT", 1.0)
    address = f"tcp://127.0.0.1:{_free_port()}"
    start = time.perf_counter()
    code, err = sweep_cli(capsys, str(_write(tmp_path, '[grid]\n"contact.gap" = [0.01]\n')),
                          "--scheduler", address)
    assert time.perf_counter() - start < 11
    assert code == 2 and err == [
        f"error: scheduler: no Dask scheduler answers at {address} (waited 1 s); check the "
        "address, start one (`dask scheduler`), or leave out --scheduler for a local cluster"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.toml"]


def test_no_scheduler_leaves_a_finished_sweep_as_it_was(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr("pounding.studies.sweep.cluster.SCHEDULER_TIMEOUT", 1.0)
    path = _write(tmp_path, '[grid]\n"contact.gap" = [0.01, 0.02]\n"record.duration" = [2.0]\n')
    run_sweep(load_sweep(path), scheduler="synchronous")
    before = {p: p.stat().st_mtime_ns for p in (tmp_path / "out").rglob("*")}
    address = f"tcp://127.0.0.1:{_free_port()}"
    code, err = sweep_cli(capsys, str(path), "--scheduler", address, "--overwrite")
    assert code == 2 and len(err) == 1 and "no Dask scheduler answers" in err[0]
    assert {p: p.stat().st_mtime_ns for p in (tmp_path / "out").rglob("*")} == before


def test_a_second_local_cluster_prints_nothing_about_its_port(tmp_path, capsys, recwarn):
    """The scheduler's HTTP server of the local cluster takes a free port: with port 8787
    taken (by another sweep, say) there is no warning on standard error."""
    path = _write(tmp_path, '[grid]\n"contact.gap" = [0.01, 0.02]\n"record.duration" = [2.0]\n')
    with socket.socket() as taken:
        try:
            taken.bind(("0.0.0.0", 8787))
            taken.listen()
        except OSError:
            pass  # taken already: the same situation
        code, err = sweep_cli(capsys, str(path), "--workers", "1")
    assert code == 0 and err == []
    assert not [w for w in recwarn if "8787" in str(w.message)]


# ------------------------------------------------------------------ stopped mid-sweep
STOP = """
batch_size = 5
[grid]
"contact.gap" = [0.0, 0.004, 0.008, 0.012, 0.016, 0.02, 0.024, 0.028, 0.032, 0.036]
"contact.e" = [0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85]
"record.scale" = [0.8, 1.2, 1.6, 2.0]
"""


@pytest.fixture(scope="module")
def clean(tmp_path_factory: pytest.TempPathFactory):  # noqa: ANN201
    """The table of the STOP sweep run start to end, in this process."""
    tmp = tmp_path_factory.mktemp("clean")
    res = run_sweep(load_sweep(_write(tmp, STOP)), scheduler="synchronous")
    return load_results(res.results, deterministic=True)


def _wait_for_parts(proc: subprocess.Popen, parts: Path, n: int = 2) -> set[str]:
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if parts.is_dir() and len(list(parts.glob("part-*.parquet"))) >= n:
            break
        time.sleep(0.02)
    return {p.name for p in parts.glob("part-*.parquet")}


def _saved_from_line(err: str, pattern: str) -> int:
    """Standard error is one line matching ``pattern``: the number of cases it says are
    saved (its group 1)."""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    m = re.fullmatch(pattern, lines[0])
    assert m, lines[0]
    return int(m.group(1))


def _resume_matches_clean(path: Path, saved_parts: set[str], n_saved: int, clean) -> None:
    res = run_sweep(load_sweep(path), scheduler="synchronous")
    assert res.n_run == res.n_cases - n_saved
    assert saved_parts <= {p.name for p in (path.parent / "out" / "parts").iterdir()}
    assert load_results(res.results, deterministic=True).equals(clean)


def _sigint_default() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)  # as a shell starts a foreground command


def test_ctrl_c_is_one_line_saves_what_finished_and_stops_workers_quietly(tmp_path, clean):
    path = _write(tmp_path, STOP)
    proc = subprocess.Popen([str(EXE), "sweep", str(path), "--workers", "2"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=_sigint_default)
    try:
        _wait_for_parts(proc, tmp_path / "out" / "parts")
        os.killpg(proc.pid, signal.SIGINT)  # Ctrl-C: the terminal signals the whole group
        out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    assert proc.returncode == 130, err
    n_saved = _saved_from_line(err, rf"error: stopped \(interrupted\): (\d+) of 400 cases are "
                               rf"saved in {re.escape(str(tmp_path / 'out'))}; resume with: "
                               rf"pounding sweep {re.escape(str(path))} --workers 2")
    assert "Traceback" not in out
    deadline = time.monotonic() + 15  # every worker process is gone
    while time.monotonic() < deadline:
        try:
            os.killpg(proc.pid, 0)
        except ProcessLookupError:
            break
        time.sleep(0.1)
    else:
        pytest.fail("worker processes outlived the sweep")
    saved = {p.name for p in (tmp_path / "out" / "parts").glob("part-*.parquet")}
    assert 0 < n_saved < 400 and len(saved) * 5 == n_saved
    _resume_matches_clean(path, saved, n_saved, clean)


def test_a_lost_scheduler_is_one_line_with_the_command_to_resume(tmp_path, clean):
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    sched = subprocess.Popen([str(BIN / "dask"), "scheduler", "--port", str(port),
                              "--no-dashboard"], **quiet)
    worker = None
    sweep = None
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            with socket.socket() as s:
                if s.connect_ex(("127.0.0.1", port)) == 0:
                    break
            time.sleep(0.1)
        worker = subprocess.Popen([str(BIN / "dask"), "worker", address, "--nthreads", "1",
                                   "--no-dashboard"], **quiet)
        path = _write(tmp_path, STOP)
        sweep = subprocess.Popen([str(EXE), "sweep", str(path), "--scheduler", address],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        saved = _wait_for_parts(sweep, tmp_path / "out" / "parts")
        sched.kill()
        lost = time.monotonic()
        _, err = sweep.communicate(timeout=60)
        assert time.monotonic() - lost < 15
    finally:
        for p in (sweep, worker, sched):
            if p is not None and p.poll() is None:
                p.kill()
                p.wait()
    assert sweep.returncode == 1, err
    n_saved = _saved_from_line(err, rf"error: the Dask scheduler at {address} was lost: (\d+) of "
                               rf"400 cases are saved in {re.escape(str(tmp_path / 'out'))}; "
                               rf"resume with: pounding sweep {re.escape(str(path))} "
                               rf"--scheduler {address}")
    now = {p.name for p in (tmp_path / "out" / "parts").glob("part-*.parquet")}
    assert saved <= now and len(now) * 5 == n_saved < 400
    _resume_matches_clean(path, now, n_saved, clean)


def test_interrupted_before_any_case_was_saved_leaves_no_folder(tmp_path, capsys, monkeypatch):
    def stop(*args: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr("pounding.studies.sweep.runner._run_batch", stop)
    path = _write(tmp_path, '[grid]\n"contact.gap" = [0.01, 0.02]\n')
    code, err = sweep_cli(capsys, str(path), "--scheduler", "synchronous", "--batch-size", "1")
    assert code == 130 and err == [
        f"error: stopped (interrupted) before any case was saved, leaving {tmp_path / 'out'} "
        f"as it was; start again with: pounding sweep {path} --scheduler synchronous "
        "--batch-size 1"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.toml"]
    with pytest.raises(SweepInterrupted) as info:
        run_sweep(load_sweep(path), scheduler="synchronous")
    assert info.value.n_saved == 0 and not (tmp_path / "out").exists()
