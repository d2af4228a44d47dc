"""The cable restrainer link (tension only, slack, elastic, yielding) against solutions
written here from its definition alone.

* Two undamped masses on soft springs, tied by an elastic restrainer with slack and pulled
  apart from rest: the exact piecewise-linear solution (the matrix exponential of each
  phase's first-order system, the phases' ends found by root-finding on it) — slack, taut,
  slack again.
* A yielding restrainer pulled open: its force against the bilinear backbone, and, once it
  has unloaded, against the elastic line of a cable longer by its plastic elongation (read
  off the backbone at the largest opening).
* The SciPy reference (its own restrainer on event-switched branches) under El Centro; the
  energy balance; a model file from the command line.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import CubicHermiteSpline
from scipy.linalg import expm
from scipy.optimize import brentq

from pounding import ContactSpec, PoundingModel, ShearBuilding, el_centro, simulate
from pounding.cli import main
from pounding.devices import Link
from pounding.ground_motion.motion import GroundMotion
from pounding.integrate.reference import simulate_reference

KV = ContactSpec("kelvin-voigt", k=9.3e8, e=0.65)
M1, M2 = 2e5, 3e5


def _masses(period: float, zeta: float = 0.0) -> list[ShearBuilding]:
    return [ShearBuilding.sdof(M1, period=period, damping_ratio=zeta),
            ShearBuilding.sdof(M2, period=period, damping_ratio=zeta)]


def _openings(res) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    t = np.arange(res.displacement.shape[0]) * res.dt
    return (t, res.displacement[:, 1] - res.displacement[:, 0],
            res.velocity[:, 1] - res.velocity[:, 0])


def _crossings(t, f, fdot, level):
    """Times where the cubic Hermite of (f, ḟ) on the output steps crosses ``level``."""
    spline = CubicHermiteSpline(t, f - level, fdot)
    return np.array([r for r in spline.roots(extrapolate=False)
                     if t[0] < r < t[-1]])


def test_an_elastic_slack_restrainer_matches_the_exact_piecewise_solution():
    period, k_r, slack, v0 = 20.0, 4e7, 0.02, 0.1
    links = [Link(("B1F1", "B2F1"), "restrainer", k=k_r, slack=slack)]
    model = PoundingModel(_masses(period), [1.0], KV, devices=links)
    quiet = GroundMotion(0.01, np.zeros(151), name="at rest")
    v_init = np.array([-0.4 * v0, 0.6 * v0])  # the right deck moves away from the left
    res = simulate(model, quiet, dt=1e-3, rtol=1e-10, initial_velocity=v_init)
    # the exact solution: x = [u1, u2, v1, v2, 1], ẋ = A x on each phase
    k_g = [M1 * (2 * np.pi / period) ** 2, M2 * (2 * np.pi / period) ** 2]

    def system(taut: bool) -> np.ndarray:
        a = np.zeros((5, 5))
        a[0, 2] = a[1, 3] = 1.0
        a[2, 0] = -k_g[0] / M1
        a[3, 1] = -k_g[1] / M2
        if taut:  # F = k_r (u2 − u1 − slack): +F on mass 1, −F on mass 2
            for row, sgn, m in ((2, 1.0, M1), (3, -1.0, M2)):
                a[row, 0] -= sgn * k_r / m
                a[row, 1] += sgn * k_r / m
                a[row, 4] -= sgn * k_r * slack / m
        return a

    a_slack, a_taut = system(False), system(True)
    x0 = np.array([0.0, 0.0, *v_init, 1.0])

    def opening(a, x, t):
        y = expm(a * t) @ x
        return y[1] - y[0] - slack

    t1 = brentq(lambda t: opening(a_slack, x0, t), 1e-6, 1.0, xtol=1e-15)
    x1 = expm(a_slack * t1) @ x0
    omega = np.sqrt(k_r * (1 / M1 + 1 / M2))
    t2 = t1 + brentq(lambda t: opening(a_taut, x1, t), 0.5 * np.pi / omega,
                     1.5 * np.pi / omega, xtol=1e-15)
    x2 = expm(a_taut * (t2 - t1)) @ x1
    t, d, ddot = _openings(res)
    exact = np.array([expm(a_slack * s) @ x0 if s <= t1 else
                      expm(a_taut * (s - t1)) @ x1 if s <= t2 else
                      expm(a_slack * (s - t2)) @ x2 for s in t])
    assert np.abs(res.displacement - exact[:, :2]).max() < 1e-8
    # taut for half a period of the pair (the soft ground springs change it by 1e-3)
    assert t2 - t1 == pytest.approx(np.pi / omega, rel=2e-3)
    taut, slack_again = _crossings(t, d, ddot, slack)
    assert abs(taut - t1) < 1e-8 and abs(slack_again - t2) < 1e-8
    # never in compression; zero while slack
    assert res.link_force.min() == 0.0
    assert np.all(res.link_force[(t < t1 - 1e-6) | (t > t2 + 1e-6), 0] == 0.0)
    assert res.energy_balance_error < 1e-8
    # slack, it is stepped exactly (as an open gap is): adaptive steps only while taut
    # (0.17 s of the 1.5 s), against every grid step when stepped adaptively throughout
    rk = simulate(model, quiet, dt=1e-3, rtol=1e-10, initial_velocity=v_init,
                  free_stepping="rk")
    assert res.stats.rk_steps < 0.4 * rk.stats.rk_steps
    assert np.abs(rk.displacement - exact[:, :2]).max() < 1e-8


def test_a_restrainer_that_stays_slack_changes_nothing_and_takes_no_adaptive_step():
    """Its slack never taken up (gaps wide, no pounding either), the pair is stepped exactly
    throughout, as it is without the restrainer: the same motion, no force, no energy."""
    link = Link(("B1F1", "B2F1"), "restrainer", k=3e7, slack=0.5, yield_force=4e5)
    bare = PoundingModel(_masses(1.0, 0.05), [1.0], KV)
    tied = PoundingModel(_masses(1.0, 0.05), [1.0], KV, devices=[link])
    gm = el_centro().trimmed(6.0)
    a, b = simulate(bare, gm), simulate(tied, gm)
    assert a.stats.rk_steps == b.stats.rk_steps == 0
    np.testing.assert_array_equal(b.displacement, a.displacement)
    np.testing.assert_array_equal(b.energy[:, :7], a.energy[:, :7])
    assert np.all(b.link_force == 0.0) and np.all(b.energy[:, 7] == 0.0)


def _yielding_run(hardening: float):
    k_r, slack, f_y = 4e7, 0.01, 1.5e6
    link = Link(("B1F1", "B2F1"), "restrainer", k=k_r, slack=slack, yield_force=f_y,
                hardening=hardening)
    model = PoundingModel(_masses(1.0), [1.0], KV, devices=[link])
    quiet = GroundMotion(0.01, np.zeros(301), name="at rest")
    res = simulate(model, quiet, dt=5e-4, rtol=1e-10,
                   initial_velocity=np.array([-0.6, 0.9]))
    return link, res


@pytest.mark.parametrize("hardening", [0.0, 0.05])
def test_a_yielding_restrainer_follows_the_backbone_and_comes_back_longer(hardening):
    link, res = _yielding_run(hardening)
    k_r, slack, f_y = link.k, link.slack, link.yield_force
    t, d, ddot = _openings(res)
    f = res.link_force[:, 0]
    assert f.min() == 0.0
    # the first opening up to its largest value (located on the output's cubic Hermite)
    t_max = _crossings(t, ddot, np.gradient(ddot, t), 0.0)[0]
    spline = CubicHermiteSpline(t, d, ddot)
    d_max = float(spline(t_max))
    first = t <= t_max
    backbone = f_y + hardening * k_r * (d - slack - f_y / k_r)
    expected = np.clip(np.minimum(k_r * (d - slack), backbone), 0.0, None)
    assert np.abs(f[first] - expected[first]).max() < 1e-6 * f_y
    assert f[first].max() > 0.99 * f_y and d_max > link.yield_elongation + 0.01
    # after it: elastic, tension only, on a cable longer by its plastic elongation
    plastic = d_max - slack - (f_y + hardening * k_r * (d_max - slack - f_y / k_r)) / k_r
    later = t > t_max
    assert np.abs(f[later] - np.clip(k_r * (d[later] - slack - plastic), 0.0, None)).max() \
        < 1e-6 * f_y
    # (it goes slack, and taut again at its longer slack)
    first_slack = np.flatnonzero(later & (f == 0.0))[0]
    assert f[first_slack:].max() > 0.1 * f_y
    assert res.final_z[-1] == pytest.approx(plastic, abs=1e-9)
    assert res.energy_balance_error < 1e-8
    # what the cable dissipated is its plastic work: F on the backbone over the plastic
    # elongation, ∫ (F_y + H s) ds from 0 to s_p (H = b k/(1 − b))
    h = hardening * k_r / (1 - hardening)
    assert res.energy[-1, 7] == pytest.approx(f_y * plastic + 0.5 * h * plastic**2, rel=1e-7)


def test_a_restrainer_under_el_centro_matches_the_scipy_reference():
    link = Link(("B1F1", "B2F1"), "restrainer", k=3e7, slack=0.005, yield_force=4e5,
                hardening=0.02)
    b1 = ShearBuilding.sdof(M1, period=0.5, damping_ratio=0.05)
    b2 = ShearBuilding.sdof(M2, period=1.0, damping_ratio=0.05)
    model = PoundingModel([b1, b2], [0.01], KV, devices=[link])
    gm = el_centro().trimmed(5.0)
    res = simulate(model, gm, rtol=1e-10)
    ref = simulate_reference(model, gm, rtol=1e-10)
    assert res.n_impacts == ref.n_impacts > 0
    assert ref.final_z[-1] > 0.0  # it yielded
    scale = np.abs(ref.displacement).max()
    assert np.abs(res.displacement - ref.displacement).max() < 1e-6 * scale
    f_scale = np.abs(ref.link_force).max()
    assert f_scale > link.yield_force
    assert np.abs(res.link_force - ref.link_force).max() < 1e-6 * f_scale
    assert res.final_z[-1] == pytest.approx(ref.final_z[-1], rel=1e-6)
    assert res.energy[-1, 7] == pytest.approx(ref.energy[-1, 7], rel=1e-6)
    assert res.energy_balance_error < 1e-8 and ref.energy_balance_error < 1e-8


MODEL = """
name = "restrained pair"
[record]
bundled = "el_centro"
duration = 3.0
[[building]]
mass = 2e5
period = 0.5
[[building]]
mass = 3e5
period = 1.0
[contact]
law = "kelvin-voigt"
k = 9.3e8
e = 0.65
gap = 0.01
"""

RESTRAINER = """[[device]]
type = "restrainer"
floors = ["B1F1", "B2F1"]
k = 3e7
slack = 0.005
yield_force = 4e5
hardening = 0.02
"""


def test_a_restrainer_in_a_model_file_runs_from_the_command_line(tmp_path: Path, capsys):
    f = tmp_path / "m.toml"
    f.write_text(MODEL + RESTRAINER)
    assert main(["run", str(f), "--out", str(tmp_path / "o"), "--no-figures"]) == 0
    s = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert s["links"][0]["name"] == "B1F1-B2F1"
    assert s["energy_balance_error"] < 1e-7


@pytest.mark.parametrize("change, line", [
    (("slack = 0.005", "slack = -0.005"), "device[0].slack"),
    (("hardening = 0.02", "hardening = 1.0"), "device[0].hardening"),
    (("yield_force = 4e5", "yield_force = 0"), "device[0].yield_force"),
    (("k = 3e7\n", ""), "device[0].k: required by a restrainer device"),
    (("slack = 0.005\n", ""), "device[0].slack: required by a restrainer device"),
    (("k = 3e7\n", "k = 3e7\nc = 1e5\n"), "device[0].c: not used by a restrainer device"),
])
def test_bad_restrainer_values_get_one_line_naming_the_field(tmp_path: Path, capsys, change,
                                                              line):
    f = tmp_path / "m.toml"
    f.write_text(MODEL + RESTRAINER.replace(*change))
    assert main(["run", str(f), "--out", str(tmp_path / "o"), "--no-figures"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and line in err[0], err
    assert not (tmp_path / "o").exists()


def test_a_restrainer_refuses_what_it_does_not_have():
    with pytest.raises(ValueError, match="^c: a restrainer has no dashpot"):
        Link(("B1F1", "B2F1"), "restrainer", c=1e5, k=1e7, slack=0.01)
    with pytest.raises(ValueError, match="^slack: a restrainer needs its slack"):
        Link(("B1F1", "B2F1"), "restrainer", k=1e7)
    with pytest.raises(ValueError, match="^slack: only a restrainer"):
        Link(("B1F1", "B2F1"), "kelvin", c=1e5, k=1e7, slack=0.01)


def test_each_links_dissipated_energy_leaves_out_what_its_springs_hold() -> None:
    """A taut elastic restrainer beside a Maxwell link at the end of a run: the restrainer
    has dissipated nothing (its cables hold F²/(2k), given back), the Maxwell link its
    dashpot's work (its spring's z is its own, not the restrainer's elongation), and their
    sum is the solver's `links` energy to the trapezoidal rule's order."""
    from pounding.contact.spec import ContactSpec
    from pounding.devices import Link
    from pounding.ground_motion import el_centro
    from pounding.integrate import simulate
    from pounding.model import PoundingModel
    from pounding.structure import ShearBuilding

    a = ShearBuilding.sdof(2e5, period=0.5, name="A")
    b = ShearBuilding.sdof(3e5, period=1.0, name="B")
    links = [Link(("B1F1", "B2F1"), "restrainer", k=2e7, slack=0.0),
             Link(("B1F1", "B2F1"), "maxwell", k=1e7, c=1e5, name="M")]
    model = PoundingModel([a, b], [0.5], ContactSpec("kelvin-voigt", k=1e9, e=0.6),
                          devices=links)
    res = simulate(model, el_centro(), duration=3.3, dt=0.001)
    assert res.link_force[-1, 0] > 1e5  # (taut at the end: its cables hold energy)
    assert abs(res.link_dissipated[0]) < 1e-4 * res.energy[-1, 7]
    assert res.link_dissipated.sum() == pytest.approx(res.energy[-1, 7], rel=1e-4)
