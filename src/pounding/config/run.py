"""A whole model file: ``[solver]``, ``[output]`` and the run they make (reading one from a
file is :mod:`pounding.config.load`)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any, NamedTuple

from pydantic import Field, PrivateAttr, model_validator

from pounding.config.base import Section, field_error, fmt, prefixed
from pounding.config.bridge import BridgeConfig
from pounding.config.building import BuildingConfig
from pounding.config.contact import CONTACT_COMMON, LAW_FIELDS, ContactConfig
from pounding.config.device import DeviceConfig
from pounding.config.isolation import WallConfig
from pounding.config.quantities import Duration, Step
from pounding.config.record import RecordConfig
from pounding.config.spatial import SpatialConfig
from pounding.config.toml import dump_toml

if TYPE_CHECKING:  # the model is imported by the builder that makes one
    from pounding.ground_motion import GroundMotion, GroundMotionComponents
    from pounding.model import ContactSpec, PoundingModel


class SolverConfig(Section):
    """``[solver]``: options of :func:`pounding.integrate.simulate`.

    ``dt`` [s] output step (rounded down to a divisor of the record step; default 1 ms),
    ``duration`` [s] time simulated (default: the record's; after it, free vibration),
    ``rtol`` [-] tolerance of the adaptive steps through contacts, ``h_max`` [s] their
    largest size.
    """

    dt: Step | None = None
    duration: Duration | None = None
    rtol: Annotated[float, Field(gt=0, lt=1)] = 1e-8
    h_max: Step | None = None

    def kwargs(self) -> dict[str, Any]:
        """Keyword arguments of :func:`~pounding.integrate.simulate`."""
        return {"dt": self.dt, "duration": self.duration, "rtol": self.rtol, "h_max": self.h_max}


class OutputConfig(Section):
    """``[output]``: ``figures`` (write the PNG figures), ``dpi`` (their resolution)."""

    figures: bool = True
    dpi: Annotated[int, Field(ge=30, le=1200)] = 150


class Built(NamedTuple):
    """What :meth:`RunConfig.build` returns: unpack as ``model, motion, solver_kwargs``
    (``motion`` the site's x and y components for a model with buildings in plan)."""

    model: PoundingModel
    motion: GroundMotion | GroundMotionComponents
    solver: dict[str, Any]


class RunConfig(Section):
    """A whole model file. See the module docstring and ``docs/running.md``."""

    name: str = "model"
    description: str | None = None
    record: RecordConfig
    building: list[BuildingConfig] = Field(default_factory=list)
    bridge: BridgeConfig | None = None  #: ``[bridge]``: frames of a bridge, in place of buildings
    contact: ContactConfig | None = None
    device: list[DeviceConfig] = []
    wall: list[WallConfig] = []
    solver: SolverConfig = SolverConfig()
    output: OutputConfig = OutputConfig()
    pushover: dict[str, Any] | None = None  #: ``[pushover]``, read by ``pounding pushover`` alone
    spatial: SpatialConfig | None = None  #: ``[spatial]``: each building on its own ground

    _source: Path | None = PrivateAttr(default=None)
    _plausibility: tuple[str, ...] = PrivateAttr(default=())

    @property
    def in_plan(self) -> bool:
        """True if some building is in plan (the ground then has an x and a y component)."""
        return any(b.kind == "plan" for b in self.building)

    @model_validator(mode="after")
    def _pairs(self) -> RunConfig:
        if self.bridge is not None:
            return self._bridge_keys()
        if not self.building:
            if "building" in self.model_fields_set:  # (given, and empty)
                raise field_error("building", "must hold at least 1 value(s) (got [])")
            raise field_error("building", "required: one [[building]] table or more (or a "
                                          "[bridge])")
        nb = len(self.building)
        if not self.in_plan:
            for key in ("second", "second_file", "incidence"):
                value = getattr(self.record, key)
                if value is not None:
                    raise field_error(("record", key),
                                      f"a second horizontal component and its incidence are "
                                      f"for a model with buildings in plan (plan = {{ … }}); "
                                      f"these buildings are planar, shaken along x by the "
                                      f"record alone (got {key} = {fmt(value)})")
        if self.spatial is not None:
            if self.in_plan:
                raise field_error("spatial", "buildings in plan (two ground components) on "
                                             "spatially varying ground are not modelled yet")
            frames = [i for i, b in enumerate(self.building) if b.kind == "frame"]
            if frames:
                raise field_error("spatial", f"yielding frames (building[{frames[0]}]) on "
                                             "spatially varying ground are not modelled yet")
            given = self.spatial.n_buildings()
            if self.spatial.records is not None and given != nb:
                raise field_error(("spatial", "records"),
                                  f"need {nb - 1} record(s), one for each building after the "
                                  f"first (building 1 stands on [record]) (got {given - 1})")
            if self.spatial.positions is not None and given != nb:
                raise field_error(("spatial", "positions"),
                                  f"need {nb} value(s), one per building (got "
                                  f"{len(self.spatial.positions)}: "
                                  f"{fmt(self.spatial.positions)})")
        if self.contact is None:
            lawless = [i for i, w in enumerate(self.wall) if w.law is None]
            if lawless:
                raise field_error("contact", f"required with a [[wall]] without a law of its "
                                              f"own (wall[{lawless[0]}]): a [contact] table "
                                              "with the law its impacts follow, or law = "
                                              "... in the wall's table")
            if nb > 1:
                raise field_error("contact", f"required with {nb} buildings: a [contact] "
                                              "table with law, its parameters and gap(s)")
            return self
        if nb > 1 and self.contact.gap is None and self.contact.gaps is None:
            raise field_error(("contact", "gap"), "required: the separation [m] between "
                                                   "neighbours (gap = 0.02, or gaps = [...] "
                                                   "one per pair)")
        if self.contact.gaps is not None and len(self.contact.gaps) != nb - 1:
            raise field_error(("contact", "gaps"),
                               f"need {nb - 1} value(s) for {nb} buildings (got "
                               f"{len(self.contact.gaps)}: {self.contact.gaps})")
        return self

    def _bridge_keys(self) -> RunConfig:
        """A bridge's file: no buildings or walls beside it, a contact law without gaps."""
        for key in ("building", "wall"):
            if getattr(self, key):
                raise field_error(key, f"a model file with a [bridge] has no [[{key}]]: its "
                                       "frames are the row, its abutments the walls")
        assert self.bridge is not None
        if self.bridge.transverse:
            if self.contact is not None:
                raise field_error("contact", "a bridge across its axis has no [contact] table: "
                                             "its decks do not strike each other, its keys "
                                             "have their own law (bridge.abutment_keys, "
                                             "bridge.joint[].shear_key)")
            if self.spatial is not None:
                raise field_error("spatial", "a bridge across its axis on spatially varying "
                                             "ground is not modelled yet: give one record")
        if self.contact is None and not self.bridge.transverse:
            raise field_error("contact", "required with a [bridge]: a [contact] table with the "
                                         "law of the impacts at the joints and abutments")
        for key in ("gap", "gaps"):
            if self.contact is None:
                break
            if getattr(self.contact, key) is not None:
                raise field_error(("contact", key), f"the gaps of a bridge are its joints' and "
                                                    f"abutments' (bridge.joint[].gap, "
                                                    f"bridge.abutment_gaps); got "
                                                    f"{fmt(getattr(self.contact, key))}")
        for key in ("second", "second_file", "incidence"):
            if getattr(self.record, key) is not None:
                raise field_error(("record", key), "a bridge along its axis is shaken by one "
                                                   "component (the record's)")
        return self

    @property
    def source(self) -> Path | None:
        """The file this was read from, if any."""
        return self._source

    @property
    def plausibility(self) -> tuple[str, ...]:
        """The plausibility warnings of the file as read by :func:`load_config` or
        :func:`parse_config` (inputs probably in the wrong unit, one line each,
        :mod:`pounding.config.plausibility`); each was also issued as a
        :class:`~pounding.plausibility.PlausibilityWarning`."""
        return self._plausibility

    def build(self) -> Built:
        """The model, the ground motion and the solver keyword arguments.

        A :class:`ValueError` from a constructor of the library is re-raised prefixed
        with the path of the section at fault (``building[1]: ...``).
        """
        from pounding.ground_motion import GroundMotion
        from pounding.model import ContactSpec, PoundingModel

        if self.bridge is not None:
            return self._build_bridge()
        buildings = []
        for i, b in enumerate(self.building):
            with prefixed(f"building[{i}]", BuildingConfig.model_fields):
                buildings.append(b.build(f"B{i + 1}"))
        if self.contact is not None:
            with prefixed("contact", ContactConfig.model_fields):
                spec = self.contact.spec()
            gaps = self.contact.gap_list(len(buildings) - 1)
        else:
            spec, gaps = ContactSpec("linear-spring", k=1.0), []
        geometry: dict[str, Any] = {}
        if self.contact is not None:
            geometry = {"floor_to_column": self.contact.floor_to_column,
                        "level_tolerance": self.contact.level_tolerance}
        devices: list[Any] = []
        if self.device:
            try:
                bare = PoundingModel(buildings, gaps, spec, **geometry)
            except ValueError as exc:
                text = str(exc)
                if text.startswith("buildings["):
                    raise ValueError("building[" + text[len("buildings["):]) from exc
                raise ValueError(f"contact: {text}") from exc
            floors = [(c.left.label(), c.right.label()) for c in bare.contacts
                      if c.is_floor_to_floor]
        owner: list[int] = []  # the file's device table of each of the model's devices
        for i, d in enumerate(self.device):
            with prefixed(f"device[{i}]", DeviceConfig.model_fields):
                made = d.build(floors)
            devices.extend(made)
            owner.extend([i] * len(made))
        try:
            walls = []
            for i, w in enumerate(self.wall):
                with prefixed(f"wall[{i}]", WallConfig.model_fields):
                    walls.append(w.build())
            model = PoundingModel(buildings, gaps, spec, name=self.name, **geometry,
                                  devices=devices, walls=walls)
            model.contacts  # noqa: B018  (builds every contact law with its floor masses)
        except ValueError as exc:
            text = str(exc)
            found = re.match(r"devices\[(\d+)\]", text)
            if found and int(found[1]) < len(owner):
                # the model's devices[k] comes from the file's device[owner[k]] (a table with
                # floors = "all" makes one device at each shared floor level)
                raise ValueError(f"device[{owner[int(found[1])]}]" + text[found.end():]) from exc
            if text.startswith("buildings["):  # and its buildings[i] the file's building[i]
                raise ValueError("building[" + text[len("buildings["):]) from exc
            if text.startswith("walls["):  # the model's walls[i] is the file's wall[i]
                raise ValueError("wall[" + text[len("walls["):]) from exc
            raise ValueError(f"contact: {text}") from exc
        for p in range(len(buildings) - 1):
            if not any(c.pair == p for c in model.contacts):
                left, right = buildings[p], buildings[p + 1]
                raise ValueError(
                    f"building[{p}] and building[{p + 1}]: no floor at the same elevation, "
                    "so they can never collide (floor levels [m]: "
                    f"{[round(float(x), 6) for x in left.floor_levels]} and "
                    f"{[round(float(x), 6) for x in right.floor_levels]}); with "
                    "contact.floor_to_column = false floors meet only at equal levels")
        with prefixed("record", RecordConfig.model_fields):
            motion = self.record.load(components=self.in_plan)
        if self.spatial is not None:
            assert isinstance(motion, GroundMotion)
            with prefixed("spatial", SpatialConfig.model_fields):
                motion = self.spatial.apply(motion, self.record.factor_of(motion))
            _walls_on_their_ground(self.spatial, model)
        return Built(model, motion, self.solver.kwargs())

    def _build_bridge(self) -> Built:
        """:meth:`build` of a file with a ``[bridge]``."""
        from pounding.ground_motion import GroundMotion
        from pounding.model import ContactSpec, PoundingModel

        assert self.bridge is not None
        with prefixed("bridge", BridgeConfig.model_fields):
            bridge = self.bridge.build(self.name)
        if self.contact is not None:
            with prefixed("contact", ContactConfig.model_fields):
                spec = self.contact.spec()
            tolerance = self.contact.level_tolerance
        else:  # (across the axis: the keys' law names the model's contacts)
            stops = bridge.stops()
            spec = stops[0].law if stops else ContactSpec("linear-spring", k=1.0)
            tolerance = 0.1
        # [[device]] beside the bridge's own restrainers: links between decks, bumpers in a
        # joint's gap or at a backwall (floors = "all": at every joint)
        devices: list[Any] = []
        owner: list[int] = []
        joints = [(f"B{j + 1}F1", f"B{j + 2}F1") for j in range(len(bridge.frames) - 1)]
        for i, d in enumerate(self.device):
            with prefixed(f"device[{i}]", DeviceConfig.model_fields):
                made = d.build(joints)
            devices.extend(made)
            owner.extend([i] * len(made))
        arguments = bridge.model_arguments()
        own = len(arguments.get("devices", ()))  # the restrainers come first
        arguments["devices"] = [*arguments.get("devices", ()), *devices]
        try:
            model = PoundingModel(contact=spec, level_tolerance=tolerance, **arguments)
            model.contacts  # noqa: B018  (builds every contact law with its deck masses)
        except ValueError as exc:
            text = str(exc)
            found = re.match(r"devices\[(\d+)\]", text)
            if found and int(found[1]) >= own:  # a [[device]] of the file
                raise ValueError(f"device[{owner[int(found[1]) - own]}]"
                                 + text[found.end():]) from exc
            raise ValueError(f"bridge: {text}") from exc
        with prefixed("record", RecordConfig.model_fields):
            motion = self.record.load(components=False)
        if self.spatial is not None:
            assert isinstance(motion, GroundMotion)
            with prefixed("spatial", SpatialConfig.model_fields):
                motion = self.spatial.apply(motion, self.record.factor_of(motion))
            _walls_on_their_ground(self.spatial, model)
        return Built(model, motion, self.solver.kwargs())

    # ------------------------------------------------------------------ writing
    def to_dict(self, resolve_paths: bool = False) -> dict[str, Any]:
        """The configuration as plain data (no None values), ready for :meth:`to_toml`.

        With ``resolve_paths`` the record file (and a ``match`` target) is written as an
        absolute path, so the copy still works from another folder.
        """
        data = self.model_dump(exclude_none=True)
        if self.contact is not None:
            keep = LAW_FIELDS[self.contact.law] | CONTACT_COMMON
            data["contact"] = {k: v for k, v in data["contact"].items() if k in keep}
            if self.bridge is not None:  # (a bridge's contacts are deck to deck only)
                data["contact"].pop("floor_to_column", None)
        for dev, raw in zip(self.device, data.get("device", [])):
            if dev.rubber is not None:
                keep = LAW_FIELDS[dev.rubber.law] | {"law"}
                raw["rubber"] = {k: v for k, v in raw["rubber"].items() if k in keep}
        if not data.get("device"):
            data.pop("device", None)
        if resolve_paths and self.record.file is not None and self.record.path is not None:
            data["record"]["file"] = str(self.record.path)
        if resolve_paths and self.record.second_path is not None:
            data["record"]["second_file"] = str(self.record.second_path)
        if resolve_paths and self.record.match is not None:
            data["record"]["match"]["target"] = str(self.record.match.path)
        return data

    def to_toml(self, resolve_paths: bool = False, header: str = "",
                defaults: bool = False) -> str:
        """The configuration as TOML text that :func:`parse_config` reads back equal (with
        ``defaults``: :meth:`with_defaults`, which builds the same run)."""
        data = self.with_defaults(resolve_paths) if defaults else self.to_dict(resolve_paths)
        return dump_toml(data, header=header)

    def with_defaults(self, resolve_paths: bool = False) -> dict[str, Any]:
        """:meth:`to_dict` with every default the run takes written out: each building's
        name, storey height and damping, the contact's damping formula, and the solver's
        output step (the one used: the largest divisor of the record step not above the
        one asked for), duration and largest adaptive step. The file it makes runs the same
        model to the last bit, and says what was assumed."""
        from pounding.config.record import SA_DAMPING
        from pounding.contact.factory import default_formula
        from pounding.integrate import DEFAULT_OUTPUT_STEP, grid_step

        data = self.to_dict(resolve_paths)
        for i, (b, raw) in enumerate(zip(self.building, data["building"])):
            raw.setdefault("name", f"B{i + 1}")
            if b.kind in ("sdof", "uniform"):
                raw.setdefault("height", 3.0)
            elif b.kind == "storeys" and b.heights is None:
                raw.setdefault("height", 3.0)
            if b.kind == "matrices" and (b.matrices is not None and b.matrices.C is not None
                                         or _npz_has_c(b.npz)):
                continue  # damped by its matrix C
            elif b.kind == "plan" and b.heights is None:
                raw.setdefault("height", 3.0)
            if b.damping is None:
                raw["damping"] = ({"ratio": 0.05} if b.kind == "sdof" else
                                  {"rayleigh": [0.05, 0.05], "modes": [1, 3]}
                                  if b.kind == "plan" else
                                  {"rayleigh": [0.05, 0.05], "modes": [1, 2]})
        if self.contact is not None:
            c = data["contact"]
            law = self.contact.law
            default = default_formula(law, self.contact.tension)
            if "formula" in LAW_FIELDS[law] and default and "e" in c and "formula" not in c:
                c["formula"] = default
        if self.record.sa_g is not None or self.record.saavg_g is not None:
            data["record"].setdefault("sa_damping", SA_DAMPING)
        if self.record.saavg_g is not None:
            from pounding.spectra.scaling import SAAVG_N

            data["record"].setdefault("saavg_n", SAAVG_N)
        if self.in_plan:
            data["record"].setdefault("incidence", 0.0)
        motion = self.record.load(components=self.in_plan)
        step = grid_step(motion.dt, self.solver.dt or DEFAULT_OUTPUT_STEP)
        sol = data.setdefault("solver", {})
        sol["dt"] = step
        sol.setdefault("duration", motion.duration)
        sol.setdefault("h_max", step)
        return data


def _npz_has_c(path: str | None) -> bool:
    """True if the ``.npz`` archive at ``path`` holds a damping matrix ``C``."""
    if path is None:
        return False
    import numpy as np

    with np.load(path, allow_pickle=False) as archive:
        return "C" in archive.files


def _walls_on_their_ground(spatial: SpatialConfig, model: PoundingModel) -> None:
    """A wall given a ground of its own (``[spatial] wall_positions`` / ``wall_records``)
    must stand at that end of the row."""
    sides = {w.side for w in model.walls}
    for side in spatial.wall_sides():
        if side not in sides:
            key = "wall_positions" if spatial.wall_positions is not None else "wall_records"
            raise ValueError(f"spatial.{key}.{side}: the row has no wall on its {side} "
                             f"(walls: {', '.join(sorted(sides)) or 'none'})")
