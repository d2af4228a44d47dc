"""Hertz-type contact laws: elastic Hertz, the Hunt–Crossley family, and Jankowski's
nonlinear viscoelastic law (seed eqs 17–18), the law of the seed's proposed formula (eq 39).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from pounding.contact.base import ContactLaw, m_effective
from pounding.contact.codes import HERTZ, HUNT_CROSSLEY, NONLINEAR_VISCOELASTIC
from pounding.validation import in_range, non_negative, positive


@dataclass(frozen=True)
class Hertz(ContactLaw):
    """Elastic Hertz contact, ``F = k_h δⁿ`` with ``n = 3/2`` (Davis 1992, EESD 21(3):253–274).

    Parameters
    ----------
    k_h : float
        Hertz stiffness [N/m^n].
    n : float
        Exponent (1.5 for two spheres; keep it unless you know better).

    Notes
    -----
    Elastic (e = 1). For two free masses closing at ``v0`` the maximum penetration is
    ``δmax = ((n + 1) m_eff v0² / (2 k_h))^(1/(n+1))`` — for n = 1.5,
    ``(5 m_eff v0² / (4 k_h))^(2/5)`` (energy balance).
    """

    k_h: float
    n: float = 1.5
    code: ClassVar[int] = HERTZ
    label: ClassVar[str] = "Hertz"
    source: ClassVar[str] = "Davis"
    units: ClassVar[dict[str, str]] = {"k_h": "N/m^n", "n": "-"}

    def __post_init__(self) -> None:
        object.__setattr__(self, "k_h", positive("k_h", self.k_h))
        object.__setattr__(self, "n", in_range("n", self.n, 1.0, 3.0))

    def secant_stiffness(self, delta: float) -> float:
        """Elastic secant stiffness F/δ at penetration ``delta`` [N/m]: ``k_h δ^(n−1)``."""
        return self.k_h * delta ** (self.n - 1.0)

    def params(self) -> np.ndarray:
        return np.array([self.k_h, self.n])


@dataclass(frozen=True)
class HuntCrossley(ContactLaw):
    """Hunt–Crossley family: ``F = k_h δⁿ (1 + χ δ̇ / v0)``, damping in both phases.

    The family differs only in how χ comes from ``e`` (see
    :mod:`pounding.contact.restitution`): exactly, by the law's own ``e(χ)`` inverted
    (``exact-hunt-crossley``, the default); or by a published closed form: Hunt & Crossley
    (1975) ``3(1−e)/2``; Lankarani &
    Nikravesh (1990) ``3(1−e²)/4``, which is also the Hertzdamp model of Muthukumar &
    DesRoches (2006, EESD 35(7):811–828); Ye et al. (2009) / Flores et al. (2011)
    ``8(1−e)/(5e)``; Gonthier et al. (2004) ``(1−e²)/e``.

    Parameters
    ----------
    k_h : float
        Hertz stiffness [N/m^n].
    chi : float
        Dimensionless damping factor χ ≥ 0.
    n : float
        Exponent (1.5).

    Notes
    -----
    ``v0`` is the approach velocity at the located instant of first contact (contract
    step 3). Where ``1 + χ δ̇/v0 < 0`` (large χ late in restitution) the force is clipped to
    zero: contact cannot pull.
    """

    k_h: float
    chi: float
    n: float = 1.5
    code: ClassVar[int] = HUNT_CROSSLEY
    label: ClassVar[str] = "Hunt-Crossley"
    damping_field: ClassVar[str | None] = "chi"
    units: ClassVar[dict[str, str]] = {"k_h": "N/m^n", "chi": "-", "n": "-"}

    def __post_init__(self) -> None:
        object.__setattr__(self, "k_h", positive("k_h", self.k_h))
        object.__setattr__(self, "chi", non_negative("chi", self.chi))
        object.__setattr__(self, "n", in_range("n", self.n, 1.0, 3.0))

    def secant_stiffness(self, delta: float) -> float:
        """Elastic secant stiffness F/δ at penetration ``delta`` [N/m]: ``k_h δ^(n−1)``."""
        return self.k_h * delta ** (self.n - 1.0)

    def params(self) -> np.ndarray:
        return np.array([self.k_h, self.n, self.chi])

    # No release function: during restitution ``1 + χ δ̇/v0`` decays towards zero but never
    # reaches it while δ > 0 (with w = 1 + χ δ̇/v0, m_eff ẇ = −(χ/v0) k δⁿ w), so the force
    # stays positive until the bodies separate at δ = 0 (with e < 1/χ). A release event on
    # w = 0 was only ever triggered by round-off, ending χ ≳ 40 impacts with the bodies still
    # overlapping.

    @classmethod
    def from_restitution(cls, k_h: float, e: float, formula: str = "exact-hunt-crossley",
                         n: float = 1.5) -> "HuntCrossley":
        """Build from ``e`` via a χ formula (default the exact one, which achieves ``e``;
        ``"lankarani-nikravesh"`` is the published Hertzdamp χ, :func:`hertzdamp`)."""
        from pounding.contact.restitution import formula as _formula

        f = _formula(formula)
        if f.kind != "chi":
            raise ValueError(f"formula: {formula!r} gives a damping ratio zeta, not a "
                             f"Hunt-Crossley chi")
        return cls(k_h=k_h, chi=float(f(e)), n=n)


def hertzdamp(k_h: float, e: float, n: float = 1.5) -> HuntCrossley:
    """The Hertzdamp model of Muthukumar & DesRoches (2006) as published: Hunt–Crossley with
    the Lankarani–Nikravesh factor ``χ = 3(1 − e²)/4``, which misses ``e`` (0.775 achieved
    for 0.65). The law name ``hertzdamp`` of a model file takes the exact χ by default
    (``formula = "lankarani-nikravesh"`` for this one)."""
    return HuntCrossley.from_restitution(k_h, e, formula="lankarani-nikravesh", n=n)


@dataclass(frozen=True)
class NonlinearViscoelastic(ContactLaw):
    """Jankowski's nonlinear viscoelastic law (seed eqs 17–18).

    ``F = k_h δ^1.5 + c δ̇`` while approaching (``δ̇ > 0``), ``F = k_h δ^1.5`` while
    separating, with ``c = 2 ζ sqrt(k_h sqrt(δ) m1 m2 / (m1 + m2))`` (eq 18).

    Source: Jankowski (2005), EESD 34(6):595–611; ζ(e) by default the exact inverse of the
    law's restitution (:func:`~pounding.contact.exact_restitution.zeta_nonlinear_viscoelastic_exact`),
    of which Jankowski (2006) = seed eq 19 is a fit. The seed's proposed model (Naderpour et al. 2015) is this law with ζ from eq 39.

    Parameters
    ----------
    k_h : float
        Hertz stiffness [N/m^1.5]; Jankowski's concrete value is 2.75e9.
    zeta : float
        Impact damping ratio ζ ≥ 0.
    m_eff : float
        Effective mass ``m1 m2 / (m1 + m2)`` [kg] of the colliding bodies (eq 18).
    """

    k_h: float
    zeta: float
    m_eff: float
    code: ClassVar[int] = NONLINEAR_VISCOELASTIC
    label: ClassVar[str] = "nonlinear viscoelastic"
    source: ClassVar[str] = "Jankowski"
    damping_field: ClassVar[str | None] = "zeta"
    units: ClassVar[dict[str, str]] = {"k_h": "N/m^1.5", "zeta": "-", "m_eff": "kg"}

    def __post_init__(self) -> None:
        object.__setattr__(self, "k_h", positive("k_h", self.k_h))
        object.__setattr__(self, "zeta", non_negative("zeta", self.zeta))
        object.__setattr__(self, "m_eff", positive("m_eff", self.m_eff))

    def secant_stiffness(self, delta: float) -> float:
        """Elastic secant stiffness F/δ at penetration ``delta`` [N/m]: ``k_h δ^0.5``."""
        return self.k_h * delta ** 0.5

    def params(self) -> np.ndarray:
        return np.array([self.k_h, self.zeta, self.m_eff])

    @classmethod
    def from_restitution(cls, k_h: float, e: float, m1: float, m2: float,
                         formula: str = "exact-nonlinear-viscoelastic") -> "NonlinearViscoelastic":
        """Build from ``e`` via a ζ formula (default the exact one, which achieves ``e``;
        ``"jankowski"`` is seed eq 19, a fit to it)."""
        from pounding.contact.restitution import formula as _formula

        f = _formula(formula)
        if f.kind != "zeta":
            raise ValueError(f"formula: {formula!r} gives a Hunt-Crossley chi, not a damping ratio")
        return cls(k_h=k_h, zeta=float(f(e)), m_eff=m_effective(m1, m2))


def naderpour_2015(k_h: float, e: float, m1: float, m2: float) -> NonlinearViscoelastic:
    """The seed paper's proposed model: Jankowski's law (eqs 17–18) with ζ from eq 39."""
    return NonlinearViscoelastic.from_restitution(k_h, e, m1, m2, formula="naderpour")
