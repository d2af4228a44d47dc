"""The restitution audit: does a damping formula give the ``e`` it was built from?

For each formula, used with the law it was derived for and with the other laws people pair
it with, :func:`restitution_audit` builds the law from a target ``e``, simulates one impact
(:func:`~pounding.contact.collision.simulate_collision`) and records the ``e`` the impact
actually achieves. ``pounding audit`` prints the table; ``docs/audit.md`` discusses it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pounding.contact.base import ContactLaw, m_effective
from pounding.contact.bilinear import BilinearImpact
from pounding.contact.calibration import hertz_delta_max
from pounding.contact.collision import simulate_collision
from pounding.contact.hertz import HuntCrossley, NonlinearViscoelastic
from pounding.contact.linear import KelvinVoigt, ModifiedKelvinVoigt
from pounding.contact.restitution import TABLE1_E, FORMULAS
from pounding.validation import positive, restitution


@dataclass(frozen=True)
class AuditCase:
    """Impact used by the audit (defaults: Jankowski's concrete contact between the two
    SDOF structures of the benchmark; achieved e does not depend on them except for the
    bilinear element, whose loop is sized at the elastic Hertz ``δmax`` at this ``v0``)."""

    m1: float = 2.0e5
    """Mass of body 1 [kg]."""
    m2: float = 3.0e5
    """Mass of body 2 [kg]."""
    v0: float = 0.5
    """Impact velocity [m/s]."""
    k_h: float = 2.75e9
    """Hertz stiffness of the nonlinear laws [N/m^1.5] (Jankowski 2005)."""
    k: float = 9.3e8
    """Stiffness of the linear laws [N/m]."""

    def __post_init__(self) -> None:
        for name in ("m1", "m2", "v0", "k_h", "k"):
            positive(name, getattr(self, name))


@dataclass(frozen=True)
class Pairing:
    """A damping formula used with a law."""

    formula: str
    law: str
    intended: bool
    """True if the formula was derived for this law."""
    build: Callable[[float, AuditCase], ContactLaw]


def _zeta(key: str, e: float) -> float:
    return float(FORMULAS[key](e))


PAIRINGS: tuple[Pairing, ...] = (
    Pairing("anagnostopoulos", "kelvin-voigt (tension)", True,
            lambda e, c: KelvinVoigt.from_zeta(c.k, _zeta("anagnostopoulos", e), c.m1, c.m2, True)),
    Pairing("anagnostopoulos", "kelvin-voigt (no tension)", False,
            lambda e, c: KelvinVoigt.from_zeta(c.k, _zeta("anagnostopoulos", e), c.m1, c.m2, False)),
    Pairing("schwager-poschel", "kelvin-voigt (no tension)", True,
            lambda e, c: KelvinVoigt.from_zeta(c.k, _zeta("schwager-poschel", e), c.m1, c.m2,
                                               False)),
    Pairing("anagnostopoulos", "modified-kelvin-voigt", False,
            lambda e, c: ModifiedKelvinVoigt.from_zeta(c.k, _zeta("anagnostopoulos", e), c.m1, c.m2)),
    Pairing("mahmoud", "modified-kelvin-voigt", True,
            lambda e, c: ModifiedKelvinVoigt.from_zeta(c.k, _zeta("mahmoud", e), c.m1, c.m2)),
    Pairing("mahmoud", "nonlinear-viscoelastic", False,
            lambda e, c: NonlinearViscoelastic(c.k_h, _zeta("mahmoud", e), m_effective(c.m1, c.m2))),
    Pairing("jankowski", "nonlinear-viscoelastic", True,
            lambda e, c: NonlinearViscoelastic(c.k_h, _zeta("jankowski", e), m_effective(c.m1, c.m2))),
    Pairing("naderpour", "nonlinear-viscoelastic", True,
            lambda e, c: NonlinearViscoelastic(c.k_h, _zeta("naderpour", e), m_effective(c.m1, c.m2))),
    Pairing("naderpour", "kelvin-voigt (tension)", False,
            lambda e, c: KelvinVoigt.from_zeta(c.k, _zeta("naderpour", e), c.m1, c.m2, True)),
    Pairing("hunt-crossley", "hunt-crossley", True,
            lambda e, c: HuntCrossley.from_restitution(c.k_h, e, "hunt-crossley")),
    Pairing("lankarani-nikravesh", "hunt-crossley", True,
            lambda e, c: HuntCrossley.from_restitution(c.k_h, e, "lankarani-nikravesh")),
    Pairing("flores", "hunt-crossley", True,
            lambda e, c: HuntCrossley.from_restitution(c.k_h, e, "flores")),
    Pairing("gonthier", "hunt-crossley", True,
            lambda e, c: HuntCrossley.from_restitution(c.k_h, e, "gonthier")),
    Pairing("muthukumar (energy-equivalent)", "bilinear-impact", True,
            lambda e, c: BilinearImpact.from_hertz(
                c.k_h, e, hertz_delta_max(c.k_h, m_effective(c.m1, c.m2), c.v0))),
)
"""Every (formula, law) pair the audit runs."""


def restitution_audit(e: ArrayLike = TABLE1_E, case: AuditCase | None = None,
                      pairings: tuple[Pairing, ...] = PAIRINGS) -> pd.DataFrame:
    """Target ``e`` against the ``e`` each formula achieves with each law.

    Parameters
    ----------
    e : array_like
        Target coefficients of restitution (default: the seed's Table 1 values 0.1 … 0.9).
    case : AuditCase, optional
        Masses, impact velocity and stiffnesses of the impact.
    pairings : tuple of Pairing
        Which formula–law pairs to run.

    Returns
    -------
    pandas.DataFrame
        One row per (pairing, target e): ``formula``, ``law``, ``intended``, ``target_e``,
        ``damping`` (ζ, χ or — for the bilinear element — the loop's design e),
        ``achieved_e``, ``error`` (achieved − target), ``separated``,
        ``energy_error`` (integration check), ``peak_force`` [N], ``duration`` [s].
    """
    targets = np.atleast_1d(restitution(e))
    case = case or AuditCase()
    rows = []
    for p in pairings:
        for target in targets:
            law = p.build(float(target), case)
            r = simulate_collision(law, case.m1, case.m2, case.v0)
            damping = law.damping if law.damping_field else float(target)
            if isinstance(law, (KelvinVoigt, ModifiedKelvinVoigt)):
                damping = law.c / (2.0 * np.sqrt(law.k * m_effective(case.m1, case.m2)))
            rows.append({
                "formula": p.formula, "law": p.law, "intended": p.intended,
                "target_e": float(target), "damping": damping, "achieved_e": r.e,
                "error": r.e - float(target), "separated": r.separated,
                "energy_error": r.energy_error, "peak_force": r.peak_force,
                "duration": r.duration,
            })
    return pd.DataFrame(rows)
