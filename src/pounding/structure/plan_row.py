"""A building in plan in a row of buildings: the matrix building it stands in the row as, the
points where its façades meet a neighbour's, and the histories of named points.

A :class:`~pounding.structure.plan.PlanBuilding` describes rigid floors in plan; in a
:class:`~pounding.model.PoundingModel` it is its :class:`PlanMatrixBuilding`, a matrix
building whose DOFs are ``F1x, F1y, F1θ, …`` and whose floors are the ``u_x`` DOFs, so that
every part of the engine and its outputs takes it as one. Neighbours stand along x; two
floors at the same elevation meet at the ends of the stretch where their façades face each
other (:func:`facing_points`): between two straight edges of rigid floors the gap is linear
along that stretch, so the first touch is at one of its ends. The penetration at such a point
is a linear combination of the floors' DOFs (:func:`plan_contact_points`).

This module reads a building in plan through what :class:`FloorPlan` names (a
:class:`~pounding.structure.plan.PlanBuilding` has it all); the plan makes its row building
(:meth:`~pounding.structure.plan.PlanBuilding.as_matrix_building`), not the other way round.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.assembly import shared_levels
from pounding.structure.damping import DampingModel
from pounding.structure.matrices import MatrixBuilding

__all__ = ["FloorPlan", "PlanMatrixBuilding", "facing_points", "plan_contact_points",
           "point_history"]


@runtime_checkable
class FloorPlan(Protocol):
    """What this module reads of a building in plan
    (:class:`~pounding.structure.plan.PlanBuilding`): its plan's size and place on the site,
    its floors, and the kinematics of a point of a rigid floor."""

    @property
    def width(self) -> float:
        """Plan dimension along x [m]."""
        ...

    @property
    def depth(self) -> float:
        """Plan dimension along y [m]."""
        ...

    @property
    def site_y(self) -> float:
        """Site y of the plan's ``y = 0`` edge [m]."""
        ...

    @property
    def n_floors(self) -> int:
        """Number of floors."""
        ...

    def dof(self, floor: int, component: str) -> int:
        """The DOF of ``floor`` (0-based) and ``component`` ``"x"``, ``"y"`` or ``"θ"``."""
        ...

    def influence_matrix(self) -> NDArray[np.float64]:
        """``R`` (3n × 2) of the ground's x and y components."""
        ...

    def point_weights(self, floor: int, x: float, y: float, direction: str | float = "x"
                      ) -> list[tuple[int, float]]:
        """``(DOF, weight)`` pairs of the displacement of a point of ``floor``."""
        ...

    def point_displacement(self, u: ArrayLike, floor: int, x: float, y: float,
                           direction: str | float = "x") -> NDArray[np.float64]:
        """Displacement [m] of a point of ``floor`` from DOF histories ``u[..., 3n]``."""
        ...


def facing_points(left: FloorPlan, right: FloorPlan) -> list[float]:
    """Site y [m] of the contact points between the right façade (``x = width``) of
    ``left`` and the left façade (``x = 0``) of ``right``: the two ends of the stretch over
    which they face each other (one point if it is a single point; none if they do not face
    each other). Between two straight edges of rigid floors the gap is linear along that
    stretch, so the first touch is at one of its ends."""
    lo = max(left.site_y, right.site_y)
    hi = min(left.site_y + left.depth, right.site_y + right.depth)
    if hi < lo:
        return []
    if hi == lo:
        return [lo]
    return [lo, hi]


@dataclass(frozen=True, eq=False, init=False)
class PlanMatrixBuilding(MatrixBuilding):
    """A :class:`~pounding.structure.plan.PlanBuilding` as it stands in a row of buildings:
    a matrix building (so that every part of the engine and its outputs takes it as one: DOF
    labels ``F1x, F1y, F1θ``, the ``u_x`` DOFs its floors) that keeps its plan
    (:attr:`plan`) for the influence matrix of two ground components and the kinematics of
    its façade points. Made by
    :meth:`~pounding.structure.plan.PlanBuilding.as_matrix_building`;
    :class:`~pounding.model.PoundingModel` makes it of every PlanBuilding it is given.

    Parameters are those of :class:`~pounding.structure.MatrixBuilding`, and ``plan``
    (keyword only): the building in plan (:class:`FloorPlan`)."""

    plan: FloorPlan

    def __init__(self, M: ArrayLike, K: ArrayLike, labels: Sequence[str], elevations: ArrayLike,
                 r: ArrayLike | None = None, C: ArrayLike | None = None,
                 damping: DampingModel | None = None, name: str = "",
                 sources: Mapping[str, str] = MappingProxyType({}),
                 floors: Sequence[int | str] | None = None, *, plan: FloorPlan) -> None:
        if not isinstance(plan, FloorPlan):
            raise ValueError(f"plan must be a PlanBuilding (got {plan!r})")
        object.__setattr__(self, "plan", plan)  # the attributes of a frozen dataclass
        super().__init__(M, K, labels, elevations, r, C, damping, name, sources, floors)

    def influence_matrix(self) -> NDArray[np.float64]:
        """``R`` (3n × 2) of the plan
        (:meth:`~pounding.structure.plan.PlanBuilding.influence_matrix`)."""
        return self.plan.influence_matrix()

    def point_displacement(self, u: ArrayLike, floor: int, x: float, y: float,
                           direction: str | float = "x") -> NDArray[np.float64]:
        """Displacement [m] of a point ``(x, y)`` (plan coordinates) of ``floor`` (0-based)
        from this building's DOF histories ``u[..., 3n]``
        (:meth:`~pounding.structure.plan.PlanBuilding.point_displacement`)."""
        return self.plan.point_displacement(u, floor, x, y, direction)


def _plan_of(building: Any) -> FloorPlan | None:
    return building.plan if isinstance(building, PlanMatrixBuilding) else None


def plan_contact_points(a: Any, b: Any, tol: float = 1e-6
                        ) -> list[tuple[float, int, list[tuple[int, float]], int,
                                        list[tuple[int, float]], float]]:
    """Where two neighbours in a row meet when one or both are buildings in plan.

    Floors at the same elevation (within ``tol`` [m]) meet at the ends of the stretch over
    which their façades face each other (:func:`facing_points`): the right façade
    (``x = width``) of the left building, the left façade (``x = 0``) of the right one. A
    planar neighbour (a shear or matrix building) has no plan: its floor faces the whole
    façade of the building in plan. No floor-to-column contacts: floors at different levels
    do not meet here.

    Returns
    -------
    list of (elevation, i, weights_i, j, weights_j, y)
        ``i``, ``j``: the floor (``u_x``) DOFs of ``a`` and ``b``; ``weights``: the point's
        ``(DOF, weight)`` pairs of its displacement along x
        (:meth:`~pounding.structure.plan.PlanBuilding.point_weights`; ``[(i, 1.0)]`` for a
        planar floor); ``y``: site y of the point [m]. Sorted by elevation, then y.
    """
    pa, pb = _plan_of(a), _plan_of(b)
    one = pa if pb is None else pb  # the one building in plan, if only one is
    if pa is not None and pb is not None:
        ys = facing_points(pa, pb)
    elif one is not None:  # a planar floor faces its whole façade
        ys = [one.site_y, one.site_y + one.depth]
    else:
        raise ValueError("plan_contact_points: neither building is in plan")
    rows = []
    levels = np.asarray(a.floor_levels)
    for i, j in shared_levels(a, b, tol):  # floors at the same elevation, u_x DOFs
        for y in ys:
            wi = ([(i, 1.0)] if pa is None
                  else pa.point_weights(i // 3, pa.width, y - pa.site_y, "x"))
            wj = [(j, 1.0)] if pb is None else pb.point_weights(j // 3, 0.0, y - pb.site_y, "x")
            rows.append((float(levels[i]), i, wi, j, wj, float(y)))
    rows.sort(key=lambda r: (r[0], r[5]))
    return rows


def point_history(result: Any, building: int, floor: int, x: float, y: float,
                  direction: str | float = "x") -> NDArray[np.float64]:
    """Displacement history [m] of a named point of a floor in plan, relative to the ground.

    Parameters
    ----------
    result : pounding.result.Result
        A run of a model with buildings in plan.
    building : int
        0-based index of the building in the row (a :class:`~pounding.structure.plan.PlanBuilding`).
    floor : int
        0-based floor (0 = floor 1).
    x, y : float
        The point in the building's plan coordinates [m] (a corner: ``(width, 0)``, …).
    direction : {"x", "y"} or float
        Along x, y or an angle [degrees] from x.

    Returns
    -------
    ndarray (nt,)
        ``c (u_x − (y − y_c) θ) + s (u_y + (x − x_c) θ)`` at every output time
        (:meth:`~pounding.structure.plan.PlanBuilding.point_weights`).
    """
    model = result.model
    if not 0 <= building < len(model.buildings):
        raise ValueError(f"building must be in [0, {len(model.buildings) - 1}] "
                         f"(got {building!r})")
    b = model.buildings[building]
    if not isinstance(b, PlanMatrixBuilding):
        raise ValueError(f"building {building} ({b.name!r}) is not in plan: its DOFs are "
                         "translations along the row; read result.displacement")
    if not 0 <= floor < b.plan.n_floors:
        raise ValueError(f"floor must be in [0, {b.plan.n_floors - 1}] "
                         f"(got {floor!r})")
    off = int(model.system.offsets[building])
    u = np.asarray(result.displacement)[:, off: off + b.n]
    return b.point_displacement(u, floor, x, y, direction)
