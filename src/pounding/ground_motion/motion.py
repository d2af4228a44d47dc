"""The ground-motion record: :class:`GroundMotion`, a uniformly sampled horizontal ground
acceleration in m/s² whose first sample is at ``t = 0``, with its peaks (PGA, PGV, PGD),
its velocity and displacement by the trapezoidal rule, and scaled or trimmed copies.

Readers (:mod:`pounding.ground_motion.readers`) and generators
(:mod:`pounding.ground_motion.synthetic`) build it; see ``docs/ground_motion.md``.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.units import G
from pounding.validation import finite, non_negative, positive

__all__ = ["GroundMotion"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False, init=False)
class GroundMotion:
    """A uniformly sampled ground acceleration record, in SI units.

    Parameters
    ----------
    dt : float
        Time step [s], > 0.
    accel : array_like
        Ground acceleration [m/s²], one value per step, first sample at ``t = 0``. Stored
        as a read-only float64 array; every value must be finite and there must be at least
        one.
    name : str
        Short name used in tables and plot titles.
    source : str
        Where the record came from: a file path or a description.
    units_read : str
        The acceleration unit of the source (``"g"``, ``"cm/s2"``, ``"m/s2"``...). A unit
        that was not stated in the file but assumed carries the suffix ``" (assumed)"``.
    metadata : dict
        Anything else read with the record, e.g. ``"header"``: the header lines of an AT2
        file.

    Raises
    ------
    ValueError
        If ``dt`` is not a positive finite number, or ``accel`` is empty, not 1-D or holds
        a non-finite value; the message names the field and the value.
    """

    dt: float
    accel: FloatArray
    name: str
    source: str
    units_read: str
    metadata: Mapping[str, Any]

    def __init__(self, dt: float, accel: ArrayLike, name: str = "record", source: str = "",
                 units_read: str = "m/s2",
                 metadata: Mapping[str, Any] = MappingProxyType({})) -> None:
        label = f"ground motion {name!r}"
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "dt", positive(f"{label}: dt", dt))
        try:
            arr = np.array(accel, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"{label}: accel must be an array of numbers") from None
        if arr.ndim != 1:
            raise ValueError(f"{label}: accel must be one-dimensional (got shape {arr.shape})")
        if arr.size == 0:
            raise ValueError(f"{label}: accel must hold at least one value (got none)")
        bad = ~np.isfinite(arr)
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(f"{label}: accel must be finite (got {arr[i]} at index {i})")
        arr.setflags(write=False)
        frozen_set(self, "accel", arr)
        frozen_set(self, "name", name)
        frozen_set(self, "source", source)
        frozen_set(self, "units_read", units_read)
        frozen_set(self, "metadata", dict(metadata))

    # ------------------------------------------------------------------ sampling
    @property
    def npts(self) -> int:
        """Number of samples."""
        return int(self.accel.size)

    @property
    def time(self) -> FloatArray:
        """Sample times [s]: ``0, dt, 2 dt, ..., (npts - 1) dt``."""
        return np.arange(self.npts, dtype=np.float64) * self.dt

    @property
    def duration(self) -> float:
        """Time of the last sample [s], ``(npts - 1) dt``."""
        return (self.npts - 1) * self.dt

    # ------------------------------------------------------------------ peaks
    @functools.cached_property
    def pga(self) -> float:
        """Peak ground acceleration, ``max |a|`` [m/s²] (computed once: the record is
        read-only)."""
        return float(np.max(np.abs(self.accel)))

    @property
    def pga_g(self) -> float:
        """Peak ground acceleration in units of standard gravity [g]."""
        return self.pga / G

    @functools.cached_property
    def pgv(self) -> float:
        """Peak ground velocity, ``max |v|`` [m/s], from :meth:`velocity` (computed once:
        the record is read-only)."""
        return float(np.max(np.abs(self.velocity())))

    @property
    def pgd(self) -> float:
        """Peak ground displacement, ``max |u|`` [m], from :meth:`displacement`.

        With no baseline correction this drifts for most recorded motions; use it as an
        indication only.
        """
        return float(np.max(np.abs(self.displacement())))

    def velocity(self) -> FloatArray:
        """Ground velocity [m/s] at :attr:`time`, by the trapezoidal rule from ``v(0) = 0``.

        No baseline correction or filtering is applied.
        """
        return _cumtrapz(self.accel, self.dt)

    def displacement(self) -> FloatArray:
        """Ground displacement [m] at :attr:`time`: :meth:`velocity` integrated likewise."""
        return _cumtrapz(self.velocity(), self.dt)

    def arias_time(self, fraction: float) -> float:
        """The time [s] by which the record has built ``fraction`` (0–1) of its Arias
        intensity: where the Husid curve ``∫₀ᵗ a² dt / ∫₀ᵀ a² dt`` (the trapezoidal rule on
        the samples, linear between them) first reaches ``fraction``. ``arias_time(0.95) −
        arias_time(0.05)`` is the significant duration D5-95 (Trifunac & Brady 1975). 0 for
        a record of zeros."""
        if not 0.0 <= fraction <= 1.0:
            raise ValueError(f"fraction: must be within [0, 1] (got {fraction!r})")
        husid = _cumtrapz(self.accel * self.accel, self.dt)
        if husid[-1] <= 0.0:
            return 0.0
        return float(np.interp(fraction * husid[-1], husid, self.time))

    # ------------------------------------------------------------------ evaluation
    @overload
    def accel_at(self, t: float) -> float: ...

    @overload
    def accel_at(self, t: ArrayLike) -> FloatArray | float: ...

    def accel_at(self, t: ArrayLike) -> FloatArray | float:
        """Ground acceleration [m/s²] at time(s) ``t`` [s], by linear interpolation.

        The ground is at rest outside the record: the result is 0 for ``t < 0`` and for
        ``t > duration``.

        Parameters
        ----------
        t : float or array_like
            Time(s) [s].

        Returns
        -------
        float or ndarray
            A float for a scalar ``t``, else an array of the same shape.
        """
        tt = np.asarray(t, dtype=np.float64)
        x = tt / self.dt
        out = np.interp(x, np.arange(self.npts, dtype=np.float64), self.accel,
                        left=0.0, right=0.0)
        return float(out) if out.ndim == 0 else out

    # ------------------------------------------------------------------ new records
    def scaled(self, factor: float) -> GroundMotion:
        """Return this record with every acceleration multiplied by ``factor`` [-].

        Raises
        ------
        ValueError
            If ``factor`` is not finite, or takes an acceleration beyond the largest float.
        """
        f = finite("scale factor", factor)
        with np.errstate(over="ignore"):
            accel = self.accel * f
        bad = ~np.isfinite(accel)
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(f"ground motion {self.name!r}: scale factor {f:g} takes accel[{i}] "
                             f"= {self.accel[i]:g} m/s2 beyond the largest float "
                             f"({sys.float_info.max:.3g})")
        return dataclasses.replace(self, accel=accel,
                                   metadata={**self.metadata,
                                             "scale_factor": self.metadata.get(
                                                 "scale_factor", 1.0) * f})

    def scaled_to_pga(self, pga_g: float) -> GroundMotion:
        """Return this record scaled so that its PGA is ``pga_g`` [g].

        Raises
        ------
        ValueError
            If ``pga_g`` is not > 0, the record is all zeros, or the scale factor is beyond
            the largest float.
        """
        target = positive("pga_g", pga_g)
        if self.pga == 0.0:
            raise ValueError(f"ground motion {self.name!r}: cannot scale to pga_g={target:g}: "
                             "the record is all zeros")
        factor = target * G / self.pga
        if not math.isfinite(factor):
            raise ValueError(f"ground motion {self.name!r}: cannot scale to pga_g={target:g}: "
                             f"the scale factor {target:g} g / {self.pga_g:g} g is beyond the "
                             f"largest float ({sys.float_info.max:.3g})")
        return self.scaled(factor)

    def trimmed(self, t_end: float) -> GroundMotion:
        """Return the samples at times ``t <= t_end`` [s] (at least the first one)."""
        te = non_negative("t_end", t_end)
        n = min(self.npts, int(math.floor(te / self.dt * (1.0 + 1e-12) + 1e-9)) + 1)
        return dataclasses.replace(self, accel=self.accel[:n])


def _cumtrapz(y: FloatArray, dt: float) -> FloatArray:
    out = np.zeros_like(y, dtype=np.float64)
    if y.size > 1:
        out[1:] = np.cumsum(0.5 * dt * (y[1:] + y[:-1]))
    return out
