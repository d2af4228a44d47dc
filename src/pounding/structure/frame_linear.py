"""A frame's linear lateral model: its stiffness condensed onto the floors, as a
:class:`~pounding.structure.MatrixBuilding` that stands in a row and pounds.

With rigid floors and masses on the floors' lateral motion only (the usual lumped-mass
model of a moment frame), every other degree of freedom — vertical displacements, joint and
member-end rotations — is massless and follows the floors statically: the frame's lateral
stiffness is the static condensation ``K_ff − K_fo K_oo⁻¹ K_of`` (Chopra, *Dynamics of
Structures*, 4th ed., §9.3), with the hinges at their elastic stiffness and, when the frame
has P-Delta (``geometry`` or a leaning column), the geometric stiffness of its gravity
loads included. That is exact for a frame that stays elastic.
"""

from __future__ import annotations

import numpy as np

from pounding.structure.frame import Frame
from pounding.structure.frame_analysis import frame_modes, gravity
from pounding.structure.matrices import MatrixBuilding

__all__ = ["frame_matrix_building"]


def frame_matrix_building(frame: Frame) -> MatrixBuilding:
    """The elastic frame as a :class:`MatrixBuilding` of its floors (module docstring).

    Raises
    ------
    ValueError
        If the frame has plastic hinges (a yielding frame's time history is not linear: it
        is not available yet — its pushover is, :func:`pounding.structure.frame_analysis.
        pushover`), has no rigid floors, or carries mass other than on the floors' lateral
        motion.
    """
    if frame.hinges:
        raise ValueError(f"{frame.name}: a frame with plastic hinges has no linear model; time "
                         "histories of yielding frames are not available yet (run `pounding "
                         "pushover` for its capacity curve, or drop the hinges to run it "
                         "elastic)")
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
    return MatrixBuilding(M=M, K=K, labels=[f"F{j + 1}" for j in range(nf)],
                          elevations=frame.levels - frame.base, damping=frame.damping,
                          name=frame.name)
