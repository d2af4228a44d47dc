"""Inherent (structural) damping of a building: how the damping matrix ``C`` is built.

A damping model is data: a frozen dataclass holding the target damping ratios and where
they apply. Its one method, :meth:`DampingModel.matrix`, turns a mass matrix ``M`` [kg] and a
stiffness matrix ``K`` [N/m] into a damping matrix ``C`` [N·s/m], shape (n, n), float64.

Both models here are *classical* damping: ``C`` is diagonalised by the undamped modes, so
the modal damping ratio of mode n is ``ζₙ = φₙᵀ C φₙ / (2 ωₙ Mₙ)``.

* :class:`RayleighDamping` — ``C = a₀ M + a₁ K``, with ``a₀, a₁`` chosen so that two modes (or
  two periods) have the requested ratios (Chopra, *Dynamics of Structures*, 4th ed.,
  §11.4.1).
* :class:`ModalDamping` — the same ratio ζ in every mode, by superposition of modal damping
  matrices ``C = M Φ diag(2 ζ ωₙ / Mₙ) Φᵀ M`` (Chopra §11.4.3).

Equation numbers differ between editions of Chopra; the formulas are written out in full in
each docstring.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass, fields, is_dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.structure.modal import eigenmodes, square_pair
from pounding.units import format_value
from pounding.validation import in_range, positive

__all__ = ["DampingModel", "ModalDamping", "RayleighDamping", "rayleigh_coefficients"]


def _ratio(name: str, value: float) -> float:
    return in_range(name, value, 0.0, 1.0)


def _mode_number(name: str, value: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise ValueError(f"{name} must be a mode number, an integer >= 1 (got {value!r})")
    return int(value)


def rayleigh_coefficients(omega_i: float, omega_j: float, zeta_i: float,
                          zeta_j: float) -> tuple[float, float]:
    """Rayleigh coefficients ``(a₀, a₁)`` giving ratio ζᵢ at ωᵢ and ζⱼ at ωⱼ.

    Solves the 2×2 system (Chopra §11.4.1)

    .. math::  \\tfrac12 \\begin{bmatrix} 1/ω_i & ω_i \\\\ 1/ω_j & ω_j \\end{bmatrix}
               \\begin{bmatrix} a_0 \\\\ a_1 \\end{bmatrix}
               = \\begin{bmatrix} ζ_i \\\\ ζ_j \\end{bmatrix}

    in closed form: ``a₀ = 2 ωᵢ ωⱼ (ζᵢ ωⱼ − ζⱼ ωᵢ)/(ωⱼ² − ωᵢ²)``,
    ``a₁ = 2 (ζⱼ ωⱼ − ζᵢ ωᵢ)/(ωⱼ² − ωᵢ²)``. For ζᵢ = ζⱼ = ζ these reduce to Chopra's
    ``a₀ = ζ 2ωᵢωⱼ/(ωᵢ + ωⱼ)``, ``a₁ = ζ 2/(ωᵢ + ωⱼ)``.

    Parameters
    ----------
    omega_i, omega_j : float
        The two circular frequencies [rad/s]; must differ.
    zeta_i, zeta_j : float
        The damping ratios [-] wanted at them.

    Returns
    -------
    a0 : float
        Mass-proportional coefficient [1/s].
    a1 : float
        Stiffness-proportional coefficient [s].

    Raises
    ------
    ValueError
        If the frequencies are not positive and distinct, a ratio is outside [0, 1], or the
        ratios would need a negative coefficient (negative damping in some frequency band):
        that happens unless ``ωᵢ/ωⱼ ≤ ζⱼ/ζᵢ ≤ ωⱼ/ωᵢ`` (for ωᵢ < ωⱼ).
    """
    wi = positive("omega_i", omega_i)
    wj = positive("omega_j", omega_j)
    zi = _ratio("zeta_i", zeta_i)
    zj = _ratio("zeta_j", zeta_j)
    if math.isclose(wi, wj, rel_tol=1e-12):
        raise ValueError(f"omega_i and omega_j must differ (got {wi:g} and {wj:g} rad/s)")
    den = wj * wj - wi * wi
    a0 = 2.0 * wi * wj * (zi * wj - zj * wi) / den
    a1 = 2.0 * (zj * wj - zi * wi) / den
    scale = max(zi, zj, 1e-300)
    if a0 < -1e-12 * scale * min(wi, wj) or a1 < -1e-12 * scale / max(wi, wj):
        raise ValueError(
            f"Rayleigh damping with zeta_i={zi:g} at omega_i={wi:g} rad/s and zeta_j={zj:g} at "
            f"omega_j={wj:g} rad/s needs a negative coefficient (a0={a0:g} 1/s, a1={a1:g} s), "
            "i.e. negative damping in some band; choose ratios whose quotient zeta_j/zeta_i "
            f"lies in [{min(wi, wj) / max(wi, wj):.4g}, {max(wi, wj) / min(wi, wj):.4g}] "
            "(between omega_i/omega_j and omega_j/omega_i)")
    return max(a0, 0.0), max(a1, 0.0)


class DampingModel(ABC):
    """The contract of a damping model.

    1. A model is an immutable value (a frozen dataclass) whose fields are its parameters.
    2. :meth:`matrix` maps ``(M, K)`` to a symmetric, positive semi-definite float64 ``C``
       of the same shape [N·s/m]; it never changes its inputs.
    3. :meth:`check` raises :class:`ValueError` early if the model cannot apply to a
       structure with ``n_dof`` degrees of freedom (e.g. a mode number larger than ``n``).
    """

    @abstractmethod
    def matrix(self, M: ArrayLike, K: ArrayLike) -> NDArray[np.float64]:
        """Damping matrix ``C`` [N·s/m], shape (n, n), for mass ``M`` [kg] and stiffness ``K``
        [N/m], both shape (n, n)."""

    def check(self, n_dof: int) -> None:
        """Raise :class:`ValueError` if the model cannot apply to ``n_dof`` degrees of freedom.

        The default accepts any size.
        """
        return None

    def readable(self) -> str:
        """One line for people: the model and its parameters (the default: the class name
        and every field in three significant digits)."""
        values: list[tuple[str, object]] = []
        if is_dataclass(self):
            values = [(f.name, getattr(self, f.name)) for f in fields(self)]
        return f"{type(self).__name__}: " + ", ".join(
            f"{k} = {format_value(v) if isinstance(v, float) else v}" for k, v in values)


@dataclass(frozen=True, init=False)
class RayleighDamping(DampingModel):
    """Rayleigh (mass- plus stiffness-proportional) damping, ``C = a₀ M + a₁ K``.

    The modal damping ratio it gives is ``ζ(ω) = a₀/(2ω) + a₁ ω/2`` (Chopra §11.4.1);
    ``a₀, a₁`` are fixed by requiring ``ζᵢ`` at mode ``mode_i`` and ``ζⱼ`` at mode ``mode_j``
    (see :func:`rayleigh_coefficients`), or, if ``period_i`` and ``period_j`` are given, at
    the circular frequencies ``2π/Tᵢ`` and ``2π/Tⱼ`` instead of at natural modes.

    Parameters
    ----------
    zeta_i : float
        Damping ratio [-] at the first anchor, in [0, 1].
    zeta_j : float, optional
        Damping ratio [-] at the second anchor; defaults to ``zeta_i``.
    mode_i, mode_j : int
        The two anchor modes (1 = fundamental); must differ. Ignored when periods are given.
    period_i, period_j : float, optional
        Two anchor periods [s]; give both or neither. Use :meth:`from_periods`.

    Notes
    -----
    A structure with one degree of freedom has one mode. There, with modes as anchors and
    ``zeta_j == zeta_i``, the coefficients are the ``ωⱼ → ωᵢ`` limit of Chopra's equal-ratio
    formula, ``a₀ = ζ ω``, ``a₁ = ζ/ω``, so ``c = a₀ m + a₁ k = 2 ζ m ω`` (Chopra §2.2,
    ``ζ = c/(2 m ω)``) exactly.
    """

    zeta_i: float
    zeta_j: float
    mode_i: int
    mode_j: int
    period_i: float | None
    period_j: float | None

    def __init__(self, zeta_i: float = 0.05, zeta_j: float | None = None, mode_i: int = 1,
                 mode_j: int = 2, period_i: float | None = None,
                 period_j: float | None = None) -> None:
        zi = _ratio("zeta_i", zeta_i)
        zj = zi if zeta_j is None else _ratio("zeta_j", zeta_j)
        mi = _mode_number("mode_i", mode_i)
        mj = _mode_number("mode_j", mode_j)
        if period_i is not None and period_j is not None:
            period_i = positive("period_i", period_i)
            period_j = positive("period_j", period_j)
            # Validates distinctness and the sign of the coefficients now.
            rayleigh_coefficients(2.0 * math.pi / period_i, 2.0 * math.pi / period_j, zi, zj)
        elif period_i is not None or period_j is not None:
            raise ValueError("period_i and period_j must be given together "
                             f"(got period_i={period_i!r}, period_j={period_j!r})")
        elif mi == mj:
            raise ValueError(f"mode_i and mode_j must differ (got {mi} and {mj})")
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "zeta_i", zi)
        frozen_set(self, "zeta_j", zj)
        frozen_set(self, "mode_i", mi)
        frozen_set(self, "mode_j", mj)
        frozen_set(self, "period_i", period_i)
        frozen_set(self, "period_j", period_j)

    @classmethod
    def from_periods(cls, period_i: float, period_j: float, zeta_i: float = 0.05,
                     zeta_j: float | None = None) -> RayleighDamping:
        """Rayleigh damping anchored at two periods [s] rather than at two natural modes.

        Parameters
        ----------
        period_i, period_j : float
            Anchor periods [s], positive and distinct.
        zeta_i : float
            Ratio [-] at ``period_i``.
        zeta_j : float, optional
            Ratio [-] at ``period_j``; defaults to ``zeta_i``.
        """
        return cls(zeta_i=zeta_i, zeta_j=zeta_j, period_i=period_i, period_j=period_j)

    @property
    def by_periods(self) -> bool:
        """True if anchored at two periods rather than two natural modes."""
        return self.anchor_periods is not None

    @property
    def anchor_periods(self) -> tuple[float, float] | None:
        """``(period_i, period_j)`` [s] if anchored at two periods, else None."""
        if self.period_i is None or self.period_j is None:
            return None
        return self.period_i, self.period_j

    def readable(self) -> str:
        """``Rayleigh, ζ = 0.05 at modes 1 and 2``, ``Rayleigh, ζ = 0.05 at 0.8 s and 0.02
        at 0.2 s``."""
        zi, zj = format_value(self.zeta_i), format_value(self.zeta_j)
        periods = self.anchor_periods
        if periods is not None:
            at_i, at_j = (format_value(t, "s") for t in periods)
            where = (f"at {at_i} and {at_j}" if zi == zj
                     else f"at {at_i} and {zj} at {at_j}")
        else:
            where = (f"at modes {self.mode_i} and {self.mode_j}" if zi == zj
                     else f"at mode {self.mode_i} and {zj} at mode {self.mode_j}")
        return f"Rayleigh, ζ = {zi} {where}"

    def check(self, n_dof: int) -> None:
        """Raise if an anchor mode does not exist in a structure with ``n_dof`` DOFs."""
        if self.by_periods:
            return
        if n_dof == 1:
            if self.mode_i != 1:
                raise ValueError(f"mode_i must be 1 for a structure with one mode "
                                 f"(got {self.mode_i})")
            if self.zeta_j != self.zeta_i:
                raise ValueError(
                    f"a structure with one mode takes one damping ratio: zeta_j ({self.zeta_j:g}) "
                    f"must equal zeta_i ({self.zeta_i:g}); or use ModalDamping")
            return
        for label, mode in (("mode_i", self.mode_i), ("mode_j", self.mode_j)):
            if mode > n_dof:
                raise ValueError(f"{label} must be <= the number of modes, {n_dof} "
                                 f"(got {mode})")

    def coefficients(self, M: ArrayLike, K: ArrayLike) -> tuple[float, float]:
        """The coefficients ``(a₀ [1/s], a₁ [s])`` of ``C = a₀ M + a₁ K`` for ``(M, K)``."""
        periods = self.anchor_periods
        if periods is not None:
            return rayleigh_coefficients(2.0 * math.pi / periods[0], 2.0 * math.pi / periods[1],
                                         self.zeta_i, self.zeta_j)
        Mf, Kf = square_pair(M, K)
        n = Mf.shape[0]
        self.check(n)
        omega, _ = eigenmodes(Mf, Kf)
        if n == 1:
            w = float(omega[0])
            return self.zeta_i * w, self.zeta_i / w
        return rayleigh_coefficients(float(omega[self.mode_i - 1]), float(omega[self.mode_j - 1]),
                                     self.zeta_i, self.zeta_j)

    def ratio(self, omega: ArrayLike, M: ArrayLike, K: ArrayLike) -> NDArray[np.float64]:
        """Damping ratio ``ζ(ω) = a₀/(2ω) + a₁ω/2`` [-] this model gives at ``omega`` [rad/s]."""
        a0, a1 = self.coefficients(M, K)
        w = np.asarray(omega, dtype=np.float64)
        return a0 / (2.0 * w) + a1 * w / 2.0

    def matrix(self, M: ArrayLike, K: ArrayLike) -> NDArray[np.float64]:
        """``C = a₀ M + a₁ K`` [N·s/m] (Chopra §11.4.1), shape (n, n)."""
        Mf, Kf = square_pair(M, K)
        a0, a1 = self.coefficients(Mf, Kf)
        with np.errstate(invalid="ignore", over="ignore"):
            # (a stiffness far outside any building's overflows: the solver refuses the
            # building in one line, pounding.integrate.periods.check_building_periods)
            return a0 * Mf + a1 * Kf


@dataclass(frozen=True)
class ModalDamping(DampingModel):
    """The same damping ratio ζ in every natural mode.

    Built by superposing modal damping matrices (Chopra §11.4.3):

    .. math::  C = M \\Big( \\sum_n \\frac{2 ζ ω_n}{M_n} φ_n φ_n^T \\Big) M
                 = M Φ \\,\\mathrm{diag}(2 ζ ω_n / M_n)\\, Φ^T M

    For one degree of freedom this is ``c = 2 ζ m ω`` (Chopra §2.2). ``C`` is full
    (every floor's velocity damps every other floor) but classical.

    Parameters
    ----------
    zeta : float
        Damping ratio [-] of every mode, in [0, 1].
    """

    zeta: float = 0.05

    def __post_init__(self) -> None:
        object.__setattr__(self, "zeta", _ratio("zeta", self.zeta))

    def readable(self) -> str:
        """``modal, ζ = 0.05 in every mode``."""
        return f"modal, ζ = {format_value(self.zeta)} in every mode"

    def matrix(self, M: ArrayLike, K: ArrayLike) -> NDArray[np.float64]:
        """``C = M Φ diag(2ζωₙ/Mₙ) Φᵀ M`` [N·s/m], shape (n, n)."""
        Mf, Kf = square_pair(M, K)
        omega, phi = eigenmodes(Mf, Kf)
        Mn = np.einsum("in,ij,jn->n", phi, Mf, phi)
        A = Mf @ phi
        C = (A * (2.0 * self.zeta * omega / Mn)[np.newaxis, :]) @ A.T
        return 0.5 * (C + C.T)
