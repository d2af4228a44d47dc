"""Structures: the shear building, its damping, its modes, and buildings side by side.

* :class:`ShearBuilding` — lumped floor masses, storey stiffnesses and heights
  (:mod:`pounding.structure.shear_building`).
* :class:`RayleighDamping`, :class:`ModalDamping` — how ``C`` is built
  (:mod:`pounding.structure.damping`).
* :func:`modes` → :class:`ModalResult` — periods, shapes, participation, effective masses
  (:mod:`pounding.structure.modal`).
* :func:`assemble`, :func:`shared_levels` — several buildings as one block-diagonal system
  and the floor pairs that can collide (:mod:`pounding.structure.assembly`).
* :class:`MatrixBuilding`, :func:`read_matrix_building`, :func:`read_matrix`,
  :func:`lumped_masses` — buildings given as mass and stiffness matrices read from files
  (:mod:`pounding.structure.matrices`, :mod:`~pounding.structure.matrix_files`,
  :mod:`~pounding.structure.matrix_checks`), planar, beside shear buildings in a
  :class:`~pounding.model.PoundingModel`. Matrices out of an
  OpenSeesPy model: :func:`pounding.structure.opensees_matrices.matrices_from_opensees`.

Names are imported on first use (PEP 562): importing one module of the package (say
:mod:`pounding.structure.floor_arrays`) loads only what that module needs.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pounding.lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    "AssembledSystem": "pounding.structure.assembly",
    "assemble": "pounding.structure.assembly",
    "shared_levels": "pounding.structure.assembly",
    "DampingModel": "pounding.structure.damping",
    "ModalDamping": "pounding.structure.damping",
    "RayleighDamping": "pounding.structure.damping",
    "rayleigh_coefficients": "pounding.structure.damping",
    "MatrixBuilding": "pounding.structure.matrices",
    "lumped_masses": "pounding.structure.matrix_checks",
    "read_matrix": "pounding.structure.matrix_files",
    "read_matrix_building": "pounding.structure.matrix_files",
    "ModalResult": "pounding.structure.modal",
    "eigenmodes": "pounding.structure.modal",
    "modal_result": "pounding.structure.modal",
    "modes": "pounding.structure.modal",
    "ShearBuilding": "pounding.structure.shear_building",
    "shear_stiffness_matrix": "pounding.structure.shear_building",
}
"""Public name → the module that defines it."""

__all__ = [
    "AssembledSystem",
    "DampingModel",
    "MatrixBuilding",
    "ModalDamping",
    "ModalResult",
    "RayleighDamping",
    "ShearBuilding",
    "assemble",
    "eigenmodes",
    "lumped_masses",
    "modal_result",
    "modes",
    "rayleigh_coefficients",
    "read_matrix",
    "read_matrix_building",
    "shared_levels",
    "shear_stiffness_matrix",
]

__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


if TYPE_CHECKING:  # what type checkers and IDEs see: the same names, imported eagerly
    from pounding.structure.assembly import AssembledSystem, assemble, shared_levels
    from pounding.structure.damping import (
        DampingModel,
        ModalDamping,
        RayleighDamping,
        rayleigh_coefficients,
    )
    from pounding.structure.matrices import MatrixBuilding
    from pounding.structure.matrix_checks import lumped_masses
    from pounding.structure.matrix_files import read_matrix, read_matrix_building
    from pounding.structure.modal import ModalResult, eigenmodes, modal_result, modes
    from pounding.structure.shear_building import ShearBuilding, shear_stiffness_matrix
