"""Foundations on soil: soil–structure interaction by the substructure method.

* :class:`Soil` — a homogeneous half-space and its strain-compatible properties (EN 1998-5
  Table 4.1) (:mod:`.soil`).
* :class:`Footing`, :func:`footing_stiffness`, :func:`footing_dashpots` — a rigid
  footing's sway and rocking springs and dashpots, on the surface or embedded
  (:mod:`.impedance`).
* :func:`flexible_base` → :class:`FlexibleBaseBuilding` — a building on its footing
  (:mod:`.flexible_base`).
"""

from pounding.structure.foundation.flexible_base import (
    FlexibleBaseBuilding,
    Foundation,
    flexible_base,
)
from pounding.structure.foundation.impedance import (
    Footing,
    Impedance,
    footing_dashpots,
    footing_stiffness,
)
from pounding.structure.foundation.soil import Soil, en1998_5_reduction

__all__ = ["FlexibleBaseBuilding", "Footing", "Foundation", "Impedance", "Soil",
           "en1998_5_reduction", "flexible_base", "footing_dashpots", "footing_stiffness"]
