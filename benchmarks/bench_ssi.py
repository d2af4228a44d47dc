"""Soil–structure interaction (issue 27): a pounding pair with one building on a flexible
base, pounding against OpenSeesPy on the same model and record, in one process — OpenSees'
matrices against pounding's, its accuracy as its step shrinks, and the speed of both, with
the cost of the flexible base against the same pair on a fixed base.

    PYTHONPATH=src:benchmarks python benchmarks/bench_ssi.py                # all, ~2–4 min
    PYTHONPATH=src:benchmarks python benchmarks/bench_ssi.py --sections speed --rounds 5
    PYTHONPATH=src:benchmarks python benchmarks/bench_ssi.py --sections accuracy --duration 10

The pair (left to right), El Centro 1940 (180) with a zero sample in front (both tools
start at rest under zero ground acceleration, as OpenSees' Newmark assumes), 40.00 s:

* **A** — 5 storeys of 3.5 m, 3×10⁵ kg a floor, uniform storey stiffness for T1 = 0.6 s on
  a fixed base, 5 % Rayleigh damping in its fixed-base modes 1 and 2. (a) on a flexible base:
  a rigid 12 m × 12 m surface mat of 1.0×10⁶ kg and rotational inertia
  ``m_f L²/12`` = 1.2×10⁷ kg·m² (a thin mat about its own axis), explicit sway ``Fdn`` and
  rocking ``Fdn_r`` DOFs, on a half-space with V_s = 150 m/s, ρ = 1800 kg/m³, ν = 0.33
  (Pais & Kausel's springs, Wolf's cone dashpots at the flexible-base mode: docs/ground.md);
  (b) on a fixed base;
* **B** — 3 storeys of 3.5 m, 2.5×10⁵ kg a floor, T1 = 0.4 s, 5 % Rayleigh, fixed base;
* contacts at the three shared floors, gap 30 mm, Kelvin–Voigt k = 9.3×10⁸ N/m with the
  dashpot of e = 0.65 (Anagnostopoulos) for the two floor masses, pulling until the gap
  reopens (pounding ``tension=True``, OpenSees ``ViscoelasticGap``).

The issue's own example (``examples/ssi_sdof.toml``) has a massless footing, condensed out
of pounding's matrices; OpenSees has no such element, so it is not run here.

Sections:

model     pounding's periods and impedances; OpenSees' M, C, K (assembled by its ``GimmeMCK``
          integrator, ``opensees_ssi.py``) against pounding's, and its eigen periods.
linear    no pounding (gap 10 m): OpenSees at each ``--steps`` step against pounding (exact
          between samples): peaks of the floors, the footing's sway and rocking, the
          largest history difference and its observed order (Newmark: 2).
accuracy  with pounding: impacts, peak contact force, peak floor displacements of A and B,
          the footing's peak sway and rocking; OpenSees' relative differences from
          pounding's values at each step, and its largest history difference.
reference pounding against ``simulate_reference`` (SciPy DOP853, rtol 1e-10, every contact
          event located) on the flexible-base pair, first ``--reference-duration`` s.
speed     whole runs, warm (compilation excluded), alternating: (1) pounding's flexible-base
          pair against its fixed-base pair, with pounding and without (gap 10 m), at output
          steps 1 ms and 10 ms, ``--rounds`` rounds of each (the issue's goal: flexible
          ≤ 1.5× fixed); (2) pounding (output step 10 ms) against OpenSees at its practice
          step ``--opensees-dt`` (the record's 10 ms), both pairs, ``--opensees-rounds``
          rounds. Best (median–worst) and the spread of the ratio over every pair of runs.
          pounding: the whole ``simulate()`` call on a built model; OpenSees: the domain's
          build and the analysis loop reading every DOF and contact force each step.
cost      where the flexible base's time goes, without pounding (gap 10 m, exact steps
          only, output step 1 ms; the kernel's own timer, and the whole call less it):
          controls that separate the extra DOFs from the footing's couplings to every
          floor — A on a fixed base, a 7-storey A on a fixed base (10 DOFs, half-
          bandwidth 1), A on a massless footing (condensed: 8 DOFs, K and C dense in A's
          block), A on the footing with mass (10 DOFs; the kernel keeps a band of 1 and
          the footing's entries apart, ``kernel_model.banding``: column ``bw+far``) — the kernel's
          banded product ``K u, C v`` (``rhs.band_mv``, timed in a compiled loop with the
          arrays ``simulate`` passes, as ``profile_kernel.py`` does), and the ratio
          flexible / fixed for A of 5, 10 and 20 storeys (T1 = 0.12 n s).
yielding  A with bilinear storeys (yield at 0.5 % drift, 5 % hardening) on the footing with
          mass against the same A on a fixed base, beside B, with pounding and without (gap
          10 m), output step 10 ms, ``--rounds`` alternating rounds: whole ``simulate()``
          calls (every run adaptive: yielding storeys), the ratio flexible / fixed, impacts,
          RK steps and the first storey's ductility (no OpenSees peer here: the yielding
          storeys on a rocking footing are checked against the SciPy reference in
          tests/integrate/test_flexible_base_yielding.py).
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import opensees_models as osm
import opensees_ssi as oss
import _figures
from _environment import load, parse_list, print_environment
from _memory import keep_freed_memory

from pounding.contact.spec import ContactSpec
from pounding.hysteresis import Bilinear
from pounding.ground_motion import GroundMotion, el_centro
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure import ShearBuilding
from pounding.structure.damping import RayleighDamping
from pounding.structure.foundation import Footing, Soil, flexible_base

SECTIONS = ("model", "linear", "accuracy", "reference", "speed", "cost", "yielding")
DEFAULT_STEPS = "0.01,0.005,0.002,0.001"

STOREY_HEIGHT = 3.5  #: m, both buildings
A_STOREYS, A_MASS, A_PERIOD = 5, 3.0e5, 0.6  #: building A (left): storeys, kg a floor, s
B_STOREYS, B_MASS, B_PERIOD = 3, 2.5e5, 0.4  #: building B (right)
FOOTING = Footing(length=12.0, width=12.0, mass=1.0e6, inertia=1.0e6 * 12.0 ** 2 / 12.0)
SOIL = Soil(150.0, 1800.0, 0.33)
GAP = 0.03  #: m
WIDE_GAP = 10.0  #: m: nothing touches
K_KV = osm.K_KV_DEFAULT  #: N/m
RESTITUTION = 0.65
POUNDING_DT = 1e-3
"""pounding's output step in the accuracy sections [s] (its answer does not depend on it;
1 ms is every OpenSees step's common multiple here)."""


# ====================================================================== the models
def shear_building(n: int, mass: float, period: float, name: str) -> ShearBuilding:
    masses, stiffnesses = osm.uniform_building(n, mass, period)
    return ShearBuilding.uniform(n, float(masses[0]), float(stiffnesses[0]),
                                 height=STOREY_HEIGHT, damping=RayleighDamping(0.05), name=name)


@dataclass
class Case:
    """One pair as pounding's model and as the numbers OpenSees is built from."""

    name: str
    model: PoundingModel
    left: oss.Building
    right: oss.Building
    contacts: list[tuple[int, int, float, float]]  #: (left floor, right floor, K, C)
    gap: float

    @property
    def flexible(self) -> bool:
        return self.left.soil is not None

    @property
    def a_floors(self) -> slice:
        return slice(0, self.left.n)

    @property
    def b_floors(self) -> slice:
        return slice(self.left.dofs, self.left.dofs + self.right.n)

    def opensees(self, motion: GroundMotion, dt: float, duration: float) -> oss.History:
        import openseespy.opensees as ops

        return oss.run_pair(ops, self.left, self.right, self.contacts, self.gap, motion.accel,
                            motion.dt, dt, duration)


def _spec(b: ShearBuilding, soil: oss.Soil | None) -> oss.Building:
    a0, a1 = b.damping.coefficients(b.mass_matrix(), b.stiffness_matrix())
    return oss.Building(list(map(float, b.masses)), list(map(float, b.stiffnesses)),
                        list(map(float, b.heights)), float(a0), float(a1), soil)


def make_case(flexible: bool, gap: float) -> Case:
    """Pair (a) (``flexible``) or (b), with ``gap`` [m] (module docstring)."""
    a = shear_building(A_STOREYS, A_MASS, A_PERIOD, "A")
    b = shear_building(B_STOREYS, B_MASS, B_PERIOD, "B")
    soil = None
    left: Any = a
    if flexible:
        left = flexible_base(a, FOOTING, SOIL)
        imp = left.foundation.impedance
        soil = oss.Soil(FOOTING.mass, FOOTING.inertia, imp.k_x, imp.k_r, imp.c_x, imp.c_r)
    spec = ContactSpec("kelvin-voigt", k=K_KV, e=RESTITUTION, formula="anagnostopoulos",
                       tension=True)
    model = PoundingModel([left, b], [gap], spec,
                          name=f"A on {'soil' if flexible else 'a fixed base'} beside B")
    contacts = []
    for c in model.contacts:  # floor to floor (ξ = 1): equal storey heights
        if c.left.xi != 1.0 or c.right.xi != 1.0:
            raise AssertionError(f"{c.label}: a floor-to-column contact, not modelled here")
        contacts.append((int(c.left.upper), int(c.right.upper), float(c.law.k), float(c.law.c)))
    return Case("(a) flexible base" if flexible else "(b) fixed base", model,
                _spec(a, soil), _spec(b, None), contacts, gap)


def record() -> GroundMotion:
    """El Centro with a zero sample in front (module docstring)."""
    g = el_centro()
    return GroundMotion(g.dt, np.concatenate([[0.0], g.accel]), name=g.name)


# ====================================================================== measures
@dataclass
class Measures:
    """What the accuracy tables compare (SI units)."""

    impacts: int
    force: float  #: peak contact force, all contacts [N]
    peaks: np.ndarray  #: peak |u| of every DOF [m, rad]
    time: np.ndarray
    u: np.ndarray  #: (nt, N) history

    def floor_peak(self, case: Case, which: str) -> float:
        return float(np.max(self.peaks[case.a_floors if which == "A" else case.b_floors]))

    def footing(self, case: Case) -> tuple[float, float]:
        if not case.flexible:
            return math.nan, math.nan
        n = case.left.n
        return float(self.peaks[n]), float(self.peaks[n + 1])


def pounding_measures(r: Any) -> Measures:
    return Measures(int(r.n_impacts), float(np.max(r.peak_contact_force, initial=0.0)),
                    np.asarray(r.peak_displacement, dtype=float), np.asarray(r.time),
                    np.asarray(r.displacement))


def opensees_measures(h: oss.History) -> Measures:
    return Measures(h.n_impacts, float(np.max(h.force, initial=0.0)),
                    np.max(np.abs(h.u), axis=0), h.time, h.u)


def pct(x: float, ref: float) -> float:
    if ref == 0.0:
        return 0.0 if x == 0.0 else math.inf
    return 100.0 * (x - ref) / ref


def history_difference(ours: Measures, theirs: Measures, cols: slice | list[int]) -> float:
    """Largest |u_OpenSees − u_pounding| of the DOFs ``cols`` at the times both have, in
    % of pounding's largest |u| of those DOFs (OpenSees' steps are multiples of 1 ms)."""
    stride = round((theirs.time[1] - theirs.time[0]) / (ours.time[1] - ours.time[0]))
    a = theirs.u[:, cols]
    b = ours.u[::stride][: a.shape[0], cols]
    a = a[: b.shape[0]]
    return 100.0 * float(np.max(np.abs(a - b)) / np.max(np.abs(ours.u[:, cols])))


def spread(values: list[float], scale: float = 1.0, fmt: str = ".2f") -> str:
    """``best (median–worst) ×N`` of timing repeats, times ``scale``."""
    v = [scale * x for x in values]
    return f"{min(v):{fmt}} ({statistics.median(v):{fmt}}–{max(v):{fmt}}) ×{len(v)}"


def ratio_line(num: list[float], den: list[float]) -> str:
    """Best / best, median / median, and every pair of runs' ratio's range."""
    pairs = [a / b for a in num for b in den]
    return (f"{min(num) / min(den):.2f}× (best), "
            f"{statistics.median(num) / statistics.median(den):.2f}× (median), "
            f"{min(pairs):.2f}–{max(pairs):.2f}× over every pair of runs")


# ====================================================================== sections
def section_model(cases: dict[str, Case]) -> None:
    import openseespy.opensees as ops

    print("\n== model: pounding's matrices against OpenSees' (assembled from beams, "
          "zeroLength springs and dashpots) ==")
    fb = cases["flexible"].model.buildings[0]
    f = fb.foundation
    imp = f.impedance
    print(f"  A on a fixed base: periods {', '.join(f'{t:.4f}' for t in f.fixed_base_periods)} s")
    print(f"  A on soil: periods {', '.join(f'{t:.4f}' for t in fb.modes().periods)} s; "
          f"k_x = {imp.k_x:.5g} N/m, k_r = {imp.k_r:.5g} N·m/rad, c_x = {imp.c_x:.5g} N·s/m, "
          f"c_r = {imp.c_r:.5g} N·m·s/rad (at {imp.omega:.4f} rad/s); DOFs {list(fb.labels)}")
    print(f"  B: periods {', '.join(f'{t:.4f}' for t in cases['fixed'].model.buildings[1].modes().periods)} s")
    law = cases["flexible"].model.contacts[0].law
    print(f"  contacts {[c.label for c in cases['flexible'].model.contacts]}: k = {law.k:.4g} "
          f"N/m, c = {law.c:.6g} N·s/m")
    for case in cases.values():
        tags = oss.build_pair(ops, case.left, case.right, case.contacts, WIDE_GAP)
        M, C, K = oss.matrices(ops, tags)
        sys_ = case.model.system
        n = M.shape[0]
        T = oss.periods(ops, n)
        ops.wipe()
        Tp = np.sort(np.concatenate([b.modes().periods for b in case.model.buildings]))[::-1]
        diffs = [float(np.max(np.abs(X - np.asarray(Y))) / np.max(np.abs(np.asarray(Y))))
                 for X, Y in ((M, sys_.M), (C, sys_.C), (K, case.model.linear_stiffness()))]
        print(f"  {case.name}: {n} DOFs; OpenSees − pounding, largest entry / largest of "
              f"pounding's: M {diffs[0]:.1e}, C {diffs[1]:.1e}, K {diffs[2]:.1e}; periods "
              f"largest relative difference {np.max(np.abs(T / Tp - 1.0)):.1e}")


def _pounding_run(case: Case, motion: GroundMotion, duration: float) -> Any:
    return simulate(case.model, motion, dt=POUNDING_DT, duration=duration)


HEAD = (f"{'':<18} {'impacts':>7} {'F max MN':>9} {'A max|u| mm':>11} {'B max|u| mm':>11} "
        f"{'sway mm':>8} {'rock mrad':>9} | {'ΔF %':>8} {'ΔA %':>8} {'ΔB %':>8} {'Δsway %':>8} "
        f"{'Δrock %':>8} {'Δu hist %':>9} {'order':>5} {'retried':>7} {'s':>6}")


def _row(label: str, m: Measures, case: Case, errs: str = "") -> str:
    sway, rock = m.footing(case)
    fmt = (lambda x, s: "—" if math.isnan(x) else f"{s * x:.4f}")
    return (f"{label:<18} {m.impacts:>7} {m.force / 1e6:>9.4f} {1e3 * m.floor_peak(case, 'A'):>11.4f} "
            f"{1e3 * m.floor_peak(case, 'B'):>11.4f} {fmt(sway, 1e3):>8} {fmt(rock, 1e3):>9}"
            + errs)


def _floors(case: Case) -> list[int]:
    return list(range(case.left.n)) + list(range(case.b_floors.start, case.b_floors.stop))


def _errors(ours: Measures, theirs: Measures, case: Case, hist: float, order: str,
            h: oss.History) -> str:
    s_o, r_o = ours.footing(case)
    s_t, r_t = theirs.footing(case)
    cells = [pct(theirs.force, ours.force) if ours.force > 0 else math.nan,
             pct(theirs.floor_peak(case, "A"), ours.floor_peak(case, "A")),
             pct(theirs.floor_peak(case, "B"), ours.floor_peak(case, "B")),
             pct(s_t, s_o) if case.flexible else math.nan,
             pct(r_t, r_o) if case.flexible else math.nan]
    text = " | " + " ".join(f"{'—':>8}" if math.isnan(c) else f"{c:>+8.3f}" for c in cells)
    return (text + f" {hist:>9.4f} {order:>5} {h.retried:>7} {h.wall:>6.2f}"
            + ("" if not h.failed else f"  STOPPED at {h.time[-1]:.3f} s"))


def section_steps(title: str, cases: dict[str, Case], motion: GroundMotion, duration: float,
                  steps: list[float]) -> None:
    print(f"\n== {title} ==")
    print("  OpenSees' differences from pounding's values (pounding: exact between contact "
          "events, peaks located between output steps); Δu hist = largest |u_OS − u| over "
          "the floors of both buildings at OpenSees' steps, in % of pounding's largest "
          "floor |u|; order = log(its ratio) / log(the steps' ratio) between successive "
          "rows (Newmark: 2); retried = steps Newton alone did not complete; s = OpenSees' "
          "wall time (build and analysis with its reads)")
    print(HEAD)
    for case in cases.values():
        gap = f"{case.gap:g} m" if case.gap >= 1.0 else f"{1e3 * case.gap:g} mm"
        print(f"{case.name}, gap {gap}, {duration:.2f} s:")
        ours = pounding_measures(_pounding_run(case, motion, duration))
        print(_row("pounding", ours, case))
        prev, prev_dt = None, None
        for dt in steps:
            h = case.opensees(motion, dt, duration)
            theirs = opensees_measures(h)
            hist = history_difference(ours, theirs, _floors(case))
            order = ("" if prev is None or hist == 0.0 else
                     f"{math.log(prev / hist) / math.log(prev_dt / dt):.2f}")
            prev, prev_dt = hist, dt
            print(_row(f"OpenSees {1e3 * dt:g} ms", theirs, case,
                       _errors(ours, theirs, case, hist, order, h)), flush=True)


def section_reference(case: Case, motion: GroundMotion, duration: float) -> None:
    from pounding.integrate.reference import simulate_reference

    print(f"\n== reference: pounding against simulate_reference (DOP853, rtol 1e-10), "
          f"{case.name}, {duration:.2f} s ==")
    t0 = time.perf_counter()
    ref = pounding_measures(simulate_reference(case.model, motion, dt=POUNDING_DT,
                                               duration=duration))
    t_ref = time.perf_counter() - t0
    ours = pounding_measures(_pounding_run(case, motion, duration))
    sway_o, rock_o = ours.footing(case)
    sway_r, rock_r = ref.footing(case)
    # every DOF against its own largest |u| (floors in m, the rocking in rad)
    worst = max(history_difference(ref, ours, [q])
                for q in range(case.left.dofs + case.right.n))
    print(f"  impacts {ours.impacts} (reference {ref.impacts}); peak force {ours.force:.6g} N "
          f"({pct(ours.force, ref.force):+.2e} %); A max|u| "
          f"{pct(ours.floor_peak(case, 'A'), ref.floor_peak(case, 'A')):+.2e} %, B "
          f"{pct(ours.floor_peak(case, 'B'), ref.floor_peak(case, 'B')):+.2e} %, sway "
          f"{pct(sway_o, sway_r):+.2e} %, rocking {pct(rock_o, rock_r):+.2e} %; every DOF's "
          f"history (floors, sway, rocking) within {worst:.1e} % of its largest |u|; the "
          f"reference took {t_ref:.1f} s")


def _time_pounding(case: Case, motion: GroundMotion, dt: float) -> tuple[float, Any]:
    t0 = time.perf_counter()
    r = simulate(case.model, motion, dt=dt)
    return time.perf_counter() - t0, r


def section_speed(cases: dict[str, Case], wide: dict[str, Case], motion: GroundMotion,
                  rounds: int, os_rounds: int, os_dt: float) -> None:
    print(f"\n== speed: whole runs, {motion.duration:.2f} s, warm, alternating ==")
    print(f"  (1) pounding, flexible-base pair (a) against fixed-base pair (b); {rounds} "
          f"rounds, each: (a), (b) at both output steps, with pounding (gap "
          f"{1e3 * GAP:g} mm) and without (gap {WIDE_GAP:g} m)")
    variants = [(f"gap {1e3 * GAP:g} mm", cases), (f"gap {WIDE_GAP:g} m", wide)]
    dts = (1e-3, 1e-2)
    for _, group in variants:  # warm-up: compilation, the models' caches
        for case in group.values():
            for dt in dts:
                _time_pounding(case, motion, dt)
    walls: dict[tuple[str, str, float], list[float]] = {}
    info: dict[tuple[str, str, float], Any] = {}
    for _ in range(rounds):
        for vname, group in variants:
            for dt in dts:
                for key, case in group.items():
                    w, r = _time_pounding(case, motion, dt)
                    walls.setdefault((vname, key, dt), []).append(w)
                    info[(vname, key, dt)] = r
    print(f"  {'':<14} {'output':>6} {'pair':<18} {'impacts':>7} {'RK steps':>8} "
          f"{'whole simulate() ms, best (median–worst)':>42}  flexible / fixed")
    for vname, _ in variants:
        for dt in dts:
            for key in ("flexible", "fixed"):
                r = info[(vname, key, dt)]
                ratio = (ratio_line(walls[(vname, "flexible", dt)], walls[(vname, "fixed", dt)])
                         if key == "flexible" else "")
                print(f"  {vname:<14} {1e3 * dt:>4g}ms {cases[key].name:<18} {r.n_impacts:>7} "
                      f"{r.stats.rk_steps:>8} {spread(walls[(vname, key, dt)], 1e3):>42}  {ratio}")
                if key == "flexible":
                    fixed = info[(vname, "fixed", dt)]
                    _figures.figure(
                        f"{vname}, output step {1e3 * dt:g} ms: flexible-base pair (a), "
                        f"{r.n_impacts} impacts", min(walls[(vname, key, dt)]),
                        f"the fixed-base pair (b), {fixed.n_impacts} impacts",
                        min(walls[(vname, "fixed", dt)]), ratio_meaning="pounding / peer",
                        goal="<= 1.5x" if vname.endswith(" m") else None,
                        spread=f"best of {rounds} alternating rounds; {ratio}")
    print("  (the issue's goal: the flexible-base pair's run ≤ 1.5× the fixed-base pair's)")

    import openseespy.opensees as ops  # noqa: F401  (imported before the timed runs)

    print(f"\n  (2) pounding (output step 10 ms) against OpenSees (Newmark at {1e3 * os_dt:g} ms, "
          f"its practice step: the record's), {os_rounds} rounds, each: pounding (a), "
          f"OpenSees (a), pounding (b), OpenSees (b)")
    ours_t: dict[str, list[float]] = {k: [] for k in cases}
    theirs_t: dict[str, list[float]] = {k: [] for k in cases}
    last: dict[str, tuple[Any, oss.History]] = {}
    for _ in range(os_rounds):
        for key, case in cases.items():
            w, r = _time_pounding(case, motion, 1e-2)
            ours_t[key].append(w)
            h = case.opensees(motion, os_dt, motion.duration)
            theirs_t[key].append(h.wall)
            last[key] = (r, h)
    for key, case in cases.items():
        r, h = last[key]
        ours, theirs = pounding_measures(r), opensees_measures(h)
        sway_o, rock_o = ours.footing(case)
        sway_t, rock_t = theirs.footing(case)
        print(f"  {case.name}: pounding {spread(ours_t[key], 1e3)} ms; OpenSees "
              f"{spread(theirs_t[key], 1e3, '.0f')} ms ({h.retried} steps retried); OpenSees "
              f"/ pounding {ratio_line(theirs_t[key], ours_t[key])}")
        _figures.figure(f"{case.name}: whole run, pounding's output 10 ms, OpenSees' step "
                        f"{1e3 * os_dt:g} ms", min(ours_t[key]), _figures.opensees_name(),
                        min(theirs_t[key]), ratio_meaning="OpenSees / pounding",
                        spread=f"best of {os_rounds} alternating rounds")
        print(f"      OpenSees at {1e3 * os_dt:g} ms there: impacts {theirs.impacts} (pounding "
              f"{ours.impacts}), ΔF {pct(theirs.force, ours.force):+.2f} %, ΔA "
              f"{pct(theirs.floor_peak(case, 'A'), ours.floor_peak(case, 'A')):+.2f} %, ΔB "
              f"{pct(theirs.floor_peak(case, 'B'), ours.floor_peak(case, 'B')):+.2f} %"
              + (f", Δsway {pct(sway_t, sway_o):+.2f} %, Δrock {pct(rock_t, rock_o):+.2f} %"
                 if case.flexible else ""))


def section_yielding(motion: GroundMotion, rounds: int) -> None:
    law = Bilinear(yield_drift=0.005 * STOREY_HEIGHT, hardening=0.05)
    spec = ContactSpec("kelvin-voigt", k=K_KV, e=RESTITUTION, formula="anagnostopoulos",
                       tension=True)
    b = shear_building(B_STOREYS, B_MASS, B_PERIOD, "B")
    models: dict[tuple[float, str], PoundingModel] = {}
    for gap in (GAP, WIDE_GAP):
        a = shear_building(A_STOREYS, A_MASS, A_PERIOD, "A").with_storey_law(law)
        models[(gap, "flexible")] = PoundingModel([flexible_base(a, FOOTING, SOIL), b], [gap],
                                                  spec)
        models[(gap, "fixed")] = PoundingModel([a, b], [gap], spec)
    print(f"\n== yielding: A with bilinear storeys (yield drift {1e3 * law.yield_drift:g} mm, "
          f"b = {law.hardening:g}) on the footing vs on a fixed base, beside B; "
          f"{motion.duration:.2f} s, output step 10 ms, warm, {rounds} alternating rounds ==")
    for m in models.values():  # warm-up: compilation, the models' caches
        simulate(m, motion, dt=1e-2)
    walls: dict[tuple[float, str], list[float]] = {k: [] for k in models}
    last: dict[tuple[float, str], Any] = {}
    for _ in range(rounds):
        for key, m in models.items():
            t0 = time.perf_counter()
            last[key] = simulate(m, motion, dt=1e-2)
            walls[key].append(time.perf_counter() - t0)
    print(f"  {'':<12} {'A on':<10} {'impacts':>7} {'RK steps':>8} {'μ storey 1':>10} "
          f"{'whole simulate() ms, best (median–worst)':>42}  flexible / fixed")
    for gap in (GAP, WIDE_GAP):
        for base in ("flexible", "fixed"):
            r = last[(gap, base)]
            ratio = (ratio_line(walls[(gap, "flexible")], walls[(gap, "fixed")])
                     if base == "flexible" else "")
            label = f"gap {1e3 * gap:g} mm" if gap < 1 else f"gap {gap:g} m"
            print(f"  {label:<12} {base:<10} {r.n_impacts:>7} {r.stats.rk_steps:>8} "
                  f"{float(r.ductility[0]):>10.2f} {spread(walls[(gap, base)], 1e3):>42}  "
                  f"{ratio}")


def _catch_kernel_arguments(model: PoundingModel, motion: GroundMotion) -> dict[str, Any]:
    """The arguments ``simulate`` passes to the compiled kernel, by name (as
    ``profile_kernel.kernel_arguments``; 1 s of the record)."""
    from pounding import integrate

    caught: dict[str, Any] = {}
    real = integrate.integrate_chunk
    code = real.py_func.__code__
    names = code.co_varnames[:code.co_argcount]

    def catch(*args: Any) -> None:
        caught.update(zip(names, args))
        real(*args)

    integrate.integrate_chunk = catch
    try:
        simulate(model, motion, dt=1e-3, duration=1.0)
    finally:
        integrate.integrate_chunk = real
    return caught


def _band_mv_ns(model: PoundingModel, motion: GroundMotion, calls: int = 1_000_000) -> float:
    """ns per call of the kernel's banded ``K u, C v`` on ``model``'s arrays (best of 3)."""
    from numba import njit

    from pounding.integrate import rhs

    @njit(cache=False)
    def loop(calls: int, kb: Any, cb: Any, y: Any, n: int, bw: int, lin: Any) -> float:
        total = 0.0
        for _ in range(calls):
            y[0] += 1e-12  # not loop-invariant
            rhs.band_mv(kb, cb, y, n, bw, lin)
            total += lin[1, n - 1]
        return total

    fl = _catch_kernel_arguments(model, motion)["km"][0]
    n = fl.m_diag.shape[0]
    y = np.linspace(0.1, 1.0, 2 * n)
    lin = np.zeros((2, n))
    loop(10, fl.k_band, fl.c_band, y, n, fl.bw, lin)
    best = math.inf
    for _ in range(3):
        t0 = time.perf_counter()
        loop(calls, fl.k_band, fl.c_band, y, n, fl.bw, lin)
        best = min(best, time.perf_counter() - t0)
    return 1e9 * best / calls


def section_cost(motion: GroundMotion, rounds: int) -> None:
    from pounding.integrate.kernel_model import banding

    print(f"\n== cost: where the flexible base's time goes (no pounding: gap {WIDE_GAP:g} m, "
          f"exact steps only; output step 1 ms; {rounds} rounds, alternating) ==")
    a = shear_building(A_STOREYS, A_MASS, A_PERIOD, "A")
    b = shear_building(B_STOREYS, B_MASS, B_PERIOD, "B")
    a7 = shear_building(A_STOREYS + 2, A_MASS, A_PERIOD, "A7")
    massless = Footing(length=FOOTING.length, width=FOOTING.width)
    spec = make_case(False, WIDE_GAP).model.contact
    base = "A fixed, B (pair (b))"
    # name: (model, the name of the model its kernel time is divided by)
    models: dict[str, tuple[PoundingModel, str]] = {
        base: (PoundingModel([a, b], [WIDE_GAP], spec), base),
        "A 7 storeys fixed, B": (PoundingModel([a7, b], [WIDE_GAP], spec), base),
        "A massless footing, B": (PoundingModel([flexible_base(a, massless, SOIL), b],
                                                [WIDE_GAP], spec), base),
        "A on soil, B (pair (a))": (PoundingModel([flexible_base(a, FOOTING, SOIL), b],
                                                  [WIDE_GAP], spec), base),
    }
    for n in (10, 20):
        an = shear_building(n, A_MASS, 0.12 * n, f"A{n}")
        fixed = f"A {n} storeys fixed, B"
        models[fixed] = (PoundingModel([an, b], [WIDE_GAP], spec), fixed)
        models[f"A {n} storeys on soil, B"] = (PoundingModel(
            [flexible_base(an, FOOTING, SOIL), b], [WIDE_GAP], spec), fixed)
    kernel: dict[str, list[float]] = {k: [] for k in models}
    whole: dict[str, list[float]] = {k: [] for k in models}
    for m, _ in models.values():
        simulate(m, motion)  # warm-up
    steps = 0
    for _ in range(rounds):
        for key, (m, _) in models.items():
            t0 = time.perf_counter()
            r = simulate(m, motion)
            whole[key].append(time.perf_counter() - t0)
            kernel[key].append(r.wall_time)
            steps = r.time.size - 1
    print(f"  {'model':<26} {'DOFs':>4} {'bw+far':>5} {'blocks':>7} "
          f"{'kernel ns/step, best (median–worst)':>38} {'÷ fixed':>7} "
          f"{'outside the kernel ms':>22}")
    for key, (m, ref) in models.items():
        bw, far = banding(m.linear_stiffness(), np.asarray(m.system.C))
        blocks = "+".join(str(bl.n) for bl in m.buildings)
        outside = [w - k for w, k in zip(whole[key], kernel[key])]
        ratio = statistics.median(kernel[key]) / statistics.median(kernel[ref])
        print(f"  {key:<26} {m.system.M.shape[0]:>4} {f'{bw}+{len(far)}':>5} {blocks:>7} "
              f"{spread(kernel[key], 1e9 / steps, '.0f'):>38} {ratio:>7.2f} "
              f"{1e3 * statistics.median(outside):>22.2f}")
    print("  (bw+far: the half-bandwidth the kernel stores K and C with, and their entries "
          "outside it (kernel_model.banding); ÷ fixed: median kernel time over that of the "
          "same pair with A on a fixed base (pair (b) for the 5- and 7-storey rows); outside "
          "the kernel: the median of the whole simulate() call less the kernel's timer)")
    for key in (base, "A on soil, B (pair (a))"):
        print(f"  kernel's banded K u, C v (rhs.band_mv), {key}: "
              f"{_band_mv_ns(models[key][0], motion):.0f} ns a call (one a step for the outputs, "
              "one a stage of every RK step)")


# ====================================================================== main
def _floats(ap: argparse.ArgumentParser, name: str, text: str) -> list[float]:
    try:
        values = [float(s) for s in text.split(",") if s.strip()]
    except ValueError:
        ap.error(f"--{name}: need numbers separated by commas (got {text!r})")
    if not values or any(not (v > 0) for v in values):
        ap.error(f"--{name}: need numbers > 0 (got {text!r})")
    return values


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help=f"comma-separated, of {', '.join(SECTIONS)} (default all)")
    ap.add_argument("--steps", default=DEFAULT_STEPS,
                    help=f"linear, accuracy: OpenSees' steps [s] (default {DEFAULT_STEPS})")
    ap.add_argument("--duration", type=float, default=None,
                    help="linear, accuracy: seconds of the record (default all, 40.00 s)")
    ap.add_argument("--reference-duration", type=float, default=None,
                    help="reference: seconds (default all of the record, ~1 min)")
    ap.add_argument("--rounds", type=int, default=15,
                    help="speed (1): rounds of pounding runs (default 15)")
    ap.add_argument("--opensees-rounds", type=int, default=3,
                    help="speed (2): rounds with OpenSees (default 3)")
    ap.add_argument("--opensees-dt", type=float, default=0.01,
                    help="speed (2): OpenSees' step [s] (default 0.01, the record's)")
    ap.add_argument("--fresh-memory", action="store_true",
                    help="leave glibc's malloc as it is (default: keep freed memory for reuse, "
                         "benchmarks/_memory.py)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_ssi", "Soil-structure interaction")
    wanted = parse_list(ap, args.sections, SECTIONS)
    steps = _floats(ap, "steps", args.steps)
    if any(abs(s / POUNDING_DT - round(s / POUNDING_DT)) > 1e-9 for s in steps):
        ap.error(f"--steps: need multiples of {POUNDING_DT:g} s (got {args.steps!r})")
    if args.rounds < 1 or args.opensees_rounds < 1:
        ap.error("--rounds, --opensees-rounds: need at least 1")
    for name in ("duration", "reference_duration", "opensees_dt"):
        v = getattr(args, name)
        if v is not None and not v > 0:
            ap.error(f"--{name.replace('_', '-')}: need seconds > 0 (got {v})")
    kept = keep_freed_memory(args.fresh_memory)
    print_environment(kept)
    print(f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', '(not set)')}")
    motion = record()
    duration = motion.duration if args.duration is None else min(args.duration, motion.duration)
    print(f"record: {motion.name} with a zero sample in front, {motion.npts} samples at "
          f"{motion.dt} s, {motion.duration:.2f} s")
    cases = {"flexible": make_case(True, GAP), "fixed": make_case(False, GAP)}
    wide = {"flexible": make_case(True, WIDE_GAP), "fixed": make_case(False, WIDE_GAP)}
    t_start = time.perf_counter()
    if "model" in wanted:
        section_model(cases)
    if "linear" in wanted:
        section_steps(f"linear: no pounding (gap {WIDE_GAP:g} m), OpenSees' step against "
                      "pounding", wide, motion, duration, steps)
    if "accuracy" in wanted:
        section_steps(f"accuracy: with pounding (gap {1e3 * GAP:g} mm), OpenSees' step against "
                      "pounding", cases, motion, duration, steps)
    if "reference" in wanted:
        section_reference(cases["flexible"], motion, args.reference_duration or motion.duration)
    if "speed" in wanted:
        section_speed(cases, wide, motion, args.rounds, args.opensees_rounds, args.opensees_dt)
    if "cost" in wanted:
        section_cost(motion, max(3, args.rounds // 2))
    if "yielding" in wanted:
        section_yielding(motion, args.rounds)
    print(f"\nend: {load()}; {time.perf_counter() - t_start:.0f} s")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
