"""``plan = {...}`` and ``elements = [...]`` of a ``[[building]]`` in plan: the floor plan and
the lateral load-resisting elements of a :class:`~pounding.structure.plan.PlanBuilding`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, model_validator

from pounding.config.base import Section, field_error, fmt
from pounding.config.quantities import Angle, Coordinate, PlanLength, StiffnessOrZero, Unit
from pounding.structure.floor_arrays import MAX_FLOORS

if TYPE_CHECKING:
    from pounding.structure.plan import LateralElement

__all__ = ["ElementConfig", "PlanConfig"]

Inertia = Annotated[float, Field(gt=0), Unit("kg·m²")]
"""A floor's polar moment of inertia about its centre of mass [kg·m²] (bounded above by its
mass and plan: :meth:`PlanConfig.check_inertias`)."""
Point = Annotated[list[Coordinate], Field(min_length=2, max_length=2)]


class PlanConfig(Section):
    """``plan = { width = 20.0, depth = 12.0, site_y = 6.0 }``: the floor plan of a building in
    plan (:class:`~pounding.structure.plan.PlanBuilding`), the rectangle ``[0, width] ×
    [0, depth]`` [m] in the building's own plan coordinates, standing with its ``y = 0``
    edge at site ``y = site_y`` [m] (default 0). Optional ``mass_centres`` [m] (one
    ``[x, y]`` for every floor, or one a floor; default the centre of the plan), each inside
    the plan, and ``inertias`` [kg·m²] (polar moment of inertia of each floor about its
    centre of mass, one value or one a floor; default ``m (width² + depth²) / 12``), each at
    most ``m ρ²`` with ``ρ`` the distance from the centre of mass to the farthest corner
    (all the floor's mass there)."""

    width: PlanLength
    depth: PlanLength
    site_y: Coordinate = 0.0
    mass_centres: Point | Annotated[list[Point], Field(min_length=1)] | None = None
    inertias: Inertia | Annotated[list[Inertia], Field(min_length=1)] | None = None

    @model_validator(mode="after")
    def _centres_inside(self) -> PlanConfig:
        for i, (x, y) in enumerate(self.centres()):
            if not (0.0 <= x <= self.width and 0.0 <= y <= self.depth):
                at = ("mass_centres", i) if self.mass_centres and isinstance(
                    self.mass_centres[0], list) else "mass_centres"
                raise field_error(at, f"must lie inside the plan, x in [0, {fmt(self.width)}] "
                                      f"and y in [0, {fmt(self.depth)}] m (got "
                                      f"[{fmt(x)}, {fmt(y)}])")
        return self

    def centres(self) -> list[tuple[float, float]]:
        """The mass centres given, as ``(x, y)`` pairs (none: an empty list)."""
        if self.mass_centres is None:
            return []
        if isinstance(self.mass_centres[0], list):
            return [(float(p[0]), float(p[1])) for p in self.mass_centres]
        return [(float(self.mass_centres[0]), float(self.mass_centres[1]))]

    def check_inertias(self, masses: list[float]) -> None:
        """Refuse an inertia no floor of that mass on this plan can have: above ``m ρ²``,
        ``ρ`` the distance from the floor's centre of mass to the farthest plan corner."""
        if self.inertias is None:
            return
        n = len(masses)
        centres = self.centres() or [(self.width / 2, self.depth / 2)]
        for i, m in enumerate(masses):
            value = self.inertias[i] if isinstance(self.inertias, list) else self.inertias
            if isinstance(self.inertias, list) and len(self.inertias) != n:
                return  # the count is reported by the building
            xc, yc = centres[i] if len(centres) == n else centres[0]
            rho2 = max((cx - xc) ** 2 + (cy - yc) ** 2
                       for cx in (0.0, self.width) for cy in (0.0, self.depth))
            if value > m * rho2 * (1 + 1e-12):
                at = ("plan", "inertias", i) if isinstance(self.inertias, list) else (
                    "plan", "inertias")
                raise field_error(at, f"must be in (0, {m * rho2:.6g}] kg·m² for floor {i + 1} "
                                      f"(mass {fmt(m)} kg, its farthest corner "
                                      f"{rho2 ** 0.5:.6g} m from its centre of mass) (got "
                                      f"{fmt(value)})")


class ElementConfig(Section):
    """One of ``elements = [ { x = 0.0, y = 6.0, direction = "y", stiffnesses = [...] }, … ]``:
    a lateral load-resisting element (frame, wall line) of a building in plan
    (:class:`~pounding.structure.plan.LateralElement`): its plan position ``x``, ``y`` [m]
    (inside the plan), the ``direction`` it resists (``"x"``, ``"y"`` or an angle in
    [-360, 360] degrees from x, counter-clockwise), ``stiffnesses`` [N/m] one a storey (or one
    value for every storey; 0 where the element stops) and an optional ``name``."""

    x: Coordinate
    y: Coordinate
    direction: Literal["x", "y"] | Angle
    stiffnesses: StiffnessOrZero | Annotated[list[StiffnessOrZero],
                                             Field(min_length=1, max_length=MAX_FLOORS)]
    name: str = ""

    def build(self) -> LateralElement:
        """The :class:`~pounding.structure.plan.LateralElement`."""
        from pounding.structure.plan import LateralElement

        return LateralElement(self.x, self.y, self.direction, self.stiffnesses, self.name)
