"""A frame's condensation for a set of hinge tangents, updated from the first set's by the
Woodbury identity (:mod:`pounding.structure.frame_condensation`), against the same set
factorised afresh: condensed stiffness, hinge rotations per floor displacement, every DOF per
floor displacement and the solve of the massless DOFs; and the sets the update leaves to a
fresh factorisation (a joint with no stiffness left, a mechanism, many hinges changed)."""

from __future__ import annotations

import numpy as np
import pytest

from pounding.hysteresis.hinges import BilinearHinge
from pounding.structure.frame import Frame, FrameHinge, regular_frame
from pounding.structure.frame_analysis import gravity
from pounding.structure.frame_condensation import UPDATE_LIMIT, Condensation


def _frame() -> Frame:
    """4 storeys, 3 bays, bilinear hinges at every member end, gravity and P-Delta."""
    law = BilinearHinge(k0=2e10, m_y=4e5, hardening=0.03)
    return regular_frame([6.0, 7.0, 6.0], [4.5, 3.6, 3.6, 3.6], column_EI=[4e8, 3e8, 3e8, 2e8],
                         beam_EI=3e8, column_hinge=law, beam_hinge=law, floor_mass=1e5,
                         beam_load=2e4, leaning_load=4e5, geometry="p-delta", name="four")


def _pair() -> tuple[Condensation, Condensation, np.ndarray]:
    """Two condensations of the frame (one to update, one to factorise every set afresh)
    and its elastic tangents; the first has the elastic set as its anchor."""
    frame = _frame()
    state = gravity(frame)
    k0 = np.array([h.law.k0 for h in frame.hinges])
    updated = Condensation(state.base, state.dofs, frame.name)
    updated.part(k0)
    fresh = Condensation(state.base, state.dofs, frame.name)
    return updated, fresh, k0


def _agree(a, b, rtol: float) -> None:  # type: ignore[no-untyped-def]
    for name in ("Kc", "A", "P"):
        x, y = getattr(a, name), getattr(b, name)
        assert np.max(np.abs(x - y)) <= rtol * np.max(np.abs(y)), name
    assert np.array_equal(a.live, b.live) and np.array_equal(a.dead, b.dead)
    rhs = np.linspace(-1.0, 2.0, a.live.size) * 1e5
    ya, yb = a.solve(rhs), b.solve(rhs)
    assert np.max(np.abs(ya - yb)) <= rtol * np.max(np.abs(yb))


@pytest.mark.parametrize("changed", [1, 4, 12, 24])
def test_an_updated_condensation_is_the_factorised_one(changed: int) -> None:
    updated, fresh, k0 = _pair()
    rng = np.random.default_rng(changed)
    for _ in range(3):
        k = k0.copy()
        c = rng.choice(k.size, changed, replace=False)
        k[c] = np.where(rng.random(changed) < 0.5, 0.0, 0.03 * k0[c])  # plastic, hardening
        got = updated.part(k)
        assert updated._updated(k) is not None  # (the update, not a fresh factorisation)
        # measured 2026-11-27: 7e-15 … 1.1e-13 (the largest of Kc, A, P and the solve)
        _agree(got, fresh._condense(k), 1e-11)


def test_a_joint_left_without_stiffness_is_factorised_afresh() -> None:
    updated, fresh, k0 = _pair()
    frame = _frame()
    # every hinge at the roof's left joint (its column's top, its beam's left end) at zero
    # tangent: the joint's rotation has no stiffness (it stays where it is)
    joint = int(np.flatnonzero((frame.nodes[:, 0] == 0.0)
                               & (frame.nodes[:, 1] == frame.nodes[:, 1].max()))[0])
    at = [h for h, fh in enumerate(frame.hinges) if frame.elements[fh.element, fh.end] == joint]
    k = k0.copy()
    k[at] = 0.0
    assert updated._updated(k) is None
    got = updated.part(k)
    assert got.dead.size == 1
    _agree(got, fresh._condense(k), 1e-12)


def test_a_mechanism_without_mass_is_refused_as_before() -> None:
    # a portal with a massless cantilever beam out of its top right joint, hinged at its
    # root: at zero tangent there the cantilever swings freely (no unique equilibrium)
    law = BilinearHinge(k0=2e10, m_y=4e5, hardening=0.03)
    supports = np.zeros((5, 3), dtype=bool)
    supports[[0, 1]] = True
    masses = np.zeros((5, 3))
    masses[[2, 3], 0] = 5e4
    frame = Frame(nodes=[[0, 0], [6, 0], [0, 4], [6, 4], [8, 4]],
                  elements=[[0, 2], [1, 3], [2, 3], [3, 4]], EA=[1e12] * 4, EI=[3e8] * 4,
                  supports=supports, masses=masses,
                  hinges=(FrameHinge(0, 0, law), FrameHinge(1, 0, law), FrameHinge(3, 0, law)),
                  name="cantilevered")
    state = gravity(frame)
    k0 = np.array([h.law.k0 for h in frame.hinges])
    updated = Condensation(state.base, state.dofs, frame.name)
    updated.part(k0)
    k = k0.copy()
    k[2] = 0.0
    with pytest.raises(ValueError, match="no unique equilibrium") as fresh_error:
        Condensation(state.base, state.dofs, frame.name).part(k)
    assert updated._updated(k) is None
    with pytest.raises(ValueError, match="no unique equilibrium") as updated_error:
        updated.part(k)
    assert str(updated_error.value) == str(fresh_error.value)


def test_many_hinges_changed_are_factorised_afresh() -> None:
    updated, fresh, k0 = _pair()
    k = 0.5 * k0
    k[: int((1 - UPDATE_LIMIT) * k.size) - 1] = k0[: int((1 - UPDATE_LIMIT) * k.size) - 1]
    assert np.count_nonzero(k != k0) > UPDATE_LIMIT * k.size
    assert updated._updated(k) is None
    _agree(updated.part(k), fresh._condense(k), 1e-12)
