"""The code rules for the separation gap of two neighbours, from their peak displacements
``u1, u2`` at a level: ABS (the sum), SRSS and DDC (the double difference combination, with
the correlation ``ρ`` of the two buildings' fundamental modes). :mod:`pounding.studies.gap`
applies them beside the critical gap by simulation (``docs/gap.md``).

Units: m, s.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.validation import non_negative, positive

__all__ = ["RULES", "abs_sum", "code_gaps", "cqc_correlation", "ddc", "srss"]

FloatArray = NDArray[np.float64]


# ============================================================================ code rules
def abs_sum(u1: ArrayLike, u2: ArrayLike) -> FloatArray | float:
    """ABS rule: the gap is the sum of the two peak displacements, ``u1 + u2`` [m].

    The absolute-sum rule of older codes, the "ABS" of Jeng, Kasai & Maison (1992,
    *Earthquake Spectra* 8(2), 201–223) and of Penzien (1997, *Earthq. Eng. Struct. Dyn.*
    26, 849–858). It is a strict upper bound of the simulated critical gap *for the same
    record*: ``|u1(t) − u2(t)| ≤ |u1(t)| + |u2(t)| ≤ u1 + u2`` at every time; it is reached
    only if both peaks happen at the same instant in opposite directions.

    Parameters
    ----------
    u1, u2 : float or array_like
        Peak displacements [m] (≥ 0) of the two buildings at the same level.
    """
    out = np.asarray(u1, dtype=float) + np.asarray(u2, dtype=float)
    return float(out) if out.ndim == 0 else out


def srss(u1: ArrayLike, u2: ArrayLike) -> FloatArray | float:
    """SRSS rule: ``sqrt(u1² + u2²)`` [m].

    ASCE/SEI 7-16 §12.12.3, eq. (12.12-2): adjacent structures on the same property are
    separated by at least ``δ_MT = sqrt(δ_M1² + δ_M2²)``, where ``δ_M = C_d δ_max / I_e``
    (eq. 12.12-1) are the *maximum inelastic* displacements at critical locations. Eurocode 8
    (EN 1998-1 §4.4.2.7) uses the same square root of the sum of squares. Here ``u1, u2``
    are whatever peaks are given (elastic, from the simulation or a spectrum): multiply them
    by ``C_d / I_e`` first for the code value.

    It equals :func:`ddc` with ``ρ = 0`` (uncorrelated responses).
    """
    a = np.asarray(u1, dtype=float)
    b = np.asarray(u2, dtype=float)
    out = np.sqrt(a * a + b * b)
    return float(out) if out.ndim == 0 else out


def ddc(u1: ArrayLike, u2: ArrayLike, rho: ArrayLike) -> FloatArray | float:
    """Double-difference combination (DDC): ``sqrt(u1² + u2² − 2 ρ u1 u2)`` [m].

    The peak of the relative displacement ``u1(t) − u2(t)`` of two linear oscillators from
    their peak responses and the correlation ``ρ`` of the two responses (random-vibration
    argument of the CQC rule): Jeng, Kasai & Maison (1992, *Earthquake Spectra* 8(2),
    201–223, the "spectral difference" method) and Penzien (1997, *Earthq. Eng. Struct.
    Dyn.* 26, 849–858, "Evaluation of building separation distance required to prevent
    pounding during strong earthquakes"). Use :func:`cqc_correlation` for ``ρ``.

    Limits: ``ρ = 0`` gives :func:`srss`; ``ρ = 1`` (identical periods and damping) gives
    ``|u1 − u2|`` (buildings in phase); ``ρ = −1`` would give :func:`abs_sum`.

    Parameters
    ----------
    u1, u2 : float or array_like
        Peak displacements [m] (≥ 0).
    rho : float or array_like
        Correlation coefficient, in [−1, 1].
    """
    a = np.asarray(u1, dtype=float)
    b = np.asarray(u2, dtype=float)
    r = np.asarray(rho, dtype=float)
    if np.any(np.abs(r) > 1.0 + 1e-12):
        raise ValueError(f"rho: must be in [-1, 1] (got {rho!r})")
    # (u1 - u2)^2 + 2 (1 - rho) u1 u2: the same value, never negative by round-off
    out = np.sqrt((a - b) ** 2 + 2.0 * (1.0 - np.clip(r, -1.0, 1.0)) * a * b)
    return float(out) if out.ndim == 0 else out


def cqc_correlation(period1: float, period2: float, zeta1: float, zeta2: float) -> float:
    """Correlation coefficient ρ of two damped oscillators (Der Kiureghian 1981, CQC).

    ::

        ρ = 8 sqrt(ζ1 ζ2) (ζ1 + r ζ2) r^1.5
            / ((1 − r²)² + 4 ζ1 ζ2 r (1 + r²) + 4 (ζ1² + ζ2²) r²),   r = T1/T2 = ω2/ω1.

    Der Kiureghian, A. (1981), "A response spectrum method for random vibration analysis
    of MDF systems", *Earthq. Eng. Struct. Dyn.* 9, 419–435; the same formula is Chopra,
    *Dynamics of Structures*, eq. 13.7.10, written there with ``β = ω_i/ω_n`` and the factor
    ``(β ζ_i + ζ_n)``. **Convention**: ``r`` is the period ratio ``T1/T2`` (frequency ratio
    ``ω2/ω1``) and it multiplies ``ζ2``. The value is symmetric — swapping the two
    oscillators (``T1 ↔ T2`` *and* ``ζ1 ↔ ζ2``) gives the same ρ — but swapping only the
    ratio (``r = T2/T1`` with the same ``ζ1 + r ζ2``) is wrong when ``ζ1 ≠ ζ2``. It is the
    exact correlation of the two stationary displacement responses to white noise (checked
    by numerical integration in the tests); ρ = 1 for equal periods and damping.

    Parameters
    ----------
    period1, period2 : float
        Periods [s] (> 0).
    zeta1, zeta2 : float
        Damping ratios [-] (≥ 0). Undamped: ρ = 1 for equal periods, else 0.
    """
    t1 = positive("period1", period1)
    t2 = positive("period2", period2)
    z1 = non_negative("zeta1", zeta1)
    z2 = non_negative("zeta2", zeta2)
    r = t1 / t2
    num = 8.0 * math.sqrt(z1 * z2) * (z1 + r * z2) * r ** 1.5
    den = (1.0 - r * r) ** 2 + 4.0 * z1 * z2 * r * (1.0 + r * r) + 4.0 * (z1 * z1 + z2 * z2) * r * r
    if den == 0.0:  # r = 1 and no damping: the two responses are the same motion
        return 1.0
    return min(1.0, num / den)


RULES: dict[str, str] = {
    "ABS": "u1 + u2 (absolute sum; Jeng et al. 1992, Penzien 1997)",
    "SRSS": "sqrt(u1² + u2²) (ASCE 7-16 §12.12.3 eq. 12.12-2; EN 1998-1 §4.4.2.7)",
    "DDC": "sqrt(u1² + u2² − 2ρu1u2), ρ = CQC coefficient of the fundamental modes "
           "(Der Kiureghian 1981; Jeng et al. 1992; Penzien 1997)",
}
"""The code rules, by name, with their formula and source."""


def code_gaps(u1: ArrayLike, u2: ArrayLike, rho: ArrayLike) -> dict[str, FloatArray]:
    """Every rule of :data:`RULES` for peak displacements ``u1, u2`` [m] and correlation ρ."""
    a = np.atleast_1d(np.asarray(u1, dtype=float))
    b = np.atleast_1d(np.asarray(u2, dtype=float))
    r = np.broadcast_to(np.asarray(rho, dtype=float), a.shape)
    return {"ABS": np.asarray(abs_sum(a, b)), "SRSS": np.asarray(srss(a, b)),
            "DDC": np.asarray(ddc(a, b, r))}
