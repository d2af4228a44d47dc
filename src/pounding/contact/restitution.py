"""Damping of an impact law from the coefficient of restitution ``e``.

Each formula maps ``e`` (0 < e ≤ 1; vectorised over arrays) to the damping parameter of the
law it was derived for: an impact damping *ratio* ζ for the (linear or nonlinear)
viscoelastic laws, or a damping *factor* χ for the Hunt–Crossley family
``F = k δⁿ (1 + χ δ̇ / v0)``. What each formula actually achieves when simulated is measured
by :mod:`pounding.contact.audit`; see ``docs/formulas/``.

The registry :data:`FORMULAS` lists every formula with its source, equation and law: the
published closed forms, and for each damped law the exact inverse of its own ``e``
(``schwager-poschel``, ``exact-modified-kelvin-voigt``, ``exact-hunt-crossley``,
``exact-nonlinear-viscoelastic``; :mod:`pounding.contact.exact_restitution`), which is the
law's default (:data:`pounding.contact.factory.DEFAULT_FORMULA`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.contact.exact_restitution import (
    chi_hunt_crossley_exact,
    zeta_kelvin_voigt_clipped,
    zeta_modified_kelvin_voigt_exact,
    zeta_nonlinear_viscoelastic_exact,
)
from pounding.validation import restitution as _check_e

FloatArray = NDArray[np.float64]


def _out(x: FloatArray) -> FloatArray | float:
    return float(x) if np.ndim(x) == 0 else x


# --------------------------------------------------------------------------- ζ formulas
def zeta_anagnostopoulos(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio of the linear viscoelastic (Kelvin–Voigt) law.

    ``ζ = −ln e / sqrt(π² + ln² e)``, with ``c = 2 ζ sqrt(k m_eff)``.

    Source: Anagnostopoulos (1988), *Pounding of buildings in series during earthquakes*,
    EESD 16(3):443–456. Exact for the Kelvin–Voigt law when the dashpot may pull until
    ``δ = 0`` (the half-period of a damped oscillator).
    """
    x = _check_e(e)
    ln = np.log(x)
    return _out(-ln / np.sqrt(np.pi**2 + ln**2) + 0.0)  # (+ 0.0: e = 1 gives 0, not −0)


def zeta_jankowski(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio of Jankowski's nonlinear viscoelastic law (seed eq 19).

    ``ζ = (9√5 / 2) (1 − e²) / (e (e (9π − 16) + 16))``.

    Source: Jankowski (2006), *Analytical expression between the impact damping ratio and the
    coefficient of restitution in the non-linear viscoelastic model of structural pounding*,
    EESD 35(4):517–524; quoted as eq 19 of Naderpour, Khatami & Barros (2015). Derived for
    ``F = k_h δ^1.5 + c δ̇`` with ``c = 2ζ sqrt(k_h sqrt(δ) m_eff)`` damping only on approach.
    """
    x = _check_e(e)
    return _out((9.0 * np.sqrt(5.0) / 2.0) * (1.0 - x**2) / (x * (x * (9.0 * np.pi - 16.0) + 16.0)))


def zeta_mahmoud(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio of the modified linear viscoelastic law (seed eq 20).

    ``ζ = (1 − e²) / (e (e (π − 2) + 2))``.

    Source: Mahmoud & Jankowski (2011), *Modified linear viscoelastic model of
    earthquake-induced structural pounding*, Iranian J. Sci. Technol. 35(C1):51–62, derived
    for ``F = k δ + c δ̇`` with the dashpot acting only while approaching. The seed paper
    (eq 20) presents it as a formula for the *nonlinear* viscoelastic law; the audit runs it
    with both.
    """
    x = _check_e(e)
    return _out((1.0 - x**2) / (x * (x * (np.pi - 2.0) + 2.0)))


def zeta_naderpour(e: ArrayLike) -> FloatArray | float:
    """Impact damping ratio proposed by the seed paper (eq 39, Table 1).

    ``ζ = ((1 − e²) / (e (sqrt(π)(0.5 e + 1/π) − e)))²``.

    Source: Naderpour, Khatami & Barros (2015), COMPDYN, eq 39; proposed for the nonlinear
    viscoelastic law (eqs 17–18). It reproduces the paper's Table 1 to its printed precision
    (the table truncates rather than rounds some entries, e.g. 32.74 for 32.745).
    """
    x = _check_e(e)
    return _out(((1.0 - x**2) / (x * (np.sqrt(np.pi) * (0.5 * x + 1.0 / np.pi) - x))) ** 2)


# --------------------------------------------------------------------------- χ formulas
def chi_hunt_crossley(e: ArrayLike) -> FloatArray | float:
    """Hunt & Crossley (1975) damping factor ``χ = 3 (1 − e) / 2``.

    Source: Hunt & Crossley, *Coefficient of restitution interpreted as damping in
    vibroimpact*, J. Appl. Mech. 42(2):440–445. For ``F = k δⁿ (1 + χ δ̇ / v0)``.
    """
    x = _check_e(e)
    return _out(1.5 * (1.0 - x))


def chi_lankarani_nikravesh(e: ArrayLike) -> FloatArray | float:
    """Lankarani & Nikravesh (1990) damping factor ``χ = 3 (1 − e²) / 4``.

    Source: Lankarani & Nikravesh, *A contact force model with hysteresis damping for impact
    analysis of multibody systems*, J. Mech. Des. 112(3):369–376. The same factor defines
    the Hertzdamp model of Muthukumar & DesRoches (2006), EESD 35(7):811–828. Valid for e
    near 1 (derived assuming small dissipation).
    """
    x = _check_e(e)
    return _out(0.75 * (1.0 - x**2))


def chi_flores(e: ArrayLike) -> FloatArray | float:
    """Ye, Li & Zhu (2009) / Flores et al. (2011) damping factor ``χ = 8 (1 − e) / (5 e)``.

    Sources: Ye, Li & Zhu, EESD 38:1135–1142 (2009); Flores, Machado, Silva & Martins,
    Multibody Syst. Dyn. 25:357–375 (2011). For ``F = k δⁿ (1 + χ δ̇ / v0)``.
    """
    x = _check_e(e)
    return _out(1.6 * (1.0 - x) / x)


def chi_gonthier(e: ArrayLike) -> FloatArray | float:
    """Gonthier et al. (2004) damping factor ``χ = (1 − e²) / e``.

    Source: Gonthier, McPhee, Lange & Piedbœuf, *A regularized contact model with asymmetric
    damping and dwell-time dependent friction*, Multibody Syst. Dyn. 11:209–233.
    """
    x = _check_e(e)
    return _out((1.0 - x**2) / x)


# --------------------------------------------------------------------------- registry
@dataclass(frozen=True)
class DampingFormula:
    """A formula mapping ``e`` to a law's damping parameter, with its provenance."""

    key: str
    kind: Literal["zeta", "chi"]
    function: Callable[[ArrayLike], FloatArray | float]
    source: str
    equation: str
    derived_for: str
    """Key of the contact law the formula was derived for (see ``pounding.contact.LAWS``)."""
    exact: bool = False
    """True for the exact inverse of the law's own ``e`` (no approximation: an impact of two
    free bodies achieves the target to round-off); False for a published closed form."""

    def __call__(self, e: ArrayLike) -> FloatArray | float:
        return self.function(e)


FORMULAS: dict[str, DampingFormula] = {
    f.key: f
    for f in [
        DampingFormula("anagnostopoulos", "zeta", zeta_anagnostopoulos,
                       "Anagnostopoulos 1988, EESD 16(3):443-456", "zeta = -ln e / sqrt(pi^2 + ln^2 e)",
                       "kelvin-voigt"),
        DampingFormula("schwager-poschel", "zeta", zeta_kelvin_voigt_clipped,
                       "Schwager & Poschel 2007, Granular Matter 9:465-469",
                       "e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)), inverted exactly",
                       "kelvin-voigt", exact=True),
        DampingFormula("jankowski", "zeta", zeta_jankowski,
                       "Jankowski 2006, EESD 35(4):517-524", "seed eq 19", "nonlinear-viscoelastic"),
        DampingFormula("mahmoud", "zeta", zeta_mahmoud,
                       "Mahmoud & Jankowski 2011, IJST 35(C1):51-62", "seed eq 20",
                       "modified-kelvin-voigt"),
        DampingFormula("naderpour", "zeta", zeta_naderpour,
                       "Naderpour, Khatami & Barros 2015, COMPDYN", "seed eq 39, Table 1",
                       "nonlinear-viscoelastic"),
        DampingFormula("hunt-crossley", "chi", chi_hunt_crossley,
                       "Hunt & Crossley 1975, J. Appl. Mech. 42(2):440-445", "chi = 3(1-e)/2",
                       "hunt-crossley"),
        DampingFormula("lankarani-nikravesh", "chi", chi_lankarani_nikravesh,
                       "Lankarani & Nikravesh 1990, J. Mech. Des. 112(3):369-376; Hertzdamp of "
                       "Muthukumar & DesRoches 2006", "chi = 3(1-e^2)/4", "hunt-crossley"),
        DampingFormula("flores", "chi", chi_flores,
                       "Ye, Li & Zhu 2009, EESD 38:1135-1142; Flores et al. 2011, MSD 25:357-375",
                       "chi = 8(1-e)/(5e)", "hunt-crossley"),
        DampingFormula("gonthier", "chi", chi_gonthier,
                       "Gonthier et al. 2004, MSD 11:209-233", "chi = (1-e^2)/e", "hunt-crossley"),
        DampingFormula("exact-modified-kelvin-voigt", "zeta", zeta_modified_kelvin_voigt_exact,
                       "the law's e(zeta) from the damped free vibration of the approach "
                       "(docs/laws/modified-kelvin-voigt.md)",
                       "e = exp(-zeta atan(sqrt(1 - zeta^2)/zeta) / sqrt(1 - zeta^2)), inverted "
                       "exactly", "modified-kelvin-voigt", exact=True),
        DampingFormula("exact-hunt-crossley", "chi", chi_hunt_crossley_exact,
                       "Hunt & Crossley 1975, J. Appl. Mech. 42(2):440-445 (the law's own e(chi))",
                       "chi (1 + e) = ln((1 + chi) / (1 - chi e)), inverted exactly",
                       "hunt-crossley", exact=True),
        DampingFormula("exact-nonlinear-viscoelastic", "zeta", zeta_nonlinear_viscoelastic_exact,
                       "Jankowski 2006, EESD 35(4):517-524 (the law's approach, integrated)",
                       "e = sqrt(0.8 x_max^2.5) of x'' = -x^1.5 - 2 zeta x^0.25 x', inverted "
                       "exactly", "nonlinear-viscoelastic", exact=True),
    ]
}
"""Every damping formula, keyed by a short name used on the command line."""


TABLE1_E: tuple[float, ...] = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)
"""Coefficients of restitution of the seed paper's Table 1."""

TABLE1_ZETA: tuple[float, ...] = (320.71, 78.59, 32.74, 16.39, 8.74, 4.62, 2.26, 0.90, 0.21)
"""Impact damping ratios printed in the seed paper's Table 1 (Naderpour et al. 2015)."""


def formula(key: str) -> DampingFormula:
    """Look up a damping formula by key, raising a ValueError that lists the keys."""
    from pounding.validation import choice

    return FORMULAS[choice("formula", key, FORMULAS)]


PUBLISHED: tuple[str, ...] = tuple(k for k in FORMULAS if not k.startswith("exact-"))
"""Keys of the published formulas (closed forms, and Schwager & Pöschel's exact e(ζ) of the
clipped Kelvin–Voigt law): what the seed's Fig 4 and ``pounding zeta`` compare."""
