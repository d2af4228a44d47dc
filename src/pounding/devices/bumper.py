"""Bumpers: elastomeric pads fixed in the gap where two floors would strike.

A pad of thickness ``t`` fixed to one of the two floors of a contact meets the other floor
when the gap ``g`` has closed by ``g − t``; it is then compressed by ``δ_r = δ_bare + t``
(``δ_bare`` the penetration of the bare gap) under its own law, the *rubber* contact law.
Once compressed by ``r t`` (``r`` the compression limit) it has bottomed out: the floors
strike through the squeezed pad with the building's own contact law, acting on
``δ_r − r t``. The two act in parallel, as two contact elements of the same two points:

* ``<contact>/bumper``: gap ``g − t``, the rubber law;
* ``<contact>``: gap ``g − t + r t``, the building law (the bare contact, moved).

This is the structure of Polycarpou, Komodromos & Polycarpou (2013), "A nonlinear impact
model for simulating the use of rubber shock absorbers for mitigating the effects of
structural pounding during earthquakes", Earthquake Engng Struct. Dyn. 42,
doi:10.1002/eqe.2194: a nonlinear rubber law while the pad is compressed, with the pad's
limited thickness taken into account. Their own law and constants were not available to
this project; the rubber law here is any of the contact laws (e.g. a Hertz-damp or
Jankowski law with the pad's stiffness and restitution), and its constants, the thickness
and the compression limit are the user's (docs/mitigation.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from pounding.devices.link import _FLOOR, parse_floor

if TYPE_CHECKING:
    from pounding.contact.base import ContactLaw
    from pounding.contact.geometry import Contact
    from pounding.contact.spec import ContactSpec

__all__ = ["BUMPER_TAG", "Bumper", "split_contact"]

BUMPER_TAG = "bumper"
"""Suffix of a bumper's contact element in labels: ``B1F3-B2F3/bumper``."""


@dataclass(frozen=True)
class Bumper:
    """An elastomeric pad in the gap of one contact.

    Parameters
    ----------
    floors : (str, str)
        The contact's two floors, e.g. ``("B1F3", "B2F3")`` (which floor carries the pad does
        not change the motion); or a floor and a wall's name, ``("A1", "B1F1")``: a pad on
        the wall (a bridge's backwall) where that floor strikes it.
    thickness : float
        Pad thickness t [m], at most the gap.
    compression_limit : float
        Fraction r of the thickness by which the pad can be compressed before it bottoms
        out, 0 < r < 1.
    rubber : ContactSpec
        The pad's contact law (its stiffness and damping, or restitution).
    """

    floors: tuple[str, str]
    thickness: float
    compression_limit: float
    rubber: "ContactSpec"

    def __post_init__(self) -> None:
        if not isinstance(self.floors, (tuple, list)) or len(self.floors) != 2:
            raise ValueError(f"floors: give the contact's two floor labels, e.g. "
                             f"['B1F3', 'B2F3'] (got {self.floors!r})")
        texts = [str(f).strip() for f in self.floors]
        walls = [t for t in texts if _FLOOR.match(t.upper()) is None]
        if len(walls) == 2 or "" in walls:
            raise ValueError(f"floors: give two floor labels like 'B1F3' (building and floor "
                             f"numbers from 1), or a floor and a wall's name like ['A1', "
                             f"'B1F1'] (got {self.floors!r})")
        if walls:  # a floor and a wall, in the order given
            object.__setattr__(self, "floors", tuple(t if t in walls else t.upper()
                                                     for t in texts))
        else:
            ends = sorted((parse_floor(f), str(f).strip().upper()) for f in self.floors)
            object.__setattr__(self, "floors", (ends[0][1], ends[1][1]))
        if not (math.isfinite(self.thickness) and self.thickness > 0):
            raise ValueError(f"thickness: must be finite and > 0 [m] (got {self.thickness!r})")
        if not (math.isfinite(self.compression_limit) and 0 < self.compression_limit < 1):
            raise ValueError(f"compression_limit: must be between 0 and 1 (a fraction of the "
                             f"thickness; got {self.compression_limit!r})")

    @property
    def label(self) -> str:
        """The contact it sits in: ``"B1F3-B2F3"`` (``"A1-B1F1"``: on wall A1)."""
        return f"{self.floors[0]}-{self.floors[1]}"

    def sits_in(self, contact: Contact) -> bool:
        """Whether this pad sits in ``contact``: its two ends are the contact's two points
        (floors, or a floor and a wall), in either order."""
        return {contact.left.label(), contact.right.label()} == set(self.floors)

    @property
    def bottoming(self) -> float:
        """Compression at which the pad bottoms out, ``r t`` [m]."""
        return self.compression_limit * self.thickness

    def gaps(self, gap: float) -> tuple[float, float]:
        """``(pad gap, building gap)`` [m] of a contact whose bare gap is ``gap``."""
        if self.thickness > gap + 1e-12:
            raise ValueError(f"thickness: the {self.label} bumper ({self.thickness:g} m) is "
                             f"thicker than its gap ({gap:g} m)")
        pad = max(gap - self.thickness, 0.0)
        return pad, pad + self.bottoming

    def describe(self) -> str:
        """One line with the exact values."""
        return (f"Bumper(floors={self.floors!r}, thickness={self.thickness!r}, "
                f"compression_limit={self.compression_limit!r}, rubber={self.rubber!r})")

    def readable(self) -> str:
        """One line for people."""
        return (f"bumper in {self.label}: {self.thickness * 1e3:.3g} mm pad, bottoms out at "
                f"{self.compression_limit:.0%} compression; rubber {self.rubber.describe()}")


def split_contact(contact: Contact, bumper: Bumper, rubber_law: ContactLaw,
                  index: int) -> list[Contact]:
    """The two contact elements that replace ``contact`` when ``bumper`` sits in it: the pad
    (``/bumper``, index ``index``, with ``rubber_law``) and the building contact moved to
    where the pad bottoms out (index ``index + 1``)."""
    pad_gap, building_gap = bumper.gaps(contact.gap)
    return [replace(contact, index=index, gap=pad_gap, law=rubber_law, tag=BUMPER_TAG),
            replace(contact, index=index + 1, gap=building_gap)]
