"""Base-isolated buildings: a superstructure on an isolation storey, and its damping.

A base-isolated shear building (:meth:`pounding.structure.ShearBuilding.base_isolated`) has
``n + 1`` floors: floor 1 is the base slab (mass ``m_b``), carried by the isolation storey
(storey 1, between the ground and the base slab), whose shear follows the isolator's law
(:mod:`pounding.hysteresis.isolators`); floors 2 … n + 1 are the superstructure, whose
storeys stay linear (Kelly 1990, "Base isolation: linear theory and design", Earthquake
Spectra 6(2); Naeim & Kelly 1999, ch. 2). Only the isolation storey becomes an element row
of the kernel
(:attr:`pounding.structure.ShearBuilding.yielding_storeys` ``= (0,)``); the superstructure
stays in the linear stiffness matrix.

Damping. Rayleigh damping built on the initial stiffness of the whole isolated building
puts a large stiffness-proportional damper across the isolator (its initial stiffness is
the stiffest spring of the building) and damps the sliding with forces that are not
there; the recommended practice is to damp the superstructure only, on its fixed-base
modes, acting on the velocities *relative to the base* (Ryan & Polanco 2008, "Problems
with Rayleigh damping in base-isolated buildings", J. Struct. Eng. 134(11):1780–1784), and
to let the isolator dissipate by its hysteresis (plus a viscous coefficient if the
bearings have one). :class:`SuperstructureDamping` does that:

    C = Tᵀ C_s T + c_b e₁ e₁ᵀ,   T = [−1 | I]   (T u = u_s − 1 u_b, the drifts from the base)

with ``C_s`` the superstructure's own damping matrix built from its fixed-base ``M_s``,
``K_s`` (the lower-right blocks of the isolated building's ``M`` and ``K``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.damping import DampingModel
from pounding.units import format_value
from pounding.validation import non_negative

__all__ = ["SuperstructureDamping"]


@dataclass(frozen=True)
class SuperstructureDamping(DampingModel):
    """The superstructure's damping acting on drifts from the base, plus an optional viscous
    isolator (module docstring).

    Parameters
    ----------
    superstructure : DampingModel
        The damping model of the fixed-base superstructure (floors 2 … n of the building).
    isolator : float
        Viscous coefficient of the isolation storey ``c_b`` [N·s/m] (default 0: the
        isolator damps by its hysteresis only).
    """

    superstructure: DampingModel
    isolator: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.superstructure, DampingModel):
            raise ValueError(f"superstructure: expected a DampingModel (got "
                             f"{self.superstructure!r})")
        object.__setattr__(self, "isolator", non_negative("isolator_damping", self.isolator))

    def check(self, n_dof: int) -> None:
        if n_dof < 2:
            raise ValueError(f"damping: a base-isolated building needs a base slab and at "
                             f"least one floor above it (got {n_dof} floor)")
        self.superstructure.check(n_dof - 1)

    def readable(self) -> str:
        """``superstructure (…) on the base; isolator c = … N·s/m``."""
        return (f"superstructure ({self.superstructure.readable()}) relative to the base; "
                f"isolator c = {format_value(self.isolator)} N·s/m")

    def matrix(self, M: ArrayLike, K: ArrayLike) -> NDArray[np.float64]:
        """``C = Tᵀ C_s T + c_b e₁ e₁ᵀ`` [N·s/m], shape (n, n)."""
        Mf = np.asarray(M, dtype=float)
        Kf = np.asarray(K, dtype=float)
        n = Mf.shape[0]
        Cs = self.superstructure.matrix(Mf[1:, 1:], Kf[1:, 1:])
        T = np.hstack([-np.ones((n - 1, 1)), np.eye(n - 1)])
        C = T.T @ Cs @ T
        C[0, 0] += self.isolator
        return 0.5 * (C + C.T)
