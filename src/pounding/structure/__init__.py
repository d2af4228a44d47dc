"""Structures: the shear building, its damping, its modes, and buildings side by side.

* :class:`ShearBuilding` — lumped floor masses, storey stiffnesses and heights
  (:mod:`pounding.structure.shear_building`).
* :class:`RayleighDamping`, :class:`ModalDamping` — how ``C`` is built
  (:mod:`pounding.structure.damping`).
* :func:`modes` → :class:`ModalResult` — periods, shapes, participation, effective masses
  (:mod:`pounding.structure.modal`).
* :func:`assemble`, :func:`shared_levels` — several buildings as one block-diagonal system
  and the floor pairs that can collide (:mod:`pounding.structure.assembly`).
"""

from pounding.structure.assembly import AssembledSystem, assemble, shared_levels
from pounding.structure.damping import (
    DampingModel,
    ModalDamping,
    RayleighDamping,
    rayleigh_coefficients,
)
from pounding.structure.modal import ModalResult, eigenmodes, modal_result, modes
from pounding.structure.shear_building import ShearBuilding, shear_stiffness_matrix

__all__ = [
    "AssembledSystem",
    "DampingModel",
    "ModalDamping",
    "ModalResult",
    "RayleighDamping",
    "ShearBuilding",
    "assemble",
    "eigenmodes",
    "modal_result",
    "modes",
    "rayleigh_coefficients",
    "shared_levels",
    "shear_stiffness_matrix",
]
