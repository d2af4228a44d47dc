"""A building's peak response from a spectrum, fundamental mode only: its period, damping
ratio and modal contribution (:func:`fundamental_mode`) and the peak floor displacements
(:func:`spectral_displacements`, Chopra, *Dynamics of Structures*, §13.8).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from pounding.spectra.design import DesignSpectrum

if TYPE_CHECKING:
    from pounding.structure.modal import ModalResult

__all__ = ["fundamental_mode", "spectral_displacements"]

FloatArray = NDArray[np.float64]


class ModalBuilding(Protocol):
    """A building that gives its natural modes (a shear or a matrix building)."""

    def modes(self) -> ModalResult:
        """Natural modes, longest period first."""
        ...


def fundamental_mode(building: ModalBuilding) -> tuple[float, float, FloatArray]:
    """Period T1 [s], damping ratio ζ1 [-] and ``Γ1 φ1`` [-] (per floor) of mode 1."""
    m = building.modes()
    return (float(m.periods[0]), float(m.damping_ratios[0]),
            np.asarray(m.modal_contributions[:, 0], dtype=float))


def spectral_displacements(building: ModalBuilding, spectrum: DesignSpectrum) -> FloatArray:
    """Peak floor displacements [m] from the fundamental mode: ``|Γ1 φ1(floor)| Sd(T1)``.

    Chopra §13.8 (modal response spectrum analysis) keeping mode 1 only: its floor
    displacements are ``u_j = Γ1 φ_j1 D1`` with ``D1 = Sd(T1)``. Higher modes are left out
    (they add little to displacements of regular buildings).
    """
    t1, _, gphi = fundamental_mode(building)
    return np.abs(gphi) * float(spectrum.sd(t1))
