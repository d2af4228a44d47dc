"""The bilinear impact element of Muthukumar (2003), as OpenSees' ``ImpactMaterial``.

A piecewise-linear stand-in for the Hertzdamp law that dissipates the same energy in an
impact that reaches the assumed maximum penetration ``δm``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from pounding.contact.base import ContactLaw
from pounding.contact.codes import BILINEAR_IMPACT
from pounding.validation import in_range, positive, restitution


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

    def restitution_at(self, delta_max: float) -> float:
        """The ``e`` of an impact of two free bodies that reaches ``delta_max`` [m]:
        ``sqrt(1 − ΔE/A)``, with ``A`` the energy stored by the loading branch up to
        ``delta_max`` and ``ΔE`` the loop's area (:meth:`dissipated_energy`)."""
        d = positive("delta_max", delta_max)
        dy = min(self.delta_y, d)
        stored = (0.5 * self.K1 * dy**2 + self.K1 * dy * (d - dy)
                  + 0.5 * self.K2 * (d - dy) ** 2)
        return float(np.sqrt(max(1.0 - self.dissipated_energy(d) / stored, 0.0)))

    @classmethod
    def from_hertz(cls, k_h: float, e: float, delta_m: float, a: float = 0.1,
                   n: float = 1.5) -> "BilinearImpact":
        """The element energy-equivalent to a Hertzdamp contact (Muthukumar 2003): formula
        ``muthukumar``.

        ``ΔE = k_h δm^(n+1) (1 − e²)/(n + 1)``, ``K_eff = k_h δm^(n−1)`` (``k_h sqrt(δm)``
        for n = 3/2), ``δy = a δm``, ``K1 = K_eff + ΔE/(a δm²)``,
        ``K2 = K_eff − ΔE/((1 − a) δm²)``.

        An impact of this element does not achieve ``e``, even one that reaches ``δm``: it
        stores ``K_eff δm²/2 + ΔE/2`` there, not the Hertz energy ``k_h δm^(n+1)/(n+1)``
        that ``ΔE`` was sized against (0.758 for a target of 0.65 at the elastic Hertz
        ``δm``, ``docs/audit.md``). :meth:`from_restitution` is the element that does.

        Parameters
        ----------
        k_h : float
            Hertz stiffness [N/m^n].
        e : float
            Coefficient of restitution the loop is sized for.
        delta_m : float
            Assumed maximum penetration δm [m].
        a : float
            Yield ratio δy/δm (0.1 in Muthukumar's work).
        n : float
            Hertz exponent (1.5).
        """
        kh, ee, dm, aa, nn = _sizing_inputs(k_h, e, delta_m, a, n)
        d_e = kh * dm ** (nn + 1.0) * (1.0 - ee**2) / (nn + 1.0)
        return cls._with_loop(kh * dm ** (nn - 1.0), d_e, dm, aa, ee)

    @classmethod
    def from_restitution(cls, k_h: float, e: float, delta_m: float, a: float = 0.1,
                         n: float = 1.5) -> "BilinearImpact":
        """The element whose impact reaching ``δm`` achieves exactly ``e``: formula
        ``exact-bilinear``, the default of the ``bilinear-impact`` law.

        Same shape as Muthukumar's (``K_eff = k_h δm^(n−1)``, ``δy = a δm``, the loop
        ``ΔE`` split as in :meth:`from_hertz`), with the loop sized so the energy balance of
        the impact closes: loading to ``δm`` stores ``A = K_eff δm²/2 + ΔE/2`` (the area
        under K1 then K2), unloading returns ``A − ΔE``, so ``e² = 1 − ΔE/A`` gives

            ΔE = (1 − e²) K_eff δm² / (1 + e²),   A = K_eff δm² / (1 + e²).

        The impact that reaches ``δm`` is the one of two free bodies closing at
        ``v0 = sqrt(2 A / m_eff)`` (:func:`exact_delta_m` turns a ``v0`` into that ``δm``).
        The element's e depends on the impact velocity (a slower impact yields less and
        restores a larger share); only the impact that reaches ``δm`` achieves ``e``
        exactly. ``K2 ≥ 0`` needs ``(1 − e²)/(1 + e²) ≤ 1 − a``, i.e. ``a ≤ 2e²/(1 + e²)``.
        """
        kh, ee, dm, aa, nn = _sizing_inputs(k_h, e, delta_m, a, n)
        k_eff = kh * dm ** (nn - 1.0)
        return cls._with_loop(k_eff, (1.0 - ee**2) * k_eff * dm**2 / (1.0 + ee**2), dm, aa, ee)

    @classmethod
    def _with_loop(cls, k_eff: float, d_e: float, dm: float, a: float,
                   e: float) -> "BilinearImpact":
        """The element of secant ``k_eff`` at ``dm`` whose loop dissipates ``d_e``."""
        k1 = k_eff + d_e / (a * dm**2)
        k2 = k_eff - d_e / ((1.0 - a) * dm**2)
        if k2 < 0.0:
            a_max = 1.0 - d_e / (k_eff * dm**2)
            raise ValueError(f"e: restitution {e:g} with a={a:g} gives a negative post-yield "
                             f"stiffness K2={k2:g}; use a larger e or a <= {a_max:.4g}")
        return cls(K1=k1, K2=k2, delta_y=a * dm)


def _sizing_inputs(k_h: float, e: float, delta_m: float, a: float, n: float
                   ) -> tuple[float, float, float, float, float]:
    """The checked inputs of a bilinear element's sizing."""
    kh = positive("k_h", k_h)
    ee = float(restitution(e))
    if ee >= 1.0:
        raise ValueError("e must be < 1 for a bilinear impact element (got 1); an elastic "
                         "contact is Hertz(k_h)")
    return (kh, ee, positive("delta_m", delta_m),
            in_range("a", a, 0.0, 1.0, low_open=True, high_open=True), in_range("n", n, 1.0, 3.0))


def exact_delta_m(k_h: float, e: float, m_eff: float, v0: float, n: float = 1.5) -> float:
    """Maximum penetration [m] of the :meth:`BilinearImpact.from_restitution` element sized
    for ``e`` in an impact of two free bodies closing at ``v0``:
    ``((1 + e²) m_eff v0² / (2 k_h))^(1/(n+1))`` (its stored energy at ``δm``,
    ``k_h δm^(n+1)/(1 + e²)``, equals ``m_eff v0²/2``)."""
    ee = float(restitution(e))
    return ((1.0 + ee * ee) * positive("m_eff", m_eff) * positive("v0", v0) ** 2
            / (2.0 * positive("k_h", k_h))) ** (1.0 / (in_range("n", n, 1.0, 3.0) + 1.0))


BILINEAR_FORMULAS: dict[str, str] = {
    "exact-bilinear": "from_restitution",
    "muthukumar": "from_hertz",
}
"""How ``e`` sizes a bilinear element: by the exact energy balance of an impact reaching
``δm`` (default) or by Muthukumar's (2003) Hertzdamp equivalence."""
