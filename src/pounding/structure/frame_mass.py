"""A frame's mass: the nodes' lumped masses and the members' own, lumped or consistent.

A member of mass ``m̄`` per length [kg/m] and length ``L`` carries ``m̄ L``:

* **lumped** (``mass_matrix = "lumped"``, the default; OpenSees' ``elasticBeamColumn …
  -mass m̄``): half at each end node, on both translations ``u_x`` and ``u_y``, no rotary
  inertia — a diagonal mass matrix, which the time stepper takes;
* **consistent** (``"consistent"``; OpenSees' ``-cMass``): the element's consistent mass
  matrix from its shape functions (Przemieniecki, *Theory of Matrix Structural Analysis*,
  1968, §11.3; Chopra, *Dynamics of Structures*, 4th ed., eq. 17.3.11) on
  ``(u₁, v₁, θ₁, u₂, v₂, θ₂)`` in the member's axes,

      axial  m̄L/6 [[2, 1], [1, 2]],
      bending m̄L/420 [[156, 22L, 54, −13L], [22L, 4L², 13L, −3L²],
                      [54, 13L, 156, −22L], [−13L, −3L², −22L, 4L²]],

  rotated to the global axes. It couples rotations (a hinged member end's own rotation
  among them) with translations: exact element by element for the modes of a member
  (converging from above, as ``h⁴``), but not diagonal, so it serves the modes, not the time
  stepper.

The nodes' own masses ``[m_x, m_y, J]`` add on the diagonal in both.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from pounding.structure.frame import Frame
from pounding.structure.frame_stiffness import FrameDofs, member_transform

__all__ = ["consistent_member_mass", "frame_mass_matrix"]


def consistent_member_mass(mass_per_length: float, L: float) -> NDArray[np.float64]:
    """The consistent 6×6 mass matrix [kg, kg·m, kg·m²] of a member on ``(u₁, v₁, θ₁, u₂,
    v₂, θ₂)`` in its own axes (module docstring)."""
    a = mass_per_length * L / 6.0
    b = mass_per_length * L / 420.0
    m = np.zeros((6, 6))
    m[np.ix_([0, 3], [0, 3])] = a * np.array([[2.0, 1.0], [1.0, 2.0]])
    m[np.ix_([1, 2, 4, 5], [1, 2, 4, 5])] = b * np.array(
        [[156.0, 22 * L, 54.0, -13 * L],
         [22 * L, 4 * L * L, 13 * L, -3 * L * L],
         [54.0, 13 * L, 156.0, -22 * L],
         [-13 * L, -3 * L * L, -22 * L, 4 * L * L]])
    return m


def frame_mass_matrix(frame: Frame, dofs: FrameDofs) -> NDArray[np.float64]:
    """The frame's mass matrix over its free DOFs [kg, kg·m, kg·m²], (n, n): its nodes'
    masses and its members' own, lumped (diagonal) or consistent as ``frame.mass_matrix``
    says (module docstring). Mass on a fixed DOF goes to the ground."""
    n = dofs.n
    M = np.zeros((n, n))
    for i in range(frame.n_nodes):
        for d in range(3):
            k = dofs.node[i, d]
            if k >= 0:
                M[k, k] += frame.masses[i, d]
    lengths = frame.lengths
    for e, (a, b) in enumerate(frame.elements):
        mbar = float(frame.member_mass[e])
        if mbar == 0.0:
            continue
        L = float(lengths[e])
        where = dofs.element[e]
        if frame.mass_matrix == "lumped":
            for k in (where[0], where[1], where[3], where[4]):
                if k >= 0:
                    M[k, k] += 0.5 * mbar * L
            continue
        c, s = (frame.nodes[b] - frame.nodes[a]) / L
        t = member_transform(float(c), float(s))
        me = t.T @ consistent_member_mass(mbar, L) @ t
        free = where >= 0
        M[np.ix_(where[free], where[free])] += me[np.ix_(free, free)]
    return 0.5 * (M + M.T)
