"""``plan = {...}`` and ``elements = [...]`` of a ``[[building]]`` in plan: the floor plan and
the lateral load-resisting elements of a :class:`~pounding.structure.plan.PlanBuilding`."""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field, field_validator

from pounding.config.base import Pos, Section, fmt
from pounding.structure.plan import LateralElement
from pounding.structure.shear_building import MAX_FLOORS

__all__ = ["ElementConfig", "PlanConfig"]


def _each(value: float | list[float] | None, ok: Any, words: str) -> None:
    """Raise ``ValueError("<words> (got …)")`` naming the first value (and its index in a
    list) that is not ``ok`` (one message for a number or a list of them)."""
    values = [] if value is None else value if isinstance(value, list) else [value]
    for i, x in enumerate(values):
        if not ok(x):
            at = f"[{i}] " if isinstance(value, list) else ""
            raise ValueError(f"{at}{words} (got {fmt(x)})")


class PlanConfig(Section):
    """``plan = { width = 20.0, depth = 12.0, site_y = 6.0 }``: the floor plan of a building in
    plan (:class:`~pounding.structure.plan.PlanBuilding`), the rectangle ``[0, width] ×
    [0, depth]`` [m] in the building's own plan coordinates, standing with its ``y = 0``
    edge at site ``y = site_y`` [m] (default 0). Optional ``mass_centres`` [m] (one
    ``[x, y]`` for every floor, or one a floor; default the centre of the plan) and
    ``inertias`` [kg·m²] (polar moment of inertia of each floor about its centre of mass,
    one value or one a floor; default ``m (width² + depth²) / 12``)."""

    width: Pos
    depth: Pos
    site_y: float = 0.0
    mass_centres: (Annotated[list[float], Field(min_length=2, max_length=2)]
                   | Annotated[list[Annotated[list[float], Field(min_length=2, max_length=2)]],
                               Field(min_length=1)] | None) = None
    inertias: float | Annotated[list[float], Field(min_length=1)] | None = None

    @field_validator("inertias")
    @classmethod
    def _positive(cls, v: float | list[float] | None) -> float | list[float] | None:
        _each(v, lambda x: x > 0, "must be > 0 [kg·m²]")
        return v


class ElementConfig(Section):
    """One of ``elements = [ { x = 0.0, y = 6.0, direction = "y", stiffnesses = [...] }, … ]``:
    a lateral load-resisting element (frame, wall line) of a building in plan
    (:class:`~pounding.structure.plan.LateralElement`): its plan position ``x``, ``y`` [m],
    the ``direction`` it resists (``"x"``, ``"y"`` or an angle [degrees] from x,
    counter-clockwise), ``stiffnesses`` [N/m] one a storey (or one value for every storey;
    0 where the element stops) and an optional ``name``."""

    x: float
    y: float
    direction: str | float
    stiffnesses: float | Annotated[list[float], Field(min_length=1, max_length=MAX_FLOORS)]
    name: str = ""

    @field_validator("stiffnesses")
    @classmethod
    def _non_negative(cls, v: float | list[float]) -> float | list[float]:
        _each(v, lambda x: x >= 0, "must be >= 0 [N/m] (0 where the element stops)")
        return v

    @field_validator("direction")
    @classmethod
    def _known_direction(cls, v: str | float) -> str | float:
        from pounding.units import direction_cosines

        try:
            direction_cosines(v)
        except (TypeError, ValueError):
            raise ValueError(f"must be \"x\", \"y\" or an angle [degrees] from the x axis "
                             f"(got {fmt(v)})") from None
        return v

    def build(self) -> LateralElement:
        """The :class:`~pounding.structure.plan.LateralElement`."""
        return LateralElement(self.x, self.y, self.direction, self.stiffnesses, self.name)
