"""``[[device]]``: links between buildings and bumpers in the gaps, in a model file."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, model_validator

from pounding.config.base import Section, field_error
from pounding.config.contact import LawConfig
from pounding.config.quantities import Force, Gap, Length, PositiveDamping, Stiffness

if TYPE_CHECKING:
    from pounding.devices import Bumper, Link

_LINK_KEYS = {"viscous": {"c", "alpha"}, "kelvin": {"c", "k"}, "maxwell": {"c", "k", "alpha"},
              "restrainer": {"k", "slack", "yield_force", "hardening"}}
_OPTIONAL = {"alpha", "yield_force", "hardening"}
_BUMPER_KEYS = {"thickness", "compression_limit", "rubber"}


class DeviceConfig(Section):
    """``[[device]]``: one device.

    ``type`` is ``viscous`` (``c`` [N·(s/m)^α], ``alpha`` [-], default 1), ``kelvin`` (``k``
    [N/m], ``c`` [N·s/m]), ``maxwell`` (``k``, ``c``, ``alpha``), ``restrainer`` (a bridge's
    cable restrainer across a joint, tension only: ``k`` [N/m], ``slack`` [m],
    ``yield_force`` [N] — none: elastic — and ``hardening`` [-], default 0) — links between
    two floors of different buildings (:class:`pounding.devices.Link`) — or ``bumper``: a
    pad of
    ``thickness`` [m] in the gap of a contact that bottoms out at ``compression_limit`` (a
    fraction of the thickness), with its own contact law ``rubber`` (a table like
    ``[contact]`` without gaps; :class:`pounding.devices.Bumper`). ``floors`` names the two
    floors, e.g. ``["B1F3", "B2F3"]`` (building and floor numbers from 1, as in every
    output), or is ``"all"``: one device at every floor-to-floor contact of the model (every
    shared floor level of every pair of neighbours).
    """

    type: Literal["viscous", "kelvin", "maxwell", "restrainer", "bumper"]
    floors: Annotated[list[str], Field(min_length=2, max_length=2)] | Literal["all"]
    c: PositiveDamping | None = None
    alpha: Annotated[float, Field(gt=0, le=2)] | None = None
    k: Stiffness | None = None
    slack: Gap | None = None
    yield_force: Force | None = None
    hardening: Annotated[float, Field(ge=0, lt=1)] | None = None
    thickness: Length | None = None
    compression_limit: Annotated[float, Field(gt=0, lt=1)] | None = None
    rubber: LawConfig | None = None

    @model_validator(mode="after")
    def _keys(self) -> DeviceConfig:
        used = _BUMPER_KEYS if self.type == "bumper" else _LINK_KEYS[self.type]
        for key in sorted(self.model_fields_set - used - {"type", "floors"}):
            raise field_error(key, f"not used by a {self.type} device; it reads "
                                    f"{', '.join(sorted(used))}")
        required = (_BUMPER_KEYS if self.type == "bumper"
                    else _LINK_KEYS[self.type] - _OPTIONAL)
        for key in sorted(required - self.model_fields_set):
            raise field_error(key, f"required by a {self.type} device")
        return self

    def build(self, contact_floors: list[tuple[str, str]]) -> list[Link | Bumper]:
        """The device, or one at each pair of ``contact_floors`` for ``floors = "all"``
        (domain errors propagate unprefixed)."""
        from pounding.devices import Bumper, Link

        pairs = contact_floors if self.floors == "all" else [tuple(self.floors)]
        out: list[Link | Bumper] = []
        for pair in pairs:
            if self.type == "bumper":
                assert self.rubber is not None
                out.append(Bumper(pair, float(self.thickness),  # type: ignore[arg-type]
                                  float(self.compression_limit),  # type: ignore[arg-type]
                                  self.rubber.spec()))
            elif self.type == "restrainer":
                out.append(Link(pair, "restrainer",  # type: ignore[arg-type]
                                k=self.k, slack=self.slack,
                                yield_force=self.yield_force,
                                hardening=0.0 if self.hardening is None else self.hardening))
            else:
                out.append(Link(pair, self.type, c=float(self.c),  # type: ignore[arg-type]
                                alpha=1.0 if self.alpha is None else self.alpha, k=self.k))
        return out
