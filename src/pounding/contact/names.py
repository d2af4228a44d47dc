"""The names of the contact laws, as model files and the command line give them (a light
module: checking a name loads no law)."""

from __future__ import annotations

__all__ = ["IMPACT_LAW_NAMES", "LAW_NAMES"]

IMPACT_LAW_NAMES: tuple[str, ...] = (
    "linear-spring", "kelvin-voigt", "modified-kelvin-voigt", "hertz", "hunt-crossley",
    "hertzdamp", "nonlinear-viscoelastic", "naderpour", "bilinear-impact",
)
"""The impact laws: those the single-collision commands (``pounding collide``) offer."""

LAW_NAMES: tuple[str, ...] = (*IMPACT_LAW_NAMES, "abutment", "shear-key")
"""Names :func:`pounding.contact.factory.make_law` accepts: the impact laws, the abutment
backfill (a wall's law in a model file; :mod:`pounding.contact.abutment`) and the
sacrificial shear key (a bridge's, :mod:`pounding.contact.shear_key`). ``hertzdamp`` is
Hunt–Crossley with the Lankarani–Nikravesh χ; ``naderpour`` is the nonlinear viscoelastic
law with ζ of seed eq 39."""
