"""Keep freed memory for reuse between simulations (glibc's ``mallopt``; a no-op elsewhere).

A simulation allocates its outputs afresh on every call (about 5 MB for the seed's SDOF pair
over El Centro, tens of MB for tall buildings). glibc serves allocations that large as new
pages from the kernel (``mmap``) unless a recent free left room on its heap, and its own
heuristics (a dynamic mmap threshold, trimming the heap top) decide which from call to
call. New pages cost a page fault each on first touch: the two 10-storey buildings of the
demo fault in ~2,400 fresh pages (~10 MB) on every call without the setting and about one
with it (``benchmarks/bench_memory.py``, docs/performance.md "Memory between runs").

:func:`keep_freed_memory` asks glibc to serve allocations up to :data:`MMAP_THRESHOLD` from
its heap and to trim the heap only beyond :data:`TRIM_THRESHOLD` of free memory at its top,
so a second simulation reuses what the first one freed, as a long-running process would.
:func:`pounding.integrate.simulate` calls it once per process, before its first run; the
price is that up to :data:`TRIM_THRESHOLD` of freed memory stays with the process instead
of going back to the system. Set ``POUNDING_KEEP_FREED_MEMORY=0`` in the environment
(before the first simulation) to leave glibc's own settings alone. The sweep's local
cluster sets its workers the same way (:data:`pounding.studies.sweep.cluster.WORKER_MALLOC_ENV`).
"""

from __future__ import annotations

import os

__all__ = ["ENV_VARIABLE", "MMAP_THRESHOLD", "TRIM_THRESHOLD", "keep_freed_memory"]

MMAP_THRESHOLD = 64 * 1024 * 1024
"""Bytes: allocations up to this size come from the heap, not fresh ``mmap`` pages."""

TRIM_THRESHOLD = 256 * 1024 * 1024
"""Bytes of free memory at the heap's top kept before glibc gives it back to the system."""

ENV_VARIABLE = "POUNDING_KEEP_FREED_MEMORY"
"""``0`` (or ``no``, ``false``, ``off``) leaves the allocator as glibc set it."""

_M_TRIM_THRESHOLD = -1  # <malloc.h>
_M_MMAP_THRESHOLD = -3

_done: bool | None = None


def keep_freed_memory(*, force: bool = False) -> bool:
    """Set glibc's mmap and trim thresholds (:data:`MMAP_THRESHOLD`, :data:`TRIM_THRESHOLD`)
    once per process.

    Parameters
    ----------
    force : bool
        Set them even where :data:`ENV_VARIABLE` says not to (the benchmarks do, to time both
        tools of a comparison under one setting), and again if already set.

    Returns
    -------
    bool
        Whether glibc took both settings (False where the C library is not glibc, or where
        the environment said no).
    """
    global _done
    if _done is not None and not force:
        return _done
    if not force and os.environ.get(ENV_VARIABLE, "1").strip().lower() in (
            "0", "no", "false", "off"):
        _done = False
        return False
    import ctypes
    import ctypes.util

    ok = False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        pass
    else:
        ok = (mallopt(ctypes.c_int(_M_MMAP_THRESHOLD), ctypes.c_int(MMAP_THRESHOLD)) == 1)
        ok &= (mallopt(ctypes.c_int(_M_TRIM_THRESHOLD), ctypes.c_int(TRIM_THRESHOLD)) == 1)
    _done = ok
    return ok
