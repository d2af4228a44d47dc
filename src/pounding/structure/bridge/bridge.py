"""A bridge along its axis: frames in a row, expansion joints, abutments and restrainers.

The longitudinal model of a multi-frame bridge (DesRoches & Fenves 2000, "Design of seismic
cable hinge restrainers for bridges", J. Struct. Eng. 126(4):500–509; Caltrans SDC 2.0
§4.1.2's frames between expansion joints) maps onto the row of buildings of
:class:`pounding.model.PoundingModel`:

* each **frame** (:class:`~pounding.structure.bridge.frame.BridgeFrame`) is a building of the
  row, left to right along the axis; its deck is what its neighbours strike;
* each **expansion joint** is the gap between two neighbouring decks (the row's ``gaps``):
  deck-to-deck contacts with the model's contact law (floor to floor only, the decks at one
  elevation);
* each **abutment** is a rigid wall at an end of the row
  (:class:`~pounding.structure.wall.MoatWall`, its top at the deck's elevation) with the gap
  between the end deck and its backwall, struck with the model's contact law, or with the
  backfill's own passive resistance (:attr:`Abutment.law`: the ``abutment`` contact law,
  Caltrans SDC's elastic–perfectly-plastic backbone or a hyperbolic one,
  :mod:`pounding.contact.abutment`), and its piles in parallel behind the same gap
  (:attr:`Abutment.piles`, :func:`abutment_piles`);
* each **restrainer** is a link between the decks on either side of a joint
  (:class:`~pounding.devices.Link`: the cable restrainer, kind ``restrainer`` — tension only,
  slack, yielding — or a ``kelvin``, ``viscous`` or ``maxwell`` device; :class:`Restrainer`
  passes its keywords to :class:`~pounding.devices.Link` unchanged);
* each frame stands on its own ground: under a
  :class:`~pounding.ground_motion.spatial.SpatialMotion` with one record per building, each
  frame feels its own (the abutments move with the ground of the row's reference);
* each **seat** (abutment ``A1``, joint ``J1`` …, abutment ``A2``) may have a width, checked
  after a run against its peak opening and against a clause's minimum
  (:attr:`Bridge.seat_widths`, :attr:`Bridge.seat_clause`, :meth:`Bridge.seats`,
  :mod:`pounding.structure.bridge.seats`).

A :class:`Bridge` holds these and gives the model's arguments
(:meth:`Bridge.model_arguments`; :meth:`pounding.model.PoundingModel.from_bridge` builds the
model: the structure layer does not import the model).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from pounding.devices.link import Link
from pounding.structure.bridge.frame import BridgeFrame
from pounding.structure.bridge.seats import Seat, seat_names, seats_of
from pounding.contact.spec import ContactSpec
from pounding.structure.seat_width import AashtoLrfdSeatClause, GivenSeatWidths, SeatClause
from pounding.structure.wall import MoatWall
from pounding.validation import non_negative, positive

__all__ = ["CALTRANS_PILE_STIFFNESS", "Abutment", "Bridge", "Restrainer", "abutment_piles"]


@dataclass(frozen=True)
class Abutment:
    """An abutment at one end of the bridge: a backwall the end deck strikes.

    Parameters
    ----------
    gap : float
        Gap between the end deck and the backwall at rest [m].
    law : ContactSpec, optional
        The backfill's own force–deformation law (``ContactSpec("abutment", ...)``: the
        Caltrans SDC or hyperbolic backbone, :mod:`pounding.contact.abutment`); None: the
        backwall is a rigid wall struck with the model's contact law.
    piles : ContactSpec, optional
        The abutment's piles, in parallel with the backfill behind the same gap
        (:func:`abutment_piles`: a linear spring of the pile group's stiffness, or
        elastic–perfectly-plastic); their force is the contact ``…/piles``. None: none.
    """

    gap: float
    law: ContactSpec | None = None
    piles: ContactSpec | None = None

    def __post_init__(self) -> None:
        non_negative("gap", self.gap)
        for key in ("law", "piles"):
            value = getattr(self, key)
            if value is not None and not isinstance(value, ContactSpec):
                raise ValueError(f"{key}: expected a ContactSpec or None (got "
                                 f"{type(value).__name__})")

    def wall(self, height: float, side: str, name: str) -> MoatWall:
        """The wall of this abutment, its top at ``height`` [m] (the deck's), struck with
        its own law where it has one, its piles behind the same gap."""
        return MoatWall(height=height, gap=self.gap, side=side, name=name, contact=self.law,
                        piles=self.piles)


CALTRANS_PILE_STIFFNESS: float = 40.0 * 4448.2216152605 / 0.0254
"""Stiffness of one abutment pile, 40 kip/in in SI [N/m]: 7.0051e6 (7.0 kN/mm). The value
Caltrans gives for a standard abutment pile, as used in the OpenSees bridge models of the
Nielson (2005) tradition (BridgePM's ``materials.tcl``: "7kN/mm ... per pile"); the Caltrans
text itself was not read here."""


def abutment_piles(count: int, stiffness: float = CALTRANS_PILE_STIFFNESS,
                   yield_force: float | None = None) -> ContactSpec:
    """The law of ``count`` piles under an abutment acting together: a linear spring of
    ``count × stiffness`` [N/m] (default :data:`CALTRANS_PILE_STIFFNESS` a pile), or, with
    a ``yield_force`` [N] a pile, elastic–perfectly-plastic at ``count × yield_force``
    (the shear-key law without fracture: unloading at the stiffness, its set kept).

    >>> abutment_piles(3).describe()
    'linear-spring: k = 2.10152e+07 N/m'
    """
    if not (isinstance(count, int) and count >= 1):
        raise ValueError(f"count: need a whole number of piles >= 1 (got {count!r})")
    k = count * positive("stiffness", stiffness)
    if yield_force is None:
        return ContactSpec("linear-spring", k=k)
    return ContactSpec("shear-key", k=k, capacity=count * positive("yield_force", yield_force))


@dataclass(frozen=True)
class Restrainer:
    """Restrainers across joint ``joint`` (0-based: between frames ``joint`` and
    ``joint + 1``), lumped into one link between the two decks.

    Parameters
    ----------
    joint : int
        The joint (0-based).
    link : mapping
        Keywords of :class:`pounding.devices.Link` but ``floors``: ``kind`` and its
        constants (``kind="restrainer", k=…, slack=…, yield_force=…, hardening=…`` for cables;
        ``kind="kelvin", k=…, c=…`` …).
    """

    joint: int
    link: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not (isinstance(self.joint, int) and self.joint >= 0):
            raise ValueError(f"joint: need a joint index ≥ 0 (got {self.joint!r})")
        object.__setattr__(self, "link", MappingProxyType(dict(self.link)))

    def __reduce__(self) -> tuple[type, tuple[int, dict[str, Any]]]:
        # a mapping proxy cannot be pickled (copy, multiprocessing): it travels as a dict
        return (Restrainer, (self.joint, dict(self.link)))

    def build(self, name: str = "") -> Link:
        """The link between deck ``joint`` (``B<joint+1>F1``) and the next."""
        left, right = f"B{self.joint + 1}F1", f"B{self.joint + 2}F1"
        kw = dict(self.link)
        kw.setdefault("name", name or f"R{self.joint + 1}")
        return Link((left, right), **kw)


@dataclass(frozen=True)
class Bridge:
    """Frames in a row along the bridge's axis, the joints between them, the abutments at
    its ends and the restrainers across the joints (module docstring).

    Parameters
    ----------
    frames : sequence of BridgeFrame
        Left to right (at least one), every deck at one elevation.
    joint_gaps : sequence of float
        Gap of every expansion joint [m], ``len(frames) − 1`` values.
    abutments : (Abutment or None, Abutment or None)
        Left and right abutment (None: no abutment on that side, a free end).
    restrainers : sequence of Restrainer
        Restrainers across the joints (none by default).
    name : str
        A label.
    seat_widths : sequence of float or None
        The seat width of every seat [m], > 0: the left abutment, each joint left to right,
        the right abutment (``len(frames) + 1`` values; None: a seat not checked); empty
        (the default): no seat is checked. A seat at an end needs an abutment there.
    seat_clause : AashtoLrfdSeatClause or GivenSeatWidths, optional
        The clause whose minimum widths the seats are checked against
        (:mod:`pounding.structure.seat_width`); None: the margins alone. Needs seat widths;
        AASHTO LRFD's needs the spans of every frame under a checked seat.
    """

    frames: tuple[BridgeFrame, ...]
    joint_gaps: tuple[float, ...]
    abutments: tuple[Abutment | None, Abutment | None] = (None, None)
    restrainers: tuple[Restrainer, ...] = ()
    name: str = "bridge"
    seat_widths: tuple[float | None, ...] = ()
    seat_clause: SeatClause | None = None

    def __post_init__(self) -> None:
        frames = tuple(self.frames)
        if not frames:
            raise ValueError("frames: give at least one BridgeFrame")
        for i, f in enumerate(frames):
            if not isinstance(f, BridgeFrame):
                raise ValueError(f"frames[{i}]: expected a BridgeFrame (got "
                                 f"{type(f).__name__})")
        z0 = self.deck_elevation_of(frames[0])
        for i, f in enumerate(frames[1:], start=1):
            z = self.deck_elevation_of(f)
            if abs(z - z0) > 1e-9 * max(1.0, z0):
                raise ValueError(f"frames[{i}]: deck at {z:g} m, frames[0]'s at {z0:g} m; the "
                                 "decks meet at the joints at one level: give every frame "
                                 "the same deck_elevation")
        gaps = tuple(self.joint_gaps)
        if len(gaps) != len(frames) - 1:
            raise ValueError(f"joint_gaps: need {len(frames) - 1} value(s) for {len(frames)} "
                             f"frames (got {len(gaps)})")
        gaps = tuple(non_negative(f"joint_gaps[{i}]", g) for i, g in enumerate(gaps))
        ab = tuple(self.abutments)
        if len(ab) != 2 or not all(a is None or isinstance(a, Abutment) for a in ab):
            raise ValueError("abutments: give (left, right), each an Abutment or None")
        rs = tuple(self.restrainers)
        for i, r in enumerate(rs):
            if not isinstance(r, Restrainer):
                raise ValueError(f"restrainers[{i}]: expected a Restrainer")
            if r.joint >= len(gaps):
                raise ValueError(f"restrainers[{i}].joint: no joint {r.joint} ({len(gaps)} "
                                 f"joint(s), numbered from 0)")
        object.__setattr__(self, "frames", frames)
        object.__setattr__(self, "joint_gaps", gaps)
        object.__setattr__(self, "abutments", ab)
        object.__setattr__(self, "restrainers", rs)
        object.__setattr__(self, "seat_widths", self._checked_seat_widths())
        self._check_seat_clause()

    def _checked_seat_widths(self) -> tuple[float | None, ...]:
        widths = tuple(self.seat_widths)
        if not widths:
            return ()
        names = seat_names(len(self.frames))
        if len(widths) != len(names):
            raise ValueError(f"seat_widths: need {len(names)} value(s), one per seat "
                             f"({', '.join(names)}; None where not checked), got {len(widths)}")
        out = tuple(None if w is None else positive(f"seat_widths[{i}]", w)
                    for i, w in enumerate(widths))
        for i, side in ((0, 0), (len(names) - 1, 1)):
            if out[i] is not None and self.abutments[side] is None:
                raise ValueError(f"seat_widths[{i}]: seat {names[i]} is at an end with no "
                                 f"abutment (abutments[{side}] is None); give the abutment "
                                 "(a large gap if its backwall is never reached) or no width")
        return out

    def _check_seat_clause(self) -> None:
        clause = self.seat_clause
        if clause is None:
            return
        if not isinstance(clause, AashtoLrfdSeatClause | GivenSeatWidths):
            raise ValueError(f"seat_clause: expected an AashtoLrfdSeatClause or "
                             f"GivenSeatWidths (got {type(clause).__name__})")
        if not any(w is not None for w in self.seat_widths):
            raise ValueError("seat_clause: no seat has a width to check against it "
                             "(seat_widths)")
        names = seat_names(len(self.frames))
        if isinstance(clause, GivenSeatWidths):
            if len(clause.required) != len(names):
                raise ValueError(f"seat_clause.required: need {len(names)} value(s), one per "
                                 f"seat ({', '.join(names)}), got {len(clause.required)}")
            for i, (w, need) in enumerate(zip(self.seat_widths, clause.required)):
                if w is not None and need is None:
                    raise ValueError(f"seat_clause.required[{i}]: seat {names[i]} has a width "
                                     "but no required width")
        self.seats()  # (a frame without spans under an AASHTO-checked seat)

    @staticmethod
    def deck_elevation_of(frame: BridgeFrame) -> float:
        """The elevation of a frame's deck [m]."""
        return float(frame.elevations[frame.deck_dof])

    @property
    def deck_elevation(self) -> float:
        """The decks' elevation [m]."""
        return self.deck_elevation_of(self.frames[0])

    def walls(self) -> list[MoatWall]:
        """The abutments' walls: ``A1`` left of the first frame, ``A2`` right of the last."""
        out = []
        for abut, side, name in zip(self.abutments, ("left", "right"), ("A1", "A2")):
            if abut is not None:
                out.append(abut.wall(self.deck_elevation, side, name))
        return out

    def links(self) -> list[Link]:
        """The restrainers as links (``R1`` across joint 1, …; a second one across the same
        joint ``R1b``)."""
        seen: dict[int, int] = {}
        out = []
        for r in self.restrainers:
            k = seen.get(r.joint, 0)
            seen[r.joint] = k + 1
            name = f"R{r.joint + 1}" + ("" if k == 0 else chr(ord("a") + k))
            out.append(r.build(name))
        return out

    def seats(self) -> list[Seat]:
        """Every seat with a width, its requirement under :attr:`seat_clause` and the L and
        H it was evaluated with (:func:`pounding.structure.bridge.seats.seats_of`); empty
        without seat widths."""
        if not self.seat_widths:
            return []
        return seats_of(self.frames, self.seat_widths, self.seat_clause)

    def model_arguments(self) -> dict[str, Any]:
        """The keyword arguments of :class:`pounding.model.PoundingModel` but the contact:
        the frames as buildings, the joints as gaps, the abutments as walls, the
        restrainers as devices, contacts floor to floor (deck to deck) only, and the
        bridge itself (the model keeps it: its seats are read after a run)."""
        return {"buildings": list(self.frames), "gaps": list(self.joint_gaps),
                "walls": self.walls(), "devices": self.links(), "name": self.name,
                "floor_to_column": False, "bridge": self}

    def describe(self) -> str:
        """One line: frames, joints, abutments, restrainers."""
        ab = ", ".join(f"{side} gap {a.gap * 1e3:g} mm" for a, side in
                       zip(self.abutments, ("left", "right")) if a is not None) or "none"
        return (f"{len(self.frames)} frame(s), joints "
                f"{[round(g * 1e3, 3) for g in self.joint_gaps]} mm, abutments: {ab}, "
                f"{len(self.restrainers)} restrainer(s)")
