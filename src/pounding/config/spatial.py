"""``[spatial]``: each building of the row on its own ground (spatially varying ground
motion, :mod:`pounding.ground_motion.spatial` and :mod:`pounding.ground_motion.coherency`).

* ``records`` — the records under buildings 2, 3, … (building 1 stands on ``[record]``),
  each a table like ``[record]``'s source keys (``bundled`` or ``file``, with ``dt``,
  ``units``, ``column``, ``time_column``, ``channel``, ``duration``), every one multiplied by
  the factor that ``[record]``'s ``scale`` / ``pga_g`` / ``sa_g`` / ``saavg_g`` gives building
  1's record (an IDA scales the row's motions together); same step as ``[record]``. Or:
* ``positions`` [m] — each building's place along the row (where its ground's motion is
  taken), one a building;
* ``apparent_velocity`` [m/s] — the record reaches each building after
  ``(x_b − x_first)/V`` (wave passage; positive: waves travelling toward +x);
* ``coherency`` — ``"none"`` (default: the same record, delayed), ``"harichandran-vanmarcke"``
  or ``"luco-wong"``: the other buildings' motions simulated from the record, which stays
  under building ``recorded_at`` (default 0, the first), with that lagged coherency and the
  wave passage of ``apparent_velocity`` if given; ``seed`` (default 0) makes them
  reproducible, ``beta`` [s/m] is Luco & Wong's ``α/V_s`` (default 2.5e-4).

Without ``records`` the ``[record]`` is the recorded motion (scaled as it says) and every
building's motion follows from it.

The walls at the ends of the row (``[[wall]]``, a bridge's abutments) stand on their
building's ground unless given their own: ``wall_positions = { left = …, right = … }`` [m]
with ``positions`` (their motions made with the buildings', one coherent set), or
``wall_records = { left = { … }, right = { … } }`` with ``records``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, model_validator

from pounding.config.base import Section, field_error, prefixed
from pounding.config.quantities import MAX_PLAN, Unit
from pounding.config.record import RecordConfig

if TYPE_CHECKING:
    from pounding.ground_motion import GroundMotion
    from pounding.ground_motion.spatial import SpatialMotion

__all__ = ["SpatialConfig"]

Position = Annotated[float, Field(ge=-MAX_PLAN, le=MAX_PLAN), Unit("m")]
Velocity = Annotated[float, Field(ge=-1e5, le=1e5), Unit("m/s")]


class SpatialConfig(Section):
    """``[spatial]`` (module docstring)."""

    positions: Annotated[list[Position], Field(min_length=1)] | None = None
    records: Annotated[list[RecordConfig], Field(min_length=1)] | None = None
    apparent_velocity: Velocity | None = None
    coherency: Literal["none", "harichandran-vanmarcke", "luco-wong"] = "none"
    recorded_at: Annotated[int, Field(ge=0)] = 0
    seed: Annotated[int, Field(ge=0)] = 0
    beta: Annotated[float, Field(ge=0, le=1.0), Unit("s/m")] | None = None
    wall_positions: dict[str, Position] | None = None
    wall_records: dict[str, RecordConfig] | None = None

    @model_validator(mode="after")
    def _consistent(self) -> SpatialConfig:
        for key in ("wall_positions", "wall_records"):
            for side in getattr(self, key) or {}:
                if side not in ("left", "right"):
                    raise field_error((key, side), f"a wall's side is left or right (got "
                                                   f"{side!r})")
        if self.wall_positions is not None and self.positions is None:
            raise field_error("wall_positions", "with positions only (with records, give the "
                                                "walls' own: wall_records = { left = { … } })")
        if self.wall_records is not None and self.records is None:
            raise field_error("wall_records", "with records only (with positions, give the "
                                              "walls' places: wall_positions = { left = … })")
        if self.records is not None:
            for key in ("positions", "apparent_velocity", "beta"):
                if getattr(self, key) is not None:
                    raise field_error(key, "not with records (each building's own record is "
                                           "given; positions and waves make them from one)")
            if self.coherency != "none":
                raise field_error("coherency", "not with records (each building's own record "
                                               "is given)")
            tables: list[tuple[tuple[str | int, ...], RecordConfig]] = [
                *((("records", i), r) for i, r in enumerate(self.records)),
                *((("wall_records", s), r) for s, r in (self.wall_records or {}).items())]
            for where, r in tables:
                for key in ("scale", "pga_g", "sa_g", "saavg_g", "second", "second_file",
                            "incidence"):
                    if getattr(r, key) is not None:
                        raise field_error((*where, key),
                                          "not here: every building's record is scaled by "
                                          "[record]'s factor (give it there)")
            return self
        if self.positions is None:
            raise field_error("positions", "required: each building's place along the row "
                                           "[m] (or records = [...], the other buildings' own "
                                           "records)")
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

    def n_buildings(self) -> int:
        """How many buildings the table gives a motion for."""
        if self.records is not None:
            return len(self.records) + 1
        assert self.positions is not None
        return len(self.positions)

    def wall_sides(self) -> list[str]:
        """The sides of the walls given a ground of their own (left first)."""
        given = self.wall_positions or self.wall_records or {}
        return [s for s in ("left", "right") if s in given]

    def apply(self, record: GroundMotion, factor: float = 1.0) -> SpatialMotion:
        """Every building's (and wall's) motion from ``record`` (module docstring);
        ``factor``: what ``[record]``'s scaling multiplied its record by (for ``records``)."""
        from pounding.ground_motion.coherency import coherent_motions
        from pounding.ground_motion.spatial import SpatialMotion, wave_passage

        sides = self.wall_sides()
        if self.records is not None:
            others = []
            for i, r in enumerate(self.records):
                with prefixed(f"records[{i}]", RecordConfig.model_fields):
                    others.append(r.load().scaled(factor))
            walls = {}
            for side in sides:
                assert self.wall_records is not None
                with prefixed(f"wall_records.{side}", RecordConfig.model_fields):
                    walls[side] = self.wall_records[side].load().scaled(factor)
            return SpatialMotion([record, *others], description="each building's own record",
                                 walls=walls)
        assert self.positions is not None
        positions = [*self.positions,
                     *(self.wall_positions[s] for s in sides
                       if self.wall_positions is not None)]
        if self.coherency == "none":
            assert self.apparent_velocity is not None
            motion = wave_passage(record, positions, self.apparent_velocity)
        elif self.beta is not None:
            motion = coherent_motions(record, positions, coherency=self.coherency,
                                      apparent_velocity=self.apparent_velocity,
                                      recorded_at=self.recorded_at, seed=self.seed,
                                      beta=self.beta)
        else:
            motion = coherent_motions(record, positions, coherency=self.coherency,
                                      apparent_velocity=self.apparent_velocity,
                                      recorded_at=self.recorded_at, seed=self.seed)
        return motion.with_walls(sides) if sides else motion
