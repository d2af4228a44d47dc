"""Modal analysis of a linear structure: natural periods, mode shapes, participation.

The undamped free-vibration eigenproblem ``K φ = ω² M φ`` (Chopra, *Dynamics of
Structures*, 4th ed., §10.2, eq. 10.2.4) is solved with :func:`scipy.linalg.eigh`, which
returns mode shapes already normalised to the mass matrix, ``Φᵀ M Φ = I`` (Chopra §10.6).

Conventions
-----------
* Modes are sorted by natural period, longest first (mode 1 is the fundamental mode).
* Each mode shape is mass-normalised (``M_n = φₙᵀ M φₙ = 1`` [kg·(1)²], so a mode shape has
  units of kg^-1/2) and its sign is fixed so that the roof (last) entry is positive. For a
  shear building the roof entry of every mode is non-zero (the stiffness matrix is an
  irreducible tridiagonal matrix), so the convention is always well defined.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
import scipy.linalg
from numpy.typing import ArrayLike, NDArray

__all__ = ["LinearStructure", "ModalResult", "eigenmodes", "modes", "square_pair"]


class LinearStructure(Protocol):
    """What :func:`modes` reads of a structure (a :class:`~pounding.structure.ShearBuilding`,
    a :class:`~pounding.structure.MatrixBuilding`): its matrices and influence vector."""

    def mass_matrix(self) -> NDArray[np.float64]:
        """``M`` [kg], shape (n, n)."""
        ...

    def stiffness_matrix(self) -> NDArray[np.float64]:
        """``K`` [N/m], shape (n, n)."""
        ...

    def damping_matrix(self) -> NDArray[np.float64]:
        """``C`` [N·s/m], shape (n, n)."""
        ...

    def influence_vector(self) -> NDArray[np.float64]:
        """``ι`` [-], shape (n,)."""
        ...


def square_pair(M: ArrayLike, K: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return ``M`` and ``K`` as float64 arrays after checking they are square and alike.

    Raises
    ------
    ValueError
        If either is not a finite square 2-D array, or their shapes differ.
    """
    out = []
    for label, A in (("M", M), ("K", K)):
        try:
            arr = np.array(A, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"{label} must be a square numeric matrix (got {A!r})") from None
        if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or arr.shape[0] == 0:
            raise ValueError(f"{label} must be a non-empty square matrix (got shape {arr.shape})")
        if not np.all(np.isfinite(arr)):
            raise ValueError(f"{label} must contain only finite values (got {arr.tolist()!r})")
        out.append(arr)
    if out[0].shape != out[1].shape:
        raise ValueError(f"M and K must have the same shape "
                         f"(got {out[0].shape} and {out[1].shape})")
    return out[0], out[1]


def eigenmodes(M: ArrayLike, K: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Natural circular frequencies and mass-normalised mode shapes of ``(M, K)``.

    Solves ``K φ = ω² M φ`` (Chopra §10.2, eq. 10.2.4) with :func:`scipy.linalg.eigh`.

    Parameters
    ----------
    M : array_like, shape (n, n)
        Symmetric positive-definite mass matrix [kg].
    K : array_like, shape (n, n)
        Symmetric positive-definite stiffness matrix [N/m].

    Returns
    -------
    omega : ndarray, shape (n,)
        Natural circular frequencies [rad/s], ascending (periods descending).
    phi : ndarray, shape (n, n)
        Mode shapes as columns, ``phi.T @ M @ phi = I`` [kg^-1/2]; sign chosen so that the
        last entry (the roof) is positive (or, if it is zero, the largest entry).

    Raises
    ------
    ValueError
        If the matrices are malformed, ``M`` is not positive definite, or ``K`` is not
        positive definite (a mechanism or an unrestrained structure).
    """
    Mf, Kf = square_pair(M, K)
    try:
        lam, phi = scipy.linalg.eigh(Kf, Mf)
    except np.linalg.LinAlgError as exc:
        raise ValueError(f"M must be symmetric positive definite ({exc})") from None
    if lam[0] <= 0.0:
        raise ValueError(f"K must be positive definite (got eigenvalue ω² = {lam[0]:g} rad²/s²)")
    order = np.argsort(lam, kind="stable")
    lam = lam[order]
    phi = np.ascontiguousarray(phi[:, order])
    for j in range(phi.shape[1]):
        col = phi[:, j]
        big = np.max(np.abs(col))
        ref = col[-1] if abs(col[-1]) > 1e-12 * big else col[np.argmax(np.abs(col))]
        if ref < 0.0:
            phi[:, j] = -col
    return np.sqrt(lam), phi


@dataclass(frozen=True, eq=False)
class ModalResult:
    """Modes of a structure, longest period first.

    Attributes
    ----------
    omegas : ndarray, shape (n,)
        Natural circular frequencies ωₙ [rad/s], ascending.
    periods : ndarray, shape (n,)
        Natural periods Tₙ = 2π/ωₙ [s], descending.
    shapes : ndarray, shape (n, n)
        Mass-normalised mode shapes φₙ as columns [kg^-1/2]; roof entry positive.
    participation_factors : ndarray, shape (n,)
        Γₙ = Lₙ/Mₙ with Lₙ = φₙᵀ M ι, Mₙ = φₙᵀ M φₙ (Chopra eq. 13.2.3) [kg^1/2 for
        mass-normalised shapes]; the product Γₙ φₙ (dimensionless) does not depend on the
        normalisation.
    effective_masses : ndarray, shape (n,)
        Effective modal masses Mₙ* = Lₙ²/Mₙ [kg] (Chopra §13.2); they sum to the total mass
        (Chopra §13.2, a consequence of the modal expansion of M ι).
    damping_ratios : ndarray, shape (n,)
        ζₙ = φₙᵀ C φₙ / (2 ωₙ Mₙ) [-] (from Cₙ = 2 ζₙ Mₙ ωₙ, Chopra §12.4); exact for
        classical damping (Rayleigh, modal), the diagonal approximation otherwise.
    total_mass : float
        Σ m_j [kg].
    """

    omegas: NDArray[np.float64]
    periods: NDArray[np.float64]
    shapes: NDArray[np.float64]
    participation_factors: NDArray[np.float64]
    effective_masses: NDArray[np.float64]
    damping_ratios: NDArray[np.float64]
    total_mass: float

    @property
    def n_modes(self) -> int:
        """Number of modes (= number of degrees of freedom)."""
        return int(self.omegas.shape[0])

    @property
    def frequencies(self) -> NDArray[np.float64]:
        """Cyclic natural frequencies fₙ = ωₙ/2π [Hz], shape (n,)."""
        return self.omegas / (2.0 * np.pi)

    @property
    def effective_mass_ratios(self) -> NDArray[np.float64]:
        """Mₙ*/Σm [-], shape (n,); sums to 1."""
        return self.effective_masses / self.total_mass

    @property
    def modal_contributions(self) -> NDArray[np.float64]:
        """Γₙ φₙ as columns [-], shape (n, n): the modal expansion of ι (Chopra §13.2.1).

        The columns sum to the influence vector ι (all ones for a shear building).
        """
        return self.shapes * self.participation_factors[np.newaxis, :]


def modal_result(M: ArrayLike, K: ArrayLike, C: ArrayLike | None = None,
                 r: ArrayLike | None = None) -> ModalResult:
    """Modal analysis of the matrices ``(M, K)``, optionally with ``C`` and influence ``r``.

    Parameters
    ----------
    M, K : array_like, shape (n, n)
        Mass [kg] and stiffness [N/m] matrices.
    C : array_like, shape (n, n), optional
        Damping matrix [N·s/m]; zero if omitted.
    r : array_like, shape (n,), optional
        Influence vector ι [-] of the ground motion; all ones if omitted.

    Returns
    -------
    ModalResult
    """
    omega, phi = eigenmodes(M, K)
    Mf = np.asarray(M, dtype=np.float64)
    n = Mf.shape[0]
    iota = np.ones(n) if r is None else np.asarray(r, dtype=np.float64).reshape(n)
    Cf = np.zeros((n, n)) if C is None else np.asarray(C, dtype=np.float64)
    Mn = np.einsum("in,ij,jn->n", phi, Mf, phi)           # generalised masses (≈ 1)
    Ln = phi.T @ (Mf @ iota)                               # Chopra eq. 13.2.3
    Cn = np.einsum("in,ij,jn->n", phi, Cf, phi)
    return ModalResult(
        omegas=omega,
        periods=2.0 * np.pi / omega,
        shapes=phi,
        participation_factors=Ln / Mn,
        effective_masses=Ln**2 / Mn,
        damping_ratios=Cn / (2.0 * omega * Mn),
        total_mass=float(iota @ Mf @ iota),
    )


def modes(building: LinearStructure) -> ModalResult:
    """Modal analysis of a shear building (or any :class:`LinearStructure`).

    Parameters
    ----------
    building : ShearBuilding
        The building; its mass, stiffness and damping matrices are used, with its ground
        motion influence vector (ι = 1 for a shear building).

    Returns
    -------
    ModalResult
        Periods [s] (longest first), circular frequencies [rad/s], mass-normalised shapes,
        participation factors, effective modal masses [kg] and modal damping ratios [-].

    Examples
    --------
    >>> from pounding.structure import ShearBuilding, modes
    >>> b = ShearBuilding.sdof(mass=1000.0, period=0.5)
    >>> float(round(modes(b).periods[0], 12))
    0.5
    """
    return modal_result(building.mass_matrix(), building.stiffness_matrix(),
                        building.damping_matrix(), building.influence_vector())
