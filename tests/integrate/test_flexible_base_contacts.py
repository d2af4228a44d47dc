"""Contacts with a building on a flexible base: a floor striking the ground storey's column
of a building on a footing strikes a column whose foot moves with the footing."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import el_centro
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.foundation import Footing, Soil, flexible_base

SOIL = Soil(150.0, 1800.0, 0.33)
SPEC = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
REGULAR = ShearBuilding.uniform(6, 4.0e5, 5.0e8, height=3.0, name="regular")
TALL_FOOT = ShearBuilding([5.0e5, 4.0e5, 4.0e5, 3.5e5], [4.0e8, 6.0e8, 6.0e8, 5.0e8],
                          [4.5, 3.5, 3.5, 3.5], name="tall ground storey")


def _pair(footing: Footing) -> PoundingModel:
    return PoundingModel([REGULAR, flexible_base(TALL_FOOT, footing, SOIL)], [0.02], SPEC,
                         floor_to_column=True)


def test_a_column_point_of_the_ground_storey_moves_with_the_footing() -> None:
    """Floor 1 of the left building (3 m) strikes the right one's ground storey (4.5 m) at
    ξ = 2/3: on a footing with mass the point moves as ``(1 − ξ) u_f + ξ x_1`` — the rigid
    sway and rocking of the footing (``u_f + z φ``, linear in the height, plus the storey's
    own deformation, linear too) — and takes ``(1 − ξ) F`` to the footing, not the ground:
    its penetration from the run's displacements, written out here, is the kernel's."""
    model = _pair(Footing(radius=5.0, mass=3.0e5, inertia=2.0e6))
    (c,) = [c for c in model.contacts if not c.right.is_floor and c.right.upper == 0]
    assert c.right.lower == TALL_FOOT.n  # the footing's sway DOF (the building's own numbering)
    assert c.right.xi == pytest.approx(3.0 / 4.5)
    sway = model.system.offsets[1] + TALL_FOOT.n
    res = simulate(model, el_centro(), duration=10.0, dt=0.002)
    u = res.displacement
    xi = 3.0 / 4.5
    struck = (1 - xi) * u[:, sway] + xi * u[:, model.system.offsets[1]]
    expected = u[:, 0] - struck - 0.02
    assert np.max(np.abs(res.penetration[:, c.index] - expected)) < 1e-12
    assert np.max(np.abs(u[:, sway])) > 1e-3  # (the footing did sway: the test means it)
    assert res.energy_balance_error < 1e-8


@pytest.mark.parametrize("footing", [Footing(radius=5.0),
                                     Footing(radius=5.0, mass=3e5, inertia=2e6,
                                             embedment=1.0)])
def test_a_ground_storey_column_point_it_cannot_follow_is_refused(footing: Footing) -> None:
    """A massless footing (condensed out) or an embedded one (the foot of the ground storey
    moves by ``u_f + D φ``: three DOFs): a column point of the ground storey is refused in
    one line; slab-to-slab contacts stay."""
    with pytest.raises(ValueError, match="ground storey of a building on a flexible base"):
        _ = _pair(footing).contacts
    model = PoundingModel([REGULAR, flexible_base(TALL_FOOT, footing, SOIL)], [0.02], SPEC,
                          floor_to_column=False)
    assert len(model.contacts) > 0
