"""The pounding problem: buildings in a row, the gaps between them, and the contact law.

A :class:`PoundingModel` is pure data: it says *what* collides, not how to integrate it
(that is :mod:`pounding.integrate`) nor what shakes it (:mod:`pounding.ground_motion`).

Geometry. Buildings stand left to right along x, building ``b`` and ``b + 1`` separated by
``gaps[b]``. Displacements are positive to the right, so at a shared floor level the
penetration is ``δ = u_left − u_right − gap`` (seed case 2A for two buildings of equal
floor levels, 2C for a row). Where both buildings have a floor at the same elevation the
floors meet floor to floor; a floor of one building that lies between two floors of the
other strikes the other's column there (floor to column, :class:`ContactPoint`), unless
``floor_to_column=False``. Nothing collides above the lower roof (case 2B).

The contact law of a model file is a :class:`ContactSpec` (:mod:`pounding.contact.spec`); the
contact points and elements are in :mod:`pounding.contact.geometry`, and where two buildings
can touch (:func:`contact_points`) in :mod:`pounding.structure.assembly`; all are importable
from here too.

A building is a :class:`ShearBuilding` or a planar :class:`~pounding.structure.MatrixBuilding`
with lumped masses: each of its floor DOFs is a lateral translation along the row at its
elevation, and contacts are found from those elevations exactly as for the floors of a
shear building (:func:`pounding.structure.assembly.floor_dofs`). A building in plan
(:class:`~pounding.structure.plan.PlanBuilding`: rigid floors with ``u_x``, ``u_y``, ``θ``)
stands in the row as its :class:`~pounding.structure.plan_row.PlanMatrixBuilding`: its floors
meet a neighbour's at the ends of the stretch where their façades face each other, the
floors' rotations in the contacts' kinematics, and the model's influence matrix has two
columns, the ground's x and y components (run it under a
:class:`~pounding.ground_motion.GroundMotionComponents`).

A gap of ``math.inf`` says the two neighbours never meet: no contacts between them (the
decks of a bridge in its transverse direction slide past each other,
:mod:`pounding.structure.bridge.transverse`). *Stops* (:class:`pounding.structure.stops.Stop`)
are one-sided contacts the row does not make — a floor against the ground, or against a floor
of another building, engaged one given way (a deck's shear keys) — after the walls'.

Rigid moat walls (:class:`pounding.structure.wall.MoatWall`) may stand at the ends of the row;
the floors of the end building at or below a wall's top strike it, with the model's contact law
(or the wall's own: an abutment's backfill) and the wall's gap (contacts ``'B1F1-W'``, ``'W-B1F1'``, after the buildings' contacts).

For the kernel the model also lists its contacts and its nonlinear elements as plain arrays
(:mod:`pounding.model.kernel_rows`, :attr:`PoundingModel.element_rows`,
:meth:`PoundingModel.storey_arrays`): a shear
building's yielding storeys, all with the building's storey law, and the piers and
bearings of a bridge frame (:mod:`pounding.structure.bridge`), each with a law of its own;
their forces come from their laws, and the stiffness matrix handed to the kernel
(:meth:`PoundingModel.linear_stiffness`) holds only the linear elements.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from pounding.contact.dispatch import check_contact_law
from pounding.contact.geometry import Contact, ContactPoint
from pounding.contact.spec import CONTACT_LAWS, ContactSpec
from pounding.devices import Bumper, Link
from pounding.devices.bumper import split_contact
from pounding.memo import Memo
from pounding.model.kernel_rows import KernelRows
from pounding.structure import MatrixBuilding
from pounding.structure.assembly import (
    BUILDING_TYPES,
    AssembledSystem,
    Building,
    assemble,
    contact_points,
    face_below,
    face_dofs,
    face_point_name,
    floor_below,
    floor_dofs,
)
from pounding.structure.dof_names import dof_labels, dof_units
from pounding.structure.plan_row import PlanMatrixBuilding, plan_contact_points
from pounding.structure.stops import Stop, stop_contacts
from pounding.structure.wall import MoatWall, WallPoint, check_walls, wall_contacts
from pounding.validation import non_negative, positive

if TYPE_CHECKING:  # (a bridge's model is made by pounding.structure.bridge, which imports it)
    from pounding.structure.bridge import Bridge, TransverseBridge
    from pounding.structure.plan import PlanBuilding

__all__ = ["CONTACT_LAWS", "SYSTEMS", "Contact", "ContactPoint", "ContactSpec", "PoundingModel",
           "contact_points"]


SYSTEMS = Memo(max_items=64, max_bytes=256 << 20)
"""Assembled systems (:attr:`PoundingModel.system`), by the identity of the buildings."""


def _floor_counts(buildings: Sequence[Building]) -> str:
    """``"B1: 10 floors, B2: 8 floors"``."""
    return ", ".join(f"B{i + 1}: {b.n} floor{'s' if b.n != 1 else ''}"
                     for i, b in enumerate(buildings))


def _check_matrix_building(i: int, b: MatrixBuilding) -> None:
    """A matrix building the kernel can take: lumped masses, floors at distinct elevations
    above the ground (one line naming the building and the fault)."""
    who = f"buildings[{i}] ({b.name!r})" if b.name else f"buildings[{i}]"
    try:
        b.lumped_masses()
    except ValueError as exc:  # naming the largest off-diagonal entry of M
        raise ValueError(f"{who}: {exc}; the time stepper takes lumped masses") from None
    f = floor_dofs(b)
    z = b.elevations[f]
    if not z[0] > 0.0:
        raise ValueError(f"{who}: floor {b.labels[f[0]]!r} is at elevation {z[0]:g} m; "
                         "floors must stand above the ground (> 0)")
    same = np.flatnonzero(np.diff(z) <= 0.0)
    if same.size:
        k = int(same[0])
        raise ValueError(f"{who}: floors {b.labels[f[k]]!r} and {b.labels[f[k + 1]]!r} are both "
                         f"at elevation {z[k]:g} m; give each floor its own elevation (or list "
                         "only one of them in floors)")
    for side in b.faces:  # (one DOF an elevation: MatrixBuilding's own check)
        f = b.face_dofs(side)
        if not b.elevations[f[0]] > 0.0:
            raise ValueError(f"{who}: faces.{side}: {b.labels[f[0]]!r} is at elevation "
                             f"{b.elevations[f[0]]:g} m; the DOFs of a face stand above the "
                             "ground (> 0)")


def _with_plan_influence(system: AssembledSystem,
                         buildings: Sequence[Building]) -> AssembledSystem:
    """The system with the influence matrix R (N × 2) of two ground components, x and y,
    where a building is in plan (its own R; a planar building feels the x component
    through its ``r``, nothing of y); unchanged (r of shape (N,)) otherwise."""
    if not any(isinstance(b, PlanMatrixBuilding) for b in buildings):
        return system
    R = np.zeros((system.n_dof, 2))
    for off, b in zip(system.offsets, buildings):
        rows = slice(int(off), int(off) + b.n)
        if isinstance(b, PlanMatrixBuilding):
            R[rows] = b.influence_matrix()
        else:
            R[rows, 0] = b.influence_vector()
    return system._replace(r=R)


def _row_building(b: Any) -> Any:
    """A building in plan as it stands in the row: its matrix building; anything else as
    it is (a row of shear and matrix buildings does not load :mod:`pounding.structure.plan`).
    """
    from pounding.structure.plan import PlanBuilding

    return b.as_matrix_building() if isinstance(b, PlanBuilding) else b


def _read_only(system: AssembledSystem) -> AssembledSystem:
    """The system with its arrays made read-only (it is shared)."""
    for a in system:
        a.setflags(write=False)
    return system


@dataclass(frozen=True, init=False)
class PoundingModel(KernelRows):
    """Buildings in a row, the gaps between them, and the contact law.

    Parameters
    ----------
    buildings : sequence of ShearBuilding, MatrixBuilding or PlanBuilding
        From left to right (at least one; one building is a plain response analysis). A
        matrix building needs a diagonal (lumped) ``M`` and floors at distinct elevations
        above the ground.
    gaps : sequence of float
        Separation gap between each pair of neighbours [m], ``len(buildings) − 1`` values;
        ``math.inf``: the pair never meets (no contacts between them).
    contact : ContactSpec
        The contact law used at every contact.
    name : str
        A label for outputs.
    floor_to_column : bool
        Let a floor that does not line up with a floor of its neighbour strike the
        neighbour's column (default True); False keeps floor-to-floor contacts only.
    level_tolerance : float
        Floors whose elevations differ by at most this much [m] line up and meet slab to
        slab (default 0.1 m, about half a slab's thickness: closer slabs overlap).
    devices : sequence of Link or Bumper
        Dampers and springs linking floors of different buildings
        (:class:`pounding.devices.Link`) and bumpers in the gaps of contacts
        (:class:`pounding.devices.Bumper`); none by default.
    walls : sequence of MoatWall
        Rigid walls fixed to the ground at the ends of the row
        (:class:`pounding.structure.wall.MoatWall`, at most one a side); their contacts
        come after the buildings' (labels such as ``'B1F1-W'``). None by default.
    bridge : Bridge, optional
        The bridge the row was made of (:meth:`from_bridge` passes it; its frames are the
        buildings): kept for what is read after a run, its seats
        (:func:`pounding.result.bridge_seats.seat_checks`). None by default.
    stops : sequence of Stop
        One-sided contacts of a floor against the ground or another building's floor
        (:class:`pounding.structure.stops.Stop`: a bridge deck's shear keys), after the
        walls'. None by default.

    Examples
    --------
    >>> from pounding.structure import ShearBuilding
    >>> left = ShearBuilding.sdof(2e5, period=0.5)
    >>> right = ShearBuilding.sdof(3e5, period=1.0)
    >>> model = PoundingModel([left, right], gaps=[0.02],
    ...                       contact=ContactSpec("kelvin-voigt", k=9.3e8, e=0.65))
    >>> [c.label for c in model.contacts]
    ['B1F1-B2F1']
    """

    buildings: tuple[Building, ...]
    gaps: tuple[float, ...]
    contact: ContactSpec
    name: str
    floor_to_column: bool
    level_tolerance: float
    devices: tuple[Link | Bumper, ...]
    walls: tuple[MoatWall, ...]
    bridge: Bridge | None
    stops: tuple[Stop, ...]

    def __init__(self, buildings: Sequence[Building | PlanBuilding], gaps: Sequence[float],
                 contact: ContactSpec, name: str = "model", floor_to_column: bool = True,
                 level_tolerance: float = 0.1, devices: Sequence[Link | Bumper] = (),
                 walls: Sequence[MoatWall] = (), bridge: Bridge | None = None,
                 stops: Sequence[Stop] = ()) -> None:
        if len(buildings) < 1:
            raise ValueError("buildings: give at least one building")
        # a building in plan stands in the row as its matrix building (which keeps the plan)
        row = tuple(b if isinstance(b, BUILDING_TYPES) else _row_building(b)
                    for b in buildings)
        for i, b in enumerate(row):
            if not isinstance(b, BUILDING_TYPES):
                raise ValueError(f"buildings[{i}]: expected a ShearBuilding or a MatrixBuilding "
                                 f"(got {type(b).__name__})")
            if isinstance(b, MatrixBuilding):
                _check_matrix_building(i, b)
        if len(gaps) != len(row) - 1:
            raise ValueError(f"gaps: need {len(row) - 1} value(s) for "
                             f"{len(row)} buildings (got {len(gaps)})")
        frozen_set = object.__setattr__  # the attributes of a frozen dataclass
        frozen_set(self, "buildings", row)
        frozen_set(self, "contact", contact)
        frozen_set(self, "name", name)
        frozen_set(self, "floor_to_column", floor_to_column)
        frozen_set(self, "level_tolerance", positive("level_tolerance", level_tolerance))
        frozen_set(self, "gaps", tuple(math.inf if g == math.inf
                                       else non_negative(f"gaps[{i}]", g)
                                       for i, g in enumerate(gaps)))
        frozen_set(self, "devices", tuple(devices))
        frozen_set(self, "walls", tuple(walls))
        if self.walls:
            check_walls(self.walls, self.buildings, self.floor_to_column, self.level_tolerance)
        frozen_set(self, "stops", tuple(stops))
        stop_contacts(self.stops, self.buildings, 0)  # (a stop off the row: one line)
        if bridge is not None:
            from pounding.structure.bridge import Bridge
        if bridge is not None and not (isinstance(bridge, Bridge)
                                       and len(bridge.frames) == len(row)
                                       and all(f is b for f, b in zip(bridge.frames, row))):
            raise ValueError("bridge: the buildings must be the bridge's frames, in order "
                             "(PoundingModel.from_bridge)")
        frozen_set(self, "bridge", bridge)
        self._check_devices()
        self._check_law_codes()

    @classmethod
    def from_bridge(cls, bridge: Bridge | TransverseBridge, contact: ContactSpec,
                    level_tolerance: float = 0.1) -> PoundingModel:
        """The model of a bridge along its axis (:class:`pounding.structure.bridge.Bridge`):
        its frames as the row's buildings, its joints as the gaps, its abutments as walls at
        the ends and its restrainers as links, every contact deck to deck (or deck to
        abutment) with ``contact``; or across it
        (:class:`pounding.structure.bridge.TransverseBridge`): its frames as buildings that
        never meet, its shear keys as stops (``contact``: the model's law, which no contact
        uses but the stops' own laws are named in outputs)."""
        return cls(contact=contact, level_tolerance=level_tolerance,
                   **bridge.model_arguments())

    def _check_law_codes(self) -> None:
        """Every law the model's contacts, bumpers and storeys are built with is one the
        compiled kernel implements: a law class with a code of its own would otherwise be
        run as no law at all (NaN); one line naming the field, the law's class and code."""
        from pounding.hysteresis.dispatch import check_storey_law

        checks: list[tuple[str, Any, Any]] = [("contact", check_contact_law,
                                               lambda: self.contact.build(1.0, 1.0))]
        checks += [(f"devices[{i}].rubber", check_contact_law,
                    lambda dev=dev: dev.rubber.build(1.0, 1.0))
                   for i, dev in enumerate(self.devices) if isinstance(dev, Bumper)]
        checks += [(f"buildings[{i}].storey_law", check_storey_law, lambda b=b: b.storey_law)
                   for i, b in enumerate(self.buildings) if b.storey_law is not None]
        checks += [(f"buildings[{p}].{row.label}", check_storey_law, lambda row=row: row.law)
                   for p, row in self.element_rows
                   if getattr(self.buildings[p], "storey_law", None) is None]
        for where, check, law in checks:
            try:
                check(law())
            except ValueError as exc:
                raise ValueError(f"{where}: {exc}") from None

    def _check_devices(self) -> None:
        """Every device is a Link or a Bumper on floors that exist; a bumper sits in a
        floor-to-floor contact, at most one in each."""
        seen: set[frozenset[str]] = set()
        for i, dev in enumerate(self.devices):
            if isinstance(dev, Link):
                for label, (b, f) in zip(dev.floors, dev.ends):
                    if b >= len(self.buildings) or f >= self.buildings[b].n:
                        raise ValueError(f"devices[{i}].floors: no floor {label} in this "
                                         f"model ({_floor_counts(self.buildings)})")
                    if floor_below(self.buildings[b])[f] == -2:
                        raise ValueError(f"devices[{i}].floors: {label} is not a floor of "
                                         f"building B{b + 1} (DOF {f + 1} is not among its "
                                         "floors)")
            elif isinstance(dev, Bumper):
                ends = frozenset(dev.floors)
                if ends in seen:
                    raise ValueError(f"devices[{i}]: a second bumper in {dev.label}")
                seen.add(ends)
                bare = [c for c in self._bare_contacts + self._wall_contacts
                        if c.is_floor_to_floor]
                where = next((c for c in bare if dev.sits_in(c)), None)
                if where is None:
                    raise ValueError(f"devices[{i}].floors: {dev.label} is not a floor-to-floor "
                                     f"contact of this model (contacts"
                                     f"{', with the walls' if self.walls else ''}: "
                                     f"{', '.join(c.label for c in bare) or 'none'})")
                try:
                    dev.gaps(where.gap)
                except ValueError as exc:
                    raise ValueError(f"devices[{i}].{exc}") from exc
            else:
                raise ValueError(f"devices[{i}]: expected a Link or a Bumper (got "
                                 f"{type(dev).__name__})")

    @cached_property
    def system(self) -> AssembledSystem:
        """Block-diagonal M, C, K, influence vector and DOF offsets of all buildings
        (read-only).

        Assembled once for the same building objects (:data:`SYSTEMS`) and shared by every
        model of them: the cases of a sweep that change only gaps, contact law or record.
        """
        return SYSTEMS.get(tuple(map(id, self.buildings)), lambda: _read_only(
            _with_plan_influence(assemble(self.buildings), self.buildings)),
            size=lambda s: 8 * 3 * s.n_dof ** 2, keep=self.buildings)

    @cached_property
    def _bare_contacts(self) -> tuple[Contact, ...]:
        """The contacts of the buildings, without bumpers."""
        out: list[Contact] = []
        for p, (a, b) in enumerate(zip(self.buildings[:-1], self.buildings[1:])):
            if self.gaps[p] == math.inf:
                continue  # (neighbours that never meet)
            if isinstance(a, PlanMatrixBuilding) or isinstance(b, PlanMatrixBuilding):
                out.extend(self._plan_pair_contacts(p, a, b, len(out)))
                continue
            tol = self.level_tolerance
            below_a, below_b = face_below(a, "right"), face_below(b, "left")
            for z, i, xi_i, j, xi_j in contact_points(a, b, self.floor_to_column, tol):
                left = ContactPoint(p, i, xi_i, int(below_a[i]),
                                    name=face_point_name(p, a, "right", z, tol))
                right = ContactPoint(p + 1, j, xi_j, int(below_b[j]),
                                     name=face_point_name(p + 1, b, "left", z, tol))
                law = self.contact.build(left.effective_mass(a.masses),
                                         right.effective_mass(b.masses))
                out.append(Contact(len(out), p, left, right, z, float(self.gaps[p]), law))
        return tuple(out)

    def _plan_pair_contacts(self, p: int, a: Building, b: Building,
                            start: int) -> list[Contact]:
        """The contacts of pair ``p`` where a building is in plan: at the ends of the
        stretch where the façades face each other, with the floors' rotations in the
        kinematics (:func:`pounding.structure.plan_row.plan_contact_points`)."""
        out: list[Contact] = []
        for z, i, wi, j, wj, y in plan_contact_points(a, b, self.level_tolerance):
            points = []
            for k, (bl, dof, weights) in enumerate(((a, i, wi), (b, j, wj))):
                twist = next(((d, w) for d, w in weights if d != dof), None)
                # a floor in plan is named by its floor number (its u_x DOF is 3 (floor − 1))
                name = (f"B{p + k + 1}F{dof // 3 + 1}@y={y:g}"
                        if isinstance(bl, PlanMatrixBuilding) else "")
                points.append(ContactPoint(p + k, dof, 1.0, int(floor_below(bl)[dof]),
                                           twist=twist, name=name))
            left, right = points
            law = self.contact.build(left.effective_mass(a.masses),
                                     right.effective_mass(b.masses))
            out.append(Contact(start + len(out), p, left, right, z, float(self.gaps[p]), law))
        return out

    @cached_property
    def contacts(self) -> tuple[Contact, ...]:
        """Every contact, pair by pair, bottom to top (see :func:`contact_points`), then the
        contacts with the walls (:func:`pounding.structure.wall.wall_contacts`); where a
        bumper sits (between two floors, or on a wall), its pad (``…/bumper``) and then the
        contact moved to where the pad bottoms out
        (:func:`pounding.devices.bumper.split_contact`); then the stops'
        (:func:`pounding.structure.stops.stop_contacts`)."""
        bumpers = [d for d in self.devices if isinstance(d, Bumper)]
        out: list[Contact] = []
        for c in self._bare_contacts + self._wall_contacts:
            bumper = next((d for d in bumpers if c.is_floor_to_floor and d.sits_in(c)), None)
            if bumper is None:  # renumbered after a bumper's pad
                out.append(replace(c, index=len(out)) if c.index != len(out) else c)
                continue
            rubber = bumper.rubber.build(*(math.inf if isinstance(p, WallPoint) else
                                           p.effective_mass(self.buildings[p.building].masses)
                                           for p in (c.left, c.right)))
            out.extend(split_contact(c, bumper, rubber, len(out)))
        return tuple(out) + stop_contacts(self.stops, self.buildings, len(out))

    @cached_property
    def _wall_contacts(self) -> tuple[Contact, ...]:
        """The contacts of the walls, without bumpers, numbered after the buildings'
        (:func:`pounding.structure.wall.wall_contacts`)."""
        return wall_contacts(self.walls, self.buildings, self.contact, self.floor_to_column,
                             self.level_tolerance, len(self._bare_contacts))

    @property
    def links(self) -> tuple[Link, ...]:
        """The links between buildings, in the order given."""
        return tuple(d for d in self.devices if isinstance(d, Link))

    @cached_property
    def link_dofs(self) -> tuple[tuple[int, int], ...]:
        """The global DOFs of every link's two ends, left end first as given: each end at
        its floor — on a building struck on faces other than its floors (a frame without
        rigid floors, :attr:`MatrixBuilding.faces`), the DOF of its face toward the other
        end's building at that floor's level."""
        offsets = self.system.offsets
        out = []
        for link in self.links:
            (ba, fa), (bb, fb) = link.ends
            ends = []
            for b, f, other in ((ba, fa, bb), (bb, fb, ba)):
                building = self.buildings[b]
                side = "right" if other > b else "left"
                face = face_dofs(building, side)
                z = building.floor_levels
                at = face[np.abs(z[face] - z[f]) <= self.level_tolerance]
                ends.append(int(offsets[b]) + (int(at[0]) if at.size else f))
            out.append((ends[0], ends[1]))
        return tuple(out)

    @property
    def n_dof(self) -> int:
        """Total number of floors (degrees of freedom)."""
        return self.system.n_dof

    @property
    def is_inelastic(self) -> bool:
        """True if any building has yielding storeys."""
        return any(b.is_inelastic for b in self.buildings)

    @cached_property
    def yielding_frames(self) -> tuple[tuple[int, Any], ...]:
        """``(building index, building)`` of every frame with plastic hinges
        (:class:`~pounding.structure.frame_linear.FrameBuilding`), left to right: the
        buildings whose time history the kernel takes configuration by configuration of
        their hinges (:mod:`pounding.integrate.frame_run`)."""
        return tuple((b, bl) for b, bl in enumerate(self.buildings)
                     if getattr(bl, "has_hinges", False))

    def member_end_labels(self) -> list[str]:
        """``'B1E1i'``, ``'B1E1j'``, ``'B1E2i'``, … for both ends (i: its first node, j: its
        second) of every member of the yielding frames (building, the element's number in
        its frame, 1-based), in :attr:`yielding_frames` order."""
        return [f"B{b + 1}E{e + 1}{end}" for b, bl in self.yielding_frames
                for e in range(bl.frame.n_elements) for end in "ij"]

    def hinge_labels(self) -> list[str]:
        """``'B1H1'``, ``'B1H2'``, … for every hinge of the yielding frames (building, then
        the hinge's number in its frame, 1-based), in :attr:`yielding_frames` order."""
        return [f"B{b + 1}{lb}" for b, bl in self.yielding_frames for lb in bl.hinge_labels()]

    def linear_stiffness(self) -> NDArray[np.float64]:
        """Stiffness matrix [N/m] of the linear storeys only (yielding storeys left out: the
        kernel adds their shear from their laws). Assembled once per model; read-only."""
        return self._linear_stiffness

    @cached_property
    def _linear_stiffness(self) -> NDArray[np.float64]:
        blocks = [b.linear_stiffness_matrix() for b in self.buildings]
        k = np.ascontiguousarray(scipy.linalg.block_diag(*blocks))
        k.setflags(write=False)
        return k

    def dof_labels(self) -> list[str]:
        """``'B1F1'``, ``'B1F2'``, … for every degree of freedom
        (:func:`pounding.structure.dof_names.dof_labels`)."""
        return dof_labels(self.buildings)

    def dof_units(self) -> list[str]:
        """The unit of every degree of freedom's displacement, ``'m'``, ``'rad'`` or ``''``
        (:func:`pounding.structure.dof_names.dof_units`)."""
        return dof_units(self.buildings, self.is_floor)

    def dof_names(self) -> list[str]:
        """Every DOF's name in its building: a matrix building's labels, ``'F1'``, ``'F2'``,
        … for a shear building."""
        return [bl.labels[j] if isinstance(bl, MatrixBuilding) else f"F{j + 1}"
                for bl in self.buildings for j in range(bl.n)]

    def floor_below(self) -> NDArray[np.int64]:
        """The global DOF of the floor below every DOF (−1: the ground; −2: not a floor, no
        storey drift), so that the drift of storey j is ``u[j] − u[below[j]]``: consecutive
        floors ordered by elevation (:func:`pounding.structure.assembly.floor_below`)."""
        out = []
        for off, b in zip(self.system.offsets, self.buildings):
            below = floor_below(b)
            out.append(np.where(below >= 0, below + int(off), below))
        return np.concatenate(out).astype(np.int64)

    @cached_property
    def is_floor(self) -> NDArray[np.bool_]:
        """True for every DOF that is a floor (has a storey drift and may take contacts)."""
        return self.floor_below() > -2
