"""``isolator = {...}`` of a ``[[building]]`` and ``[[wall]]``: base isolation and moat walls.

A ``[[building]]`` with an ``isolator`` table is base-isolated: its other keys describe the
superstructure (fixed-base, linear storeys), and the isolator table adds the base slab and
the isolation storey under it (:meth:`pounding.structure.ShearBuilding.base_isolated`):

* ``isolator = { law = "friction-pendulum", radius = 2.0, mu = 0.06, base_mass = 4.0e5 }``
  (optional ``yield_displacement`` [m], ``weight`` [N]: default the building's weight,
  ``n``, ``beta``, ``gamma``: :class:`pounding.hysteresis.isolators.FrictionPendulum`);
* ``isolator = { law = "bilinear", pre_yield_stiffness = 1.2e8, post_yield_stiffness =
  1.2e7, characteristic_strength = 5.0e5, base_mass = 4.0e5 }`` (or ``yield_force``:
  :class:`pounding.hysteresis.isolators.BilinearIsolator`);
* both take ``base_height`` [m] (the isolation storey, default 1.0) and ``damping``
  [N·s/m] (a viscous coefficient across the isolator, default 0).

``[[wall]]`` is a rigid moat wall at one end of the row
(:class:`pounding.structure.wall.MoatWall`): ``height`` [m] of its top, ``gap`` [m] to the
building next to it, ``side = "right"`` (default; right of the last building) or
``"left"``, and ``name`` (default ``"W"``). Its contacts use the ``[contact]`` law unless
the wall gives its own, with the keys of ``[contact]``: ``law`` and the keys that law reads
(an abutment: ``law = "abutment", backbone = "caltrans", backwall_width = 12.0,
backwall_height = 2.0``, :class:`pounding.contact.abutment.AbutmentBackfill`). A
flexible wall is a one-storey ``[[building]]`` of the wall's height, mass and stiffness
standing in the row (:func:`pounding.structure.wall.flexible_wall`).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, field_validator, model_validator

from pounding.config.base import Section, check_bouc_wen_shape, field_error, fmt
from pounding.config.contact import LAW_FIELDS, LawConfig, known_law
from pounding.config.quantities import (
    DampingCoefficient,
    Force,
    Gap,
    Length,
    Mass,
    Stiffness,
    StiffnessOrZero,
)

_OWN = {"friction-pendulum": {"radius", "mu", "weight", "yield_displacement", "n", "beta",
                              "gamma"},
        "bilinear": {"pre_yield_stiffness", "post_yield_stiffness",
                     "characteristic_strength", "yield_force"}}


class IsolatorConfig(Section):
    """``isolator = {...}`` of a ``[[building]]`` (module docstring)."""

    law: Literal["friction-pendulum", "bilinear"]
    base_mass: Mass
    base_height: Length = 1.0
    damping: DampingCoefficient = 0.0
    radius: Length | None = None
    mu: Annotated[float, Field(gt=0, lt=1)] | None = None
    weight: Force | None = None
    yield_displacement: Length | None = None
    n: Annotated[float, Field(ge=1, le=100)] | None = None
    beta: Annotated[float, Field(ge=0, le=100)] | None = None
    gamma: Annotated[float, Field(ge=-100, le=100)] | None = None
    pre_yield_stiffness: Stiffness | None = None
    post_yield_stiffness: StiffnessOrZero | None = None
    characteristic_strength: Force | None = None
    yield_force: Force | None = None

    @model_validator(mode="after")
    def _keys(self) -> IsolatorConfig:
        own = _OWN[self.law]
        for key in set().union(*_OWN.values()) - own:
            if getattr(self, key) is not None:
                raise field_error(key, f"not a constant of the {self.law} isolator (got "
                                        f"{fmt(getattr(self, key))}); it reads "
                                        f"{', '.join(sorted(own))}")
        need = (("radius", "mu") if self.law == "friction-pendulum"
                else ("pre_yield_stiffness", "post_yield_stiffness"))
        for key in need:
            if getattr(self, key) is None:
                raise field_error(key, f"required for the {self.law} isolator")
        if self.law == "friction-pendulum":
            check_bouc_wen_shape(self.beta, self.gamma)
        return self

    def build(self) -> Any:
        """The :class:`pounding.hysteresis.isolators.Isolator`."""
        from pounding.hysteresis.isolators import BilinearIsolator, FrictionPendulum

        kw = self.model_dump(exclude={"law", "base_mass", "base_height", "damping"},
                             exclude_none=True)
        if self.law == "friction-pendulum":
            return FrictionPendulum(**kw)
        return BilinearIsolator(**kw)


WALL_KEYS = frozenset({"height", "gap", "side", "name"})
"""``[[wall]]`` keys of the wall itself; the others are its own contact law's."""


class WallConfig(LawConfig):
    """``[[wall]]``: a rigid moat wall at one end of the row, with an optional contact law of
    its own (``law`` and its keys, as ``[contact]``; module docstring)."""

    law: str | None = None  # type: ignore[assignment]
    height: Length
    gap: Gap
    side: Literal["right", "left"] = "right"
    name: Annotated[str, Field(min_length=1)] = "W"

    @field_validator("law")
    @classmethod
    def _known_law(cls, v: str | None) -> str | None:  # type: ignore[override]
        return None if v is None else known_law(v)

    @model_validator(mode="after")
    def _law_keys(self) -> WallConfig:
        # (a key at its default, as a written-out model file has them, says nothing)
        law_keys = sorted(k for k in self.model_fields_set - WALL_KEYS - {"law"}
                          if getattr(self, k) != type(self).model_fields[k].default)
        if self.law is None:
            if law_keys:
                raise field_error(law_keys[0], f"a key of the wall's own contact law (got "
                                               f"{fmt(getattr(self, law_keys[0]))}); give "
                                               "the law too (law = \"abutment\", ...)")
            return self
        used = LAW_FIELDS[self.law]
        for key in law_keys:
            if key not in used:
                raise field_error(key, f"not used by the {self.law} law (got "
                                       f"{fmt(getattr(self, key))}); it reads "
                                       f"{', '.join(sorted(used))}")
        return self

    def spec(self) -> Any:
        """The wall's own :class:`pounding.contact.spec.ContactSpec`, or None (its contacts
        follow ``[contact]``)."""
        from pounding.contact.spec import ContactSpec

        if self.law is None:
            return None
        return ContactSpec(**self.model_dump(exclude=set(WALL_KEYS), exclude_none=True))

    def build(self) -> Any:
        """The :class:`pounding.structure.wall.MoatWall`."""
        from pounding.structure.wall import MoatWall

        return MoatWall(self.height, self.gap, self.side, self.name, contact=self.spec())
