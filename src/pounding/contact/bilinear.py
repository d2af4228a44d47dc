"""The bilinear impact element of Muthukumar (2003), as OpenSees' ``ImpactMaterial``.

A piecewise-linear stand-in for the Hertzdamp law that dissipates the same energy in an
impact that reaches the assumed maximum penetration ``δm``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit

from pounding.contact.base import BILINEAR_IMPACT, ContactLaw, open_or_onset
from pounding.validation import in_range, positive, restitution


@njit(cache=True, inline="always", error_model="numpy")
def bilinear_impact_trial(k1, k2, dy, delta, rate, v0, slip, dmax):
    """Bilinear impact element (params: [K1, K2, δy]).

    Written as a spring ``K2`` in parallel with an elasto-plastic spring of stiffness
    ``K1 − K2`` whose force stays in ``[0, (K1 − K2) δy]``; ``slip`` is that spring's
    plastic offset. Loading follows K1 up to ``δy`` then K2; unloading follows K1 down to the
    line ``F = K2 δ`` through the gap point, then that line to zero force — the parallelogram
    loop of Muthukumar (2003). The return mapping is exact for any monotonic increment.
    """
    v0, slip, dmax = open_or_onset(delta, rate, v0, slip, dmax)
    if v0 == 0.0:
        return 0.0, 0.0, 0.0, v0, slip, dmax
    kp = k1 - k2
    fy = kp * dy
    fp = kp * (delta - slip)
    if fp > fy:
        return k2 * delta + fy, k2, 0.0, v0, delta - dy, dmax
    if fp < 0.0:
        return k2 * delta, k2, 0.0, v0, delta, dmax
    return k2 * delta + fp, k1, 0.0, v0, slip, dmax


@dataclass(frozen=True)
class BilinearImpact(ContactLaw):
    """Bilinear impact element (Muthukumar 2003; OpenSees ``ImpactMaterial``).

    Parameters
    ----------
    K1 : float
        Initial (and unloading) stiffness [N/m].
    K2 : float
        Post-yield stiffness [N/m], ``0 ≤ K2 < K1``.
    delta_y : float
        Yield penetration δy [m] (positive here; OpenSees writes it negative).

    See Also
    --------
    BilinearImpact.from_hertz : the energy-equivalent element of a Hertzdamp contact.
    """

    K1: float
    K2: float
    delta_y: float
    code: ClassVar[int] = BILINEAR_IMPACT
    label: ClassVar[str] = "bilinear impact"
    source: ClassVar[str] = "Muthukumar"
    units: ClassVar[dict[str, str]] = {"K1": "N/m", "K2": "N/m", "delta_y": "m"}

    def __post_init__(self) -> None:
        k1 = positive("K1", self.K1)
        k2 = in_range("K2", self.K2, 0.0, k1, high_open=True)
        object.__setattr__(self, "K1", k1)
        object.__setattr__(self, "K2", k2)
        object.__setattr__(self, "delta_y", positive("delta_y", self.delta_y))

    def secant_stiffness(self, delta: float) -> float:
        """Secant stiffness F/δ of the first loading at penetration ``delta`` [N/m]: ``K1``
        up to ``delta_y``, then ``(K1 δy + K2 (δ − δy)) / δ``."""
        if delta <= self.delta_y:
            return self.K1
        return (self.K1 * self.delta_y + self.K2 * (delta - self.delta_y)) / delta

    def params(self) -> np.ndarray:
        return np.array([self.K1, self.K2, self.delta_y])

    def dissipated_energy(self, delta_max: float) -> float:
        """Energy [J] dissipated by one impact reaching ``delta_max`` [m]: the parallelogram
        area ``(K1 − K2) δy (δmax − δy)`` (zero if the element never yields)."""
        d = positive("delta_max", delta_max)
        return (self.K1 - self.K2) * self.delta_y * max(d - self.delta_y, 0.0)

    @classmethod
    def from_hertz(cls, k_h: float, e: float, delta_m: float, a: float = 0.1,
                   n: float = 1.5) -> "BilinearImpact":
        """The element energy-equivalent to a Hertzdamp contact (Muthukumar 2003).

        ``ΔE = k_h δm^(n+1) (1 − e²)/(n + 1)``, ``K_eff = k_h sqrt(δm)``, ``δy = a δm``,
        ``K1 = K_eff + ΔE/(a δm²)``, ``K2 = K_eff − ΔE/((1 − a) δm²)``.

        Parameters
        ----------
        k_h : float
            Hertz stiffness [N/m^n].
        e : float
            Coefficient of restitution the loop is sized for.
        delta_m : float
            Assumed maximum penetration δm [m] (an impact reaching exactly δm dissipates ΔE).
        a : float
            Yield ratio δy/δm (0.1 in Muthukumar's work).
        n : float
            Hertz exponent (1.5).
        """
        kh = positive("k_h", k_h)
        ee = float(restitution(e))
        if ee >= 1.0:
            raise ValueError("e must be < 1 for a bilinear impact element (got 1); an elastic "
                             "contact is Hertz(k_h)")
        dm = positive("delta_m", delta_m)
        aa = in_range("a", a, 0.0, 1.0, low_open=True, high_open=True)
        nn = in_range("n", n, 1.0, 3.0)
        d_e = kh * dm ** (nn + 1.0) * (1.0 - ee**2) / (nn + 1.0)
        k_eff = kh * np.sqrt(dm)
        k1 = k_eff + d_e / (aa * dm**2)
        k2 = k_eff - d_e / ((1.0 - aa) * dm**2)
        if k2 < 0.0:
            raise ValueError(f"e: restitution {ee:g} with a={aa:g} gives a negative post-yield "
                             f"stiffness K2={k2:g}; use a larger e or a smaller a")
        return cls(K1=k1, K2=k2, delta_y=aa * dm)
