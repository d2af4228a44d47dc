"""Buildings in plan (pounding.structure.plan): matrices against closed forms and against the
rigid-floor kinematics written out here, not through the module's own functions."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest

from pounding.structure import ShearBuilding, shear_stiffness_matrix
from pounding.structure import plan as plan_module
from pounding.structure.plan import LateralElement, PlanBuilding
from pounding.structure.plan_row import facing_points


def one_storey(kx_right: float = 1e8) -> PlanBuilding:
    """20 m × 10 m, frames at the four edges; the y frame at x = 20 m may be stiffer."""
    return PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0, elements=[
        LateralElement(0.0, 0.0, "x", 5e7), LateralElement(0.0, 10.0, "x", 5e7),
        LateralElement(0.0, 5.0, "y", 5e7), LateralElement(20.0, 5.0, "y", kx_right)])


def test_one_storey_periods_match_the_closed_form_of_an_unsymmetric_plan() -> None:
    """Chopra §9.5: u_x is uncoupled (ω² = k_x/m); u_y and θ couple through the stiffness
    eccentricity e_x: det([[k_y − ω² m, e k_y], [e k_y, k_θ − ω² I]]) = 0, a quadratic in ω²,
    with k_θ the torsional stiffness about the centre of mass."""
    b = one_storey()
    m, inertia = 4e5, 4e5 * (20.0 ** 2 + 10.0 ** 2) / 12.0
    kx, ky = 1e8, 1.5e8
    e = (0.0 * 5e7 + 20.0 * 1e8) / ky - 10.0  # centre of stiffness minus centre of mass
    k_theta = 5e7 * 5.0 ** 2 * 2 + 5e7 * 10.0 ** 2 + 1e8 * 10.0 ** 2
    w2 = np.roots([m * inertia, -(ky * inertia + k_theta * m), ky * k_theta - (e * ky) ** 2])
    expected = sorted([2 * math.pi / math.sqrt(kx / m), *(2 * math.pi / np.sqrt(w2))],
                      reverse=True)
    assert np.allclose(b.modes().periods, expected, rtol=1e-12)
    assert b.stiffness_eccentricity()[0] == pytest.approx([e, 0.0], abs=1e-12)


def test_a_symmetric_plan_is_a_shear_building_in_each_direction() -> None:
    """Elements symmetric about the centre of mass: x, y and θ uncouple, and the x DOFs carry
    the shear-building stiffness matrix of the summed storey stiffnesses (Chopra §9.2)."""
    kx = np.array([3e8, 2e8, 1e8])
    ky = np.array([4e8, 3e8, 2e8])
    b = PlanBuilding(masses=[3e5, 3e5, 2e5], heights=[4.0, 3.0, 3.0], width=30.0, depth=12.0,
                     elements=[LateralElement(0.0, 0.0, "x", kx / 2),
                               LateralElement(0.0, 12.0, "x", kx / 2),
                               LateralElement(0.0, 6.0, "y", ky / 2),
                               LateralElement(30.0, 6.0, "y", ky / 2)])
    K = b.stiffness_matrix()
    ix, iy, it = np.arange(0, 9, 3), np.arange(1, 9, 3), np.arange(2, 9, 3)
    assert np.array_equal(K[np.ix_(ix, ix)], shear_stiffness_matrix(kx))
    assert np.array_equal(K[np.ix_(iy, iy)], shear_stiffness_matrix(ky))
    assert not K[np.ix_(ix, iy)].any() and not K[np.ix_(ix, it)].any()
    assert not K[np.ix_(iy, it)].any()
    # the torsional stiffness of each storey: Σ k r² about the centre of mass
    kt = kx / 2 * 6.0 ** 2 * 2 + ky / 2 * 15.0 ** 2 * 2
    assert np.allclose(K[np.ix_(it, it)], shear_stiffness_matrix(kt), rtol=1e-14)
    # and the x periods are those of the shear building
    sb = ShearBuilding(masses=[3e5, 3e5, 2e5], stiffnesses=kx, heights=[4.0, 3.0, 3.0])
    assert set(np.round(sb.modes().periods, 12)) <= set(np.round(b.modes().periods, 12))
    assert np.array_equal(b.floor_levels, [4.0, 7.0, 10.0])


def test_stiffness_is_the_strain_energy_of_the_elements_from_rigid_floor_kinematics() -> None:
    """qᵀ K q = Σ k (deformation)² with each element's deformation computed from the rigid
    motion of its point on the floors above and below (centres of mass differ floor to floor,
    an inclined element included)."""
    rng = np.random.default_rng(7)
    centres = [(9.0, 5.5), (10.5, 4.0), (8.0, 6.0)]
    elements = [LateralElement(1.0, 0.5, "x", [2e8, 1e8, 5e7]),
                LateralElement(2.0, 9.0, "x", [1e8, 1e8, 1e8]),
                LateralElement(0.5, 3.0, "y", [3e8, 2e8, 1e8]),
                LateralElement(19.0, 7.0, "y", [1e8, 2e8, 0.0]),
                LateralElement(15.0, 2.0, 30.0, [4e7, 4e7, 4e7]),
                LateralElement(12.0, 8.0, "y", [0.0, 0.0, 8e7])]
    b = PlanBuilding(masses=[2e5, 2e5, 1e5], heights=[3.0, 3.0, 3.0], width=20.0, depth=10.0,
                     elements=elements, mass_centres=centres)
    K = b.stiffness_matrix()
    for _ in range(5):
        q = rng.normal(size=9) * np.tile([0.01, 0.01, 0.001], 3)

        def moved(floor: int, x: float, y: float) -> np.ndarray:
            if floor < 0:
                return np.zeros(2)
            ux, uy, th = q[3 * floor: 3 * floor + 3]
            xc, yc = centres[floor]
            # rotate the arm (x − xc, y − yc) by a small θ: (−θ (y − yc), θ (x − xc))
            return np.array([ux - th * (y - yc), uy + th * (x - xc)])

        energy = 0.0
        for e in elements:
            beta = math.radians(e.direction) if not isinstance(e.direction, str) else \
                (0.0 if e.direction == "x" else math.pi / 2)
            d = np.array([math.cos(beta), math.sin(beta)])
            k = e.storey_stiffnesses(3)
            for j in range(3):
                energy += k[j] * (d @ (moved(j, e.x, e.y) - moved(j - 1, e.x, e.y))) ** 2
        assert q @ K @ q == pytest.approx(energy, rel=1e-12)


def test_point_weights_are_the_rigid_floor_motion() -> None:
    b = one_storey()
    q = np.array([0.01, -0.02, 0.003])
    # corner (20, 10): centre (10, 5); u_x = u − θ (10 − 5), u_y = v + θ (20 − 10)
    assert b.point_displacement(q, 0, 20.0, 10.0, "x") == pytest.approx(0.01 - 0.003 * 5)
    assert b.point_displacement(q, 0, 20.0, 10.0, "y") == pytest.approx(-0.02 + 0.003 * 10)
    # along 45°: the projection of the two
    assert b.point_displacement(q, 0, 20.0, 10.0, 45.0) == pytest.approx(
        (0.01 - 0.015 + -0.02 + 0.03) / math.sqrt(2))
    assert b.point_weights(0, 10.0, 5.0, "x") == [(0, 1.0)]  # the centre itself: no lever
    R = b.influence_matrix()
    assert np.array_equal(R, [[1, 0], [0, 1], [0, 0]])


def test_facing_points_are_the_ends_of_the_overlap() -> None:
    a = one_storey()
    shifted = PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0,
                           elements=a.elements, site_y=6.0)
    assert facing_points(a, shifted) == [6.0, 10.0]
    assert facing_points(a, a) == [0.0, 10.0]
    far = PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0,
                       elements=a.elements, site_y=12.0)
    assert facing_points(a, far) == []


@pytest.mark.parametrize(("kwargs", "message"), [
    (dict(elements=[LateralElement(0.0, 0.0, "x", 1e8), LateralElement(0.0, 9.0, "x", 1e8)]),
     "do not restrain floor 1 in y"),
    (dict(elements=[]), "elements: give"),
    (dict(width=-1.0), "width must be a finite number > 0"),
    (dict(mass_centres=[[1.0, 2.0, 3.0]]), "mass_centres must be"),
    (dict(elements=[LateralElement(0.0, 0.0, "x", [1e8, 1e8])]), "one value per storey (1)"),
])
def test_bad_input_names_the_field(kwargs: dict, message: str) -> None:
    base = dict(masses=[4e5], heights=[3.5], width=20.0, depth=10.0,
                elements=one_storey().elements)
    with pytest.raises(ValueError, match=None) as err:
        PlanBuilding(**{**base, **kwargs})
    assert message in str(err.value)


def test_bad_element_direction() -> None:
    with pytest.raises(ValueError, match="direction must be 'x', 'y' or an angle"):
        LateralElement(0.0, 0.0, "z", 1e8)


def test_docstring_examples_run() -> None:
    failures, tried = doctest.testmod(plan_module, verbose=False)
    assert tried > 0 and failures == 0


def test_a_given_stiffness_matrix_is_the_same_building() -> None:
    b = one_storey()
    same = PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0,
                        stiffness=b.stiffness_matrix())
    assert np.array_equal(same.stiffness_matrix(), b.stiffness_matrix())
    assert np.array_equal(same.modes().periods, b.modes().periods)
    assert np.array_equal(same.damping_matrix(), b.damping_matrix())
    K = b.stiffness_matrix()
    K[0, 1] = 1e6
    with pytest.raises(ValueError, match=r"stiffness must be symmetric: stiffness\[0, 1\]"):
        PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0, stiffness=K)
    with pytest.raises(ValueError, match="not both"):
        PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0,
                     stiffness=b.stiffness_matrix(), elements=b.elements)
    with pytest.raises(ValueError, match="must be 3 × 3"):
        PlanBuilding(masses=[4e5], heights=[3.5], width=20.0, depth=10.0, stiffness=np.eye(2))
