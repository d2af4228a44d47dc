"""The frames of the kernel's frame tests (``test_frame_kernel*.py``; pytest puts a test's
folder on sys.path)."""

from __future__ import annotations

from pounding.contact.spec import ContactSpec
from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
from pounding.structure.damping import RayleighDamping
from pounding.structure.frame import Frame, regular_frame

KV = ContactSpec("kelvin-voigt", k=2e9, e=0.65)
MASS = 5e4  # kg, the portal's floor
MP_COLUMN = 3e5  # N·m


def _portal(k0: float = 1e11) -> Frame:
    """The portal of examples/portal_pushover.toml with a floor mass: span 6 m, height 4 m,
    EI 2e8 N·m², EPP hinges Mp 300 kN·m (columns) / 600 kN·m (beam), 5 % Rayleigh."""
    return regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                         column_hinge=ElasticPlastic(k0=k0, m_y=MP_COLUMN),
                         beam_hinge=ElasticPlastic(k0=k0, m_y=6e5), floor_mass=MASS,
                         damping=RayleighDamping(0.05, 0.05), name="portal")


def _three_storeys(name: str, strength: float = 1.0, gravity: bool = False) -> Frame:
    """A 3-storey, 2-bay frame with bilinear hinges (3 % hardening); with ``gravity``, beam
    loads, a leaning column and the columns' P-Delta."""
    law = [BilinearHinge(k0=1e11, m_y=strength * m, hardening=0.03) for m in (4e5, 3.5e5, 3e5)]
    return regular_frame([6.0, 6.0], [4.0, 3.5, 3.5], column_EI=[3e8, 2.5e8, 2e8],
                         beam_EI=[2.5e8, 2e8, 1.5e8], column_hinge=law, beam_hinge=law[::-1],
                         floor_mass=[8e4, 8e4, 6e4], beam_load=2e4 if gravity else 0.0,
                         leaning_load=5e5 if gravity else 0.0,
                         geometry="p-delta" if gravity else "linear", name=name)
