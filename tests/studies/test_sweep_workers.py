"""The local cluster's workers: forked from a server process that loaded what they need
once, with the allocator settings and the held-back Ctrl-C the workers must start with.
Read from the operating system (``/proc``), not from the sweep's own bookkeeping."""

from __future__ import annotations

import os
import re
import signal
import sys
from multiprocessing import forkserver
from pathlib import Path

import pytest

from pounding.studies.sweep.cluster import (
    WORKER_MALLOC_ENV,
    WORKER_PRELOAD,
    _client,
    _forks_workers,
    _start_worker_server,
)

pytestmark = pytest.mark.skipif(not (_forks_workers() and Path("/proc/self/status").exists()),
                                reason="needs a fork server and /proc (Linux)")


def _server_pid() -> int:
    pid = forkserver._forkserver._forkserver_pid  # type: ignore[attr-defined]
    assert pid is not None
    return int(pid)


def test_the_server_starts_with_the_allocator_settings_and_ctrl_c_held_back():
    before = {k: os.environ.get(k) for k in WORKER_MALLOC_ENV}
    _start_worker_server()
    pid = _server_pid()
    environ = Path(f"/proc/{pid}/environ").read_bytes().split(b"\0")
    for key, value in WORKER_MALLOC_ENV.items():
        assert f"{key}={value}".encode() in environ
    status = Path(f"/proc/{pid}/status").read_text()
    blocked = int(re.search(r"^SigBlk:\s*([0-9a-f]+)$", status, re.M).group(1), 16)
    assert blocked & (1 << (signal.SIGINT - 1)), "SIGINT is not held back in the server"
    # this process's own environment and signal mask are as they were
    assert {k: os.environ.get(k) for k in WORKER_MALLOC_ENV} == before
    assert signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, set())


def _who_am_i() -> tuple[int, bool, bool]:
    """In a worker: its parent, whether it imported the preload and holds back SIGINT."""
    return (os.getppid(), WORKER_PRELOAD in sys.modules,
            signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, set()))


def test_a_local_clusters_workers_are_forked_from_the_preloaded_server():
    with _client(None, 2) as client:
        answers = list(client.run(_who_am_i).values())
    assert len(answers) == 2
    pid = _server_pid()
    for parent, preloaded, sigint_held in answers:
        assert parent == pid and preloaded and sigint_held
