"""``foundation = {...}`` of a ``[[building]]``: the building on a flexible base (soil–structure
interaction, :mod:`pounding.structure.foundation`).

* ``foundation = { radius = 5.0, soil = { vs = 150.0, density = 1800.0, poisson = 0.33 } }``
  — a rigid circular surface footing of radius 5 m on a half-space
  (``embedment = 2.0``: its base 2 m below the surface);
* ``length`` and ``width`` [m] (along the row and across it) instead of ``radius``: a
  rectangular footing;
* ``mass`` [kg] and ``inertia`` [kg·m²] (about the rocking axis) of the footing: default 0
  (massless: condensed out of the building's matrices);
* ``embedment`` [m]: the depth of the footing's base below the ground surface, its sidewalls
  in contact with the soil over all of it (default 0: a surface footing); at most the
  footing's width (a circle: 1.75 R) — Pais & Kausel's embedment factors (NIST GCR
  12-917-21 Table 2-2b) and the sidewalls' radiation dashpots
  (:mod:`pounding.structure.foundation.impedance`);
* ``dashpots = false``: the soil's springs only (default: the springs and the radiation and
  material dashpots);
* ``soil.shaking`` = ``α S`` (0.1–0.3): take the strain-compatible shear modulus and the
  soil's own damping of EN 1998-5 Table 4.1 for that level of shaking (default: the
  small-strain modulus, no material damping).

A building on a flexible base is an SDOF, uniform, storey-by-storey or matrix building,
not base-isolated — one with ``storey_law`` (yielding storeys) needs the footing's ``mass``
and ``inertia`` (its sway and rocking are then degrees of freedom) — a frame (one with
plastic hinges needs them too: :func:`pounding.structure.frame_linear.
frame_on_flexible_base`), or a building in plan
(its footing centred under the plan, ``length`` along x and ``width`` along y, ``inertia``
about y: it also sways along y, rocks about x and twists;
:mod:`pounding.structure.foundation.plan_base`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

from pydantic import Field, model_validator

from pounding.config.base import Section, field_error
from pounding.config.quantities import MAX_LENGTH, MAX_MASS, Length, Unit

if TYPE_CHECKING:
    from pounding.structure.foundation import Footing, Soil

__all__ = ["FoundationConfig", "SoilConfig"]

MassOrZero = Annotated[float, Field(ge=0, le=MAX_MASS), Unit("kg")]
Inertia = Annotated[float, Field(ge=0, le=MAX_MASS * 1e6), Unit("kg·m²")]
Depth = Annotated[float, Field(ge=0, le=MAX_LENGTH), Unit("m")]


class SoilConfig(Section):
    """``soil = { vs, density, poisson, shaking }``
    (:class:`pounding.structure.foundation.Soil`)."""

    vs: Annotated[float, Field(gt=0, le=10_000.0), Unit("m/s")]
    density: Annotated[float, Field(gt=0, le=10_000.0), Unit("kg/m³")]
    poisson: Annotated[float, Field(ge=0, lt=0.5)]
    shaking: Annotated[float, Field(ge=0.1, le=0.3)] | None = None


class FoundationConfig(Section):
    """``foundation = {...}`` (module docstring)."""

    radius: Length | None = None
    length: Length | None = None
    width: Length | None = None
    mass: MassOrZero = 0.0
    inertia: Inertia = 0.0
    dashpots: bool = True
    embedment: Depth = 0.0
    soil: SoilConfig

    @model_validator(mode="after")
    def _shape(self) -> FoundationConfig:
        if self.radius is not None:
            for key in ("length", "width"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"give radius (a circle) or length and width (a "
                                           f"rectangle), not both (got radius = {self.radius:g} "
                                           "m)")
        elif self.length is None or self.width is None:
            missing = "length" if self.length is None else "width"
            raise field_error(missing, "required: give radius [m] (a circular footing) or "
                                       "length and width [m] (a rectangle: along the row and "
                                       "across it)")
        from pounding.structure.foundation.impedance import embedment_message, max_embedment

        deepest = max_embedment(self.radius, self.length, self.width)
        if self.embedment > deepest:
            raise field_error("embedment", embedment_message(self.embedment, deepest))
        return self

    def build(self) -> tuple[Footing, Soil]:
        """The ``(Footing, Soil)`` of :mod:`pounding.structure.foundation`."""
        from pounding.structure.foundation import Footing, Soil

        s = self.soil
        return (Footing(radius=self.radius, length=self.length, width=self.width,
                        mass=self.mass, inertia=self.inertia, dashpots=self.dashpots,
                        embedment=self.embedment),
                Soil(s.vs, s.density, s.poisson, s.shaking))
