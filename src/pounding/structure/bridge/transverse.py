"""A bridge across its axis: decks sway transversely on their piers, held by shear keys.

In the transverse direction the frames of a multi-frame bridge (each deck segment on its
piers through its bearings, :class:`~pounding.structure.bridge.frame.BridgeFrame`, every
number now of the transverse direction: the piers' transverse stiffness — a multi-column
bent's frame action, ``12 EI/H³`` per column fixed at both ends, a single column's
``3 EI/H³`` — and the bearings' transverse laws) do not strike each other: at an expansion
joint the decks slide past each other. What holds them are **shear keys**
(:class:`~pounding.contact.shear_key.ShearKey`: a gap, then stiff up to a capacity, then —
the sacrificial ones — broken off):

* at each **abutment**, an exterior key on each side of the end deck, each a one-sided
  contact against the ground with its gap: ``A1+y`` stops the first deck moving toward
  +y, ``A1-y`` toward −y (``A2±y`` the last deck, at the right abutment);
* optionally at an **in-span joint**, keys between the two decks that stop their relative
  transverse motion either way: two contacts, deck j against deck j + 1 each way.

The model (:meth:`TransverseBridge.model_arguments`): the frames as the row's buildings
with infinite gaps (no deck-to-deck impacts), the keys as stops
(:class:`pounding.structure.stops.Stop`) tagged ``key``: contacts ``'B1F1-A1+y/key'``,
``'A1-y-B1F1/key'``, ``'B1F1-B2F1/key'`` (deck 1 moving +y relative to deck 2) and
``'B2F1-B1F1/key'``. A deck is rigid and does not rotate about the vertical axis, so both
abutments' keys of a one-frame bridge act on its one deck DOF.

Not modelled: the abutment's own transverse flexibility behind its keys (its piles and
wingwalls, in series with the keys: the abutment is rigid here), deck rotation in plan,
skew; and, for now, spatially varying ground in the model file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from pounding.contact.spec import ContactSpec
from pounding.structure.bridge.frame import BridgeFrame
from pounding.structure.stops import Stop
from pounding.validation import non_negative

__all__ = ["ShearKeys", "TransverseBridge"]


@dataclass(frozen=True)
class ShearKeys:
    """A key on each side of a deck (or each way across a joint), both alike.

    Parameters
    ----------
    gap : float
        Clear gap between the deck and each key at rest [m].
    law : ContactSpec
        The keys' law: ``ContactSpec("shear-key", k=…, capacity=…,
        fracture_displacement=…)`` (:class:`pounding.contact.shear_key.ShearKey`).
    """

    gap: float
    law: ContactSpec

    def __post_init__(self) -> None:
        non_negative("gap", self.gap)
        if not isinstance(self.law, ContactSpec):
            raise ValueError(f"law: expected a ContactSpec (got {type(self.law).__name__})")

    @classmethod
    def of(cls, gap: float, k: float, capacity: float,
           fracture_displacement: float | None = None) -> ShearKeys:
        """Keys of stiffness ``k`` [N/m] and ``capacity`` [N] breaking off at
        ``fracture_displacement`` [m] (None: never) behind ``gap`` [m]."""
        return cls(gap, ContactSpec("shear-key", k=k, capacity=capacity,
                                    fracture_displacement=fracture_displacement))


@dataclass(frozen=True)
class TransverseBridge:
    """Frames across the bridge's axis, held by shear keys (module docstring).

    Parameters
    ----------
    frames : sequence of BridgeFrame
        Left to right along the axis (at least one), their piers' and bearings' transverse
        properties.
    abutment_keys : (ShearKeys or None, ShearKeys or None)
        The keys at the left and the right abutment (None: none there).
    joint_keys : sequence of ShearKeys or None
        The keys at each in-span joint, ``len(frames) − 1`` entries (None: none there; an
        empty sequence: none anywhere).
    name : str
        A label.
    """

    frames: tuple[BridgeFrame, ...]
    abutment_keys: tuple[ShearKeys | None, ShearKeys | None] = (None, None)
    joint_keys: tuple[ShearKeys | None, ...] = ()
    name: str = "bridge"

    def __post_init__(self) -> None:
        frames = tuple(self.frames)
        if not frames:
            raise ValueError("frames: give at least one BridgeFrame")
        for i, f in enumerate(frames):
            if not isinstance(f, BridgeFrame):
                raise ValueError(f"frames[{i}]: expected a BridgeFrame (got "
                                 f"{type(f).__name__})")
        ab = tuple(self.abutment_keys)
        if len(ab) != 2 or not all(a is None or isinstance(a, ShearKeys) for a in ab):
            raise ValueError("abutment_keys: give (left, right), each ShearKeys or None")
        joints = tuple(self.joint_keys) or (None,) * (len(frames) - 1)
        if len(joints) != len(frames) - 1:
            raise ValueError(f"joint_keys: need {len(frames) - 1} entr(ies) for {len(frames)} "
                             f"frames, one per joint (got {len(joints)})")
        for j, keys in enumerate(joints):
            if keys is not None and not isinstance(keys, ShearKeys):
                raise ValueError(f"joint_keys[{j}]: expected ShearKeys or None (got "
                                 f"{type(keys).__name__})")
        object.__setattr__(self, "frames", frames)
        object.__setattr__(self, "abutment_keys", ab)
        object.__setattr__(self, "joint_keys", joints)

    def stops(self) -> list[Stop]:
        """Every key as a stop on a deck (DOF 0 of its frame): the left abutment's
        (``A1+y``, ``A1-y``), the right one's (``A2+y``, ``A2-y``), then each joint's
        (deck j against deck j + 1, then deck j + 1 against deck j)."""
        deck = 0
        last = len(self.frames) - 1
        out = []
        for keys, b, name in zip(self.abutment_keys, (0, last), ("A1", "A2")):
            if keys is not None:
                out += [Stop(b, deck, +1, keys.gap, keys.law, name=f"{name}+y"),
                        Stop(b, deck, -1, keys.gap, keys.law, name=f"{name}-y")]
        for j, keys in enumerate(self.joint_keys):
            if keys is not None:
                out += [Stop(j, deck, +1, keys.gap, keys.law, other=(j + 1, deck)),
                        Stop(j + 1, deck, +1, keys.gap, keys.law, other=(j, deck))]
        return out

    def model_arguments(self) -> dict[str, Any]:
        """The keyword arguments of :class:`pounding.model.PoundingModel` but the contact:
        the frames as buildings that never meet (infinite gaps), the keys as stops."""
        return {"buildings": list(self.frames), "gaps": [math.inf] * (len(self.frames) - 1),
                "stops": self.stops(), "name": self.name, "floor_to_column": False}

    def describe(self) -> str:
        """One line: frames and keys."""
        ab = ", ".join(f"{side} gap {k.gap * 1e3:g} mm" for k, side in
                       zip(self.abutment_keys, ("left", "right")) if k is not None) or "none"
        nj = sum(k is not None for k in self.joint_keys)
        return (f"{len(self.frames)} frame(s) across the axis, abutment keys: {ab}, "
                f"{nj} joint(s) with keys")
