"""Moat walls: the retaining wall around a base-isolated building, as a neighbour in the row.

A base-isolated building needs a clear gap around its base slab, the *moat*, bounded by a
retaining wall; an isolator displacement larger than the gap makes the base slab strike the
wall (Tsai 1997, EESD 26:1017; Malhotra 1997, "Dynamics of seismic impacts in base-isolated
buildings", EESD 26:797–813; Komodromos, Polycarpou, Papaloizou & Phocas 2007, "Response
of seismically isolated buildings considering poundings", EESD 36:1605–1622; Polycarpou &
Komodromos 2010, EESD 39:933–940; Masroor & Mosqueda 2013, MCEER-13-0003).

Two idealisations are in use and both are here:

* **Rigid wall** (:class:`MoatWall`): fixed to the ground, it does not move; the contact law
  alone carries the local flexibility of the impact (Komodromos et al. 2007 model the moat
  wall this way, the impact stiffness standing for the wall's and the slab's local
  deformation). A contact with it has weights on the building's side only
  (:meth:`pounding.model.PoundingModel.contact_kinematics`: the wall's slots carry weight 0),
  and the law is built with the building point's mass against an infinite one
  (``m_eff = m``). It stands at either end of the row of buildings: left of the first
  (``side = "left"``) or right of the last (``side = "right"``), or one at each end.
* **Flexible wall** (:func:`flexible_wall`): the wall and its backfill as a one-degree-of-
  freedom oscillator (a mass on a lateral spring, Masroor & Mosqueda 2013 give the wall's
  flexural stiffness and the backfill's passive resistance; here both are lumped into one
  linear stiffness). It is a one-storey :class:`pounding.structure.ShearBuilding` of the
  wall's height placed in the row like any neighbour, with the gap among the model's
  ``gaps``: the building's floors below its top strike its "column" at ``ξ = z / H``
  (a wall deflecting linearly up its height), a floor level with its top strikes its top.

A rigid wall may carry a contact law of its own (``MoatWall(contact=ContactSpec(...))``),
used for its contacts only; without one its contacts follow the model's. An abutment is
such a wall: its backwall across the gap from the deck's end, its backfill's passive
resistance the law (``ContactSpec("abutment", ...)``,
:class:`pounding.contact.abutment.AbutmentBackfill`). The abutment's piles stand in
parallel with the backfill behind the same gap (``MoatWall(piles=ContactSpec(...))``): a
second contact at each of the wall's points with the piles' own law, tagged ``piles``
(labels ``'B2F1-A2/piles'``), so the pile group's force is an output of its own.

Which floors strike a wall: every floor of the neighbouring building at or below the wall's
top (within the model's ``level_tolerance``), typically only the base slab; with
``floor_to_column`` the top edge of a wall that stops between two floors also strikes the
building's column there.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.contact.geometry import Contact, ContactPoint
from pounding.contact.spec import ContactSpec
from pounding.structure.assembly import Building, face_below, face_dofs, face_point_name
from pounding.structure.shear_building import ShearBuilding
from pounding.validation import choice, non_negative, positive

__all__ = ["MoatWall", "WallPoint", "check_walls", "flexible_wall", "wall_contacts", "wall_points"]

SIDES = ("left", "right")


@dataclass(frozen=True)
class MoatWall:
    """A rigid wall fixed to the ground at one end of the row of buildings.

    Parameters
    ----------
    height : float
        Elevation of the wall's top above the ground [m].
    gap : float
        Clear gap between the wall and the building next to it, at rest [m].
    side : {"right", "left"}
        Right of the last building (default) or left of the first.
    name : str
        Label of the wall in contact labels (``'B1F1-W'``, ``'W-B1F1'``).
    contact : ContactSpec, optional
        The contact law of this wall's contacts (an abutment's backfill:
        ``ContactSpec("abutment", ...)``); None (default): the model's.
    piles : ContactSpec, optional
        A law in parallel behind the same gap (an abutment's piles: a ``linear-spring`` of
        the pile group's stiffness, or a ``shear-key`` without fracture for piles that
        yield), as contacts of their own tagged ``piles``; None (default): none.

    Examples
    --------
    >>> MoatWall(height=1.0, gap=0.15)
    MoatWall(height=1.0, gap=0.15, side='right', name='W', contact=None, piles=None)
    """

    height: float
    gap: float
    side: str = "right"
    name: str = "W"
    contact: ContactSpec | None = None
    piles: ContactSpec | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "height", positive("height", self.height))
        object.__setattr__(self, "gap", non_negative("gap", self.gap))
        object.__setattr__(self, "side", choice("side", self.side, SIDES))
        if not isinstance(self.name, str) or not self.name:
            raise ValueError(f"name: the wall needs a non-empty label (got {self.name!r})")
        for key in ("contact", "piles"):
            value = getattr(self, key)
            if value is not None and not isinstance(value, ContactSpec):
                raise ValueError(f"{key}: expected a ContactSpec or None (got "
                                 f"{type(value).__name__})")


@dataclass(frozen=True)
class WallPoint(ContactPoint):
    """The wall's side of a contact: no degree of freedom (it moves with the ground).

    ``building`` and ``upper`` are −1 (no building, no floor); a floor-like point
    (``ξ = 1``), so a contact with a wall has no struck column on the wall's side.
    """

    building: int = -1
    upper: int = -1
    xi: float = 1.0
    name: str = "W"

    def floor_weights(self) -> list[tuple[int, float]]:
        """None: the wall does not move relative to the ground."""
        return []

    def of(self, floors: NDArray[np.float64]) -> NDArray[np.float64]:
        """Zero, shaped like one floor's values."""
        return np.zeros_like(floors[..., 0])

    def effective_mass(self, masses: NDArray[np.float64]) -> float:
        """Infinite: a rigid wall fixed to the ground."""
        return math.inf

    def label(self) -> str:
        return self.name


def wall_points(wall: MoatWall, building: Building, index: int, floor_to_column: bool,
                tol: float) -> list[tuple[float, ContactPoint]]:
    """``(elevation, point)`` of the building (``index``) that strike ``wall``, bottom up:
    the DOFs of its face toward the wall (its floors, or a matrix building's
    :attr:`~pounding.structure.MatrixBuilding.faces`: a frame's outer column line) at or
    below the wall's top, then (``floor_to_column``) the face between two of them at the
    wall's top if that lies below the highest."""
    side = wall.side  # (the building's face toward the wall: its left face for a left wall)
    f = face_dofs(building, side)
    below = face_below(building, side)
    z = building.floor_levels[f]

    def point(k: int, xi: float, at: float) -> ContactPoint:
        return ContactPoint(index, int(f[k]), xi, int(below[f[k]]),
                            name=face_point_name(index, building, side, at, tol))

    out = [(float(z[k]), point(k, 1.0, float(z[k]))) for k in range(f.size)
           if z[k] <= wall.height + tol]
    level = np.abs(z - wall.height) <= tol
    if floor_to_column and not level.any() and wall.height < z[-1] - tol:
        k = int(np.searchsorted(z, wall.height))
        low = float(z[k - 1]) if k > 0 else 0.0
        out.append((wall.height, point(k, (wall.height - low) / (float(z[k]) - low),
                                       wall.height)))
    return sorted(out, key=lambda r: r[0])


def _neighbour(i: int, wall: MoatWall, buildings: Sequence[Building]
               ) -> tuple[int, Building]:
    """The index in the row and the building beside ``walls[i]``: a shear building or a
    planar matrix building (a frame among them); one line naming the wall for a building in
    plan."""
    b = 0 if wall.side == "left" else len(buildings) - 1
    building = buildings[b]
    if getattr(building, "plan", None) is not None:
        raise ValueError(f"walls[{i}]: a moat wall stands beside a planar building; B{b + 1} "
                         f"is a {type(building).__name__} in plan (not supported yet)")
    return b, building


def wall_contacts(walls: Sequence[MoatWall], buildings: Sequence[Building],
                  contact: ContactSpec, floor_to_column: bool, tol: float,
                  start: int) -> tuple[Contact, ...]:
    """The contacts of every wall (in the order of ``walls``) with the end building of the
    row ``buildings`` beside it, numbered from ``start``; the building on the left of a
    contact is the left point. ``contact`` builds each contact's law, unless the wall has a
    law of its own (:attr:`MoatWall.contact`), and after each contact the wall's piles' own
    (:attr:`MoatWall.piles`, tagged ``piles``); ``floor_to_column``
    and ``tol`` [m] are the model's (:class:`pounding.model.PoundingModel`). The building
    beside a wall is planar (a ``ValueError`` naming the wall otherwise, as
    :func:`check_walls`)."""
    out: list[Contact] = []
    last = len(buildings) - 1
    for i, wall in enumerate(walls):
        b, building = _neighbour(i, wall, buildings)
        wp = WallPoint(name=wall.name)
        spec = contact if wall.contact is None else wall.contact
        for z, point in wall_points(wall, building, b, floor_to_column, tol):
            m = point.effective_mass(building.masses)
            left, right = (wp, point) if wall.side == "left" else (point, wp)
            pair = -1 if wall.side == "left" else last
            out.append(Contact(start + len(out), pair, left, right, z, wall.gap,
                               spec.build(m, math.inf)))
            if wall.piles is not None:  # (in parallel behind the same gap)
                out.append(Contact(start + len(out), pair, left, right, z, wall.gap,
                                   wall.piles.build(m, math.inf), tag="piles"))
    return tuple(out)


def check_walls(walls: Sequence[MoatWall], buildings: Sequence[Building],
                floor_to_column: bool, tol: float) -> None:
    """At most one wall a side, and every wall has a floor of its neighbour in the row
    ``buildings`` at or below its top (within ``tol`` [m]); one line naming the wall
    otherwise."""
    seen: set[str] = set()
    for i, wall in enumerate(walls):
        if not isinstance(wall, MoatWall):
            raise ValueError(f"walls[{i}]: expected a MoatWall (got {type(wall).__name__})")
        if wall.side in seen:
            raise ValueError(f"walls[{i}]: a second wall on the {wall.side} of the row")
        seen.add(wall.side)
        b, building = _neighbour(i, wall, buildings)
        if not wall_points(wall, building, b, floor_to_column, tol):
            lowest = float(np.min(building.floor_levels[face_dofs(building, wall.side)]))
            raise ValueError(f"walls[{i}]: no floor of B{b + 1} at or below the wall's top "
                             f"({wall.height:g} m; lowest floor at {lowest:g} m), so it can "
                             "never strike it")


def flexible_wall(height: float, stiffness: float, mass: float, damping_ratio: float = 0.05,
                  name: str = "wall") -> ShearBuilding:
    """A flexible moat wall: a one-storey neighbour of lateral stiffness and mass.

    Parameters
    ----------
    height : float
        Height of the wall's top [m] (the elevation of its mass).
    stiffness : float
        Lateral stiffness of wall and backfill at its top [N/m].
    mass : float
        Participating mass [kg].
    damping_ratio : float
        Viscous damping ratio of the wall's mode (default 5 %).
    name : str
        Label (``'wall'``).

    Returns
    -------
    ShearBuilding
        Put it in the row with the gap among the model's ``gaps``.
    """
    return ShearBuilding.sdof(mass, stiffness=stiffness, height=height,
                              damping_ratio=damping_ratio, name=name)

