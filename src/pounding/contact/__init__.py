"""Contact laws (impact models), damping-from-restitution formulas and impact analysis.

Every law obeys one contract, written in :mod:`pounding.contact.base`. The seed paper's link
element under harmonic motion (its eqs 1–15) is :mod:`pounding.contact.link_element`.
"""

from pounding.contact.base import ContactLaw, ContactResponse, m_effective
from pounding.contact.bilinear import BilinearImpact
from pounding.contact.hertz import Hertz, HuntCrossley, NonlinearViscoelastic, hertzdamp, naderpour_2015
from pounding.contact.linear import KelvinVoigt, LinearSpring, ModifiedKelvinVoigt
from pounding.contact.restitution import FORMULAS, DampingFormula, formula

LAWS: dict[str, type[ContactLaw]] = {
    "linear-spring": LinearSpring,
    "kelvin-voigt": KelvinVoigt,
    "modified-kelvin-voigt": ModifiedKelvinVoigt,
    "hertz": Hertz,
    "hunt-crossley": HuntCrossley,
    "nonlinear-viscoelastic": NonlinearViscoelastic,
    "bilinear-impact": BilinearImpact,
}
"""Every contact law class, keyed by the name used in configs and on the command line."""

__all__ = [
    "BilinearImpact",
    "ContactLaw",
    "ContactResponse",
    "DampingFormula",
    "FORMULAS",
    "Hertz",
    "HuntCrossley",
    "KelvinVoigt",
    "LAWS",
    "LinearSpring",
    "ModifiedKelvinVoigt",
    "NonlinearViscoelastic",
    "formula",
    "hertzdamp",
    "m_effective",
    "naderpour_2015",
]
