"""Bridges along their axis: frames (deck segments on piers through bearings) in a row,
pounding across their expansion joints and against the abutments.

* :class:`BridgeFrame`, :class:`Pier`, :class:`Bearing`, :func:`pier_stiffness` — one frame
  (:mod:`pounding.structure.bridge.frame`);
* :class:`Bridge` — the frames, joints, abutments and restrainers, and the
  :class:`~pounding.model.PoundingModel` they make (:mod:`pounding.structure.bridge.bridge`);
* :class:`Seat` — a seat with its width and a clause's minimum, the L and H it read
  (:mod:`pounding.structure.bridge.seats`).
* :class:`TransverseBridge`, :class:`ShearKeys` — the frames across the axis, held by shear
  keys at the abutments and joints (:mod:`pounding.structure.bridge.transverse`).
"""

from pounding.structure.bridge.bridge import (
    CALTRANS_PILE_STIFFNESS,
    Abutment,
    Bridge,
    Restrainer,
    abutment_piles,
)
from pounding.structure.bridge.frame import Bearing, BridgeFrame, Pier, pier_stiffness
from pounding.structure.bridge.seats import Seat
from pounding.structure.bridge.transverse import ShearKeys, TransverseBridge

__all__ = ["CALTRANS_PILE_STIFFNESS", "Abutment", "Bearing", "Bridge", "BridgeFrame", "Pier",
           "Restrainer", "Seat", "ShearKeys", "TransverseBridge", "abutment_piles",
           "pier_stiffness"]
