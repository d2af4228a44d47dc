"""The allocator setting of a benchmark: what ``pounding`` itself does, or glibc left alone.

``pounding.integrate.simulate`` keeps freed memory for reuse (glibc ``mallopt``, once per
process: :mod:`pounding.allocator`), so a user's loop of simulations reuses the memory the
last one freed instead of faulting in fresh pages. A benchmark sets the same thing at its
start, before either tool of a comparison runs, so both are timed under the setting a user
of pounding gets; ``--fresh-memory`` leaves glibc's own settings alone for both (and so also
stops pounding from making them: ``POUNDING_KEEP_FREED_MEMORY=0``).
"""

from __future__ import annotations

import os

from pounding.allocator import ENV_VARIABLE
from pounding.allocator import keep_freed_memory as _library_setting


def keep_freed_memory(fresh: bool = False) -> bool:
    """pounding's allocator setting now, for both tools; with ``fresh`` none at all (here,
    nor later in ``simulate``). True if glibc took the setting."""
    if fresh:
        os.environ[ENV_VARIABLE] = "0"
        return False
    return _library_setting(force=True)
