"""Whether a compiled (numba) function will load from numba's on-disk cache or be compiled
first: what a command says before a first run's pause (the solver's kernel, the response
spectra's).

Reads numba's cache index only (one small file); loads and compiles nothing. A foundation:
the packages that own a compiled kernel (:mod:`pounding.integrate`,
:mod:`pounding.spectra`) ask it about their own functions and say how long their compiling
takes. A caller that wants to be told before a kernel compiles (the command line, which
prints one line) passes a callback to :func:`tell_compiling_to`; the kernels' owners call
:func:`before_first_call`.
"""

from __future__ import annotations

import os
import pickle
from collections.abc import Callable

__all__ = ["before_first_call", "cached_here", "tell_compiling_to", "will_compile"]

_LISTENERS: list[Callable[[str, float], None]] = []
"""Who is told ``(what, seconds)`` before a kernel compiles (:func:`tell_compiling_to`)."""


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


def will_compile(dispatcher: object) -> bool:
    """True if the first call of ``dispatcher`` in this process compiles it: not loaded yet
    (no signature in this process) and not in numba's cache for this machine
    (:func:`cached_here`). False for a plain function (numba's JIT disabled)."""
    if not hasattr(dispatcher, "signatures"):  # a plain function (NUMBA_DISABLE_JIT=1)
        return False
    return not dispatcher.signatures and not cached_here(dispatcher)


def tell_compiling_to(listener: Callable[[str, float], None] | None) -> None:
    """Have ``listener(what, seconds)`` called before a kernel that announces itself
    (:func:`before_first_call`) compiles in this process (None: nobody). ``what`` names the
    kernel (``"the response-spectrum kernel"``), ``seconds`` the CPU time it usually takes."""
    _LISTENERS.clear()
    if listener is not None:
        _LISTENERS.append(listener)


def before_first_call(dispatcher: object, what: str, seconds: float) -> None:
    """Tell the listener (:func:`tell_compiling_to`) that ``dispatcher`` is about to be
    compiled, if it will be (:func:`will_compile`); nothing if nobody listens or it loads
    from the cache. Cheap once the function is loaded in this process."""
    if _LISTENERS and will_compile(dispatcher):
        for listener in _LISTENERS:
            listener(what, seconds)
