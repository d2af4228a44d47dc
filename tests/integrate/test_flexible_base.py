"""Buildings on flexible bases in time histories (the compiled kernel), against closed forms
and a frequency-domain solution written out here from the physics, and from the command
line (the issue's example)."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotion
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import ModalDamping, ShearBuilding
from pounding.structure.foundation import Footing, Soil, flexible_base

ROOT = Path(__file__).resolve().parents[2]
SOIL = Soil(150.0, 1800.0, 0.33)
SPEC = ContactSpec("kelvin-voigt", k=2e9, e=0.65)


def _alone(footing: Footing) -> PoundingModel:
    """The footing carrying a 1 g storey of period 6 ms (its inertia 1e-9 of the footing's)."""
    b = ShearBuilding.sdof(1.0e-3, stiffness=1.0e3, height=10.0, damping_ratio=0.0)
    return PoundingModel([flexible_base(b, footing, SOIL)], [], SPEC)


def test_free_vibration_of_the_footing_alone() -> None:
    """Sway: u_f(t) = v0/ω_d e^{−ζωt} sin ω_d t, ω = √(k_x/m_f), ζ = c_x/(2√(k_x m_f));
    rocking likewise with k_φ, c_φ, I_f — the footing's own impedance, to 1e-7 of the peak
    (the 1 g storey's inertia far below it)."""
    ft = Footing(radius=5.0, mass=2.0e6, inertia=3.0e7)
    model = _alone(ft)
    fb = model.buildings[0]
    imp = fb.foundation.impedance
    quiet = GroundMotion(dt=0.01, accel=np.zeros(201))
    t = np.arange(401) * 0.005
    for dof, k, c, m, v0 in ((1, imp.k_x, imp.c_x, ft.mass, 0.1),
                             (2, imp.k_r, imp.c_r, ft.inertia, 0.01)):
        v = np.zeros(3)
        v[dof] = v0
        v[0] = v0 * (10.0 if dof == 2 else 1.0)  # (the storey moves with the footing)
        res = simulate(model, quiet, dt=0.005, duration=2.0, initial_velocity=v)
        w = math.sqrt(k / m)
        z = c / (2 * math.sqrt(k * m))
        wd = w * math.sqrt(1 - z * z)
        exact = v0 / wd * np.exp(-z * w * t) * np.sin(wd * t)
        err = np.max(np.abs(res.displacement[:, dof] - exact)) / np.max(np.abs(exact))
        assert err < 1e-7, (dof, err)


def test_harmonic_steady_state_matches_the_frequency_domain() -> None:
    """A 2-storey building on a footing with mass and inertia under a ground acceleration
    A sin Ωt: after the transients die, every DOF is Re(X e^{iΩt}) with
    X = −(K − Ω² M + iΩ C)⁻¹ M r A, the matrices written out here from the deformations
    (not the model's): to 2e-5 of the amplitude (the record's linear interpolation between
    its 1 ms samples)."""
    masses, ks, hs = [3e5, 2e5], [2.0e8, 1.5e8], [4.0, 3.0]
    b = ShearBuilding(masses=masses, stiffnesses=ks, heights=hs, damping=ModalDamping(0.05))
    ft = Footing(radius=5.0, mass=5.0e5, inertia=4.0e6)
    fb = flexible_base(b, ft, SOIL)
    imp = fb.foundation.impedance
    Cs = b.damping_matrix()
    z = np.array([4.0, 7.0])
    # y = [x1, x2, u_f, φ]; deformation u = x − u_f − z φ
    T = np.array([[1.0, 0.0, -1.0, -z[0]], [0.0, 1.0, -1.0, -z[1]]])
    Ks = np.array([[ks[0] + ks[1], -ks[1]], [-ks[1], ks[1]]])
    K = T.T @ Ks @ T + np.diag([0, 0, imp.k_x, imp.k_r])
    C = T.T @ Cs @ T + np.diag([0, 0, imp.c_x, imp.c_r])
    M = np.diag([*masses, ft.mass, ft.inertia])
    r = np.array([1.0, 1.0, 1.0, 0.0])
    A, Om = 1.0, 2 * math.pi * 1.3
    X = -np.linalg.solve(K - Om ** 2 * M + 1j * Om * C, M @ r * A)
    dt = 0.001
    n = 40_001
    tt = np.arange(n) * dt
    motion = GroundMotion(dt=dt, accel=A * np.sin(Om * tt))
    res = simulate(PoundingModel([fb], [], SPEC), motion)
    t = res.time
    last = t > 36.0
    # a sine A sin Ωt = Im(A e^{iΩt}): the response is Im(X e^{iΩt})
    steady = np.imag(np.outer(np.exp(1j * Om * t[last]), X))
    amp = np.abs(X)
    err = np.max(np.abs(res.displacement[last] - steady), axis=0) / amp
    assert np.all(err < 2e-5), err


def test_energy_balances_with_pounding_on_a_flexible_base() -> None:
    """A flexible-base building (dashpots, footing with mass) striking a fixed-base one:
    the energy balance closes (the soil's dashpots in the damping term)."""
    from pounding.ground_motion import el_centro

    a = flexible_base(ShearBuilding.sdof(1.0e6, period=0.5, height=10.0),
                      Footing(radius=5.0, mass=3.0e5, inertia=2.0e6), SOIL)
    b = ShearBuilding.sdof(6.0e5, period=0.7, height=10.0)
    res = simulate(PoundingModel([a, b], [0.01], SPEC), el_centro(), duration=15.0, dt=0.005)
    assert res.n_impacts > 0
    assert res.energy_balance_error < 1e-7


def test_the_issue_example_from_the_command_line(tmp_path: Path) -> None:
    """`pounding run examples/ssi_sdof.toml`: summary.json's buildings[0].periods_s[0] is the
    Veletsos–Meek period, and `foundations` reports the footing."""
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "pounding", "run",
                           str(ROOT / "examples" / "ssi_sdof.toml"), "--out", str(out),
                           "--no-figures"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    summary = json.loads((out / "summary.json").read_text())
    G = 1800.0 * 150.0 ** 2
    m, T, h, R, nu = 1.0e6, 0.5, 10.0, 5.0, 0.33
    k = m * (2 * math.pi / T) ** 2
    expected = T * math.sqrt(1 + k / (8 * G * R / (2 - nu))
                             + k * h ** 2 / (8 * G * R ** 3 / (3 * (1 - nu))))
    assert summary["buildings"][0]["periods_s"][0] == pytest.approx(expected, rel=1e-12)
    (f,) = summary["foundations"]
    assert f["building"] == "B1" and f["fixed_base_periods_s"] == [pytest.approx(0.5)]
    assert f["peak_sway_m"] > 0 and f["peak_rocking_rad"] > 0
    assert summary["energy_balance_error"] < 1e-7


def test_soil_dashpot_work_is_the_damping_energy_without_structural_damping() -> None:
    """With no damping in the building, all the damping energy the kernel integrates is the
    soil's: the summary's dashpot work (trapezoids on the output steps) equals it to the
    trapezoidal rule's O(dt²)."""
    from pounding.ground_motion import el_centro
    from pounding.result.columns import ENERGY_NAMES

    for footing in (Footing(radius=5.0), Footing(radius=5.0, mass=3.0e5, inertia=2.0e6)):
        a = flexible_base(ShearBuilding.sdof(1.0e6, period=0.5, height=10.0, damping_ratio=0.0),
                          footing, SOIL)
        res = simulate(PoundingModel([a], [], SPEC), el_centro(), duration=10.0, dt=0.002)
        (f,) = res.summary()["foundations"]
        damping = res.energy[-1, ENERGY_NAMES.index("damping")]
        assert f["soil_dashpot_work_J"] == pytest.approx(damping, rel=2e-4)


def test_the_footing_rows_outside_the_band_give_the_full_band_answer(monkeypatch) -> None:
    """A 6-storey building on a footing with mass and inertia: the kernel keeps a narrow band
    and the footing's couplings apart (kernel_model.banding); a pounding run equals the same
    run with K and C stored as one full band, to 1e-12 of the peaks."""
    import importlib

    from pounding.ground_motion import el_centro

    km_module = importlib.import_module("pounding.integrate.kernel_model")
    b = ShearBuilding(masses=[3e5] * 6, stiffnesses=[4e8, 3.6e8, 3.2e8, 2.8e8, 2.4e8, 2.0e8],
                      heights=[3.5] * 6)
    footing = Footing(length=12.0, width=12.0, mass=1e6, inertia=1.2e7)
    a = flexible_base(b, footing, SOIL)
    bw, far = km_module.banding(a.stiffness_matrix(), a.damping_matrix())
    assert bw == 1 and len(far) > 0
    runs = []
    for cost in (km_module.FAR_COST, 1e12):
        monkeypatch.setattr(km_module, "FAR_COST", cost)
        # (new buildings each time: the kernel's arrays are remembered per building)
        model = PoundingModel([flexible_base(b, footing, SOIL),
                               ShearBuilding.sdof(4e5, period=0.4, height=7.0)], [0.01], SPEC)
        runs.append(simulate(model, el_centro(), duration=12.0, dt=0.005))
    assert km_module.kernel_model(model).floors.k_band.shape[1] == model.n_dof  # (full band)
    fast, full = runs
    assert fast.n_impacts == full.n_impacts > 0
    for x, y in ((fast.displacement, full.displacement),
                 (fast.abs_acceleration, full.abs_acceleration),
                 (fast.contact_force, full.contact_force), (fast.energy, full.energy),
                 (fast.located_peaks, full.located_peaks)):
        assert np.max(np.abs(x - y)) <= 1e-12 * np.max(np.abs(y))
    assert fast.energy_balance_error < 1e-8


def test_drifts_are_the_buildings_own_deformation() -> None:
    """The storey's drift on a flexible base is its own deformation x − u_f − h φ: with no
    damping and a massless footing (springs only) the storey shear k·drift equals the soil's
    sway reaction k_x u_f and k·drift·h its rocking reaction k_φ φ at every step (the
    massless footing's equilibrium); the drift ratio and storey shear in the outputs are
    those, not the floor's displacement relative to the ground."""
    from pounding.ground_motion import el_centro

    b = ShearBuilding.sdof(1.0e6, period=0.5, height=10.0, damping_ratio=0.0)
    fb = flexible_base(b, Footing(radius=5.0, dashpots=False), SOIL)
    res = simulate(PoundingModel([fb], [], SPEC), el_centro(), duration=10.0, dt=0.005)
    imp = fb.foundation.impedance
    sway, rocking, shear, moment = fb.foundation.base_reactions(res.displacement,
                                                                res.velocity)
    k = float(b.stiffnesses[0])
    storey = res.storey_shear[:, 0]
    assert np.max(np.abs(storey - imp.k_x * sway)) < 1e-9 * np.max(np.abs(storey))
    assert np.max(np.abs(10.0 * storey - imp.k_r * rocking)) < 1e-9 * np.max(np.abs(moment))
    assert np.allclose(res.drift[:, 0], storey / k, rtol=0, atol=1e-15)
    assert res.peak_drift_ratio[0] == pytest.approx(np.max(np.abs(storey)) / k / 10.0,
                                                    rel=1e-12)
    # the floor's displacement relative to the ground is larger: the footing moves it too
    assert np.max(np.abs(res.displacement[:, 0])) > 1.5 * res.peak_drift[0]
