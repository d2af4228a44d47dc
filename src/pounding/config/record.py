"""``[record]``: the ground motion of a model file."""

from __future__ import annotations

import functools
from pathlib import Path

from pydantic import PrivateAttr, ValidationInfo, field_validator, model_validator

from pounding.config.base import Pos, Section, field_error, fmt
from pounding.ground_motion import GroundMotion, bundled_records, el_centro, load_bundled, read_record

EL_CENTRO_ALIASES: tuple[str, ...] = ("el_centro", "elcentro", "el-centro")
"""Names that select :func:`pounding.ground_motion.el_centro` in ``record.bundled``."""


@functools.lru_cache(maxsize=32)
def _read_record_cached(path: Path, version: tuple[int, int] | None, dt: float | None,
                        units: str | None) -> GroundMotion:
    """:func:`read_record`, remembered per file version (modification time and size), so a
    sweep reading one record for thousands of cases parses it once per process."""
    return read_record(path, dt=dt, units=units)


class RecordConfig(Section):
    """``[record]``: the ground motion.

    Exactly one of ``bundled`` (a record shipped with pounding) and ``file`` (a path,
    relative to the model file). ``dt`` [s] and ``units`` are for files that do not state
    them. Then, in this order: ``duration`` [s] keeps the record up to that time,
    ``scale`` [-] multiplies it, or ``pga_g`` [g] scales it to that peak.
    """

    bundled: str | None = None
    file: str | None = None
    dt: Pos | None = None
    units: str | None = None
    duration: Pos | None = None
    scale: float | None = None
    pga_g: Pos | None = None

    _path: Path | None = PrivateAttr(default=None)

    @field_validator("bundled")
    @classmethod
    def _known_bundled(cls, v: str | None) -> str | None:
        if v is None:
            return v
        stems = [Path(n).stem for n in bundled_records()]
        if v.lower() not in EL_CENTRO_ALIASES and v not in stems and v not in bundled_records():
            raise ValueError(f"unknown bundled record {v!r}; choose one of "
                             f"{', '.join(('el_centro', *stems))}")
        return v

    @model_validator(mode="after")
    def _one_source(self, info: ValidationInfo) -> RecordConfig:
        if (self.bundled is None) == (self.file is None):
            raise ValueError("give exactly one of bundled (e.g. bundled = \"el_centro\") and "
                             f"file (got bundled={self.bundled!r}, file={self.file!r})")
        if self.scale is not None and self.pga_g is not None:
            raise field_error("pga_g", f"give scale or pga_g, not both (got scale="
                                        f"{self.scale:g}, pga_g={self.pga_g:g})")
        if self.bundled is not None:
            for key in ("dt", "units"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"only for record files; a bundled record states "
                                            f"its own (got {fmt(getattr(self, key))})")
        else:
            base = Path((info.context or {}).get("base_dir", "."))
            path = (base / Path(self.file).expanduser()).resolve()  # type: ignore[arg-type]
            if not path.is_file():
                what = (f"{str(path)!r} is a directory, not a record file" if path.is_dir()
                        else f"no such file {str(path)!r}")
                raise field_error("file", f"{what} (got {self.file!r}; relative paths start "
                                           "at the model file's folder)")
            self._path = path
        return self

    @property
    def path(self) -> Path | None:
        """The record file, resolved (None for a bundled record)."""
        if self.file is not None and self._path is None:
            self._path = Path(self.file).expanduser().resolve()
        return self._path

    def load(self) -> GroundMotion:
        """Read the record and apply ``duration``, ``scale`` / ``pga_g``."""
        if self.bundled is not None:
            gm = (el_centro() if self.bundled.lower() in EL_CENTRO_ALIASES
                  else load_bundled(self.bundled))
        else:
            path = self.path
            stat = path.stat() if path is not None and path.exists() else None
            gm = _read_record_cached(path, None if stat is None else (stat.st_mtime_ns, stat.st_size),
                                     self.dt, self.units)
        if self.duration is not None:
            gm = gm.trimmed(self.duration)
        if self.scale is not None:
            gm = gm.scaled(self.scale)
        if self.pga_g is not None:
            gm = gm.scaled_to_pga(self.pga_g)
        return gm
