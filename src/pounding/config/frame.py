"""``frame = {...}`` of a ``[[building]]``: a planar moment frame with plastic hinges
(:class:`pounding.structure.frame.Frame`), and its hinge laws.

Two forms, told apart by the keys present:

* **regular** (a frame written by hand): ``bays`` [m] (bay widths), ``storey_heights`` [m]
  (or ``height`` and ``n_storeys``), ``column_EI``, ``beam_EI`` [N·m²] (one value or one per
  storey), optional ``column_EA``, ``beam_EA`` [N] (default effectively rigid),
  ``column_hinge``, ``beam_hinge`` (a hinge law, or one per storey), ``floor_mass`` [kg],
  ``beam_load`` [N/m] (uniform gravity load on the beams), ``leaning_load`` [N] (per floor),
  ``column_mass``, ``beam_mass`` [kg/m] (the members' own mass, per storey);
* **full**: ``nodes = [[x, y], …]`` [m], ``members = [{ nodes = [i, j], EA, EI, w, mass,
  hinges = [law_i, law_j] }, …]`` (0-based node numbers; ``w`` [N/m] uniform gravity load;
  ``mass`` [kg/m] the member's own; a hinge law, or ``{}`` for a rigid end), ``supports =
  [{ node, fix = "fixed" | "pinned" | "roller" }, …]``, optional ``masses = [{ node, mass =
  [m_x, m_y, J] }, …]``, ``loads = [{ node, force = [F_x, F_y, M] }, …]`` (gravity,
  downward ``F_y < 0``) and ``leaning_load`` [N] per floor.

Both take ``diaphragm`` (rigid floors, default true), ``geometry`` (``"linear"``,
``"p-delta"``, ``"consistent"``; default ``"linear"``) and ``mass_matrix`` (``"lumped"``,
the default, or ``"consistent"``: the members' own mass in the modes; a time history takes
lumped masses).

A hinge law: ``{ type = "elastic-plastic", k0 = …, m_y = … }``, ``{ type = "bilinear",
k0 = …, m_y = …, hardening = 0.03 }`` or the modified Ibarra–Medina–Krawinkler laws
``{ type = "imk-bilinear" | "imk-peak-oriented", k0, m_y, theta_p, theta_pc, … }``
(:class:`HingeLawConfig`; ``k0`` [N·m/rad] the hinge's elastic rotational stiffness, ``m_y``
[N·m] its yield moment).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from pounding.config.base import Section, field_error, fmt
from pounding.config.quantities import MAX_FORCE, MAX_LENGTH, MAX_MASS, Length, Mass

__all__ = ["FrameConfig", "HingeLawConfig", "HINGE_LAWS"]

MAX_RIGIDITY = 1e20
"""Largest EA [N], EI [N·m²] or k0 [N·m/rad] accepted (1e16 is a rigid member in practice)."""

Rigidity = Annotated[float, Field(gt=0, le=MAX_RIGIDITY)]
Moment = Annotated[float, Field(gt=0, le=MAX_FORCE * MAX_LENGTH)]
LineLoad = Annotated[float, Field(ge=0, le=MAX_FORCE)]
"""A uniform gravity load on a member [N/m], downward."""
NodalForce = Annotated[float, Field(ge=-MAX_FORCE * MAX_LENGTH, le=MAX_FORCE * MAX_LENGTH)]
NodeMass = Annotated[float, Field(ge=0, le=MAX_MASS)]
MemberMass = Annotated[float, Field(ge=0, le=MAX_MASS)]
"""A member's own mass per length [kg/m]."""
Coordinate = Annotated[float, Field(ge=-MAX_LENGTH, le=MAX_LENGTH)]
GravityLoad = Annotated[float, Field(ge=0, le=MAX_FORCE)]

HINGE_LAWS: tuple[str, ...] = ("elastic-plastic", "bilinear", "imk-bilinear",
                               "imk-peak-oriented")
"""Hinge laws by the name model files use (``type = …``)."""

FIXITIES: dict[str, tuple[bool, bool, bool]] = {
    "fixed": (True, True, True), "pinned": (True, True, False), "roller": (False, True, False)}
"""Support kinds (``fix = …``): the fixed ``(u_x, u_y, θ)``."""

Rotation = Annotated[float, Field(gt=0, le=10)]
"""A plastic or ultimate rotation [rad]."""
Ratio = Annotated[float, Field(ge=0, le=100)]

_IMK_KEYS = ("theta_p", "theta_pc", "theta_u", "mc_my", "kappa", "m_y_neg", "theta_p_neg",
             "theta_pc_neg", "theta_u_neg", "mc_my_neg", "kappa_neg", "Lambda", "Lambda_S",
             "Lambda_C", "Lambda_K", "Lambda_A", "c", "c_S", "c_C", "c_K", "c_A", "D_pos",
             "D_neg")
_TO_LAW = {"Lambda": "lambda_", "Lambda_S": "lambda_s", "Lambda_C": "lambda_c",
           "Lambda_K": "lambda_k", "Lambda_A": "lambda_a", "c_S": "c_s", "c_C": "c_c",
           "c_K": "c_k", "c_A": "c_a", "D_pos": "d_pos", "D_neg": "d_neg"}


class HingeLawConfig(Section):
    """A hinge law: ``{ type, k0, m_y, … }`` (docs/frames.md).

    * ``"elastic-plastic"``: ``k0`` [N·m/rad], ``m_y`` [N·m];
    * ``"bilinear"``: also ``hardening`` (post-yield ratio b);
    * ``"imk-bilinear"``, ``"imk-peak-oriented"`` (the modified Ibarra–Medina–Krawinkler laws,
      :mod:`pounding.hysteresis.imk`): ``theta_p``, ``theta_pc`` [rad] (*required*),
      ``theta_u`` [rad] (default none), ``mc_my`` (1.1), ``kappa`` (0.4), the negative side's
      ``*_neg`` (default as the positive), cyclic deterioration ``Lambda`` [rad] (Λ; 0: none)
      or per mode ``Lambda_S``, ``Lambda_C``, ``Lambda_K`` (``Lambda_A`` peak-oriented), the
      exponents ``c`` or ``c_S`` …, and the rates ``D_pos``, ``D_neg``.
    """

    type: Literal["elastic-plastic", "bilinear", "imk-bilinear", "imk-peak-oriented"]
    k0: Rigidity
    m_y: Moment
    hardening: Annotated[float, Field(ge=0, lt=1)] | None = None
    theta_p: Rotation | None = None
    theta_pc: Rotation | None = None
    theta_u: Rotation | None = None
    mc_my: Annotated[float, Field(ge=1, le=10)] | None = None
    kappa: Annotated[float, Field(ge=0, lt=1)] | None = None
    m_y_neg: Moment | None = None
    theta_p_neg: Rotation | None = None
    theta_pc_neg: Rotation | None = None
    theta_u_neg: Rotation | None = None
    mc_my_neg: Annotated[float, Field(ge=1, le=10)] | None = None
    kappa_neg: Annotated[float, Field(ge=0, lt=1)] | None = None
    Lambda: Ratio | None = None
    Lambda_S: Ratio | None = None
    Lambda_C: Ratio | None = None
    Lambda_K: Ratio | None = None
    Lambda_A: Ratio | None = None
    c: Ratio | None = None
    c_S: Ratio | None = None
    c_C: Ratio | None = None
    c_K: Ratio | None = None
    c_A: Ratio | None = None
    D_pos: Annotated[float, Field(gt=0, le=1)] | None = None
    D_neg: Annotated[float, Field(gt=0, le=1)] | None = None

    @model_validator(mode="after")
    def _keys(self) -> HingeLawConfig:
        if self.type == "elastic-plastic" and self.hardening not in (None, 0.0):
            raise field_error("hardening", f"an elastic-plastic hinge does not harden; use type "
                                           f"= \"bilinear\" (got {fmt(self.hardening)})")
        imk = self.type.startswith("imk")
        if not imk:
            for key in _IMK_KEYS:
                if getattr(self, key) is not None:
                    raise field_error(key, f"a constant of the IMK laws, not of a "
                                           f"{self.type} hinge (got {fmt(getattr(self, key))})")
            return self
        if self.hardening is not None:
            raise field_error("hardening", f"not a constant of {self.type} (its post-yield "
                                           f"slope follows from mc_my and theta_p) (got "
                                           f"{fmt(self.hardening)})")
        for key in ("theta_p", "theta_pc"):
            if getattr(self, key) is None:
                raise field_error(key, f"required for an {self.type} hinge [rad]")
        if self.type == "imk-bilinear":
            for key in ("Lambda_A", "c_A"):
                if getattr(self, key) is not None:
                    raise field_error(key, "only for imk-peak-oriented (the reloading "
                                           f"deterioration) (got {fmt(getattr(self, key))})")
        return self

    def build(self) -> Any:
        """The :class:`~pounding.hysteresis.hinges.HingeLaw`."""
        if self.type == "elastic-plastic":
            from pounding.hysteresis.hinges import ElasticPlastic

            return ElasticPlastic(k0=self.k0, m_y=self.m_y)
        if self.type == "bilinear":
            from pounding.hysteresis.hinges import BilinearHinge

            return BilinearHinge(k0=self.k0, m_y=self.m_y, hardening=self.hardening or 0.0)
        from pounding.hysteresis.imk import IMKBilinear, IMKPeakOriented

        kw = {_TO_LAW.get(key, key): getattr(self, key) for key in _IMK_KEYS
              if getattr(self, key) is not None}
        cls = IMKPeakOriented if self.type == "imk-peak-oriented" else IMKBilinear
        return cls(k0=self.k0, m_y=self.m_y, **kw)


class MemberConfig(Section):
    """``members = [{ nodes = [i, j], EA, EI, w, mass, hinges = [law_i, law_j] }, …]``."""

    nodes: Annotated[list[Annotated[int, Field(ge=0)]], Field(min_length=2, max_length=2)]
    EA: Rigidity = 1e12
    EI: Rigidity
    w: LineLoad = 0.0
    mass: MemberMass = 0.0
    hinges: Annotated[list[HingeLawConfig | dict[str, Any]],
                      Field(min_length=2, max_length=2)] | None = None

    @model_validator(mode="after")
    def _empty_or_law(self) -> MemberConfig:
        for i, h in enumerate(self.hinges or []):
            if isinstance(h, dict) and h:
                raise field_error(("hinges", i), f"a hinge law ({{ type = …, k0 = …, m_y = … }}) "
                                                 f"or {{}} for a rigid end (got {fmt(h)})")
        return self


class SupportConfig(Section):
    """``supports = [{ node, fix = "fixed" | "pinned" | "roller" }, …]``."""

    node: Annotated[int, Field(ge=0)]
    fix: Literal["fixed", "pinned", "roller"] = "fixed"


class NodeMassConfig(Section):
    """``masses = [{ node, mass = [m_x, m_y, J] }, …]`` [kg, kg, kg·m²]."""

    node: Annotated[int, Field(ge=0)]
    mass: Annotated[list[NodeMass], Field(min_length=3, max_length=3)]


class NodeLoadConfig(Section):
    """``loads = [{ node, force = [F_x, F_y, M] }, …]`` [N, N, N·m]: gravity, applied first."""

    node: Annotated[int, Field(ge=0)]
    force: Annotated[list[NodalForce], Field(min_length=3, max_length=3)]


PerStorey = float | Annotated[list[float], Field(min_length=1)]


class FrameConfig(Section):
    """``frame = {...}``: see the module docstring."""

    # regular form
    bays: Length | Annotated[list[Length], Field(min_length=1)] | None = None
    storey_heights: Annotated[list[Length], Field(min_length=1)] | None = None
    height: Length | None = None
    n_storeys: Annotated[int, Field(ge=1, le=200)] | None = None
    column_EI: Rigidity | Annotated[list[Rigidity], Field(min_length=1)] | None = None
    beam_EI: Rigidity | Annotated[list[Rigidity], Field(min_length=1)] | None = None
    column_EA: Rigidity | Annotated[list[Rigidity], Field(min_length=1)] = 1e12
    beam_EA: Rigidity | Annotated[list[Rigidity], Field(min_length=1)] = 1e12
    column_hinge: HingeLawConfig | Annotated[list[HingeLawConfig], Field(min_length=1)] | None = None
    beam_hinge: HingeLawConfig | Annotated[list[HingeLawConfig], Field(min_length=1)] | None = None
    floor_mass: NodeMass | Annotated[list[NodeMass], Field(min_length=1)] = 0.0
    beam_load: LineLoad | Annotated[list[LineLoad], Field(min_length=1)] = 0.0
    column_mass: MemberMass | Annotated[list[MemberMass], Field(min_length=1)] = 0.0
    beam_mass: MemberMass | Annotated[list[MemberMass], Field(min_length=1)] = 0.0
    # full form
    nodes: Annotated[list[Annotated[list[Coordinate], Field(min_length=2, max_length=2)]],
                     Field(min_length=2)] | None = None
    members: Annotated[list[MemberConfig], Field(min_length=1)] | None = None
    supports: Annotated[list[SupportConfig], Field(min_length=1)] | None = None
    masses: list[NodeMassConfig] | None = None
    loads: list[NodeLoadConfig] | None = None
    # both
    leaning_load: GravityLoad | Annotated[list[GravityLoad], Field(min_length=1)] = 0.0
    diaphragm: bool = True
    geometry: Literal["linear", "p-delta", "consistent"] = "linear"
    mass_matrix: Literal["lumped", "consistent"] = "lumped"

    @property
    def form(self) -> str:
        """``"full"`` (nodes and members) or ``"regular"`` (bays and storeys)."""
        return "full" if self.nodes is not None or self.members is not None else "regular"

    @property
    def n_storeys_given(self) -> int:
        """Number of storeys of the regular form."""
        if self.storey_heights is not None:
            return len(self.storey_heights)
        return self.n_storeys or 1

    @model_validator(mode="after")
    def _shape(self) -> FrameConfig:
        regular = ("bays", "storey_heights", "height", "n_storeys", "column_EI", "beam_EI",
                   "column_hinge", "beam_hinge")
        if self.form == "full":
            for key in ("column_mass", "beam_mass"):
                if getattr(self, key) != 0.0:
                    raise field_error(key, "a key of the regular form (per storey); give each "
                                           "member's own mass as members[i].mass [kg/m]")
        full = ("nodes", "members", "supports", "masses", "loads")
        if self.form == "full":
            for key in regular:
                if getattr(self, key) is not None:
                    raise field_error(key, f"a key of the regular form (bays, storeys), not of "
                                           f"the full form (nodes, members) (got "
                                           f"{fmt(getattr(self, key))})")
            for key in ("nodes", "members", "supports"):
                if getattr(self, key) is None:
                    raise field_error(key, "required for a frame given node by node (nodes, "
                                           "members, supports)")
            n = len(self.nodes or [])
            given: dict[int, int] = {}
            for i, item in enumerate(self.masses or []):
                if item.node in given:
                    raise field_error(("masses", i, "node"),
                                      f"node {item.node} is given a mass twice (masses"
                                      f"[{given[item.node]}] too); give each node one entry "
                                      "with all its masses")
                given[item.node] = i
            for key in ("members", "supports", "masses", "loads"):
                for i, item in enumerate(getattr(self, key) or []):
                    for j in (item.nodes if key == "members" else [item.node]):
                        if j >= n:
                            raise field_error((key, i, "nodes" if key == "members" else "node"),
                                              f"must be a node number in [0, {n - 1}] (got {j})")
            return self
        for key in full:
            if getattr(self, key) is not None:
                raise field_error(key, f"a key of the full form (nodes, members), not of the "
                                       f"regular form (bays, storeys) (got "
                                       f"{fmt(getattr(self, key))})")
        for key in ("bays", "column_EI", "beam_EI"):
            if getattr(self, key) is None:
                raise field_error(key, "required for a regular frame (bays, storey_heights, "
                                       "column_EI, beam_EI)")
        if self.storey_heights is not None and (self.height is not None
                                                or self.n_storeys is not None):
            raise field_error("height", "give storey_heights, or height with n_storeys, not "
                                        "both")
        if self.storey_heights is None and self.height is None:
            raise field_error("storey_heights", "required: one height [m] per storey (or "
                                                "height and n_storeys)")
        n = self.n_storeys_given
        for key in ("column_EI", "beam_EI", "column_EA", "beam_EA", "column_hinge",
                    "beam_hinge", "floor_mass", "beam_load", "leaning_load", "column_mass",
                    "beam_mass"):
            value = getattr(self, key)
            if isinstance(value, list) and len(value) not in (1, n):
                raise field_error(key, f"need one value or {n} (one per storey), got "
                                       f"{len(value)}")
        return self

    def build(self, name: str, damping: Any) -> Any:
        """The :class:`~pounding.structure.frame.Frame`."""
        import numpy as np

        from pounding.structure.frame import Frame, FrameHinge, regular_frame

        def laws(value: Any) -> Any:
            if value is None:
                return None
            if isinstance(value, list):
                return [v.build() for v in value]
            return value.build()

        own: dict[str, Any] = {} if damping is None else {"damping": damping}
        if self.form == "regular":
            return regular_frame(
                self.bays,  # type: ignore[arg-type]
                self.storey_heights if self.storey_heights is not None else self.height,  # type: ignore[arg-type]
                n_storeys=self.n_storeys_given, column_EI=self.column_EI,  # type: ignore[arg-type]
                beam_EI=self.beam_EI, column_EA=self.column_EA,  # type: ignore[arg-type]
                beam_EA=self.beam_EA, column_hinge=laws(self.column_hinge),
                beam_hinge=laws(self.beam_hinge), floor_mass=self.floor_mass,
                beam_load=self.beam_load, leaning_load=self.leaning_load,
                diaphragm=self.diaphragm, geometry=self.geometry, name=name,
                column_mass=self.column_mass, beam_mass=self.beam_mass,
                mass_matrix=self.mass_matrix, **own)
        assert self.nodes is not None and self.members is not None and self.supports is not None
        n = len(self.nodes)
        supports = np.zeros((n, 3), dtype=bool)
        for s in self.supports:
            supports[s.node] = FIXITIES[s.fix]
        masses = np.zeros((n, 3))
        for m in self.masses or []:
            masses[m.node] += m.mass
        loads = np.zeros((n, 3))
        for ld in self.loads or []:
            loads[ld.node] += ld.force
        hinges = []
        for e, mem in enumerate(self.members):
            for end, h in enumerate(mem.hinges or []):
                if isinstance(h, HingeLawConfig):
                    hinges.append(FrameHinge(e, end, h.build()))
        lean: Any = self.leaning_load
        if isinstance(lean, float) and lean == 0.0:
            lean = None
        return Frame(nodes=np.array(self.nodes, dtype=float),
                     elements=np.array([m.nodes for m in self.members], dtype=np.int64),
                     EA=np.array([m.EA for m in self.members]),
                     EI=np.array([m.EI for m in self.members]), supports=supports,
                     hinges=tuple(hinges), masses=masses, nodal_loads=loads,
                     member_loads=np.array([m.w for m in self.members]),
                     diaphragm=self.diaphragm, leaning_loads=lean, geometry=self.geometry,
                     name=name, member_mass=np.array([m.mass for m in self.members]),
                     mass_matrix=self.mass_matrix, **own)
