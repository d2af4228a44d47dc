"""ASCE/SEI 7-22 §12.8, the equivalent lateral force (ELF) procedure on one of the model's
buildings, for :mod:`pounding.studies.codes.asce7_22`: the seismic response coefficient
``C_s`` (eqs. 12.8-2 to 12.8-6), the vertical distribution of the base shear (§12.8.3) and
the elastic deflections under it (§12.8.6); and the modal base shear ``V_t`` of §12.9.1.4.

Units: m, s, N, kg; spectral values and C_s in g (dimensionless).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from pounding.studies.codes.common import SPECTRUM_DAMPING, cqc_matrix
from pounding.units import G

__all__ = ["ElfResult", "elf", "modal_base_shear", "response_coefficient"]


def response_coefficient(period: float, *, sds: float, sd1: float, tl: float, r: float,
                         ie: float, s1: float | None, for_drift: bool
                         ) -> tuple[float, str]:
    """C_s of §12.8.1.1 at ``period`` and the equation that sets it.

    ``S_DS/(R/I_e)`` (eq. 12.8-2), at most ``S_D1/(T R/I_e)`` for ``T ≤ T_L`` (eq. 12.8-3)
    or ``S_D1 T_L/(T² R/I_e)`` beyond (eq. 12.8-4); at least ``max(0.044 S_DS I_e, 0.01)``
    (eq. 12.8-5) unless ``for_drift`` (§12.8.6.1's exception), and where ``S1 ≥ 0.6 g`` at
    least ``0.5 S1/(R/I_e)`` (eq. 12.8-6).
    """
    ri = r / ie
    cs, eq = sds / ri, "eq. 12.8-2"
    top, top_eq = ((sd1 / (period * ri), "eq. 12.8-3") if period <= tl else
                   (sd1 * tl / (period ** 2 * ri), "eq. 12.8-4"))
    if top < cs:
        cs, eq = top, top_eq
    if not for_drift:
        low = max(0.044 * sds * ie, 0.01)
        if low > cs:
            cs, eq = low, "eq. 12.8-5"
    if s1 is not None and s1 >= 0.6 and 0.5 * s1 / ri > cs:
        cs, eq = 0.5 * s1 / ri, "eq. 12.8-6"
    return cs, eq


@dataclass(frozen=True)
class ElfResult:
    """The ELF of one building: period T [s] (its first mode, §12.8.6.2), C_s and its
    equation, the exponent k (§12.8.3), seismic weight W [N], base shear V [N], and the
    elastic deflections δ_xe [m] of every DOF under the lateral forces."""

    period: float
    cs: float
    equation: str
    k: float
    weight: float
    base_shear: float
    deflections: Any


def distribution_exponent(period: float) -> float:
    """k of §12.8.3: 1 for T ≤ 0.5 s, 2 for T ≥ 2.5 s, linear between."""
    return 1.0 if period <= 0.5 else 2.0 if period >= 2.5 else 1.0 + (period - 0.5) / 2.0


def elf(building: Any, *, sds: float, sd1: float, tl: float, r: float, ie: float,
        s1: float | None) -> ElfResult:
    """The ELF deflections of ``building`` (§12.8.6): ``V = C_s W`` (eq. 12.8-1) with
    ``W = g Σ m`` (the model's masses) and ``C_s`` at the building's first-mode period,
    ``F_x = C_vx V``, ``C_vx = w_x h_x^k / Σ w_i h_i^k`` (eqs. 12.8-11, 12.8-12), and
    ``δ_xe = K⁻¹ F``.

    Raises
    ------
    ValueError
        A building with a degree of freedom at or below the ground (a base-isolated
        building: ASCE 7-22 Chapter 17, not §12.8).
    """
    modes = building.modes()
    period = float(modes.periods[0])
    levels = np.asarray(building.floor_levels, dtype=float)
    iota = np.asarray(building.influence_vector(), dtype=float)
    lateral = iota != 0.0
    if getattr(building, "isolator", None) is not None or np.any(levels[lateral] <= 0.0):
        raise ValueError(f"procedure: the ELF of ASCE 7-22 §12.8 is for a fixed-base "
                         f"building; {building.name or 'a building'} moves at the ground "
                         "(base-isolated: ASCE 7-22 Chapter 17, not covered); use "
                         "--procedure modal")
    weights = G * (np.asarray(building.mass_matrix(), dtype=float) @ iota) * lateral
    cs, eq = response_coefficient(period, sds=sds, sd1=sd1, tl=tl, r=r, ie=ie, s1=s1,
                                  for_drift=True)
    k = distribution_exponent(period)
    weight = float(np.sum(weights))
    base_shear = cs * weight
    share = weights * np.where(lateral, np.abs(levels), 0.0) ** k
    forces = base_shear * share / float(np.sum(share))
    deflections = np.linalg.solve(np.asarray(building.stiffness_matrix(), dtype=float),
                                  forces)
    return ElfResult(period, cs, eq, k, weight, base_shear, deflections)


def modal_base_shear(building: Any, sa_g: Any, combination: str) -> float:
    """V_t [N]: the building's base shear by modal response spectrum analysis, the modal
    ``V_n = M_n* Sa(T_n) g`` combined by SRSS or CQC (§12.9.1.3), on the spectrum ``sa_g``
    as used (already divided by R/I_e)."""
    modes = building.modes()
    periods = np.asarray(modes.periods, dtype=float)
    v = np.asarray(modes.effective_masses, dtype=float) * np.asarray(sa_g(periods)) * G
    if combination == "srss":
        return math.sqrt(float(np.sum(v * v)))
    rho = cqc_matrix(2.0 * np.pi / periods, SPECTRUM_DAMPING)
    with np.errstate(over="ignore", invalid="ignore"):  # (refused below)
        quad = float(v @ rho @ v)
    if not math.isfinite(quad):
        raise ValueError("spectrum: the modal base shear is not a finite number; check the "
                         "spectrum's parameters")
    return math.sqrt(max(0.0, quad))  # (round-off can make it −0)
