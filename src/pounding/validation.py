"""Checks on user input that raise early, naming the field and the value.

Every public constructor and function in ``pounding`` validates with these, so a bad
number is reported where it enters, as ``ValueError("<field> must be ... (got <value>)")``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray


def _fmt(value: Any) -> str:
    return repr(value) if not isinstance(value, float) else f"{value:g}"


def finite(name: str, value: float) -> float:
    """Return ``value`` as float, or raise if it is not a finite number."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number (got {value!r})") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite (got {_fmt(value)})")
    return x


def positive(name: str, value: float) -> float:
    """Return ``value`` as float, or raise unless it is finite and > 0."""
    x = finite(name, value)
    if x <= 0.0:
        raise ValueError(f"{name} must be > 0 (got {_fmt(x)})")
    return x


def non_negative(name: str, value: float) -> float:
    """Return ``value`` as float, or raise unless it is finite and >= 0."""
    x = finite(name, value)
    if x < 0.0:
        raise ValueError(f"{name} must be >= 0 (got {_fmt(x)})")
    return x


def in_range(name: str, value: float, low: float, high: float, *, low_open: bool = False,
             high_open: bool = False) -> float:
    """Return ``value`` as float, or raise unless it lies in the stated interval."""
    x = finite(name, value)
    bad_low = x <= low if low_open else x < low
    bad_high = x >= high if high_open else x > high
    if bad_low or bad_high:
        lo = "(" if low_open else "["
        hi = ")" if high_open else "]"
        raise ValueError(f"{name} must be in {lo}{low:g}, {high:g}{hi} (got {_fmt(x)})")
    return x


def restitution(e: ArrayLike, name: str = "e") -> NDArray[np.float64]:
    """Return the coefficient(s) of restitution as a float array, checking 0 < e <= 1.

    Raises
    ------
    ValueError
        Naming ``name`` and the first offending value.
    """
    arr = np.asarray(e, dtype=float)
    bad = ~np.isfinite(arr) | (arr <= 0.0) | (arr > 1.0)
    if np.any(bad):
        first = arr[bad].flat[0] if arr.ndim else float(arr)
        raise ValueError(f"{name} (coefficient of restitution) must satisfy 0 < {name} <= 1 "
                         f"(got {first:g})")
    return arr


def choice(name: str, value: str, options: list[str] | tuple[str, ...] | dict[str, Any]) -> str:
    """Return ``value`` if it is one of ``options`` (case-insensitive), else raise."""
    key = str(value).strip().lower()
    names = list(options)
    if key not in names:
        raise ValueError(f"{name}: unknown value {value!r}; choose one of {', '.join(names)}")
    return key
