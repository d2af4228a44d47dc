"""Yielding shear buildings on flexible bases: each storey's law reads the building's own
deformation ``x_j − x_{j−1} − h_j φ`` and its shear loads the floors and, through its lever,
the rocking footing. Checked against the SciPy reference (its own drift and loads), the
global equilibrium of building and footing with the soil's reactions, the fixed-base
building as the soil stiffens, the elastic–perfectly-plastic cap on the shear, and the
command line."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import el_centro
from pounding.hysteresis import Bilinear, BoucWen
from pounding.integrate import simulate
from pounding.integrate.reference import simulate_reference
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.foundation import Footing, Soil, flexible_base

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
FOOTING = Footing(radius=4.0, mass=3.0e5, inertia=2.0e6)
EPP = Bilinear(yield_drift=0.004 * 3.2, hardening=0.0)


@pytest.fixture(scope="module")
def elc():
    return el_centro()


def _epp_building() -> ShearBuilding:
    return ShearBuilding.uniform(3, 3e5, 3.5e8, height=3.2).with_storey_law(EPP)


@pytest.mark.slow  # a reference comparison (pyproject.toml: markers)
def test_yielding_pair_on_footings_matches_the_reference(elc) -> None:
    """A bilinear and a Bouc–Wen 3-storey building, each on its own footing on soft soil,
    pounding floor to floor under El Centro × 2 (2.5 s: two impacts, ductility 4): the kernel
    and the SciPy reference (which writes the rocking term of each storey's drift and load
    itself) agree, and both balance energy."""
    a = ShearBuilding.uniform(3, 3e5, 3.5e8, height=3.2).with_storey_law(
        Bilinear(yield_drift=0.004 * 3.2, hardening=0.05))
    b = ShearBuilding.uniform(3, 2.5e5, 1.5e8, height=3.2).with_storey_law(
        BoucWen(yield_drift=0.006 * 3.2, alpha=0.05, n=1.5))
    model = PoundingModel([flexible_base(a, FOOTING, Soil(150.0, 1800.0, 0.33)),
                           flexible_base(b, Footing(radius=4.0, mass=2e5, inertia=1.5e6),
                                         Soil(200.0, 1800.0, 0.33))], [0.01], KV)
    record = elc.scaled(2.0)
    res = simulate(model, record, duration=2.5)
    ref = simulate_reference(model, record, duration=2.5)
    assert res.n_impacts == ref.n_impacts > 0
    assert np.nanmax(res.ductility) > 3.0  # (it yielded)
    np.testing.assert_allclose(res.peak_contact_force, ref.peak_contact_force, rtol=1e-5)
    scale = np.abs(ref.displacement).max()
    assert np.max(np.abs(res.displacement - ref.displacement)) < 1e-5 * scale
    floors = [0, 1, 2, 5, 6, 7]
    assert np.max(np.abs(res.storey_shear[:, floors] - ref.storey_shear[:, floors])) < (
        1e-5 * np.abs(ref.storey_shear[:, floors]).max())
    np.testing.assert_allclose(res.residual_drift, ref.residual_drift, rtol=1e-4, atol=1e-8)
    assert res.energy_balance_error < 1e-8 and ref.energy_balance_error < 1e-8


def test_building_and_footing_are_in_equilibrium_with_the_soil(elc) -> None:
    """Without contacts the only external forces on building + footing are the soil's
    (``V = k_x u_f + c_x u̇_f``, ``M = k_φ φ + c_φ φ̇``): at every output step
    ``Σ m_j a_j + m_f a_f = −V`` and ``Σ m_j z_j a_j + I_f φ̈ = −M`` (absolute
    accelerations; the storeys' internal shears cancel only if each storey's moment
    ``h_j V_j`` reaches the footing), while the first storey yields."""
    b = _epp_building()
    fb = flexible_base(b, FOOTING, Soil(150.0, 1800.0, 0.33))
    res = simulate(PoundingModel([fb], [], KV), elc, duration=8.0, dt=0.002)
    assert res.ductility[0] > 1.5
    _, _, shear, moment = fb.foundation.base_reactions(res.displacement, res.velocity)
    acc = res.abs_acceleration
    sway = acc[:, :4] @ np.r_[b.masses, FOOTING.mass]
    rocking = acc[:, :3] @ (b.masses * b.floor_levels) + FOOTING.inertia * acc[:, 4]
    assert np.max(np.abs(sway + shear)) < 1e-9 * np.max(np.abs(shear))
    assert np.max(np.abs(rocking + moment)) < 1e-9 * np.max(np.abs(moment))
    # elastic–perfectly-plastic: the storey's shear never passes its yield force
    fy = float(b.yield_forces[0])
    assert np.max(np.abs(res.storey_shear[:, 0])) <= fy * (1 + 1e-9)
    assert np.max(np.abs(res.storey_shear[:, 0])) >= fy * (1 - 1e-9)
    assert res.energy_balance_error < 1e-8


def test_stiff_soil_gives_the_fixed_base_building(elc) -> None:
    """As the soil stiffens (V_s × 10, × 100: G × 10², × 10⁴) the yielding building on its
    footing approaches the same building on a rigid base: its peak storey drifts within
    1 % and then 0.05 % of the fixed base's (the footing's sway and rocking ∝ 1/G)."""
    b = _epp_building()
    fixed = simulate(PoundingModel([b], [], KV), elc, duration=8.0, dt=0.002)
    errors = []
    for vs in (1500.0, 15000.0):
        fb = flexible_base(b, FOOTING, Soil(vs, 1800.0, 0.33))
        r = simulate(PoundingModel([fb], [], KV), elc, duration=8.0, dt=0.002)
        errors.append(np.max(np.abs(r.peak_drift[:3] / fixed.peak_drift - 1.0)))
    assert fixed.ductility[0] > 1.0
    assert errors[0] < 1e-2 and errors[1] < 5e-4 and errors[1] < errors[0] / 10


def test_a_yielding_building_on_a_footing_from_the_command_line(tmp_path: Path) -> None:
    """A model file with `storey_law` and `foundation` runs; summary.json has the ductility
    of the building's own deformation and the footing's peaks; a massless footing under a
    yielding building is refused with one line naming the field (exit 2)."""
    text = """
[record]
bundled = "el_centro"
duration = 3.0

[[building]]
name = "yielding"
n_storeys = 3
mass = 3.0e5
stiffness = 3.5e8
height = 3.2
storey_law = { type = "bilinear", yield_drift = 0.0128, hardening = 0.0 }
foundation = { radius = 4.0, mass = 3.0e5, inertia = 2.0e6, soil = { vs = 150.0, density = 1800.0, poisson = 0.33 } }

[[building]]
name = "neighbour"
n_storeys = 3
mass = 2.5e5
stiffness = 1.5e8
height = 3.2

[contact]
law = "kelvin-voigt"
k = 9.3e8
e = 0.65
gap = 0.01
"""
    model = tmp_path / "m.toml"
    model.write_text(text)
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "pounding", "run", str(model), "--out",
                           str(out), "--no-figures"], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    summary = json.loads((out / "summary.json").read_text())
    (f,) = summary["foundations"]
    assert f["peak_sway_m"] > 0 and f["peak_rocking_rad"] > 0
    assert summary["energy_balance_error"] < 1e-7
    text_bad = text.replace("mass = 3.0e5, inertia = 2.0e6, ", "")
    model.write_text(text_bad)
    bad = subprocess.run([sys.executable, "-m", "pounding", "run", str(model), "--out",
                          str(tmp_path / "bad"), "--no-figures"], capture_output=True,
                         text=True, timeout=300)
    assert bad.returncode == 2
    assert "foundation.mass" in bad.stderr and "Traceback" not in bad.stderr
    assert not (tmp_path / "bad").exists()


def test_every_law_leaves_the_rocking_columns_free() -> None:
    """An element row's constants are its law's (at most hysteresis.base.PARAMS_SIZE of
    them, links padded to the same width) and then the rocking DOF and lever: the columns
    must not overlap (integrate.layout.EL_ROCK, EL_LEVER)."""
    from pounding.hysteresis.base import PARAMS_SIZE
    from pounding.integrate.layout import EL_LEVER, EL_ROCK, ELEMENT_PARAMS

    assert PARAMS_SIZE <= EL_ROCK < EL_LEVER < ELEMENT_PARAMS
