"""Model files: a pounding run described in TOML, validated before anything is computed.

A model file names the ground motion, the buildings from left to right, the contact law
and gaps, the solver options and what to write. :func:`load_config` reads and validates it
into a :class:`RunConfig`; :meth:`RunConfig.build` turns that into the objects of the
library — a :class:`~pounding.model.PoundingModel`, a
:class:`~pounding.ground_motion.GroundMotion` and the keyword arguments of
:func:`~pounding.integrate.simulate`.

Every problem is reported as one :class:`ValueError` holding one line per problem, each
naming the key by its path in the file and the value found, e.g.::

    model.toml: building[1].period: must be > 0 (got -0.5)
    model.toml: contact.gaps: need 1 value for 2 buildings (got 2: [0.02, 0.03])

(``building[1]`` is the second ``[[building]]`` table: indices are 0-based, as in the
error messages of the library itself). The format, key by key, is in ``docs/running.md``.
"""

from __future__ import annotations

import functools

import difflib
import json
import math
import os
import types
import typing
from pathlib import Path
from typing import Annotated, Any, NamedTuple

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    PrivateAttr,
    ValidationError,
    ValidationInfo,
    field_validator,
    model_validator,
)
from pydantic_core import PydanticCustomError

from pounding.contact.factory import LAW_NAMES
from pounding.io import read_toml
from pounding.ground_motion import GroundMotion, bundled_records, el_centro, load_bundled, read_record
from pounding.model import ContactSpec, PoundingModel
from pounding.structure import ModalDamping, RayleighDamping, ShearBuilding
from pounding.structure.damping import DampingModel

__all__ = [
    "BuildingConfig",
    "Built",
    "ContactConfig",
    "DampingConfig",
    "OutputConfig",
    "RecordConfig",
    "RunConfig",
    "SolverConfig",
    "format_validation_error",
    "load_config",
    "parse_config",
]

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]
Ratio = Annotated[float, Field(ge=0, le=1)]

EL_CENTRO_ALIASES: tuple[str, ...] = ("el_centro", "elcentro", "el-centro")
"""Names that select :func:`pounding.ground_motion.el_centro` in ``record.bundled``."""

LAW_FIELDS: dict[str, frozenset[str]] = {
    "linear-spring": frozenset({"k"}),
    "kelvin-voigt": frozenset({"k", "e", "formula", "c", "zeta", "tension"}),
    "modified-kelvin-voigt": frozenset({"k", "e", "formula", "c", "zeta"}),
    "hertz": frozenset({"k_h", "n"}),
    "hunt-crossley": frozenset({"k_h", "e", "formula", "chi", "n"}),
    "hertzdamp": frozenset({"k_h", "e", "formula", "chi", "n"}),
    "nonlinear-viscoelastic": frozenset({"k_h", "e", "formula", "zeta"}),
    "naderpour": frozenset({"k_h", "e", "formula", "zeta"}),
    "bilinear-impact": frozenset({"k_h", "e", "delta_m", "n", "a"}),
}
"""The ``[contact]`` keys each law reads (:func:`pounding.contact.factory.make_law`); giving
another is an error rather than being silently ignored."""

_CONTACT_COMMON = frozenset({"law", "gap", "gaps", "floor_to_column", "level_tolerance"})
"""``[contact]`` keys of every law."""


def _field_error(field: str | tuple[str | int, ...], message: str) -> PydanticCustomError:
    """An error about ``field`` of the model being validated (located by the formatter)."""
    return PydanticCustomError("config_field", "{message}",
                               {"field": field, "message": message})


def _fmt(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:g}"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


class _Section(BaseModel):
    """Strict: no unknown keys, no strings for numbers, no inf/nan."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


# ============================================================================ record
@functools.lru_cache(maxsize=32)
def _read_record_cached(path: Path, version: tuple[int, int] | None, dt: float | None,
                        units: str | None) -> GroundMotion:
    """:func:`read_record`, remembered per file version (modification time and size), so a
    sweep reading one record for thousands of cases parses it once per process."""
    return read_record(path, dt=dt, units=units)


class RecordConfig(_Section):
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
            raise _field_error("pga_g", f"give scale or pga_g, not both (got scale="
                                        f"{self.scale:g}, pga_g={self.pga_g:g})")
        if self.bundled is not None:
            for key in ("dt", "units"):
                if getattr(self, key) is not None:
                    raise _field_error(key, f"only for record files; a bundled record states "
                                            f"its own (got {_fmt(getattr(self, key))})")
        else:
            base = Path((info.context or {}).get("base_dir", "."))
            path = (base / Path(self.file).expanduser()).resolve()  # type: ignore[arg-type]
            if not path.is_file():
                raise _field_error("file", f"no such file {str(path)!r} (got {self.file!r}; "
                                           "relative paths start at the model file's folder)")
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


# ============================================================================ buildings
class DampingConfig(_Section):
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
    periods: Annotated[list[Pos], Field(min_length=2, max_length=2)] | None = None

    @model_validator(mode="after")
    def _one_kind(self) -> DampingConfig:
        if (self.ratio is None) == (self.rayleigh is None):
            raise ValueError("give exactly one of ratio (same ratio in every mode) and "
                             f"rayleigh (got ratio={self.ratio!r}, rayleigh={self.rayleigh!r})")
        if self.ratio is not None:
            for key in ("modes", "periods"):
                if getattr(self, key) is not None:
                    raise _field_error(key, f"only with rayleigh (got {getattr(self, key)!r})")
        if self.modes is not None and self.periods is not None:
            raise _field_error("periods", "give modes or periods, not both "
                                          f"(got modes={self.modes!r}, periods={self.periods!r})")
        return self

    def build(self) -> DampingModel:
        """The damping model."""
        if self.ratio is not None:
            return ModalDamping(self.ratio)
        assert self.rayleigh is not None
        zi = self.rayleigh[0]
        zj = self.rayleigh[-1]
        if self.periods is not None:
            return RayleighDamping.from_periods(self.periods[0], self.periods[1], zi, zj)
        mi, mj = self.modes or (1, 2)
        return RayleighDamping(zeta_i=zi, zeta_j=zj, mode_i=mi, mode_j=mj)


class StoreyLawConfig(_Section):
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
    yield_force: Pos | list[Pos] | None = None
    yield_drift: Pos | list[Pos] | None = None
    yield_drift_ratio: Pos | list[Pos] | None = None
    hardening: Annotated[float, Field(ge=0, lt=1)] | None = None
    alpha: Annotated[float, Field(ge=0, lt=1)] | None = None
    n: Annotated[float, Field(ge=1)] | None = None
    beta: float | None = None
    gamma: float | None = None

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
                raise _field_error(key, f"not a constant of the {self.type} law (got "
                                        f"{_fmt(getattr(self, key))}); it reads "
                                        f"{', '.join(sorted(own))}")
        given = [k for k in ("yield_force", "yield_drift", "yield_drift_ratio")
                 if getattr(self, k) is not None]
        if len(given) != 1:
            raise _field_error("yield_force", "give exactly one of yield_force [N], "
                                              "yield_drift [m] or yield_drift_ratio [-] "
                                              f"(got {', '.join(given) or 'none'})")
        return self

    def build(self, heights: Any) -> Any:
        """The :class:`pounding.hysteresis.StoreyLaw` for storeys of these heights [m]."""
        import numpy as np

        from pounding.hysteresis import STOREY_LAWS

        kw = self.model_dump(exclude={"type", "yield_drift_ratio"}, exclude_none=True)
        if self.yield_drift_ratio is not None:
            ratio = np.asarray(self.yield_drift_ratio, dtype=float)
            if ratio.size not in (1, len(heights)):
                raise _field_error("yield_drift_ratio", f"need one value or {len(heights)} "
                                   f"(one per storey), got {ratio.size}")
            kw["yield_drift"] = [float(v) for v in ratio * np.asarray(heights, dtype=float)]
        return STOREY_LAWS[self.type](**kw)


_SDOF_KEYS = ("mass", "stiffness", "period", "height")
_UNIFORM_KEYS = ("n_storeys", "mass", "stiffness", "period", "height")
_STOREY_KEYS = ("masses", "stiffnesses", "heights", "height", "period")


class BuildingConfig(_Section):
    """``[[building]]``: one building; the tables go left to right.

    Three ways to give it, told apart by the keys present:

    * SDOF: ``mass`` [kg] and ``period`` [s] or ``stiffness`` [N/m]; ``height`` [m] (3).
    * uniform: ``n_storeys``, ``mass`` [kg] per floor, ``stiffness`` [N/m] per storey or
      ``period`` [s] (fundamental; the stiffness follows), ``height`` [m] per storey (3).
    * storeys: ``masses`` [kg], ``stiffnesses`` [N/m], ``heights`` [m] (or one ``height``
      for all; default 3), ground storey first; optional ``period`` [s] rescales all
      stiffnesses to that fundamental period.

    ``damping`` (:class:`DampingConfig`) defaults to 5 % in every mode for an SDOF and 5 %
    Rayleigh at modes 1 and 2 otherwise. ``storey_law`` (:class:`StoreyLawConfig`) makes the
    storeys yield; without it they stay linear.
    """

    name: str | None = None
    mass: Pos | None = None
    stiffness: Pos | None = None
    period: Pos | None = None
    height: Pos | None = None
    n_storeys: Annotated[int, Field(ge=1)] | None = None
    masses: Annotated[list[Pos], Field(min_length=1)] | None = None
    stiffnesses: Annotated[list[Pos], Field(min_length=1)] | None = None
    heights: Annotated[list[Pos], Field(min_length=1)] | None = None
    damping: DampingConfig | None = None
    storey_law: StoreyLawConfig | None = None

    @property
    def kind(self) -> str:
        """``'storeys'``, ``'uniform'`` or ``'sdof'``."""
        if self.masses is not None:
            return "storeys"
        if self.n_storeys is not None:
            return "uniform"
        return "sdof"

    @model_validator(mode="after")
    def _consistent(self) -> BuildingConfig:
        kind = self.kind
        allowed = {"sdof": _SDOF_KEYS, "uniform": _UNIFORM_KEYS, "storeys": _STOREY_KEYS}[kind]
        shape = {"sdof": "an SDOF building (mass, period|stiffness)",
                 "uniform": "a uniform building (n_storeys, mass, stiffness|period)",
                 "storeys": "a building given storey by storey (masses, stiffnesses, heights)"
                 }[kind]
        if kind == "sdof" and (self.stiffnesses is not None or self.heights is not None):
            raise _field_error("masses", "required with stiffnesses/heights: one value [kg] "
                                         "per floor")
        for key in (*_UNIFORM_KEYS, *_STOREY_KEYS):
            if key not in allowed and getattr(self, key) is not None:
                raise _field_error(key, f"not a key of {shape} (got {_fmt(getattr(self, key))})")
        if kind in ("sdof", "uniform"):
            if self.mass is None:
                raise _field_error("mass", f"required for {shape}")
            if (self.stiffness is None) == (self.period is None):
                raise _field_error("period", f"give exactly one of period and stiffness "
                                             f"(got period={self.period!r}, "
                                             f"stiffness={self.stiffness!r})")
        else:
            n = len(self.masses)  # type: ignore[arg-type]
            if self.stiffnesses is None:
                raise _field_error("stiffnesses", "required with masses, one value [N/m] "
                                                  "per storey")
            if len(self.stiffnesses) != n:
                raise _field_error("stiffnesses", f"need {n} values, one per floor like "
                                                  f"masses (got {len(self.stiffnesses)})")
            if self.heights is not None and self.height is not None:
                raise _field_error("height", "give heights or height, not both")
            if self.heights is not None and len(self.heights) != n:
                raise _field_error("heights", f"need {n} values, one per floor like masses "
                                              f"(got {len(self.heights)})")
        return self

    @property
    def n(self) -> int:
        """Number of storeys."""
        return {"sdof": 1, "uniform": self.n_storeys or 1,
                "storeys": len(self.masses or ())}[self.kind]

    def build(self, default_name: str) -> ShearBuilding:
        """The :class:`ShearBuilding` (domain errors propagate unprefixed)."""
        name = self.name or default_name
        damping = self.damping.build() if self.damping is not None else None
        h = self.height if self.height is not None else 3.0
        if self.kind == "sdof":
            assert self.mass is not None
            k = (self.stiffness if self.stiffness is not None
                 else self.mass * (2.0 * math.pi / self.period) ** 2)  # type: ignore[operator]
            return self._with_law(ShearBuilding(masses=[self.mass], stiffnesses=[k],
                                                heights=[h], damping=damping or ModalDamping(0.05),
                                                name=name))
        if self.kind == "uniform":
            assert self.mass is not None and self.n_storeys is not None
            b = ShearBuilding.uniform(self.n_storeys, self.mass, self.stiffness or 1.0, h,
                                      damping=damping, name=name)
        else:
            n = len(self.masses)  # type: ignore[arg-type]
            heights = self.heights if self.heights is not None else [h] * n
            b = ShearBuilding(masses=self.masses, stiffnesses=self.stiffnesses,
                              heights=heights, damping=damping or RayleighDamping(), name=name)
        b = b.with_period(self.period) if self.period is not None else b
        return self._with_law(b)

    def _with_law(self, b: ShearBuilding) -> ShearBuilding:
        if self.storey_law is None:
            return b
        with _prefixed("storey_law"):
            return b.with_storey_law(self.storey_law.build(b.heights))


# ============================================================================ contact
class ContactConfig(_Section):
    """``[contact]``: the contact law used at every shared floor level, and the gaps.

    ``law`` is a name of :data:`pounding.contact.factory.LAW_NAMES`; the other keys are
    those of :class:`pounding.model.ContactSpec` (``k`` [N/m], ``k_h`` [N/m^n], ``e`` [-],
    ``formula``, ``c`` [N·s/m], ``zeta`` [-], ``chi`` [-], ``n`` [-], ``tension``,
    ``delta_m`` [m], ``a`` [-]); only the keys the law reads are accepted (:data:`LAW_FIELDS`).
    ``gap`` [m] is the gap between every pair of neighbours, or ``gaps`` one per pair.
    ``floor_to_column`` (default true): a floor that does not line up with a floor of its
    neighbour strikes the neighbour's column (:class:`pounding.model.ContactPoint`); false
    keeps floor-to-floor contacts only. ``level_tolerance`` [m] (default 0.1): floors closer
    in elevation than this meet slab to slab.
    """

    law: str
    k: Pos | None = None
    k_h: Pos | None = None
    e: Annotated[float, Field(gt=0, le=1)] | None = None
    formula: str | None = None
    c: NonNeg | None = None
    zeta: NonNeg | None = None
    chi: NonNeg | None = None
    n: Pos = 1.5
    tension: bool = True
    delta_m: Pos | None = None
    a: Annotated[float, Field(gt=0, lt=1)] = 0.1
    gap: NonNeg | None = None
    gaps: list[NonNeg] | None = None
    floor_to_column: bool = True
    level_tolerance: Pos = 0.1

    @field_validator("law")
    @classmethod
    def _known_law(cls, v: str) -> str:
        key = v.strip().lower()
        if key not in LAW_NAMES:
            close = difflib.get_close_matches(key, LAW_NAMES, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise ValueError(f"unknown law {v!r}{hint}; choose one of {', '.join(LAW_NAMES)}")
        return key

    @model_validator(mode="after")
    def _law_keys(self) -> ContactConfig:
        used = LAW_FIELDS[self.law]
        for key in sorted(self.model_fields_set - used - _CONTACT_COMMON):
            raise _field_error(key, f"not used by the {self.law} law (got "
                                    f"{_fmt(getattr(self, key))}); it reads "
                                    f"{', '.join(sorted(used))}")
        if self.gap is not None and self.gaps is not None:
            raise _field_error("gaps", "give gap (all pairs) or gaps (one per pair), not both")
        if self.gap is None and self.gaps is None:
            raise _field_error("gap", "required: the separation [m] between neighbours "
                                      "(gap = 0.02, or gaps = [...] one per pair)")
        return self

    def gap_list(self, n_pairs: int) -> list[float]:
        """The gap of each pair of neighbours [m]."""
        return list(self.gaps) if self.gaps is not None else [self.gap] * n_pairs  # type: ignore[list-item]

    def spec(self) -> ContactSpec:
        """The :class:`ContactSpec` (domain errors propagate unprefixed)."""
        kw = self.model_dump(exclude=set(_CONTACT_COMMON - {"law"}), exclude_none=True)
        return ContactSpec(**kw)


# ============================================================================ solver/output
class SolverConfig(_Section):
    """``[solver]``: options of :func:`pounding.integrate.simulate`.

    ``dt`` [s] output step (rounded down to a divisor of the record step; default 1 ms),
    ``duration`` [s] time simulated (default: the record's; after it, free vibration),
    ``rtol`` [-] tolerance of the adaptive steps through contacts, ``h_max`` [s] their
    largest size.
    """

    dt: Pos | None = None
    duration: Pos | None = None
    rtol: Annotated[float, Field(gt=0, lt=1)] = 1e-8
    h_max: Pos | None = None

    def kwargs(self) -> dict[str, Any]:
        """Keyword arguments of :func:`~pounding.integrate.simulate`."""
        return {"dt": self.dt, "duration": self.duration, "rtol": self.rtol, "h_max": self.h_max}


class OutputConfig(_Section):
    """``[output]``: ``figures`` (write the PNG figures), ``dpi`` (their resolution)."""

    figures: bool = True
    dpi: Annotated[int, Field(ge=30, le=1200)] = 150


# ============================================================================ the run
class Built(NamedTuple):
    """What :meth:`RunConfig.build` returns: unpack as ``model, motion, solver_kwargs``."""

    model: PoundingModel
    motion: GroundMotion
    solver: dict[str, Any]


class RunConfig(_Section):
    """A whole model file. See the module docstring and ``docs/running.md``."""

    name: str = "model"
    description: str | None = None
    record: RecordConfig
    building: Annotated[list[BuildingConfig], Field(min_length=1)]
    contact: ContactConfig | None = None
    solver: SolverConfig = SolverConfig()
    output: OutputConfig = OutputConfig()

    _source: Path | None = PrivateAttr(default=None)

    @model_validator(mode="after")
    def _pairs(self) -> RunConfig:
        nb = len(self.building)
        if self.contact is None:
            if nb > 1:
                raise _field_error("contact", f"required with {nb} buildings: a [contact] "
                                              "table with law, its parameters and gap(s)")
            return self
        if self.contact.gaps is not None and len(self.contact.gaps) != nb - 1:
            raise _field_error(("contact", "gaps"),
                               f"need {nb - 1} value(s) for {nb} buildings (got "
                               f"{len(self.contact.gaps)}: {self.contact.gaps})")
        return self

    @property
    def source(self) -> Path | None:
        """The file this was read from, if any."""
        return self._source

    def build(self) -> Built:
        """The model, the ground motion and the solver keyword arguments.

        A :class:`ValueError` from a constructor of the library is re-raised prefixed
        with the path of the section at fault (``building[1]: ...``).
        """
        buildings = []
        for i, b in enumerate(self.building):
            with _prefixed(f"building[{i}]"):
                buildings.append(b.build(f"B{i + 1}"))
        if self.contact is not None:
            with _prefixed("contact"):
                spec = self.contact.spec()
            gaps = self.contact.gap_list(len(buildings) - 1)
        else:
            spec, gaps = ContactSpec("linear-spring", k=1.0), []
        geometry: dict[str, Any] = {}
        if self.contact is not None:
            geometry = {"floor_to_column": self.contact.floor_to_column,
                        "level_tolerance": self.contact.level_tolerance}
        with _prefixed("contact"):
            model = PoundingModel(buildings, gaps, spec, name=self.name, **geometry)
            model.contacts  # noqa: B018  (builds every contact law with its floor masses)
        for p in range(len(buildings) - 1):
            if not any(c.pair == p for c in model.contacts):
                a, b = buildings[p], buildings[p + 1]
                raise ValueError(
                    f"building[{p}] and building[{p + 1}]: no floor at the same elevation, "
                    "so they can never collide (floor levels [m]: "
                    f"{[round(float(x), 6) for x in a.floor_levels]} and "
                    f"{[round(float(x), 6) for x in b.floor_levels]}); with "
                    "contact.floor_to_column = false floors meet only at equal levels")
        with _prefixed("record"):
            motion = self.record.load()
        return Built(model, motion, self.solver.kwargs())

    # ------------------------------------------------------------------ writing
    def to_dict(self, resolve_paths: bool = False) -> dict[str, Any]:
        """The configuration as plain data (no None values), ready for :meth:`to_toml`.

        With ``resolve_paths`` the record file is written as an absolute path, so the
        copy still works from another folder.
        """
        data = self.model_dump(exclude_none=True)
        if self.contact is not None:
            keep = LAW_FIELDS[self.contact.law] | _CONTACT_COMMON
            data["contact"] = {k: v for k, v in data["contact"].items() if k in keep}
        if resolve_paths and self.record.file is not None and self.record.path is not None:
            data["record"]["file"] = str(self.record.path)
        return data

    def to_toml(self, resolve_paths: bool = False, header: str = "") -> str:
        """The configuration as TOML text that :func:`parse_config` reads back equal."""
        return dump_toml(self.to_dict(resolve_paths), header=header)


class _prefixed:
    """Context manager: re-raise a ValueError as ``ValueError("<where>: <message>")``."""

    def __init__(self, where: str) -> None:
        self.where = where

    def __enter__(self) -> None:
        return None

    def __exit__(self, typ: type | None, exc: BaseException | None, tb: Any) -> bool:
        if isinstance(exc, ValueError) and not isinstance(exc, ValidationError):
            raise ValueError(f"{self.where}: {exc}") from exc
        return False


# ============================================================================ loading
def parse_config(data: dict[str, Any], base_dir: str | os.PathLike[str] = ".",
                 where: str = "config") -> RunConfig:
    """Validate already-parsed TOML data; ``base_dir`` is where relative paths start.

    Raises
    ------
    ValueError
        One line per problem, each ``<where>: <key path>: <problem> (got <value>)``.
    """
    try:
        cfg = RunConfig.model_validate(data, context={"base_dir": Path(base_dir)})
    except ValidationError as exc:
        raise ValueError(format_validation_error(exc, prefix=f"{where}: ")) from None
    try:
        cfg.build()
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    return cfg


SWEEP_CASE_TABLES = ("grid", "list", "random")
"""The tables of a sweep file that give its cases (:mod:`pounding.studies.sweep`); a file
with ``base`` and one of them is a sweep file, not a model file."""


def load_config(path: str | os.PathLike[str]) -> RunConfig:
    """Read and validate a TOML model file (and check it builds).

    Raises
    ------
    ValueError
        If the file is missing or not TOML, or any key is unknown or has a bad value:
        one line per problem naming the key path and the value.
    """
    p = Path(path)
    data = read_toml(p, "model file")
    if "base" in data and any(k in data for k in SWEEP_CASE_TABLES):
        raise ValueError(f"{p}: this is a sweep file (it has 'base' and a [grid], [list] or "
                         f"[random] table), not a model file: run it with `pounding sweep {p}`")
    cfg = parse_config(data, base_dir=p.resolve().parent, where=str(p))
    cfg._source = p.resolve()
    return cfg


# ============================================================================ error text
_TYPE_WORDS = {
    "float_type": "must be a number",
    "float_parsing": "must be a number",
    "int_type": "must be an integer",
    "int_from_float": "must be an integer",
    "int_parsing": "must be an integer",
    "string_type": "must be a string (in quotes)",
    "bool_type": "must be true or false",
    "list_type": "must be a list [ ... ]",
    "model_type": "must be a table",
    "dict_type": "must be a table",
    "finite_number": "must be a finite number",
    "missing": "required",
}


def _loc_text(loc: tuple[Any, ...]) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + str(part)
    return out


def _section_model(loc: tuple[Any, ...]) -> type[BaseModel] | None:
    """The pydantic model class at ``loc`` inside :class:`RunConfig` (for key suggestions)."""
    model: Any = RunConfig
    for part in loc:
        if isinstance(part, int):
            continue
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            return None
        field = model.model_fields.get(part)
        if field is None:
            return None
        model = _inner_model(field.annotation)
    return model if isinstance(model, type) and issubclass(model, BaseModel) else None


def _inner_model(tp: Any) -> Any:
    """Unwrap ``X | None``, ``list[X]``, ``Annotated[X, ...]`` down to a model class."""
    for _ in range(6):
        if isinstance(tp, type) and issubclass(tp, BaseModel):
            return tp
        origin = typing.get_origin(tp)
        args = [a for a in typing.get_args(tp) if a is not type(None)]
        if origin in (typing.Union, types.UnionType, list, typing.Annotated) and args:
            tp = args[0]
        else:
            return None
    return None


def _one_error(err: dict[str, Any]) -> str:
    loc = tuple(err.get("loc", ()))
    typ = err.get("type", "")
    ctx = err.get("ctx") or {}
    inp = err.get("input")
    if typ == "config_field":
        field = ctx["field"]
        loc = loc + (tuple(field) if isinstance(field, (tuple, list)) else (field,))
        return f"{_loc_text(loc)}: {ctx['message']}"
    where = _loc_text(loc) or "(top level)"
    if typ == "value_error":
        msg = str(err.get("msg", "")).removeprefix("Value error, ")
        return f"{where}: {msg}"
    if typ == "extra_forbidden":
        key = str(loc[-1]) if loc else "?"
        model = _section_model(loc[:-1])
        allowed = sorted(model.model_fields) if model is not None else []
        close = difflib.get_close_matches(key, allowed, n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        keys = f" (keys here: {', '.join(allowed)})" if allowed else ""
        return f"{where}: unknown key (got {_fmt(inp)}){hint}{keys}"
    if typ == "missing":
        return f"{where}: required"
    if typ in ("greater_than", "greater_than_equal", "less_than", "less_than_equal"):
        op = {"greater_than": ">", "greater_than_equal": ">=", "less_than": "<",
              "less_than_equal": "<="}[typ]
        bound = next(iter(ctx.values()))
        return f"{where}: must be {op} {_fmt(bound)} (got {_fmt(inp)})"
    if typ in ("too_short", "too_long"):
        lo = ctx.get("min_length")
        hi = ctx.get("max_length")
        want = (f"{lo} value(s)" if lo == hi else
                f"at least {lo} value(s)" if typ == "too_short" else f"at most {hi} value(s)")
        return f"{where}: must hold {want} (got {ctx.get('actual_length')}: {_fmt(inp)})"
    words = _TYPE_WORDS.get(typ, str(err.get("msg", "invalid")))
    return f"{where}: {words} (got {_fmt(inp)})"


def format_validation_error(exc: ValidationError, prefix: str = "") -> str:
    """One line per problem: ``<prefix><key path>: <problem> (got <value>)``."""
    lines = []
    for err in exc.errors(include_url=False):
        line = prefix + _one_error(dict(err))
        if line not in lines:
            lines.append(line)
    return "\n".join(lines)


# ============================================================================ TOML writing
def _toml_key(key: str) -> str:
    return key if key.replace("_", "").replace("-", "").isalnum() else json.dumps(key)


def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"cannot write {v!r} to TOML")
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def dump_toml(data: dict[str, Any], header: str = "") -> str:
    """Write a dict of scalars, tables and arrays of tables as TOML (nested tables inline)."""
    lines = [f"# {h}" if h else "#" for h in header.splitlines()]
    tables: list[tuple[str, dict[str, Any]]] = []
    arrays: list[tuple[str, list[dict[str, Any]]]] = []
    for k, v in data.items():
        if isinstance(v, dict):
            tables.append((k, v))
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            arrays.append((k, v))
        else:
            lines.append(f"{_toml_key(k)} = {_toml_value(v)}")
    order = [k for k in data if any(k == t for t, _ in tables) or any(k == a for a, _ in arrays)]
    tdict, adict = dict(tables), dict(arrays)
    for k in order:
        if k in tdict:
            lines += ["", f"[{_toml_key(k)}]"]
            lines += [f"{_toml_key(kk)} = {_toml_value(vv)}" for kk, vv in tdict[k].items()]
        else:
            for item in adict[k]:
                lines += ["", f"[[{_toml_key(k)}]]"]
                lines += [f"{_toml_key(kk)} = {_toml_value(vv)}" for kk, vv in item.items()]
    return "\n".join(lines) + "\n"
