"""The LA9-type frame pair under earthquake records: pounding against OpenSeesPy on the same
model — accuracy as OpenSees' step shrinks, speed per run, and the cost of an IDA.

Run from the repository root, in a Python holding pounding's requirements and
``openseespy`` (see ``benchmarks/README.md``)::

    PYTHONPATH=src:benchmarks python benchmarks/bench_frames.py                 # everything
    PYTHONPATH=src:benchmarks python benchmarks/bench_frames.py --sections accuracy \\
        --duration 10 --steps 0.01,0.005,0.0025,0.001
    PYTHONPATH=src:benchmarks python benchmarks/bench_frames.py --sections speed --repeat 3
    PYTHONPATH=src:benchmarks python benchmarks/bench_frames.py --sections ida \\
        --ida-scales 0.25,0.5,1,2,3

The pair, the records and their scales: ``frames_pair.py`` (frame A the LA9-type frame of
``frames_la9.py``, frame B the same with half the mass, T1 2.117 and 1.481 s, a 20 mm gap,
Kelvin–Voigt contacts at the nine floors; El Centro × 2.5 and Northridge Newhall × 1.0).
The OpenSees model and analysis: ``opensees_frame_pair.py`` (the same members, hinges,
leaning column, gravity first, pounding's floor damping, ``ViscoelasticGap`` contacts,
Newmark average acceleration with Newton and the usual fallbacks).

Sections:

accuracy  For each record, with pounding (20 mm gap) and without (10 m gap): pounding's
          impacts, peak contact force, peak storey drift ratios of both frames, peak hinge
          rotations, against OpenSees' at each ``--steps`` step; OpenSees' errors relative
          to pounding's values (largest over storeys and over hinges), its floor
          displacement histories' largest difference, the steps it needed a fallback for,
          and where it failed to converge (it then stops: a failure ends the run).
          pounding's output step is 1 ms (its answer does not depend on it).
speed     El Centro (its 39.99 s) × its scale, with pounding: ``--repeat`` timed runs of
          each program alternating (after an untimed warm-up of each), pounding with the
          output step ``--pounding-dt``, OpenSees at ``--opensees-dt`` (the record's step,
          practice); each run's wall time, the spread (best, median, worst), the ratios;
          OpenSees' accuracy there against pounding; and one OpenSees run at
          ``--fine-dt`` (0 to skip): how long OpenSees takes to come near pounding's
          accuracy. Times are whole analyses: pounding's ``simulate`` call (building the
          pair excluded), OpenSees' gravity + transient loop with its reads of the floors
          and contacts and its hinge envelope recorder (building the domain excluded).
ida       pounding alone: the pair under El Centro at each ``--ida-scales`` factor (one
          run each, 39.99 s, output step ``--pounding-dt``); the cost of one frame pair in
          an IDA of 10 records × 20 levels on 2 cores, extrapolated: 20 levels evenly
          spaced over the scales' range, each run's time interpolated linearly in the scale
          factor between the measured ones, × 10 records (El Centro standing for each),
          / 2 workers (perfect parallel speed-up assumed).

numpy's OpenBLAS runs on one thread unless ``--blas-threads`` says otherwise (as in
``bench_pushover.py``); OpenSees 3.7.1.2 solves with its ``SparseGEN`` solver on one
thread, the fastest of four on this model (2 s of El Centro × 0.2, elastic, 10 ms steps,
2026-11-27, load average 1.7–2.7: ``SparseGEN`` 3.3 ms a step, ``UmfPack`` 5.0,
``BandGeneral`` 46 — the floor dashpots and contacts tie far-apart nodes, so the band is
wide — and ``FullGeneral`` 75).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import _figures

SECTIONS = ("accuracy", "speed", "ida")
DEFAULT_STEPS = "0.01,0.005,0.0025,0.001"


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help=f"comma-separated, of {', '.join(SECTIONS)} (default all)")
    ap.add_argument("--duration", type=float, default=None,
                    help="accuracy: seconds of each record (default the whole record)")
    ap.add_argument("--steps", default=DEFAULT_STEPS,
                    help=f"accuracy: OpenSees' steps [s], comma-separated (default {DEFAULT_STEPS})")
    ap.add_argument("--records", default="El Centro,Northridge",
                    help="accuracy: comma-separated, of 'El Centro', 'Northridge'")
    ap.add_argument("--northridge", default=None,
                    help="the Northridge Newhall 360 .AT2 file (default /work/shared/records/…)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="speed: timed runs of pounding (default 3, ≥ 1)")
    ap.add_argument("--opensees-repeat", type=int, default=2,
                    help="speed: timed runs of OpenSees (default 2, ≥ 1)")
    ap.add_argument("--opensees-dt", type=float, default=0.01,
                    help="speed: OpenSees' step [s] (default 0.01, El Centro's own)")
    ap.add_argument("--fine-dt", type=float, default=0.001,
                    help="speed: one more OpenSees run at this step [s] (0: none)")
    ap.add_argument("--pounding-dt", type=float, default=0.01,
                    help="speed, ida: pounding's output step [s] (default 0.01)")
    ap.add_argument("--ida-scales", default="0.25,0.5,1,2,3",
                    help="ida: El Centro scale factors, comma-separated")
    ap.add_argument("--blas-threads", default="1",
                    help="OPENBLAS_NUM_THREADS for numpy (default 1; 'default': as set)")
    _figures.add_json_option(ap)
    return ap


def spread(values: list[float], fmt: str = ".2f") -> str:
    """``best (median–worst) xN`` of timing repeats."""
    return (f"{min(values):{fmt}} ({statistics.median(values):{fmt}}–{max(values):{fmt}})"
            f" x{len(values)}")


def _floats(ap: argparse.ArgumentParser, name: str, text: str) -> list[float]:
    try:
        values = [float(s) for s in text.split(",") if s.strip()]
    except ValueError:
        ap.error(f"--{name}: need numbers separated by commas (got {text!r})")
    if not values or any(not (v > 0) for v in values):
        ap.error(f"--{name}: need numbers > 0 (got {text!r})")
    return values


# ====================================================================== shared
class Setup:
    """The pair, its floor damping as OpenSees computes it, OpenSees and its log."""

    def __init__(self, args: argparse.Namespace) -> None:
        import frames_pair as fp
        import numpy as np
        import opensees_frame_pair as ofp
        import openseespy.opensees as ops

        self.np, self.ops, self.fp, self.ofp = np, ops, fp, ofp
        self.northridge = Path(args.northridge) if args.northridge else fp.NORTHRIDGE
        self.log = str(Path(os.environ.get("TMPDIR", "/tmp"))
                       / f"bench_frames_opensees_{os.getpid()}.log")
        ops.logFile(self.log, "-noEcho")
        self.pair = fp.pair()
        self.damping = []
        for frame, building in zip(self.pair.frames, self.pair.buildings, strict=True):
            C, a0, a1 = ofp.floor_damping(ops, frame, building.masses, building.K)
            ops.logFile(self.log, "-noEcho")
            diff = np.max(np.abs(C - building.damping_matrix())) / np.max(np.abs(C))
            print(f"  {frame.name}: {frame.describe()}; T1 {self._t1(building):.3f} s; "
                  f"Rayleigh a0 = {a0:.5f} 1/s, a1 = {a1:.6f} s from OpenSees' periods; "
                  f"C against pounding's: {diff:.1e} (relative)")
            self.damping.append(C)

    def _t1(self, building: Any) -> float:
        np = self.np
        w2 = np.linalg.eigvals(np.linalg.solve(building.M, building.K)).real
        return float(2 * np.pi / np.sqrt(np.min(w2)))

    def motion(self, name: str) -> Any:
        return self.fp.record(name, self.northridge).scaled(self.fp.SCALES[name])

    def pounding(self, gap: float, motion: Any, duration: float, dt: float) -> tuple[Any, float]:
        from pounding.integrate import simulate

        model = self.pair.with_gap(gap).model
        t = time.perf_counter()
        r = simulate(model, motion, duration=duration, dt=dt)
        return r, time.perf_counter() - t

    def opensees(self, gap: float, motion: Any, duration: float, dt: float) -> Any:
        a, b = self.pair.frames
        contacts = self.fp.opensees_contacts(self.pair.with_gap(gap).model)
        built = self.ofp.build_pair(self.ops, a, b, tuple(self.damping), contacts, gap)
        history = self.ofp.run_pair(self.ops, built, motion.accel, motion.dt, dt, duration,
                                    log=self.log)
        self.ops.wipe()
        return history


def _measures_row(label: str, m: Any, extra: str = "") -> str:
    return (f"  {label:<16} {m.impacts:>7d} {m.peak_force / 1e6:>8.2f} "
            f"{100 * m.drift_a.max():>8.3f} {100 * m.drift_b.max():>8.3f} "
            f"{1e3 * m.hinge.max():>8.3f}{extra}")


HEADER = (f"  {'':<16} {'impacts':>7} {'F MN':>8} {'drift A%':>8} {'drift B%':>8} "
          f"{'θ mrad':>8}")
ERR_HEADER = (f" | {'ΔF/F':>8} {'Δdrift':>8} {'Δθ':>8} {'Δu hist':>8} | {'rescued':>7} "
              f"{'wall s':>7}  converged")


# ====================================================================== accuracy
def accuracy_section(args: argparse.Namespace, s: Setup, steps: list[float]) -> None:
    fp = s.fp
    print("\n== accuracy: pounding (exact between events) against OpenSees as its step "
          "shrinks ==")
    print("  errors relative to pounding's largest value of each quantity: ΔF/F the peak "
          "contact force, Δdrift the storeys' peak drift ratios (both frames), Δθ the "
          "hinges' peak rotations, Δu hist the floors' displacement histories at OpenSees' "
          "steps; impacts: OpenSees counts closures seen at its steps")
    failures: list[str] = []
    newton_alone: list[str] = []
    out_dt = min(0.001, min(steps))
    for name in [n.strip() for n in args.records.split(",") if n.strip()]:
        motion = s.motion(name)
        duration = motion.duration if args.duration is None else min(args.duration,
                                                                      motion.duration)
        for label, gap in (("with pounding", fp.GAP), ("without pounding", fp.NO_POUNDING_GAP)):
            print(f"\n  -- {name} × {fp.SCALES[name]:g} (PGA {motion.pga_g:.3f} g), "
                  f"{duration:.2f} s, {label} (gap {gap:g} m) --")
            r, wall = s.pounding(gap, motion, duration, out_dt)
            ours = fp.pounding_measures(r)
            print(HEADER + ERR_HEADER)
            print(_measures_row("pounding", ours, f" | {'':>8} {'':>8} {'':>8} {'':>8} | "
                                f"{'':>7} {wall:7.1f}  ({r.stats.events} events)"))
            for dt in steps:
                h = s.opensees(gap, motion, duration, dt)
                theirs = fp.opensees_measures(h)
                if h.complete:
                    e = fp.errors(ours, theirs, r, h)
                    errs = (f" | {e.force:8.1e} {e.drift:8.1e} {e.hinge:8.1e} "
                            f"{e.history:8.1e}")
                else:
                    errs = f" | {'(stopped: no errors)':>35}"
                    failures.append(f"{name}, {label}, dt = {dt:g} s: {h.failures[0]}")
                print(_measures_row(f"OpenSees {dt:g} s", theirs, errs
                                    + f" | {len(h.rescued):7d} {h.wall:7.1f}  "
                                    + ("yes" if h.complete else
                                       f"NO, stopped at {h.time[-1]:.3f} s")))
                if h.rescued:
                    kinds: dict[str, int] = {}
                    for _, how in h.rescued:
                        kinds[how] = kinds.get(how, 0) + 1
                    print("  " + " " * 16 + "   rescued by: " + "; ".join(
                        f"{k} ×{v}" for k, v in sorted(kinds.items(), key=lambda kv: -kv[1]))
                        + f" (Newton alone would have stopped at t = {h.rescued[0][0]:.3f} s)")
                    newton_alone.append(f"{name}, {label}, dt = {dt:g} s: t = "
                                        f"{h.rescued[0][0]:.3f} s")
    print("\n  OpenSees failed to converge (every strategy, down to dt/100): "
          + ("; ".join(failures) if failures else "nowhere") + "; pounding ran every case")
    print("  Newton alone (no fallback) fails first at: "
          + ("; ".join(newton_alone) if newton_alone else "nowhere"))
    print(f"  (OpenSees' warnings: {s.log})")


# ====================================================================== speed
def speed_section(args: argparse.Namespace, s: Setup) -> None:
    fp = s.fp
    name = "El Centro"
    motion = s.motion(name)
    duration = motion.duration
    gap = fp.GAP
    print(f"\n== speed: the pair under {name} × {fp.SCALES[name]:g}, {duration:.2f} s, gap "
          f"{1e3 * gap:g} mm ==")
    print(f"  pounding: simulate(..., dt={args.pounding_dt:g}) (output step; the answer "
          f"does not depend on it); OpenSees: Newmark, dt = {args.opensees_dt:g} s, "
          f"{round(duration / args.opensees_dt)} steps")
    s.pounding(gap, motion, 1.0, args.pounding_dt)  # warm-up (compiled kernel loaded)
    ours_t: list[float] = []
    theirs_t: list[float] = []
    r = h = None
    for k in range(max(args.repeat, args.opensees_repeat)):
        if k < args.repeat:
            r, wall = s.pounding(gap, motion, duration, args.pounding_dt)
            ours_t.append(wall)
            print(f"  round {k + 1}: pounding {wall:7.2f} s ({r.stats.events} events, "
                  f"{r.n_impacts} impacts)", flush=True)
        if k < args.opensees_repeat:
            h = s.opensees(gap, motion, duration, args.opensees_dt)
            theirs_t.append(h.wall)
            print(f"  round {k + 1}: OpenSees {h.wall:7.2f} s ({len(h.rescued)} steps "
                  f"rescued, {'complete' if h.complete else f'STOPPED at {h.time[-1]:.3f} s'})",
                  flush=True)
    assert r is not None and h is not None
    print(f"  pounding [s], best (median–worst): {spread(ours_t)}")
    print(f"  OpenSees [s], best (median–worst): {spread(theirs_t)}")
    ratios = [t / o for t in theirs_t for o in ours_t]
    print(f"  OpenSees / pounding: {min(theirs_t) / min(ours_t):.2f}x (best), "
          f"{statistics.median(theirs_t) / statistics.median(ours_t):.2f}x (median); "
          f"the day's spread over every pair of runs {min(ratios):.2f}x – {max(ratios):.2f}x")
    _figures.figure(f"two LA9-type frames, {name} x {fp.SCALES[name]:g}, {duration:.0f} s: "
                    f"pounding (output {args.pounding_dt:g} s) against OpenSees' Newmark at "
                    f"{args.opensees_dt:g} s", min(ours_t), _figures.opensees_name(),
                    min(theirs_t), ratio_meaning="OpenSees / pounding",
                    spread=f"best of {len(ours_t)} / {len(theirs_t)}; every pair of runs "
                           f"{min(ratios):.2f}-{max(ratios):.2f}x")
    ours, theirs = fp.pounding_measures(r), fp.opensees_measures(h)
    print(HEADER + ERR_HEADER)
    print(_measures_row("pounding", ours))
    _speed_row(fp, f"OpenSees {args.opensees_dt:g} s", ours, theirs, r, h)
    if args.fine_dt > 0:
        fine = s.opensees(gap, motion, duration, args.fine_dt)
        _speed_row(fp, f"OpenSees {args.fine_dt:g} s", ours, fp.opensees_measures(fine), r,
                   fine)
        _figures.figure(f"two LA9-type frames, {name} x {fp.SCALES[name]:g}, {duration:.0f} s:"
                        f" pounding against OpenSees' Newmark at {args.fine_dt:g} s",
                        min(ours_t), _figures.opensees_name(), fine.wall,
                        ratio_meaning="OpenSees / pounding",
                        spread=f"pounding best of {len(ours_t)}, OpenSees one run")
        print(f"  OpenSees at {args.fine_dt:g} s takes {fine.wall / min(ours_t):.1f}x "
              f"pounding's best ({fine.wall / statistics.median(ours_t):.1f}x its median)")


def _speed_row(fp: Any, label: str, ours: Any, theirs: Any, r: Any, h: Any) -> None:
    if h.complete:
        e = fp.errors(ours, theirs, r, h)
        errs = f" | {e.force:8.1e} {e.drift:8.1e} {e.hinge:8.1e} {e.history:8.1e}"
    else:
        errs = f" | stopped at {h.time[-1]:.3f} s: {h.failures[0]}"
    print(_measures_row(label, theirs, errs + f" | {len(h.rescued):7d} {h.wall:7.1f}"))


# ====================================================================== ida
def ida_section(args: argparse.Namespace, s: Setup, scales: list[float]) -> None:
    np, fp = s.np, s.fp
    base = fp.record("El Centro")
    print(f"\n== ida: pounding, the pair under El Centro at each scale, {base.duration:.2f} s, "
          f"gap {1e3 * fp.GAP:g} mm, output step {args.pounding_dt:g} s ==")
    s.pounding(fp.GAP, base, 1.0, args.pounding_dt)  # warm-up
    times = []
    for scale in sorted(scales):
        r, wall = s.pounding(fp.GAP, base.scaled(scale), base.duration, args.pounding_dt)
        m = fp.pounding_measures(r)
        times.append(wall)
        print(f"  × {scale:<5g} {wall:7.2f} s  {r.stats.events:6d} events  {m.impacts:4d} "
              f"impacts  peak drift A {100 * m.drift_a.max():.2f} %, B "
              f"{100 * m.drift_b.max():.2f} %  θ {1e3 * m.hinge.max():.2f} mrad", flush=True)
    levels = np.linspace(min(scales), max(scales), 20)
    per_level = np.interp(levels, sorted(scales), times)
    total = 10 * float(np.sum(per_level)) / 2
    print(f"  20 levels × {min(scales):g} … {max(scales):g} (even), each run's time "
          f"interpolated: mean {np.mean(per_level):.2f} s a run; 10 records × 20 levels = "
          f"200 runs on 2 workers: {total:.0f} s ({total / 60:.1f} min; the goal: ≤ 60 s)")
    _figures.note(f"IDA of the LA9-type pair, El Centro x {min(scales):g}-{max(scales):g}: "
                  f"{np.mean(per_level):.2f} s a run; 200 runs on 2 workers estimated "
                  f"{total:.0f} s (goal <= 60 s: {'met' if total <= 60 else 'missed'})")


def main(argv: list[str] | None = None) -> int:
    ap = _parser()
    args = ap.parse_args(argv)
    _figures.start("bench_frames", "LA9-type pair time history")
    if args.blas_threads != "default":
        os.environ["OPENBLAS_NUM_THREADS"] = str(int(args.blas_threads))
    if args.repeat < 1 or args.opensees_repeat < 1:
        ap.error(f"--repeat, --opensees-repeat: need at least 1 (got {args.repeat}, "
                 f"{args.opensees_repeat})")
    if args.duration is not None and not args.duration > 0:
        ap.error(f"--duration: need seconds > 0 (got {args.duration})")
    for name in ("opensees_dt", "pounding_dt"):
        if not getattr(args, name) > 0:
            ap.error(f"--{name.replace('_', '-')}: need seconds > 0 (got {getattr(args, name)})")
    if not args.fine_dt >= 0:
        ap.error(f"--fine-dt: need seconds ≥ 0 (got {args.fine_dt})")
    sys.path.insert(0, str(HERE))
    from _environment import load, parse_list, print_environment

    wanted = parse_list(ap, args.sections, SECTIONS)
    steps = _floats(ap, "steps", args.steps)
    scales = _floats(ap, "ida-scales", args.ida_scales)
    parse_list(ap, args.records, ("El Centro", "Northridge"), what="record")
    print_environment(False)
    print(f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', '(not set)')}")
    setup = Setup(args)
    if "accuracy" in wanted:
        accuracy_section(args, setup, steps)
    if "speed" in wanted:
        speed_section(args, setup)
    if "ida" in wanted:
        ida_section(args, setup, scales)
    print(f"\nend: {load()}")
    _figures.write(args.json)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
