"""Bridges (issue 28): a two-frame bridge along its axis, pounding at its expansion joint
and on its abutments, tied by cable restrainers, in pounding (``structure.bridge``) and in
OpenSeesPy (``opensees_bridge.py``) from one set of numbers, in one process — OpenSees'
matrices against pounding's, its accuracy as its step shrinks, and the speed of both, with
a five-frame bridge (four joints) beside it.

    PYTHONPATH=src:benchmarks python benchmarks/bench_bridge.py                # all, ~15 s
    PYTHONPATH=src:benchmarks python benchmarks/bench_bridge.py --sections speed --rounds 7
    PYTHONPATH=src:benchmarks python benchmarks/bench_bridge.py --sections accuracy --duration 10

The bridge: ``opensees_bridge.example_bridge()`` (its values and their sources in that
module's docstring) with every element linear, El Centro 1940 (180) with a zero sample in
front (both tools start at rest under zero ground acceleration, as OpenSees' Newmark
assumes), 40.00 s:

* **frames** (left to right): deck 3000 t on one pier of 500 kN/mm (cap 300 t) through an
  elastomeric bearing of 1000 kN/mm with a dashpot of 2 % of critical for the deck on it;
  deck 4000 t on a pier of 120 kN/mm (cap 400 t), bearing 240 kN/mm, 2 %. Linear piers.
  Damping: 5 % Rayleigh at each frame's own modes 1 and 2 (pounding's ``BridgeFrame(zeta=
  0.05)``; OpenSees ``opensees_bridge.rayleigh_for``), ``C = a0 M + a1 K + c_bearing``;
* **joint**: gap 25.4 mm, a linear spring k = K_eff = 4378 kN/mm behind it, no dashpot
  (pounding ``ContactSpec("linear-spring", k)``; OpenSees ``ElasticPPGap k −10²⁰ −gap``);
* **abutments**: rigid backwalls 50.8 mm from the end decks, struck with the same linear
  spring (pounding: ``Abutment(gap)``, walls with the model's contact law; OpenSees: the
  abutment element ``ElasticPPGap k −10²⁰ −gap``, no piles);
* **restrainers** across the joint: 17.6 kN/mm, slack 12.7 mm, elastic (pounding
  ``Link`` kind ``restrainer`` without ``yield_force``; OpenSees ``ElasticPPGap k 10²⁰
  slack`` in tension).

The five-frame bridge (speed only): frames of (deck t, pier kN/mm) = (3000, 500),
(4000, 120), (3500, 300), (4000, 120), (3000, 500), caps 10 % of the deck, bearings twice
the pier, 2 % in the bearing, 5 % Rayleigh a frame, four joints as above, each with the
restrainers above, and the abutments above.

Sections:

model     pounding's M, C, K against OpenSees' (assembled by its ``GimmeMCK`` integrator,
          contacts open) and the eigen periods of both.
accuracy  OpenSees at each ``--steps`` step against pounding (output step 1 ms; its answer
          does not depend on it): impacts at the joint and the abutments, peak joint and
          abutment forces, peak deck displacements, peak restrainer force, the largest
          history difference of every DOF and its observed order (Newmark: 2).
speed     whole runs, warm, alternating, ``--rounds`` rounds of each: pounding (output step
          10 ms) against OpenSees at its practice step ``--opensees-dt`` (the record's
          10 ms), two frames and five. Best (median–worst) and the spread of the ratio over
          every pair of runs. pounding: the whole ``simulate()`` call on a built model;
          OpenSees: the domain's build and the analysis loop reading every node and element
          force each step (``opensees_bridge.run_bridge``).
cost      where pounding's time goes: each bridge with and without its restrainers, with
          pounding and without (every gap ``WIDE_GAP``), both tools as in ``speed``:
          impacts, pounding's adaptive (RK) steps, both times and their ratio.
"""

from __future__ import annotations

import argparse
import dataclasses
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

import _figures
import opensees_bridge as ob
import opensees_models as osm
from _environment import load, parse_list, print_environment
from _memory import keep_freed_memory

from pounding.contact.spec import ContactSpec
from pounding.ground_motion import GroundMotion, el_centro
from pounding.integrate import simulate
from pounding.model import PoundingModel
from pounding.structure.bridge import (
    Abutment,
    Bearing,
    Bridge,
    BridgeFrame,
    Pier,
    Restrainer,
)

SECTIONS = ("model", "accuracy", "speed", "cost")
WIDE_GAP = 10.0  #: m: nothing touches
DEFAULT_STEPS = "0.01,0.005,0.002,0.001"
ZETA = 0.05
PIER_HEIGHT = 8.0  #: m (pounding needs an elevation; it plays no part along the axis)
POUNDING_DT = 1e-3
"""pounding's output step in the accuracy section [s] (1 ms: every OpenSees step's common
multiple here)."""
FIVE_FRAMES = ((3.0e6, 5.0e8), (4.0e6, 1.2e8), (3.5e6, 3.0e8), (4.0e6, 1.2e8), (3.0e6, 5.0e8))
"""(deck mass [kg], pier stiffness [N/m]) of the five-frame bridge's frames."""


# ====================================================================== the models
def _os_frame(deck_mass: float, pier_stiffness: float) -> ob.Frame:
    """A frame as ``opensees_bridge.example_bridge`` makes them (linear pier)."""
    k_b = 2.0 * pier_stiffness
    pier = ob.Pier(pier_stiffness, k_b, cap_mass=0.1 * deck_mass,
                   bearing_damping=2.0 * 0.02 * math.sqrt(k_b * deck_mass))
    a0, a1 = ob.rayleigh_for(ob.Frame(deck_mass, (pier,)), ZETA)
    return ob.Frame(deck_mass, (pier,), a0, a1)


def opensees_spec(n_frames: int) -> ob.Bridge:
    """The OpenSees bridge (module docstring): linear joints, rigid elastic abutments
    (no piles), elastic restrainers."""
    base = ob.example_bridge("linear", "epp", yielding=False, zeta=ZETA)
    j0 = base.joints[0]
    frames = (list(base.frames) if n_frames == 2 else
              [_os_frame(m, k) for m, k in FIVE_FRAMES])
    restrainers = ob.Restrainers(j0.restrainers.stiffness, j0.restrainers.slack, None)
    joint = ob.Joint(j0.gap, "linear", stiffness=j0.stiffness, restrainers=restrainers)
    a0 = base.left_abutment
    abutment = ob.Abutment(a0.gap, j0.stiffness, ob.BIG_FORCE, "epp", pile_stiffness=0.0)
    return ob.Bridge(frames, [joint] * (len(frames) - 1), abutment, abutment)


def pounding_model(spec: ob.Bridge) -> PoundingModel:
    """The same bridge in pounding, from the OpenSees spec's numbers (not its a0, a1:
    ``BridgeFrame`` computes its own Rayleigh coefficients; ``section_model`` compares)."""
    frames = []
    for f, fr in enumerate(spec.frames):
        piers = [Pier(PIER_HEIGHT, p.stiffness, p.cap_mass) for p in fr.piers]
        bearings = [Bearing.elastomeric(p.bearing_stiffness, p.bearing_damping)
                    for p in fr.piers]
        frames.append(BridgeFrame(fr.deck_mass, piers, bearings, zeta=ZETA, name=f"F{f + 1}"))
    restrainers = tuple(Restrainer(j, {"kind": "restrainer", "k": jt.restrainers.stiffness,
                                       "slack": jt.restrainers.slack})
                        for j, jt in enumerate(spec.joints) if jt.restrainers is not None)
    gaps = {a.gap for a in (spec.left_abutment, spec.right_abutment)}
    ks = {jt.stiffness for jt in spec.joints} | {a.stiffness for a in
                                                 (spec.left_abutment, spec.right_abutment)}
    if len(ks) != 1 or len(gaps) != 1:
        raise AssertionError("one contact stiffness and one abutment gap are modelled here")
    bridge = Bridge(frames, [jt.gap for jt in spec.joints],
                    (Abutment(spec.left_abutment.gap), Abutment(spec.right_abutment.gap)),
                    restrainers, name=f"{len(frames)}-frame bridge")
    return PoundingModel.from_bridge(bridge, ContactSpec("linear-spring", k=ks.pop()))


@dataclass
class Case:
    """One bridge as pounding's model and as OpenSees' spec."""

    name: str
    model: PoundingModel
    spec: ob.Bridge

    def opensees(self, motion: GroundMotion, dt: float, duration: float) -> ob.BridgeHistory:
        import openseespy.opensees as ops

        return ob.run_bridge(ops, self.spec, motion.accel, motion.dt, dt, duration)


def make_case(n_frames: int) -> Case:
    spec = opensees_spec(n_frames)
    return Case(f"{n_frames} frames", pounding_model(spec), spec)


def variant(case: Case, restrainers: bool, wide: bool) -> Case:
    """``case`` without its restrainers (``restrainers`` False) and/or with every joint and
    abutment gap ``WIDE_GAP`` (``wide``: nothing pounds)."""
    s = case.spec
    joints = [dataclasses.replace(j, gap=WIDE_GAP if wide else j.gap,
                                  restrainers=j.restrainers if restrainers else None)
              for j in s.joints]
    abut = [dataclasses.replace(a, gap=WIDE_GAP if wide else a.gap)
            for a in (s.left_abutment, s.right_abutment)]
    spec = ob.Bridge(s.frames, joints, *abut)
    label = ", ".join(["restrainers" if restrainers else "no restrainers",
                       f"gaps {WIDE_GAP:g} m" if wide else "pounding"])
    return Case(f"{case.name}, {label}", pounding_model(spec), spec)


def record() -> GroundMotion:
    """El Centro with a zero sample in front (module docstring)."""
    g = el_centro()
    return GroundMotion(g.dt, np.concatenate([[0.0], g.accel]), name=g.name)


# ====================================================================== measures
@dataclass
class Measures:
    """What the accuracy tables compare (SI units)."""

    joint_impacts: int
    abutment_impacts: int
    joint_force: float  #: peak, all joints [N]
    abutment_force: float  #: peak, both abutments [N]
    restrainer_force: float  #: peak, all restrainers [N]
    decks: np.ndarray  #: peak |u| of every deck [m]
    time: np.ndarray
    u: np.ndarray  #: (nt, N) in pounding's DOF order (per frame: deck, caps)


def _is_abutment(label: str) -> bool:
    return label.startswith("A") or "-A" in label


def pounding_measures(case: Case, r: Any) -> Measures:
    labels = [c.label for c in case.model.contacts]
    abut = np.array([_is_abutment(s) for s in labels])
    peaks = np.asarray(r.peak_contact_force, dtype=float)
    counts = np.asarray(r.impacts_per_contact)
    decks = [case.model.buildings[f].deck_dof for f in range(len(case.model.buildings))]
    offsets = np.cumsum([0] + [b.n for b in case.model.buildings])[:-1]
    u = np.asarray(r.displacement)
    return Measures(int(counts[~abut].sum()), int(counts[abut].sum()),
                    float(np.max(peaks[~abut], initial=0.0)),
                    float(np.max(peaks[abut], initial=0.0)),
                    float(np.max(r.link_peak_force, initial=0.0)),
                    np.max(np.abs(u[:, offsets + np.array(decks)]), axis=0),
                    np.asarray(r.time), u)


def opensees_measures(h: ob.BridgeHistory) -> Measures:
    cols = []
    for f in range(h.deck.shape[1]):
        cols.append(h.deck[:, f])
        cols += [h.cap[:, q] for q, fr in enumerate(h.cap_frame) if fr == f]
    return Measures(h.joint_impacts, osm.count_impacts(h.abutment_force),
                    float(np.max(h.joint_force, initial=0.0)),
                    float(np.max(h.abutment_force, initial=0.0)),
                    float(np.max(h.restrainer_force, initial=0.0)),
                    np.max(np.abs(h.deck), axis=0), h.time, np.column_stack(cols))


def pct(x: float, ref: float) -> float:
    if ref == 0.0:
        return 0.0 if x == 0.0 else math.inf
    return 100.0 * (x - ref) / ref


def history_difference(ours: Measures, theirs: Measures) -> float:
    """Largest |u_OpenSees − u_pounding| over every DOF at the times both have, in % of
    pounding's largest |u| (OpenSees' steps are multiples of pounding's 1 ms)."""
    stride = round((theirs.time[1] - theirs.time[0]) / (ours.time[1] - ours.time[0]))
    b = ours.u[::stride]
    n = min(b.shape[0], theirs.u.shape[0])
    return 100.0 * float(np.max(np.abs(theirs.u[:n] - b[:n])) / np.max(np.abs(ours.u)))


def spread(values: list[float], scale: float = 1.0, fmt: str = ".2f") -> str:
    """``best (median–worst) ×N`` of timing repeats, times ``scale``."""
    v = [scale * x for x in values]
    return f"{min(v):{fmt}} ({statistics.median(v):{fmt}}–{max(v):{fmt}}) ×{len(v)}"


def ratio_line(num: list[float], den: list[float]) -> str:
    """Best / best, median / median, and every pair of runs' ratio's range."""
    pairs = [a / b for a in num for b in den]
    return (f"{min(num) / min(den):.1f}× (best), "
            f"{statistics.median(num) / statistics.median(den):.1f}× (median), "
            f"{min(pairs):.1f}–{max(pairs):.1f}× over every pair of runs")


# ====================================================================== sections
def opensees_matrices(spec: ob.Bridge) -> tuple[np.ndarray, ...]:
    """``(M, C, K)`` as OpenSees assembles them (``integrator GimmeMCK``, ``printA``;
    contacts and restrainers open: zero tangent), in pounding's DOF order."""
    import openseespy.opensees as ops

    tags = ob.build_bridge(ops, spec)
    nodes = []
    for f, deck in enumerate(tags.decks):
        nodes.append(deck)
        nodes += [c for c, fr in zip(tags.caps, tags.cap_frame) if fr == f]
    out = []
    for coefficients in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
        ops.wipeAnalysis()
        ops.constraints("Plain")
        ops.numberer("Plain")
        ops.system("FullGeneral")
        ops.algorithm("Linear")
        ops.integrator("GimmeMCK", *coefficients)
        ops.analysis("Transient")
        ops.analyze(1, 0.0)
        eqs = [ops.nodeDOFs(nd)[0] for nd in nodes]
        a = np.array(ops.printA("-ret"))
        n = math.isqrt(a.size)
        out.append(a.reshape(n, n)[np.ix_(eqs, eqs)])
    ops.wipeAnalysis()
    periods = np.sort(ob.eigen_periods(ops, len(nodes)))[::-1]
    ops.wipe()
    return (*out, periods)


def section_model(cases: dict[str, Case]) -> None:
    print("\n== model: pounding's matrices against OpenSees' (zeroLength elements, region "
          "Rayleigh a0 M; GimmeMCK) ==")
    for case in cases.values():
        m = case.model
        M, C, K = (np.asarray(x) for x in (m.system.M, m.system.C, m.linear_stiffness()))
        Mo, Co, Ko, t_os = opensees_matrices(case.spec)
        t_p = np.sort(np.concatenate([b.modes().periods for b in m.buildings]))[::-1]
        print(f"  {case.name}: {M.shape[0]} DOFs; largest difference in % of the largest "
              f"entry: M {100 * np.max(np.abs(Mo - M)) / np.max(np.abs(M)):.1e}, "
              f"C {100 * np.max(np.abs(Co - C)) / np.max(np.abs(C)):.1e}, "
              f"K {100 * np.max(np.abs(Ko - K)) / np.max(np.abs(K)):.1e}")
        for f, (b, fr) in enumerate(zip(m.buildings, case.spec.frames)):
            print(f"    frame {f + 1}: Rayleigh a0 {b.rayleigh[0]:.6g} 1/s, a1 "
                  f"{b.rayleigh[1]:.6g} s (OpenSees rayleigh_for: {pct(fr.a0, b.rayleigh[0]):+.1e} "
                  f"%, {pct(fr.a1, b.rayleigh[1]):+.1e} %); periods "
                  + ", ".join(f"{t:.4f}" for t in b.modes().periods) + " s")
        print("    eigen periods [s], pounding " + " ".join(f"{t:.6f}" for t in t_p)
              + f"; OpenSees within {np.max(np.abs(t_os / t_p - 1.0)):.1e}")


def _row(label: str, x: Measures, ref: Measures | None = None, hist: str = "",
         order: str = "", retried: str = "") -> str:
    decks = " / ".join(f"{1e3 * d:.2f}" for d in x.decks)
    if ref is None:
        return (f"  {label:<16} {x.joint_impacts:>3} {x.abutment_impacts:>3} "
                f"{x.joint_force / 1e6:>10.3f} MN {x.abutment_force / 1e6:>9.3f} MN "
                f"{x.restrainer_force / 1e6:>9.4f} MN  {decks} mm")
    dd = " / ".join(f"{pct(a, b):+.3f}" for a, b in zip(x.decks, ref.decks))
    return (f"  {label:<16} {x.joint_impacts:>3} {x.abutment_impacts:>3} "
            f"{pct(x.joint_force, ref.joint_force):>+11.2f} % "
            f"{pct(x.abutment_force, ref.abutment_force):>+9.2f} % "
            f"{pct(x.restrainer_force, ref.restrainer_force):>+9.3f} %  {dd} %   "
            f"Δu hist {hist:>8} % {order:>5}  retried {retried}")


def section_accuracy(case: Case, motion: GroundMotion, duration: float,
                     steps: list[float]) -> None:
    print(f"\n== accuracy: OpenSees' step against pounding, {case.name}, "
          f"{duration:.2f} s ==")
    print(f"  {'':<16} {'imp':>3} {'abt':>3} {'joint force':>14} {'abut force':>12} "
          f"{'restrainer':>12}  decks 1 / 2 …   (OpenSees: relative to pounding; "
          "Δu hist in % of pounding's largest |u|, every DOF; observed order)")
    r = simulate(case.model, motion, dt=POUNDING_DT, duration=duration)
    ours = pounding_measures(case, r)
    print(_row("pounding", ours), flush=True)
    prev, prev_dt = None, None
    for dt in steps:
        h = case.opensees(motion, dt, duration)
        theirs = opensees_measures(h)
        hist = history_difference(ours, theirs)
        order = ("" if prev is None or hist == 0.0 else
                 f"{math.log(prev / hist) / math.log(prev_dt / dt):.2f}")
        prev, prev_dt = hist, dt
        print(_row(f"OpenSees {1e3 * dt:g} ms", theirs, ours, f"{hist:.3g}", order,
                   f"{h.retried}" + (f", FAILED {h.failed}" if h.failed else "")), flush=True)
    print("  (imp / abt: impacts at the joint(s) / the abutments; pounding's peak forces "
          "are located inside its steps, OpenSees' are at its steps)")


def _time_pounding(case: Case, motion: GroundMotion, dt: float) -> tuple[float, Any]:
    t0 = time.perf_counter()
    r = simulate(case.model, motion, dt=dt)
    return time.perf_counter() - t0, r


def section_speed(cases: dict[str, Case], motion: GroundMotion, rounds: int,
                  os_dt: float) -> None:
    import openseespy.opensees as ops  # noqa: F401  (imported before the timed runs)

    print(f"\n== speed: whole runs, {motion.duration:.2f} s, warm, {rounds} alternating rounds"
          f", each: pounding (output step 10 ms), OpenSees (Newmark at {1e3 * os_dt:g} ms, "
          "its practice step: the record's), for each bridge ==")
    for case in cases.values():  # warm-up: compilation, the models' caches
        _time_pounding(case, motion, 1e-2)
        case.opensees(motion, os_dt, 1.0)
    ours_t: dict[str, list[float]] = {k: [] for k in cases}
    theirs_t: dict[str, list[float]] = {k: [] for k in cases}
    last: dict[str, tuple[Any, ob.BridgeHistory]] = {}
    for _ in range(rounds):
        for key, case in cases.items():
            w, r = _time_pounding(case, motion, 1e-2)
            ours_t[key].append(w)
            h = case.opensees(motion, os_dt, motion.duration)
            theirs_t[key].append(h.wall)
            last[key] = (r, h)
    for key, case in cases.items():
        r, h = last[key]
        ours, theirs = pounding_measures(case, r), opensees_measures(h)
        print(f"  {case.name} ({case.model.system.M.shape[0]} DOFs, "
              f"{len(case.model.contacts)} contacts, {len(case.model.devices)} restrainer "
              f"links): pounding {spread(ours_t[key], 1e3)} ms ({r.n_impacts} impacts, "
              f"{r.stats.rk_steps} RK steps); OpenSees {spread(theirs_t[key], 1e3, '.0f')} ms "
              f"({h.retried} steps retried)")
        print(f"      OpenSees / pounding {ratio_line(theirs_t[key], ours_t[key])}")
        _figures.figure(f"{case.name}: whole run, {motion.duration:.0f} s, pounding's output "
                        f"10 ms, OpenSees' step {1e3 * os_dt:g} ms", min(ours_t[key]),
                        _figures.opensees_name(), min(theirs_t[key]),
                        ratio_meaning="OpenSees / pounding",
                        goal=">= 50x" if key == "five" else None,
                        spread=f"best of {rounds} alternating rounds; "
                               f"{ratio_line(theirs_t[key], ours_t[key])}")
        _figures.note(f"{case.name}: impacts {r.n_impacts}, RK steps {r.stats.rk_steps}; "
                      f"OpenSees' joint force {pct(theirs.joint_force, ours.joint_force):+.2f} %"
                      f" of pounding's")
        print(f"      OpenSees at {1e3 * os_dt:g} ms there: impacts joint {theirs.joint_impacts}"
              f" (pounding {ours.joint_impacts}), abutment {theirs.abutment_impacts} "
              f"({ours.abutment_impacts}); Δ joint force "
              f"{pct(theirs.joint_force, ours.joint_force):+.2f} %, Δ abutment force "
              f"{pct(theirs.abutment_force, ours.abutment_force):+.2f} %, Δ restrainer "
              f"{pct(theirs.restrainer_force, ours.restrainer_force):+.2f} %, Δ decks "
              + " / ".join(f"{pct(a, b):+.2f}" for a, b in zip(theirs.decks, ours.decks))
              + f" %; Δu hist {history_difference(ours, theirs):.2f} %")
    print("  (the issue's goal: a 5-span bridge with 4 joints ≥ 50× faster than OpenSeesPy)")


def section_cost(cases: dict[str, Case], motion: GroundMotion, rounds: int,
                 os_dt: float) -> None:
    print(f"\n== cost: where pounding's time goes — each bridge with and without its "
          f"restrainers, pounding (gaps as given) or not (gaps {WIDE_GAP:g} m); "
          f"{motion.duration:.2f} s, output step 10 ms, OpenSees at {1e3 * os_dt:g} ms, warm, "
          f"{rounds} alternating rounds ==")
    variants = [variant(case, r, w) for case in cases.values()
                for r in (True, False) for w in (False, True)]
    for v in variants:  # warm-up
        _time_pounding(v, motion, 1e-2)
    ours_t: dict[str, list[float]] = {v.name: [] for v in variants}
    theirs_t: dict[str, list[float]] = {v.name: [] for v in variants}
    info: dict[str, Any] = {}
    for _ in range(rounds):
        for v in variants:
            w, r = _time_pounding(v, motion, 1e-2)
            ours_t[v.name].append(w)
            info[v.name] = r
            theirs_t[v.name].append(v.opensees(motion, os_dt, motion.duration).wall)
    print(f"  {'bridge':<44} {'impacts':>7} {'RK steps':>8} {'pounding ms':>26} "
          f"{'OpenSees ms':>20}  OpenSees / pounding, best (median)")
    for v in variants:
        r = info[v.name]
        o, t = ours_t[v.name], theirs_t[v.name]
        print(f"  {v.name:<44} {r.n_impacts:>7} {r.stats.rk_steps:>8} {spread(o, 1e3):>26} "
              f"{spread(t, 1e3, '.0f'):>20}  {min(t) / min(o):.1f}× "
              f"({statistics.median(t) / statistics.median(o):.1f}×)")
        _figures.figure(f"cost: {v.name} ({r.n_impacts} impacts, {r.stats.rk_steps} RK steps)",
                        min(o), _figures.opensees_name(), min(t),
                        ratio_meaning="OpenSees / pounding",
                        spread=f"best of {len(o)} alternating rounds")
    print("  (RK steps: pounding's adaptive steps — through contacts, and wherever a "
          "restrainer is taut; outside them its steps are exact)")


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
                    help=f"accuracy: OpenSees' steps [s] (default {DEFAULT_STEPS})")
    ap.add_argument("--duration", type=float, default=None,
                    help="accuracy: seconds of the record (default all, 40.00 s)")
    ap.add_argument("--rounds", type=int, default=5,
                    help="speed: alternating rounds (default 5)")
    ap.add_argument("--opensees-dt", type=float, default=0.01,
                    help="speed: OpenSees' step [s] (default 0.01, the record's)")
    ap.add_argument("--fresh-memory", action="store_true",
                    help="leave glibc's malloc as it is (default: keep freed memory for reuse, "
                         "benchmarks/_memory.py)")
    _figures.add_json_option(ap)
    args = ap.parse_args(argv)
    _figures.start("bench_bridge", "Bridges")
    wanted = parse_list(ap, args.sections, SECTIONS)
    steps = _floats(ap, "steps", args.steps)
    if any(abs(s / POUNDING_DT - round(s / POUNDING_DT)) > 1e-9 for s in steps):
        ap.error(f"--steps: need multiples of {POUNDING_DT:g} s (got {args.steps!r})")
    if args.rounds < 1:
        ap.error("--rounds: need at least 1")
    for name in ("duration", "opensees_dt"):
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
    cases = {"two": make_case(2), "five": make_case(5)}
    for case in cases.values():
        print(f"{case.name}: {case.model.name}; " + "; ".join(
            f"F{f + 1} " + b.describe() for f, b in enumerate(case.model.buildings)))
    t_start = time.perf_counter()
    if "model" in wanted:
        section_model(cases)
    if "accuracy" in wanted:
        section_accuracy(cases["two"], motion, duration, steps)
    if "speed" in wanted:
        section_speed(cases, motion, args.rounds, args.opensees_dt)
    if "cost" in wanted:
        section_cost(cases, motion, max(3, args.rounds), args.opensees_dt)
    print(f"\nend: {load()}; {time.perf_counter() - t_start:.0f} s")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
