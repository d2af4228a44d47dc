"""Foundations on soil: soil–structure interaction by the substructure method.

* :class:`Soil` — a homogeneous half-space and its strain-compatible properties (EN 1998-5
  Table 4.1) (:mod:`.soil`).
* :class:`Footing`, :func:`footing_stiffness`, :func:`footing_dashpots` — a rigid
  footing's sway and rocking springs and dashpots, on the surface or embedded, and its
  torsion spring and dashpot (:func:`~.impedance.footing_torsion`) (:mod:`.impedance`).
* :func:`flexible_base` → :class:`FlexibleBaseBuilding` — a building on its footing
  (:mod:`.flexible_base`).
* :func:`plan_flexible_base` → :class:`PlanFlexibleBaseBuilding` — a building in plan on its
  footing: sway along x and y, rocking about both, torsion (:mod:`.plan_base`).
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
from pounding.structure.foundation.plan_base import (
    PlanFlexibleBaseBuilding,
    PlanFoundation,
    plan_flexible_base,
)
from pounding.structure.foundation.soil import Soil, en1998_5_reduction

__all__ = ["FlexibleBaseBuilding", "Footing", "Foundation", "Impedance",
           "PlanFlexibleBaseBuilding", "PlanFoundation", "Soil", "en1998_5_reduction",
           "flexible_base", "footing_dashpots", "footing_stiffness", "plan_flexible_base"]
