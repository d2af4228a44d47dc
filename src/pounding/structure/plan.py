"""Buildings in plan: rigid floors that translate and twist (torsional pounding).

A building whose floors are rigid in their own plane (rigid diaphragms) has three degrees of
freedom (DOFs) a floor: the translations ``u_x``, ``u_y`` of the floor's centre of mass and
its rotation ``θ`` about the vertical axis (counter-clockwise positive), relative to the
ground (Chopra, *Dynamics of Structures*, 4th ed., §9.5 "Unsymmetric-plan buildings" for
one storey and §9.6 for several). With the DOFs at the centres of mass the mass matrix is
diagonal, ``diag(m_j, m_j, I_Oj)`` floor by floor, ``I_Oj`` the floor's polar moment of
inertia about its centre of mass (``m (a² + b²)/12`` for a uniform ``a × b`` rectangle).

The storeys resist through lateral load-resisting elements — frames or walls — each at a
plan position ``(x_e, y_e)`` acting along a direction ``(c, s) = (cos β, sin β)`` with one
lateral stiffness a storey. A point ``p`` of floor j moves by

    u(p) = (u_xj − (p_y − y_cj) θ_j,  u_yj + (p_x − x_cj) θ_j),

so the element's deformation in storey j is ``a_j · q_j − a_{j−1} · q_{j−1}`` with
``q_j = (u_xj, u_yj, θ_j)`` and ``a_j = (c, s, −c (y_e − y_cj) + s (x_e − x_cj))``; its
stiffness contributes ``k a aᵀ`` to the stiffness matrix (Chopra §9.5.1, the element
stiffness transformed to the floor's DOFs; Kan & Chopra 1977, J. Struct. Div. 103(ST4)).
The eccentricity of a storey — the distance between its centre of mass and its centre of
stiffness — follows from where the elements are, and couples translation and twist.

Two horizontal components of the ground act together through the influence matrix
``R`` (3n × 2): a unit ground displacement along x moves every ``u_x`` by 1, along y every
``u_y`` by 1, and no rotation (Chopra §9.5.2):

    M ü + C u̇ + K u = −M R [a_gx(t), a_gy(t)]ᵀ + (contact forces).

Where a floor meets its neighbour, a point of its façade strikes: the penetration at a point
is a linear combination of the floor's DOFs (:meth:`PlanBuilding.point_weights`), so the same
contact laws apply and a floor may strike at a corner and twist. A façade is a straight edge
of a rigid floor, so along the stretch two façades face each other the gap between them is
linear in the position, and the first touch is at an end of that stretch:
:func:`pounding.structure.plan_row.facing_points` puts the contact points there; a
building in plan stands in a row of buildings as its
:class:`~pounding.structure.plan_row.PlanMatrixBuilding` (:mod:`pounding.structure.plan_row`).

DOF numbering: floor j (1-based) has DOFs ``3(j − 1) + {0, 1, 2}`` = ``(u_x, u_y, θ)``.
Units: m, kg, kg·m², N/m, rad.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.damping import DampingModel, RayleighDamping
from pounding.structure.floor_arrays import floor_vector, readonly
from pounding.structure.modal import ModalResult, modal_result
from pounding.structure.plan_row import PlanMatrixBuilding
from pounding.units import direction_cosines

__all__ = ["LateralElement", "PlanBuilding", "plan_stiffness_matrix"]

#: DOFs of a floor in plan, in order.
FLOOR_DOFS: tuple[str, str, str] = ("x", "y", "θ")


_DEFAULT_DAMPING = RayleighDamping(0.05, mode_i=1, mode_j=3)
"""A building in plan's damping when none is given: 5 % Rayleigh damping anchored at modes
1 and 3: in a building in plan the first three modes are usually the first of each family
(x, y, torsion), and a symmetric building has modes 1 and 2 at the same period, which cannot
anchor Rayleigh damping."""


@dataclass(frozen=True)
class LateralElement:
    """A lateral load-resisting element of a building in plan: a frame or a wall line.

    Parameters
    ----------
    x, y : float
        Plan position [m] of the element, in the building's plan coordinates (the same as
        :attr:`PlanBuilding.width` and :attr:`PlanBuilding.depth`).
    direction : {"x", "y"} or float
        The direction it resists: along x, along y, or an angle [degrees] from the x axis,
        counter-clockwise, in [-360, 360].
    stiffnesses : array_like, shape (n,) or float
        Its lateral stiffness in each storey [N/m], storey 1 first (a single value: the same
        in every storey).
    name : str
        A label (for example ``"frame A"``).
    """

    x: float
    y: float
    direction: str | float
    stiffnesses: ArrayLike
    name: str = ""

    def __post_init__(self) -> None:
        for label in ("x", "y"):
            v = getattr(self, label)
            if not isinstance(v, (int, float, np.floating, np.integer)) or not math.isfinite(v):
                raise ValueError(f"{label} must be a finite number [m] (got {v!r})")
            object.__setattr__(self, label, float(v))
        self.angle  # validates direction

    @property
    def angle(self) -> float:
        """The direction as an angle from the x axis [rad]."""
        c, s = direction_cosines(self.direction)
        return math.atan2(s, c)

    @property
    def cosines(self) -> tuple[float, float]:
        """``(cos β, sin β)`` of the direction, exact for x and y (and multiples of 90°)."""
        return direction_cosines(self.direction)

    def storey_stiffnesses(self, n: int) -> NDArray[np.float64]:
        """The stiffness in each of ``n`` storeys [N/m] (≥ 0; a zero means no element there)."""
        k = np.broadcast_to(np.asarray(self.stiffnesses, dtype=float), (n,)) \
            if np.ndim(self.stiffnesses) == 0 else np.asarray(self.stiffnesses, dtype=float)
        if k.shape != (n,):
            raise ValueError(f"stiffnesses of element {self.name or (self.x, self.y)!r} must "
                             f"have one value per storey ({n}) (got {k.size})")
        bad = np.flatnonzero(~np.isfinite(k) | (k < 0))
        if bad.size:
            raise ValueError(f"stiffnesses[{bad[0]}] of element {self.name or (self.x, self.y)!r}"
                             f" must be finite and >= 0 [N/m] (got {k[bad[0]]!r})")
        return np.array(k, dtype=float)


@dataclass(frozen=True, eq=False, init=False)
class PlanBuilding:
    """A multi-storey building with rigid floors in plan: three DOFs a floor (u_x, u_y, θ).

    The floor plan is the rectangle ``[0, width] × [0, depth]`` in the building's plan
    coordinates [m]; the building stands with that rectangle's ``y = 0`` edge at site
    ``y = site_y`` (neighbours in a row along x may be offset along y, so that they face each
    other over part of their façades only).

    Parameters
    ----------
    masses : array_like, shape (n,)
        Floor masses [kg], floor 1 (the first suspended floor) first.
    heights : array_like, shape (n,)
        Storey heights [m].
    width, depth : float
        Plan dimensions along x and y [m].
    elements : sequence of LateralElement
        The lateral load-resisting elements; together they must restrain every floor in x,
        y and rotation (at least two non-parallel directions and a lever arm). Give either
        these or ``stiffness``.
    mass_centres : array_like, shape (n, 2), optional
        Centre of mass ``(x_c, y_c)`` of each floor [m], inside the plan; default the
        centre of the plan.
    inertias : array_like, shape (n,), optional
        Polar moment of inertia of each floor about its centre of mass [kg·m²]; default
        that of a uniform rectangle, ``m (width² + depth²) / 12``. At most ``m ρ²``, ``ρ``
        the distance from the centre of mass to the farthest corner of the plan (the
        floor's whole mass there): no floor on the plan has more.
    damping : DampingModel
        Default 5 % Rayleigh damping at modes 1 and 3 (see :data:`_DEFAULT_DAMPING`).
    name : str
        A label.
    site_y : float
        Site y of the plan's ``y = 0`` edge [m].
    stiffness : array_like, shape (3n, 3n), optional
        The stiffness matrix itself, in this class's DOFs (``u_x, u_y, θ`` at each floor's
        centre of mass, floor by floor) [N/m, N, N·m] — for a building whose stiffness was
        condensed elsewhere (see :mod:`pounding.structure.matrices`); instead of
        ``elements``. Checked symmetric and positive definite.

    Examples
    --------
    A one-storey building 20 m × 10 m, two frames along x at the long edges, two along y at
    the short edges, the y frame at x = 20 m twice as stiff (stiffness eccentricity):

    >>> b = PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0, elements=[
    ...     LateralElement(0.0, 0.0, "x", 5e7), LateralElement(0.0, 10.0, "x", 5e7),
    ...     LateralElement(0.0, 5.0, "y", 5e7), LateralElement(20.0, 5.0, "y", 1e8)])
    >>> b.n, b.n_floors, b.stiffness_eccentricity()[0].round(3).tolist()
    (3, 1, [3.333, 0.0])
    """

    masses: NDArray[np.float64]
    heights: NDArray[np.float64]
    width: float
    depth: float
    elements: tuple[LateralElement, ...]
    mass_centres: NDArray[np.float64]
    inertias: NDArray[np.float64]
    damping: DampingModel
    name: str
    site_y: float
    stiffness: NDArray[np.float64] | None

    def __init__(self, masses: ArrayLike, heights: ArrayLike, width: float, depth: float,
                 elements: Sequence[LateralElement] = (), mass_centres: ArrayLike | None = None,
                 inertias: ArrayLike | None = None, damping: DampingModel = _DEFAULT_DAMPING,
                 name: str = "", site_y: float = 0.0, stiffness: ArrayLike | None = None
                 ) -> None:
        m = floor_vector("masses", masses)
        h = floor_vector("heights", heights)
        n = m.size
        if h.size != n:
            raise ValueError(f"heights must have one value per floor, as many as masses ({n}) "
                             f"(got {h.size})")
        sizes = []
        for label, v in (("width", width), ("depth", depth)):
            if not isinstance(v, (int, float, np.floating, np.integer)) or not v > 0 \
                    or not math.isfinite(v):
                raise ValueError(f"{label} must be a finite number > 0 [m] (got {v!r})")
            sizes.append(float(v))
        width, depth = sizes
        if not isinstance(site_y, (int, float, np.floating, np.integer)) \
                or not math.isfinite(site_y):
            raise ValueError(f"site_y must be a finite number [m] (got {site_y!r})")
        site_y = float(site_y)
        if mass_centres is None:
            centres = np.tile([0.5 * width, 0.5 * depth], (n, 1))
        else:
            centres = np.asarray(mass_centres, dtype=float)
            if centres.shape == (2,):
                centres = np.tile(centres, (n, 1))
            if centres.shape != (n, 2) or not np.all(np.isfinite(centres)):
                raise ValueError(f"mass_centres must be finite (x, y) pairs [m], one a floor "
                                 f"({n}) (got shape {centres.shape})")
            outside = np.flatnonzero((centres[:, 0] < 0.0) | (centres[:, 0] > width)
                                     | (centres[:, 1] < 0.0) | (centres[:, 1] > depth))
            if outside.size:
                k = int(outside[0])
                raise ValueError(f"mass_centres[{k}] must lie inside the plan, x in [0, "
                                 f"{width:g}] and y in [0, {depth:g}] m (got "
                                 f"[{centres[k, 0]:g}, {centres[k, 1]:g}])")
        if inertias is None:
            inertia = m * (width ** 2 + depth ** 2) / 12.0
        else:
            inertia = floor_vector("inertias", inertias)
            if inertia.size != n:
                raise ValueError(f"inertias must have one value per floor ({n}) "
                                 f"(got {inertia.size})")
            rho2 = np.max([(cx - centres[:, 0]) ** 2 + (cy - centres[:, 1]) ** 2
                           for cx in (0.0, width) for cy in (0.0, depth)], axis=0)
            over = np.flatnonzero(inertia > m * rho2 * (1.0 + 1e-12))
            if over.size:
                k = int(over[0])
                raise ValueError(f"inertias[{k}] must be in (0, {m[k] * rho2[k]:.6g}] kg·m² "
                                 f"(mass {m[k]:g} kg, the farthest plan corner "
                                 f"{math.sqrt(rho2[k]):.6g} m from its centre of mass) (got "
                                 f"{inertia[k]:g})")
        elements = tuple(elements)
        if not elements and stiffness is None:
            raise ValueError("elements: give the lateral load-resisting elements (none given), "
                             "or the stiffness matrix")
        if elements and stiffness is not None:
            raise ValueError("stiffness: give the elements or the stiffness matrix, not both")
        for i, e in enumerate(elements):
            if not isinstance(e, LateralElement):
                raise ValueError(f"elements[{i}] must be a LateralElement (got {e!r})")
            e.storey_stiffnesses(n)
            for key, value, size in (("x", e.x, width), ("y", e.y, depth)):
                if not 0.0 <= value <= size:
                    raise ValueError(f"elements[{i}].{key} must lie inside the plan, in [0, "
                                     f"{size:g}] m (got {value:g})")
        if not isinstance(damping, DampingModel):
            raise ValueError(f"damping must be a DampingModel such as RayleighDamping or "
                             f"ModalDamping (got {damping!r})")
        if not isinstance(name, str):
            raise ValueError(f"name must be a string (got {name!r})")
        M = readonly(np.diag(np.column_stack([m, m, inertia]).ravel()))
        if stiffness is None:
            K = readonly(plan_stiffness_matrix(elements, centres))
        else:
            K = readonly(_given_stiffness(stiffness, 3 * n))
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "masses", readonly(m))
        frozen_set(self, "heights", readonly(h))
        frozen_set(self, "width", width)
        frozen_set(self, "depth", depth)
        frozen_set(self, "elements", elements)
        frozen_set(self, "mass_centres", readonly(centres))
        frozen_set(self, "inertias", readonly(inertia))
        frozen_set(self, "damping", damping)
        frozen_set(self, "name", name)
        frozen_set(self, "site_y", site_y)
        frozen_set(self, "stiffness", None if stiffness is None else K)
        self._check_restrained(K)
        damping.check(3 * n)
        C = readonly(damping.matrix(M, K))
        # the matrices, read-only (private: the methods hand out copies)
        self._M: NDArray[np.float64]
        self._K: NDArray[np.float64]
        self._C: NDArray[np.float64]
        frozen_set(self, "_M", M)
        frozen_set(self, "_K", K)
        frozen_set(self, "_C", C)

    def _check_restrained(self, K: NDArray[np.float64]) -> None:
        """Raise unless K is positive definite: the elements restrain every floor."""
        try:
            np.linalg.cholesky(K)
        except np.linalg.LinAlgError:
            w, v = np.linalg.eigh(K)
            mode = v[:, 0]
            dof = int(np.argmax(np.abs(mode)))
            raise ValueError(
                f"elements: they do not restrain floor {dof // 3 + 1} in "
                f"{FLOOR_DOFS[dof % 3]} (the stiffness matrix is singular: smallest eigenvalue "
                f"{w[0]:.3g}); give elements in two directions and at least two lines in one "
                f"of them, so that the floor cannot slide or twist freely") from None

    # ----------------------------------------------------------------- geometry
    @property
    def n_floors(self) -> int:
        """Number of floors (storeys)."""
        return int(self.masses.size)

    @property
    def n(self) -> int:
        """Number of DOFs, three a floor."""
        return 3 * self.n_floors

    @property
    def floor_levels(self) -> NDArray[np.float64]:
        """Elevation of each floor above ground [m]."""
        return np.cumsum(self.heights)

    @property
    def total_height(self) -> float:
        """Height of the roof [m]."""
        return float(np.sum(self.heights))

    @property
    def total_mass(self) -> float:
        """Sum of the floor masses [kg]."""
        return float(np.sum(self.masses))

    def dof(self, floor: int, component: str) -> int:
        """The DOF of ``floor`` (0-based) and ``component`` ``"x"``, ``"y"`` or ``"θ"``
        (also ``"theta"``)."""
        c = {"x": 0, "y": 1, "θ": 2, "theta": 2}.get(component)
        if c is None:
            raise ValueError(f"component must be 'x', 'y' or 'θ' (got {component!r})")
        if not 0 <= floor < self.n_floors:
            raise ValueError(f"floor must be in [0, {self.n_floors - 1}] (got {floor!r})")
        return 3 * floor + c

    def dof_labels(self) -> list[str]:
        """``'F1x', 'F1y', 'F1θ', 'F2x', …`` (1-based floors)."""
        return [f"F{j + 1}{c}" for j in range(self.n_floors) for c in FLOOR_DOFS]

    def point_weights(self, floor: int, x: float, y: float, direction: str | float = "x"
                      ) -> list[tuple[int, float]]:
        """``(DOF, weight)`` pairs that make the displacement [m] of the point ``(x, y)``
        (plan coordinates) of ``floor`` (0-based) along ``direction`` (``"x"``, ``"y"`` or
        an angle in degrees): ``c (u_x − (y − y_c) θ) + s (u_y + (x − x_c) θ)``."""
        c, s = direction_cosines(direction)
        xc, yc = self.mass_centres[floor]
        base = 3 * floor
        out = [(base, c), (base + 1, s), (base + 2, -c * (y - yc) + s * (x - xc))]
        return [(d, w) for d, w in out if w != 0.0]

    def point_displacement(self, u: ArrayLike, floor: int, x: float, y: float,
                           direction: str | float = "x") -> NDArray[np.float64]:
        """Displacement [m] of a point of a floor along a direction, from DOF histories
        ``u[..., N]`` (see :meth:`point_weights`)."""
        arr = np.asarray(u, dtype=float)
        return sum((w * arr[..., d] for d, w in self.point_weights(floor, x, y, direction)),
                   np.zeros(arr.shape[:-1]))

    def stiffness_eccentricity(self) -> NDArray[np.float64]:
        """Centre of stiffness minus centre of mass of each storey ``(e_x, e_y)`` [m].

        The centre of stiffness of storey j (Chopra §9.5.1, for elements along x and y):
        ``x_s = Σ k_yi x_i / Σ k_yi`` over the elements along y, ``y_s = Σ k_xi y_i / Σ k_xi``
        over those along x; inclined elements count by their components ``k cos²β``,
        ``k sin²β``. A storey with no element in a direction has NaN there (so does every
        storey of a building given by its stiffness matrix).
        """
        n = self.n_floors
        sx = np.zeros(n)
        sxy = np.zeros(n)
        sy = np.zeros(n)
        syx = np.zeros(n)
        for e in self.elements:
            k = e.storey_stiffnesses(n)
            c, s = e.cosines
            c2, s2 = c * c, s * s
            sx += k * c2
            sxy += k * c2 * e.y
            sy += k * s2
            syx += k * s2 * e.x
        with np.errstate(invalid="ignore", divide="ignore"):
            xs = np.where(sy > 0, syx / np.where(sy > 0, sy, 1.0), np.nan)
            ys = np.where(sx > 0, sxy / np.where(sx > 0, sx, 1.0), np.nan)
        return np.column_stack([xs - self.mass_centres[:, 0], ys - self.mass_centres[:, 1]])

    # ----------------------------------------------------------------- matrices
    def mass_matrix(self) -> NDArray[np.float64]:
        """``diag(m_1, m_1, I_1, m_2, …)`` [kg, kg·m²], (3n, 3n)."""
        return np.array(self._M)

    def stiffness_matrix(self) -> NDArray[np.float64]:
        """Stiffness matrix [N/m, N, N·m] from the elements (:func:`plan_stiffness_matrix`)."""
        return np.array(self._K)

    def damping_matrix(self) -> NDArray[np.float64]:
        """Damping matrix from the building's damping model."""
        return np.array(self._C)

    def influence_matrix(self) -> NDArray[np.float64]:
        """``R`` (3n × 2): column 0 the ground's x component, column 1 its y component."""
        r = np.zeros((self.n, 2))
        r[0::3, 0] = 1.0
        r[1::3, 1] = 1.0
        return r

    def modes(self) -> ModalResult:
        """Natural modes of the building in plan (lateral–torsional)."""
        return modal_result(self._M, self._K, self._C)

    @property
    def fundamental_period(self) -> float:
        """Period of the first mode [s]."""
        return float(self.modes().periods[0])

    def as_matrix_building(self) -> PlanMatrixBuilding:
        """This building as the row of buildings of a :class:`~pounding.model.PoundingModel`
        holds it: a :class:`PlanMatrixBuilding` with this building's M, K, C, the DOF labels
        ``F1x, F1y, F1θ, …``, every DOF at its floor's elevation, the ``u_x`` DOFs as the
        floors (they take the contacts along the row and have storey drifts) and the plan
        kept for the contacts' kinematics. Made once and remembered."""
        cached = self.__dict__.get("_as_matrix")
        if cached is None:
            cached = PlanMatrixBuilding(
                M=self._M, K=self._K, C=self._C,
                labels=tuple(self.dof_labels()), elevations=np.repeat(self.floor_levels, 3),
                r=self.influence_matrix()[:, 0], floors=list(range(0, self.n, 3)),
                name=self.name, plan=self)
            object.__setattr__(self, "_as_matrix", cached)
        return cached

    def __eq__(self, other: Any) -> bool:
        if not isinstance(other, PlanBuilding):
            return NotImplemented
        return (np.array_equal(self.masses, other.masses)
                and np.array_equal(self.heights, other.heights)
                and np.array_equal(self.mass_centres, other.mass_centres)
                and np.array_equal(self.inertias, other.inertias)
                and (self.width, self.depth, self.site_y, self.name, self.damping,
                     self.elements) == (other.width, other.depth, other.site_y, other.name,
                                        other.damping, other.elements)
                and np.array_equal(self._K, other._K))

    __hash__ = object.__hash__


def _given_stiffness(value: ArrayLike, size: int) -> NDArray[np.float64]:
    """A given stiffness matrix, checked: (size × size), finite, symmetric to 1e-10 of its
    largest entry (then symmetrised)."""
    try:
        K = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"stiffness must be a {size} × {size} matrix of numbers "
                         f"(got {type(value).__name__})") from None
    if K.shape != (size, size):
        raise ValueError(f"stiffness must be {size} × {size}, three DOFs a floor "
                         f"(got shape {K.shape})")
    if not np.all(np.isfinite(K)):
        i, j = np.argwhere(~np.isfinite(K))[0]
        raise ValueError(f"stiffness[{i}, {j}] must be finite (got {K[i, j]!r})")
    asym = np.abs(K - K.T)
    if asym.max() > 1e-10 * np.abs(K).max():
        i, j = np.unravel_index(np.argmax(asym), K.shape)
        raise ValueError(f"stiffness must be symmetric: stiffness[{i}, {j}] = {K[i, j]:.6g} "
                         f"but stiffness[{j}, {i}] = {K[j, i]:.6g}")
    return 0.5 * (K + K.T)


def plan_stiffness_matrix(elements: Sequence[LateralElement],
                          mass_centres: NDArray[np.float64]) -> NDArray[np.float64]:
    """Stiffness matrix (3n × 3n) of floors in plan joined by lateral elements.

    Element e in storey j deforms by ``a_j · q_j − a_{j−1} · q_{j−1}`` (the ground below
    storey 1), with ``a_j = (c, s, −c (y_e − y_cj) + s (x_e − x_cj))`` its direction cosines
    and lever arm about floor j's centre of mass; each storey adds ``k_ej b bᵀ`` with
    ``b`` that row over the two floors (Chopra §9.5.1; Kan & Chopra 1977).
    """
    n = mass_centres.shape[0]
    K = np.zeros((3 * n, 3 * n))
    for e in elements:
        k = e.storey_stiffnesses(n)
        c, s = e.cosines
        for j in range(n):
            if k[j] == 0.0:
                continue
            b = np.zeros(3 * n)
            for floor, sign in ((j, 1.0), (j - 1, -1.0)):
                if floor < 0:
                    continue
                xc, yc = mass_centres[floor]
                b[3 * floor: 3 * floor + 3] = sign * np.array(
                    [c, s, -c * (e.y - yc) + s * (e.x - xc)])
            K += k[j] * np.outer(b, b)
    return 0.5 * (K + K.T)
