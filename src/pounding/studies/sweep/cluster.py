"""The Dask client a sweep runs on: a local cluster (default), an existing scheduler, or
none (in this process); and the batch size."""

from __future__ import annotations

import contextlib
import math
import os
from collections.abc import Iterator
from typing import Any

__all__: list[str] = []


def _auto_batch(n_pending: int, n_workers: int) -> int:
    """About 8 batches per worker, 10 … 200 cases each (a case takes a few ms)."""
    return max(10, min(200, math.ceil(n_pending / max(1, 8 * n_workers))))


@contextlib.contextmanager
def _client(scheduler: str | None, n_workers: int | None) -> Iterator[Any]:
    """A Dask client: local cluster (default), an existing scheduler, or none (in-process)."""
    if scheduler in ("synchronous", "none", "sync"):
        yield None
        return
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            yield client
        return
    n = n_workers or (os.cpu_count() or 1)
    import dask

    # Dask's nanny sets MALLOC_TRIM_THRESHOLD_=65536 in every worker, which turns off
    # glibc's adaptive mmap threshold: each output array of a case (hundreds of kB) is then
    # a fresh mmap whose pages fault in on first touch, and a case runs ~2x slower than in
    # this process. A large threshold keeps them on the reusable heap. (Dask already gives
    # each worker one BLAS/OpenMP thread.) The statistical profiler, which samples every
    # thread each 10 ms, is measurable on ms-long cases: off.
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    environ["MALLOC_TRIM_THRESHOLD_"] = 1 << 30
    environ["MALLOC_MMAP_THRESHOLD_"] = 1 << 27
    with dask.config.set({"distributed.worker.profile.enabled": False,
                          "distributed.nanny.pre-spawn-environ": environ}), \
            LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                         dashboard_address=None, silence_logs=40) as cluster, \
            Client(cluster) as client:
        yield client
