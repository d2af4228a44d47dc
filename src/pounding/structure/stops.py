"""Stops: one-sided contacts beside the row's, a floor against the ground or against a
floor of another building, each engaged when the floor moves one given way.

The row of :class:`pounding.model.PoundingModel` makes its contacts from the neighbours'
facing floors (each pair across its gap) and from the moat walls at its ends. A *stop* is a
contact the row does not make: a bridge deck's shear keys in the transverse direction
(:mod:`pounding.structure.bridge.transverse`) — at an abutment, a key on each side of the
deck against the ground; at an in-span joint, a key each way between the two decks, which
slide past each other rather than strike. Each is a :class:`~pounding.contact.geometry.
Contact` with its own gap and law, its penetration

    δ = toward · (u_floor − u_other) − gap        (u_other = 0: the ground)

so that ``toward = +1`` engages as the floor moves in +x (relative to the other), −1 as it
moves in −x. As contacts, stops are in every output of the contacts (labels such as
``'B1F1-A1+y/key'``, ``'A1-y-B1F1/key'``, ``'B1F1-B2F1/key'``, ``'B2F1-B1F1/key'``).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from pounding.contact.geometry import Contact, ContactPoint
from pounding.contact.spec import ContactSpec
from pounding.structure.assembly import Building, floor_below
from pounding.structure.wall import WallPoint
from pounding.validation import non_negative

__all__ = ["Stop", "stop_contacts"]


@dataclass(frozen=True)
class Stop:
    """A one-sided contact of a floor (module docstring).

    Parameters
    ----------
    building, floor : int
        The floor that strikes: 0-based building index in the row and the floor's DOF.
    toward : {+1, −1}
        The way the floor moves to close the gap (relative to the other side).
    gap : float
        Gap at rest [m].
    law : ContactSpec
        The stop's contact law (a shear key's: ``ContactSpec("shear-key", ...)``).
    other : (int, int), optional
        Building and floor DOF on the other side; None: the ground.
    name : str
        The ground side's label (``'A1+y'``) where ``other`` is None.
    tag : str
        The contact's tag (its label ends in ``/tag``; default ``"key"``).
    """

    building: int
    floor: int
    toward: int
    gap: float
    law: ContactSpec
    other: tuple[int, int] | None = None
    name: str = "G"
    tag: str = "key"

    def __post_init__(self) -> None:
        if self.toward not in (1, -1):
            raise ValueError(f"toward: +1 or -1, the way the floor moves to close the gap "
                             f"(got {self.toward!r})")
        non_negative("gap", self.gap)
        if not isinstance(self.law, ContactSpec):
            raise ValueError(f"law: expected a ContactSpec (got {type(self.law).__name__})")
        if self.other is not None and tuple(self.other) == (self.building, self.floor):
            raise ValueError("other: a floor cannot stop against itself")


def _point(buildings: Sequence[Building], b: int, f: int, i: int, what: str) -> ContactPoint:
    if not (0 <= b < len(buildings)) or not (0 <= f < buildings[b].n):
        raise ValueError(f"stops[{i}].{what}: no floor F{f + 1} of building B{b + 1} in this "
                         f"row ({len(buildings)} building(s))")
    below = int(floor_below(buildings[b])[f])
    if below == -2:
        raise ValueError(f"stops[{i}].{what}: DOF {f + 1} of B{b + 1} is not a floor")
    return ContactPoint(b, f, 1.0, below)


def stop_contacts(stops: Sequence[Stop], buildings: Sequence[Building],
                  start: int) -> tuple[Contact, ...]:
    """The contacts of ``stops`` (in their order), numbered from ``start``: the floor is the
    left point for ``toward = +1``, the right one for −1 (δ = left − right − gap); the law
    built with the floor's mass against the other floor's (the ground's: infinite). A
    ``ValueError`` names a stop whose floors are not in ``buildings``."""
    out: list[Contact] = []
    for i, s in enumerate(stops):
        if not isinstance(s, Stop):
            raise ValueError(f"stops[{i}]: expected a Stop (got {type(s).__name__})")
        point = _point(buildings, s.building, s.floor, i, "floor")
        m = point.effective_mass(buildings[s.building].masses)
        pair = -1
        if s.other is None:
            other: ContactPoint = WallPoint(name=s.name)
            m_other = math.inf
        else:
            ob, of = s.other
            other = _point(buildings, ob, of, i, "other")
            m_other = other.effective_mass(buildings[ob].masses)
            pair = min(s.building, ob)
        left, right = (point, other) if s.toward > 0 else (other, point)
        z = float(buildings[s.building].floor_levels[s.floor])
        out.append(Contact(start + len(out), pair, left, right, z, float(s.gap),
                           s.law.build(m, m_other), tag=s.tag))
    return tuple(out)
