"""A frame's lateral model in a row of buildings: its stiffness condensed onto the floors,
as a :class:`~pounding.structure.MatrixBuilding` that stands in a row and pounds.

With rigid floors and masses on the floors' lateral motion only (the usual lumped-mass
model of a moment frame), every other degree of freedom — vertical displacements, joint and
member-end rotations — is massless and follows the floors statically: the frame's lateral
stiffness is the static condensation ``K_ff − K_fo K_oo⁻¹ K_of`` (Chopra, *Dynamics of
Structures*, 4th ed., §9.3), with the hinges at their elastic stiffness and, when the frame
has P-Delta (``geometry`` or a leaning column), the geometric stiffness of its gravity
loads included. That is exact for a frame that stays elastic.

A frame with plastic hinges is a :class:`FrameBuilding`: the same matrix building (its
``K`` the elastic condensed stiffness, its damping built on it), carrying the frame and its
gravity state, which the time stepper moves configuration by configuration
(:mod:`pounding.structure.frame_configuration`, :mod:`pounding.integrate.frame_run`).
"""

from __future__ import annotations

import numpy as np

from pounding.structure.frame import Frame
from pounding.structure.frame_analysis import FrameState, frame_modes, gravity
from pounding.structure.matrices import MatrixBuilding

__all__ = ["FrameBuilding", "frame_matrix_building"]


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


def frame_matrix_building(frame: Frame) -> FrameBuilding:
    """The frame as a building of a row (module docstring): a :class:`FrameBuilding`, the
    :class:`MatrixBuilding` of its floors with the frame attached.

    Raises
    ------
    ValueError
        If the frame has no rigid floors or carries mass other than on the floors' lateral
        motion.
    """
    if not frame.diaphragm:
        raise ValueError(f"{frame.name}: diaphragm: a time history of a frame needs rigid "
                         "floors (diaphragm = true)")
    state = gravity(frame)
    _, _, keep, Kc, m = frame_modes(frame, state)
    floor_dofs = state.dofs.floor_dof
    if not np.array_equal(np.sort(keep), np.sort(floor_dofs)):
        raise ValueError(f"{frame.name}: masses: a time history of a frame takes masses on the "
                         "floors' lateral motion only (m_x of the floor nodes), not vertical or "
                         "rotational masses")
    pos = {int(d): i for i, d in enumerate(keep)}
    idx = np.array([pos[int(d)] for d in floor_dofs])
    K = Kc[np.ix_(idx, idx)]
    M = np.diag(m[idx])
    nf = idx.size
    building = FrameBuilding(M=M, K=K, labels=[f"F{j + 1}" for j in range(nf)],
                             elevations=frame.levels - frame.base, damping=frame.damping,
                             name=frame.name)
    object.__setattr__(building, "frame", frame)
    object.__setattr__(building, "gravity_state", state)
    return building
