"""The study file of ``pounding fragility``: a base model, a record suite and its scaling,
the intensity measure and its levels, the limit states, the gap analysis, the bootstrap and
how to run — validated like a model file (every bad key named with its value, one line
each). See ``docs/fragility.md``.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, ValidationError, model_validator

from pounding.config.base import Section, field_error, fmt
from pounding.config.quantities import Duration, Gap, Intensity, Period, Step
from pounding.result.demands import DEMANDS

__all__ = ["COLLAPSE_DRIFT", "IntensitySpec", "JOINT_DEMANDS", "LimitStateSpec",
           "StudyConfig", "load_study", "parse_study"]


MAX_WORKERS = 1024
"""Most workers of a local cluster (more processes than any one machine runs well)."""
MAX_BATCH = 1_000_000
"""Most cases in one batch (a sweep may have no more cases than that)."""

MEASURES = ("pga", "sa", "saavg")
"""Intensity measures: peak ground acceleration, Sa(T1, ζ), average spectral acceleration."""


class LevelRange(Section):
    """``levels = { start, stop, n }``: ``n`` levels from ``start`` to ``stop`` [g],
    equally spaced (``spacing = "linear"``, the default) or in geometric progression
    (``"log"``)."""

    start: Intensity
    stop: Intensity
    n: Annotated[int, Field(ge=2, le=1000)]
    spacing: Literal["linear", "log"] = "linear"

    @model_validator(mode="after")
    def _order(self) -> LevelRange:
        if not self.start < self.stop:
            raise field_error("stop", f"must be above start = {self.start:g} (got "
                                      f"{self.stop:g})")
        return self

    def values(self) -> list[float]:
        import numpy as np

        f = np.geomspace if self.spacing == "log" else np.linspace
        return [float(v) for v in f(self.start, self.stop, self.n)]


class IntensitySpec(Section):
    """``[intensity]``: ``measure`` = ``"pga"``, ``"sa"`` (with ``period`` [s]) or ``"saavg"``
    (with ``periods = [low, high]`` [s], ``n_periods``), ``damping`` of the spectra, and the
    ``levels`` [g] each record is scaled to: a list, or ``{ start, stop, n }``."""

    measure: Literal["pga", "sa", "saavg"]
    period: Period | None = None
    periods: Annotated[list[Period], Field(min_length=2, max_length=2)] | None = None
    n_periods: Annotated[int, Field(ge=2, le=1000)] = 10
    damping: Annotated[float, Field(ge=0.0, lt=1.0)] = 0.05
    levels: Annotated[list[Intensity], Field(min_length=2, max_length=1000)] | LevelRange

    @model_validator(mode="after")
    def _keys(self) -> IntensitySpec:
        if self.measure == "sa" and self.period is None:
            raise field_error("period", "measure \"sa\" needs the period [s] of Sa "
                                        "(e.g. period = 1.15, the first mode of a building)")
        if self.measure != "sa" and self.period is not None:
            raise field_error("period", f"only with measure \"sa\" (got {self.period:g})")
        if self.measure != "saavg" and self.periods is not None:
            raise field_error("periods", f"only with measure \"saavg\" (got {self.periods})")
        if self.periods is not None and not self.periods[0] < self.periods[1]:
            raise field_error("periods", f"the lower period must be below the upper (got "
                                         f"{self.periods})")
        vals = self.level_values()
        if any(b <= a for a, b in zip(vals, vals[1:])):
            raise field_error("levels", f"must increase strictly (got {vals})")
        return self

    def level_values(self) -> list[float]:
        """The levels [g], increasing."""
        return list(self.levels) if isinstance(self.levels, list) else self.levels.values()


COLLAPSE_DRIFT = 10.0
"""Default drift limit of the ``collapse`` demand [%]: the global collapse-prevention limit of
FEMA-350 (SAC 2000) for steel moment frames, 10 % interstorey drift, which Vamvatsikos &
Cornell (2002) take as the collapse capacity of an IDA curve that has not flattened before
it."""


JOINT_DEMANDS = ("pounding", "impacts", "impact_force", "seat_opening")
"""The demands a bridge's limit state may put at one joint (``joint``)."""

JOINT_NAME = re.compile(r"J[1-9]\d*|A[12]|joints|abutments")
"""``joint`` of a limit state: an expansion joint, an abutment, or every one of either."""


class LimitStateSpec(Section):
    """``[[limit_state]]``: ``demand`` (a key of :data:`DEMANDS`), ``limit`` in the demand's
    unit (not for the yes/no demands ``"pounding"`` and ``"collapse"``), ``drift_limit`` [%]
    of ``"collapse"`` (default :data:`COLLAPSE_DRIFT`), ``joint`` (a bridge: the seat or
    joint the demand is read at, :data:`JOINT_NAME`; default every contact for impacts,
    every seat for ``"seat_opening"``), and an optional ``name``.

    ``"seat_opening"`` is a bridge's peak seat opening [m] (the deck end moving off its
    seat, :func:`pounding.result.bridge_seats.seat_openings`) and its ``limit`` the seat
    width [m]: the limit state is unseating."""

    demand: Literal["pounding", "impacts", "impact_force", "drift", "acceleration",
                    "ductility", "plastic_rotation", "collapse", "seat_opening"]
    limit: Annotated[float, Field(ge=0)] | None = None
    drift_limit: Annotated[float, Field(gt=0, le=100)] | None = None
    joint: str | None = None
    name: str | None = None

    @model_validator(mode="after")
    def _limit(self) -> LimitStateSpec:
        d = DEMANDS[self.demand]
        if self.demand == "pounding" and self.limit is not None:
            raise field_error("limit", f"demand \"pounding\" is any impact; it takes no limit "
                                       f"(got {self.limit:g}); for a number of impacts use "
                                       "demand = \"impacts\"")
        if self.demand == "collapse" and self.limit is not None:
            raise field_error("limit", f"demand \"collapse\" is yes or no; it takes no limit "
                                       f"(got {self.limit:g}); its storey drift ratio is "
                                       f"drift_limit [%] (default {COLLAPSE_DRIFT:g})")
        if self.joint is not None:
            if self.demand not in JOINT_DEMANDS:
                raise field_error("joint", f"only for a bridge's demands "
                                           f"{', '.join(JOINT_DEMANDS)} (got {fmt(self.joint)} "
                                           f"with demand \"{self.demand}\")")
            if JOINT_NAME.fullmatch(self.joint) is None:
                raise field_error("joint", "an expansion joint (\"J1\", \"J2\", …), an "
                                           "abutment (\"A1\" left, \"A2\" right), \"joints\" "
                                           "(every expansion joint) or \"abutments\" (got "
                                           f"{fmt(self.joint)})")
        if self.drift_limit is not None and self.demand != "collapse":
            raise field_error("drift_limit", f"only for demand \"collapse\" (got "
                                             f"{self.drift_limit:g}); a limit on the drift "
                                             "itself is demand = \"drift\" with limit [%]")
        if d.binary:
            return self
        if self.limit is None:
            raise field_error("limit", f"required for demand \"{self.demand}\": the "
                                       f"{d.label} beyond which the limit state is exceeded "
                                       f"[{d.unit}]")
        if self.limit is not None and self.limit > d.largest:
            raise field_error("limit", f"must be in [0, {fmt(d.largest)}] {d.unit} for demand "
                                       f"\"{self.demand}\" ({d.label}) (got "
                                       f"{fmt(self.limit)})")
        return self

    @property
    def label(self) -> str:
        """The name, or one made from the demand and limit."""
        if self.name:
            return self.name
        d = DEMANDS[self.demand]
        if self.demand == "collapse":
            return f"collapse (drift > {self.collapse_drift_percent:g} % or a hinge past its cap)"
        at = f" at {self.joint}" if self.joint else ""
        if self.limit is None:
            return f"pounding{at}"
        return f"{d.label}{at} > {self.limit:g} {d.unit}".replace(" -", "")

    @property
    def limit_si(self) -> float:
        """The limit in SI units (the sweep table's), 0.5 for the binary demands."""
        if self.limit is None:
            return 0.5
        return self.limit / DEMANDS[self.demand].factor

    @property
    def collapse_drift_percent(self) -> float:
        """The drift limit of ``"collapse"`` [%]: ``drift_limit``, else :data:`COLLAPSE_DRIFT`."""
        return COLLAPSE_DRIFT if self.drift_limit is None else self.drift_limit


class SpectrumScaling(Section):
    """``[suite.scaling]``: the suite scaled to a target spectrum first
    (:func:`pounding.spectra.scale_suite`): ``target`` (a spectrum file, relative to the
    study file), ``period`` T1 [s], ``method`` (code, sa, pga, lsq), ``code`` (asce7-22,
    en1998-1: the keys of ``pounding code-check``; asce7 and ec8, their keys before issue
    29, are refused naming the new one)."""

    target: str
    period: Period
    method: Literal["code", "sa", "pga", "lsq"] = "code"
    code: Literal["asce7-22", "en1998-1"] = "asce7-22"

    @model_validator(mode="before")
    @classmethod
    def _renamed_code(cls, data: Any) -> Any:
        from pounding.spectra.scaling import RENAMED_CODES

        old = data.get("code") if isinstance(data, dict) else None
        if isinstance(old, str) and old in RENAMED_CODES:
            raise field_error("code", f"{old!r} is now spelled {RENAMED_CODES[old]!r}")
        return data


class SuiteStochastic(Section):
    """``[suite] stochastic = { magnitude, distance, vs30, mechanism, count, seed, dt }``:
    ``count`` records of the stochastic model of Rezaeian & Der Kiureghian (2010) for
    moment magnitude ``magnitude``, rupture distance ``distance`` [km], ``vs30`` [m/s] and
    ``mechanism`` (``"strike-slip"``, ``"reverse"``), record ``i`` drawn from its own
    stream of ``seed`` (the same records whatever ``count``), sampled every ``dt`` [s]
    (default 0.01, at most 0.02)."""

    magnitude: Annotated[float, Field(ge=4.0, le=9.0)]
    distance: Annotated[float, Field(gt=0.0, le=500.0)]
    vs30: Annotated[float, Field(ge=100.0, le=3000.0)]
    mechanism: Literal["strike-slip", "reverse"] = "strike-slip"
    count: Annotated[int, Field(ge=2, le=10_000, strict=True)]
    seed: Annotated[int, Field(ge=0, le=2**63 - 1, strict=True)] = 0
    dt: Annotated[float, Field(gt=0.0, le=0.02)] = 0.01

    def record(self, index: int) -> dict[str, Any]:
        """The ``[record] stochastic`` table of record ``index``."""
        out = self.model_dump(exclude={"count"})
        out["index"] = index
        return out


class SuiteMatch(Section):
    """``[suite] match = { target, range, tolerance }``: every record of the suite (the
    seeds) is first made spectrum-compatible with the spectrum file ``target`` (relative
    to the study file) over ``range = [lo, hi]`` [s] (default 0.05–4) within ``tolerance``
    (default 0.10) by :func:`pounding.spectra.matching.match_record`; ``iterations``
    (default 30)."""

    target: str
    range: Annotated[list[Period], Field(min_length=2, max_length=2)] = [0.05, 4.0]
    tolerance: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.10
    iterations: Annotated[int, Field(ge=1, le=1000, strict=True)] = 30

    @model_validator(mode="after")
    def _order(self) -> SuiteMatch:
        if not self.range[0] < self.range[1]:
            raise field_error("range", f"the lower period must be below the upper (got "
                                       f"{self.range})")
        return self


class SuiteSpec(Section):
    """``[suite]``: exactly one of ``bundled = true`` (the bundled suite: the nine records
    of :func:`~pounding.ground_motion.bundled_records`), ``folder`` and ``files`` (relative
    to the study file; ``dt``, ``units`` for files that do not state them) — recorded
    motions, made spectrum-compatible first with ``match = {…}`` — or ``stochastic = {…}``
    (simulated motions); ``duration`` [s] keeps each record up to that time; ``scaling``
    scales the suite to a target spectrum before the levels are applied."""

    bundled: bool | None = None
    folder: str | None = None
    files: Annotated[list[str], Field(min_length=1)] | None = None
    stochastic: SuiteStochastic | None = None
    match: SuiteMatch | None = None
    dt: Step | None = None
    units: str | None = None
    duration: Duration | None = None
    scaling: SpectrumScaling | None = None

    @model_validator(mode="after")
    def _one_source(self) -> SuiteSpec:
        given = [k for k in ("bundled", "folder", "files", "stochastic")
                 if getattr(self, k) not in (None, False)]
        if len(given) != 1:
            raise field_error("bundled", "give exactly one of bundled = true, folder = "
                                         "\"records/\", files = [...] and stochastic = {…} "
                                         f"(got {', '.join(given) or 'none'})")
        if self.stochastic is not None:
            for key in ("dt", "units", "match"):
                if getattr(self, key) is not None:
                    raise field_error(key, "not with stochastic = {…} (its step is "
                                           "stochastic.dt; a simulated suite is not matched)")
        if self.bundled and (self.dt is not None or self.units is not None):
            raise field_error("dt" if self.dt is not None else "units",
                              "only for record files; the bundled records state their own")
        return self

    @property
    def kind(self) -> str:
        """``"stochastic"``, ``"matched"`` or ``"recorded"``."""
        if self.stochastic is not None:
            return "stochastic"
        return "matched" if self.match is not None else "recorded"


class GapSpec(Section):
    """``[gap]``: the probability of pounding against the gap at the intensity ``at`` [g]
    (default: the middle level), the gap for the ``target`` probability (default 0.10),
    and gaps ``values`` [m] at which every run is also simulated with contact."""

    at: Intensity | None = None
    target: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.10
    values: list[Gap] = []


class BootstrapSpec(Section):
    """``[bootstrap]``: ``n`` resamples of the records (0: no intervals), ``seed``, and the
    two-sided ``confidence`` of the intervals and bands."""

    n: Annotated[int, Field(ge=0, le=100_000)] = 1000
    seed: Annotated[int, Field(ge=0)] = 2015
    confidence: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.90


class RunSpec(Section):
    """``[run]``: ``workers`` of the local Dask cluster, or ``scheduler`` (an address, or
    ``"synchronous"``), ``batch_size``, and ``histories`` (false, ``"netcdf"``, ``"zarr"``)."""

    workers: Annotated[int, Field(ge=1, le=MAX_WORKERS)] | None = None
    scheduler: str | None = None
    batch_size: Annotated[int, Field(ge=1, le=MAX_BATCH)] | None = None
    histories: Literal[False, "netcdf", "zarr"] = False


class StudyConfig(Section):
    """A whole study file (``docs/fragility.md``)."""

    name: str = "fragility"
    description: str | None = None
    base: str
    out: str | None = None
    suite: SuiteSpec
    intensity: IntensitySpec
    limit_state: Annotated[list[LimitStateSpec], Field(min_length=1)] = [
        LimitStateSpec(demand="pounding")]
    gap: GapSpec = GapSpec()
    bootstrap: BootstrapSpec = BootstrapSpec()
    run: RunSpec = RunSpec()

    @model_validator(mode="after")
    def _unique_names(self) -> StudyConfig:
        names = [ls.label for ls in self.limit_state]
        for i, n in enumerate(names):
            if n in names[:i]:
                raise field_error(("limit_state", i, "name"), f"two limit states are called "
                                                              f"{n!r}; name them apart")
        return self

    def gap_at(self) -> float:
        """The intensity of the gap analysis [g]: ``[gap] at``, else the middle level."""
        if self.gap.at is not None:
            return self.gap.at
        vals = self.intensity.level_values()
        return vals[(len(vals) - 1) // 2]


def parse_study(data: dict[str, Any], where: str = "study") -> StudyConfig:
    """Validate a parsed study file.

    Raises
    ------
    ValueError
        One line per problem, ``<where>: <key path>: <problem> (got <value>)``.
    """
    from pounding.config.errors import format_validation_error

    try:
        return StudyConfig.model_validate(data)
    except ValidationError as exc:
        raise ValueError(format_validation_error(exc, prefix=f"{where}: ",
                                                 root=StudyConfig)) from None


def load_study(path: str | os.PathLike[str]) -> tuple[StudyConfig, Path]:
    """Read and validate a study file: ``(config, the file's folder)``.

    Raises
    ------
    ValueError
        A missing or malformed file, or a bad key (one line each, naming it).
    """
    from pounding.io.files import read_toml

    p = Path(path)
    data = read_toml(p, "study file")
    return parse_study(data, where=str(p)), p.resolve().parent

