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

:func:`cached_here` tells, from numba's cache index alone (one small file read), whether a
compiled function will load from the cache or be compiled first: what the command line's
progress line says while it compiles (:data:`COLD_COMPILE_S`).
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import pickle
from pathlib import Path
from types import ModuleType

KERNEL_MODULES: tuple[str, ...] = (
    "pounding.integrate.kernel", "pounding.integrate.adaptive", "pounding.integrate.commit",
    "pounding.integrate.dormand_prince", "pounding.integrate.events",
    "pounding.integrate.exact_steps", "pounding.integrate.exact_links",
    "pounding.integrate.layout", "pounding.integrate.peaks",
    "pounding.integrate.rhs", "pounding.integrate.kernel_model",
    "pounding.integrate.workspace", "pounding.integrate.propagator",
    "pounding.integrate.frame_outputs",
    "pounding.contact.codes", "pounding.contact.dispatch", "pounding.contact.kernels",
    "pounding.hysteresis.base", "pounding.hysteresis.dispatch",
    "pounding.hysteresis.bilinear", "pounding.hysteresis.bouc_wen", "pounding.devices.laws",
)
"""Every module whose compiled code ends up in the kernel, or that defines the named tuples
the kernel takes (a field moved in one of those leaves the compiled signature's types as
they were, so numba's own check would not see it)."""

STAMP_FILE = "pounding-kernel-sources.stamp"

COLD_COMPILE_S: float = 44.0
"""Seconds (CPU, one core) of a first ``pounding run`` on an empty numba cache, the solver's
kernel compiled, on the project's 2-core machine (``benchmarks/bench_cold.py``, 2026-11-28:
43.8 s at load 1, where the kernel with Python wrappers on every function (before
rhs.NRT_FREE's ``no_cpython_wrapper``) took 49.7 s the minute after): what the progress
line quotes while it compiles."""


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


def cached_here(dispatcher: object) -> bool:
    """True if numba's on-disk cache holds compiled code of ``dispatcher`` that this process
    would load rather than compile: an index whose stamp matches the function's source file,
    with an entry for this machine's code generator (CPU name and features) whose data file
    is there. Reads the index only (no compiling, no loading of code).

    False where there is no such entry, or the cache cannot be read (then numba compiles).
    """
    try:
        cache_file = dispatcher._cache._cache_file  # type: ignore[attr-defined]
        # numba's own reading of the index: {} if missing, of another numba version, or
        # stale (its source file's stamp changed); keys (signature, codegen magic, hashes)
        overloads = cache_file._load_index()
        magic = dispatcher.targetctx.codegen().magic_tuple()  # type: ignore[attr-defined]
        folder = cache_file._cache_path
    except (AttributeError, OSError, EOFError, ValueError, TypeError, IndexError,
            pickle.UnpicklingError):
        return False
    return any(key[1] == magic and os.path.isfile(os.path.join(folder, name))
               for key, name in overloads.items())
