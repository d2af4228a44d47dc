"""The shear building: lumped floor masses on massless storeys that deform only in shear.

Model (Chopra, *Dynamics of Structures*, 4th ed., §9.2)
-------------------------------------------------------
Floor ``j`` (``j = 1 … n``; floor 1 is the first suspended floor above the ground, floor
``n`` the roof) carries the lumped mass ``m_j`` [kg] and moves laterally by ``u_j`` [m]
relative to the ground. Storey ``j`` joins floor ``j − 1`` (the ground for ``j = 1``) to
floor ``j``; it has lateral stiffness ``k_j`` [N/m] and height ``h_j`` [m]. The storey shear
is ``V_j = k_j (u_j − u_{j−1})`` with ``u_0 = 0`` — or, for a building with a
:attr:`ShearBuilding.storey_law`, the shear of that yielding law
(:mod:`pounding.hysteresis`), whose elastic stiffness is ``k_j``. In Python (0-based) floor ``j`` is index
``j − 1`` of every array. A single-degree-of-freedom (SDOF) system is the one-storey case.

Relative to the ground, the equation of motion is (Chopra §9.4.1)

    M ü + C u̇ + K u = −M ι a_g(t) + (contact forces),

with ``M = diag(m)`` [kg], the tridiagonal ``K`` [N/m] of :meth:`ShearBuilding.stiffness_matrix`,
``C`` [N·s/m] from the building's damping model and influence vector ``ι = 1``.

All arrays handed out are C-contiguous float64, ready for a compiled time stepper.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.hysteresis.base import StoreyLaw
from pounding.hysteresis.isolators import Isolator
from pounding.structure.damping import DampingModel, ModalDamping, RayleighDamping
from pounding.structure.floor_arrays import MAX_FLOORS, SMALLEST, floor_vector, readonly
from pounding.structure.isolation import SuperstructureDamping
from pounding.structure.modal import ModalResult, modes
from pounding.validation import positive

__all__ = ["ShearBuilding", "shear_stiffness_matrix"]

_DEFAULT_DAMPING = RayleighDamping()
"""A building's damping when none is given: 5 % Rayleigh damping at modes 1 and 2."""


def shear_stiffness_matrix(stiffnesses: ArrayLike) -> NDArray[np.float64]:
    """Stiffness matrix ``K`` [N/m] of a fixed-base shear building, shape (n, n).

    ``K[j, j] = k_j + k_{j+1}`` (``k_{n+1} = 0``), ``K[j, j+1] = K[j+1, j] = −k_{j+1}``
    (Chopra §9.2, the two-storey shear frame generalised to n storeys).

    Parameters
    ----------
    stiffnesses : array_like, shape (n,)
        Storey lateral stiffnesses ``k_1 … k_n`` [N/m], ground storey first.
    """
    return _chain_matrix(floor_vector("stiffnesses", stiffnesses))


def _chain_matrix(k: NDArray[np.float64]) -> NDArray[np.float64]:
    """The shear-building ``K`` of storey stiffnesses ``k`` (entries may be 0: a storey left
    out)."""
    n = k.size
    K = np.zeros((n, n), dtype=np.float64)
    idx = np.arange(n)
    K[idx, idx] = k
    K[idx[:-1], idx[:-1]] += k[1:]
    K[idx[:-1], idx[1:]] = -k[1:]
    K[idx[1:], idx[:-1]] = -k[1:]
    return K


def _storey_indices(value: Any, n: int, has_law: bool) -> tuple[int, ...]:
    """``yielding_storeys`` as a sorted tuple of distinct 0-based storey indices < n."""
    if not has_law:
        raise ValueError(f"yielding_storeys: needs a storey_law (got yielding_storeys="
                         f"{value!r} without one)")
    try:
        idx = [int(i) for i in value]
        ok = all(float(i) == float(j) for i, j in zip(idx, value))
    except (TypeError, ValueError):
        ok = False
    if not ok or not idx:
        raise ValueError(f"yielding_storeys: need a non-empty sequence of storey indices "
                         f"(0-based integers) (got {value!r})")
    for i in idx:
        if not 0 <= i < n:
            raise ValueError(f"yielding_storeys: storey index {i} is not in 0 … {n - 1} "
                             f"(the building has {n} storeys)")
    if len(set(idx)) != len(idx):
        raise ValueError(f"yielding_storeys: a storey given twice (got {value!r})")
    return tuple(sorted(idx))


@dataclass(frozen=True, eq=False, init=False)
class ShearBuilding:
    """A multi-storey shear building with lumped floor masses (n storeys, n DOFs).

    Parameters
    ----------
    masses : array_like, shape (n,)
        Floor masses ``m_1 … m_n`` [kg], floor 1 (first suspended floor) first.
    stiffnesses : array_like, shape (n,)
        Storey lateral stiffnesses ``k_1 … k_n`` [N/m]; storey 1 joins floor 1 to the ground.
    heights : array_like, shape (n,)
        Storey heights ``h_1 … h_n`` [m].
    damping : DampingModel
        How the damping matrix is built; default 5 % Rayleigh damping anchored at modes 1
        and 2 (the usual choice in pounding studies).
    name : str
        A label for tables and plots.
    storey_law : StoreyLaw, optional
        How the storeys yield (:class:`pounding.hysteresis.Bilinear`,
        :class:`pounding.hysteresis.BoucWen`); ``None`` (default) keeps them linear. Its
        elastic stiffness is ``stiffnesses``, which also sets the periods and the damping
        matrix (initial-stiffness Rayleigh damping).
    yielding_storeys : sequence of int, optional
        0-based indices of the storeys that follow ``storey_law`` (the others stay linear);
        ``None`` (default): every storey. A base-isolated building
        (:meth:`base_isolated`) has ``(0,)``: its isolation storey.
    isolator : Isolator, optional
        Set by :meth:`base_isolated` only: the isolation bearing storey 1 stands for
        (:mod:`pounding.hysteresis.isolators`), so that outputs report it as a bearing, apart
        from the storeys; ``None`` for a fixed-base building.

    Raises
    ------
    ValueError
        Naming the field (and entry) at fault: an entry that is not finite and positive,
        arrays of different lengths, a damping model that does not fit the building.

    Notes
    -----
    Instances are immutable; the stored arrays are read-only float64. The matrix methods
    return fresh writable copies.

    Examples
    --------
    >>> b = ShearBuilding(masses=[2.0e5, 1.0e5], stiffnesses=[4.0e7, 2.0e7],
    ...                   heights=[3.5, 3.0], name="A")
    >>> b.n, float(b.total_height)
    (2, 6.5)
    """

    masses: NDArray[np.float64]
    stiffnesses: NDArray[np.float64]
    heights: NDArray[np.float64]
    damping: DampingModel
    name: str
    storey_law: StoreyLaw | None
    yielding_storeys: tuple[int, ...] | None
    isolator: Isolator | None

    def __init__(self, masses: ArrayLike, stiffnesses: ArrayLike, heights: ArrayLike,
                 damping: DampingModel = _DEFAULT_DAMPING, name: str = "",
                 storey_law: StoreyLaw | None = None,
                 yielding_storeys: Sequence[int] | None = None,
                 isolator: Isolator | None = None) -> None:
        m = floor_vector("masses", masses)
        k = floor_vector("stiffnesses", stiffnesses)
        h = floor_vector("heights", heights)
        for label, arr in (("stiffnesses", k), ("heights", h)):
            if arr.size != m.size:
                raise ValueError(f"{label} must have one value per floor, as many as masses "
                                 f"({m.size}) (got {arr.size})")
        if not isinstance(damping, DampingModel):
            raise ValueError(f"damping must be a DampingModel such as RayleighDamping or "
                             f"ModalDamping (got {damping!r})")
        if not isinstance(name, str):
            raise ValueError(f"name must be a string (got {name!r})")
        if storey_law is not None and not isinstance(storey_law, StoreyLaw):
            raise ValueError(f"storey_law must be a StoreyLaw such as Bilinear or BoucWen, or "
                             f"None for linear storeys (got {storey_law!r})")
        storeys = (None if yielding_storeys is None
                   else _storey_indices(yielding_storeys, m.size, storey_law is not None))
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "damping", damping)
        frozen_set(self, "name", name)
        frozen_set(self, "storey_law", storey_law)
        frozen_set(self, "yielding_storeys", storeys)
        frozen_set(self, "isolator", isolator)
        if storey_law is not None:
            # one yield value, or one per yielding storey
            storey_law.yield_forces(k[list(self._yielding(m.size))])
        frozen_set(self, "masses", m)
        frozen_set(self, "stiffnesses", k)
        frozen_set(self, "heights", h)
        damping.check(m.size)
        M = readonly(np.diag(m))
        K = readonly(shear_stiffness_matrix(k))
        # Build C now so that a damping model unfit for this building fails here, early.
        C = readonly(damping.matrix(M, K))
        # the matrices, read-only (private: the methods hand out copies)
        self._M: NDArray[np.float64]
        self._K: NDArray[np.float64]
        self._C: NDArray[np.float64]
        frozen_set(self, "_M", M)
        frozen_set(self, "_K", K)
        frozen_set(self, "_C", C)

    # ----------------------------------------------------------------- constructors
    @classmethod
    def sdof(cls, mass: float, stiffness: float | None = None, period: float | None = None,
             damping_ratio: float = 0.05, height: float = 3.0, name: str = "SDOF"
             ) -> ShearBuilding:
        """A single-degree-of-freedom system (a one-storey shear building).

        Parameters
        ----------
        mass : float
            Lumped mass ``m`` [kg].
        stiffness : float, optional
            Lateral stiffness ``k`` [N/m]. Give exactly one of ``stiffness`` and ``period``.
        period : float, optional
            Natural period ``T`` [s]; then ``k = m (2π/T)²`` (Chopra §2.1,
            ``ωₙ = √(k/m)``, ``Tₙ = 2π/ωₙ``).
        damping_ratio : float
            Viscous damping ratio ζ [-]; ``c = 2 ζ m ω`` (:class:`ModalDamping`).
        height : float
            Storey height [m], the elevation of the mass.
        name : str
            Label.
        """
        if (stiffness is None) == (period is None):
            raise ValueError("give exactly one of stiffness and period "
                             f"(got stiffness={stiffness!r}, period={period!r})")
        m = positive("mass", mass)
        if stiffness is None:
            T = positive("period", period)  # type: ignore[arg-type]
            k = m * (2.0 * math.pi / T) ** 2
            if not SMALLEST <= k < math.inf:
                raise ValueError(f"mass {m:g} kg with period {T:g} s gives a stiffness "
                                 f"m (2π/T)² = {k:g} N/m, outside the floating-point range; "
                                 "check mass and period")
        else:
            k = positive("stiffness", stiffness)
        h = positive("height", height)
        return cls(masses=np.array([m]), stiffnesses=np.array([k]), heights=np.array([h]),
                   damping=ModalDamping(damping_ratio), name=name)

    @classmethod
    def uniform(cls, n_storeys: int, mass: float, stiffness: float, height: float = 3.0,
                damping: DampingModel | None = None, name: str = "") -> ShearBuilding:
        """A building whose floors all have the same mass, stiffness and storey height.

        Parameters
        ----------
        n_storeys : int
            Number of storeys ``n`` (>= 1).
        mass : float
            Mass of every floor [kg].
        stiffness : float
            Lateral stiffness of every storey [N/m].
        height : float
            Height of every storey [m].
        damping : DampingModel, optional
            Default: 5 % Rayleigh damping in modes 1 and 2.
        name : str
            Label.

        Notes
        -----
        Its natural frequencies have the closed form
        ``ω_j = 2 √(k/m) sin((2j − 1) π / (2 (2n + 1)))``, ``j = 1 … n`` (the fixed–free
        uniform spring–mass chain; see the tests and ``docs/structures.md``).
        """
        if (isinstance(n_storeys, bool) or not isinstance(n_storeys, (int, np.integer))
                or n_storeys < 1):
            raise ValueError(f"n_storeys must be an integer >= 1 (got {n_storeys!r})")
        if n_storeys > MAX_FLOORS:
            raise ValueError(f"n_storeys must be at most {MAX_FLOORS} (got {n_storeys!r})")
        m = positive("mass", mass)
        k = positive("stiffness", stiffness)
        h = positive("height", height)
        n = int(n_storeys)
        return cls(masses=np.full(n, m), stiffnesses=np.full(n, k), heights=np.full(n, h),
                   damping=RayleighDamping() if damping is None else damping, name=name)

    def with_period(self, period: float) -> ShearBuilding:
        """A copy with every storey stiffness scaled so the fundamental period is ``period``.

        Scaling ``K`` by ``s`` scales every ``ωₙ²`` by ``s`` (``K φ = ω² M φ``), so
        ``s = (T₁/T)²``; mode shapes, masses and the damping model are kept.

        Parameters
        ----------
        period : float
            Target fundamental period [s].
        """
        T = positive("period", period)
        s = (self.fundamental_period / T) ** 2
        k = self.stiffnesses * s
        if not np.all((k >= SMALLEST) & np.isfinite(k)):
            raise ValueError(f"period {T:g} s scales the storey stiffnesses by {s:g}, outside "
                             f"the floating-point range (got {k.min():g} … {k.max():g} N/m); "
                             "check period and the masses")
        return dataclasses.replace(self, stiffnesses=k)

    @classmethod
    def base_isolated(cls, superstructure: ShearBuilding, base_mass: float,
                      isolator: Isolator, base_height: float = 1.0,
                      isolator_damping: float = 0.0, name: str | None = None) -> ShearBuilding:
        """A base-isolated building: ``superstructure`` on a base slab on ``isolator``
        (:mod:`pounding.structure.isolation`).

        Parameters
        ----------
        superstructure : ShearBuilding
            The fixed-base superstructure (linear storeys; its damping model becomes the
            superstructure's damping, relative to the base:
            :class:`~pounding.structure.isolation.SuperstructureDamping`).
        base_mass : float
            Mass of the base slab ``m_b`` [kg] (floor 1 of the isolated building).
        isolator : Isolator
            :class:`pounding.hysteresis.isolators.BilinearIsolator` or
            :class:`pounding.hysteresis.isolators.FrictionPendulum` (one equivalent bearing
            for the whole isolation system; a friction pendulum without a weight carries the
            whole building, ``W = g (m_b + Σ m_s)``).
        base_height : float
            Height of the isolation storey [m]: the base slab's elevation.
        isolator_damping : float
            Viscous coefficient across the isolator [N·s/m] (default 0).
        name : str, optional
            Default: the superstructure's name.

        Returns
        -------
        ShearBuilding
            ``n + 1`` floors, storey 1 the isolator (stiffness = the isolator's initial
            stiffness, ``yielding_storeys = (0,)``).

        Examples
        --------
        >>> from pounding.hysteresis.isolators import FrictionPendulum
        >>> sup = ShearBuilding.uniform(3, 1.0e5, 1.0e8)
        >>> b = ShearBuilding.base_isolated(sup, 1.5e5, FrictionPendulum(radius=2.0, mu=0.05))
        >>> b.n, b.yielding, [round(float(z), 1) for z in b.floor_levels]
        (4, (0,), [1.0, 4.0, 7.0, 10.0])
        """
        if not isinstance(superstructure, ShearBuilding):
            raise ValueError(f"superstructure: expected a ShearBuilding (got "
                             f"{type(superstructure).__name__})")
        if superstructure.storey_law is not None:
            raise ValueError("superstructure: its storeys must be linear (got storey_law="
                             f"{superstructure.storey_law.describe()})")
        if not isinstance(isolator, Isolator):
            raise ValueError(f"isolator: expected a BilinearIsolator or FrictionPendulum (got "
                             f"{isolator!r})")
        mb = positive("base_mass", base_mass)
        hb = positive("base_height", base_height)
        iso = isolator.carrying(mb + superstructure.total_mass)
        return cls(
            masses=np.concatenate([[mb], superstructure.masses]),
            stiffnesses=np.concatenate([[iso.stiffness], superstructure.stiffnesses]),
            heights=np.concatenate([[hb], superstructure.heights]),
            damping=SuperstructureDamping(superstructure.damping, isolator_damping),
            name=superstructure.name if name is None else name,
            storey_law=iso.law(), yielding_storeys=(0,), isolator=iso)

    def with_storey_law(self, law: StoreyLaw | None,
                        storeys: tuple[int, ...] | None = None) -> ShearBuilding:
        """A copy whose storeys follow ``law`` (None: linear), e.g.
        ``b.with_storey_law(Bilinear(yield_drift=0.01, hardening=0.05))``; ``storeys``
        (0-based) limits it to those storeys (an isolated building's storey 1 is then no
        bearing: :attr:`isolator` is dropped)."""
        return dataclasses.replace(self, storey_law=law,
                                   yielding_storeys=storeys if law is not None else None,
                                   isolator=None)

    def _yielding(self, n: int) -> tuple[int, ...]:
        if self.storey_law is None:
            return ()
        return tuple(range(n)) if self.yielding_storeys is None else self.yielding_storeys

    @property
    def yielding(self) -> tuple[int, ...]:
        """0-based indices of the storeys that follow :attr:`storey_law` (empty if none)."""
        return self._yielding(self.n)

    @property
    def is_inelastic(self) -> bool:
        """True if some storeys follow a yielding :attr:`storey_law`."""
        return self.storey_law is not None

    def yielding_storey_dofs(self) -> list[tuple[int, int, int, float]]:
        """``(lower, upper, rock, lever)`` of every yielding storey (:attr:`yielding` order):
        the DOFs below (−1: the ground) and above it; on a fixed base no rocking DOF (−1)
        and no lever (0 m) (a building on a flexible base has them:
        :meth:`pounding.structure.foundation.FlexibleBaseBuilding.yielding_storey_dofs`)."""
        return [(j - 1 if j > 0 else -1, j, -1, 0.0) for j in self.yielding]

    def storey_law_params(self) -> NDArray[np.float64]:
        """Constants of the law of every yielding storey (:attr:`yielding` order), shape
        (len(yielding), P) (see :mod:`pounding.hysteresis.base`); raises if the storeys are
        linear."""
        if self.storey_law is None:
            raise ValueError(f"building {self.name!r}: its storeys are linear (no storey_law)")
        return self.storey_law.params(self.stiffnesses[list(self.yielding)])

    @property
    def yield_forces(self) -> NDArray[np.float64] | None:
        """Storey yield shears [N] (n,), NaN for the storeys that stay linear; None if every
        storey is linear."""
        if self.storey_law is None:
            return None
        out = np.full(self.n, np.nan)
        ys = list(self.yielding)
        out[ys] = self.storey_law.yield_forces(self.stiffnesses[ys])
        return out

    def linear_stiffness_matrix(self) -> NDArray[np.float64]:
        """``K`` [N/m] of the storeys that stay linear (yielding storeys left out; their
        shear comes from their law), shape (n, n)."""
        ys = self.yielding
        if not ys:
            return self.stiffness_matrix()
        if len(ys) == self.n:
            return np.zeros((self.n, self.n))
        k = np.array(self.stiffnesses)
        k[list(ys)] = 0.0
        return _chain_matrix(k)

    # ----------------------------------------------------------------- geometry
    @property
    def n(self) -> int:
        """Number of storeys = floors = degrees of freedom."""
        return int(self.masses.size)

    @property
    def floor_levels(self) -> NDArray[np.float64]:
        """Elevation of each floor above the ground [m], shape (n,): cumulative storey heights."""
        return np.cumsum(self.heights)

    @property
    def total_height(self) -> float:
        """Roof elevation above the ground [m]."""
        return float(np.sum(self.heights))

    @property
    def total_mass(self) -> float:
        """Sum of the floor masses [kg]."""
        return float(np.sum(self.masses))

    # ----------------------------------------------------------------- matrices
    def mass_matrix(self) -> NDArray[np.float64]:
        """Diagonal mass matrix ``M = diag(m_1 … m_n)`` [kg], shape (n, n)."""
        return np.array(self._M)

    def stiffness_matrix(self) -> NDArray[np.float64]:
        """Tridiagonal shear-building stiffness matrix ``K`` [N/m], shape (n, n).

        See :func:`shear_stiffness_matrix` (Chopra §9.2).
        """
        return np.array(self._K)

    def damping_matrix(self) -> NDArray[np.float64]:
        """Damping matrix ``C`` [N·s/m], shape (n, n), from :attr:`damping`."""
        return np.array(self._C)

    def influence_vector(self) -> NDArray[np.float64]:
        """Ground-motion influence vector ``ι`` [-], shape (n,): all ones (Chopra §9.4.1)."""
        return np.ones(self.n, dtype=np.float64)

    # ----------------------------------------------------------------- dynamics
    def modes(self) -> ModalResult:
        """Modal analysis; see :func:`pounding.structure.modal.modes`."""
        return modes(self)

    @property
    def fundamental_period(self) -> float:
        """Period of mode 1 [s]."""
        return float(self.modes().periods[0])

    # ----------------------------------------------------------------- value semantics
    def __eq__(self, other: Any) -> bool:
        if not isinstance(other, ShearBuilding):
            return NotImplemented
        return (np.array_equal(self.masses, other.masses)
                and np.array_equal(self.stiffnesses, other.stiffnesses)
                and np.array_equal(self.heights, other.heights)
                and self.damping == other.damping and self.name == other.name
                and self.storey_law == other.storey_law
                and self.yielding == other.yielding)

    __hash__ = None  # type: ignore[assignment]
