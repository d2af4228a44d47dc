"""The Dask client a sweep runs on: a local cluster (default; its workers forked from a
server process that loaded what they need once, :func:`_start_worker_server`), an existing
scheduler, or none (in this process); the batch size; and a quiet stop.

A sweep stopped by Ctrl-C, or by a lost scheduler, ends in one line from the caller, not
in Dask's log records and the tracebacks of its worker processes: the workers of the local
cluster never receive Ctrl-C (their process group does, from the terminal, but they start
with SIGINT held back), and logging is silenced from the first Ctrl-C (or failure) until
the cluster is closed.
"""

from __future__ import annotations

import contextlib
import logging
import math
import multiprocessing
import os
import signal
import threading
from collections.abc import Iterator
from typing import Any

__all__ = ["QUIET_INTERVALS", "SCHEDULER_TIMEOUT", "WORKER_MALLOC_ENV", "WORKER_PRELOAD"]

SCHEDULER_TIMEOUT = 10.0
"""Seconds to wait for a Dask scheduler given by address to answer (Dask's default is 30):
also how long a client tries to reconnect to a scheduler it lost."""


WORKER_MALLOC_ENV: dict[str, int] = {"MALLOC_TRIM_THRESHOLD_": 1 << 30,
                                     "MALLOC_MMAP_THRESHOLD_": 1 << 27}
"""glibc's settings in the local cluster's workers (see :func:`_local_config`): freed
memory is kept for reuse, so a case's output arrays do not fault in afresh. The worker
server makes them with ``mallopt`` (:mod:`~pounding.studies.sweep.worker_preload`, the same
parameters as these environment variables; its workers inherit them), and the workers'
environment names them."""


WORKER_PRELOAD = "pounding.studies.sweep.worker_preload"
"""The module the local cluster's workers are forked from (:func:`_start_worker_server`)."""


QUIET_INTERVALS: dict[str, str] = {
    "distributed.admin.tick.interval": "1s",
    "distributed.worker.memory.monitor-interval": "1s",
    "distributed.admin.system-monitor.interval": "2s",
}
"""Dask's periodic housekeeping in the local cluster, less often than its defaults (20 ms,
100 ms, 500 ms): an event-loop health check in every process, the nanny's look at each
worker's memory, the dashboard's system monitor. Measured on an idle 2-worker cluster
(2026-11-25): 21 → 9 ms of CPU a second in this process, 14 → 3.5 in each worker."""


MIN_BATCH = 10
"""Fewest cases of an automatic batch (a case takes a few ms; a batch costs the client a
Parquet part)."""

MAX_BATCH = 500
"""Most cases of an automatic batch: a second or so of cases of a few ms. A batch costs
about 10 ms of CPU (Dask's task in the client and the worker, the Parquet part), 1–2 % of
such a batch; it is also what Ctrl-C can lose, and the step of the progress bar."""


def _auto_batch(n_pending: int, n_workers: int) -> int:
    """About 4 batches per worker, :data:`MIN_BATCH` … :data:`MAX_BATCH` cases each (a
    case takes a few ms), before the last ones shrink (:func:`_batch_sizes`)."""
    return max(MIN_BATCH, min(MAX_BATCH, math.ceil(n_pending / max(1, 4 * n_workers))))


def _batch_sizes(n_pending: int, n_workers: int, size: int, taper: bool) -> list[int]:
    """Cases of each batch, in order: ``size`` each; with ``taper`` the last ones shrink
    (each at most the cases left over twice the workers, at least :data:`MIN_BATCH`), so
    the workers finish together instead of one waiting on the other's last large batch."""
    sizes = []
    left = n_pending
    while left > 0:
        s = min(size, max(MIN_BATCH, math.ceil(left / (2 * n_workers)))) if taper else size
        sizes.append(min(s, left))
        left -= sizes[-1]
    return sizes


def _silence_dask() -> None:
    """Silence logging (Dask's loggers, and its event loop's) until :func:`_client` ends."""
    logging.disable(logging.CRITICAL)


def _in_main_thread() -> bool:
    """Signal handlers and masks can be set only here."""
    return threading.current_thread() is threading.main_thread()


@contextlib.contextmanager
def _sigint_held() -> Iterator[None]:
    """Hold SIGINT back from this thread while the block runs. The threads it starts, and
    the processes they start, inherit the held signal: Ctrl-C in the terminal never
    reaches the worker processes of a local cluster. A Ctrl-C pressed meanwhile arrives
    when the block ends."""
    if not (hasattr(signal, "pthread_sigmask") and _in_main_thread()):
        yield
        return
    # multiprocessing starts its resource tracker on first use, and unblocks SIGINT in the
    # thread that starts it: start it now, before the signal is held
    from multiprocessing import resource_tracker

    resource_tracker.ensure_running()
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


@contextlib.contextmanager
def _quiet_interrupt() -> Iterator[None]:
    """Ctrl-C silences logging before it raises KeyboardInterrupt (a Dask call interrupted
    half-way logs its own cancellation as an error)."""
    if not _in_main_thread() or signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return

    def handler(signum: int, frame: Any) -> None:
        _silence_dask()
        raise KeyboardInterrupt

    signal.signal(signal.SIGINT, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)


@contextlib.contextmanager
def _sigint_ignored() -> Iterator[None]:
    """Ignore Ctrl-C while the block runs (closing a cluster is not to be interrupted)."""
    if not _in_main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def _forks_workers() -> bool:
    """Whether the local cluster's workers are forked from a server process that loaded
    what they need once (:func:`_start_worker_server`): wherever Python has a fork server
    (Linux, macOS; not Windows, where each worker starts afresh)."""
    return "forkserver" in multiprocessing.get_all_start_methods()


SERVER_IDLE = 120.0
"""Seconds the worker server (:func:`_start_worker_server`) waits for another sweep of this
process before it stops."""

_SERVER_LOCK = threading.Lock()
_server: Any = None
"""The sweep's own fork server (a ``multiprocessing.forkserver.ForkServer``), not the
process's: None until the first local cluster."""
_idle_timer: threading.Timer | None = None


@contextlib.contextmanager
def _start_method_kept() -> Iterator[None]:
    """The start method of ``multiprocessing`` in this process as it was, after the block:
    not chosen if it was not (``multiprocessing`` fixes it the first time it prepares a
    child process, ``spawn.get_preparation_data``; it is chosen again at its next use)."""
    method = multiprocessing.get_start_method(allow_none=True)
    try:
        yield
    finally:
        if method is None:
            with contextlib.suppress(AttributeError):
                multiprocessing.context._default_context._actual_context = None


def _start_worker_server() -> None:
    """Start the process the local cluster's workers will be forked from, if it is not
    running yet: it imports :data:`WORKER_PRELOAD` (Dask's worker, the sweep's worker
    side, the compiled kernel; glibc's settings :data:`WORKER_MALLOC_ENV`) while this
    process goes on, and serves the later sweeps of this process that start within
    :data:`SERVER_IDLE` seconds of the last one's end; then it stops.

    Each worker then starts with its imports done and the kernel loaded, instead of
    spawning a fresh Python that imports Dask and pounding and loads the kernel on its own
    (0.35 s and 0.47 s a worker on the project's machine at a quiet moment, 2026-11-25):
    the work is done once, beside the client's own start (its ``import distributed``).

    The server is the sweep's own, not the fork server of ``multiprocessing`` in this
    process: that one is lent to Dask only while a local cluster runs
    (:func:`_lend_worker_server`), then given back as it was — its preload list, and its
    server if it had one. Nothing else of this process changes: the allocator's settings
    are made inside the server (this process's environment is not touched), and SIGINT is
    held back only in the thread that starts it, while it starts (the server and the
    workers forked from it keep it held, :func:`_sigint_held`). Nothing happens where
    Python has no fork server (:func:`_forks_workers`).
    """
    global _server, _idle_timer
    if not _forks_workers():
        return
    from multiprocessing import forkserver

    with _SERVER_LOCK:
        if _idle_timer is not None:
            _idle_timer.cancel()
            _idle_timer = None
        if _lent:  # running, lent to a local cluster of another thread
            return
        if _server is None:
            _server = forkserver.ForkServer()
        _server.set_forkserver_preload([WORKER_PRELOAD])
        with _sigint_held(), _start_method_kept():
            _server.ensure_running()


def worker_server_pid() -> int | None:
    """The process id of the worker server (:func:`_start_worker_server`); None if none
    runs."""
    from multiprocessing import forkserver

    with _SERVER_LOCK:
        # while a local cluster runs, multiprocessing's fork server holds its state (Any:
        # typeshed leaves out the private fields read here)
        server: Any = forkserver._forkserver if _lent else _server
        return None if server is None else server._forkserver_pid


def stop_worker_server() -> None:
    """Stop the worker server now, if it runs and no local cluster uses it (it also stops
    by itself, :data:`SERVER_IDLE` seconds after a sweep, and with this process)."""
    global _idle_timer
    with _SERVER_LOCK:
        if _idle_timer is not None:
            _idle_timer.cancel()
            _idle_timer = None
        if _server is not None and _lent == 0:
            _server._stop()


def _swap_servers(a: Any, b: Any) -> None:
    """Exchange the state of two fork servers (their process, address and preload list);
    each keeps its own lock."""
    for key in (set(vars(a)) | set(vars(b))) - {"_lock"}:
        va, vb = vars(a).get(key), vars(b).get(key)
        setattr(a, key, vb)
        setattr(b, key, va)


_lent = 0
"""How many local clusters of this process have the worker server lent (sweeps in several
threads at once share it)."""


@contextlib.contextmanager
def _lend_worker_server() -> Iterator[None]:
    """The fork server of ``multiprocessing`` is the worker server while the block runs.

    Dask's nanny forks its worker from ``multiprocessing.get_context("forkserver")``, whose
    server is one per process: the worker server's state takes its place while a local
    cluster runs, and the process's own (its preload list, its server if any) is back
    after it. Dask names its own preload list on the server it is lent; the worker server
    keeps :data:`WORKER_PRELOAD`. It stops :data:`SERVER_IDLE` seconds after the last
    cluster unless another sweep starts.
    """
    global _idle_timer, _lent
    if not _forks_workers():
        yield
        return
    from multiprocessing import forkserver

    _start_worker_server()  # (at once if the sweep started it already)
    own: Any = forkserver._forkserver  # (Any: typeshed leaves out its private _lock)
    with own._lock, _SERVER_LOCK:
        if _lent == 0:
            _swap_servers(own, _server)
        _lent += 1
    try:
        yield
    finally:
        with own._lock, _SERVER_LOCK:
            _lent -= 1
            if _lent == 0:
                _swap_servers(own, _server)
                _server.set_forkserver_preload([WORKER_PRELOAD])
                if _idle_timer is not None:
                    _idle_timer.cancel()
                _idle_timer = threading.Timer(SERVER_IDLE, stop_worker_server)
                _idle_timer.daemon = True
                _idle_timer.start()


def _connect(scheduler: str) -> Any:
    """A client of the Dask scheduler at ``scheduler``, or one line saying why not."""
    from distributed import Client

    try:
        return Client(scheduler, timeout=SCHEDULER_TIMEOUT)
    except ValueError as exc:  # not an address
        raise ValueError(f"scheduler: {scheduler}: {exc}") from None
    except OSError:
        raise ValueError(f"scheduler: no Dask scheduler answers at {scheduler} (waited "
                         f"{SCHEDULER_TIMEOUT:g} s); check the address, start one "
                         "(`dask scheduler`), or leave out --scheduler for a local cluster"
                         ) from None


def _local_config() -> Any:
    """The Dask configuration of the local cluster's workers (a context manager)."""
    import dask

    # Dask's nanny sets MALLOC_TRIM_THRESHOLD_=65536 in every worker, which turns off
    # glibc's adaptive mmap threshold: each output array of a case (hundreds of kB) is then
    # a fresh mmap whose pages fault in on first touch, and a case runs ~2x slower than in
    # this process. A large threshold keeps them on the reusable heap. (Dask already gives
    # each worker one BLAS/OpenMP thread.) The statistical profiler, which samples every
    # thread each 10 ms, is measurable on ms-long cases: off. So is the housekeeping of an
    # idle cluster, about 5 % of a core (QUIET_INTERVALS). The workers are forked from the
    # server of _start_worker_server where there is one (the nanny's MALLOC_* settings then
    # do not reach glibc, which reads them when a process starts: the server sets them
    # with mallopt, and its workers inherit them).
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    environ.update(WORKER_MALLOC_ENV)
    method = "forkserver" if _forks_workers() else "spawn"
    return dask.config.set({"distributed.worker.profile.enabled": False,
                            "distributed.worker.multiprocessing-method": method,
                            "distributed.nanny.pre-spawn-environ": environ,
                            **QUIET_INTERVALS})


_DASK_ENVIRON = ("PYTHONHASHSEED", "__DASK_PARENT_PID")
"""Environment variables Dask's nanny sets in the process that starts its workers, beside
those of ``distributed.nanny.pre-spawn-environ``."""


@contextlib.contextmanager
def _process_state_kept() -> Iterator[None]:
    """Put back, after the block, what a local cluster changes in this process.

    Dask's nanny sets its ``distributed.nanny.pre-spawn-environ`` (one BLAS/OpenMP thread,
    glibc's settings), ``PYTHONHASHSEED`` and ``__DASK_PARENT_PID`` in ``os.environ`` before
    it starts a worker, for the worker to inherit; and ``multiprocessing`` fixes the start
    method of this process the first time it prepares a child process
    (:func:`_start_method_kept`). Both are as they were after the block (while it runs,
    they are Dask's and multiprocessing's)."""
    import dask

    keys = {*dask.config.get("distributed.nanny.pre-spawn-environ", {}), *_DASK_ENVIRON}
    environ = {k: os.environ.get(k) for k in keys}
    try:
        with _start_method_kept():
            yield
    finally:
        for key, value in environ.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value


_CLIENT_LOGGERS = ("distributed", "distributed.client", "tornado", "tornado.application")
"""The loggers a sweep silences in this process while it has a client: Dask gives each of
them a level and a handler of its own, so each is named."""


@contextlib.contextmanager
def _client(scheduler: str | None, n_workers: int | None) -> Iterator[Any]:
    """A Dask client: local cluster (default), an existing scheduler, or none (in-process).

    Parameters
    ----------
    scheduler : str or None
        None: a local cluster; ``"synchronous"`` (or ``"sync"``, ``"none"``): no client,
        the cases run in this process; else the address of a running Dask scheduler.
    n_workers : int or None
        Worker processes of the local cluster (default: the CPU count).

    Raises
    ------
    ValueError
        No scheduler answers at ``scheduler`` within :data:`SCHEDULER_TIMEOUT`, or it is
        not an address.
    """
    if scheduler in ("synchronous", "none", "sync"):
        yield None
        return
    from distributed import Client, LocalCluster

    disabled = logging.root.manager.disable
    # Dask's client-side loggers in this process (a batched comm closing, a reconnect
    # attempt) print tracebacks at INFO/WARNING when a scheduler goes away, before the
    # sweep can say so in one line: the sweep reports its own failures. So does the event
    # loop's (tornado.application): a gather of results cut by the lost scheduler ends in
    # an exception that no one awaits, which it logs with a traceback.
    quiet = [logging.getLogger(name) for name in _CLIENT_LOGGERS]
    levels = [lg.level for lg in quiet]
    for lg in quiet:
        lg.setLevel(logging.CRITICAL)
    cluster = client = None
    try:
        with (contextlib.nullcontext() if scheduler else _local_config(),
              contextlib.nullcontext() if scheduler else _process_state_kept(),
              contextlib.nullcontext() if scheduler else _lend_worker_server()):
            try:
                if scheduler:
                    client = _connect(scheduler)
                else:
                    # the workers log nothing below CRITICAL: a sweep reports its own
                    # failures, and a worker stopped with its cluster may log an error.
                    # The scheduler's HTTP server (None would still mean 0.0.0.0:8787, and
                    # a warning on a second sweep) on a free port of this machine only.
                    with _sigint_held():
                        cluster = LocalCluster(
                            n_workers=n_workers or (os.cpu_count() or 1), threads_per_worker=1,
                            processes=True, dashboard_address="127.0.0.1:0",
                            silence_logs=logging.CRITICAL)
                        client = Client(cluster)
                with _quiet_interrupt():
                    yield client
            except BaseException:
                _silence_dask()
                raise
            finally:
                with _sigint_ignored():  # nothing interrupts the closing
                    if client is not None:
                        client.close()
                    if cluster is not None:
                        cluster.close()
    finally:
        logging.disable(disabled)
        for lg, level in zip(quiet, levels):
            lg.setLevel(level)
