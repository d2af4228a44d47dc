"""A frame's lateral model in a row of buildings: its stiffness condensed onto its DOFs with
mass, as a :class:`~pounding.structure.MatrixBuilding` that stands in a row and pounds.

With lumped masses (the usual model of a moment frame: the floors' masses on their lateral
motion, with rigid floors one DOF a floor), every DOF without mass — vertical displacements,
joint and member-end rotations, unless given mass — follows the others statically: the
frame's stiffness is the static condensation ``K_ff − K_fo K_oo⁻¹ K_of`` onto the DOFs with
mass (Chopra, *Dynamics of Structures*, 4th ed., §9.3), with the hinges at their elastic
stiffness and, when the frame has P-Delta (``geometry`` or a leaning column), the geometric
stiffness of its gravity loads included. That is exact for a frame that stays elastic. A
frame without rigid floors keeps each node's lateral DOF that has mass; its floors (where
drifts are measured) are its left column line, and a neighbour on its right strikes its
right column line (:attr:`~pounding.structure.MatrixBuilding.faces`).

A frame with plastic hinges is a :class:`FrameBuilding`: the same matrix building (its
``K`` the elastic condensed stiffness, its damping built on it), carrying the frame and its
gravity state, which the time stepper moves configuration by configuration
(:mod:`pounding.structure.frame_configuration`, :mod:`pounding.integrate.frame_run`).
"""

from __future__ import annotations

import numpy as np

from pounding.structure.foundation.flexible_base import (
    FlexibleBaseBuilding,
    flexible_base,
)
from pounding.structure.foundation.impedance import Footing
from pounding.structure.foundation.soil import Soil
from pounding.structure.frame import LEVEL_TOL, Frame
from pounding.structure.frame_analysis import FrameState, frame_modes, gravity
from pounding.structure.matrices import MatrixBuilding

__all__ = ["FlexibleBaseFrame", "FrameBuilding", "frame_matrix_building",
           "frame_on_flexible_base"]


class FrameBuilding(MatrixBuilding):
    """A frame as a building of a row: the :class:`MatrixBuilding` of its floors (``K`` the
    elastic condensed stiffness under gravity, hinges at their elastic stiffness; ``C`` from
    the frame's damping model on that ``K`` and the floor masses, held constant — Rayleigh
    damping on the elastic stiffness, not the hinges' tangent, as Zareian & Medina (2010)
    recommend), with the frame itself (:attr:`frame`) and its gravity state
    (:attr:`gravity_state`), from which a run moves the hinges.

    Built by :func:`frame_matrix_building`.
    """

    frame: Frame
    gravity_state: FrameState
    #: the frame's DOF (:class:`~pounding.structure.frame_stiffness.FrameDofs` numbering)
    #: of each of the building's DOFs
    kept: np.ndarray

    @property
    def hinges(self) -> tuple:
        """The frame's plastic hinges (:class:`~pounding.structure.frame.FrameHinge`)."""
        return self.frame.hinges

    @property
    def has_hinges(self) -> bool:
        """True if the frame has plastic hinges (its time history is not linear)."""
        return bool(self.frame.hinges)

    def hinge_labels(self) -> list[str]:
        """``'H1'``, ``'H2'``, … for the hinges in the frame's order."""
        return [f"H{h + 1}" for h in range(len(self.frame.hinges))]


class FlexibleBaseFrame(FlexibleBaseBuilding, FrameBuilding):
    """A frame on a flexible base (:func:`frame_on_flexible_base`): the
    :class:`~pounding.structure.foundation.FlexibleBaseBuilding` of its
    :class:`FrameBuilding` — its DOFs the frame's (relative to the free-field ground) then the
    footing's sway and rocking where they have mass — with the frame and its gravity state.

    The frame's own deformation, in which its hinges, member forces and drifts live, is
    ``u = T y`` (:attr:`deformation`, ``foundation.deformation``): its DOFs less the
    footing's rigid sway and rocking."""

    @property
    def frame_dofs(self) -> int:
        """How many of the building's DOFs are the frame's (the first ones)."""
        return int(self.kept.size)

    @property
    def deformation(self) -> np.ndarray:
        """``T`` (frame_dofs, n): the frame's own deformation ``u = T y`` from the DOFs."""
        T = self.foundation.deformation
        assert T is not None
        return T


def frame_on_flexible_base(building: FrameBuilding, footing: Footing, soil: Soil
                           ) -> FlexibleBaseFrame:
    """The frame ``building`` on ``footing`` on ``soil``
    (:func:`~pounding.structure.foundation.flexible_base`): ``u = T y``, ``T = [I | −1 |
    −z]`` over the frame's DOFs (each a lateral translation at its elevation ``z`` above
    the frame's base), ``K_y = Tᵀ K T + diag(0, k_x, k_φ)``, ``C_y`` likewise,
    ``M_y = diag(M, m_f, I_f)``.

    An elastic frame takes any footing (a massless one condensed out); a frame with plastic
    hinges needs the footing's sway and rocking as DOFs of their own (its hinge
    configurations change ``K`` in ``Tᵀ K T``, which a static condensation fixed at the
    start would not follow).

    Raises
    ------
    ValueError
        If a DOF with mass is not lateral (vertical or rotational masses: the footing's
        rocking would move them too), or if a frame with hinges stands on a footing
        without mass or without rocking inertia.
    """
    name = building.name
    lateral = np.asarray(building.r) == 1.0
    if not np.all(lateral):
        d = int(np.argmin(lateral))
        raise ValueError(f"building {name!r}: foundation: a frame on a flexible base takes "
                         f"lateral masses only ({building.labels[d]!r} is a vertical or "
                         "rotational DOF with mass, which the footing's rocking would move "
                         "too: not modelled)")
    if building.has_hinges and not (footing.mass > 0.0 and footing.inertia > 0.0):
        raise ValueError(f"building {name!r}: foundation.mass and foundation.inertia: a frame "
                         f"with plastic hinges on a flexible base needs a footing with mass "
                         f"and rocking inertia, > 0 both (got mass = {footing.mass:g} kg, "
                         f"inertia = {footing.inertia:g} kg·m²): its sway and rocking are then "
                         "DOFs, coupled to the frame in each configuration of its hinges")
    fb = flexible_base(building, footing, soil)
    out = FlexibleBaseFrame(fb.foundation, building, M=fb.M, K=fb.K, C=fb.damping_matrix(),
                            labels=fb.labels, elevations=fb.elevations, r=fb.r, name=fb.name,
                            floors=fb.floors, faces=dict(fb.faces) or None)
    object.__setattr__(out, "frame", building.frame)
    object.__setattr__(out, "gravity_state", building.gravity_state)
    object.__setattr__(out, "kept", building.kept)
    # (its damping model, for what is said of it: the frame's own, on its fixed-base modes,
    # in C through T; the soil's dashpots on the footing)
    object.__setattr__(out, "damping", building.damping)
    return out


def frame_matrix_building(frame: Frame) -> FrameBuilding:
    """The frame as a building of a row (module docstring): a :class:`FrameBuilding`, the
    :class:`MatrixBuilding` of its DOFs with mass with the frame attached.

    Its DOFs are the floors first — the lateral displacement of each floor (a level where a
    beam stands), with rigid floors the floor's, without them its first node's (the left
    column line), ``F1`` … ``Fn`` — then every other DOF with mass, labelled by node (``N7x``,
    ``N7y``, ``N7r``: node 7's lateral, vertical and rotational DOF; nodes counted from 1,
    so ``N7`` is ``nodes[6]`` of a model file). Drifts are measured at
    the floors. A neighbour strikes the frame's outer column line on its side
    (:attr:`MatrixBuilding.faces`): without rigid floors each floor's last node on the
    right; and a node with lateral mass on an outer column between two floors (a level with
    no beam, at the frame's leftmost or rightmost x) is struck by a neighbour's slab at its
    level — floor to column at a node of the column, with its bending — and bounds the
    stretch of column a slab between nodes strikes.

    Raises
    ------
    ValueError
        If a floor's node where drifts are measured or where a neighbour strikes carries
        no lateral mass, or a member end's own rotation is given mass.
    """
    state = gravity(frame)
    dofs = state.dofs
    if frame.mass_matrix != "lumped":
        raise ValueError(f"{frame.name}: mass_matrix: a time history takes lumped masses (got "
                         f"{frame.mass_matrix!r}; the consistent one serves the modes)")
    _, _, keep, Kc, Mk = frame_modes(frame, state)
    m = np.diag(Mk)
    mass_at = {int(d): i for i, d in enumerate(keep)}
    floors, left, right = _row_dofs(frame, state.dofs.node, mass_at)
    order = list(dict.fromkeys(floors + left + right))  # (unique, in order)
    order += [int(d) for d in keep if int(d) not in set(order)]
    kept = np.array(order, dtype=np.int64)
    idx = np.array([mass_at[d] for d in kept], dtype=np.int64)
    position = {d: k for k, d in enumerate(order)}
    faces = None
    if left != floors or right != floors:
        faces = {"left": [position[d] for d in left], "right": [position[d] for d in right]}
    # each DOF's node and direction, for its label, elevation and influence
    node_of = {int(dofs.node[i, d]): (i, d) for i in range(frame.n_nodes) for d in range(3)
               if dofs.node[i, d] >= 0}
    nf = len(floors)
    labels = [f"F{k + 1}" if k < nf else f"N{node_of[d][0] + 1}{'xyr'[node_of[d][1]]}"
              for k, d in enumerate(order)]
    elevations = np.array([frame.nodes[node_of[d][0], 1] for d in order]) - frame.base
    r = np.array([1.0 if node_of[d][1] == 0 else 0.0 for d in order])
    building = FrameBuilding(M=np.diag(m[idx]), K=Kc[np.ix_(idx, idx)], labels=labels,
                             elevations=elevations, r=r, damping=frame.damping,
                             name=frame.name, floors=list(range(nf)), faces=faces)
    object.__setattr__(building, "frame", frame)
    object.__setattr__(building, "gravity_state", state)
    object.__setattr__(building, "kept", kept)
    return building


def _row_dofs(frame: Frame, node_dof: np.ndarray, mass_at: dict[int, int]
              ) -> tuple[list[int], list[int], list[int]]:
    """The frame's DOFs (its own numbering) of its floors, lowest first, and of its left and
    right faces, by elevation (:func:`frame_matrix_building`)."""
    level, x = frame.node_level, frame.nodes[:, 0]
    ends = frame.elements
    beams = {int(level[a]) for a, b in ends if level[a] >= 0 and level[a] == level[b]}
    standing = np.flatnonzero(level >= 0)
    x_min, x_max = float(np.min(x[standing])), float(np.max(x[standing]))
    floors: list[int] = []
    left: list[int] = []
    right: list[int] = []
    for j in range(frame.levels.size):
        nodes = np.flatnonzero(level == j)
        nodes = nodes[node_dof[nodes, 0] >= 0]
        if j in beams:  # a floor: drifts at its first node, struck at its first and last
            order = nodes[np.argsort(x[nodes], kind="stable")]
            for face, node in ((left, int(order[0])), (right, int(order[-1]))):
                d = int(node_dof[node, 0])
                if d not in mass_at:
                    where = (f"floor {len(floors) + 1} (y = {frame.levels[j]:.6g} m)"
                             if frame.diaphragm else
                             f"node {node + 1} (nodes[{node}], floor {len(floors) + 1}, "
                             f"y = {frame.levels[j]:.6g} m)")
                    raise ValueError(f"{frame.name}: masses: {where} has no lateral mass; a "
                                     "time history needs a lateral mass where each floor's "
                                     "drift is measured and where a neighbour may strike")
                face.append(d)
            floors.append(left[-1])
            continue
        for node in nodes:  # a column node: struck where it has mass on an outer column
            d = int(node_dof[node, 0])
            if d not in mass_at:
                continue
            if abs(x[node] - x_min) <= LEVEL_TOL:
                left.append(d)
            if abs(x[node] - x_max) <= LEVEL_TOL:
                right.append(d)
    if not floors:
        raise ValueError(f"{frame.name}: no floor (no beam at any level above the base) for a "
                         "time history")
    return floors, left, right
