"""pounding: seismic pounding of adjacent buildings.

The public API, by concept (each lives in its own module):

* contact laws and damping formulas — :mod:`pounding.contact`
* one collision of two bodies: :func:`simulate_collision`, calibration and fitting
* ground motions — :mod:`pounding.ground_motion`
* structures — :mod:`pounding.structure`
* the seed paper's link-element relations — :mod:`pounding.link_element`

Units are SI throughout: m, kg, s, N, J.
"""

from pounding.contact import (
    FORMULAS,
    LAWS,
    BilinearImpact,
    ContactLaw,
    Hertz,
    HuntCrossley,
    KelvinVoigt,
    LinearSpring,
    ModifiedKelvinVoigt,
    NonlinearViscoelastic,
    hertzdamp,
    m_effective,
    naderpour_2015,
)
from pounding.contact.audit import restitution_audit
from pounding.contact.calibration import calibrate, calibrate_bilinear, fit_impact
from pounding.contact.collision import CollisionResult, simulate_collision
from pounding.contact.factory import make_law
from pounding.ground_motion import GroundMotion, el_centro, read_at2, read_record, read_text
from pounding.structure import ModalDamping, RayleighDamping, ShearBuilding, modes

__version__ = "0.1.0"

__all__ = [
    "FORMULAS", "LAWS", "BilinearImpact", "CollisionResult", "ContactLaw", "GroundMotion",
    "Hertz", "HuntCrossley", "KelvinVoigt", "LinearSpring", "ModalDamping",
    "ModifiedKelvinVoigt", "NonlinearViscoelastic", "RayleighDamping", "ShearBuilding",
    "calibrate", "calibrate_bilinear", "el_centro", "fit_impact", "hertzdamp", "m_effective",
    "make_law", "modes", "naderpour_2015", "read_at2", "read_record", "read_text",
    "restitution_audit", "simulate_collision",
]
