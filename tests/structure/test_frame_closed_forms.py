"""Frames against closed forms: periods, mechanism loads, buckling loads, P-Delta stiffness.

Every expected value here is a textbook formula, computed in the test, not by the frame code:

* a portal frame with a rigid beam sways with stiffness ``2 · 12 EI / h³`` (Chopra, *Dynamics
  of Structures*, 4th ed., Example 1.1);
* its sway mechanism with plastic moments ``M_p`` in the columns carries ``4 M_p / h``
  (Neal, *The Plastic Methods of Structural Analysis*, §2.4);
* a cantilever column buckles at ``π² EI / (4 L²)`` (Timoshenko & Gere, *Theory of Elastic
  Stability*, §2.1); one element with the consistent geometric stiffness gives
  ``2.4860 EI/L²`` (McGuire, Gallagher & Ziemian, §8.4, +0.75 %), one with the P-Delta string
  stiffness ``3 EI/L²``;
* a cantilever's lateral stiffness under an axial load ``P`` with P-Delta is
  ``3 EI/L³ − P/L`` (the string stiffness of the chord).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
from pounding.structure.frame import Frame, regular_frame
from pounding.structure.frame_analysis import frame_modes, gravity, pushover

EI_CANT = 1.0e7
L_CANT = 5.0


def _cantilever(n_el: int, P: float, geometry: str) -> Frame:
    ys = np.linspace(0.0, L_CANT, n_el + 1)
    supports = np.zeros((n_el + 1, 3), dtype=bool)
    supports[0] = True
    loads = np.zeros((n_el + 1, 3))
    loads[-1, 1] = -P
    return Frame(nodes=np.c_[np.zeros(n_el + 1), ys],
                 elements=np.c_[np.arange(n_el), np.arange(1, n_el + 1)],
                 EA=1e12, EI=EI_CANT, supports=supports, nodal_loads=loads,
                 geometry=geometry, diaphragm=False, name="cantilever")


def _stable(n_el: int, P: float, geometry: str) -> bool:
    try:
        gravity(_cantilever(n_el, P, geometry))
    except ValueError as exc:
        # past the buckling load, or so close to it that the lateral stiffness is lost
        assert ("buckles under its gravity loads" in str(exc)
                or "cannot carry its gravity loads" in str(exc))
        return False
    return True


def _buckling_load(n_el: int, geometry: str) -> float:
    p_euler = math.pi ** 2 * EI_CANT / (4 * L_CANT ** 2)
    lo, hi = 0.5 * p_euler, 2.0 * p_euler
    for _ in range(45):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _stable(n_el, mid, geometry) else (lo, mid)
    return lo


def test_portal_with_rigid_beam_sways_at_the_two_column_period() -> None:
    m, EI, h = 1.0e5, 2.0e8, 4.0
    f = regular_frame(6.0, h, n_storeys=1, column_EI=EI, beam_EI=EI * 1e8, column_EA=1e16,
                      floor_mass=m)
    periods = frame_modes(f)[0]
    expected = 2 * math.pi / math.sqrt(2 * 12 * EI / h ** 3 / m)
    assert periods[0] == pytest.approx(expected, rel=1e-6)


def test_portal_sway_mechanism_carries_four_mp_over_h() -> None:
    f = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                      column_hinge=ElasticPlastic(k0=1e11, m_y=3e5),
                      beam_hinge=ElasticPlastic(k0=1e11, m_y=6e5))
    r = pushover(f, 0.2)
    assert r.stopped == "target"
    assert r.peak_base_shear == pytest.approx(4 * 3e5 / 4.0, rel=1e-9)
    # the four column hinges are plastic, the beam's are not
    assert np.abs(r.hinge_moments[-1][:4]) == pytest.approx(np.full(4, 3e5), rel=1e-9)
    assert np.all(np.abs(r.hinge_moments[-1][4:]) < 6e5)


def test_portal_elastic_branch_matches_the_elastic_stiffness() -> None:
    """Before the first hinge yields, base shear / roof displacement is the frame's lateral
    stiffness, which for a portal with equal EI is, by slope deflection (Chopra Example 1.1,
    with beam flexibility): k = 24 EI/h³ (12 ρ + 1)/(12 ρ + 4), ρ = (EI_b/L)/(2 EI_c/h)
    (Chopra's ρ = I_b/(4 I_c) for L = 2h)."""
    EI, h, L = 2.0e8, 4.0, 6.0
    f = regular_frame(L, h, n_storeys=1, column_EI=EI, beam_EI=EI, column_EA=1e16,
                      beam_EA=1e16, column_hinge=ElasticPlastic(k0=1e16, m_y=3e5),
                      beam_hinge=ElasticPlastic(k0=1e16, m_y=6e5))
    r = pushover(f, 0.2)
    rho = (EI / L) / (2 * EI / h)
    k = 24 * EI / h ** 3 * (12 * rho + 1) / (12 * rho + 4)
    assert r.base_shear[1] / r.roof_displacement[1] == pytest.approx(k, rel=1e-6)


@pytest.mark.parametrize(("n_el", "geometry", "coefficient", "rel"), [
    (1, "p-delta", 3.0, 1e-6),
    (1, "consistent", 2.4860, 1e-4),
    (4, "consistent", math.pi ** 2 / 4, 1e-4),
    (16, "p-delta", math.pi ** 2 / 4, 1e-3),
])
def test_cantilever_buckling_load(n_el: int, geometry: str, coefficient: float,
                                  rel: float) -> None:
    assert _buckling_load(n_el, geometry) == pytest.approx(
        coefficient * EI_CANT / L_CANT ** 2, rel=rel)


def test_lateral_stiffness_under_gravity_is_reduced_by_p_over_l() -> None:
    P = 0.4 * 3 * EI_CANT / L_CANT ** 2
    state = gravity(_cantilever(1, P, "p-delta"))
    tip = state.dofs.node[-1, 0]
    F = np.zeros(state.dofs.n)
    F[tip] = 1.0
    k = 1.0 / np.linalg.solve(state.base, F)[tip]
    assert k == pytest.approx(3 * EI_CANT / L_CANT ** 3 - P / L_CANT, rel=1e-9)


def test_leaning_column_reduces_a_storey_by_p_over_h() -> None:
    """A one-storey frame with a rigid beam and a leaning column carrying P: lateral stiffness
    24 EI/h³ − P/h (FEMA P695 §6 / Gupta & Krawinkler 1999)."""
    EI, h, P = 2.0e8, 4.0, 2.0e6
    f = regular_frame(6.0, h, n_storeys=1, column_EI=EI, beam_EI=EI * 1e8, column_EA=1e16,
                      floor_mass=1e5, leaning_load=P)
    Kc = frame_modes(f)[3]
    assert Kc[0, 0] == pytest.approx(24 * EI / h ** 3 - P / h, rel=1e-6)


def test_bilinear_hinge_follows_the_bilinear_storey_law() -> None:
    """The hinge's bilinear law and the storey's (a separate compiled implementation,
    :mod:`pounding.hysteresis.bilinear`) agree along a cyclic path."""
    from pounding.hysteresis import Bilinear, respond_drift_path
    from pounding.hysteresis.hinges import moment_path

    path = np.concatenate([np.linspace(0, 0.02, 7), np.linspace(0.02, -0.03, 11),
                           np.linspace(-0.03, 0.01, 5)])
    hinge = moment_path(BilinearHinge(k0=1e8, m_y=3e5, hardening=0.03), path)
    storey = respond_drift_path(Bilinear(yield_force=3e5, hardening=0.03), 1e8, path)
    assert hinge == pytest.approx(storey, rel=1e-12, abs=1e-6)


def test_fractures_shed_their_moment_in_equilibrium() -> None:
    """A portal on IMK hinges whose left base fractures first (θ_u = 0.08 rad, the others
    0.12 rad), pushed until every column hinge has fractured: at every point of the curve the
    base shear equals the columns' shears from their end moments, (ΣM)/h (statics of the
    two columns, independent of the load factor's bookkeeping) — before and after each
    fracture's moment is shed — and the frame ends with no strength."""
    from pounding.hysteresis.imk import IMKBilinear
    from pounding.structure.frame import FrameHinge

    lk = dict(k0=1e11, m_y=3e5, theta_p=0.025, theta_pc=0.15, mc_my=1.1, kappa=0.4)
    f = regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8,
                      column_hinge=IMKBilinear(**lk, theta_u=0.12),
                      beam_hinge=ElasticPlastic(k0=1e11, m_y=6e5))
    hinges = list(f.hinges)
    hinges[0] = FrameHinge(0, 0, IMKBilinear(**lk, theta_u=0.08))
    f = Frame(nodes=f.nodes, elements=f.elements, EA=f.EA, EI=f.EI, supports=f.supports,
              hinges=tuple(hinges))
    r = pushover(f, 0.8)
    assert r.stopped == "target"
    columns = r.hinge_moments[:, :4].sum(axis=1) / 4.0
    np.testing.assert_allclose(r.base_shear, columns, rtol=0, atol=1e-6 * 3e5)
    drops = np.flatnonzero(np.diff(r.base_shear) < -1e3)
    assert any(r.roof_displacement[i + 1] == pytest.approx(r.roof_displacement[i], abs=1e-12)
               for i in drops)  # a fracture drops the shear at one roof displacement
    assert abs(r.base_shear[-1]) < 1e-6 * 3e5
