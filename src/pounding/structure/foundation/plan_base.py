"""A building in plan on a flexible base: rigid floors that translate and twist, a rigid
footing that sways, rocks and twists, and the soil's springs and dashpots (soil–structure
interaction in plan, the substructure method with a lumped-parameter soil).

The three-dimensional counterpart of :mod:`pounding.structure.foundation.flexible_base`.
Degrees of freedom: every floor's ``u_x``, ``u_y`` (its centre of mass) and ``θ`` (about
the vertical, counter-clockwise positive) relative to the free-field ground, as on a fixed
base (:mod:`pounding.structure.plan`), then the footing's five at its centre
``(x0, y0)`` (plan coordinates, at the ground surface):

    y_f = [u_fx, u_fy, φ_x, φ_y, ψ]

— sway along x (the row) and y, rocking about the horizontal x and y axes and torsion
about the vertical, rotations by the right-hand rule (``φ_y`` positive moves the floors
above along +x by ``z φ_y``: the rocking ``φ`` of the row's flexible base; ``ψ``
positive is the floors' ``θ``). The footing's rigid motion moves the centre of mass
``(x_c, y_c)`` of a floor at elevation ``z`` by the small rotation ``(φ_x, φ_y, ψ)``
about the footing's centre (``X = x_c − x0``, ``Y = y_c − y0``):

    u_x = u_fx + z φ_y − Y ψ,   u_y = u_fy − z φ_x + X ψ,   θ = ψ,

(the floor's vertical motion ``φ_x Y − φ_y X`` has no DOF: the floors' vertical and
rotary inertia about horizontal axes are not included, as in the row's flexible base).
With ``A`` (3n × 5) those rows, the building's own deformation is

    q = T y,   T = [I | −A],   y = [x, y_f],

and, as in the plane case (Wolf 1985 §2; Chopra §9.4, §9.5),

    M_y = diag(M, m_f, m_f, I_fx, I_fy, I_fz),
    K_y = Tᵀ K T + diag(0, k_x, k_y, k_rx, k_ry, k_t),
    C_y = Tᵀ C T + diag(0, c_x, c_y, c_rx, c_ry, c_t),
    R_y = [R; (1, 0); (0, 1); 0; 0; 0],

``K`` and ``C`` the fixed-base building's (its lateral elements and damping model), ``R``
its influence matrix of the ground's x and y components (:meth:`PlanBuilding.
influence_matrix`): the footing's sway along x feels the x component, along y the y one,
its rotations neither.

The soil (:mod:`.impedance`): sway along x and rocking about y are those of the row's
flexible base (:func:`footing_stiffness`, :func:`footing_dashpots`); sway along y and
rocking about x the same formulas for the footing turned a quarter turn (Pais & Kausel's
across-the-row rectangle; a circle is the same both ways); torsion :func:`footing_torsion`
(``16 G R³/3``; Pais & Kausel's rectangle; Wolf's torsional cone for the dashpot). The
dashpots are taken at the flexible-base building's first mode, with the soil's material
damping ``2 β k/ω``.

The footing's inertia: ``Footing.mass`` for both sways; ``Footing.inertia`` about the y
axis (the rocking axis of the row); about x, by default that times the ratio of the plan's
second moments of area (1 for a circle, ``(width/length)²`` for a rectangle: a thin
uniform plate); about the vertical, by default their sum (a thin plate's polar moment).
Either may be given (``inertias``). A DOF whose inertia is zero is condensed out
statically as in the plane case
(:func:`~pounding.structure.foundation.flexible_base.static_shape`).

Outputs: the footing's motion and the soil's reactions on it
(:meth:`PlanFoundation.base_reactions`), and the building's own deformation
(:meth:`PlanFoundation.deformation`), from which its storeys' drifts and forces follow.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.foundation.flexible_base import static_shape
from pounding.structure.foundation.impedance import (
    Footing,
    footing_dashpots,
    footing_stiffness,
    footing_torsion,
)
from pounding.structure.foundation.soil import Soil
from pounding.structure.modal import eigenmodes
from pounding.structure.plan import PlanBuilding
from pounding.structure.plan_row import PlanMatrixBuilding

__all__ = ["FOOTING_DOFS", "PlanFlexibleBaseBuilding", "PlanFoundation", "PlanImpedance",
           "plan_flexible_base"]

FOOTING_DOFS: tuple[str, ...] = ("Fdn_x", "Fdn_y", "Fdn_rx", "Fdn_ry", "Fdn_t")
"""The labels of the footing's DOFs: sway along x and y, rocking about x and y, torsion."""


@dataclass(frozen=True)
class PlanImpedance:
    """A footing's frequency-independent springs and dashpots in plan, in the order of
    :data:`FOOTING_DOFS` (sway x, sway y, rocking about x, rocking about y, torsion)."""

    springs: tuple[float, float, float, float, float]  #: [N/m, N/m, N·m/rad ×3]
    dashpots: tuple[float, float, float, float, float]  #: [N·s/m ×2, N·m·s/rad ×3]
    omega: float  #: the circular frequency the dashpots were taken at [rad/s]


@dataclass(frozen=True)
class PlanFoundation:
    """What a flexible base adds to a building in plan (module docstring): the footing,
    soil and impedance, the fixed-base periods, the footing's centre and inertias, the rigid
    motion ``A`` its DOFs give the floors, and how its five DOFs follow from the building's
    (``y_f = recovery @ y``: rows of the identity where they are DOFs, the static
    condensation where they are not)."""

    footing: Footing
    soil: Soil
    impedance: PlanImpedance
    fixed_base_periods: NDArray[np.float64]  #: the building's on a rigid base [s]
    centre: tuple[float, float]  #: the footing's centre (x0, y0) in plan coordinates [m]
    inertias: tuple[float, float, float]  #: the footing's I_x, I_y, I_z [kg·m²]
    rigid: NDArray[np.float64]  #: A (3 n_floors, 5): the floors' rigid motion [m/m, m/rad]
    recovery: NDArray[np.float64]  #: (5, n): the footing's DOFs from the building's
    explicit: tuple[bool, ...]  #: which of the footing's five are DOFs of the building

    def footing_motion(self, displacement: NDArray[np.float64]) -> NDArray[np.float64]:
        """The footing's ``[u_fx, u_fy, φ_x, φ_y, ψ]`` [m, m, rad, rad, rad] (nt, 5) from
        the building's DOF histories (nt, n)."""
        return np.asarray(displacement @ self.recovery.T)

    def deformation(self, displacement: NDArray[np.float64]) -> NDArray[np.float64]:
        """The building's own deformation ``q = x − A y_f`` (nt, 3 n_floors): its floors'
        ``u_x``, ``u_y``, ``θ`` less the footing's rigid motion — what its lateral elements
        feel — from its DOF histories (nt, n) relative to the free-field ground."""
        m = self.rigid.shape[0]
        return np.asarray(displacement[:, :m] - self.footing_motion(displacement)
                          @ self.rigid.T)

    def deformation_drifts(self, displacement: NDArray[np.float64]
                           ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The storeys' drifts along x and y of the building's own deformation [m], each
        (nt, n_floors): ``q_j − q_{j−1}`` at the centres of mass (``q_0 = 0``), as a fixed
        base's drifts of the floors relative to the ground."""
        q = self.deformation(displacement)
        out = []
        for c in (0, 1):
            v = q[:, c::3]
            out.append(np.asarray(np.diff(v, axis=1, prepend=0.0)))
        return out[0], out[1]

    def base_reactions(self, displacement: NDArray[np.float64],
                       velocity: NDArray[np.float64]
                       ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The footing's motion ``[u_fx, u_fy, φ_x, φ_y, ψ]`` (nt, 5) and the soil's
        reactions on it ``[V_x, V_y, M_x, M_y, T]`` [N, N, N·m ×3] (nt, 5),
        ``k y_f + c ẏ_f`` DOF by DOF, from the building's displacement and velocity
        histories (nt, n)."""
        u = self.footing_motion(displacement)
        v = self.footing_motion(velocity)
        k = np.asarray(self.impedance.springs)
        c = np.asarray(self.impedance.dashpots)
        return u, u * k + v * c


class PlanFlexibleBaseBuilding(PlanMatrixBuilding):
    """A building in plan on a flexible base (module docstring): the
    :class:`~pounding.structure.plan_row.PlanMatrixBuilding` of its plan with the footing's
    DOFs after the floors' (labels :data:`FOOTING_DOFS`, those that have inertia), its
    matrices including the footing and soil, and its :attr:`foundation`. Made by
    :func:`plan_flexible_base`."""

    foundation: PlanFoundation

    def __init__(self, foundation: PlanFoundation, influence: NDArray[np.float64],
                 **matrices: Any) -> None:
        super().__init__(**matrices)
        frozen_set = object.__setattr__
        frozen_set(self, "foundation", foundation)
        R = np.array(influence, dtype=float)
        R.setflags(write=False)
        frozen_set(self, "_influence", R)

    def influence_matrix(self) -> NDArray[np.float64]:
        """``R`` (n × 2): the floors' of the plan, then the footing's sways (x, y)."""
        return np.array(self.__dict__["_influence"])

    def __eq__(self, other: object) -> bool:
        same = super().__eq__(other)
        if same is NotImplemented or not same:
            return same
        return (isinstance(other, PlanFlexibleBaseBuilding)
                and self.foundation.footing == other.foundation.footing
                and self.foundation.soil == other.foundation.soil
                and self.foundation.centre == other.foundation.centre
                and self.foundation.inertias == other.foundation.inertias)

    __hash__ = None  # type: ignore[assignment]


def _quarter_turn(footing: Footing) -> Footing:
    """The footing turned a quarter turn in plan (a rectangle's length and width swapped):
    its sway along the row and rocking about the axis across the row are the footing's
    sway across the row and rocking about the axis along it."""
    if footing.radius is not None:
        return footing
    return dataclasses.replace(footing, length=footing.width, width=footing.length)


def _default_inertias(footing: Footing) -> tuple[float, float, float]:
    """``(I_x, I_y, I_z)`` [kg·m²] of the footing (module docstring): ``I_y`` its rocking
    inertia, ``I_x`` that times the ratio of the plan's second moments of area, ``I_z``
    their sum (a thin uniform plate)."""
    i_y = float(footing.inertia)
    i_x = i_y * _quarter_turn(footing).rocking_moment / footing.rocking_moment
    return i_x, i_y, i_x + i_y


def plan_flexible_base(building: PlanBuilding, footing: Footing, soil: Soil,
                       centre: Sequence[float] | None = None,
                       inertias: ArrayLike | None = None) -> PlanFlexibleBaseBuilding:
    """``building`` (in plan) on ``footing`` on ``soil`` (module docstring).

    Parameters
    ----------
    building : PlanBuilding
        The fixed-base building in plan (linear; floors at their elevations above the
        footing's base [m]).
    footing : Footing
        The footing: a circle, or a rectangle ``length`` along x (the row) by ``width``
        along y; its mass and rocking inertia (about y) (zero: condensed out).
    soil : Soil
        The half-space under it.
    centre : (float, float), optional
        The footing's centre ``(x0, y0)`` in the plan's coordinates [m]; default the
        plan's centre ``(width/2, depth/2)``.
    inertias : (float, float, float), optional
        The footing's mass moments of inertia about x, y and the vertical [kg·m²]; default
        from ``footing.inertia`` (module docstring).

    Raises
    ------
    ValueError
        If ``building`` is not a PlanBuilding, or ``centre``/``inertias`` are not finite
        (inertias ≥ 0).

    Examples
    --------
    A one-storey building 20 m × 10 m, symmetric, on a massless disk of radius 6 m:

    >>> from pounding.structure.plan import LateralElement
    >>> b = PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0, elements=[
    ...     LateralElement(0.0, 0.0, "x", 5e7), LateralElement(0.0, 10.0, "x", 5e7),
    ...     LateralElement(0.0, 5.0, "y", 5e7), LateralElement(20.0, 5.0, "y", 5e7)])
    >>> fb = plan_flexible_base(b, Footing(radius=6.0), Soil(150.0, 1800.0, 0.33))
    >>> fb.n, fb.labels
    (3, ('F1x', 'F1y', 'F1θ'))
    >>> bool(fb.modes().periods[0] > b.modes().periods[0])
    True
    """
    if not isinstance(building, PlanBuilding):
        raise ValueError(f"foundation: plan_flexible_base takes a PlanBuilding (got "  # noqa: TRY004
                         f"{type(building).__name__})")
    name = building.name
    if centre is None:
        x0, y0 = 0.5 * building.width, 0.5 * building.depth
    else:
        x0, y0 = (float(v) for v in centre)
        if not (np.isfinite(x0) and np.isfinite(y0)):
            raise ValueError(f"foundation.centre must be finite (x, y) [m] (got {centre!r})")
    if inertias is None:
        i_fx, i_fy, i_fz = _default_inertias(footing)
    else:
        vals = np.asarray(inertias, dtype=float)
        if vals.shape != (3,) or not np.all(np.isfinite(vals)) or np.any(vals < 0):
            raise ValueError("foundation.inertias must be three finite values >= 0 [kg·m²] "
                             f"(about x, y and the vertical) (got {inertias!r})")
        i_fx, i_fy, i_fz = (float(v) for v in vals)
    nf = building.n_floors
    m = 3 * nf
    M0 = building.mass_matrix()
    K0 = building.stiffness_matrix()
    C0 = building.damping_matrix()
    fixed_periods = 2.0 * np.pi / eigenmodes(M0, K0)[0]
    # (levers from the footing's base, about which it rocks, D below the ground)
    z = np.asarray(building.floor_levels, dtype=float) + footing.embedment
    X = building.mass_centres[:, 0] - x0
    Y = building.mass_centres[:, 1] - y0
    A = np.zeros((m, 5))
    A[0::3, 0] = 1.0
    A[0::3, 3] = z
    A[0::3, 4] = -Y
    A[1::3, 1] = 1.0
    A[1::3, 2] = -z
    A[1::3, 4] = X
    A[2::3, 4] = 1.0
    T = np.hstack([np.eye(m), -A])
    turned = _quarter_turn(footing)
    k_x, k_ry = footing_stiffness(footing, soil)
    k_y, k_rx = footing_stiffness(turned, soil)
    masses = np.array([footing.mass, footing.mass, i_fx, i_fy, i_fz])
    M = np.zeros((m + 5, m + 5))
    M[:m, :m] = M0
    M[m:, m:] = np.diag(masses)
    K = T.T @ K0 @ T
    keep = np.r_[np.arange(m), m + np.flatnonzero(masses > 0.0)].astype(np.int64)
    k_t = footing_torsion(footing, soil, 1.0)[0]  # (the spring: any frequency)
    springs = (k_x, k_y, k_rx, k_ry, k_t)
    K[m:, m:] += np.diag(springs)
    Phi = static_shape(K, keep)
    M_k, K_k = Phi.T @ M @ Phi, Phi.T @ K @ Phi
    omega = float(eigenmodes(M_k, K_k)[0][0])
    c_x, c_ry = footing_dashpots(footing, soil, omega)
    c_y, c_rx = footing_dashpots(turned, soil, omega)
    _, c_t = footing_torsion(footing, soil, omega)
    dashpots = (c_x, c_y, c_rx, c_ry, c_t)
    C = T.T @ C0 @ T
    C[m:, m:] += np.diag(dashpots)
    C_k = Phi.T @ C @ Phi
    M_k, K_k, C_k = (0.5 * (B + B.T) for B in (M_k, K_k, C_k))
    kept = [d - m for d in keep if d >= m]
    R = np.zeros((m + 5, 2))
    R[:m] = building.influence_matrix()
    R[m, 0] = R[m + 1, 1] = 1.0
    R = R[keep]
    foundation = PlanFoundation(
        footing, soil, PlanImpedance(springs, dashpots, omega), fixed_periods,
        (x0, y0), (i_fx, i_fy, i_fz), A, Phi[m:], tuple(bool(v > 0.0) for v in masses))
    return PlanFlexibleBaseBuilding(
        foundation, R, M=M_k, K=K_k, C=C_k,
        labels=tuple(building.dof_labels()) + tuple(FOOTING_DOFS[d] for d in kept),
        elevations=np.r_[np.repeat(z, 3), np.zeros(len(kept))], r=R[:, 0],
        floors=list(range(0, m, 3)), name=name, plan=building)
