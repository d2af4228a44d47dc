"""Spatially varying ground motion: each building of the row on its own ground.

Two buildings 30 m apart do not feel the same motion: the seismic waves reach them at
different times (wave passage) and lose coherence on the way (incoherence). A
:class:`SpatialMotion` gives each building of the row its own record. It *is* the record of
the first building (a :class:`~pounding.ground_motion.GroundMotion`: its name, peaks and
samples are those of building 1's ground, so everything that reads one record reads it),
and it carries every building's record in :attr:`SpatialMotion.records`.

Under it each building moves relative to its own ground, and a contact between buildings
on different grounds sees their grounds' relative displacement:
``δ = (u_left + u_g,left) − (u_right + u_g,right) − gap`` with ``u_g`` the double integral
of each ground's acceleration — exactly, for records linear between their samples
(:func:`pounding.integrate.simulate`).

The rigid walls at the ends of the row (moat walls, a bridge's abutments) stand on their
building's ground unless the motion gives them their own (:attr:`SpatialMotion.walls`, by
side): an abutment 60 m from the first pier feels the waves at its own time, and the backwall
contact sees ``δ = u_g,wall − (u_1 + u_g,1) − gap`` on the left,
``(u_n + u_g,n) − u_g,wall − gap`` on the right.

* :func:`delayed` — a record arriving ``τ`` later: exact (a shift by whole samples) when
  ``τ`` is a multiple of the step, the record's linear interpolant sampled at ``t − τ``
  otherwise;
* :func:`wave_passage` — one record reaching each building after a delay from its position
  along the row and an apparent velocity (Der Kiureghian 1996's wave-passage term;
  the incoherence term is :mod:`pounding.ground_motion.coherency`'s).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from types import MappingProxyType

import numpy as np
from numpy.typing import ArrayLike

from pounding.ground_motion.components import records_of_one_step
from pounding.ground_motion.motion import GroundMotion
from pounding.validation import finite, non_negative

__all__ = ["SpatialMotion", "delayed", "wave_passage"]

EXACT_SHIFT_TOL = 1e-9
"""A delay within this fraction of a step of a whole number of steps is that whole number
(a shift by samples, exact)."""


class SpatialMotion(GroundMotion):
    """One ground-motion record per building of the row (module docstring).

    Parameters
    ----------
    records : sequence of GroundMotion
        The record under each building, left to right (at least one), all with the same
        step; shorter records are continued with zeros to the longest.
    name : str, optional
        Default: the first record's name with ``" (spatially varying)"``.
    description : str
        How the records were made (a delay, a coherency model …), for the outputs.
    delays : sequence of float, optional
        Each building's delay [s] (for the outputs; default 0).
    walls : mapping, optional
        The ground of the row's end walls by side (``"left"``, ``"right"``): a wall not
        given stands on its building's ground.
    wall_delays : mapping, optional
        Their delays [s] (for the outputs; default 0).

    Raises
    ------
    ValueError
        If there is no record or the steps differ (one line naming the record), or a wall's
        side is not left or right.

    Examples
    --------
    >>> from pounding.ground_motion import GroundMotion
    >>> a = GroundMotion(0.01, [0.0, 1.0, 0.0])
    >>> s = wave_passage(a, positions=[0.0, 30.0], apparent_velocity=1500.0)
    >>> [round(float(t), 6) for t in s.delays]
    [0.0, 0.02]
    >>> s.records[1].accel.tolist()
    [0.0, 0.0, 0.0, 1.0, 0.0]
    """

    records: tuple[GroundMotion, ...]
    description: str
    delays: tuple[float, ...]
    walls: Mapping[str, GroundMotion]
    wall_delays: Mapping[str, float]

    def __init__(self, records: Sequence[GroundMotion], name: str | None = None,
                 description: str = "", delays: Sequence[float] | None = None,
                 walls: Mapping[str, GroundMotion] | None = None,
                 wall_delays: Mapping[str, float] | None = None) -> None:
        sides = [side for side in ("left", "right") if walls and side in walls]
        for side in walls or {}:
            if side not in ("left", "right"):
                raise ValueError(f"walls: a wall's side is 'left' or 'right' (got {side!r})")
        recs = records_of_one_step(
            [*records, *(walls[s] for s in sides)] if walls else records,
            "spatial motion (one record per building)", "record")
        n = max(r.npts for r in recs)
        padded = tuple(r if r.npts == n else GroundMotion(
            r.dt, np.concatenate([r.accel, np.zeros(n - r.npts)]), r.name, r.source,
            r.units_read, r.metadata) for r in recs)
        first = padded[0]
        super().__init__(first.dt, first.accel,
                         name if name is not None else f"{first.name} (spatially varying)",
                         first.source, first.units_read, first.metadata)
        nb = len(padded) - len(sides)
        frozen_set = object.__setattr__
        frozen_set(self, "records", padded[:nb])
        frozen_set(self, "description", description)
        frozen_set(self, "delays", tuple(float(d) for d in delays) if delays is not None
                   else (0.0,) * nb)
        frozen_set(self, "walls", MappingProxyType(dict(zip(sides, padded[nb:]))))
        frozen_set(self, "wall_delays", MappingProxyType(
            {s: float((wall_delays or {}).get(s, 0.0)) for s in sides}))

    def _like(self, records: Sequence[GroundMotion], walls: Mapping[str, GroundMotion],
              name: str) -> SpatialMotion:
        return SpatialMotion(records, name, self.description, self.delays, walls,
                             self.wall_delays)

    def stations(self) -> tuple[list[int], list[GroundMotion]]:
        """``(station of each building, the stations' records)``: buildings whose records
        are equal (same samples) share a station, numbered in order of first appearance;
        then the walls' (:meth:`wall_stations`)."""
        index, distinct = self._stations()
        return index[:len(self.records)], distinct

    def wall_stations(self) -> dict[str, int]:
        """The station of each wall with a ground of its own, by side (numbered with the
        buildings', :meth:`stations`)."""
        index, _ = self._stations()
        return dict(zip(self.walls, index[len(self.records):]))

    def _stations(self) -> tuple[list[int], list[GroundMotion]]:
        index: list[int] = []
        distinct: list[GroundMotion] = []
        for r in (*self.records, *self.walls.values()):
            for s, d in enumerate(distinct):
                if d is r or np.array_equal(d.accel, r.accel):
                    index.append(s)
                    break
            else:
                index.append(len(distinct))
                distinct.append(r)
        return index, distinct

    def scaled(self, factor: float) -> SpatialMotion:
        """Every building's (and wall's) record multiplied by ``factor``."""
        return self._like([r.scaled(factor) for r in self.records],
                          {s: r.scaled(factor) for s, r in self.walls.items()},
                          f"{self.name} x {factor:g}")

    def scaled_to_pga(self, pga_g: float) -> SpatialMotion:
        """Every record scaled by the factor that brings the first to ``pga_g`` [g]."""
        return self.scaled(pga_g / self.pga_g)

    def trimmed(self, t_end: float) -> SpatialMotion:
        """Every record cut after ``t_end`` [s]."""
        return self._like([r.trimmed(t_end) for r in self.records],
                          {s: r.trimmed(t_end) for s, r in self.walls.items()}, self.name)

    def with_walls(self, sides: Sequence[str]) -> SpatialMotion:
        """The last ``len(sides)`` records taken as the grounds of the walls on ``sides``
        (a motion made for the buildings' positions followed by the walls')."""
        nb = len(self.records) - len(sides)
        if nb < 1:
            raise ValueError(f"walls: {len(sides)} wall(s) and {len(self.records)} records "
                             "leave no building")
        return SpatialMotion(self.records[:nb], self.name, self.description, self.delays[:nb],
                             dict(zip(sides, self.records[nb:])),
                             dict(zip(sides, self.delays[nb:])))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, SpatialMotion):
            return NotImplemented
        mine = (*self.records, *self.walls.values())
        theirs = (*other.records, *other.walls.values())
        return (len(self.records) == len(other.records) and list(self.walls) == list(other.walls)
                and all(a.dt == b.dt and np.array_equal(a.accel, b.accel)
                        for a, b in zip(mine, theirs)))

    __hash__ = object.__hash__  # (records are read-only; identity, as GroundMotion)


def delayed(motion: GroundMotion, delay: float) -> GroundMotion:
    """``motion`` arriving ``delay`` [s] later: ``a(t − τ)``, zero before ``τ``; as long
    as the record plus the delay. A delay of a whole number of steps (within
    :data:`EXACT_SHIFT_TOL` of a step) shifts the samples, exactly; any other delay samples
    the record's linear interpolant at ``t − τ`` (as the time stepper reads the record:
    back to zero one step after its last sample) — the new record's own interpolant then
    differs from the shifted one by the interpolation error, O((ω dt)²). (A record whose
    first sample is not zero jumps to it at t = 0; delayed, it ramps to it over the step
    before.)

    Examples
    --------
    >>> delayed(GroundMotion(0.01, [1.0, 2.0]), 0.02).accel.tolist()
    [0.0, 0.0, 1.0, 2.0]
    >>> delayed(GroundMotion(0.01, [0.0, 2.0]), 0.005).accel.tolist()
    [0.0, 1.0, 1.0]
    """
    tau = non_negative("delay [s]", finite("delay [s]", delay))
    steps = tau / motion.dt
    whole = round(steps)
    if abs(steps - whole) <= EXACT_SHIFT_TOL:
        accel = np.concatenate([np.zeros(whole), motion.accel])
    else:
        n = motion.npts + math.ceil(steps)
        t = np.arange(n) * motion.dt - tau
        # (the record as the time stepper reads it: back to zero one step after its end)
        t_rec = np.append(motion.time, motion.npts * motion.dt)
        accel = np.interp(t, t_rec, np.append(motion.accel, 0.0), left=0.0, right=0.0)
    return GroundMotion(motion.dt, accel, motion.name, motion.source, motion.units_read,
                        motion.metadata)


def wave_passage(motion: GroundMotion, positions: ArrayLike,
                 apparent_velocity: float) -> SpatialMotion:
    """``motion`` reaching each building of the row after the time the waves take to travel
    there: building ``b`` at position ``x_b`` [m] along the row (its ground's station)
    feels ``a(t − τ_b)``, ``τ_b = (x_b − x_0)/V`` with ``x_0`` where the waves arrive
    first — ``V`` [m/s] the apparent velocity along the row, positive for waves travelling
    toward +x (left to right), negative for the other way.

    Raises
    ------
    ValueError
        If the velocity is zero or not finite, or a position is not finite.
    """
    v = finite("apparent_velocity [m/s]", apparent_velocity)
    if v == 0.0:
        raise ValueError("apparent_velocity [m/s] must not be 0 (waves that never arrive)")
    x = np.asarray(positions, dtype=float)
    if x.ndim != 1 or not np.all(np.isfinite(x)):
        raise ValueError(f"positions [m] must be finite numbers, one a building (got "
                         f"{positions!r})")
    tau = x / v
    tau = tau - tau.min()
    return SpatialMotion([delayed(motion, t) for t in tau], description=(
        f"wave passage: apparent velocity {v:g} m/s, positions "
        f"{', '.join(f'{p:g}' for p in x)} m"), delays=tau)
