"""Buildings side by side: one block-diagonal system, and the floors that can meet.

Adjacent buildings share the ground motion but, until they touch, nothing else; so their
equations of motion stack into one block-diagonal system

    M ü + C u̇ + K u = −M r a_g(t) + (contact forces),

with ``M = diag(M_1, M_2, …)`` and likewise ``C`` and ``K``, and ``r`` the stacked influence
vectors (Chopra §9.4.1, applied to each building). Contact couples the blocks later, through
the floors listed by :func:`shared_levels` (floor to floor) and :func:`contact_points` (also
floor to column).

DOF numbering: building ``b``'s floor ``j`` (1-based, floor 1 = first suspended floor) is
global degree of freedom ``offsets[b] + j − 1``; a :class:`~pounding.structure.MatrixBuilding`'s
DOF ``j`` (0-based, in its own order) is ``offsets[b] + j``. Its floors are the DOFs of
:attr:`~pounding.structure.MatrixBuilding.floors` (:func:`floor_dofs`, lowest first); a
neighbour strikes it there, or at the DOFs its
:attr:`~pounding.structure.MatrixBuilding.faces` name for that side (:func:`face_dofs`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from pounding.structure.matrices import MatrixBuilding
from pounding.structure.shear_building import ShearBuilding
from pounding.validation import positive

__all__ = ["BUILDING_TYPES", "AssembledSystem", "Building", "assemble", "contact_points",
           "face_below", "face_dofs", "face_point_name", "floor_below", "floor_dofs",
           "shared_levels"]

Building = ShearBuilding | MatrixBuilding
"""A building that stands in a row: a shear building or a (planar) matrix building."""

BUILDING_TYPES = (ShearBuilding, MatrixBuilding)
"""The classes of :data:`Building` (for ``isinstance``)."""


def floor_dofs(building: Building) -> NDArray[np.int64]:
    """The building's floor DOFs (0-based, its own numbering), lowest floor first: every DOF
    of a shear building; a matrix building's :attr:`~MatrixBuilding.floors` by elevation."""
    if isinstance(building, MatrixBuilding):
        return building.floor_dofs
    return np.arange(building.n, dtype=np.int64)


def floor_below(building: Building) -> NDArray[np.int64]:
    """For every DOF, the floor DOF below it: −1 for the lowest floor (the ground below),
    −2 for a DOF that is not a floor (no storey drift)."""
    if isinstance(building, MatrixBuilding):
        return building.floor_below()
    return np.arange(building.n, dtype=np.int64) - 1


def face_dofs(building: Building, side: str) -> NDArray[np.int64]:
    """The DOFs a neighbour on ``side`` (``"left"`` or ``"right"``) strikes, lowest first: a
    matrix building's :meth:`~MatrixBuilding.face_dofs`, else the floors."""
    if isinstance(building, MatrixBuilding):
        return building.face_dofs(side)
    return floor_dofs(building)


def face_below(building: Building, side: str) -> NDArray[np.int64]:
    """For every DOF, the DOF below it on the face of ``side`` (−1: the ground, −2: not on
    that face): :func:`floor_below` unless a matrix building's faces say otherwise."""
    if isinstance(building, MatrixBuilding):
        return building.face_below(side)
    return floor_below(building)


def face_point_name(index: int, building: Building, side: str, z: float, tol: float) -> str:
    """The label of a contact point at elevation ``z`` [m] on the face of ``side`` of
    ``building`` (number ``index`` in the row, 0-based) where that face is not its floors
    (:attr:`MatrixBuilding.faces`): ``'B1F3'`` within ``tol`` [m] of the level of floor 3,
    ``'B1S3@0.50'`` half way up storey 3; ``""`` where the floors are the face (the point's
    own :meth:`~pounding.contact.geometry.ContactPoint.label` names it)."""
    if not isinstance(building, MatrixBuilding) or side not in building.faces:
        return ""
    f = floor_dofs(building)
    levels = building.elevations[f]
    k = int(np.searchsorted(levels, z - tol))
    if k < levels.size and abs(levels[k] - z) <= tol:
        return f"B{index + 1}F{k + 1}"
    below = float(levels[k - 1]) if k > 0 else 0.0
    top = float(levels[min(k, levels.size - 1)])
    xi = (z - below) / (top - below) if top > below else 1.0
    return f"B{index + 1}S{k + 1}@{xi:.2f}"


class AssembledSystem(NamedTuple):
    """Matrices of several uncoupled buildings stacked block-diagonally.

    Unpacks as ``M, C, K, r, offsets = assemble(buildings)``. Every array is a
    C-contiguous float64 (``offsets``: int64) array, ready for a compiled time stepper.

    Attributes
    ----------
    M : ndarray, shape (N, N)
        Mass matrix [kg], ``N`` = total number of floors.
    C : ndarray, shape (N, N)
        Damping matrix [N·s/m]; each block from its building's own damping model.
    K : ndarray, shape (N, N)
        Stiffness matrix [N/m].
    r : ndarray, shape (N,) or (N, G)
        Influence vector [-]: each building's own (all ones for a shear building: every
        floor feels the ground acceleration); as :func:`assemble` makes it, (N,). A model
        with buildings in plan replaces it by the influence matrix R (N × 2) of the
        ground's x and y components (:class:`pounding.model.PoundingModel`).
    offsets : ndarray of int64, shape (B,)
        Global index of each building's first degree of freedom (its floor 1).
    """

    M: NDArray[np.float64]
    C: NDArray[np.float64]
    K: NDArray[np.float64]
    r: NDArray[np.float64]
    offsets: NDArray[np.int64]

    @property
    def n_dof(self) -> int:
        """Total number of degrees of freedom ``N``."""
        return int(self.r.shape[0])

    def dof(self, building: int, floor_index: int) -> int:
        """Global DOF of ``building``'s floor at 0-based ``floor_index`` (0 = floor 1)."""
        b = int(building)
        if not 0 <= b < self.offsets.shape[0]:
            raise ValueError(f"building must be in [0, {self.offsets.shape[0] - 1}] "
                             f"(got {building!r})")
        end = self.offsets[b + 1] if b + 1 < self.offsets.shape[0] else self.n_dof
        i = int(floor_index)
        if not 0 <= i < end - self.offsets[b]:
            raise ValueError(f"floor_index must be in [0, {end - self.offsets[b] - 1}] for "
                             f"building {b} (got {floor_index!r})")
        return int(self.offsets[b] + i)


def assemble(buildings: Sequence[Building]) -> AssembledSystem:
    """Stack buildings into one block-diagonal system (no coupling between them).

    Parameters
    ----------
    buildings : sequence of ShearBuilding or MatrixBuilding
        One or more buildings, in the order they stand (left to right).

    Returns
    -------
    AssembledSystem
        ``(M, C, K, r, offsets)``; see :class:`AssembledSystem`.

    Raises
    ------
    ValueError
        If ``buildings`` is empty or an entry is not a :class:`ShearBuilding` or a
        :class:`MatrixBuilding`.
    """
    items = list(buildings)
    if not items:
        raise ValueError("buildings must hold at least one ShearBuilding (got an empty sequence)")
    for i, b in enumerate(items):
        if not isinstance(b, BUILDING_TYPES):
            raise ValueError(f"buildings[{i}] must be a ShearBuilding or a MatrixBuilding "
                             f"(got {b!r})")
    # a matrix building's M is lumped: off-diagonal round-off (≤ DIAGONAL_RTOL) is dropped
    M = scipy.linalg.block_diag(*(np.diag(b.masses) if isinstance(b, MatrixBuilding)
                                  else b.mass_matrix() for b in items))
    C = scipy.linalg.block_diag(*(b.damping_matrix() for b in items))
    K = scipy.linalg.block_diag(*(b.stiffness_matrix() for b in items))
    r = np.concatenate([b.influence_vector() for b in items])
    sizes = np.array([b.n for b in items], dtype=np.int64)
    offsets = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    return AssembledSystem(np.ascontiguousarray(M, dtype=np.float64),
                           np.ascontiguousarray(C, dtype=np.float64),
                           np.ascontiguousarray(K, dtype=np.float64),
                           np.ascontiguousarray(r, dtype=np.float64),
                           offsets)


def shared_levels(a: Building, b: Building, tol: float = 1e-6) -> list[tuple[int, int]]:
    """Pairs of floors of ``a`` and ``b`` at the same elevation, where floor-to-floor impact
    can occur.

    Parameters
    ----------
    a, b : ShearBuilding or MatrixBuilding
        The two adjacent buildings, ``a`` on the left (of a matrix building, its floor DOFs,
        or the DOFs of its faces that face the other).
    tol : float
        Two floors are at the same elevation if their levels differ by at most ``tol`` [m].

    Returns
    -------
    list of (int, int)
        ``(i, j)`` with ``a.floor_levels[i] ≈ b.floor_levels[j]``, 0-based DOF indices
        (0 = floor 1 of a shear building), by elevation. Buildings of different heights pair only up to the lower
        roof; floors at different elevations are not paired (floor-to-column impact is
        another matter).

    Raises
    ------
    ValueError
        If ``a`` or ``b`` is not a building or ``tol`` is not positive.
    """
    for label, x in (("a", a), ("b", b)):
        if not isinstance(x, BUILDING_TYPES):
            raise ValueError(f"{label} must be a ShearBuilding or a MatrixBuilding (got {x!r})")
    t = positive("tol", tol)
    fa, fb = face_dofs(a, "right"), face_dofs(b, "left")
    za, zb = a.floor_levels[fa], b.floor_levels[fb]
    pairs: list[tuple[int, int]] = []
    for i, z in enumerate(za):
        j = int(np.argmin(np.abs(zb - z)))
        # mutual nearest neighbours within tol: never pairs one floor twice
        if abs(zb[j] - z) <= t and int(np.argmin(np.abs(za - zb[j]))) == i:
            pairs.append((int(fa[i]), int(fb[j])))
    return pairs


def contact_points(a: Building, b: Building, floor_to_column: bool = True,
                   tol: float = 1e-6) -> list[tuple[float, int, float, int, float]]:
    """Where two neighbouring buildings can touch: ``(elevation, i, ξ_i, j, ξ_j)`` rows.

    Only floors take part: every DOF of a shear building, the
    :attr:`~pounding.structure.MatrixBuilding.floors` of a matrix building — or the DOFs of
    its :attr:`~pounding.structure.MatrixBuilding.faces` that face the other (``a``'s right,
    ``b``'s left) — ordered by elevation. Floors at the same elevation (within ``tol`` [m]) meet floor to floor
    (``ξ = 1`` both). With ``floor_to_column``, every other floor of one building below the
    roof of the other meets the other's column at the same elevation, in the storey below
    the other's floor ``j`` at position ``ξ_j`` (0 at the floor below it or the ground, 1 at
    floor ``j``). ``i`` and ``j`` are 0-based DOFs of ``a`` and ``b``; rows are sorted by
    elevation.
    """
    fa, fb = face_dofs(a, "right"), face_dofs(b, "left")
    za, zb = a.floor_levels[fa], b.floor_levels[fb]
    rows: list[tuple[float, int, float, int, float]] = []
    paired_a: set[int] = set()
    paired_b: set[int] = set()
    for i, j in shared_levels(a, b, tol):
        rows.append((float(a.floor_levels[i]), i, 1.0, j, 1.0))
        paired_a.add(i)
        paired_b.add(j)
    if floor_to_column:
        for levels, dofs, other, odofs, paired, left in ((za, fa, zb, fb, paired_a, True),
                                                          (zb, fb, za, fa, paired_b, False)):
            for k, z in enumerate(levels):
                i = int(dofs[k])
                if i in paired or z >= other[-1] - tol:
                    continue  # paired already, or level with / above the other's roof
                j = int(np.searchsorted(other, z))  # storey j + 1: other[j-1] < z < other[j]
                below = float(other[j - 1]) if j > 0 else 0.0
                xi = (float(z) - below) / (float(other[j]) - below)
                jd = int(odofs[j])
                rows.append((float(z), i, 1.0, jd, xi) if left else (float(z), jd, xi, i, 1.0))
    rows.sort(key=lambda r: (r[0], r[1], r[3]))
    return rows
