"""What the workers of a sweep's local cluster start with, loaded once for them all.

This module is not imported by the library: the process the local cluster's workers are
forked from (:func:`pounding.studies.sweep.cluster._start_worker_server`) imports it
before it forks any. Importing it sets glibc's allocator as the workers want it
(:data:`~pounding.studies.sweep.cluster.WORKER_MALLOC_ENV`, by ``mallopt``: in this process
only, and so in the workers forked from it), loads what every worker would otherwise load
on its own — Dask's worker, the sweep's worker side, the compiled kernel from numba's disk
cache (:func:`~pounding.studies.sweep.execute.warm_up`) — and then freezes every object
alive out of the cyclic garbage collector (``gc.freeze``, as Python's documentation advises
before forking: the workers' collections then never touch, and so never copy, the pages
they share). A worker forked from it starts with its imports done and the kernel loaded.

A warm-up that fails here (a kernel that cannot compile, say) is left to each worker's own
warm-up, which reports it.
"""

from __future__ import annotations

import contextlib
import gc

import distributed.nanny  # noqa: F401  (a worker's own machinery: what a worker imports first)

from pounding.studies.sweep.cluster import WORKER_MALLOC_ENV
from pounding.studies.sweep.execute import warm_up

_MALLOPT_PARAM = {"MALLOC_TRIM_THRESHOLD_": -1, "MALLOC_MMAP_THRESHOLD_": -3}
"""glibc's ``mallopt`` parameter of each environment variable (``M_TRIM_THRESHOLD``,
``M_MMAP_THRESHOLD`` in ``<malloc.h>``)."""


def _set_allocator() -> dict[str, bool]:
    """:data:`WORKER_MALLOC_ENV` made by ``mallopt`` in this process: for each, whether
    glibc took it (none where the C library is not glibc)."""
    import ctypes
    import ctypes.util

    done = dict.fromkeys(WORKER_MALLOC_ENV, False)
    with contextlib.suppress(OSError, AttributeError, TypeError):
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        for key, value in WORKER_MALLOC_ENV.items():
            done[key] = libc.mallopt(ctypes.c_int(_MALLOPT_PARAM[key]), ctypes.c_int(value)) == 1
    return done


ALLOCATOR_SET = _set_allocator()
"""Which of :data:`WORKER_MALLOC_ENV` glibc took in this process (and so in its workers)."""

with contextlib.suppress(Exception):
    warm_up()
gc.freeze()
