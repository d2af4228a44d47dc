"""A frame's members' own mass, lumped at their ends or consistent
(:mod:`pounding.structure.frame_mass`): the modes of a cantilever against Euler–Bernoulli's
closed form, the modes of a portal against OpenSeesPy's ``elasticBeamColumn -mass``
(lumped) and ``-cMass`` (consistent), and the time history's refusal of the consistent one."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from pounding.structure.frame import Frame, regular_frame
from pounding.structure.frame_analysis import frame_modes
from pounding.structure.frame_linear import frame_matrix_building

EI, EA, MBAR, LENGTH = 2.0e8, 4.0e10, 500.0, 8.0  # N·m², N, kg/m, m


def _cantilever(n: int, mass_matrix: str) -> Frame:
    """A vertical cantilever column of ``n`` equal elements, fixed at its base."""
    y = np.linspace(0.0, LENGTH, n + 1)
    supports = np.zeros((n + 1, 3), dtype=bool)
    supports[0] = True
    return Frame(nodes=np.column_stack([np.zeros(n + 1), y]),
                 elements=np.column_stack([np.arange(n), np.arange(1, n + 1)]),
                 EA=np.full(n, EA), EI=np.full(n, EI), supports=supports, diaphragm=False,
                 member_mass=np.full(n, MBAR), mass_matrix=mass_matrix, name="cantilever")


def test_a_cantilevers_first_period_converges_to_euler_bernoulli() -> None:
    # ω₁ = (1.875104)² √(EI / (m̄ L⁴)) (Chopra, Dynamics of Structures, 4th ed., Table 16.1.1
    # / Clough & Penzien §18-3); the consistent mass converges from above (ω too high, h⁴),
    # the lumped one from below (h²)
    beta = 1.8751040687119611
    exact = 2 * math.pi / (beta ** 2 * math.sqrt(EI / (MBAR * LENGTH ** 4)))
    consistent = [frame_modes(_cantilever(n, "consistent"))[0][0] for n in (2, 4, 8)]
    lumped = [frame_modes(_cantilever(n, "lumped"))[0][0] for n in (4, 16, 64)]
    err_c = [(t - exact) / exact for t in consistent]
    err_l = [(t - exact) / exact for t in lumped]
    assert all(e < 0 for e in err_c)  # (period short: frequency high)
    assert all(e > 0 for e in err_l)
    # measured 2026-11-27: consistent −4.8e-4, −3.3e-5, −2.1e-6 (÷16 a halving: h⁴);
    # lumped 2.9e-2, 1.8e-3, 1.1e-4 (÷16 every 4 × elements: h²)
    assert abs(err_c[2]) < 3e-6 and abs(err_c[1] / err_c[2]) > 12
    assert abs(err_l[2]) < 3e-4 and abs(err_l[1] / err_l[2]) > 12


def _opensees_portal_periods(ops: Any, cmass: bool, n: int) -> np.ndarray:
    """The portal with member mass in OpenSeesPy: its first ``n`` periods."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, (x, y) in enumerate([(0, 0), (6, 0), (0, 4), (6, 4)], start=1):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    extra = ["-mass", MBAR] + (["-cMass"] if cmass else [])
    for tag, (i, j) in {1: (1, 3), 2: (2, 4), 3: (3, 4)}.items():
        ops.element("elasticBeamColumn", tag, i, j, EA, 1.0, EI, 1, *extra)
    ops.mass(3, 2e4, 0.0, 0.0)
    ops.mass(4, 2e4, 0.0, 0.0)
    w2 = np.array(ops.eigen("-fullGenLapack", n))
    ops.wipe()
    return 2 * np.pi / np.sqrt(w2)


@pytest.mark.parametrize("mass_matrix", ["lumped", "consistent"])
def test_a_portals_periods_with_member_mass_agree_with_opensees(mass_matrix: str) -> None:
    ops = pytest.importorskip("openseespy.opensees")
    frame = regular_frame(6.0, 4.0, n_storeys=1, column_EI=EI, beam_EI=EI, column_EA=EA,
                          beam_EA=EA, floor_mass=4e4, diaphragm=False, name="portal")
    frame = Frame(nodes=frame.nodes, elements=frame.elements, EA=frame.EA, EI=frame.EI,
                  supports=frame.supports, masses=frame.masses, diaphragm=False,
                  member_mass=np.full(frame.n_elements, MBAR), mass_matrix=mass_matrix,
                  name="portal")
    ours = frame_modes(frame)[0][:4]
    theirs = _opensees_portal_periods(ops, mass_matrix == "consistent", 4)
    assert ours == pytest.approx(theirs, rel=1e-8)


def test_member_mass_lumped_adds_to_the_floors_and_runs() -> None:
    frame = regular_frame(6.0, 4.0, n_storeys=1, column_EI=EI, beam_EI=EI, floor_mass=4e4,
                          name="portal")
    heavy = Frame(nodes=frame.nodes, elements=frame.elements, EA=frame.EA, EI=frame.EI,
                  supports=frame.supports, masses=frame.masses,
                  member_mass=np.full(frame.n_elements, MBAR), name="portal")
    # the floor carries its nodes' 40 t, the beam's 3 t and half of each column's 2 t
    assert heavy.floor_masses == pytest.approx([4e4 + 6 * MBAR + 4 * MBAR])
    b = frame_matrix_building(heavy)
    assert b.masses[0] == pytest.approx(4e4 + 10 * MBAR)  # (+ the vertical masses after)
    assert b.labels[1:] == ("N3y", "N4y")


def test_a_time_history_refuses_the_consistent_mass_in_one_line() -> None:
    with pytest.raises(ValueError, match=r"cantilever: mass_matrix: a time history takes "
                                         r"lumped masses \(got 'consistent'"):
        frame_matrix_building(_cantilever(2, "consistent"))


def test_bad_member_masses_are_named() -> None:
    with pytest.raises(ValueError, match=r"cantilever: member_mass\[1\]: must be finite and "
                                         r">= 0 \(got -1\.0\)"):
        Frame(nodes=[[0, 0], [0, 1], [0, 2]], elements=[[0, 1], [1, 2]], EA=[1e9] * 2,
              EI=[1e8] * 2, supports=[[1, 1, 1], [0, 0, 0], [0, 0, 0]],
              member_mass=[1.0, -1.0], name="cantilever")
    with pytest.raises(ValueError, match=r"mass_matrix: must be one of lumped, consistent "
                                         r"\(got 'diagonal'\)"):
        _cantilever(2, "diagonal")


def test_member_masses_in_a_model_file(tmp_path: Any) -> None:
    from pounding.config import load_config

    path = tmp_path / "model.toml"
    path.write_text("""
[record]
bundled = "el_centro"
[[building]]
name = "regular"
[building.frame]
bays = [6.0]
storey_heights = [4.0, 3.5]
column_EI = 2e8
beam_EI = 2e8
floor_mass = 4e4
column_mass = [300.0, 250.0]
beam_mass = 500.0
mass_matrix = "lumped"
[[building]]
name = "full"
[building.frame]
nodes = [[0.0, 0.0], [6.0, 0.0], [0.0, 4.0], [6.0, 4.0]]
supports = [{ node = 0 }, { node = 1 }]
members = [{ nodes = [0, 2], EI = 2e8, mass = 300.0 }, { nodes = [1, 3], EI = 2e8 },
           { nodes = [2, 3], EI = 2e8, mass = 500.0 }]
masses = [{ node = 2, mass = [2e4, 0, 0] }, { node = 3, mass = [2e4, 0, 0] }]
[contact]
law = "linear-spring"
k = 1e9
gap = 0.02
""")
    cfg = load_config(path)
    regular, full = (b.frame.build(b.name, None) for b in cfg.building)
    assert regular.mass_matrix == full.mass_matrix == "lumped"
    # columns of storey 1, of storey 2, then the beams of floors 1 and 2
    assert list(regular.member_mass) == [300.0, 300.0, 250.0, 250.0, 500.0, 500.0]
    assert list(full.member_mass) == [300.0, 0.0, 500.0]
    text = path.read_text()
    path.write_text(text.replace('mass = 300.0 }, { nodes = [1, 3]',
                                 'mass = -3.0 }, { nodes = [1, 3]'))
    with pytest.raises(ValueError, match=r"building\[1\]\.frame\.members\[0\]\.mass"):
        load_config(path)
    # a node given a mass twice: refused (OpenSees' mass command overwrites, a sum would not)
    path.write_text(text.replace('{ node = 3, mass = [2e4, 0, 0] }',
                                 '{ node = 2, mass = [2e4, 0, 0] }'))
    with pytest.raises(ValueError, match=r"building\[1\]\.frame\.masses\[1\]\.node: node 2 is "
                                         r"given a mass twice \(masses\[0\] too\)"):
        load_config(path)
    path.write_text(text.replace('"lumped"', '"consistent"'))
    with pytest.raises(ValueError, match=r"building\[0\]: regular: mass_matrix: a time history "
                                         "takes lumped masses"):
        load_config(path)


def test_an_over_damped_stiff_mode_is_named_when_the_steps_run_out() -> None:
    # the members' vertical masses give the frame stiff vertical modes, which the stiffness
    # part of Rayleigh damping over-damps (ζ ≫ 1): the yielding frame's explicit steps must
    # follow their decay; the step budget runs out, and the line says why and what to do
    from pounding.contact.spec import ContactSpec
    from pounding.ground_motion import el_centro
    from pounding.hysteresis.hinges import ElasticPlastic
    from pounding.integrate import IntegrationError, simulate
    from pounding.model import PoundingModel
    from pounding.structure.damping import ModalDamping

    law = ElasticPlastic(k0=1e11, m_y=3e5)
    kw = dict(column_EI=2e8, beam_EI=2e8, floor_mass=4e4, column_mass=300.0, beam_mass=500.0,
              diaphragm=False, column_hinge=law, beam_hinge=law, name="portal")
    frame = regular_frame([6.0], [4.0, 3.5], **kw)  # type: ignore[arg-type]
    model = PoundingModel([frame_matrix_building(frame)], [], ContactSpec("linear-spring",
                                                                           k=1e9))
    # refused before the run where even stable steps would overrun the budget …
    with pytest.raises(IntegrationError, match=r"a yielding frame's damping over-damps a stiff "
                                               r"mode \(B1 'portal': a mode of period .* ms "
                                               r"damped at ζ = .*give that frame modal damping.*"
                                               r"; the run would take at least .* adaptive "
                                               r"steps, beyond its budget of 20,000"):
        simulate(model, el_centro(), duration=3.0, max_rk_steps=20_000)
    # … else stopped where the budget runs out, saying the same
    from pounding.integrate.periods import RK_STABILITY, stiff_frame_rate

    rate, _ = stiff_frame_rate(model)
    budget = int(3.0 * rate / RK_STABILITY) + 1000
    with pytest.raises(IntegrationError, match=rf"stopped after {budget:,} adaptive steps at "
                                               r"t = .*: a yielding frame's damping over-damps "
                                               r"a stiff mode \(B1 'portal'"):
        simulate(model, el_centro(), duration=3.0, max_rk_steps=budget)
    modal = regular_frame([6.0], [4.0, 3.5], damping=ModalDamping(0.05), **kw)  # type: ignore[arg-type]
    r = simulate(PoundingModel([frame_matrix_building(modal)], [], ContactSpec(
        "linear-spring", k=1e9)), el_centro(), duration=3.0, max_rk_steps=200_000)
    # measured 2026-11-27: 32,188 steps for 3 s (the Rayleigh-damped one: 20,000 for 0.17 s)
    assert r.stats.rk_steps < 100_000, r.stats.rk_steps
