"""``[pushover]``: a static pushover of a frame in a model file, and reading such a file.

A pushover file is a model file whose building of interest is a frame (``frame = {...}``,
:mod:`pounding.config.frame`); ``[record]``, ``[contact]`` and the other tables of a run may
be there too (the same file then also runs with ``pounding run``) and are not read::

    [pushover]
    building = "portal"        # which building (default: the first frame)
    target_drift = 0.05        # roof drift ratio to push to (or target = 0.2 [m])
    pattern = "uniform"        # "uniform", "triangular" or "first-mode"
    stop_below = 0.2           # optional: stop once the base shear falls below 20 % of its peak
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, ValidationError, model_validator

from pounding.config.base import Section, field_error, prefixed
from pounding.config.building import BuildingConfig
from pounding.config.quantities import Length

__all__ = ["PushoverConfig", "PushoverFile", "load_pushover"]


class PushoverConfig(Section):
    """``[pushover]``: see the module docstring."""

    building: str | None = None
    target: Length | None = None
    target_drift: Annotated[float, Field(gt=0, le=1)] | None = None
    pattern: Literal["uniform", "triangular", "first-mode"] = "uniform"
    stop_below: Annotated[float, Field(ge=0, lt=1)] | None = None

    @model_validator(mode="after")
    def _one_target(self) -> PushoverConfig:
        if self.target is not None and self.target_drift is not None:
            raise field_error("target_drift", f"give target [m] or target_drift [-], not both "
                                              f"(got target = {self.target!r})")
        return self


class _PushoverFileModel(Section):
    """What a pushover reads of a model file (other tables pass through unread)."""

    name: str = "model"
    description: str | None = None
    building: Annotated[list[BuildingConfig], Field(min_length=1)]
    pushover: PushoverConfig = PushoverConfig()


@dataclass(frozen=True)
class PushoverFile:
    """A pushover file as read: the frame, the options, the file's name and source."""

    frame: Any  #: :class:`pounding.structure.frame.Frame`
    options: PushoverConfig
    name: str
    source: Path
    building: BuildingConfig

    @property
    def target(self) -> float:
        """Roof displacement to push to [m]: ``target``, or ``target_drift`` × the frame's
        height (default 5 % of it)."""
        if self.options.target is not None:
            return float(self.options.target)
        drift = self.options.target_drift if self.options.target_drift is not None else 0.05
        return float(drift * (self.frame.levels[-1] - self.frame.base))


_RUN_TABLES = ("record", "contact", "device", "wall", "solver", "output")


def load_pushover(path: str | os.PathLike[str], *, building: str | None = None
                  ) -> PushoverFile:
    """Read a model file for a pushover: validate its buildings and ``[pushover]`` table and
    build the frame to push (``building``, else ``[pushover] building``, else the first
    frame).

    Raises
    ------
    ValueError
        One line per problem, naming the file and the key path.
    """
    from pounding.config.errors import format_validation_error
    from pounding.io.files import read_toml

    p = Path(path)
    data = read_toml(p, "model file")
    mine = {k: v for k, v in data.items() if k not in _RUN_TABLES}
    where = str(p)
    try:
        cfg = _PushoverFileModel.model_validate(mine, context={"base_dir": p.resolve().parent})
    except ValidationError as exc:
        raise ValueError(format_validation_error(exc, prefix=f"{where}: ",
                                                 root=_PushoverFileModel)) from None
    wanted = building if building is not None else cfg.pushover.building
    frames = [(i, b) for i, b in enumerate(cfg.building) if b.kind == "frame"]
    if not frames:
        raise ValueError(f"{where}: building: no frame to push (a pushover needs a building "
                         "given as frame = {...})")
    if wanted is None:
        i, chosen = frames[0]
    else:
        named = [(i, b) for i, b in frames if (b.name or f"B{i + 1}") == wanted]
        if not named:
            names = ", ".join(repr(b.name or f"B{i + 1}") for i, b in frames)
            key = "--building" if building is not None else "pushover.building"
            raise ValueError(f"{where}: {key}: no frame named {wanted!r} (frames: {names})")
        i, chosen = named[0]
    if chosen.foundation is not None:
        # (the pushover's base shear is its supports' reactions: a footing on soil would
        # rotate and sway under it, which the event-to-event push does not model)
        raise ValueError(f"{where}: building[{i}].foundation: a pushover is on a fixed base; "
                         "remove foundation to push the frame")
    try:
        with prefixed(f"building[{i}]", BuildingConfig.model_fields):
            frame = chosen.build_frame(f"B{i + 1}")
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    return PushoverFile(frame=frame, options=cfg.pushover, name=cfg.name, source=p.resolve(),
                        building=chosen)
