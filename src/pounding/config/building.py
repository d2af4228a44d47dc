"""``[[building]]``: the buildings of a model file (their damping and storey laws:
:mod:`pounding.config.storeys`)."""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

from pydantic import Field, ValidationInfo, model_validator

from pounding.config.base import Section, field_error, fmt, prefixed
from pounding.config.foundation import FoundationConfig
from pounding.config.frame import FrameConfig
from pounding.config.isolation import IsolatorConfig
from pounding.config.plan import ElementConfig, PlanConfig
from pounding.config.quantities import MAX_LENGTH, Elevation, Length, Mass, Period, Stiffness
from pounding.config.storeys import DampingConfig, StoreyLawConfig
from pounding.memo import Memo
from pounding.structure.floor_arrays import MAX_FLOORS, SMALLEST

if TYPE_CHECKING:  # the buildings are imported by the builder that makes one
    from pounding.structure.frame import Frame
    from pounding.structure.matrices import MatrixBuilding
    from pounding.structure.plan import PlanBuilding
    from pounding.structure.shear_building import ShearBuilding

__all__ = ["BUILDINGS", "BuildingConfig", "DampingConfig", "MatrixFilesConfig",
           "StoreyLawConfig"]

Influence = Annotated[float, Field(ge=-MAX_LENGTH, le=MAX_LENGTH)]
"""An entry of an influence vector ``r`` (1 for a translation along the ground motion, a
lever arm [m] for a rotation)."""


BUILDINGS = Memo(max_items=64, max_bytes=256 << 20)
"""Buildings made by :meth:`BuildingConfig.build`, by configuration (as JSON, every field)
and default name."""


def _building_bytes(b: ShearBuilding | MatrixBuilding | PlanBuilding) -> int:
    """Bytes a building holds: its mass, stiffness and damping matrices."""
    return 3 * 8 * b.n * b.n


_SDOF_KEYS = ("mass", "stiffness", "period", "height")
_UNIFORM_KEYS = ("n_storeys", "mass", "stiffness", "period", "height")
_STOREY_KEYS = ("masses", "stiffnesses", "heights", "height", "period")
_MATRIX_KEYS = ("matrices", "npz", "elevations", "labels", "r", "floors")
_PLAN_KEYS = ("masses", "heights", "height")
_PLAN_ONLY = ("plan", "elements")
_SHEAR_KEYS = ("mass", "stiffness", "period", "height", "n_storeys", "masses", "stiffnesses",
               "heights", "storey_law", "isolator")


class MatrixFilesConfig(Section):
    """``matrices = { M = "m.csv", K = "k.csv", C = "c.csv" }``: one file a matrix (any
    format of :func:`pounding.structure.read_matrix`), relative to the model file; ``C`` is
    optional (without it, ``damping``)."""

    M: str
    K: str
    C: str | None = None


def _resolve(base: Path, value: str) -> str:
    return str((base / Path(value).expanduser()).resolve())


class BuildingConfig(Section):
    """``[[building]]``: one building; the tables go left to right.

    Five ways to give it, told apart by the keys present:

    * SDOF: ``mass`` [kg] and ``period`` [s] or ``stiffness`` [N/m]; ``height`` [m] (3).
    * uniform: ``n_storeys``, ``mass`` [kg] per floor, ``stiffness`` [N/m] per storey or
      ``period`` [s] (fundamental; the stiffness follows), ``height`` [m] per storey (3).
    * storeys: ``masses`` [kg], ``stiffnesses`` [N/m], ``heights`` [m] (or one ``height``
      for all; default 3), ground storey first; optional ``period`` [s] rescales all
      stiffnesses to that fundamental period.
    * matrices (a :class:`~pounding.structure.MatrixBuilding`): ``matrices = { M = …,
      K = …, C = … }`` (files; ``C`` optional) or ``npz = "b.npz"`` (arrays ``M``, ``K``,
      optionally ``C``), paths relative to the model file (the copy a run writes names them
      in full); ``elevations`` [m], one per degree of freedom; optional ``labels`` (default
      ``F1`` … ``Fn``), ``r`` (influence vector) and ``floors`` (the DOFs that are floor
      translations, labels or 0-based indices; default all). No storey law.
    * plan (a :class:`~pounding.structure.plan.PlanBuilding`, rigid floors with ``u_x``,
      ``u_y``, ``θ``): ``plan = { width, depth, site_y }`` (:class:`PlanConfig`),
      ``masses`` [kg], ``heights`` [m] (or one ``height``; default 3) and ``elements``
      (:class:`ElementConfig`), the lateral load-resisting elements. Linear: no storey law,
      no isolator. Under two horizontal components of the ground (``[record] second``).

    ``foundation`` (:class:`pounding.config.foundation.FoundationConfig`) puts an SDOF,
    uniform, storey-by-storey or matrix building, or a frame, on a footing on soil (a
    flexible base: :func:`pounding.structure.foundation.flexible_base`,
    :func:`pounding.structure.frame_linear.frame_on_flexible_base`; a building with
    ``storey_law`` or a frame with plastic hinges there needs the footing's ``mass`` and
    ``inertia``), and a building in plan on one that also sways across the row, rocks about
    the row's axis and twists (:func:`pounding.structure.foundation.plan_flexible_base`; the
    footing centred under the plan).

    ``damping`` (:class:`DampingConfig`) defaults to 5 % in every mode for an SDOF, 5 %
    Rayleigh at modes 1 and 3 for a building in plan (the PlanBuilding's own: modes 1 and 2
    of a symmetric plan share a period) and 5 % Rayleigh at modes 1 and 2 otherwise. ``storey_law`` (:class:`StoreyLawConfig`) makes the
    storeys yield; without it they stay linear. ``isolator``
    (:class:`pounding.config.isolation.IsolatorConfig`) puts the building, as its
    superstructure, on a base slab and an isolation storey (base isolation).
    """

    name: str | None = None
    mass: Mass | None = None
    stiffness: Stiffness | None = None
    period: Period | None = None
    height: Length | None = None
    n_storeys: Annotated[int, Field(ge=1, le=MAX_FLOORS)] | None = None
    masses: Annotated[list[Mass], Field(min_length=1, max_length=MAX_FLOORS)] | None = None
    stiffnesses: Annotated[list[Stiffness], Field(min_length=1, max_length=MAX_FLOORS)] | None = None
    heights: Annotated[list[Length], Field(min_length=1, max_length=MAX_FLOORS)] | None = None
    damping: DampingConfig | None = None
    storey_law: StoreyLawConfig | None = None
    isolator: IsolatorConfig | None = None
    matrices: MatrixFilesConfig | None = None
    npz: str | None = None
    elevations: Annotated[list[Elevation], Field(min_length=1)] | None = None
    labels: Annotated[list[str], Field(min_length=1)] | None = None
    r: Annotated[list[Influence], Field(min_length=1)] | None = None
    floors: Annotated[list[str | int], Field(min_length=1)] | None = None
    plan: PlanConfig | None = None
    elements: Annotated[list[ElementConfig], Field(min_length=1)] | None = None
    frame: FrameConfig | None = None
    foundation: FoundationConfig | None = None

    @model_validator(mode="before")
    @classmethod
    def _full_paths(cls, data: Any, info: ValidationInfo) -> Any:
        """Matrix files relative to the model file's folder, resolved."""
        if not isinstance(data, dict) or ("matrices" not in data and "npz" not in data):
            return data
        base = Path((info.context or {}).get("base_dir", "."))
        data = dict(data)
        if isinstance(data.get("npz"), str):
            data["npz"] = _resolve(base, data["npz"])
        mats = data.get("matrices")
        if isinstance(mats, dict):
            data["matrices"] = {k: _resolve(base, v) if isinstance(v, str) else v
                                for k, v in mats.items()}
        return data

    @property
    def kind(self) -> str:
        """``'storeys'``, ``'uniform'``, ``'sdof'``, ``'matrices'``, ``'plan'`` or
        ``'frame'``."""
        if self.frame is not None:
            return "frame"
        if self.plan is not None:
            return "plan"
        if self.matrices is not None or self.npz is not None:
            return "matrices"
        if self.masses is not None:
            return "storeys"
        if self.n_storeys is not None:
            return "uniform"
        return "sdof"

    @model_validator(mode="after")
    def _consistent(self) -> BuildingConfig:
        for key in ("mass", "stiffness", "masses", "stiffnesses"):
            value = getattr(self, key)
            for i, x in enumerate([value] if isinstance(value, float) else value or []):
                if x < SMALLEST:
                    where = key if isinstance(value, float) else (key, i)
                    raise field_error(where, f"must be at least {SMALLEST:.3g}: smaller "
                                             f"positive numbers are subnormal (got {x:g})")
        if self.foundation is not None:
            if self.isolator is not None:
                raise field_error("foundation", "not under a base-isolated building: give "
                                                "foundation or isolator, not both")
            if self.storey_law is not None and self.kind not in ("plan", "frame"):
                f = self.foundation  # (plan, frame: their storey_law is refused below)
                for key in ("mass", "inertia"):
                    if getattr(f, key) <= 0.0:
                        raise field_error(("foundation", key), f"a yielding building's footing "
                                          f"needs its {key} (got {getattr(f, key):g}): its sway "
                                          "and rocking are then degrees of freedom (only a "
                                          "linear building's massless footing is condensed "
                                          "out)")
        if self.isolator is not None and self.storey_law is not None:
            raise field_error("isolator", "a base-isolated building's superstructure stays "
                                          "linear: give isolator or storey_law, not both")
        kind = self.kind
        self._check_shape()
        self._check_modes()
        return self

    def _check_modes(self) -> None:
        """Refuse Rayleigh damping anchored at a mode the building does not have."""
        if self.damping is None or self.damping.modes is None:
            return
        n = {"plan": 3 * self.n}.get(self.kind, self.n)
        ratios = self.damping.rayleigh or []
        for i, mode in enumerate(self.damping.modes):
            if n == 1 and i == 1 and len(set(ratios)) <= 1:
                continue  # (one mode, one ratio: the second anchor is not used, as the
                #           default damping a run's model.toml writes back)
            if mode > n:
                raise field_error(("damping", "modes", i),
                                  f"must be in [1, {n}]: the building has {n} mode(s) (got "
                                  f"{mode})")

    def _check_shape(self) -> None:
        kind = self.kind
        if kind == "frame":
            for key in type(self).model_fields:
                if key not in ("name", "damping", "frame", "foundation") and \
                        getattr(self, key) is not None:
                    raise field_error(key, f"not a key of a frame (its masses, stiffnesses "
                                           f"and heights are in frame = {{...}}) (got "
                                           f"{fmt(getattr(self, key))})")
            return
        if kind == "plan":
            self._check_plan_keys()
            return
        for key in _PLAN_ONLY:
            if getattr(self, key) is not None:
                raise field_error(key, "only for a building in plan (plan = { width = …, "
                                       "depth = … } with elements = [ … ]) (got "
                                       f"{fmt(getattr(self, key))})")
        if kind == "matrices":
            self._check_matrix_keys()
            return
        for key in _MATRIX_KEYS:
            if getattr(self, key) is not None:
                raise field_error(key, f"only for a building given as matrices (matrices = "
                                       f"{{ M = …, K = … }} or npz = …) (got "
                                       f"{fmt(getattr(self, key))})")
        allowed = {"sdof": _SDOF_KEYS, "uniform": _UNIFORM_KEYS, "storeys": _STOREY_KEYS}[kind]
        shape = {"sdof": "an SDOF building (mass, period|stiffness)",
                 "uniform": "a uniform building (n_storeys, mass, stiffness|period)",
                 "storeys": "a building given storey by storey (masses, stiffnesses, heights)"
                 }[kind]
        if kind == "sdof" and (self.stiffnesses is not None or self.heights is not None):
            raise field_error("masses", "required with stiffnesses/heights: one value [kg] "
                                         "per floor")
        for key in (*_UNIFORM_KEYS, *_STOREY_KEYS):
            if key not in allowed and getattr(self, key) is not None:
                raise field_error(key, f"not a key of {shape} (got {fmt(getattr(self, key))})")
        if kind in ("sdof", "uniform"):
            if self.mass is None:
                raise field_error("mass", f"required for {shape}")
            if (self.stiffness is None) == (self.period is None):
                raise field_error("period", f"give exactly one of period and stiffness "
                                             f"(got period={self.period!r}, "
                                             f"stiffness={self.stiffness!r})")
        else:
            n = len(self.masses)  # type: ignore[arg-type]
            if self.stiffnesses is None:
                raise field_error("stiffnesses", "required with masses, one value [N/m] "
                                                  "per storey")
            if len(self.stiffnesses) != n:
                raise field_error("stiffnesses", f"need {n} values, one per floor like "
                                                  f"masses (got {len(self.stiffnesses)})")
            if self.heights is not None and self.height is not None:
                raise field_error("height", "give heights or height, not both")
            if self.heights is not None and len(self.heights) != n:
                raise field_error("heights", f"need {n} values, one per floor like masses "
                                              f"(got {len(self.heights)})")
        if self.storey_law is not None:
            self.storey_law.check_storeys(self.n)

    def _check_matrix_keys(self) -> None:
        for key in _SHEAR_KEYS:
            if getattr(self, key) is not None:
                why = (" (a matrix building is linear: storey yielding is the shear "
                       "building's)" if key == "storey_law" else "")
                raise field_error(key, f"not a key of a building given as matrices{why} "
                                       f"(got {fmt(getattr(self, key))})")
        if self.matrices is not None and self.npz is not None:
            raise field_error("npz", f"give matrices or npz, not both (got npz = "
                                     f"{self.npz!r})")
        if self.elevations is None:
            raise field_error("elevations", "required for a building given as matrices: one "
                                            "elevation [m] per degree of freedom")
        n = len(self.elevations)
        labels = self.labels if self.labels is not None else [f"F{j + 1}" for j in range(n)]
        if self.labels is not None:
            if len(self.labels) != n:
                raise field_error("labels", f"need {n} values, one per degree of freedom like "
                                            f"elevations (got {len(self.labels)}: "
                                            f"{fmt(self.labels)})")
            for i, label in enumerate(self.labels):
                if label in self.labels[:i]:
                    raise field_error(("labels", i), f"repeats labels[{self.labels.index(label)}]"
                                                     f": each degree of freedom needs its own "
                                                     f"label (got {label!r})")
        for i, f in enumerate(self.floors or []):
            if isinstance(f, int) and not 0 <= f < n:
                raise field_error(("floors", i), f"must be a label or an index in [0, {n - 1}] "
                                                 f"(got {f})")
            if isinstance(f, str) and f not in labels:
                raise field_error(("floors", i), f"must be one of the labels "
                                                 f"({', '.join(labels[:12])}"
                                                 f"{', …' if n > 12 else ''}) or an index in "
                                                 f"[0, {n - 1}] (got {f!r})")
        if self.floors is None:  # every degree of freedom is a floor
            for i, z in enumerate(self.elevations):
                if not z > 0.0:
                    raise field_error(("elevations", i),
                                      f"must be > 0 m: without floors = [...] every degree of "
                                      f"freedom is a floor, and floors stand above the ground "
                                      f"(got {fmt(z)})")
                if i and not z > self.elevations[i - 1]:
                    raise field_error(("elevations", i),
                                      f"must be above elevations[{i - 1}] = "
                                      f"{fmt(self.elevations[i - 1])} m: each floor its own "
                                      f"elevation, the lowest first (got {fmt(z)})")
        if self.matrices is not None and self.matrices.C is not None and self.damping is not None:
            raise field_error("damping", "give a damping matrix (matrices.C) or damping, not "
                                         f"both (got C = {self.matrices.C!r})")
        files = ([("npz", self.npz)] if self.npz is not None else
                 [(f"matrices.{k}", v) for k, v in self.matrices.model_dump().items()  # type: ignore[union-attr]
                  if v is not None])
        for key, path in files:
            p = Path(path)
            if not p.is_file():
                what = "is a directory, not a matrix file" if p.is_dir() else "no such file"
                raise field_error(tuple(key.split(".")), f"{what} {path!r} (relative paths "
                                                         "start at the model file's folder)")

    def _check_plan_keys(self) -> None:
        own = {*_PLAN_KEYS, *_PLAN_ONLY, "name", "damping", "foundation"}
        for key in type(self).model_fields:
            if key in own or getattr(self, key) is None:
                continue
            why = {"storey_law": " (a building in plan is linear)",
                   "isolator": " (a building in plan stands on the ground)",
                   "stiffnesses": " (each element of elements has its own stiffnesses)",
                   }.get(key, "")
            raise field_error(key, f"not a key of a building in plan{why} (got "
                                   f"{fmt(getattr(self, key))})")
        if self.masses is None:
            raise field_error("masses", "required for a building in plan: one value [kg] per "
                                        "floor, floor 1 first")
        n = len(self.masses)
        if self.elements is None:
            raise field_error("elements", "required for a building in plan: its lateral "
                                          "load-resisting elements, e.g. elements = [ { x = "
                                          "0.0, y = 6.0, direction = \"y\", stiffnesses = "
                                          "1e8 }, … ]")
        if self.heights is not None and self.height is not None:
            raise field_error("height", "give heights or height, not both")
        if self.heights is not None and len(self.heights) != n:
            raise field_error("heights", f"need {n} values, one per floor like masses "
                                          f"(got {len(self.heights)}: {fmt(self.heights)})")
        for i, e in enumerate(self.elements):
            if isinstance(e.stiffnesses, list) and len(e.stiffnesses) != n:
                raise field_error(("elements", i, "stiffnesses"),
                                  f"need {n} values, one per storey like masses, or one value "
                                  f"for every storey (got {len(e.stiffnesses)}: "
                                  f"{fmt(e.stiffnesses)})")
        plan = self.plan
        assert plan is not None
        if plan.mass_centres is not None and isinstance(plan.mass_centres[0], list) \
                and len(plan.mass_centres) != n:
            raise field_error(("plan", "mass_centres"),
                              f"need one [x, y] for every floor or {n}, one a floor (got "
                              f"{len(plan.mass_centres)}: {fmt(plan.mass_centres)})")
        if isinstance(plan.inertias, list) and len(plan.inertias) != n:
            raise field_error(("plan", "inertias"),
                              f"need one value or {n}, one a floor (got {len(plan.inertias)}: "
                              f"{fmt(plan.inertias)})")
        plan.check_inertias(self.masses)
        for i, e in enumerate(self.elements):
            for key, value, size in (("x", e.x, plan.width), ("y", e.y, plan.depth)):
                if not 0.0 <= value <= size:
                    raise field_error(("elements", i, key),
                                      f"must lie inside the plan, in [0, {fmt(size)}] m (the "
                                      f"plan's {'width' if key == 'x' else 'depth'}) (got "
                                      f"{fmt(value)})")

    def _files(self) -> list[str]:
        if self.npz is not None:
            return [self.npz]
        return [v for v in self.matrices.model_dump().values() if v is not None]  # type: ignore[union-attr]

    @property
    def n(self) -> int:
        """Number of storeys (of degrees of freedom, for a building given as matrices)."""
        if self.frame is not None:
            if self.frame.form == "regular":
                return self.frame.n_storeys_given
            ys = sorted({y for _, y in self.frame.nodes or []})
            return max(1, len(ys) - 1)
        return {"sdof": 1, "uniform": self.n_storeys or 1, "storeys": len(self.masses or ()),
                "matrices": len(self.elevations or ()),
                "plan": len(self.masses or ())}[self.kind]

    def build(self, default_name: str) -> ShearBuilding | MatrixBuilding | PlanBuilding:
        """The :class:`ShearBuilding`, :class:`MatrixBuilding` or
        :class:`~pounding.structure.plan.PlanBuilding` (domain errors propagate
        unprefixed).

        Remembered per configuration and default name (:data:`BUILDINGS`; matrix files by
        their version too): the cases of a sweep that do not change a building share it,
        and its matrices and modal analysis are made once. (A building is immutable.)
        """
        versions: tuple[tuple[int, int], ...] = ()
        if self.kind == "matrices":
            versions = tuple((os.stat(f).st_mtime_ns, os.stat(f).st_size)
                             for f in self._files())
        return BUILDINGS.get((self.model_dump_json(), default_name, versions),
                             lambda: self._build(default_name), size=_building_bytes)

    def _build_matrices(self, name: str) -> MatrixBuilding:
        from pounding.structure import read_matrix

        damping = self.damping.build() if self.damping is not None else None
        if self.npz is not None:
            m_file, k_file, c_file = self.npz, None, None
        else:
            assert self.matrices is not None
            m_file, k_file, c_file = self.matrices.M, self.matrices.K, self.matrices.C
        n = read_matrix(m_file, "M").shape[0]
        labels = self.labels if self.labels is not None else [f"F{j + 1}" for j in range(n)]
        from pounding.structure import read_matrix_building

        b = read_matrix_building(m_file, k_file, c_file, labels=labels,
                                 elevations=self.elevations,  # type: ignore[arg-type]
                                 r=self.r, damping=damping, name=name, floors=self.floors)
        try:
            b.lumped_masses()  # names M's file and its largest off-diagonal entry
        except ValueError as exc:
            raise ValueError(f"{exc}; the time stepper takes lumped masses") from None
        return b

    def _build_plan(self, name: str) -> PlanBuilding:
        from pounding.structure.plan import PlanBuilding

        plan = self.plan
        assert plan is not None and self.masses is not None and self.elements is not None
        n = len(self.masses)
        heights = self.heights if self.heights is not None else [
            self.height if self.height is not None else 3.0] * n
        inertias = ([plan.inertias] * n if isinstance(plan.inertias, float)
                    else plan.inertias)
        own: dict[str, Any] = {}
        if self.damping is not None:
            own["damping"] = self.damping.build()
        elements = []
        for i, e in enumerate(self.elements):
            with prefixed(f"elements[{i}]", ElementConfig.model_fields):
                elements.append(e.build())
        return PlanBuilding(masses=self.masses, heights=heights, width=plan.width,
                            depth=plan.depth, elements=elements,
                            mass_centres=plan.mass_centres, inertias=inertias, name=name,
                            site_y=plan.site_y, **own)

    def _build(self, default_name: str) -> ShearBuilding | MatrixBuilding | PlanBuilding:
        try:
            b = self._make(default_name)
            if self.foundation is None:
                return b
            from pounding.structure.matrices import MatrixBuilding
            from pounding.structure.plan import PlanBuilding
            from pounding.structure.shear_building import ShearBuilding

            if isinstance(b, PlanBuilding):
                from pounding.structure.foundation import plan_flexible_base

                return plan_flexible_base(b, *self.foundation.build())
            from pounding.structure.foundation import flexible_base
            from pounding.structure.frame_linear import (
                FrameBuilding,
                frame_on_flexible_base,
            )

            if isinstance(b, FrameBuilding):
                return frame_on_flexible_base(b, *self.foundation.build())
            assert isinstance(b, (ShearBuilding, MatrixBuilding))
            return flexible_base(b, *self.foundation.build())
        except ValueError as exc:
            if str(exc).startswith("Rayleigh damping"):  # the ratios given, at these modes
                raise ValueError(f"damping.rayleigh: {exc}") from None
            raise

    def build_frame(self, default_name: str) -> Frame:
        """The :class:`~pounding.structure.frame.Frame` of a ``frame = {...}`` building."""
        if self.frame is None:
            raise ValueError(f"building {self.name or default_name!r}: not a frame (give "
                             "frame = {...})")
        damping = self.damping.build() if self.damping is not None else None
        with prefixed("frame", FrameConfig.model_fields):
            return self.frame.build(self.name or default_name, damping)

    def _make(self, default_name: str) -> ShearBuilding | MatrixBuilding | PlanBuilding:
        name = self.name or default_name
        if self.kind == "frame":
            from pounding.structure.frame_linear import frame_matrix_building

            return frame_matrix_building(self.build_frame(default_name))
        if self.kind == "matrices":
            return self._build_matrices(name)
        if self.kind == "plan":
            return self._build_plan(name)
        from pounding.structure.damping import ModalDamping, RayleighDamping
        from pounding.structure.shear_building import ShearBuilding

        damping = self.damping.build() if self.damping is not None else None
        h = self.height if self.height is not None else 3.0
        if self.kind == "sdof":
            assert self.mass is not None
            if self.stiffness is not None:
                k = self.stiffness
            else:
                assert self.period is not None  # the checks: a stiffness or a period
                k = self.mass * (2.0 * math.pi / self.period) ** 2
                if not SMALLEST <= k < math.inf:
                    raise ValueError(f"mass {self.mass:g} kg with period {self.period:g} s gives "
                                     f"a storey stiffness m (2π/T)² = {k:g} N/m, outside the "
                                     "floating-point range; check mass and period")
            return self._with_law(ShearBuilding(masses=[self.mass], stiffnesses=[k],
                                                heights=[h], damping=damping or ModalDamping(0.05),
                                                name=name))
        if self.kind == "uniform":
            assert self.mass is not None and self.n_storeys is not None
            b = ShearBuilding.uniform(self.n_storeys, self.mass, self.stiffness or 1.0, h,
                                      damping=damping, name=name)
        else:
            assert self.masses is not None and self.stiffnesses is not None
            n = len(self.masses)
            heights = self.heights if self.heights is not None else [h] * n
            b = ShearBuilding(masses=self.masses, stiffnesses=self.stiffnesses,
                              heights=heights, damping=damping or RayleighDamping(), name=name)
        b = b.with_period(self.period) if self.period is not None else b
        return self._with_law(b)

    def _with_law(self, b: ShearBuilding) -> ShearBuilding:
        if self.isolator is not None:
            from pounding.structure.shear_building import ShearBuilding

            iso = self.isolator
            with prefixed("isolator", IsolatorConfig.model_fields):
                return ShearBuilding.base_isolated(b, iso.base_mass, iso.build(),
                                                   base_height=iso.base_height,
                                                   isolator_damping=iso.damping)
        if self.storey_law is None:
            return b
        with prefixed("storey_law", StoreyLawConfig.model_fields):
            return b.with_storey_law(self.storey_law.build(b.heights))
