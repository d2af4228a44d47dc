"""``[contact]``: the contact law of a model file and the gaps."""

from __future__ import annotations

import difflib
from typing import TYPE_CHECKING, Annotated

from pydantic import Field, field_validator, model_validator

from pounding.config.base import Section, field_error, fmt
from pounding.config.quantities import (
    DampingCoefficient,
    Force,
    Gap,
    HertzStiffness,
    Length,
    Stiffness,
)
from pounding.contact.names import LAW_NAMES

if TYPE_CHECKING:
    from pounding.contact.spec import ContactSpec

LAW_FIELDS: dict[str, frozenset[str]] = {
    "linear-spring": frozenset({"k"}),
    "kelvin-voigt": frozenset({"k", "e", "formula", "c", "zeta", "tension"}),
    "modified-kelvin-voigt": frozenset({"k", "e", "formula", "c", "zeta"}),
    "hertz": frozenset({"k_h", "n"}),
    "hunt-crossley": frozenset({"k_h", "e", "formula", "chi", "n"}),
    "hertzdamp": frozenset({"k_h", "e", "formula", "chi", "n"}),
    "nonlinear-viscoelastic": frozenset({"k_h", "e", "formula", "zeta"}),
    "naderpour": frozenset({"k_h", "e", "formula", "zeta"}),
    "bilinear-impact": frozenset({"k_h", "e", "formula", "delta_m", "n", "a"}),
    "abutment": frozenset({"backbone", "k", "capacity", "delta_ult", "backwall_width",
                           "backwall_height"}),
    "shear-key": frozenset({"k", "capacity", "fracture_displacement"}),
}
"""The ``[contact]`` keys each law reads (:func:`pounding.contact.factory.make_law`); giving
another is an error rather than being silently ignored."""

CONTACT_COMMON = frozenset({"law", "gap", "gaps", "floor_to_column", "level_tolerance"})
"""``[contact]`` keys of every law."""


def known_law(v: str) -> str:
    """The law's key (lower case), or a ValueError naming the law asked for and the laws."""
    key = v.strip().lower()
    if key not in LAW_NAMES:
        close = difflib.get_close_matches(key, LAW_NAMES, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise ValueError(f"unknown law {v!r}{hint}; choose one of {', '.join(LAW_NAMES)}")
    return key


class LawConfig(Section):
    """A contact law in a model file: ``law`` and the keys it reads.

    ``law`` is a name of :data:`pounding.contact.factory.LAW_NAMES`; the other keys are
    those of :class:`pounding.model.ContactSpec` (``k`` [N/m], ``k_h`` [N/m^n], ``e`` [-],
    ``formula``, ``c`` [N·s/m], ``zeta`` [-], ``chi`` [-], ``n`` [-], ``tension``,
    ``delta_m`` [m], ``a`` [-]; the abutment backfill's ``backbone``, ``capacity`` [N],
    ``delta_ult`` [m], ``backwall_width`` [m], ``backwall_height`` [m]; the shear key's
    ``capacity`` [N] and ``fracture_displacement`` [m]); only the keys the
    law reads are accepted (:data:`LAW_FIELDS`). The ``rubber`` of a bumper
    (``[[device]]``) is one, and so is a ``[[wall]]``'s own law.
    """

    law: str
    k: Stiffness | None = None
    k_h: HertzStiffness | None = None
    e: Annotated[float, Field(gt=0, le=1)] | None = None
    formula: str | None = None
    c: DampingCoefficient | None = None
    zeta: Annotated[float, Field(ge=0, le=100)] | None = None
    chi: Annotated[float, Field(ge=0, le=100)] | None = None
    n: Annotated[float, Field(ge=1, le=3)] = 1.5
    tension: bool = False
    delta_m: Length | None = None
    a: Annotated[float, Field(gt=0, lt=1)] = 0.1
    backbone: str | None = None
    capacity: Force | None = None
    delta_ult: Length | None = None
    backwall_width: Length | None = None
    backwall_height: Length | None = None
    fracture_displacement: Length | None = None

    @field_validator("law")
    @classmethod
    def _known_law(cls, v: str) -> str:
        return known_law(v)

    @model_validator(mode="after")
    def _law_keys(self) -> LawConfig:
        used = LAW_FIELDS[self.law]
        for key in sorted(self.model_fields_set - used - CONTACT_COMMON):
            raise field_error(key, f"not used by the {self.law} law (got "
                                    f"{fmt(getattr(self, key))}); it reads "
                                    f"{', '.join(sorted(used))}")
        return self

    def spec(self) -> ContactSpec:
        """The :class:`ContactSpec` (domain errors propagate unprefixed)."""
        from pounding.contact.spec import ContactSpec

        kw = self.model_dump(exclude=set(CONTACT_COMMON - {"law"}), exclude_none=True)
        return ContactSpec(**kw)


class ContactConfig(LawConfig):
    """``[contact]``: the contact law used at every shared floor level, and the gaps.

    The law's keys as :class:`LawConfig`. ``gap`` [m] is the gap between every pair of
    neighbours, or ``gaps`` one per pair. ``floor_to_column`` (default true): a floor that
    does not line up with a floor of its neighbour strikes the neighbour's column
    (:class:`pounding.model.ContactPoint`); false keeps floor-to-floor contacts only.
    ``level_tolerance`` [m] (default 0.1): floors closer in elevation than this meet slab to
    slab.
    """

    gap: Gap | None = None
    gaps: list[Gap] | None = None
    floor_to_column: bool = True
    level_tolerance: Length = 0.1

    @model_validator(mode="after")
    def _gap_keys(self) -> ContactConfig:
        if self.gap is not None and self.gaps is not None:
            raise field_error("gaps", "give gap (all pairs) or gaps (one per pair), not both")
        return self

    def gap_list(self, n_pairs: int) -> list[float]:
        """The gap of each pair of neighbours [m]."""
        return list(self.gaps) if self.gaps is not None else [self.gap] * n_pairs  # type: ignore[list-item]
