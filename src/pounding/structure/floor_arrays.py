"""Per-floor data as every structure stores it: checked float64 vectors, read-only arrays.

Shared by the shear building (:mod:`pounding.structure.shear_building`), the building in
plan (:mod:`pounding.structure.plan`), the matrix building and its checks
(:mod:`pounding.structure.matrices`, :mod:`pounding.structure.matrix_checks`) and the model
files' limits (:mod:`pounding.config`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.validation import positive

__all__ = ["MAX_FLOORS", "SMALLEST", "floor_vector", "readonly"]

MAX_FLOORS: int = 10_000
"""Most floors a building may have: far beyond any real building (the tallest have about
160), and a guard against a typo allocating terabytes (``n_storeys = 1e18``)."""

SMALLEST: float = float(np.finfo(np.float64).tiny)
"""Smallest normal positive float (2.2e-308): masses and stiffnesses below it are subnormal,
their reciprocals infinite."""


def floor_vector(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """A read-only float64 copy of ``value``, 1-D, non-empty, at most :data:`MAX_FLOORS`
    long, every entry finite and at least :data:`SMALLEST`."""
    try:
        arr = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a sequence of numbers, one per floor "
                         f"(got {value!r})") from None
    arr = np.atleast_1d(arr)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, one value per floor "
                         f"(got shape {arr.shape})")
    if arr.size == 0:
        raise ValueError(f"{name} must hold at least one value (got {value!r})")
    if arr.size > MAX_FLOORS:
        raise ValueError(f"{name} must hold at most {MAX_FLOORS} values, one per floor "
                         f"(got {arr.size})")
    for i, x in enumerate(arr):
        if positive(f"{name}[{i}]", x) < SMALLEST:
            raise ValueError(f"{name}[{i}] must be at least {SMALLEST:.3g}: smaller "
                             f"positive numbers are subnormal (got {x:g})")
    arr = np.ascontiguousarray(arr)
    arr.flags.writeable = False
    return arr


def readonly(a: NDArray[np.float64]) -> NDArray[np.float64]:
    """A read-only C-contiguous float64 view (or copy) of ``a``, to store in a frozen
    structure."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    a.flags.writeable = False
    return a
