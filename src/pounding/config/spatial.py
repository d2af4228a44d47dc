"""``[spatial]``: each building of the row on its own ground (spatially varying ground
motion, :mod:`pounding.ground_motion.spatial` and :mod:`pounding.ground_motion.coherency`).

* ``positions`` [m] — each building's place along the row (where its ground's motion is
  taken), one a building, *required*;
* ``apparent_velocity`` [m/s] — the record reaches each building after
  ``(x_b − x_first)/V`` (wave passage; positive: waves travelling toward +x);
* ``coherency`` — ``"none"`` (default: the same record, delayed), ``"harichandran-vanmarcke"``
  or ``"luco-wong"``: the other buildings' motions simulated from the record, which stays
  under building ``recorded_at`` (default 0, the first), with that lagged coherency and the
  wave passage of ``apparent_velocity`` if given; ``seed`` (default 0) makes them
  reproducible, ``beta`` [s/m] is Luco & Wong's ``α/V_s`` (default 2.5e-4).

The ``[record]`` is the recorded motion (scaled as it says); every building's motion follows
from it.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from pounding.config.base import Section, field_error
from pounding.config.quantities import MAX_PLAN, Unit
from pounding.ground_motion import GroundMotion
from pounding.ground_motion.spatial import SpatialMotion

__all__ = ["SpatialConfig"]

Position = Annotated[float, Field(ge=-MAX_PLAN, le=MAX_PLAN), Unit("m")]
Velocity = Annotated[float, Field(ge=-1e5, le=1e5), Unit("m/s")]


class SpatialConfig(Section):
    """``[spatial]`` (module docstring)."""

    positions: Annotated[list[Position], Field(min_length=1)]
    apparent_velocity: Velocity | None = None
    coherency: Literal["none", "harichandran-vanmarcke", "luco-wong"] = "none"
    recorded_at: Annotated[int, Field(ge=0)] = 0
    seed: Annotated[int, Field(ge=0)] = 0
    beta: Annotated[float, Field(ge=0, le=1.0), Unit("s/m")] | None = None

    @model_validator(mode="after")
    def _consistent(self) -> SpatialConfig:
        if self.apparent_velocity is not None and self.apparent_velocity == 0.0:
            raise field_error("apparent_velocity", "must not be 0 m/s (waves that never "
                                                    "arrive)")
        if self.coherency == "none":
            if self.apparent_velocity is None:
                raise field_error("apparent_velocity", "required with coherency = \"none\": "
                                                        "give the waves' apparent velocity "
                                                        "[m/s] or a coherency model")
        if self.beta is not None and self.coherency != "luco-wong":
            raise field_error("beta", f"only for coherency = \"luco-wong\" (got coherency = "
                                      f"\"{self.coherency}\")")
        if self.recorded_at >= len(self.positions):
            raise field_error("recorded_at", f"must be a building index in [0, "
                                             f"{len(self.positions) - 1}] (got "
                                             f"{self.recorded_at})")
        return self

    def apply(self, record: GroundMotion) -> SpatialMotion:
        """Every building's motion from ``record`` (module docstring)."""
        from pounding.ground_motion.coherency import coherent_motions
        from pounding.ground_motion.spatial import wave_passage

        if self.coherency == "none":
            assert self.apparent_velocity is not None
            return wave_passage(record, self.positions, self.apparent_velocity)
        if self.beta is not None:
            return coherent_motions(record, self.positions, coherency=self.coherency,
                                    apparent_velocity=self.apparent_velocity,
                                    recorded_at=self.recorded_at, seed=self.seed,
                                    beta=self.beta)
        return coherent_motions(record, self.positions, coherency=self.coherency,
                                apparent_velocity=self.apparent_velocity,
                                recorded_at=self.recorded_at, seed=self.seed)
