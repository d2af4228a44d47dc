"""``[bridge]``: a bridge along its axis, written by hand (in place of ``[[building]]``).

Frames left to right, the joints between them, the abutments at the ends (SI units)::

    [bridge]
    abutment_gaps = [0.05, 0.05]      # [m] left, right backwall gaps (leave out: free ends)
    zeta = 0.05                       # damping ratio of every frame's modes 1 and 2

    [[bridge.frame]]
    spans = [36.0, 36.0]              # [m] span lengths of the deck segment
    deck_mass_per_length = 1.8e4      # [kg/m] (or deck_mass [kg], the whole segment)
    bearing = { type = "elastomeric", stiffness = 4.0e7, damping = 0.0 }
    [[bridge.frame.pier]]
    height = 9.0                      # [m] the cap (bearing seat) above the ground
    EI = 2.5e10                       # [N m²] one column's (or stiffness [N/m])
    fixity = "fixed"                  # "cantilever" (3EI/H³) or "fixed" (12EI/H³)
    columns = 2                       # columns of the bent (default 1)
    mass = 1.0e5                      # [kg] the cap and its share of the columns
    law = { type = "bilinear", yield_force = 4.0e6, hardening = 0.02 }   # optional

    [[bridge.joint]]                  # one per joint, between frame j and j + 1
    gap = 0.025                       # [m]
    restrainer = { kind = "restrainer", k = 1.76e7, slack = 0.0127, yield_force = 1.76e6 }
    seat_width = 0.60                 # [m] the seat under the joint (optional)

Seats (optional): ``seat_width`` [m] of a joint, ``abutment_seat_widths = [left, right]``
[m] (``"none"``: not checked; needs the abutment), and the clause their minimum is checked
against, ``seat_clause``: ``{ clause = "aashto-lrfd", seismic_zone = 4,
acceleration_coefficient = 0.4, skew = 0.0 }`` (AASHTO LRFD Art. 4.7.4.4; zone 1–4,
A_s [g] — required in zone 1 —, skew [degrees]; L and H from the frames' spans and piers,
:mod:`pounding.structure.bridge.seats`) or ``{ clause = "given", name = "...", required =
[...] }`` (a required width [m] for every seat, ``A1``, ``J1`` …, ``A2``, ``"none"`` where
not checked, from the clause ``name``). A run reports every seat's peak opening and margin
(``summary.json``: ``seats``).

Bearing ``type``: ``elastomeric`` (``stiffness`` [N/m], ``damping`` [N·s/m]),
``lead-rubber`` (``pre_yield_stiffness``, ``post_yield_stiffness`` [N/m],
``characteristic_strength`` or ``yield_force`` [N]), ``friction-pendulum`` (``radius``
[m], ``mu``), ``sliding`` (a flat PTFE slider: ``mu``); the friction bearings take
``yield_displacement`` [m] (default 0.5 mm) and carry an equal share of the deck's weight.
A ``bearing`` table of a pier overrides the frame's. Pier ``law``: the ``storey_law`` table
of a ``[[building]]`` (``bilinear`` or ``bouc-wen``; ``yield_drift_ratio`` is of the pier's
height). Restrainer ``kind`` (optional): ``restrainer``, cables — ``k`` [N/m], ``slack``
[m], ``yield_force`` [N] (leave out: elastic), ``hardening`` [-] — or a link of
``[[device]]`` (``kelvin``: ``k``, ``c``; ``viscous``: ``c``, ``alpha``; ``maxwell``: ``k``,
``c``, ``alpha``). ``abutment_law`` (optional): the backfill's law at both abutments, as
``[contact]``'s keys — ``{ law = "abutment", backbone = "caltrans", backwall_width = 12.0,
backwall_height = 2.0 }`` (or ``backbone = "hyperbolic"``, ``k``, ``capacity``,
``delta_ult``; :mod:`pounding.contact.abutment`); without it the backwalls are rigid walls
struck with ``[contact]``'s law.

``abutment_piles`` (optional): the abutments' piles in parallel with the backfill behind
the same gap, ``{ count = 3, stiffness = 7.0e6, yield_force = 1.78e5 }`` — per pile: its
stiffness [N/m] (default 40 kip/in, :data:`pounding.structure.bridge.CALTRANS_PILE_STIFFNESS`)
and, optionally, its yield force [N] (elastic–perfectly-plastic); their force is the
contact ``…/piles``.

The ``[contact]`` table gives the law of every impact (deck to deck, deck to abutment)
without ``gap``: the gaps are the joints' and abutments'. The frames are buildings ``B1``,
``B2`` … of every output, the deck their floor ``F1`` (:mod:`pounding.structure.bridge`).

**Across the axis** (``direction = "transverse"``,
:class:`pounding.structure.bridge.TransverseBridge`): the same frames, every number of the
transverse direction (a pier's transverse ``stiffness``, or ``EI`` with the bent's
``fixity``; the bearings' transverse laws); the decks do not strike each other, they are
held by shear keys::

    [bridge]
    direction = "transverse"
    abutment_keys = { gap = 0.02, k = 5.0e8, capacity = 1.5e6, fracture_displacement = 0.05 }

    [[bridge.joint]]                  # optional: keys at an in-span joint
    shear_key = { gap = 0.02, k = 3.0e8, capacity = 1.0e6 }

A key table: ``gap`` [m] each side, ``k`` [N/m], ``capacity`` [N], ``fracture_displacement``
[m] (leave out: the key never breaks; :class:`pounding.contact.shear_key.ShearKey`). No
``[contact]`` table (the keys have their own law), no ``abutment_gaps``, ``abutment_law``,
``abutment_piles``, joint ``gap`` or ``restrainer``; ``[[bridge.joint]]`` tables are given
for every joint or for none.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from pounding.config.base import Ratio, Section, field_error, fmt, prefixed
from pounding.config.quantities import (
    DampingCoefficient,
    Force,
    Gap,
    Length,
    Mass,
    PositiveDamping,
    Stiffness,
    StiffnessOrZero,
)
from pounding.config.contact import LawConfig
from pounding.config.storeys import StoreyLawConfig

__all__ = ["BearingConfig", "BridgeConfig", "BridgeFrameConfig", "JointConfig", "KeyConfig",
           "PierConfig", "PilesConfig", "SeatClauseConfig"]

FlexuralRigidity = Annotated[float, Field(gt=0, le=1e15)]
"""A column's ``EI`` [N·m²]."""

_BEARING_KEYS: dict[str, tuple[set[str], set[str]]] = {  # type: (required, optional)
    "elastomeric": ({"stiffness"}, {"damping"}),
    "lead-rubber": ({"pre_yield_stiffness", "post_yield_stiffness"},
                    {"characteristic_strength", "yield_force", "damping"}),
    "friction-pendulum": ({"radius", "mu"}, {"yield_displacement", "damping"}),
    "sliding": ({"mu"}, {"yield_displacement", "damping"}),
}


class BearingConfig(Section):
    """``bearing = {...}``: the bearing between a pier's cap and the deck (module
    docstring)."""

    type: Literal["elastomeric", "lead-rubber", "friction-pendulum", "sliding"]
    stiffness: Stiffness | None = None
    damping: DampingCoefficient | None = None
    pre_yield_stiffness: Stiffness | None = None
    post_yield_stiffness: StiffnessOrZero | None = None
    characteristic_strength: Force | None = None
    yield_force: Force | None = None
    radius: Length | None = None
    mu: Annotated[float, Field(gt=0, lt=1)] | None = None
    yield_displacement: Length | None = None

    @model_validator(mode="after")
    def _keys(self) -> BearingConfig:
        need, may = _BEARING_KEYS[self.type]
        for key in sorted(self.model_fields_set - need - may - {"type"}):
            raise field_error(key, f"not a constant of a {self.type} bearing (got "
                                    f"{fmt(getattr(self, key))}); it reads "
                                    f"{', '.join(sorted(need | may))}")
        for key in sorted(need):
            if getattr(self, key) is None:
                raise field_error(key, f"required for a {self.type} bearing")
        if self.type == "lead-rubber" and ((self.characteristic_strength is None)
                                           == (self.yield_force is None)):
            raise field_error("characteristic_strength", "give characteristic_strength [N] "
                                                         "or yield_force [N] (one of them)")
        return self

    def build(self, weight: float) -> Any:
        """The :class:`pounding.structure.bridge.Bearing` carrying ``weight`` [N]."""
        from pounding.hysteresis.isolators import BilinearIsolator, FrictionPendulum
        from pounding.structure.bridge import Bearing

        c = self.damping or 0.0
        y = self.yield_displacement or 5e-4
        if self.type == "elastomeric":
            assert self.stiffness is not None
            return Bearing.elastomeric(self.stiffness, c)
        if self.type == "sliding":
            assert self.mu is not None
            return Bearing.sliding(self.mu, weight, y, c)
        if self.type == "friction-pendulum":
            assert self.radius is not None and self.mu is not None
            return Bearing.isolator(FrictionPendulum(self.radius, self.mu, weight=weight,
                                                     yield_displacement=y), c)
        assert self.pre_yield_stiffness is not None and self.post_yield_stiffness is not None
        return Bearing.isolator(BilinearIsolator(
            self.pre_yield_stiffness, self.post_yield_stiffness,
            characteristic_strength=self.characteristic_strength,
            yield_force=self.yield_force), c)


class PierConfig(Section):
    """``[[bridge.frame.pier]]``: one pier (module docstring)."""

    height: Length
    mass: Mass
    stiffness: Stiffness | None = None
    EI: FlexuralRigidity | None = None
    fixity: Literal["cantilever", "fixed"] | None = None
    columns: Annotated[int, Field(ge=1, le=100)] | None = None
    law: StoreyLawConfig | None = None
    bearing: BearingConfig | None = None

    @model_validator(mode="after")
    def _stiffness(self) -> PierConfig:
        if (self.stiffness is None) == (self.EI is None):
            raise field_error("stiffness", "give the pier's lateral stiffness [N/m] or its "
                                           "columns' EI [N m²] with fixity (one of them)")
        if self.EI is None:
            for key in ("fixity", "columns"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"goes with EI, not with stiffness (got "
                                           f"{fmt(getattr(self, key))})")
        elif self.fixity is None:
            raise field_error("fixity", 'required with EI: "cantilever" (3EI/H³, free to '
                                        'rotate at the cap) or "fixed" (12EI/H³)')
        if self.law is not None:
            self.law.check_storeys(1)
        return self

    def lateral_stiffness(self) -> float:
        """The pier's lateral stiffness at the cap [N/m]."""
        from pounding.structure.bridge import pier_stiffness

        if self.stiffness is not None:
            return self.stiffness
        assert self.EI is not None and self.fixity is not None
        return pier_stiffness(self.EI, self.height, self.fixity, self.columns or 1)


class BridgeFrameConfig(Section):
    """``[[bridge.frame]]``: one deck segment on its piers (module docstring)."""

    spans: Annotated[list[Length], Field(min_length=1)]
    deck_mass_per_length: Annotated[float, Field(gt=0, le=1e7)] | None = None
    deck_mass: Mass | None = None
    bearing: BearingConfig | None = None
    pier: Annotated[list[PierConfig], Field(min_length=1)]
    name: str | None = None

    @model_validator(mode="after")
    def _mass(self) -> BridgeFrameConfig:
        if (self.deck_mass is None) == (self.deck_mass_per_length is None):
            raise field_error("deck_mass_per_length", "give the deck's mass per length "
                                                      "[kg/m] or deck_mass [kg] (one of them)")
        for i, p in enumerate(self.pier):
            if p.bearing is None and self.bearing is None:
                raise field_error(("pier", i, "bearing"), "required: a bearing table here or "
                                                         "one for the whole frame")
        return self

    @property
    def mass(self) -> float:
        """The deck segment's mass [kg]."""
        if self.deck_mass is not None:
            return self.deck_mass
        assert self.deck_mass_per_length is not None
        return self.deck_mass_per_length * sum(self.spans)

    def build(self, deck_elevation: float, zeta: float, name: str) -> Any:
        """The :class:`pounding.structure.bridge.BridgeFrame`."""
        from pounding.hysteresis.isolators import GRAVITY
        from pounding.structure.bridge import BridgeFrame, Pier

        piers, bearings = [], []
        share = self.mass * GRAVITY / len(self.pier)  # (each bearing's weight)
        for i, p in enumerate(self.pier):
            with prefixed(f"pier[{i}]", PierConfig.model_fields):
                law = p.law.build([p.height]) if p.law is not None else None
                piers.append(Pier(p.height, p.lateral_stiffness(), p.mass, law))
                bearing = p.bearing if p.bearing is not None else self.bearing
                assert bearing is not None
                bearings.append(bearing.build(share))
        return BridgeFrame(self.mass, piers, bearings, deck_elevation=deck_elevation,
                           zeta=zeta, name=self.name or name, spans=self.spans)


class RestrainerConfig(Section):
    """``restrainer = {...}`` of a joint: a link between the two decks (module
    docstring)."""

    kind: Literal["restrainer", "kelvin", "viscous", "maxwell"]
    k: Stiffness | None = None
    c: PositiveDamping | None = None
    alpha: Annotated[float, Field(gt=0, le=2)] | None = None
    slack: Gap | None = None
    yield_force: Force | None = None
    hardening: Annotated[float, Field(ge=0, lt=1)] | None = None

    @model_validator(mode="after")
    def _keys(self) -> RestrainerConfig:
        cable = ("slack", "yield_force", "hardening")
        if self.kind == "restrainer":
            for key in ("c", "alpha"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"a cable restrainer has no dashpot (got "
                                           f"{fmt(getattr(self, key))}): k, slack, "
                                           "yield_force, hardening")
            if self.k is None:
                raise field_error("k", "required for a cable restrainer [N/m] (the cables' "
                                       "axial stiffness)")
            return self
        for key in cable:
            if getattr(self, key) is not None:
                raise field_error(key, f"a key of kind = \"restrainer\" (got "
                                       f"{fmt(getattr(self, key))})")
        if self.c is None:
            raise field_error("c", f"required for a {self.kind} restrainer [N·s/m]")
        if self.kind == "viscous" and self.k is not None:
            raise field_error("k", f"a viscous restrainer has no spring (got {fmt(self.k)})")
        if self.kind != "viscous" and self.k is None:
            raise field_error("k", f"required for a {self.kind} restrainer [N/m]")
        if self.kind == "kelvin" and self.alpha not in (None, 1.0):
            raise field_error("alpha", f"a kelvin restrainer is linear (got "
                                       f"{fmt(self.alpha)})")
        return self


class KeyConfig(Section):
    """A pair of shear keys (``abutment_keys``, a joint's ``shear_key``): ``gap`` [m] each
    side, ``k`` [N/m], ``capacity`` [N], ``fracture_displacement`` [m] (leave out: never
    breaks)."""

    gap: Gap
    k: Stiffness
    capacity: Force
    fracture_displacement: Length | None = None

    def build(self) -> Any:
        """The :class:`pounding.structure.bridge.ShearKeys`."""
        from pounding.structure.bridge import ShearKeys

        return ShearKeys.of(self.gap, self.k, self.capacity, self.fracture_displacement)


class PilesConfig(Section):
    """``abutment_piles = {...}``: the piles under each abutment, per pile (module
    docstring)."""

    count: Annotated[int, Field(ge=1, le=1000)]
    stiffness: Stiffness | None = None
    yield_force: Force | None = None

    def spec(self) -> Any:
        """The piles' :class:`~pounding.contact.spec.ContactSpec`
        (:func:`pounding.structure.bridge.abutment_piles`)."""
        from pounding.structure.bridge import CALTRANS_PILE_STIFFNESS, abutment_piles

        return abutment_piles(self.count, self.stiffness or CALTRANS_PILE_STIFFNESS,
                              self.yield_force)


class JointConfig(Section):
    """``[[bridge.joint]]``: the expansion joint between two frames: its ``gap`` and
    ``restrainer`` along the axis, its ``shear_key`` across it."""

    gap: Gap | None = None
    restrainer: RestrainerConfig | None = None
    shear_key: KeyConfig | None = None
    seat_width: Length | None = None


SeatWidth = Length | Literal["none"]
"""A seat width [m], or ``"none"``: a seat not checked."""

_CLAUSE_KEYS: dict[str, tuple[set[str], set[str]]] = {  # clause: (required, optional)
    "aashto-lrfd": ({"seismic_zone"}, {"acceleration_coefficient", "skew"}),
    "given": ({"name", "required"}, set()),
}


class SeatClauseConfig(Section):
    """``seat_clause = {...}`` of ``[bridge]``: the clause the seat widths are checked
    against (module docstring, :mod:`pounding.structure.seat_width`)."""

    clause: Literal["aashto-lrfd", "given"]
    seismic_zone: Annotated[int, Field(ge=1, le=4)] | None = None
    acceleration_coefficient: Annotated[float, Field(ge=0, le=5)] | None = None
    skew: Annotated[float, Field(ge=0, lt=90)] | None = None
    name: Annotated[str, Field(min_length=1, max_length=200)] | None = None
    required: list[SeatWidth] | None = None

    @model_validator(mode="after")
    def _keys(self) -> SeatClauseConfig:
        need, may = _CLAUSE_KEYS[self.clause]
        for key in sorted(self.model_fields_set - need - may - {"clause"}):
            raise field_error(key, f"not a key of clause = \"{self.clause}\" (got "
                                    f"{fmt(getattr(self, key))}); it reads "
                                    f"{', '.join(sorted(need | may))}")
        for key in sorted(need):
            if getattr(self, key) is None:
                raise field_error(key, f"required with clause = \"{self.clause}\"")
        if (self.clause == "aashto-lrfd" and self.seismic_zone == 1
                and self.acceleration_coefficient is None):
            raise field_error("acceleration_coefficient", "required in seismic zone 1: A_s "
                                                          "[g] sets 75 % or 100 % of N")
        if self.name is not None and not self.name.strip():
            raise field_error("name", "name the clause the required widths come from")
        return self

    def build(self) -> Any:
        """The clause object (:mod:`pounding.structure.seat_width`)."""
        from pounding.structure.seat_width import AashtoLrfdSeatClause, GivenSeatWidths

        if self.clause == "given":
            assert self.name is not None and self.required is not None
            return GivenSeatWidths(self.name, [None if w == "none" else float(w)
                                               for w in self.required])
        assert self.seismic_zone is not None
        return AashtoLrfdSeatClause(self.seismic_zone, self.acceleration_coefficient or 0.0,
                                    self.skew or 0.0)


class BridgeConfig(Section):
    """``[bridge]``: frames, joints, abutments (module docstring)."""

    frame: Annotated[list[BridgeFrameConfig], Field(min_length=1)]
    joint: list[JointConfig] = Field(default_factory=list)
    abutment_gaps: Annotated[list[Gap | Literal["none"]],
                             Field(min_length=2, max_length=2)] | None = None
    abutment_law: LawConfig | None = None
    abutment_seat_widths: Annotated[list[SeatWidth],
                                    Field(min_length=2, max_length=2)] | None = None
    seat_clause: SeatClauseConfig | None = None
    abutment_piles: PilesConfig | None = None
    abutment_keys: KeyConfig | None = None
    direction: Literal["longitudinal", "transverse"] = "longitudinal"
    deck_elevation: Length | None = None
    zeta: Ratio = 0.05

    @property
    def transverse(self) -> bool:
        """True for a model across the bridge's axis."""
        return self.direction == "transverse"

    @model_validator(mode="after")
    def _direction(self) -> BridgeConfig:
        """The keys of the other direction are refused, naming them."""
        if self.transverse:
            for key in ("abutment_gaps", "abutment_law", "abutment_piles"):
                if getattr(self, key) is not None:
                    raise field_error(key, f"a key of the longitudinal model (got "
                                           f"{fmt(getattr(self, key))}); across the axis the "
                                           "abutments hold the decks by their shear keys: "
                                           "abutment_keys")
            for j, joint in enumerate(self.joint):
                for key in ("gap", "restrainer"):
                    if getattr(joint, key) is not None:
                        raise field_error(("joint", j, key),
                                          f"a key of the longitudinal model (got "
                                          f"{fmt(getattr(joint, key))}); across the axis the "
                                          "decks slide past each other at a joint: shear_key")
            if self.joint and len(self.joint) != len(self.frame) - 1:
                raise field_error("joint", f"give {len(self.frame) - 1} [[bridge.joint]] "
                                           f"table(s) for {len(self.frame)} frames, or none "
                                           f"(got {len(self.joint)})")
            return self
        if self.abutment_keys is not None:
            raise field_error("abutment_keys", 'shear keys hold the decks across the axis: '
                                               'direction = "transverse"')
        for j, joint in enumerate(self.joint):
            if joint.shear_key is not None:
                raise field_error(("joint", j, "shear_key"), 'shear keys hold the decks '
                                  'across the axis: direction = "transverse"')
            if joint.gap is None:
                raise field_error(("joint", j, "gap"), "required: the joint's gap [m]")
        if self.abutment_piles is not None and not any(
                g != "none" for g in (self.abutment_gaps or ["none", "none"])):
            raise field_error("abutment_piles", "piles stand under an abutment: give "
                                                "abutment_gaps")
        return self

    @model_validator(mode="after")
    def _joints(self) -> BridgeConfig:
        if not self.transverse and len(self.joint) != len(self.frame) - 1:
            raise field_error("joint", f"need {len(self.frame) - 1} [[bridge.joint]] table(s) "
                                       f"for {len(self.frame)} frames, one between each pair "
                                       f"(got {len(self.joint)})")
        tallest = max(p.height for f in self.frame for p in f.pier)
        if self.deck_elevation is not None and self.deck_elevation < tallest:
            raise field_error("deck_elevation", f"below the tallest pier's cap ({tallest:g} m; "
                                                f"got {fmt(self.deck_elevation)})")
        self._check_seats()
        return self

    def seat_widths(self) -> list[float | None]:
        """The width of every seat [m], ``A1``, ``J1`` …, ``A2`` (None: not checked)."""
        ends = self.abutment_seat_widths or ["none", "none"]
        return [None if ends[0] == "none" else float(ends[0]),
                *(j.seat_width for j in self.joint),
                None if ends[1] == "none" else float(ends[1])]

    def _check_seats(self) -> None:
        gaps = self.abutment_gaps or ["none", "none"]
        for side, (width, gap) in enumerate(zip(self.abutment_seat_widths or [], gaps)):
            if width != "none" and gap == "none":
                raise field_error(("abutment_seat_widths", side),
                                  f"a seat {fmt(width)} m wide at an end with no abutment "
                                  f"(abutment_gaps[{side}] is \"none\" or not given); give "
                                  "the abutment's gap, or \"none\" here")
        widths = self.seat_widths()
        clause = self.seat_clause
        if clause is None:
            return
        if all(w is None for w in widths):
            raise field_error("seat_clause", "no seat has a width to check against it: give "
                                             "joint[].seat_width or abutment_seat_widths")
        if clause.clause == "given":
            assert clause.required is not None
            if len(clause.required) != len(widths):
                raise field_error(("seat_clause", "required"),
                                  f"need {len(widths)} value(s), one per seat (left "
                                  f"abutment, {len(widths) - 2} joint(s), right abutment; "
                                  f"\"none\" where not checked), got {len(clause.required)}")
            for i, (w, need) in enumerate(zip(widths, clause.required)):
                if w is not None and need == "none":
                    raise field_error(("seat_clause", "required", i),
                                      f"the seat has a width ({w:g} m) but \"none\" here: "
                                      "give its required width [m]")

    def build(self, name: str = "bridge") -> Any:
        """The :class:`pounding.structure.bridge.Bridge` named ``name`` (across the axis: the
        :class:`~pounding.structure.bridge.TransverseBridge`)."""
        from pounding.structure.bridge import Abutment, Bridge, Restrainer, TransverseBridge

        z = self.deck_elevation or max(p.height for f in self.frame for p in f.pier)
        frames = []
        for j, f in enumerate(self.frame):
            with prefixed(f"frame[{j}]", BridgeFrameConfig.model_fields):
                frames.append(f.build(z, self.zeta, f"B{j + 1}"))
        if self.transverse:
            keys = None
            if self.abutment_keys is not None:
                with prefixed("abutment_keys", KeyConfig.model_fields):
                    keys = self.abutment_keys.build()
            joint_keys = []
            for j, joint in enumerate(self.joint):
                with prefixed(f"joint[{j}].shear_key", KeyConfig.model_fields):
                    joint_keys.append(None if joint.shear_key is None
                                      else joint.shear_key.build())
            return TransverseBridge(tuple(frames), (keys, keys), tuple(joint_keys), name=name)
        gaps = self.abutment_gaps or ["none", "none"]
        law = None
        if self.abutment_law is not None:
            with prefixed("abutment_law", LawConfig.model_fields):
                law = self.abutment_law.spec()
        piles = None
        if self.abutment_piles is not None:
            with prefixed("abutment_piles", PilesConfig.model_fields):
                piles = self.abutment_piles.spec()
        abutments = tuple(None if g == "none" else Abutment(float(g), law, piles)
                          for g in gaps)
        restrainers = [Restrainer(j, joint.restrainer.model_dump(exclude_none=True))
                       for j, joint in enumerate(self.joint) if joint.restrainer is not None]
        clause = None
        if self.seat_clause is not None:
            with prefixed("seat_clause", SeatClauseConfig.model_fields):
                clause = self.seat_clause.build()
        widths = self.seat_widths()
        return Bridge(tuple(frames), tuple(joint.gap for joint in self.joint),  # type: ignore[misc]
                      abutments=abutments,  # type: ignore[arg-type]
                      restrainers=tuple(restrainers), name=name,
                      seat_widths=tuple(widths) if any(w is not None for w in widths) else (),
                      seat_clause=clause)
