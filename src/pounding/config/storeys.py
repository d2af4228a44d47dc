"""``damping = {...}`` and ``storey_law = {...}`` of a ``[[building]]``: its inherent
damping and how its storeys yield."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

from pydantic import Field, field_validator, model_validator

from pounding.config.base import Ratio, Section, check_bouc_wen_shape, field_error, fmt
from pounding.config.quantities import Force, Length, Period

if TYPE_CHECKING:
    from pounding.structure.damping import DampingModel

__all__ = ["DampingConfig", "StoreyLawConfig"]

DriftRatio = Annotated[float, Field(gt=0, le=1)]
"""A yield drift ratio [-]: yield drift / storey height (a drift of the whole storey height
is no yield point)."""
BoucWenExponent = Annotated[float, Field(ge=1, le=100)]
"""Bouc–Wen ``n`` [-]: 1 (smooth) to about 20 (nearly bilinear); 100 is the bilinear law in
all but name."""
BoucWenBeta = Annotated[float, Field(ge=0, le=100)]
"""Bouc–Wen ``beta`` [-] (>= 0; with ``beta + gamma = 1`` the usual choice)."""
BoucWenGamma = Annotated[float, Field(ge=-100, le=100)]
"""Bouc–Wen ``gamma`` [-]."""
class DampingConfig(Section):
    """``damping = {...}``: inherent damping of one building.

    * ``{ ratio = 0.05 }`` — the same ratio in every mode (:class:`ModalDamping`);
    * ``{ rayleigh = [0.05, 0.05], modes = [1, 2] }`` — Rayleigh damping with those ratios
      at those modes (default modes 1 and 2; one ratio means the same at both);
    * ``{ rayleigh = [0.05, 0.05], periods = [1.0, 0.2] }`` — anchored at two periods [s].
    """

    ratio: Ratio | None = None
    rayleigh: Annotated[list[Ratio], Field(min_length=1, max_length=2)] | None = None
    modes: Annotated[list[Annotated[int, Field(ge=1)]],
                     Field(min_length=2, max_length=2)] | None = None
    periods: Annotated[list[Period], Field(min_length=2, max_length=2)] | None = None

    @model_validator(mode="after")
    def _one_kind(self) -> DampingConfig:
        if (self.ratio is None) == (self.rayleigh is None):
            raise ValueError("give exactly one of ratio (same ratio in every mode) and "
                             f"rayleigh (got ratio={self.ratio!r}, rayleigh={self.rayleigh!r})")
        if self.ratio is not None:
            for key in ("modes", "periods"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"only with rayleigh (got {getattr(self, key)!r})")
        if self.modes is not None and self.periods is not None:
            raise field_error("periods", "give modes or periods, not both "
                                          f"(got modes={self.modes!r}, periods={self.periods!r})")
        for key in ("modes", "periods"):
            pair = getattr(self, key)
            if pair is not None and pair[0] == pair[1]:
                raise field_error((key, 1), f"must differ from {key}[0]: Rayleigh damping is "
                                            f"anchored at two {key} (got {fmt(pair[1])})")
        return self

    def build(self) -> DampingModel:
        """The damping model."""
        from pounding.structure.damping import ModalDamping, RayleighDamping

        if self.ratio is not None:
            return ModalDamping(self.ratio)
        assert self.rayleigh is not None
        zi = self.rayleigh[0]
        zj = self.rayleigh[-1]
        if self.periods is not None:
            return RayleighDamping.from_periods(self.periods[0], self.periods[1], zi, zj)
        mi, mj = self.modes or (1, 2)
        return RayleighDamping(zeta_i=zi, zeta_j=zj, mode_i=mi, mode_j=mj)


class StoreyLawConfig(Section):
    """``storey_law = {...}``: how the storeys of one building yield (default: linear).

    * ``{ type = "bilinear", yield_force = 2.0e6, hardening = 0.05 }`` — bilinear with
      kinematic hardening (:class:`pounding.hysteresis.Bilinear`);
    * ``{ type = "bouc-wen", yield_drift_ratio = 0.005, alpha = 0.05, n = 2, beta = 0.5,
      gamma = 0.5 }`` — Bouc–Wen (:class:`pounding.hysteresis.BoucWen`).

    The yield point is one of ``yield_force`` [N], ``yield_drift`` [m] or
    ``yield_drift_ratio`` [-] (yield drift / storey height), each a number for every storey
    or a list with one value per storey. The elastic stiffness is the building's.
    """

    type: str
    yield_force: Force | Annotated[list[Force], Field(min_length=1)] | None = None
    yield_drift: Length | Annotated[list[Length], Field(min_length=1)] | None = None
    yield_drift_ratio: (DriftRatio | Annotated[list[DriftRatio], Field(min_length=1)]
                        | None) = None
    hardening: Annotated[float, Field(ge=0, lt=1)] | None = None
    alpha: Annotated[float, Field(ge=0, lt=1)] | None = None
    n: BoucWenExponent | None = None
    beta: BoucWenBeta | None = None
    gamma: BoucWenGamma | None = None

    @field_validator("type")
    @classmethod
    def _known_type(cls, v: str) -> str:
        from pounding.hysteresis import STOREY_LAWS

        key = v.strip().lower()
        if key not in STOREY_LAWS:
            raise ValueError(f"unknown storey law {v!r}; choose one of "
                             f"{', '.join(STOREY_LAWS)}")
        return key

    @model_validator(mode="after")
    def _keys(self) -> StoreyLawConfig:
        own = {"bilinear": {"hardening"}, "bouc-wen": {"alpha", "n", "beta", "gamma"}}[self.type]
        for key in ("hardening", "alpha", "n", "beta", "gamma"):
            if key not in own and getattr(self, key) is not None:
                raise field_error(key, f"not a constant of the {self.type} law (got "
                                        f"{fmt(getattr(self, key))}); it reads "
                                        f"{', '.join(sorted(own))}")
        given = [k for k in ("yield_force", "yield_drift", "yield_drift_ratio")
                 if getattr(self, k) is not None]
        if len(given) != 1:
            raise field_error("yield_force", "give exactly one of yield_force [N], "
                                              "yield_drift [m] or yield_drift_ratio [-] "
                                              f"(got {', '.join(given) or 'none'})")
        if self.type == "bouc-wen":
            check_bouc_wen_shape(self.beta, self.gamma)
        return self

    def check_storeys(self, n: int) -> None:
        """Refuse a list of yield points that is not one value or ``n`` (one per storey)."""
        for key in ("yield_force", "yield_drift", "yield_drift_ratio"):
            value = getattr(self, key)
            if isinstance(value, list) and len(value) not in (1, n):
                raise field_error(("storey_law", key),
                                  f"need one value or {n}, one per storey (got {len(value)}: "
                                  f"{fmt(value)})")

    def build(self, heights: Any) -> Any:
        """The :class:`pounding.hysteresis.StoreyLaw` for storeys of these heights [m]."""
        import numpy as np

        from pounding.hysteresis import STOREY_LAWS

        kw = self.model_dump(exclude={"type", "yield_drift_ratio"}, exclude_none=True)
        if self.yield_drift_ratio is not None:
            ratio = np.asarray(self.yield_drift_ratio, dtype=float)
            if ratio.size not in (1, len(heights)):
                raise field_error("yield_drift_ratio", f"need one value or {len(heights)} "
                                   f"(one per storey), got {ratio.size}")
            kw["yield_drift"] = [float(v) for v in ratio * np.asarray(heights, dtype=float)]
        return STOREY_LAWS[self.type](**kw)
