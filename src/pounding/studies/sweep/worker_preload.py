"""What the workers of a sweep's local cluster start with, loaded once for them all.

This module is not imported by the library: the process the local cluster's workers are
forked from (:func:`pounding.studies.sweep.cluster._start_worker_server`) imports it
before it forks any. Importing it loads what every worker would otherwise load on its own
— Dask's worker, the sweep's worker side, the compiled kernel from numba's disk cache
(:func:`~pounding.studies.sweep.execute.warm_up`) — and then freezes every object alive out
of the cyclic garbage collector (``gc.freeze``, as Python's documentation advises before
forking: the workers' collections then never touch, and so never copy, the pages they
share). A worker forked from it starts with its imports done and the kernel loaded.

A warm-up that fails here (a kernel that cannot compile, say) is left to each worker's own
warm-up, which reports it.
"""

from __future__ import annotations

import contextlib
import gc

import distributed.nanny  # noqa: F401  (a worker's own machinery: what a worker imports first)

from pounding.studies.sweep.execute import warm_up

with contextlib.suppress(Exception):
    warm_up()
gc.freeze()
