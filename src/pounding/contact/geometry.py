"""Where neighbouring buildings meet: contact points on floors and columns, and the contact
elements between them (see :mod:`pounding.model` for the geometry; which floors meet is
:func:`pounding.structure.assembly.contact_points`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from pounding.contact.base import ContactLaw

__all__ = ["Contact", "ContactPoint"]


MOVING_BASE = -3
"""``ContactPoint.lower`` of the lowest storey of a building on a flexible base whose foot
the kinematics cannot follow (a massless footing, or an embedded one): a floor there is a
contact point, a column point between it and the ground is refused."""


@dataclass(frozen=True)
class ContactPoint:
    """Where a contact element meets one building: a floor slab, or a column between floors.

    The contact point moves with ``(1 − ξ) u_lower + ξ u_upper`` (linear interpolation
    between the two floors of the struck storey, ``u = 0`` for the ground), and the contact
    force ``F`` is shared back to those floors as ``(1 − ξ) F`` and ``ξ F``: the same
    weights, so the work the force does on the building equals ``F`` times the point's
    displacement (energy-consistent, virtual work) and the shares sum to ``F`` (equal and
    opposite to the force on the other building). A floor contact is ``ξ = 1`` at its floor.

    Attributes
    ----------
    building : int
        0-based building index.
    upper : int
        0-based DOF of the floor struck (a floor contact) or of the floor above the struck
        storey (a column contact).
    xi : float
        Position of the point in storey ``upper + 1``: 0 at the floor below, 1 at floor
        ``upper``. Exactly 1 for a floor contact.
    lower : int, optional
        0-based DOF of the floor below the struck storey (−1: the ground); default
        ``upper − 1``, as in a shear building (a matrix building's floor below may be
        another DOF: :func:`pounding.structure.assembly.floor_below`).
    twist : (int, float), optional
        For a point of a floor in plan (:mod:`pounding.structure.plan`), away from the
        floor's centre of mass: the floor's rotation DOF and the lever weight
        ``−(y − y_c)`` with which the rotation moves the point along x (rigid-floor
        kinematics), so that the point moves with ``u_upper − (y − y_c) θ``.
    name : str, optional
        The point's label, where :meth:`label` cannot make it from the DOF (a point of a
        floor in plan: ``'B2F3@y=6'``).
    """

    building: int
    upper: int
    xi: float = 1.0
    lower: int = None  # type: ignore[assignment]  # upper − 1 unless given
    twist: tuple[int, float] | None = None
    name: str = ""

    def __post_init__(self) -> None:
        if self.lower is None:
            object.__setattr__(self, "lower", self.upper - 1)
        if self.lower == MOVING_BASE and self.xi != 1.0:
            raise ValueError(
                f"contact point at ξ = {self.xi:.3g} of storey {self.upper + 1} of building "
                f"{self.building + 1}: the foot of that storey moves with a footing the "
                "contact cannot follow (a massless footing, condensed out, or an embedded one, "
                "rocking about its base below the ground): a floor-to-column contact in the "
                "ground storey of a building on a flexible base needs a surface footing with "
                "mass (its sway a DOF), or floor_to_column = false")

    @property
    def is_floor(self) -> bool:
        """True for a slab (floor) contact point, False for a point on a column."""
        return self.xi == 1.0

    @property
    def storey(self) -> int:
        """1-based number of the storey the point lies in (or below, for a floor)."""
        return self.upper + 1

    def floor_weights(self) -> list[tuple[int, float]]:
        """``(floor index, weight)`` pairs that make the point's displacement (ground
        omitted); weights of a column point are ``1 − ξ`` and ``ξ``; a point of a floor in
        plan adds its floor's rotation (:attr:`twist`)."""
        if self.is_floor:
            return [(self.upper, 1.0)] if self.twist is None else [(self.upper, 1.0), self.twist]
        out = [(self.upper, self.xi)]
        if self.lower >= 0:
            out.insert(0, (self.lower, 1.0 - self.xi))
        return out

    def of(self, floors: NDArray[np.float64]) -> NDArray[np.float64]:
        """The point's value from per-floor values of its building, ``floors[..., floor]``."""
        return sum((w * floors[..., i] for i, w in self.floor_weights()),
                   np.zeros(floors.shape[:-1]))

    def effective_mass(self, masses: NDArray[np.float64]) -> float:
        """Apparent mass at the point [kg]: ``1 / Σ w_i² / m_i`` (the mass a short impulse
        at the point meets, the floors being the only masses); the floor mass for a slab."""
        return 1.0 / sum(w * w / float(masses[i]) for i, w in self.floor_weights())

    def label(self) -> str:
        """``'B2F3'`` for a floor, ``'B2S3@0.40'`` for storey 3's column at 40 % of its
        height (1-based building, floor and storey numbers); :attr:`name` where given."""
        if self.name:
            return self.name
        if self.is_floor:
            return f"B{self.building + 1}F{self.upper + 1}"
        return f"B{self.building + 1}S{self.storey}@{self.xi:.2f}"


@dataclass(frozen=True)
class Contact:
    """One contact element between two neighbouring buildings.

    Floor to floor where both have a floor at the same elevation (seed case 2A); floor to
    column where a slab of one lies between two floors of the other (case 2B with floors
    that do not line up): the slab strikes the other building's column.

    Attributes
    ----------
    index : int
        Position in :attr:`PoundingModel.contacts`.
    pair : int
        Which gap: between building ``pair`` and ``pair + 1``.
    left, right : ContactPoint
        Where the element meets the left and the right building.
    elevation : float
        Height of the contact above ground [m].
    gap : float
        Separation gap at rest [m].
    law : ContactLaw
        The contact law, built with the apparent masses of the two contact points.
    tag : str
        ``""`` for the contact of the buildings; ``"bumper"`` for the pad of a bumper in its
        gap (:class:`pounding.devices.Bumper`), whose label ends in ``/bumper``.
    """

    index: int
    pair: int
    left: ContactPoint
    right: ContactPoint
    elevation: float
    gap: float
    law: ContactLaw
    tag: str = ""

    @property
    def is_floor_to_floor(self) -> bool:
        """True if both points are floor slabs."""
        return self.left.is_floor and self.right.is_floor

    @property
    def on_wall(self) -> bool:
        """True for a contact with a moat wall (:mod:`pounding.structure.wall`): one side
        belongs to no building."""
        return self.left.building < 0 or self.right.building < 0

    @property
    def struck(self) -> ContactPoint | None:
        """The column point of a floor-to-column contact (None for floor to floor)."""
        if self.is_floor_to_floor:
            return None
        return self.right if self.left.is_floor else self.left

    @property
    def left_floor(self) -> int:
        """0-based floor index of the left point (the floor above, for a column point)."""
        return self.left.upper

    @property
    def right_floor(self) -> int:
        """0-based floor index of the right point (the floor above, for a column point)."""
        return self.right.upper

    @property
    def label(self) -> str:
        """Readable name, e.g. ``'B1F3-B2F3'``, ``'B1F2-B2S3@0.40'`` or, for a bumper's
        pad, ``'B1F3-B2F3/bumper'``."""
        base = f"{self.left.label()}-{self.right.label()}"
        return f"{base}/{self.tag}" if self.tag else base
