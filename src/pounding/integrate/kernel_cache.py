"""Keep numba's on-disk cache of the kernel consistent with the kernel's sources.

numba decides whether a cached function is still valid from the time stamp and size of the
one source file that defines it. The kernel's entry point (``integrate_chunk`` in
:mod:`pounding.integrate.kernel`) compiles in the functions of a dozen other modules (the
right-hand side, the step, the events, the contact and storey laws), and a change to any
of those alone would leave a stale compiled kernel in the cache. So a stamp of every kernel
source file (name, size, modification time) is kept beside the cache, and when it differs
every cached kernel function is flushed (numba then compiles afresh, once).

This costs a dozen ``stat`` calls at import; it matters for anyone who edits the kernel, and
for installs that replace some files but not others.

:func:`pounding.compiled_cache.cached_here` (re-exported here) tells, from numba's cache
index alone (one small file read), whether a compiled function will load from the cache or
be compiled first: what the command line's progress line says while it compiles
(:data:`COLD_COMPILE_S`).
"""

from __future__ import annotations

import contextlib
import hashlib
import os
from pathlib import Path
from types import ModuleType

from pounding.compiled_cache import cached_here

__all__ = ["COLD_COMPILE_S", "KERNEL_MODULES", "STAMP_FILE", "cached_here", "invalidate_if_stale",
           "sources_stamp"]

KERNEL_MODULES: tuple[str, ...] = (
    "pounding.integrate.kernel", "pounding.integrate.adaptive", "pounding.integrate.commit",
    "pounding.integrate.dormand_prince", "pounding.integrate.events",
    "pounding.integrate.exact_steps", "pounding.integrate.exact_links",
    "pounding.integrate.layout", "pounding.integrate.peaks",
    "pounding.integrate.rhs", "pounding.integrate.kernel_model",
    "pounding.integrate.workspace", "pounding.integrate.propagator",
    "pounding.integrate.modal_steps", "pounding.integrate.exact_maxwell",
    "pounding.integrate.frame_outputs",
    "pounding.contact.codes", "pounding.contact.dispatch", "pounding.contact.kernels",
    "pounding.hysteresis.base", "pounding.hysteresis.dispatch",
    "pounding.hysteresis.bilinear", "pounding.hysteresis.bouc_wen", "pounding.devices.laws",
)
"""Every module whose compiled code ends up in the kernel, or that defines the named tuples
the kernel takes (a field moved in one of those leaves the compiled signature's types as
they were, so numba's own check would not see it)."""

STAMP_FILE = "pounding-kernel-sources.stamp"

COLD_COMPILE_S: float = 56.0
"""Seconds (CPU, one core) of a first ``pounding run`` on an empty numba cache, the solver's
kernel compiled, on the project's 2-core machine (``benchmarks/bench_cold.py``, 2026-11-28:
55.6 s at load 1.4 with the Maxwell links' and tall buildings' exact steps in the kernel;
43.8 s before they joined it): what the progress line quotes while it compiles."""


def sources_stamp(modules: list[ModuleType]) -> str:
    """A hash of the kernel's source files' names, sizes and modification times."""
    h = hashlib.sha1()
    for mod in modules:
        path = Path(mod.__file__ or "")
        with contextlib.suppress(OSError):
            st = path.stat()
            h.update(f"{mod.__name__}:{st.st_size}:{st.st_mtime_ns};".encode())
    return h.hexdigest()


def invalidate_if_stale(modules: list[ModuleType]) -> bool:
    """Flush every cached compiled function of ``modules`` if their sources changed since
    the stamp was written (then write the new stamp). Returns True if it flushed.

    Never raises: a cache that cannot be read or written only means compiling again.
    """
    from numba.core.registry import CPUDispatcher

    dispatchers = [obj for mod in modules for obj in vars(mod).values()
                   if isinstance(obj, CPUDispatcher) and obj.__module__ == mod.__name__]
    cache = getattr(modules[0].integrate_chunk, "_cache", None)
    folder = getattr(cache, "_cache_path", None)
    if folder is None:
        return False
    stamp = sources_stamp(modules)
    path = Path(folder) / STAMP_FILE
    with contextlib.suppress(OSError):
        if path.read_text() == stamp:
            return False
    for disp in dispatchers:
        with contextlib.suppress(Exception):
            # numba's own invalidation: empties the cache index (a private attribute, which
            # numba's stubs leave out)
            disp._cache.flush()  # type: ignore[attr-defined]
    with contextlib.suppress(OSError):
        Path(folder).mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(stamp)
        os.replace(tmp, path)
    return True
