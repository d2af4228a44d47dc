"""The names and units of the degrees of freedom of a row of buildings, as every output
labels them (:meth:`pounding.model.PoundingModel.dof_labels`, ``dof_units``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from pounding.structure.matrices import MatrixBuilding

# A row of shear buildings names its DOFs without the kinds of matrix building (bridge
# frames, flexible bases, buildings in plan, frames): they are imported for a row that holds
# a matrix building, so that a run of shear buildings does not load them.

__all__ = ["dof_labels", "dof_units"]


def dof_labels(buildings: Sequence[Any]) -> list[str]:
    """``'B1F1'``, ``'B1F2'``, … for every degree of freedom (1-based): ``F<j>`` is the
    building's DOF ``j`` (a matrix building's own labels); of a building in plan, its floor and direction, ``'B2F3x'``, ``'B2F3y'``, ``'B2F3θ'``
    (building 2, floor 3), as its contacts name its floors; of a frame, its own labels
    (its floors ``F1`` … first, then its nodes' DOFs with mass, ``'B1N6x'``); of a
    building on a flexible base, its footing's DOFs after its own: ``'B1Fdn'`` (sway)
    and ``'B1Fdn_r'`` (rocking), in plan ``'B1Fdn_x'``, ``'B1Fdn_y'``, ``'B1Fdn_rx'``,
    ``'B1Fdn_ry'``, ``'B1Fdn_t'`` (:mod:`pounding.structure.foundation`)."""
    out = []
    for b, bl in enumerate(buildings):
        if not isinstance(bl, MatrixBuilding):
            out += [f"B{b + 1}F{j + 1}" for j in range(bl.n)]
            continue
        from pounding.structure.foundation import FlexibleBaseBuilding
        from pounding.structure.plan_row import PlanMatrixBuilding

        if isinstance(bl, PlanMatrixBuilding) or getattr(bl, "frame", None) is not None:
            names = list(bl.labels)
        elif isinstance(bl, FlexibleBaseBuilding):  # its DOFs, then the footing's
            n0 = int(bl.fixed_base.n)
            names = [f"F{j + 1}" for j in range(n0)] + list(bl.labels[n0:])
        else:
            names = [f"F{j + 1}" for j in range(bl.n)]
        out += [f"B{b + 1}{name}" for name in names]
    return out


def dof_units(buildings: Sequence[Any], is_floor: NDArray[np.bool_]) -> list[str]:
    """The unit of every degree of freedom's displacement: ``'m'`` for a translation
    (every floor; a building in plan's ``u_x``, ``u_y``; a footing's sway; a frame
    node's ``x``, ``y``), ``'rad'`` for a rotation (a building in plan's ``θ``, a
    footing's rocking and torsion, ``Fdn_r``, ``Fdn_rx``, ``Fdn_ry``, ``Fdn_t``; a frame
    node's ``r``), ``''`` for a DOF of a building given as matrices that is no floor
    (its matrices say what it is). Its velocity is in that unit per second, its
    acceleration per second squared."""
    out: list[str] = []
    k = 0
    for bl in buildings:
        if not isinstance(bl, MatrixBuilding):  # a shear building: every DOF a floor
            out += ["m"] * bl.n
            k += bl.n
            continue
        from pounding.structure.bridge import BridgeFrame
        from pounding.structure.foundation import FlexibleBaseBuilding
        from pounding.structure.foundation.flexible_base import SWAY_LABEL
        from pounding.structure.foundation.plan_base import FOOTING_DOFS
        from pounding.structure.plan_row import PlanMatrixBuilding

        rotations = {f"{SWAY_LABEL}_r", *FOOTING_DOFS[2:]}
        frame = getattr(bl, "frame", None) is not None
        for j in range(bl.n):
            label = bl.labels[j] if isinstance(bl, MatrixBuilding) else ""
            if label in rotations or (isinstance(bl, PlanMatrixBuilding)
                                      and label.endswith("θ")):
                unit = "rad"
            elif frame and label.startswith("N"):
                unit = "rad" if label.endswith("r") else "m"
            elif isinstance(bl, BridgeFrame):
                unit = "m"  # (its deck and pier caps: translations along the axis)
            elif (is_floor[k] or not isinstance(bl, MatrixBuilding) or frame
                  or isinstance(bl, PlanMatrixBuilding | FlexibleBaseBuilding)):
                unit = "m"  # (a flexible base's building: every DOF a translation)
            else:
                unit = ""
            out.append(unit)
            k += 1
    return out
