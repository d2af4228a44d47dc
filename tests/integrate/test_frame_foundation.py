"""Frames on flexible bases (:func:`pounding.structure.frame_linear.frame_on_flexible_base`):
elastic frames against the Veletsos–Meek replacement oscillator and against the frame and
its footing assembled here apart, from Newton's law in the frame's own coordinates (a
non-diagonal mass matrix, no ``Tᵀ K T``)."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

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
    restoring forces ``K u`` above each storey (u = T y); the footing is in horizontal
    equilibrium at every output step, the frame's base shear plus its damping force on
    the footing being the soil's reaction ``k_x u_f + c_x u̇_f`` plus the footing's inertia
    ``m_f (ü_f + a_g)`` (from the run's accelerations); the energy balances."""
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
    # damping force on the footing), with the footing's absolute acceleration the run's
    v = res.velocity
    u_dot = v[:, :n] - v[:, n:n + 1] - z[None, :] * v[:, n + 1:n + 2]
    frame_on_footing = base + (u_dot @ b.damping_matrix().T).sum(axis=1)
    imp = fb.foundation.impedance
    soil = imp.k_x * u_f + imp.c_x * v[:, n]
    inertia = fb.foundation.footing.mass * res.abs_acceleration[:, n]
    np.testing.assert_allclose(soil + inertia, frame_on_footing, rtol=0.0,
                               atol=1e-9 * np.max(np.abs(soil)))
    assert np.max(np.abs(inertia)) > 0.05 * np.max(np.abs(soil))  # (the inertia matters)
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


# ------------------------------------------------------------------ yielding frames
def _springs(fb: FlexibleBaseFrame, footing: Footing) -> object:
    from pounding.integrate.frame_reference import FootingSprings

    imp = fb.foundation.impedance
    return FootingSprings(footing.mass, footing.inertia, imp.k_x, imp.k_r, imp.c_x, imp.c_r)


def _gravity_three_storeys() -> Frame:
    from frame_kernel_models import _three_storeys  # (this folder)

    return _three_storeys("A", strength=0.6, gravity=True)


@pytest.mark.parametrize(("make", "scale", "duration", "footing"), [
    (lambda: _portal(hinges=True), 3.0, 4.0, Footing(radius=3.0, mass=3e4, inertia=1e5)),
    (_gravity_three_storeys, 1.5, 3.0,
     Footing(length=12.0, width=8.0, mass=2e5, inertia=3e6)),
], ids=["portal", "three-storeys-gravity-p-delta"])
def test_a_yielding_frame_on_a_footing_follows_the_scipy_reference(
        make: object, scale: float, duration: float, footing: Footing) -> None:
    """The compiled kernel (the frame's configurations written in ``y = [x, u_f, φ]``,
    ``Tᵀ K_c T``) against the SciPy frame reference given the footing
    (:class:`~pounding.integrate.frame_reference.FootingSprings`: Newton's law in the
    frame's own coordinates, one full mass matrix, its own condensation and events): every
    DOF, the footing's sway and rocking, hinge rotations, moments and hysteretic energy,
    the storey drifts (the frame's own), on soft soil where the footing matters."""
    from pounding.integrate.frame_reference import simulate_frame_reference

    frame = make()  # type: ignore[operator]
    b = frame_matrix_building(frame)
    fb = frame_on_flexible_base(b, footing, SOIL)
    motion = el_centro().scaled(scale)
    ref = simulate_frame_reference(frame, motion.accel, motion.dt, duration=duration,
                                   footing=_springs(fb, footing))  # type: ignore[arg-type]
    got = simulate(PoundingModel([fb], [], KV), motion, duration=duration, dt=motion.dt)
    n = b.n
    at = [int(np.flatnonzero(ref.mass_dofs == d)[0]) for d in b.kept]
    w = ref.footing
    assert w is not None
    y_ref = ref.displacement[:, at] + w[:, :1] + b.elevations[None, :] * w[:, 1:2]

    def close(a: np.ndarray, c: np.ndarray, rel: float) -> None:
        assert np.max(np.abs(a - c)) <= rel * np.max(np.abs(c))

    # measured 2026-11-28 (portal / three storeys): 3.0e-9 / 1.0e-9 (floors), 1.4e-9 /
    # 2.3e-9 (sway), 4.4e-9 / 1.8e-9 (rocking), 6.5e-9 / 1.1e-8 (rotations), 1.2e-8 /
    # 9.5e-9 (moments), 6e-10 / 3e-9 (peak rotations), 3.4e-9 / 6.3e-9 (drifts)
    close(got.displacement[:, :n], y_ref, 1e-7)
    close(got.displacement[:, n:], w, 1e-7)
    close(got.hinge_rotation, ref.hinge_rotations, 1e-6)
    close(got.hinge_moment, ref.hinge_moments, 1e-6)
    close(got.hinge_peak_rotation, ref.peak_hinge_rotation, 1e-6)
    close(got.drift[:, b.floor_dofs], ref.storey_drifts - ref.storey_drifts[0], 1e-6)
    assert np.sum(got.hinge_dissipated) == pytest.approx(np.sum(ref.hinge_hysteretic[-1]),
                                                         rel=1e-6)
    # the energy balances: the reference's (2e-12 / 1e-11 of the input), the kernel's
    # (7.8e-10 / 2e-9), with the soil's springs and dashpots in them
    assert np.max(np.abs(ref.energy.residual)) <= 1e-9 * np.max(ref.energy.input)
    assert got.energy_balance_error < 1e-8
    assert np.max(ref.peak_hinge_rotation) > 10 * min(h.law.theta_y for h in frame.hinges)
    fixed = simulate(PoundingModel([b], [], KV), motion, duration=duration, dt=motion.dt)
    assert np.max(np.abs(got.drift[:, 0] - fixed.drift[:, 0])) > \
        0.05 * np.max(np.abs(fixed.drift[:, 0]))  # (the soil matters here)


def test_a_yielding_frame_on_very_stiff_soil_is_the_fixed_base_frame() -> None:
    """The yielding portal on a footing on soil 10⁶ times stiffer (G × 10⁶, V_s × 10³)
    gives the fixed-base portal's drifts, hinge rotations and moments, to 1e-5 (measured
    1.3e-6, 1.6e-6 and 4.0e-6: the soil's compliance, ``k/k_x`` ≈ 3e-7, and 10 times more
    at G × 10⁵)."""
    frame = _portal(hinges=True)
    b = frame_matrix_building(frame)
    stiff = Soil(80.0e3, 1800.0, 0.33)
    fb = frame_on_flexible_base(b, Footing(radius=3.0, mass=3e5, inertia=1e6), stiff)
    motion = el_centro().scaled(3.0)
    got = simulate(PoundingModel([fb], [], KV), motion, duration=4.0, dt=motion.dt,
                   max_rk_steps=1_000_000)  # (the footing's own modes, ~0.2 ms)
    fixed = simulate(PoundingModel([b], [], KV), motion, duration=4.0, dt=motion.dt)
    for a, c in ((got.drift[:, 0], fixed.drift[:, 0]),
                 (got.hinge_rotation, fixed.hinge_rotation),
                 (got.hinge_moment, fixed.hinge_moment)):
        assert np.max(np.abs(a - c)) <= 1e-5 * np.max(np.abs(c))
    assert np.max(np.abs(fixed.hinge_rotation)) > 0.005  # (it yields)
    assert got.energy_balance_error < 1e-8


def test_a_yielding_frame_on_a_massless_footing_is_refused() -> None:
    """A frame with hinges needs its footing's sway and rocking as DOFs: a footing without
    mass or without inertia is refused, in one message naming both keys."""
    b = frame_matrix_building(_portal(hinges=True))
    for footing in (Footing(radius=3.0), Footing(radius=3.0, mass=3e4),
                    Footing(radius=3.0, inertia=1e5)):
        with pytest.raises(ValueError, match=r"foundation\.mass and foundation\.inertia"):
            frame_on_flexible_base(b, footing, SOIL)


MODEL_FILE = """
name = "yielding frame on soil"
[record]
bundled = "el_centro"
scale = 1.5

[[building]]
name = "on soil"
damping = { rayleigh = [0.05, 0.05], modes = [1, 2] }
foundation = { length = 8.0, width = 6.0,FOOTING soil = { vs = 120.0, density = 1800.0, poisson = 0.33 } }

[building.frame]
bays = [5.0]
storey_heights = [4.0, 3.5]
column_EI = 1.2e8
beam_EI = 1.5e8
floor_mass = 4.0e4
beam_load = 1.0e4
leaning_load = 3.0e5
geometry = "p-delta"
column_hinge = { type = "elastic-plastic", k0 = 1.0e11, m_y = 2.0e5 }
beam_hinge = { type = "elastic-plastic", k0 = 1.0e11, m_y = 1.5e5 }

[[building]]
name = "fixed"
mass = 1.2e5
period = 0.5
height = 7.5

[contact]
law = "kelvin-voigt"
k = 1.0e9
e = 0.65
gap = 0.015

[solver]
duration = 4.0
"""


def _run(tmp_path: Path, footing: str) -> subprocess.CompletedProcess[str]:
    model = tmp_path / "frame_ssi.toml"
    model.write_text(MODEL_FILE.replace("FOOTING", footing))
    return subprocess.run([sys.executable, "-m", "pounding", "run", str(model), "--out",
                           str(tmp_path / "out"), "--no-figures"], check=False,
                          capture_output=True, text=True, timeout=300)


def test_a_yielding_frame_on_a_footing_runs_from_the_command_line(tmp_path: Path) -> None:
    """`pounding run` on a model file with a yielding 2-storey frame on a footing beside a
    fixed-base building: summary.json has the footing (`foundations`: its DOFs, the fixed-
    and flexible-base periods, the peaks of sway and rocking) and the frame's hinges, and
    the energy balances."""
    done = _run(tmp_path, " mass = 1.5e5, inertia = 1.2e6,")
    assert done.returncode == 0, done.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    (f,) = summary["foundations"]
    assert f["building"] == "B1" and f["footing"]["sway_dof"] and f["footing"]["rocking_dof"]
    assert f["flexible_base_periods_s"][0] > f["fixed_base_periods_s"][0]
    assert summary["buildings"][0]["periods_s"][0] == pytest.approx(
        f["flexible_base_periods_s"][0], rel=1e-12)
    assert f["peak_sway_m"] > 0 and f["peak_rocking_rad"] > 0
    assert summary["hinges"] and all(h["hinge"].startswith("B1H") for h in summary["hinges"])
    assert summary["peak_hinge_rotation_rad"] > 0.003  # (they yield: θ_y ≈ 2e-6 here)
    assert summary["energy_balance_error"] < 1e-8


def test_a_yielding_frame_on_a_massless_footing_is_refused_from_the_command_line(
        tmp_path: Path) -> None:
    done = _run(tmp_path, "")
    assert done.returncode == 2 and done.stdout == ""
    (line,) = done.stderr.strip().splitlines()
    assert "foundation.mass and foundation.inertia" in line and "got mass = 0 kg" in line
    assert not (tmp_path / "out").exists()
