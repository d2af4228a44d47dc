"""The local cluster's workers: forked from a server process that loaded what they need
once, with the allocator settings and the held-back Ctrl-C the workers must start with —
and nothing of the calling process changed by it (its environment, umask, start method,
fork server and its preload list). Read from the operating system (``/proc``) where it
can be, not from the sweep's own bookkeeping."""

from __future__ import annotations

import os
import platform
import re
import signal
import subprocess
import sys
import textwrap
from multiprocessing import forkserver
from pathlib import Path

import pytest

from pounding.studies.sweep import cluster
from pounding.studies.sweep.cluster import (
    WORKER_MALLOC_ENV,
    WORKER_PRELOAD,
    _client,
    _forks_workers,
    _start_worker_server,
    worker_server_pid,
)

pytestmark = pytest.mark.skipif(not (_forks_workers() and Path("/proc/self/status").exists()),
                                reason="needs a fork server and /proc (Linux)")

ROOT = Path(__file__).resolve().parents[2]


def _server_pid() -> int:
    pid = worker_server_pid()
    assert pid is not None
    return int(pid)


def test_the_server_starts_with_ctrl_c_held_back_and_this_process_unchanged():
    environ = dict(os.environ)
    _start_worker_server()
    pid = _server_pid()
    status = Path(f"/proc/{pid}/status").read_text()
    blocked = int(re.search(r"^SigBlk:\s*([0-9a-f]+)$", status, re.M).group(1), 16)
    assert blocked & (1 << (signal.SIGINT - 1)), "SIGINT is not held back in the server"
    # this process's own environment and signal mask are as they were, and it is not
    # multiprocessing's fork server of this process
    assert dict(os.environ) == environ
    assert signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, set())
    assert forkserver._forkserver._forkserver_pid != pid  # type: ignore[attr-defined]


def _who_am_i() -> tuple[int, bool, bool, dict[str, bool]]:
    """In a worker: its parent, whether it imported the preload and holds back SIGINT,
    and which allocator settings glibc took."""
    allocator = getattr(sys.modules.get(WORKER_PRELOAD), "ALLOCATOR_SET", {})
    return (os.getppid(), WORKER_PRELOAD in sys.modules,
            signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, set()), allocator)


def test_a_local_clusters_workers_are_forked_from_the_preloaded_server():
    with _client(None, 2) as client:
        answers = list(client.run(_who_am_i).values())
        pid = _server_pid()
    assert len(answers) == 2
    for parent, preloaded, sigint_held, allocator in answers:
        assert parent == pid and preloaded and sigint_held
        if platform.libc_ver()[0] == "glibc":  # mallopt took both settings
            assert allocator == dict.fromkeys(WORKER_MALLOC_ENV, True)


def test_the_server_stops_when_no_sweep_comes(monkeypatch):
    monkeypatch.setattr(cluster, "SERVER_IDLE", 0.2)
    with _client(None, 1):
        pid = _server_pid()
    cluster._idle_timer.join(10)  # type: ignore[union-attr]
    assert worker_server_pid() is None
    assert not Path(f"/proc/{pid}").exists() or "Z" in Path(f"/proc/{pid}/stat").read_text()


_PROBE = textwrap.dedent("""
    import json, multiprocessing, os, signal, sys
    from multiprocessing import forkserver
    from pathlib import Path

    def state():
        fs = forkserver._forkserver
        umask = [l for l in Path("/proc/self/status").read_text().splitlines()
                 if l.startswith("Umask:")]
        return {"environ": dict(os.environ), "umask": umask,
                "start": multiprocessing.get_start_method(allow_none=True),
                "preload": list(fs._preload_modules), "server": fs._forkserver_pid,
                "sigmask": sorted(map(int, signal.pthread_sigmask(signal.SIG_BLOCK, set())))}

    def sweep(out, workers):
        from pounding.studies.sweep import load_results, run_sweep
        res = run_sweep(sys.argv[1], out, scheduler=None, n_workers=workers)
        assert load_results(res.results)["status"].eq("ok").all()

    if __name__ == "__main__":
        os.umask(0o027)
        states = {}
        # a process that never used multiprocessing: its first sweep
        before = state()
        sweep("out1", 2)
        states["fresh"] = (before, state())
        # a process with a fork server of its own, and its own preload list
        multiprocessing.set_start_method("forkserver")
        multiprocessing.set_forkserver_preload(["json"])
        forkserver.ensure_running()
        before = state()
        sweep("out2", 1)
        states["own-server"] = (before, state())
        ctx = multiprocessing.get_context("forkserver")  # which still serves it
        p = ctx.Process(target=os.getpid)
        p.start(); p.join()
        assert p.exitcode == 0
        print(json.dumps(states))
""")


def test_a_sweep_leaves_the_calling_process_as_it_was(tmp_path):
    """After a sweep on a local cluster: the caller's environment, umask, start method,
    signal mask, fork server (none, or its own) and preload list are as before — for a
    process's first sweep, and for a process that runs a fork server of its own."""
    import json

    sweep = tmp_path / "sweep.toml"
    sweep.write_text(f'base = "{ROOT / "examples" / "seed_sdof_pair.toml"}"\n'
                     '[grid]\n"contact.gap" = [0.01, 0.02]\n"record.duration" = [2.0]\n',
                     encoding="utf-8")
    probe = tmp_path / "probe.py"
    probe.write_text(_PROBE, encoding="utf-8")
    # the pounding under test, wherever the probe runs (PYTHONPATH may be relative)
    import pounding

    src = str(Path(pounding.__file__).resolve().parents[1])
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [src, *(str(Path(p).resolve()) for p in os.environ.get("PYTHONPATH", "").split(
            os.pathsep) if p)])}
    proc = subprocess.run([sys.executable, str(probe), str(sweep)], capture_output=True,
                          text=True, timeout=300, cwd=tmp_path, env=env)
    assert proc.returncode == 0, proc.stderr[-3000:]
    states = json.loads(proc.stdout.strip().splitlines()[-1])
    for mode, (before, after) in states.items():
        assert after == before, mode
        assert before["umask"] == ["Umask:\t0027"]
    assert states["fresh"][0]["server"] is None and states["fresh"][0]["start"] is None
    assert states["own-server"][0]["server"] is not None
    assert states["own-server"][0]["preload"] == ["json"]
