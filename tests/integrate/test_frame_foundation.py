"""Frames on flexible bases (:func:`pounding.structure.frame_linear.frame_on_flexible_base`):
elastic frames against the Veletsos–Meek replacement oscillator and against the frame and
its footing assembled here apart, from Newton's law in the frame's own coordinates (a
non-diagonal mass matrix, no ``Tᵀ K T``)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import el_centro
from pounding.hysteresis.hinges import ElasticPlastic
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure.damping import ModalDamping, RayleighDamping
from pounding.structure.foundation import Footing, Soil
from pounding.structure.foundation.impedance import footing_stiffness
from pounding.structure.frame import Frame, regular_frame
from pounding.structure.frame_linear import (
    FlexibleBaseFrame,
    frame_matrix_building,
    frame_on_flexible_base,
)

SOIL = Soil(80.0, 1800.0, 0.33)  # (soft: the base matters)
KV = ContactSpec("kelvin-voigt", k=2e9, e=0.65)


def _portal(hinges: bool = False) -> Frame:
    """A one-storey, one-bay portal: span 6 m, height 4 m, EI 2e8 N·m², 50 t floor."""
    law = {"column_hinge": ElasticPlastic(k0=1e11, m_y=3e5),
           "beam_hinge": ElasticPlastic(k0=1e11, m_y=6e5)} if hinges else {}
    return regular_frame(6.0, 4.0, n_storeys=1, column_EI=2e8, beam_EI=2e8, floor_mass=5e4,
                         damping=RayleighDamping(0.05, 0.05), name="portal", **law)


def _three_storeys(rigid_floors: bool) -> Frame:
    return regular_frame([6.0, 6.0], [4.0, 3.5, 3.5], column_EI=[3e8, 2.5e8, 2e8],
                         beam_EI=[2.5e8, 2e8, 1.5e8], floor_mass=[8e4, 8e4, 6e4],
                         diaphragm=rigid_floors, damping=ModalDamping(0.05), name="three")


def test_a_portal_on_a_massless_footing_has_the_veletsos_meek_period() -> None:
    """T̃ = T √(1 + k/k_x + k h²/k_φ) (Veletsos & Meek 1974) with T, k and h the fixed-base
    portal's (its condensed lateral stiffness, h = 4 m), to 1e-10."""
    b = frame_matrix_building(_portal())
    footing = Footing(radius=3.0)
    fb = frame_on_flexible_base(b, footing, SOIL)
    k_x, k_r = footing_stiffness(footing, SOIL)
    k, h = float(b.K[0, 0]), float(b.elevations[0])
    T = 2 * math.pi * math.sqrt(b.masses[0] / k)
    assert b.modes().periods[0] == pytest.approx(T, rel=1e-12)
    expected = T * math.sqrt(1 + k / k_x + k * h * h / k_r)
    assert fb.modes().periods[0] == pytest.approx(expected, rel=1e-10)
    assert fb.modes().periods[0] > 1.1 * T  # (the soil matters here)
    assert isinstance(fb, FlexibleBaseFrame) and fb.n == 1  # (the footing condensed out)


def _newton_periods(b: object, footing: Footing) -> np.ndarray:
    """The frame's DOFs relative to its moving base ``u``, the footing's sway ``u_f`` and
    rocking ``φ``: the absolute motion of a lateral DOF at height z is ``u + u_f + z φ``
    (+ the ground's), so the kinetic energy gives the mass matrix
    ``[[M, M1, Mz], [1ᵀM, m_f + 1ᵀM1, 1ᵀMz], [zᵀM, zᵀM1, I_f + zᵀMz]]``, and the frame's
    fixed-base K acts on u, the soil's springs on u_f and φ."""
    M = np.diag(b.masses)  # type: ignore[attr-defined]
    z = np.asarray(b.elevations)  # type: ignore[attr-defined]
    one = np.ones(z.size)
    k_x, k_r = footing_stiffness(footing, SOIL)
    G = np.column_stack([np.eye(z.size), one, z])  # absolute motion = G [u, u_f, φ]
    Mq = G.T @ M @ G
    Mq[-2, -2] += footing.mass
    Mq[-1, -1] += footing.inertia
    Kq = scipy.linalg.block_diag(b.K, [[k_x]], [[k_r]])  # type: ignore[attr-defined]
    w2 = scipy.linalg.eigh(Kq, Mq, eigvals_only=True)
    return 2 * math.pi / np.sqrt(w2)


@pytest.mark.parametrize("rigid_floors", [True, False], ids=["rigid-floors", "column-nodes"])
def test_a_frame_on_a_footing_has_the_periods_of_newtons_law(rigid_floors: bool) -> None:
    """A 3-storey, 2-bay frame (with rigid floors: 3 lateral DOFs; without: 9, its three
    column lines) on a 12 × 8 m footing with mass and inertia: every period of the
    flexible-base building against the eigenproblem of :func:`_newton_periods`, to 1e-10;
    the floors and the faces a neighbour strikes are the frame's."""
    b = frame_matrix_building(_three_storeys(rigid_floors))
    footing = Footing(length=12.0, width=8.0, mass=2.0e5, inertia=3.0e6)
    fb = frame_on_flexible_base(b, footing, SOIL)
    assert fb.n == b.n + 2 and fb.labels[-2:] == ("Fdn", "Fdn_r")
    assert fb.floors == b.floors and dict(fb.faces) == dict(b.faces)
    expected = _newton_periods(b, footing)
    np.testing.assert_allclose(fb.modes().periods, expected, rtol=1e-10)
    assert fb.modes().periods[0] > 1.1 * b.modes().periods[0]
    # the same frame on a massless footing: the condensed building's periods are those of
    # the footing with vanishing mass (1e-6 of the frame's)
    light = Footing(length=12.0, width=8.0, mass=1e-6 * 2.2e5, inertia=1e-6 * 3e6)
    condensed = frame_on_flexible_base(b, Footing(length=12.0, width=8.0), SOIL)
    assert condensed.n == b.n
    np.testing.assert_allclose(condensed.modes().periods,
                               _newton_periods(b, light)[:b.n], rtol=1e-6)


def test_an_elastic_frame_on_a_footing_reports_its_own_deformation() -> None:
    """An elastic 3-storey frame without rigid floors on a footing under El Centro: the
    storey drifts reported are the frame's own (its floors less the footing's sway and
    rocking, ``x_j − x_{j−1} − Δz φ``, ``x_0 = u_f``), its storey shears the sum of its
    restoring forces ``K u`` above each storey (u = T y) — the base shear equals the
    soil's base shear less the footing's inertia and the dashpot; the energy balances."""
    b = frame_matrix_building(_three_storeys(rigid_floors=False))
    fb = frame_on_flexible_base(b, Footing(length=12.0, width=8.0, mass=2.0e5,
                                           inertia=3.0e6), SOIL)
    res = simulate(PoundingModel([fb], [], KV), el_centro(), duration=3.0, dt=0.01)
    y = res.displacement
    n = b.n
    u_f, phi = y[:, n], y[:, n + 1]
    z = b.elevations
    u = y[:, :n] - u_f[:, None] - z[None, :] * phi[:, None]
    floors = np.asarray(b.floors)
    drift = np.diff(np.column_stack([np.zeros(len(y)), u[:, floors]]), axis=1)
    np.testing.assert_allclose(res.drift[:, floors], drift, atol=1e-12 * np.max(np.abs(y)))
    relative = np.diff(np.column_stack([np.zeros(len(y)), y[:, floors]]), axis=1)
    assert np.max(np.abs(relative - drift)) > 0.05 * np.max(np.abs(drift))  # (not those)
    R = u @ b.K.T  # the frame's restoring force on its DOFs, from its own deformation
    base = R.sum(axis=1)
    assert np.max(np.abs(res.storey_shear[:, floors[0]] - base)) <= 1e-9 * np.max(np.abs(base))
    # the footing: m_f (ü_f + a_g) = −(k_x u_f + c_x u̇_f) + (the frame's base shear + its
    # damping force on the footing)
    assert res.energy_balance_error < 1e-7
    assert np.max(np.abs(phi)) > 0 and np.max(np.abs(drift)) > 1e-3


def test_a_model_file_puts_a_frame_on_a_footing(tmp_path) -> None:
    """``foundation = {...}`` beside ``frame = {...}`` builds the frame on its footing."""
    from pounding.config.building import BuildingConfig

    cfg = BuildingConfig.model_validate({
        "name": "portal", "damping": {"ratio": 0.05},
        "frame": {"bays": [6.0], "storey_heights": [4.0], "column_EI": 2e8, "beam_EI": 2e8,
                  "floor_mass": 5e4},
        "foundation": {"radius": 3.0, "mass": 1e5, "inertia": 4e5,
                       "soil": {"vs": 80.0, "density": 1800.0, "poisson": 0.33}}})
    b = cfg.build("B1")
    assert isinstance(b, FlexibleBaseFrame) and b.labels == ("F1", "Fdn", "Fdn_r")
    direct = frame_on_flexible_base(frame_matrix_building(cfg.build_frame("B1")),
                                    Footing(radius=3.0, mass=1e5, inertia=4e5), SOIL)
    np.testing.assert_allclose(b.K, direct.K, rtol=1e-13)
