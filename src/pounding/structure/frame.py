"""Planar moment frames: elastic beam-columns with concentrated plastic hinges at their ends.

A :class:`Frame` is the model a structural engineer draws for a moment frame in its plane
(OpenSees practice for concentrated-plasticity frames, e.g. Lignos & Krawinkler 2011,
FEMA P695 archetypes):

* **nodes** at (x, y) [m] with three degrees of freedom each: ``u_x``, ``u_y`` [m] and the
  rotation ``θ`` [rad];
* **elements**: elastic Euler–Bernoulli beam-columns between two nodes with axial rigidity
  ``EA`` [N] and flexural rigidity ``EI`` [N·m²];
* **hinges**: a rotational spring with a :class:`~pounding.hysteresis.hinges.HingeLaw`
  between a node and the end of an element framing into it (in series with the element);
* **supports**: fixed degrees of freedom (a fixed base fixes all three);
* **masses**: lumped at the nodes (``[m_x, m_y, J]`` in kg, kg, kg·m²), and the members'
  own (``member_mass`` [kg/m]), lumped at their ends or consistent (``mass_matrix``;
  :mod:`pounding.structure.frame_mass`);
* **gravity**: nodal loads [N, N, N·m] and uniform loads on members [N/m] (downward), applied
  first, before any lateral load or shaking;
* **rigid floors** (``diaphragm=True``): every node of a floor level moves together
  horizontally (OpenSees ``equalDOF``), so beams are axially rigid and a floor has one lateral
  displacement;
* a **leaning column**: the gravity load of the frames' tributary gravity system, per floor
  level [N], carried by a pin-ended column tied to the floor, which adds only its P-Delta
  (negative geometric) stiffness ``−P/h`` between the floors (FEMA P695 §6; Gupta &
  Krawinkler 1999);
* **P-Delta of the frame's own columns** (``geometry``): ``"linear"`` (none),
  ``"p-delta"`` (the chord's ``N/L`` string stiffness, as OpenSees' ``PDelta`` transformation)
  or ``"consistent"`` (the beam-column's consistent geometric stiffness, which adds the
  member's own bowing, P-δ), with the axial forces of the gravity analysis held constant.

Floors (the levels above the base where nodes stand) are numbered from the lowest; their
lateral displacement is that of the floor (rigid floors) or the mean of its nodes'.

The analyses of a frame (stiffness, condensation, modes, pushover) are in
:mod:`pounding.structure.frame_stiffness` and :mod:`pounding.structure.frame_analysis`; a
regular frame is written from bays and storeys by :func:`regular_frame`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from pounding.hysteresis.hinges import HingeLaw
from pounding.structure.damping import DampingModel, RayleighDamping
from pounding.structure.floor_arrays import readonly

__all__ = ["Frame", "FrameHinge", "GEOMETRIES", "MASS_MATRICES", "regular_frame"]

GEOMETRIES: tuple[str, ...] = ("linear", "p-delta", "consistent")
"""How the frame's own columns' gravity loads enter its stiffness (see the module docstring)."""

MASS_MATRICES: tuple[str, ...] = ("lumped", "consistent")
"""How the members' own mass enters the frame's mass matrix
(:mod:`pounding.structure.frame_mass`)."""

LEVEL_TOL: float = 1e-6
"""Nodes whose elevations differ by less than this [m] stand on the same floor level."""


@dataclass(frozen=True)
class FrameHinge:
    """A plastic hinge at end ``end`` (0: the element's first node, 1: its second) of element
    ``element``, with moment–rotation law ``law``."""

    element: int
    end: int
    law: HingeLaw


def _array(name: str, value: ArrayLike, shape: tuple[int, ...], *, positive: bool = False,
           nonnegative: bool = False) -> NDArray[np.float64]:
    a = np.asarray(value, dtype=float)
    if a.ndim == 0 and len(shape) == 1:
        a = np.full(shape, float(a))
    if a.shape != shape:
        raise ValueError(f"{name}: need shape {shape}, got {a.shape}")
    bad = ~np.isfinite(a)
    if positive:
        bad |= a <= 0.0
    if nonnegative:
        bad |= a < 0.0
    if np.any(bad):
        idx = tuple(int(i) for i in np.argwhere(bad)[0])
        need = "finite and > 0" if positive else ("finite and >= 0" if nonnegative else "finite")
        where = idx[0] if len(idx) == 1 else list(idx)
        raise ValueError(f"{name}[{where}]: must be {need} (got {float(a[idx])!r})")
    return readonly(a)


@dataclass(frozen=True, eq=False)
class Frame:
    """A planar frame with concentrated plastic hinges (see the module docstring).

    Parameters
    ----------
    nodes : array_like, shape (n, 2)
        Node coordinates ``(x, y)`` [m]; ``y`` is the elevation.
    elements : array_like of int, shape (m, 2)
        The two nodes of each element (0-based).
    EA, EI : array_like, shape (m,)
        Axial [N] and flexural [N·m²] rigidity of each element.
    supports : array_like of bool, shape (n, 3)
        Fixed ``(u_x, u_y, θ)`` of each node.
    hinges : sequence of FrameHinge
        The hinges, at most one per element end.
    masses : array_like, shape (n, 3), optional
        Lumped nodal masses ``[m_x, m_y, J]`` [kg, kg, kg·m²]; default none.
    nodal_loads : array_like, shape (n, 3), optional
        Gravity loads on the nodes ``[F_x, F_y, M]`` [N, N, N·m] (downward is ``F_y < 0``).
    member_loads : array_like, shape (m,), optional
        Uniform gravity load on each element [N/m of its length], downward.
    diaphragm : bool
        Rigid floors: the nodes of each floor level share ``u_x``.
    leaning_loads : array_like, shape (n_floors,), optional
        Gravity load [N] the leaning column takes at each floor level (lowest first).
    geometry : str
        ``"linear"``, ``"p-delta"`` or ``"consistent"`` (module docstring).
    damping : DampingModel
        Damping of the frame's lateral motion (default 5 % Rayleigh at modes 1 and 2).
    member_mass : array_like, shape (m,), optional
        Each member's own mass per length [kg/m]; default none.
    mass_matrix : str
        ``"lumped"`` (the members' mass at their ends' translations; the default) or
        ``"consistent"`` (:mod:`pounding.structure.frame_mass`: modes only, a time history
        takes lumped masses).
    name : str
        A label for tables, plots and messages.
    """

    nodes: NDArray[np.float64]
    elements: NDArray[np.int64]
    EA: NDArray[np.float64]
    EI: NDArray[np.float64]
    supports: NDArray[np.bool_]
    hinges: tuple[FrameHinge, ...] = ()
    masses: NDArray[np.float64] = None  # type: ignore[assignment]  # an array once built
    nodal_loads: NDArray[np.float64] = None  # type: ignore[assignment]  # an array once built
    member_loads: NDArray[np.float64] = None  # type: ignore[assignment]  # an array once built
    diaphragm: bool = True
    leaning_loads: NDArray[np.float64] = None  # type: ignore[assignment]  # an array once built
    geometry: str = "linear"
    damping: DampingModel = field(default_factory=lambda: RayleighDamping(0.05, 0.05))
    name: str = "frame"
    member_mass: NDArray[np.float64] = None  # type: ignore[assignment]  # an array once built
    mass_matrix: str = "lumped"

    def __post_init__(self) -> None:
        who = self.name
        nodes = _array(f"{who}: nodes", self.nodes, np.shape(self.nodes))
        if nodes.ndim != 2 or nodes.shape[1] != 2 or nodes.shape[0] < 2:
            raise ValueError(f"{who}: nodes: need (n, 2) coordinates [m] of at least 2 nodes, "
                             f"got shape {nodes.shape}")
        n = nodes.shape[0]
        el = np.asarray(self.elements)
        if el.ndim != 2 or el.shape[1] != 2 or el.shape[0] < 1 or not np.issubdtype(
                el.dtype, np.integer):
            raise ValueError(f"{who}: elements: need (m, 2) integer node numbers, got "
                             f"{el.dtype} of shape {el.shape}")
        if np.any((el < 0) | (el >= n)):
            e = int(np.argwhere((el < 0) | (el >= n))[0][0])
            raise ValueError(f"{who}: elements[{e}]: node numbers must be 0 … {n - 1} "
                             f"(got {el[e].tolist()})")
        m = el.shape[0]
        lengths = np.hypot(*(nodes[el[:, 1]] - nodes[el[:, 0]]).T)
        if np.any(lengths <= LEVEL_TOL):
            e = int(np.argmax(lengths <= LEVEL_TOL))
            raise ValueError(f"{who}: elements[{e}]: its two nodes coincide (length "
                             f"{lengths[e]:.3g} m)")
        sup = np.asarray(self.supports, dtype=bool)
        if sup.shape != (n, 3):
            raise ValueError(f"{who}: supports: need shape ({n}, 3), got {sup.shape}")
        if not np.any(sup):
            raise ValueError(f"{who}: supports: no node is supported; the frame must stand on "
                             "the ground")
        set_ = object.__setattr__
        set_(self, "nodes", nodes)
        ints = np.array(el, dtype=np.int64)
        ints.flags.writeable = False
        set_(self, "elements", ints)
        set_(self, "EA", _array(f"{who}: EA", self.EA, (m,), positive=True))
        set_(self, "EI", _array(f"{who}: EI", self.EI, (m,), positive=True))
        sup = sup.copy()
        sup.flags.writeable = False
        set_(self, "supports", sup)
        hinges = tuple(self.hinges)
        seen: set[tuple[int, int]] = set()
        for k, h in enumerate(hinges):
            if not isinstance(h, FrameHinge) or not isinstance(h.law, HingeLaw):
                raise ValueError(f"{who}: hinges[{k}]: need a FrameHinge with a hinge law")
            if not (0 <= h.element < m) or h.end not in (0, 1):
                raise ValueError(f"{who}: hinges[{k}]: element {h.element}, end {h.end}: need "
                                 f"an element 0 … {m - 1} and end 0 or 1")
            if (h.element, h.end) in seen:
                raise ValueError(f"{who}: hinges[{k}]: element {h.element} end {h.end} has "
                                 "two hinges")
            seen.add((h.element, h.end))
        set_(self, "hinges", hinges)
        zeros3 = np.zeros((n, 3))
        set_(self, "masses", _array(f"{who}: masses", zeros3 if self.masses is None
                                    else self.masses, (n, 3), nonnegative=True))
        set_(self, "nodal_loads", _array(f"{who}: nodal_loads", zeros3 if self.nodal_loads is None
                                         else self.nodal_loads, (n, 3)))
        set_(self, "member_loads", _array(f"{who}: member_loads", np.zeros(m)
                                          if self.member_loads is None else self.member_loads,
                                          (m,)))
        nf = self.levels.size
        set_(self, "leaning_loads", _array(f"{who}: leaning_loads", np.zeros(nf)
                                           if self.leaning_loads is None else self.leaning_loads,
                                           (nf,), nonnegative=True))
        set_(self, "member_mass", _array(f"{who}: member_mass", np.zeros(m)
                                         if self.member_mass is None else self.member_mass,
                                         (m,), nonnegative=True))
        if self.mass_matrix not in MASS_MATRICES:
            raise ValueError(f"{who}: mass_matrix: must be one of {', '.join(MASS_MATRICES)} "
                             f"(got {self.mass_matrix!r})")
        if self.geometry not in GEOMETRIES:
            raise ValueError(f"{who}: geometry: must be one of {', '.join(GEOMETRIES)} "
                             f"(got {self.geometry!r})")
        if not isinstance(self.damping, DampingModel):
            raise ValueError(f"{who}: damping: need a damping model (got {self.damping!r})")

    # ------------------------------------------------------------------ geometry
    @property
    def n_nodes(self) -> int:
        """Number of nodes."""
        return int(self.nodes.shape[0])

    @property
    def n_elements(self) -> int:
        """Number of elements."""
        return int(self.elements.shape[0])

    @property
    def lengths(self) -> NDArray[np.float64]:
        """Element lengths [m]."""
        d = self.nodes[self.elements[:, 1]] - self.nodes[self.elements[:, 0]]
        return np.hypot(d[:, 0], d[:, 1])

    @property
    def is_column(self) -> NDArray[np.bool_]:
        """True for the elements that are more vertical than horizontal."""
        d = self.nodes[self.elements[:, 1]] - self.nodes[self.elements[:, 0]]
        return np.abs(d[:, 1]) > np.abs(d[:, 0])

    @property
    def base(self) -> float:
        """Elevation of the lowest supported node [m]."""
        return float(np.min(self.nodes[np.any(self.supports, axis=1), 1]))

    @property
    def levels(self) -> NDArray[np.float64]:
        """Elevations of the floor levels [m]: the distinct elevations of nodes above the base
        that are not fully fixed, lowest first."""
        free = ~np.all(self.supports, axis=1) & (self.nodes[:, 1] > self.base + LEVEL_TOL)
        ys = np.sort(self.nodes[free, 1])
        if ys.size == 0:
            return np.zeros(0)
        keep = np.concatenate([[True], np.diff(ys) > LEVEL_TOL])
        return ys[keep]

    @property
    def node_level(self) -> NDArray[np.int64]:
        """Floor level of each node (−1: at the base or below, or fully fixed)."""
        lv = self.levels
        out = np.full(self.n_nodes, -1, dtype=np.int64)
        fixed = np.all(self.supports, axis=1)
        for i, (_, y) in enumerate(self.nodes):
            if fixed[i] or y <= self.base + LEVEL_TOL:
                continue
            j = int(np.argmin(np.abs(lv - y)))
            if abs(lv[j] - y) <= LEVEL_TOL:
                out[i] = j
        return out

    @property
    def storey_heights(self) -> NDArray[np.float64]:
        """Height of each storey [m]: between consecutive floor levels (the first from the
        base)."""
        return np.diff(np.concatenate([[self.base], self.levels]))

    @property
    def floor_masses(self) -> NDArray[np.float64]:
        """Horizontal mass of each floor level [kg]: its nodes' and half of each member's own
        mass at each of its ends there."""
        lv = self.node_level
        out = np.array([float(np.sum(self.masses[lv == j, 0])) for j in range(self.levels.size)])
        half = 0.5 * self.member_mass * self.lengths
        for e, ends in enumerate(self.elements):
            for node in ends:
                if lv[node] >= 0:
                    out[lv[node]] += half[e]
        return out

    def hinge_at(self, element: int, end: int) -> FrameHinge | None:
        """The hinge at an element's end, or None."""
        for h in self.hinges:
            if h.element == element and h.end == end:
                return h
        return None

    def describe(self) -> str:
        """One line: size and hinges."""
        return (f"{self.name}: planar frame, {self.n_nodes} nodes, {self.n_elements} elements, "
                f"{len(self.hinges)} hinges, {self.levels.size} floor{'s' if self.levels.size != 1 else ''}"
                f"{', rigid floors' if self.diaphragm else ''}, geometry {self.geometry}")


def _per_storey(name: str, value: float | Sequence[float] | ArrayLike, n: int) -> NDArray[np.float64]:
    a = np.atleast_1d(np.asarray(value, dtype=float))
    if a.size == 1:
        a = np.full(n, float(a[0]))
    if a.shape != (n,):
        raise ValueError(f"{name}: need one value or {n} (one per storey), got {a.size}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name}: must be finite (got {a.tolist()!r})")
    return a


def _law_per_storey(name: str, value: HingeLaw | Sequence[HingeLaw | None] | None,
                    n: int) -> list[HingeLaw | None]:
    if value is None or isinstance(value, HingeLaw):
        return [value] * n
    laws = list(value)
    if len(laws) == 1:
        laws = laws * n
    if len(laws) != n:
        raise ValueError(f"{name}: need one hinge law or {n} (one per storey), got {len(laws)}")
    return laws


def regular_frame(bays: float | Sequence[float], storey_heights: float | Sequence[float],
                  *, n_storeys: int | None = None,
                  column_EI: float | Sequence[float], beam_EI: float | Sequence[float],
                  column_EA: float | Sequence[float] = 1e12,
                  beam_EA: float | Sequence[float] = 1e12,
                  column_hinge: HingeLaw | Sequence[HingeLaw | None] | None = None,
                  beam_hinge: HingeLaw | Sequence[HingeLaw | None] | None = None,
                  floor_mass: float | Sequence[float] = 0.0,
                  beam_load: float | Sequence[float] = 0.0,
                  leaning_load: float | Sequence[float] = 0.0,
                  diaphragm: bool = True, geometry: str = "linear",
                  damping: DampingModel | None = None, name: str = "frame",
                  column_mass: float | Sequence[float] = 0.0,
                  beam_mass: float | Sequence[float] = 0.0,
                  mass_matrix: str = "lumped") -> Frame:
    """A regular moment frame: ``len(bays)`` bays and ``n_storeys`` storeys, fixed at the base.

    Column lines stand at the cumulative bay widths from x = 0; each storey has one column
    per line and one beam per bay. Per-storey values are one number or one per storey
    (lowest first). A hinge law given for columns sits at both ends of every column of that
    storey, one for beams at both ends of every beam of that floor.

    Parameters
    ----------
    bays : float or sequence of float
        Bay widths [m] (a single number: one bay).
    storey_heights : float or sequence of float
        Storey heights [m].
    n_storeys : int, optional
        Number of storeys when ``storey_heights`` is one number.
    column_EI, beam_EI, column_EA, beam_EA : float or sequence
        Rigidities per storey [N·m², N] (axial defaults are effectively rigid).
    column_hinge, beam_hinge : HingeLaw or sequence, optional
        Hinge laws per storey (None: no hinge; the member end is rigidly connected).
    floor_mass : float or sequence
        Horizontal mass of each floor [kg], shared equally by its nodes.
    beam_load : float or sequence
        Uniform gravity load on the beams of each floor [N/m].
    leaning_load : float or sequence
        Gravity load the leaning column takes at each floor [N].
    diaphragm, geometry, damping, name
        As :class:`Frame`.
    column_mass, beam_mass : float or sequence
        The columns' and beams' own mass per length in each storey [kg/m] (default none),
        in the frame's ``mass_matrix`` (``"lumped"`` or ``"consistent"``).

    Examples
    --------
    >>> from pounding.hysteresis.hinges import ElasticPlastic
    >>> f = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
    ...                   column_hinge=ElasticPlastic(k0=1e11, m_y=3e5),
    ...                   beam_hinge=ElasticPlastic(k0=1e11, m_y=6e5))
    >>> f.n_nodes, f.n_elements, len(f.hinges)
    (4, 3, 6)
    """
    widths = np.atleast_1d(np.asarray(bays, dtype=float))
    if widths.ndim != 1 or widths.size < 1 or not np.all(np.isfinite(widths) & (widths > 0)):
        raise ValueError(f"bays: need bay widths > 0 [m] (got {np.asarray(bays).tolist()!r})")
    hs = np.atleast_1d(np.asarray(storey_heights, dtype=float))
    if hs.size == 1 and n_storeys is not None:
        hs = np.full(int(n_storeys), float(hs[0]))
    if n_storeys is not None and hs.size != n_storeys:
        raise ValueError(f"storey_heights: need one value or {n_storeys}, got {hs.size}")
    if hs.size < 1 or not np.all(np.isfinite(hs) & (hs > 0)):
        raise ValueError(f"storey_heights: need heights > 0 [m] (got {hs.tolist()!r})")
    ns, nb = hs.size, widths.size
    xs = np.concatenate([[0.0], np.cumsum(widths)])
    ys = np.concatenate([[0.0], np.cumsum(hs)])
    ncol = nb + 1
    nodes = np.array([(x, y) for y in ys for x in xs])

    def node(level: int, line: int) -> int:
        return level * ncol + line

    cEI, bEI = _per_storey("column_EI", column_EI, ns), _per_storey("beam_EI", beam_EI, ns)
    cEA, bEA = _per_storey("column_EA", column_EA, ns), _per_storey("beam_EA", beam_EA, ns)
    ch, bh = _law_per_storey("column_hinge", column_hinge, ns), _law_per_storey(
        "beam_hinge", beam_hinge, ns)
    fm = _per_storey("floor_mass", floor_mass, ns)
    bl = _per_storey("beam_load", beam_load, ns)
    cm, bm = _per_storey("column_mass", column_mass, ns), _per_storey("beam_mass", beam_mass, ns)
    member_mass: list[float] = []
    elements: list[tuple[int, int]] = []
    EA: list[float] = []
    EI: list[float] = []
    loads: list[float] = []
    hinges: list[FrameHinge] = []
    for s in range(ns):
        for line in range(ncol):
            e = len(elements)
            elements.append((node(s, line), node(s + 1, line)))
            EA.append(cEA[s])
            EI.append(cEI[s])
            loads.append(0.0)
            member_mass.append(cm[s])
            law = ch[s]
            if law is not None:
                hinges += [FrameHinge(e, 0, law), FrameHinge(e, 1, law)]
    for s in range(ns):
        for b in range(nb):
            e = len(elements)
            elements.append((node(s + 1, b), node(s + 1, b + 1)))
            EA.append(bEA[s])
            EI.append(bEI[s])
            loads.append(bl[s])
            member_mass.append(bm[s])
            law = bh[s]
            if law is not None:
                hinges += [FrameHinge(e, 0, law), FrameHinge(e, 1, law)]
    supports = np.zeros((nodes.shape[0], 3), dtype=bool)
    supports[:ncol] = True
    masses = np.zeros((nodes.shape[0], 3))
    for s in range(ns):
        masses[node(s + 1, 0): node(s + 1, 0) + ncol, 0] = fm[s] / ncol
    lean = _per_storey("leaning_load", leaning_load, ns)
    if math.isfinite(float(np.sum(lean))) and np.any(lean < 0):
        raise ValueError(f"leaning_load: must be >= 0 [N] (got {lean.tolist()!r})")
    return Frame(nodes=nodes, elements=np.array(elements, dtype=np.int64), EA=np.array(EA),
                 EI=np.array(EI), supports=supports, hinges=tuple(hinges), masses=masses,
                 member_loads=np.array(loads), diaphragm=diaphragm, leaning_loads=lean,
                 geometry=geometry, damping=damping or RayleighDamping(0.05, 0.05), name=name,
                 member_mass=np.array(member_mass), mass_matrix=mass_matrix)
