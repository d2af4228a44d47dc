"""Element rows: the nonlinear elements of a building, each with its own law.

The compiled kernel takes a building's nonlinear elements as *element rows*
(:meth:`pounding.model.PoundingModel.storey_arrays`): a force between two DOFs, ``lower``
(−1: the ground) and ``upper``, that follows a storey law of :mod:`pounding.hysteresis`
(contract: :mod:`pounding.hysteresis.base`) on the deformation

    d = u[upper] − u[lower] − lever · u[rock]

(``rock``: the DOF of a rocking footing under the element, −1 for none). The force ``V``
acts as ``−V`` on ``upper``, ``+V`` on ``lower`` and ``lever · V`` on ``rock``.

A shear building's rows are its yielding storeys, all with the building's one storey law
(:func:`storey_rows`, read through :meth:`~pounding.structure.ShearBuilding.
yielding_storey_dofs` and :meth:`~pounding.structure.ShearBuilding.storey_law_params`). A
building whose elements follow laws of their own — a bridge frame's piers and bearings
(:class:`pounding.structure.bridge.BridgeFrame`) — lists them itself with a method
``element_rows()``; :func:`element_rows` asks the building for it and falls back on the
storeys.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from pounding.hysteresis.base import StoreyLaw

__all__ = ["ElementRow", "element_rows", "storey_rows"]


class ElementRow(NamedTuple):
    """One nonlinear element of a building (DOFs are the building's own, 0-based)."""

    lower: int  #: DOF below (−1: the ground)
    upper: int  #: DOF above
    rock: int  #: DOF of a rocking footing under it (−1: none)
    lever: float  #: its height over that footing [m] (0: none)
    law: StoreyLaw  #: its force–deformation law
    params: NDArray[np.float64]  #: the law's constants ``[k, F_y, …]`` (PARAMS_SIZE)
    storey: int  #: the DOF whose storey it is (its shear fills that storey column; −1: none)
    label: str  #: its name in its building (``'F3'`` for storey 3, ``'P1'``, ``'Br1'`` …)


def storey_rows(building: Any) -> list[ElementRow]:
    """The yielding storeys of a building with one storey law for all of them (a shear
    building, one on a flexible base): one row per storey of ``building.yielding``, in that
    order, with the DOFs of ``yielding_storey_dofs()`` and the constants of
    ``storey_law_params()``; none for a linear building."""
    law = building.storey_law
    if law is None:
        return []
    prm = building.storey_law_params()
    return [ElementRow(int(lo), int(hi), int(rk), float(arm), law, prm[r], int(j), f"F{j + 1}")
            for r, (j, (lo, hi, rk, arm)) in enumerate(zip(building.yielding,
                                                           building.yielding_storey_dofs()))]


def element_rows(building: Any) -> list[ElementRow]:
    """The element rows of ``building``: its own ``element_rows()`` if it has the method
    (a building whose elements have laws of their own), else its yielding storeys
    (:func:`storey_rows`)."""
    own = getattr(building, "element_rows", None)
    return list(own()) if callable(own) else storey_rows(building)
