"""The LA9-type frame of ``benchmarks/frames_la9.py``: the model as its docstring defines it,
checked against published values and closed forms (fast: the whole file takes a few
seconds).

* Its first period against the published LA9 periods (Ohtori et al. 2004: 0.443 Hz,
  2.26 s, a model with the basement; Gupta & Krawinkler 1999: 2.2–2.4 s): 2.12 s here, with
  the basement left out (fixed at the ground, stiffer; with the basement modelled — the
  ground level restrained horizontally, storey 1's columns continued 3.65 m down — the same
  frame gives 2.21 s).
* Its seismic mass against the published half building (Ohtori et al. 2004: 9.00e6 kg above
  ground for the whole structure), and its gravity loads against that mass's weight.
* Its plastic strength: with elastic–perfectly plastic hinges and first-order geometry the
  pushover's peak is the least upper bound of a family of sway mechanisms (Neal, *The
  Plastic Methods of Structural Analysis*: every mechanism's load bounds the collapse load
  from above, and the pushover's states are statically admissible), computed here by hand
  from the sections' plastic moments.
* The IMK beam constants against Lignos & Krawinkler (2011)'s regressions written in the
  imperial units of FM-2D's ``Spring_IMK.tcl`` (d in inches, F_y in ksi).
* The spring stiffness rule of Ibarra & Krawinkler (2005, App. B): spring and element in
  series give the member its ``6EI/L`` and its 3 % hardening.
* The IMK model's pushover (first mode, gravity, P-Delta) reaches a peak and loses strength
  after it.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import math
import sys
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest

from pounding.hysteresis.hinges import BilinearHinge, ElasticPlastic
from pounding.hysteresis.imk import IMKBilinear
from pounding.structure.frame_analysis import frame_modes, gravity, pushover


def _load_la9() -> ModuleType:
    """``benchmarks/frames_la9.py`` by its path (no change to sys.path: the benchmarks'
    modules stay out of the tests' import path)."""
    path = Path(__file__).resolve().parents[2] / "benchmarks" / "frames_la9.py"
    spec = importlib.util.spec_from_file_location("frames_la9", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("frames_la9", module)
    spec.loader.exec_module(module)
    return module


la9 = _load_la9()

PUBLISHED_T1 = 1.0 / 0.443  # s: Ohtori, Christenson, Spencer & Dyke (2004), J. Eng. Mech. 130(4)
PUBLISHED_MASS = 9.00e6 / 2.0  # kg: the same paper, the structure above ground; one frame of two


@pytest.fixture(scope="module")
def frame() -> object:
    return la9.la9_frame()


def test_the_model_builds_as_its_docstring_says(frame: object) -> None:
    f = frame
    assert (f.n_nodes, f.n_elements, len(f.hinges), f.levels.size) == (60, 99, 198, 9)
    assert f.geometry == "p-delta" and f.diaphragm
    assert f.levels[-1] == pytest.approx(5.49 + 8 * 3.96, abs=1e-9)  # 37.17 m
    assert np.max(f.nodes[:, 0]) == pytest.approx(5 * 9.15, abs=1e-9)
    assert np.all(f.supports[:6]) and not np.any(f.supports[6:])
    # storey 1: exterior W14x370, interior W14x500; the roof beams W24x68 (E = 200 GPa,
    # EI of the element × 11/10)
    inch4 = 0.0254**4
    assert f.EI[0] == pytest.approx(1.1 * 200e9 * 5440 * inch4, rel=1e-12)
    assert f.EI[1] == pytest.approx(1.1 * 200e9 * 8210 * inch4, rel=1e-12)
    assert f.EI[-1] == pytest.approx(1.1 * 200e9 * 1830 * inch4, rel=1e-12)
    beams = [h.law for h in f.hinges if not f.is_column[h.element]]
    columns = [h.law for h in f.hinges if f.is_column[h.element]]
    assert len(beams) == 90 and all(type(b) is IMKBilinear for b in beams)
    assert len(columns) == 108 and all(type(c) is BilinearHinge for c in columns)
    ep = la9.la9_frame(hinges="elastic-plastic")
    assert all(type(h.law) is ElasticPlastic for h in ep.hinges)
    assert all(type(h.law) is BilinearHinge for h in la9.la9_frame(hinges="bilinear").hinges)
    # M_p = Z_x F_y,exp: the roof beam W24x68, Z_x = 177 in³, F_y,exp = 1.1 × 345 MPa
    assert beams[-1].m_y == pytest.approx(177 * 0.0254**3 * 1.1 * 345e6, rel=1e-12)


def test_a_hinge_type_it_does_not_know_is_refused_by_name() -> None:
    with pytest.raises(ValueError, match=r"hinges: must be one of .*'imk'"):
        la9.la9_frame(hinges="imk")


def test_floor_masses_sum_to_the_published_half_building(frame: object) -> None:
    f = frame
    masses = f.floor_masses
    assert masses.tolist() == pytest.approx([5.05e5] + [4.945e5] * 7 + [5.35e5], rel=1e-12)
    # Ohtori et al.'s three rounded floor values sum to their stated total within 0.04 %
    assert float(np.sum(masses)) == pytest.approx(PUBLISHED_MASS, rel=5e-4)
    # gravity = the seismic weight: 20 % on the frame's beams, 80 % on the leaning column
    on_beams = float(np.sum(f.member_loads * f.lengths))
    total = float(np.sum(masses)) * 9.81
    assert on_beams == pytest.approx(0.2 * total, rel=1e-12)
    assert float(np.sum(f.leaning_loads)) == pytest.approx(0.8 * total, rel=1e-12)
    assert not np.any(la9.la9_frame(leaning=False).leaning_loads)


def test_first_period_is_near_the_published_la9_periods(frame: object) -> None:
    state = gravity(frame)
    t1 = frame_modes(frame, state)[0][0]
    t1_alone = frame_modes(la9.la9_frame(leaning=False))[0][0]
    # published 2.26 s with the basement; this model is fixed at the ground (stiffer):
    # 2.12 s, 6 % shorter. The band: ±10 % of the published value.
    assert abs(t1 / PUBLISHED_T1 - 1.0) < 0.10, t1
    assert t1 == pytest.approx(2.117, abs=0.005)
    # the leaning column's P-Delta lengthens it (2.08 s without it)
    assert t1_alone < t1 and t1_alone == pytest.approx(2.082, abs=0.005)
    # the columns' gravity axial loads are below 10 % of A F_y (docstring: P–M interaction
    # left out)
    columns = np.flatnonzero(frame.is_column)
    ratio = [abs(state.axial[e]) / (frame.EA[e] / 200e9 * la9.FY_EXPECTED) for e in columns]
    assert max(ratio) < 0.10


def _imperial_regression(name: str) -> tuple[float, float, float]:
    """θ_p, θ_pc, Λ of an other-than-RBS beam (d ≥ 21 in), as FM-2D's Spring_IMK.tcl writes
    them with Units = 2 (inches, ksi): c1 = 25.4, c2 = 6.895."""
    s = la9.SECTIONS[name]
    htw = (s.d_in - 2 * s.tf_in) / s.tw_in
    bftf = s.bf_in / (2 * s.tf_in)
    half_span_in = 9.15 / 2 / 0.0254
    lb_ry = half_span_in / s.ry_in
    fy_ksi = 1.1 * 345.0 / 6.895
    c1, c2 = 25.4, 6.895
    tp = (0.318 * htw**-0.550 * bftf**-0.345 * lb_ry**-0.023 * (half_span_in / s.d_in)**0.090
          * (c1 * s.d_in / 533)**-0.330 * (c2 * fy_ksi / 355)**-0.130)
    tpc = (7.500 * htw**-0.610 * bftf**-0.710 * lb_ry**-0.110 * (c1 * s.d_in / 533)**-0.161
           * (c2 * fy_ksi / 355)**-0.320)
    lam = 536 * htw**-1.260 * bftf**-0.525 * lb_ry**-0.130 * (c2 * fy_ksi / 355)**-0.291
    return tp, tpc, lam


@pytest.mark.parametrize("name", ["W36x160", "W36x135", "W30x99", "W27x84", "W24x68"])
def test_beam_imk_constants_follow_the_regressions(name: str) -> None:
    c = la9.BEAM_IMK[name]
    tp, tpc, lam = _imperial_regression(name)
    assert c.theta_p == pytest.approx(tp, rel=2e-3)  # 6.895 MPa/ksi is itself rounded
    assert c.theta_pc == pytest.approx(tpc, rel=2e-3)
    assert c.lambda_ == pytest.approx(lam, rel=2e-3)
    assert 0.010 < c.theta_p < 0.025 and 0.05 < c.theta_pc < 0.15 and 0.5 < c.lambda_ < 1.0


def test_springs_in_series_give_the_member_its_6EI_over_L_and_3_percent(frame: object) -> None:
    f = frame
    for e in (0, 1, 60, 98):  # columns (5.49 m) and beams (9.15 m)
        h = f.hinge_at(e, 0).law
        element = 6.0 * f.EI[e] / f.lengths[e]
        section = element / 1.1  # 6 E I_x / L
        member = 1.0 / (1.0 / h.k0 + 1.0 / element)
        assert member == pytest.approx(section, rel=1e-12)
        if isinstance(h, BilinearHinge):
            hardened = 1.0 / (1.0 / (h.hardening * h.k0) + 1.0 / element)
            assert hardened == pytest.approx(0.03 * section, rel=1e-12)


def _mechanism_bound(shape: np.ndarray, levels: np.ndarray) -> float:
    """The least base shear [N] of the sway mechanisms "the lower k storeys sway" (k = 1 …
    9: column bases and the beams of floors 2 … k hinge; at each joint of floor k + 1 the
    column below hinges, or the beams there and the column above, whichever is weaker) and
    "storey j alone" (its columns hinge top and bottom), by virtual work, first order."""
    s, cols, beams = la9.SECTIONS, la9.COLUMNS, la9.BEAMS

    def mp_col(storey: int, line: int) -> float:
        return s[cols[storey][0 if line in (0, 5) else 1]].Mp

    bounds = []
    base = sum(mp_col(0, line) for line in range(6))
    for k in range(1, 10):
        internal = base + sum(2 * 5 * s[beams[f]].Mp for f in range(k - 1))
        for line in range(6):
            ends = 1 if line in (0, 5) else 2
            joint = ends * s[beams[k - 1]].Mp + (mp_col(k, line) if k < 9 else 0.0)
            internal += min(joint, mp_col(k - 1, line))
        bounds.append(internal / float(np.sum(shape * np.minimum(levels, levels[k - 1]))))
    for j in range(9):
        internal = 2 * sum(mp_col(j, line) for line in range(6))
        bounds.append(internal / (float(np.sum(shape[j:])) * la9.STOREY_HEIGHTS[j]))
    return min(bounds)


def test_plastic_pushover_peak_is_the_least_mechanism_load() -> None:
    f = la9.la9_frame(hinges="elastic-plastic", leaning=False)
    f = dataclasses.replace(f, geometry="linear")
    curve = pushover(f, 2.0, pattern="first-mode")
    bound = _mechanism_bound(curve.load_shape, f.levels - f.base)
    # upper-bound theorem: never above; here the bound is reached (the pushover finds the
    # mechanism "the lower 6 storeys sway", 10.33 MN)
    assert curve.peak_base_shear <= bound * (1 + 1e-9)
    assert curve.peak_base_shear == pytest.approx(bound, rel=1e-9)
    assert curve.peak_base_shear == pytest.approx(10.329e6, rel=1e-3)


def test_imk_pushover_reaches_a_peak_then_loses_strength(frame: object) -> None:
    """First mode, gravity and P-Delta first; pushed to 2.5 % roof drift (the benchmark
    goes to 5 %). Measured: peak 9.87 MN (V/W = 0.224) at 0.695 m of roof displacement
    (1.87 % drift), the beams past their capping rotation after it."""
    height = float(frame.levels[-1])
    curve = pushover(frame, 0.025 * height, pattern="first-mode")
    assert curve.stopped == "target"
    k = int(np.argmax(curve.base_shear))
    weight = float(np.sum(frame.floor_masses)) * 9.81
    drift_at_peak = curve.roof_displacement[k] / height
    assert curve.peak_base_shear / weight == pytest.approx(0.224, abs=0.002)
    assert drift_at_peak == pytest.approx(0.0187, abs=0.0005)
    assert curve.base_shear[-1] < 0.9 * curve.peak_base_shear  # softening after the peak
    beams = [i for i, h in enumerate(frame.hinges) if not frame.is_column[h.element]]
    yield_rotation = np.array([frame.hinges[i].law.theta_y for i in beams])
    capping = np.array([frame.hinges[i].law.theta_p for i in beams]) + yield_rotation
    assert np.max(np.abs(curve.hinge_rotations[-1, beams]) - capping) > 0.0
    assert math.isfinite(curve.base_shear[-1])
