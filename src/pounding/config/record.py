"""``[record]``: the ground motion of a model file."""

from __future__ import annotations

import functools
from pathlib import Path

from typing import Annotated, Literal, overload

from pydantic import Field, PrivateAttr, ValidationInfo, field_validator, model_validator

from pounding.config.base import Section, field_error, fmt
from pounding.config.quantities import Angle, Duration, Intensity, Period, Scale, Step
from pounding.config.synthetic_record import MatchSpec, StochasticRecord
from pounding.ground_motion import (
    GroundMotion,
    GroundMotionComponents,
    bundled_files,
    el_centro,
    load_bundled,
    read_record,
)
from pounding.ground_motion.incidence import at_incidence
from pounding.ground_motion.readers import UNIT_NAMES, needs_units
from pounding.memo import Memo

EL_CENTRO_ALIASES: tuple[str, ...] = ("el_centro", "elcentro", "el-centro")
SA_DAMPING = 0.05
"""Damping ratio of ``sa_g`` unless ``sa_damping`` says otherwise (5 %, the codes')."""
"""Names that select :func:`pounding.ground_motion.el_centro` in ``record.bundled``."""


@functools.lru_cache(maxsize=32)
def _read_record_cached(path: Path, version: tuple[int, int] | None, dt: float | None,
                        units: str | None, column: int | None = None,
                        time_column: int | None = None,
                        channel: int | None = None) -> GroundMotion:
    """:func:`read_record`, remembered per file version (modification time and size), so a
    sweep reading one record for thousands of cases parses it once per process."""
    return read_record(path, dt=dt, units=units, column=column, time_column=time_column,
                       channel=channel)


@functools.lru_cache(maxsize=32)
def _needs_units(path: Path, version: tuple[int, int] | None) -> bool:
    """:func:`needs_units`, remembered per file version (a sweep validates every case)."""
    return needs_units(path)


@functools.lru_cache(maxsize=1)
def _bundled_names() -> frozenset[str]:
    """Every name of a bundled record: file names and their stems (read once: the records
    ship with the package)."""
    return frozenset([*bundled_files(), *(Path(n).stem for n in bundled_files())])


RECORDS = Memo(max_items=64, max_bytes=128 << 20)
"""Motions made by :meth:`RecordConfig.load`."""


class RecordConfig(Section):
    """``[record]``: the ground motion.

    Exactly one of ``bundled`` (a record shipped with pounding), ``file`` (a path,
    relative to the model file) and ``stochastic = {…}`` (a record of the stochastic model
    of Rezaeian & Der Kiureghian 2010 for a magnitude, distance, Vs30, mechanism and seed:
    :class:`~pounding.config.synthetic_record.StochasticRecord`). ``match = {…}`` makes the
    record spectrum-compatible with a target spectrum, after ``duration`` and before the
    scaling (:class:`~pounding.config.synthetic_record.MatchSpec`). ``dt`` [s] and ``units`` are for files that do not state
    them; a plain-text record states no unit, so it needs ``units`` (none is assumed).
    ``column`` and ``time_column`` (from 1; ``time_column = 0``: none) choose the columns of
    a plain-text ``file`` of several (``t, NS, EW, V``), and ``channel`` (from 1) the
    acceleration channel of a COSMOS ``file`` of several
    (:func:`pounding.ground_motion.read_record`). Then,
    in this order: ``duration`` [s] keeps the record up to that time, and at most one of
    ``scale`` [-] (multiplies it: in [-1000, 1000] and not 0, a negative factor reversing
    the record's polarity), ``pga_g`` [g] (scales it to that peak) and
    ``sa_g`` [g] with ``sa_period`` [s] (scales it so that its pseudo-acceleration at that
    period and ``sa_damping``, default 0.05, is ``sa_g``: the intensity measure Sa(T1) of an
    incremental dynamic analysis; :func:`pounding.spectra.scale_to_sa`), or ``saavg_g`` [g]
    with ``saavg_periods = [T_low, T_high]`` [s] (and ``saavg_n`` periods, default 10):
    scales it so that the geometric mean of its pseudo-acceleration at ``saavg_n`` periods
    equally spaced over that range (``sa_damping``) is ``saavg_g``
    (:func:`pounding.spectra.scale_to_saavg`).

    Two horizontal components (for a model with buildings in plan): ``second`` (a bundled
    record) or ``second_file`` (a path, relative to the model file), the component
    orthogonal to the first, and ``incidence`` [degrees], the angle of the first component
    from the site x axis, counter-clockwise, in [-360, 360] (default 0):
    :func:`pounding.ground_motion.incidence.at_incidence`. ``dt`` and ``units`` are for
    every record file given; ``duration`` and the scaling apply to both components alike:
    the factor is the first component's (``pga_g``, ``sa_g``, ``saavg_g`` measured on the
    first), and the second is multiplied by the same factor. A model with buildings in plan
    given one component shakes along ``incidence`` with it alone (``a_x = a cos α``,
    ``a_y = a sin α``); a model without them takes no ``second``, ``second_file`` or
    ``incidence``.
    """

    bundled: str | None = None
    file: str | None = None
    dt: Step | None = None
    units: str | None = None
    column: Annotated[int, Field(ge=1, le=10_000, strict=True)] | None = None
    time_column: Annotated[int, Field(ge=0, le=10_000, strict=True)] | None = None
    channel: Annotated[int, Field(ge=1, le=10_000, strict=True)] | None = None
    duration: Duration | None = None
    scale: Scale | None = None
    pga_g: Intensity | None = None
    sa_g: Intensity | None = None
    sa_period: Period | None = None
    sa_damping: Annotated[float, Field(ge=0.0, lt=1.0)] | None = None
    saavg_g: Intensity | None = None
    saavg_periods: Annotated[list[Period], Field(min_length=2, max_length=2)] | None = None
    saavg_n: Annotated[int, Field(ge=2, le=1000)] | None = None
    second: str | None = None
    second_file: str | None = None
    incidence: Angle | None = None
    stochastic: StochasticRecord | None = None
    match: MatchSpec | None = None

    _path: Path | None = PrivateAttr(default=None)
    _second_path: Path | None = PrivateAttr(default=None)

    @field_validator("bundled", "second")
    @classmethod
    def _known_bundled(cls, v: str | None) -> str | None:
        if v is None:
            return v
        if v.lower() not in EL_CENTRO_ALIASES and v not in _bundled_names():
            stems = [Path(n).stem for n in bundled_files()]
            raise ValueError(f"unknown bundled record {v!r}; choose one of "
                             f"{', '.join(('el_centro', *stems))}")
        return v

    @model_validator(mode="after")
    def _one_source(self, info: ValidationInfo) -> RecordConfig:
        sources = [k for k in ("bundled", "file", "stochastic") if getattr(self, k) is not None]
        if len(sources) != 1:
            raise ValueError("give exactly one of bundled (e.g. bundled = \"el_centro\"), "
                             "file and stochastic = {…} (got "
                             f"{', '.join(sources) or 'none'})")
        if self.stochastic is not None:
            for key in ("dt", "units", "column", "time_column", "channel", "second",
                        "second_file"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"not with stochastic = {{…}} (its dt is "
                                           f"stochastic.dt; got {fmt(getattr(self, key))})")
        if self.scale == 0.0:
            raise field_error("scale", "must not be 0: the record would not shake anything "
                                       "(a factor in [-1000, 1000]; negative flips the "
                                       "record's polarity) (got 0)")
        given = [k for k in ("scale", "pga_g", "sa_g", "saavg_g") if getattr(self, k) is not None]
        if len(given) > 1:
            raise field_error(given[-1], "give one of scale, pga_g, sa_g and saavg_g (got "
                              + ", ".join(f"{k}={getattr(self, k):g}" for k in given) + ")")
        if self.sa_g is not None and self.sa_period is None:
            raise field_error("sa_period", f"sa_g = {self.sa_g:g} g needs the period [s] of "
                                           "that pseudo-acceleration (e.g. sa_period = 1.0)")
        if self.sa_g is None and self.sa_period is not None:
            raise field_error("sa_period", f"only with sa_g (got {fmt(self.sa_period)})")
        if self.sa_g is None and self.saavg_g is None and self.sa_damping is not None:
            raise field_error("sa_damping", f"only with sa_g or saavg_g (got "
                                            f"{fmt(self.sa_damping)})")
        if self.saavg_g is not None and self.saavg_periods is None:
            raise field_error("saavg_periods", f"saavg_g = {self.saavg_g:g} g needs the period "
                                               "range [s] of the average (e.g. saavg_periods "
                                               "= [0.2, 3.0])")
        if self.saavg_periods is not None and not self.saavg_periods[0] < self.saavg_periods[1]:
            raise field_error("saavg_periods", "the lower period must be below the upper (got "
                                               f"{self.saavg_periods})")
        if self.saavg_g is None:
            for key in ("saavg_periods", "saavg_n"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"only with saavg_g (got {fmt(getattr(self, key))})")
        if self.second is not None and self.second_file is not None:
            raise field_error("second_file", f"give second (bundled) or second_file, not both "
                                             f"(got second={self.second!r}, "
                                             f"second_file={self.second_file!r})")
        if self.bundled is not None and self.second_file is None:
            for key in ("dt", "units"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"only for record files; a bundled record states "
                                            f"its own (got {fmt(getattr(self, key))})")
        if self.bundled is not None:
            for key in ("column", "time_column", "channel"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"only with file = ...: it chooses what a record "
                                            f"file of several series is read for (got "
                                            f"{fmt(getattr(self, key))})")
        base = Path((info.context or {}).get("base_dir", "."))
        for key in ("file", "second_file"):
            if getattr(self, key) is not None:
                path = _record_file(base, key, getattr(self, key))
                setattr(self, f"_{'' if key == 'file' else 'second_'}path", path)
                if self.units is None and _needs_units(path, _version(path)):
                    # a text record states no unit, and none is assumed: El Centro in g
                    # read as m/s2 would shake the model ten times too weakly
                    raise field_error("units", f"{key} = {getattr(self, key)!r} is a plain-"
                                               "text record, which does not state its "
                                               "acceleration unit; give units = \"g\" (or "
                                               f"{UNIT_NAMES.removeprefix('g, ')})")
        return self

    def factor_of(self, motion: GroundMotion) -> float:
        """The factor ``scale`` / ``pga_g`` / ``sa_g`` / ``saavg_g`` multiplied the record by
        to make ``motion`` (its :meth:`load`): 1 without them."""
        if all(getattr(self, k) is None for k in ("scale", "pga_g", "sa_g", "saavg_g")):
            return 1.0
        raw = self.model_copy(update={"scale": None, "pga_g": None, "sa_g": None,
                                      "sa_period": None, "sa_damping": None,
                                      "saavg_g": None, "saavg_periods": None,
                                      "saavg_n": None})
        raw._path, raw._second_path = self._path, self._second_path
        a = raw.load().accel
        k = int(abs(a).argmax())
        return float(motion.accel[k] / a[k])

    @property
    def two_components(self) -> bool:
        """True if a second horizontal component is given."""
        return self.second is not None or self.second_file is not None

    @property
    def second_path(self) -> Path | None:
        """The second component's file, resolved (None if none or bundled)."""
        if self.second_file is not None and self._second_path is None:
            self._second_path = Path(self.second_file).expanduser().resolve()
        return self._second_path

    @property
    def path(self) -> Path | None:
        """The record file, resolved (None for a bundled record)."""
        if self.file is not None and self._path is None:
            self._path = Path(self.file).expanduser().resolve()
        return self._path

    @overload
    def load(self, components: Literal[False] = False) -> GroundMotion: ...

    @overload
    def load(self, components: bool) -> GroundMotion | GroundMotionComponents: ...

    def load(self, components: bool = False) -> GroundMotion | GroundMotionComponents:
        """Read the record and apply ``duration``, then ``scale`` / ``pga_g`` / ``sa_g`` /
        ``saavg_g``.

        Parameters
        ----------
        components : bool
            Return the site's x and y components
            (:class:`~pounding.ground_motion.GroundMotionComponents`, for a model with
            buildings in plan): ``at_incidence(first, second, incidence)``, the second
            component scaled by the first's factor. Else the first component alone (a
            :class:`GroundMotion`).

        Remembered (:data:`RECORDS`, keyed by every field, the files resolved and their
        versions): the cases of a sweep that share a record share one (immutable) motion,
        and with it its samples on the output grid
        (:func:`pounding.integrate.grid.ground_on_grid_memo`).
        """
        path, second = self.path, self.second_path
        version, version2 = _version(path), _version(second)
        # every field, as text (equal text: equal values of the same types)
        return RECORDS.get((repr(self.__dict__), str(path), version, str(second), version2,
                            components),
                           lambda: self._components(path, version, second, version2)
                           if components else self._load(path, version)[0],
                           size=lambda gm: gm.accel.nbytes)

    def _components(self, path: Path | None, version: tuple[int, int] | None,
                    second_path: Path | None, version2: tuple[int, int] | None
                    ) -> GroundMotionComponents:
        first, factor = self._load(path, version)
        angle = 0.0 if self.incidence is None else self.incidence
        if not self.two_components:
            ax, ay = at_incidence(first, None, angle)
            return GroundMotionComponents((ax, ay), name=f"{first.name} alone (one "
                                                         f"component) at {angle:g}°")
        if self.second is not None:
            gm2 = _bundled(self.second)
        else:
            gm2 = _read_record_cached(second_path, version2, self.dt, self.units)
        if self.duration is not None:
            gm2 = gm2.trimmed(self.duration)
        if factor != 1.0:
            gm2 = gm2.scaled(factor)
        try:
            ax, ay = at_incidence(first, gm2, angle)
        except ValueError as exc:
            key = "second" if self.second is not None else "second_file"
            raise ValueError(f"{key}: {gm2.name!r}: {exc}") from None
        return GroundMotionComponents((ax, ay), name=f"{first.name} + {gm2.name} at "
                                                     f"{angle:g}°")

    def _load(self, path: Path | None, version: tuple[int, int] | None
              ) -> tuple[GroundMotion, float]:
        """The first component, and the factor its scaling multiplied it by."""
        if self.bundled is not None:
            gm = _bundled(self.bundled)
        elif self.stochastic is not None:
            gm = self.stochastic.motion()
        else:
            gm = _read_record_cached(path, version, self.dt, self.units, self.column,
                                     self.time_column, self.channel)
        if self.duration is not None:
            gm = gm.trimmed(self.duration)
        if self.match is not None:
            gm = self.match.apply(gm)
        unscaled = gm
        if self.scale is not None:
            gm = gm.scaled(self.scale)
        if self.pga_g is not None:
            gm = gm.scaled_to_pga(self.pga_g)
        if self.sa_g is not None:
            from pounding.spectra.scaling import scale_to_sa

            gm = scale_to_sa(gm, self.sa_g, self.sa_period,  # type: ignore[arg-type]
                             SA_DAMPING if self.sa_damping is None else self.sa_damping)
        if self.saavg_g is not None:
            from pounding.spectra.scaling import SAAVG_N, scale_to_saavg

            gm = scale_to_saavg(gm, self.saavg_g, self.saavg_periods,  # type: ignore[arg-type]
                                SA_DAMPING if self.sa_damping is None else self.sa_damping,
                                SAAVG_N if self.saavg_n is None else self.saavg_n)
        if gm is unscaled:
            return gm, 1.0
        if self.scale is not None:
            return gm, self.scale
        return gm, gm.pga / unscaled.pga


def _bundled(name: str) -> GroundMotion:
    return el_centro() if name.lower() in EL_CENTRO_ALIASES else load_bundled(name)


def _version(path: Path | None) -> tuple[int, int] | None:
    """A file's modification time and size (None: no file)."""
    if path is None or not path.exists():
        return None
    stat = path.stat()
    return (stat.st_mtime_ns, stat.st_size)


def _record_file(base: Path, key: str, value: str) -> Path:
    """The record file ``value`` of ``key``, relative to ``base``, resolved; must exist."""
    path = (base / Path(value).expanduser()).resolve()
    if not path.is_file():
        what = (f"{str(path)!r} is a directory, not a record file" if path.is_dir()
                else f"no such file {str(path)!r}")
        raise field_error(key, f"{what} (got {value!r}; relative paths start at the model "
                               "file's folder)")
    return path
