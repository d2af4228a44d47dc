"""matrices_from_opensees: M and condensed K of OpenSeesPy models against hand formulas.

The models are built in OpenSeesPy (the ``peers`` extra, ``pip install -e ".[test,peers]"``;
skipped, saying why, where it cannot load, and a failure under CI: ``tests/conftest.py``):

* a three-storey, one-bay shear frame (rigid beams: floor rotations fixed, the two floor nodes
  tied by equalDOF) with storey stiffness ``2 · 12 E I_j / h_j³`` (two fixed–fixed columns);
* a one-storey portal frame with a flexible beam, the joint rotations condensed out, against
  ``k = 24 E I_c / h³ · (12ρ + 1)/(12ρ + 4)``, ``ρ = (E I_b / L)/(2 E I_c / h)`` (Chopra,
  *Dynamics of Structures*, 4th ed., §1.3; derived again in the test's docstring);
* a three-node cantilever column, the rotations condensed out, against the inverse of its
  flexibility matrix ``f_ij = x_i² (3 x_j − x_i)/(6 E I)``, ``x_i <= x_j``;
* a one-storey 3-D frame with a rigid diaphragm (Transformation handler): the floor's two
  translations and its rotation against the columns' sway and torsion stiffnesses.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from pounding.structure import ShearBuilding, shear_stiffness_matrix
from pounding.structure.matrices import MatrixBuilding
from pounding.structure.opensees_matrices import matrices_from_opensees

E = 2.0e11          # Pa
A_BIG = 1.0e-2      # m², column area (axial DOFs are condensed; uncoupled from sway here)


@pytest.fixture
def ops(opensees: Any) -> Any:
    return opensees  # (conftest.py: skipped, saying why, where OpenSeesPy cannot load)


def _shear_frame(ops: Any, heights: list[float], inertias: list[float], masses: list[float],
                 bay: float = 6.0) -> list[int]:
    """Two column lines; floor j: nodes 10j+1 (left, retained) and 10j+2 (right, tied)."""
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.geomTransf("Linear", 1)
    ops.node(1, 0.0, 0.0)
    ops.node(2, bay, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    below, z, tag = (1, 2), 0.0, 1
    for j, (h, inertia, m) in enumerate(zip(heights, inertias, masses, strict=True), start=1):
        z += h
        left, right = 10 * j + 1, 10 * j + 2
        ops.node(left, 0.0, z)
        ops.node(right, bay, z)
        ops.fix(left, 0, 0, 1)          # rigid beams: the floor does not rotate
        ops.fix(right, 0, 0, 1)
        ops.equalDOF(left, right, 1)    # ... and does not stretch
        ops.mass(left, m / 2, 0.0, 0.0)
        ops.mass(right, m / 2, 0.0, 0.0)
        for bottom, top in zip(below, (left, right), strict=True):
            ops.element("elasticBeamColumn", tag, bottom, top, A_BIG, E, inertia, 1)
            tag += 1
        ops.element("elasticBeamColumn", tag, left, right, A_BIG, E, 1.0e-3, 1)   # the beam
        tag += 1
        below = (left, right)
    return [10 * j + 1 for j in range(1, len(heights) + 1)]


def test_three_storey_shear_frame_gives_the_shear_building(ops: Any) -> None:
    heights = [4.0, 3.2, 3.0]
    inertias = [3.0e-4, 2.0e-4, 1.0e-4]
    masses = [3.0e5, 2.5e5, 2.0e5]
    floors = _shear_frame(ops, heights, inertias, masses)
    M, K, labels = matrices_from_opensees(floors)
    k = np.array([2 * 12 * E * i / h**3 for i, h in zip(inertias, heights, strict=True)])
    np.testing.assert_allclose(K, shear_stiffness_matrix(k), rtol=1e-12, atol=1e-12 * k.max())
    np.testing.assert_allclose(M, np.diag(masses), rtol=1e-14, atol=0.0)
    assert labels == ("node 11 dof 1", "node 21 dof 1", "node 31 dof 1")
    # Into a MatrixBuilding and back to the shear building of the same frame.
    b = MatrixBuilding(M=M, K=K, labels=labels, elevations=np.cumsum(heights))
    sb = b.to_shear_building()
    np.testing.assert_allclose(sb.stiffnesses, k, rtol=1e-12)
    np.testing.assert_allclose(sb.masses, masses, rtol=1e-14)
    np.testing.assert_allclose(sb.heights, heights, rtol=1e-14)
    ref = ShearBuilding(masses=masses, stiffnesses=k, heights=heights)
    np.testing.assert_allclose(b.modes().periods, ref.modes().periods, rtol=1e-12)


def test_transformation_handler_gives_the_same_matrices(ops: Any) -> None:
    floors = _shear_frame(ops, [4.0, 3.0], [3.0e-4, 2.0e-4], [2.0e5, 1.0e5])
    plain = matrices_from_opensees(floors)
    trans = matrices_from_opensees(floors, constraints="Transformation")
    np.testing.assert_allclose(trans.K, plain.K, rtol=1e-12)
    np.testing.assert_allclose(trans.M, plain.M, rtol=1e-14)
    # The tied right-hand nodes are refused under Transformation, named.
    with pytest.raises(ValueError, match=r"node 12 dof 1: node 12 is constrained by an MP"):
        matrices_from_opensees([12, 22], constraints="Transformation")


def _portal(ops: Any, Ic: float, Ib: float, h: float = 3.0, L: float = 6.0, m: float = 1.0e4,
            J: float = 0.0) -> None:
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.geomTransf("Linear", 1)
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.node(3, 0.0, h)
    ops.node(4, L, h)
    ops.fix(3, 0, 1, 0)          # axially rigid columns
    ops.fix(4, 0, 1, 0)
    ops.equalDOF(3, 4, 1)        # axially rigid beam
    ops.element("elasticBeamColumn", 1, 1, 3, A_BIG, E, Ic, 1)
    ops.element("elasticBeamColumn", 2, 2, 4, A_BIG, E, Ic, 1)
    ops.element("elasticBeamColumn", 3, 3, 4, A_BIG, E, Ib, 1)
    ops.mass(3, m, 0.0, J)


@pytest.mark.parametrize("ratio", [0.0625, 0.5, 4.0])
def test_portal_frame_condensed_lateral_stiffness(ops: Any, ratio: float) -> None:
    """Sway Δ, joint rotation θ (equal at both joints). Joint equilibrium:
    ``(4 E I_c/h + 6 E I_b/L) θ = 6 E I_c/h² Δ``; base shear
    ``2 (12 E I_c/h³ Δ − 6 E I_c/h² θ)``, which is ``k Δ`` with Chopra's
    ``k = 24 E I_c/h³ (12ρ + 1)/(12ρ + 4)``, ``ρ = (E I_b/L)/(2 E I_c/h)``."""
    h, L, Ic = 3.0, 6.0, 2.0e-4
    Ib = ratio * Ic
    _portal(ops, Ic, Ib, h, L)
    M, K, _ = matrices_from_opensees([3])
    rho = (E * Ib / L) / (2 * E * Ic / h)
    k = 24 * E * Ic / h**3 * (12 * rho + 1) / (12 * rho + 4)
    assert K.shape == (1, 1)
    assert K[0, 0] == pytest.approx(k, rel=1e-12)
    assert M[0, 0] == pytest.approx(1.0e4, rel=1e-15)


def test_portal_frame_guyan_mass_carries_the_joint_inertia(ops: Any) -> None:
    """Guyan: the joints turn by θ = 6 E I_c/h² / (4 E I_c/h + 6 E I_b/L) per unit sway, so
    a rotational inertia J at one joint adds J θ² to the lateral mass."""
    h, L, Ic, Ib, m, J = 3.0, 6.0, 2.0e-4, 1.0e-4, 1.0e4, 3.0e3
    _portal(ops, Ic, Ib, h, L, m=m, J=J)
    theta = (6 * E * Ic / h**2) / (4 * E * Ic / h + 6 * E * Ib / L)
    retained = matrices_from_opensees([3])
    guyan = matrices_from_opensees([3], mass="guyan")
    assert retained.M[0, 0] == pytest.approx(m, rel=1e-15)
    assert guyan.M[0, 0] == pytest.approx(m + J * theta**2, rel=1e-12)
    np.testing.assert_allclose(guyan.K, retained.K, rtol=0.0)


def test_cantilever_condensed_stiffness_is_inverse_flexibility(ops: Any) -> None:
    """Rotations (and axial DOFs) condensed out of a cantilever with nodes at x = 2, 5, 6 m:
    ``K̂ = F⁻¹``, ``F_ij = x_i² (3 x_j − x_i)/(6 E I)`` for ``x_i <= x_j`` (unit load at
    ``x_j``, deflection at ``x_i``)."""
    inertia = 4.0e-4
    xs = [2.0, 5.0, 6.0]
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.geomTransf("Linear", 1)
    ops.node(1, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    for j, x in enumerate(xs, start=2):
        ops.node(j, 0.0, x)
        ops.mass(j, 1.0e3 * j, 0.0, 0.0)
        ops.element("elasticBeamColumn", j, j - 1, j, A_BIG, E, inertia, 1)
    M, K, labels = matrices_from_opensees([(2, 1), (3, 1), (4, 1)])
    F = np.empty((3, 3))
    for i, xi in enumerate(xs):
        for j, xj in enumerate(xs):
            a, b = min(xi, xj), max(xi, xj)
            F[i, j] = a**2 * (3 * b - a) / (6 * E * inertia)
    np.testing.assert_allclose(K, np.linalg.inv(F), rtol=1e-10, atol=1e-10 * np.abs(K).max())
    np.testing.assert_allclose(K @ F, np.eye(3), atol=1e-10)
    # A linear model: the current tangent stiffness is the initial stiffness.
    np.testing.assert_array_equal(matrices_from_opensees([2, 3, 4], stiffness="current").K, K)
    np.testing.assert_array_equal(M, np.diag([2.0e3, 3.0e3, 4.0e3]))
    assert labels == ("node 2 dof 1", "node 3 dof 1", "node 4 dof 1")


def test_the_domain_is_not_moved(ops: Any) -> None:
    floors = _shear_frame(ops, [4.0, 3.0], [3.0e-4, 2.0e-4], [2.0e5, 1.0e5])
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(21, 1.0e5, -1.0e5, 0.0)
    matrices_from_opensees(floors)
    for node in (11, 12, 21, 22):
        assert ops.nodeDisp(node) == [0.0, 0.0, 0.0]
    assert ops.getTime() == 0.0


def test_bad_choices_are_named(ops: Any) -> None:
    floors = _shear_frame(ops, [4.0, 3.0], [3.0e-4, 2.0e-4], [2.0e5, 1.0e5])
    with pytest.raises(ValueError, match=r"node 99 dof 1: node 99 is not in the OpenSees domain"):
        matrices_from_opensees([99])
    with pytest.raises(ValueError, match=r"node 1 dof 1 is fixed or constrained"):
        matrices_from_opensees([1])
    with pytest.raises(ValueError, match=r"node 11 dof 3 is fixed or constrained"):
        matrices_from_opensees([(11, 3)])
    with pytest.raises(ValueError, match=r"node 11 dof 4: node 11 has 3 DOFs"):
        matrices_from_opensees([(11, 4)])
    with pytest.raises(ValueError, match=r"node 12 dof 1 is the same equation as node 11 dof 1"):
        matrices_from_opensees([11, 12])
    assert floors == [11, 21]


def test_unrestrained_condensed_dof_is_refused(ops: Any) -> None:
    _portal(ops, 2.0e-4, 1.0e-4)
    ops.node(9, 20.0, 0.0)     # a node that nothing holds
    with pytest.raises(ValueError, match=r"not restrained by stiffness alone .* smallest "
                                         r"eigenvalue -?0\b"):
        matrices_from_opensees([3])


def test_plain_handler_refuses_a_rigid_link(ops: Any) -> None:
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.geomTransf("Linear", 1)
    ops.node(1, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.node(2, 0.0, 3.0)
    ops.node(3, 2.0, 3.0)
    ops.element("elasticBeamColumn", 1, 1, 2, A_BIG, E, 1.0e-4, 1)
    ops.rigidLink("beam", 2, 3)
    ops.mass(2, 100.0, 0.0, 0.0)
    with pytest.raises(ValueError, match=r"did not apply the MP constraint of node 3 on node 2"):
        matrices_from_opensees([2])
    # Under Transformation the rigid link is applied: the lateral stiffness is the column's
    # cantilever stiffness with the rotation condensed out, 3 E I / h³.
    _, K, _ = matrices_from_opensees([2], constraints="Transformation")
    assert K[0, 0] == pytest.approx(3 * E * 1.0e-4 / 27.0, rel=1e-12)


def test_rigid_diaphragm_floor_in_plan(ops: Any) -> None:
    """A one-storey 3-D frame: four columns at (±a, ±b), fixed at the base, their tops kept
    from bending rotations (rigid beams) and tied by a rigid diaphragm to a master node at
    the centre. On the master's x, y and rotation about z: ``k_x = k_y = 4 · 12 E I/h³``,
    ``k_θ = Σ 12 E I/h³ (x_i² + y_i²) + 4 G J/h`` (each column's sway stiffness at its lever
    arm, plus its torsion), no coupling (the plan is symmetric)."""
    E_, G, A, inertia, J, h, a, b = 2.0e11, 8.0e10, 1.0e-2, 2.0e-4, 3.0e-4, 3.0, 4.0, 2.5
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    for i, (x, y) in enumerate([(a, b), (-a, b), (-a, -b), (a, -b)], start=1):
        ops.node(i, x, y, 0.0)
        ops.fix(i, 1, 1, 1, 1, 1, 1)
        ops.node(10 + i, x, y, h)
        ops.fix(10 + i, 0, 0, 0, 1, 1, 0)
        ops.element("elasticBeamColumn", i, i, 10 + i, A, E_, G, J, inertia, inertia, 1)
    ops.node(100, 0.0, 0.0, h)
    ops.fix(100, 0, 0, 1, 1, 1, 0)
    ops.rigidDiaphragm(3, 100, 11, 12, 13, 14)
    ops.mass(100, 1.0e4, 1.0e4, 0.0, 0.0, 0.0, 5.0e4)
    with pytest.raises(ValueError, match=r"did not apply the MP constraint of node 11 on node "
                                         r"100 .*use constraints='Transformation'"):
        matrices_from_opensees([(100, 1), (100, 2), (100, 6)])
    M, K, labels = matrices_from_opensees([(100, 1), (100, 2), (100, 6)],
                                          constraints="Transformation")
    k = 12 * E_ * inertia / h**3
    expected = np.diag([4 * k, 4 * k, 4 * k * (a * a + b * b) + 4 * G * J / h])
    np.testing.assert_allclose(K, expected, rtol=1e-12, atol=1e-12 * expected.max())
    np.testing.assert_array_equal(M, np.diag([1.0e4, 1.0e4, 5.0e4]))
    assert labels == ("node 100 dof 1", "node 100 dof 2", "node 100 dof 6")


@pytest.mark.parametrize("kwargs, message", [
    ({"dofs": []}, "dofs must be a non-empty sequence"),
    ({"dofs": "12"}, "dofs must be a non-empty sequence"),
    ({"dofs": [(1, 0)]}, r"each entry of dofs must be a node tag or a \(node tag, dof\) pair"),
    ({"dofs": [(1, 2, 3)]}, r"each entry of dofs must be"),
    ({"dofs": [1.5]}, r"each entry of dofs must be"),
    ({"dofs": [1], "mass": "consistent"}, "mass must be 'retained' or 'guyan'"),
    ({"dofs": [1], "stiffness": "secant"}, "stiffness must be 'initial' or 'current'"),
    ({"dofs": [1], "constraints": "Penalty"}, "constraints must be 'Plain' or 'Transformation'"),
])
def test_arguments_are_checked_before_opensees_is_imported(kwargs: dict[str, object],
                                                           message: str) -> None:
    with pytest.raises(ValueError, match=message):
        matrices_from_opensees(**kwargs)  # type: ignore[arg-type]
