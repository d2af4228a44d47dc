"""Keep freed memory for reuse while timing (glibc only; a no-op elsewhere).

A simulation allocates its output arrays afresh on every call (about 5 MB for the SDOF pair
over El Centro). glibc hands allocations that large out as new pages from the kernel
unless a recent free left room on its heap, and its own heuristics (a dynamic mmap
threshold, heap trimming) decide which, from call to call. New pages cost a page fault
each on first touch, inside the timed loop: up to ~1 ms on a 2–3 ms run, on some calls
and not others. ``keep_freed_memory()`` asks glibc (``mallopt``) to serve allocations up
to 32 MB from its heap and not to trim it, so repeats reuse the memory the last one
freed, as a long-running process would. Both tools of a comparison run in the same
process, under the same setting.
"""

from __future__ import annotations

import ctypes
import ctypes.util

M_TRIM_THRESHOLD = -1
M_MMAP_THRESHOLD = -3


def keep_freed_memory() -> bool:
    """Set glibc's mmap and trim thresholds high; True if glibc took the setting."""
    name = ctypes.util.find_library("c")
    if not name:
        return False
    try:
        libc = ctypes.CDLL(name)
        ok = libc.mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024)
        ok &= libc.mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024)
    except (OSError, AttributeError):
        return False
    return bool(ok)
