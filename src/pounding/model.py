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

For the kernel the model also lists its yielding storeys (:meth:`PoundingModel.storey_arrays`):
their shear comes from their storey law, and the stiffness matrix handed to the kernel
(:meth:`PoundingModel.linear_stiffness`) holds only the linear storeys.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from pounding.contact.base import ContactLaw
from pounding.contact.dispatch import PARAMS_SIZE
from pounding.contact.factory import make_law
from pounding.devices import Bumper, Link
from pounding.hysteresis.base import PARAMS_SIZE as STOREY_PARAMS_SIZE
from pounding.memo import Memo
from pounding.structure import ShearBuilding
from pounding.structure.assembly import AssembledSystem, assemble, shared_levels
from pounding.validation import non_negative, positive


@dataclass(frozen=True)
class ContactSpec:
    """How to build the contact law of every floor-to-floor contact.

    Fields are those of :func:`pounding.contact.factory.make_law`; the masses ``m1, m2``
    of each contact are the two floor masses that meet, so laws whose damping scales with
    the colliding masses (Kelvin–Voigt from ``e``, Jankowski's eq 18) are built per contact.

    Parameters
    ----------
    law : str
        A name of :data:`pounding.contact.factory.LAW_NAMES`.
    k, k_h : float, optional
        Linear stiffness [N/m] or Hertz stiffness [N/m^n].
    e : float, optional
        Coefficient of restitution (turned into damping by ``formula``).
    formula : str, optional
        Damping formula (default: the law's own).
    c, zeta, chi : float, optional
        Damping given directly.
    n : float
        Hertz exponent.
    tension : bool
        Kelvin–Voigt only: may the dashpot pull before separation (default no: the force is
        clipped at zero, the physical choice; ``True`` as OpenSees' ``ViscoelasticGap``).
    delta_m : float, optional
        Bilinear element: assumed maximum penetration [m].
    a : float
        Bilinear element: yield ratio δy/δm (Muthukumar's 0.1).
    """

    law: str
    k: float | None = None
    k_h: float | None = None
    e: float | None = None
    formula: str | None = None
    c: float | None = None
    zeta: float | None = None
    chi: float | None = None
    n: float = 1.5
    tension: bool = False
    delta_m: float | None = None
    a: float = 0.1

    def __post_init__(self) -> None:
        # build once with unit masses so a bad spec fails here, naming its field
        self.build(1.0, 1.0)

    def describe(self) -> str:
        """One line for outputs: the law, the fields given (with units), the damping formula
        ``e`` goes through, and for Kelvin–Voigt whether the dashpot may pull."""
        from pounding.contact.factory import default_formula

        units = {"k": " N/m", "k_h": f" N/m^{self.n:g}", "c": " N·s/m", "delta_m": " m"}
        formula = self.formula or default_formula(self.law, self.tension)
        parts = []
        for name in ("k", "k_h", "e", "c", "zeta", "chi", "delta_m"):
            value = getattr(self, name)
            if value is not None:
                via = f" via {formula}" if name == "e" and formula else ""
                parts.append(f"{name} = {value:g}{units.get(name, '')}{via}")
        if self.law == "kelvin-voigt":
            parts.append("tension (pulls until δ = 0)" if self.tension
                         else "no tension (clipped at zero)")
        return f"{self.law}: {', '.join(parts)}" if parts else self.law

    def build(self, m1: float, m2: float) -> ContactLaw:
        """The contact law between two floors of masses ``m1`` and ``m2`` [kg].

        Remembered (:data:`CONTACT_LAWS`, keyed by the spec's and the masses' exact
        values): the cases of a sweep that share a law build it once. (A law is immutable.)
        """
        return CONTACT_LAWS.get((repr(self), repr(m1), repr(m2)), lambda: make_law(
            self.law, k=self.k, k_h=self.k_h, e=self.e, formula=self.formula, c=self.c,
            zeta=self.zeta, chi=self.chi, m1=m1, m2=m2, n=self.n, tension=self.tension,
            delta_m=self.delta_m, a=self.a))


CONTACT_LAWS = Memo(max_items=256)
"""Contact laws made by :meth:`ContactSpec.build`."""

SYSTEMS = Memo(max_items=64, max_bytes=256 << 20)
"""Assembled systems (:attr:`PoundingModel.system`), by the identity of the buildings."""


@dataclass(frozen=True)
class ContactPoint:
    """Where a contact element meets one building: a floor slab, or a column between floors.

    The contact point moves with ``(1 − ξ) u_lower + ξ u_upper`` (linear interpolation
    between the two floors of the struck storey, ``u = 0`` for the ground), and the contact
    force ``F`` is shared back to those floors as ``(1 − ξ) F`` and ``ξ F``: the same
    weights, so the work the force does on the building equals ``F`` times the point's
    displacement (energy-consistent, virtual work) and the shares sum to ``F`` (equal and
    opposite to the force on the other building). A floor contact is ``ξ = 1`` at its floor.

    Attributes
    ----------
    building : int
        0-based building index.
    upper : int
        0-based index of the floor struck (a floor contact) or of the floor above the struck
        storey (a column contact).
    xi : float
        Position of the point in storey ``upper + 1``: 0 at the floor below, 1 at floor
        ``upper``. Exactly 1 for a floor contact.
    """

    building: int
    upper: int
    xi: float = 1.0

    @property
    def is_floor(self) -> bool:
        """True for a slab (floor) contact point, False for a point on a column."""
        return self.xi == 1.0

    @property
    def lower(self) -> int:
        """0-based index of the floor below the struck storey (−1: the ground)."""
        return self.upper - 1

    @property
    def storey(self) -> int:
        """1-based number of the storey the point lies in (or below, for a floor)."""
        return self.upper + 1

    def floor_weights(self) -> list[tuple[int, float]]:
        """``(floor index, weight)`` pairs that make the point's displacement (ground
        omitted); weights of a column point are ``1 − ξ`` and ``ξ``."""
        if self.is_floor:
            return [(self.upper, 1.0)]
        out = [(self.upper, self.xi)]
        if self.lower >= 0:
            out.insert(0, (self.lower, 1.0 - self.xi))
        return out

    def of(self, floors: NDArray[np.float64]) -> NDArray[np.float64]:
        """The point's value from per-floor values of its building, ``floors[..., floor]``."""
        return sum(w * floors[..., i] for i, w in self.floor_weights())

    def effective_mass(self, masses: NDArray[np.float64]) -> float:
        """Apparent mass at the point [kg]: ``1 / Σ w_i² / m_i`` (the mass a short impulse
        at the point meets, the floors being the only masses); the floor mass for a slab."""
        return 1.0 / sum(w * w / float(masses[i]) for i, w in self.floor_weights())

    def label(self) -> str:
        """``'B2F3'`` for a floor, ``'B2S3@0.40'`` for storey 3's column at 40 % of its
        height (1-based building, floor and storey numbers)."""
        if self.is_floor:
            return f"B{self.building + 1}F{self.upper + 1}"
        return f"B{self.building + 1}S{self.storey}@{self.xi:.2f}"


@dataclass(frozen=True)
class Contact:
    """One contact element between two neighbouring buildings.

    Floor to floor where both have a floor at the same elevation (seed case 2A); floor to
    column where a slab of one lies between two floors of the other (case 2B with floors
    that do not line up): the slab strikes the other building's column.

    Attributes
    ----------
    index : int
        Position in :attr:`PoundingModel.contacts`.
    pair : int
        Which gap: between building ``pair`` and ``pair + 1``.
    left, right : ContactPoint
        Where the element meets the left and the right building.
    elevation : float
        Height of the contact above ground [m].
    gap : float
        Separation gap at rest [m].
    law : ContactLaw
        The contact law, built with the apparent masses of the two contact points.
    tag : str
        ``""`` for the contact of the buildings; ``"bumper"`` for the pad of a bumper in its
        gap (:class:`pounding.devices.Bumper`), whose label ends in ``/bumper``.
    """

    index: int
    pair: int
    left: ContactPoint
    right: ContactPoint
    elevation: float
    gap: float
    law: ContactLaw
    tag: str = ""

    @property
    def is_floor_to_floor(self) -> bool:
        """True if both points are floor slabs."""
        return self.left.is_floor and self.right.is_floor

    @property
    def struck(self) -> ContactPoint | None:
        """The column point of a floor-to-column contact (None for floor to floor)."""
        if self.is_floor_to_floor:
            return None
        return self.right if self.left.is_floor else self.left

    @property
    def left_floor(self) -> int:
        """0-based floor index of the left point (the floor above, for a column point)."""
        return self.left.upper

    @property
    def right_floor(self) -> int:
        """0-based floor index of the right point (the floor above, for a column point)."""
        return self.right.upper

    @property
    def label(self) -> str:
        """Readable name, e.g. ``'B1F3-B2F3'``, ``'B1F2-B2S3@0.40'`` or, for a bumper's
        pad, ``'B1F3-B2F3/bumper'``."""
        base = f"{self.left.label()}-{self.right.label()}"
        return f"{base}/{self.tag}" if self.tag else base


def contact_points(a: ShearBuilding, b: ShearBuilding, floor_to_column: bool = True,
                   tol: float = 1e-6) -> list[tuple[float, int, float, int, float]]:
    """Where two neighbouring buildings can touch: ``(elevation, i, ξ_i, j, ξ_j)`` rows.

    Floors at the same elevation (within ``tol`` [m]) meet floor to floor (``ξ = 1`` both).
    With ``floor_to_column``, every other floor of one building below the roof of the other
    meets the other's column at the same elevation, in storey ``j + 1`` at position ``ξ_j``
    (0 at floor ``j − 1`` or the ground, 1 at floor ``j``). Rows are sorted by elevation.
    """
    za, zb = a.floor_levels, b.floor_levels
    rows: list[tuple[float, int, float, int, float]] = []
    paired_a: set[int] = set()
    paired_b: set[int] = set()
    for i, j in shared_levels(a, b, tol):
        rows.append((float(za[i]), i, 1.0, j, 1.0))
        paired_a.add(i)
        paired_b.add(j)
    if floor_to_column:
        for levels, other, paired, left in ((za, zb, paired_a, True), (zb, za, paired_b, False)):
            for i, z in enumerate(levels):
                if i in paired or z >= other[-1] - tol:
                    continue  # paired already, or level with / above the other's roof
                j = int(np.searchsorted(other, z))  # storey j + 1: other[j-1] < z < other[j]
                below = float(other[j - 1]) if j > 0 else 0.0
                xi = (float(z) - below) / (float(other[j]) - below)
                rows.append((float(z), i, 1.0, j, xi) if left else (float(z), j, xi, i, 1.0))
    rows.sort(key=lambda r: (r[0], r[1], r[3]))
    return rows


def _floor_counts(buildings: Sequence[ShearBuilding]) -> str:
    """``"B1: 10 floors, B2: 8 floors"``."""
    return ", ".join(f"B{i + 1}: {b.n} floor{'s' if b.n != 1 else ''}"
                     for i, b in enumerate(buildings))


def _read_only(system: AssembledSystem) -> AssembledSystem:
    """The system with its arrays made read-only (it is shared)."""
    for a in system:
        a.setflags(write=False)
    return system


@dataclass(frozen=True)
class PoundingModel:
    """Buildings in a row, the gaps between them, and the contact law.

    Parameters
    ----------
    buildings : sequence of ShearBuilding
        From left to right (at least one; one building is a plain response analysis).
    gaps : sequence of float
        Separation gap between each pair of neighbours [m], ``len(buildings) − 1`` values.
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

    buildings: Sequence[ShearBuilding]
    gaps: Sequence[float]
    contact: ContactSpec
    name: str = "model"
    floor_to_column: bool = True
    level_tolerance: float = 0.1
    devices: Sequence[Link | Bumper] = ()

    def __post_init__(self) -> None:
        if len(self.buildings) < 1:
            raise ValueError("buildings: give at least one building")
        for i, b in enumerate(self.buildings):
            if not isinstance(b, ShearBuilding):
                raise ValueError(f"buildings[{i}]: expected a ShearBuilding (got {type(b).__name__})")
        if len(self.gaps) != len(self.buildings) - 1:
            raise ValueError(f"gaps: need {len(self.buildings) - 1} value(s) for "
                             f"{len(self.buildings)} buildings (got {len(self.gaps)})")
        object.__setattr__(self, "level_tolerance", positive("level_tolerance",
                                                             self.level_tolerance))
        object.__setattr__(self, "buildings", tuple(self.buildings))
        object.__setattr__(self, "gaps", tuple(non_negative(f"gaps[{i}]", g)
                                               for i, g in enumerate(self.gaps)))
        object.__setattr__(self, "devices", tuple(self.devices))
        self._check_devices()

    def _check_devices(self) -> None:
        """Every device is a Link or a Bumper on floors that exist; a bumper sits in a
        floor-to-floor contact, at most one in each."""
        seen: set[str] = set()
        for i, dev in enumerate(self.devices):
            if isinstance(dev, Link):
                for label, (b, f) in zip(dev.floors, dev.ends):
                    if b >= len(self.buildings) or f >= self.buildings[b].n:
                        raise ValueError(f"devices[{i}].floors: no floor {label} in this "
                                         f"model ({_floor_counts(self.buildings)})")
            elif isinstance(dev, Bumper):
                if dev.label in seen:
                    raise ValueError(f"devices[{i}]: a second bumper in {dev.label}")
                seen.add(dev.label)
                bare = {c.label: c for c in self._bare_contacts}
                if dev.label not in bare:
                    raise ValueError(f"devices[{i}].floors: {dev.label} is not a floor-to-floor "
                                     f"contact of this model (contacts: "
                                     f"{', '.join(bare) or 'none'})")
                try:
                    dev.gaps(bare[dev.label].gap)
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
        return SYSTEMS.get(tuple(map(id, self.buildings)), lambda: _read_only(assemble(
            self.buildings)), size=lambda s: 8 * 3 * s.n_dof ** 2, keep=self.buildings)

    @cached_property
    def _bare_contacts(self) -> tuple[Contact, ...]:
        """The contacts of the buildings, without bumpers."""
        out: list[Contact] = []
        for p, (a, b) in enumerate(zip(self.buildings[:-1], self.buildings[1:])):
            for z, i, xi_i, j, xi_j in contact_points(a, b, self.floor_to_column,
                                                      self.level_tolerance):
                left, right = ContactPoint(p, i, xi_i), ContactPoint(p + 1, j, xi_j)
                law = self.contact.build(left.effective_mass(a.masses),
                                         right.effective_mass(b.masses))
                out.append(Contact(len(out), p, left, right, z, float(self.gaps[p]), law))
        return tuple(out)

    @cached_property
    def contacts(self) -> tuple[Contact, ...]:
        """Every contact, pair by pair, bottom to top (see :func:`contact_points`); where a
        bumper sits, its pad (``…/bumper``) and then the building contact moved to where the
        pad bottoms out (:func:`pounding.devices.bumper.split_contact`)."""
        bumpers = {d.label: d for d in self.devices if isinstance(d, Bumper)}
        if not bumpers:
            return self._bare_contacts
        from pounding.devices.bumper import split_contact

        out: list[Contact] = []
        for c in self._bare_contacts:
            bumper = bumpers.get(c.label)
            if bumper is None:
                out.append(replace(c, index=len(out)))
                continue
            a, b = self.buildings[c.left.building], self.buildings[c.right.building]
            rubber = bumper.rubber.build(c.left.effective_mass(a.masses),
                                         c.right.effective_mass(b.masses))
            out.extend(split_contact(c, bumper, rubber, len(out)))
        return tuple(out)

    @property
    def links(self) -> tuple[Link, ...]:
        """The links between buildings, in the order given."""
        return tuple(d for d in self.devices if isinstance(d, Link))

    @property
    def n_dof(self) -> int:
        """Total number of floors (degrees of freedom)."""
        return self.system.n_dof

    @property
    def is_inelastic(self) -> bool:
        """True if any building has yielding storeys."""
        return any(b.is_inelastic for b in self.buildings)

    def contact_kinematics(self) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
        """Global DOFs and signed weights of every contact, each shape ``(n_c, 4)``.

        ``δ = Σ_q w[c, q] u[dof[c, q]] − gap``: weights of the left point positive, of the
        right point negative; unused slots carry weight 0 (on a valid DOF). The force ``F`` of
        contact c acts on DOF ``dof[c, q]`` as ``−w[c, q] F``.
        """
        cs = self.contacts
        dof = np.zeros((len(cs), 4), dtype=np.int64)
        w = np.zeros((len(cs), 4))
        offsets = self.system.offsets
        for c in cs:
            for side, point, sign in ((0, c.left, 1.0), (2, c.right, -1.0)):
                fw = point.floor_weights()
                base = int(offsets[point.building])
                for q in range(2):
                    i, wt = fw[q] if q < len(fw) else (fw[0][0], 0.0)
                    dof[c.index, side + q] = base + i
                    w[c.index, side + q] = sign * wt
        return dof, w

    def contact_penetration(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """Penetration ``δ`` [m] of every contact from floor displacements ``u[..., N]``."""
        dof, w = self.contact_kinematics()
        gap = np.array([c.gap for c in self.contacts])
        return np.einsum("...cq,cq->...c", u[..., dof], w) - gap

    def contact_arrays(self) -> tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.float64],
                                      NDArray[np.int64], NDArray[np.float64]]:
        """The contacts as plain arrays for the compiled kernel.

        Returns
        -------
        dof, weight : int64 / float64 (n_c, 4)
            :meth:`contact_kinematics`.
        gap : float64 (n_c,) [m]
        code : int64 (n_c,) law codes
        params : float64 (n_c, p) law constants, zero-padded
        """
        cs = self.contacts
        params = np.zeros((len(cs), PARAMS_SIZE))  # every law's constants fit, zero-padded
        for c in cs:
            p = c.law.params()
            params[c.index, : p.size] = p
        dof, w = self.contact_kinematics()
        return (dof, w, np.array([c.gap for c in cs], dtype=float),
                np.array([c.law.code for c in cs], dtype=np.int64), params)

    @cached_property
    def yielding_storeys(self) -> tuple[tuple[int, int], ...]:
        """``(building, storey index)`` of every storey with a storey law, in DOF order."""
        return tuple((p, j) for p, b in enumerate(self.buildings) if b.is_inelastic
                     for j in range(b.n))

    def storey_arrays(self) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64],
                                     NDArray[np.float64], NDArray[np.int64]]:
        """The yielding storeys, and then the links between buildings, as plain arrays for
        the compiled kernel (element rows of one kind).

        Returns
        -------
        lower, upper : int64 (n_s,)
            Global DOF of the floor below (−1: the ground) and above each storey.
        code : int64 (n_s,)
            Storey-law codes (:mod:`pounding.hysteresis.base`).
        params : float64 (n_s, P)
            Storey-law constants ``[k, F_y, …]``.
        z_index : int64 (n_s,)
            Index of the storey's internal variable among the ``z`` states (−1: none).
        """
        offsets = self.system.offsets
        lower, upper, code, zi = [], [], [], []
        rows: list[NDArray[np.float64]] = []
        nz = 0
        for p, b in enumerate(self.buildings):
            if not b.is_inelastic:
                continue
            law = b.storey_law
            assert law is not None
            prm = b.storey_law_params()
            for j in range(b.n):
                upper.append(int(offsets[p] + j))
                lower.append(int(offsets[p] + j - 1) if j > 0 else -1)
                code.append(law.code)
                rows.append(prm[j])
                zi.append(nz if law.has_internal_variable else -1)
                nz += 1 if law.has_internal_variable else 0
        # the links: rows of the same kind after the storeys, from the left end (lower) to
        # the right end (upper), so the "drift" is u_right − u_left
        width = rows[0].size if rows else STOREY_PARAMS_SIZE
        for link in self.links:
            (ba, fa), (bb, fb) = link.ends
            lower.append(int(offsets[ba] + fa))
            upper.append(int(offsets[bb] + fb))
            code.append(link.code)
            rows.append(link.params(width))
            zi.append(nz if link.has_internal_variable else -1)
            nz += 1 if link.has_internal_variable else 0
        return (np.array(lower, dtype=np.int64), np.array(upper, dtype=np.int64),
                np.array(code, dtype=np.int64),
                np.array(rows, dtype=float).reshape(len(rows), width),
                np.array(zi, dtype=np.int64))

    def linear_stiffness(self) -> NDArray[np.float64]:
        """Stiffness matrix [N/m] of the linear storeys only (yielding storeys left out: the
        kernel adds their shear from their laws). Assembled once per model; read-only."""
        return self._linear_stiffness

    @cached_property
    def _linear_stiffness(self) -> NDArray[np.float64]:
        blocks = [b.stiffness_matrix() if not b.is_inelastic else np.zeros((b.n, b.n))
                  for b in self.buildings]
        k = np.ascontiguousarray(scipy.linalg.block_diag(*blocks))
        k.setflags(write=False)
        return k

    def dof_labels(self) -> list[str]:
        """``'B1F1'``, ``'B1F2'``, … for every degree of freedom (1-based)."""
        return [f"B{b + 1}F{j + 1}" for b, bl in enumerate(self.buildings) for j in range(bl.n)]
