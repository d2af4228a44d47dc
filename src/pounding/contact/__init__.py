"""Contact laws (impact models), damping-from-restitution formulas and impact analysis.

Every law obeys one contract, written in :mod:`pounding.contact.base`. The seed paper's link
element under harmonic motion (its eqs 1–15) is :mod:`pounding.contact.link_element`.

Names are imported on first use (PEP 562): importing one module of the package (the link
element, say) does not load the laws' compiled kernels.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    **{name: "pounding.contact.base" for name in ("ContactLaw", "ContactResponse",
                                                    "m_effective")},
    "AbutmentBackfill": "pounding.contact.abutment",
    "BilinearImpact": "pounding.contact.bilinear",
    "LAWS": "pounding.contact.factory",
    **{name: "pounding.contact.hertz" for name in ("Hertz", "HuntCrossley",
                                                     "NonlinearViscoelastic", "hertzdamp",
                                                     "naderpour_2015")},
    **{name: "pounding.contact.linear" for name in ("KelvinVoigt", "LinearSpring",
                                                      "ModifiedKelvinVoigt")},
    **{name: "pounding.contact.restitution" for name in ("FORMULAS", "DampingFormula",
                                                           "formula")},
    "ShearKey": "pounding.contact.shear_key",
}
"""Public name → the module that defines it."""

__all__ = [
    "AbutmentBackfill",
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
    "ShearKey",
    "formula",
    "hertzdamp",
    "m_effective",
    "naderpour_2015",
]


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.contact.abutment import AbutmentBackfill
    from pounding.contact.base import ContactLaw, ContactResponse, m_effective
    from pounding.contact.bilinear import BilinearImpact
    from pounding.contact.factory import LAWS
    from pounding.contact.hertz import (
        Hertz,
        HuntCrossley,
        NonlinearViscoelastic,
        hertzdamp,
        naderpour_2015,
    )
    from pounding.contact.linear import KelvinVoigt, LinearSpring, ModifiedKelvinVoigt
    from pounding.contact.restitution import FORMULAS, DampingFormula, formula
    from pounding.contact.shear_key import ShearKey
