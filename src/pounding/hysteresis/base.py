"""The storey-law contract: force–drift laws of a shear building's storeys.

A storey law is to a storey what a contact law (:mod:`pounding.contact.base`) is to a gap,
and what an OpenSees uniaxial material is to a ``zeroLength`` element: it maps the storey
drift and its rate to the storey shear, with a small state. The linear storey of
:class:`pounding.structure.ShearBuilding` (``V = k d``) is the default; the laws here let
storeys yield.

Contract
--------
1. **Sign convention.** The drift of storey ``j`` is ``d = u_j − u_{j−1}`` [m] (``u_0 = 0``:
   the ground), its rate ``ḋ`` [m/s]. The storey shear ``V`` [N] is the force the storey
   exerts on the floor above it, positive when it resists a positive drift: the floor above
   receives ``−V``, the floor below ``+V``.
2. **Constants.** A law's constants are a float64 row of :data:`PARAMS_SIZE` numbers; the
   first two are always the elastic (initial) stiffness ``k`` [N/m] — the building's storey
   stiffness, so modal analysis and Rayleigh damping use it — and the yield force ``F_y``
   [N]. Its family is an integer :attr:`StoreyLaw.code`.
3. **Trial, then commit.** ``trial(p0 … p5, d, ḋ, z, d_c, V_c)`` is pure and scalar and
   returns ``(V, ∂V/∂d, ż)``. ``(d_c, V_c)`` is the committed drift and shear
   (:data:`STATE_SIZE` numbers per storey); the caller commits ``(d, V)`` when a step is
   accepted. Within a step along which ``ḋ`` keeps its sign — the time stepper ends steps
   where a yielding storey's drift rate changes sign — the trial from the step's starting
   state is exact: a rate-independent law's response to a monotonic drift increment
   depends only on where it starts and ends.
4. **Internal variable.** A law with an evolution equation (Bouc–Wen) carries one
   dimensionless variable ``z`` that the caller integrates *with the motion*, as one more
   first-order equation ``ż = trial(...)[2]``; laws without one return ``ż = 0``.
5. **Energy.** :func:`pounding.hysteresis.dispatch.storey_recoverable` is the elastic
   (recoverable) energy stored in the storey: for the bilinear law ``V²/(2k)``, what it gives
   back when unloaded to zero shear along its elastic branch; for Bouc–Wen the energy of its
   two springs, ``½ α k d² + ½ (1 − α) F_y d_y z²`` (the usual convention: for β = γ it
   differs from the unloading-branch energy by terms of order ``α``). The work ``∫V ḋ dt``
   done on the storey minus it is the *hysteretic* energy (dissipated by yielding, plus the
   energy locked in the hardening branch, as is customary in seismic energy balances, e.g.
   Uang & Bertero 1990).
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

PARAMS_SIZE: int = 6
"""Every storey law's constants fit in six numbers (zero-padded): ``[k, F_y, …]``."""

P_K: int = 0
P_FY: int = 1

D_C: int = 0
V_C: int = 1
STATE_SIZE: int = 2
"""Committed state of a storey: drift ``d_c`` [m] and shear ``V_c`` [N]."""

# Law codes for the compiled dispatcher (never reuse a number).
ELASTIC: int = 0
BILINEAR: int = 1
BOUC_WEN: int = 2


def per_storey(name: str, value: float | ArrayLike, n: int) -> NDArray[np.float64]:
    """``value`` as ``n`` finite positive floats: a scalar is repeated for every storey."""
    arr = np.atleast_1d(np.asarray(value, dtype=float))
    if arr.size == 1:
        arr = np.full(n, float(arr[0]))
    if arr.shape != (n,):
        raise ValueError(f"{name}: need one value or {n} (one per storey), got {arr.size}")
    bad = ~(np.isfinite(arr) & (arr > 0.0))
    if np.any(bad):
        j = int(np.argmax(bad))
        raise ValueError(f"{name}[{j}]: must be finite and > 0 (got {arr[j]!r})")
    return arr


def _scalar_or_list(value: float | ArrayLike | None) -> float | tuple[float, ...] | None:
    if value is None:
        return None
    arr = np.atleast_1d(np.asarray(value, dtype=float))
    return float(arr[0]) if arr.size == 1 and np.ndim(value) == 0 else tuple(float(v) for v in arr)


@dataclass(frozen=True)
class StoreyLaw(ABC):
    """Base of every yielding storey law. Give exactly one of ``yield_force`` [N] or
    ``yield_drift`` [m] (a scalar for every storey, or one value per storey); the elastic
    stiffness is the building's storey stiffness."""

    yield_force: float | tuple[float, ...] | None = None
    yield_drift: float | tuple[float, ...] | None = None

    code: ClassVar[int]
    label: ClassVar[str]

    def __post_init__(self) -> None:
        if (self.yield_force is None) == (self.yield_drift is None):
            raise ValueError(f"{self.label}: give exactly one of yield_force [N] or "
                             f"yield_drift [m] (got yield_force={self.yield_force!r}, "
                             f"yield_drift={self.yield_drift!r})")
        name = "yield_force" if self.yield_force is not None else "yield_drift"
        value = getattr(self, name)
        per_storey(name, value, np.atleast_1d(np.asarray(value, dtype=float)).size)
        object.__setattr__(self, name, _scalar_or_list(value))
        self._check()

    def _check(self) -> None:
        """Validate the law's own constants (subclasses)."""

    def yield_forces(self, stiffness: ArrayLike) -> NDArray[np.float64]:
        """Yield force of every storey [N] for storey stiffnesses ``stiffness`` [N/m]."""
        k = np.asarray(stiffness, dtype=float)
        if self.yield_force is not None:
            return per_storey("yield_force", self.yield_force, k.size)
        assert self.yield_drift is not None  # __post_init__ requires exactly one of the two
        return per_storey("yield_drift", self.yield_drift, k.size) * k

    def params(self, stiffness: ArrayLike) -> NDArray[np.float64]:
        """Constants of every storey, shape ``(n, PARAMS_SIZE)``: ``[k, F_y, …]``."""
        k = np.asarray(stiffness, dtype=float)
        out = np.zeros((k.size, PARAMS_SIZE))
        out[:, P_K] = k
        out[:, P_FY] = self.yield_forces(k)
        extra = self._extra()
        out[:, 2: 2 + len(extra)] = extra
        return out

    @abstractmethod
    def _extra(self) -> tuple[float, ...]:
        """The law's constants after ``k`` and ``F_y``."""

    @property
    def has_internal_variable(self) -> bool:
        """True if the law carries a ``z`` integrated with the motion (contract step 4)."""
        return False

    def unloading_stiffness(self, params: NDArray[np.float64], z: float) -> float:
        """Tangent stiffness [N/m] when the storey unloads (its drift moving against its
        shear) from internal variable ``z``, used for the residual drift. Elastic ``k``
        unless overridden."""
        return float(params[P_K])

    def describe(self) -> str:
        """One line: the label and the constants."""
        return f"{self.label}({self._describe()})"

    def _describe(self) -> str:
        y = (f"yield_force={self.yield_force!r}" if self.yield_force is not None
             else f"yield_drift={self.yield_drift!r}")
        return y
